"""One solve of one discrete line in space: damped semismooth Newton, full steps, the polish.

As the plane line's (`skcable.mooring.line_bvp.iterate`): `skcable.fe.newton` damped by
backtracking on the max-norm merit, else full semismooth steps from the same start (which
identify an active set where the damped steps stall), the damped one's error raised when both
fail; from a start near the solution (a warm start, a refitted touchdown: ``near``) full steps
first, the damped ones where they fail; a trial off a seabed grid
(`skcable.mooring.bathymetry.OffGrid`) is a step too long. Past ``rtol``, full Newton steps go
on while the merit halves (`POLISH` at most), taking the solution to its round-off floor.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable.errors import ConvergenceError
from skcable.fe.newton import newton
from skcable.mooring.bathymetry import OffGrid
from skcable.mooring.line_bvp.iterate import first_success, full_newton, polish

__all__ = ["POLISH", "Solved", "solve_on"]

#: Newton steps past rtol at most, while the merit halves
POLISH = 3
#: halvings of a full step at most where its trial collapses or leaves the seabed's grid
HALVINGS = 12


@dataclass
class Solved:
    """A converged solve: the problem, its iterate, the merit history and the state there."""

    problem: object
    z: np.ndarray
    history: list = field(default_factory=list)
    state: object = None


def _damped(problem, z0, rtol, max_iter):
    result = newton(
        problem.assemble,
        z0,
        norm=lambda state: state.merit,
        increment=problem.increment,
        tol=rtol,
        max_iter=max_iter,
        stagnation_window=8,
        name="solve_line_bvp_3d",
        floor=problem.merit_floor,
        rejects=(OffGrid,),
    )
    return result.x, result.state, list(result.history)


def _full_steps(problem, z0, rtol, max_iter):
    z, state, history, done = full_newton(
        problem, z0, lambda st: st.merit < rtol, max_iter, HALVINGS, rejects=(OffGrid,)
    )
    if done:
        return z, state, history
    raise ConvergenceError("solve_line_bvp_3d: full semismooth steps did not converge", history, last=z)


def solve_on(problem, z0, rtol, max_iter, near=False) -> Solved:
    """The line of ``problem`` from ``z0`` (module docstring); ``near``: ``z0`` is a converged
    line moved a little (a warm start, a touchdown refitted), whose active set full steps
    identify in a few iterations where the damped ones crawl: full steps first."""
    damped, full = (
        (lambda: _damped(problem, z0, rtol, max_iter)),
        (lambda: _full_steps(problem, z0, rtol, max_iter)),
    )
    if near:
        try:
            z, state, history = full()
        except ConvergenceError:
            z, state, history = damped()
    else:
        z, state, history = first_success(damped, full)
    z, state, history = polish(problem, z, state, history, POLISH, 0.5, rejects=(OffGrid,))
    return Solved(problem, z, history, state)
