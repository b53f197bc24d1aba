r"""Irvine's elastic catenary: an extensible cable under its own weight.

Lagrangian coordinate ``s`` along the *unstretched* cable, ``s = 0`` at A,
``s = L0`` at B; weight ``w`` per unstretched length, axial stiffness
``EA``. With the vertical tension component :math:`T_v(s) = w s - V_A` and
:math:`T = \sqrt{H^2 + T_v^2}` (Irvine, *Cable Structures*, 1981, §2.2):

.. math::
    x(s) = \frac{H s}{EA} + \frac{H}{w}\left[\operatorname{asinh}\frac{T_v(s)}{H}
           - \operatorname{asinh}\frac{T_v(0)}{H}\right], \qquad
    y(s) = \frac{w s^2/2 - V_A s}{EA} + \frac{T(s) - T(0)}{w}.

The two closure conditions ``x(L0) = span`` and ``y(L0) = dh`` (the one closure of an elastic
segment, `skcable.cable.closure`) are solved for ``(H, V_A)`` by Newton's method with the
analytic Jacobian and backtracking, started from the inextensible catenary of a length
corrected for the mean stretch; the solution is checked by other formulas than the solve's
(`skcable.cable.closure.check`).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, float_range, positive, real
from skcable._newton2 import solve2
from skcable._xp import namespace, scalar_math
from skcable.cable._answers import check_catenary
from skcable.cable._catenary import finite_at, hanging
from skcable.cable._extreme import outsized
from skcable.cable._hanging import hanging_forces
from skcable.cable._roots import find_root
from skcable.cable.closure import check, closure, end_ratios, positions, stretched_length
from skcable.cable.solution import ACCEPT, CableSolution, checked_closed_form
from skcable.errors import InputError

__all__ = ["ElasticCatenary", "elastic_catenary"]


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
    """``(H, V_A, history)``: Newton on the one closure (`skcable.cable.closure.closure`) in
    ``(H, V_b)``, ``V_b = -V_A``, from `_initial_guess`."""
    H, V_A = _initial_guess(span, dh, w, EA, L0)
    result = solve2(closure, H, -V_A, (span, dh, w, EA, L0), what="elastic_catenary")
    return result.x, -result.y, result.history


def inverse_2x2(j11, j12, j21, j22):
    """Inverse of ``[[j11, j12], [j21, j22]]`` elementwise, shape ``(*shape, 2, 2)``."""
    det = np.asarray(j11 * j22 - j12 * j21)[..., None, None]
    return np.stack([np.stack([j22, -j12], -1), np.stack([-j21, j11], -1)], -2) / det


def elastic_stiffness(s):
    """``∂(H, V_B)/∂(span, dh)`` of a free `ElasticCatenary`: the closure's Jacobian
    in ``(H, V_b)`` inverted (implicit function theorem), ``V_B = wL + V_b``."""
    _, _, j_xh, j_xv, j_yh, j_yv, _, _ = closure(s.H, -s.V_A, s.span, s.dh, s.w, s.EA, s.length)
    return inverse_2x2(j_xh, j_xv, j_yh, j_yv)


def _x_of_s_minus(s, x, H, V_A, w, EA):
    return positions(H, -V_A, w, EA, s, namespace(s, H))[0] - x


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
        """``(q, d, p, r_q, r_p)`` of the ends (`skcable.cable.closure.end_ratios`)."""
        return end_ratios(self.H, -self.V_A, self.w, self.length, self._xp)

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
            x = positions(self.H, -self.V_A, self.w, self.EA, s, namespace(s, self.H))[0]
        return finite_at("s", x, "x(s)")

    def y_of_s(self, s):
        """Height above A of the material point ``s``."""
        s = real("s", s)
        with float_range("s", "y(s)"):
            y = positions(self.H, -self.V_A, self.w, self.EA, s, namespace(s, self.H))[1]
            return finite_at("s", y, "y(s)")

    def s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span] (x(s) is increasing)."""
        x = self._abscissa(x)
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

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(*shape, 2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the Jacobian of
        the closure equations (implicit function theorem), at constant length.
        """
        return elastic_stiffness(self)

    @cached_property
    def stretched_length(self):
        """Length of the loaded cable, ``L0 + ∫ T/EA ds`` (`skcable.cable.closure.stretched_length`)."""
        return stretched_length(self.H, -self.V_A, self.w, self.EA, self.length, self._xp)

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
        """The closure evaluated by other formulas than the solve's (`skcable.cable.closure.check`),
        so that neither can hide the other's round-off, each over the size of its terms (its
        round-off); the end tensions; the vertical balance; the length."""
        xp = self._xp
        yield from check(
            self.H, -self.V_A, self.w, self.EA, self.length, self.span, self.dh, xp, self._ratios
        )
        weight = self.w * self.length
        # V_B is w·L - V_A: the sum cancels to round-off of the reactions
        yield (self.V_A + self.V_B - weight) / (xp.abs(self.V_A) + xp.abs(self.V_B) + weight)
        yield from self._common_residuals(xp)


def _checked_floats(e) -> bool:
    """`ElasticCatenary._residuals` (and the finiteness of the vertex) on the floats of one
    scene, each term within `ACCEPT`; the values it computes are kept on ``e``. False where
    the general check must decide (it then raises the right error)."""
    H, V_A, w, L, EA = e.H, e.V_A, e.w, e.length, e.EA
    try:
        ratios = end_ratios(H, -V_A, w, L)
        V_B, weight, T_A, T_B = w * L - V_A, w * L, H * ratios[3], H * ratios[4]
        t_a, v_a, t_b, v_b = H / T_A, V_A / T_A, H / T_B, V_B / T_B
        terms = (
            *check(H, -V_A, w, EA, L, e.span, e.dh, scalar_math, ratios),
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
    e.__dict__.update(_ratios=ratios, V_B=V_B, T_A=T_A, T_B=T_B, x_vertex=x_vertex, y_vertex=y_vertex)
    return True


_INF = math.inf


@_plausible.answer(check_catenary)
def elastic_catenary(span, dh, w, EA, *, length):
    """Elastic (Irvine) catenary from A = (0, 0) to B = (span, dh), free of any seabed: the
    `ElasticCatenary` of `skcable.cable.elastic_catenary` without ``seabed`` (its parameters,
    returns and errors)."""
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
