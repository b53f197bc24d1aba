r"""Cable under a uniform load per unit horizontal length: the parabola.

With ``w`` per horizontal length and :math:`a = H/w` (seed 000 §2, seed 001
§3.2), the slope grows linearly, :math:`y'(x) = p_A + x/a`, so

.. math:: y(x) = p_A x + \frac{x^2}{2a}, \qquad
          H = \frac{w\,\mathrm{span}^2}{8f}, \qquad
          p_{A,B} = \frac{dh}{\mathrm{span}} \mp \delta,\quad
          \delta = \frac{\mathrm{span}}{2a},

where ``f`` is the mid-span sag measured vertically from the chord (the
largest chord-to-cable distance, valid for inclined chords). Every
constraint but ``length`` has a closed form: ``low`` gives
:math:`a = \mathrm{span}^2 / (2(\sqrt{d_A} + \sqrt{d_B})^2)` with
:math:`d_{A,B}` the depths of the vertex below A and B; ``T_max`` a
quadratic in ``a``. The length

.. math:: S = \frac{a}{2}\Big[p\sqrt{1+p^2} + \operatorname{asinh} p\Big]_{p_A}^{p_B}

is evaluated as chord + excess, the excess by 24-point Gauss–Legendre
quadrature of a cancellation-free integrand while ``δ ≤ 1/2`` (error below
1e-16 relative), so that very taut cables keep their digits.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from skcable._checks import exactly_one, positive, real, require
from skcable._xp import namespace
from skcable.cable._roots import find_root
from skcable.cable._special import asinh_diff
from skcable.cable.solution import CableSolution, checked
from skcable.errors import InputError

__all__ = ["Parabola", "parabola"]

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(24)


def _excess_quadrature(a, slope, delta):
    t = np.multiply.outer(_NODES, delta)  # (24, ...)
    integrand = t * (2.0 * slope + t) / (np.sqrt(1.0 + (slope + t) ** 2) + np.sqrt(1.0 + slope**2))
    return a * delta * np.tensordot(_WEIGHTS, integrand, axes=1)


def _excess_closed(a, slope, delta):
    xp = namespace(a, slope, delta)
    p_a, p_b = slope - delta, slope + delta
    rise = p_b * xp.sqrt(1.0 + p_b * p_b) - p_a * xp.sqrt(1.0 + p_a * p_a)
    return 0.5 * a * (rise + asinh_diff(p_b, p_a)) - 2.0 * a * delta * xp.sqrt(1.0 + slope * slope)


def _excess_length(a, slope, delta):
    """Length minus chord of the parabola with parameter ``a`` whose slopes
    run from ``slope - delta`` to ``slope + delta``."""
    if namespace(a, slope, delta) is not np:
        return float(_excess_quadrature(a, slope, delta)) if delta <= 0.5 else _excess_closed(a, slope, delta)
    a, slope, delta = np.broadcast_arrays(a, slope, delta)
    small = delta <= 0.5
    out = np.empty(a.shape)
    out[small] = _excess_quadrature(a[small], slope[small], delta[small])
    out[~small] = _excess_closed(a[~small], slope[~small], delta[~small])
    return out


class Parabola(CableSolution):
    """Solution of :func:`parabola`; every attribute broadcasts.

    Attributes are those of :class:`~skcable.cable.Catenary` (``H, V_A, V_B,
    T_A, T_B, length, sag, x_low, y_low``); ``a = H/w`` and the end slopes
    ``p_A``, ``p_B``.
    """

    def __init__(self, span, dh, w, a, constraint):
        self.span, self.dh, self.w, self.a = span, dh, w, a
        self._xp = namespace(span, dh, w, a)
        self.constraint = constraint
        self._slope = dh / span
        self._delta = span / (2.0 * a)
        self.p_A = self._slope - self._delta
        self.p_B = self._slope + self._delta

    @cached_property
    def H(self):
        return self.w * self.a

    @cached_property
    def V_A(self):
        return -self.H * self.p_A

    @cached_property
    def V_B(self):
        return self.H * self.p_B

    @cached_property
    def T_A(self):
        return self.H * self._xp.sqrt(1.0 + self.p_A**2)

    @cached_property
    def T_B(self):
        return self.H * self._xp.sqrt(1.0 + self.p_B**2)

    @cached_property
    def length(self):
        chord = self._xp.hypot(self.span, self.dh)
        return chord + _excess_length(self.a, self._slope, self._delta)

    @cached_property
    def sag(self):
        return self.span**2 / (8.0 * self.a)

    @cached_property
    def x_low(self):
        return -self.a * self.p_A

    @cached_property
    def y_low(self):
        return -0.5 * self.a * self.p_A**2

    def slope(self, x):
        """dy/dx at ``x``."""
        return self.p_A + real("x", x) / self.a

    def y(self, x):
        """Height of the cable above A at abscissa ``x`` (m)."""
        x = real("x", x)
        return x * (self.p_A + 0.5 * x / self.a)

    def T(self, x):
        """Tension at ``x`` (N)."""
        slope = self.slope(x)
        return self.H * namespace(slope).sqrt(1.0 + slope * slope)

    def weight_per_length(self, x, slope):
        return self.w / np.sqrt(1.0 + slope * slope)  # w per horizontal metre

    def _residuals(self):
        xp = self._xp
        chord = xp.hypot(self.span, self.dh)
        load = self.w * self.span
        yield (self.span * (self.p_A + 0.5 * self.span / self.a) - self.dh) / chord
        yield (self.V_A + self.V_B - load) / load
        yield from self._common_residuals(xp)


def _a_from_length(span, dh, length):
    xp = namespace(span, dh, length)
    chord = xp.hypot(span, dh)
    require("length", length > chord, "must exceed the chord sqrt(span**2 + dh**2)", length)
    excess = length - chord
    slope = dh / span
    # shallow-parabola estimate, excess ~ span^3 / (24 a^2 (1 + slope^2)^(3/2))
    a_guess = xp.sqrt(span**3 / (24.0 * excess)) / (1.0 + slope * slope) ** 0.75

    def f(t, span, slope, excess, a_guess):
        a = a_guess * np.exp(t)
        return _excess_length(a, slope, span / (2.0 * a)) / excess - 1.0

    t, history = find_root(f, -40.0, 40.0, (span, slope, excess, a_guess), what="parabola(length=...)")
    return a_guess * namespace(t).exp(t), history


def parabola(span, dh, w, *, length=None, sag=None, H=None, low=None, T_max=None):
    """Cable under ``w`` per unit horizontal length from A = (0, 0) to B = (span, dh).

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance A→B (> 0) and height of B above A (m).
    w : float or array_like
        Load per unit horizontal length (N/m), > 0, downward (a deck hung
        from the cable, seed 000 §2).
    length, sag, H, low, T_max : float or array_like
        Exactly one constraint, as in :func:`~skcable.cable.catenary`; here
        ``sag`` is the mid-span sag ``f`` of ``H = w span² / (8 f)``.

    Returns
    -------
    Parabola
        The same interface as :class:`~skcable.cable.Catenary`.

    Examples
    --------
    Seed 001, example 4 (kg, m): ``T0 = 250.0``, ``Tmax = 269.26``.

    >>> p = parabola(200.0, 0.0, 1.0, sag=20.0)
    >>> round(p.H, 4), round(p.T_max, 2), round(p.length, 4)
    (250.0, 269.26, 205.2121)
    """
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    xp = namespace(span, dh, w, value if isinstance(value, np.ndarray) else 0.0)
    history = []
    if name == "H":
        a = positive("H", value) / w
    elif name == "sag":
        a = span**2 / (8.0 * positive("sag", value))
    elif name == "low":
        low = real("low", value)
        depth_a, depth_b = -low, dh - low
        require("low", (depth_a > 0) & (depth_b > 0), "must lie below both supports, low < min(0, dh)", low)
        a = span**2 / (2.0 * (xp.sqrt(depth_a) + xp.sqrt(depth_b)) ** 2)
    elif name == "T_max":
        tau = positive("T_max", value) / w
        require(
            "T_max",
            tau > 0.5 * span,
            "must exceed w·span/2, the weight carried by one support at least",
            value,
        )
        slope = xp.abs(dh / span)
        a = (
            2.0
            * (tau**2 - 0.25 * span**2)
            / (span * slope + xp.sqrt(4.0 * (1.0 + slope**2) * tau**2 - span**2))
        )
    elif name == "length":
        a, history = _a_from_length(span, dh, positive("length", value))
    else:  # pragma: no cover - exactly_one guards the names
        raise InputError("constraint", name)
    value = np.asarray(value, dtype=float)[()]
    return checked(Parabola(span, dh, w, a, (name, value)), history)
