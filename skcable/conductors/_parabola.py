"""The parabolic change-of-state equation, elementwise (see `skcable.conductors.change_of_state`:
CIGRE TB 324, "Sag-tension calculation methods for overhead lines", 2007; F. Kiessling et al.,
"Overhead Power Lines", Springer, 2003)."""

from __future__ import annotations

import numpy as np

from skcable._checks import TINY
from skcable.errors import ConvergenceError, InputError

__all__ = ["parabola_states", "parabolic_cubic"]


def parabolic_cubic(b, d, rtol=4e-16):
    """The positive root of ``H³ + b H² - d = 0`` (``d > 0``), elementwise: Newton from above.

    Both ``max(0, -b) + d^(1/3)`` and, for ``b > 0``, ``(d/b)^(1/2)`` bound the root from
    above, and the cubic is convex there: Newton from the smaller one decreases to the root.
    """
    H = np.maximum(0.0, -b) + np.cbrt(d)
    with np.errstate(divide="ignore"):
        H = np.where(b > 0, np.minimum(H, np.sqrt(d / np.where(b > 0, b, 1.0))), H)
    history = []
    for _ in range(200):
        step = (H**3 + b * H**2 - d) / (3 * H**2 + 2 * b * H)
        H = H - step
        history.append(float(np.max(np.abs(step / H))))
        if history[-1] < rtol:
            return H
    raise ConvergenceError("parabolic change of state: Newton on the cubic did not converge", history)


def _square(x):
    """``x * x``: a Python float's ``x**2`` raises OverflowError where the product is inf (refused
    by the checks that follow, naming an argument)."""
    return x * x


def parabola_states(span, dh, EA, alpha, w0, t0, H0, sag0, t, q, span_p, dh_p):
    """The parabolic change of state (module text), elementwise over broadcast arrays.

    Returns ``L0, H0, sag0, H_plane, sag, T_max, length`` (the reference's and the states').
    """
    chord = np.hypot(span, dh)
    cos0 = span / chord
    name = "H0" if sag0 is None else "sag0"
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
        if H0 is None:  # products, not powers: a float's ** raises on overflow
            H0 = w0 * span * span / (8.0 * sag0 * cos0)
        sag0_out = w0 * span * span / (8.0 * H0 * cos0)
    if not np.all(np.isfinite(H0) & (H0 >= TINY) & np.isfinite(sag0_out) & (sag0_out >= TINY)):
        raise InputError(
            name,
            "gives a parabolic reference state (H0 = w0 span^2/(8 sag0 cos psi)) outside the range "
            "of a float",
        )
    cos = span_p / chord
    with np.errstate(over="ignore", invalid="ignore"):
        excess0 = _square(w0 * span * cos0) / (24.0 * _square(H0))  # (S0 - c) / c
        L0 = chord * (1.0 + excess0) - H0 * chord / (EA * cos0)
    if not np.all(L0 > 0):
        name = "H0" if sag0 is None else "sag0"
        strain = np.max(H0 / (EA * cos0))
        raise InputError(
            name,
            "the reference state stretches the cable by more than its length (H0/(EA cos psi) "
            f"= {strain:.3g}): the parabolic equation, a small-strain form, does not apply",
        )
    b = -H0 * cos / cos0 + EA * cos * (alpha * (t - t0)) + EA * cos * excess0
    d = EA * cos * _square(q * span_p * cos) / 24.0
    H_plane = parabolic_cubic(b, d)
    sag = q * span_p * span_p / (8.0 * H_plane * cos)
    tan = dh_p / span_p
    T_max = np.hypot(H_plane, H_plane * np.abs(tan) + q * span_p / (2.0 * cos))
    length = chord * (1.0 + _square(q * span_p * cos) / (24.0 * _square(H_plane)))
    return L0, H0, sag0_out, H_plane, sag, T_max, length
