"""Survey of `solve_line_bvp` over seeded scenes that the closed-form `mooring.Line` solves.

The scenes are those of ``tests/mooring/line_scenes.py`` (the CI test runs a sample of them): one
to three segments of chain, wire or rope (weights 1 to 3000 N/m, ``EA/(wL)`` 1e2 to 1e9), a
clump weight at a joint or none, no seabed, a flat seabed through the anchor (friction 0, 0.3,
1) or one below it, lengths from 0.98 to 3 chords. Each scene is solved by ``mooring.Line``
(the reference; for one-segment lines also a 60-digit mpmath closure) and by
``solve_line_bvp`` at its default 64 elements, again at 256 where the 64-element fairlead force
is farther from the reference than the tolerance (``line_scenes.tolerance``: 1e-6 of the
largest tension, or 64 ε times the condition number of H where larger). Outcomes:

- right: within the tolerance at 64 elements; right at 256: within it at 256 (the 64-element
  mesh did not resolve a bend);
- heap refused: ``Line`` finds the slack in a heap on the seabed (H = 0) and the BVP refuses
  the scene with ``InputError("length")``, the right answer;
- clump refused: the BVP's documented refusal (``InputError("point_loads")``): the slack
  stretch near the anchor ends at a clump weight whose friction is partly mobilised;
- wrong: farther than the tolerance at 256 elements too; failed: any other exception;
- not counted: ``Line`` refuses the scene itself (a second touchdown, a buoy on the seabed).

Run:  python benchmarks/line_bvp_survey.py [--count N] [--seeds 1 2 3]   (about 3 minutes
      for the default 3 x 2500 scenes on one core)
Output: the table on stdout and in docs/bvp.md between the survey markers;
benchmarks/out/line_bvp_survey.csv (every scene, its outcome, error and time).
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
import time
import warnings
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).parent))
from _tables import counts_table, markdown_table, write_section  # noqa: E402

from skcable.errors import InputError  # noqa: E402
from tests.mooring.line_scenes import exact_one_segment, scenes, tolerance  # noqa: E402

OUTCOMES = ("right", "right at 256", "heap refused", "clump refused", "wrong", "failed")


def _error(b, H, V_B, scale):
    return math.hypot(b.H - H, b.V_B - V_B) / scale


def classify(sc):
    """(outcome, error, seconds of the 64-element solve, message) of one scene, or None where
    `Line` refuses it."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            line = sc.line().solve(sc.span, sc.dh)
    except InputError:
        return None
    start = time.perf_counter()
    try:
        b = sc.solve_bvp()
    except InputError as refused:
        seconds = time.perf_counter() - start
        if line.heap and refused.argument == "length":
            return "heap refused", "", seconds, ""
        if not line.heap and refused.argument == "point_loads":
            return "clump refused", "", seconds, str(refused)[:120]
        return "failed", "", seconds, f"InputError: {refused}"[:160]
    except Exception as exc:  # noqa: BLE001 - a failure is data here
        return "failed", "", time.perf_counter() - start, f"{type(exc).__name__}: {exc}"[:160]
    seconds = time.perf_counter() - start
    if line.heap:
        return "wrong", "", seconds, f"returned H = {b.H:g} where Line finds a heap"
    scale, tol = max(line.T_A, line.T_B), tolerance(sc, line)
    reference = (line.H, line.V_B)
    if len(sc.segments) == 1 and sc.clump is None and not line.length_on_seabed:
        reference = exact_one_segment(sc, reference) or reference
    error = _error(b, *reference, scale)
    if error <= tol:
        return "right", error, seconds, ""
    try:
        error = _error(sc.solve_bvp(n_elements=256), *reference, scale)
    except Exception as exc:  # noqa: BLE001
        return "failed", "", seconds, f"at 256 elements: {type(exc).__name__}: {exc}"[:160]
    return ("right at 256" if error <= tol else "wrong"), error, seconds, ""


def run(seeds, count):
    rows = []
    for seed in seeds:
        for k, sc in enumerate(scenes(seed, count)):
            out = classify(sc)
            if out is not None:
                rows.append((seed, k, sc.tags["kind"], sc.tags["regime"], sc.tags["n"], *out))
    return rows


def report(rows, seeds, count):
    counts = Counter(r[5] for r in rows)
    times = np.array([r[7] for r in rows if r[5] in ("right", "right at 256")])
    lines = [
        f"{len(seeds)} seeds x {count} scenes, {len(rows)} that `mooring.Line` solves or finds a heap in:",
        "",
        *markdown_table(OUTCOMES, [[counts.get(o, 0) for o in OUTCOMES]]),
        "",
        f"64-element solve: median {1e3 * np.median(times):.1f} ms, 90th percentile "
        f"{1e3 * np.quantile(times, 0.9):.1f} ms (this machine, one process).",
    ]
    by_regime = Counter((r[3], r[5]) for r in rows)
    lines += ["", *counts_table("regime", ("taut", "mid", "slack"), OUTCOMES, by_regime)]
    bad = [r for r in rows if r[5] in ("wrong", "failed")]
    for r in bad[:10]:
        lines.append(f"- {r[5]}: seed {r[0]} scene {r[1]} ({r[2]}, {r[3]}, {r[4]} segments): {r[8] or r[6]}")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=2500)
    parser.add_argument("--seeds", type=int, nargs="+", default=[2, 3, 4])
    args = parser.parse_args(argv)
    rows = run(args.seeds, args.count)
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    path = out / "line_bvp_survey.csv"
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        header = ("seed", "scene", "kind", "regime", "segments", "outcome", "error", "seconds", "message")
        csv.writer(f).writerows([header, *rows])
    tmp.replace(path)
    body = report(rows, args.seeds, args.count)
    print(body)
    write_section(ROOT / "docs" / "bvp.md", "line-bvp-survey", body.split("\n"))


if __name__ == "__main__":
    main()
