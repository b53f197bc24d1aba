"""The parts of a mooring line: uniform segments, and clump weights and buoys at its joints.

Joint ``j`` lies between segments ``j-1`` and ``j``; joint 0 is the anchor A, joint ``n``
the fairlead B of a line of ``n`` segments. A point force at a joint is downward
positive: a clump weight ``W`` in water, a buoy ``-B`` (its net buoyancy).
"""

from __future__ import annotations

import numpy as np

from skcable import _plausible
from skcable._checks import positive, real, scalar
from skcable.errors import InputError

__all__ = ["Buoy", "ClumpWeight", "Segment", "joint_index"]


class Segment:
    """A uniform segment of a mooring line.

    Parameters
    ----------
    length : float
        Unstretched length (m), > 0.
    w : float
        Weight in water per unstretched length (N/m), not zero: negative for a segment
        lighter than water (a buoyancy section of a lazy-wave line, a synthetic rope that
        floats), which rises where it hangs free.
    EA : float
        Axial stiffness (N), > 0.
    mbl : float, optional
        Minimum breaking load (N), > 0: the strength the line checks compare its largest
        tension with (`skcable.cable.lines.checks`); from a component of the library
        (`skcable.cable.lines.library`) or the maker's data.
    diameter : float, optional
        Volume-equivalent diameter (m), > 0: the diameter of the cylinder that displaces as much
        water per length (MoorDyn's ``Diam``; written to MoorDyn files). The statics use ``w``.
    """

    __slots__ = ("length", "w", "EA", "mbl", "diameter")

    def __init__(self, length, w, EA, *, mbl=None, diameter=None):
        self.length = scalar("length", positive("length", length))
        self.w = scalar("w", real("w", w))
        if self.w == 0.0:
            raise InputError(
                "w", "must not be 0: a weightless segment has no catenary (give its weight in water)"
            )
        self.EA = scalar("EA", positive("EA", EA))
        self.mbl = None if mbl is None else scalar("mbl", positive("mbl", mbl))
        self.diameter = None if diameter is None else scalar("diameter", positive("diameter", diameter))
        _plausible.stiffness(self.EA, abs(self.w), self.length)

    def __repr__(self):
        extra = "" if self.mbl is None else f", mbl={self.mbl!r}"
        extra += "" if self.diameter is None else f", diameter={self.diameter!r}"
        return f"Segment(length={self.length!r}, w={self.w!r}, EA={self.EA!r}{extra})"


class ClumpWeight:
    """A clump weight at ``joint`` (0 = anchor, n = fairlead): a downward force ``weight`` (N, > 0)
    in water."""

    __slots__ = ("joint", "weight")

    def __init__(self, joint, weight):
        self.joint = joint_index(joint)
        self.weight = scalar("weight", positive("weight", weight))

    @property
    def force(self):
        """Downward force on the joint (N)."""
        return self.weight

    def __repr__(self):
        return f"ClumpWeight(joint={self.joint}, weight={self.weight!r})"


class Buoy:
    """A buoy at ``joint`` (0 = anchor, n = fairlead): a net upward force ``buoyancy`` (N, > 0)."""

    __slots__ = ("joint", "buoyancy")

    def __init__(self, joint, buoyancy):
        self.joint = joint_index(joint)
        self.buoyancy = scalar("buoyancy", positive("buoyancy", buoyancy))

    @property
    def force(self):
        """Downward force on the joint (N), negative."""
        return -self.buoyancy

    def __repr__(self):
        return f"Buoy(joint={self.joint}, buoyancy={self.buoyancy!r})"


def joint_index(joint):
    """``joint`` as a joint number (an integer >= 0), or `InputError` naming ``joint``."""
    if isinstance(joint, (bool, np.bool_)) or not isinstance(joint, (int, np.integer)):
        raise InputError("joint", f"must be an integer joint index, got {joint!r}")
    if joint < 0:
        raise InputError("joint", f"must be >= 0 (0 is the anchor), got {joint}")
    return int(joint)
