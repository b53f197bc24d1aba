"""Differential survey of the two line BVPs in a vertical plane: `solve_line_bvp` against
`solve_line_bvp_3d` solved in the plane x-z, over seeded scenes.

The two share one discrete line law (`skcable.mooring.line_bvp.discrete`) and, on a seabed, the
grading of their meshes, but not their drivers (`skcable.mooring.line_bvp.driver`: its first
solves, nested meshes, the slack stretch with friction; `skcable.mooring.line_bvp.space.driver`: its
starts, the current by steps, the uniform mesh where the graded ones fail), so a scene one solves and the
other does not is a driver's failure, and two answers farther apart than both discretisations
allow is a bug in one of them. Each public solver falls back on the other's strategy where its own
fails (`skcable.mooring.line_bvp.fallback`), as a user's call does: a scene one fails only is one
where the fallback failed too, and a scene solved by a fallback agrees to round-off by
construction. The scenes cover what ``benchmarks/line_bvp_survey.py`` (against
the closed form) does not: a seabed sloping along the line (``b(x) = h + slope x``, slopes
-0.1 to 0.1, through the anchor or below it), a flat seabed below the anchor, clump weights and
buoys inside the segments (not at the joints), weights that vary along the line (a callable of
the arc length), one to three segments of chain (about 1000 N/m), wire (80 N/m) or rope
(20 N/m) with ``EA`` from 1e7 to 1e10 N, lengths from 1.02 to 2 chords, 64 or 256 elements,
friction 0 mostly (0.3 to 1 on a fifth of the seabed scenes). A scene whose uniform line (its
mean weight, its segments' EA in series) has no equilibrium on the seabed by Jonkman's closed
form on the slope (a heap; without friction, a slack end on a rising slope, which slides) is
shortened towards 1.02 chords, else drawn again (`_has_equilibrium`): the point loads and the
varying weights can still take a scene out of equilibrium, which both then fail (the uniform
line longer than a frictionless slope below both ends holds taut, `taut_length_on_slope`, is not
redrawn: the solvers' diagnosis names it). Both solvers run with their own defaults otherwise
(``fit_touchdown`` 3 in both); the plane line takes the sloped seabed as two numbers
(``seabed=h, seabed_slope=slope``).

In space the anchor is at (0, 0, 0), the fairlead at (span, 0, dh), the seabed
``Plane(h, (slope, 0))``; the plane's end forces ``(H_A, V_A, H_B, V_B)`` are space's
``force_on_anchor[[0, 2]] = (H_A, -V_A)`` and ``force_on_fairlead[[0, 2]] = (-H_B, -V_B)``.
Outcomes:

- agree: both solve, the four end forces within ``TOLERANCE`` (1e-6) of the largest; the plane
  line is solved again on 4 times the elements (`converged`): ``both coarse`` where it moves
  more than ``COARSE_ALIKE`` (1e-4), since the two share their law and their grading and a mesh
  can leave both wrong alike, else ``converged``;
- disagree: both solve, farther apart; both are solved again on 4, then 16 times the elements
  (`refined`): ``mesh (space)`` or ``mesh (plane)`` where the refined pair come together and
  that driver's forces moved the most (a discretisation error), ``persists`` where they do not;
- plane fails only, space fails only, both fail: an exception (`ConvergenceError`,
  `InputError`, any other) from one, both;
- both refuse: both raise an `InputError` naming the same argument (a scene without equilibrium,
  such as a line the seabed rising from the anchor pushes into compression, which both refuse
  by naming ``friction``: a loud failure, right for the scene);
- out of scope: the plane line refuses the scene because its slack stretch near the anchor ends
  at a clump resting on the seabed (``InputError("point_loads")``). A slack stretch itself is in
  scope: both lines model it (the plane line by friction holding each node's weight, the line in
  space by laying the stretch on the seabed).

Run:  python benchmarks/line_bvp_planes.py [--count N] [--seeds 1 2 3] [--progress]
      (about 10 minutes for the default 3 x 250 scenes on one core)
      python benchmarks/line_bvp_planes.py --show SEED:SCENE   (the scene as Python to paste)
Output: the tables on stdout (by seabed, point loads, length and elements; the distribution of
the differences; the times; every scene one driver fails and every disagreement but the line in
space's coarser mesh; the both-fail by error); benchmarks/out/line_bvp_planes.csv (every scene:
its outcome, the difference, the refinement's verdict, both times and both errors).
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
import time
import warnings
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).parent))
from _tables import counts_table, markdown_table  # noqa: E402

from skcable import mooring  # noqa: E402
from skcable.cable import sloped_seabed_catenary  # noqa: E402
from skcable.errors import ConvergenceError, InputError  # noqa: E402
from skcable.mooring.bathymetry import Plane  # noqa: E402
from skcable.mooring.line_bvp.space import solve_line_bvp_3d  # noqa: E402

#: end forces within this share of the largest: the two agree
TOLERANCE = 1e-6
OUTCOMES = (
    "agree", "disagree", "plane fails only", "space fails only", "both fail", "both refuse", "out of scope",
)  # fmt: skip
#: where the two disagree, both are solved again on these many times the elements, in turn (`refined`)
REFINE = (4, 16)
#: where they agree, the plane line on ``REFINE[0]`` times the elements moving more than this share of
#: the largest end force: both coarse alike (`converged`)
COARSE_ALIKE = 1e-4
#: weight per unit length (N/m) of the three kinds of segment (each drawn within ±20 %)
KINDS = {"chain": 1000.0, "wire": 80.0, "rope": 20.0}


@dataclass(frozen=True)
class Varying:
    """A weight varying along the line: ``w(s) = w0 (1 + amplitude sin(2π s/wavelength + phase))``
    (N/m, s the arc length from the anchor, m)."""

    w0: float
    amplitude: float
    wavelength: float
    phase: float

    def __call__(self, s):
        return self.w0 * (
            1.0 + self.amplitude * np.sin(2.0 * np.pi * np.asarray(s) / self.wavelength + self.phase)
        )

    def code(self) -> str:
        return (
            f"lambda s: {self.w0!r} * (1 + {self.amplitude!r} * np.sin(2 * np.pi * s / {self.wavelength!r} "
            f"+ {self.phase!r}))"
        )


@dataclass(frozen=True)
class Scene:
    """One line in the plane: ``span, dh`` (m), ``segments`` ``(length, w, EA)`` from the anchor
    (``w`` a number or a `Varying`), ``point_loads`` ``(s, P)`` (P > 0 down), ``seabed`` None or
    ``(height, slope)`` (``b(x) = height + slope x``, m), ``friction``, ``n_elements``."""

    span: float
    dh: float
    segments: tuple
    point_loads: tuple = ()
    seabed: tuple | None = None
    friction: float = 0.0
    n_elements: int = 64
    tags: dict = field(default_factory=dict, compare=False)

    def plane_seabed(self):
        if self.seabed is None:
            return dict(seabed=None)
        height, slope = self.seabed
        if slope == 0.0:
            return dict(seabed=height)
        return dict(seabed=height, seabed_slope=slope)  # the straight seabed b(x) = height + slope x

    def solve_plane(self):
        return mooring.solve_line_bvp(
            self.span, self.dh, list(self.segments), point_loads=list(self.point_loads),
            friction=self.friction, n_elements=self.n_elements, **self.plane_seabed(),
        )  # fmt: skip

    def solve_space(self):
        seabed = None if self.seabed is None else Plane(self.seabed[0], (self.seabed[1], 0.0))
        return solve_line_bvp_3d(
            (0.0, 0.0, 0.0), (self.span, 0.0, self.dh), list(self.segments),
            point_loads=list(self.point_loads), seabed=seabed, friction=self.friction,
            n_elements=self.n_elements,
        )  # fmt: skip

    def code(self) -> str:
        """The scene as Python: both solves and their difference."""

        def w(value):
            return value.code() if isinstance(value, Varying) else repr(value)

        segs = ", ".join(f"({length!r}, {w(wv)}, {ea!r})" for length, wv, ea in self.segments)
        if self.seabed is None:
            bed_plane, bed_space = "", ""
        elif self.seabed[1] == 0.0:
            bed_plane, bed_space = f", seabed={self.seabed[0]!r}", f", seabed={self.seabed[0]!r}"
        else:
            h, k = self.seabed
            bed_plane = f", seabed={h!r}, seabed_slope={k!r}"
            bed_space = f", seabed=Plane({h!r}, ({k!r}, 0.0))"
        loads = list(self.point_loads)
        common = f"point_loads={loads!r}, friction={self.friction!r}, n_elements={self.n_elements}"
        return "\n".join(
            [
                "import numpy as np",
                "from skcable import mooring",
                "from skcable.mooring.bathymetry import Plane",
                "from skcable.mooring.line_bvp.space import solve_line_bvp_3d",
                f"segments = [{segs}]",
                f"common = dict({common})",
                f"plane = mooring.solve_line_bvp({self.span!r}, {self.dh!r}, segments{bed_plane}, **common)",
                f"space = solve_line_bvp_3d((0.0, 0.0, 0.0), ({self.span!r}, 0.0, {self.dh!r}), segments"
                f"{bed_space}, **common)",
                "want = np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])",
                "got = np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])",
                "print(np.abs(got - want).max() / np.abs(want).max())",
            ]
        )


def _log_uniform(rng, low, high):
    return float(math.exp(rng.uniform(math.log(low), math.log(high))))


def _has_equilibrium(span, dh, length, shares, w0s, eas, seabed, friction) -> bool:
    """Whether the uniform line of the scene (its length, mean weight, the segments' EA in
    series) has an equilibrium on the seabed, by Jonkman's closed form on a slope
    (`skcable.cable.sloped_seabed_catenary`): not a heap, and without friction a taut anchor
    end (a slack end on a rising slope slides down it). With the anchor above the seabed, the
    closed form of the line anchored on the seabed under it, shorter by the drop (it hangs less
    of its length on the seabed than that line does)."""
    if seabed is None:
        return True
    height, slope = seabed
    w = float(np.dot(shares, w0s))
    ea = 1.0 / float(np.dot(shares, 1.0 / np.asarray(eas)))
    try:
        with warnings.catch_warnings():  # a taut line's strain past plausible: a screen, not an answer
            warnings.simplefilter("ignore")
            line = sloped_seabed_catenary(
                span, dh - height, w, ea, length=length + height, seabed_slope=slope, friction=friction
            )
    except (InputError, ConvergenceError):
        return False
    return friction > 0 or line.T_A > 0.02 * line.T_B


def _geometry(rng):
    """``(span, dh, seabed, friction, kind, length, shares, w0s, eas)`` of a scene, or None where
    its uniform line has no equilibrium even at 1.02 chords."""
    n = int(rng.integers(1, 4))
    span = _log_uniform(rng, 50.0, 2000.0)
    kind = str(rng.choice(["slope", "slope below", "below", "free"], p=[0.45, 0.15, 0.3, 0.1]))
    slope = float(rng.uniform(-0.1, 0.1)) if kind.startswith("slope") else 0.0
    rise = _log_uniform(rng, 0.02, 3.0) * span  # the fairlead's height above the seabed under it
    height = 0.0
    if kind in ("below", "slope below"):
        height = -float(rng.uniform(0.05, 0.8)) * rise
    dh = height + slope * span + rise if kind != "free" else float(span * rng.uniform(-1.0, 2.0))
    seabed = None if kind == "free" else (height, slope)
    friction = 0.0
    if seabed is not None and rng.uniform() < 0.2:
        friction = float(rng.choice([0.3, 0.6, 1.0]))
    chord = math.hypot(span, dh)
    w0s = [KINDS[str(rng.choice(list(KINDS)))] * float(rng.uniform(0.8, 1.2)) for _ in range(n)]
    eas = [_log_uniform(rng, 1e7, 1e10) for _ in range(n)]
    shares = rng.dirichlet(np.ones(n)) * 0.8 + 0.2 / n
    length = chord * float(rng.uniform(1.02, 2.0))
    for _ in range(8):  # shorter, towards 1.02 chords, until the uniform line has an equilibrium
        if _has_equilibrium(span, dh, length, shares, w0s, eas, seabed, friction):
            return span, dh, seabed, friction, kind, length, shares, w0s, eas
        length = 1.02 * chord + 0.6 * (length - 1.02 * chord)
    return None


def scene(rng) -> Scene:
    """One scene drawn from ``rng`` (module docstring): its seabed, ends, segments and length
    drawn again until the uniform line of it has an equilibrium (`_has_equilibrium`, its length
    shortened towards 1.02 chords up to 8 times first); then the weights varying along it and
    the point loads."""
    while True:
        drawn = _geometry(rng)
        if drawn is not None:
            break
    span, dh, seabed, friction, kind, length, shares, w0s, eas = drawn
    n, chord = len(shares), math.hypot(span, dh)
    segments, varying = [], False
    for share, w0, ea in zip(shares, w0s, eas, strict=True):
        w: float | Varying = w0
        if rng.uniform() < 0.3:
            w, varying = Varying(w0, float(rng.uniform(0.05, 0.5)), _log_uniform(rng, 0.1, 2.0) * length,
                                 float(rng.uniform(0, 2 * np.pi))), True  # fmt: skip
        segments.append((float(share * length), w, ea))

    joints = np.cumsum([0.0] + [s[0] for s in segments])
    weight = float(sum(s[0] * (s[1].w0 if isinstance(s[1], Varying) else s[1]) for s in segments))
    loads = []
    for sign, chance in ((1.0, 0.45), (-1.0, 0.25)):
        if rng.uniform() < chance:
            k = int(rng.integers(0, n))  # inside segment k, away from its ends
            s = float(joints[k] + rng.uniform(0.05, 0.95) * (joints[k + 1] - joints[k]))
            size = _log_uniform(rng, 0.01, 0.5 if sign > 0 else 0.3)
            loads.append((s, sign * size * weight))
    loads.sort()
    n_elements = int(rng.choice([64, 256], p=[0.6, 0.4]))
    load_tag = {0: "none", 1: "clump" if loads and loads[0][1] > 0 else "buoy", 2: "both"}[len(loads)]
    ratio = length / chord
    regime = "short" if ratio < 1.1 else ("mid" if ratio < 1.4 else "long")
    tags = dict(kind=kind, regime=regime, ratio=ratio, n=n, loads=load_tag, varying=varying)
    return Scene(span, dh, tuple(segments), tuple(loads), seabed, friction, n_elements, tags)


def scenes(seed: int, count: int):
    """``count`` scenes from the seed (a `numpy.random.default_rng`)."""
    rng = np.random.default_rng(seed)
    return [scene(rng) for _ in range(count)]


def _timed(solve):
    """(solution or None, seconds, message)."""
    start = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            out = solve()
    except Exception as exc:  # noqa: BLE001 - a failure is data here
        name = type(exc).__name__
        if isinstance(exc, InputError):
            name += f"({exc.argument})"
        return None, time.perf_counter() - start, f"{name}: {exc}"[:200]
    return out, time.perf_counter() - start, ""


def _refused(message) -> str:
    """The argument an `InputError` message names (``InputError(friction): ...``), else ``""``."""
    return message.split(")", 1)[0].removeprefix("InputError(") if message.startswith("InputError(") else ""


def _slack(sc, plane, m_plane, m_space) -> bool:
    """Whether the scene is out of scope: the plane line refuses it because its slack stretch
    near the anchor ends at a clump resting on the seabed (``InputError("point_loads")``: friction
    partly mobilised there, which neither line BVP models). Both model the stretch itself (the
    line in space since it lays it on the seabed): those scenes are compared."""
    return plane is None and m_plane.startswith("InputError(point_loads)")


def _plane_forces(plane):
    return np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])


def _space_forces(space):
    return np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])


def refined(sc, plane, space, difference):
    """Where the two disagree: both again on `REFINE` times the elements, in turn; (verdict,
    factor, the difference there, the plane's change, space's change), each over the largest
    end force. The verdict: ``mesh (space)``/``mesh (plane)`` at the first factor where the
    refined pair are within `TOLERANCE` or at least 4 times closer (a discretisation error of
    order h² falls 16 times at 4 times the elements; an element pinned between a fitted node
    and a joint may not shrink at the first) and that driver's end forces moved the most;
    ``persists`` where no factor brings them closer; ``refined fails`` where a refined solve
    fails."""
    for factor in REFINE:
        fine = replace(sc, n_elements=factor * sc.n_elements)
        plane_f, _, _ = _timed(fine.solve_plane)
        space_f, _, _ = _timed(fine.solve_space)
        if plane_f is None or space_f is None:
            return "refined fails", factor, "", "", ""
        want, got = _plane_forces(plane_f), _space_forces(space_f)
        scale = np.abs(want).max()
        gap = float(np.abs(got - want).max() / scale)
        moved_plane = float(np.abs(_plane_forces(plane) - want).max() / scale)
        moved_space = float(np.abs(_space_forces(space) - got).max() / scale)
        if gap <= TOLERANCE or 4.0 * gap <= difference:
            verdict = "mesh (space)" if moved_space > moved_plane else "mesh (plane)"
            return verdict, factor, gap, moved_plane, moved_space
    return "persists", factor, gap, moved_plane, moved_space


def converged(sc, plane):
    """Where the two agree: the plane line again on ``REFINE[0]`` times the elements; (verdict,
    factor, "", the plane's change over the largest end force, ""). Agreement is not
    correctness: the two share their law and their meshes' grading, so a mesh that misses a
    feature of the line can leave both wrong alike (a buoy's arch in one element held the buoy
    down in both, 4.7e-3 of the largest force off, scene 2:117). The verdict: ``both coarse``
    where the plane line moved more than `COARSE_ALIKE`, else ``converged``; ``refined fails``
    where the refined solve fails."""
    factor = REFINE[0]
    fine, _, _ = _timed(replace(sc, n_elements=factor * sc.n_elements).solve_plane)
    if fine is None:
        return "refined fails", factor, "", "", ""
    want = _plane_forces(fine)
    moved = float(np.abs(_plane_forces(plane) - want).max() / np.abs(want).max())
    return ("both coarse" if moved > COARSE_ALIKE else "converged"), factor, "", moved, ""


def classify(sc):
    """(outcome, difference, plane seconds, space seconds, plane message, space message, and
    where they disagree `refined`'s verdict, the refined difference and the two changes,
    whether the plane line's resolution check flags it, `LineBVPSolution.unresolved`, and whether
    the plane line holds a slack stretch)."""
    plane, t_plane, m_plane = _timed(sc.solve_plane)
    space, t_space, m_space = _timed(sc.solve_space)
    difference: float | str = ""
    verdict: tuple = ("", "", "", "", "")
    if _refused(m_plane) and _refused(m_plane) == _refused(m_space):
        outcome = "both refuse"
    elif _slack(sc, plane, m_plane, m_space):
        outcome = "out of scope"
    elif plane is None and space is None:
        outcome = "both fail"
    elif plane is None:
        outcome = "plane fails only"
    elif space is None:
        outcome = "space fails only"
    else:
        want, got = _plane_forces(plane), _space_forces(space)
        difference = float(np.abs(got - want).max() / np.abs(want).max())
        outcome = "agree" if difference <= TOLERANCE else "disagree"
        verdict = refined(sc, plane, space, difference) if outcome == "disagree" else converged(sc, plane)
    flagged = bool(plane.unresolved()) if plane is not None else ""
    slack = plane is not None and plane.problem.slack_end > 0
    return outcome, difference, t_plane, t_space, m_plane, m_space, *verdict, flagged, slack


HEADER = (
    "seed", "scene", "kind", "regime", "ratio", "segments", "loads", "varying", "friction", "n_elements",
    "outcome", "difference", "plane_seconds", "space_seconds", "plane_message", "space_message",
    "refined", "refined_factor", "refined_difference", "plane_change", "space_change", "unresolved",
    "plane_slack",
)  # fmt: skip


def run(seeds, count, progress=False):
    """A row (a dict over `HEADER`) per scene."""
    rows = []
    for seed in seeds:
        for k, sc in enumerate(scenes(seed, count)):
            t = sc.tags
            out = classify(sc)
            described = (
                seed,
                k,
                t["kind"],
                t["regime"],
                round(t["ratio"], 4),
                t["n"],
                t["loads"],
                t["varying"],
            )
            rows.append(dict(zip(HEADER, (*described, sc.friction, sc.n_elements, *out), strict=True)))
            if progress and out[0] not in ("agree", "out of scope"):
                print(f"  {_described(rows[-1])}: {out[0]}: {_what(rows[-1])[:150]}", flush=True)
    return rows


def _table(rows, column, values):
    return counts_table(column, values, OUTCOMES, Counter((r[column], r["outcome"]) for r in rows))


def report(rows, seeds, count):
    """The tables, the distribution of the differences, the times and the cases to look at."""
    counts = Counter(r["outcome"] for r in rows)
    lines = [
        f"{len(seeds)} seeds ({' '.join(map(str, seeds))}) x {count} scenes:",
        "",
        *markdown_table(OUTCOMES, [[counts.get(o, 0) for o in OUTCOMES]]),
        "",
    ]
    scope = [r for r in rows if r["outcome"] == "out of scope"]
    if scope:
        lines += [
            f"out of scope: the plane line refuses {len(scope)} scenes whose slack stretch ends at a clump "
            "on the seabed",
        ]
    slack = [r for r in rows if r["plane_slack"]]
    if slack:
        lines += [
            f"with a slack stretch (the plane line's): {len(slack)}, "
            + ", ".join(f"{o} {n}" for o, n in Counter(r["outcome"] for r in slack).most_common()),
        ]
    both_fail = [r for r in rows if r["outcome"] == "both fail"]
    if both_fail:
        above = sum(r["friction"] > 0 and r["kind"] in ("below", "slope below") for r in both_fail)
        said = sum("fully mobilised (μ" in r["plane_message"] for r in both_fail)
        lines += [
            f"both fail: {above} of {len(both_fail)} with friction and the anchor above the seabed; the "
            f"plane line says in {said} that friction fully mobilised may take more than the pull",
            "",
        ]
    for column, values in (
        ("kind", ("slope", "slope below", "below", "free")),
        ("loads", ("none", "clump", "buoy", "both")),
        ("regime", ("short", "mid", "long")),
        ("n_elements", (64, 256)),
    ):
        lines += [*_table(rows, column, values), ""]
    both = [r for r in rows if r["difference"] != ""]
    if both:
        diff = np.array([r["difference"] for r in both])
        q = np.quantile(diff, [0.5, 0.9, 0.99, 1.0])
        lines.append(
            f"difference of the end forces / the largest, both solved ({diff.size}): median {q[0]:.2g}, "
            f"90th percentile {q[1]:.2g}, 99th {q[2]:.2g}, max {q[3]:.2g}"
        )
        for n in (64, 256):
            d = np.array([r["difference"] for r in both if r["n_elements"] == n])
            if d.size:
                q = np.quantile(d, [0.5, 0.9, 1.0])
                lines.append(f"  {n} elements ({d.size}): median {q[0]:.2g}, 90th {q[1]:.2g}, max {q[2]:.2g}")
        for name in ("plane", "space"):
            t = np.array([r[f"{name}_seconds"] for r in both])
            lines.append(
                f"{name} solve, both solved: median {1e3 * np.median(t):.0f} ms, 90th percentile "
                f"{1e3 * np.quantile(t, 0.9):.0f} ms, max {1e3 * t.max():.0f} ms (this machine, one process)"
            )
    verdicts = Counter(r["refined"] for r in rows if r["outcome"] == "disagree")
    if verdicts:
        lines.append(
            f"disagreements on {' or '.join(map(str, REFINE))} times the elements: "
            + ", ".join(
                f"{v} {verdicts[v]}" for v in ("mesh (space)", "mesh (plane)", "persists", "refined fails")
            )
        )
    agreeing = [r for r in rows if r["outcome"] == "agree"]
    if agreeing:
        alike = Counter(r["refined"] for r in agreeing)
        moved = [r for r in agreeing if r["plane_change"] != ""]
        worst = max(moved, key=lambda r: r["plane_change"], default=None)
        lines.append(
            f"agreements, the plane line on {REFINE[0]} times the elements: converged {alike['converged']}, "
            f"both coarse {alike['both coarse']} (moved more than {COARSE_ALIKE:g} of the largest force), "
            f"refined fails {alike['refined fails']}"
            + (
                f"; moved at most {worst['plane_change']:.2g} (seed {worst['seed']} scene {worst['scene']})"
                if worst
                else ""
            )
        )
    checked = {
        verdict: [r["unresolved"] for r in agreeing if r["refined"] == verdict]
        for verdict in ("both coarse", "converged")
    }
    if any(checked.values()):
        lines.append(
            "the plane line's resolution check (`ResolutionWarning`) flagged "
            + ", ".join(f"{sum(v)} of the {len(v)} {verdict}" for verdict, v in checked.items())
        )
    lines += [
        "",
        "Each scene one driver fails, each disagreement but space's coarser mesh and each agreement "
        "both coarse alike (all in the CSV):",
    ]
    for r in rows:
        listed = r["outcome"] in ("plane fails only", "space fails only")
        if r["outcome"] == "disagree" and r["refined"] != "mesh (space)":
            listed = True
        if r["outcome"] == "agree" and r["refined"] != "converged":
            listed = True
        if listed:
            lines.append(f"- {r['outcome']}: {_described(r)}: {_what(r)[:160]}")
    causes = Counter(_cause(r["plane_message"]) + " / " + _cause(r["space_message"]) for r in both_fail)
    if causes:
        lines += ["", "both fail, by the plane's / space's error:"]
        lines += [f"- {count}: {cause}" for cause, count in causes.most_common()]
    return "\n".join(lines)


def _described(r) -> str:
    return (
        f"seed {r['seed']} scene {r['scene']} ({r['kind']}, {r['ratio']} chords, {r['segments']} segments, "
        f"loads {r['loads']}, varying {r['varying']}, μ {r['friction']}, {r['n_elements']} elements)"
    )


def _what(r) -> str:
    if r["outcome"] == "agree":
        moved = (
            ""
            if r["plane_change"] == ""
            else f" (x{r['refined_factor']}: plane moved {r['plane_change']:.2g})"
        )
        return f"{r['difference']:.2g}, {r['refined']}{moved}"
    if r["outcome"] != "disagree":
        return r["plane_message"] or r["space_message"]
    what = f"{r['difference']:.2g}, {r['refined']}"
    if r["refined_difference"] != "":
        what += (
            f" (x{r['refined_factor']}: {r['refined_difference']:.2g} apart, plane moved "
            f"{r['plane_change']:.2g}, space {r['space_change']:.2g})"
        )
    return what


def _cause(message: str) -> str:
    """The kind of a solver's error, without its numbers."""
    causes = (
        "compression",
        "stagnates",
        "no descent",
        "no convergence",
        "singular",
        "slack stretch",
        "no sign change",
    )
    for cause in causes:
        if cause in message:
            return cause
    return message.split(":")[0] or "solved"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=250)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--show", help="SEED:SCENE: print the scene as Python and exit")
    parser.add_argument("--progress", action="store_true", help="print each scene that is not agreed")
    args = parser.parse_args(argv)
    if args.show:
        seed, k = (int(v) for v in args.show.split(":"))
        print(scenes(seed, k + 1)[k].code())
        return
    rows = run(args.seeds, args.count, args.progress)
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    path = out / "line_bvp_planes.csv"
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, HEADER)
        writer.writeheader()
        writer.writerows(rows)
    tmp.replace(path)
    print(report(rows, args.seeds, args.count))


if __name__ == "__main__":
    main()
