r"""Inextensible catenary between supports at different heights.

A uniform cable of weight ``w`` per unit length hangs from A = (0, 0) to
B = (span, dh). With the catenary parameter :math:`a = H/w` its profile is
(the lecture notes "Cables" §3, Goicolea (2012) eq. 17)

.. math:: y(x) = y_\mathrm{low} + a\left[\cosh\frac{x - x_\mathrm{low}}{a} - 1\right],
          \qquad T(x) = H\cosh\frac{x - x_\mathrm{low}}{a}.

Everything is parametrised by :math:`z = \mathrm{span}/(2a)` and the
hyperbolic angle at mid-span :math:`m`, where :math:`u_A = m - z`,
:math:`u_B = m + z` and

.. math:: \sinh m = \frac{dh}{\mathrm{span}}\,\frac{z}{\sinh z}, \qquad
          S^2 - dh^2 = 4a^2\sinh^2 z, \qquad S = 2a\sinh z\cosh m.

The "fourth equation" (the lecture notes "Cables") is one of: unstretched ``length``, ``sag``
(largest vertical distance chord–cable), horizontal tension ``H``, ``low``
(y of the vertex relative to A; it must lie below both supports, so the
vertex lies inside the span and is the cable's lowest point) or ``T_max``
(tension at the higher support, Goicolea (2012) §3.4.1: a counterweight over a
pulley). Given the length,
``sinh(z)/z = sqrt(S² − dh²)/span`` is solved by Newton's method on
``log(sinh z / z)``, which is increasing and convex in z: started from an
upper bound it converges monotonically, with no bracket and no fallback.
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from skcable._checks import broadcast, exactly_one, float_range, positive, real, require
from skcable._xp import namespace
from skcable.cable._roots import find_root
from skcable.cable._special import (
    dsinhc,
    largest_abs,
    ldexp_sum,
    log_cosh,
    piecewise,
    power_product,
    sinhc_m1,
    z_minus_tanh_over_cube,
)
from skcable.cable.solution import CableSolution, checked_closed_form, matrix_2x2
from skcable.errors import ConvergenceError, InputError

__all__ = ["Catenary", "catenary"]

_Z_MAX = 350.0  # the sag search: phi(z)**2 overflows near z = 355
#: Range of z = span/(2a) the closed form evaluates: below _Z_MIN the abscissae
#: x/(2a) turn subnormal (no relative precision), above _Z_LIMIT sinh(z) overflows.
_Z_MIN, _Z_LIMIT = 1e-300, 709.0
#: Largest |dh|/span: squares of lengths scaled by the longer leg stay representable.
_STEEPEST = 1e150


class Catenary(CableSolution):
    """Solution of `catenary`; every attribute broadcasts.

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
    length, sag : float or ndarray
        Cable length and largest vertical chord-to-cable distance (m).
    x_low, y_low : float or ndarray
        Lowest point of the cable (m), in [0, span]: the vertex when it lies
        between the supports, else the lower support.
    x_vertex, y_vertex : float or ndarray
        Vertex of the catenary (horizontal tangent, m); it may lie outside
        the span, where it is not a point of the cable.
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
        return 2.0 * (self.a * self._xp.sinh(self.z)) * self._xp.cosh(self.m)

    @cached_property
    def x_vertex(self):
        return self.a * (self.z - self.m)

    @cached_property
    def y_vertex(self):
        half = self._xp.sinh(0.5 * (self.m - self.z))
        return -2.0 * (self.a * half) * half  # a first: no underflow of half**2

    @cached_property
    def x_low(self):
        # u_A = m - z >= 0: the cable rises from A; u_B = m + z <= 0: it falls to B
        xp = self._xp
        return xp.minimum(xp.maximum(self.x_vertex, 0.0), self.span)

    @cached_property
    def y_low(self):
        return _lowest(self.m - self.z, self.m + self.z, self.y_vertex, self.dh)

    @cached_property
    def sag(self):
        return _sag_over_a(self.z, self.m, self._phi, self.a)

    def _u(self, x):
        x = real("x", x)
        return self.m - self.z + x / self.a, namespace(x, self.a, self.m)

    def y(self, x):
        """Height of the cable above A at abscissa ``x`` (m)."""
        x = real("x", x)
        xp, half = namespace(x, self.a, self.m), 0.5 * x / self.a
        with float_range("x", "y(x)"):
            return _finite_at("x", 2.0 * xp.sinh(self.m - self.z + half) * (self.a * xp.sinh(half)), "y(x)")

    def slope(self, x):
        """dy/dx at ``x``."""
        u, xp = self._u(x)
        with float_range("x", "slope(x)"):
            return _finite_at("x", xp.sinh(u), "slope(x)")

    def T(self, x):
        """Tension at ``x`` (N)."""
        u, xp = self._u(x)
        with float_range("x", "T(x)"):
            return _finite_at("x", self.H * xp.cosh(u), "T(x)")

    def weight_per_length(self, x, slope):
        return self.w + 0.0 * slope

    @cached_property
    def k_G(self):
        r"""Geometric stiffness ``dH/d(span)`` at constant length and ``dh`` (N/m).

        :math:`k_G = w/(2(z - \tanh z))` (Goicolea 2012, example 7), any ``dh``.
        """
        # w/z³ from mantissas and exponents: z³ underflows for taut cables long
        # before the stiffness overflows
        z = self.z
        with float_range("solution", "k_G"):
            return ldexp_sum(power_product(0.5, (self.w, 1), (z, -3))) / z_minus_tanh_over_cube(z)

    def stiffness(self):
        r"""Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, length constant.

        From :math:`S^2 = dh^2 + Q^2`, :math:`Q = 2a\sinh z`,
        :math:`V_B = (wS + w\,dh\coth z)/2` and :math:`\sinh m = dh/Q`:

        .. math::
            K = \begin{pmatrix} k_G & k_G \sinh m/\cosh z \\
                k_G \sinh m/\cosh z & \tfrac{w}{2}\coth z + k_G \sinh^2 m \, z/(\sinh z\cosh z)
                \end{pmatrix}.

        Returns an array of shape ``(*shape, 2, 2)`` (N/m): rows ``(H, V_B)``,
        columns ``(span, dh)``.
        """
        xp, z, k_g = self._xp, self.z, self.k_G
        with float_range("solution", "the stiffness"), np.errstate(over="ignore"):
            sinh_m, cosh_z, tanh_z = xp.sinh(self.m), xp.cosh(z), xp.tanh(z)
            cross = k_g * (sinh_m / cosh_z)
            # z/(sinh z cosh z) = 2z/sinh 2z, in (0, 1]
            vv = 0.5 * self.w / tanh_z + k_g * sinh_m * sinh_m * (z / cosh_z) / xp.sinh(z)
        return matrix_2x2(k_g, cross, cross, vv)

    def _residuals(self):
        span, dh, a, z, m, xp = self.span, self.dh, self.a, self.z, self.m, self._xp
        chord = xp.hypot(span, dh)
        weight = self.w * self.length
        yield (2.0 * xp.sinh(m) * (a * xp.sinh(z)) - dh) / chord  # closure at B
        # vertical equilibrium: V_A and V_B cancel for taut inclined cables
        # (|V| ~ H·|dh|/span >> weight): scale by what cancels
        yield (self.V_A + self.V_B - weight) / (xp.abs(self.V_A) + xp.abs(self.V_B) + weight)
        yield from self._common_residuals(xp)


def _lowest(u_a, u_b, y_vertex, dh):
    """y of the cable's lowest point: A (0) when it rises from A (u_A >= 0), B
    (dh) when it falls to B (u_B <= 0), else the vertex. Shared with the parabola."""
    if not isinstance(y_vertex, np.ndarray) and not isinstance(dh, np.ndarray):
        return 0.0 if u_a >= 0 else dh if u_b <= 0 else y_vertex
    return np.where(u_a >= 0, 0.0, np.where(u_b <= 0, dh, y_vertex))


def _finite_at(name, value, what):
    if isinstance(value, np.ndarray):
        if not np.isfinite(value).all():
            raise InputError(name, f"is so far outside the span that {what} overflows a float")
    elif not math.isfinite(value):
        raise InputError(name, f"is so far outside the span that {what} overflows a float")
    return value


def _sag_over_a(z, m, phi, a=1.0):
    """Largest vertical chord-to-cable distance divided by ``a`` (times ``a``
    if given: multiplied in before the small factors, so that nothing underflows).

    With ``t`` the hyperbolic angle measured from mid-span, the distance is
    ``a[cosh m (cosh z - cosh t) + sinh m · t (φ(z) - φ(t))]``, φ(z) =
    sinh(z)/z - 1, largest where the slope equals the chord's.
    """
    xp = namespace(z, m)
    sm, cm = xp.sinh(m), xp.cosh(m)
    s = sm * (1.0 + phi)  # chord slope dh/span
    t = xp.arcsinh(sm * phi * (2.0 + phi) / ((1.0 + phi) * cm + xp.sqrt(1.0 + s * s)))
    return 2.0 * cm * (a * xp.sinh(0.5 * (z + t))) * xp.sinh(0.5 * (z - t)) + (a * sm * t) * (
        phi - sinhc_m1(t)
    )


def _unit(length, xp):
    """A power of two near ``length``: dividing lengths by it is exact and
    brings them to order one."""
    return xp.ldexp(0.5, xp.frexp(length)[1])


def _z_from_length(span, dh, length):
    xp = namespace(span, dh, length)
    legs = xp.abs(dh)
    unit = _unit(xp.maximum(span, legs), xp)
    span, dh, legs, length = span / unit, dh / unit, legs / unit, length / unit  # exact
    chord = xp.hypot(span, dh)
    require("length", length > chord, "must exceed the chord sqrt(span**2 + dh**2)", length * unit)
    # r - 1 with r = sqrt(S^2 - dh^2)/span, free of cancellation for taut
    # cables: S^2 - chord^2 = (S - M)(S + M) - m^2 with M the longer leg, so
    # that S - M is exact (Sterbenz) and level or vertical spans lose nothing;
    # divided by span first, so that nearly vertical chords do not underflow.
    # Slack cables (S > 2 chord) take sqrt((S-|dh|)/span)·sqrt((S+|dh|)/span) - 1.
    longer, shorter = xp.maximum(span, legs), xp.minimum(span, legs)

    def taut(length):
        excess_sq = (length - longer) * (length + longer) - shorter * shorter
        return excess_sq / span / (xp.sqrt((length - legs) * (length + legs)) + span)

    def slack(length):
        return xp.sqrt((length - legs) / span) * xp.sqrt((length + legs) / span) - 1.0

    if xp is np:
        with np.errstate(over="ignore", invalid="ignore"):
            rho = np.where(length < 2.0 * chord, taut(length), slack(length))
    else:
        rho = taut(length) if length < 2.0 * chord else slack(length)
    # sinh(z)/z = 1 + rho: z stays below _Z_LIMIT while rho stays below this
    require(
        "length",
        rho < math.sinh(_Z_LIMIT) / _Z_LIMIT,
        f"is so long relative to the span that span/(2a) exceeds {_Z_LIMIT:g} (cosh overflows a float)",
        length * unit,
    )
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
        step = _newton_step(z, target, xp)
        z = z - step
        change = largest_abs(step / z)
        history.append(change)
        if change < 1e-8:  # quadratic convergence: the error is now ~1e-16
            return z, history
    raise ConvergenceError("catenary(length=...): Newton did not converge", history)


def _newton_step(z, target, xp):
    """g/g' for g(z) = log(sinh z / z) - target, g' = coth z - 1/z; above z = 20
    in the form z - log(2z) + log1p(-e^{-2z}), which does not overflow."""

    def small(z):
        phi = sinhc_m1(z)
        return (xp.log1p(phi) - target) * (1.0 + phi) / dsinhc(z)

    def large(z):
        return (z - xp.log(2.0 * z) + xp.log1p(-xp.exp(-2.0 * z)) - target) / (1.0 / xp.tanh(z) - 1.0 / z)

    if xp is not np:
        return small(z) if z <= 20.0 else large(z)
    big = z > 20.0
    return np.where(big, large(np.where(big, z, 21.0)), small(np.where(big, 1.0, z)))


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
    require(
        "sag",
        f(hi, s, ratio) > 0,
        f"is too large: span/(2a) would exceed {_Z_MAX:g}, beyond the range this closed form evaluates",
        sag,
    )
    logz, history = find_root(f, lo, hi, (s, ratio), what="catenary(sag=...)", xtol=_LOG_XTOL)
    return np.exp(logz), history


#: Absolute tolerance of roots sought in log space: a relative one on the quantity.
_LOG_XTOL = 4.0 * np.finfo(float).eps


def _z_from_low(span, dh, low):
    depth_a, depth_b = -low, dh - low
    require(
        "low",
        (depth_a > 0) & (depth_b > 0),
        "must lie below both supports, low < min(0, dh); a cable whose lowest point "
        "is a support is not determined by it",
        low,
    )
    # with z = span/(2a), the two arcs from the vertex add up to the span:
    # [asinh(sqrt(z d_A/span)) + asinh(sqrt(z d_B/span))] / z = 1. The
    # parabola's z_p = (sqrt(d_A/span) + sqrt(d_B/span))^2 is an upper bound
    # (asinh x <= x); t = log(z/z_p) is near 0 for taut cables.
    xp = namespace(span, dh, low)
    root_a, root_b = xp.sqrt(depth_a / span), xp.sqrt(depth_b / span)
    z_p = (root_a + root_b) ** 2
    require("low", z_p > 2.0 * _Z_MIN, "is so close to the supports that span/(2a) underflows", low)
    coef_a, coef_b = root_a * (root_a + root_b), root_b * (root_a + root_b)  # coef_a + coef_b = z_p

    def f(t, coef_a, coef_b, log_zp):
        half = np.exp(0.5 * t)
        return np.log(np.arcsinh(coef_a * half) + np.arcsinh(coef_b * half)) - log_zp - t

    args = (coef_a, coef_b, xp.log(z_p))
    hi = xp.minimum(math.log(_Z_LIMIT) - xp.log(z_p), 1e-9)  # f(0) <= 0 but for rounding
    lo = math.log(_Z_MIN) - xp.log(z_p)
    require(
        "low",
        f(hi, *args) <= 0,
        f"is so deep below the supports that span/(2a) exceeds {_Z_LIMIT:g} (cosh overflows a float)",
        low,
    )
    t, history = find_root(f, lo, hi, args, what="catenary(low=...)", xtol=_LOG_XTOL)
    return z_p * xp.exp(t), history


def _log_tau(t, s):
    """log(T_max / (w·span)) as a function of t = ln(a/span), with s = dh/span.

    T_max/(w·span) = cosh(|m| + z) / (2z), z = e^{-t}/2, evaluated in logs so
    that no z overflows: sinh m = s·z/sinh z = s·2z e^{-z} / (1 - e^{-2z}).
    """
    z = 0.5 * np.exp(-t)
    sinh_m = s * 2.0 * z * np.exp(-z) / -np.expm1(-2.0 * z)
    return log_cosh(np.abs(np.arcsinh(sinh_m)) + z) - np.log(2.0 * z)


def _z_from_T_max(span, dh, w, T_max, branch):
    from scipy.optimize import elementwise  # imported here: `import skcable.cable` stays light

    if branch not in ("taut", "slack"):
        raise InputError("branch", f"must be 'taut' or 'slack', got {branch!r}")
    xp = namespace(span, dh, w, T_max)
    s = dh / span + 0.0 * T_max
    log_target = xp.log(T_max) - xp.log(w) - xp.log(span)  # T_max/(w·span) may overflow, its log not
    bracket = elementwise.bracket_minimum(_log_tau, np.full(np.shape(s), np.log(1 / 2.4)), args=(s,))
    best = elementwise.find_minimum(_log_tau, bracket.bracket, args=(s,))
    if not (np.all(bracket.success) and np.all(best.success)):
        raise ConvergenceError("catenary(T_max=...): least maximum tension not found")
    least = np.exp(best.f_x) * w * span
    require(
        "T_max",
        log_target >= best.f_x,
        f"is below the least maximum tension that spans this gap ({np.min(least):.6g})",
        T_max,
    )
    t_taut = np.log(0.5 / _Z_MIN)  # tau >= e^t: the taut root lies below log(target) + 1
    t_slack = np.log(0.5 / (2.0 * _Z_LIMIT))
    if branch == "taut":
        lo, hi = best.x, np.minimum(np.maximum(log_target + 1.0, best.x + 1.0), t_taut)
    else:
        lo, hi = t_slack, best.x
    edge = hi if branch == "taut" else lo
    require(
        "T_max",
        _log_tau(edge, s) >= log_target,
        f"is too large for the {branch} branch: span/(2a) would leave [{_Z_MIN:g}, {2 * _Z_LIMIT:g}]",
        T_max,
    )
    t, history = find_root(
        lambda t, s, target: _log_tau(t, s) - target,
        lo,
        hi,
        (s, log_target),
        what="catenary(T_max=...)",
        xtol=_LOG_XTOL,
    )
    return 0.5 * xp.exp(-t), history


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
        distance chord–cable; the horizontal tension; the y of the vertex
        relative to A, which must lie below both supports (``low < min(0,
        dh)``: the vertex is then inside the span and is the lowest point);
        or the tension at the higher support (a counterweight over a
        pulley, Goicolea (2012) §3.4.1).
    branch : {"taut", "slack"}
        With ``T_max`` two catenaries exist (Goicolea 2012, §3.4.1): the taut one
        (default) or the slack one.

    Returns
    -------
    Catenary
        ``H, V_A, V_B, T_A, T_B, length, sag``, the lowest point of the cable
        ``x_low, y_low`` (a support when the vertex lies outside the span),
        the vertex ``x_vertex, y_vertex``, and ``y(x)``, ``T(x)``,
        ``slope(x)``, ``residual()``; arrays when inputs are.

    Raises
    ------
    InputError
        A non-physical argument (named), not exactly one constraint, arrays
        that do not broadcast, or data so extreme that a result would leave
        the range of a float.
    ConvergenceError
        The solver stopped, or the residual of the solution exceeds 1e-9.

    Examples
    --------
    The lecture notes "Cables", example 4 (kN, m): lowest point 30 m below A.

    >>> c = catenary(800.0, -20.0, 20.0, low=-30.0)
    >>> round(float(c.H), 1), round(float(c.x_low), 2)
    (85819.2, 507.11)
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
        if name == "length":
            z, history = _z_from_length(span, dh, value)
        elif name == "H":
            a = value / w
            require("H", a > 0, "is so small relative to w that H/w underflows", value)
            z = 0.5 * span / a
        elif name == "sag":
            z, history = _z_from_sag(span, dh, value)
        elif name == "low":
            z, history = _z_from_low(span, dh, value)
        else:
            z, history = _z_from_T_max(span, dh, w, value, branch)
    require(name, z >= _Z_MIN, "makes the cable so taut that span·w/(2H) underflows (below 1e-300)", value)
    require(
        name,
        z <= _Z_LIMIT,
        f"makes the cable so slack that span·w/(2H) exceeds {_Z_LIMIT:g} (cosh overflows a float)",
        value,
    )
    if name != "H":
        a = span / (2.0 * z)
    require(name, a < math.inf, "makes H/w overflow a float", value)
    value = np.asarray(value, dtype=float)[()]
    with float_range(name, "a result"):
        return checked_closed_form(Catenary(span, dh, w, a, z, (name, value)), name, history)
