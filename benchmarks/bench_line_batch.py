"""Lines of one model solved together on arrays against line by line: where batching pays.

A spread mooring of ``n`` identical chain lines (120 mm studless, 850 m, anchors 800 m out on
a seabed 200 m deep) on one body; its lines are solved at the equilibrium moved by 1 m surge
and 1/3 m sway, warm-started from the equilibrium's lines (`MooringSystem.solve_lines(position,
start=...)`, as every evaluation of an equilibrium does), once with the lines of the model
solved together (`skcable.mooring.choice.solve_many_between`) and once line by line.
The ratio batched / line by line, median over alternating rounds, sets
`skcable.mooring.choice.BATCH` (where it falls below 1).

Run:  python benchmarks/bench_line_batch.py [--repeat 7]
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the skcable of this checkout
from bench_system import skcable_scene  # noqa: E402

from skcable.mooring import choice, system  # noqa: E402


def _solve(moored, q, lines, batch):
    """The lines solved at ``q``, batched from ``batch`` lines of a model (the threshold that the
    system and `solve_many_between` read, set for the call)."""
    default = choice.BATCH
    system.BATCH = choice.BATCH = batch
    try:
        return moored.solve_lines(q, start=lines)
    finally:
        system.BATCH = choice.BATCH = default


def run(repeat: int) -> str:
    from threadpoolctl import threadpool_limits

    rows = ["| lines | batched [ms] | line by line [ms] | ratio (median) |", "|---|---|---|---|"]
    with threadpool_limits(1), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for n in (4, 8, 16, 24, 32, 48, 96):
            moored, loads = skcable_scene(1, n)
            eq = moored.equilibrium(force=loads)
            q = eq.position + np.array([1.0, 1.0 / 3.0, 0.0, 0.0, 0.0, 0.0])
            together, alone = _solve(moored, q, eq.lines, 1), _solve(moored, q, eq.lines, 10**9)
            gap = max(
                float(np.abs(a.end_forces - b.end_forces).max()) for a, b in zip(together, alone, strict=True)
            )
            assert gap <= 1e-9 * max(float(np.abs(b.end_forces).max()) for b in alone), gap  # the same lines
            times = {1: [], 10**9: []}
            for _ in range(repeat):
                for batch in times:
                    t0 = time.process_time()
                    for _ in range(20):
                        _solve(moored, q, eq.lines, batch)
                    times[batch].append((time.process_time() - t0) / 20)
            ratio = float(np.median(np.array(times[1]) / np.array(times[10**9])))
            batched, alone_ms = np.median(times[1]) * 1e3, np.median(times[10**9]) * 1e3
            rows.append(f"| {n} | {batched:.3f} | {alone_ms:.3f} | {ratio:.2f} |")
    return "\n".join(rows)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    print(run(parser.parse_args().repeat))
    print(f"BATCH = {choice.BATCH}")


if __name__ == "__main__":
    main()
