r"""The heap regime: a line longer than its L-shape lies with its slack in a heap on the seabed.

With the vertical hanging lengths :math:`l = 2d/(1 + \sqrt{1 + 2 w d/EA})` over the heights
``d`` of B and A above the seabed (`skcable.cable.closure.hanging_length`, the
root of :math:`d = l + w l^2/(2EA)`), a line with :math:`X \le L - l_A - l_B` has no
solution with :math:`H > 0`: its slack lies on the seabed, :math:`H = 0`,
:math:`V_B = w l_B`, :math:`\partial V_B/\partial Z = w/(1 + w l_B/EA)` (MoorPy's slack
profiles 4 and 5; the elastic catenary of H.M. Irvine, "Cable Structures", MIT Press,
1981, at :math:`H = 0`).

The part from B hangs vertically at ``x = span`` over ``l_B``, the part from an anchor above
the seabed vertically at ``x = 0`` over ``s_1 = l_A``; the rest, ``L_B = L - l_A - l_B``,
carries no tension and does not stretch. Statics do not fix where that slack lies: the maps
below draw it spread evenly along the seabed from A to the touchdown.

The functions take the heap state's numbers (``s_1``, ``L_B``, ``w``, ``EA``, the seabed
height ``y_t`` and the span) and arc lengths ``s`` or abscissae ``x``, already checked.
"""

from __future__ import annotations

import numpy as np

from skcable.cable.solution import matrix_2x2
from skcable.errors import InputError

__all__ = [
    "as_float",
    "heap_T_of_s",
    "heap_residuals",
    "heap_s_of_x",
    "heap_slope",
    "heap_stiffness",
    "heap_x_of_s",
    "heap_y_of_s",
]


def as_float(value):
    """A 0-d result as a Python float (scalar in, scalar out)."""
    return float(value) if np.ndim(value) == 0 else value


def _sigma(s, s1, L_B):
    """Arc length (m) above the seabed on B's vertical part."""
    return np.maximum(s - s1 - L_B, 0.0)


def heap_T_of_s(s, s1, L_B, w):
    """Tension (N): each vertical part carries the weight below it down to the seabed
    (``w (s_1 - s)`` from A, ``w sigma`` at ``sigma`` above the seabed on the part from B);
    the slack on the seabed carries none."""
    sigma = _sigma(s, s1, L_B)
    return as_float(np.where(s <= s1, w * (s1 - s), np.where(s <= s1 + L_B, 0.0, w * sigma)))


def heap_x_of_s(s, s1, L_B, span):
    """Abscissa (m): the vertical parts at ``x = 0`` and ``x = span``, the slack spread
    evenly between, ``x`` linear in ``s``."""
    spread = np.clip(s - s1, 0.0, L_B) / L_B * span
    return as_float(spread + 0.0 * s)


def heap_y_of_s(s, s1, L_B, w, EA, y_t):
    """Height above A (m): the part from B carries ``w u`` at ``u`` above its foot, so the
    point ``sigma`` above the foot lies ``sigma + w sigma^2/(2 EA)`` above the seabed; the
    part from A carries ``w (s_1 - s)`` and the point ``s`` lies
    ``s + w (s_1 s - s^2/2)/EA`` below A (Irvine 1981, the elastic catenary at ``H = 0``)."""
    sigma = _sigma(s, s1, L_B)
    a = np.minimum(s, s1)
    below_A = 0.0 - (a + w * (s1 * a - 0.5 * a * a) / EA)
    above = y_t + sigma * (1.0 + 0.5 * w * sigma / EA)
    return as_float(np.where(s <= s1, below_A, np.where(s <= s1 + L_B, y_t, above)))


def heap_s_of_x(x, s1, L_B, span, length):
    """Material point (m): ``x = 0`` is A, ``x = span`` is B (the vertical parts project to
    the ends), the points between map to the slack spread evenly on the seabed."""
    spread = s1 + x / span * L_B
    return as_float(np.where(x <= 0.0, 0.0, np.where(x >= span, length, spread)))


def heap_slope(x, span, heap, V1):
    """dy/dx: 0 on the seabed; the line hangs vertically at ``x = span`` (and at ``x = 0``
    with the anchor above the seabed, ``V1 > 0``): no finite slope there, `InputError`."""
    x_b = np.broadcast_to(x, np.broadcast_shapes(np.shape(x), np.shape(span)))
    vertical = heap & ((x_b >= span) | ((x_b <= 0.0) & (V1 > 0)))
    if np.any(vertical):
        raise InputError("x", "the line hangs vertically there (slack in a heap, H = 0): no finite slope")
    return as_float(0.0 * x_b)


def heap_stiffness(w, EA, l_B):
    """``∂(H, V_B)/∂(span, dh)``: ``V_B = w l_B`` with ``dh - seabed = l_B + w l_B^2/(2EA)``,
    so ``∂V_B/∂dh = w/(1 + w l_B/EA)`` and the other three entries are 0 (N/m)."""
    k22 = w / (1.0 + w * l_B / EA)
    zero = 0.0 * k22
    return matrix_2x2(zero, zero, zero, k22)


def heap_residuals(xp, span, dh, w, EA, y_t, l_A, l_B, L_B, length, forces):
    """Residuals of a heap state: the vertical parts span their heights, the supports and
    the seabed carry the weight, the slack covers the span. ``forces`` is
    ``(V_A, V_B, T_A, T_B, H)`` (N)."""
    V_A, V_B, T_A, T_B, H = forces
    chord = xp.hypot(span, dh)
    yield (l_B + w * l_B * l_B / (2.0 * EA) - (dh - y_t)) / chord
    yield (l_A + w * l_A * l_A / (2.0 * EA) + y_t) / chord
    weight = w * length
    yield (V_A + V_B + w * L_B - weight) / weight
    yield xp.minimum(L_B - span, 0.0) / span
    yield (T_A - V_A) / weight + (T_B - V_B) / weight + H / weight
