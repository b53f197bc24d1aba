r"""Inextensible catenary between supports at different heights.

A uniform cable of weight ``w`` per unit length hangs from A = (0, 0) to
B = (span, dh). With the catenary parameter :math:`a = H/w` its profile is
(seed 000 §3, seed 001 eq. 17)

.. math:: y(x) = y_\mathrm{low} + a\left[\cosh\frac{x - x_\mathrm{low}}{a} - 1\right],
          \qquad T(x) = H\cosh\frac{x - x_\mathrm{low}}{a}.

Everything is parametrised by :math:`z = \mathrm{span}/(2a)` and the
hyperbolic angle at mid-span :math:`m`, where :math:`u_A = m - z`,
:math:`u_B = m + z` and

.. math:: \sinh m = \frac{dh}{\mathrm{span}}\,\frac{z}{\sinh z}, \qquad
          S^2 - dh^2 = 4a^2\sinh^2 z, \qquad S = 2a\sinh z\cosh m.

The "fourth equation" (seed 000) is one of: unstretched ``length``, ``sag``
(largest vertical distance chord–cable), horizontal tension ``H``, ``low``
(y of the lowest point, relative to A) or ``T_max`` (tension at the higher
support, seed 001 §3.4.1: a counterweight over a pulley). Given the length,
``sinh(z)/z = sqrt(S² − dh²)/span`` is solved by Newton's method on
``log(sinh z / z)``, which is increasing and convex in z: started from an
upper bound it converges monotonically, with no bracket and no fallback.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np
from scipy.optimize import elementwise

from skcable._checks import exactly_one, positive, real, require
from skcable._xp import namespace
from skcable.cable._roots import find_root
from skcable.cable._special import dsinhc, largest_abs, piecewise, sinhc_m1
from skcable.cable.solution import CableSolution, checked
from skcable.errors import ConvergenceError, InputError

__all__ = ["Catenary", "catenary"]

_Z_MAX = 350.0  # cosh(350 + m) stays far from overflow for any |dh/span| < 1e100


class Catenary(CableSolution):
    """Solution of :func:`catenary`; every attribute broadcasts.

    Attributes
    ----------
    span, dh, w : float or ndarray
        The data (m, m, N/m).
    a : float or ndarray
        Catenary parameter H/w (m).
    z, m : float or ndarray
        Half-span over ``a``, and the hyperbolic angle at mid-span.
    H, V_A, V_B, T_A, T_B : float or ndarray
        Horizontal tension, upward reactions and end tensions (N).
    length, sag, x_low, y_low : float or ndarray
        Cable length, largest vertical chord-to-cable distance, and the
        vertex of the catenary (m); the vertex may lie outside the span.
    """

    def __init__(self, span, dh, w, a, z, constraint: tuple[str, object]):
        self.span, self.dh, self.w, self.a, self.z = span, dh, w, a, z
        self._xp = xp = namespace(span, dh, w, a, z)
        self._phi = sinhc_m1(z)
        self.m = xp.arcsinh(dh / span / (1.0 + self._phi))
        self.constraint = constraint

    # --- reactions and tensions ------------------------------------------
    @cached_property
    def H(self):
        return self.w * self.a

    @cached_property
    def V_A(self):
        return self.H * self._xp.sinh(self.z - self.m)

    @cached_property
    def V_B(self):
        return self.H * self._xp.sinh(self.z + self.m)

    @cached_property
    def T_A(self):
        return self.H * self._xp.cosh(self.m - self.z)

    @cached_property
    def T_B(self):
        return self.H * self._xp.cosh(self.m + self.z)

    # --- geometry ----------------------------------------------------------
    @cached_property
    def length(self):
        return 2.0 * self.a * self._xp.sinh(self.z) * self._xp.cosh(self.m)

    @cached_property
    def x_low(self):
        return self.a * (self.z - self.m)

    @cached_property
    def y_low(self):
        return -2.0 * self.a * self._xp.sinh(0.5 * (self.m - self.z)) ** 2

    @cached_property
    def sag(self):
        return self.a * _sag_over_a(self.z, self.m, self._phi)

    def _u(self, x):
        x = real("x", x)
        return self.m - self.z + x / self.a, namespace(x, self.a)

    def y(self, x):
        """Height of the cable above A at abscissa ``x`` (m)."""
        x = real("x", x)
        xp, half = namespace(x, self.a), 0.5 * x / self.a
        return 2.0 * self.a * xp.sinh(self.m - self.z + half) * xp.sinh(half)

    def slope(self, x):
        """dy/dx at ``x``."""
        u, xp = self._u(x)
        return xp.sinh(u)

    def T(self, x):
        """Tension at ``x`` (N)."""
        u, xp = self._u(x)
        return self.H * xp.cosh(u)

    def weight_per_length(self, x, slope):
        return self.w + 0.0 * slope

    def _residuals(self):
        span, dh, a, z, m, xp = self.span, self.dh, self.a, self.z, self.m, self._xp
        chord = xp.hypot(span, dh)
        weight = self.w * self.length
        yield (2.0 * a * xp.sinh(m) * xp.sinh(z) - dh) / chord  # closure at B
        yield (self.V_A + self.V_B - weight) / weight  # vertical equilibrium
        yield from self._common_residuals(xp)


def _sag_over_a(z, m, phi):
    """Largest vertical chord-to-cable distance divided by ``a``.

    With ``t`` the hyperbolic angle measured from mid-span, the distance is
    ``a[cosh m (cosh z - cosh t) + sinh m · t (φ(z) - φ(t))]``, φ(z) =
    sinh(z)/z - 1, largest where the slope equals the chord's.
    """
    xp = namespace(z, m)
    sm, cm = xp.sinh(m), xp.cosh(m)
    s = sm * (1.0 + phi)  # chord slope dh/span
    t = xp.arcsinh(sm * phi * (2.0 + phi) / ((1.0 + phi) * cm + xp.sqrt(1.0 + s * s)))
    return 2.0 * cm * xp.sinh(0.5 * (z + t)) * xp.sinh(0.5 * (z - t)) + sm * t * (phi - sinhc_m1(t))


def _z_from_length(span, dh, length):
    xp = namespace(span, dh, length)
    chord = xp.hypot(span, dh)
    require("length", length > chord, "must exceed the chord sqrt(span**2 + dh**2)", length)
    # r - 1 with r = sqrt(S^2 - dh^2)/span, free of cancellation for taut
    # cables: S^2 - chord^2 = (S - M)(S + M) - m^2 with M the longer leg, so
    # that S - M is exact (Sterbenz) and level or vertical spans lose nothing
    legs = xp.abs(dh)
    longer, shorter = xp.maximum(span, legs), xp.minimum(span, legs)
    excess_sq = (length - longer) * (length + longer) - shorter * shorter
    rho = excess_sq / (span * (xp.sqrt((length - legs) * (length + legs)) + span))
    target = xp.log1p(rho)
    # g(z) = log(sinh z / z) - target is convex and increasing: whatever the
    # start, Newton's iterates lie right of the root after one step and then
    # decrease monotonically to it. Start from the inverted Maclaurin series
    # (error O(rho^4)) for small rho, from an upper bound otherwise.
    z = piecewise(
        rho,
        rho < 0.1,
        lambda r: xp.sqrt(r * (6.0 + r * (-1.8 + 0.8229 * r))),
        lambda r: xp.log1p(r) + 2.0 * xp.log(xp.log1p(r) + 2.0) + 1.0,
    )
    history = []
    for _ in range(100):
        phi = sinhc_m1(z)
        step = (xp.log1p(phi) - target) * (1.0 + phi) / dsinhc(z)
        z = z - step
        change = largest_abs(step / z)
        history.append(change)
        if change < 1e-8:  # quadratic convergence: the error is now ~1e-16
            return z, history
    raise ConvergenceError("catenary(length=...): Newton did not converge", history)


def _z_from_sag(span, dh, sag):
    ratio = sag / span

    def f(logz, s, ratio):
        z = np.exp(logz)
        phi = sinhc_m1(z)
        m = np.arcsinh(s / (1.0 + phi))
        return _sag_over_a(z, m, phi) / (2.0 * z) - ratio

    lo, hi = np.log(1e-14), np.log(_Z_MAX)
    s = dh / span
    require("sag", f(lo, s, ratio) < 0, "is too small: below 1e-14·span the cable is its chord", sag)
    require("sag", f(hi, s, ratio) > 0, "is too large for a hanging cable of this span", sag)
    logz, history = find_root(f, lo, hi, (s, ratio), what="catenary(sag=...)")
    return np.exp(logz), history


def _a_from_low(span, dh, low):
    depth_a, depth_b = -low, dh - low
    require(
        "low",
        (depth_a > 0) & (depth_b > 0),
        "must lie below both supports, low < min(0, dh); a cable whose lowest point "
        "is a support is not determined by it",
        low,
    )
    a_parabola = span**2 / (2.0 * (np.sqrt(depth_a) + np.sqrt(depth_b)) ** 2)

    def f(t, span, depth_a, depth_b, a_parabola):
        a = a_parabola * np.exp(t)
        arcs = np.arcsinh(np.sqrt(depth_a / (2 * a))) + np.arcsinh(np.sqrt(depth_b / (2 * a)))
        return 2.0 * a / span * arcs - 1.0

    t, history = find_root(f, -70.0, 70.0, (span, depth_a, depth_b, a_parabola), what="catenary(low=...)")
    return a_parabola * np.exp(t), history


def _tau(t, s):
    """T_max / (w·span) as a function of t = ln(a/span), with s = dh/span."""
    z = np.minimum(0.5 * np.exp(-t), _Z_MAX)
    phi = sinhc_m1(z)
    m = np.arcsinh(s / (1.0 + phi))
    return 0.5 / z * np.cosh(np.abs(m) + z)


def _a_from_T_max(span, dh, w, T_max, branch):
    if branch not in ("taut", "slack"):
        raise InputError("branch", f"must be 'taut' or 'slack', got {branch!r}")
    s = dh / span + 0.0 * T_max
    bracket = elementwise.bracket_minimum(_tau, np.full(np.shape(s), np.log(1 / 2.4)), args=(s,))
    best = elementwise.find_minimum(_tau, bracket.bracket, args=(s,))
    if not (np.all(bracket.success) and np.all(best.success)):
        raise ConvergenceError("catenary(T_max=...): least maximum tension not found")
    target = T_max / (w * span)
    least = best.f_x * w * span
    require(
        "T_max",
        target >= best.f_x,
        f"is below the least maximum tension that spans this gap ({np.min(least):.6g})",
        T_max,
    )
    lo, hi = (best.x, 70.0) if branch == "taut" else (np.log(0.5 / _Z_MAX), best.x)
    t, history = find_root(
        lambda t, s, target: _tau(t, s) - target, lo, hi, (s, target), what="catenary(T_max=...)"
    )
    return span * np.exp(t), history


def catenary(span, dh, w, *, length=None, sag=None, H=None, low=None, T_max=None, branch="taut"):
    """Inextensible catenary from A = (0, 0) to B = (span, dh).

    Parameters
    ----------
    span : float or array_like
        Horizontal distance A→B (m), > 0.
    dh : float or array_like
        Height of B above A (m); negative when B is below A.
    w : float or array_like
        Weight per unit cable length (N/m), > 0, acting downward.
    length, sag, H, low, T_max : float or array_like
        Exactly one: the cable length (> chord); the largest vertical
        distance chord–cable; the horizontal tension; the y of the lowest
        point relative to A (< min(0, dh)); or the tension at the higher
        support (a counterweight over a pulley, seed 001 §3.4.1).
    branch : {"taut", "slack"}
        With ``T_max`` two catenaries exist (seed 001 §3.4.1): the taut one
        (default) or the slack one.

    Returns
    -------
    Catenary
        ``H, V_A, V_B, T_A, T_B, length, sag, x_low, y_low`` and ``y(x)``,
        ``T(x)``, ``slope(x)``, ``residual()``; arrays when inputs are.

    Raises
    ------
    InputError
        A non-physical argument (named), or not exactly one constraint.
    ConvergenceError
        The solver stopped, or the residual of the solution exceeds 1e-9.

    Examples
    --------
    Seed 000, example 4 (kN, m): lowest point 30 m below A.

    >>> c = catenary(800.0, -20.0, 20.0, low=-30.0)
    >>> round(float(c.H), 1), round(float(c.x_low), 2)
    (85819.2, 507.11)
    """
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    if name == "length":
        z, history = _z_from_length(span, dh, positive("length", value))
        a = span / (2.0 * z)
    elif name == "H":
        a = positive("H", value) / w
        history = []
    elif name == "sag":
        z, history = _z_from_sag(span, dh, positive("sag", value))
        a = span / (2.0 * z)
    elif name == "low":
        a, history = _a_from_low(span, dh, real("low", value))
    else:
        a, history = _a_from_T_max(span, dh, w, positive("T_max", value), branch)
    value = np.asarray(value, dtype=float)[()]
    return checked(Catenary(span, dh, w, a, span / (2.0 * a), (name, value)), history)
