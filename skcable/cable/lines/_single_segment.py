"""A one-segment line model for the 3-D layer, until the multi-segment ``cable.Line`` lands.

TEMPORARY ADAPTER, to be replaced by ``cable.Line(segments=[cable.Segment(length, w, EA)],
seabed=..., friction=...)`` at merge: it implements the line-model protocol the 3-D
layer (`skcable.cable.lines.line3d`) relies on, "a line model is any object with
``solve(span, dh)`` returning a solution with ``H, V_A, V_B, H_A, length,
length_on_seabed, x_touchdown, x_of_s, y_of_s, T_of_s, stiffness(), tensions()``",
by calling `skcable.cable.elastic_catenary` (J.M. Jonkman, "Dynamics modeling and
loads analysis of an offshore floating wind turbine", NREL, 2007).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from skcable._checks import nonnegative, positive, real, require, scalar
from skcable.cable.lines.seabed import elastic_catenary

__all__ = ["_SingleSegment"]


class _SingleSegmentSolution:
    """A solved one-segment line: the 2-D solution's attributes, plus ``tensions()``."""

    __slots__ = ("_solution",)

    def __init__(self, solution):
        self._solution = solution

    def __getattr__(self, name):
        solution = self._solution
        if not hasattr(solution, "H_A"):  # Irvine's free catenary, no seabed: nothing grounded
            if name == "H_A":
                return solution.H
            if name in ("length_on_seabed", "x_touchdown"):
                return 0.0
            if name == "T_of_s":
                return lambda s: np.hypot(solution.H, solution.w * np.asarray(s, dtype=float) - solution.V_A)
        return getattr(solution, name)

    def tensions(self) -> pd.DataFrame:
        """One row per segment (here one): its unstretched length (m), its weight per
        unstretched length (N/m), the tensions at its lower and upper ends (N) and the largest."""
        s = self._solution
        T_low, T_high = float(self.T_of_s(0.0)), float(self.T_of_s(s.length))
        return pd.DataFrame(
            {
                "segment": [0],
                "length": [float(s.length)],
                "w": [float(s.w)],
                "EA": [float(s.EA)],
                "T_bottom": [T_low],
                "T_top": [T_high],
                "T_max": [max(T_low, T_high)],
            }
        )


class _SingleSegment:
    """One uniform elastic segment from the anchor A to the fairlead B (temporary, see module).

    Parameters
    ----------
    length : float
        Unstretched length (m), > 0.
    w : float
        Weight in water per unstretched length (N/m), > 0.
    EA : float
        Axial stiffness (N), > 0.
    seabed : float or None
        Height of a flat seabed relative to A (m), <= 0; None: no seabed.
    friction : float
        Coulomb friction coefficient on the seabed, >= 0.
    """

    def __init__(self, length, w, EA, seabed=None, friction=0.0):
        self.length = scalar("length", positive("length", length))
        self.w = scalar("w", positive("w", w))
        self.EA = scalar("EA", positive("EA", EA))
        if seabed is not None:
            seabed = scalar("seabed", real("seabed", seabed))
            require("seabed", seabed <= 0, "must be at or below the anchor (A at height 0)", seabed)
        self.seabed = seabed
        self.friction = scalar("friction", nonnegative("friction", friction))

    def solve(self, span, dh):
        """The line from A = (0, 0) to B = (span, dh) (m): `elastic_catenary` with this line's data."""
        solution = elastic_catenary(
            span, dh, self.w, self.EA, length=self.length, seabed=self.seabed, friction=self.friction
        )
        if np.ndim(solution.H) != 0:
            raise ValueError("one scene at a time")  # pragma: no cover - span and dh are scalars here
        return _SingleSegmentSolution(solution)

    def __repr__(self):
        return (
            f"_SingleSegment(length={self.length!r}, w={self.w!r}, EA={self.EA!r}, "
            f"seabed={self.seabed!r}, friction={self.friction!r})"
        )
