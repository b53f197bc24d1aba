r"""One discrete line: mesh, bases, properties at the quadrature points, residual and tangent.

The arc-length form of `skcable.bvp.arc` (Goicolea 2012, eq. (3)) on the *unstretched*
arc length ``s ∈ [0, L]`` itself: positions ``r(s) = (x, y)`` P2, tension ``T(s)``
discontinuous P1, ``a = dr/ds``, ``n = |a|``, ``e = a/n``; the length is given (a mooring line),
so there is no global unknown. With the weight ``w(s)`` per unstretched length (N/m, any sign: a
buoyant segment has ``w < 0``) and the axial stiffness ``EA(s)`` per element:

.. math::
    R_{\mathbf r} = \int_0^L T\,\mathbf e\cdot\delta\mathbf r'\,ds
        + \int_0^L w\,\delta y\,ds - \int_0^L \mathbf f\cdot\delta\mathbf r\,ds
        + \sum_k P_k\,\delta y(s_k)
        - \sum_i \lambda_i (\mathbf n_i - \mu\,\mathbf t_i)\cdot\delta\mathbf r_i = 0,
    \qquad R_T = \int_0^L \big(n - 1 - T/EA\big)\,\delta T\,ds = 0,

``P_k`` the downward point loads (clump weights ``P > 0``, buoys ``P < 0``) at mesh nodes
``s_k``, ``f(r, s, a, T)`` the force of the cable terms per unstretched length (y up:
`skcable.mooring.line_bvp.loads`, whose derivatives enter the tangent); the contact rows (the
``λ_i`` terms) are `skcable.mooring.line_bvp.contact`'s.

Support reactions come from ``R⁰`` (the residual without contact) at the supports:
``H_A = -R⁰_x(A)``, ``V_A = R⁰_y(A)``, ``H_B = R⁰_x(B)``, ``V_B = R⁰_y(B)``.

Every call of the assembly is in this module: `LineProblem.internal` (residual and element
tangents), `LineProblem.load_vector` (the external loads) and the banded solves.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace

import numpy as np

from skcable.bvp.section import STRAINS, tension_section
from skcable.errors import InputError
from skcable.fe.check import sparse_of
from skcable.mooring.line_bvp.contact import ContactRows, ContactTerms
from skcable.mooring.line_bvp.discrete import DiscreteLine
from skcable.mooring.line_bvp.loads import TermLoad, term_load
from skcable.mooring.line_bvp.start import closed_form_start

__all__ = ["STRAINS", "LineProblem", "LineState"]

AX, AY, X, Y, T_ = range(5)  # the generalized strains of `STRAINS`: x', y', x, y, T
EPS = float(np.finfo(float).eps)


@dataclass
class LineState:
    """The residual ``F`` (contact rows in), ``R⁰`` (without), the element tangents ``Ke``, the
    contact terms (None without contact), the merit and the iterate ``z`` itself (``F`` None:
    rejected)."""

    F: np.ndarray | None
    R0: np.ndarray | None
    Ke: np.ndarray | None
    terms: ContactTerms | None
    merit: float
    z: np.ndarray | None = None


REJECTED = LineState(None, None, None, None, np.inf)


class LineProblem(DiscreteLine):
    """Mesh, bases, properties per quadrature point and the assembly of one line.

    Parameters
    ----------
    span, dh : float
        B relative to A (m).
    segments : list of BVPSegment
    point_loads : list of (s, P)
    seabed : Seabed or None
    friction : float
        μ where the line slides.
    n_elements : int
        Elements, shared among segments by length (ignored where ``nodes_at`` is given).
    fitted : sequence of float
        Points (m of arc length) where a node is put (`skcable.mooring.line_bvp.mesh.line_nodes`).
    slack_end : float
        End ``s0`` of the slack stretch near the anchor (m); 0 without one.
    nodes_at : ndarray, optional
        The nodes of a graded mesh.
    terms : sequence of CableTerm
        The cable terms (`skcable.bvp.terms`) on the line besides its self weight.
    """

    def __init__(
        self,
        span,
        dh,
        segments,
        point_loads,
        seabed,
        friction,
        n_elements,
        fitted=(),
        slack_end=0.0,
        nodes_at=None,
        terms=(),
    ):
        self.span, self.dh, self.seabed, self.friction = span, dh, seabed, friction
        self.slack_end = float(slack_end)
        self.terms = tuple(terms)
        if self.terms and self.slack_end > 0:
            self._slack_terms()
        self.segments = segments
        self.point_loads = point_loads
        lengths = np.array([seg.length for seg in segments])
        inner = self.discretise(lengths, point_loads, n_elements, fitted, nodes_at, STRAINS)
        self._properties()
        self.load_scale = float(
            np.sum(np.abs(self.w_q) * self.assembly.dx) + np.sum(np.abs(self.point_values))
        )
        #: the mean downward load per unstretched length (N/m) the closed-form start hangs under:
        #: the weight's, less the cable terms' vertical force on the chord (`chord_forces`)
        self.start_weight = self.weight / self.L
        if self.terms:
            f = self.chord_forces()
            self.load_scale += float(np.sum(np.hypot(f[0], f[1]) * self.assembly.dx))
            self.start_weight = (self.weight - float(np.sum(f[1] * self.assembly.dx))) / self.L
        self.length_scale = self.L
        self.stiffness = self.load_scale / self.L  # c of the complementarity function (N/m)
        self.contact = inner if seabed is not None else np.zeros(0, dtype=int)
        self.external = self.load_vector()
        self._contact_rows()

    def _slack_terms(self):
        """Refuse terms the slack stretch near the anchor cannot carry: there friction holds the
        line's own tangential load, which `skcable.mooring.line_bvp.contact` takes as the weight's;
        a vertical load on a flat seabed has none, any other term would be held by the tension."""
        flat = self.seabed is not None and self.seabed.flat is not None
        if not (flat and all(term.vertical for term in self.terms)):
            raise InputError(
                "terms",
                "friction holds a slack stretch near the anchor here, which the line BVP models with "
                "vertical cable terms (Buoyancy) on a flat seabed only; "
                f"got {list(self.terms)!r} on a {'flat' if flat else 'shaped'} seabed",
            )

    def chord_forces(self) -> np.ndarray:
        """The cable terms' force ``f`` (N/m, (2, nq, ne)) on the straight chord from A to B,
        unstretched and slack (``T = 0``): their share of the force scale `load_scale` (``∫ |f|
        ds``) and of the start's weight `start_weight`."""
        s = self.assembly.x
        share = s / self.L
        a = np.broadcast_to((np.array([self.span, self.dh]) / self.L)[:, None, None], (2, *s.shape))
        return term_load(self.terms, share * self.span, share * self.dh, s, a, np.zeros_like(s)).f

    def _properties(self):
        """Weight and compliance at the quadrature points (an element's segment by its midpoint);
        the line's weight, each element's and its integrated compliance."""
        s_q = self.assembly.x
        middle = self.mesh.p[0, self.mesh.t].mean(axis=0)
        owner = np.clip(np.searchsorted(self.joints, middle) - 1, 0, len(self.segments) - 1)
        self.w_q = np.empty_like(s_q)
        self.compliance_q = np.empty_like(s_q)
        for k, seg in enumerate(self.segments):
            cols = owner == k
            if callable(seg.w):
                values = np.asarray(seg.w(s_q[:, cols]), dtype=float)
                try:
                    values = np.broadcast_to(values, s_q[:, cols].shape)
                except ValueError as exc:
                    raise InputError("w", f"the callable returned shape {values.shape}") from exc
                if not np.all(np.isfinite(values)):
                    raise InputError("w", "the callable returned non-finite values")
                self.w_q[:, cols] = values
            else:
                self.w_q[:, cols] = seg.w
            self.compliance_q[:, cols] = 0.0 if seg.EA is None else 1.0 / seg.EA
        self.middle = middle
        self.weight = float(np.sum(self.w_q * self.assembly.dx))
        #: weight of each element (N), in mesh order
        self.element_weight = np.sum(self.w_q * self.assembly.dx, axis=0)
        #: ∫ ds / EA over the line (m/N)
        self.compliance = float(np.sum(self.compliance_q * self.assembly.dx))

    def weight_at(self, s):
        """The weight per unstretched length (N/m, downward) at arc lengths ``s`` (m): its
        segment's (the upper one at a joint but the last), or the callable of s."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        owner = np.clip(np.searchsorted(self.joints, s, side="right") - 1, 0, len(self.segments) - 1)
        out = np.empty_like(s)
        for k, seg in enumerate(self.segments):
            cols = owner == k
            out[cols] = np.broadcast_to(seg.w(s[cols]), s[cols].shape) if callable(seg.w) else seg.w
        return out

    # --- loads: the one place where external forces enter ---------------------------------
    def distributed_load(self, g):
        """The distributed load at the quadrature points: ``(p_x, p_y, forces)``, ``p`` (N per
        unstretched m) in ``R ∋ ∫ p_x δx + p_y δy ds``: the dead weight ``(0, w)`` (``w``
        downward positive) less the cable terms' force ``f`` (y up), ``forces`` their
        `TermLoad` (None without terms), from the strains ``g`` at the quadrature points
        (``(5, nq, ne)``: x', y', x, y, T)."""
        if not self.terms:
            return np.zeros_like(g[AX]), self.w_q, None
        forces = self.term_load(g)
        return -forces.f[0], self.w_q - forces.f[1], forces

    def term_load(self, g, terms=None) -> TermLoad:
        """The cable terms' (``terms``, default all) force and derivatives at the quadrature
        points, from the strains ``g``; ``s`` the unstretched arc length from A."""
        terms = self.terms if terms is None else terms
        return term_load(terms, g[X], g[Y], self.assembly.x, g[AX : AY + 1], g[T_])

    @staticmethod
    def add_term_tangent(D, forces: TermLoad) -> None:
        """Add the derivatives of ``p = -f`` (`distributed_load`) to the section tangent ``D``
        (in place): rows x, y by the strains x, y (``∂f/∂r``), x', y' (``∂f/∂a``) and T."""
        if forces.df_dr is not None:
            D[X : Y + 1, X : Y + 1] -= forces.df_dr
        if forces.df_da is not None:
            D[X : Y + 1, AX : AY + 1] -= forces.df_da
        if forces.df_dT is not None:
            D[X : Y + 1, T_] -= forces.df_dT

    def element_term_load(self, z) -> np.ndarray:
        """``∫ -f ds`` (N) per element (2, ne), in mesh order, at the iterate ``z``: the terms'
        share of the load ``p`` (`distributed_load`); zeros without terms."""
        if not self.terms:
            return np.zeros((2, self.mesh.t.shape[1]))
        f = self.term_load(self.assembly.interpolate(z)).f
        return -np.sum(f * self.assembly.dx, axis=1)

    def add_point_loads(self, R):
        """Add the point loads ``P_k δy(s_k)`` to the vector ``R`` (in place)."""
        np.add.at(R, self.point_rows, self.point_values)

    def load_vector(self, w_q=None, points=True):
        """The external load vector: ``∫ w δy`` (``w_q`` at the quadrature points, the weight by
        default) and, with ``points``, the point loads."""
        w_q = self.w_q if w_q is None else w_q
        zero = np.zeros_like(self.w_q)
        vector = self.assembly.vector(np.stack([zero, zero, zero, w_q, zero]))
        if points:
            self.add_point_loads(vector)
        return vector

    def _contact_rows(self):
        """The contact nodes' rows: c per node, the friction per node (μ where the line slides, 0
        on the slack stretch ``[0, slack_end]``), whether A lies on the seabed."""
        N, seabed = self.N, self.seabed
        # c per contact node (`DiscreteLine.contact_stiffness`): λ_i ~ w h_i switches at a gap ~ h_i
        self.stiffness_nodes, self.node_length = self.contact_stiffness(self.contact)
        # per contact node the share of its weight that lies beyond the slack stretch [0, slack_end]
        # (where friction is fully mobilised)
        sliding_q = np.where((self.middle > self.slack_end)[None, :], self.w_q, 0.0)
        sliding = self.load_vector(sliding_q, points=False)[N + self.contact]
        own = self.load_vector(points=False)[N + self.contact]
        self.sliding_share = np.ones(self.contact.size)
        if self.slack_end > 0:
            self.sliding_share = np.divide(sliding, own, out=np.ones_like(own), where=own != 0)
            self.sliding_share[self.basis.doflocs[0][self.contact] < self.slack_end] = 0.0
        #: friction coefficient per contact node: μ where it slides, 0 on the slack stretch
        self.mu_nodes = self.friction * self.sliding_share
        #: A lies on the seabed (to 1e-12 of the length): the seabed, not the anchor, carries its push
        self.anchor_on_seabed = (
            seabed is not None and abs(float(seabed(np.array([0.0]))[0])) <= 1e-12 * self.L
        )
        self.contact_rows = None
        if self.contact.size:
            self.contact_rows = ContactRows(
                self.contact,
                N,
                seabed,
                self.stiffness_nodes,
                self.mu_nodes,
                self.sliding_share,
                self.external[N + self.contact],
            )

    # --- residual and tangent -----------------------------------------------------------
    def internal(self, z):
        """``R⁰`` (no contact) and the element tangents, or None for a collapsed tangent."""
        asmb = self.assembly
        g = asmb.interpolate(z)
        T = g[T_]
        section = tension_section(g[AX], g[AY], T)
        if section is None:
            return None
        n, ex, ey, D = section  # T e, the stretch and their tangent (skcable.bvp.section)
        c = self.compliance_q
        fx, fy, forces = self.distributed_load(g)
        S = np.stack([T * ex, T * ey, fx, fy, n - 1.0 - T * c])
        D[T_, T_] = -c
        if forces is not None:
            self.add_term_tangent(D, forces)
        R = asmb.vector(S)
        self.add_point_loads(R)
        return R, asmb.element_matrices(D)

    # --- one term alone (skcable.fe.check_tangent) ---------------------------------------------
    def term_contribution(self, term, U, state=None):
        """``(R, K)`` of the cable term ``term`` alone at the iterate ``U``: its residual ``-∫ f·δr``
        over the dofs and its tangent (sparse)."""
        asmb = self.assembly
        g = asmb.interpolate(np.asarray(U, dtype=float))
        forces = self.term_load(g, (term,))
        S = np.zeros_like(g)
        S[X : Y + 1] = -forces.f
        D = np.zeros((5, 5, *g.shape[1:]))
        self.add_term_tangent(D, forces)
        return asmb.vector(S), sparse_of(asmb.matrix(asmb.element_matrices(D)), asmb.N)

    def free_dofs(self):
        """The dofs a solve moves (for `skcable.fe.check_tangent`)."""
        return self.free

    def tangent_check_state(self):
        """The closed-form start of a solve (for `skcable.fe.check_tangent`)."""
        return closed_form_start(self)

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
        tension = float(np.max(np.abs(z[2 * self.N :])))
        other = copy.copy(self)
        switch = np.maximum(self.stiffness_nodes, tension / self.node_length)
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

    def gaps(self, z):
        """Height of every contact node above the seabed (m)."""
        i = self.contact
        return z[self.N + i] - self.seabed(z[i])

    def contact_terms(self, z, R0):
        """Per contact node: slope, curvature, gap, multiplier λ, active flag, R⁰ rows."""
        assert self.contact_rows is not None, "a line without a seabed has no contact terms"
        return self.contact_rows.terms(z, R0)

    def assemble(self, z):
        """The state at the iterate ``z``: residual with the contact rows, its merit (the largest
        force row over `load_scale`, stretch row over `length_scale`)."""
        out = self.internal(z)
        if out is None:
            return REJECTED
        R0, Ke = out
        F = R0.copy()
        terms = None
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

    def merit_floor(self, state) -> float:
        """The round-off floor of the merit at ``state``: the merit of ``ε |J| |z|`` (``J`` the
        generalized Jacobian, ``ε`` the machine epsilon), the first-order change of ``F`` when
        every dof of the iterate ``z`` moves by its own rounding.

        A taut line's force rows are differences of tensions ``T`` far above the total load
        ``W`` (``H/W`` of 1e4 and more), and each element's direction carries the rounding of
        its end positions over its length, ``ε L/h``: the floor is about ``ε (L/h) T/W``, above
        the default ``rtol`` = 1e-10 once ``T/W`` passes about 1e4 on 64 elements. The merit
        measured at the round-off floor of such lines is 0.13–0.44 of this bound.
        """
        if state.z is None:
            return 0.0
        rows = abs(self.jacobian(state)) @ np.abs(state.z) * EPS
        return self.merit(rows)

    def reactions(self, R0):
        """``(H_A, V_A, H_B, V_B)`` (N) from the residual without contact at the supports."""
        N = self.N
        return -R0[self.end_a], R0[N + self.end_a], R0[self.end_b], R0[N + self.end_b]
