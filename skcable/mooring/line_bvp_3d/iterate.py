"""One solve of one discrete line in space: damped semismooth Newton, full steps, the polish.

As the plane line's (`skcable.mooring.line_bvp.iterate`), by `skcable.fe.newton` and its
fallbacks (*Fallbacks* there): damped by backtracking on the max-norm merit, else full
semismooth steps from the same start (which identify an active set where the damped steps
stall), the damped one's error raised when both fail; from a start near the solution (a warm
start, a refitted touchdown: ``near``) full steps first, the damped ones where they fail; a
trial off a seabed grid (`skcable.mooring.bathymetry.OffGrid`) is a step too long. Past
``rtol``, full Newton steps go on while the merit halves (`POLISH` at most), taking the solution
to its round-off floor.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable.fe.newton import newton
from skcable.mooring.bathymetry import OffGrid

__all__ = ["POLISH", "Solved", "solve_on"]

#: Newton steps past rtol at most, while the merit halves
POLISH = 3
#: halvings of a step at most where its trial collapses or leaves the seabed's grid
HALVINGS = 12


@dataclass
class Solved:
    """A converged solve: the problem, its iterate, the merit history and the state there."""

    problem: object
    z: np.ndarray
    history: list = field(default_factory=list)
    state: object = None


def solve_on(problem, z0, rtol, max_iter, near=False) -> Solved:
    """The line of ``problem`` from ``z0`` (module docstring); ``near``: ``z0`` is a converged
    line moved a little (a warm start, a touchdown refitted), whose active set full steps
    identify in a few iterations where the damped ones crawl: full steps first."""
    result = newton(
        problem.assemble,
        z0,
        norm=lambda state: state.merit,
        increment=problem.increment,
        tol=rtol,
        max_iter=max_iter,
        max_halvings=HALVINGS,
        stagnation_window=8,
        name="solve_line_bvp_3d",
        floor=problem.merit_floor,
        rejects=(OffGrid,),
        full_steps="first" if near else "after",
        polish=POLISH,
        polish_factor=0.5,
    )
    return Solved(problem, result.x, list(result.history), result.state)
