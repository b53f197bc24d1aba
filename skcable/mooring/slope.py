r"""A line between two ends over a plane sloped seabed ``y = seabed + x tan α``: the model and why.

The same choice as over a flat seabed (`skcable.mooring.geometry`), by the end that rests on
the seabed rather than the lower one (on a slope the end on the seabed may be the higher):

- an end on the slope, one uniform segment: it is the anchor of
  `skcable.cable.sloped_seabed_catenary` (Jonkman's grounded line on a slope, J.M. Jonkman,
  "Dynamics modeling and loads analysis of an offshore floating wind turbine", NREL, 2007, as
  MoorPy's ``catenary(alpha=...)``), the line seen from that end: from B, ``x' = span - x`` turns
  the slope to ``-tan α`` (``"grounded (slope)"``);
- neither end on it: the free line (``"free"``) where it clears the slope, the clearance
  ``y(s) - seabed - x(s) tan α`` sampled along the line and its least value polished by Brent's
  method (the clearance is convex along each heavy segment);
- anything else: the line BVP with the plane as its seabed (``"bvp"``).

The grounded line's end forces at A, :math:`H_A = T_A\cos\alpha`, :math:`V_A = -T_A\sin\alpha` with
:math:`T_A = \max(H/\cos\alpha - k L_B, 0)`, :math:`k = w(\sin\alpha + \mu\cos\alpha)` and
:math:`L_B = L - (V_B - H\tan\alpha)/w`, are differentiated through ``(H, V_B)``; A moves with
the seabed (`skcable.mooring.geometry`).
"""

from __future__ import annotations

from functools import partial

import numpy as np

from skcable.cable.seabed import sloped_seabed_catenary
from skcable.errors import InputError
from skcable.mooring.jacobians import of_free, of_sloped
from skcable.mooring.plane import PlaneLine, on_seabed_tolerance, uniform

__all__ = ["clearance", "solve_on_slope"]


def clearance(solution, floor, slope) -> float:
    """The least height (m) of the line ``solution`` (from its lower end) above the plane
    ``y = floor + x slope``: sampled, then polished by Brent's method around the least sample."""
    from scipy.optimize import minimize_scalar

    L = float(solution.length)
    s = np.linspace(0.0, L, 257)

    def gap(t):
        return float(solution.y_of_s(t)) - floor - slope * float(solution.x_of_s(t))

    values = np.asarray(solution.y_of_s(s)) - floor - slope * np.asarray(solution.x_of_s(s))
    i = int(np.argmin(values))
    lo, hi = s[max(i - 1, 0)], s[min(i + 1, len(s) - 1)]
    best = minimize_scalar(gap, bounds=(lo, hi), method="bounded", options={"xatol": 1e-10 * L})
    return min(float(values[i]), float(best.fun))


def _free_clear(line, scene, start, tol):
    """The free line, if it clears the slope (else None)."""
    span, dh, seabed, slope = scene
    reverse = dh < 0
    variant = line.variant(reverse=reverse)
    previous = start.solution if start is not None and start.key == ("free", reverse) else None
    solution = (
        variant.solve(span, abs(dh)) if previous is None else variant.solve(span, abs(dh), start=previous)
    )
    floor, m = (seabed - dh + span * slope, -slope) if reverse else (seabed, slope)
    if clearance(solution, floor, m) < -tol:
        return None
    reason = "neither end on the sloped seabed and the line clear of it"
    return PlaneLine(
        span,
        dh,
        seabed,
        solution,
        reverse,
        "free",
        reason,
        ("free", reverse),
        partial(of_free, solution),
        variant,
        slope,
    )


def solve_on_slope(line, scene, on_A, on_B, start, bvp) -> PlaneLine:
    """`skcable.mooring.geometry.solve_in_plane` over a sloped seabed (module docstring)."""
    span, dh, seabed, slope = scene
    tol = on_seabed_tolerance(span, dh, seabed)
    if on_A and on_B:
        raise InputError(
            "seabed_slope", "both ends on the sloped seabed: a line lying along a slope is not solved"
        )
    if not (on_A or on_B):
        free = _free_clear(line, scene, start, tol)
        if free is not None:
            return free
        return bvp(
            line,
            span,
            dh,
            seabed,
            "the line touches down on the slope between its ends (no closed form)",
            slope,
        )
    reverse = on_B
    variant = line.variant(reverse=reverse)
    if not uniform(variant):
        return bvp(line, span, dh, seabed, "an end on the sloped seabed and not one uniform segment", slope)
    seg = variant.segments[0]
    span_o, dh_o, slope_o = (span, -dh, -slope) if reverse else (span, dh, slope)
    solution = sloped_seabed_catenary(
        span_o, dh_o, seg.w, seg.EA, length=seg.length, seabed_slope=slope_o, friction=line.friction
    )
    if solution.free is not None:
        reason = "an end on the sloped seabed and the line leaving it upwards: it hangs free"
        return PlaneLine(
            span,
            dh,
            seabed,
            solution,
            reverse,
            "free",
            reason,
            ("slope",),
            partial(of_free, solution),
            variant,
            slope,
        )
    reason = "an end on the sloped seabed: the line rests on the slope up to a touchdown (closed form)"
    return PlaneLine(
        span,
        dh,
        seabed,
        solution,
        reverse,
        "grounded (slope)",
        reason,
        ("slope",),
        partial(of_sloped, solution),
        variant,
        slope,
    )
