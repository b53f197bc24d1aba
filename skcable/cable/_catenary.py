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

The "fourth equation" (the lecture notes "Cables") is one of the constraints of `catenary`.
Given the length, ``sinh(z)/z = sqrt(S² − dh²)/span`` is solved as `skcable.cable._hanging`
says (Halley's method on ``log(sinh z / z)``, increasing and convex in z).
"""

from __future__ import annotations

import math
from functools import cached_property
from math import asinh, cosh, sinh
from typing import Any

import numpy as np

from skcable._checks import broadcast, exactly_one, float_range, positive, real, require, within
from skcable._xp import namespace, power_of_two_near, scalar_math
from skcable.cable import _catenary_batch as _batch
from skcable.cable._hanging import RHO_LIMIT as _RHO_LIMIT
from skcable.cable._hanging import Z_LIMIT, Z_MIN, excess, z_of_excess
from skcable.cable._roots import LOG_XTOL, find_root
from skcable.cable._special import (
    ldexp_sum,
    log_cosh,
    power_product,
    sinhc_m1,
    z_minus_tanh_over_cube,
)
from skcable.cable.closure import positions
from skcable.cable.solution import ACCEPT, ATTRIBUTE_OF, CableSolution, checked_closed_form, matrix_2x2
from skcable.errors import ConvergenceError, InputError

__all__ = ["Catenary", "catenary"]

_Z_MAX = 350.0  # the sag search: phi(z)**2 overflows near z = 355
#: Range of z = span/(2a) the closed form evaluates: below _Z_MIN the abscissae
#: x/(2a) turn subnormal (no relative precision), above _Z_LIMIT sinh(z) overflows.
_Z_MIN, _Z_LIMIT = Z_MIN, Z_LIMIT
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
        Horizontal tension (the same all along: ``H = H_A = H_B``), upward reactions and
        end tensions (N).
    length, sag : float or ndarray
        Cable length and largest vertical chord-to-cable distance (m).
    x_low, y_low : float or ndarray
        Lowest point of the cable (m), in [0, span]: the vertex when it lies
        between the supports, else the lower support.
    x_vertex, y_vertex : float or ndarray
        Vertex of the catenary (horizontal tangent, m); it may lie outside
        the span, where it is not a point of the cable.
    """

    _xp: Any = scalar_math  # the float path's back end; ``__init__`` sets the instance's own

    def __init__(self, span, dh, w, a, z, constraint: tuple[str, object]):
        self.span, self.dh, self.w, self.a, self.z = span, dh, w, a, z
        self._xp = xp = namespace(span, dh, w, a, z)
        self._sinh_z = xp.sinh(z)
        # sinh(z)/z needs no series: it is 1 + phi, free of cancellation (phi is, below)
        if (
            xp is np
            and np.ndim(z)
            and np.shape(z) == np.broadcast_shapes(np.shape(dh), np.shape(span), np.shape(z))
        ):
            self.m = _m_in_place(span, dh, z, self._sinh_z)
        else:
            self.m = xp.arcsinh(dh / span / (self._sinh_z / z))
        self.constraint = constraint

    @classmethod
    def _of_batch(cls, span, dh, w, constraint: tuple[str, object], results, shape) -> Catenary:
        """`Catenary` of the rows ``results`` of `skcable.cable._catenary_batch` (flat, brought
        to ``shape``; ``a`` and ``z`` there, or given in ``results`` already shaped):
        ``__init__`` and `_arrays` done pass by pass."""
        solution = _new(cls)
        if len(shape) == 1:  # the rows themselves
            V, T, rows = results["V"], results["T"], results
        else:
            V, T = (results[k].reshape(2, *shape) for k in ("V", "T"))
            rows = {k: results[k].reshape(shape) for k in ("a", "z", "sinh_z", "m", "H", "length")}
        solution.__dict__.update(
            span=span, dh=dh, w=w, a=rows["a"], z=rows["z"], _xp=np, _sinh_z=rows["sinh_z"],
            m=rows["m"], constraint=constraint, H=rows["H"], V_A=V[0], V_B=V[1], T_A=T[0],
            T_B=T[1], length=rows["length"], _ends=(V, T),
        )  # fmt: skip
        return solution

    def _arrays(self):
        """Fill the forces and the length of an array of scenes at once: the formulas of the
        properties below, evaluated in place (`skcable.cable._catenary_batch.forces_into`: the
        same bits, fewer temporaries). The ends' forces are the rows of two blocks, ``(V_A,
        V_B)`` and ``(T_A, T_B)``: each function is called once for both ends (and so is each
        term of `residual`)."""
        shape = self.m.shape
        block = np.empty((8, *shape))
        out = dict(sinh_z=self._sinh_z, m=self.m, H=block[0], length=block[1], V=block[2:4], T=block[4:6])
        _batch.forces_into(self.span, self.dh, self.w, self.a, self.z, out, block[6:])
        V, T = out["V"], out["T"]
        self.__dict__.update(
            H=out["H"], V_A=V[0], V_B=V[1], T_A=T[0], T_B=T[1], length=out["length"], _ends=(V, T)
        )
        return self

    def _end_blocks(self, shape):
        """``(V, T)``: the blocks of shape ``(2, *shape)`` of the ends' forces (`_arrays`'), or
        new ones filled from the attributes."""
        ends = self.__dict__.get("_ends")
        if ends is not None and ends[0].shape[1:] == shape:
            return ends
        V, T = np.empty((2, *shape)), np.empty((2, *shape))
        V[0], V[1], T[0], T[1] = self.V_A, self.V_B, self.T_A, self.T_B
        return V, T

    def finite_beyond_residual(self) -> bool:
        """The length and the vertex are finite. The vertex need not be evaluated: ``|x_vertex|``
        and ``|y_vertex|`` are below ``a cosh(u_A) = T_A/w`` (as ``|u| < cosh u`` and
        ``2 sinh²(u/2) < cosh u``), finite when ``max T_A / min w`` is."""
        if self._xp is not np:
            return super().finite_beyond_residual()
        w = self.w
        bound = float(_MAX(self.T_A, axis=None)) / (w if isinstance(w, float) else float(np.min(w)))
        # the length is positive: finite where its largest is (a NaN makes that NaN)
        return float(_MAX(self.length, axis=None)) < math.inf and (
            bound < math.inf or super().finite_beyond_residual()
        )

    def residual(self) -> float:
        """`CableSolution.residual`; on arrays the same terms, written in place into the rows
        of one block (then one reduction)."""
        if self._xp is not np or np.ndim(self.T_A) == 0:
            return super().residual()
        T_A, w = self.T_A, self.w
        dh = self.dh
        if isinstance(w, float) and isinstance(dh, float):
            shape = T_A.shape
        else:
            shape = np.broadcast_shapes(T_A.shape, np.shape(w), np.shape(dh))
        V, T = self._end_blocks(shape)
        return self._residual_rows(np.empty((7, *shape)), V, T)

    def _residual_rows(self, block, V, T):
        """`residual` written into the first five rows of ``block`` (the last two are scratch),
        with the ends' forces in the blocks ``V`` and ``T``
        (`skcable.cable._catenary_batch.residual_rows`)."""
        name, value = self.constraint

        def met(row):  # the constraint met, as in `_common_residuals`
            if name == "low":
                row[...] = self._common_residuals(np)[2]
            else:
                np.subtract(getattr(self, ATTRIBUTE_OF[name]), value, out=row)
                row /= value

        return _batch.residual_rows(block, V, T, self.H, self.w, self.dh, self.length, met)

    @cached_property
    def _phi(self):
        return sinhc_m1(self.z)  # sinh(z)/z - 1 by its series where that cancels

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
        return 2.0 * (self.a * self._sinh_z) * self._xp.cosh(self.m)

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
        return lowest_point_y(self.m - self.z, self.m + self.z, self.y_vertex, self.dh)

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
            return finite_at("x", 2.0 * xp.sinh(self.m - self.z + half) * (self.a * xp.sinh(half)), "y(x)")

    def slope(self, x):
        """dy/dx at ``x``."""
        u, xp = self._u(x)
        with float_range("x", "slope(x)"):
            return finite_at("x", xp.sinh(u), "slope(x)")

    def T(self, x):
        """Tension at ``x`` (N)."""
        u, xp = self._u(x)
        with float_range("x", "T(x)"):
            return finite_at("x", self.H * xp.cosh(u), "T(x)")

    def xy(self, s):
        r"""Positions ``(..., 2)`` (m) at unstretched arc length ``s`` (m) from A, in [0, length].

        With :math:`q = \sinh u_A`, the arc from A to :math:`u` is :math:`a(\sinh u - q)`, so
        :math:`\sinh u = q + s/a` and :math:`x = a(u - u_A)`, :math:`y = a(\cosh u - \cosh u_A)`:
        the hanging piece of the one closure with EA infinite (`skcable.cable.closure.positions`;
        Irvine, *Cable Structures*, 1981, §2.2), free of cancellation for taut cables.
        """
        s = self._arc(s)
        with float_range("s", "xy(s)"):
            x, y = positions(self.H, -self.V_A, self.w, math.inf, s, namespace(s, self.a))
            return np.stack(np.broadcast_arrays(x, y), axis=-1)

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` (m) from A: ``sqrt(H² + (w s - V_A)²)``."""
        s = self._arc(s)
        return namespace(s, self.a).hypot(self.H, self.w * s - self.V_A)

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
        """Closure at B through the tensions (a catenary's ``T_B - T_A = w dh``, evaluated
        from the cosh of the end angles, not from the sinh that placed B), vertical balance,
        end tensions along their components, the constraint: each over what it sums."""
        xp, T_A, T_B, V_A, V_B = self._xp, self.T_A, self.T_B, self.V_A, self.V_B
        weight = self.w * self.length
        yield (T_B - T_A - self.w * self.dh) / (T_A + T_B)
        # V_A and V_B cancel for taut inclined cables (|V| ~ H·|dh|/span >> weight)
        yield (V_A + V_B - weight) / (xp.abs(V_A) + xp.abs(V_B) + weight)
        yield from self._common_residuals(xp)


def _m_in_place(span, dh, z, sinh_z):
    """The angle at mid-span, ``asinh(dh / span / (sinh z / z))``, for an array ``z`` of the
    shape the data broadcast to: each step in place in the array of ``sinh z / z``."""
    m = sinh_z / z
    np.arcsinh(np.divide(dh / span, m, out=m), out=m)
    return m


def lowest_point_y(u_a, u_b, y_vertex, dh):
    """y of the cable's lowest point: A (0) when it rises from A (u_A >= 0), B
    (dh) when it falls to B (u_B <= 0), else the vertex. Shared with the parabola."""
    if not isinstance(y_vertex, np.ndarray) and not isinstance(dh, np.ndarray):
        return 0.0 if u_a >= 0 else dh if u_b <= 0 else y_vertex
    return np.where(u_a >= 0, 0.0, np.where(u_b <= 0, dh, y_vertex))


def finite_at(name, value, what):
    """``value``, refused naming ``name`` unless finite (``what`` overflows)."""
    if not (np.isfinite(value).all() if isinstance(value, np.ndarray) else math.isfinite(value)):
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


def _z_from_length(span, dh, length):
    xp = namespace(span, dh, length)
    legs = xp.abs(dh)
    unit = power_of_two_near(xp.maximum(span, legs), xp)
    span, dh, legs, length = span / unit, dh / unit, legs / unit, length / unit  # exact
    chord = xp.sqrt(span * span + dh * dh)  # both below 1 now: no overflow (and no hypot's cost)
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
        short = length < 2.0 * chord
        with np.errstate(over="ignore", invalid="ignore"):
            rho = taut(length) if short.all() else np.where(short, taut(length), slack(length))
    else:
        rho = taut(length) if length < 2.0 * chord else slack(length)
    # sinh(z)/z = 1 + rho: z stays below _Z_LIMIT while rho stays below this
    require(
        "length",
        rho < math.sinh(_Z_LIMIT) / _Z_LIMIT,
        f"is so long relative to the span that span/(2a) exceeds {_Z_LIMIT:g} (cosh overflows a float)",
        length * unit,
    )
    if xp is not np:
        z, history = z_of_excess(rho)
        if z is None:
            raise ConvergenceError("catenary(length=...): Halley's method did not converge", history)
        return z, history
    # g(z) = log(sinh z / z) - target is convex and increasing: Halley's method (Newton's far
    # from the root) from the start of `skcable.cable._hanging.start`, elementwise
    z = _batch.start(rho)
    return z, _batch.iterate(z, rho)


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
    logz, history = find_root(f, lo, hi, (s, ratio), what="catenary(sag=...)", xtol=LOG_XTOL)
    return np.exp(logz), history


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
    t, history = find_root(f, lo, hi, args, what="catenary(low=...)", xtol=LOG_XTOL)
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
        xtol=LOG_XTOL,
    )
    return 0.5 * xp.exp(-t), history


_INF = math.inf
_MAX_FLOAT = float(np.finfo(float).max)
#: The least positive float (a subnormal): H/w above it has not underflowed to zero.
TINY_POSITIVE = 5e-324
_new = object.__new__
_MIN, _MAX = np.minimum.reduce, np.maximum.reduce


def _length_on_floats(span, dh, w, length):
    """`catenary` with ``length=`` on Python numbers: the same formulas and checks as the
    general path (`skcable.cable._hanging`, `Catenary._residuals` written out on floats), or
    None wherever the general path must decide (it then raises the right error)."""
    if not (type(span) is float and type(dh) is float and type(w) is float and type(length) is float):
        if not all(type(v) in (float, int) for v in (span, dh, w, length)):
            return None
        try:
            span, dh, w, length = float(span), float(dh), float(w), float(length)
        except OverflowError:  # an integer beyond the float range: the general path names it
            return None
    if not (0.0 < span < _INF and -_INF < dh < _INF and 0.0 < w < _INF and 0.0 < length < _INF):
        return None
    if not abs(dh) <= _STEEPEST * span:
        return None
    rho = excess(span, dh, length)  # `z_of_length`, inlined
    if rho is None or not rho < _RHO_LIMIT:
        return None
    z = z_of_excess(rho)[0]
    if z is None or not _Z_MIN <= z <= _Z_LIMIT:
        return None
    try:
        a = span / (2.0 * z)
        sinh_z = sinh(z)
        m = asinh(dh / span / (sinh_z / z))
        H = w * a
        V_A, V_B = H * sinh(z - m), H * sinh(z + m)
        T_A, T_B = H * cosh(m - z), H * cosh(m + z)
        achieved = 2.0 * (a * sinh_z) * cosh(m)
        weight = w * achieved
        t_a, v_a, t_b, v_b = H / T_A, V_A / T_A, H / T_B, V_B / T_B
        # `Catenary._residuals`, each within ACCEPT (a NaN fails every comparison)
        closure = (T_B - T_A - w * dh) / (T_A + T_B)
        balance = (V_A + V_B - weight) / (abs(V_A) + abs(V_B) + weight)
        end_a = 0.5 * ((1.0 - t_a) * (1.0 + t_a) - v_a * v_a)
        end_b = 0.5 * ((1.0 - t_b) * (1.0 + t_b) - v_b * v_b)
        met = (achieved - length) / length
    except (OverflowError, ZeroDivisionError):
        return None
    ok = -ACCEPT <= closure <= ACCEPT and -ACCEPT <= balance <= ACCEPT and -ACCEPT <= met <= ACCEPT
    # the vertex is below a cosh(u_A) = T_A/w (`Catenary.finite_beyond_residual`)
    if not (ok and -ACCEPT <= end_a <= ACCEPT and -ACCEPT <= end_b <= ACCEPT and a < _INF and T_A / w < _INF):
        return None
    solution = _new(Catenary)  # `_xp` is the class's: `scalar_math`
    solution.__dict__ = {
        "span": span, "dh": dh, "w": w, "a": a, "z": z, "_sinh_z": sinh_z, "m": m,
        "constraint": ("length", length), "H": H, "V_A": V_A, "V_B": V_B, "T_A": T_A, "T_B": T_B,
        "length": achieved,
    }  # fmt: skip
    return solution


def _range(value):
    """``(min, max)`` of a Python float or a float64 array: two reductions on an array (a NaN
    makes them NaN, which fails every bound)."""
    if isinstance(value, float):
        return value, value
    return _MIN(value, axis=None), _MAX(value, axis=None)  # the ufuncs' reductions, unwrapped


def _array_ranges(span, dh, w, value):
    """``(min, max)`` of ``span``, ``value``, ``w`` and ``dh`` when ``span`` and ``value`` are
    float64 arrays of one shape and ``dh``, ``w`` Python floats or float64 arrays of that shape
    (the vectorised paths' data), else None."""
    shape = span.shape
    if not (span.dtype == value.dtype == np.float64 and span.size):
        return None
    for v in (value, dh, w):
        if not (
            isinstance(v, float) or (type(v) is np.ndarray and v.dtype == np.float64 and v.shape == shape)
        ):
            return None
    return tuple(map(_range, (span, value, w, dh)))


def _batch_solution(span, dh, w, constraint, done, extra=None):
    """The `Catenary` of the vectorised pass ``done`` (`skcable.cable._catenary_batch`), or None
    where its residual or a result the residual does not evaluate fails (the general path then
    names the argument)."""
    if done is None or not done[0] <= ACCEPT:
        return None
    results = done[1] if extra is None else {**done[1], **extra}
    solution = Catenary._of_batch(span, dh, w, constraint, results, span.shape)
    return solution if solution.finite_beyond_residual() else None


def _H_on_arrays(span, dh, w, H):
    """`catenary(span, dh, w, H=H)` for float64 arrays ``span`` and ``H`` of one shape (``dh``
    and ``w`` Python floats or float64 arrays of that shape), or None where any check of the
    general path would fail or the data are of another kind: the general path then gives the
    same solution, or raises naming the argument.

    The same checks, fused: two reductions an argument, none on ``H/w`` when ``w`` is a float
    and none on ``z``. Correctly rounded division and halving are monotone, so that
    ``fl(H_min/w)`` and ``fl(H_max/w)`` are the extremes of ``a = H/w``, and
    ``z = fl(fl(span/a)/2)`` lies between ``fl(fl(span_min/a_max)/2)`` and
    ``fl(fl(span_max/a_min)/2)``: the bounds of ``z`` are tested on these (where they are too
    wide, the general path tests every element)."""
    ranges = _array_ranges(span, dh, w, H)
    if ranges is None:
        return None
    (span_lo, span_hi), (H_lo, H_hi), (w_lo, w_hi), (dh_lo, dh_hi) = ranges
    if not (0.0 < span_lo and span_hi < _INF and 0.0 < H_lo and H_hi < _INF and 0.0 < w_lo and w_hi < _INF):
        return None
    if not -_INF < dh_lo <= dh_hi < _INF:
        return None
    if isinstance(dh, float):
        if not abs(dh) / _STEEPEST <= span_lo:  # `catenary`'s test, for the shortest span
            return None
    elif not (np.abs(dh) <= _STEEPEST * span).all():
        return None
    with np.errstate(over="ignore"):  # an overflow of H/w is refused just below, by the general path
        a = H / w
        a_lo, a_hi = (H_lo / w, H_hi / w) if isinstance(w, float) else _range(a)
    if not (TINY_POSITIVE <= a_lo and a_hi <= _MAX_FLOAT):
        return None
    if not (_Z_MIN <= span_lo / a_hi * 0.5 and span_hi / a_lo * 0.5 <= _Z_LIMIT):
        return None
    z = span / a
    z *= 0.5  # = 0.5 * span / a: halving is exact
    flat = [v if isinstance(v, float) else v.reshape(-1) for v in (span, dh, w, a, z, H)]
    with np.errstate(all="ignore"):  # a NaN or inf fails the residual: the general path then names it
        return _batch_solution(span, dh, w, ("H", H[()]), _batch.of_H(*flat), {"a": a, "z": z})


#: Bounds of the data the vectorised ``length=`` path takes: within them every square and
#: product of the excess is a normal float, so that the general path's scaling by a power of
#: two (`skcable._xp.power_of_two_near`) changes no bit, and is left out.
_NORMAL_RANGE = (1e-100, 1e100)


def _length_on_arrays(span, dh, w, length):
    """`catenary(span, dh, w, length=length)` for float64 arrays ``span`` and ``length`` of one
    shape (``dh`` and ``w`` Python floats or float64 arrays of that shape), solved and checked
    pass by pass (`skcable.cable._catenary_batch.of_length`), or None where any check of the
    general path would fail or the data are of another kind: the general path then gives the
    same solution, or raises naming the argument.

    The argument checks fused into two reductions an argument; the data held within
    `_NORMAL_RANGE` (else the general path)."""
    ranges = _array_ranges(span, dh, w, length)
    if ranges is None:
        return None
    (span_lo, span_hi), (L_lo, L_hi), (w_lo, w_hi), (dh_lo, dh_hi) = ranges
    tiny, huge = _NORMAL_RANGE
    if not (tiny < span_lo and span_hi < huge and tiny < L_lo and L_hi < huge and 0.0 < w_lo and w_hi < _INF):
        return None
    if not (-huge < dh_lo <= dh_hi < huge and max(-dh_lo, dh_hi) / _STEEPEST <= span_lo):
        return None  # ... and |dh| <= _STEEPEST·span (`catenary`'s test, for the shortest span)
    s, d, wf, L = (v if isinstance(v, float) else v.reshape(-1) for v in (span, dh, w, length))
    with np.errstate(all="ignore"):  # a NaN or inf fails the residual: the general path then names it
        done = _batch.of_length(s, d, wf, L, (span_lo, span_hi))
        return _batch_solution(span, dh, w, ("length", length[()]), done)


def hanging(span, dh, w, length) -> Catenary:
    """The catenary of ``length`` (float or array, > chord), unchecked: a start for the elastic
    forms, which check what they return. Data out of the closed form's range raise as in
    `catenary`."""
    with float_range("length", "an intermediate value"):
        z, _ = _z_from_length(span, dh, length)
        return Catenary(span, dh, w, span / (2.0 * z), z, ("length", length))


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
        Its attributes (arrays when inputs are) and ``y(x)``, ``T(x)``, ``slope(x)``,
        ``residual()``.

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
    if length is not None and sag is H is low is T_max is None:  # the length alone
        solution = _length_on_floats(span, dh, w, length)  # one scene of Python numbers
        if solution is None and type(span) is type(length) is np.ndarray:
            solution = _length_on_arrays(span, dh, w, length)  # arrays of one shape
        if solution is not None:
            return solution
    elif H is not None and length is sag is low is T_max is None and type(span) is type(H) is np.ndarray:
        solution = _H_on_arrays(span, dh, w, H)  # arrays of one shape
        if solution is not None:
            return solution
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    value = real(name, value) if name == "low" else positive(name, value)
    broadcast(span=span, dh=dh, w=w, **{name: value})
    xp = namespace(span, dh, w, value)
    steep = (
        xp.abs(dh) / _STEEPEST <= span if not isinstance(dh, np.ndarray) else xp.abs(dh) <= _STEEPEST * span
    )
    require("dh", steep, f"must satisfy |dh| <= {_STEEPEST:g}·span", dh)
    history = []
    with float_range(name, "an intermediate value"):
        if name == "length":
            z, history = _z_from_length(span, dh, value)
        elif name == "H":
            with np.errstate(over="ignore"):  # H/w beyond the float range: refused by the z checks
                a = value / w
            within("H", a, TINY_POSITIVE, math.inf, "is so small relative to w that H/w underflows", value)
            z = span / a
            z *= 0.5  # = 0.5 * span / a: halving is exact
        elif name == "sag":
            z, history = _z_from_sag(span, dh, value)
        elif name == "low":
            z, history = _z_from_low(span, dh, value)
        else:
            z, history = _z_from_T_max(span, dh, w, value, branch)
    if not (isinstance(z, np.ndarray) and z.size and _Z_MIN <= z.min() and z.max() <= _Z_LIMIT):
        require(
            name, z >= _Z_MIN, "makes the cable so taut that span·w/(2H) underflows (below 1e-300)", value
        )
        require(
            name,
            z <= _Z_LIMIT,
            f"makes the cable so slack that span·w/(2H) exceeds {_Z_LIMIT:g} (cosh overflows a float)",
            value,
        )
    if name != "H":
        a = span / z
        a *= 0.5  # = span / (2 z): halving is exact
    within(name, a, -math.inf, _MAX_FLOAT, "makes H/w overflow a float", value)
    value = np.asarray(value, dtype=float)[()]
    with float_range(name, "a result"):
        solution = Catenary(span, dh, w, a, z, (name, value))
        if solution._xp is np and np.ndim(z) and np.shape(z) == np.shape(solution.m):
            solution._arrays()
        return checked_closed_form(solution, name, history)
