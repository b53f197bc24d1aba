"""Argument checks and renamings shared by the conductor functions (`change_of_state`,
`tension_section`, `sag_tension_table`, `thermal_catenary`, the line path)."""

from __future__ import annotations

import numpy as np

from skcable import _plausible
from skcable._checks import TINY, positive, require
from skcable.cable._extreme import extreme
from skcable.errors import InputError

__all__ = ["normal", "thermal_factor", "load_plane", "renamed"]


def normal(name, value):
    """``positive(name, value)``, refusing also a subnormal number (below the smallest normal
    float, 2.2e-308): a load, stiffness or length there has lost its relative precision."""
    value = positive(name, value)
    require(
        name, np.asarray(value) >= TINY, f"must be at least the smallest normal float ({TINY:.3g})", value
    )
    return value


def thermal_factor(alpha, t, t0, *, name="t"):
    """``k = 1 + alpha (t - t0)``, refused unless the thermal strain lies in (-1, 1).

    A linear thermal strain of 100 % is beyond any material; the bound also keeps
    ``w/k``, ``EA k`` and ``L0 k`` in the float range. The refusal names the one of ``alpha``,
    ``t``, ``t0`` beyond any physical magnitude (`extreme`), else a temperature below absolute
    zero, else ``alpha`` when it is no cable material's expansion coefficient (beyond 1e-4 1/K,
    or a strain that overflows at a finite ``t - t0``), else the temperature (``name``):
    `skcable._plausible.thermal_argument`.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        dt = np.subtract(t, t0)
        strain = alpha * dt
    ok = np.isfinite(strain) & (np.abs(strain) < 1.0)
    if np.all(ok):
        k = 1.0 + strain
        return float(k) if np.ndim(k) == 0 else k
    overflow = not np.all(np.isfinite(strain))
    outsized = extreme(alpha=alpha, t=t, t0=t0)
    if outsized is not None:  # a magnitude no material or climate has
        blame = name if outsized == "t" else outsized
    elif not np.all(np.isfinite(dt)):
        blame = name
    elif overflow:
        blame = "alpha"
    else:  # one rule with the plausibility checks: below absolute zero, else an implausible alpha
        blame = _plausible.thermal_argument(alpha, t, t0)
        blame = name if blame == "t" else blame
    bad = np.flatnonzero(~np.atleast_1d(ok))[0]
    value = float(np.ravel(np.broadcast_to(strain, np.shape(ok)))[bad])
    raise InputError(
        blame,
        f"gives a thermal strain alpha (t - t0) = {value:.3g} (a thermal factor 1 + alpha (t - t0) "
        f"= {1 + value:.3g}) outside (-1, 1): beyond any material's thermal expansion",
    )


def load_plane(span, dh, w, wind):
    """Resultant load and the span, height difference in its plane.

    ``span_p² = span² + dh² - dh_p² = span² + (dh wind / q)²``, formed without squaring
    the span (no overflow for any float span).
    """
    q = np.hypot(w, wind)
    dh_p = dh * (w / q)
    span_p = np.hypot(span, dh * (wind / q))
    return q, span_p, dh_p


class renamed:  # noqa: N801 - used like a function: ``with renamed({...}):``
    """Context re-raising an inner `InputError` under the public name of the argument at fault
    (the inner solvers name their own arguments: ``H``, ``sag``, ``length``, ``w``)."""

    __slots__ = ("names",)

    def __init__(self, names):
        self.names = names

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, traceback):
        if kind is None or not issubclass(kind, InputError) or exc.argument not in self.names:
            return False
        name = self.names[exc.argument]
        reason = str(exc).split(": ", 1)[-1]
        raise InputError(name, f"(as {exc.argument} of the solved state) {reason}") from exc
