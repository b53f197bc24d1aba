r"""Irvine's elastic catenary: an extensible cable under its own weight.

Lagrangian coordinate ``s`` along the *unstretched* cable, ``s = 0`` at A,
``s = L0`` at B; weight ``w`` per unstretched length, axial stiffness
``EA``. With the vertical tension component :math:`T_v(s) = w s - V_A` and
:math:`T = \sqrt{H^2 + T_v^2}` (Irvine, *Cable Structures*, 1981, §2.2):

.. math::
    x(s) = \frac{H s}{EA} + \frac{H}{w}\left[\operatorname{asinh}\frac{T_v(s)}{H}
           - \operatorname{asinh}\frac{T_v(0)}{H}\right], \qquad
    y(s) = \frac{w s^2/2 - V_A s}{EA} + \frac{T(s) - T(0)}{w}.

The two closure conditions ``x(L0) = span`` and ``y(L0) = dh`` are solved
for ``(H, V_A)`` by Newton's method with the analytic Jacobian and
backtracking, started from the inextensible catenary of a length corrected
for the mean stretch.
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, float_range, positive, real, require
from skcable._newton2 import solve2
from skcable._xp import namespace
from skcable.cable._answers import check_catenary
from skcable.cable._catenary import finite_at, hanging
from skcable.cable._extreme import outsized
from skcable.cable._hanging import hanging_forces
from skcable.cable._roots import find_root
from skcable.cable._special import asinh_step, asinh_step_log, asinh_step_parts, sinhc_m1, sinhc_pair
from skcable.cable.solution import ACCEPT, CableSolution, checked_closed_form
from skcable.errors import InputError

__all__ = ["ElasticCatenary", "elastic_catenary"]

_NAN8 = (math.nan,) * 8


def ratios(H, V_A, w, L):
    r"""``(q, d, p, r_q, r_p)``: the vertical tension components at A and B over ``H``,
    :math:`q = -V_A/H`, :math:`p = q + d`, their step :math:`d = wL/H` formed directly (never
    as :math:`p - q`), and :math:`r = \sqrt{1 + (\cdot)^2}` (``T_A/H``, ``T_B/H``)."""
    xp = namespace(H, V_A, w, L)
    q, d = -V_A / H, w * L / H
    p = q + d
    return q, d, p, xp.hypot(1.0, q), xp.hypot(1.0, p)


def _x_h_core(S, A, p, q, rr):
    r""":math:`A - \sinh A/(r_p r_q)`, the geometric part of :math:`w\,\partial X/\partial H`, without
    cancellation: below ``A = 2`` as :math:`S(p^2 + q^2 + p^2q^2)/((r_pr_q + 1)r_pr_q) - (\sinh A - A)`
    (:math:`r_pr_q - 1` rationalised), above it directly (the loss is at most 4 ulps at ``A = 2``)."""

    def small(S, A, p, q, rr):
        p2, q2 = p * p, q * q
        return S * (p2 + q2 + p2 * q2) / ((rr + 1.0) * rr) - A * sinhc_m1(A)

    def large(S, A, p, q, rr):
        return A - S / rr

    if not isinstance(A, np.ndarray):
        return small(S, A, p, q, rr) if A < 2.0 else large(S, A, p, q, rr)
    out = np.empty(np.shape(A))
    below = A < 2.0
    out[below] = small(S[below], A[below], p[below], q[below], rr[below])
    out[~below] = large(S[~below], A[~below], p[~below], q[~below], rr[~below])
    return out


def _closure_floats(span, dh, w, EA, L, H, V_A):
    """`closure` on Python floats: the same formulas, written out."""
    if not H > 0:
        return _NAN8
    q, d = -V_A / H, w * L / H
    p = q + d
    rq, rp = math.hypot(1.0, q), math.hypot(1.0, p)
    S = d * (p + q) / (p * rq + q * rp) if p * q > 0 else p * rq - q * rp
    A = math.asinh(S)
    stretch, x_geo, compliance = H * L / EA, H / w * A, L / EA
    rsum, rr = rp + rq, rp * rq
    if A < 2.0:
        p2, q2 = p * p, q * q
        core = S * (p2 + q2 + p2 * q2) / ((rr + 1.0) * rr) - A * sinhc_pair(A)[0]
    else:
        core = A - S / rr
    j_xv = d * (p + q) / (rsum * rr * w)
    terms_y = L * (0.5 * w * L + abs(V_A)) / EA + L * (abs(p) + abs(q)) / rsum + abs(dh)
    return (
        stretch + x_geo - span,
        L * (0.5 * w * L - V_A) / EA + L * (p + q) / rsum - dh,
        compliance + core / w,
        j_xv,
        -j_xv,
        -compliance - S / (rr * w),
        stretch + x_geo + span,
        terms_y,
    )


def closure(span, dh, w, EA, L, H, V_A):
    r"""Irvine's closure :math:`X(H, V_A) - \mathrm{span}`, :math:`Y(H, V_A) - dh` (m), its Jacobian
    in ``(H, V_A)`` (m/N) and the sizes of the two residuals' terms (m), whose few ulps are their
    round-off.

    In the ratios of `ratios`, with :math:`A = \operatorname{asinh} p - \operatorname{asinh} q`
    from `asinh_step_parts` (d formed directly, so that taut steep lines keep their digits) and
    :math:`S = \sinh A`:

    .. math::
        X = \frac{HL}{EA} + \frac{H}{w} A, \qquad
        Y = \frac{L (wL/2 - V_A)}{EA} + L\,\frac{p + q}{r_p + r_q},

    (:math:`(T_B - T_A)/w` rationalised), and
    :math:`\partial X/\partial H = L/EA + (A - S/(r_pr_q))/w`,
    :math:`\partial X/\partial V_A = -\partial Y/\partial H = d\,(p + q)/((r_p + r_q) r_p r_q w)`,
    :math:`\partial Y/\partial V_A = -L/EA - S/(r_p r_q w)`. ``H <= 0`` gives NaN.
    """
    xp = namespace(span, dh, w, EA, L, H, V_A)
    if xp is np:
        H = np.where(H > 0, H, np.nan)
    elif not H > 0:
        return _NAN8
    q, d, p, rq, rp = ratios(H, V_A, w, L)
    S, A = asinh_step_parts(q, d, p, rq, rp)
    stretch, x_geo, compliance = H * L / EA, H / w * A, L / EA
    s_y = L * (0.5 * w * L - V_A) / EA
    rsum, rr = rp + rq, rp * rq
    rise = L * (p + q) / rsum  # (T_B - T_A)/w
    j_xv = d * (p + q) / (rsum * rr * w)
    j_xh = compliance + _x_h_core(S, A, p, q, rr) / w
    j_yv = -compliance - S / (rr * w)
    # the terms summed, and the operands of the differences w L/2 - V_A and p + q
    terms_x = stretch + x_geo + span
    terms_y = L * (0.5 * w * L + xp.abs(V_A)) / EA + L * (xp.abs(p) + xp.abs(q)) / rsum + xp.abs(dh)
    return stretch + x_geo - span, s_y + rise - dh, j_xh, j_xv, -j_xv, j_yv, terms_x, terms_y


def _closure_of(H, V_A, span, dh, w, EA, L):
    """`closure` in the argument order of `solve2`."""
    if type(H) is float and type(V_A) is float:
        return _closure_floats(span, dh, w, EA, L, H, V_A)
    return closure(span, dh, w, EA, L, H, V_A)


def _inextensible(span, dh, w, length):
    """``(H, V_A, T_A, T_B)`` of the inextensible catenary of ``length``, unchecked (a start:
    the elastic solution is checked); Python floats where the data are, else arrays."""
    if namespace(span, dh, w, length) is not np:
        forces = hanging_forces(span, dh, w, length)
        if forces is not None:
            return forces
    c = hanging(span, dh, w, length)  # arrays, or data the float path leaves to the checked one
    return c.H, c.V_A, c.T_A, c.T_B


def _initial_guess(span, dh, w, EA, L0):
    xp = namespace(span, dh, w, EA, L0)
    chord = xp.hypot(span, dh)
    # inextensible catenary of a length at least 1e-6 above the chord,
    # lengthened once by the mean strain it predicts
    _, _, T_A, T_B = _inextensible(span, dh, w, xp.maximum(L0, chord * (1 + 1e-6)))
    strain = 0.5 * (T_A + T_B) / EA
    H_c, V_c, _, _ = _inextensible(span, dh, w, xp.maximum(L0 * (1.0 + strain), chord * (1 + 1e-6)))
    # a cable shorter than its chord is a stretched bar: H ≈ EA·(chord/L0 - 1)·span/chord
    bar = EA * (chord / L0 - 1.0) * span / chord
    H = xp.maximum(H_c, bar)
    return H, V_c * H / H_c


def _solve(span, dh, w, EA, L0):
    H, V_A = _initial_guess(span, dh, w, EA, L0)
    result = solve2(_closure_of, H, V_A, (span, dh, w, EA, L0), what="elastic_catenary")
    return result.x, result.y, result.history


def inverse_2x2(j11, j12, j21, j22):
    """Inverse of ``[[j11, j12], [j21, j22]]`` elementwise, shape ``(*shape, 2, 2)``."""
    det = np.asarray(j11 * j22 - j12 * j21)[..., None, None]
    return np.stack([np.stack([j22, -j12], -1), np.stack([-j21, j11], -1)], -2) / det


def elastic_stiffness(s):
    """``∂(H, V_B)/∂(span, dh)`` of a free `ElasticCatenary`: the closure's Jacobian
    in ``(H, V_A)`` inverted (implicit function theorem), ``V_B = wL - V_A``."""
    _, _, j_xh, j_xv, j_yh, j_yv, _, _ = closure(s.span, s.dh, s.w, s.EA, s.length, s.H, s.V_A)
    return inverse_2x2(j_xh, j_xv, j_yh, j_yv) * np.array([[1.0], [-1.0]])


def _x_of_s_minus(s, x, H, V_A, w, EA):
    return H * s / EA + H / w * asinh_step(-V_A / H, w * s / H) - x


class ElasticCatenary(CableSolution):
    """Solution of `elastic_catenary`.

    Attributes are those of `Catenary` (``H = H_A = H_B``, the horizontal tension being the
    same all along), with
    ``length`` the unstretched length, plus ``EA``, ``stretched_length`` and
    the Lagrangian maps ``x_of_s(s)``, ``y_of_s(s)``, ``s_of_x(x)``. The
    lowest point ``x_low, y_low`` is that of the cable (a support when the
    material point of zero slope, ``s = V_A/w``, lies outside ``[0, length]``);
    ``x_vertex, y_vertex`` is that point of the elastic catenary continued
    beyond the supports.
    """

    def __init__(self, span, dh, w, EA, length, H, V_A, constraint):
        self.span, self.dh, self.w, self.EA, self.length = span, dh, w, EA, length
        self.H, self.V_A = H, V_A
        self.constraint = constraint
        self._xp = namespace(span, dh, w, EA, length, H, V_A)

    @cached_property
    def V_B(self):
        return self.w * self.length - self.V_A

    @cached_property
    def _ratios(self):
        return ratios(self.H, self.V_A, self.w, self.length)

    @cached_property
    def T_A(self):
        return self.H * self._ratios[3]

    @cached_property
    def T_B(self):
        return self.H * self._ratios[4]

    def _tv(self, s):
        return self.w * s - self.V_A

    def xy(self, s):
        """Positions ``(..., 2)`` (m) of the material points ``s`` (m of unstretched length from A)."""
        return np.stack(np.broadcast_arrays(self.x_of_s(s), self.y_of_s(s)), axis=-1)

    def T_of_s(self, s):
        """Tension (N) at the material point ``s``: ``H sqrt(1 + (q + w s/H)²)``."""
        s = real("s", s)
        p_s = self._ratios[0] + self.w * s / self.H
        with float_range("s", "T(s)"):
            return finite_at("s", self.H * namespace(p_s).hypot(1.0, p_s), "T(s)")

    def x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A)."""
        s = real("s", s)
        with float_range("s", "x(s)"):
            x = self.H * s / self.EA + self.H / self.w * asinh_step(self._ratios[0], self.w * s / self.H)
        return finite_at("s", x, "x(s)")

    def _y_terms(self, s):
        """The stretch and the inextensible part of ``y(s)``: ``(T(s) - T_A)/w`` as
        ``s (p_s + q)/(r_s + r_q)`` with ``p_s = q + w s/H`` (the step formed directly)."""
        q, rq = self._ratios[0], self._ratios[3]
        p_s = q + self.w * s / self.H
        shape = s * (p_s + q) / (namespace(p_s).hypot(1.0, p_s) + rq)
        return s * (0.5 * self.w * s - self.V_A) / self.EA, shape

    def y_of_s(self, s):
        """Height above A of the material point ``s``."""
        s = real("s", s)
        with float_range("s", "y(s)"):
            stretch, shape = self._y_terms(s)
            return finite_at("s", stretch + shape, "y(s)")

    def s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span] (x(s) is increasing)."""
        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        x_end = self.x_of_s(self.length)
        x = namespace(x, x_end).minimum(x, x_end)  # x(length) = span up to rounding
        # the parameters go in as arguments: the vectorised search passes them
        # compressed to the elements still iterating. The array back end may round x(length)
        # otherwise: the bracket reaches 1e-9 beyond B, and the root is kept in [0, length]
        args = (x, self.H, self.V_A, self.w, self.EA)
        s, _ = find_root(_x_of_s_minus, 0.0, self.length * (1.0 + 1e-9), args, what="s_of_x")
        return namespace(s, self.length).minimum(s, self.length)

    def y(self, x):
        """Height of the cable above A at abscissa ``x`` (m)."""
        return self.y_of_s(self.s_of_x(x))

    def slope(self, x):
        """dy/dx at ``x``."""
        return self._tv(self.s_of_x(x)) / self.H

    def T(self, x):
        """Tension at ``x`` (N)."""
        tv = self._tv(self.s_of_x(x))
        return namespace(tv).hypot(self.H, tv)

    def weight_per_length(self, x, slope):
        return self.w + 0.0 * slope

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(*shape, 2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the Jacobian of
        the closure equations (implicit function theorem), at constant length.
        """
        return elastic_stiffness(self)

    @cached_property
    def stretched_length(self):
        r"""Length of the loaded cable, ``L0 + ∫ T/EA ds`` (Irvine 1981, §2.2).

        :math:`\int_0^{L_0} T\,ds = \frac{H^2}{2w}\,(p r_p - q r_q + A)`, taken as
        :math:`\frac{HL_0}{2}\,(K + A/d)` with :math:`K = (p r_p - q r_q)/d`, which is
        :math:`r_p + q (p + q)/(r_p + r_q)` where p and q share a sign (no cancellation).
        """
        xp = self._xp
        q, d, p, rq, rp = self._ratios
        A = asinh_step_parts(q, d, p, rq, rp)[1]
        same = p * q > 0
        with np.errstate(invalid="ignore", divide="ignore"):
            rationalised = rp + q * (p + q) / (rp + rq)
            direct = (p * rp - q * rq) / d
        K = xp.where(same, rationalised, direct) if xp is np else (rationalised if same else direct)
        return self.length + 0.5 * self.H * self.length / self.EA * (K + A / d)

    @cached_property
    def _s_vertex(self):
        return self.V_A / self.w  # T_v(s) = 0

    @cached_property
    def x_vertex(self):
        """``x(V_A/w)``: ``H V_A/(w EA) + (H/w) asinh(V_A/H)`` (the vertical force vanishes there)."""
        return self.H * self.V_A / (self.w * self.EA) + self.H / self.w * self._xp.arcsinh(self.V_A / self.H)

    @cached_property
    def y_vertex(self):
        """``y(V_A/w)``: ``-(V_A/w) V_A (1/(2 EA) + 1/(H + T_A))``, no cancellation."""
        return -(self.V_A / self.w) * (self.V_A * (0.5 / self.EA + 1.0 / (self.H + self.T_A)))

    @cached_property
    def x_low(self):
        s, xp = self._s_vertex, self._xp
        if xp is not np:
            return 0.0 if s <= 0 else self.span if s >= self.length else self.x_vertex
        return np.where(s <= 0, 0.0, np.where(s >= self.length, self.span, self.x_vertex))

    @cached_property
    def y_low(self):
        s, xp = self._s_vertex, self._xp
        if xp is not np:
            return 0.0 if s <= 0 else self.dh if s >= self.length else self.y_vertex
        return np.where(s <= 0, 0.0, np.where(s >= self.length, self.dh, self.y_vertex))

    @cached_property
    def sag(self):
        s_star = (self.V_A + self.H * self.dh / self.span) / self.w  # slope = chord slope
        return self.dh * self.x_of_s(s_star) / self.span - self.y_of_s(s_star)

    def _residuals(self):
        """The closure evaluated by other formulas than the solve's (`asinh_step_log` for
        the arc, ``(H/w)(p + q) tanh(A/2)`` for ``(T_B - T_A)/w``), so that neither can hide
        the other's round-off, each over the size of its terms (its round-off); the end
        tensions; the vertical balance; the length."""
        xp = self._xp
        q, d, p, rq, rp = self._ratios
        A = asinh_step_log(q, d, p, rq, rp)
        stretch, shape = self.H * self.length / self.EA, self.H / self.w * A
        yield (stretch + shape - self.span) / (stretch + shape + self.span)  # terms all positive
        L, w, V_A = self.length, self.w, self.V_A
        half = self.H / w * xp.tanh(0.5 * A)
        y_stretch, y_shape = L * (0.5 * w * L - V_A) / self.EA, half * (p + q)
        operands = L * (0.5 * w * L + xp.abs(V_A)) / self.EA + half * (xp.abs(p) + xp.abs(q))
        yield (y_stretch + y_shape - self.dh) / (operands + xp.abs(self.dh))
        weight = self.w * self.length
        # V_B is w·L - V_A: the sum cancels to round-off of the reactions
        yield (self.V_A + self.V_B - weight) / (xp.abs(self.V_A) + xp.abs(self.V_B) + weight)
        yield from self._common_residuals(xp)


def _checked_floats(e) -> bool:
    """`ElasticCatenary._residuals` (and the finiteness of the vertex) written out on the floats
    of one scene, each term within `ACCEPT`; the values it computes are kept on ``e``. False
    where the general check must decide (it then raises the right error)."""
    H, V_A, w, L, EA = e.H, e.V_A, e.w, e.length, e.EA
    try:
        q, d = -V_A / H, w * L / H
        p = q + d
        rq, rp = math.hypot(1.0, q), math.hypot(1.0, p)
        e_p = p + rp if p >= 0 else 1.0 / (rp - p)  # exp(asinh p), as in `asinh_step_log`
        e_q = q + rq if q >= 0 else 1.0 / (rq - q)
        A = math.log1p(d * (e_p + e_q) / ((rp + rq) * e_q))
        stretch, shape = H * L / EA, H / w * A
        half = H / w * math.tanh(0.5 * A)
        y_stretch, operands = L * (0.5 * w * L - V_A) / EA, L * (0.5 * w * L + abs(V_A)) / EA
        V_B, weight, T_A, T_B = w * L - V_A, w * L, H * rq, H * rp
        t_a, v_a, t_b, v_b = H / T_A, V_A / T_A, H / T_B, V_B / T_B
        terms = (
            (stretch + shape - e.span) / (stretch + shape + e.span),
            (y_stretch + half * (p + q) - e.dh) / (operands + half * (abs(p) + abs(q)) + abs(e.dh)),
            (V_A + V_B - weight) / (abs(V_A) + abs(V_B) + weight),
            0.5 * ((1.0 - t_a) * (1.0 + t_a) - v_a * v_a),
            0.5 * ((1.0 - t_b) * (1.0 + t_b) - v_b * v_b),
        )
        x_vertex = H * V_A / (w * EA) + H / w * math.asinh(V_A / H)
        y_vertex = -(V_A / w) * (V_A * (0.5 / EA + 1.0 / (H + T_A)))
    except (OverflowError, ZeroDivisionError, ValueError):
        return False
    if not (
        all(-ACCEPT <= t <= ACCEPT for t in terms) and -_INF < x_vertex < _INF and -_INF < y_vertex < _INF
    ):
        return False  # NaN too
    e.__dict__.update(
        _ratios=(q, d, p, rq, rp), V_B=V_B, T_A=T_A, T_B=T_B, x_vertex=x_vertex, y_vertex=y_vertex
    )
    return True


_INF = math.inf


@_plausible.answer(check_catenary)
def elastic_catenary(span, dh, w, EA, *, length):
    """Elastic (Irvine) catenary from A = (0, 0) to B = (span, dh).

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance A→B (> 0) and height of B above A (m).
    w : float or array_like
        Weight per unit *unstretched* length (N/m), > 0.
    EA : float or array_like
        Axial stiffness (N), > 0.
    length : float or array_like
        Unstretched length (m), > 0; it may be shorter than the chord (the
        cable then stretches to reach B).

    Returns
    -------
    ElasticCatenary
        ``H, V_A, V_B, T_A, T_B, length`` (unstretched), ``stretched_length``,
        ``sag``, the lowest point ``x_low, y_low``, the vertex ``x_vertex,
        y_vertex``, ``y(x), T(x), slope(x), residual()``, ``stiffness()``.

    Raises
    ------
    InputError
        A non-physical argument, named.
    ConvergenceError
        Newton stalled; the error carries the residual history.
    """
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    EA = positive("EA", EA)
    L0 = positive("length", length)
    broadcast(span=span, dh=dh, w=w, EA=EA, length=L0)
    with outsized(span=span, dh=dh, w=w, EA=EA, length=L0):  # a refusal inside names the outsized one
        try:
            H, V_A, history = _solve(span, dh, w, EA, L0)
        except (OverflowError, ZeroDivisionError) as exc:
            raise InputError("EA", f"the closure equations overflow for these data ({exc})") from exc
        _plausible.stiffness(EA, w, L0)
        with float_range("length", "a result"):
            solution = ElasticCatenary(span, dh, w, EA, L0, H, V_A, ("length", L0))
            if type(H) is float and type(V_A) is float and _checked_floats(solution):
                return solution
            return checked_closed_form(solution, "length", history)


#: `elastic_catenary` without its answer check (`skcable._plausible.answer`): the solve inside
#: another model, which checks its own answer against its own limits (a conductor's change of
#: state against a conductor's strain).
elastic_catenary_unchecked = elastic_catenary.__wrapped__
