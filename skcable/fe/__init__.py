"""Finite-element machinery shared by cables and strands; it knows no physics.

- `skcable.fe.assembly`: one assembly of section laws on scikit-fem's basis values (elements
  last, batched products, a sparsity pattern computed once);
- `skcable.fe.linear`: banded LAPACK solves, a sparse solve where a term breaks the band, the
  bordered solve of one global unknown;
- `skcable.fe.newton`: one Newton–Raphson with line search, a stagnation stop and a result
  carrying its history.
"""

from skcable.fe.assembly import Assembly, StrainAssembly
from skcable.fe.check import check_tangent
from skcable.fe.linear import BandedSystem, BorderedSolver, LinearSystem, SparseSystem
from skcable.fe.newton import NewtonOptions, NewtonResult, minimize, newton

__all__ = [
    "Assembly",
    "BandedSystem",
    "BorderedSolver",
    "LinearSystem",
    "NewtonOptions",
    "NewtonResult",
    "SparseSystem",
    "StrainAssembly",
    "check_tangent",
    "minimize",
    "newton",
]
