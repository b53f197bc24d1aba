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
    """

    dim = 3

    def __init__(self, scene, n_elements, fitted=(), nodes_at=None, load_factor=1.0):
        self.scene, self.load_factor = scene, float(load_factor)
        self.anchor, self.fairlead = scene.anchor, scene.fairlead
        self.segments, self.seabed, self.friction = scene.segments, scene.seabed, scene.friction
        lengths = np.array([seg.length for seg in self.segments])
        self.point_loads = [(s, self.load_factor * P) for s, P in scene.point_loads]
        self.fitted = tuple(float(p) for p in fitted)
        #: the graded mesh's nodes (without the fitted ones), or None: uniform
        self.nodes_at = None if nodes_at is None else np.asarray(nodes_at, dtype=float)
        inner = self.discretise(lengths, self.point_loads, n_elements, fitted, nodes_at)
        self.properties()
        self.terms = self._terms()
        self.load_scale = self._load_scale()
        self.length_scale = self.L
        self.contact_rows = self._contact_rows(inner) if self.seabed is not None else None
        a, bed = self.anchor, self.seabed
        #: A lies on the seabed (to 1e-12 of the length): the seabed, not the anchor, carries its push
        self.anchor_on_seabed = (
            bed is not None and abs(a[2] - float(bed.height(a[0], a[1]))) <= 1e-12 * self.L
        )

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
