"""Oracle of a line on a sloped seabed ``y = x tan α`` through the anchor, at 50 digits.

Written from the statics (J.M. Jonkman's seabed line, NREL 2007, on a slope): the grounded
part lies straight along the slope from A over ``L_B``; its tension is ``T_t = H/cos α`` at the
touchdown and falls towards A by ``k = w (sin α + μ cos α)`` per metre (to zero where ``k > 0``
runs it out); the suspended part leaves tangentially (``V_t = H tan α``) and hangs as
Irvine's elastic catenary to B. Unknowns ``(H, L_B)``::

    g = L_B + ∫T/EA                         (the grounded part, stretched)
    X = g cos α + H L_s/EA + (H/w)(asinh(V_B/H) - asinh(V_t/H))
    Z = g sin α + (T_B - T_t)/w + (V_B² - V_t²)/(2 w EA),     V_B = V_t + w L_s

The line hangs free where the free catenary leaves A at or above the slope (it is convex:
it stays above its tangent at A, above the seabed).
"""

from __future__ import annotations

import mpmath
from mpmath import mp, mpf

from tests.fuzz.catenary import digits, free_line, hanging_length, solve_from
from tests.fuzz.mp import DPS, NoRoot, OutOfScope

__all__ = ["sloped_closure", "sloped_line"]


def _frame(m, mu, w):
    cos = 1 / mpmath.sqrt(1 + m * m)
    sin = m * cos
    return cos, sin, w * (sin + mu * cos)


def sloped_closure(u, p):
    """``(X - span, Z - dh)`` at ``u = (H, L_B)``, ``p = (span, dh, w, EA, L, m, mu)``."""
    H, L_B = u
    span, dh, w, EA, L, m, mu = p
    cos, sin, k = _frame(m, mu, w)
    T_t = H / cos
    ell = L_B if k <= 0 else min(L_B, T_t / k)
    g = L_B + (T_t * ell - k * ell * ell / 2) / EA
    L_s = L - L_B
    V_t = H * m
    V_B = V_t + w * L_s
    X = g * cos + H * L_s / EA + H / w * (mpmath.asinh(V_B / H) - mpmath.asinh(V_t / H))
    Z = g * sin + (mpmath.hypot(H, V_B) - mpmath.hypot(H, V_t)) / w + (V_B * V_B - V_t * V_t) / (2 * w * EA)
    return [X - span, Z - dh]


def _starts(p, start):
    """Starts for Newton: the answer to check, MoorPy's (frictionless slope, an independent
    solver), a grid."""
    span, dh, w, EA, L, m, mu = (float(v) for v in p)
    out = []
    if start is not None and start.get("H", 0) > 0:
        out.append([mpf(start["H"]), mpf(start["length_on_seabed"])])

    def moorpy():
        import math

        from moorpy.Catenary import catenary

        fAH, fAV, fBH, fBV, info = catenary(span, dh, L, EA, w, CB=mu, alpha=math.degrees(math.atan(m)))
        return [mpf(abs(fBH)), mpf(min(max(info["LBot"], 0.0), 0.999 * L))]

    out.append(moorpy)
    out += [[mpf(w * L * 10.0**a), mpf(b * L)] for a in (0, -1, 1, -2, 2) for b in (0.5, 0.1, 0.9, 0.99)]
    return out


def sloped_line(p, start=None):
    """``H, V_B, H_A, V_A, length_on_seabed``, ``regime`` (free, grounded) of a line on a
    sloped seabed (module text); `OutOfScope` for the states the closure does not describe
    (slack in a heap on the slope, a slack stretch friction cannot hold)."""
    with mp.workdps(DPS):
        p = [mpf(v) for v in p]
        span, dh, w, EA, L, m, mu = p
        free = free_line(p[:5], start if start is not None and start.get("free") else None)
        if -free["V_A"] / free["H"] >= m:
            return free
        cos, sin, k = _frame(m, mu, w)

        def admissible(u):
            return u[0] > 0 and 0 <= u[1] < L

        scales = [abs(span) + L + abs(dh)] * 2
        try:
            H, L_B = solve_from(sloped_closure, _starts(p, start), p, scales, admissible, digits(EA, w * L))
        except NoRoot:
            if L >= span / cos + hanging_length(dh - m * span, w, EA):
                raise OutOfScope("slack in a heap on the sloped seabed") from None
            raise
        T_A = max(H / cos - k * L_B, mpf(0))
        if k > 0 and H / cos - k * L_B < 0 and mu < m:
            raise OutOfScope("a slack stretch on a slope steeper than friction holds")
        return {
            "regime": "grounded",
            "H": H,
            "V_B": H * m + w * (L - L_B),
            "length_on_seabed": L_B,
            "H_A": T_A * cos,
            "V_A": -T_A * sin,
        }
