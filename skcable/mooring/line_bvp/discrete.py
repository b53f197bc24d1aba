r"""The discrete line of the line BVP in the plane and in space: what the two write once.

Both solve the arc-length form on the unstretched arc length ``s ∈ [0, L]`` (J.M. Goicolea,
"Cálculo de cables", UPM, 2012, eq. (3)) in ``dim`` dimensions: positions
``r(s) = (x, y[, z])`` P2 per coordinate, tension ``T(s)`` discontinuous P1, the ends fixed.
`DiscreteLine` holds what does not depend on the section law, the loads or the contact rows:

- the mesh (`skcable.mooring.line_bvp.mesh.line_nodes`), the bases and the assembly of the fields
  ``x, y[, z], T`` over the strains its subclass gives; the free dofs (every position dof but
  the ends', every tension dof) and the rows of the point loads (the vertical one, y in the
  plane, z in space);
- the merit of a residual (the largest force row over the force scale ``load_scale``, N; the
  largest stretch row over the length, m);
- the generalized Jacobian (the element matrices with the contact rows mixed in, and the sparse
  rest: `tangent`), its banded factorisation and solves (`increment`, `solve_many`);
- the ends' sensitivities by the implicit function theorem: at a converged state, the active set
  held, ``J_ff ∂z_f/∂r_B = −J_fB`` (one factorisation, ``dim`` right-hand sides), and the
  supports' rows ``∂R_B/∂r_B = J_Bf ∂z_f/∂r_B + J_BB``, ``∂R_A/∂r_B`` likewise;
- the contact stiffness ``c_i`` of the complementarity function per node: the force scale per
  length times the node's element length over the mean one, so that ``λ_i ~ w h_i`` switches
  at a gap ``~ h_i``.

`skcable.mooring.line_bvp.problem.LineProblem` (the plane, ``dim = 2``) and
`skcable.mooring.line_bvp_3d.problem.LineProblem3D` (space, ``dim = 3``) add their section laws,
loads, contact rows and reactions.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from skfem import Basis, ElementLineP1DG, ElementLineP2, MeshLine

from skcable.bvp.elements import end_dofs
from skcable.fe.assembly import Assembly
from skcable.mooring.line_bvp.mesh import joints_of, line_nodes

__all__ = ["DiscreteLine"]


class DiscreteLine:
    """Mesh, bases, dofs, merit, banded solves and end sensitivities of a line in ``dim``
    dimensions (module docstring); a subclass sets ``load_scale``, ``length_scale``,
    ``contact_rows`` (None without a seabed) and ``assemble``."""

    #: 2 (the plane) or 3 (space)
    dim = 2
    #: the seabed's contact rows (``ContactRows`` in the plane, ``ContactRows3D`` in space), or None
    contact_rows: Any = None
    load_scale = 1.0
    length_scale = 1.0

    def discretise(self, lengths, point_loads, n_elements, fitted, nodes_at, strains) -> np.ndarray:
        """Build the mesh on segments of ``lengths`` (m) with nodes at the ``point_loads``' arc
        lengths and at ``fitted`` (``nodes_at``: a given mesh), the bases, the assembly over
        ``strains`` and the free dofs; the inner position nodes (the dofs of one coordinate)."""
        dim = self.dim
        self.joints = joints_of(lengths)
        self.L = float(self.joints[-1])
        self.mesh = MeshLine(line_nodes(lengths, point_loads, n_elements, fitted, nodes_at))
        self.basis = Basis(self.mesh, ElementLineP2(), intorder=6)
        self.tbasis = self.basis.with_element(ElementLineP1DG())
        N, M = self.basis.N, self.tbasis.N
        self.N, self.M = N, M
        fields = {name: self.basis for name in "xyz"[:dim]}
        self.assembly = Assembly({**fields, "T": self.tbasis}, strains)
        self.end_a, self.end_b, inner = end_dofs(self.basis)
        self.free = np.concatenate([*(k * N + inner for k in range(dim)), dim * N + np.arange(M)])
        self.system = self.assembly.banded(self.free)
        self._force_rows = self.free[self.free < dim * N]
        self._stretch_rows = self.free[self.free >= dim * N]
        s_dof = self.basis.doflocs[0]
        vertical = (dim - 1) * N  # the point loads' rows: y in the plane, z in space
        nearest = [int(np.argmin(np.abs(s_dof - s))) for s, _ in point_loads]
        self.point_rows = np.array([vertical + k for k in nearest], dtype=int)
        self.point_values = np.array([P for _, P in point_loads], dtype=float)
        return inner

    def contact_stiffness(self, nodes) -> tuple[np.ndarray, np.ndarray]:
        """``(c_i, h_i)`` of the position nodes ``nodes``: the complementarity function's constant
        (N/m, module docstring) and the node's element length (m; the longer of two)."""
        element_length = np.diff(self.mesh.p[0, self.mesh.t], axis=0)[0]
        node_length = np.zeros(self.N)
        np.maximum.at(node_length, self.basis.element_dofs.ravel(), np.tile(element_length, 3))
        c = self.load_scale / self.L * node_length[nodes] / (self.L / element_length.size)
        return c, node_length[nodes]

    def merit(self, F) -> float:
        """The largest free row of ``F``: force rows over `load_scale` (N), stretch rows over
        `length_scale` (m)."""
        force = np.abs(F[self._force_rows]) / self.load_scale
        stretch = np.abs(F[self._stretch_rows]) / self.length_scale
        return max(float(np.max(force, initial=0.0)), float(np.max(stretch, initial=0.0)))

    def tangent(self, state):
        """The generalized Jacobian of ``F``: element matrices with the contact rows mixed in,
        and the terms they cannot carry (sparse, or None)."""
        if self.contact_rows is None:
            return state.Ke, None
        assert state.terms is not None, "a state of a line with contact carries its contact terms"
        return self.contact_rows.mixed(state.Ke, state.terms, self.basis.element_dofs, self.assembly.N)

    def jacobian(self, state):
        """The generalized Jacobian as a CSR matrix over all dofs (for inspection and the
        sensitivities; Newton uses the band)."""
        Ke, extra = self.tangent(state)
        J = self.assembly.matrix(Ke)
        return J if extra is None else (J + extra).tocsr()

    def _band(self, state):
        Ke, extra = self.tangent(state)
        system = self.system
        ab = system.add_elements(system.band(), Ke)
        if extra is not None:
            system.add_sparse(ab, extra)
        return ab

    def increment(self, state):
        """Newton increment: the banded solve of the generalized Jacobian."""
        step = np.zeros(self.assembly.N)
        step[self.free] = self.system.solve(self._band(state), -state.F[self.free])
        return step

    def solve_many(self, state, rhs):
        """``J⁻¹ rhs`` over the free dofs for several right-hand sides at once (``rhs`` (n_free,
        k), in ``free`` order): one banded LU factorisation (LAPACK ``dgbsv``) of the generalized
        Jacobian at ``state``."""
        return self.system.solve(self._band(state), rhs)

    def end_dofs(self, end) -> np.ndarray:
        """The ``dim`` position dofs of the anchor (``"a"``) or the fairlead (``"b"``)."""
        k = self.end_a if end == "a" else self.end_b
        return np.array([i * self.N + k for i in range(self.dim)])

    def end_sensitivities(self, state):
        """``(K_B, K_A, dz)`` at a converged ``state`` (module docstring): ``K_B = ∂R_B/∂r_B``
        and ``K_A = ∂R_A/∂r_B`` (N/m, ``dim × dim``; ``R`` the residual without contact rows at
        the supports' dofs: the fairlead and the anchor are no contact nodes) and ``dz = ∂z/∂r_B``
        (every dof, ``dim`` columns)."""
        J = self.jacobian(state)
        ends = self.end_dofs("b")
        dz = np.zeros((self.assembly.N, self.dim))
        dz[ends, np.arange(self.dim)] = 1.0
        dz[self.free] = self.solve_many(state, -(J[self.free][:, ends]).toarray())
        return np.asarray(J[ends] @ dz), np.asarray(J[self.end_dofs("a")] @ dz), dz
