"""One solve of one discrete line: semismooth Newton, its full-step fallback, and the polish.

`solve_on(problem, z0, rtol, max_iter)` runs `skcable.fe.newton` (damped by backtracking on the
max-norm merit) from ``z0``. The max-norm merit of a semismooth system can refuse every damped
step where full steps identify the active set and converge: then `full_steps` is tried from the
same start before the first failure is raised. Past ``rtol``, full Newton steps go on while the
merit still falls tenfold (`POLISH` at most): quadratic convergence takes the solution to its
round-off floor for one or two more assemblies.
"""

from __future__ import annotations

import numpy as np

from skcable.cable.bvp.line.solution import LineBVPSolution
from skcable.errors import ConvergenceError
from skcable.fe import newton

__all__ = ["POLISH", "first_success", "full_steps", "solve_on"]

#: Newton steps past rtol at most, while the merit falls tenfold
POLISH = 2


def first_success(*attempts):
    """The result of the first of ``attempts`` (callables) that does not raise
    `ConvergenceError`; when every one does, the first one's error (the later ones only try to
    rescue it). Any other exception passes at once."""
    first = None
    for attempt in attempts:
        try:
            return attempt()
        except ConvergenceError as failed:
            first = failed if first is None else first
    raise first from None


def full_steps(problem, z0, rtol, max_iter):
    """Semismooth Newton with full steps (halved only where the tangent collapses): (z, state,
    history) once the merit is below ``rtol``, None if it is not within ``max_iter`` steps or
    grows a thousandfold."""
    state = problem.assemble(z0)
    z, history = z0, [state.merit]
    for _ in range(max_iter):
        if state.merit < rtol:
            return z, state, history
        if not state.merit < 1e3 * history[0]:
            return None
        dz, t = problem.increment(state), 1.0
        for _ in range(12):
            trial = problem.assemble(z + t * dz)
            if np.isfinite(trial.merit):
                break
            t *= 0.5
        else:
            return None
        z, state = z + t * dz, trial
        history.append(state.merit)
    return (z, state, history) if state.merit < rtol else None


def _damped(problem, z0, rtol, max_iter):
    result = newton(
        problem.assemble,
        z0,
        norm=lambda state: state.merit,
        increment=problem.increment,
        tol=rtol,
        max_iter=max_iter,
        stagnation_window=8,
        name="solve_line_bvp",
        floor=problem.merit_floor,
    )
    return result.x, result.state, list(result.history)


def _undamped(problem, z0, rtol, max_iter):
    out = full_steps(problem, z0, rtol, max_iter)
    if out is None:
        raise ConvergenceError("solve_line_bvp: full semismooth steps did not converge", [])
    return out


def solve_on(problem, z0, rtol, max_iter) -> LineBVPSolution:
    """The line of ``problem`` from the iterate ``z0``: damped Newton, else full steps (the
    damped one's error raised when both fail), then the polish."""
    z, state, history = first_success(
        lambda: _damped(problem, z0, rtol, max_iter), lambda: _undamped(problem, z0, rtol, max_iter)
    )
    for _ in range(POLISH):
        trial_z = z + problem.increment(state)
        trial = problem.assemble(trial_z)
        if not trial.merit < 0.1 * state.merit:
            break
        z, state = trial_z, trial
        history.append(state.merit)
    return LineBVPSolution(problem, z, history, state)
