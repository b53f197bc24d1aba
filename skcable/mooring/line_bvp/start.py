"""The closed-form starts of a line BVP.

- `closed_form_start`: the elastic catenary of the line's mean weight and compliance (H. M.
  Irvine, "Cable Structures", MIT Press, 1981, ch. 2; an inextensible line starts from the
  inextensible catenary) or, where it dips below the seabed, Jonkman's grounded one on a flat
  seabed at the anchor's level (J.M. Jonkman, NREL, 2007), its positions lifted onto the
  seabed. Exact for one uniform segment. With cable terms the mean weight is the weight less
  the terms' vertical force on the chord (`LineProblem.start_weight`); a line they buoy up
  (a negative mean weight) hangs upward, the mirror image of the line under the opposite load.
- `segmented_start`: the multi-segment closed form `skcable.mooring.Line` of the same segments,
  clump weights and buoys at the joints and flat seabed: the start of a line whose segments
  differ (a light rope under a heavy chain hangs far from the uniform line of their mean
  weight). Only for lines it can describe: constant weights ``w > 0`` (a point load inside a
  segment splits it, and hangs at the new joint); an inextensible segment gets ``EA = 1e9``
  times the line's weight.
- `start_form`: the uniform start's shape, which grades the first mesh
  (`skcable.mooring.line_bvp.mesh.start_nodes`).

**The heap.** A line longer than its L-shape leaves its slack in a heap on the seabed: ``H = 0``,
and the arc form has no tension to solve for (the tangent is singular on the heap). The uniform
closed form's heap is the line's own only for one uniform segment without point loads on a flat
seabed: then ``InputError("length")``. For any other line the uniform line's heap says nothing
of the line's (a heavy chain at the fairlead holds a light rope off the seabed): the verdict is
`skcable.mooring.Line`'s, the closed form of the segments themselves, where it applies
(``InputError("length")`` if it finds a heap), and the Newton solve's otherwise, from the free
uniform line lifted onto the seabed.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from skcable import _plausible
from skcable.cable._catenary import catenary
from skcable.cable._elastic import elastic_catenary as free_catenary
from skcable.cable.seabed import SlopeTouchdownLine, elastic_catenary, slope_touchdown, sloped_seabed_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.segments import Buoy, ClumpWeight, Line, Segment

__all__ = [
    "closed_form_start",
    "hanging",
    "lifted_start",
    "on_dofs",
    "on_slope",
    "segmented_solution",
    "segmented_start",
    "slack_end_of",
    "smeared_start",
    "start_form",
]

_HEAP = (
    "leaves slack line lying in a heap on the seabed (H = 0): elastic_catenary(seabed=...) "
    "and mooring.Line return that state"
)


class _Heap(Exception):
    """The uniform line's grounded closed form is a heap."""


def _uniform(problem, w=None):
    """``(x, y, T, form, heap)``: the uniform start on the problem's dofs (under ``w`` N/m where
    given, else `LineProblem.start_weight`); ``form = (H, w, s_v, grounded)``, the catenary's
    horizontal force, weight and vertical force ``w (s - s_v)`` (zero where grounded); ``heap``
    whether the grounded uniform line is a heap (then x, y, T and form are the free line's,
    lifted onto the seabed)."""
    span, dh, L = problem.span, problem.dh, problem.L
    w = problem.start_weight if w is None else w
    if not (w > 0 or (problem.terms and w < 0)):
        what = "weight less the cable terms' vertical force" if problem.terms else "weight"
        raise InputError("segments", f"the line's mean {what} must be > 0 (downward), got {w:g} N/m")
    c = problem.compliance / L
    EA = 1.0 / c if c > 0 else 1e6 * abs(w) * L
    s_dof, s_t = problem.basis.doflocs[0], problem.tbasis.doflocs[0]
    # an inextensible line starts inextensible: a stiff elastic start (EA = 1e6 wL) of a line
    # 1e-9 longer than its chord stretches by more than that excess, and starts H far off
    free, stiff = _free_line(span, dh, w, EA, L, c > 0), (EA if c > 0 else np.inf)
    free_x, free_y, free_T = hanging(free.H, free.V_A, w, stiff)
    x, y, T = free_x(s_dof), free_y(s_dof), free_T(s_t)
    form = (float(free.H), w, float(free.V_A) / w, False)
    bed, heap = problem.seabed, False
    if bed is not None and w > 0 and np.any(y < bed(x)):
        level = min(float(bed(np.array([0.0]))[0]), 0.0)
        level = min(level, dh - 1e-3 * abs(span))
        try:
            with _plausible.quiet():  # a start, not an answer
                grounded = elastic_catenary(span, dh, w, EA, length=L, seabed=level)
            if np.any(grounded.heap):  # H = 0: the arc form has no tension to solve for
                raise _Heap
            x, y, T = grounded.x_of_s(s_dof), grounded.y_of_s(s_dof), grounded.T_of_s(s_t)
            form = (float(grounded.H), w, L - float(grounded.V_B) / w, True)
        except _Heap:
            heap = True
        except InputError:
            if bed.flat is not None:  # on a flat seabed the closed form's refusal holds
                raise
        except ConvergenceError:  # its Newton stalled (at round-off): the free line lifted instead
            pass
        y = np.maximum(y, bed(x))  # a curved seabed: the free line lifted onto it, if nothing better
    return x, y, T, form, heap


def hanging(H, V_A, w, EA):
    r"""``(x(s), y(s), T(s))``: the elastic catenary hanging from A = (0, 0) under ``w`` (N/m,
    downward) with the horizontal force ``H`` and A's upward reaction ``V_A`` (N), stiffness
    ``EA`` (N; inf: inextensible), as callables of the unstretched arc length ``s`` from A (H.M.
    Irvine, "Cable Structures", MIT Press, 1981, ch. 2):

    .. math::
        x = \frac{H s}{EA} + \frac{H}{w}\Big(\operatorname{asinh}\frac{w s - V_A}{H}
            - \operatorname{asinh}\frac{-V_A}{H}\Big),\quad
        y = \frac{H}{w}\Big(\sqrt{1 + \big(\tfrac{w s - V_A}{H}\big)^2}
            - \sqrt{1 + \big(\tfrac{V_A}{H}\big)^2}\Big) + \frac{w s^2/2 - V_A s}{EA},\quad
        T = \sqrt{H^2 + (w s - V_A)^2}.
    """
    u_a = -V_A / H

    def x(s):
        return H * s / EA + H / w * (np.arcsinh(u_a + w * s / H) - np.arcsinh(u_a))

    def y(s):
        t0, t1 = np.hypot(1.0, u_a), np.hypot(1.0, u_a + w * s / H)
        return (H / w) * (t1 - t0) + (-V_A * s + 0.5 * w * s * s) / EA

    def T(s):
        return np.hypot(H, -V_A + w * s)

    return x, y, T


class _Free(NamedTuple):
    """The free uniform line's horizontal force and A's upward reaction (N)."""

    H: float
    V_A: float


def _free_line(span, dh, w, EA, L, elastic) -> _Free:
    """The free uniform line under ``w`` (N/m, downward; a line that cable terms buoy up, ``w <
    0``, hangs upward: the mirror image of the line under ``-w`` to ``(span, -dh)``), elastic
    (`_free_elastic`) or inextensible (`skcable.cable.catenary`)."""
    sign = 1.0 if w > 0 else -1.0
    if elastic:
        free = _free_elastic(span, sign * dh, sign * w, EA, L)
    else:
        free = catenary(span, sign * dh, sign * w, length=L)
    return _Free(free.H, sign * free.V_A)


def _free_elastic(span, dh, w, EA, L):
    """Irvine's elastic catenary (``H``, ``V_A``); where its Newton stalls above its own
    tolerance (the round-off of a nearly taut, stiff line), the multi-segment closed form `Line`
    of the one segment, whose solve polishes the same closure from bracketing."""
    try:
        with _plausible.quiet():  # a start, not an answer
            return free_catenary(span, dh, w, EA, length=L)
    except ConvergenceError as failed:
        try:
            with _plausible.quiet():
                return Line([Segment(L, w, EA)]).solve(span, dh)
        except (InputError, ConvergenceError):
            raise failed from None


def _exact(problem) -> bool:
    """Whether the uniform closed form is the line's own: one segment of constant weight, no
    point loads, a flat seabed."""
    one = len(problem.segments) == 1 and not callable(problem.segments[0].w) and not problem.terms
    return one and not problem.point_loads and problem.seabed is not None and problem.seabed.flat is not None


def start_form(problem):
    """``(H, w, s_v, grounded)`` of the uniform start's catenary: its vertical force is
    ``w (s - s_v)``, zero where it is grounded."""
    return _uniform(problem)[3]


def _straight(problem) -> tuple[float, float] | None:
    """``(b(0), b')`` of a sloped seabed known to be straight (`Seabed.straight`) or that looks
    straight (the slope the same at A and under B, and the height under B the line's through
    them) under a line of positive start weight, else None: a start's guess, not a claim."""
    bed, L = problem.seabed, problem.L
    if bed is None or bed.flat is not None or not problem.start_weight > 0:
        return None
    if bed.straight is not None:
        return bed.straight
    b0, b1 = (float(b) for b in bed(np.array([0.0, problem.span])))
    k0, k1 = (float(k) for k in bed.slope(np.array([0.0, problem.span])))
    if abs(k0 - k1) > 1e-12 * max(1.0, abs(k0)) or abs(b0 + k0 * problem.span - b1) > 1e-12 * L:
        return None
    return b0, k0


def _straight_slope(problem) -> float | None:
    """The slope of a straight seabed through A along the line (``b(0) = 0``; `_straight`) under
    a line of positive start weight, else None."""
    line = _straight(problem)
    if line is None or abs(line[0]) > 1e-12 * problem.L:
        return None
    return line[1]


def _start_stiffness(problem) -> float:
    """The uniform line's axial stiffness (N) for a closed-form start: its mean compliance's, an
    inextensible line's ``1e9 w L``."""
    w, L = problem.start_weight, problem.L
    return L / problem.compliance if problem.compliance > 0 else 1e9 * w * L


def uniform_on_slope(problem) -> tuple[float, float, float, float] | None:
    """``(w, EA, b(0), b')`` of ``problem``'s uniform line (its start weight, N/m, and axial
    stiffness, N: `_start_stiffness`) over a straight seabed sloping along the line below A
    (`_straight`: ``b(0) < 0``, ``b' ≠ 0``), else None. The scene of the closed forms on the slope
    (`skcable.cable.seabed.slope_touchdown`, `skcable.cable.seabed.taut_length_on_slope`)."""
    line = _straight(problem)
    if line is None or not line[0] < -1e-12 * problem.L or line[1] == 0.0:
        return None
    return problem.start_weight, _start_stiffness(problem), line[0], line[1]


def _slope_touchdown(problem):
    """The start on a straight seabed sloping along the line below both ends (`uniform_on_slope`):
    the uniform line touching down between them on the slope without friction
    (`skcable.cable.seabed.slope_touchdown`: it hangs, lies on the slope and rises, its tension
    growing uphill by the weight's component), on the problem's dofs; None elsewhere or where it
    has no such state. The flat line at the anchor's level lifted onto the slope can leave Newton
    stagnating (a chain 440 m long between ends 40 m and 60.06 m above a 6° slope, 380 m apart,
    ``tests/mooring/test_line_geometry.py``)."""
    scene = uniform_on_slope(problem)
    if scene is None:
        return None
    (w, EA, level, slope), L, span, dh = scene, problem.L, problem.span, problem.dh
    try:
        with _plausible.quiet():  # a start, not an answer
            touchdown = slope_touchdown(span, dh, w, EA, L, seabed=level, seabed_slope=slope)
    except (InputError, ConvergenceError):
        return None
    if touchdown is None:
        return None
    closed = SlopeTouchdownLine(span, dh, w, EA, L, level, slope, touchdown)
    xy = closed.xy(problem.basis.doflocs[0])
    return problem.with_ends([xy[..., 0], xy[..., 1]], closed.T_of_s(problem.tension_points()))


def _on_slope(problem):
    """The start on a straight seabed sloping along the line through A (``b(0) = 0``, the slope
    the same at A and under B): Jonkman's line on the slope
    (`skcable.cable.seabed.sloped_seabed_catenary`, the line in space's start there) of the
    uniform line, on the problem's dofs; None elsewhere or where it has no such form. The flat
    grounded start lifted onto a slope can leave Newton no descent (35 of the 44 lines that the
    plane line failed and the line in space solved in ``benchmarks/line_bvp_planes.py``, seeds
    1–3, solve from this start)."""
    k0 = _straight_slope(problem)
    if k0 is None:
        return None
    w, L, EA = problem.start_weight, problem.L, _start_stiffness(problem)
    try:
        with _plausible.quiet():  # a start, not an answer
            line = sloped_seabed_catenary(
                problem.span, problem.dh, w, EA, length=L, seabed_slope=k0, friction=problem.friction
            )
    except (InputError, ConvergenceError):
        return None
    xy = line.xy(problem.basis.doflocs[0])
    x, y = np.array(xy[..., 0], dtype=float), np.array(xy[..., 1], dtype=float)
    return problem.with_ends([x, y], np.asarray(line.T_of_s(problem.tension_points()), dtype=float))


def closed_form_start(problem):
    """The first iterate on ``problem``'s dofs: ``[x, y, T]``, the ends at A and B exactly; on a
    straight slope through A, the line on the slope (`_on_slope`); on one below both ends, where
    the line touches down on it, the line touching down (`_slope_touchdown`); elsewhere
    `lifted_start`; the heap refused (module docstring)."""
    for sloped in (_on_slope, _slope_touchdown):
        start = sloped(problem)
        if start is not None:
            return start
    return lifted_start(problem)


def on_slope(problem) -> bool:
    """Whether the seabed is a straight slope (`_straight`) through A or below it, where
    `closed_form_start` is the line on the slope or touching down on it unless those have no
    closed form, and `lifted_start` its alternative."""
    line = _straight(problem)
    return line is not None and line[1] != 0.0 and line[0] <= 1e-12 * problem.L


def smeared_start(problem):
    """The first iterate of the uniform line under the mean weight with the point loads smeared
    along it, ``start_weight + ΣP/L`` (the line in space's start's weight), lifted onto the
    seabed as `lifted_start`; None without point loads or where they make it light (buoys):
    the start of a line whose clump weights hold it down far from where its own weight does."""
    total = float(sum(P for _, P in problem.point_loads))
    w = problem.start_weight + total / problem.L
    if total == 0.0 or not w > 0 or problem.terms:
        return None
    try:
        x, y, T, _, _ = _uniform(problem, w)
    except InputError:  # the smeared line's own refusal (a flat seabed's heap) is not the line's
        return None
    return problem.with_ends([x, y], T)


def lifted_start(problem):
    """The first iterate of the uniform line, free or grounded on a flat seabed at the anchor's
    level and lifted onto the seabed (module docstring), on ``problem``'s dofs; the heap refused.
    On a straight slope (`on_slope`) it is the alternative to the line on the slope or touching
    down on it: a varying weight, a clump and a buoy can leave Newton no descent from that one
    (the survey's scene 3:234, ``benchmarks/line_bvp_planes.py``)."""
    x, y, T, _, heap = _uniform(problem)
    if heap:
        if _exact(problem):
            raise InputError("length", _HEAP)
        segmented = segmented_start(problem)  # raises where mooring.Line finds the heap
        if segmented is not None:
            return segmented
    return problem.with_ends([x, y], T)


def _line(problem, friction=None):
    """The `Line` of the problem's segments, point loads and friction (``friction`` instead,
    if given), or None where it has none. A point load inside a segment splits it there: the
    load hangs at the joint of its two pieces."""
    if problem.seabed is not None and problem.seabed.flat is None:
        return None
    if any(callable(seg.w) or not seg.w > 0 for seg in problem.segments):
        return None
    stiff = 1e9 * abs(problem.weight)
    joints, tol = problem.joints, 1e-9 * problem.L
    loads = [(float(s), float(P)) for s, P in problem.point_loads if P != 0]
    inner = [s for s, _ in loads if not np.any(np.abs(joints - s) <= tol)]
    cuts = np.unique(np.concatenate([joints, inner]))  # the joints of the split line
    segments = []
    for seg, start, end in zip(problem.segments, joints[:-1], joints[1:], strict=True):
        EA = stiff if seg.law is None else seg.law.EA
        inside = cuts[(cuts >= start - tol) & (cuts <= end + tol)]
        segments += [Segment(float(b - a), seg.w, EA) for a, b in zip(inside[:-1], inside[1:], strict=True)]
    attachments = []
    for s, P in loads:
        k = int(np.argmin(np.abs(cuts - s)))
        attachments.append(ClumpWeight(k, P) if P > 0 else Buoy(k, -P))
    bed = None if problem.seabed is None else problem.seabed.flat
    friction = problem.friction if friction is None else friction
    return Line(segments, attachments, seabed=bed, friction=friction if bed is not None else 0.0)


def segmented_solution(problem, friction=None):
    """The `Line` solution of the problem's segments (module docstring; with ``friction``
    instead of the problem's, if given), or None where it does not describe the line or finds
    no solution; ``InputError("length")`` where it finds the slack in a heap."""
    if friction is None and len(problem.segments) == 1 and not problem.point_loads:
        return None  # the uniform start is this closed form already
    line = _line(problem, friction)
    if line is None:
        return None
    try:
        with _plausible.quiet():  # a start, not an answer
            solution = line.solve(problem.span, problem.dh)
    except (InputError, ConvergenceError):
        return None
    if solution.heap:
        if problem.terms:  # the segments' heap is not the line's: its terms load it otherwise
            return None
        raise InputError("length", _HEAP)
    return solution


def slack_end_of(solution, length):
    """Where the tension of a closed-form ``solution`` first rises above zero from the anchor
    (m of arc length, to 1e-12 of the ``length``): the end of its slack stretch; 0 without one."""
    if not solution.T_of_s(0.0) <= 0.0:
        return 0.0
    lo, hi = 0.0, float(length)
    while hi - lo > 1e-12 * length:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if solution.T_of_s(mid) <= 0.0 else (lo, mid)
    return lo


def on_dofs(problem, solution):
    """A closed-form ``solution`` (``x_of_s``, ``y_of_s``, ``T_of_s``) on the problem's dofs."""
    s_dof = problem.basis.doflocs[0]
    x, y = np.asarray(solution.x_of_s(s_dof), float), np.asarray(solution.y_of_s(s_dof), float)
    T = np.asarray(solution.T_of_s(problem.tension_points()), float)
    return problem.with_ends([x, y], T)


def segmented_start(problem):
    """The start from `Line`, the closed form of the segments (module docstring), on the
    problem's dofs, or None where there is none (`segmented_solution`)."""
    solution = segmented_solution(problem)
    return None if solution is None else on_dofs(problem, solution)


def restart(old, z, problem) -> np.ndarray:
    """The solution ``z`` of the discrete line ``old`` interpolated onto ``problem``'s dofs
    (another mesh of the same line, in the plane or in space): positions at its nodes, tensions
    just inside its elements (`DiscreteLine.tension_points`: each side of a jump its own), the
    ends exact."""
    state = old.state_at(z, problem.basis.doflocs[0])
    return problem.with_ends(state.position, old.tension_at(z, problem.tension_points()))
