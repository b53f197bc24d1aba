r"""Cable under a uniform load per unit horizontal length: the parabola.

With ``w`` per horizontal length and :math:`a = H/w` (the lecture notes "Cables" §2, Goicolea (2012)
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

import math
from functools import cached_property

import numpy as np

from skcable._checks import broadcast, exactly_one, float_range, positive, real, require
from skcable._xp import namespace, power_of_two_near
from skcable.cable._catenary import finite_at, lowest_point_y
from skcable.cable._roots import LOG_XTOL, find_root
from skcable.cable._special import asinh_step
from skcable.cable.solution import CableSolution, checked_closed_form, matrix_2x2
from skcable.errors import InputError

__all__ = ["Parabola", "parabola"]

#: Range of delta = span/(2a), the half-difference of the end slopes, and
#: largest |dh|/span: below/above, squares of slopes or x/(2a) leave the
#: range (or the precision) of a float.
_DELTA_MIN, _DELTA_MAX = 1e-300, 1e150
_STEEPEST = 1e150

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(24)


_NODE_WEIGHT = tuple(zip(_NODES.tolist(), _WEIGHTS.tolist(), strict=True))


def _excess_quadrature_scalar(a, slope, delta):
    """`_excess_quadrature` for floats (a NumPy call per node pair costs more)."""
    base = math.hypot(1.0, slope)
    total = 0.0
    for node, weight in _NODE_WEIGHT:
        t = node * delta
        total += weight * t * (2.0 * slope + t) / (math.hypot(1.0, slope + t) + base)
    return a * delta * total


def _excess_quadrature(a, slope, delta):
    t = np.multiply.outer(_NODES, delta)  # (24, ...)
    integrand = t * (2.0 * slope + t) / (np.sqrt(1.0 + (slope + t) ** 2) + np.sqrt(1.0 + slope**2))
    return a * delta * np.tensordot(_WEIGHTS, integrand, axes=1)


def _excess_closed(a, slope, delta):
    xp = namespace(a, slope, delta)
    p_a, p_b = slope - delta, slope + delta
    rise = p_b * xp.hypot(1.0, p_b) - p_a * xp.hypot(1.0, p_a)
    return 0.5 * a * (rise + asinh_step(p_a, 2.0 * delta)) - 2.0 * a * delta * xp.hypot(1.0, slope)


def _excess_length(a, slope, delta):
    """Length minus chord of the parabola with parameter ``a`` whose slopes
    run from ``slope - delta`` to ``slope + delta``."""
    if namespace(a, slope, delta) is not np:
        return _excess_quadrature_scalar(a, slope, delta) if delta <= 0.5 else _excess_closed(a, slope, delta)
    a, slope, delta = np.broadcast_arrays(a, slope, delta)
    small = delta <= 0.5
    out = np.empty(a.shape)
    out[small] = _excess_quadrature(a[small], slope[small], delta[small])
    out[~small] = _excess_closed(a[~small], slope[~small], delta[~small])
    return out


def length_derivatives(a, slope, delta, length):
    """``(dS/da, dS/dspan)`` of the parabola's length at constant ``dh``.

    With ``r = sqrt(1 + p²)``: ``dS/da = S/a - delta (r_A + r_B)``, the error
    of the trapezoidal rule for ``∫ r dp``, which cancels for taut cables: for
    ``delta <= 1/2`` it is taken as that error's integral,
    ``-(delta³/2) ∫_{-1}^{1} (1 - t²) (1 + (slope + delta t)²)^{-3/2} dt``
    (24-point Gauss–Legendre). ``dS/dspan = (r_A + r_B)/2 - 2 slope²/(r_A + r_B)``
    is written as ``(1 + delta² + r_A r_B - slope²)/(r_A + r_B)`` with
    ``r_A r_B - slope² = ((1 + delta²)² + 2 slope² (1 - delta²))/(r_A r_B + slope²)``,
    free of cancellation for ``delta <= 1``.
    """
    xp = namespace(a, slope, delta, length)
    p_a, p_b = slope - delta, slope + delta
    r_a, r_b = xp.hypot(1.0, p_a), xp.hypot(1.0, p_b)

    def quadrature(slope, delta):
        t = np.multiply.outer(_NODES, delta)
        integrand = (1.0 - _NODES[:, None] ** 2).reshape((24,) + (1,) * np.ndim(delta)) * (
            1.0 + (slope + t) ** 2
        ) ** -1.5
        return -0.5 * delta**3 * np.tensordot(_WEIGHTS, integrand, axes=1)

    def direct(length, a, delta, r_a, r_b):
        return length / a - delta * (r_a + r_b)

    if xp is not np:
        d_a = float(quadrature(slope, delta)) if delta <= 0.5 else direct(length, a, delta, r_a, r_b)
    else:
        a, slope, delta, length, r_a, r_b = np.broadcast_arrays(a, slope, delta, length, r_a, r_b)
        small = delta <= 0.5
        d_a = np.empty(a.shape)
        d_a[small] = quadrature(slope[small], delta[small])
        d_a[~small] = direct(length[~small], a[~small], delta[~small], r_a[~small], r_b[~small])
    product = r_a * r_b
    rest = ((1.0 + delta * delta) ** 2 + 2.0 * slope * slope * (1.0 - delta * delta)) / (
        product + slope * slope
    )
    d_span = (1.0 + delta * delta + rest) / (r_a + r_b)
    return d_a, d_span


class Parabola(CableSolution):
    """Solution of `parabola`; every attribute broadcasts.

    Attributes are those of `Catenary` (``H = H_A = H_B``, the same all along, ``V_A, V_B,
    T_A, T_B, length, sag``, the lowest point ``x_low, y_low`` in [0, span],
    the vertex ``x_vertex, y_vertex``, which may lie outside the span);
    ``a = H/w`` and the end slopes ``p_A``, ``p_B``.
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
        return self.H * self._xp.hypot(1.0, self.p_A)

    @cached_property
    def T_B(self):
        return self.H * self._xp.hypot(1.0, self.p_B)

    @cached_property
    def length(self):
        chord = self._xp.hypot(self.span, self.dh)
        return chord + _excess_length(self.a, self._slope, self._delta)

    @cached_property
    def sag(self):
        return 0.25 * self.span * self._delta  # span²/(8a)

    @cached_property
    def x_vertex(self):
        return -self.a * self.p_A

    @cached_property
    def y_vertex(self):
        return -0.5 * (self.a * self.p_A) * self.p_A

    @cached_property
    def x_low(self):
        xp = self._xp
        return xp.minimum(xp.maximum(self.x_vertex, 0.0), self.span)

    @cached_property
    def y_low(self):
        return lowest_point_y(self.p_A, self.p_B, self.y_vertex, self.dh)

    def slope(self, x):
        """dy/dx at ``x``."""
        with float_range("x", "slope(x)"):
            return finite_at("x", self.p_A + real("x", x) / self.a, "slope(x)")

    def y(self, x):
        """Height of the cable above A at abscissa ``x`` (m)."""
        x = real("x", x)
        with float_range("x", "y(x)"):
            return finite_at("x", x * (self.p_A + 0.5 * x / self.a), "y(x)")

    def T(self, x):
        """Tension at ``x`` (N)."""
        slope = self.slope(x)
        with float_range("x", "T(x)"):
            return finite_at("x", self.H * namespace(slope).hypot(1.0, slope), "T(x)")

    def weight_per_length(self, x, slope):
        return self.w / np.hypot(1.0, slope)  # w per horizontal metre

    def s_of_x(self, x):
        """Arc length (m) from A to the abscissa ``x`` (`arc_length`)."""
        return arc_length(real("x", x), self.a, self.p_A)

    def x_of_s(self, s):
        """Abscissa (m) of the point at arc length ``s`` (m) from A, in [0, length] (a root of
        the increasing `s_of_x`)."""
        s = self._arc(s)
        s = namespace(s).minimum(s, self.s_of_x(self.span))  # the length up to rounding
        args = (s, self.a, self.p_A)
        x, _ = find_root(_arc_length_minus, 0.0, self.span * (1.0 + 1e-9), args, what="x_of_s")
        return namespace(x).minimum(x, self.span)

    def xy(self, s):
        """Positions ``(..., 2)`` (m) at arc length ``s`` (m) from A."""
        x = self.x_of_s(s)
        return np.stack(np.broadcast_arrays(x, self.y(x)), axis=-1)

    def T_of_s(self, s):
        """Tension (N) at arc length ``s`` (m) from A."""
        return self.T(self.x_of_s(s))

    @cached_property
    def k_G(self):
        """Geometric stiffness ``dH/d(span)`` at constant length and ``dh`` (N/m).

        ``S(a, span)`` held constant: ``k_G = -w (∂S/∂span)/(∂S/∂a)``, both
        derivatives free of the cancellation of the textbook forms for taut cables.
        """
        with float_range("solution", "k_G"), np.errstate(over="ignore", divide="ignore"):
            ds_da, ds_dspan = length_derivatives(self.a, self._slope, self._delta, self.length)
            return -self.w * ds_dspan / ds_da

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, length constant.

        ``S(a, span, dh)`` constant gives ``da/dq = -S_q/S_a``; then ``H = w a``
        and ``V_B = H dh/span + w span/2``. Returns an array of shape
        ``(*shape, 2, 2)`` (N/m): rows ``(H, V_B)``, columns ``(span, dh)``.
        """
        slope, delta = self._slope, self._delta
        with float_range("solution", "the stiffness"), np.errstate(over="ignore", divide="ignore"):
            ds_da, ds_dspan = length_derivatives(self.a, slope, delta, self.length)
            r_a, r_b = namespace(slope).hypot(1.0, self.p_A), namespace(slope).hypot(1.0, self.p_B)
            ds_ddh = 2.0 * slope / (r_a + r_b)
            h_span, h_dh = -self.w * ds_dspan / ds_da, -self.w * ds_ddh / ds_da
            v_span = h_span * slope - self.H * slope / self.span + 0.5 * self.w
            v_dh = h_dh * slope + self.H / self.span
        return matrix_2x2(h_span, h_dh, v_span, v_dh)

    def _residuals(self):
        xp = self._xp
        chord = xp.hypot(self.span, self.dh)
        load = self.w * self.span
        # closure at B: p_A = slope - delta, then + delta again: scale by the slopes that cancel
        closure = self.span * (self.p_A + 0.5 * self.span / self.a) - self.dh
        yield closure / (chord + self.span * (xp.abs(self.p_A) + xp.abs(self.p_B)))
        # vertical equilibrium: V_A and V_B cancel for taut inclined cables
        yield (self.V_A + self.V_B - load) / (xp.abs(self.V_A) + xp.abs(self.V_B) + load)
        yield from self._common_residuals(xp)


def arc_length(x, a, p_A):
    r"""Arc length (m) of the parabola ``y' = p_A + x/a`` from 0 to ``x``:
    :math:`\frac{a}{2}\big[p\sqrt{1 + p^2} + \operatorname{asinh} p\big]_{p_A}^{p}`,
    ``p = p_A + x/a``, with the step ``d = x/a`` formed directly (`asinh_step`, and
    :math:`p r - p_A r_A = d\,(r + p_A (p + p_A)/(r + r_A))` where the slopes share a sign)."""
    xp = namespace(x, a, p_A)
    d = x / a
    p_a = p_A + 0.0 * d
    p = p_a + d
    r, r_a = xp.hypot(1.0, p), xp.hypot(1.0, p_a)
    same = p * p_a > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        rationalised = d * (r + p_a * (p + p_a) / (r + r_a))
        direct = p * r - p_a * r_a
    rise = xp.where(same, rationalised, direct) if xp is np else (rationalised if same else direct)
    return 0.5 * a * (rise + asinh_step(p_a, d))


def _arc_length_minus(x, s, a, p_A):
    return arc_length(x, a, p_A) - s


def _a_from_length(span, dh, length):
    xp = namespace(span, dh, length)
    unit = power_of_two_near(xp.maximum(span, xp.abs(dh)), xp)
    span, dh, length = span / unit, dh / unit, length / unit  # exact
    chord = xp.hypot(span, dh)
    require("length", length > chord, "must exceed the chord sqrt(span**2 + dh**2)", length * unit)
    require(
        "length",
        length <= 1e100 * span,
        "is more than 1e100 spans: the end slopes of the parabola leave the range of a float",
        length * unit,
    )
    excess = length - chord
    slope = dh / span
    # shallow-parabola estimate, excess ~ span^3 / (24 a^2 (1 + slope^2)^(3/2))
    a_guess = xp.sqrt(span / (24.0 * excess)) * span / (1.0 + slope * slope) ** 0.75

    def f(t, span, slope, excess, a_guess):
        a = a_guess * np.exp(t)
        return _excess_length(a, slope, span / (2.0 * a)) / excess - 1.0

    # at lo the end slopes differ by 2·_DELTA_MAX: far more excess than asked
    lo = xp.log(span / (2.0 * _DELTA_MAX * a_guess))
    t, history = find_root(
        f, lo, 40.0, (span, slope, excess, a_guess), what="parabola(length=...)", xtol=LOG_XTOL
    )
    return a_guess * namespace(t).exp(t) * unit, history


def _a_from_T_max(span, dh, tau, T_max):
    """``a`` from ``tau = T_max/w``: T_max = w·a·sqrt(1 + (|dh|/span + span/2a)²)
    is a quadratic in ``a``; lengths scaled to order one first."""
    xp = namespace(span, dh, tau)
    require(
        "T_max", tau > 0.5 * span, "must exceed w·span/2, the weight carried by one support at least", T_max
    )
    slope = xp.abs(dh / span)
    unit = power_of_two_near(xp.maximum(span, tau), xp)
    span, tau = span / unit, tau / unit  # exact
    root = xp.sqrt(4.0 * (1.0 + slope * slope) * tau * tau - span * span)
    return 2.0 * (tau - 0.5 * span) * (tau + 0.5 * span) / (span * slope + root) * unit


def parabola(span, dh, w, *, length=None, sag=None, H=None, low=None, T_max=None):
    """Cable under ``w`` per unit horizontal length from A = (0, 0) to B = (span, dh).

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance A→B (> 0) and height of B above A (m).
    w : float or array_like
        Load per unit horizontal length (N/m), > 0, downward (a deck hung
        from the cable, the lecture notes "Cables" §2).
    length, sag, H, low, T_max : float or array_like
        Exactly one constraint, as in `catenary`; here
        ``sag`` is the mid-span sag ``f`` of ``H = w span² / (8 f)`` and
        ``low`` the y of the vertex, below both supports (``low < min(0, dh)``).

    Returns
    -------
    Parabola
        The same interface as `Catenary`: ``x_low, y_low``
        the cable's lowest point, ``x_vertex, y_vertex`` the parabola's vertex.

    Raises
    ------
    InputError, ConvergenceError
        As `catenary` (here the length search is the solver that may stop).

    Examples
    --------
    Goicolea (2012), example 4 (kg, m): ``T0 = 250.0``, ``Tmax = 269.26``.

    >>> p = parabola(200.0, 0.0, 1.0, sag=20.0)
    >>> round(p.H, 4), round(p.T_max, 2), round(p.length, 4)
    (250.0, 269.26, 205.2121)
    """
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    value = real(name, value) if name == "low" else positive(name, value)
    broadcast(span=span, dh=dh, w=w, **{name: value})
    xp = namespace(span, dh, w, value)
    require("dh", xp.abs(dh) <= _STEEPEST * span, f"must satisfy |dh| <= {_STEEPEST:g}·span", dh)
    history = []
    with float_range(name, "an intermediate value"):
        if name == "H":
            a = value / w
        elif name == "sag":
            a = span / 8.0 * (span / value)
        elif name == "low":
            depth_a, depth_b = -value, dh - value
            require(
                "low", (depth_a > 0) & (depth_b > 0), "must lie below both supports, low < min(0, dh)", value
            )
            a = 0.5 * (span / (xp.sqrt(depth_a) + xp.sqrt(depth_b))) ** 2
        elif name == "T_max":
            tau = value / w
            require("T_max", tau < math.inf, "is so large relative to w that T_max/w overflows", value)
            a = _a_from_T_max(span, dh, tau, value)
        elif name == "length":
            a, history = _a_from_length(span, dh, value)
        else:  # pragma: no cover - exactly_one guards the names
            raise InputError("constraint", name)
        delta = span / (2.0 * a)
    require(name, a > 0, "makes a = H/w underflow", value)
    require(name, a < math.inf, "makes a = H/w overflow a float", value)
    require(
        name, delta >= _DELTA_MIN, "makes the cable so taut that span·w/(2H) underflows (below 1e-300)", value
    )
    require(
        name,
        delta <= _DELTA_MAX,
        f"makes the cable so slack that span·w/(2H) exceeds {_DELTA_MAX:g} (squared slopes overflow)",
        value,
    )
    value = np.asarray(value, dtype=float)[()]
    with float_range(name, "a result"):
        return checked_closed_form(Parabola(span, dh, w, a, (name, value)), name, history)
