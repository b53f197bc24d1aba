r"""The heap state of a multi-segment line: ``H = 0``, its slack in a heap on the seabed.

A line longer than its L-shape has no solution with ``H > 0``: the part from B hangs
vertically down to the seabed and the rest lies on it without tension or stretch
(MoorPy's profile 4; H.M. Irvine, "Cable Structures", MIT Press, 1981, the elastic
catenary at ``H = 0``). Walking down from B, the tension falls by ``w_i`` per unit length
and by the clump weight ``P_j`` at a joint; the vertical part reaches the seabed where it
falls to 0. Its height ``Z(V)`` is a piecewise quadratic, increasing in the tension ``V``
just below B, solved by bracketing and polished by Newton's method.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._roots import find_root
from skcable.errors import InputError
from skcable.mooring.segments.state import ClosureState

__all__ = ["heap_state", "vertical"]


def vertical(arrays, V):
    """The part hanging vertically (``H = 0``) from B with tension ``V`` just below B:
    ``(Z, dZ/dV, k, a, V_top, V_bot)``, or None when it would lift the anchor.

    The part reaches the seabed inside segment ``k`` (``a`` above its lower end) or at
    joint ``k`` (``a = 0``, the clump there partly carried by the seabed). A piece with end
    tensions ``V_bot <= V_top = V_bot + w L`` is ``L (1 + (V_top + V_bot)/(2 EA))`` tall."""
    V_top = V - arrays.load_above
    V_bot = V_top - arrays.wL
    if V_bot[0] >= 0.0:
        return None  # the whole line would hang from B: the anchor lifted, no heap
    up = np.flatnonzero(V_top > 0)
    if up.size == 0:
        return 0.0, 0.0, arrays.n - 1, arrays.L_list[-1], V_top, V_bot  # nothing hangs
    k = int(up[0])
    Vb = V_bot[k:].copy()
    Ls = arrays.L[k:].copy()
    dVb = np.ones_like(Vb)
    a = 0.0
    if Vb[0] < 0:  # the foot inside segment k, a above its lower end
        a = -float(Vb[0]) / arrays.w_list[k]
        Vb[0], dVb[0], Ls[0] = 0.0, 0.0, Ls[0] - a
    Vt, EA, w = V_top[k:], arrays.EA[k:], arrays.w[k:]
    Z = float(np.sum(Ls * (1.0 + 0.5 * (Vt + Vb) / EA)))
    dZ = float(np.sum((1.0 + Vt / EA) / w - dVb * (1.0 + Vb / EA) / w))
    return Z, dZ, k, a, V_top, V_bot


def _height(V, arrays, dh):
    """Height of the vertical part at ``V`` less ``dh`` (m)."""
    return vertical(arrays, V)[0] - dh


def _hanging_force(arrays, span, dh):
    """The tension ``V`` just below B of a heap state at ``(span, dh)``, or None where the
    line cannot lie in a heap there (cheap tests first, then the root of `_height`)."""
    # necessary: the slack covers the span, and the vertical part is at least dh
    # stretched by the whole weight (a cheap test before the root search)
    EA_min, W = min(arrays.EA_list), arrays.segment_weight + max(arrays.abs_joint_forces, 0.0)
    if arrays.total_length - dh / (1.0 + W / EA_min) < span:
        return None
    V_all = float(arrays.load_above[0] + arrays.wL[0])  # V at which the anchor would lift
    top = vertical(arrays, V_all * (1.0 - 1e-15))
    if top is None or top[0] <= dh:
        return None
    if _height(0.0, arrays, dh) >= 0:  # buoys hold the line up even with no pull at B: no heap state
        return None
    V, _ = find_root(
        _height, 0.0, V_all * (1.0 - 1e-15), (arrays, dh), what="Line.solve, heap", xtol=1e-15 * V_all
    )
    for _ in range(3):  # Newton polish on the piecewise quadratic Z(V), kept in the bracket
        Z, dZ = vertical(arrays, V)[:2]
        polished = V - (Z - dh) / dZ if dZ > 0 else V
        if not 0.0 <= polished < V_all * (1.0 - 1e-15) or vertical(arrays, polished) is None:
            break
        V = polished
    return V


def _heap_pieces(arrays, st, span, Z, dZ, k, a, V_bot):
    """The suspended (vertical) and grounded pieces of a heap state into ``st``."""
    V_top = st.V_top
    Vb, Ls = V_bot[k:].copy(), arrays.L[k:].copy()
    if a > 0:
        Vb[0], Ls[0] = 0.0, Ls[0] - a
    st.Vb, st.L_s, st.Tt, st.Tb = Vb, Ls, V_top[k:].copy(), Vb.copy()
    st.dx = np.zeros_like(Vb)
    st.dy = Ls * (1.0 + 0.5 * (st.Tt + Vb) / arrays.EA[k:])
    if k == arrays.n - 1:  # one piece hangs: Python floats, as `closure_state` keeps them
        pieces = (Vb, Ls, st.Tt, st.Tb, st.dx, st.dy)
        st.Vb, st.L_s, st.Tt, st.Tb, st.dx, st.dy = (float(v[0]) for v in pieces)
    st.X, st.Z = span, Z  # the slack fills the span (an inequality, checked in residual())
    st.jac = (0.0, 0.0, 0.0, dZ)
    st.l_g = [*arrays.L_list[:k], a]
    st.T_g = [0.0] * (k + 1)
    st.stretch = [0.0] * (k + 1)
    st.R = [0.0, *arrays.P_list[1 : k + 1]]
    if k > 0 and a == 0.0:  # a clump at the foot, partly carried by the seabed
        st.R[k] = arrays.P_list[k] - max(float(V_bot[k]), 0.0)
    st.H_A = 0.0


def heap_state(arrays, span, dh):
    """The heap state at ``(span, dh)`` (a `ClosureState` with ``H = 0``) of a line that may
    rest on a seabed through its anchor, or None when the line is taut there (``H > 0``):
    the grounded length is shorter than the span.

    Raises `InputError` (``attachments``) for a buoy between the ends of a line whose slack
    lies in a heap: it would lift slack off the seabed."""
    V = _hanging_force(arrays, span, dh)
    if V is None:
        return None
    Z, dZ, k, a, V_top, V_bot = vertical(arrays, V)
    grounded = float(arrays.s_joint[k]) + a
    if grounded < span:
        return None  # taut: H > 0
    buoys = np.flatnonzero(arrays.P[1:-1] < 0) + 1
    if buoys.size:
        raise InputError(
            "attachments",
            f"a buoy at joint {int(buoys[0])} in a line whose slack lies in a heap on the seabed "
            "(H = 0): it would lift slack off the seabed, which this closed form does not represent "
            "(solve it with mooring.solve_line_bvp)",
        )
    st = ClosureState()
    st.H, st.V, st.k, st.a, st.contact, st.heap = 0.0, V, k, a, True, True
    st.V_top, st.V_bot, st.V_bot0 = V_top, V_bot, float(V_bot[0])
    _heap_pieces(arrays, st, span, Z, dZ, k, a, V_bot)
    return st
