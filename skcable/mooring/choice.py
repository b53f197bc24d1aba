r"""Which model a mooring line takes in its scene, and why: the one place the choice is made.

Every solved line reports ``model`` and ``reason`` (and a line in the sea its `ModelChoice`, with
its estimated error); both are decided here. The models' solves stay in their modules
(`skcable.mooring.Line`, `skcable.cable.elastic_catenary`, `skcable.cable.sloped_seabed_catenary`,
`skcable.mooring.line_on_seabed`, `skcable.mooring.straight`, `skcable.mooring.bvp_model`,
`skcable.mooring.line_bvp.space`); this module calls them in the order below and says why.

**A `skcable.mooring.Line` in the vertical plane of its ends** (`solve_in_plane`,
`line_in_plane`): B at ``(span, dh)`` from A, the seabed the plane ``y = seabed + x tan α``
(relative to A, at or below both ends; or none). Its closed forms put the anchor at the lower
end, so over a flat seabed the line is solved from its lower end (`Line.variant` with
``reverse`` when B is lower), over a slope from the end that rests on it:

- no seabed, or the lower end above it and the free line clear of it: it hangs free
  (``"free"``; H.M. Irvine, "Cable Structures", MIT Press, 1981, segment by segment);
- the lower end on the seabed: it rests on it up to a touchdown, with Coulomb friction
  (``"grounded"``; J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore floating
  wind turbine", NREL, 2007), or its slack lies in a heap (``H = 0``), or it leaves the seabed
  upwards (``"free"``);
- the lower end above the seabed and the free line below it: one uniform segment hangs down to
  the seabed, lies on it and rises to the upper end (``"touchdown between the ends"``,
  `skcable.cable.elastic_catenary` with ``seabed < 0``; frictionless only: between two
  touchdowns static friction depends on the history of the motion);
- both ends on the seabed: the line lies on it, straight and taut or slack (``"on the
  seabed"``, `skcable.mooring.line_on_seabed`);
- on a slope, an end on it and one uniform segment: `skcable.cable.sloped_seabed_catenary` from
  that end (``"grounded (slope)"``, or ``"free"`` where it leaves the slope upwards); neither end
  on it: the free line where it clears the slope (`skcable.mooring.slope.clearance`); a
  frictionless uniform segment that touches down between them hangs, lies on it and rises
  (``"touchdown on the slope"``, `skcable.cable.seabed.touchdown_on_slope`), refused beyond the
  length the slope holds taut (its slack heaps at the slope's foot);
- anything else (several segments or attachments touching down, a buoy on the grounded part, a
  second touchdown, a line lying along a slope with a buoy): the plane line BVP (``"bvp"``,
  `skcable.mooring.bvp_model`).

**Between two points in space** (`solve_between`, `line_between`): a model with its own
``solve_between`` (`skcable.mooring.rod.Rod`) by it; a line of weightless segments straight
between its ends (``"weightless"``); ends on one vertical straight (``"vertical"``,
`skcable.mooring.straight`); any other line in the vertical plane of its ends, as above.

**In the sea** (`solve_line_in_sea`, what `skcable.mooring.line_3d` takes for a `Line`): the
cheapest model that is exact for the line, reported as a `skcable.mooring.ModelChoice`:

- ``"closed form"``: no current and a flat seabed (or none), constant ``EA``: the line in the
  vertical plane of its ends. Error: the closure's relative residual (round-off);
- ``"closed form (slope)"``: no current, one uniform heavy segment of constant ``EA`` without
  attachments, its anchor on a `skcable.mooring.bathymetry.Plane` that slopes along the line
  only. Error: the closure's relative residual;
- ``"closed form (axial laws)"``: nonlinear axial laws ``ε(T)`` on a line hanging clear of the
  seabed (`skcable.mooring.segments.law`). Error: the closure's residual;
- ``"3-D line BVP"`` (`skcable.mooring.line_bvp.space`): a current, a shaped seabed, or a nonlinear
  law on a line that rests on the seabed. Error: measured on the solution
  (`skcable.mooring.sea_line`).

**In a system** (`solved_in_sea`): a `Line` in the sea (a current, a `Bathymetry`, a nonlinear
law) that is not weightless is solved from its fixed end as a line in the sea; any other `Line`
between its two points, either end higher.
"""

from __future__ import annotations

import math
from functools import partial

import numpy as np

from skcable import _plausible
from skcable._checks import point, positive, real, scalar
from skcable.cable.seabed import elastic_catenary, sloped_seabed_catenary, touchdown_on_slope
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.bathymetry import Plane
from skcable.mooring.between_points import LineBetween, plane_of
from skcable.mooring.bvp_model import solve_bvp_line
from skcable.mooring.jacobians import of_free, of_grounded, of_own, of_sloped, touchdown_jacobian
from skcable.mooring.line_on_seabed import lying_line
from skcable.mooring.plane_line import MODELS, PlaneLine, on_seabed_tolerance, uniform
from skcable.mooring.sea_line import LineInSea, bvp_model, relative_seabed
from skcable.mooring.segments import Line
from skcable.mooring.segments.batch import batchable, solve_batch
from skcable.mooring.segments.law import GroundedLaw
from skcable.mooring.slope import SlopeModel, clearance
from skcable.mooring.straight import vertical_between, weightless_between

__all__ = [
    "BATCH", "MODELS", "PlaneLine", "batchable", "grounded_batch", "is_grounded_scene", "is_line",
    "line_between", "line_in_plane", "on_seabed_tolerance", "solve_between", "solve_in_plane",
    "solve_line_in_sea", "solve_many_between", "solve_on_slope", "solved_in_sea",
]  # fmt: skip


# -- the checks every scene in the plane needs -------------------------------------------------------
def _check_ends(span, dh, seabed, slope):
    """``(gap_A, gap_B, tol)``: the ends' heights above the seabed (m) and the on-seabed tolerance."""
    tol = on_seabed_tolerance(span, dh, seabed)
    gap_A, gap_B = -seabed, dh - seabed - span * slope
    if gap_A < -tol or gap_B < -tol:
        name, gap = ("A", gap_A) if gap_A < -tol else ("B", gap_B)
        raise InputError(
            "seabed", f"end {name} lies {-gap:.6g} m below the seabed: both ends must be on or above it"
        )
    return max(gap_A, 0.0), max(gap_B, 0.0), tol


def _warm(previous, key):
    """The previous solution as a warm start where it is of the same variant."""
    if previous is not None and previous.key == key and key[0] in ("free", "grounded"):
        return previous.solution
    return None


def _plane(scene, solution, reverse, model, reason, key, jacobian, variant) -> PlaneLine:
    span, dh, seabed, slope = scene
    return PlaneLine(span, dh, seabed, solution, reverse, model, reason, key, jacobian, variant, slope)


def refuse_weightless(line) -> None:
    """`InputError` naming ``w`` for a line with a weightless segment (``w = 0``): it has no
    catenary (`line_between` takes a line of weightless segments: straight)."""
    if any(seg.w == 0.0 for seg in line.segments):
        raise InputError(
            "w",
            "a segment of w = 0 is weightless: it has no catenary (a line of weightless segments is "
            "straight between two points: line_between)",
        )


def indeterminate_friction(line, depth):
    """`InputError` naming ``friction``: a touchdown between suspended ends with friction."""
    if line.friction > 0:
        raise InputError(
            "friction",
            f"the line touches down between its ends (the lower one {depth:.6g} m above the seabed): "
            "static friction there depends on the history of the motion; give the line friction=0",
        )


def is_line(model) -> bool:
    """Whether ``model`` is a `skcable.mooring.Line` (its model chosen here) rather than another
    line model (solved as given)."""
    return isinstance(model, Line)


# -- in the vertical plane of the ends ------------------------------------------------------------------
def solve_in_plane(line, span, dh, *, seabed=None, seabed_slope=0.0, start=None, bvp=None) -> PlaneLine:
    """`line_in_plane` on checked arguments (``span > 0``, finite floats): a `PlaneLine` with
    ``model`` and ``reason`` (module docstring). ``start``: a previous `PlaneLine` of this line, a
    warm start where the same model applies; ``bvp(line, span, dh, seabed, reason, slope)`` →
    `PlaneLine` for the scenes no closed form takes (`skcable.mooring.bvp_model.solve_bvp_line` by
    default)."""
    bvp = solve_bvp_line if bvp is None else bvp
    refuse_weightless(line)
    if seabed is None:
        return _free(line, (span, dh, None, 0.0), start, "no seabed: the line hangs free")
    slope = float(seabed_slope)
    gap_A, gap_B, tol = _check_ends(span, dh, seabed, slope)
    scene = (span, dh, seabed, slope)
    if slope != 0.0:
        return solve_on_slope(line, scene, gap_A <= tol, gap_B <= tol, start, bvp)
    reverse = dh < 0
    low, high = (gap_B, gap_A) if reverse else (gap_A, gap_B)
    if low <= tol and high <= tol:
        return _lying(line, scene, reverse, bvp)
    if low <= tol:
        return _grounded(line, scene, reverse, start, bvp)
    free = _free(line, scene, start, "the lower end above the seabed and the line clear of it")
    if free.solution.lowest_height() >= -low - tol:  # -low: the seabed in the solution's axes
        return free
    return _touchdown(line, scene, reverse, low, bvp)


def _lying(line, scene, reverse, bvp) -> PlaneLine:
    variant = line.variant(reverse=reverse)
    try:
        solution = lying_line(variant, scene[0])
    except InputError as err:
        return bvp(line, *scene[:3], f"both ends on the seabed and {err}", scene[3])
    reason = "both ends on the seabed: the line lies on it"
    key, jacobian = ("on the seabed",), partial(of_own, solution)
    return _plane(scene, solution, reverse, "on the seabed", reason, key, jacobian, variant)


def _free(line, scene, start, reason) -> PlaneLine:
    reverse = scene[1] < 0
    key = ("free", reverse)
    variant = line.variant(reverse=reverse)
    solution = variant.solve_checked(float(scene[0]), float(abs(scene[1])), _warm(start, key))
    return _plane(scene, solution, reverse, "free", reason, key, partial(of_free, solution), variant)


def _grounded(line, scene, reverse, start, bvp) -> PlaneLine:
    key = ("grounded", reverse)
    variant = line.variant(reverse=reverse, contact=True)
    try:
        solution = variant.solve_checked(float(scene[0]), float(abs(scene[1])), _warm(start, key))
    except InputError as err:
        if err.argument not in ("attachments", "segments"):
            raise
        return bvp(line, *scene[:3], f"the lower end on the seabed and {err}", scene[3])
    return _grounded_plane(scene, reverse, key, variant, solution)


def _grounded_plane(scene, reverse, key, variant, solution) -> PlaneLine:
    """The `PlaneLine` of a solution of the grounded variant: grounded, a heap, or hanging free."""
    if not solution.state.contact:
        reason = "the lower end on the seabed and the line leaving it upwards: it hangs free"
        return _plane(scene, solution, reverse, "free", reason, key, partial(of_free, solution), variant)
    reason = "the lower end on the seabed: the line rests on it up to a touchdown (Jonkman's closed form)"
    if solution.heap:
        reason = "the lower end on the seabed and the line longer than its L-shape: its slack lies in a heap"
    jacobian = partial(of_grounded, solution, variant.friction, solution.H_A)
    return _plane(scene, solution, reverse, "grounded", reason, key, jacobian, variant)


def _touchdown(line, scene, reverse, depth, bvp) -> PlaneLine:
    """The lower end ``depth`` above the seabed, the free line below it: a touchdown between the ends."""
    variant = line.variant(reverse=reverse)
    if not uniform(variant):
        reason = "the line touches down between its ends and is not one uniform segment (no closed form)"
        return bvp(line, *scene[:3], reason, scene[3])
    indeterminate_friction(line, depth)
    seg = variant.segments[0]
    solution = elastic_catenary(scene[0], abs(scene[1]), seg.w, seg.EA, length=seg.length, seabed=-depth)
    reason = "the lower end above the seabed and the line reaching it: it hangs down, rests on it and rises"
    model, key, jacobian = "touchdown between the ends", ("touchdown",), partial(touchdown_jacobian, solution)
    return _plane(scene, solution, reverse, model, reason, key, jacobian, variant)


def solve_on_slope(line, scene, on_A, on_B, start, bvp) -> PlaneLine:
    """`solve_in_plane` over a sloped seabed (module docstring), ``on_A``, ``on_B`` whether each
    end rests on it: the end on the slope is the anchor of the closed form."""
    span, dh, seabed, slope = scene
    if on_A and on_B:
        raise InputError(
            "seabed_slope", "both ends on the sloped seabed: a line lying along a slope is not solved"
        )
    if not (on_A or on_B):
        free = _free_clear(line, scene, start, on_seabed_tolerance(span, dh, seabed))
        if free is not None:
            return free
        if line.friction == 0 and uniform(line):
            return _touchdown_on_slope(line, scene, bvp)
        reason = "the line touches down on the slope between its ends (no closed form)"
        return bvp(line, *scene[:3], reason, slope)
    reverse = on_B
    variant = line.variant(reverse=reverse)
    if not uniform(variant):
        return bvp(line, *scene[:3], "an end on the sloped seabed and not one uniform segment", slope)
    seg = variant.segments[0]
    span_o, dh_o, slope_o = (span, -dh, -slope) if reverse else (span, dh, slope)
    solution = sloped_seabed_catenary(
        span_o, dh_o, seg.w, seg.EA, length=seg.length, seabed_slope=slope_o, friction=line.friction
    )
    if solution.free is not None:
        reason = "an end on the sloped seabed and the line leaving it upwards: it hangs free"
        return _plane(
            scene, solution, reverse, "free", reason, ("slope",), partial(of_free, solution), variant
        )
    reason = "an end on the sloped seabed: the line rests on the slope up to a touchdown (closed form)"
    jacobian = partial(of_sloped, solution)
    return _plane(scene, solution, reverse, "grounded (slope)", reason, ("slope",), jacobian, variant)


def _touchdown_on_slope(line, scene, bvp) -> PlaneLine:
    """One uniform frictionless segment that touches down on the slope between its ends: refused
    beyond the length the slope holds taut, else its closed form (`touchdown_on_slope`), else
    (where its continuation does not reach it) the line BVP from the same start."""
    span, dh, seabed, slope = scene
    seg = line.segments[0]
    try:
        solution = touchdown_on_slope(
            span, dh, seg.w, seg.EA, length=seg.length, seabed=seabed, seabed_slope=slope
        )
    except (ConvergenceError, InputError) as failed:  # the continuation, or a touch below its sampling
        if isinstance(failed, InputError) and failed.argument != "seabed":
            raise
        reason = f"the line touches down on the slope between its ends (its closed form: {failed})"
        return bvp(line, *scene[:3], reason, slope)
    reason = (
        "neither end on the sloped seabed and the line touching down between them: it hangs, lies on "
        "it and rises (closed form)"
    )
    key, jacobian = ("touchdown (slope)",), partial(of_own, solution)
    return _plane(
        scene, solution, False, "touchdown on the slope", reason, key, jacobian, line.variant(reverse=False)
    )


def _free_clear(line, scene, start, tol):
    """The free line where it clears the slope (`skcable.mooring.slope.clearance`), else None."""
    span, dh, seabed, slope = scene
    reverse = dh < 0
    variant = line.variant(reverse=reverse)
    solution = variant.solve(span, abs(dh), start=_warm(start, ("free", reverse)))
    floor, m = (seabed - dh + span * slope, -slope) if reverse else (seabed, slope)
    if clearance(solution, floor, m) < -tol:
        return None
    reason = "neither end on the sloped seabed and the line clear of it"
    key, jacobian = ("free", reverse), partial(of_free, solution)
    return _plane(scene, solution, reverse, "free", reason, key, jacobian, variant)


def line_in_plane(line, span, dh, *, seabed=None, seabed_slope=0.0) -> PlaneLine:
    """A `skcable.mooring.Line` from A = (0, 0) to B = (span, dh), either end higher, over a seabed.

    Parameters
    ----------
    line : Line
        Segments from A to B (buoyant ones, ``w < 0``, too), attachments, ``friction``; its own
        ``seabed`` is not used.
    span, dh : float
        B relative to A (m), ``span > 0``.
    seabed : float, optional
        The seabed's height below A, relative to A (m): ``0`` puts A on it, ``< 0`` above it;
        B is on or above it too. None: no seabed.
    seabed_slope : float
        ``tan α`` of a plane seabed ``y = seabed + x tan α`` (0: flat).

    Returns
    -------
    PlaneLine
        End forces by end (``H_A, V_A, H_B, V_B, T_A, T_B``), ``model`` and ``reason`` (module
        docstring), ``xy(s)``, ``T_of_s(s)``, ``profile(n)``, ``stiffness()`` (B moving, A fixed),
        ``jacobian()`` and ``tensions()``.

    Examples
    --------
    MoorPy's sloped mirror: one line seen from either end over a 10° slope.

    >>> import math
    >>> from skcable import mooring
    >>> line = mooring.Line([mooring.Segment(80.0, 100.0, 1e12)])
    >>> up = mooring.line_in_plane(line, 60.0, 40.0, seabed=0.0, seabed_slope=math.tan(math.radians(10)))
    >>> hB = 40.0 - 60.0 * math.tan(math.radians(10))
    >>> down = mooring.line_in_plane(line, 60.0, -40.0, seabed=-hB, seabed_slope=-math.tan(math.radians(10)))
    >>> up.model, round(up.H_B, 6) == round(down.H_A, 6), round(up.V_A, 6) == round(down.V_B, 6)
    ('grounded (slope)', True, True)
    """
    if not is_line(line):
        raise InputError("line", f"must be a mooring.Line, got {type(line).__name__}")
    span = scalar("span", positive("span", span))
    dh = scalar("dh", real("dh", dh))
    seabed = None if seabed is None else scalar("seabed", real("seabed", seabed))
    slope = scalar("seabed_slope", real("seabed_slope", seabed_slope))
    if seabed is None and slope != 0.0:
        raise InputError("seabed_slope", "applies to a seabed: give seabed= as well")
    return solve_in_plane(line, span, dh, seabed=seabed, seabed_slope=slope)


# -- the grounded lines of one model, solved together ----------------------------------------------------
#: Lines of one model a system solves together (`solve_many_between`) from this many: below it,
#: a Python-float Newton per line is faster than one on arrays (`benchmarks/bench_line_batch.py`).
BATCH = 32


def is_grounded_scene(span, dh, seabed, start) -> bool:
    """Whether `grounded_batch` takes the scene: A on the flat seabed, B above it, and the
    previous solution ``start`` of that model with ``H > 0`` (not a heap)."""
    if start is None or start.key != ("grounded", False) or not start.solution.H > 0 or dh < 0:
        return False
    try:  # the choice of `solve_in_plane`: the lower end A on the seabed, B above it
        gap_A, gap_B, tol = _check_ends(span, dh, seabed, 0.0)
    except InputError:  # an end below the seabed: `solve_in_plane` refuses it by name
        return False
    return gap_A <= tol < gap_B


def grounded_batch(line, scenes, starts) -> list:
    """Scenes ``(span, dh, seabed)`` of ``line`` with A on the flat seabed and B above it
    (`is_grounded_scene`), each from its previous `PlaneLine` of that model, solved together
    (`skcable.mooring.segments.batch`, for a `batchable` line): a `PlaneLine` per scene as
    `solve_in_plane` gives it, or None where the scene is left to `solve_in_plane`."""
    key = ("grounded", False)
    variant = line.variant(contact=True)
    solutions = solve_batch(
        variant, [s[0] for s in scenes], [s[1] for s in scenes], [p.solution for p in starts]
    )
    return [
        None if sol is None else _grounded_plane((*scene, 0.0), False, key, variant, sol)
        for scene, sol in zip(scenes, solutions, strict=True)
    ]


def solve_many_between(line, ends, depth, starts) -> list:
    """Lines of one model ``line`` with their ends ``ends`` (pairs of checked float 3-vectors
    ``(a, b)``) over the flat seabed ``z = -depth``, warm-started from ``starts`` (their
    `LineBetween` solutions elsewhere): those whose anchor end a rests on the seabed with b above
    it are solved together where there are `BATCH` of them and the model is one segment
    (`grounded_batch`); a `LineBetween` per line, or None for the caller's `solve_between`."""
    out: list = [None] * len(ends)
    if depth is None or len(ends) < BATCH or not batchable(line):
        return out
    picked, scenes, previous, geometry = [], [], [], []
    for i, ((a, b), start) in enumerate(zip(ends, starts, strict=True)):
        plane, previous_plane = plane_of(a, b), getattr(start, "plane", None)
        if plane is None:  # left to `solve_between`, which refuses it by name
            continue
        r, dz, az, e = plane
        if is_grounded_scene(r, dz, -depth - az, previous_plane):
            picked.append(i)
            scenes.append((r, dz, -depth - az))
            previous.append(previous_plane)
            geometry.append((a, b, r, e))
    if len(picked) < BATCH:
        return out
    for i, solved, (a, b, r, e) in zip(picked, grounded_batch(line, scenes, previous), geometry, strict=True):
        if solved is not None:
            out[i] = LineBetween(line, a, b, solved, r, e)
    return out


# -- between two points in space ----------------------------------------------------------------------
def solve_between(line, a, b, depth, start=None, bvp=None):
    """`line_between` on checked float 3-vectors (module docstring): a `LineBetween`, a
    `skcable.mooring.straight.VerticalBetween`, or what a model's own ``solve_between`` gives."""
    if not is_line(line):
        return line.solve_between(a, b, depth, start)
    if all(seg.w == 0.0 for seg in line.segments):  # no gravity: straight between its ends
        solved = weightless_between(line, a, b)
        solved.model, solved.reason = "weightless", "weightless (w = 0): straight between its ends"
        return solved
    plane = plane_of(a, b)
    if plane is None:  # its ends on one vertical: it hangs straight
        solved = vertical_between(line, a, b, depth)
        solved.model, solved.reason = (
            "vertical",
            f"its ends share a vertical: it hangs straight ({solved.state})",
        )
        return solved
    r, dz, az, e = plane
    seabed = None if depth is None else -depth - az
    previous = None if start is None else start.plane
    return LineBetween(line, a, b, solve_in_plane(line, r, dz, seabed=seabed, start=previous, bvp=bvp), r, e)


def line_between(line, a, b, *, depth=None, start=None) -> LineBetween:
    """Solve a `skcable.mooring.Line` between the points ``a`` and ``b`` over a flat seabed.

    Parameters
    ----------
    line : Line
        Segments from a to b; its ``friction`` acts on the seabed, its own ``seabed`` is not used.
    a, b : array_like, shape (3,)
        The ends (m), z up, either one higher, on or above the seabed, not on one vertical.
    depth : float, optional
        Water depth (m): the seabed is the plane ``z = -depth``; None: no seabed.
    start : LineBetween, optional
        An earlier solution of this line: its 2-D solution starts Newton's method where the
        same model applies (the same solution to round-off).

    Returns
    -------
    LineBetween
        ``end_forces``, the 6 × 6 ``stiffness()``, ``model`` and ``reason``.

    Examples
    --------
    >>> from skcable import mooring
    >>> chain = mooring.Line([mooring.Segment(120.0, 2500.0, 1.2e9)])
    >>> one = mooring.line_between(chain, [0, 0, -60], [100, 10, -30], depth=60.0)
    >>> other = mooring.line_between(chain, [100, 10, -30], [0, 0, -60], depth=60.0)
    >>> one.model, bool(abs(one.end_forces - other.end_forces[::-1]).max() < 1e-9)
    ('grounded', True)
    """
    if not is_line(line):
        raise InputError(
            "line", f"must be a mooring.Line, got {type(line).__name__} (use line_3d for other models)"
        )
    a, b = point("a", a), point("b", b)
    if depth is not None:
        depth = scalar("depth", positive("depth", depth))
    if start is not None and not isinstance(start, LineBetween):
        raise InputError("start", f"must be a LineBetween of this line, got {type(start).__name__}")
    return solve_between(line, a, b, depth, start)


# -- in the sea ---------------------------------------------------------------------------------------
def solved_in_sea(model) -> bool:
    """Whether a system solves ``model`` as a line in the sea from its fixed end (module
    docstring): a `Line` the plane closed forms do not take (``off_plane``) that is not weightless."""
    return is_line(model) and model.off_plane is not None and not all(seg.w == 0.0 for seg in model.segments)


def _along_slope(line, anchor, fairlead, span):
    """The slope (-) of the line's `Plane` along it where the closed form on a slope holds
    (module docstring), else None."""
    bed, segs = line.bathymetry, line.segments
    if not (isinstance(bed, Plane) and line.current is None and len(segs) == 1 and not line.attachments):
        return None
    if segs[0].nonlinear or not segs[0].w > 0:
        return None
    e = (np.asarray(fairlead[:2]) - np.asarray(anchor[:2])) / span
    grad = np.asarray(bed.slope, dtype=float)
    along = float(grad @ e)
    across = grad - along * e
    on_bed = abs(float(anchor[2]) - float(bed.height(anchor[0], anchor[1]))) <= 1e-9 * line.length
    if not on_bed or float(np.abs(across).max()) > 1e-12 * (1.0 + abs(along)):
        return None
    return along


def _closed_form(line, anchor, fairlead, span, start, solve_in_space):
    """`LineInSea` by the closed form (module docstring), or None where a nonlinear law rests on
    the seabed (`GroundedLaw`)."""
    plain = line.variant_with_seabed(relative_seabed(line, anchor))
    try:
        solved = solve_in_space(plain, anchor, fairlead, span, start)
    except GroundedLaw:
        return None
    sol = solved.solution
    if line.nonlinear:
        name, error = "closed form (axial laws)", float(sol.history[-1]) if sol.history else 0.0
        reason = (
            "no current, a flat seabed, the line hangs clear of it: the laws' elongation integrated exactly"
        )
    else:
        name, error = "closed form", float(sol.residual())
        reason = "no current, a flat seabed (or none), constant EA: the elastic catenary is exact"
    return LineInSea(line, anchor, fairlead, solved, name, reason, error)


def _by_bvp(line, anchor, fairlead, reason, start=None) -> LineInSea:
    model, ends = bvp_model(line, anchor_z=float(anchor[2]))
    previous = start.result if isinstance(start, LineInSea) and start.bvp else None
    if previous is not None and previous.model is not model:
        previous = None
    with _plausible.quiet():  # its mesh is the library's, its error the half mesh's (`LineInSea.error`)
        fine = model.solve(anchor, fairlead, start=previous)
    return LineInSea(line, anchor, fairlead, fine, "3-D line BVP", reason, None, ends)


def solve_line_in_sea(line, anchor, fairlead, span: float, start, solve_in_space) -> LineInSea:
    """``line`` between the checked float 3-vectors ``anchor`` and ``fairlead`` at the horizontal
    distance ``span > 0`` by the model it needs (module docstring); ``start`` a previous
    solution (a `LineInSea` or a `skcable.mooring.line3d.Line3D`) for a warm start of the
    closed form, or None; ``solve_in_space``: `skcable.mooring.line3d.solve_in_plane_of_ends`, which
    solves a line model in the plane of its ends (`skcable.mooring.line_3d` passes it: this
    module is below it)."""
    need = line.in_space
    if need is not None and need[0] == "seabed" and line.current is None and line.bathymetry.flat is not None:
        need = None  # a flat Bathymetry: the closed forms, placed at the anchor
    slope = None if need is None else _along_slope(line, anchor, fairlead, span)
    if slope is not None:
        solved = solve_in_space(SlopeModel(line, slope), anchor, fairlead, span)
        reason = "no current, one uniform segment anchored on a plane sloping along the line"
        return LineInSea(
            line, anchor, fairlead, solved, "closed form (slope)", reason, solved.solution.residual()
        )
    if need is None:
        plain = start.result if isinstance(start, LineInSea) and not start.bvp else start
        solved = _closed_form(
            line, anchor, fairlead, span, None if isinstance(plain, LineInSea) else plain, solve_in_space
        )
        if solved is not None:
            return solved
        return _by_bvp(
            line, anchor, fairlead, "a nonlinear axial law on a line that rests on the seabed", start
        )
    if not math.isfinite(span):
        raise InputError("fairlead", "must be finite")
    return _by_bvp(line, anchor, fairlead, need[1], start)
