r"""Newton increment of a banded tangent bordered by one global unknown.

Both formulations solve

.. math:: \begin{bmatrix} K & c \\ r^T & d \end{bmatrix}
          \begin{bmatrix}\delta u \\ \delta\lambda\end{bmatrix}
          = -\begin{bmatrix} R \\ g \end{bmatrix}

with ``K`` banded (the free dofs of a line mesh, ordered along it), ``λ``
the global unknown (H or L0), ``c = ∂R/∂λ`` and ``(r, d)`` the constraint's
row. By the Schur complement: one LU of ``K`` (LAPACK ``dgbsv``) with the two
right-hand sides ``-R`` and ``c`` gives ``a = -K⁻¹R``, ``b = K⁻¹c``, then
``δλ = (-g - r·a) / (d - r·b)`` and ``δu = a - b δλ``. Dot products are
plain reductions (``np.sum``), not BLAS calls that would wake its threads.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import lapack

from skcable.errors import ConvergenceError
from skcable.fe import BandedSystem

__all__ = ["BorderedSolver"]


class BorderedSolver:
    """Solves the bordered system above on the free dofs of a `BandedSystem`."""

    def __init__(self, system: BandedSystem):
        self.system = system
        self._rank = system.position[np.asarray(system.free)]  # banded index of free[k]

    def solve(self, ab, residual, column=None, row=None, corner=1.0, gap=0.0):
        """``(δu, δλ)`` over the free dofs; without ``column`` only ``K δu = -R`` (δλ = -gap/corner).

        ``ab`` is the band of ``K`` (overwritten). Raises ConvergenceError (empty
        history: the caller adds its own) when ``K`` or the Schur complement is singular.
        """
        system, rank = self.system, self._rank
        bordered = column is not None
        rhs = np.empty((system.n, 2 if bordered else 1), order="F")
        rhs[rank, 0] = -residual
        if bordered:
            rhs[rank, 1] = column
        _, _, x, info = lapack.dgbsv(system.kl, system.ku, ab, rhs, overwrite_ab=True, overwrite_b=True)
        if info != 0:
            raise ConvergenceError(f"the tangent is singular (LAPACK dgbsv info = {info})", [])
        a = x[rank, 0]
        if not bordered:
            return a, -gap / corner
        b = x[rank, 1]
        schur = corner - np.sum(row * b)
        scale = abs(corner) + np.sum(np.abs(row * b))
        if not (np.isfinite(schur) and abs(schur) > 1e-14 * scale):
            raise ConvergenceError("the bordered tangent is singular (Schur complement zero)", [])
        d_global = (-gap - np.sum(row * a)) / schur
        return a - b * d_global, float(d_global)
