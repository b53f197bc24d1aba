r"""The closed form of a multi-segment line at given fairlead forces: closure and Jacobian.

From the vertical component ``V`` of the tension just below the fairlead's joint and the
horizontal tension ``H`` of the suspended part, the vertical components at the ends of
each segment follow by statics, ``V_{bot,i} = V_{top,i} - w_i L_i``,
``V_{top,i-1} = V_{bot,i} - P_i``, and each suspended segment spans the elastic catenary
run and rise (H.M. Irvine, "Cable Structures", MIT Press, 1981)

.. math::
    \Delta x_i = \frac{H L_i}{EA_i} + \frac{H}{w_i}\Big(\operatorname{asinh}\frac{V_{top}}{H}
        - \operatorname{asinh}\frac{V_{bot}}{H}\Big), \qquad
    \Delta y_i = \frac{L_i (V_{top} + V_{bot})}{2 EA_i} + \frac{T_{top} - T_{bot}}{w_i}.

On a flat seabed through the anchor the line rests on it from A up to the touchdown, the
first point (from A) where the vertical force of the suspended extension becomes
non-negative: inside a segment (``V = 0``, tangent touchdown) or at a joint carrying a
clump weight that the seabed partly supports. Along the grounded part the tension falls
towards the anchor by Coulomb friction ``C_B w_i`` per unit length and ``C_B R_j`` at a
grounded clump (``R_j`` the part of its weight the seabed carries), down to
``H_A = max(H - friction, 0)``; a grounded piece of length ``\ell`` under tension ``T_u`` at
its upper end stretches by ``(T_u \ell - C_B w \ell^2/2)/EA`` (J.M. Jonkman, "Dynamics
modeling and loads analysis of an offshore floating wind turbine", NREL, 2007, applied
piece by piece). Each piece, hanging or grounded, is one segment of the one closure
(`skcable.cable.closure`: `hanging`, `grounded`); this module composes them.

`closure_state` evaluates all of it at ``(H, V)`` into a `ClosureState`: the closure
``(X, Z)``, its analytic Jacobian and the pieces the solution maps along the line.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from skcable.cable.closure import grounded, hanging

__all__ = ["ClosureState", "closure_state"]


class ClosureState:
    """The closed form of a line evaluated at fairlead forces ``(H, V)`` (SI units).

    Attributes
    ----------
    H, V : float
        Horizontal tension of the suspended part and vertical force just below the
        fairlead's joint (N).
    heap : bool
        Whether this is the heap state (``H = 0``, `skcable.mooring.segments.heap`).
    contact : bool
        Whether the line rests on the seabed from A.
    k : int
        The lowest segment that (partly) hangs; the grounded pieces are segments
        ``0 .. k-1`` and the length ``a`` of segment ``k``.
    a : float
        Grounded length of segment ``k`` (m): the tangent touchdown lies inside it.
    V_top, V_bot : ndarray or None
        Vertical force at the top and bottom of every segment (N); None for a one-segment
        line until the solution forms them.
    V_bot0 : float
        ``V_bot`` of segment 0 (N): minus the anchor's reaction where nothing touches.
    Vb, L_s, Tt, Tb, dx, dy : float or ndarray
        The suspended pieces (segments ``k ..``): vertical force at the lower end, hanging
        length, tensions at the upper and lower ends, run and rise (floats when one piece
        hangs).
    X, Z : float
        The closure: the run and rise of the line from A to B (m).
    jac : tuple of float
        ``(∂X/∂H, ∂X/∂V, ∂Z/∂H, ∂Z/∂V)``.
    l_g, T_g, R, stretch : list of float or None
        The grounded pieces ``0 .. k``: unstretched lengths (m), tensions at their upper
        ends (N), the seabed's reactions at the joints (N, index ``j``) and elongations (m).
    m_g : ndarray
        Friction force per unit length of each grounded piece (N/m), set by the solution.
    H_A : float
        Horizontal tension at the anchor (N).
    """

    __slots__ = (
        "H", "V", "k", "a", "V_top", "V_bot", "V_bot0", "Vb", "L_s", "Tt", "Tb", "dx", "dy", "X", "Z", "jac",
        "l_g", "T_g", "m_g", "R", "stretch", "contact", "H_A", "heap",
    )  # fmt: skip
    # the slots' types, for mypy (floats or arrays of the segments: Any)
    H: float
    V: float
    k: int
    a: float
    V_top: Any
    V_bot: Any
    V_bot0: float
    Vb: Any
    L_s: Any
    Tt: Any
    Tb: Any
    dx: Any
    dy: Any
    X: float
    Z: float
    jac: tuple
    l_g: Any
    T_g: Any
    m_g: Any
    R: Any
    stretch: Any
    contact: bool
    H_A: float
    heap: bool


def _split(arrays, contact, V, st):
    """The touchdown segment ``k`` and the vertical forces of a line at ``V``, or None when
    the whole line would lie on the seabed. Returns ``contact, k, V_top, V_bot, V_bot_k,
    V_top_k`` and sets ``st.V_bot0``."""
    if arrays.n == 1:  # one segment: Python floats throughout
        V_top = V_bot = None  # not needed here; LineSolution forms them
        V_bot_k = st.V_bot0 = V - arrays.wL_list[0]
        contact = contact and V_bot_k < 0
        if contact and not V > 0:
            return None  # the whole line would lie on the seabed
        return contact, 0, V_top, V_bot, V_bot_k, V
    V_top = V - arrays.load_above
    V_bot = V_top - arrays.wL
    st.V_bot0 = float(V_bot[0])
    contact = contact and V_bot[0] < 0
    if contact:
        up = np.flatnonzero(V_top > 0)
        if up.size == 0:
            return None  # the whole line would lie on the seabed
        k = int(up[0])
    else:
        k = 0
    return contact, k, V_top, V_bot, float(V_bot[k]), float(V_top[k])


def _suspended(arrays, H, k, a, touchdown, V_top, V_bot, V_bot_k, V_top_k, st):
    """Run, rise and their Jacobian of the suspended pieces ``k .. n-1``, each a hanging piece of
    the one closure (`skcable.cable.closure.hanging`; a tangent touchdown inside piece ``k``
    starts it at ``V_b = 0``, ``a`` from its lower end, its length growing with ``V``).
    Returns ``X, Z, jxh, jxv, jzh, jzv`` and keeps the pieces in ``st``."""
    n = arrays.n
    if k == n - 1:  # one suspended piece: Python floats
        Vb, Ls, w = (0.0 if touchdown else V_bot_k), arrays.L_list[k] - a, arrays.w_list[k]
        dx, dy, x_h, y_h, y_v, x_l, y_l, Tb, Tt = hanging(H, Vb, w, arrays.EA_list[k], Ls)
        x_v = y_h  # ∂x/∂V_b = ∂y/∂H
        if touchdown:  # V_b = 0, L_s = V_t/w: the columns in V are those in L over w
            x_v, y_v = x_l / w, y_l / w
        st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = Vb, Ls, Tt, Tb, dx, dy
        return dx, dy, x_h, x_v, y_h, y_v
    Vb, Ls, w = V_bot[k:].copy(), arrays.L[k:].copy(), arrays.w[k:]
    if touchdown:
        Vb[0] = 0.0
        Ls[0] -= a
    dx, dy, x_h, x_v, y_v, x_l, y_l, Tb, Tt = hanging(H, Vb, w, arrays.EA[k:], Ls, np)
    y_h = x_v.copy()
    if touchdown:
        x_v[0], y_v[0] = x_l[0] / w[0], y_l[0] / w[0]
    st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = Vb, Ls, Tt, Tb, dx, dy
    return tuple(float(v.sum()) for v in (dx, dy, x_h, x_v, y_h, y_v))


def _grounded(arrays, mu, H, k, a, vk, X, jxh, jxv, st):
    """Walk the grounded pieces ``k, k-1, .. 0`` from the touchdown towards the anchor,
    with the tension ``T`` and its derivatives ``(dT_h, dT_v)`` in ``(H, V)`` at the upper end
    of each piece (each a grounded piece of the one closure, `skcable.cable.closure.grounded`);
    adds their run to ``X`` and its derivatives. Returns ``X, jxh, jxv`` and
    keeps the pieces and ``H_A`` in ``st``."""
    Lf, wf, EAf = arrays.L_list, arrays.w_list, arrays.EA_list
    l_g = [*Lf[:k], a]
    T_g = [0.0] * (k + 1)  # tension at each grounded piece's upper end
    stretch = [0.0] * (k + 1)  # elongation of each grounded piece
    R = [0.0, *arrays.P_list[1 : k + 1]]  # seabed reaction at joints 1..k (index j)
    if k > 0:
        R[k] = arrays.P_list[k] - max(vk, 0.0)
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
        stretch[i], e_T, e_l, T_low = grounded(T, l, m, EAf[i])
        X += l + stretch[i]
        jxh += e_T * dT_h
        jxv += dl_v + e_T * dT_v + e_l * dl_v
        if m == 0 or T_low > 0:  # the tension reaches the piece's lower end
            T, dT_v = T_low, dT_v - m * dl_v
        else:
            T, dT_h, dT_v = 0.0, 0.0, 0.0
    st.l_g, st.T_g, st.R, st.stretch = l_g, T_g, R, stretch
    st.H_A = T
    return X, jxh, jxv


def closure_state(arrays, friction, contact, H, V):
    """Closure ``(X, Z)`` and its Jacobian in ``(H, V)`` at fairlead forces ``(H, V)``.

    ``arrays`` is the line's `LineArrays`, ``friction`` its Coulomb coefficient and
    ``contact`` whether it may rest on a seabed through the anchor. Returns a
    `ClosureState`, or None where the whole line would lie on the seabed.

    The suspended pieces are evaluated with NumPy over the segments, or on Python floats
    when a single piece hangs (`skcable._xp`: one formula, two back ends); the
    grounded pieces are walked from the touchdown to the anchor with Python floats
    (the tension at each piece's lower end depends on the piece above it)."""
    st = ClosureState()
    st.H, st.V, st.heap = H, V, False
    split = _split(arrays, contact, V, st)
    if split is None:
        return None
    contact, k, V_top, V_bot, V_bot_k, V_top_k = split
    st.contact, st.k = contact, k
    a = 0.0
    touchdown = contact and V_bot_k < 0
    if touchdown:
        a = -V_bot_k / arrays.w_list[k]
    st.a = a
    X, Z, jxh, jxv, jzh, jzv = _suspended(arrays, H, k, a, touchdown, V_top, V_bot, V_bot_k, V_top_k, st)
    if contact:
        X, jxh, jxv = _grounded(arrays, friction, H, k, a, V_bot_k, X, jxh, jxv, st)
    else:
        st.l_g = st.T_g = st.R = st.stretch = None
        st.H_A = H
    st.V_top, st.V_bot = V_top, V_bot
    st.X, st.Z, st.jac = X, Z, (jxh, jxv, jzh, jzv)
    return st
