"""Former home of :func:`solve_bvp`, now in :mod:`skcable.cable.bvp` (kept for its importers)."""

from skcable.cable.bvp import BVPSolution, solve_bvp

__all__ = ["BVPSolution", "solve_bvp"]
