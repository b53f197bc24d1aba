r"""Geometric stiffness of a suspended cable (seed 001 §3.2, example 7).

``k_G = dH/d(span)`` at constant cable length and support height difference
(an inextensible cable whose end moves horizontally). For the catenary,
differentiating :math:`S^2 - dh^2 = 4a^2\sinh^2 z` (z = span/2a) at constant
S and dh gives, for any dh,

.. math:: k_G = \frac{w}{2\,(z - \tanh z)},

which is seed 001's :math:`k_G = (H/2a)/((x/a) - \tanh(x/a))` with x = span/2.
In series with the elastic stiffness :math:`k_E = EA/S`:
:math:`1/k = 1/k_G + 1/k_E` (seed 001, footnote 5).
"""

from __future__ import annotations

from skcable._checks import positive
from skcable._xp import namespace
from skcable.cable._catenary import Catenary
from skcable.cable._parabola import Parabola
from skcable.cable._special import z_minus_tanh
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
    """
    if isinstance(solution, Catenary):
        k_g = solution.w / (2.0 * z_minus_tanh(solution.z))
    elif isinstance(solution, Parabola):
        # S(a, span) at constant dh; k_G = -w (dS/dspan) / (dS/da)
        s, a, span, dh = solution, solution.a, solution.span, solution.dh
        xp = namespace(a, span, dh)
        r_a, r_b = xp.sqrt(1.0 + s.p_A**2), xp.sqrt(1.0 + s.p_B**2)
        ds_da = s.length / a - span / (2.0 * a) * (r_a + r_b)
        ds_dspan = 0.5 * (r_a + r_b) + a * dh * (r_a - r_b) / span**2
        k_g = -s.w * ds_dspan / ds_da
    else:
        raise InputError("solution", f"must be a Catenary or a Parabola, got {type(solution).__name__}")
    if EA is None:
        return k_g
    k_e = positive("EA", EA) / solution.length
    return 1.0 / (1.0 / k_g + 1.0 / k_e)


def geometric_stiffness_series(span, w, H):
    r"""Seed 001's parabolic approximation of the catenary's ``k_G`` (equal heights).

    With the two-term length series :math:`S \approx 2x(1 + \xi^2/6)`,
    :math:`\xi = x/a = w\,\mathrm{span}/(2H)` (seed 001 eq. 25):

    .. math:: k_G = \frac{H}{2a}\,\frac{1 + \xi^2/2}{\xi^3/3}.

    Its leading term is the textbook :math:`12 H^3/(w^2 \mathrm{span}^3)`.
    ``w`` is the weight per unit cable length (N/m).
    """
    span, w, H = positive("span", span), positive("w", w), positive("H", H)
    xi = 0.5 * w * span / H
    return 0.5 * w * (1.0 + 0.5 * xi * xi) / (xi**3 / 3.0)
