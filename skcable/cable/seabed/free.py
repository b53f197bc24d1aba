r"""The free regime: the line hangs clear of the seabed, an elastic catenary from A to B
(H.M. Irvine, "Cable Structures", MIT Press, 1981; `skcable.cable.elastic_catenary`).

With the anchor on the seabed the line is free where it leaves A upwards: at lift-off
``V_A = 0`` and ``V_B = wL``, which fixes the lift-off ``H`` in closed form (`lifted`).
With the anchor above the seabed the free line is solved and checked against the seabed
(`free_part`): where it dips below, it touches down between A and B and is grounded.
"""

from __future__ import annotations

import numpy as np

from skcable._xp import namespace, scalar_math
from skcable.cable._elastic import elastic_catenary as free_elastic_catenary
from skcable.cable.closure import positions

__all__ = ["free_part", "lifted"]


def lifted(span, dh, w, EA, L):
    """Whether the line leaves the anchor upwards (no contact), and the lift-off ``H`` (N).

    At lift-off ``V_A = 0``, ``V_B = wL``: the height equation gives
    ``T + H = P = wL²/D`` with ``D = dh - wL²/(2EA)``, so ``H = (P - (wL)²/P)/2``;
    the line is lifted where ``span`` reaches the lift-off run ``X(H, wL)`` (the hanging piece
    from ``V_b = 0``, `skcable.cable.closure.positions`). With
    ``D <= 0`` the line's own stretch exceeds ``dh`` and it always touches.
    """
    D = dh - w * L * L / (2.0 * EA)
    if namespace(span, dh, w, EA, L) is scalar_math:  # one scene, on floats
        if D <= 0:
            return False, 0.0
        P = w * L * L / D
        H = 0.5 * (P - (w * L) * (w * L / P))
        if not H > 0:
            return True, 0.0
        return span >= positions(H, 0.0, w, EA, L)[0], H
    touches = np.asarray(D <= 0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        P = w * L * L / np.where(touches, 1.0, D)
        H = 0.5 * (P - (w * L) * (w * L / P))
        ok = ~touches & (H > 0)
        H_safe = np.where(ok, H, 1.0)
        X = positions(H_safe, 0.0, w, EA, L, np)[0]
    return ~touches & (~ok | (span >= X)), np.where(ok, H, 0.0)


def free_part(span, dh, w, EA, L, seabed):
    """The free line's ``(H, V_A)`` (N) and whether it dips below the ``seabed`` (a touchdown
    between A and B), floats or arrays of the elements. Only an anchor above the seabed
    (``seabed < 0``) has such a dip: with the anchor on it, `lifted` has judged the line free,
    and a lowest point a rounding below A at lift-off (``V_A = 0``) is A itself."""
    free = free_elastic_catenary(span, dh, w, EA, length=L)
    return free.H, free.V_A, (free.y_low < seabed) & (seabed < 0)
