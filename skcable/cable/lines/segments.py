r"""Multi-segment mooring lines with clump weights and buoys, in closed form.

A line runs from the anchor A = (0, 0) to the fairlead B = (span, dh) through
segments ``0 .. n-1`` (from A), each an elastic catenary with its own
unstretched length ``L_i``, weight in water per unstretched length ``w_i > 0``
and axial stiffness ``EA_i``. Joint ``j`` lies between segments ``j-1`` and
``j`` (joint 0 is A, joint n is B) and may carry a point force ``P_j``
(downward positive: a clump weight ``P_j = W``, a buoy ``P_j = -B``).

With no horizontal point load the horizontal tension ``H`` of the suspended
part is the same in every segment. From the vertical component ``V`` of the
tension at the fairlead (just below joint n) the vertical components at the
ends of each segment follow by statics, ``V_{bot,i} = V_{top,i} - w_i L_i``,
``V_{top,i-1} = V_{bot,i} - P_i``, and each suspended segment spans the
elastic catenary run and rise (H.M. Irvine, "Cable Structures", MIT Press,
1981)

.. math::
    \Delta x_i = \frac{H L_i}{EA_i} + \frac{H}{w_i}\Big(\operatorname{asinh}\frac{V_{top}}{H}
        - \operatorname{asinh}\frac{V_{bot}}{H}\Big), \qquad
    \Delta y_i = \frac{L_i (V_{top} + V_{bot})}{2 EA_i} + \frac{T_{top} - T_{bot}}{w_i}.

On a flat seabed through the anchor (``seabed=0``) the line rests on it from
A up to the touchdown, the first point (from A) where the vertical force of
the suspended extension ``V_{ext}(s)`` becomes non-negative: inside a segment
(``V = 0``, tangent touchdown) or at a joint carrying a clump weight that the
seabed partly supports. Along the grounded part the tension falls towards the
anchor by Coulomb friction ``C_B w_i`` per unit length and ``C_B R_j`` at a
grounded clump (``R_j`` the part of its weight the seabed carries), down to
``H_A = max(H - friction, 0)``; the grounded length ``\ell`` of a piece under
tension ``T_u`` at its upper end stretches by ``(T_u \ell - C_B w \ell^2/2)/EA``
(J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore floating
wind turbine", NREL, 2007, applied piece by piece).

The closure ``X(H, V) = span``, ``Z(H, V) = dh`` is solved by Newton's method
with its analytic Jacobian, from a previous solution (a warm start), else from
the uniform line of the same length, weight and compliance, else from nested
bracketing (``Z`` increases with ``V`` at fixed ``H``; then ``X`` in ``H``); every
path ends polishing the same root to round-off. The fairlead stiffness is the
inverse of that Jacobian (implicit function theorem).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, positive, real, require, scalar, whole
from skcable._xp import scalar_math
from skcable.cable._roots import find_root
from skcable.cable._special import asinh_diff
from skcable.cable.lines.seabed import elastic_catenary
from skcable.errors import ConvergenceError, InputError

__all__ = ["Buoy", "ClumpWeight", "Line", "LineSolution", "Segment"]

_TOL = 1e-13


class Segment:
    """A uniform segment of a mooring line.

    Parameters
    ----------
    length : float
        Unstretched length (m), > 0.
    w : float
        Weight in water per unstretched length (N/m), > 0 (a segment lighter
        than water is a buoyant line: model its buoyancy with `Buoy` at joints).
    EA : float
        Axial stiffness (N), > 0.
    """

    __slots__ = ("length", "w", "EA")

    def __init__(self, length, w, EA):
        self.length = scalar("length", positive("length", length))
        self.w = scalar("w", positive("w", w))
        self.EA = scalar("EA", positive("EA", EA))
        _plausible.stiffness(self.EA, self.w, self.length)

    def __repr__(self):
        return f"Segment(length={self.length!r}, w={self.w!r}, EA={self.EA!r})"


class ClumpWeight:
    """A clump weight at ``joint`` (0 = anchor, n = fairlead): a downward force ``weight`` (N, > 0)
    in water."""

    __slots__ = ("joint", "weight")

    def __init__(self, joint, weight):
        self.joint = _joint_index(joint)
        self.weight = scalar("weight", positive("weight", weight))

    @property
    def force(self):
        """Downward force on the joint (N)."""
        return self.weight

    def __repr__(self):
        return f"ClumpWeight(joint={self.joint}, weight={self.weight!r})"


class Buoy:
    """A buoy at ``joint`` (0 = anchor, n = fairlead): a net upward force ``buoyancy`` (N, > 0)."""

    __slots__ = ("joint", "buoyancy")

    def __init__(self, joint, buoyancy):
        self.joint = _joint_index(joint)
        self.buoyancy = scalar("buoyancy", positive("buoyancy", buoyancy))

    @property
    def force(self):
        """Downward force on the joint (N), negative."""
        return -self.buoyancy

    def __repr__(self):
        return f"Buoy(joint={self.joint}, buoyancy={self.buoyancy!r})"


def _joint_index(joint):
    if isinstance(joint, (bool, np.bool_)) or not isinstance(joint, (int, np.integer)):
        raise InputError("joint", f"must be an integer joint index, got {joint!r}")
    if joint < 0:
        raise InputError("joint", f"must be >= 0 (0 is the anchor), got {joint}")
    return int(joint)


class _State:
    """The closed form evaluated at ``(H, V)``: closure, Jacobian and the pieces."""

    __slots__ = (
        "H", "V", "k", "a", "V_top", "V_bot", "V_bot0", "Vb", "L_s", "Tt", "Tb", "dx", "dy", "X", "Z", "jac",
        "l_g", "T_g", "m_g", "R", "stretch", "contact", "H_A", "heap",
    )  # fmt: skip


class Line:
    """A mooring line of segments in series, with clump weights and buoys at the joints.

    Parameters
    ----------
    segments : sequence of Segment
        From the anchor (segment 0) to the fairlead.
    attachments : sequence of ClumpWeight or Buoy, optional
        Point forces at the joints; joint ``j`` joins segments ``j-1`` and ``j``,
        joint 0 is the anchor A, joint ``n = len(segments)`` the fairlead B. A force
        at an end joint is carried by the support there (it enters ``V_A`` or ``V_B``).
        Several attachments at one joint add up.
    seabed : float, optional
        Height of a flat seabed relative to A (m), ``<= 0``, as in `elastic_catenary`.
        With ``seabed=0`` the line may rest on it from A up to a touchdown; with
        ``seabed < 0`` the line must stay clear of it (a touchdown between A and B
        raises).
    friction : float, optional
        Coulomb coefficient ``C_B >= 0`` of the grounded part (only with ``seabed``).
    """

    def __init__(self, segments, attachments=(), *, seabed=None, friction=0.0):
        for name, value in (("segments", segments), ("attachments", attachments)):
            if isinstance(value, (Segment, ClumpWeight, Buoy)) or not hasattr(value, "__iter__"):
                raise InputError(name, f"must be a sequence (a list) of them, got {value!r}")
        segments, attachments = list(segments), list(attachments)
        if not segments or not all(isinstance(s, Segment) for s in segments):
            raise InputError("segments", "must be a non-empty sequence of cable.Segment")
        n = len(segments)
        if not all(isinstance(a, (ClumpWeight, Buoy)) for a in attachments):
            raise InputError("attachments", "must be cable.ClumpWeight or cable.Buoy objects")
        P = np.zeros(n + 1)
        for att in attachments:
            if att.joint > n:
                raise InputError("joint", f"{att!r}: joint must lie in [0, {n}] for {n} segments")
            P[att.joint] += att.force
        if seabed is None:
            friction = 0.0 if friction is None else friction
            if real("friction", friction) != 0.0:
                raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
        else:
            seabed = scalar("seabed", seabed)
            require("seabed", seabed <= 0, "must be at or below the anchor (A at height 0)", seabed)
        self.friction = scalar("friction", nonnegative("friction", friction))
        self.seabed = seabed
        self.segments = tuple(segments)
        self.attachments = tuple(attachments)
        self._L = np.array([s.length for s in segments])
        self._w = np.array([s.w for s in segments])
        self._EA = np.array([s.EA for s in segments])
        # the same as Python floats, for the scalar parts of the closed form
        self._Lf = [float(s.length) for s in segments]
        self._wf = [float(s.w) for s in segments]
        self._EAf = [float(s.EA) for s in segments]
        self._wL = self._w * self._L
        self._wLf = self._wL.tolist()
        self._Pf = P.tolist()
        self._weight = float(self._w @ self._L + P.sum())
        self._length = float(self._L.sum())
        self._P_end = (float(P[0]), float(P[n]))
        self._weight_segments = float(self._w @ self._L)
        self._abs_joint_forces = float(np.abs(P).sum())
        self._no_ground = np.zeros(1)
        self._no_ground.flags.writeable = False
        self._s0 = np.concatenate([[0.0], np.cumsum(self._L)])
        self._s0.flags.writeable = False
        self.joint_forces = P
        """Downward point force at each joint (N), ``n + 1`` values (buoys negative)."""
        # load between the top of segment i and the fairlead (joint n excluded)
        c = P[1:n] + self._w[1:] * self._L[1:]
        self._Q_top = np.append(np.cumsum(c[::-1])[::-1], 0.0)
        self._contact = seabed is not None and seabed == 0.0
        self._buoyed = bool((P[1:n] < 0).any())  # buoys between the ends

    @property
    def length(self):
        """Total unstretched length (m)."""
        return self._length

    @property
    def weight(self):
        """Total weight in water of the segments and the attachments (N)."""
        return self._weight

    def __repr__(self):
        return (
            f"Line(segments={list(self.segments)!r}, attachments={list(self.attachments)!r}, "
            f"seabed={self.seabed!r}, friction={self.friction!r})"
        )

    # -- the closed form ----------------------------------------------------------------
    def _state(self, H, V):
        """Closure ``(X, Z)`` and its Jacobian in ``(H, V)`` at fairlead forces ``(H, V)``.

        The suspended pieces are evaluated with NumPy over the segments, or with `math`
        when a single piece hangs (`skcable._xp`: one formula, two back ends); the
        grounded pieces are walked from the touchdown to the anchor with Python floats
        (the tension at each piece's lower end depends on the piece above it)."""
        L, w, EA, mu = self._L, self._w, self._EA, self.friction
        st = _State()
        st.H, st.V, st.heap = H, V, False
        n = len(L)
        if n == 1:  # one segment: Python floats throughout
            V_top = V_bot = None  # not needed here; LineSolution forms them
            V_bot_k = st.V_bot0 = V - self._wLf[0]
            contact = self._contact and V_bot_k < 0
            if contact and not V > 0:
                return None  # the whole line would lie on the seabed
            k = 0
            V_top_k = V
        else:
            V_top = V - self._Q_top
            V_bot = V_top - self._wL
            st.V_bot0 = float(V_bot[0])
            contact = self._contact and V_bot[0] < 0
            if contact:
                up = np.flatnonzero(V_top > 0)
                if up.size == 0:
                    return None  # the whole line would lie on the seabed
                k = int(up[0])
            else:
                k = 0
            V_bot_k, V_top_k = float(V_bot[k]), float(V_top[k])
        st.contact, st.k = contact, k
        # suspended pieces k .. n-1; a tangent touchdown inside piece k (contact, V_bot < 0)
        # starts it at V = 0, a length a = -V_bot/w from its lower end
        a = 0.0
        touchdown = contact and V_bot_k < 0
        if touchdown:
            a = -V_bot_k / self._wf[k]
        st.a = a
        if k == n - 1:  # one suspended piece: Python floats
            xp = scalar_math
            Vt, Vb, Ls = V_top_k, (0.0 if touchdown else V_bot_k), self._Lf[k] - a
            ws, EAs, dVb = self._wf[k], self._EAf[k], (0.0 if touchdown else 1.0)
        else:
            xp = np
            Vt, Vb, Ls = V_top[k:], V_bot[k:].copy(), L[k:].copy()
            ws, EAs, dVb = w[k:], EA[k:], np.ones(n - k)
            if touchdown:
                Vb[0], dVb[0] = 0.0, 0.0
                Ls[0] -= a
        Tt, Tb = xp.hypot(H, Vt), xp.hypot(H, Vb)
        ad = asinh_diff(Vt / H, Vb / H)
        dx = H * Ls / EAs + H / ws * ad
        dy = Ls * (Vt + Vb) / (2.0 * EAs) + (Vt - Vb) * (Vt + Vb) / ((Tt + Tb) * ws)
        x_h = Ls / EAs + ad / ws - (Vt / Tt - Vb / Tb) / ws
        x_v = H / ws * (1.0 / EAs + 1.0 / Tt) - dVb * H / ws * (1.0 / EAs + 1.0 / Tb)
        y_h = H * (Tb - Tt) / (Tt * Tb * ws)
        y_v = Vt * (1.0 / Tt + 1.0 / EAs) / ws - dVb * Vb * (1.0 / Tb + 1.0 / EAs) / ws
        if xp is np:
            X, Z = float(dx.sum()), float(dy.sum())
            jxh, jxv, jzh, jzv = float(x_h.sum()), float(x_v.sum()), float(y_h.sum()), float(y_v.sum())
        else:
            X, Z, jxh, jxv, jzh, jzv = dx, dy, x_h, x_v, y_h, y_v
        st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = Vb, Ls, Tt, Tb, dx, dy
        # grounded pieces k, k-1, .. 0 from the touchdown towards the anchor; T and its
        # derivatives (dT_h, dT_v) in (H, V) at the upper end of each piece
        if contact:
            Lf, wf, EAf = self._Lf, self._wf, self._EAf
            l_g = [*Lf[:k], a]
            T_g = [0.0] * (k + 1)  # tension at each grounded piece's upper end
            stretch = [0.0] * (k + 1)  # elongation of each grounded piece
            R = [0.0, *self._Pf[1 : k + 1]]  # seabed reaction at joints 1..k (index j)
            vk = V_bot_k
            if k > 0:
                R[k] = self._Pf[k] - max(vk, 0.0)
            T, dT_h, dT_v = H, 1.0, 0.0
            for i in range(k, -1, -1):
                if i < k:  # the joint above piece i (joint i+1)
                    Rj = R[i + 1]
                    if Rj > 0:
                        T = T - mu * Rj
                        if i + 1 == k and vk > 0:  # dR/dV = -1
                            dT_v = dT_v + mu
                    if T <= 0:
                        T, dT_h, dT_v = 0.0, 0.0, 0.0
                T_g[i] = T
                l = l_g[i]
                dl_v = -1.0 / wf[k] if (i == k and a > 0) else 0.0
                m = mu * wf[i]
                if m == 0 or T - m * l > 0:
                    stretch[i] = (T * l - 0.5 * m * l * l) / EAf[i]
                    X += l + stretch[i]
                    jxh += dT_h * l / EAf[i]
                    jxv += dl_v + (dT_v * l + T * dl_v - m * l * dl_v) / EAf[i]
                    T, dT_v = T - m * l, dT_v - m * dl_v
                else:
                    stretch[i] = 0.5 * T * T / (m * EAf[i])
                    X += l + stretch[i]
                    jxh += T * dT_h / (m * EAf[i])
                    jxv += dl_v + T * dT_v / (m * EAf[i])
                    T, dT_h, dT_v = 0.0, 0.0, 0.0
            st.l_g, st.T_g, st.R, st.stretch = l_g, T_g, R, stretch
            st.H_A = T
        else:
            st.l_g = st.T_g = st.R = st.stretch = None
            st.H_A = H
        st.V_top, st.V_bot = V_top, V_bot
        st.X, st.Z, st.jac = X, Z, (jxh, jxv, jzh, jzv)
        return st

    # -- the heap state: H = 0, the part from B hangs vertically, the slack lies on the seabed --
    def _vertical(self, V):
        """The part hanging vertically (``H = 0``) from B with tension ``V`` just below B:
        ``(Z, dZ/dV, k, a, V_top, V_bot)``, or None when it would lift the anchor.

        Walking down from B, the tension falls by ``w_i`` per unit length and by the
        clump weight ``P_j`` at a joint; the part reaches the seabed where it falls to 0,
        inside segment ``k`` (``a`` above its lower end) or at joint ``k`` (``a = 0``, the
        clump there partly carried by the seabed). A piece with end tensions
        ``V_bot <= V_top = V_bot + w L`` is ``L (1 + (V_top + V_bot)/(2 EA))`` tall."""
        V_top = V - self._Q_top
        V_bot = V_top - self._wL
        if V_bot[0] >= 0.0:
            return None  # the whole line would hang from B: the anchor lifted, no heap
        up = np.flatnonzero(V_top > 0)
        if up.size == 0:
            return 0.0, 0.0, len(self._L) - 1, self._Lf[-1], V_top, V_bot  # nothing hangs
        k = int(up[0])
        Vb = V_bot[k:].copy()
        Ls = self._L[k:].copy()
        dVb = np.ones_like(Vb)
        a = 0.0
        if Vb[0] < 0:  # the foot inside segment k, a above its lower end
            a = -float(Vb[0]) / self._wf[k]
            Vb[0], dVb[0], Ls[0] = 0.0, 0.0, Ls[0] - a
        Vt, EA, w = V_top[k:], self._EA[k:], self._w[k:]
        Z = float(np.sum(Ls * (1.0 + 0.5 * (Vt + Vb) / EA)))
        dZ = float(np.sum((1.0 + Vt / EA) / w - dVb * (1.0 + Vb / EA) / w))
        return Z, dZ, k, a, V_top, V_bot

    def _heap(self, span, dh):
        """The heap state at ``(span, dh)`` (a `_State` with ``H = 0``), or None when the
        line is taut there (``H > 0``): the grounded length is shorter than the span."""
        if not self._contact:
            return None
        # necessary: the slack covers the span, and the vertical part is at least dh
        # stretched by the whole weight (a cheap test before the root search)
        EA_min, W = min(self._EAf), self._weight_segments + max(self._abs_joint_forces, 0.0)
        if self._length - dh / (1.0 + W / EA_min) < span:
            return None
        V_all = float(self._Q_top[0] + self._wL[0])  # V at which the anchor would lift
        top = self._vertical(V_all * (1.0 - 1e-15))
        if top is None or top[0] <= dh:
            return None

        def height(V):
            return self._vertical(V)[0] - dh

        if height(0.0) >= 0:  # buoys hold the line up even with no pull at B: no heap state
            return None
        V, _ = find_root(height, 0.0, V_all * (1.0 - 1e-15), what="Line.solve, heap", xtol=1e-15 * V_all)
        for _ in range(3):  # Newton polish on the piecewise quadratic Z(V), kept in the bracket
            Z, dZ = self._vertical(V)[:2]
            polished = V - (Z - dh) / dZ if dZ > 0 else V
            if not 0.0 <= polished < V_all * (1.0 - 1e-15) or self._vertical(polished) is None:
                break
            V = polished
        Z, dZ, k, a, V_top, V_bot = self._vertical(V)
        grounded = float(self._s0[k]) + a
        if grounded < span:
            return None  # taut: H > 0
        buoys = np.flatnonzero(self.joint_forces[1:-1] < 0) + 1
        if buoys.size:
            raise InputError(
                "attachments",
                f"a buoy at joint {int(buoys[0])} in a line whose slack lies in a heap on the seabed "
                "(H = 0): it would lift slack off the seabed, which this closed form does not represent "
                "(solve it with cable.solve_line_bvp)",
            )
        st = _State()
        st.H, st.V, st.k, st.a, st.contact, st.heap = 0.0, V, k, a, True, True
        st.V_top, st.V_bot, st.V_bot0 = V_top, V_bot, float(V_bot[0])
        Vb, Ls = V_bot[k:].copy(), self._L[k:].copy()
        if a > 0:
            Vb[0], Ls[0] = 0.0, Ls[0] - a
        st.Vb, st.L_s, st.Tt, st.Tb = Vb, Ls, V_top[k:].copy(), Vb.copy()
        st.dx = np.zeros_like(Vb)
        st.dy = Ls * (1.0 + 0.5 * (st.Tt + Vb) / self._EA[k:])
        if k == len(self._L) - 1:  # one piece hangs: Python floats, as `_state` keeps them
            pieces = (Vb, Ls, st.Tt, st.Tb, st.dx, st.dy)
            st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = (float(v[0]) for v in pieces)
        st.X, st.Z = span, Z  # the slack fills the span (an inequality, checked in residual())
        st.jac = (0.0, 0.0, 0.0, dZ)
        st.l_g = [*self._Lf[:k], a]
        st.T_g = [0.0] * (k + 1)
        st.stretch = [0.0] * (k + 1)
        st.R = [0.0, *self._Pf[1 : k + 1]]
        if k > 0 and a == 0.0:  # a clump at the foot, partly carried by the seabed
            st.R[k] = self._Pf[k] - max(float(V_bot[k]), 0.0)
        st.H_A = 0.0
        return st

    def _trial_state(self, H, V):
        """`_state` at a Newton iterate, None where it is no state: ``H <= 0``, the whole line
        on the seabed, or forces so small that a product of them underflows to a division
        by zero (the Python floats of a one-segment line raise there)."""
        if not H > 0:
            return None
        try:
            return self._state(H, V)
        except ZeroDivisionError:
            return None

    def _height_of_v(self, H, dh):
        """``V`` with ``Z(H, V) = dh`` (``Z`` increases with ``V``), by bracketing."""
        scale = float(self._w @ self._L + np.abs(self.joint_forces).sum())

        def f(V):
            st = self._state(H, V)
            return -dh if st is None else st.Z - dh

        lo = -scale  # V < 0: the fairlead holds a buoyant line down
        while f(lo) > 0:
            lo *= 2.0
            if lo < -1e12 * scale:
                raise ConvergenceError("Line.solve: no bracket for the fairlead's vertical force")
        hi = scale
        while f(hi) < 0:
            hi *= 2.0
            if hi > 1e12 * scale:
                raise ConvergenceError("Line.solve: no bracket for the fairlead's vertical force")
        if f(lo) >= 0:
            return lo
        return find_root(lambda v: f(v), lo, hi, what="Line.solve, V at fixed H", xtol=1e-12 * hi)[0]

    def _guess(self, span, dh):
        """``(H, V)`` of the uniform line of the same length, weight and compliance, or None."""
        L = self.length
        W = float(self._w @ self._L + self.joint_forces[1:-1].sum())
        w = W / L if W > 0 else float(self._w @ self._L) / L
        EA = L / float(np.sum(self._L / self._EA))
        seabed = 0.0 if self._contact else None
        try:
            ref = elastic_catenary(span, dh, w, EA, length=L, seabed=seabed, friction=0.0)
        except (InputError, ConvergenceError):
            return None
        return float(ref.H), float(ref.V_B)

    def _newton(self, span, dh, H, V, chord, iterations, state=None):
        """Newton's method with the analytic Jacobian and backtracking on ``max|residual|``.

        Works on Python floats: the 2x2 step by Cramer's rule (a singular or non-finite
        step ends the iteration; the caller checks the residual reached). ``state``: the
        closed form already evaluated at ``(H, V)`` (a previous solution's)."""
        H, V = float(H), float(V)
        st = self._trial_state(H, V) if state is None else state
        if st is None:
            return None, np.inf, []
        norm = max(abs(st.X - span), abs(st.Z - dh)) / chord
        history = [norm]
        for _ in range(iterations):
            if norm < _TOL:
                break
            j11, j12, j21, j22 = st.jac
            r1, r2 = st.X - span, st.Z - dh
            det = j11 * j22 - j12 * j21
            if not (det != 0.0 and math.isfinite(det)):
                break
            step_H = -(r1 * j22 - r2 * j12) / det
            step_V = -(j11 * r2 - j21 * r1) / det
            if not (math.isfinite(step_H) and math.isfinite(step_V)):
                break
            t = 1.0
            for _ in range(30):
                H_new, V_new = H + t * step_H, V + t * step_V
                new = self._trial_state(H_new, V_new)
                if new is not None:
                    new_norm = max(abs(new.X - span), abs(new.Z - dh)) / chord
                    if new_norm < norm:  # False for NaN
                        break
                t *= 0.5
            else:
                break
            H, V, st, norm = H_new, V_new, new, new_norm
            history.append(norm)
        if st is state:  # no step from a previous solution's state: a state of its own
            st = self._state(H, V)
        return st, norm, history

    def _bracketed(self, span, dh):
        """``(H, V)`` by nested bracketing: ``V(H)`` from the height, then ``H`` from the run."""
        W = float(self._w @ self._L)

        def x_of_h(H):
            V = self._height_of_v(H, dh)
            return self._state(H, V).X - span

        H_lo = 1e-10 * W
        if x_of_h(H_lo) >= 0:
            if self._contact:  # buoys: a heap state raises in `_heap`, else none of this form
                self._heap(span, dh)
                raise InputError(
                    "attachments",
                    "leave slack line on the seabed with H -> 0 that is no heap state of this closed "
                    "form (buoys lift it): solve it with cable.solve_line_bvp",
                )
            raise ConvergenceError("Line.solve: the run exceeds the span at H -> 0")
        H_hi = W
        while x_of_h(H_hi) < 0:
            H_hi *= 4.0
            if H_hi > 1e16 * W:
                raise InputError("span", "is out of reach of the line (tension beyond the float range)")
        H, hist = find_root(x_of_h, H_lo, H_hi, what="Line.solve, H", xtol=1e-10 * H_hi)
        return H, self._height_of_v(H, dh), hist

    def solve(self, span, dh, start=None):
        """Static equilibrium with A at (0, 0) and B at (span, dh).

        Parameters
        ----------
        span : float
            Horizontal distance A→B (m), > 0.
        dh : float
            Height of B above A (m); above the seabed when one is given.
        start : LineSolution or (float, float), optional
            A warm start: a previous solution of this line (typically at a nearby
            ``(span, dh)``, as in the Newton iterations of a moored body), or the pair
            ``(H, V_B)`` (N, ``H > 0``). Newton's method starts from its fairlead forces
            instead of from the uniform line of the same length, weight and compliance.
            If it does not converge from there, the cold path runs (Newton from the
            uniform line, then nested bracketing). This is no fallback of results:
            the closure ``X(H, V) = span``, ``Z(H, V) = dh`` has one root, every path
            polishes it to a relative residual below 1e-13 and the solution is
            checked the same way, so warm and cold solutions agree to round-off.

        Returns
        -------
        LineSolution
            With ``seabed=0`` and a line longer than its L-shape, the heap state
            (``heap`` True, ``H = 0``: the part from B hangs vertically, the slack lies
            on the seabed; see `LineSolution`).

        Raises
        ------
        InputError
            ``span``/``dh`` not finite or out of range; ``attachments`` when a buoy
            between the ends meets a line whose slack lies in a heap on the seabed, when
            a buoy would rest on the grounded part or the suspended line would dip
            to the seabed again (a second touchdown: solve it with `cable.solve_line_bvp`);
            ``seabed`` when the line would touch a seabed below the anchor; ``start``
            when it is neither a solution of this line nor a pair ``(H, V_B)`` of
            finite numbers with ``H > 0``. An elastic line always reaches B by
            stretching, so a short line is not an error.
        ConvergenceError
            Bracketing or Newton failed; carries the residual history.
        """
        span = scalar("span", positive("span", span))
        dh = scalar("dh", real("dh", dh))
        if self.seabed is not None:
            require("dh", dh > self.seabed, "must put B above the seabed", dh)
        chord = math.hypot(span, dh)
        st, norm, history = None, np.inf, []
        if start is not None:  # Newton from the previous solution (its closed form known)
            H0, V0, state = self._start(start)
            if H0 > 0:  # a heap state (H = 0) is no start for Newton
                st, norm, history = self._newton(span, dh, H0, V0, chord, 40, state)
        if not norm < 1e-11 and not self._buoyed:  # the slack in a heap on the seabed (H = 0)?
            heap = self._heap(span, dh)
            if heap is not None:
                st, norm = heap, 0.0
        if not norm < 1e-11:  # Newton from the equivalent uniform line
            guess = self._guess(span, dh)
            if guess is not None:
                st, norm, more = self._newton(span, dh, *guess, chord, 40)
                history = [*history, *more]
        if not norm < 1e-11:  # nested bracketing, then Newton polish
            H, V, hist = self._bracketed(span, dh)
            st, norm, more = self._newton(span, dh, H, V, chord, 20)
            history = [*history, *hist, *more]
        if not norm < 1e-11:
            raise ConvergenceError("Line.solve: closure not met", history)
        solution = LineSolution(self, span, dh, st)
        solution._validate()
        return solution

    def _start(self, start):
        """``(H, V, state)`` of a warm start: fairlead forces (``V`` below the fairlead's
        joint) and the closed form evaluated there (None for a pair ``(H, V_B)``)."""
        if isinstance(start, LineSolution):
            if start.line is not self:
                raise InputError("start", "is a solution of another line: give one of this line or (H, V_B)")
            return start._st.H, start._st.V, start._st
        try:
            H, V_B = start
        except (TypeError, ValueError):
            raise InputError(
                "start", f"must be a LineSolution of this line or a pair (H, V_B), got {start!r}"
            ) from None
        H = scalar("start", positive("start", H))
        V_B = scalar("start", real("start", V_B))
        return H, V_B - self._P_end[1], None


class LineSolution:
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
        self.length = line._length
        self.H = float(st.H)
        self.H_A = float(st.H_A)
        self.V_B = float(st.V + line._P_end[1])
        V_A0 = 0.0 if contact else float(st.V_bot0)
        self.V_A = float((0.0 if contact else -V_A0) + line._P_end[0])
        self.T_B = math.hypot(st.H, st.V)
        self.T_A = math.hypot(self.H_A, V_A0)
        self.joint_forces = P.copy()
        self.heap = bool(st.heap)
        if contact:  # the grounded pieces, still Python floats from the closed form
            self.length_on_seabed = float(sum(st.l_g))
            self.seabed_reaction = float(line._w[: k + 1] @ np.array(st.l_g) + sum(st.R[1:]))
            self.x_touchdown = float(sum(l + e for l, e in zip(st.l_g, st.stretch, strict=True)))
            if st.heap:
                self.x_touchdown = float(span)
        else:
            self.length_on_seabed = self.seabed_reaction = self.x_touchdown = 0.0
        if len(line._L) == 1:  # A, then B at the end of the one suspended piece
            self.x_joints = np.array([0.0, self.x_touchdown + st.dx])
            self.y_joints = np.array([0.0, st.dy])
        else:
            self._expand()

    def _expand(self):
        """The per-piece arrays of the profile (built once, when a map or the joints need them)."""
        if self._expanded:
            return
        self._expanded = True
        st, line = self._st, self.line
        k = st.k
        if st.V_top is None:
            st.V_top = st.V - line._Q_top
            st.V_bot = st.V_top - line._wL
        if not isinstance(st.Vb, np.ndarray):  # one suspended piece, kept as floats
            st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = np.array(
                [st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy], dtype=float
            ).reshape(6, 1)
        if st.contact:
            st.l_g, st.T_g, st.R, stretch = np.array([st.l_g, st.T_g, st.R, st.stretch], dtype=float)
        else:
            st.l_g = st.T_g = st.R = stretch = line._no_ground
        st.m_g = line.friction * line._w[: k + 1]
        # per-segment arrays: start of each segment along s, and of each suspended piece
        self._s0 = line._s0
        # grounded pieces: x at their lower ends, stretched lengths
        # heap: the slack spread evenly from A to the touchdown (its shape is not determined)
        self._spread = self.span / float(st.l_g.sum()) if st.heap else 1.0
        if st.contact:
            g_str = st.l_g + stretch
            x_g0 = np.concatenate([[0.0], np.cumsum(g_str * self._spread)[:-1]])
        else:
            g_str, x_g0 = line._no_ground, line._no_ground
        self._x_g0 = x_g0
        self._g_str = g_str
        # suspended pieces: segment i >= k from s_b (start on the line) with Vb
        dx, dy = st.dx, st.dy
        self._x_p0 = self.x_touchdown + np.concatenate([[0.0], np.cumsum(dx)])[:-1]
        self._y_p0 = np.concatenate([[0.0], np.cumsum(dy)])[:-1]
        self._s_p0 = self._s0[k:-1].copy()
        self._s_p0[0] += st.a
        self._Tt, self._Tb, self._dx, self._dy = st.Tt, st.Tb, dx, dy
        if len(line._L) == 1:
            return  # the joints are set
        self.x_joints = np.concatenate([x_g0, self._x_p0[1:], [self._x_p0[-1] + dx[-1]]])
        self.y_joints = np.concatenate([np.zeros(k + 1), self._y_p0[1:], [self._y_p0[-1] + dy[-1]]])
        if st.contact and st.a > 0:  # joint k lies on the seabed, the piece starts at the touchdown
            self.x_joints[k] = x_g0[k]

    def __repr__(self):
        note = "; heap: H = 0, the slack lies on the seabed" if self.heap else ""
        return (
            f"LineSolution(span={self.span:g}, dh={self.dh:g}: H={self.H:.9g}, V_A={self.V_A:.9g}, "
            f"V_B={self.V_B:.9g}, length_on_seabed={self.length_on_seabed:.9g}{note})"
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
        st, line = self._st, self.line
        chord = math.hypot(self.span, self.dh)
        closure = max(abs(st.X - self.span), abs(st.Z - self.dh)) / chord
        if st.heap:  # the slack covers the span
            closure = max(closure, max(self.span - self.length_on_seabed, 0.0) / chord)
        scale = abs(self.V_A) + abs(self.V_B) + line._weight_segments + line._abs_joint_forces
        statics = abs(self.V_A + self.V_B + self.seabed_reaction - line._weight) / scale
        geometry = max(abs(self.x_joints[-1] - self.span) / chord, abs(self.y_joints[-1] - self.dh) / chord)
        return float(max(closure, statics, geometry))

    def _validate(self):
        st, line = self._st, self.line
        values = (self.H, self.V_A, self.V_B, self.H_A, self.T_A, self.T_B, self.length_on_seabed)
        if not all(map(math.isfinite, values)) or not np.isfinite(self.x_joints).all():
            raise InputError("span", "gives a result outside the range of a float")
        if st.contact and st.k > 0:
            buoyed = np.flatnonzero(st.R[1:] < 0) + 1
            if buoyed.size:
                raise InputError(
                    "attachments",
                    f"a buoy at joint {int(buoyed[0])} lies on the grounded part and would lift it: a second "
                    "touchdown that this closed form does not represent (solve it with cable.solve_line_bvp)",
                )
        if line.seabed is not None:
            y_min = self._lowest_suspended()
            floor = line.seabed
            tol = 1e-9 * math.hypot(self.span, self.dh)
            if y_min < floor - tol:
                argument = "attachments" if st.contact or floor == 0.0 else "seabed"
                raise InputError(
                    argument,
                    f"the suspended line dips to {y_min:.6g} m, below the seabed at {floor:.6g} m: a "
                    "touchdown between A and B that this closed form does not represent (solve it with "
                    "cable.solve_line_bvp, or elastic_catenary for one segment)",
                )
        residual = self.residual()
        if not residual < 1e-9:
            raise ConvergenceError(f"Line.solve: residual {residual:.3e} after the solve", [residual])

    def _lowest_suspended(self):
        """Lowest height of the suspended part: its joints and the vertices inside segments."""
        st = self._st
        H, k = st.H, st.k
        start = 1 if st.contact else 0
        lowest_joint = float(self.y_joints[start:].min())
        if k == len(self.line._L) - 1:  # one suspended piece, on floats; it starts at height 0
            Vb = st.Vb if isinstance(st.Vb, float) else float(st.Vb[0])
            Vt = st.V if st.V_top is None else float(st.V_top[k])
            if not (Vb < 0 and Vt > 0):
                return lowest_joint
            w, EA = self.line._wf[k], self.line._EAf[k]
            sig = -Vb / w
            drop = sig * Vb / (2.0 * EA) + (H - math.hypot(H, Vb)) / w
            return min(lowest_joint, drop)
        Vb, Vt = st.Vb, st.V_top[k:]
        ws, EAs = self.line._w[k:], self.line._EA[k:]
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
        seg = np.clip(np.searchsorted(self._s0, s, side="right") - 1, 0, len(self.line._L) - 1)
        piece = np.clip(seg - k, 0, None)
        return grounded, seg, piece

    def _suspended(self, s, piece):
        st = self._st
        H = st.H
        k = st.k
        w, EA = self.line._w[k:][piece], self.line._EA[k:][piece]
        sig = np.maximum(s - self._s_p0[piece], 0.0)
        Vb = st.Vb[piece]
        V = Vb + w * sig
        if st.heap:  # vertical: x = span, the piece's tension rising linearly from Vb
            y = self._y_p0[piece] + sig * (1.0 + (Vb + 0.5 * w * sig) / EA)
            return self._x_p0[piece] + 0.0 * sig, y, V
        T, Tb = np.hypot(H, V), np.hypot(H, Vb)
        x = self._x_p0[piece] + H * sig / EA + H / w * asinh_diff(V / H, Vb / H)
        y = self._y_p0[piece] + sig * (Vb + 0.5 * w * sig) / EA + (V - Vb) * (V + Vb) / ((T + Tb) * w)
        return x, y, T

    def _grounded(self, s, seg):
        st = self._st
        k = st.k
        i = np.minimum(seg, k)
        up = self._s0[i] + st.l_g[i]  # upper end of the grounded piece
        d = np.maximum(up - s, 0.0)
        T_u, m, EA = st.T_g[i], st.m_g[i], self.line._EA[i]
        T = np.maximum(T_u - m * d, 0.0)
        x_up = self._x_g0[i] + self._g_str[i] * self._spread
        back = d * self._spread + self._grounded_stretch(T_u, m, d, EA)
        return x_up - back, T

    def _maps(self, s):
        s = self._arc(s)
        self._expand()
        grounded, seg, piece = self._locate(s)
        x, y, T = self._suspended(s, piece)
        if self._st.contact:
            xg, Tg = self._grounded(s, seg)
            x = np.where(grounded, xg, x)
            y = np.where(grounded, 0.0, y)
            T = np.where(grounded, Tg, T)
        return x, y, T

    def x_of_s(self, s):
        """Abscissa (m) of the material point at unstretched arc length ``s`` from A."""
        return _out(self._maps(s)[0])

    def y_of_s(self, s):
        """Height above A (m) of the material point ``s`` (the seabed's on the grounded part)."""
        return _out(self._maps(s)[1])

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A; at a joint, that of the segment above it."""
        return _out(self._maps(s)[2])

    def profile(self, n=200):
        """``(x, y)`` arrays of ``n`` points evenly spaced in unstretched arc length, plus the joints
        and the touchdown, sorted along the line (the grounded part on the seabed)."""
        n = whole("n", n, 2)
        self._expand()
        st = self._st
        s = np.concatenate([np.linspace(0.0, self.length, max(n, 2)), self._s0, [self._s0[st.k] + st.a]])
        s = np.unique(np.clip(s, 0.0, self.length))
        x, y, _ = self._maps(s)
        return x, y

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the closure's Jacobian
        ``∂(X, Z)/∂(H, V)`` (implicit function theorem), friction and clump regimes included.

        In a heap state (``H = 0``) only ``∂V_B/∂dh = 1/(dZ/dV)`` is not zero, ``Z(V)`` the
        height of the vertical part (``w/(1 + w l_B/EA)`` for one segment hanging ``l_B``):
        the heap side's stiffness, one-sided at the boundary (the line becomes taut again
        only when the span exceeds the slack's length on the seabed).
        """
        if self._st.heap:
            return np.array([[0.0, 0.0], [0.0, 1.0 / self._st.jac[3]]])
        j11, j12, j21, j22 = self._st.jac
        det = j11 * j22 - j12 * j21
        K = (j22 / det, -j12 / det, -j21 / det, j11 / det) if det != 0.0 else (math.inf,)
        if not all(map(math.isfinite, K)):
            raise ConvergenceError("LineSolution.stiffness: the closure's Jacobian is singular here")
        return np.array(K).reshape(2, 2)

    @cached_property
    def _segment_table(self):
        self._expand()
        st, line = self._st, self.line
        n, k = len(line._L), st.k
        H = st.H
        T_low, T_up, H_seg = np.zeros(n), np.zeros(n), np.full(n, H)
        stretched, grounded = np.zeros(n), np.zeros(n)
        # suspended pieces
        Vt, Vb = st.V_top[k:], st.Vb
        ws, EAs, Ls = line._w[k:], line._EA[k:], st.L_s

        def prim(v):  # ∫ sqrt(H² + v²) dv
            if st.heap:
                return 0.5 * v * np.abs(v)
            return 0.5 * (v * np.hypot(H, v) + H * H * np.arcsinh(v / H))

        T_up[k:] = np.hypot(H, Vt)
        T_low[k:] = np.hypot(H, Vb)
        stretched[k:] = Ls + (prim(Vt) - prim(Vb)) / (ws * EAs)
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
        import pandas as pd

        line = self.line
        T_low, T_up, H_seg, stretched, grounded = self._segment_table
        return pd.DataFrame(
            {
                "segment": np.arange(len(line._L)),
                "length": line._L,
                "w": line._w,
                "EA": line._EA,
                "T_lower": T_low,
                "T_upper": T_up,
                "H_upper": H_seg,
                "stretched_length": stretched,
                "grounded_length": grounded,
            }
        )


def _out(value):
    return float(value) if np.ndim(value) == 0 else value
