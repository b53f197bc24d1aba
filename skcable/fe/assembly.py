r"""Assembly of section laws on scikit-fem bases, vectorised over elements and points.

A model whose physics is a *section law* — section forces :math:`S_a(g)` and
their tangent :math:`D_{ab} = \partial S_a / \partial g_b` at the quadrature
points, as functions of generalized strains :math:`g_a = \partial^{k_a}
f_a / \partial x^{k_a}` of its fields — has the internal force and tangent

.. math:: R_i = \int_0^L \sum_a S_a\, B_{ai}\,dx, \qquad
          K_{ij} = \int_0^L \sum_{ab} B_{ai}\, D_{ab}\, B_{bj}\,dx,

with :math:`B_{ai}` the derivative of order :math:`k_a` of basis function
:math:`i` of field :math:`f_a`. These are the forms
``LinearForm(lambda v, w: sum(w.S[a] * d_a(v)))`` and
``BilinearForm(lambda u, v, w: sum(w.D[a, b] * d_b(u) * d_a(v)))`` of
scikit-fem; `StrainAssembly` evaluates them with the basis values that
scikit-fem computes once (``Basis.basis``, ``Basis.dx``), one ``einsum`` per
call, and a sparsity pattern whose index maps are computed once: no form
evaluation, COO sorting or keyword normalisation per call. The result equals
scikit-fem's ``asm`` to round-off (``tests/fe/test_assembly.py``).

The linear systems of a one-dimensional mesh are banded once the dofs are
ordered along the axis: `BandedSystem` keeps that ordering and solves
with LAPACK's banded LU (``dgbsv``), which on a 2-core machine beats a sparse
factorisation for every size used here and wakes no BLAS threads.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from scipy.linalg import lapack
from skfem import Basis

from skcable.errors import ConvergenceError, InputError

__all__ = ["StrainAssembly", "BandedSystem", "contract"]


def contract(subscripts: str, *operands) -> np.ndarray:
    """``np.einsum`` in its plain C loop: for the small arrays of a strand or cable (a few
    elements' worth of points and wires), finding a BLAS contraction order and reshaping
    for it costs more than the contraction (measured: 3x slower with ``optimize=True``)."""
    return np.einsum(subscripts, *operands, optimize=False)


def _derivative(field, order: int) -> np.ndarray:
    """Derivative of order 0, 1 or 2 of a scikit-fem DiscreteField on a line: (ne, nq)."""
    if order == 0:
        return np.asarray(field)  # the field itself is its value (``.value`` is deprecated)
    if order == 1:
        return field.grad[0]
    if order == 2:
        return field.hess[0][0]
    raise InputError("order", f"must be 0, 1 or 2, got {order!r}")


class StrainAssembly:
    """Fast assembly of ``∫ Bᵀ S`` and ``∫ Bᵀ D B`` for fields on bases sharing one quadrature.

    Parameters
    ----------
    bases : dict of str to skfem.Basis
        The fields, in dof order (the global vector stacks them), all on one
        mesh and one quadrature rule.
    strains : sequence of (str, int)
        The generalized strains: (field, derivative order 0/1/2).

    Attributes
    ----------
    B : ndarray (n_strains, n_local, n_elements, n_quad)
        Basis derivatives per strain and local dof (zero where the local dof
        belongs to another field).
    dofs : ndarray (n_local, n_elements)
        Global dof of each local dof.
    dx : ndarray (n_elements, n_quad)
        Quadrature weights times the Jacobian.
    offsets : ndarray (n_fields + 1,)
        Where each field's dofs start in the global vector.
    """

    def __init__(self, bases: dict, strains):
        self.bases = dict(bases)
        self.fields = tuple(self.bases)
        self.strains = tuple(strains)
        first = next(iter(self.bases.values()))
        for name, basis in self.bases.items():
            if not isinstance(basis, Basis) or basis.dx.shape != first.dx.shape:
                raise InputError("bases", f"field {name!r} must share the first basis's mesh and quadrature")
        self.offsets = np.cumsum([0] + [b.N for b in self.bases.values()])
        self.N = int(self.offsets[-1])
        self.dx = first.dx
        local, start = [], {}
        for k, (name, basis) in enumerate(self.bases.items()):
            start[name] = sum(len(x) for x in local)
            local.append(basis.element_dofs + self.offsets[k])
        self.dofs = np.concatenate(local)  # (n_local, ne)
        n_local = self.dofs.shape[0]
        ne, nq = self.dx.shape
        self.B = np.zeros((len(self.strains), n_local, ne, nq))
        for a, (name, order) in enumerate(self.strains):
            if name not in self.bases:
                raise InputError("strains", f"unknown field {name!r}")
            basis = self.bases[name]
            for i in range(basis.Nbfun):
                self.B[a, start[name] + i] = _derivative(basis.basis[i][0], order)
        self.Bdx = self.B * self.dx  # weights folded in once
        # the same, laid out for batched matrix products: (e, i, q·a) and (e, q, a, j)
        self._Bt = np.ascontiguousarray(
            self.B.transpose(2, 1, 3, 0).reshape(ne, n_local, nq * len(self.strains))
        )
        self._Bdx_t = np.ascontiguousarray(self.Bdx.transpose(2, 3, 0, 1))
        # the (row, column) of every (element, i, j) entry; the CSR pattern is built from them
        # once, when a sparse matrix is first asked for
        self._rows = np.broadcast_to(self.dofs.T[:, :, None], (ne, n_local, n_local)).ravel()
        self._cols = np.broadcast_to(self.dofs.T[:, None, :], (ne, n_local, n_local)).ravel()

    @cached_property
    def _pattern(self):
        key = self._rows.astype(np.int64) * self.N + self._cols
        unique, entry = np.unique(key, return_inverse=True)
        indices = (unique % self.N).astype(np.int32)
        indptr = np.searchsorted(unique // self.N, np.arange(self.N + 1)).astype(np.int32)
        return entry, indices, indptr

    def interpolate(self, U: np.ndarray) -> np.ndarray:
        """Generalized strains at the quadrature points: (n_strains, ne, nq)."""
        return contract("aieq,ie->aeq", self.B, U[self.dofs])

    def vector(self, S: np.ndarray) -> np.ndarray:
        """``∫ Σ_a S_a B_a dx``: global vector (N,) from section forces S (n_strains, ne, nq)."""
        local = contract("aieq,aeq->ie", self.Bdx, S)
        return np.bincount(self.dofs.ravel(), weights=local.ravel(), minlength=self.N)

    def element_matrices(self, D: np.ndarray) -> np.ndarray:
        """``∫ Bᵀ D B`` per element: (ne, n_local, n_local) from D (n_strains, n_strains, ne, nq)."""
        DB = np.matmul(D.transpose(2, 3, 0, 1), self._Bdx_t)  # (e, q, a, j)
        ne, nq, na, nj = DB.shape
        return np.matmul(self._Bt, DB.reshape(ne, nq * na, nj))

    def matrix(self, D: np.ndarray | None = None, *, element_matrices=None) -> sp.csr_matrix:
        """Global CSR matrix (N, N) from D (or from element matrices already computed)."""
        Ke = self.element_matrices(D) if element_matrices is None else element_matrices
        entry, indices, indptr = self._pattern
        data = np.bincount(entry, weights=Ke.ravel(), minlength=len(indices))
        return sp.csr_matrix((data, indices, indptr), shape=(self.N, self.N))

    def banded(self, free: np.ndarray) -> BandedSystem:
        """A `BandedSystem` for the ``free`` dofs of this pattern (ordered along the axis)."""
        location = np.zeros(self.N)
        for k, basis in enumerate(self.bases.values()):
            location[self.offsets[k] : self.offsets[k + 1]] = basis.doflocs[0]
        return BandedSystem(self.N, free, self._rows, self._cols, location)


@dataclass
class BandedSystem:
    """The free–free block of a pattern in LAPACK band storage, dofs ordered along the axis.

    ``add_elements(Ke)`` and ``add_sparse(K)`` fill the band of a matrix; ``solve(b)``
    factorises and solves with ``dgbsv`` (``b`` over the free dofs, in their given order).
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
        return (self.kl + self.ku + i - j) * self.n + j

    def band(self) -> np.ndarray:
        return np.zeros(self.shape)

    def add_elements(self, ab: np.ndarray, Ke: np.ndarray) -> np.ndarray:
        """Add element matrices (ne, n_local, n_local) of the pattern into band storage ``ab``."""
        ab.ravel()[:] += np.bincount(self._slot, weights=Ke.ravel()[self._keep], minlength=ab.size)
        return ab

    def add_sparse(self, ab: np.ndarray, K) -> np.ndarray:
        """Add the free–free entries of a sparse (N, N) matrix into ``ab``; they must lie in the band."""
        K = sp.coo_matrix(K)
        i, j = self.position[K.row], self.position[K.col]
        keep = (i >= 0) & (j >= 0) & (K.data != 0)
        if np.any(np.abs(i[keep] - j[keep]) > self.kl):
            raise InputError("K", "couples dofs farther apart than one element: not a banded term")
        np.add.at(ab.ravel(), self._flat(i[keep], j[keep]), K.data[keep])
        return ab

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
        """Solve the banded system for a right-hand side over the free dofs (in ``free`` order)."""
        rhs = np.empty(self.n)
        rhs[self._free_rank] = b
        _, _, x, info = lapack.dgbsv(self.kl, self.ku, ab, rhs, overwrite_ab=True, overwrite_b=True)
        if info != 0:
            raise ConvergenceError(f"banded solve: the tangent is singular (LAPACK dgbsv info = {info})", [])
        return x[self._free_rank]
