"""The scene of one line BVP, checked: segments, point loads, seabed, friction, cable terms and
the Newton options.

`LineSegment` (also named `BVPSegment`) is one segment, in the plane and in space; `scene`
checks every argument of `solve_line_bvp` (each refusal an `skcable.InputError` naming the
argument as the public API spells it) and returns a `Scene`, which the solver
(`skcable.mooring.line_bvp.driver`) takes as it is. `terms_of` checks the cable terms
(`skcable.bvp.terms`), `newton_options_of` the Newton options (`skcable.fe.NewtonOptions`, with
the line BVP's own defaults, `LINE_OPTIONS`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, positive, real, require, scalar, whole
from skcable.bvp.terms import CableTerm
from skcable.errors import InputError
from skcable.fe import NewtonOptions
from skcable.mooring.axial import ConstantEA, StrainLaw, strain_law
from skcable.mooring.line_bvp.check import refuse_slack_on_slope
from skcable.mooring.line_bvp.contact import Seabed, seabed_of

__all__ = [
    "LINE_OPTIONS",
    "BVPSegment",
    "LineSegment",
    "Scene",
    "newton_options_of",
    "magnitudes",
    "point_loads_of",
    "scene",
    "segments_of",
    "terms_of",
]

#: the line BVP's Newton defaults: ``tol`` 1e-10 of the total load, 50 iterations, backtracking on
#: the residual's max-norm, and a damped start on a slack line may crawl for 8 iterations
LINE_OPTIONS = NewtonOptions(tol=1e-10, max_iter=50, line_search="residual", stagnation_window=8)


@dataclass(frozen=True)
class LineSegment:
    """One segment of a line BVP, in the plane (`solve_line_bvp`) or in space
    (`skcable.mooring.line_bvp.space.solve_line_bvp_3d`), listed from the anchor A.

    Attributes
    ----------
    length : float
        Unstretched length (m), > 0.
    w : float or callable
        Weight in water per unstretched length (N/m, downward; negative for a buoyant segment),
        or a callable of the arc length ``s`` from A (m, over the whole line) returning it: a
        weight that varies continuously.
    EA : float, StrainLaw or None
        Axial stiffness (N), > 0 and finite; or a `skcable.mooring.axial.StrainLaw` (in space);
        ``None`` for an inextensible segment.
    diameter : float or None
        Hydrodynamic diameter (m) for a current's drag (in space); None: no drag.
    cd_normal, cd_tangential : float
        Drag coefficients normal and along the line (Morison), >= 0; a positive one needs the
        diameter.
    """

    length: float
    w: float | Callable
    EA: StrainLaw | float | None = None
    diameter: float | None = None
    cd_normal: float = 0.0
    cd_tangential: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "length", _one("length", positive("length", self.length)))
        if not callable(self.w):
            object.__setattr__(self, "w", _one("w", real("w", self.w), " (or a callable of s)"))
        if not (self.EA is None or isinstance(self.EA, StrainLaw) or callable(self.EA)):
            EA = _one("EA", positive("EA", self.EA))
            require("EA", EA < np.inf, "must be finite (None for an inextensible segment)", EA)
            object.__setattr__(self, "EA", EA)
        strain_law(self.EA)  # a callable refused by name
        for name in ("cd_normal", "cd_tangential"):
            object.__setattr__(self, name, scalar(name, nonnegative(name, getattr(self, name))))
        if self.diameter is not None:
            object.__setattr__(self, "diameter", scalar("diameter", positive("diameter", self.diameter)))
        elif self.cd_normal > 0 or self.cd_tangential > 0:
            raise InputError("diameter", "a segment with drag coefficients needs its diameter (m)")

    @property
    def law(self) -> StrainLaw | None:
        """The axial law (`skcable.mooring.axial`: `ConstantEA` for a number; None: inextensible)."""
        return strain_law(self.EA)

    @property
    def drags(self) -> bool:
        """Whether a current drags this segment."""
        return self.diameter is not None and (self.cd_normal > 0 or self.cd_tangential > 0)


#: the plane line's name of `LineSegment` (the same class)
BVPSegment = LineSegment


def _one(name: str, value, alternative: str = ""):
    """``value`` unless it is an array: a segment has one number of each (a list of EA is two)."""
    if isinstance(value, np.ndarray):
        raise InputError(name, f"one number per segment{alternative}, got an array of shape {value.shape}")
    return value


def segments_of(segments) -> list[LineSegment]:
    """The segments as a list of `LineSegment` (``(length, w[, EA[, diameter, cd_normal,
    cd_tangential]])`` tuples converted)."""
    if isinstance(segments, LineSegment):
        segments = [segments]
    try:
        items = list(segments)
    except TypeError as exc:
        raise InputError("segments", "give a list of LineSegment or (length, w, EA) tuples") from exc
    if not items:
        raise InputError("segments", "give at least one segment")
    out = []
    for item in items:
        if isinstance(item, LineSegment):
            out.append(item)
        elif isinstance(item, (tuple, list)) and 2 <= len(item) <= 6:
            out.append(LineSegment(*item))
        else:
            raise InputError(
                "segments", f"each segment is a LineSegment or (length, w[, EA, ...]), got {item!r}"
            )
    return out


def plane_segments(segments) -> list[LineSegment]:
    """`segments_of` for the plane line: a constant ``EA`` (a number; `ConstantEA` taken as its
    number) and no drag, which the plane line has no current for; anything else refused."""
    out = []
    for seg in segments_of(segments):
        if seg.drags:
            raise InputError(
                "segments",
                "the plane line BVP has no current to drag a segment: solve it with solve_line_bvp_3d",
            )
        if isinstance(seg.EA, ConstantEA):
            seg = LineSegment(seg.length, seg.w, seg.EA.EA, seg.diameter)
        elif isinstance(seg.EA, StrainLaw):
            raise InputError(
                "segments", f"the plane line BVP takes a constant EA (N), got {seg.EA!r}: a strain law "
                "is solved by solve_line_bvp_3d"
            )  # fmt: skip
        out.append(seg)
    return out


def point_loads_of(point_loads, length: float) -> list[tuple[float, float]]:
    """The point loads as ``(s, P)`` float pairs, ``0 < s < length``."""
    loads = []
    try:
        items = list(point_loads)
    except TypeError:
        raise InputError("point_loads", f"must be a sequence of (s, P) pairs, got {point_loads!r}") from None
    for item in items:
        try:
            s, P = item
        except (TypeError, ValueError) as exc:
            raise InputError("point_loads", f"each is (s, P), got {item!r}") from exc
        s, P = real("point_loads", s), real("point_loads", P)
        if np.ndim(s) or np.ndim(P):
            raise InputError("point_loads", f"each is (s, P) with two numbers, got {item!r}")
        require("point_loads", 0.0 < s < length, "s must lie strictly inside the line (0, length)", s)
        loads.append((float(s), float(P)))
    return loads


def terms_of(terms) -> tuple[CableTerm, ...]:
    """The cable terms as a tuple of `skcable.bvp.terms.CableTerm` (one term or a sequence)."""
    if isinstance(terms, CableTerm):
        return (terms,)
    try:
        items = tuple(terms)
    except TypeError:
        raise InputError(
            "terms", f"give a list of CableTerm (Buoyancy, CurrentDrag, ...), got {terms!r}"
        ) from None
    for term in items:
        if not isinstance(term, CableTerm):
            raise InputError(
                "terms",
                f"each is a CableTerm (skcable.bvp.terms: Buoyancy, WindDrag, CurrentDrag or a subclass), "
                f"got {term!r}",
            )
    return items


def newton_options_of(options=None, **given) -> NewtonOptions:
    """The Newton options of a line BVP: ``options`` (a `skcable.fe.NewtonOptions`, `LINE_OPTIONS`
    by default) updated by the keywords ``given`` that are not None (``rtol`` is ``tol``'s name
    here, as in `skcable.bvp.solve_bvp`); an unknown keyword is an `InputError` naming it, and
    so is ``line_search="energy"`` (the line BVP minimises no energy: its Newton runs on the
    residual, contact and friction rows included)."""
    rtol = given.pop("rtol", None)
    if rtol is not None:
        if given.get("tol") is not None:
            raise InputError("rtol", "give rtol or tol (the same tolerance), not both")
        given["tol"] = scalar("rtol", positive("rtol", rtol))
    elif given.get("tol") is not None:
        given["tol"] = scalar("tol", positive("tol", given["tol"]))
    out = NewtonOptions.of(LINE_OPTIONS if options is None else options, **given)
    if out.line_search == "energy":
        raise InputError(
            "line_search", "'energy' needs a potential; the line BVP minimises none: use 'residual' or 'none'"
        )
    return out


@dataclass(frozen=True)
class Scene:
    """A checked scene and the solver's options (the arguments of `solve_line_bvp`)."""

    span: float
    dh: float
    segments: list
    point_loads: list
    seabed: Seabed | None
    friction: float
    n_elements: int
    fit_touchdown: int
    options: NewtonOptions = LINE_OPTIONS
    terms: tuple = ()
    time_limit: float = 60.0

    @property
    def length(self) -> float:
        """Unstretched length of the line (m)."""
        return sum(seg.length for seg in self.segments)


def magnitudes(checked: Scene) -> dict:
    """The numbers of a checked scene by the argument names of `solve_line_bvp` (a segment's
    fields under theirs): what `skcable.cable._extreme.outsized` judges the magnitude of."""
    segs = checked.segments
    return {
        "span": checked.span,
        "dh": checked.dh,
        "length": [seg.length for seg in segs],
        "w": [seg.w for seg in segs if not callable(seg.w)],
        "EA": [seg.EA for seg in segs if seg.EA is not None],
        "friction": checked.friction,
        "point_loads": [value for load in checked.point_loads for value in load],
    }


def scene(
    span,
    dh,
    segments,
    *,
    seabed,
    seabed_slope,
    friction,
    point_loads,
    n_elements,
    fit_touchdown,
    options=LINE_OPTIONS,
    terms=(),
    time_limit=60.0,
) -> Scene:
    """Every argument of `solve_line_bvp` checked, in its order; a `Scene` (``options`` checked by
    `newton_options_of` already)."""
    span, dh = positive("span", span), real("dh", dh)
    for name, value in (("span", span), ("dh", dh)):
        if not isinstance(value, float):
            raise InputError(name, "solve_line_bvp solves one scene: give scalar span and dh")
    segs = plane_segments(segments)
    bed = seabed_of(seabed, seabed_slope, span)
    friction = nonnegative("friction", friction)
    _plausible.friction(friction)
    if not isinstance(friction, float):
        raise InputError("friction", "one coefficient for the whole line")
    if friction > 0 and bed is None:
        raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
    if bed is not None:
        ends = bed(np.array([0.0, span]))
        require("seabed", ends[0] <= 0.0, "must be at or below the anchor A = (0, 0)", ends[0])
        require("dh", dh > ends[1], "must put B above the seabed", dh)
    loads = point_loads_of(point_loads, sum(seg.length for seg in segs))
    whole("n_elements", n_elements, 1)
    whole("fit_touchdown", fit_touchdown, 0, 10)
    terms = terms_of(terms)
    time_limit = scalar("time_limit", positive("time_limit", time_limit))
    checked = Scene(
        span, dh, segs, loads, bed, friction, int(n_elements), int(fit_touchdown), options, terms, time_limit
    )
    refuse_slack_on_slope(checked)  # no equilibrium in tension: its slack heaps at the slope's foot
    return checked
