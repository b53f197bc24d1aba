r"""The inextensible catenary of a given length, on Python floats.

The scalar path of `skcable.cable.catenary` with ``length=`` and the start of the elastic
forms (Irvine's catenary, the lines on a seabed) solve the same equation thousands of times a
second (H.M. Irvine, *Cable Structures*, 1981, §2.1): with :math:`z = \mathrm{span}/(2a)`,

.. math:: \frac{\sinh z}{z} = \frac{\sqrt{S^2 - dh^2}}{\mathrm{span}} = 1 + \rho,

solved by Halley's method (E. Halley, 1694; cubic convergence) on :math:`\log(\sinh z/z)`,
increasing and convex, by the same formulas as the array path (`skcable.cable._catenary_batch`)
and from the same start but below ``rho = 0.01``, where a float takes the inverted series' first
terms (as close there as the Padé approximant the arrays take, and cheaper), on floats and
without the argument checks, which the callers have done. Each function returns None where the
general path must decide (data out of its range: it raises the error that names the argument).
"""

from __future__ import annotations

import math
from math import log1p, sqrt

from skcable.cable._special import sinhc_pair

__all__ = [
    "PADE_DEN",
    "PADE_NUM",
    "RHO_LIMIT",
    "STEP_TOL",
    "Z_LIMIT",
    "Z_MIN",
    "excess",
    "hanging_forces",
    "start",
    "step",
    "z_of_excess",
    "z_of_length",
]

#: Range of z = span/(2a) the closed form evaluates: below Z_MIN the abscissae x/(2a) turn
#: subnormal (no relative precision), above Z_LIMIT sinh(z) overflows.
Z_MIN, Z_LIMIT = 1e-300, 709.0
#: sinh(z)/z at the largest z evaluated (cosh overflows beyond).
RHO_LIMIT = math.sinh(Z_LIMIT) / Z_LIMIT
#: Relative change of Halley's method below which the iteration stops (cubic convergence: the
#: error is then below 1e-20).
STEP_TOL = 1e-7
#: The [4/4] Padé approximant of z²/rho, ``PADE_NUM(rho)/PADE_DEN(rho)`` (highest power
#: first), built on the inverted Maclaurin series of ``sinh(z)/z = 1 + rho``,
#: ``z² = 6 rho - 9/5 rho² + 144/175 rho³ - 78/175 rho⁴ + ...``; the coefficients are the
#: exact rationals of the approximant, rounded (``6 P`` over ``Q``, ``Q(0) = 1``). On
#: ``0 < rho <= 1`` the start ``sqrt(rho PADE_NUM/PADE_DEN)`` lies within 2.5e-8 of the root.
PADE_NUM = (0.005722844662462971, 0.45112759888939313, 3.5843451643580484, 8.4486403084625, 6.0)
PADE_DEN = (0.012408553118772064, 0.20702301751392926, 0.9726800190066092, 1.708106718077083, 1.0)
_N0, _N1, _N2, _N3, _N4 = PADE_NUM
_D0, _D1, _D2, _D3, _D4 = PADE_DEN


def excess(span, dh, length):
    """``rho = sqrt(S² - dh²)/span - 1`` free of cancellation (lengths brought to order one by
    a power of two), or None when the length does not exceed the chord."""
    legs = abs(dh)
    top = span if span > legs else legs
    if not (1e-100 < top and length < 1e100 and top < 1e100):  # else every square is normal and
        unit = math.ldexp(0.5, math.frexp(top)[1])  # the scaling, exact, changes no bit
        span, dh, legs, length = span / unit, dh / unit, legs / unit, length / unit
    chord = sqrt(span * span + dh * dh)
    if not length > chord:
        return None
    if length < 2.0 * chord:
        longer, shorter = (span, legs) if span >= legs else (legs, span)
        excess_sq = (length - longer) * (length + longer) - shorter * shorter
        return excess_sq / span / (sqrt((length - legs) * (length + legs)) + span)
    return sqrt((length - legs) / span) * sqrt((length + legs) / span) - 1.0


def z_of_length(span: float, dh: float, length: float) -> float | None:
    """``z = span/(2a)`` of the catenary of unstretched ``length`` from A = (0, 0) to
    B = (span, dh) (m), or None outside the closed form's range."""
    rho = excess(span, dh, length)
    if rho is None or not rho < RHO_LIMIT:
        return None
    return z_of_excess(rho)[0]


def start(rho: float) -> float:
    """A start for the root of ``log(sinh z / z) = log1p(rho)``: below ``rho = 1`` the [4/4]
    Padé approximant of the inverted Maclaurin series (`PADE_NUM`, `PADE_DEN`; within 2.5e-8,
    so that one step of Halley's method reaches round-off), below ``rho = 0.01`` the series'
    first three terms ``z² = 6 rho - 9/5 rho² + 144/175 rho³`` (within 4e-8 there, and cheaper on
    a float), above ``rho = 1`` three fixed-point steps of ``z = y + log(2z)``,
    ``y = log1p(rho)``, from ``z = y + 1`` (the asymptote ``sinh z ~ e^z/2``; error below 4 %,
    0.3 % beyond ``rho = 10``)."""
    if rho < 0.01:
        return sqrt(rho * (6.0 + rho * (-1.8 + 0.8228571428571429 * rho)))
    if rho < 1.0:
        return sqrt(
            rho
            * ((((_N0 * rho + _N1) * rho + _N2) * rho + _N3) * rho + _N4)
            / ((((_D0 * rho + _D1) * rho + _D2) * rho + _D3) * rho + _D4)
        )
    y = math.log1p(rho)
    z = y + math.log(2.0 * (y + 1.0))
    z = y + math.log(2.0 * z)
    return y + math.log(2.0 * z)


def step(z: float, rho: float) -> float:
    r"""The step of Halley's method for :math:`g(z) = \log(\sinh z/z) - \operatorname{log1p}
    \rho` (cubic convergence), Newton's where Halley's correction exceeds one half (far from
    the root).

    :math:`g = \operatorname{log1p}((\varphi - \rho)/(1 + \rho))` with :math:`\varphi =
    \sinh z/z - 1` (its series below z = 1: no cancellation; near the root
    :math:`\varphi - \rho` is exact), :math:`g' = \coth z - 1/z`,
    :math:`g'' = 1/z^2 - 1/\sinh^2 z`, the latter as
    :math:`\varphi(2 + \varphi)/(z^2 (1 + \varphi)^2)`; above z = 20 in the forms
    :math:`z - \log 2z + \operatorname{log1p}(-e^{-2z})` and :math:`1/z^2`, which do not overflow.
    """
    if z <= 20.0:
        phi, slope = sinhc_pair(z)
        newton = math.log1p((phi - rho) / (1.0 + rho)) * (1.0 + phi) / slope
        if z < 1e-150:  # z² underflows: Newton's step (Halley's correction is ~1e-300 there)
            return newton
        curvature = phi * (2.0 + phi) / (z * z) / (1.0 + phi) / (1.0 + phi)
        first = slope / (1.0 + phi)
    else:
        first = 1.0 / math.tanh(z) - 1.0 / z
        newton = (z - math.log(2.0 * z) + math.log1p(-math.exp(-2.0 * z)) - math.log1p(rho)) / first
        curvature = 1.0 / (z * z)
    correction = 0.5 * newton * curvature / first
    return newton / (1.0 - correction) if abs(correction) <= 0.5 else newton


def z_of_excess(rho: float) -> tuple[float | None, list]:
    """The root of ``sinh(z)/z = 1 + rho`` (``0 < rho < sinh(709)/709``) and the history of
    the relative steps, or None (with the history) if the iteration does not settle.

    `start` and `step` (the same operations), inlined where the closed forms spend their
    time: ``rho < 1`` and ``z`` in [1e-150, 1]."""
    history = []  # `start`, its first branch inlined
    z = sqrt(rho * (6.0 + rho * (-1.8 + 0.8228571428571429 * rho))) if rho < 0.01 else start(rho)
    for _ in range(100):
        if 1e-150 <= z < 1.0:
            phi, slope = sinhc_pair(z)
            newton = log1p((phi - rho) / (1.0 + rho)) * (1.0 + phi) / slope
            curvature = phi * (2.0 + phi) / (z * z) / (1.0 + phi) / (1.0 + phi)
            correction = 0.5 * newton * curvature / (slope / (1.0 + phi))
            change = newton / (1.0 - correction) if abs(correction) <= 0.5 else newton
        else:
            change = step(z, rho)
        z = z - change
        history.append(abs(change / z))
        if history[-1] < 1e-7:  # `STEP_TOL`: cubic convergence, the error is now below 1e-20
            return z, history
    return None, history


def hanging_forces(
    span: float, dh: float, w: float, length: float
) -> tuple[float, float, float, float] | None:
    """``(H, V_A, T_A, T_B)`` (N) of the inextensible catenary of ``length`` under ``w`` per
    metre, unchecked: a start for the elastic forms (which check what they return), or None."""
    z = z_of_length(span, dh, length)
    if z is None or not Z_MIN <= z <= Z_LIMIT:
        return None
    a = span / (2.0 * z)
    m = math.asinh(dh / span / (math.sinh(z) / z))
    H = w * a
    return H, H * math.sinh(z - m), H * math.cosh(m - z), H * math.cosh(m + z)
