"""40-digit reference solutions shared by the benchmark scripts."""

from __future__ import annotations

import mpmath as mp

from skcable import cable


def irvine_H(span, dh, w, EA, length, digits=40):
    """Horizontal tension of Irvine's elastic catenary, solved with mpmath."""
    mp.mp.dps = digits
    span, dh, w, ea, L0 = (mp.mpf(repr(float(v))) for v in (span, dh, w, EA, length))

    def closure(H, VA):
        tva, tvb = -VA, w * L0 - VA
        x = H * L0 / ea + H / w * (mp.asinh(tvb / H) - mp.asinh(tva / H))
        y = L0 * (w * L0 / 2 - VA) / ea + (mp.hypot(H, tvb) - mp.hypot(H, tva)) / w
        return x - span, y - dh

    start = cable.elastic_catenary(float(span), float(dh), float(w), float(ea), length=float(L0))
    H, _ = mp.findroot(closure, (mp.mpf(start.H), mp.mpf(start.V_A)))
    return float(H)


def catenary_H(span, dh, w, length, digits=40):
    """Horizontal tension of the inextensible catenary, solved with mpmath."""
    mp.mp.dps = digits
    span, dh, w, length = (mp.mpf(repr(float(v))) for v in (span, dh, w, length))
    r = mp.sqrt(length**2 - dh**2) / span
    z = mp.findroot(lambda z: mp.log(mp.sinh(z) / z / r), (mp.mpf("1e-12"), mp.mpf(60)), solver="anderson")
    return float(w * span / (2 * z))


def jonkman_grounded(span, dh, w, EA, L, cb):
    """Jonkman's closure of a line grounded from the anchor on a flat seabed with friction
    ``cb`` (J.M. Jonkman, NREL, 2007), in mpmath: ``f(H, V) -> [X - span, Z - dh]`` with
    ``V`` the vertical force at the fairlead (the reference's max() form of the friction term)."""
    span, dh, w, EA, L, cb = (mp.mpf(repr(float(v))) for v in (span, dh, w, EA, L, cb))

    def f(H, V):
        L_B = L - V / w
        X = L_B + H / w * mp.asinh(V / H) + H * L / EA
        if cb > 0:
            d = L_B - H / (cb * w)
            X += cb * w / (2 * EA) * (-(L_B**2) + d * max(d, 0))
        Z = H / w * (mp.sqrt(1 + (V / H) ** 2) - 1) + V**2 / (2 * EA * w)
        return [X - span, Z - dh]

    return f
