"""The strand's stick curve timed in this checkout and in another one, alternating processes.

The curve of `benchmarks/bench_targets.py` (the steel 9.5 mm strand with one broken wire,
32 elements, 40 steps, as `bench_strand_opensees.py` defines it) run in a fresh Python process
with ``PYTHONPATH`` set to each checkout in turn, ``--rounds`` times; each process warms up once,
then times ``--runs`` curves by CPU time and prints its minimum and median. Code in different
versions cannot share one process, so alternation is what makes the two comparable on a shared
machine.

Run:  python benchmarks/ab_strand_curve.py OTHER_CHECKOUT [--rounds 4] [--runs 15]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CHILD = """
import json, statistics, sys, time, warnings
warnings.simplefilter("ignore")
# the checkout's skcable, not an editable install's finder nor the working directory's
sys.meta_path = [f for f in sys.meta_path if "editable" not in repr(f).lower()]
sys.path[:0] = [{checkout!r}, {benchmarks!r}]
from bench_strand_opensees import LENGTH, STEPS, STRAND, TOP
import skcable
from skcable import strand
assert skcable.__file__.startswith({checkout!r}), skcable.__file__

def curve():
    model = strand.StrandModel(STRAND, LENGTH, n_elements=32)
    return model.capacity_curve(max_strain=TOP, n_steps=STEPS)

curve()
times = []
for _ in range({runs}):
    t = time.process_time()
    curve()
    times.append(time.process_time() - t)
print(json.dumps([min(times), statistics.median(times)]))
"""


def timed(checkout: Path, runs: int) -> tuple[float, float]:
    """(minimum, median) CPU seconds of the curve with ``checkout`` first on the path."""
    env = dict(os.environ, PYTHONPATH=str(checkout))
    code = CHILD.format(checkout=str(checkout.resolve()), benchmarks=str(ROOT / "benchmarks"), runs=runs)
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    low, mid = json.loads(out.stdout.strip().splitlines()[-1])
    return low, mid


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("other", type=Path, help="the other checkout (its root, holding skcable/)")
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--runs", type=int, default=15)
    args = parser.parse_args()
    if not (args.other / "skcable" / "__init__.py").is_file():
        parser.error(f"other: {args.other} holds no skcable/ package")
    ours, theirs = [], []
    for _ in range(args.rounds):
        theirs.append(timed(args.other, args.runs))
        ours.append(timed(ROOT, args.runs))
    for name, rows in (("other", theirs), ("this", ours)):
        lows = [low for low, _ in rows]
        print(f"{name}: minimum per process {min(lows):.4f}-{max(lows):.4f} s, median of minima "
              f"{statistics.median(lows):.4f} s")  # fmt: skip
    ratio = statistics.median(a for a, _ in ours) / statistics.median(b for b, _ in theirs)
    print(f"this / other (medians of the per-process minima): {ratio:.3f}")


if __name__ == "__main__":
    main()
