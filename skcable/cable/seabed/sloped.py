"""A line on a sloped seabed ``y = x tan α`` through the anchor, in closed form
(`sloped_seabed_catenary`, which states the closure and its sources)."""

from __future__ import annotations

import numpy as np

from skcable._checks import nonnegative, positive, real, require
from skcable.cable._elastic import elastic_catenary as free_elastic_catenary
from skcable.cable._extreme import outsized
from skcable.cable.closure import hanging_length, on_slope, slope_frame
from skcable.cable.seabed.sloped_solution import SlopedSeabedCatenary
from skcable.cable.seabed.solve import elastic_catenary
from skcable.errors import ConvergenceError, InputError

__all__ = ["SlopedSeabedCatenary", "sloped_seabed_catenary"]


def _scaled_closure(u, scene, scale, chord, history):
    """The closure over the chord at the scaled unknowns ``u = (H, L_B)/scale`` (a large
    value outside ``H > 0, 0 <= L_B < L``); appends its largest term to ``history``."""
    H, L_B = u * scale
    if not (H > 0 and 0 <= L_B < scene[4]):
        return np.array([1e3 * chord, 1e3 * chord])
    span, dh, w, EA, L, m, mu = scene
    X, Z = on_slope(float(H), float(L_B), w, EA, L, m, mu)[:2]
    r = np.array([X - span, Z - dh])
    history.append(float(np.max(np.abs(r)) / chord))
    return r / chord


def _hybr(start, scene, scale, chord, history):
    """``(H, L_B)`` by MINPACK's ``hybr`` from ``start``, or None where it ends off the root."""
    from scipy.optimize import root

    args = (scene, scale, chord, history)
    sol = root(_scaled_closure, start / scale, args=args, method="hybr", options={"xtol": 1e-15})
    H, L_B = sol.x * scale
    if H > 0 and 0 <= L_B < scene[4] and np.max(np.abs(_scaled_closure(sol.x, *args))) <= 1e-12:
        return H, L_B
    return None


def sloped_seabed_catenary(span, dh, w, EA, *, length, seabed_slope, friction=0.0):
    r"""Elastic catenary from an anchor A = (0, 0) lying on a sloped seabed ``y = x tan α``.

    The grounded part lies straight along the slope from A; its tension
    grows towards the fairlead by :math:`dT/ds = w(\sin\alpha + \mu\cos\alpha)`
    (the weight's component along the slope, and Coulomb friction on the
    normal force :math:`w\cos\alpha`, fully mobilised towards the anchor);
    the suspended part leaves the seabed tangentially, with
    :math:`V_t = H\tan\alpha` and :math:`T_t = H/\cos\alpha`, and hangs as an
    elastic catenary to B (H.M. Irvine, "Cable Structures", MIT Press, 1981).
    With :math:`k = w(\sin\alpha + \mu\cos\alpha)` and the tensioned grounded
    length :math:`\ell = \min(L_B, T_t/k)` (:math:`\ell = L_B` when
    :math:`k \le 0`), the closure equations in ``(H, L_B)`` are

    .. math::
        \Big[L_B + \frac{T_t\ell - k\ell^2/2}{EA}\Big]\cos\alpha
          + \frac{H L_s}{EA} + \frac{H}{w}\Big(\operatorname{asinh}\frac{V_B}{H}
          - \operatorname{asinh}\frac{V_t}{H}\Big) = X, \\
        \Big[L_B + \frac{T_t\ell - k\ell^2/2}{EA}\Big]\sin\alpha
          + \frac{\sqrt{H^2 + V_B^2} - \sqrt{H^2 + V_t^2}}{w}
          + \frac{V_B^2 - V_t^2}{2 EA w} = Z,

    :math:`L_s = L - L_B`, :math:`V_B = V_t + w L_s`: J.M. Jonkman's
    seabed line ("Dynamics modeling and loads analysis of an offshore
    floating wind turbine", NREL, 2007) on a slope, as in MoorPy's
    ``catenary(..., alpha=...)`` (which takes the friction force as
    :math:`\mu w` instead of :math:`\mu w\cos\alpha`; equal without friction).
    Exact: no approximation beyond the model's (straight seabed through A,
    friction fully mobilised).

    Parameters
    ----------
    span, dh : float
        Fairlead B relative to A (m); B above the seabed, ``dh > span·seabed_slope``.
    w, EA : float
        Weight per unstretched length (N/m) and axial stiffness (N), > 0.
    length : float
        Unstretched length (m).
    seabed_slope : float
        ``tan α`` (rise of the seabed per unit x towards B; negative: it falls).
    friction : float
        Coulomb coefficient μ >= 0.

    Returns
    -------
    SlopedSeabedCatenary
        ``H, V_B, H_A, V_A, T_A, T_B, length_on_seabed, x_touchdown, y_touchdown``.
        When the free line leaves A above the slope (no contact) the free
        `elastic_catenary`'s forces with ``length_on_seabed = 0``.

    Raises
    ------
    InputError
        Non-physical data, named: B on or below the seabed; a grounded line
        whose anchor end would need a zero-tension stretch that friction
        cannot hold on the slope (``μ < tan α``); slack in a heap.
    ConvergenceError
        The closure solve did not reach 1e-12 of the chord (with its history).
    """
    span, dh = positive("span", span), real("dh", dh)
    w, EA, L = positive("w", w), positive("EA", EA), positive("length", length)
    m = real("seabed_slope", seabed_slope)
    mu = nonnegative("friction", friction)
    for name, value in (("span", span), ("dh", dh), ("w", w), ("EA", EA), ("length", L), ("seabed_slope", m)):
        if not isinstance(value, float):
            raise InputError(name, "sloped_seabed_catenary solves one scene: give scalars")
    if not isinstance(mu, float):
        raise InputError("friction", "sloped_seabed_catenary solves one scene: give a scalar")
    with outsized(
        span=span, dh=dh, w=w, EA=EA, length=L, seabed_slope=m, friction=mu
    ):  # names the outsized one
        require("dh", dh > m * span, "must put B above the seabed (dh > span * seabed_slope)", dh)
        return _sloped(span, dh, w, EA, L, m, mu)


def _sloped(span, dh, w, EA, L, m, mu):
    """`sloped_seabed_catenary` on checked scalars."""
    free = free_elastic_catenary(span, dh, w, EA, length=L)
    if -free.V_A / free.H >= m:  # the free line leaves A at or above the slope: no contact
        return SlopedSeabedCatenary(span, dh, w, EA, L, m, mu, free.H, 0.0, [0.0], free=free)
    chord = float(np.hypot(span, dh))
    # start: the flat line of the same data in the frame of the slope
    cos, sin = slope_frame(m, np)
    along, across = span * cos + dh * sin, dh * cos - span * sin
    try:
        flat = elastic_catenary(along, across, w * cos, EA, length=L, seabed=0.0)
        H0, L_B0 = flat.H * cos, flat.length_on_seabed
    except (InputError, ConvergenceError):
        H0, L_B0 = free.H, 0.5 * L
    if not H0 > 1e-6 * w * L:  # the flat line lies in a heap: the slope may still pull it taut
        H0, L_B0 = w * L, 0.5 * L
    scene = (span, dh, w, EA, L, m, mu)
    scale = np.array([H0, L])
    history: list = []
    # the closure has one root (H > 0, 0 <= L_B < L); hybr from the flat line's start finds it
    # mostly, and from a few others where the slope bends the line away from that start
    starts = [(H0, min(max(L_B0, 0.0), 0.999 * L))]
    starts += [(H0 * a, b * L) for a in (1.0, 0.1, 10.0, 0.01) for b in (0.05, 0.5, 0.9, 0.99)]
    for start in starts:
        found = _hybr(np.array(start), scene, scale, chord, history)
        if found is not None:
            break
    else:
        height = dh - m * span  # B above the slope, vertically
        if L >= span / cos + float(hanging_length(height, w, EA)):
            raise InputError(
                "length",
                "leaves slack line lying in a heap on the sloped seabed (H -> 0): give a shorter "
                "line or a longer span",
            )
        raise ConvergenceError("sloped_seabed_catenary: the closure equations did not converge", history)
    H, L_B = found
    k = w * (sin + mu * cos)
    if k > 0 and H / cos - k * L_B < 0 and mu < m:
        raise InputError(
            "friction",
            "the grounded line would need a slack stretch near the anchor that friction cannot hold "
            "on this slope (friction < seabed_slope)",
        )
    return SlopedSeabedCatenary(span, dh, w, EA, L, m, mu, float(H), float(L_B), history)
