"""Hyperbolic helpers that stay accurate where the textbook forms cancel.

A taut catenary has ``z = span / (2a)`` of order 1e-5 or less; the direct
forms of ``sinh(z)/z - 1`` or ``z - tanh z`` then lose every digit. These
helpers switch to their Maclaurin series below ``|z| = 1`` (9 terms, error
below 1e-17 relative there) and use the direct forms above, where the loss
is at most a factor 6 of the machine epsilon. They take floats or arrays
(see `skcable._xp`).
"""

from __future__ import annotations

import math
from math import factorial, log

import numpy as np

from skcable._xp import namespace

#: Maclaurin coefficients of (sinh z / z - 1) / z**2 in powers of z**2, highest first.
SINHC_SERIES = _SINHC = tuple(1.0 / factorial(2 * k + 1) for k in range(9, 0, -1))
#: Coefficients of d/dz(sinh z / z) / z in powers of z**2, highest first.
DSINHC_SERIES = _DSINHC = tuple(2.0 * k / factorial(2 * k + 1) for k in range(9, 0, -1))
_SERIES_BELOW = 1.0
_LOG2 = log(2.0)


def horner(coefficients, t):
    """Polynomial with ``coefficients`` (highest power first) at ``t``.

    ``numpy.polyval`` does the same with ten times the overhead on scalars.
    """
    if isinstance(t, np.ndarray):  # in place: one array, not two per coefficient
        result = np.full(t.shape, coefficients[0])
        for c in coefficients[1:]:
            result *= t
            result += c
        return result
    result = coefficients[0]
    for c in coefficients[1:]:
        result = result * t + c
    return result


def largest_abs(value) -> float:
    """``max(|value|)`` as a float, NaN if any element is NaN; cheap on scalars."""
    if not isinstance(value, np.ndarray):
        return abs(float(value))
    # two reductions (the ufuncs', without ndarray.max's wrapper), no |value| array
    top, low = float(np.maximum.reduce(value, axis=None)), float(np.minimum.reduce(value, axis=None))
    return top if top != top else low if low != low else max(top, -low)


def piecewise(z, small, series, direct):
    """``series(z)`` where ``small``, ``direct(z)`` elsewhere; each branch is
    evaluated only where it is used (on scalars, only one is evaluated)."""
    if not isinstance(z, np.ndarray):
        return series(z) if small else direct(z)
    if small.all():  # one branch everywhere: no indexing
        return series(z)
    if not small.any():
        return direct(z)
    out = np.empty(z.shape)
    out[small] = series(z[small])
    out[~small] = direct(z[~small])
    return out


def sinhc_m1(z):
    """``sinh(z)/z - 1``, accurate for all real z (even function); a Python float by
    `sinhc_pair`'s unrolled series."""
    if not isinstance(z, np.ndarray):
        return _sinhc_m1_float(z)
    xp = namespace(z)
    return piecewise(
        z,
        abs(z) < _SERIES_BELOW,
        lambda z: z * z * horner(_SINHC, z * z),
        lambda z: xp.sinh(z) / z - 1.0,
    )


def dsinhc(z):
    """Derivative of ``sinh(z)/z``: ``(z cosh z - sinh z) / z**2``."""
    xp = namespace(z)
    return piecewise(
        z,
        abs(z) < _SERIES_BELOW,
        lambda z: z * horner(_DSINHC, z * z),
        lambda z: (z * xp.cosh(z) - xp.sinh(z)) / (z * z),
    )


_S0, _S1, _S2, _S3, _S4, _S5, _S6, _S7, _S8 = _SINHC
_D0, _D1, _D2, _D3, _D4, _D5, _D6, _D7, _D8 = _DSINHC


def sinhc_pair(z: float) -> tuple[float, float]:
    """`sinhc_m1` and `dsinhc` of one Python float ``z > 0``, by the same series unrolled: the
    hot scalar path of the catenary's length solve. Below ``z² = 0.01`` five terms of each
    series, below 0.1 seven, reach what nine do (the first term left out is below 1e-18 of the
    sum there): the result differs from the nine-term evaluation by an ulp at most
    (checked on 2·10⁵ random z in (1e-10, 1.2): 3 differed, by one ulp of ``dsinhc``)."""
    if z < _SERIES_BELOW:
        t = z * z
        if t < 0.01:
            phi = (((_S4 * t + _S5) * t + _S6) * t + _S7) * t + _S8
            dphi = (((_D4 * t + _D5) * t + _D6) * t + _D7) * t + _D8
        elif t < 0.1:
            phi = (((((_S2 * t + _S3) * t + _S4) * t + _S5) * t + _S6) * t + _S7) * t + _S8
            dphi = (((((_D2 * t + _D3) * t + _D4) * t + _D5) * t + _D6) * t + _D7) * t + _D8
        else:
            phi = (
                ((((((_S0 * t + _S1) * t + _S2) * t + _S3) * t + _S4) * t + _S5) * t + _S6) * t + _S7
            ) * t + _S8
            dphi = (
                ((((((_D0 * t + _D1) * t + _D2) * t + _D3) * t + _D4) * t + _D5) * t + _D6) * t + _D7
            ) * t + _D8
        return t * phi, z * dphi
    s = math.sinh(z)
    return s / z - 1.0, (z * math.cosh(z) - s) / (z * z)


def _sinhc_m1_float(z: float) -> float:
    """`sinhc_m1` of a Python float: `sinhc_pair`'s first value, without its second."""
    if -_SERIES_BELOW < z < _SERIES_BELOW:
        t = z * z
        if t < 0.01:
            return t * ((((_S4 * t + _S5) * t + _S6) * t + _S7) * t + _S8)
        if t < 0.1:
            return t * ((((((_S2 * t + _S3) * t + _S4) * t + _S5) * t + _S6) * t + _S7) * t + _S8)
        return t * (
            (((((((_S0 * t + _S1) * t + _S2) * t + _S3) * t + _S4) * t + _S5) * t + _S6) * t + _S7) * t + _S8
        )
    return math.sinh(z) / z - 1.0


def z_minus_tanh(z):
    """``z - tanh(z)`` without cancellation: ``z**2 * dsinhc(z) / cosh(z)``."""
    return z * z * dsinhc(z) / namespace(z).cosh(z)


def z_minus_tanh_over_cube(z):
    """``(z - tanh z) / z**3`` (-> 1/3 as z -> 0), without forming z**3."""
    xp = namespace(z)
    return piecewise(
        z,
        abs(z) < _SERIES_BELOW,
        lambda z: horner(_DSINHC, z * z) / xp.cosh(z),
        lambda z: z_minus_tanh(z) / (z * z * z),
    )


def asinh_step_parts(q, d, p, rq, rp, xp=None):
    r"""``(S, A)``: ``A = asinh(q + d) - asinh(q)`` and ``S = sinh(A)``, from ``q``, the step
    ``d >= 0`` formed directly (``wL/H``, never a difference of rounded ratios), ``p = q + d``
    and ``rq = sqrt(1 + q²)``, ``rp = sqrt(1 + p²)`` (the caller's, often ``T/H`` at the ends).

    With :math:`\alpha = \operatorname{asinh} p`, :math:`\beta = \operatorname{asinh} q`,
    :math:`\sinh(\alpha - \beta) = p r_q - q r_p`, rationalised where p and q share a sign
    (the only case where it cancels) to :math:`d\,(p + q)/(p r_q + q r_p)`: every operation
    is then free of cancellation, and the result keeps its digits however small ``d`` is
    against ``|q|`` (a taut, steep line: ``d`` ~ 1e-12, ``|q|`` ~ 1). The difference of the
    rounded ratios loses ``|q|/d`` ulps there. ``xp``: the back end, if the caller
    knows it (`skcable._xp.namespace`).
    """
    xp = namespace(q, d, p) if xp is None else xp
    if xp is not np:
        S = d * (p + q) / (p * rq + q * rp) if p * q > 0 else p * rq - q * rp
        return S, xp.arcsinh(S)
    same = p * q > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        S = np.where(same, d * (p + q) / np.where(same, p * rq + q * rp, 1.0), p * rq - q * rp)
    return S, np.arcsinh(S)


def asinh_step(q, d):
    """``asinh(q + d) - asinh(q)`` from ``q`` and the step ``d >= 0`` formed directly
    (see `asinh_step_parts`): the arc of a catenary between two points of vertical
    tension components ``q·H`` and ``(q + d)·H`` is ``(H/w)·asinh_step(q, d)`` with
    ``d = w·s/H``, ``s`` the unstretched length between them.

    This is the primitive of every closure of a hanging line (Irvine's elastic
    catenary, the suspended part of a line on the seabed, each piece of a multi-segment
    line): pass ``d = w s / H`` computed from the weight and the length, never
    ``V_top/H - V_bot/H``.

    >>> import math
    >>> q, d = -1.15, 1.5e-12
    >>> abs(asinh_step(q, d) / (d / math.sqrt(1 + q * q)) - 1) < 1e-11
    True
    """
    xp = namespace(q, d)
    p = q + d
    return asinh_step_parts(q, d, p, xp.hypot(1.0, q), xp.hypot(1.0, p))[1]


def exp_asinh(v, rv, xp=None):
    """``v + sqrt(1 + v²) = exp(asinh v)`` without cancellation (``rv = sqrt(1 + v²)``);
    ``xp``: the back end, if the caller knows it (`skcable._xp.namespace`)."""
    if xp is not np and (xp is not None or not isinstance(v, np.ndarray) and not isinstance(rv, np.ndarray)):
        return v + rv if v >= 0 else 1.0 / (rv - v)
    with np.errstate(divide="ignore"):
        return np.where(v >= 0, v + rv, 1.0 / (rv - v))


def log_cosh(x):
    """``log(cosh(x))`` for any real x, without overflow (absolute error ~1e-16)."""
    xp = namespace(x)
    ax = xp.abs(x)
    return ax + xp.log1p(xp.exp(-2.0 * ax)) - _LOG2


def power_product(coefficient, *factors):
    """``coefficient · Π x**p`` over ``(x, p)`` in ``factors`` as ``(mantissa, exponent)``.

    ``x > 0`` (float or array), ``p`` a small integer. The mantissas of the
    factors (in [1/2, 1)) and their binary exponents are combined apart, so
    that no intermediate over- or underflows: the result is right to a few
    ulps whenever it is representable. Turn it into a float with `ldexp_sum`.
    """
    xp = namespace(*(x for x, _ in factors))
    mantissa, exponent = coefficient, 0
    for x, p in factors:
        m, e = xp.frexp(x)
        mantissa = mantissa * m**p
        exponent = exponent + e * p
    return mantissa, exponent


def ldexp_sum(*terms):
    """Sum of ``mantissa · 2**exponent`` terms (from `power_product`).

    The terms are brought to the largest exponent before adding, so only the
    final scaling can over- or underflow: it gives ``inf`` (never raises) or
    a zero/subnormal the caller can reject.
    """
    xp = namespace(*(m for m, _ in terms), *(e for _, e in terms))
    top = terms[0][1]
    for _, e in terms[1:]:
        top = xp.maximum(top, e)
    total = 0.0
    for m, e in terms:
        total = total + xp.ldexp(m, e - top)  # underflows harmlessly to 0 for negligible terms
    if xp is np:
        with np.errstate(over="ignore"):
            return np.ldexp(total, top)
    try:
        return xp.ldexp(total, top)
    except OverflowError:
        return float("inf") if total > 0 else float("-inf")
