r"""Jonkman's slack stretch near the anchor: where friction fully mobilised would take more than the pull.

A grounded line whose friction could hold more than the pull is slack near the anchor
(J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore floating wind turbine",
NREL, 2007: ``H_A = 0``, tension ``max(H - μ w (L_B - s), 0)``): friction is only partly
mobilised there. Its end ``s0`` is a mesh node found like the touchdown: on ``[0, s0]`` the
friction holds the line's own tangential weight (`skcable.mooring.line_bvp.contact`), beyond it
friction is fully mobilised (at the node ``s0`` for the share of its weight beyond), and ``s0``
is moved (a Newton step on the tension just past it, with slope ``μ w``, kept in the bracket of
the tensions tried: `next_slack_end`) until that tension is zero to ``rtol`` of the total load.
With P2 positions and P1 tension the grounded line's exact solution (T linear, x quadratic in
s) is then represented exactly; the friction that holds a slack stretch on a slope is checked
against ``μN``.

The functions read a `skcable.mooring.line_bvp.solution.LineBVPSolution` through its public
names.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from skcable.errors import ConvergenceError

__all__ = [
    "BUOY_ON_STRETCH",
    "buoy_on_stretch",
    "next_slack_end",
    "secant_slack_end",
    "slack_estimate",
    "slack_tension",
    "tension_zero",
]

#: updates of the end of the slack stretch at most (secant on the tension there)
SLACK_PASSES = 12


def next_slack_end(tried, slope, s_touchdown):
    """The next end ``s0`` of the slack stretch from the (s0, tension just past s0) pairs tried.

    The tension there grows with s0 by about the friction force per length, ``slope`` (N/m): a
    Newton step on the last pair with that slope, kept inside the bracket of the earlier pairs
    (the largest s0 with a negative tension and the smallest with a positive one; bisection when
    the step leaves it), and below the touchdown; 0 when the step passes the anchor and no
    negative tension was tried (friction does not take the whole pull after all).
    """
    s_last, g_last = tried[-1]
    if not slope > 0:
        raise ConvergenceError(
            "solve_line_bvp: the tension does not grow away from the slack stretch",
            [abs(g) for _, g in tried],
        )
    lo = max((s for s, g in tried if g < 0), default=0.0)
    hi = min((s for s, g in tried if g > 0), default=s_touchdown)
    s_next = s_last - g_last / slope
    if s_next <= 0 and not any(g < 0 for _, g in tried):
        return 0.0  # the tension stays positive down to the anchor: no slack stretch
    if not lo < s_next < hi:
        s_next = 0.5 * (lo + hi)
    return float(s_next)


def secant_slack_end(tried, slope, s_touchdown):
    """`next_slack_end` with the secant slope of the last two (end, tension past it) pairs of
    ``tried`` where there are two and it is positive, else ``slope`` (N/m): where the end's move
    moves the whole line the tension past it falls by a constant factor per Newton step on
    ``slope``, and the secant restores the superlinear convergence (both line BVPs' passes)."""
    if len(tried) > 1:
        (s1, g1), (s2, g2) = tried[-2:]
        secant = (g2 - g1) / (s2 - s1) if s2 != s1 else 0.0
        slope = secant if secant > 0 else slope
    return next_slack_end(tried, slope, s_touchdown)


def buoy_on_stretch(point_loads, s0, weight_at) -> float | None:
    """The arc length (m) of the first buoy (a net upward point load ``P < 0``, the loads at one
    arc length summed) on the slack stretch ``[0, s0]`` or within the length of line it lifts past
    its end, ``|P|/w`` (``weight_at(s)``, N/m), or None (and None without a stretch). No tension
    holds it down there: it lifts a bight of the line off the seabed, which neither line BVP models
    (their stretch lies on the seabed, and their answers moved with the mesh: a 2 kN buoy 10 m from
    the anchor of a 1 kN/m chain was held flat on 64 and 128 elements, the stretch ending at
    32.8 m, and lifted on 256, ending at 8.3 m, 3.6 % apart in H)."""
    if not s0 > 0:
        return None
    net: dict[float, float] = {}
    for s, P in point_loads:
        net[float(s)] = net.get(float(s), 0.0) + float(P)
    for s, P in sorted(net.items()):
        if P < 0:
            w = float(weight_at(np.array([s]))[0])
            if s <= s0 + (-P / w if w > 0 else np.inf):
                return s
    return None


BUOY_ON_STRETCH = (
    "lifts the slack stretch near the anchor at s = {s:.6g} m: no tension holds it down there, so "
    "it raises a bight of the line off the seabed, which this BVP does not model (its stretch lies "
    "on the seabed)"
)


def tension_zero(solution, tol):
    """Where the tension of a line grounded at A last rises through zero (m of arc length): the
    end of Jonkman's slack stretch estimated from a solve with friction fully mobilised
    everywhere; 0 when the tension is nowhere below ``-tol`` (N)."""
    s_l, s_r, T_l, T_r = solution.tension_profile()
    s, T = np.column_stack([s_l, s_r]).ravel(), np.column_stack([T_l, T_r]).ravel()
    negative = np.flatnonzero(T < -tol)
    if not negative.size:
        return 0.0
    k = int(negative[-1])
    if k + 1 >= T.size or s[k + 1] == s[k] or T[k + 1] <= T[k]:
        zero = s[min(k + 1, T.size - 1)]
    else:
        zero = s[k] - T[k] * (s[k + 1] - s[k]) / (T[k + 1] - T[k])
    return float(min(zero, 0.99 * solution.s_touchdown))


def slack_estimate(solution, friction):
    """The end ``s0`` of the slack stretch (m) that friction ``μ`` fully mobilised from the
    touchdown towards A would give a frictionless solution's grounded line on a flat seabed:
    ``μ (W(s_td) - W(s0)) = T(s_td)``, W the vertical load from A (the weight, the point loads
    and the cable terms' share, `LineFields.load_before`); 0 when friction cannot take the
    pull."""
    if not solution.touches_beyond_anchor():
        return 0.0
    s_td = solution.s_touchdown
    slope = solution.seabed_slope_at(s_td)
    pull = solution.H * np.sqrt(1.0 + slope * slope) / friction  # the tension at the touchdown / μ
    if not pull > 0:  # a frictionless line pushing at its fairlead: a spurious branch, no estimate
        raise ConvergenceError(
            f"solve_line_bvp: the frictionless line has H = {solution.H:.3g} N, no slack stretch to "
            "estimate from it",
            solution.history,
        )

    def before(s):
        return solution.load_before(s)[-1]

    if before(s_td) <= pull:
        return 0.0
    return float(brentq(lambda s: before(s_td) - before(s) - pull, 0.0, s_td))


def slack_tension(solution):
    """Tension (N) just past the end ``s0`` of the slack stretch, and its slope (N/m) there:
    the first element that starts at s0 (its friction: μ times its vertical load,
    `LineFields.load_before`)."""
    s_l, s_r, T_l, T_r = solution.tension_profile()
    k = int(np.argmin(np.abs(s_l - solution.problem.slack_end)))
    friction_force = solution.friction * (solution.load_before(s_r[k])[-1] - solution.load_before(s_l[k])[-1])
    return float(T_l[k]), float(friction_force / (s_r[k] - s_l[k]))
