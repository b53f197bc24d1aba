r"""The linear systems of a Newton step: banded where the band holds, sparse where it does not.

The tangent of a one-dimensional mesh is banded once the dofs are ordered along the axis:
`BandedSystem` keeps that ordering and solves with LAPACK's banded LU (``dgbsv``) or Cholesky
(``dpbtrf``/``dpbtrs``), which on a 2-core machine beats a sparse factorisation for every size
used here and wakes no BLAS threads. A term that couples distant dofs (a tie, a multi-point
constraint) breaks the band: `SparseSystem` offers the same calls on SuperLU
(``scipy.sparse.linalg.splu``), with symmetric diagonal pivoting for the Cholesky-like solve so
that the signs of its pivots tell a positive-definite matrix. `LinearSystem` starts banded and
moves to the sparse one, for good, the first time a matrix does not fit the band: the user is
told neither to stop nor to reformulate.

`BorderedSolver` solves a banded tangent bordered by one global unknown (a cable's H or its
unstretched length):

.. math:: \begin{bmatrix} K & c \\ r^T & d \end{bmatrix}
          \begin{bmatrix}\delta u \\ \delta\lambda\end{bmatrix}
          = -\begin{bmatrix} R \\ g \end{bmatrix}

by the Schur complement: one LU of ``K`` with the two right-hand sides ``-R`` and ``c`` gives
``a = -K⁻¹R``, ``b = K⁻¹c``, then ``δλ = (-g - r·a) / (d - r·b)`` and ``δu = a - b δλ``. Dot
products are plain reductions (``np.sum``), not BLAS calls that would wake its threads. Bands
and right-hand sides are kept in Fortran order, so that LAPACK works on them in place (f2py
copies a C-ordered array to Fortran order on every call).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from scipy.linalg import lapack

from skcable.errors import ConvergenceError

__all__ = ["BandedSystem", "BorderedSolver", "LinearSystem", "SparseSystem"]


@dataclass
class BandedSystem:
    """The free–free block of a pattern in LAPACK band storage, dofs ordered along the axis.

    ``add_elements(ab, Ke)`` and ``add_sparse(ab, K)`` fill the band of a matrix; ``solve(ab, b)``
    factorises and solves with ``dgbsv`` (``b`` over the free dofs, in their given order).

    Parameters
    ----------
    N : int
        Size of the global vector.
    free : ndarray of int
        The unknown dofs, in the order of the right-hand sides.
    rows, cols : ndarray of int
        Global row and column of every entry of the element matrices, in their ravel order.
    location : ndarray (N,)
        Where each dof lies along the axis (m): the band's ordering.
    """

    N: int
    free: np.ndarray
    rows: np.ndarray
    cols: np.ndarray
    location: np.ndarray

    def __post_init__(self):
        free = np.asarray(self.free)
        n = len(free)
        order = free[np.argsort(self.location[free], kind="stable")]
        self.position = np.full(self.N, -1)
        self.position[order] = np.arange(n)  # banded index of each free dof
        self._free_rank = self.position[free]  # banded index of free[k]
        i, j = self.position[self.rows], self.position[self.cols]
        keep = (i >= 0) & (j >= 0)
        self._keep = keep
        self.kl = self.ku = int(np.max(np.abs(i[keep] - j[keep]))) if keep.any() else 0
        self.n = n
        self.shape = (2 * self.kl + self.ku + 1, n)
        self._slot = self._flat(i[keep], j[keep])

    def _flat(self, i, j):
        """Position of entry (i, j) in the band storage read in Fortran order."""
        return (self.kl + self.ku + i - j) + j * self.shape[0]

    def band(self) -> np.ndarray:
        """An empty matrix in this band storage, in Fortran order: LAPACK takes it as it is
        (a C-ordered band is copied to Fortran order by every call)."""
        return np.zeros(self.shape, order="F")

    def add_elements(self, ab: np.ndarray, Ke: np.ndarray) -> np.ndarray:
        """Add element matrices of the pattern (in its ravel order) into band storage ``ab``
        (in place, whatever its memory order)."""
        values, slot = self._entries(Ke, "band")
        ab += np.bincount(slot, weights=values, minlength=ab.size).reshape(self.shape, order="F")
        return ab

    def _entries(self, Ke, which: str) -> tuple[np.ndarray, np.ndarray]:
        """``(values, slots)``: the entries of element matrices ``Ke`` (n_local, n_local,
        n_elements) that go into the band (``which="band"``) or its lower part (``"lower"``),
        and their slots there. Matrices laid out elements first in memory (a batched product's
        ``(n_elements, n, n)`` seen transposed) are read where they lie, not copied to the
        pattern's order: the same value goes to the same slot, in the same order."""
        keep, slot = (self._keep, self._slot) if which == "band" else self._lower
        Ke = np.asarray(Ke)
        if Ke.ndim != 3 or not Ke.transpose(2, 0, 1).flags.c_contiguous:
            return Ke.ravel()[keep], slot
        cache = self.__dict__.setdefault("_by_element", {})
        key = (which, Ke.shape)
        if key not in cache:
            i, j, e = np.unravel_index(np.flatnonzero(keep), Ke.shape)
            cache[key] = np.ravel_multi_index((e, i, j), (Ke.shape[2], Ke.shape[0], Ke.shape[1]))
        return Ke.transpose(2, 0, 1).ravel().take(cache[key]), slot

    def _free_entries(self, K, inside: bool = False):
        """Free–free ``(i, j, data)`` of ``K`` in banded indices; ``inside``: in the band or `ValueError`."""
        K = sp.coo_matrix(K)
        i, j = self.position[K.row], self.position[K.col]
        keep = (i >= 0) & (j >= 0) & (K.data != 0)
        i, j = i[keep], j[keep]
        if inside and np.any(np.abs(i - j) > self.kl):
            raise ValueError("the matrix couples dofs farther apart than the band")
        return i, j, K.data[keep]

    def fits(self, K) -> bool:
        """Whether the free–free entries of the sparse (N, N) matrix ``K`` lie in the band."""
        i, j, _ = self._free_entries(K)
        return not np.any(np.abs(i - j) > self.kl)

    def add_sparse(self, ab: np.ndarray, K) -> np.ndarray:
        """Add the free–free entries of a sparse (N, N) matrix into ``ab``; they must lie in the band
        (`fits`), else `ValueError`."""
        i, j, data = self._free_entries(K, inside=True)
        np.add.at(ab, (self.kl + self.ku + i - j, j), data)
        return ab

    # --- the lower band alone, for a symmetric matrix (half the entries to sum) ---------------
    @cached_property
    def _lower(self) -> tuple[np.ndarray, np.ndarray]:
        """``(keep, slot)``: which entries of the element matrices lie on or below the diagonal
        of the free block, and where each goes in the (kl + 1, n) lower band (Fortran order)."""
        i, j = self.position[self.rows], self.position[self.cols]
        keep = (i >= 0) & (j >= 0) & (i >= j)
        return keep, (i[keep] - j[keep]) + j[keep] * (self.kl + 1)

    def band_lower(self) -> np.ndarray:
        """An empty lower band ``(kl + 1, n)`` in Fortran order: LAPACK's ``dpbtrf`` storage of
        the lower triangle (whose factorisation runs on unit strides: faster than the upper's)."""
        return np.zeros((self.kl + 1, self.n), order="F")

    def lower_of(self, Ke: np.ndarray) -> np.ndarray:
        """A new lower band ``(kl + 1, n)`` (Fortran order, as `band_lower`) holding the lower
        triangle of the sum of symmetric element matrices ``Ke``."""
        values, slot = self._entries(Ke, "lower")
        return np.bincount(slot, weights=values, minlength=(self.kl + 1) * self.n).reshape(
            (self.kl + 1, self.n), order="F"
        )

    def add_sparse_lower(self, ab: np.ndarray, K) -> np.ndarray:
        """Add the free–free lower triangle of a symmetric sparse (N, N) matrix into ``ab`` (it must
        lie in the band, else `ValueError`)."""
        i, j, data = self._free_entries(K, inside=True)
        lower = i >= j
        np.add.at(ab, (i[lower] - j[lower], j[lower]), data[lower])
        return ab

    def solve_positive_lower(self, ab: np.ndarray, b: np.ndarray, shift=None, mu: float = 0.0):
        """`solve_positive` for lower bands (`band_lower`): ``ab`` is overwritten."""
        if shift is not None and mu != 0.0:
            ab = ab + mu * shift
        rhs = np.empty(self.n)
        rhs[self._free_rank] = b
        # ``dpbsv``: ``dpbtrf`` then ``dpbtrs`` in one call
        _, x, info = lapack.dpbsv(ab, rhs, lower=1, overwrite_ab=True, overwrite_b=True)
        if info > 0:
            raise np.linalg.LinAlgError(f"not positive definite (LAPACK dpbsv info = {info})")
        if info != 0:
            raise np.linalg.LinAlgError(f"LAPACK dpbsv info = {info}")
        return x.take(self._free_rank)

    def solve_positive(self, ab: np.ndarray, b: np.ndarray, shift: np.ndarray | None = None, mu: float = 0.0):
        """Solve ``(A + mu·M) x = b`` by banded Cholesky (LAPACK ``dpbtrf``/``dpbtrs``) for a
        symmetric A (and M) in this band storage; raises ``numpy.linalg.LinAlgError`` when the
        matrix is not positive definite."""
        upper = ab[self.kl : self.kl + self.ku + 1]
        if shift is not None and mu != 0.0:
            upper = upper + mu * shift[self.kl : self.kl + self.ku + 1]
        c, info = lapack.dpbtrf(upper, lower=0)
        if info != 0:
            raise np.linalg.LinAlgError(f"not positive definite (LAPACK dpbtrf info = {info})")
        rhs = np.empty(self.n)
        rhs[self._free_rank] = b
        x, info = lapack.dpbtrs(c, rhs, lower=0)
        if info != 0:
            raise np.linalg.LinAlgError(f"LAPACK dpbtrs info = {info}")
        return x[self._free_rank]

    def solve(self, ab: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Solve the banded system for right-hand sides over the free dofs (in ``free`` order):
        ``b`` of shape (n,) or (n, k). ``ab`` is overwritten."""
        b = np.asarray(b, dtype=float)
        rhs = np.empty((self.n, *b.shape[1:]), order="F")
        rhs[self._free_rank] = b
        _, _, x, info = lapack.dgbsv(self.kl, self.ku, ab, rhs, overwrite_ab=True, overwrite_b=True)
        if info != 0:
            raise ConvergenceError(f"banded solve: the tangent is singular (LAPACK dgbsv info = {info})", [])
        return x[self._free_rank]


class SparseSystem:
    """The free–free block of a sparse (N, N) matrix, with the calls of `BandedSystem`.

    Matrices are accumulated as a list of COO pieces (``band()`` returns an empty one); the
    solves factorise the free block with SuperLU.
    """

    def __init__(self, N: int, free: np.ndarray, rows: np.ndarray, cols: np.ndarray):
        self.N, self.free = int(N), np.asarray(free)
        self.rows, self.cols = rows, cols
        self.n = len(self.free)

    def band(self) -> list:
        return []

    def add_elements(self, acc: list, Ke: np.ndarray) -> list:
        acc.append(sp.coo_matrix((np.asarray(Ke).ravel(), (self.rows, self.cols)), shape=(self.N, self.N)))
        return acc

    def add_sparse(self, acc: list, K) -> list:
        acc.append(sp.coo_matrix(K))
        return acc

    def fits(self, K) -> bool:
        return True

    def _global(self, acc) -> sp.csr_matrix:
        return sum((sp.csr_matrix(piece) for piece in acc), sp.csr_matrix((self.N, self.N)))

    def _free_block(self, acc, shift=None, mu=0.0):
        A = self._global(acc)
        if shift is not None and mu != 0.0:
            A = A + mu * self._global(shift)
        return A[self.free][:, self.free].tocsc()

    def solve(self, acc: list, b: np.ndarray) -> np.ndarray:
        from scipy.sparse.linalg import splu

        try:
            lu = splu(self._free_block(acc))
        except RuntimeError as exc:  # SuperLU: "Factor is exactly singular"
            raise ConvergenceError(f"sparse solve: the tangent is singular ({exc})", []) from None
        x = lu.solve(np.asarray(b, dtype=float))
        if not np.all(np.isfinite(x)):
            raise ConvergenceError("sparse solve: the tangent is singular (non-finite solution)", [])
        return x

    def solve_positive(self, acc: list, b: np.ndarray, shift=None, mu: float = 0.0) -> np.ndarray:
        """As `BandedSystem.solve_positive`: SuperLU with symmetric diagonal pivoting, whose pivots
        are all positive exactly when the symmetric matrix is positive definite."""
        from scipy.sparse.linalg import splu

        A = self._free_block(acc, shift, mu)
        try:
            lu = splu(A, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
        except RuntimeError as exc:
            raise np.linalg.LinAlgError(f"not positive definite ({exc})") from None
        if not (np.all(lu.perm_r == lu.perm_c) and np.all(lu.U.diagonal() > 0)):
            raise np.linalg.LinAlgError("not positive definite (a pivot of the symmetric factorisation <= 0)")
        return lu.solve(np.asarray(b, dtype=float))


class LinearSystem:
    """`BandedSystem` while every matrix fits its band, `SparseSystem` from the first that does not.

    ``accept(extra)`` is called with the sparse matrices a model is about to add; it switches to
    the sparse system (for good) when one of them leaves the band and returns whether it did.
    """

    def __init__(self, banded: BandedSystem):
        self.banded = banded
        self.current: BandedSystem | SparseSystem = banded

    @property
    def is_banded(self) -> bool:
        return self.current is self.banded

    def accept(self, extra) -> bool:
        if self.is_banded and not all(self.banded.fits(K) for K in extra):
            b = self.banded
            self.current = SparseSystem(b.N, b.free, b.rows, b.cols)
            return True
        return False

    def __getattr__(self, name):  # band, add_elements, add_sparse, solve, solve_positive, n
        return getattr(self.current, name)


class BorderedSolver:
    """Solves the bordered system of the module docstring on the free dofs of a `BandedSystem`."""

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
        columns = np.empty((2 if bordered else 1, system.n))  # the right-hand sides, one a row
        columns[0][rank] = -residual  # one-dimensional scatters and gathers: the cheapest kind
        if bordered:
            columns[1][rank] = column
        # columns.T is the Fortran-ordered (n, k) array dgbsv solves in place, one call for both
        _, _, x, info = lapack.dgbsv(system.kl, system.ku, ab, columns.T, overwrite_ab=True, overwrite_b=True)
        if info != 0:
            raise ConvergenceError(f"the tangent is singular (LAPACK dgbsv info = {info})", [])
        a = x[:, 0].take(rank)
        if not bordered:
            return a, -gap / corner
        b = x[:, 1].take(rank)
        weighted = row * b
        schur = corner - np.sum(weighted)
        scale = abs(corner) + np.sum(np.abs(weighted, out=weighted))
        if not (np.isfinite(schur) and abs(schur) > 1e-14 * scale):
            raise ConvergenceError("the bordered tangent is singular (Schur complement zero)", [])
        d_global = (-gap - np.sum(row * a)) / schur
        return a - b * d_global, float(d_global)
