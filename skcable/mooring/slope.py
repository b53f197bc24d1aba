r"""A line on a plane sloped seabed: the closed form on the slope as a line model, and the clearance.

Jonkman's grounded line on a slope (J.M. Jonkman, "Dynamics modeling and loads analysis of an
offshore floating wind turbine", NREL, 2007, as MoorPy's ``catenary(alpha=...)``) is
`skcable.cable.sloped_seabed_catenary`; `SlopeModel` gives it the line-model protocol
(``solve(span, dh)``, `skcable.mooring.line3d`) for a one-segment `skcable.mooring.Line` anchored
on a `skcable.mooring.bathymetry.Plane` that slopes along the line, and `clearance` the least
height of a free line above a slope (sampled, then polished by Brent's method: the clearance is
convex along each heavy segment). Which model a line on a slope takes, and why, is
`skcable.mooring.choice`'s.

The grounded line's end forces at A, :math:`H_A = T_A\cos\alpha`, :math:`V_A = -T_A\sin\alpha` with
:math:`T_A = \max(H/\cos\alpha - k L_B, 0)`, :math:`k = w(\sin\alpha + \mu\cos\alpha)` and
:math:`L_B = L - (V_B - H\tan\alpha)/w`, are differentiated through ``(H, V_B)``
(`skcable.mooring.jacobians.of_sloped`); A moves with the seabed.
"""

from __future__ import annotations

import numpy as np

from skcable._show import Shown
from skcable.cable.seabed import sloped_seabed_catenary

__all__ = ["SlopeModel", "SlopeSolution", "clearance"]


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


class SlopeModel:
    """A one-segment `Line` on a plane slope along it, as a line model: ``solve(span, dh)`` is
    `skcable.cable.sloped_seabed_catenary` (``seabed_slope`` the slope along the line, -)."""

    def __init__(self, line, seabed_slope: float):
        self.line, self.seabed_slope = line, float(seabed_slope)

    def solve(self, span, dh):
        seg = self.line.segments[0]
        solved = sloped_seabed_catenary(
            span, dh, seg.w, seg.EA, length=seg.length, seabed_slope=self.seabed_slope,
            friction=self.line.friction,
        )  # fmt: skip
        return SlopeSolution(solved)


class SlopeSolution(Shown):
    """A `SlopedSeabedCatenary` with the 2-D solution's ``x_of_s``, ``y_of_s`` of a line model."""

    def __init__(self, solved):
        self.solved = solved
        for name in ("H", "H_A", "V_A", "V_B", "length", "length_on_seabed", "x_touchdown"):
            setattr(self, name, getattr(solved, name))

    def x_of_s(self, s):
        return self.solved.xy(s)[..., 0]

    def y_of_s(self, s):
        return self.solved.xy(s)[..., 1]

    def T_of_s(self, s):
        return self.solved.T_of_s(s)

    def stiffness(self):
        return self.solved.stiffness()

    def tensions(self):
        return self.solved.tensions()

    def residual(self) -> float:
        return float(self.solved.residual())
