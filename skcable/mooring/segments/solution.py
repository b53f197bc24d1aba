r"""`LineSolution`: the equilibrium of a multi-segment `Line`, mapped along the line.

The closed form at the converged fairlead forces (`skcable.mooring.segments.state`)
gives the grounded pieces from the anchor to the touchdown and the suspended pieces from
the touchdown to B. Along a suspended piece from its lower end, at unstretched arc length
``sigma`` with ``V = V_b + w sigma`` (H.M. Irvine, "Cable Structures", MIT Press, 1981):

.. math::
    x = \frac{H\sigma}{EA} + \frac{H}{w}\Big(\operatorname{asinh}\frac{V}{H}
        - \operatorname{asinh}\frac{V_b}{H}\Big), \qquad
    y = \frac{\sigma (V_b + w\sigma/2)}{EA} + \frac{T - T_b}{w};

along a grounded piece the tension falls by friction towards the anchor and the piece
stretches by ``∫ T ds / EA`` (J.M. Jonkman, "Dynamics modeling and loads analysis of an
offshore floating wind turbine", NREL, 2007). The solution reads its line through the
line's public `LineArrays` (``line.arrays``).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from skcable._checks import real, require, whole
from skcable.cable.arc_samples import arc_samples, write_profile
from skcable.cable.closure import positions, stretched_length
from skcable.errors import ConvergenceError, InputError
from skcable.results import ProfileMixin

__all__ = ["CLOSURE_TOLERANCE", "LineSolution", "segment_table"]

#: A solution closes its scene where the closure misses the end by less than this over the chord:
#: every path of `Line.solve` (warm, cold, bracketed, batched, with nonlinear laws) checks it.
CLOSURE_TOLERANCE = 1e-11

_NO_GROUND = np.zeros(1)
_NO_GROUND.flags.writeable = False


class LineSolution(ProfileMixin):
    """Equilibrium of a `Line` between A = (0, 0) and B = (span, dh).

    Attributes
    ----------
    H : float
        Horizontal tension of the suspended part (N), the fairlead's.
    V_B, V_A : float
        Upward reactions at B and A (N), attachments at the end joints included.
    H_A : float
        Horizontal tension at the anchor (N), ``H`` less the friction, never negative.
    T_A, T_B : float
        Line tension at A and B (N).
    length : float
        Total unstretched length (m).
    length_on_seabed : float
        Unstretched grounded length (m).
    x_touchdown : float
        Abscissa where the line leaves the seabed towards B (m), 0 when it hangs freely.
    x_joints, y_joints : ndarray
        Position of the joints (m), ``n + 1`` values from A to B.
    joint_forces : ndarray
        Downward point force at each joint (N).
    seabed_reaction : float
        Total upward force of the seabed on the line (N).
    heap : bool
        Whether the slack lies in a heap on the seabed (``H = 0``, MoorPy's profile 4):
        the part from B hangs vertically down to the seabed at ``x_touchdown = span``
        (its tension at a height is the weight below it down to the seabed, clump
        weights included), the rest lies on the seabed without tension or stretch.
        The shape of that slack is not determined by statics: the maps draw it spread
        evenly from A to the touchdown (``x_of_s`` linear in ``s`` there).
    """

    def __init__(self, line, span, dh, state):
        self.line, self.span, self.dh = line, span, dh
        self._st = st = state
        self._expanded = False
        k, contact = st.k, st.contact
        P = line.joint_forces
        arrays = line.arrays
        self.length = arrays.total_length
        self.H = float(st.H)
        self.H_A = float(st.H_A)
        self.V_B = float(st.V + arrays.P_end[1])
        V_A0 = 0.0 if contact else float(st.V_bot0)
        self.V_A = float((0.0 if contact else -V_A0) + arrays.P_end[0])
        self.T_B = math.hypot(st.H, st.V)
        self.T_A = math.hypot(self.H_A, V_A0)
        self.joint_forces = P.copy()
        self.heap = bool(st.heap)
        if contact and arrays.n == 1:  # one grounded piece, on floats
            self.length_on_seabed = float(st.l_g[0])
            self.seabed_reaction = arrays.w_list[0] * self.length_on_seabed
            self.x_touchdown = float(st.l_g[0] + st.stretch[0])
            if st.heap:
                self.x_touchdown = float(span)
        elif contact:  # the grounded pieces, still Python floats from the closed form
            self.length_on_seabed = float(sum(st.l_g))
            self.seabed_reaction = float(arrays.w[: k + 1] @ np.array(st.l_g) + sum(st.R[1:]))
            self.x_touchdown = float(sum(l + e for l, e in zip(st.l_g, st.stretch, strict=True)))
            if st.heap:
                self.x_touchdown = float(span)
        else:
            self.length_on_seabed = self.seabed_reaction = self.x_touchdown = 0.0
        if arrays.n == 1:  # A, then B at the end of the one suspended piece
            self.x_joints = np.array([0.0, self.x_touchdown + st.dx])
            self.y_joints = np.array([0.0, st.dy])
        else:
            self._expand()

    def _expand(self):
        """The per-piece arrays of the profile (built once, when a map or the joints need them)."""
        if self._expanded:
            return
        self._expanded = True
        st, line, arrays = self._st, self.line, self.line.arrays
        k = st.k
        if st.V_top is None:
            st.V_top = st.V - arrays.load_above
            st.V_bot = st.V_top - arrays.wL
        if not isinstance(st.Vb, np.ndarray):  # one suspended piece, kept as floats
            st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = np.array(
                [st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy], dtype=float
            ).reshape(6, 1)
        if st.contact:
            st.l_g, st.T_g, st.R, stretch = np.array([st.l_g, st.T_g, st.R, st.stretch], dtype=float)
        else:
            st.l_g = st.T_g = st.R = stretch = _NO_GROUND
        st.m_g = line.friction * arrays.w[: k + 1]
        # per-segment arrays: start of each segment along s, and of each suspended piece
        self._s0 = arrays.s_joint
        # grounded pieces: x at their lower ends, stretched lengths
        # heap: the slack spread evenly from A to the touchdown (its shape is not determined)
        self._spread = self.span / float(st.l_g.sum()) if st.heap else 1.0
        if st.contact:
            g_str = st.l_g + stretch
            x_g0 = np.concatenate([[0.0], np.cumsum(g_str * self._spread)[:-1]])
        else:
            g_str, x_g0 = _NO_GROUND, _NO_GROUND
        self._x_g0 = x_g0
        self._g_str = g_str
        # suspended pieces: segment i >= k from s_b (start on the line) with Vb
        dx, dy = st.dx, st.dy
        self._x_p0 = self.x_touchdown + np.concatenate([[0.0], np.cumsum(dx)])[:-1]
        self._y_p0 = np.concatenate([[0.0], np.cumsum(dy)])[:-1]
        self._s_p0 = self._s0[k:-1].copy()
        self._s_p0[0] += st.a
        if arrays.n == 1:
            return  # the joints are set
        self.x_joints = np.concatenate([x_g0, self._x_p0[1:], [self._x_p0[-1] + dx[-1]]])
        self.y_joints = np.concatenate([np.zeros(k + 1), self._y_p0[1:], [self._y_p0[-1] + dy[-1]]])
        if st.contact and st.a > 0:  # joint k lies on the seabed, the piece starts at the touchdown
            self.x_joints[k] = x_g0[k]

    @property
    def H_B(self):
        """Horizontal tension at B (N): ``H``, the suspended part's."""
        return self.H

    @property
    def state(self):
        """The closed form at the solution (`ClosureState`, read it only)."""
        return self._st

    def __repr__(self):
        note = "; heap: H = 0, the slack lies on the seabed" if self.heap else ""
        return (
            f"LineSolution(span={self.span:g}, dh={self.dh:g}: H={self.H:.9g}, H_A={self.H_A:.9g}, "
            f"V_A={self.V_A:.9g}, V_B={self.V_B:.9g}, T_A={self.T_A:.9g}, T_B={self.T_B:.9g}, "
            f"length={self.length:.9g}, length_on_seabed={self.length_on_seabed:.9g}{note})"
        )

    @staticmethod
    def _grounded_stretch(T_u, m, l, EA):
        """``∫ max(T_u - m d, 0) dd / EA`` over ``d`` in ``[0, l]``."""
        with np.errstate(divide="ignore", invalid="ignore"):
            ell = np.where(m > 0, np.minimum(l, T_u / np.where(m > 0, m, 1.0)), l)
        ell = np.maximum(ell, 0.0)
        return (T_u * ell - 0.5 * m * ell * ell) / EA

    # -- checks -----------------------------------------------------------------------
    def residual(self):
        """Largest relative residual of the closure and of the vertical equilibrium."""
        st, arrays = self._st, self.line.arrays
        chord = math.hypot(self.span, self.dh)
        closure = max(abs(st.X - self.span), abs(st.Z - self.dh)) / chord
        if st.heap:  # the slack covers the span
            closure = max(closure, max(self.span - self.length_on_seabed, 0.0) / chord)
        scale = abs(self.V_A) + abs(self.V_B) + arrays.abs_segment_weight + arrays.abs_joint_forces
        statics = abs(self.V_A + self.V_B + self.seabed_reaction - arrays.total_weight) / scale
        geometry = max(abs(self.x_joints[-1] - self.span) / chord, abs(self.y_joints[-1] - self.dh) / chord)
        return float(max(closure, statics, geometry))

    def validate(self):
        """Raise unless the solution is one of the closed form: finite, no buoy on the grounded
        part, no dip to the seabed between A and B, and a residual below 1e-9.

        Raises `InputError` (``span``, ``attachments`` or ``seabed``) or `ConvergenceError`."""
        st, line = self._st, self.line
        values = (self.H, self.V_A, self.V_B, self.H_A, self.T_A, self.T_B, self.length_on_seabed)
        if not all(map(math.isfinite, (*values, *self.x_joints.tolist()))):
            raise InputError("span", "gives a result outside the range of a float")
        if st.contact and min(line.arrays.w_list[: st.k + 1]) < 0:
            raise InputError(
                "segments",
                "a buoyant segment lies on the grounded part and would float up: a second touchdown that "
                "this closed form does not represent (solve it with mooring.solve_line_bvp)",
            )
        if st.contact and st.k > 0:
            buoyed = np.flatnonzero(st.R[1:] < 0) + 1
            if buoyed.size:
                raise InputError(
                    "attachments",
                    f"a buoy at joint {int(buoyed[0])} lies on the grounded part and would lift it: a "
                    "second touchdown that this closed form does not represent (solve it with "
                    "mooring.solve_line_bvp)",
                )
        arrays = line.arrays
        # one heavy segment from an anchor on the seabed: it rises from its touchdown or from A
        rises = (
            arrays.n == 1 and line.seabed == 0.0 and arrays.w_list[0] > 0 and (st.contact or st.V_bot0 >= 0)
        )
        if line.seabed is not None and not rises:
            y_min = self._lowest_suspended()
            floor = line.seabed
            tol = 1e-9 * math.hypot(self.span, self.dh)
            if y_min < floor - tol:
                argument = "attachments" if st.contact or floor == 0.0 else "seabed"
                raise InputError(
                    argument,
                    f"the suspended line dips to {y_min:.6g} m, below the seabed at {floor:.6g} m: a "
                    "touchdown between A and B that this closed form does not represent (solve it with "
                    "mooring.solve_line_bvp, or elastic_catenary for one segment)",
                )
        residual = self.residual()
        if not residual < 1e-9:
            raise ConvergenceError(f"Line.solve: residual {residual:.3e} after the solve", [residual])

    def lowest_height(self) -> float:
        """Lowest height (m, above A) of the line's suspended part: its joints and the vertices
        inside segments (the grounded part, at the seabed, left out)."""
        return float(self._lowest_suspended())

    def _lowest_suspended(self):
        """Lowest height of the suspended part: its joints and the vertices inside segments."""
        st = self._st
        H, k = st.H, st.k
        start = 1 if st.contact else 0
        lowest_joint = float(self.y_joints[start:].min())
        arrays = self.line.arrays
        if k == arrays.n - 1:  # one suspended piece, on floats; it starts at height 0
            Vb = st.Vb if isinstance(st.Vb, float) else float(st.Vb[0])
            Vt = st.V if st.V_top is None else float(st.V_top[k])
            if not (Vb < 0 and Vt > 0):
                return lowest_joint
            w, EA = arrays.w_list[k], arrays.EA_list[k]
            sig = -Vb / w
            drop = sig * Vb / (2.0 * EA) + (H - math.hypot(H, Vb)) / w
            return min(lowest_joint, drop)
        Vb, Vt = st.Vb, st.V_top[k:]
        ws, EAs = arrays.w[k:], arrays.EA[k:]
        inside = (Vb < 0) & (Vt > 0)
        sig = np.where(inside, -Vb / ws, 0.0)
        Tb = np.hypot(H, Vb)
        drop = sig * Vb / (2.0 * EAs) + (H - Tb) / ws  # from the piece's start to its vertex
        y_vertex = np.where(inside, self._y_p0 + drop, np.inf)
        return float(min(lowest_joint, y_vertex.min()))

    # -- along the line ---------------------------------------------------------------
    def _arc(self, s):
        s = real("s", s)
        require("s", (np.asarray(s) >= 0) & (np.asarray(s) <= self.length), "must lie in [0, length]", s)
        return np.asarray(s, dtype=float)

    def _locate(self, s):
        st = self._st
        k = st.k
        s_t = self._s0[k] + st.a
        grounded = st.contact & (s < s_t)
        seg = np.clip(np.searchsorted(self._s0, s, side="right") - 1, 0, self.line.arrays.n - 1)
        piece = np.clip(seg - k, 0, None)
        return grounded, seg, piece

    def _suspended(self, s, piece):
        st = self._st
        H = st.H
        k = st.k
        w, EA = self.line.arrays.w[k:][piece], self.line.arrays.EA[k:][piece]
        sig = np.maximum(s - self._s_p0[piece], 0.0)
        Vb = st.Vb[piece]
        V = Vb + w * sig
        if st.heap:  # vertical: x = span, the piece's tension rising linearly from Vb
            y = self._y_p0[piece] + sig * (1.0 + (Vb + 0.5 * w * sig) / EA)
            return self._x_p0[piece] + 0.0 * sig, y, V, V
        x, y = positions(H, Vb, w, EA, sig, np)  # the one closure's hanging piece
        return self._x_p0[piece] + x, self._y_p0[piece] + y, np.hypot(H, V), V

    def _grounded(self, s, seg):
        st = self._st
        k = st.k
        i = np.minimum(seg, k)
        up = self._s0[i] + st.l_g[i]  # upper end of the grounded piece
        d = np.maximum(up - s, 0.0)
        T_u, m, EA = st.T_g[i], st.m_g[i], self.line.arrays.EA[i]
        T = np.maximum(T_u - m * d, 0.0)
        x_up = self._x_g0[i] + self._g_str[i] * self._spread
        back = d * self._spread + self._grounded_stretch(T_u, m, d, EA)
        return x_up - back, T

    def _maps(self, s):
        """``x, y, T`` at the checked arc lengths ``s``, and the tangent's angle above the horizontal."""
        s = self._arc(s)
        self._expand()
        grounded, seg, piece = self._locate(s)
        x, y, T, V = self._suspended(s, piece)
        angle = np.arctan2(V, self._st.H)  # pi/2 on a heap state's vertical part
        if self._st.contact:
            xg, Tg = self._grounded(s, seg)
            x = np.where(grounded, xg, x)
            y = np.where(grounded, 0.0, y)
            T = np.where(grounded, Tg, T)
            angle = np.where(grounded, 0.0, angle)
        return x, y, T, angle

    def x_of_s(self, s):
        """Abscissa (m) of the material point at unstretched arc length ``s`` from A."""
        return _out(self._maps(s)[0])

    def y_of_s(self, s):
        """Height above A (m) of the material point ``s`` (the seabed's on the grounded part)."""
        return _out(self._maps(s)[1])

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A; at a joint, that of the segment above it."""
        return _out(self._maps(s)[2])

    def xy(self, s):
        """Positions ``(..., 2)`` (m) of the material points at unstretched arc length ``s`` from A."""
        x, y = self._maps(s)[:2]
        return np.stack(np.broadcast_arrays(x, y), axis=-1)

    def outline(self, n=200):
        """Positions ``(m, 2)`` (m) of ``n`` points evenly spaced in unstretched arc length, plus the
        joints and the touchdown, sorted along the line (the grounded part on the seabed): the
        points to draw it with its corners (``profile(n)`` has exactly ``n``)."""
        n = whole("n", n, 2)
        self._expand()
        st = self._st
        s = np.concatenate([np.linspace(0.0, self.length, max(n, 2)), self._s0, [self._s0[st.k] + st.a]])
        s = np.unique(np.clip(s, 0.0, self.length))
        x, y = self._maps(s)[:2]
        return np.column_stack([x, y])

    def samples(self, n: int = 201) -> dict:
        """``n`` points evenly spaced in unstretched arc length, the input of `to_vtk`: ``xy`` (n, 2)
        m, ``tension`` (N), ``angle`` (rad above the horizontal), ``load`` (n, 2) N/m (the segments'
        weight; the point forces at the joints are not included)."""
        s = np.linspace(0.0, self.length, whole("n", n, 2))
        arrays = self.line.arrays
        w = arrays.w[np.clip(np.searchsorted(arrays.s_joint, s, side="right") - 1, 0, arrays.n - 1)]
        x, y, T, angle = self._maps(s)
        return arc_samples(x, y, T, angle, w)

    def to_vtk(self, path, n: int = 201):
        """Write the profile as a VTK polyline (see `skcable.io.cable_mesh`); returns the path."""
        return write_profile(self, path, n)

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the closure's Jacobian
        ``∂(X, Z)/∂(H, V)`` (implicit function theorem), friction and clump regimes included.

        In a heap state (``H = 0``) only ``∂V_B/∂dh = 1/(dZ/dV)`` is not zero, ``Z(V)`` the
        height of the vertical part (``w/(1 + w l_B/EA)`` for one segment hanging ``l_B``):
        the heap side's stiffness, one-sided at the boundary (the line becomes taut again
        only when the span exceeds the slack's length on the seabed).
        """
        return np.array(self.stiffness_values()).reshape(2, 2)

    def stiffness_values(self) -> tuple[float, float, float, float]:
        """`stiffness` by rows, as Python floats: ``(k_H_span, k_H_dh, k_VB_span, k_VB_dh)``."""
        if self._st.heap:
            return 0.0, 0.0, 0.0, 1.0 / self._st.jac[3]
        j11, j12, j21, j22 = self._st.jac
        det = j11 * j22 - j12 * j21
        K = (j22 / det, -j12 / det, -j21 / det, j11 / det) if det != 0.0 else (math.inf,) * 4
        if not all(map(math.isfinite, K)):
            raise ConvergenceError("LineSolution.stiffness: the closure's Jacobian is singular here")
        return K

    @cached_property
    def _segment_table(self):
        self._expand()
        st, arrays = self._st, self.line.arrays
        n, k = arrays.n, st.k
        H = st.H
        T_low, T_up, H_seg = np.zeros(n), np.zeros(n), np.full(n, H)
        stretched, grounded = np.zeros(n), np.zeros(n)
        # suspended pieces
        Vt, Vb = st.V_top[k:], st.Vb
        ws, EAs, Ls = arrays.w[k:], arrays.EA[k:], st.L_s
        T_up[k:] = np.hypot(H, Vt)
        T_low[k:] = np.hypot(H, Vb)
        if st.heap:  # vertical: the tension rises linearly from V_b
            stretched[k:] = Ls + 0.5 * (Vt * np.abs(Vt) - Vb * np.abs(Vb)) / (ws * EAs)
        else:
            stretched[k:] = stretched_length(H, Vb, ws, EAs, Ls, np)
        if st.contact:
            grounded[: k + 1] = st.l_g
            stretched[: k + 1] += self._g_str
            T_end = np.maximum(st.T_g - st.m_g * st.l_g, 0.0)
            T_low[:k] = T_end[:k]
            T_up[:k] = st.T_g[:k]
            H_seg[:k] = st.T_g[:k]
            if st.a > 0:
                T_low[k] = T_end[k]
        return T_low, T_up, H_seg, stretched, grounded

    def tensions(self):
        """One row per segment: ``segment, length, w, EA, T_lower, T_upper, H_upper,
        stretched_length, grounded_length`` (SI units), a `pandas.DataFrame`.

        ``T_lower``/``T_upper`` are the tensions at the segment's ends towards A and B,
        ``H_upper`` its horizontal tension at the upper end (``H`` where suspended, less
        the friction below the touchdown)."""
        arrays = self.line.arrays
        T_lower, T_upper, H_upper, stretched, grounded = self._segment_table
        return segment_table(
            arrays.L, arrays.w, arrays.EA, T_lower, T_upper,
            H_upper=H_upper, stretched_length=stretched, grounded_length=grounded,
        )  # fmt: skip


def segment_table(length, w, EA, T_lower, T_upper, **columns):
    """The per-segment tension table of a line (a `pandas.DataFrame`, one row per segment from
    its anchor, or end a): ``segment``, ``length`` (m), ``w`` (N/m), ``EA`` (N), ``T_lower`` and
    ``T_upper`` (N, at the segment's ends towards the anchor and the fairlead), then ``columns``
    in their order (SI: ``T_max``, ``H_upper`` in N; ``stretched_length``, ``grounded_length`` in
    m)."""
    import pandas as pd

    T_lower, T_upper = np.asarray(T_lower, dtype=float), np.asarray(T_upper, dtype=float)
    table = {"segment": np.arange(T_lower.size), "length": length, "w": w, "EA": EA}
    return pd.DataFrame({**table, "T_lower": T_lower, "T_upper": T_upper, **columns})


def _out(value):
    return float(value) if np.ndim(value) == 0 else value
