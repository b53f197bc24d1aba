"""`PlaneLine`: a line solved between its two ends in its vertical plane, the forces by end.

The result of `skcable.mooring.choice.solve_in_plane`: the 2-D solution of the line as
seen from its lower end (any solution of the result protocol, `skcable.results`), mapped to the
user's ends A and B, with the model it took and why, and the Jacobian of the end forces in the
span and the ends' heights.
"""

from __future__ import annotations

import math

import numpy as np

from skcable.errors import ConvergenceError
from skcable.mooring.segments.solution import segment_table
from skcable.results import ProfileMixin

__all__ = ["MODELS", "ON_SEABED", "PlaneLine", "on_seabed_tolerance", "uniform"]

#: The models a line between two ends may take.
MODELS = (
    "free",
    "grounded",
    "grounded (slope)",
    "touchdown between the ends",
    "touchdown on the slope",
    "on the seabed",
    "bvp",
)
#: An end within this fraction of the scene's size (span, heights, at least 1 m) lies on the seabed.
ON_SEABED = 1e-9


def on_seabed_tolerance(span, dh, seabed) -> float:
    """Height (m) within which an end lies on the seabed: `ON_SEABED` times the scene's size."""
    return ON_SEABED * max(1.0, abs(span), abs(dh), abs(seabed))


class PlaneLine(ProfileMixin):
    """A line solved between its ends A = (0, 0) and B = (span, dh) over a seabed.

    Attributes
    ----------
    span, dh, seabed : float
        B relative to A (m); the seabed's height below A relative to A (m, None without one).
    seabed_slope : float
        ``tan α`` of a plane seabed ``y = seabed + x tan α`` (0: flat).
    solution : object
        The 2-D solution of the variant solved, from the lower end (a `LineSolution`,
        `SeabedCatenary`, `LyingLine` or BVP view: the result protocol, `skcable.results`).
    solution_line : Line
        The variant solved: the line as seen from its lower end (`Line.variant`).
    reversed : bool
        Whether the solution runs from B (B is the lower end).
    model, reason : str
        Which model (one of `MODELS`) and why.
    key : tuple
        The variant solved (for warm starts: the same key takes the solution as a start).
    H_A, V_A, H_B, V_B, T_A, T_B : float
        End forces by end (N): horizontal tension, upward reaction, tension.
    """

    def __init__(self, span, dh, seabed, solution, reversed_, model, reason, key, jacobian, line, slope=0.0):
        self.span, self.dh, self.seabed, self.seabed_slope = span, dh, seabed, slope
        self.solution_line = line
        self.solution, self.reversed, self.model, self.reason = solution, reversed_, model, reason
        self.key = key
        self._jacobian = jacobian
        low = (float(solution.H_A), float(solution.V_A))
        high = (float(solution.H_B), float(solution.V_B))
        (self.H_A, self.V_A), (self.H_B, self.V_B) = (high, low) if reversed_ else (low, high)
        if not all(map(math.isfinite, (*low, *high))):
            raise ConvergenceError(f"line between two ends: non-finite end forces from the {model} model")
        self.T_A, self.T_B = math.hypot(self.H_A, self.V_A), math.hypot(self.H_B, self.V_B)

    @property
    def length(self) -> float:
        return float(self.solution.length)

    def jacobian(self) -> np.ndarray:
        """``∂(H_A, V_A, H_B, V_B)/∂(span, y_A, y_B)``, shape (4, 3), the seabed fixed (module
        docstring; an end on the seabed moves with it)."""
        J = self._jacobian()
        if self.reversed:  # the solution's A is B: swap the rows and the height columns
            J = J[[2, 3, 0, 1]][:, [0, 2, 1]]
        if not np.isfinite(J).all():
            raise ConvergenceError(f"line between two ends: non-finite stiffness from the {self.model} model")
        return J

    def stiffness(self) -> np.ndarray:
        """``∂(H_B, V_B)/∂(span, dh)`` (N/m) with A and the seabed fixed, shape (2, 2): B's rows and
        columns of `jacobian` (an end B on the seabed moves with it)."""
        return self.jacobian()[2:][:, [0, 2]]

    @property
    def length_on_seabed(self) -> float:
        """Unstretched length resting on the seabed (m)."""
        return float(self.solution.length_on_seabed)

    def s_of_solution(self, s):
        """The unstretched arc length from A of the points ``s`` of the solution (from its lower end)."""
        return self.length - np.asarray(s) if self.reversed else np.asarray(s)

    def xy(self, s):
        """Positions ``(..., 2)`` (m) relative to A at unstretched arc length ``s`` from A."""
        s = np.asarray(s, dtype=float)
        xy = np.asarray(self.solution.xy(self.s_of_solution(s)), dtype=float)
        if self.reversed:
            return np.stack([self.span - xy[..., 0], xy[..., 1] + self.dh], axis=-1)
        return xy

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A."""
        return self.solution.T_of_s(self.s_of_solution(s))

    def tensions(self):
        """One row per segment, from A to B: ``segment, length, w, EA`` (SI), ``T_lower``,
        ``T_upper`` (the tensions at its ends towards A and B, N), ``T_max`` (the largest on it:
        at an end for the closed forms, whose tension is convex in the arc length; sampled on
        the BVP's elements) and ``grounded_length`` (m)."""
        table = self.solution.tensions()
        arrays = self.solution_line.arrays
        T_low, T_up = table["T_lower"].to_numpy(float), table["T_upper"].to_numpy(float)
        T_max = table["T_max"].to_numpy(float) if "T_max" in table else np.maximum(T_low, T_up)
        if "grounded_length" in table:
            grounded = table["grounded_length"].to_numpy(float)
        else:  # the part between the landing and the touchdown, segment by segment
            start = float(
                getattr(self.solution, "length_to_seabed", getattr(self.solution, "s_landing", 0.0))
            )
            stop = start + float(self.solution.length_on_seabed)
            s0, s1 = arrays.s_joint[:-1], arrays.s_joint[1:]
            grounded = np.clip(np.minimum(s1, stop) - np.maximum(s0, start), 0.0, None)
        out = segment_table(arrays.L, arrays.w, arrays.EA, T_low, T_up, T_max=T_max, grounded_length=grounded)
        if not self.reversed:
            return out
        out = out.iloc[::-1].reset_index(drop=True)
        out["segment"] = np.arange(arrays.n)
        out["T_lower"], out["T_upper"] = T_up[::-1], T_low[::-1]
        return out

    def __repr__(self):
        return (
            f"PlaneLine(span={self.span:g}, dh={self.dh:g}, model={self.model!r}: H_A={self.H_A:.9g}, "
            f"V_A={self.V_A:.9g}, H_B={self.H_B:.9g}, V_B={self.V_B:.9g})"
        )


def uniform(variant) -> bool:
    """Whether a line is one uniform heavy segment without attachments (the one-segment closed forms)."""
    return len(variant.segments) == 1 and not variant.attachments and variant.segments[0].w > 0
