r"""Whole lines at array speed: the check of solved spans and what is derived from them.

The closure of a span of unstressed length :math:`L`, weight :math:`w` per unstressed length and
axial stiffness :math:`EA` between A = (0, 0) and B = (a, h) (H.M. Irvine, "Cable
Structures", MIT Press, 1981, §2.2) in the horizontal tension :math:`H` and the mean vertical
tension :math:`m = (T_{v,A} + T_{v,B})/2 = wL/2 - V_A`, with :math:`T_{v,A} = m - wL/2`,
:math:`T_{v,B} = m + wL/2` and the end tensions :math:`T = \sqrt{H^2 + T_v^2}`:

.. math::
    f_x = \frac{HL}{EA} + \frac{H}{w}\,\ln\frac{p_B}{p_A} - a, \qquad
    f_y = \frac{Lm}{EA} + \frac{T_B - T_A}{w} - h,

with :math:`p = (T_v + T)/H = e^{\operatorname{asinh}(T_v/H)}`. `closure_terms` evaluates both
for many spans at once, in place in rows of scratch: the arc as
:math:`\operatorname{log1p}\big(wL\,(1 + p_B/p_A)/(T_A + T_B)\big)` (as
:math:`e_B - e_A = wL(p_A + p_B)/(T_A + T_B)`, free of cancellation: :math:`p_B/p_A` is a product
or a ratio of the sums :math:`T + |T_v|`, by the signs of the ends' slopes), and the rise as the
plain difference :math:`T_B - T_A`. The solves it checks (`skcable.conductors._closure_z`)
never form an end tension, a logarithm or an inverse hyperbolic sine: they solve one equation
in the hyperbolic half-angle :math:`z` through :math:`\sinh z`, :math:`\cosh z` and the series
of :math:`\sinh z - z`, so that the check does not share their round-off. Its bound is
`CHECK_ULPS` ulps of the terms it adds.

`sag_into` and `length_into` derive the sag and the loaded length from the check's end
tensions and arc.
"""

from __future__ import annotations

import numpy as np

__all__ = ["closure_terms", "closure_residual", "closure_check", "sag_into", "length_into", "ROWS"]

_EPS = float(np.finfo(float).eps)
#: The check's bound: this many ulps of the closure's terms (the check's own round-off is a few).
CHECK_ULPS = 64.0
#: Rows of scratch `closure_terms` fills: the first seven are named in its docstring.
ROWS = 10


def _tension_and_p(tv, H_sq, T, p):
    """The tension ``T = sqrt(T_v² + H²)`` and ``p = |T_v| + T`` of an end (or a point) into
    ``T`` and ``p``, from its vertical tension ``tv`` and ``H_sq = H²``, in place."""
    np.multiply(tv, tv, out=T)
    T += H_sq
    np.sqrt(T, out=T)
    np.abs(tv, out=p)
    p += T


def _ratio_of_ends(tv_a, tv_b, P_a, P_b, H2, out):
    """``p_B/p_A`` into ``out`` from ``P = T + |T_v|``: ``P_A P_B/H²`` where the slopes at the
    ends have opposite signs, ``P_B/P_A`` where both rise, ``P_A/P_B`` where both fall."""
    np.multiply(P_a, P_b, out=out)
    out /= H2
    for ends, over, under in ((tv_a >= 0.0, P_b, P_a), (tv_b < 0.0, P_a, P_b)):
        if ends.any():  # the few spans whose vertex lies beyond an end: by index
            at = np.flatnonzero(ends)
            out[at] = over[at] / under[at]
    return out


def closure_terms(H, m, w, EA, L, a, h, rows):
    """Evaluate the closure (module text) of solved spans into ``rows`` (`ROWS` rows of the
    elements' size): 0 ``T_v,A``, 1 ``T_v,B``, 2 ``T_A``, 3 ``T_B``, 4 the arc
    ``ln(p_B/p_A)``, 5 the larger of ``|f_x|, |f_y|`` and 6 the larger sum of the magnitudes
    of their terms (m, the bound's scale); rows 7 to 9 are scratch."""
    tv_a, tv_b, T_A, T_B, arc, res, terms, u, v, y = rows
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        np.multiply(w, L, out=u)  # wL
        np.multiply(u, 0.5, out=v)
        np.subtract(m, v, out=tv_a)
        np.add(m, v, out=tv_b)
        np.multiply(H, H, out=v)
        _tension_and_p(tv_a, v, T_A, res)
        _tension_and_p(tv_b, v, T_B, terms)
        _ratio_of_ends(tv_a, tv_b, res, terms, v, out=arc)
        arc += 1.0
        arc *= u
        np.add(T_A, T_B, out=v)
        arc /= v
        np.log1p(arc, out=arc)
        np.multiply(H, L, out=res)
        res /= EA
        np.divide(H, w, out=terms)
        terms *= arc
        res += terms  # HL/EA + (H/w) arc
        np.subtract(res, a, out=u)
        np.abs(u, out=u)  # |f_x|
        res += a
        np.multiply(L, m, out=terms)
        terms /= EA  # Lm/EA
        np.subtract(T_B, T_A, out=y)
        y /= w
        y += terms
        y -= h
        np.abs(y, out=y)  # |f_y|
        np.maximum(u, y, out=u)
        np.abs(terms, out=terms)
        v /= w  # (T_A + T_B)/w
        terms += v
        np.abs(h, out=y)
        terms += y
        np.maximum(res, terms, out=terms)
        np.copyto(res, u)
    return rows


def closure_residual(H, m, w, EA, L, span, dh):
    """Relative closure residual of solved spans and its round-off bound, ``(residual,
    bound)``, arrays (`closure_terms` over the chord)."""
    H, m, w, EA, L, span, dh = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (H, m, w, EA, L, span, dh))
    )
    rows = closure_terms(H, m, w, EA, L, span, dh, np.empty((ROWS, *H.shape)))
    chord = np.hypot(span, dh)
    return rows[5] / chord, CHECK_ULPS * _EPS * rows[6] / chord


def closure_check(H, m, w, EA, L, a, h, rows):
    """``ok`` per element: the closure residual within its bound and ``H > 0`` (NaN fails);
    ``rows`` filled as by `closure_terms`."""
    closure_terms(H, m, w, EA, L, a, h, rows)
    res, terms = rows[5], rows[6]
    terms *= CHECK_ULPS * _EPS
    ok = res <= terms
    ok &= H > 0.0
    return ok


def sag_into(H, w, EA, a, h, rows, out):
    r"""The sag (largest distance chord–cable along the load) into ``out``, from the end
    tensions at A in ``rows`` (`closure_terms`' rows 0 and 2; rows 4 to 9 are overwritten).

    At the material point whose slope is the chord's, :math:`T_{v,s} = H h/a`, reached after
    the unstressed length :math:`s = (T_{v,s} - T_{v,A})/w`:
    :math:`x_s = Hs/EA + (H/w)\ln(p_s/p_A)`,
    :math:`y_s = s(T_{v,s} + T_{v,A})(1/(2EA) + 1/(T_s + T_A))`, the sag
    :math:`(h/a)x_s - y_s`.
    """
    tv_a, T_A = rows[0], rows[2]
    tv_s, s, T_s, P_a, u, v = rows[4:]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        np.divide(h, a, out=tv_s)
        tv_s *= H
        np.subtract(tv_s, tv_a, out=s)
        s /= w
        np.multiply(H, H, out=u)
        _tension_and_p(tv_s, u, T_s, v)
        np.abs(tv_a, out=P_a)
        P_a += T_A
        _ratio_of_ends(tv_a, tv_s, P_a, v, u, out=out)  # p_s / p_A
        out += 1.0
        out *= s
        out *= w
        np.add(T_s, T_A, out=v)
        out /= v
        np.log1p(out, out=out)  # ln(p_s / p_A)
        out *= H
        out /= w
        np.multiply(H, s, out=u)
        u /= EA
        out += u  # x_s
        np.divide(h, a, out=u)
        out *= u
        np.reciprocal(v, out=v)
        np.divide(0.5, EA, out=u)
        v += u
        tv_s += tv_a
        tv_s *= s
        tv_s *= v  # y_s
        out -= tv_s
    return out


def length_into(H, w, EA, L, rows, out):
    r"""Loaded length :math:`L + \int T/EA\,ds = L + (T_{v,B}T_B - T_{v,A}T_A + H^2\ln(p_B/p_A))
    /(2wEA)` into ``out``, from `closure_terms`' rows 0 to 4 (row 5 is overwritten)."""
    tv_a, tv_b, T_A, T_B, arc, u = rows[:6]
    np.multiply(tv_b, T_B, out=out)
    np.multiply(tv_a, T_A, out=u)
    out -= u
    np.multiply(H, H, out=u)
    u *= arc
    out += u
    out /= w
    out /= EA
    out *= 0.5
    out += L
    return out
