r"""A line lying on a flat seabed between two ends resting on it: straight and taut, or slack.

With both ends on the seabed the seabed carries the whole weight and the line lies straight
between them. Its segments stretch under one tension ``T`` (no friction acts: the line is not
dragged along the seabed, and static friction between two fixed ends depends on the history
of the motion), so the span is :math:`\sum_i L_i (1 + T/EA_i)`:

.. math:: T = \frac{\mathrm{span} - L}{\sum_i L_i/EA_i} \quad (\mathrm{span} > L), \qquad T = 0
    \quad\text{otherwise (the slack lies on the seabed: its shape is not determined by statics,
    the maps spread it evenly along the span)}.

An attachment at an end joint is carried by the support there (as in `skcable.mooring.Line`):
``V_A = P_0``, ``V_B = P_n``; clump weights between the ends rest on the seabed. A buoy or a
buoyant segment would lift the line off the seabed: refused (`InputError`, the caller then
takes the line BVP).
"""

from __future__ import annotations

import math

import numpy as np

from skcable._checks import real, require
from skcable.errors import InputError
from skcable.mooring.segments.solution import segment_table
from skcable.results import ProfileMixin

__all__ = ["LyingLine", "lying_line"]


class LyingLine(ProfileMixin):
    """A line lying straight on the seabed from A = (0, 0) to B = (span, 0) (module docstring).

    Attributes
    ----------
    H, H_A, H_B : float
        The tension ``T`` (N), horizontal everywhere.
    V_A, V_B : float
        The attachments at the end joints (N), carried by the supports.
    heap : bool
        Whether the line is slack (``T = 0``).
    length, length_on_seabed : float
        Its unstretched length (m), all of it on the seabed.
    """

    def __init__(self, line, span, T):
        self.line, self.span, self.dh = line, span, 0.0
        arrays = line.arrays
        self.length = self.length_on_seabed = arrays.total_length
        self.H = self.H_A = self.H_B = T
        self.V_A, self.V_B = arrays.P_end
        self.T_A, self.T_B = math.hypot(T, self.V_A), math.hypot(T, self.V_B)
        self.heap = T == 0.0
        self.x_touchdown, self.x_landing = span, 0.0
        self._x_joint = (
            arrays.s_joint * (span / self.length)
            if self.heap
            else arrays.s_joint + T * np.concatenate([[0.0], np.cumsum(arrays.L / arrays.EA)])
        )

    def _arc(self, s):
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def x_of_s(self, s):
        """Abscissa (m) of the material point at unstretched arc length ``s`` from A."""
        return np.interp(self._arc(s), self.line.arrays.s_joint, self._x_joint)[()]

    def y_of_s(self, s):
        """Height (m): 0, the seabed's."""
        return 0.0 * self._arc(s)

    def T_of_s(self, s):
        """Tension (N): ``T`` all along."""
        return self.H + 0.0 * self._arc(s)

    def xy(self, s):
        return np.stack(np.broadcast_arrays(self.x_of_s(s), self.y_of_s(s)), axis=-1)

    def lowest_height(self) -> float:
        return 0.0

    def stiffness(self):
        """Not defined: its ends rest on the seabed and cannot move vertically (raises `InputError`)."""
        raise InputError(
            "dh",
            "a line lying on the seabed between two ends resting on it has no vertical stiffness (its ends "
            "cannot move into the seabed, and lifted they take an infinite initial stiffness)",
        )

    def jacobian(self):
        return self.stiffness()

    def tensions(self):
        """One row per segment: ``segment, length, w, EA, T_lower, T_upper, H_upper,
        stretched_length, grounded_length`` (SI), as `skcable.mooring.LineSolution.tensions`."""
        arrays = self.line.arrays
        T = np.full(arrays.n, self.H)
        return segment_table(
            arrays.L, arrays.w, arrays.EA, T, T,
            H_upper=T, stretched_length=np.diff(self._x_joint), grounded_length=arrays.L,
        )  # fmt: skip

    def __repr__(self):
        state = "slack" if self.heap else "taut"
        return f"LyingLine(span={self.span:g}, {state}: T={self.H:.9g}, length={self.length:.9g})"


def lying_line(line, span) -> LyingLine:
    """The line ``line`` (a `skcable.mooring.Line`, segments from A) lying on the seabed over ``span``."""
    arrays = line.arrays
    if (arrays.w <= 0).any():
        raise InputError("segments", "a buoyant segment would lift the line off the seabed")
    if (arrays.P[1:-1] < 0).any():
        raise InputError("attachments", "a buoy between the ends would lift the line off the seabed")
    compliance = float(np.sum(arrays.L / arrays.EA))
    T = max(span - arrays.total_length, 0.0) / compliance
    return LyingLine(line, span, T)
