r"""The inextensible catenary of a given length, on Python floats.

The scalar path of `skcable.cable.catenary` with ``length=`` and the start of the elastic
forms (Irvine's catenary, the lines on a seabed) solve the same equation thousands of times a
second (H.M. Irvine, *Cable Structures*, 1981, §2.1): with :math:`z = \mathrm{span}/(2a)`,

.. math:: \frac{\sinh z}{z} = \frac{\sqrt{S^2 - dh^2}}{\mathrm{span}} = 1 + \rho,

solved by Halley's method (E. Halley, 1694; cubic convergence) on :math:`\log(\sinh z/z)`,
increasing and convex, from the same start and by the same formulas as the array path of
`skcable.cable._catenary`, on floats and without the argument checks, which the callers have
done. Each function
returns None where the general path must decide (data out of its range: it raises the error
that names the argument).
"""

from __future__ import annotations

import math

from skcable.cable._special import sinhc_pair

__all__ = ["hanging_forces", "start", "step", "z_of_excess", "z_of_length"]

#: sinh(z)/z at the largest z evaluated (cosh overflows beyond).
_RHO_LIMIT = math.sinh(709.0) / 709.0


def _excess(span, dh, length):
    """``rho = sqrt(S² - dh²)/span - 1`` free of cancellation (lengths brought to order one by
    a power of two), or None when the length does not exceed the chord."""
    legs = abs(dh)
    unit = math.ldexp(0.5, math.frexp(span if span > legs else legs)[1])
    span, dh, legs, length = span / unit, dh / unit, legs / unit, length / unit  # exact
    chord = math.sqrt(span * span + dh * dh)  # both below 1: as the array path
    if not length > chord:
        return None
    if length < 2.0 * chord:
        longer, shorter = (span, legs) if span >= legs else (legs, span)
        excess_sq = (length - longer) * (length + longer) - shorter * shorter
        return excess_sq / span / (math.sqrt((length - legs) * (length + legs)) + span)
    return math.sqrt((length - legs) / span) * math.sqrt((length + legs) / span) - 1.0


def z_of_length(span: float, dh: float, length: float) -> float | None:
    """``z = span/(2a)`` of the catenary of unstretched ``length`` from A = (0, 0) to
    B = (span, dh) (m), or None outside the closed form's range."""
    rho = _excess(span, dh, length)
    if rho is None or not rho < _RHO_LIMIT:
        return None
    return z_of_excess(rho)[0]


def start(rho: float) -> float:
    """A start for the root of ``log(sinh z / z) = log1p(rho)``, within 2 % of it: the
    inverted Maclaurin series below ``rho = 1`` (error below 6e-4 under ``rho = 0.3``), above
    it three fixed-point steps of ``z = y + log(2z)``, ``y = log1p(rho)``, from ``z = y + 1``
    (the asymptote ``sinh z ~ e^z/2``; error below 4 %, 0.3 % beyond ``rho = 10``)."""
    if rho < 1.0:
        return math.sqrt(rho * (6.0 + rho * (-1.8 + 0.8229 * rho)))
    y = math.log1p(rho)
    z = y + math.log(2.0 * (y + 1.0))
    z = y + math.log(2.0 * z)
    return y + math.log(2.0 * z)


def step(z: float, target: float) -> float:
    r"""The step of Halley's method for :math:`g(z) = \log(\sinh z/z) - t` (cubic convergence),
    Newton's where Halley's correction exceeds one half (far from the root).

    :math:`g' = \coth z - 1/z`, :math:`g'' = 1/z^2 - 1/\sinh^2 z`, the latter as
    :math:`\varphi(2 + \varphi)/(z^2 (1 + \varphi)^2)` with :math:`\varphi = \sinh z/z - 1`
    (its series below z = 1: no cancellation); above z = 20 in the forms
    :math:`z - \log 2z + \operatorname{log1p}(-e^{-2z})` and :math:`1/z^2`, which do not overflow.
    """
    if z <= 20.0:
        phi, slope = sinhc_pair(z)
        newton = (math.log1p(phi) - target) * (1.0 + phi) / slope
        if z < 1e-150:  # z² underflows: Newton's step (Halley's correction is ~1e-300 there)
            return newton
        curvature = phi * (2.0 + phi) / (z * z) / (1.0 + phi) / (1.0 + phi)
        first = slope / (1.0 + phi)
    else:
        first = 1.0 / math.tanh(z) - 1.0 / z
        newton = (z - math.log(2.0 * z) + math.log1p(-math.exp(-2.0 * z)) - target) / first
        curvature = 1.0 / (z * z)
    correction = 0.5 * newton * curvature / first
    return newton / (1.0 - correction) if abs(correction) <= 0.5 else newton


def z_of_excess(rho: float) -> tuple[float | None, list]:
    """The root of ``sinh(z)/z = 1 + rho`` (``0 < rho < sinh(709)/709``) and the history of
    the relative steps, or None (with the history) if the iteration does not settle."""
    target, z, history = math.log1p(rho), start(rho), []
    for _ in range(100):
        change = step(z, target)
        z = z - change
        history.append(abs(change / z))
        if history[-1] < 1e-7:  # cubic convergence: the error is now below 1e-20
            return z, history
    return None, history


def hanging_forces(
    span: float, dh: float, w: float, length: float
) -> tuple[float, float, float, float] | None:
    """``(H, V_A, T_A, T_B)`` (N) of the inextensible catenary of ``length`` under ``w`` per
    metre, unchecked: a start for the elastic forms (which check what they return), or None."""
    z = z_of_length(span, dh, length)
    if z is None or not 1e-300 <= z <= 709.0:
        return None
    a = span / (2.0 * z)
    m = math.asinh(dh / span / (math.sinh(z) / z))
    H = w * a
    return H, H * math.sinh(z - m), H * math.cosh(m - z), H * math.cosh(m + z)
