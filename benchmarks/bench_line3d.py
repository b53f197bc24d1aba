"""The 3-D line BVP (`skcable.cable.bvp.line3d`): time per solve, medians of repeated solves.

    python benchmarks/bench_line3d.py              # 21 repeats of each scene
    python benchmarks/bench_line3d.py --repeat 51

Scenes, each from its closed-form start (the default path of `solve_line_bvp_3d`, every check
included: the equilibrium residual by scikit-fem's own assembly, the touchdown fitted on a
seabed):

1. a 500 m chain in a uniform cross current at 200 elements (issue 23's target: <= 20 ms);
2. the same in a sheared current tabulated over depth;
3. a chain on a bilinear grid seabed with friction, in a current, at 200 elements;
4. for scale, the plane `solve_line_bvp` of the chain without current at 200 elements (one
   process, the same machine: the ratio is what a quiet machine reproduces).

Prints, per scene, the median and the spread (min, max) of the wall time, the Newton iterations
and the largest equilibrium residual over the weight per length.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from skcable.cable.bathymetry import Grid
from skcable.cable.bvp import solve_line_bvp
from skcable.cable.bvp.line3d import LineSegment, solve_line_bvp_3d
from skcable.cable.current import TabulatedCurrent

TARGET_MS = 20.0
ANCHOR, FAIRLEAD = np.array([0.0, 0.0, -200.0]), np.array([400.0, 0.0, -20.0])
CHAIN = LineSegment(500.0, 600.0, 4e8, 0.1, 1.2, 0.008)


def grid():
    xs, ys = np.linspace(-100, 900, 21), np.linspace(-300, 300, 13)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    return Grid(xs, ys, -200 + 0.03 * X + 10 * np.sin(X / 150) * np.cos(Y / 120))


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
    }


def timed(solve, repeat):
    solve()  # warm: imports, caches
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = solve()
        times.append(time.perf_counter() - start)
    return 1e3 * np.array(times), result


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=21)
    args = parser.parse_args(argv)
    medians = {}
    for name, solve in scenes().items():
        ms, result = timed(solve, args.repeat)
        medians[name] = float(np.median(ms))
        residual = getattr(result, "equilibrium_residual", None)
        extra = ""
        if residual is not None:
            w = max(abs(seg.w) for seg in result.problem.segments)
            extra = f", {result.iterations} iterations, residual {residual / w:.1e} w"
        print(f"{name}: median {medians[name]:.1f} ms (min {ms.min():.1f}, max {ms.max():.1f}){extra}")
    first = next(iter(medians))
    verdict = "met" if medians[first] <= TARGET_MS else "NOT met"
    print(f"target <= {TARGET_MS:g} ms for scene 1: {verdict}")
    plane = medians["2-D solve_line_bvp, no current, 200 elements"]
    print(f"scene 1 over the plane solve: {medians[first] / plane:.2f}")


if __name__ == "__main__":
    main()
