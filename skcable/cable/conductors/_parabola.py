"""The parabolic change-of-state equation, elementwise (see `skcable.cable.change_of_state`:
CIGRE TB 324, "Sag-tension calculation methods for overhead lines", 2007; F. Kiessling et al.,
"Overhead Power Lines", Springer, 2003)."""

from __future__ import annotations

import numpy as np

from skcable._checks import TINY
from skcable.cable.conductors._grid import parabolic_cubic
from skcable.errors import InputError

__all__ = ["parabola_states"]


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
