r"""One discrete line in the plane: its properties, its loads' scales and its seabed's contact rows.

The line law of `skcable.mooring.line_bvp.discrete` (Goicolea 2012, eq. (3)) with ``dim = 2``:
positions ``r(s) = (x, y)`` P2, y up, tension ``T(s)`` discontinuous P1 on the *unstretched*
arc length ``s ∈ [0, L]``; the length is given (a mooring line), so there is no global unknown.
Each segment has its weight (a number or a callable of ``s``) and a constant axial stiffness
``EA`` (or none); the point loads ``P_k`` lie at any arc length. The contact rows

.. math::
    R_{\mathbf r} \mathrel{-}= \sum_i \lambda_i (\mathbf n_i - \mu\,\mathbf t_i)\cdot\delta\mathbf r_i

are `skcable.mooring.line_bvp.contact`'s, with Coulomb friction fully mobilised where the line
slides and none on the slack stretch near the anchor (Jonkman's model).

Support reactions come from ``R⁰`` (the residual without contact) at the supports:
``H_A = -R⁰_x(A)``, ``V_A = R⁰_y(A)``, ``H_B = R⁰_x(B)``, ``V_B = R⁰_y(B)``.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import InputError
from skcable.mooring.line_bvp.contact import ContactRows
from skcable.mooring.line_bvp.discrete import DiscreteLine, LineState
from skcable.mooring.line_bvp.loads import term_load
from skcable.mooring.line_bvp.start import closed_form_start

__all__ = ["LineProblem", "LineState"]


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
        self.anchor, self.fairlead = np.zeros(2), np.array([span, dh], dtype=float)
        self.slack_end = float(slack_end)
        self.terms = tuple(terms)
        if self.terms and self.slack_end > 0:
            self._slack_terms()
        self.segments = segments
        self.point_loads = point_loads
        lengths = np.array([seg.length for seg in segments])
        inner = self.discretise(lengths, point_loads, n_elements, fitted, nodes_at)
        self.properties()
        assert self.compliance_q is not None, "a plane line's segments have constant EA"
        #: ∫ ds / EA over the line (m/N)
        self.compliance = float(np.sum(self.compliance_q * self.assembly.dx))
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
        self.contact, self.contact_prev, self.contact_next = self.along_line(
            inner if seabed is not None else np.zeros(0, dtype=int)
        )
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
        return term_load(self.terms, (share * self.span, share * self.dh), s, a, np.zeros_like(s)).f

    # --- the external loads ---------------------------------------------------------------
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
            # on the slack stretch friction holds the node's own tangential weight
            held = None
            if self.slack_end > 0:
                held = (1.0 - self.sliding_share) * self.external[N + self.contact]
            self.contact_rows = ContactRows(
                self.contact, self.contact_prev, self.contact_next, N, 2, seabed,
                self.stiffness_nodes, self.mu_nodes, held,
            )  # fmt: skip

    # --- for skcable.fe.check_tangent ---------------------------------------------------------
    def tangent_check_state(self):
        """The closed-form start of a solve (for `skcable.fe.check_tangent`)."""
        return closed_form_start(self)

    def reactions(self, R0):
        """``(H_A, V_A, H_B, V_B)`` (N) from the residual without contact at the supports."""
        N = self.N
        return -R0[self.end_a], R0[N + self.end_a], R0[self.end_b], R0[N + self.end_b]
