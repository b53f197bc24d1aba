"""The cost of cable terms in the line BVP: the same 200-element line with and without them.

    python benchmarks/bench_line_terms.py              # 7 rounds, medians
    python benchmarks/bench_line_terms.py --rounds 15

Two lines of 200 elements: a chain (440 m, 1000 N/m, EA 5e8 N) grounded on a flat seabed from
(0, 0) to (400, 100) m, and the same line suspended (no seabed) from (0, 0) to (420, 100) m.
Each is timed, in this process and interleaved round by round, without terms and with
`Buoyancy` (depth-varying density), with `CurrentDrag` (a sheared current, normal and
tangential drag) and with both. Two measures per case:

- **assembly**: one `LineProblem.assemble` (residual, element tangents, contact rows) at the
  converged state of the terms' line, on the same problem with and without the terms;
- **solve**: one whole `solve_line_bvp` (the continuation: gradings, touchdown fitting).

Printed: the medians over the rounds (ms) and their ratios to the line without terms. A ratio of
whole solves also counts the iterations the terms change (their line is another line).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the skcable of this checkout

from skcable import bvp, mooring  # noqa: E402
from skcable.mooring.line_bvp.driver import LineBVPSolver  # noqa: E402
from skcable.mooring.line_bvp.inputs import (
    LINE_OPTIONS,  # noqa: E402
    scene,  # noqa: E402
)

N_ELEMENTS = 200
SEGMENTS = [(440.0, 1000.0, 5e8)]
LINES = {"grounded": (400.0, 100.0, {"seabed": 0.0}), "suspended": (420.0, 100.0, {})}
TERMS = {
    "none": [],
    "buoyancy": [bvp.Buoyancy(0.04, gradient=0.05, surface=120.0)],
    "current": [bvp.CurrentDrag(lambda d: 1.5 * (1 - d / 300), 0.1, cd_tangential=0.01, surface=120.0)],
}
TERMS["both"] = TERMS["buoyancy"] + TERMS["current"]


def timed(fn, repeats: int) -> float:
    """Seconds per call of ``fn`` (mean over ``repeats`` calls)."""
    start = time.perf_counter()
    for _ in range(repeats):
        fn()
    return (time.perf_counter() - start) / repeats


def problem_of(span, dh, kw, terms, nodes):
    """The line's discrete problem on the mesh ``nodes`` (that of the terms' solution)."""
    sc = scene(
        span, dh, SEGMENTS, seabed=kw.get("seabed"), seabed_slope=None, friction=0.0, point_loads=(),
        n_elements=N_ELEMENTS, fit_touchdown=2, options=LINE_OPTIONS, terms=terms,
    )  # fmt: skip
    return LineBVPSolver(sc).problem(nodes.size - 1, nodes_at=nodes)


def cases():
    """``(line, terms) -> (solve, assemble)`` callables."""
    out = {}
    for line, (span, dh, kw) in LINES.items():
        for name, terms in TERMS.items():
            solution = mooring.solve_line_bvp(span, dh, SEGMENTS, n_elements=N_ELEMENTS, terms=terms, **kw)
            nodes = solution.problem.mesh.p[0]
            problem = problem_of(span, dh, kw, terms, nodes)
            z = solution.dofs

            def solve(span=span, dh=dh, kw=kw, terms=terms):
                return mooring.solve_line_bvp(span, dh, SEGMENTS, n_elements=N_ELEMENTS, terms=terms, **kw)

            out[line, name] = (solve, lambda problem=problem, z=z: problem.assemble(z), solution.iterations)
    return out


def main(rounds: int) -> None:
    table = cases()
    times = {key: ([], []) for key in table}
    for _ in range(rounds):
        for key, (solve, assemble, _) in table.items():
            times[key][0].append(timed(solve, 3))
            times[key][1].append(timed(assemble, 50))
    print(f"line BVP, {N_ELEMENTS} elements, medians of {rounds} rounds (ratios to the line without terms)")
    columns = ("assembly ms", "ratio", "solve ms", "ratio", "iterations")
    print(
        f"{'line':10s} {'terms':9s} "
        + " ".join(f"{c:>{w}s}" for c, w in zip(columns, (12, 6, 9, 6, 10), strict=True))
    )
    for (line, name), (solve_t, assemble_t) in times.items():
        base_solve, base_assemble = (statistics.median(t) for t in times[line, "none"])
        a, s = statistics.median(assemble_t), statistics.median(solve_t)
        iterations = table[line, name][2]
        print(
            f"{line:10s} {name:9s} {1e3 * a:12.3f} {a / base_assemble:6.2f} {1e3 * s:9.2f} "
            f"{s / base_solve:6.2f} {iterations:10d}"
        )


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    main(parser.parse_args().rounds)
