"""One solve of one discrete line: semismooth Newton, its full-step fallback, and the polish.

`solve_on(problem, z0, options)` runs `skcable.fe.newton` (damped by backtracking on the max-norm
merit, unless ``options.line_search`` is ``"none"``) from ``z0`` with the user's Newton options
(`skcable.fe.NewtonOptions`: ``tol``, ``atol``, ``max_iter``, ``max_halvings``,
``stagnation_window``, ``callback``). The max-norm merit of a semismooth system can refuse every
damped step where full steps identify the active set and converge: then `full_steps` is tried
from the same start before the first failure is raised. Past ``tol``, full Newton steps go on
while the merit still falls tenfold (`POLISH` at most): quadratic convergence takes the solution
to its round-off floor for one or two more assemblies. Where the damped Newton stops (no
descent, stagnation) with the line on the seabed, `frozen_steps` goes on from where it stopped
with the active set held: a node on the seabed with no push (``λ = g = 0``, a touchdown at a
node) makes the semismooth Newton cycle between two active sets (the max-norm merit refuses
both steps), and one of them, held, is a smooth system whose solution meets the contact
conditions to ``tol``. ``callback(iteration, residual_norm, step_norm)`` sees every step of
them all, numbered from 1 in each solve (the fallback starts again from the start); an exception
it raises stops the solve as an `skcable.InputError` naming ``callback`` and the iteration.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import ConvergenceError, InputError
from skcable.fe import NewtonOptions, newton
from skcable.mooring.line_bvp.solution import LineBVPSolution

__all__ = [
    "FROZEN_STEPS",
    "POLISH",
    "first_success",
    "frozen_steps",
    "full_newton",
    "full_steps",
    "polish",
    "report",
    "solve_on",
]

#: exceptions a trial may raise that make it a step too long (a seabed grid's `OffGrid`)
Rejects = tuple[type[BaseException], ...]

#: Newton steps past rtol at most, while the merit falls tenfold
POLISH = 2

#: full Newton steps at most per active set held (`frozen_steps`)
FROZEN_STEPS = 8


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
    assert first is not None, "first_success needs at least one attempt"
    raise first from None


def report(callback, iteration: int, merit: float, step) -> None:
    """``callback(iteration, merit, max |step|)``, if given; what it raises becomes an
    `InputError` naming ``callback`` and the iteration (as `skcable.fe.newton` does)."""
    if callback is None:
        return
    try:
        callback(iteration, merit, float(np.max(np.abs(step), initial=0.0)))
    except Exception as exc:  # a user's callback: stop, and say where
        raise InputError("callback", f"raised {type(exc).__name__} at iteration {iteration}: {exc}") from exc


def converged(problem, state, options: NewtonOptions) -> bool:
    """Whether ``state`` meets ``options.tol`` (the merit) or ``options.atol`` (the force rows, N,
    with the stretch rows within ``tol``)."""
    return state.merit < options.tol or (
        options.atol > 0 and problem.absolute(state, options.tol) < options.atol
    )


def full_newton(problem, z0, converged_at, max_iter, halvings, callback=None, rejects: Rejects = ()):
    """Semismooth Newton with full steps from ``z0``, halved only where the tangent collapses or a
    trial is one of ``rejects`` (an exception: a step off a seabed's grid), ``halvings`` times at
    most: ``(z, state, history, done)``, ``done`` whether ``converged_at(state)`` holds; it stops
    short where the merit grows a thousandfold or a step finds no trial. The plane's solves and
    the 3-D line's (`skcable.mooring.line_bvp_3d.iterate`) share it."""
    state = problem.assemble(z0)
    z, history = z0, [state.merit]
    for _ in range(max_iter):
        if converged_at(state):
            return z, state, history, True
        if not state.merit < 1e3 * history[0]:
            break
        dz, t = problem.increment(state), 1.0
        for _ in range(halvings):
            try:
                trial = problem.assemble(z + t * dz)
            except rejects:
                trial = None
            if trial is not None and np.isfinite(trial.merit):
                break
            t *= 0.5
        else:
            break
        z, state = z + t * dz, trial
        history.append(state.merit)
        report(callback, len(history) - 1, state.merit, t * dz)
    return z, state, history, converged_at(state)


def full_steps(problem, z0, options: NewtonOptions):
    """Semismooth Newton with full steps (`full_newton`): (z, state, history) once converged
    (`converged`), None if it is not within ``options.max_iter`` steps or the merit grows a
    thousandfold."""
    z, state, history, done = full_newton(
        problem, z0, lambda st: converged(problem, st, options), options.max_iter, options.max_halvings,
        options.callback,
    )  # fmt: skip
    return (z, state, history) if done else None


def polish(problem, z, state, history, steps, factor, callback=None, rejects: Rejects = ()):
    """Full Newton steps past the tolerance, ``steps`` at most, while the merit falls below
    ``factor`` times the last (quadratic convergence takes the solution to its round-off floor
    for one or two more assemblies); a trial that raises one of ``rejects`` stops it. Returns
    ``(z, state, history)``."""
    for _ in range(steps):
        step = problem.increment(state)
        trial_z = z + step
        try:
            trial = problem.assemble(trial_z)
        except rejects:
            break
        if not trial.merit < factor * state.merit:
            break
        z, state = trial_z, trial
        history.append(state.merit)
        report(callback, len(history) - 1, state.merit, step)
    return z, state, history


def _active_sets(problem, state):
    """The active sets `frozen_steps` holds: the iterate's, its full Newton step's, their union
    and their intersection (each once)."""
    here = state.terms.active
    trial = problem.assemble(state.z + problem.increment(state))
    there = here if trial.terms is None else trial.terms.active
    masks: list[np.ndarray] = []
    for mask in (here, there, here | there, here & there):
        if not any(np.array_equal(mask, seen) for seen in masks):
            masks.append(mask)
    return masks


def frozen_steps(problem, z, options: NewtonOptions, steps: int = FROZEN_STEPS):
    """Full Newton steps from ``z`` with the contact nodes' active set held
    (`LineProblem.with_active_set`), for each of `_active_sets` in turn, ``steps`` at most:
    (z, state, history) once the line's own residual (its true contact rows, ``min(λ, c g)``)
    meets ``options.tol`` (`converged`); None if no active set gets there or the line has no
    contact rows. ``history`` holds the true merit per step."""
    state = problem.assemble(z)
    if state.terms is None or not np.isfinite(state.merit):
        return None
    for mask in _active_sets(problem, state):
        held = problem.with_active_set(mask)
        zh, sh, history = z, held.assemble(z), [state.merit]
        for _ in range(steps):
            if not np.isfinite(sh.merit):
                break
            step = held.increment(sh)
            zh = zh + step
            sh, true = held.assemble(zh), problem.assemble(zh)
            history.append(true.merit)
            report(options.callback, len(history) - 1, true.merit, step)
            if converged(problem, true, options):
                return zh, true, history
    return None


def _damped(problem, z0, options: NewtonOptions):
    try:
        return _newton(problem, z0, options)
    except ConvergenceError as failed:
        # the steps left of max_iter (none where the Newton ran out of them)
        steps = min(FROZEN_STEPS, options.max_iter - (len(failed.history) - 1))
        out = None
        if failed.last is not None and steps > 0:
            out = frozen_steps(problem, failed.last, options, steps)
        if out is None:
            raise
        z, state, history = out
        return z, state, list(failed.history) + history[1:]


def _newton(problem, z0, options: NewtonOptions):
    result = newton(
        problem.assemble,
        z0,
        norm=lambda state: state.merit,
        increment=problem.increment,
        tol=options.tol,
        max_iter=options.max_iter,
        max_halvings=options.max_halvings,
        stagnation_window=options.stagnation_window,
        name="solve_line_bvp",
        floor=problem.merit_floor,
        atol=options.atol,
        absolute=lambda state: problem.absolute(state, options.tol),
        line_search=options.line_search != "none",
        callback=options.callback,
    )
    return result.x, result.state, list(result.history)


def _undamped(problem, z0, options: NewtonOptions):
    out = full_steps(problem, z0, options)
    if out is None:
        raise ConvergenceError("solve_line_bvp: full semismooth steps did not converge", [])
    return out


def solve_on(problem, z0, options: NewtonOptions) -> LineBVPSolution:
    """The line of ``problem`` from the iterate ``z0``: damped Newton, else full steps (the
    damped one's error raised when both fail; no fallback where the Newton takes full steps
    already, ``line_search="none"``), then the polish."""
    attempts = [lambda: _damped(problem, z0, options)]
    if options.line_search != "none":
        attempts.append(lambda: _undamped(problem, z0, options))
    z, state, history = first_success(*attempts)
    z, state, history = polish(problem, z, state, history, POLISH, 0.1, options.callback)
    return LineBVPSolution(problem, z, history, state)
