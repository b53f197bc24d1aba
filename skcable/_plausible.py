"""Plausibility checks: data that solve but that a unit slip would explain.

Each check warns (`skcable.errors.PlausibilityWarning`, naming the argument as the public
API spells it and the likely unit mistake) and never changes a result; the library's
functions call them in one line, after their own refusals (a refused input gets one
message: the refusal):

- a strain beyond 5 %: no steel or aluminium cable survives it (a strand's wires are
  allowed up to 1.5 times their largest rupture strain, the capacity curve's schedule);
- a conductor's sag larger than its span (change of state and natural frequencies, theories
  of a shallow cable; the catenary and the parabola are exact at any sag, and a slack rope
  does sag more than its span);
- an axial stiffness below a hundredth of the line's own weight, ``EA < 0.01 w L``: its
  weight alone would stretch it a hundredfold (EA typed in MN, say; test lines as stretchy
  as rubber, ``EA`` about ``w L``, stay quiet).

Floats (NumPy scalars too) take a fast path, a comparison of floats; arrays one ``np.any``.
"""

from __future__ import annotations

import warnings

import numpy as np

from skcable.errors import PlausibilityWarning

__all__ = [
    "MAX_STRAIN",
    "conductor",
    "stiffness",
    "strand_strain",
    "thermal_argument",
]

#: The largest strain a steel or aluminium cable survives.
MAX_STRAIN = 0.05
#: The smallest plausible EA / (w·length): below it the line's weight stretches it a hundredfold.
MIN_STIFFNESS = 0.01
#: Absolute zero in °C: a temperature below it is a mistake, not a state.
ABSOLUTE_ZERO = -273.15
#: No cable material expands by more than this per kelvin (steel 1.2e-5, aluminium 2.3e-5 1/K).
MAX_ALPHA = 1e-4


def _largest(value) -> float:
    """The largest element (a float as it is); NaN is refused by the callers' own checks."""
    if isinstance(value, float):
        return value
    return float(np.max(value))


def _warn(argument: str, reason: str) -> None:
    warnings.warn(PlausibilityWarning(argument, reason), stacklevel=3)


def stiffness(EA, w, length, argument: str = "EA") -> None:
    """Warn if ``EA < MIN_STIFFNESS·w·length`` anywhere: the line's weight alone would
    stretch it a hundredfold, which no material does (rubber-like test lines, stretched by
    their length, stay quiet). The message names ``EA`` alone, so that the solves inside a
    change of state, say, repeat the same line (shown once)."""
    if isinstance(EA, float) and isinstance(w, float) and isinstance(length, float):
        if EA >= MIN_STIFFNESS * w * length:
            return
        least = EA
    else:
        EA, weight = np.asarray(EA, dtype=float), np.asarray(w) * np.asarray(length)
        low = EA < MIN_STIFFNESS * weight
        if not np.any(low):
            return
        least = float(np.min(np.broadcast_to(EA, low.shape)[low]))
    _warn(
        argument,
        f"{least:.3g} N is below a hundredth of the line's own weight w·length: its weight alone "
        "would stretch it more than a hundredfold (a steel line's EA is thousands of times "
        "w·length); is EA in N (not kN or MN)?",
    )


def conductor(span, dh, *, EA, w, sag=None, alpha=None, t=None, t0=None) -> None:
    """A conductor's span (change of state, natural frequencies: theories of a shallow
    cable): ``sag`` against the span, ``EA`` against the weight of the chord's length, and the
    thermal strain ``alpha·(t - t0)``."""
    stiffness(EA, _largest(w), float(np.hypot(span, dh)))
    if sag is not None and _largest(sag) > span:
        _warn(
            "sag",
            f"is {_largest(sag) / span:.3g} times the span, where a conductor sags a few per cent "
            "of it; is the sag in m (not cm or mm)?",
        )
    if alpha is not None:
        strain = abs(alpha) * float(np.max(np.abs(np.asarray(t, dtype=float) - t0)))
        if strain > MAX_STRAIN:
            _warn(
                "alpha",
                f"gives a thermal strain |alpha·(t - t0)| up to {strain:.3g}, beyond 5 % (no steel or "
                "aluminium cable survives it); is alpha in 1/K (not 1e-6/K: 23e-6, not 23)?",
            )


def thermal_argument(alpha, t, t0) -> str:
    """The argument to blame for a thermal factor ``1 + alpha (t - t0) <= 0``: a temperature
    below absolute zero, else an ``alpha`` beyond any cable material's, else ``t``."""
    if _largest(-np.asarray(t0, dtype=float)) > -ABSOLUTE_ZERO:
        return "t0"
    if _largest(-np.asarray(t, dtype=float)) > -ABSOLUTE_ZERO:
        return "t"
    return "alpha" if _largest(np.abs(alpha)) > MAX_ALPHA else "t"


def strand_strain(argument: str, strain, rupture) -> None:
    """Warn if an imposed strain exceeds 5 % and 1.5 times the largest rupture strain of the
    strand's wires (``rupture``: one value or several): no wire survives it."""
    limit = max(MAX_STRAIN, 1.5 * _largest(np.asarray(rupture, dtype=float)))
    largest = _largest(np.abs(strain)) if not isinstance(strain, float) else abs(strain)
    if largest > limit:
        _warn(
            argument,
            f"is a strain of {largest:.3g}, beyond 5 % and beyond 1.5 times the wires' rupture strain "
            f"(no wire survives it); is it a strain (0.01), not a per cent (1)?",
        )
