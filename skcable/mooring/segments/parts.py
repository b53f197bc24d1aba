"""The parts of a mooring line: uniform segments, and clump weights and buoys at its joints.

Joint ``j`` lies between segments ``j-1`` and ``j``; joint 0 is the anchor A, joint ``n``
the fairlead B of a line of ``n`` segments. A point force at a joint is downward
positive: a clump weight ``W`` in water, a buoy ``-B`` (its net buoyancy).
"""

from __future__ import annotations

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, one_of, positive, real, scalar
from skcable.errors import InputError
from skcable.mooring.axial import ConstantEA, StrainLaw

__all__ = ["Buoy", "ClumpWeight", "Segment", "joint_index"]


class Segment:
    """A uniform segment of a mooring line.

    Parameters
    ----------
    length : float
        Unstretched length (m), > 0.
    w : float
        Weight in water per unstretched length (N/m): negative for a segment lighter than water
        (a buoyancy section of a lazy-wave line, a synthetic rope that floats), which rises
        where it hangs free; zero for a weightless one (no gravity), which has no catenary: a
        line of weightless segments is straight between two points in space
        (`skcable.mooring.line_between`; the plane solvers refuse it, naming ``w``).
    EA : float or StrainLaw
        Axial stiffness (N), > 0, or an axial strain law ``ε(T)`` (`skcable.mooring.axial`:
        `ConstantEA`, `StrainTable`, `StrainFunction`, `StaticDynamicRope`). A law that is not
        ``ε = T/EA`` is integrated exactly along the line's closed form
        (`skcable.mooring.segments.law`) or taken at the 3-D BVP's quadrature points.
    mbl : float, optional
        Minimum breaking load (N), > 0: the strength the line checks compare its largest
        tension with (`skcable.mooring.checks`); from a component of the library
        (`skcable.mooring.library`) or the maker's data.
    diameter : float, optional
        Volume-equivalent diameter (m), > 0: the diameter of the cylinder that displaces as much
        water per length (MoorDyn's ``Diam``; written to MoorDyn files), and the hydrodynamic
        diameter of the current's drag. The statics use ``w``.
    cd_normal, cd_tangential : float, optional
        Drag coefficients normal to and along the line (-), >= 0 (Morison's
        ``½ ρ C_d d |v_n| v_n``); a positive one needs ``diameter``. Used when the line is in
        a current (`skcable.mooring.Line`'s ``current``).
    material : {"chain", "wire rope", "synthetic rope", "conductor"}, optional
        What the segment is made of: an answer that strains it beyond what that material
        survives warns (`skcable._plausible.STRAIN_LIMITS`; unknown: 50 %). The library's
        components (`skcable.mooring.library`) give it.

    Attributes
    ----------
    EA : float or StrainLaw
        As given: the stiffness (N) of a constant law (a `ConstantEA` or a `StaticDynamicRope`
        given as a law: its static ``EA``), else the nonlinear law.
    law : StrainLaw
        The axial law.
    nominal_EA : float
        The stiffness (N): ``EA`` of a constant law; of a nonlinear one its secant ``T/ε(T)`` at
        the segment's own weight ``|w| L``, for starts and scales only (never for a result).
    """

    __slots__ = (
        "length", "w", "EA", "mbl", "diameter", "cd_normal", "cd_tangential", "law", "nominal_EA", "material",
    )  # fmt: skip

    def __init__(
        self, length, w, EA, *, mbl=None, diameter=None, cd_normal=0.0, cd_tangential=0.0, material=None
    ):
        self.length = scalar("length", positive("length", length))
        self.w = scalar("w", real("w", w))
        law: StrainLaw
        if isinstance(EA, StrainLaw):
            law = EA
            if EA.kind == "constant":
                EA = float(EA.EA)  # type: ignore[attr-defined]
                self.nominal_EA = EA
            else:
                self.nominal_EA = float(law.secant_EA(np.array(abs(self.w) * self.length)))
        else:
            EA = scalar("EA", positive("EA", EA))
            law = ConstantEA(EA)
            self.nominal_EA = EA
        self.EA, self.law = EA, law
        self.mbl = None if mbl is None else scalar("mbl", positive("mbl", mbl))
        self.diameter = None if diameter is None else scalar("diameter", positive("diameter", diameter))
        self.cd_normal = scalar("cd_normal", nonnegative("cd_normal", cd_normal))
        self.cd_tangential = scalar("cd_tangential", nonnegative("cd_tangential", cd_tangential))
        if self.diameter is None and (self.cd_normal > 0 or self.cd_tangential > 0):
            raise InputError("diameter", "a segment with drag coefficients needs its diameter (m)")
        self.material = None if material is None else one_of("material", material, _plausible.MATERIALS)
        _plausible.stiffness(self.nominal_EA, abs(self.w), self.length)

    @property
    def nonlinear(self) -> bool:
        """Whether the axial law is not ``ε = T/EA``."""
        return self.law.kind != "constant"

    @property
    def drags(self) -> bool:
        """Whether a current drags this segment (a diameter and a drag coefficient > 0)."""
        return self.diameter is not None and (self.cd_normal > 0 or self.cd_tangential > 0)

    def __repr__(self):
        extra = "" if self.mbl is None else f", mbl={self.mbl!r}"
        extra += "" if self.diameter is None else f", diameter={self.diameter!r}"
        extra += "" if self.cd_normal == 0.0 else f", cd_normal={self.cd_normal!r}"
        extra += "" if self.cd_tangential == 0.0 else f", cd_tangential={self.cd_tangential!r}"
        extra += "" if self.material is None else f", material={self.material!r}"
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
