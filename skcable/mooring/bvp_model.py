r"""A `skcable.mooring.Line` solved by the line BVP where no closed form holds, as a line solution.

`skcable.mooring.solve_line_bvp` (finite elements on scikit-fem with unilateral seabed contact
and Coulomb friction) takes any line: several segments, buoyant ones (``w < 0``), clump
weights and buoys at the joints, touchdowns anywhere. It is called through its public
signature only, on the line as seen from its lower end (`Line.variant`): the segments'
``(length, w, EA)``, the attachments between the ends as point loads at their joints' arc
lengths, the seabed's height relative to the lower end and the friction. An attachment at an
end joint is carried by the support there and added to its vertical force, as in
`skcable.mooring.Line`. The mesh is the one the line needs (``n_elements="auto"``,
`skcable.mooring.line_bvp.resolution`); the reason says where that is more than the first, and a
line still unresolved on the most warns.

`BVPLineView` gives the solution the line-solution protocol (`skcable.results`, and the
``x_of_s``, ``y_of_s``, ``T_of_s``, ``tensions()`` a system reads). Its stiffness is taken by
central differences of re-solved lines (steps of `STEP` times the chord, each solve to its
``rtol`` of 1e-10: the differences are good to about 1e-6 relative), the only stiffness of a
mooring system not in closed form; `skcable.mooring.choice` reports ``model="bvp"``
with the reason no closed form holds.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import partial

import numpy as np

from skcable import _plausible
from skcable.errors import InputError
from skcable.mooring.jacobians import of_own
from skcable.mooring.line_bvp.check import warn_unresolved
from skcable.mooring.line_bvp.resolution import AUTO, FIRST
from skcable.mooring.plane_line import PlaneLine, on_seabed_tolerance
from skcable.mooring.segments.solution import segment_table

__all__ = ["BVPLineView", "Resolver", "solve_bvp_line"]

#: Central-difference step of the BVP line's stiffness, relative to the chord.
STEP = 1e-4


class BVPLineView:
    """A `LineBVPSolution` of a `skcable.mooring.Line` (from its lower end) with the protocol of a line
    solution: end forces with the end attachments, ``x_of_s, y_of_s, T_of_s``, ``tensions()``."""

    def __init__(self, line, solution, resolve):
        self.line, self.bvp, self._resolve = line, solution, resolve
        P_A, P_B = line.arrays.P_end
        self.span, self.dh, self.length = float(solution.span), float(solution.dh), float(solution.length)
        self.H = self.H_B = float(solution.H)
        self.H_A = float(solution.H_A)
        self.V_A, self.V_B = float(solution.V_A) + P_A, float(solution.V_B) + P_B
        self.T_A, self.T_B = math.hypot(self.H_A, self.V_A), math.hypot(self.H, self.V_B)
        self.length_on_seabed = float(solution.length_on_seabed)
        self.x_touchdown = float(solution.x_touchdown)
        self.s_landing = float(solution.s_landing)
        self.heap = False

    def xy(self, s):
        return self.bvp.xy(s)

    def x_of_s(self, s):
        return self.bvp.xy(s)[..., 0]

    def y_of_s(self, s):
        return self.bvp.xy(s)[..., 1]

    def T_of_s(self, s):
        return self.bvp.tension(s)

    def profile(self, n: int = 201):
        return np.asarray(self.xy(np.linspace(0.0, self.length, n)))

    def lowest_height(self) -> float:
        return float(self.profile(401)[:, 1].min())

    def stiffness(self) -> np.ndarray:
        """``∂(H, V_B)/∂(span, dh)`` (A fixed), by central differences of re-solved lines."""
        return self.jacobian()[2:, [0, 2]]

    def jacobian(self) -> np.ndarray:
        """``∂(H_A, V_A, H_B, V_B)/∂(span, y_A, y_B)`` with the seabed fixed (an anchor on the
        seabed moves with it), by central differences (module docstring)."""
        if not hasattr(self, "_jacobian"):
            h = STEP * math.hypot(self.span, self.dh)
            columns = []
            for step in ((h, 0.0, 0.0), (0.0, h, 0.0), (0.0, 0.0, h)):
                up, down = self._resolve(*step), self._resolve(*(-v for v in step))
                columns.append([(u - d) / (2.0 * h) for u, d in zip(up, down, strict=True)])
            self._jacobian = np.array(columns).T
        return self._jacobian

    def tensions(self):
        """One row per segment: ``segment, length, w, EA, T_lower, T_upper, T_max`` (SI); ``T_max``
        the largest tension on the segment's elements."""
        arrays = self.line.arrays
        s0, s1 = arrays.s_joint[:-1], arrays.s_joint[1:]
        inset = 1e-9 * self.length
        T_low, T_up = self.T_of_s(s0 + inset), self.T_of_s(s1 - inset)
        T_max = [
            float(np.max(self.T_of_s(np.linspace(a + inset, b - inset, 64))))
            for a, b in zip(s0, s1, strict=True)
        ]
        return segment_table(arrays.L, arrays.w, arrays.EA, T_low, T_up, T_max=T_max)

    def __repr__(self):
        return f"BVPLineView({self.bvp!r})"


def _bvp_arguments(variant, seabed):
    arrays = variant.arrays
    segments = [
        (float(L), float(w), float(EA)) for L, w, EA in zip(arrays.L, arrays.w, arrays.EA, strict=True)
    ]
    loads = [(float(arrays.s_joint[j]), float(arrays.P[j])) for j in range(1, arrays.n) if arrays.P[j] != 0]
    friction = variant.friction if seabed is not None else 0.0
    return segments, loads, friction


def _options(seabed, seabed_slope, friction, loads) -> dict:
    return dict(seabed=seabed, seabed_slope=seabed_slope, friction=friction, point_loads=loads)


def _plane_seabed(low, slope, d_low, d_span=0.0):
    """The BVP's seabed relative to the lower end after it moves up by ``d_low``: None, 0 (the
    end on it, moving with it), a height, or a height and a slope (`solve_line_bvp`'s straight
    seabed)."""
    if low is None or low == 0.0 and slope == 0.0:
        return low, None
    if slope == 0.0:
        return low - d_low, None
    return (0.0 if low == 0.0 else low - d_low), slope


@dataclass(frozen=True)
class Resolver:
    """The line (as seen from its lower end) re-solved by `skcable.mooring.solve_line_bvp` with its
    span and its ends' heights moved (m): `solve` gives the solution, a call ``(H_A, V_A, H_B, V_B)``
    (N, the end attachments added)."""

    span: float
    height: float
    low: float | None
    slope: float
    segments: list
    loads: list
    friction: float
    P_end: tuple
    #: elements of every solve: the ones the first needs (``"auto"``), then that number
    n_elements: int | str = AUTO

    def solve(self, d_span=0.0, d_low=0.0, d_high=0.0):
        from skcable.mooring import solve_line_bvp

        bed, bed_slope = _plane_seabed(self.low, self.slope, d_low)
        end = self.height + d_high - d_low  # an end on the seabed moves with it (the seabed stays at 0)
        options = _options(bed, bed_slope, self.friction, self.loads)
        options["n_elements"] = self.n_elements
        with _plausible.quiet():  # its mesh is the library's, not the caller's: no ResolutionWarning
            return solve_line_bvp(self.span + d_span, end, self.segments, **options)

    def __call__(self, d_span, d_low, d_high):
        r = self.solve(d_span, d_low, d_high)
        P_A, P_B = self.P_end
        return float(r.H_A), float(r.V_A) + P_A, float(r.H), float(r.V_B) + P_B


def solve_bvp_line(line, span, dh, seabed, reason, slope=0.0):
    """``line`` (segments from A) between A = (0, 0) and B = (span, dh) over the seabed
    ``y = seabed + x slope`` (relative to A, or None) by `skcable.mooring.solve_line_bvp`, from the
    end that rests on the seabed (else the lower); a
    `skcable.mooring.plane_line.PlaneLine` with ``model="bvp"`` and ``reason``."""
    tol = on_seabed_tolerance(span, dh, 0.0 if seabed is None else seabed)
    on_A = seabed is not None and -seabed <= tol
    on_B = seabed is not None and dh - seabed - span * slope <= tol
    reverse = (on_B and not on_A) or (not (on_A or on_B) and dh < 0)
    height = -dh if reverse else dh
    slope_o = -slope if reverse else slope
    low = None if seabed is None else (seabed - dh + span * slope if reverse else seabed)
    if low is not None and -low <= tol:
        low = 0.0
    variant = line.variant(reverse=reverse, contact=low == 0.0)
    if low is not None and low < 0 and line.friction > 0:
        raise InputError(
            "friction",
            "the line touches down between its ends (neither rests on the seabed): static friction there "
            "depends on the history of the motion; give the line friction=0",
        )
    segments, loads, friction = _bvp_arguments(variant, low)

    P_end = tuple(float(p) for p in variant.arrays.P_end)
    resolver = Resolver(float(span), float(height), low, float(slope_o), segments, loads, friction, P_end)
    first = resolver.solve()
    resolver = replace(resolver, n_elements=first.n_elements)  # the stiffness's solves on its mesh
    if first.n_elements > FIRST:
        reason = f"{reason}; on {first.n_elements} elements ({FIRST} did not resolve it)"
    warn_unresolved(first, stacklevel=6)  # too coarse on `MOST` still: line_in_plane's caller named
    solution = BVPLineView(variant, first, resolver)
    key = ("bvp", reverse)
    return PlaneLine(
        span, dh, seabed, solution, reverse, "bvp", reason, key, partial(of_own, solution), variant, slope
    )
