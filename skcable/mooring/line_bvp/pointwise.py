r"""The fields of a discrete line in space at any arc length, through each element's own basis.

scikit-fem's ``Basis.probes`` (and `skcable.fe.probes.gradient_probes`) builds a sparse matrix
per call through its generic mapping and basis machinery: a few hundred microseconds, which the
touchdown's root search (`skcable.mooring.line_bvp.fitting`) pays at every evaluation.
`LinePoints` does the same evaluation directly, vectorised over the points, with the same
arithmetic: the element holding ``s`` found as scikit-fem's ``MeshLine.element_finder`` finds
it (the element to the right of a node, the last at the line's end), the reference coordinate
``ξ = (s − s₀)/h`` as scikit-fem's affine mapping forms it (``(s − s₀)·(1/h)``), and the
quadratic Lagrange basis of ``ElementLineP2`` (vertices at ξ = 0, 1, the middle at ½),

.. math:: \varphi_0 = 1 - 3\xi + 2\xi^2,\quad \varphi_1 = -\xi + 2\xi^2,\quad
          \varphi_2 = 4\xi - 4\xi^2,

with ``dφ/ds = φ'(ξ)/h``, and the linear ``1 − ξ, ξ`` of ``ElementLineP1DG`` for the tension;
the products summed in the order scikit-fem's sparse products sum them (values in the basis'
order, derivatives in the dofs' order), so the numbers are scikit-fem's to the bit.
"""

from __future__ import annotations

import numpy as np

__all__ = ["LinePoints"]


class LinePoints:
    """Point evaluation of the P2 positions and the P1-DG tension of one line mesh.

    Parameters
    ----------
    mesh : skfem.MeshLine
    basis, tbasis : skfem.Basis
        The ``ElementLineP2`` and ``ElementLineP1DG`` bases on ``mesh``.
    """

    def __init__(self, mesh, basis, tbasis):
        p, t = mesh.p[0], mesh.t
        self.order = np.argsort(p)
        self.sorted = p[self.order]
        last = t[np.argmax(p[t], axis=0), np.arange(t.shape[1])]  # each element's right vertex
        self.element_of = np.full(p.size, -1)
        self.element_of[last] = np.arange(t.shape[1])
        self.left = p[t[0]]
        self.inverse = 1.0 / (p[t[1]] - p[t[0]])
        self.dofs, self.tdofs = basis.element_dofs, tbasis.element_dofs

    def cells(self, s) -> np.ndarray:
        """The element of each arc length ``s`` (1-D, m), as scikit-fem's element finder picks it.

        Raises
        ------
        ValueError
            A point outside the mesh.
        """
        inside = s.copy()
        inside[s == self.sorted[-1]] = self.sorted[-2:].mean()
        k = np.digitize(inside, self.sorted)
        if np.any(k >= self.sorted.size):
            raise ValueError("Point is outside of the mesh.")
        cells = self.element_of[self.order[k]]
        if np.any(cells < 0):
            raise ValueError("Point is outside of the mesh.")
        return cells

    def fields(self, fields, s):
        """``(values, derivatives)`` (k, n) of the P2 ``fields`` (k, N) at the arc lengths ``s``
        (1-D, m), and the element of each point."""
        cells = self.cells(s)
        inv = self.inverse[cells]
        xi = inv * (s - self.left[cells])
        phi = np.array([1 - 3 * xi + 2 * xi**2, -xi + 2 * xi**2, 4 * xi - 4 * xi**2])
        dphi = np.array([inv * (-3 + 4 * xi), inv * (-1 + 4 * xi), inv * (4 - 8 * xi)])
        dofs = self.dofs[:, cells]
        u = fields[:, dofs]  # (k, 3, n)
        values = phi[0] * u[:, 0] + phi[1] * u[:, 1] + phi[2] * u[:, 2]
        rank = np.argsort(dofs, axis=0)  # a sparse row sums in the order of its columns
        terms = np.take_along_axis(dphi, rank, axis=0) * np.take_along_axis(u, rank[None], axis=1)
        return values, terms[:, 0] + terms[:, 1] + terms[:, 2], cells

    def tension(self, T, s, cells=None) -> np.ndarray:
        """The P1-DG field ``T`` (M,) at the arc lengths ``s`` (1-D, m)."""
        cells = self.cells(s) if cells is None else cells
        xi = self.inverse[cells] * (s - self.left[cells])
        dofs = self.tdofs[:, cells]
        return (1 - xi) * T[dofs[0]] + xi * T[dofs[1]]
