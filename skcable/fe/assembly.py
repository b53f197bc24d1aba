r"""One assembly of section laws on scikit-fem line bases, for strands and cables alike.

A model whose physics is a *section law* — section forces :math:`S_a(g)` and their tangent
:math:`D_{ab} = \partial S_a / \partial g_b` at the quadrature points, as functions of
generalized strains :math:`g_a = \partial^{k_a} f_a / \partial x^{k_a}` of its fields — has the
internal force and tangent

.. math:: R_i = \int \sum_a S_a\, B_{ai}\,dx, \qquad
          K_{ij} = \int \sum_{ab} B_{ai}\, D_{ab}\, B_{bj}\,dx,

with :math:`B_{ai}` the derivative of order :math:`k_a` of basis function :math:`i` of field
:math:`f_a`. These are scikit-fem's forms ``LinearForm(lambda v, w: sum(w.S[a] * d_a(v)))`` and
``BilinearForm(lambda u, v, w: sum(w.D[a, b] * d_b(u) * d_a(v)))``; `Assembly` evaluates them
with the basis values scikit-fem computes once (``Basis.basis``), with no form evaluation, COO
sorting or keyword handling per call, and equals scikit-fem's ``asm`` to round-off
(``tests/fe/test_assembly.py``).

**Layout: elements last.** Quadrature arrays are ``(n_quad, n_elements)``, basis values
``(n_strains, n_quad, n_local, n_elements)`` and element matrices ``(n_local, n_local,
n_elements)``: the contractions of `interpolate`, `vector`, `local` and `block` then run over the
elements, contiguous in memory (three to four times faster than with scikit-fem's ``(n_elements,
n_quad)``, whose inner loops are 2–4 points long), in NumPy's plain ``einsum`` loop (with 2–8
long contracted dimensions ``optimize=True`` goes through copies and threaded BLAS). The full
section tangent goes through batched ``matmul`` instead (`element_matrices`): per element and
point ``D B`` and then ``Bᵀ (D B)``, 2.5 to 9 times faster than an ``einsum`` of the same sum.
The global CSR matrix reuses one sparsity pattern computed on first use; the linear systems of a
one-dimensional mesh are banded once the dofs are ordered along the axis
(`skcable.fe.linear.BandedSystem`, from `banded`).

A model with scikit-fem's quadrature layout ``(n_elements, n_quad)`` (the strand's terms) passes
transposed views: `element_matrices` reads ``D`` through a transposed view in any case.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np
import scipy.sparse as sp
from skfem import Basis

from skcable.errors import InputError
from skcable.fe.linear import BandedSystem

__all__ = ["Assembly", "contract", "dof_locations"]


def contract(subscripts: str, *operands) -> np.ndarray:
    """``np.einsum`` in its plain C loop: for the small arrays of a strand or cable (a few
    elements' worth of points and wires), finding a BLAS contraction order and reshaping
    for it costs more than the contraction (measured: 3x slower with ``optimize=True``)."""
    return np.einsum(subscripts, *operands, optimize=False)


def _derivative(field, order: int) -> np.ndarray:
    """Derivative of order 0, 1 or 2 of a scikit-fem DiscreteField on a line: (ne, nq)."""
    if order == 0:
        return np.asarray(field)  # the field itself is its value
    if order == 1:
        return field.grad[0]
    if order == 2:
        return field.hess[0][0]
    raise InputError("order", f"must be 0, 1 or 2, got {order!r}")


def dof_locations(basis: Basis) -> np.ndarray:
    """Where each dof sits along the line: its node, or for a modal dof (scikit-fem's ``doflocs``
    is NaN there, e.g. ``ElementLinePp``) the middle of its element."""
    location = np.array(basis.doflocs[0], dtype=float)
    modal = ~np.isfinite(location)
    if modal.any():
        middle = basis.mesh.p[0, basis.mesh.t].mean(axis=0)  # (ne,)
        owner = np.zeros(basis.N, dtype=int)
        owner[basis.element_dofs] = np.arange(basis.element_dofs.shape[1])
        location[modal] = middle[owner[modal]]
    return location


class Assembly:
    """``∫ Bᵀ S`` and ``∫ Bᵀ D B`` for fields on line bases that share one mesh and quadrature.

    Parameters
    ----------
    bases : dict of str to skfem.Basis
        The fields, in dof order (the global vector stacks them).
    strains : sequence of (str, int)
        The generalized strains: (field, derivative order 0, 1 or 2).

    Attributes
    ----------
    fields : tuple of str
        The field names, in dof order.
    offsets : ndarray (n_fields + 1,)
        Where each field's dofs start in the global vector; ``N`` the total.
    B : ndarray (n_strains, n_quad, n_local, n_elements)
        Basis derivatives per strain and local dof (zero where the local dof belongs to another
        field).
    dofs : ndarray (n_local, n_elements)
        Global dof of each local dof.
    dx : ndarray (n_quad, n_elements)
        Quadrature weights times the Jacobian (m).
    x : ndarray (n_quad, n_elements)
        Quadrature points (m).
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
        self.dx = np.ascontiguousarray(first.dx.T)
        self.x = np.ascontiguousarray(np.asarray(first.global_coordinates())[0].T)
        start: dict[str, int] = {}
        local: list[np.ndarray] = []
        for k, (name, basis) in enumerate(self.bases.items()):
            start[name] = sum(len(d) for d in local)
            local.append(basis.element_dofs + self.offsets[k])
        self.dofs = np.concatenate(local)  # (n_local, ne)
        nq, ne = self.dx.shape
        n_local = self.dofs.shape[0]
        self.B = np.zeros((len(self.strains), nq, n_local, ne))
        for a, (name, order) in enumerate(self.strains):
            if name not in self.bases:
                raise InputError("strains", f"unknown field {name!r}")
            basis = self.bases[name]
            for i in range(basis.Nbfun):
                self.B[a, :, start[name] + i] = _derivative(basis.basis[i][0], order).T
        self._flat_dofs = self.dofs.ravel()
        self._location = np.concatenate([dof_locations(basis) for basis in self.bases.values()])

    # --- vectors ---------------------------------------------------------------------------
    def interpolate(self, U: np.ndarray) -> np.ndarray:
        """Generalized strains at the quadrature points: (n_strains, n_quad, n_elements)."""
        return np.einsum("aqie,ie->aqe", self.B, U[self.dofs])

    @cached_property
    def _interpolation(self) -> sp.csr_matrix:
        """`interpolate` as one sparse operator from the dofs to the points, rows in scikit-fem's
        order (strain, element, point), each row's entries in local-dof order (the sums of
        `interpolate`, term by term, without its zero terms)."""
        na, nq, _, ne = self.B.shape
        a, q, i, e = np.nonzero(self.B)
        rows = (a * ne + e) * nq + q
        return sp.csr_matrix((self.B[a, q, i, e], (rows, self.dofs[i, e])), shape=(na * ne * nq, self.N))

    def interpolate_by_element(self, U: np.ndarray) -> np.ndarray:
        """`interpolate` in scikit-fem's layout, (n_strains, n_elements, n_quad) contiguous, by one
        sparse product (no gather or transpose per call)."""
        na, nq, _, ne = self.B.shape
        return (self._interpolation @ np.asarray(U, dtype=float)).reshape(na, ne, nq)

    def local(self, a: int, s: np.ndarray) -> np.ndarray:
        """``∫ s B_a dx`` per element and local dof: (n_local, n_elements), from s (n_quad, n_elements)."""
        return np.einsum("qie,qe->ie", self.B[a], s * self.dx)

    def gather(self, local: np.ndarray) -> np.ndarray:
        """Global vector (N,) from local values (n_local, n_elements)."""
        return np.bincount(self._flat_dofs, weights=local.ravel(), minlength=self.N)

    def vector(self, S: np.ndarray) -> np.ndarray:
        """``∫ Σ_a S_a B_a dx``: global vector (N,) from section forces S (n_strains, n_quad, n_elements)."""
        return self.gather(np.einsum("aqie,aqe->ie", self.B, S * self.dx))

    def magnitude(self, S: np.ndarray) -> np.ndarray:
        """``∫ Σ_a |S_a| |B_a| dx`` (N,): the size of the terms whose sum `vector` forms, per dof
        (a residual's round-off is ``eps`` times it)."""
        return self.gather(np.einsum("aqie,aqe->ie", self._abs_B, np.abs(S) * self.dx))

    def vector_and_magnitude(self, S: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """`vector` and `magnitude` of ``S`` in one sparse product and one gather (a Newton
        iteration needs both: the residual and its force scale); equal to the two calls to the
        last bit. ``S`` (n_strains, n_quad, n_elements) may be a transposed view of scikit-fem's
        layout (n_strains, n_elements, n_quad): it is then read where it lies."""
        na, nq, _, ne = self.B.shape
        by_element = S.transpose(0, 2, 1).flags.c_contiguous
        weighted = np.empty((2, na, ne, nq) if by_element else (2, na, nq, ne))
        if by_element:
            np.multiply(S.transpose(0, 2, 1), self._dx_by_element, out=weighted[0])
        else:
            np.multiply(S, self.dx, out=weighted[0])
        np.abs(weighted[0], out=weighted[1])  # |S| dx: dx > 0
        local = self._local_sums(by_element) @ weighted.ravel()
        both = np.bincount(self._flat_dofs_twice, weights=local, minlength=2 * self.N)
        return both[: self.N], both[self.N :]

    def _local_sums(self, by_element: bool) -> sp.csr_matrix:
        """``∫ Σ_a S_a B_a dx`` and ``∫ Σ_a |S_a| |B_a| dx`` per element and local dof, row (k, i, e),
        as a sparse operator on ``(S dx, |S| dx)`` laid out (k, a, e, q) (``by_element``) or
        (k, a, q, e): each row's entries in (strain, point) order, the order of the contraction
        ``einsum("kaqie,kaqe->kie")`` over the stacked ``(B, |B|)``, without its zero terms
        (the same sums, to the last bit)."""
        cache = self.__dict__.setdefault("_local_sum_ops", {})
        if by_element not in cache:
            na, nq, nl, ne = self.B.shape
            k, a, q, i, e = np.nonzero(np.stack([self.B, self.B]))
            rows = (k * nl + i) * ne + e
            order = np.lexsort((q, a, rows))  # by row, then strain, then point
            k, a, q, i, e, rows = (v[order] for v in (k, a, q, i, e, rows))
            values = self.B[a, q, i, e]
            values = np.where(k == 1, np.abs(values), values)
            cols = ((k * na + a) * ne + e) * nq + q if by_element else ((k * na + a) * nq + q) * ne + e
            indptr = np.concatenate([[0], np.cumsum(np.bincount(rows, minlength=2 * nl * ne))])
            cache[by_element] = sp.csr_matrix(
                (values, cols.astype(np.int32), indptr.astype(np.int32)),
                shape=(2 * nl * ne, 2 * na * nq * ne),
            )
        return cache[by_element]

    @cached_property
    def _abs_B(self) -> np.ndarray:
        return np.abs(self.B)

    @cached_property
    def _flat_dofs_twice(self) -> np.ndarray:
        return np.concatenate([self._flat_dofs, self._flat_dofs + self.N])

    # --- element matrices --------------------------------------------------------------------
    def block(self, a: int, b: int, d=None) -> np.ndarray:
        """``∫ B_a d B_b dx`` per element: (n_local, n_local, n_elements); ``d`` (n_quad, n_elements) or 1."""
        return np.einsum("qie,qje,qe->ije", self.B[a], self.B[b], self.dx if d is None else d * self.dx)

    @cached_property
    def _B_batched(self) -> np.ndarray:
        """The basis values laid out for batched products: (n_elements, n_quad, n_strains, n_local)."""
        return np.ascontiguousarray(self.B.transpose(3, 1, 0, 2))

    @cached_property
    def _B_batched_T(self) -> np.ndarray:
        """``Bᵀ`` per element, contiguous for the batched product: (n_elements, n_local, n_quad·n_strains)."""
        ne, nq, na, nl = self._B_batched.shape
        return np.ascontiguousarray(self._B_batched.reshape(ne, nq * na, nl).transpose(0, 2, 1))

    @cached_property
    def _dx_by_element(self) -> np.ndarray:
        """``dx`` in scikit-fem's layout (n_elements, n_quad), contiguous."""
        return np.ascontiguousarray(self.dx.T)

    def element_matrices(self, D: np.ndarray) -> np.ndarray:
        """``∫ Bᵀ D B`` per element: (n_local, n_local, n_elements) from D (n_strains, n_strains,
        n_quad, n_elements) (any memory layout: it is read through a transposed view; D dx is
        formed in D's own memory order, the same products)."""
        Bb = self._B_batched
        ne, nq, na, nl = Bb.shape
        if D.strides[3] > D.strides[2]:  # scikit-fem's (.., n_elements, n_quad) in memory (a strand's)
            weighted = (D.transpose(0, 1, 3, 2) * self._dx_by_element).transpose(0, 1, 3, 2)
        else:
            weighted = D * self.dx
        DB = np.matmul(weighted.transpose(3, 2, 0, 1), Bb)  # (e, q, a, j)
        Ke = np.matmul(self._B_batched_T, DB.reshape(ne, nq * na, nl))
        return Ke.transpose(1, 2, 0)

    # --- global matrices -----------------------------------------------------------------------
    @cached_property
    def pattern(self) -> tuple[np.ndarray, np.ndarray]:
        """Global (row, column) of every entry of the element matrices, in their (i, j, e) order."""
        n_local, ne = self.dofs.shape
        rows = np.broadcast_to(self.dofs[:, None, :], (n_local, n_local, ne)).ravel()
        cols = np.broadcast_to(self.dofs[None, :, :], (n_local, n_local, ne)).ravel()
        return rows, cols

    @cached_property
    def _csr(self):
        rows, cols = self.pattern
        key = rows.astype(np.int64) * self.N + cols
        unique, entry = np.unique(key, return_inverse=True)
        indices = (unique % self.N).astype(np.int32)
        indptr = np.searchsorted(unique // self.N, np.arange(self.N + 1)).astype(np.int32)
        return entry, indices, indptr

    def matrix(self, element_matrices=None, *, D=None) -> sp.csr_matrix:
        """Global CSR matrix (N, N) from element matrices (n_local, n_local, n_elements), or from D."""
        Ke = self.element_matrices(D) if element_matrices is None else element_matrices
        entry, indices, indptr = self._csr
        data = np.bincount(entry, weights=np.asarray(Ke).ravel(), minlength=len(indices))
        return sp.csr_matrix((data, indices, indptr), shape=(self.N, self.N))

    def row(self, element_matrices: np.ndarray, dof: int) -> np.ndarray:
        """Row ``dof`` of the global matrix (N,), from the element matrices."""
        local, elements = np.nonzero(self.dofs == dof)
        values = element_matrices[local, :, elements]  # (k, n_local)
        return np.bincount(self.dofs[:, elements].T.ravel(), weights=values.ravel(), minlength=self.N)

    def banded(self, free: np.ndarray) -> BandedSystem:
        """A `BandedSystem` for the ``free`` dofs of this pattern, ordered along the axis; fill it
        with ``add_elements(ab, Ke)`` (``Ke`` as `element_matrices` returns)."""
        rows, cols = self.pattern
        return BandedSystem(self.N, free, rows, cols, self._location)
