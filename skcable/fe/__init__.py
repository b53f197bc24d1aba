"""Finite-element machinery shared by cables and strands; it knows no physics.

- `skcable.fe.assembly`: one assembly of section laws on scikit-fem's basis values (elements
  last, batched products, a sparsity pattern computed once);
- `skcable.fe.linear`: banded LAPACK solves, a sparse solve where a term breaks the band, the
  bordered solve of one global unknown;
- `skcable.fe.newton`: one Newton–Raphson with line search, a stagnation stop, full-step
  fallbacks and a polish as options, and a result carrying its history; `NewtonOptions`, the
  user's settings of it; `first_converged`, the retries from other starts;
- `skcable.fe.terms`: the term protocol every model's physics follows;
- `skcable.fe.check`: a term's tangent against central differences.

The assembly, the linear systems and the check load on first use (PEP 562): a closed-form solver
that runs `newton` does not load scikit-fem. `newton` itself is imported at once: the function
has its module's name, and a submodule imported later must not take its place.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach
from skcable.fe.newton import NewtonOptions, NewtonResult, first_converged, minimize, newton, semismooth

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.fe.assembly import Assembly
    from skcable.fe.check import check_tangent
    from skcable.fe.linear import BandedSystem, BorderedSolver, LinearSystem, SparseSystem

_NAMES = {
    ".assembly": ("Assembly",),
    ".check": ("check_tangent",),
    ".linear": ("BandedSystem", "BorderedSolver", "LinearSystem", "SparseSystem"),
}

__getattr__, __dir__ = attach(
    __name__, submodules=("assembly", "check", "elements", "linear", "probes", "terms"), names=_NAMES
)

__all__ = [
    "Assembly",
    "BandedSystem",
    "BorderedSolver",
    "LinearSystem",
    "NewtonOptions",
    "NewtonResult",
    "SparseSystem",
    "check_tangent",
    "first_converged",
    "minimize",
    "newton",
    "semismooth",
]
