"""Oracles of the conductor computations at 50 digits: the change of state (Irvine's elastic
catenary with thermal strain in the plane of the resultant load, and the parabolic cubic as
stated by CIGRE TB 324, 2007) and the balance of a tension section's suspension strings.

Change of state: the reference state (``w0``, ``t0``, the horizontal tension ``H0`` or the sag
``sag0``, no wind) fixes the unstressed length ``L0``; a state (``w``, ``t``, ``wind``) has the
thermal factor ``k = 1 + α(t - t0)`` and hangs in the plane of its resultant load
``q = sqrt(w² + wind²)`` as the elastic catenary of unstressed length ``k L0``, weight ``q/k``
per that length and stiffness ``EA k`` (the span in that plane ``sqrt(span² + (dh wind/q)²)``,
the height ``dh w/q``); ``H`` is the horizontal tension along the span.
"""

from __future__ import annotations

import mpmath
from mpmath import mp, mpf

from tests.fuzz.catenary import digits, free_closure, free_line, solve_from
from tests.fuzz.mp import DPS, NoRoot

__all__ = ["reference_length", "state", "parabola_state", "sag_of"]


def _x_y(H, V, w, EA, s):
    x = H * s / EA + H / w * (mpmath.asinh((w * s - V) / H) + mpmath.asinh(V / H))
    y = (w * s * s / 2 - V * s) / EA + (mpmath.hypot(H, w * s - V) - mpmath.hypot(H, V)) / w
    return x, y


def sag_of(H, V, span, dh, w, EA):
    """Largest vertical chord-cable distance: where the slope ``(w s - V)/H`` is the chord's."""
    s = (V + H * dh / span) / w
    x, y = _x_y(H, V, w, EA, s)
    return dh * x / span - y


def _stretched(H, V, w, EA, L):
    """``L + ∫ T ds / EA`` over the unstretched length."""

    def F(u):
        return (u * mpmath.hypot(H, u) + H * H * mpmath.asinh(u / H)) / 2

    return L + (F(w * L - V) - F(-V)) / (w * EA)


def reference_length(span, dh, w0, EA, H0=None, sag0=None, start=None):
    """``(L0, H0, V_A, sag0)`` of the reference state at `DPS` digits."""
    with mp.workdps(DPS):
        span, dh, w0, EA = (mpf(v) for v in (span, dh, w0, EA))
        chord = mpmath.hypot(span, dh)
        dps = digits(EA, w0 * chord)
        if H0 is not None:
            H0 = mpf(H0)

            def F(u, p):
                return free_closure([H0, u[0]], [span, dh, w0, EA, u[1]])

            c = H0 / w0  # the inextensible catenary of that H, lengthened by nothing: a start
            L_c = mpmath.sqrt(dh * dh + (2 * c * mpmath.sinh(span / (2 * c))) ** 2)
            starts = [start, [w0 * L_c / 2 - H0 * dh / span, L_c], [w0 * chord / 2, chord]]
            V, L0 = solve_from(F, starts, [], [chord, chord], lambda u: u[1] > 0, dps)
            return L0, H0, V, sag_of(H0, V, span, dh, w0, EA)
        sag0 = mpf(sag0)

        def G(u, p):
            H, V, L = u
            return [*free_closure([H, V], [span, dh, w0, EA, L]), sag_of(H, V, span, dh, w0, EA) - sag0]

        H_p = w0 * span * span / (8 * sag0)  # the parabola's H, a start
        L_p = chord + 8 * sag0 * sag0 / (3 * span)
        starts = [start, [H_p, w0 * L_p / 2 - H_p * dh / span, L_p]]
        H, V, L0 = solve_from(G, starts, [], [chord] * 3, lambda u: u[0] > 0 and u[2] > 0, dps)
        return L0, H, V, sag0


def state(span, dh, w, t, wind, EA, alpha, t0, L0, start=None):
    """``H, H_plane, sag, T_max, length`` of one state at `DPS` digits."""
    with mp.workdps(DPS):
        span, dh, w, t, wind, EA, alpha, t0 = (mpf(v) for v in (span, dh, w, t, wind, EA, alpha, t0))
        k = 1 + alpha * (t - t0)
        q = mpmath.hypot(w, wind)
        dh_p = dh * w / q
        span_p = mpmath.hypot(span, dh * wind / q)
        p = [span_p, dh_p, q / k, EA * k, L0 * k]
        sol = free_line(p, start)
        H_pl, V = sol["H"], sol["V_A"]
        return {
            "H": H_pl * span / span_p,
            "H_plane": H_pl,
            "V_A": V,
            "T_max": max(sol["T_A"], sol["T_B"]),
            "sag": sag_of(H_pl, V, span_p, dh_p, q / k, EA * k),
            "length": _stretched(H_pl, V, q / k, EA * k, L0 * k),
            "blowout": mpmath.atan2(wind, w),
        }


def parabola_state(span, dh, EA, alpha, w0, t0, H0, sag0, w, t, wind):
    """The parabolic change of state as stated (CIGRE TB 324, 2007): the cubic
    ``H²[H - H0 cosψ/cosψ0 + EA cosψ α Δt + EA cosψ q0² a0² cos²ψ0/(24 H0²)] = EA cosψ q² a² cos²ψ/24``
    solved at `DPS` digits, and its sag, largest tension and length."""
    with mp.workdps(DPS):
        span, dh, EA, alpha, w0, t0, w, t, wind = (mpf(v) for v in (span, dh, EA, alpha, w0, t0, w, t, wind))
        chord = mpmath.hypot(span, dh)
        cos0 = span / chord
        H0 = w0 * span * span / (8 * mpf(sag0) * cos0) if H0 is None else mpf(H0)
        q = mpmath.hypot(w, wind)
        dh_p, span_p = dh * w / q, mpmath.hypot(span, dh * wind / q)
        cos = span_p / chord
        excess0 = (w0 * span * cos0) ** 2 / (24 * H0 * H0)
        b = -H0 * cos / cos0 + EA * cos * alpha * (t - t0) + EA * cos * excess0
        d = EA * cos * (q * span_p * cos) ** 2 / 24
        roots = [
            r
            for r in mpmath.polyroots([1, b, 0, -d], maxsteps=200, extraprec=200)
            if abs(mpmath.im(r)) < 1e-30
        ]
        positive = [mpmath.re(r) for r in roots if mpmath.re(r) > 0]
        if len(positive) != 1:
            raise NoRoot(f"the cubic has {len(positive)} positive roots")
        H = positive[0]
        tan = dh_p / span_p
        return {
            "H": H * span / span_p,
            "H_plane": H,
            "sag": q * span_p**2 / (8 * H * cos),
            "T_max": mpmath.hypot(H, H * abs(tan) + q * span_p / (2 * cos)),
            "length": chord * (1 + (q * span_p * cos) ** 2 / (24 * H * H)),
            "L0": chord * (1 + excess0) - H0 * chord / (EA * cos0),
            "H0": H0,
            "sag0": w0 * span**2 / (8 * H0 * cos0),
        }
