r"""A line between two ends over a flat seabed: which end is lower, which model, and why.

A `skcable.mooring.Line` runs from its end A to its end B, whichever is higher, in the vertical
plane through them: B at ``(span, dh)`` from A, the seabed the plane ``y = seabed`` (relative
to A, at or below both ends; or none). Its closed forms put the anchor at the lower end, so
the line is solved from its lower end (`Line.variant` with ``reverse`` when B is lower), and
the model is chosen by where the ends are (the same choice as `skcable.bvp.solve`, which
reports ``model`` and ``reason``):

- no seabed, or the lower end above it and the free line clear of it: the line hangs free
  (``"free"``; H.M. Irvine, "Cable Structures", MIT Press, 1981, segment by segment);
- the lower end on the seabed: it rests on it from there up to a touchdown, with Coulomb
  friction (``"grounded"``; J.M. Jonkman, "Dynamics modeling and loads analysis of an
  offshore floating wind turbine", NREL, 2007), or lies in a heap (``H = 0``);
- the lower end above the seabed and the free line below it: one uniform segment hangs from
  the lower end down to the seabed, lies on it and rises to the upper end, in closed form
  (``"touchdown between the ends"``, `skcable.cable.elastic_catenary` with ``seabed < 0``;
  frictionless only: between two touchdowns static friction depends on the history of the
  motion);
- both ends on the seabed: the line lies on it, straight and taut or slack
  (``"on the seabed"``, `skcable.mooring.lying`);
- anything else (several segments or attachments touching down between the ends, a buoy or a
  buoyant segment on the grounded part, a second touchdown): the line BVP
  (``"bvp"``, `skcable.mooring.solve_line_bvp` through `skcable.mooring.bvp_model`).

**Forces and their derivatives.** The result gives the end forces by the user's ends, and
the Jacobian of ``(H_A, V_A, H_B, V_B)`` in ``(span, y_A, y_B)``, the heights of the ends with
the seabed fixed. Where nothing touches the line depends on ``y_B - y_A`` only and
``H_A = H_B``, ``V_A + V_B = W`` (its weight); on the grounded side
``H_A = \max(H - C_B (W - V_B - P_A), 0)`` (the friction of the grounded weight, fully
mobilised; ``P_A`` the attachment at the anchor); an end resting on the seabed has no
derivative in its height (it cannot move into the seabed): its column is that of the end and
the seabed moved together (a rigid shift, as in MoorPy's end stiffnesses). For the touchdown
between the ends the closure's dependence on the lower end's height ``d`` above the seabed is
differentiated in closed form (`touchdown_jacobian`).
"""

from __future__ import annotations

from functools import partial

from skcable.cable.seabed import elastic_catenary
from skcable.errors import InputError
from skcable.mooring.bvp_model import solve_bvp_line
from skcable.mooring.jacobians import of_free, of_grounded, of_own, touchdown_jacobian
from skcable.mooring.lying import lying_line
from skcable.mooring.plane import MODELS, PlaneLine, on_seabed_tolerance, uniform
from skcable.mooring.segments import Line
from skcable.mooring.segments.batch import batchable, solve_batch
from skcable.mooring.slope import solve_on_slope

__all__ = [
    "MODELS", "PlaneLine", "batchable", "grounded_batch", "is_grounded_scene", "is_line", "line_in_plane",
    "on_seabed_tolerance", "solve_in_plane",
]  # fmt: skip


# -- the choice of the model ---------------------------------------------------------------------------
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


def _line_solve(model_line, span, dh, start):
    """``model_line.solve`` on span and dh the callers checked (`solve_between`, `line_in_plane`)."""
    return model_line.solve_checked(float(span), float(dh), start)


def _plane(scene, solution, reverse, model, reason, key, jacobian, variant) -> PlaneLine:
    span, dh, seabed, slope = scene
    return PlaneLine(span, dh, seabed, solution, reverse, model, reason, key, jacobian, variant, slope)


def solve_in_plane(line, span, dh, *, seabed=None, seabed_slope=0.0, start=None, bvp=None) -> PlaneLine:
    """Solve ``line`` (a `skcable.mooring.Line`) between its ends A = (0, 0) and B = (span, dh).

    Parameters
    ----------
    line : Line
        Its segments run from A to B; its own ``seabed`` is not used (``seabed`` below is),
        its ``friction`` is.
    span, dh : float
        B relative to A (m), ``span > 0`` (checked by the caller).
    seabed : float, optional
        The seabed's height below A relative to A (m), at or below both ends; None: no seabed.
    seabed_slope : float
        ``tan α`` of a plane seabed, ``y = seabed + x tan α`` (0: flat; `skcable.mooring.slope`).
    start : PlaneLine, optional
        A previous solution of this line: a warm start where the same model applies.
    bvp : callable, optional
        ``bvp(line, span, dh, seabed, reason, slope)`` → `PlaneLine` for the scenes no closed
        form takes (`skcable.mooring.bvp_model.solve_bvp_line` by default).

    Returns
    -------
    PlaneLine
        With ``model`` and ``reason`` (module docstring).
    """
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
    return _plane(
        scene,
        solution,
        reverse,
        "on the seabed",
        reason,
        ("on the seabed",),
        partial(of_own, solution),
        variant,
    )


def _free(line, scene, start, reason) -> PlaneLine:
    reverse = scene[1] < 0
    key = ("free", reverse)
    variant = line.variant(reverse=reverse)
    solution = _line_solve(variant, scene[0], abs(scene[1]), _warm(start, key))
    return _plane(scene, solution, reverse, "free", reason, key, partial(of_free, solution), variant)


def _grounded(line, scene, reverse, start, bvp) -> PlaneLine:
    key = ("grounded", reverse)
    variant = line.variant(reverse=reverse, contact=True)
    try:
        solution = _line_solve(variant, scene[0], abs(scene[1]), _warm(start, key))
    except InputError as err:
        if err.argument not in ("attachments", "segments"):
            raise
        return bvp(line, *scene[:3], f"the lower end on the seabed and {err}", scene[3])
    return _grounded_plane(scene, reverse, key, variant, solution)


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


def _grounded_plane(scene, reverse, key, variant, solution) -> PlaneLine:
    """The `PlaneLine` of a solution of the grounded variant: grounded, a heap, or hanging free."""
    if not solution.state.contact:
        reason = "the lower end on the seabed and the line leaving it upwards: it hangs free"
        jacobian = partial(of_free, solution)  # noqa: E731
        return _plane(scene, solution, reverse, "free", reason, key, jacobian, variant)
    reason = "the lower end on the seabed: the line rests on it up to a touchdown (Jonkman's closed form)"
    if solution.heap:
        reason = "the lower end on the seabed and the line longer than its L-shape: its slack lies in a heap"
    friction, H_A = variant.friction, solution.H_A
    jacobian = partial(of_grounded, solution, friction, H_A)
    return _plane(scene, solution, reverse, "grounded", reason, key, jacobian, variant)


def indeterminate_friction(line, depth):
    """`InputError` naming ``friction``: a touchdown between suspended ends with friction."""
    if line.friction > 0:
        raise InputError(
            "friction",
            f"the line touches down between its ends (the lower one {depth:.6g} m above the seabed): "
            "static friction there depends on the history of the motion; give the line friction=0",
        )


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
    jacobian = partial(touchdown_jacobian, solution)
    return _plane(
        scene, solution, reverse, "touchdown between the ends", reason, ("touchdown",), jacobian, variant
    )


def refuse_weightless(line) -> None:
    """`InputError` naming ``w`` for a line with a weightless segment (``w = 0``): it has no
    catenary (`skcable.mooring.line_between` takes a line of weightless segments: straight)."""
    if any(seg.w == 0.0 for seg in line.segments):
        raise InputError(
            "w",
            "a segment of w = 0 is weightless: it has no catenary (a line of weightless segments is "
            "straight between two points: line_between)",
        )


def is_line(model) -> bool:
    """Whether ``model`` is a `skcable.mooring.Line` (solved here) rather than another line model."""
    return isinstance(model, Line)


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
    from skcable._checks import positive, real, scalar

    if not is_line(line):
        raise InputError("line", f"must be a mooring.Line, got {type(line).__name__}")
    span = scalar("span", positive("span", span))
    dh = scalar("dh", real("dh", dh))
    seabed = None if seabed is None else scalar("seabed", real("seabed", seabed))
    slope = scalar("seabed_slope", real("seabed_slope", seabed_slope))
    if seabed is None and slope != 0.0:
        raise InputError("seabed_slope", "applies to a seabed: give seabed= as well")
    return solve_in_plane(line, span, dh, seabed=seabed, seabed_slope=slope)
