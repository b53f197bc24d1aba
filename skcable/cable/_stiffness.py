r"""Geometric stiffness of a suspended cable (Goicolea 2012, §3.2, example 7).

``k_G = dH/d(span)`` at constant cable length and support height difference
(an inextensible cable whose end moves horizontally). For the catenary,
differentiating :math:`S^2 - dh^2 = 4a^2\sinh^2 z` (z = span/2a) at constant
S and dh gives, for any dh,

.. math:: k_G = \frac{w}{2\,(z - \tanh z)},

which is Goicolea's (2012) :math:`k_G = (H/2a)/((x/a) - \tanh(x/a))` with x = span/2.
In series with the elastic stiffness :math:`k_E = EA/S`:
:math:`1/k = 1/k_G + 1/k_E` (Goicolea (2012), footnote 5).

`fairlead_stiffness` gives the full 2×2 matrix :math:`\partial(H, V_B)/\partial(\mathrm{span}, dh)`
with A fixed and the (unstretched) length constant, each solution's ``stiffness()``: in closed
form for the catenary (`Catenary.stiffness`) and the parabola; for the elastic catenary (H.M.
Irvine, "Cable Structures", MIT Press, 1981) and the line on the seabed (J.M. Jonkman,
"Dynamics modeling and loads analysis of an offshore floating wind turbine", NREL, 2007) the
inverse of the Jacobian of the closure equations (implicit function theorem).
"""

from __future__ import annotations

import numpy as np

from skcable._checks import TINY, broadcast, positive
from skcable._xp import namespace
from skcable.cable._catenary import Catenary
from skcable.cable._elastic import ElasticCatenary
from skcable.cable._parabola import Parabola
from skcable.cable._special import ldexp_sum, power_product
from skcable.cable.seabed import SeabedCatenary
from skcable.errors import InputError

__all__ = ["fairlead_stiffness", "geometric_stiffness", "geometric_stiffness_series"]


def geometric_stiffness(solution, *, EA=None):
    """Horizontal stiffness ``dH/d(span)`` of an inextensible solution (N/m).

    Parameters
    ----------
    solution : Catenary, Parabola, ElasticCatenary or SeabedCatenary
        A solved cable (any constraint). For the elastic solutions (their own
        ``EA`` included) this is ``fairlead_stiffness(solution)[..., 0, 0]``.
    EA : float or array_like, optional
        Axial stiffness (N), for a Catenary or Parabola only. When given, the
        series combination ``1/(1/k_G + 1/k_E)`` with ``k_E = EA/length`` is
        returned.

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
    if isinstance(solution, (ElasticCatenary, SeabedCatenary)):
        if EA is not None:
            raise InputError("EA", "the elastic solution has its own EA; leave EA out")
        k = fairlead_stiffness(solution)[..., 0, 0]
        return _representable("solution", float(k) if k.ndim == 0 else k, "dH/dspan")
    if not isinstance(solution, (Catenary, Parabola)):
        raise _not_a_solution(solution)
    k_g = solution.k_G
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


def _not_a_solution(solution):
    kinds = "a Catenary, Parabola, ElasticCatenary or SeabedCatenary"
    return InputError("solution", f"must be {kinds}, got {type(solution).__name__}")


def fairlead_stiffness(solution):
    """Stiffness of the force at B, ``∂(H, V_B)/∂(span, dh)``, A fixed, length constant.

    Parameters
    ----------
    solution : Catenary, Parabola, ElasticCatenary or SeabedCatenary
        A solved cable (any constraint of the inextensible forms; the length is
        held at its solved value).

    Returns
    -------
    ndarray
        Shape ``(*shape, 2, 2)``: rows ``(H, V_B)``, columns ``(span, dh)`` (N/m),
        analytic (no finite differences).

    Raises
    ------
    InputError
        Another kind of solution, or a stiffness beyond the range of a float.
    """
    if not callable(getattr(solution, "stiffness", None)):  # any solution of the result protocol
        raise _not_a_solution(solution)
    k = solution.stiffness()
    if not np.isfinite(k).all():  # zeros are legitimate here (dh = 0 decouples H and V_B)
        raise InputError("solution", "gives the stiffness outside the range of a float (over- or underflow)")
    return k


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
