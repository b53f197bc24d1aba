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

from functools import cached_property

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, float_range, positive, real, require
from skcable._xp import namespace
from skcable.cable._catenary import _finite_at, catenary
from skcable.cable._roots import find_root
from skcable.cable._special import asinh_diff, largest_abs
from skcable.cable.solution import ACCEPT, CableSolution, checked_closed_form
from skcable.errors import ConvergenceError, InputError

__all__ = ["ElasticCatenary", "elastic_catenary"]

_TOL = 1e-13


def _closure(span, dh, w, EA, L0, H, V_A):
    """Residuals of the end conditions and their Jacobian w.r.t. (H, V_A)."""
    xp = namespace(H, V_A, span, EA)
    tv_a, tv_b = -V_A, w * L0 - V_A
    t_a, t_b = xp.hypot(H, tv_a), xp.hypot(H, tv_b)
    arc = asinh_diff(tv_b / H, tv_a / H)
    rise = (tv_b - tv_a) * (tv_b + tv_a) / (t_b + t_a)  # T_B - T_A
    f_x = H * L0 / EA + H / w * arc - span
    f_y = L0 * (0.5 * w * L0 - V_A) / EA + rise / w - dh
    j_xh = L0 / EA + (arc - tv_b / t_b + tv_a / t_a) / w
    j_xv = H / w * (1.0 / t_a - 1.0 / t_b)
    j_yh = H / w * (1.0 / t_b - 1.0 / t_a)
    j_yv = -L0 / EA + (tv_a / t_a - tv_b / t_b) / w
    return f_x, f_y, j_xh, j_xv, j_yh, j_yv


def _round_off(span, dh, w, EA, L0, H, V_A, chord):
    """Round-off floor of the closure residual: a few ulps of its terms over the chord
    (a strongly stretched line has terms far larger than the span)."""
    xp = namespace(H, V_A, span, EA)
    tv_a, tv_b = -V_A, w * L0 - V_A
    arc = asinh_diff(tv_b / H, tv_a / H)
    # the operands of the differences that cancel: w L0/2 - V_A and tv_b + tv_a
    rise = (tv_b - tv_a) * (xp.abs(tv_b) + xp.abs(tv_a)) / (xp.hypot(H, tv_b) + xp.hypot(H, tv_a))
    terms_x = H * L0 / EA + H / w * xp.abs(arc) + span
    terms_y = L0 * (0.5 * w * L0 + xp.abs(V_A)) / EA + rise / w + xp.abs(dh)
    return 16.0 * 2.220446049250313e-16 * xp.maximum(terms_x, terms_y) / chord


def _initial_guess(span, dh, w, EA, L0):
    xp = namespace(span, dh, w, EA, L0)
    chord = xp.hypot(span, dh)
    # inextensible catenary of a length at least 1e-6 above the chord,
    # lengthened once by the mean strain it predicts
    first = catenary(span, dh, w, length=xp.maximum(L0, chord * (1 + 1e-6)))
    strain = 0.5 * (first.T_A + first.T_B) / EA
    second = catenary(span, dh, w, length=xp.maximum(L0 * (1.0 + strain), chord * (1 + 1e-6)))
    # a cable shorter than its chord is a stretched bar: H ≈ EA·(chord/L0 - 1)·span/chord
    bar = EA * (chord / L0 - 1.0) * span / chord
    H = xp.maximum(second.H, bar)
    return H, second.V_A * H / second.H


def _solve(span, dh, w, EA, L0):
    H, V_A = _initial_guess(span, dh, w, EA, L0)
    xp = namespace(H, V_A)
    chord = xp.hypot(span, dh)
    f_x, f_y, *jac = _closure(span, dh, w, EA, L0, H, V_A)
    norm = xp.maximum(xp.abs(f_x), xp.abs(f_y)) / chord
    history = [largest_abs(norm)]
    for _ in range(60):
        if history[-1] < _TOL:
            return H, V_A, history
        # stalled above _TOL: accept if at the round-off of the closure's terms
        stalled = len(history) > 2 and history[-1] > 0.25 * history[-2]
        if stalled:
            floor = _round_off(span, dh, w, EA, L0, H, V_A, chord)
            if np.all(norm <= floor) and history[-1] <= ACCEPT:  # residual() checks it again
                return H, V_A, history
        j_xh, j_xv, j_yh, j_yv = jac
        det = j_xh * j_yv - j_xv * j_yh
        d_h = -(f_x * j_yv - f_y * j_xv) / det
        d_v = -(j_xh * f_y - j_yh * f_x) / det
        step = 1.0 + 0.0 * norm
        for _ in range(30):  # backtrack: keep H > 0 and reduce the residual
            H_new = H + step * d_h
            H_safe = xp.maximum(H_new, 1e-300)
            # a trial step may overflow (H near 0): its non-finite residual fails `ok`
            with np.errstate(over="ignore", invalid="ignore"):
                f_x, f_y, *jac = _closure(span, dh, w, EA, L0, H_safe, V_A + step * d_v)
                new = xp.maximum(xp.abs(f_x), xp.abs(f_y)) / chord
            ok = (H_new > 0) & (new < norm * (1.0 - 1e-4 * step) + 4 * _TOL)
            if np.all(ok):
                break
            step = step * np.where(ok, 1.0, 0.5) if xp is np else step * 0.5
        H, V_A, norm = H_new, V_A + step * d_v, new
        history.append(largest_abs(norm))
    raise ConvergenceError("elastic_catenary: Newton did not converge", history)


def inverse_2x2(j11, j12, j21, j22):
    """Inverse of ``[[j11, j12], [j21, j22]]`` elementwise, shape ``(*shape, 2, 2)``."""
    det = np.asarray(j11 * j22 - j12 * j21)[..., None, None]
    return np.stack([np.stack([j22, -j12], -1), np.stack([-j21, j11], -1)], -2) / det


def elastic_stiffness(s):
    """``∂(H, V_B)/∂(span, dh)`` of a free `ElasticCatenary`: the closure's Jacobian
    in ``(H, V_A)`` inverted (implicit function theorem), ``V_B = wL - V_A``."""
    _, _, j_xh, j_xv, j_yh, j_yv = _closure(s.span, s.dh, s.w, s.EA, s.length, s.H, s.V_A)
    return inverse_2x2(j_xh, j_xv, j_yh, j_yv) * np.array([[1.0], [-1.0]])


def _x_of_s_minus(s, x, H, V_A, w, EA):
    return H * s / EA + H / w * asinh_diff((w * s - V_A) / H, -V_A / H) - x


class ElasticCatenary(CableSolution):
    """Solution of `elastic_catenary`.

    Attributes are those of `Catenary`, with
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
    def T_A(self):
        return self._xp.hypot(self.H, self.V_A)

    @cached_property
    def T_B(self):
        return self._xp.hypot(self.H, self.V_B)

    def _tv(self, s):
        return self.w * s - self.V_A

    def x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A)."""
        s = real("s", s)
        with float_range("s", "x(s)"):
            x = self.H * s / self.EA + self.H / self.w * asinh_diff(self._tv(s) / self.H, -self.V_A / self.H)
        return _finite_at("s", x, "x(s)")

    def _y_terms(self, s):
        tv, tv_a = self._tv(s), -self.V_A
        xp = namespace(s, tv)
        rise = (tv - tv_a) * (tv + tv_a) / (xp.hypot(self.H, tv) + self.T_A)
        return s * (0.5 * self.w * s - self.V_A) / self.EA, rise / self.w  # stretch, inextensible

    def y_of_s(self, s):
        """Height above A of the material point ``s``."""
        s = real("s", s)
        with float_range("s", "y(s)"):
            stretch, shape = self._y_terms(s)
            return _finite_at("s", stretch + shape, "y(s)")

    def s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span] (x(s) is increasing)."""
        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        x_end = self.x_of_s(self.length)
        x = namespace(x, x_end).minimum(x, x_end)  # x(length) = span up to rounding
        # the parameters go in as arguments: the vectorised search passes them
        # compressed to the elements still iterating
        args = (x, self.H, self.V_A, self.w, self.EA)
        s, _ = find_root(_x_of_s_minus, 0.0, self.length, args, what="s_of_x")
        return s

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
        """Length of the loaded cable, ``L0 + ∫ T/EA ds``."""
        xp = self._xp

        def primitive(tv):  # ∫ sqrt(H² + tv²) d(tv)
            return 0.5 * (tv * xp.hypot(self.H, tv) + self.H**2 * xp.arcsinh(tv / self.H))

        return self.length + (primitive(self.V_B) - primitive(-self.V_A)) / (self.w * self.EA)

    @cached_property
    def _s_vertex(self):
        return self.V_A / self.w  # T_v(s) = 0

    @cached_property
    def x_vertex(self):
        return self.x_of_s(self._s_vertex)

    @cached_property
    def y_vertex(self):
        return self.y_of_s(self._s_vertex)

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
        xp = self._xp
        chord = xp.hypot(self.span, self.dh)
        yield (self.x_of_s(self.length) - self.span) / chord  # both terms of x(s) are positive
        stretch, shape = self._y_terms(self.length)
        yield (stretch + shape - self.dh) / (chord + xp.abs(stretch) + xp.abs(shape))
        weight = self.w * self.length
        # V_B is w·L - V_A: the sum cancels to round-off of the reactions
        yield (self.V_A + self.V_B - weight) / (xp.abs(self.V_A) + xp.abs(self.V_B) + weight)
        yield from self._common_residuals(xp)


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
    try:
        H, V_A, history = _solve(span, dh, w, EA, L0)
    except (OverflowError, ZeroDivisionError) as exc:
        raise InputError("EA", f"the closure equations overflow for these data ({exc})") from exc
    _plausible.stiffness(EA, w, L0)
    with float_range("length", "a result"):
        solution = ElasticCatenary(span, dh, w, EA, L0, H, V_A, ("length", L0))
        return checked_closed_form(solution, "length", history)
