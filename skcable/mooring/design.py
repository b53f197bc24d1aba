r"""Design to a target: the line length, anchor radius or clump weight that gives a pretension, a
horizontal tension, a layback, a fairlead declination or a touchdown distance.

One unknown ``x`` (the length of one segment, the anchor's horizontal distance from the fairlead
along its azimuth, or the weight of one clump) is varied within bounds; the quantity ``q(x)`` of
the solved line (`skcable.mooring.line_between`), or of a system's line at equilibrium for a whole
pattern (`design_pattern`), is to meet ``value``:

- ``"pretension"``: the tension at the fairlead (N); ``"horizontal_tension"``: its horizontal
  component (N);
- ``"declination"``: the line's angle below the horizontal at the fairlead,
  :math:`\operatorname{atan2}(V_B, H_B)` (rad);
- ``"touchdown"``: the touchdown's horizontal distance from the anchor (m; 0 where the line
  lifts off at the anchor); ``"layback"``: the horizontal distance from the fairlead to the
  touchdown (m; the span where the line lifts off).

**Bracketed and guaranteed.** ``q`` is sampled at `SAMPLES` points over the bounds (a sample
whose line cannot be solved, a buoy landing on the grounded part say, is skipped); the first
sign change of ``q - value`` between solved samples from the lower bound brackets a root, which
Brent's method
(R.P. Brent, "Algorithms for Minimization without Derivatives", 1973) closes to the last digits
of ``x`` (where a solve inside the bracket fails, the bracket is narrowed around that point
by the nearest points that solve, and Brent's method resumes); the root is accepted when
``|q - value|`` is within ``1e-10`` of ``|value|`` (of the span for lengths, 1e-10 rad for
angles). Without a sign change the target is out of reach:
`InputError` naming ``value``, with the range of ``q`` over the bounds (the sampled range; its
ends are exact where ``q`` is monotone, as a pretension is in the length of a line on the seabed).
The default bounds: a total length from 0.98 times the chord (a 2 % stretch) to the L-shape
(span plus the fairlead's height above the seabed: the line lies in a heap beyond it), an anchor
radius from 2 % of the length to the radius where the line is 2 % stretched, a clump weight from 0
to ten times the line's weight; each widened to hold the given line's own value (its segment's
length, its anchor radius, its clump), so that a target the line meets as given is in reach.

**Bounded.** A design stops after ``max_iter`` solves or ``time_limit`` seconds with a
`ConvergenceError` whose ``history`` is ``|q - value|`` of every solve and whose ``last`` is the
best ``x`` reached.
"""

from __future__ import annotations

import math

import numpy as np

from skcable import _plausible
from skcable._budget import Budget, checked_budget
from skcable._checks import one_of, real, scalar
from skcable._show import Shown
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.choice import line_between
from skcable.mooring.line3d import point
from skcable.mooring.segments import ClumpWeight, Line, Segment

__all__ = ["SAMPLES", "TARGETS", "VARIABLES", "Design", "design_line", "design_pattern"]

TARGETS = ("pretension", "horizontal_tension", "declination", "touchdown", "layback")
VARIABLES = ("length", "anchor_radius", "clump")
#: Samples of the quantity over the bounds (the bracket's search).
SAMPLES = 33
#: The relative accuracy a design reaches.
RTOL = 1e-10


def quantity(target, solved) -> float:
    """The ``target`` of a solved line between an anchor (end a) and a fairlead (end b) (module docstring)."""
    plane = solved.plane
    if target == "pretension":
        return float(solved.tension_b)
    if target == "horizontal_tension":
        return float(plane.H_B)
    if target == "declination":
        return math.atan2(plane.V_B, plane.H_B)
    grounded = float(getattr(plane.solution, "length_on_seabed", 0.0)) > 0
    touchdown = float(plane.solution.x_touchdown) if grounded else 0.0
    return touchdown if target == "touchdown" else float(solved.span - touchdown)


class Design(Shown):
    """The designed value of a variable and what it achieves.

    Attributes
    ----------
    vary, target : str
        The variable (one of `VARIABLES`) and the quantity (one of `TARGETS`).
    value : float
        The target value.
    x : float
        The designed variable: a segment length (m), an anchor radius (m) or a clump weight (N).
    achieved : float
        The quantity at ``x``, within the tolerance of ``value``.
    line : Line
        The designed line (for a pattern: the first line's).
    anchor : ndarray, shape (3,)
        The designed anchor (m).
    solved : LineBetween or MooringEquilibrium
        The line solved at ``x``, or the system's equilibrium for a pattern.
    bounds, bracket : (float, float)
        The variable's bounds and the bracket Brent's method closed.
    evaluations : int
        Solves made.
    """

    def __init__(self, vary, target, value, x, achieved, line, anchor, solved, bounds, bracket, evaluations):
        self.vary, self.target, self.value, self.x, self.achieved = vary, target, value, x, achieved
        self.line, self.anchor, self.solved = line, anchor, solved
        self.bounds, self.bracket, self.evaluations = bounds, bracket, evaluations

    def __repr__(self):
        return (
            f"Design({self.vary}={self.x:.12g} for {self.target}={self.value:.12g}: achieved "
            f"{self.achieved:.12g}, {self.evaluations} solves)"
        )


def _check_names(target, vary):
    one_of("target", target, TARGETS)
    one_of("vary", vary, VARIABLES)


def _index(name, value, lo, hi, what) -> int:
    """``value`` as an integer in ``[lo, hi]``, else `InputError` naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not lo <= value <= hi:
        raise InputError(name, f"must be {what} in [{lo}, {hi}], got {value!r}")
    return int(value)


def _segment_index(line, segment):
    if segment is None:
        if len(line.segments) != 1:
            raise InputError(
                "segment", f"the line has {len(line.segments)} segments: say which one's length varies"
            )
        return 0
    return _index("segment", segment, 0, len(line.segments) - 1, "a segment index")


def _clump_joint(line, joint):
    clumps = [a.joint for a in line.attachments if isinstance(a, ClumpWeight)]
    if joint is None:
        if len(clumps) != 1:
            raise InputError(
                "joint", f"the line has {len(clumps)} clump weights: give the joint whose weight varies"
            )
        return clumps[0]
    return _index("joint", joint, 1, len(line.segments) - 1, "an inner joint")


def _with_length(line, i, length) -> Line:
    segments = list(line.segments)
    s = segments[i]
    segments[i] = Segment(
        length, s.w, s.EA, mbl=s.mbl, diameter=s.diameter, cd_normal=s.cd_normal,
        cd_tangential=s.cd_tangential, material=s.material,
    )  # fmt: skip
    return Line(segments, line.attachments, seabed=line.seabed, friction=line.friction)


def _with_clump(line, joint, weight) -> Line:
    others = [a for a in line.attachments if not (isinstance(a, ClumpWeight) and a.joint == joint)]
    if weight > 0:
        others.append(ClumpWeight(joint, weight))
    return Line(line.segments, others, seabed=line.seabed, friction=line.friction)


def _anchor_at(anchor, fairlead, radius) -> np.ndarray:
    e = anchor[:2] - fairlead[:2]
    e = e / math.hypot(*e)
    return np.array([fairlead[0] + radius * e[0], fairlead[1] + radius * e[1], anchor[2]])


def _own(vary, line, anchor, fairlead, i, joint) -> float:
    """The given line's own value of the variable: its segment's length, its anchor radius, its
    clump's weight at ``joint`` (0 without one)."""
    if vary == "length":
        return float(line.segments[i].length)
    if vary == "anchor_radius":
        return math.hypot(*(fairlead[:2] - anchor[:2]))
    return sum(a.weight for a in line.attachments if isinstance(a, ClumpWeight) and a.joint == joint)


def _formula_bounds(vary, line, anchor, fairlead, depth, i, joint):
    span = math.hypot(*(fairlead[:2] - anchor[:2]))
    dh = abs(float(fairlead[2] - anchor[2]))
    chord, L = math.hypot(span, dh), line.length
    if vary == "length":
        others = L - line.segments[i].length
        height = float(fairlead[2]) + depth if depth is not None else dh
        top = span + max(height, dh) if depth is not None else 3.0 * chord
        return max(0.98 * chord - others, 1e-6 * L), max(top - others, 1e-6 * L)
    if vary == "anchor_radius":
        taut = (1.02 * L) ** 2 - dh * dh
        if not taut > (0.02 * L) ** 2:
            raise InputError(
                "vary", "the fairlead is higher above the anchor than the line is long: no radius reaches"
            )
        return 0.02 * L, math.sqrt(taut)
    return 0.0, 10.0 * abs(line.arrays.segment_weight)


def _tolerance(target, value, scale) -> float:
    if target == "declination":
        return RTOL * max(abs(value), 1.0)
    if target in ("touchdown", "layback"):
        return RTOL * max(abs(value), scale)
    return RTOL * abs(value)


class _Unsolved(Exception):
    """A sample whose line cannot be solved (`_Counted`, inside Brent's method): ``x`` its abscissa."""

    def __init__(self, x):
        self.x = x


def _sampled(f, xs) -> np.ndarray:
    """``f`` at ``xs``; NaN where the line cannot be solved (a failed sample is skipped)."""
    out = np.full(len(xs), np.nan)
    for k, x in enumerate(xs):
        try:
            out[k] = f(float(x))
        except _Unsolved:
            continue
    return out


def _narrowed(f, value, a, ga, b, gb, bad):
    """The bracket ``[a, b]`` (``ga``, ``gb`` of opposite signs) narrowed around the failed point
    ``bad``: the nearest points on either side that solve, tried at ``bad ± (b - a) 2^-k``."""
    for k in range(2, 30):
        step = (b - a) * 2.0**-k
        for x in (bad - step, bad + step):
            if not a < x < b:
                continue
            try:
                g = f(x) - value
            except _Unsolved:
                continue
            if np.sign(g) == np.sign(ga):
                return x, g, b, gb
            return a, ga, x, g
    raise ConvergenceError(f"design: no line solves around x = {bad:.12g} inside the bracket [{a}, {b}]", [])


def _brent(f, value, a, ga, b, gb):
    """Brent's method on ``f - value`` over ``[a, b]``; a failed solve narrows the bracket around it
    (`_narrowed`) and the method resumes."""
    from scipy.optimize import brentq

    while True:
        try:
            tol = 1e-15 * max(abs(a), abs(b))
            return brentq(lambda t: f(t) - value, a, b, xtol=tol, rtol=8.9e-16, maxiter=200), (a, b)
        except _Unsolved as failed:
            a, ga, b, gb = _narrowed(f, value, a, ga, b, gb, failed.x)


def _solve_bracketed(f, lo, hi, value, tol, what, samples):
    """``x`` in [lo, hi] with ``f(x) = value``: sampled, bracketed, Brent (module docstring)."""
    xs = np.linspace(lo, hi, samples)
    qs = _sampled(f, xs)
    solved = np.flatnonzero(~np.isnan(qs))
    if not solved.size:
        raise ConvergenceError(f"design: no line of the bounds [{lo:.9g}, {hi:.9g}] could be solved", [])
    if not np.isfinite(qs[solved]).all():
        raise ConvergenceError(f"design: a non-finite {what} over the bounds", [])
    xs, g = xs[solved], qs[solved] - value
    exact = np.flatnonzero(g == 0.0)
    change = np.flatnonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0)
    if exact.size and (not change.size or exact[0] <= change[0]):
        return float(xs[exact[0]]), (float(xs[exact[0]]),) * 2
    if not change.size:
        raise InputError(
            "value",
            f"the {what} {value:.12g} is out of reach: over the bounds [{lo:.9g}, {hi:.9g}] it takes values "
            f"in [{g.min() + value:.9g}, {g.max() + value:.9g}] (give other bounds=, or another target)",
        )
    k = int(change[0])
    x, (a, b) = _brent(f, value, float(xs[k]), float(g[k]), float(xs[k + 1]), float(g[k + 1]))
    if not abs(f(x) - value) <= tol:
        raise ConvergenceError(
            f"design: the {what} reached {f(x):.15g}, not {value:.15g} within {tol:.3g}", []
        )
    return float(x), (a, b)


def design_line(
    line,
    anchor,
    fairlead,
    *,
    target,
    value,
    vary="length",
    depth=None,
    segment=None,
    joint=None,
    bounds=None,
    max_iter: int = 500,
    time_limit: float = 60.0,
) -> Design:
    """The length, anchor radius or clump weight of one line that meets a target (module docstring).

    Parameters
    ----------
    line : Line
        The line, segments from the anchor to the fairlead.
    anchor, fairlead : array_like, shape (3,)
        Its ends (m), z up; the anchor radius moves the anchor horizontally along its azimuth from
        the fairlead.
    target : str
        One of `TARGETS`.
    value : float
        The target value (N, rad or m).
    vary : str
        ``"length"`` (of ``segment``), ``"anchor_radius"`` or ``"clump"`` (the weight at ``joint``, N).
    depth : float, optional
        Water depth (m): the seabed ``z = -depth`` (as `skcable.mooring.line_between`).
    segment, joint : int, optional
        Which segment's length or which joint's clump weight varies (needed where the line has
        several).
    bounds : (float, float), optional
        The variable's bounds (defaults in the module docstring: they hold the line's own value).
    max_iter : int
        Line solves at most (default 500; a design takes about 50).
    time_limit : float
        Seconds at most (default 60).

    Returns
    -------
    Design

    Raises
    ------
    InputError
        Unknown names; the target out of reach over the bounds (naming ``value``, with the range).
    ConvergenceError
        Past ``max_iter`` solves or ``time_limit`` seconds (``history``: ``|q - value|`` of each
        solve; ``last``: the best ``x``); no line solves inside a bracket.
    """
    _check_names(target, vary)
    if not isinstance(line, Line):
        raise InputError("line", f"must be a mooring.Line, got {type(line).__name__}")
    value = scalar("value", real("value", value))
    a, b = point("anchor", anchor), point("fairlead", fairlead)
    i = _segment_index(line, segment) if vary == "length" else None
    j = _clump_joint(line, joint) if vary == "clump" else None

    def build(x):
        if vary == "length":
            return _with_length(line, i, x), a
        if vary == "clump":
            return _with_clump(line, j, x), a
        return line, _anchor_at(a, b, x)

    def q(x):
        model, anchor_x = build(x)
        return quantity(target, line_between(model, anchor_x, b, depth=depth))

    lo, hi = _bounds(bounds, vary, line, a, b, depth, i, j)
    x, bracket, calls = _search(q, value, target, (lo, hi), (a, b), SAMPLES, (max_iter, time_limit))
    model, anchor_x = build(x)
    solved = line_between(model, anchor_x, b, depth=depth)
    achieved = quantity(target, solved)
    return Design(vary, target, value, x, achieved, model, anchor_x, solved, (lo, hi), bracket, calls)


def _search(q, value, target, bounds, ends, samples, budget):
    """``(x, bracket, solves)``: ``q(x) = value`` over ``bounds``, sampled, bracketed and closed by
    Brent's method (module docstring) within the ``budget`` ``(max_iter, time_limit)``; ``ends``
    the anchor and the fairlead (the span: the scale of a distance's tolerance)."""
    a, b = ends
    counter = _Counted(q, value, *checked_budget(*budget))
    tol = _tolerance(target, value, math.hypot(*(b[:2] - a[:2])))
    with _plausible.quiet():  # the samples are trials, not answers
        x, bracket = counter.run(_solve_bracketed, *bounds, value, tol, target, samples)
    return x, bracket, counter.calls


class _Counted:
    """``f`` counted against a `skcable._budget.Budget` of solves and seconds, each
    ``|f(x) - value|`` recorded (the history, the best ``x``); a call whose line cannot be
    solved raises `_Unsolved`."""

    def __init__(self, f, value=0.0, max_iter=math.inf, time_limit=math.inf):
        self.f, self.value = f, value
        self.budget = Budget(max_iter, time_limit)

    @property
    def calls(self) -> int:
        return self.budget.calls

    def __call__(self, x):
        self.budget.spend()
        try:
            q = self.f(x)
        except (InputError, ConvergenceError):
            raise _Unsolved(x) from None
        self.budget.record(abs(q - self.value), float(x))
        return q

    def run(self, search, *args):
        """``search(self, *args)``; past the budget, `ConvergenceError` with the history and the
        best ``x`` (``last``)."""
        return self.budget.run("design (the measure: |q - value|)", "solves", search, self, *args)


def _bounds(bounds, vary, line, a, b, depth, i, j):
    """The given ``bounds``, checked, or those of the module docstring, widened to hold the line's
    own value (`_own`)."""
    if bounds is None:
        lo, hi = _formula_bounds(vary, line, a, b, depth, i, j)
        own = _own(vary, line, a, b, i, j)
        return min(lo, own), max(hi, own)
    try:
        lo, hi = (scalar("bounds", real("bounds", v)) for v in bounds)
    except (TypeError, ValueError):
        raise InputError("bounds", f"must be two numbers (low, high), got {bounds!r}") from None
    if not (lo < hi and (lo > 0 or vary == "clump" and lo >= 0)):
        raise InputError("bounds", f"must be 0 < low < high (0 <= low for a clump), got {bounds!r}")
    return lo, hi


def design_pattern(
    system,
    lines,
    *,
    target,
    value,
    vary="length",
    segment=None,
    joint=None,
    bounds=None,
    samples: int = 13,
    max_iter: int = 200,
    time_limit: float = 600.0,
    **equilibrium,
) -> Design:
    """The same change to every line of a pattern of a `MooringSystem`, so that the first line's
    ``target`` meets ``value`` at the system's equilibrium (under the loads of ``equilibrium``,
    the keywords of `MooringSystem.equilibrium`).

    ``lines``: the pattern's line handles (each a `skcable.mooring.Line` from its anchor, end a, fixed,
    to its fairlead, end b); ``vary``, ``segment``, ``joint``, ``bounds``: as `design_line`, the
    bounds' defaults from the first line; ``samples``: the bracket's search (fewer than a line's:
    each is an equilibrium); ``max_iter``, ``time_limit``: the budget (equilibria, seconds), past
    which `ConvergenceError` carries the history and the best ``x``. Returns a `Design` whose
    ``solved`` is the equilibrium at ``x``.
    """
    _check_names(target, vary)
    handles = list(lines)
    if not handles or not all(h in system.mooring_lines for h in handles):
        raise InputError("lines", "must be a non-empty list of the system's lines (from add_line)")
    first = handles[0]
    if not (
        isinstance(first.model, Line) and first.a.fixed and all(h.managed and h.a.fixed for h in handles)
    ):
        raise InputError(
            "lines", "each must be a mooring.Line from a fixed anchor (end a) to its fairlead (end b)"
        )
    value = scalar("value", real("value", value))
    i = _segment_index(first.model, segment) if vary == "length" else None
    j = _clump_joint(first.model, joint) if vary == "clump" else None
    state = {"start": None}

    def solve(x):
        models, positions = {}, {}
        for h in handles:
            if vary == "length":
                models[h] = _with_length(h.model, i, x)
            elif vary == "clump":
                models[h] = _with_clump(h.model, j, x)
            else:
                rest = system.point_position(h.b)
                positions[h.a] = _anchor_at(h.a.position, rest, x)
        trial = system.replaced(models=models, positions=positions)
        start = state["start"]
        eq = trial.equilibrium(**equilibrium, start=None if start is None else start.position)
        state["start"] = eq
        return eq

    def q(x):
        eq = solve(x)
        return quantity(target, eq.lines[eq.line_indices.index(first.index)])

    a = first.a.position
    b = system.point_position(first.b)
    lo, hi = _bounds(bounds, vary, first.model, a, b, system.depth, i, j)
    x, bracket, calls = _search(q, value, target, (lo, hi), (a, b), int(samples), (max_iter, time_limit))
    eq = solve(x)
    line = eq.lines[eq.line_indices.index(first.index)]
    achieved = quantity(target, line)
    return Design(vary, target, value, x, achieved, line.line, line.a, eq, (lo, hi), bracket, calls)
