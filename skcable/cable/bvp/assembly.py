r"""Section-law assembly on scikit-fem line bases, for the cable's hot path.

The integrals of `skcable.fe.StrainAssembly` — ``∫ Σ_a S_a B_a dx``
and ``∫ Bᵀ D B dx`` for section forces ``S`` and tangents ``D`` at the
quadrature points — built for a solve that runs a handful of assemblies on
a large mesh:

- **elements last**: quadrature arrays are ``(nq, ne)`` and basis values
  ``(n_strains, nq, n_local, ne)``, so every contraction runs over the
  elements, contiguous in memory: ``einsum`` then vectorises over them, three
  to four times faster than with the elements first (scikit-fem's
  ``(ne, nq)``, whose inner loops are 2–4 quadrature points long);
- **plain** ``einsum``: with contracted dimensions 2–8 long,
  ``optimize=True`` goes through batched ``matmul`` with copies (slower, and
  threaded BLAS on a shared 2-core machine);
- **nothing the Newton loop does not use**: element matrices ``(n_local,
  n_local, ne)`` go into a `BandedSystem`; the CSR
  matrix (for inspection and tests) is built only when asked for; the
  quadrature weights multiply the section forces (one ``(nq, ne)`` product)
  instead of a second copy of the basis values. On this machine every fresh
  megabyte costs page faults: a 10,000-element solve touches about 15 MB.

``tests/cable/test_bvp.py`` and ``test_arc.py`` check it against
scikit-fem's ``asm`` of the forms of `skcable.cable.bvp.forms`.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np
import scipy.sparse as sp

from skcable.errors import InputError
from skcable.fe import BandedSystem

__all__ = ["LineAssembly"]


def _derivative(field, order: int) -> np.ndarray:
    if order == 0:
        return np.asarray(field)
    if order == 1:
        return field.grad[0]
    if order == 2:
        return field.hess[0][0]
    raise InputError("order", f"must be 0, 1 or 2, got {order!r}")


def _locations(basis) -> np.ndarray:
    """Where each dof sits along the line: its node, or for a modal dof (scikit-fem's
    ``doflocs`` is NaN there, e.g. ``ElementLinePp``) the middle of its element."""
    location = np.array(basis.doflocs[0], dtype=float)
    modal = ~np.isfinite(location)
    if modal.any():
        middle = basis.mesh.p[0, basis.mesh.t].mean(axis=0)  # (ne,)
        owner = np.zeros(basis.N, dtype=int)
        owner[basis.element_dofs] = np.arange(basis.element_dofs.shape[1])
        location[modal] = middle[owner[modal]]
    return location


class LineAssembly:
    """``∫ Bᵀ S`` and ``∫ Bᵀ D B`` for fields on line bases sharing one quadrature.

    Parameters
    ----------
    bases : dict of str to skfem.Basis
        The fields, in dof order (the global vector stacks them).
    strains : sequence of (str, int)
        The generalized strains: (field, derivative order 0/1/2).

    Attributes
    ----------
    B : ndarray (n_strains, nq, n_local, ne)
        Basis derivatives per strain and local dof (zero where the local dof
        belongs to another field). The quadrature weights multiply the
        section forces, not ``B``: one array of basis values, not two.
    dofs : ndarray (n_local, ne)
        Global dof of each local dof.
    dx : ndarray (nq, ne)
        Quadrature weights times the Jacobian.
    x : ndarray (nq, ne)
        Quadrature points.
    """

    def __init__(self, bases: dict, strains):
        self.bases = dict(bases)
        self.strains = tuple(strains)
        first = next(iter(self.bases.values()))
        for name, basis in self.bases.items():
            if basis.dx.shape != first.dx.shape:
                raise InputError("bases", f"field {name!r} must share the first basis's mesh and quadrature")
        offsets = np.cumsum([0] + [b.N for b in self.bases.values()])
        self.N = int(offsets[-1])
        self.dx = np.ascontiguousarray(first.dx.T)
        self.x = np.ascontiguousarray(np.asarray(first.global_coordinates())[0].T)
        start, local = {}, []
        for k, (name, basis) in enumerate(self.bases.items()):
            start[name] = sum(len(x) for x in local)
            local.append(basis.element_dofs + offsets[k])
        self.dofs = np.concatenate(local)  # (n_local, ne)
        nq, ne = self.dx.shape
        self.B = np.zeros((len(self.strains), nq, self.dofs.shape[0], ne))
        for a, (name, order) in enumerate(self.strains):
            if name not in self.bases:
                raise InputError("strains", f"unknown field {name!r}")
            basis = self.bases[name]
            for i in range(basis.Nbfun):
                self.B[a, :, start[name] + i] = _derivative(basis.basis[i][0], order).T
        self._flat_dofs = self.dofs.ravel()
        self._location = np.concatenate([_locations(basis) for basis in self.bases.values()])

    def interpolate(self, U: np.ndarray) -> np.ndarray:
        """Generalized strains at the quadrature points: (n_strains, nq, ne)."""
        return np.einsum("aqie,ie->aqe", self.B, U[self.dofs])

    def local(self, a: int, s: np.ndarray) -> np.ndarray:
        """``∫ s B_a dx`` per element and local dof: (n_local, ne), from s (nq, ne)."""
        return np.einsum("qie,qe->ie", self.B[a], s * self.dx)

    def gather(self, local: np.ndarray) -> np.ndarray:
        """Global vector (N,) from local values (n_local, ne)."""
        return np.bincount(self._flat_dofs, weights=local.ravel(), minlength=self.N)

    def vector(self, S: np.ndarray) -> np.ndarray:
        """``∫ Σ_a S_a B_a dx``: global vector (N,) from section forces S (n_strains, nq, ne)."""
        return self.gather(np.einsum("aqie,aqe->ie", self.B, S * self.dx))

    def block(self, a: int, b: int, d=None) -> np.ndarray:
        """``∫ B_a d B_b dx`` per element: (n_local, n_local, ne); ``d`` (nq, ne) or 1."""
        return np.einsum("qie,qje,qe->ije", self.B[a], self.B[b], self.dx if d is None else d * self.dx)

    def element_matrices(self, D: np.ndarray) -> np.ndarray:
        """``∫ Bᵀ D B`` per element: (n_local, n_local, ne) from D (n_strains, n_strains, nq, ne)."""
        return np.einsum("aqie,aqje->ije", self.B, np.einsum("abqe,bqje->aqje", D * self.dx, self.B))

    @cached_property
    def _pattern(self):
        """Global row and column of every entry of the element matrices, in their (i, j, e) order."""
        n_local, ne = self.dofs.shape
        rows = np.broadcast_to(self.dofs[:, None, :], (n_local, n_local, ne)).ravel()
        cols = np.broadcast_to(self.dofs[None, :, :], (n_local, n_local, ne)).ravel()
        return rows, cols

    def matrix(self, element_matrices: np.ndarray) -> sp.csr_matrix:
        """Global CSR matrix (N, N) from element matrices (n_local, n_local, ne)."""
        rows, cols = self._pattern
        return sp.coo_matrix((element_matrices.ravel(), (rows, cols)), shape=(self.N, self.N)).tocsr()

    def banded(self, free: np.ndarray) -> BandedSystem:
        """A `BandedSystem` for the ``free`` dofs, ordered along the axis;
        fill it with ``add_elements(ab, Ke)`` (``Ke`` as `element_matrices` returns)."""
        rows, cols = self._pattern
        return BandedSystem(self.N, free, rows, cols, self._location)

    def row(self, element_matrices: np.ndarray, dof: int) -> np.ndarray:
        """Row ``dof`` of the global matrix (N,), from the element matrices."""
        local, elements = np.nonzero(self.dofs == dof)
        values = element_matrices[local, :, elements]  # (k, n_local)
        return np.bincount(self.dofs[:, elements].T.ravel(), weights=values.ravel(), minlength=self.N)
