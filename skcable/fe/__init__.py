"""Finite-element machinery shared by cables and strands; it knows no physics.

- `skcable.fe.assembly`: section laws assembled by ``einsum`` on scikit-fem's basis
  values, fixed sparsity patterns, banded LAPACK solves;
- `skcable.fe.newton`: one Newton–Raphson with line search, a stagnation stop and a
  result carrying its history.
"""

from skcable.fe.assembly import BandedSystem, StrainAssembly
from skcable.fe.newton import NewtonResult, minimize, newton

__all__ = ["BandedSystem", "NewtonResult", "StrainAssembly", "minimize", "newton"]
