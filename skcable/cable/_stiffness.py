r"""Geometric stiffness of a suspended cable (Goicolea 2012, §3.2, example 7).

``k_G = dH/d(span)`` at constant cable length and support height difference
(an inextensible cable whose end moves horizontally). For the catenary,
differentiating :math:`S^2 - dh^2 = 4a^2\sinh^2 z` (z = span/2a) at constant
S and dh gives, for any dh,

.. math:: k_G = \frac{w}{2\,(z - \tanh z)},

which is Goicolea's (2012) :math:`k_G = (H/2a)/((x/a) - \tanh(x/a))` with x = span/2.
In series with the elastic stiffness :math:`k_E = EA/S`:
:math:`1/k = 1/k_G + 1/k_E` (Goicolea (2012), footnote 5).
"""

from __future__ import annotations

import numpy as np

from skcable._checks import TINY, broadcast, float_range, positive
from skcable._xp import namespace
from skcable.cable._catenary import Catenary
from skcable.cable._parabola import Parabola, length_derivatives
from skcable.cable._special import ldexp_sum, power_product, z_minus_tanh_over_cube
from skcable.errors import InputError

__all__ = ["geometric_stiffness", "geometric_stiffness_series"]


def geometric_stiffness(solution, *, EA=None):
    """Horizontal stiffness ``dH/d(span)`` of an inextensible solution (N/m).

    Parameters
    ----------
    solution : Catenary or Parabola
        A solved cable (any constraint).
    EA : float or array_like, optional
        Axial stiffness (N). When given, the series combination
        ``1/(1/k_G + 1/k_E)`` with ``k_E = EA/length`` is returned.

    Returns
    -------
    float or ndarray
        ``k_G``, or the combined stiffness with ``EA``.

    Raises
    ------
    InputError
        Not a catenary or parabola, a bad ``EA``, or a stiffness beyond the
        range of a float.
    """
    if isinstance(solution, Catenary):
        # w/(2(z - tanh z)), z - tanh z ~ z³/3 for taut cables: z³ underflows long
        # before the stiffness overflows, so w/z³ is formed from mantissas and exponents
        z = solution.z
        k_g = ldexp_sum(power_product(0.5, (solution.w, 1), (z, -3))) / z_minus_tanh_over_cube(z)
    elif isinstance(solution, Parabola):
        # S(a, span) at constant dh; k_G = -w (dS/dspan) / (dS/da), both derivatives
        # free of the cancellation of the textbook forms for taut cables
        s = solution
        with float_range("solution", "k_G"), np.errstate(over="ignore", divide="ignore"):
            ds_da, ds_dspan = length_derivatives(s.a, s._slope, s._delta, s.length)
            k_g = -s.w * ds_dspan / ds_da
    else:
        raise InputError("solution", f"must be a Catenary or a Parabola, got {type(solution).__name__}")
    _representable("solution", k_g, "k_G")
    if EA is None:
        return k_g
    EA = positive("EA", EA)
    broadcast(EA=EA, length=solution.length if isinstance(solution.length, np.ndarray) else 0.0)
    # 1/(1/k_G + 1/k_E) = k_G k_E / (k_G + k_E): the smaller over (1 + smaller/larger)
    k_e = _representable("EA", ldexp_sum(power_product(1.0, (EA, 1), (solution.length, -1))), "EA/length")
    xp = namespace(k_g, k_e)
    small, large = xp.minimum(k_g, k_e), xp.maximum(k_g, k_e)
    return small / (1.0 + small / large)


def _representable(name, value, what):
    bad = ~np.isfinite(value) | (np.abs(value) < TINY)
    if np.any(bad):
        raise InputError(name, f"gives {what} outside the range of a float (over- or underflow)")
    return value


def geometric_stiffness_series(span, w, H):
    r"""Goicolea's (2012) parabolic approximation of the catenary's ``k_G`` (equal heights).

    With the two-term length series :math:`S \approx 2x(1 + \xi^2/6)`,
    :math:`\xi = x/a = w\,\mathrm{span}/(2H)` (Goicolea 2012, eq. 25):

    .. math:: k_G = \frac{H}{2a}\,\frac{1 + \xi^2/2}{\xi^3/3}.

    Its leading term is the textbook :math:`12 H^3/(w^2 \mathrm{span}^3)`.
    ``w`` is the weight per unit cable length (N/m).

    It is evaluated as :math:`3H/(2\,\mathrm{span}) + 12 H^3/(w^2\mathrm{span}^3)`
    with mantissas and exponents apart, so that only a stiffness beyond the
    range of a float raises `InputError`.
    """
    span, w, H = positive("span", span), positive("w", w), positive("H", H)
    broadcast(span=span, w=w, H=H)
    k = ldexp_sum(
        power_product(1.5, (H, 1), (span, -1)),
        power_product(12.0, (H, 3), (w, -2), (span, -3)),
    )
    return _representable("span, w, H", k, "k_G")
