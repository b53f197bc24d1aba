"""The 3-D line BVP (`skcable.mooring.line_bvp.space`): time per solve, medians of repeated solves.

    python benchmarks/bench_line3d.py              # 21 repeats of each scene
    python benchmarks/bench_line3d.py --repeat 51
    python benchmarks/bench_line3d.py --repeat 5 --scenes 1,8,9   # the three targets

Scenes, each from its closed-form start (the default path of `solve_line_bvp_3d`, every check
included: the equilibrium residual by scikit-fem's own assembly, the touchdown fitted on a
seabed):

1. a 500 m chain in a uniform cross current at 200 elements (issue 23's target: <= 20 ms);
2. the same in a sheared current tabulated over depth;
3. a chain on a bilinear grid seabed with friction, in a current, at 200 elements;
4. for scale, the plane `solve_line_bvp` of the chain without current at 200 elements (one
   process, the same machine: the ratio is what a quiet machine reproduces);
5. `mooring.line_3d` of a `mooring.Line` in a current: the model chosen (the 3-D BVP on
   `BVP_ELEMENTS` elements), as a user calls it (its error estimate, a second solve on half as
   many elements when first asked for, is printed but not timed);
6. `mooring.line_3d` of a chain-polyester `mooring.Line` in still water: the closed form with the
   rope's nonlinear law integrated exactly;
7. twelve lines of a spread mooring in a current, each by `mooring.line_3d`: one evaluation of the
   lines of a 12-line system, cold;
8. a 12-line `mooring.MooringSystem` of those lines (built with ``current=``, taut, clear of the
   seabed) reaching its equilibrium (issue 23's target: <= 1 s), the lines warm-started by the
   system from their previous solutions;
9. the same with chains that rest on the seabed (a touchdown fitted on every solve; the same
   1 s target).

Prints, per scene, the median and the spread (min, max) of the wall time, the Newton iterations
and the largest equilibrium residual over the weight per length.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from skcable import mooring
from skcable.bvp.current import TabulatedCurrent
from skcable.mooring import solve_line_bvp
from skcable.mooring.axial import StrainTable
from skcable.mooring.bathymetry import Grid
from skcable.mooring.line_bvp.space import LineSegment, solve_line_bvp_3d

TARGET_MS = 20.0
ANCHOR, FAIRLEAD = np.array([0.0, 0.0, -200.0]), np.array([400.0, 0.0, -20.0])
CHAIN = LineSegment(500.0, 600.0, 4e8, 0.1, 1.2, 0.008)


def grid():
    xs, ys = np.linspace(-100, 900, 21), np.linspace(-300, 300, 13)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    return Grid(xs, ys, -200 + 0.03 * X + 10 * np.sin(X / 150) * np.cos(Y / 120))


def sea_line(current=(0.0, 0.9)):
    """The chain of scene 1 as a `mooring.Line` (in a current unless ``current`` is None)."""
    seg = mooring.Segment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2, cd_tangential=0.008)
    return mooring.Line([seg], current=current)


def polyester():
    rope = StrainTable([0.0, 0.01, 0.02, 0.03, 0.05], [0.0, 1.2e6, 3.0e6, 5.2e6, 1.0e7])
    return mooring.Line([mooring.Segment(60.0, 1800.0, 1.5e9), mooring.Segment(560.0, 60.0, rope)])


def twelve_lines():
    """Twelve lines 30° apart, each from its anchor to a fairlead 20 m from the centre."""
    line = sea_line((0.6, 0.3))
    angles = np.radians(np.arange(12) * 30.0)
    c, s = np.cos(angles), np.sin(angles)
    anchors = np.column_stack([420.0 * c, 420.0 * s, np.full(12, -200.0)])
    fairleads = np.column_stack([20.0 * c, 20.0 * s, np.full(12, -20.0)])
    return lambda: [mooring.line_3d(line, a, b) for a, b in zip(anchors, fairleads, strict=True)]


def spread(line, radius=420.0, depth=200.0):
    """A rigid platform on twelve copies of ``line``, 30° apart (anchors at ``radius``, m)."""
    angles = np.radians(np.arange(12) * 30.0)
    c, s = np.cos(angles), np.sin(angles)
    anchors = np.column_stack([radius * c, radius * s, np.full(12, -depth)])
    fairleads = np.column_stack([20.0 * c, 20.0 * s, np.full(12, -20.0)])
    body = mooring.RigidBody(
        fairleads, mass=8e6, volume=8.2e3, center_of_gravity=(0.0, 0.0, -5.0), metacentre=(0.0, 0.0, 10.0),
        waterplane_area=600.0,
    )  # fmt: skip
    return mooring.MooringSystem(body, [line] * 12, anchors, depth=depth)


def taut_system():
    seg = mooring.Segment(440.0, 300.0, 4e8, diameter=0.1, cd_normal=1.2, cd_tangential=0.008)
    return spread(mooring.Line([seg], seabed=0.0, current=(0.6, 0.3)))


def grounded_system():
    seg = mooring.Segment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2, cd_tangential=0.008)
    return spread(mooring.Line([seg], seabed=0.0, current=(0.6, 0.3)))


def scenes():
    table = TabulatedCurrent([0.0, 50.0, 150.0, 400.0], [[0.9, 0.3], [0.7, 0.35], [0.35, 0.2], [0.1, 0.05]])
    bed = grid()
    a = np.array([0.0, 0.0, float(bed.height(0.0, 0.0))])
    grounded = LineSegment(660.0, 1000.0, 5e8, 0.09, 2.4, 0.4)
    return {
        "3-D, uniform cross current, 200 elements": lambda: solve_line_bvp_3d(
            ANCHOR, FAIRLEAD, [CHAIN], current=(0.0, 0.9), n_elements=200
        ),
        "3-D, tabulated sheared current, 200 elements": lambda: solve_line_bvp_3d(
            ANCHOR, FAIRLEAD, [CHAIN], current=table, n_elements=200
        ),
        "3-D, grid seabed, friction, current, 200 elements": lambda: solve_line_bvp_3d(
            a, (600.0, 50.0, -20.0), [grounded], seabed=bed, friction=0.15, current=(0.2, 0.6), n_elements=200
        ),
        "2-D solve_line_bvp, no current, 200 elements": lambda: solve_line_bvp(
            400.0, 180.0, [(500.0, 600.0, 4e8)], n_elements=200
        ),
        "mooring.line_3d, Line in a current (BVP; its error estimate, asked after, untimed)": lambda: (
            mooring.line_3d(sea_line(), ANCHOR, FAIRLEAD)
        ),
        "mooring.line_3d, chain-polyester Line, closed form with its law": lambda: mooring.line_3d(
            polyester(), ANCHOR, FAIRLEAD + [200.0, 0.0, 0.0]
        ),
        "12 lines in a current by mooring.line_3d (one evaluation)": twelve_lines(),
        "12-line MooringSystem in a current, taut lines, equilibrium": lambda: taut_system().equilibrium(),
        "12-line MooringSystem in a current, grounded chains, equilibrium": lambda: (
            grounded_system().equilibrium()
        ),
    }


def timed(solve, repeat):
    solve()  # warm: imports, caches
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = solve()
        times.append(time.perf_counter() - start)
    return 1e3 * np.array(times), result


def verdicts(medians):
    """The targets and the ratios of the scenes that ran (ms medians by name)."""
    names = list(scenes())
    first, plane, taut, grounded = (medians.get(names[k]) for k in (0, 3, 7, 8))
    if first is not None:
        print(f"target <= {TARGET_MS:g} ms for scene 1: {'met' if first <= TARGET_MS else 'NOT met'}")
    if first is not None and plane is not None:
        print(f"scene 1 over the plane solve: {first / plane:.2f}")
    for label, ms in (("taut", taut), ("grounded", grounded)):
        if ms is not None:
            print(f"target <= 1000 ms for the {label} 12-line system: {'met' if ms <= 1000.0 else 'NOT met'}")
    if taut is not None and first is not None:
        print(f"the taut 12-line system over scene 1: {taut / first:.0f} (a load-free measure)")
    if taut is not None and grounded is not None:
        print(f"the grounded 12-line system over the taut one: {grounded / taut:.2f} (a load-free measure)")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=21)
    parser.add_argument("--scenes", default="", help="comma-separated scene numbers (1-9; all by default)")
    args = parser.parse_args(argv)
    chosen = {int(k) for k in args.scenes.split(",") if k.strip()}
    medians = {}
    for number, (name, solve) in enumerate(scenes().items(), start=1):
        if chosen and number not in chosen:
            continue
        ms, result = timed(solve, args.repeat)
        medians[name] = float(np.median(ms))
        residual = getattr(result, "equilibrium_residual", None)
        extra = ""
        if hasattr(result, "iterations") and hasattr(result, "lines"):
            extra = f", {result.iterations} Newton iterations of the system"
        elif hasattr(result, "model") and hasattr(result.model, "name"):
            extra = f", {result.model.name}, estimated error {result.model.error:.1e}"
        elif residual is not None:
            w = max(abs(seg.w) for seg in result.problem.segments)
            extra = f", {result.iterations} iterations, residual {residual / w:.1e} w"
        print(
            f"{number}. {name}: median {medians[name]:.1f} ms (min {ms.min():.1f}, max {ms.max():.1f}){extra}"
        )
    verdicts(medians)


if __name__ == "__main__":
    main()
