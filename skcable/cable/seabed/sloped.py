"""A line on a sloped seabed in closed form: through the anchor, ``y = x tan α``
(`sloped_seabed_catenary`, which states the closure and its sources); below both ends and without
friction, the longest line the slope holds taut (`taut_length_on_slope`, `refuse_slack_on_slope`;
the line shorter than that which touches down between them: `skcable.cable.seabed.slope_touchdown`)."""

from __future__ import annotations

import math

import numpy as np

from skcable._checks import nonnegative, positive, real, require, scalar
from skcable.cable._elastic import elastic_catenary as free_elastic_catenary
from skcable.cable._extreme import outsized
from skcable.cable.closure import hanging, hanging_length, on_slope, slope_frame
from skcable.cable.seabed.sloped_solution import SlopedSeabedCatenary
from skcable.cable.seabed.solve import elastic_catenary
from skcable.errors import ConvergenceError, InputError

__all__ = ["SlopedSeabedCatenary", "refuse_slack_on_slope", "sloped_seabed_catenary", "taut_length_on_slope"]


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


def taut_length_on_slope(span, dh, w, EA, *, seabed, seabed_slope) -> float:
    r"""The longest line a frictionless straight slope holds taut between two ends above it (m).

    A = (0, 0) and B = (span, dh) above the seabed ``y = seabed + x tan α`` (``seabed < 0``, B
    above it), one uniform segment (``w``, ``EA``). A line that touches down between its ends
    lies straight on the slope, where without friction its tension grows uphill by
    :math:`dT/ds = w\sin\alpha` per unstretched length (the weight's component along the
    slope); it leaves the slope tangentially at both ends of that stretch. The longer the
    line, the lower the tension where it lands on the slope's lower side; at this length it
    is zero there: the part from the lower end hangs vertically (``H = 0``) onto the foot of
    the slope below it, of length :math:`l_v` with :math:`l_v + w l_v^2/(2EA) = d`, ``d``
    the end's height above the slope (Irvine 1981 at ``H = 0``,
    `skcable.cable.closure.hanging_length`); a stretch ``ℓ`` lies on the slope from the foot,
    its tension rising from zero to :math:`T_2 = w\ell\sin\alpha`, stretched to
    :math:`G = \ell + w\ell^2\sin\alpha/(2EA)`; the rest, :math:`s_2`, hangs from there
    with :math:`H_2 = T_2\cos\alpha` and the vertical force :math:`H_2\tan\alpha` to the
    other end (Irvine's elastic catenary, `skcable.cable.closure.hanging`: run ``x``, rise
    ``z``):

    .. math::
        G\cos\alpha + x(H_2, s_2) = \Delta x, \qquad
        G\sin\alpha + z(H_2, s_2) = \Delta y, \qquad L^* = l_v + \ell + s_2,

    ``Δx, Δy`` the other end from the foot. A longer line has no taut equilibrium: its slack
    slides down to the foot and lies there in a heap (``H = 0`` at the lower end), as a line
    longer than its L-shape on a flat seabed (Jonkman 2007). For each ``ℓ`` the run fixes
    :math:`s_2` (``x`` grows with it), and the rise's mismatch falls from :math:`+\infty`
    (``ℓ → 0``) to below zero (the landing under the other end): both roots by Brent's method.

    Parameters
    ----------
    span, dh : float
        B relative to A (m), ``span > 0``.
    w, EA : float
        Weight per unstretched length (N/m) and axial stiffness (N, ``inf``: inextensible), > 0.
    seabed : float
        The seabed under A relative to A (m), < 0.
    seabed_slope : float
        ``tan α`` (rise per unit x towards B), nonzero; B above the seabed.

    Returns
    -------
    float
        ``L*`` (m), unstretched.
    """
    from scipy.optimize import brentq

    span, dh, w = (scalar(name, check(name, v)) for name, check, v in _SCENE(span, dh, w))
    EA = math.inf if EA == math.inf else scalar("EA", positive("EA", EA))
    b, m = (
        scalar("seabed", real("seabed", seabed)),
        scalar("seabed_slope", real("seabed_slope", seabed_slope)),
    )
    require("seabed", b < 0.0, "must lie below A (< 0)", b)
    require("seabed_slope", m != 0.0, "must be nonzero (a flat seabed's limit is its L-shape)", m)
    require("dh", dh > b + m * span, "must put B above the seabed", dh)
    if m < 0:  # the foot lies under B: the same line seen from B
        span, dh, b, m = span, -dh, b + m * span - dh, -m
    cos, sin = slope_frame(m)
    lying_end = span / cos  # the stretched length that lands under the other end
    top = brentq(lambda ell: ell + w * sin * ell * ell / (2.0 * EA) - lying_end, 0.0, lying_end)

    def lying(ell):
        return ell + w * sin * ell * ell / (2.0 * EA), w * sin * cos * ell

    def hanging_part(ell):
        """``s_2`` of the run, and the rise's mismatch (m)."""
        G, H2 = lying(ell)
        run = span - G * cos
        if run <= 0.0:
            return 0.0, b + G * sin - dh
        hi = span
        while hanging(H2, H2 * m, w, EA, hi)[0] < run:
            hi *= 2.0
        s2 = brentq(lambda s: hanging(H2, H2 * m, w, EA, s)[0] - run, 0.0, hi, xtol=1e-13 * span, rtol=1e-15)
        return s2, b + G * sin + hanging(H2, H2 * m, w, EA, s2)[1] - dh

    lo = top * 1e-9
    while hanging_part(lo)[1] <= 0.0:  # the mismatch is +inf at 0: a smaller ℓ
        lo *= 1e-3
    ell = brentq(lambda e: hanging_part(e)[1], lo, top, xtol=1e-13 * span, rtol=1e-15)
    return float(hanging_length(-b, w, EA) + ell + hanging_part(ell)[0])


def _SCENE(span, dh, w):
    """The checks of ``span``, ``dh`` and ``w``: ``(name, check, value)``."""
    return (("span", positive, span), ("dh", real, dh), ("w", positive, w))


def refuse_slack_on_slope(span, dh, w, EA, length, *, seabed, seabed_slope) -> float:
    """``InputError("length")`` where a frictionless uniform line between two ends above a straight
    slope is longer than `taut_length_on_slope`: it has no taut equilibrium, its slack lies in a
    heap at the foot of the slope. Returns that taut length (m), for a caller that needs it too."""
    length = scalar("length", positive("length", length))
    longest = taut_length_on_slope(span, dh, w, EA, seabed=seabed, seabed_slope=seabed_slope)
    if length > longest:
        end = "A" if seabed_slope > 0 else "B"
        raise InputError(
            "length",
            f"{length:.6g} m is longer than the {longest:.6g} m a frictionless slope holds taut between "
            f"two ends above it: the slack slides down to the foot of the slope below {end} and lies "
            f"there in a heap (H = 0 at {end}), a state without tension that no solver here takes; "
            f"at most {longest:.6g} m hangs taut",
        )
    return longest
