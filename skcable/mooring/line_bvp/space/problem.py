r"""One discrete line in space: its properties, the current's drag, its seabed's contact rows.

The line law of `skcable.mooring.line_bvp.discrete` (J.M. Goicolea, "Cálculo de cables", UPM,
2012, eq. (3)) with ``dim = 3``: positions ``r(s) = (x, y, z)`` P2 (z up), tension ``T(s)``
discontinuous P1 on the unstretched arc length ``s ∈ [0, L]``. The distributed force
``f(r, a, T, s)`` per unstretched length is the current's drag (`SegmentDrag`) and the analyst's
cable terms (`skcable.bvp.terms`), each bound to this line; each segment has its axial law
``ε(T)`` (`skcable.mooring.axial`); the point loads ``P_k`` (downward: clump weights ``P > 0``,
buoys ``P < 0``) lie at joints; the contact rows are
`skcable.mooring.line_bvp.contact`'s (the plane line's, in space).
"""

from __future__ import annotations

import numpy as np

from skcable.bvp.terms import CableState
from skcable.errors import InputError
from skcable.mooring.line_bvp.contact import ContactRows
from skcable.mooring.line_bvp.discrete import DiscreteLine
from skcable.mooring.line_bvp.space.loads import SegmentDrag

__all__ = ["LineProblem3D"]


class LineProblem3D(DiscreteLine):
    """Mesh, bases, properties per quadrature point and the assembly of one line in space.

    Parameters
    ----------
    scene : Scene3D
    n_elements : int
        Elements, shared among segments by length (ignored where ``nodes_at`` is given).
    fitted : sequence of float
        Arc lengths (m) where a node is put (the touchdown).
    nodes_at : ndarray, optional
        The nodes of a given mesh.
    load_factor : float
        Factor on the current's drag and the point loads (the continuation,
        `skcable.mooring.line_bvp.solver.LineSolver.continued`; 1: the scene's).
    slack_end : float
        The end ``s0`` (m) of a slack stretch laid on the seabed from the anchor (`lay_slack`; 0:
        none).
    """

    dim = 3
    #: the slack stretch's position nodes but the anchor's (dofs of one coordinate; `lay_slack`)
    laid_nodes: np.ndarray = np.zeros(0, dtype=int)

    def __init__(self, scene, n_elements, fitted=(), nodes_at=None, load_factor=1.0, slack_end=0.0):
        self.scene, self.load_factor = scene, float(load_factor)
        self.anchor, self.fairlead = scene.anchor, scene.fairlead
        self.segments, self.seabed, self.friction = scene.segments, scene.seabed, scene.friction
        lengths = np.array([seg.length for seg in self.segments])
        self.point_loads = [(s, self.load_factor * P) for s, P in scene.point_loads]
        self.fitted = tuple(float(p) for p in fitted)
        self.slack_end = float(slack_end)
        #: the graded mesh's nodes (without the fitted ones), or None: uniform
        self.nodes_at = None if nodes_at is None else np.asarray(nodes_at, dtype=float)
        nodes = [*fitted, self.slack_end] if self.slack_end > 0 else fitted
        inner = self.discretise(lengths, self.point_loads, n_elements, nodes, nodes_at)
        self.properties()
        self.terms = self._terms()
        self.load_scale = self._load_scale()
        self.length_scale = self.L
        a, bed = self.anchor, self.seabed
        #: A lies on the seabed (to 1e-12 of the length): the seabed, not the anchor, carries its push
        self.anchor_on_seabed = (
            bed is not None and abs(a[2] - float(bed.height(a[0], a[1]))) <= 1e-12 * self.L
        )
        if self.slack_end > 0:
            inner = self.lay_slack(inner)
        self.contact_rows = self._contact_rows(inner) if self.seabed is not None else None

    def lay_slack(self, inner) -> np.ndarray:
        r"""Lay the slack stretch ``[0, s0]`` on the seabed and hold it there (`DiscreteLine.hold`):
        the inner position nodes left free.

        Friction holds the stretch, its tension zero (J.M. Jonkman, "Dynamics modeling and loads
        analysis of an offshore floating wind turbine", NREL, 2007: ``max(H - μ w (L_B - s), 0)``);
        its shape is that of its laying, which statics does not decide: as Jonkman's (and
        MoorPy's) line, it lies straight from the anchor towards the fairlead, along the seabed,
        unstretched. Its nodes and tensions are held (the node at ``s0`` too, where the tensioned
        line starts), so the rest of the line is the same line anchored at ``s0``: its rows at the
        stretch's nodes are the seabed's forces there (its weight and the current's drag on it,
        which the driver checks friction holds)."""
        if not self.anchor_on_seabed:
            raise InputError("slack_end", "a slack stretch lies on the seabed from an anchor on it")
        s_dof, N = self.basis.doflocs[0], self.N
        laid = np.flatnonzero(s_dof <= self.slack_end * (1.0 + 1e-12))
        laid = laid[laid != self.end_a]
        if not laid.size:  # an end within 1e-9 of the length of the anchor: no stretch to lay
            return inner
        tension = self.tbasis.element_dofs[:, self.middle < self.slack_end].ravel()
        positions = self.seabed_path(s_dof[laid], self.fairlead)
        # as the fairlead moves across, the stretch turns with the chord: central differences
        step = 1e-6 * float(np.linalg.norm(self.fairlead[:2] - self.anchor[:2]))
        turns = np.zeros((3 * laid.size + tension.size, 3))
        for k in range(2):
            move = np.zeros(3)
            move[k] = step
            plus = self.seabed_path(s_dof[laid], self.fairlead + move)
            minus = self.seabed_path(s_dof[laid], self.fairlead - move)
            turns[: 3 * laid.size, k] = ((plus - minus) / (2.0 * step)).ravel()
        self.hold(
            np.concatenate([*(k * N + laid for k in range(3)), 3 * N + tension]),
            np.concatenate([*positions, np.zeros(tension.size)]),
            turns,
        )
        self.laid_nodes = laid
        return inner[~np.isin(inner, laid)]

    def seabed_path(self, s, fairlead) -> np.ndarray:
        """The points (3, n) (m) at arc lengths ``s`` (m) along the seabed from the anchor, in the
        vertical plane through the anchor and ``fairlead``: the seabed's heights on that line at
        2049 points up to ``max(s)`` horizontally, the arc length of the polyline through them
        (exact on a `skcable.mooring.bathymetry.Plane`, within the sampling's chord error on a
        grid)."""
        a, chord = self.anchor, fairlead[:2] - self.anchor[:2]
        u = chord / np.linalg.norm(chord)
        sigma = np.linspace(0.0, float(np.max(s)), 2049)
        xy = a[:2, None] + u[:, None] * sigma
        b = np.asarray(self.seabed.height(xy[0], xy[1]), dtype=float)
        arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(sigma), np.diff(b)))])
        along = np.interp(s, arc, sigma)
        xy = a[:2, None] + u[:, None] * along
        return np.vstack([xy, np.asarray(self.seabed.height(xy[0], xy[1]), dtype=float)])

    # --- properties, terms, scales -------------------------------------------------------------
    def _terms(self):
        """The cable terms: the current's drag on the segments that have it, the analyst's."""
        sc, terms = self.scene, []
        if sc.current is not None:
            segs = self.segments
            diameter = [seg.diameter or 0.0 for seg in segs]
            cn, ct = [seg.cd_normal for seg in segs], [seg.cd_tangential for seg in segs]
            drag = SegmentDrag(
                sc.current, self.joints, diameter, cn, ct, rho=sc.rho_water, scale=self.load_factor
            )
            terms.append(drag)
        return [*terms, *(term.bind(self) for term in sc.terms)]

    def _load_scale(self) -> float:
        """The force scale of the residual (N): the weight, the point loads, and the drag and the
        terms' forces on the chord between the ends."""
        scale = float(np.sum(np.abs(self.w_q) * self.assembly.dx) + np.sum(np.abs(self.point_values)))
        if self.terms:
            f = self.chord_forces(scale)
            scale += float(np.sum(np.sqrt(np.sum(f * f, axis=0)) * self.assembly.dx))
        return scale

    def chord_forces(self, tension: float) -> np.ndarray:
        """The terms' forces (3, nq, ne) (N/m) on the straight chord between the ends at the
        ``tension`` (N), unstretched."""
        share = self.assembly.x / self.L
        chord = self.fairlead - self.anchor
        r = self.anchor[:, None, None] + chord[:, None, None] * share
        a = np.array(np.broadcast_to((chord / self.L)[:, None, None], r.shape))
        state = CableState.at(r, self.assembly.x, a, np.full(share.shape, float(tension)))
        return sum((term.forces(state).f for term in self.terms), np.zeros_like(r))

    def _contact_rows(self, inner) -> ContactRows:
        """The contact rows of the inner position nodes, each with its neighbours along the line
        and ``c_i`` (the load per length times the node's element length over the mean one)."""
        nodes, prev, next_ = self.along_line(inner)
        stiffness = self.contact_stiffness(nodes)[0]
        mu = np.full(nodes.size, self.friction)
        return ContactRows(nodes, prev, next_, self.N, 3, self.seabed, stiffness, mu)

    def reactions(self, R0):
        """``(S_A, S_B)``: the supports' reactions on the line at A and B (N, 3-vectors)."""
        return R0[self.end_dofs("a")], R0[self.end_dofs("b")]
