r"""The inextensible catenary of a given length, on Python floats.

The scalar path of `skcable.cable.catenary` with ``length=`` and the start of the elastic
forms (Irvine's catenary, the lines on a seabed) solve the same equation thousands of times a
second (H.M. Irvine, *Cable Structures*, 1981, §2.1): with :math:`z = \mathrm{span}/(2a)`,

.. math:: \frac{\sinh z}{z} = \frac{\sqrt{S^2 - dh^2}}{\mathrm{span}} = 1 + \rho,

solved by Newton's method on :math:`\log(\sinh z/z)`, increasing and convex, from the same
start and by the same operations as the array path of `skcable.cable._catenary` (the same
bits), on floats and without the argument checks, which the callers have done. Each function
returns None where the general path must decide (data out of its range: it raises the error
that names the argument).
"""

from __future__ import annotations

import math

from skcable.cable._special import sinhc_pair

__all__ = ["hanging_forces", "z_of_length"]

#: sinh(z)/z at the largest z evaluated (cosh overflows beyond).
_RHO_LIMIT = math.sinh(709.0) / 709.0


def _excess(span, dh, length):
    """``rho = sqrt(S² - dh²)/span - 1`` free of cancellation (lengths brought to order one by
    a power of two), or None when the length does not exceed the chord."""
    legs = abs(dh)
    unit = math.ldexp(0.5, math.frexp(span if span > legs else legs)[1])
    span, dh, legs, length = span / unit, dh / unit, legs / unit, length / unit  # exact
    chord = math.hypot(span, dh)
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
    target = math.log1p(rho)
    if rho < 0.1:  # the inverted Maclaurin series, error O(rho^4)
        z = math.sqrt(rho * (6.0 + rho * (-1.8 + 0.8229 * rho)))
    else:  # an upper bound: Newton then decreases monotonically to the root
        log = math.log1p(rho)
        z = log + 2.0 * math.log(log + 2.0) + 1.0
    for _ in range(100):
        if z <= 20.0:
            phi, slope = sinhc_pair(z)
            step = (math.log1p(phi) - target) * (1.0 + phi) / slope
        else:  # log(sinh z / z) as z - log(2z) + log1p(-e^{-2z}): no overflow
            step = (z - math.log(2.0 * z) + math.log1p(-math.exp(-2.0 * z)) - target) / (
                1.0 / math.tanh(z) - 1.0 / z
            )
        z = z - step
        if abs(step / z) < 1e-8:  # quadratic convergence: the error is now ~1e-16
            return z
    return None


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
