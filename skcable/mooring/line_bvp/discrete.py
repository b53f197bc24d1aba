r"""The discrete line of the line BVP in the plane and in space: one line law, two contact models.

Both solve the arc-length form on the unstretched arc length ``s ∈ [0, L]`` (J.M. Goicolea,
"Cálculo de cables", UPM, 2012, eq. (3)) in ``dim`` dimensions: positions
``r(s) = (x, y[, z])`` P2 per coordinate (the last one up), tension ``T(s)`` discontinuous P1,
``a = dr/ds``, ``n = |a|``, ``e = a/n``, the ends fixed. With the weight ``w(s)`` per unstretched
length (N/m, downward; a buoyant segment has ``w < 0``), the force ``f(r, s, a, T)`` of the cable
terms per unstretched length (`skcable.mooring.line_bvp.loads`), the point loads ``P_k``
(downward) at nodes ``s_k`` and each segment's axial law ``ε(T)`` (`skcable.mooring.axial`; a
constant ``EA``: ``T/EA``):

.. math::
    R_{\mathbf r} = \int_0^L \big(T\,\mathbf e\cdot\delta\mathbf r'
        + (w\,\mathbf e_v - \mathbf f)\cdot\delta\mathbf r\big)\,ds
        + \sum_k P_k\,\delta r_v(s_k) - \text{(contact)} = 0,
    \qquad R_T = \int_0^L \big(n - 1 - \varepsilon(T)\big)\,\delta T\,ds = 0,

``v`` the vertical coordinate. The section law over the strains ``(a, r, T)`` is
``S = (T e, w e_v − f, n − 1 − ε)``; its tension part and tangent are
`skcable.bvp.section.tension_section`'s, the loads' ``−(f_r, f_a, f_T)``, the stretch's
``−ε'(T)``: unsymmetric where a term depends on the line's direction. `DiscreteLine` holds all
of it and what does not depend on the contact rows:

- the mesh (`skcable.mooring.line_bvp.mesh.line_nodes`), the bases and the assembly of the fields
  ``x, y[, z], T`` over the strains its subclass gives; the free dofs (every position dof but
  the ends', every tension dof) and the rows of the point loads (the vertical one, y in the
  plane, z in space);
- the merit of a residual (the largest force row over the force scale ``load_scale``, N; the
  largest stretch row over the length, m);
- the generalized Jacobian (the element matrices with the contact rows mixed in, and the sparse
  rest: `tangent`), its banded factorisation and solves (`increment`, `solve_many`);
- the ends' sensitivities by the implicit function theorem: at a converged state, the active set
  held, ``J_ff ∂z_f/∂r_B = −J_fB − J_fH ∂z_H/∂r_B`` (one factorisation, ``dim`` right-hand
  sides; ``H`` the dofs held besides the ends, a laid slack stretch's, `hold`), and the
  supports' rows ``∂R_B/∂r_B = J_Bf ∂z_f/∂r_B + J_BB``, ``∂R_A/∂r_B`` likewise;
- the contact stiffness ``c_i`` of the complementarity function per node: the force scale per
  length times the node's element length over the mean one, so that ``λ_i ~ w h_i`` switches
  at a gap ``~ h_i``.

`skcable.mooring.line_bvp.problem.LineProblem` (the plane, ``dim = 2``) and
`skcable.mooring.line_bvp.space.problem.LineProblem3D` (space, ``dim = 3``) set the properties
(``w_q``, the axial laws, the terms) and add their contact rows and reactions. Every call of the
line law's assembly is in this module.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np
from skfem import Basis, ElementLineP1DG, ElementLineP2, MeshLine

from skcable.bvp.elements import end_dofs
from skcable.bvp.section import strains_of, tension_section
from skcable.bvp.terms import CableState
from skcable.errors import InputError
from skcable.fe.assembly import Assembly
from skcable.mooring.line_bvp.loads import TermLoad, term_load
from skcable.mooring.line_bvp.mesh import joints_of, line_nodes
from skcable.mooring.line_bvp.pointwise import LinePoints

__all__ = ["REJECTED", "DiscreteLine", "LineState"]

EPS = float(np.finfo(float).eps)


@dataclass
class LineState:
    """The residual ``F`` (contact rows in), ``R⁰`` (without), the element tangents ``Ke``, the
    contact terms (None without contact), the merit and the iterate ``z`` itself (``F`` None:
    rejected)."""

    F: np.ndarray | None
    R0: np.ndarray | None
    Ke: np.ndarray | None
    terms: Any
    merit: float
    z: np.ndarray | None = None


#: the state of an iterate the line law refuses (a folded line: ``|a| = 0`` somewhere)
REJECTED = LineState(None, None, None, None, np.inf)


def _weights(w, s) -> np.ndarray:
    """A segment's weight per unstretched length ``w`` (N/m: a number, or a callable of the arc
    length) at the arc lengths ``s``; a callable's values checked (shape, finite)."""
    if not callable(w):
        return np.full(np.shape(s), w, dtype=float)
    values = np.asarray(w(s), dtype=float)
    try:
        values = np.broadcast_to(values, np.shape(s))
    except ValueError as exc:
        raise InputError("w", f"the callable returned shape {values.shape}") from exc
    if not np.all(np.isfinite(values)):
        raise InputError("w", "the callable returned non-finite values")
    return values


class DiscreteLine:
    """Mesh, bases, dofs, properties, the line law, merit, banded solves and end sensitivities of
    a line in ``dim`` dimensions (module docstring); a subclass sets ``segments``, ``terms``,
    ``load_scale``, ``length_scale`` and ``contact_rows`` (None without a seabed)."""

    #: 2 (the plane) or 3 (space)
    dim = 2
    #: the seabed's contact rows (`skcable.mooring.line_bvp.contact.ContactRows`), or None
    contact_rows: Any = None
    #: the seabed (its ``height`` of the horizontal coordinates, m), or None
    seabed: Any = None
    #: whether the anchor lies on the seabed (to 1e-12 of the length): each problem sets it
    anchor_on_seabed: bool = False
    load_scale = 1.0
    length_scale = 1.0
    #: the cable terms besides the weight (`skcable.bvp.terms.CableTerm`)
    terms: tuple | list = ()
    #: the compliance ``1/EA`` at the quadrature points (m/N, (nq, ne)) where every segment's axial
    #: law is a constant EA (0: inextensible), else None and ``laws`` per segment over ``columns``
    compliance_q: np.ndarray | None = None
    #: the segments, from the anchor (each with ``length``, ``w`` and ``law``)
    segments: list
    #: the ends (dim,) (m): the anchor and the fairlead
    anchor: np.ndarray
    fairlead: np.ndarray
    laws: list = []
    columns: list = []
    #: the dofs held at given values besides the ends (`hold`), and those values
    held_dofs: np.ndarray = np.zeros(0, dtype=int)
    held_values: np.ndarray = np.zeros(0)
    held_sensitivity: np.ndarray | None = None

    def discretise(self, lengths, point_loads, n_elements, fitted, nodes_at) -> np.ndarray:
        """Build the mesh on segments of ``lengths`` (m) with nodes at the ``point_loads``' arc
        lengths and at ``fitted`` (``nodes_at``: a given mesh), the bases, the assembly over the
        strains ``(a, r, T)`` and the free dofs; the inner position nodes (the dofs of one
        coordinate)."""
        dim = self.dim
        strains = strains_of(dim)
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

    def properties(self) -> None:
        """Per element its segment (by its midpoint: `middle`, `owner`, and each segment's
        elements `columns`); the weight per unstretched length at the quadrature points `w_q`
        (N/m: each segment's number, or its callable of ``s`` checked); the axial laws `laws`
        (one compliance array `compliance_q` where every law is a constant EA); the line's weight
        `weight` (N)."""
        s_q, dx = self.assembly.x, self.assembly.dx
        self.middle = self.mesh.p[0, self.mesh.t].mean(axis=0)
        self.owner = np.clip(np.searchsorted(self.joints, self.middle) - 1, 0, len(self.segments) - 1)
        self.columns = [np.flatnonzero(self.owner == k) for k in range(len(self.segments))]
        self.w_q = np.empty_like(s_q)
        for seg, cols in zip(self.segments, self.columns, strict=True):
            self.w_q[:, cols] = _weights(seg.w, s_q[:, cols])
        self.laws = [seg.law for seg in self.segments]
        self.compliance_q = None
        if all(law is None or law.kind == "constant" for law in self.laws):
            c = np.array([0.0 if law is None else 1.0 / law.EA for law in self.laws])
            self.compliance_q = np.broadcast_to(c[self.owner], dx.shape).copy()
        self.weight = float(np.sum(self.w_q * dx))

    def weight_at(self, s) -> np.ndarray:
        """The weight per unstretched length (N/m, downward) at arc lengths ``s`` (m): its
        segment's (the upper one at a joint but the last), or the callable of s."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        owner = np.clip(np.searchsorted(self.joints, s, side="right") - 1, 0, len(self.segments) - 1)
        out = np.empty_like(s)
        for k, seg in enumerate(self.segments):
            cols = owner == k
            out[cols] = _weights(seg.w, s[cols])
        return out

    def tension_points(self) -> np.ndarray:
        """The arc lengths (m) of the tension dofs, each moved a hair (1e-9 of the way to its
        element's middle) into its own element: where a clump at a joint makes the tension jump,
        a closed form evaluated there gives each element's side."""
        dofs, s_t = self.tbasis.element_dofs, self.tbasis.doflocs[0]
        inside = np.empty_like(s_t)
        inside[dofs] = s_t[dofs] + 1e-9 * (self.middle[None, :] - s_t[dofs])
        return np.clip(inside, 0.0, self.L)

    # --- the fields at any arc length ------------------------------------------------------
    @cached_property
    def points(self) -> LinePoints:
        """The point evaluation of the fields (`skcable.mooring.line_bvp.pointwise`)."""
        return LinePoints(self.mesh, self.basis, self.tbasis)

    def state_at(self, z, s) -> CableState:
        """The line's state (`skcable.bvp.terms.CableState`, in ``dim`` dimensions) of the dofs
        ``z`` at arc lengths ``s`` (1-D, m)."""
        s = np.asarray(s, dtype=float).ravel()
        N, d = self.N, self.dim
        r, a, cells = self.points.fields(z[: d * N].reshape(d, N), s)
        return CableState.at(r, s, a, self.points.tension(z[d * N :], s, cells))

    def gaps(self, z) -> np.ndarray:
        """Height (m) above the seabed of every contact node of the dofs ``z`` (none without
        contact rows)."""
        if self.contact_rows is None:
            return np.zeros(0)
        return self.heights(z[self.contact_rows.at])

    def heights(self, r) -> np.ndarray:
        """Height (m) above the seabed of the points ``r`` (dim, n) (m, the last row up)."""
        return r[-1] - self.seabed.height(*r[:-1])

    def tension_at(self, z, s) -> np.ndarray:
        """The tension (N) of the dofs ``z`` at arc lengths ``s`` (1-D, m): the value of the
        element holding each."""
        return self.points.tension(z[self.dim * self.N :], np.asarray(s, dtype=float).ravel())

    def forces_at(self, z, s) -> np.ndarray:
        """The distributed force (dim, n) (N per unstretched m, the last row up) of the dofs
        ``z`` at arc lengths ``s`` (m): the weight and the cable terms' force (point loads and the
        seabed's forces not included)."""
        state = self.state_at(z, s)
        f = np.zeros((self.dim, state.T.size))
        f[-1] = -self.weight_at(state.s)
        if self.terms:
            f = f + term_load(self.terms, state.position, state.s, state.a, state.T).f
        return f

    def along_line(self, inner) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(nodes, prev, next)``: the position nodes ``inner`` (dofs of one coordinate) sorted
        along the line, and each one's neighbours along it (the chord of the contact rows'
        sliding direction)."""
        s = self.basis.doflocs[0]
        order = np.argsort(s, kind="stable")
        rank = np.empty_like(order)
        rank[order] = np.arange(order.size)
        nodes = inner[np.argsort(s[inner], kind="stable")]
        return nodes, order[rank[nodes] - 1], order[rank[nodes] + 1]

    def contact_stiffness(self, nodes) -> tuple[np.ndarray, np.ndarray]:
        """``(c_i, h_i)`` of the position nodes ``nodes``: the complementarity function's constant
        (N/m, module docstring) and the node's element length (m; the longer of two)."""
        element_length = np.diff(self.mesh.p[0, self.mesh.t], axis=0)[0]
        node_length = np.zeros(self.N)
        np.maximum.at(node_length, self.basis.element_dofs.ravel(), np.tile(element_length, 3))
        c = self.load_scale / self.L * node_length[nodes] / (self.L / element_length.size)
        return c, node_length[nodes]

    def with_tension_switch(self, z):
        """A copy of the problem whose contact nodes switch to active at ``λ > max(c_i, T/h_i) g``,
        ``T`` the largest tension of the iterate ``z`` and ``h_i`` the node's element length: the
        force that bends a line of tension T down by the gap g over an element; None without
        contact.

        The switch ``c_i`` (the load per length) is the one for lines whose weight bends them:
        on a taut line (``T/h`` 1e7 times it) a start's residual force of 1e-8 of T at the first
        node past the anchor, 7 cm above the seabed, made it active, and the row ``c g = 0``
        pulled it down onto the seabed in one step (the merit went from 3e-3 to 8e3)."""
        if self.contact_rows is None:
            return None
        tension = float(np.max(np.abs(z[self.dim * self.N :])))
        stiffness, node_length = self.contact_stiffness(self.contact_rows.nodes)
        other = copy.copy(self)
        switch = np.maximum(stiffness, tension / node_length)
        other.contact_rows = replace(self.contact_rows, switch=switch)
        return other

    def with_active_set(self, active):
        """A copy of the problem whose contact nodes keep the active set ``active`` (bool per
        contact node: ``c g = 0`` where True, ``λ = 0`` where False): a smooth system, whose
        Newton converges quadratically where the semismooth one cycles between two active sets
        at a node that is on the seabed with no push (``λ = g = 0``)."""
        assert self.contact_rows is not None, "a line without a seabed has no active set"
        other = copy.copy(self)
        other.contact_rows = replace(self.contact_rows, frozen=np.array(active, dtype=bool))
        return other

    def in_compression(self, z, tol) -> np.ndarray:
        """Per tension dof of ``z`` (`tension_points`), whether it is below ``-1e3 tol`` of
        `load_scale` (N), ``tol`` Newton's tolerance on the scaled residual."""
        return z[self.dim * self.N :] < -1e3 * tol * self.load_scale

    def compressed(self, z, tol) -> bool:
        """Whether the discrete line of the dofs ``z`` is in compression anywhere
        (`in_compression`): its bends not resolved, or a spurious branch."""
        return bool(np.any(self.in_compression(z, tol)))

    def sliding_to_anchor(self, z, tol) -> float | None:
        """Where the discrete line's compression (`in_compression`) lies on the seabed from the
        anchor (every tension point in compression within 1e-6 of the length of the seabed, the
        first one among them, the anchor on the seabed): the slope ``tan α`` of the
        line at the anchor; else None.

        Such a line has no equilibrium in tension: along the seabed ``dT/ds = w (sin α −
        μ cos α)`` on the part that slides, so a stretch on a seabed rising from the anchor more
        steeply than friction holds (``tan α > μ``) pushes on the anchor with its weight; the
        solve finds the compression that equilibrium asks for, not a mesh's error."""
        if self.seabed is None:
            return None
        s = self.tension_points()
        below = self.in_compression(z, tol)
        if not below[0]:
            return None
        state = self.state_at(z, np.concatenate([[0.0], s[below]]))
        if not np.all(np.abs(self.heights(state.position)) <= 1e-6 * self.L):
            return None
        a, d = state.a[:, 0], self.dim - 1
        across = float(np.linalg.norm(a[:d]))
        return float(a[d] / across) if across > 0 else None  # vertical at the anchor: off the seabed

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

    def with_ends(self, positions, T) -> np.ndarray:
        """The dofs ``[x, y(, z), T]`` of the nodal ``positions`` (dim rows, m; changed in place)
        and the tensions ``T`` (N), the ends put exactly at the anchor and the fairlead
        (``anchor``, ``fairlead``: (dim,), m, set by the subclass), the held dofs at their values
        (`hold`)."""
        for k, end in ((self.end_a, self.anchor), (self.end_b, self.fairlead)):
            for row, value in zip(positions, end, strict=True):
                row[k] = value
        return self.placed(np.concatenate([*positions, T]))

    def hold(self, dofs, values, sensitivity=None) -> None:
        """Hold the dofs ``dofs`` at ``values`` besides the ends (a slack stretch laid on the
        seabed, `skcable.mooring.line_bvp.space.problem`): they leave the free dofs, so the
        solve and its merit leave them too, and their rows are the reactions of what holds them;
        `placed` puts them into an iterate. ``sensitivity`` (len(dofs), dim): how the values
        move with the fairlead, ``∂values/∂r_B`` (`end_sensitivities`; None: they stay)."""
        self.held_dofs, self.held_values = np.asarray(dofs, dtype=int), np.asarray(values, dtype=float)
        self.held_sensitivity = None if sensitivity is None else np.asarray(sensitivity, dtype=float)
        self.free = self.free[~np.isin(self.free, self.held_dofs)]
        self.system = self.assembly.banded(self.free)
        self._force_rows = self.free[self.free < self.dim * self.N]
        self._stretch_rows = self.free[self.free >= self.dim * self.N]

    def placed(self, z) -> np.ndarray:
        """The iterate ``z`` with the held dofs at their values (`hold`; ``z`` itself where none
        are held)."""
        if not self.held_dofs.size:
            return z
        z = np.array(z, dtype=float)
        z[self.held_dofs] = self.held_values
        return z

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
        rhs = -(J[self.free][:, ends]).toarray()
        if self.held_sensitivity is not None:  # held dofs that move with the fairlead (`hold`)
            dz[self.held_dofs] = self.held_sensitivity
            rhs -= J[self.free][:, self.held_dofs] @ self.held_sensitivity
        dz[self.free] = self.solve_many(state, rhs)
        return np.asarray(J[ends] @ dz), np.asarray(J[self.end_dofs("a")] @ dz), dz

    # --- the line law: section forces, loads, residual and tangent -------------------------------
    def strains(self, T, dynamic=False):
        """``ε(T)`` and ``dε/dT`` at the quadrature points (``dynamic``: the laws' dynamic
        compliance, for a stiffness about this state)."""
        if self.compliance_q is not None and not dynamic:
            return T * self.compliance_q, self.compliance_q
        eps, k = np.zeros_like(T), np.zeros_like(T)
        for law, cols in zip(self.laws, self.columns, strict=True):
            if law is not None and cols.size:
                eps[:, cols] = law.strain(T[:, cols])
                k[:, cols] = law.dynamic_compliance(T[:, cols]) if dynamic else law.compliance(T[:, cols])
        return eps, k

    def term_load(self, g, terms=None) -> TermLoad:
        """The cable terms' (``terms``, default all) force and derivatives at the quadrature
        points, from the strains ``g`` (``(a, r, T)``); ``s`` the unstretched arc length from A."""
        terms = self.terms if terms is None else terms
        d = self.dim
        return term_load(terms, g[d : 2 * d], self.assembly.x, g[:d], g[2 * d])

    def distributed_load(self, g) -> tuple[np.ndarray, TermLoad | None]:
        """``(p, forces)``: the load ``p = w e_v − f`` (dim, nq, ne) (N per unstretched m, the
        section law's position rows) at the quadrature points from the strains ``g``, and the
        terms' `TermLoad` (None without terms)."""
        forces = self.term_load(g) if self.terms else None
        p = np.zeros((self.dim, *g.shape[1:])) if forces is None else -forces.f
        p[-1] = self.w_q if forces is None else self.w_q - forces.f[-1]
        return p, forces

    def add_term_tangent(self, D, forces: TermLoad) -> None:
        """Add the derivatives of ``p = w e_v − f`` to the section tangent ``D`` (in place): rows
        ``r`` by the strains ``r`` (``−∂f/∂r``), ``a`` (``−∂f/∂a``) and ``T`` (``−∂f/∂T``)."""
        d = self.dim
        r = slice(d, 2 * d)
        if forces.df_dr is not None:
            D[r, r] -= forces.df_dr
        if forces.df_da is not None:
            D[r, :d] -= forces.df_da
        if forces.df_dT is not None:
            D[r, 2 * d] -= forces.df_dT

    def section(self, z, dynamic=False):
        """``(S, D)``: the section forces (2 dim + 1, nq, ne) and their tangent at ``z`` (module
        docstring), or None where the line folds (``|a| = 0`` somewhere)."""
        g = self.assembly.interpolate(z)
        d = self.dim
        T = g[2 * d]
        out = tension_section(g[:d], T)
        if out is None:
            return None
        n, e, D = out
        eps, k = self.strains(T, dynamic)
        p, forces = self.distributed_load(g)
        S = np.concatenate([T * e, p, (n - 1.0 - eps)[None]])
        D[2 * d, 2 * d] = -k
        if forces is not None:
            self.add_term_tangent(D, forces)
        return S, D

    def internal(self, z, dynamic=False):
        """``R⁰`` (no contact) and the element tangents, or None for a folded line."""
        out = self.section(z, dynamic)
        if out is None:
            return None
        S, D = out
        R = self.assembly.vector(S)
        np.add.at(R, self.point_rows, self.point_values)
        return R, self.assembly.element_matrices(D)

    def assemble(self, z, dynamic=False) -> LineState:
        """The state at the iterate ``z``: the residual with the contact rows and its merit."""
        out = self.internal(z, dynamic)
        if out is None:
            return REJECTED
        R0, Ke = out
        F, terms = R0.copy(), None
        if self.contact_rows is not None:
            terms = self.contact_rows.terms(z, R0)
            self.contact_rows.rows(F, terms)
        return LineState(F, R0, Ke, terms, self.merit(F), z)

    def absolute(self, state, tol) -> float:
        """The largest force row of ``F`` (N) where every stretch row meets ``tol`` (over
        `length_scale`), else inf: the measure of ``atol``."""
        if state.F is None:
            return np.inf
        stretch = np.abs(state.F[self._stretch_rows]) / self.length_scale
        if not float(np.max(stretch, initial=0.0)) < tol:
            return np.inf
        return float(np.max(np.abs(state.F[self._force_rows]), initial=0.0))

    def rounding(self, state) -> np.ndarray:
        """``ε |J| |z|`` (per row): the residual's change when every dof of ``state`` moves by its
        rounding, from the element matrices (no global matrix built)."""
        Ke, extra = self.tangent(state)
        size = np.abs(state.z)
        rows = self.assembly.gather(np.einsum("ije,je->ie", np.abs(Ke), size[self.assembly.dofs]))
        if extra is not None:
            rows += abs(extra.tocsr()) @ size
        return EPS * rows

    def merit_floor(self, state) -> float:
        """The round-off floor of the merit at ``state``: the merit of `rounding`, the first-order
        change of ``F`` when every dof of the iterate moves by its own rounding.

        A taut line's force rows are differences of tensions ``T`` far above the total load
        ``W`` (``H/W`` of 1e4 and more), and each element's direction carries the rounding of
        its end positions over its length, ``ε L/h``: the floor is about ``ε (L/h) T/W``, above
        the default ``rtol`` = 1e-10 once ``T/W`` passes about 1e4 on 64 elements.
        """
        return 0.0 if state.z is None else self.merit(self.rounding(state))

    # --- for skcable.fe.check_tangent ------------------------------------------------------------
    def free_dofs(self):
        """The dofs a solve moves."""
        return self.free

    def term_contribution(self, term, z, state=None):
        """``(R, K)`` of the cable term ``term`` alone at ``z``: its residual ``−∫ f·δr`` over the
        dofs and its tangent (sparse)."""
        g = self.assembly.interpolate(np.asarray(z, dtype=float))
        own = term if any(term is t for t in self.terms) else term.bind(self)
        forces = self.term_load(g, (own,))
        d = self.dim
        S = np.zeros_like(g)
        S[d : 2 * d] = -forces.f
        D = np.zeros((2 * d + 1, 2 * d + 1, *g.shape[1:]))
        self.add_term_tangent(D, forces)
        return self.assembly.vector(S), self.assembly.matrix(D=D)
