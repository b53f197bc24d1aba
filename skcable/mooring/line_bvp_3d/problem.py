r"""One discrete line in space: mesh, bases, properties at the quadrature points, residual, tangent.

The 2-D line BVP's arc-length form (`skcable.mooring.line_bvp.problem`; J.M. Goicolea, "Cálculo
de cables", UPM, 2012, eq. (3)) in three dimensions, on the unstretched arc length ``s ∈ [0, L]``:
positions ``r(s) = (x, y, z)`` P2 (z up), tension ``T(s)`` discontinuous P1, ``a = dr/ds``,
``n = |a|``, ``e = a/n``. With the distributed force ``f(r, a, T, s)`` per unstretched length
(the weight ``(0, 0, −w)``, the current's drag, the analyst's cable terms: `skcable.bvp.terms`)
and each segment's axial law ``ε(T)`` (`skcable.mooring.axial`):

.. math::
    R_{\mathbf r} = \int_0^L \big(T\,\mathbf e\cdot\delta\mathbf r' - \mathbf f\cdot\delta\mathbf r\big)\,ds
        + \sum_k P_k\,\delta z(s_k) - \text{(contact)} = 0,
    \qquad R_T = \int_0^L \big(n - 1 - \varepsilon(T)\big)\,\delta T\,ds = 0,

``P_k`` the downward point loads at joints (clump weights ``P > 0``, buoys ``P < 0``); the
contact rows are `skcable.mooring.line_bvp_3d.contact`'s. The generalized strains are
``(x', y', z', x, y, z, T)``; the section law ``S = (T e, −f, n − 1 − ε)`` has the tangent

.. math::
    \frac{\partial (T\mathbf e)}{\partial \mathbf a} = \frac{T}{n}(I - \mathbf e\mathbf e^T),\quad
    \frac{\partial (T\mathbf e)}{\partial T} = \mathbf e,\quad
    \frac{\partial(-\mathbf f)}{\partial(\mathbf r, \mathbf a, T)}
        = -(f_{\mathbf r}, f_{\mathbf a}, f_T),\quad
    \frac{\partial(n - 1 - \varepsilon)}{\partial(\mathbf a, T)} = (\mathbf e^T, -\varepsilon'(T)),

unsymmetric where the drag depends on the line's direction. Every call of the assembly is in
this module.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from skcable.bvp.terms import CableState
from skcable.mooring.line_bvp.discrete import DiscreteLine
from skcable.mooring.line_bvp_3d.contact import ContactRows3D, ContactTerms3D
from skcable.mooring.line_bvp_3d.loads import SegmentDrag
from skcable.mooring.line_bvp_3d.pointwise import LinePoints

__all__ = ["STRAINS", "LineProblem3D", "LineState3D"]

#: the generalized strains (field, derivative order): x', y', z', x, y, z, T
STRAINS = (("x", 1), ("y", 1), ("z", 1), ("x", 0), ("y", 0), ("z", 0), ("T", 0))
T_ = 6
EPS = float(np.finfo(float).eps)


@dataclass
class LineState3D:
    """The residual ``F`` (contact rows in), ``R⁰`` (without), the element tangents ``Ke``, the
    contact terms, the merit and the iterate ``z`` (``F`` None: rejected)."""

    F: np.ndarray | None
    R0: np.ndarray | None
    Ke: np.ndarray | None
    terms: ContactTerms3D | None
    merit: float
    z: np.ndarray | None = None


REJECTED = LineState3D(None, None, None, None, np.inf)


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
    drag_scale : float
        Factor on the current's drag (the driver's continuation; 1: the scene's).
    """

    dim = 3

    def __init__(self, scene, n_elements, fitted=(), nodes_at=None, drag_scale=1.0):
        self.scene, self.drag_scale = scene, float(drag_scale)
        self.anchor, self.fairlead = scene.anchor, scene.fairlead
        self.segments, self.seabed, self.friction = scene.segments, scene.seabed, scene.friction
        lengths = np.array([seg.length for seg in self.segments])
        self.point_loads = scene.point_loads
        self.fitted = tuple(float(p) for p in fitted)
        inner = self.discretise(lengths, self.point_loads, n_elements, fitted, nodes_at, STRAINS)
        self._properties()
        self.terms = self._terms()
        self.load_scale = self._load_scale()
        self.length_scale = self.L
        self.contact_rows = self._contact_rows(inner) if self.seabed is not None else None

    # --- properties, terms, scales -------------------------------------------------------------
    def _properties(self):
        """Per element its segment (by its midpoint); weight and axial law at the quadrature
        points (one compliance array where every law is a constant EA)."""
        middle = self.mesh.p[0, self.mesh.t].mean(axis=0)
        self.middle = middle
        self.owner = np.clip(np.searchsorted(self.joints, middle) - 1, 0, len(self.segments) - 1)
        w = np.array([seg.w for seg in self.segments])
        self.w_q = np.broadcast_to(w[self.owner], self.assembly.dx.shape).copy()
        self.laws = [seg.law for seg in self.segments]
        self.columns = [np.flatnonzero(self.owner == k) for k in range(len(self.segments))]
        self.compliance_q = None
        if all(law is None or law.kind == "constant" for law in self.laws):
            c = np.array([0.0 if law is None else 1.0 / law.EA for law in self.laws])
            self.compliance_q = np.broadcast_to(c[self.owner], self.assembly.dx.shape).copy()
        self.weight = float(np.sum(self.w_q * self.assembly.dx))

    def _terms(self):
        """The cable terms: the current's drag on the segments that have it, the analyst's."""
        sc, terms = self.scene, []
        if sc.current is not None:
            segs = self.segments
            diameter = [seg.diameter or 0.0 for seg in segs]
            cn, ct = [seg.cd_normal for seg in segs], [seg.cd_tangential for seg in segs]
            drag = SegmentDrag(
                sc.current, self.joints, diameter, cn, ct, rho=sc.rho_water, scale=self.drag_scale
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

    def weight_at(self, s) -> np.ndarray:
        """The weight per unstretched length (N/m, downward) at arc lengths ``s`` (m)."""
        k = np.clip(np.searchsorted(self.joints, s, side="right") - 1, 0, len(self.segments) - 1)
        return np.array([seg.w for seg in self.segments])[k]

    def _contact_rows(self, inner) -> ContactRows3D:
        """The contact rows of the inner position nodes, each with its neighbours along the line
        and ``c_i`` (the load per length times the node's element length over the mean one)."""
        s = self.basis.doflocs[0]
        order = np.argsort(s, kind="stable")
        rank = np.empty_like(order)
        rank[order] = np.arange(order.size)
        nodes = inner[np.argsort(s[inner], kind="stable")]
        stiffness = self.contact_stiffness(nodes)[0]
        return ContactRows3D(
            nodes,
            order[rank[nodes] - 1],
            order[rank[nodes] + 1],
            self.N,
            self.seabed,
            stiffness,
            self.friction,
        )

    # --- the section law at the quadrature points ------------------------------------------
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

    def loads(self, g):
        """The distributed force at the quadrature points (3, nq, ne) (N per unstretched m) and
        its derivatives ``(f_r, f_a, f_T)`` (None where they vanish), from the strains ``g``."""
        f = np.zeros((3, *g.shape[1:]))
        f[2] = -self.w_q
        if not self.terms:
            return f, None, None, None
        state = CableState.at(g[3:6], self.assembly.x, g[0:3], g[T_])
        df_dr, df_da, df_dT = np.zeros((3, 3, *f.shape[1:])), np.zeros((3, 3, *f.shape[1:])), None
        for term in self.terms:
            out = term.forces(state)
            f = f + out.f
            if out.df_dr is not None:
                df_dr += out.df_dr
            if out.df_da is not None:
                df_da += out.df_da
            if out.df_dT is not None:
                df_dT = out.df_dT if df_dT is None else df_dT + out.df_dT
        return f, df_dr, df_da, df_dT

    def section(self, z, dynamic=False):
        """``(S, D)``: the section forces (7, nq, ne) and their tangent (7, 7, nq, ne) at ``z``,
        or None where the line folds (``|a| = 0`` somewhere)."""
        g = self.assembly.interpolate(z)
        a, T = g[0:3], g[T_]
        n = np.sqrt(np.sum(a * a, axis=0))
        if not np.all(n > 0):
            return None
        e = a / n
        eps, k = self.strains(T, dynamic)
        f, df_dr, df_da, df_dT = self.loads(g)
        S = np.concatenate([T * e, -f, (n - 1.0 - eps)[None]])
        D = np.zeros((7, 7, *n.shape))
        Tn = T / n
        D[:3, :3] = -Tn * np.einsum("i...,j...->ij...", e, e)
        for i in range(3):
            D[i, i] += Tn
        D[:3, T_] = D[T_, :3] = e
        D[T_, T_] = -k
        if df_dr is not None:
            D[3:6, 3:6] = -df_dr
            D[3:6, 0:3] = -df_da
        if df_dT is not None:
            D[3:6, T_] = -df_dT
        return S, D

    # --- residual and tangent -----------------------------------------------------------------
    def internal(self, z, dynamic=False):
        """``R⁰`` (no contact) and the element tangents, or None for a folded line."""
        out = self.section(z, dynamic)
        if out is None:
            return None
        S, D = out
        R = self.assembly.vector(S)
        np.add.at(R, self.point_rows, self.point_values)
        return R, self.assembly.element_matrices(D)

    def assemble(self, z, dynamic=False) -> LineState3D:
        """The state at the iterate ``z``: residual with the contact rows and its merit."""
        out = self.internal(z, dynamic)
        if out is None:
            return REJECTED
        R0, Ke = out
        F, terms = R0.copy(), None
        if self.contact_rows is not None:
            terms = self.contact_rows.terms(z, R0)
            self.contact_rows.rows(F, terms)
        return LineState3D(F, R0, Ke, terms, self.merit(F), z)

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
        """The merit of `rounding`: the round-off floor of the merit at ``state``."""
        return 0.0 if state.z is None else self.merit(self.rounding(state))

    def reactions(self, R0):
        """``(S_A, S_B)``: the supports' reactions on the line at A and B (N, 3-vectors)."""
        return R0[self.end_dofs("a")], R0[self.end_dofs("b")]

    # --- fields at any arc length ----------------------------------------------------------
    def state_at(self, z, s) -> CableState:
        """The line's state (`CableState`, 3-D) at arc lengths ``s`` (1-D, m)."""
        s = np.asarray(s, dtype=float).ravel()
        N = self.N
        r, a, cells = self.points.fields(z[: 3 * N].reshape(3, N), s)
        return CableState.at(r, s, a, self.points.tension(z[3 * N :], s, cells))

    def tension_at(self, z, s) -> np.ndarray:
        """The tension (N) at arc lengths ``s`` (1-D, m): the value of the element holding each."""
        return self.points.tension(z[3 * self.N :], np.asarray(s, dtype=float).ravel())

    @cached_property
    def points(self) -> LinePoints:
        """The point evaluation of the fields (`skcable.mooring.line_bvp_3d.pointwise`)."""
        return LinePoints(self.mesh, self.basis, self.tbasis)

    def forces_at(self, z, s) -> np.ndarray:
        """The distributed force (3, n) (N per unstretched m) at arc lengths ``s`` (m)."""
        state = self.state_at(z, s)
        f = np.zeros((3, state.T.size))
        f[2] = -self.weight_at(state.s)
        for term in self.terms:
            f = f + term.forces(state).f
        return f

    # --- for skcable.fe.check_tangent ----------------------------------------------------------
    def free_dofs(self):
        return self.free

    def term_contribution(self, term, z, state=None):
        """``(R, K)`` of one cable term alone at ``z``: ``−∫ f·δr`` and its tangent."""
        g = self.assembly.interpolate(z)
        cable = CableState.at(g[3:6], self.assembly.x, g[0:3], g[T_])
        out = term.bind(self).forces(cable) if term not in self.terms else term.forces(cable)
        S = np.zeros((7, *g.shape[1:]))
        S[3:6] = -out.f
        D = np.zeros((7, 7, *g.shape[1:]))
        for block, rows in ((out.df_dr, slice(3, 6)), (out.df_da, slice(0, 3))):
            if block is not None:
                D[3:6, rows] = -block
        if out.df_dT is not None:
            D[3:6, T_] = -out.df_dT
        return self.assembly.vector(S), self.assembly.matrix(D=D)
