"""Start-up cost of ``import skcable`` and ``skcable --help`` over a bare ``python -c pass``.

Whole processes, run in turn (A, B, A, B, ...) so that a drift of the machine's speed moves
both alike; prints the median wall time of each command and the median of the pairwise
differences to the bare interpreter (issue 21's target: ``skcable --help`` at most 0.3 s
over ``python -c pass``). Each command also prints which heavy modules it loaded, so a
regression names its cause. The same figure from outside, with CPU time and memory:

    farm-bench -n 15 --vs 'python -c pass' -- skcable --help

Run:  python benchmarks/bench_import.py [--runs 15]
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import subprocess
import sys
import time

HEAVY = ("numpy", "pandas", "scipy.optimize", "skfem", "meshio", "pyvista", "matplotlib", "dask")
#: What each timed process runs (``python -c CODE``); ``skcable --help`` runs the console script.
CODE = {
    "skcable --help": "from skcable.cli import parser; parser().format_help()",
    "import skcable": "import skcable",
    "from skcable import cable, strand": "from skcable import cable, strand",
    "cable.catenary(..., low=)": "from skcable import cable; cable.catenary(800.0, -20.0, 20.0, low=-30.0)",
}
BARE = [sys.executable, "-c", "pass"]


def _wall(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def _loaded(code: str) -> str:
    """The heavy modules in sys.modules after ``code``, in a fresh interpreter."""
    probe = f"import json, sys\n{code}\nprint(json.dumps([m for m in {HEAVY!r} if m in sys.modules]))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    return ", ".join(json.loads(out.stdout.strip().splitlines()[-1])) or "none"


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15, help="pairs of runs per command (default: 15)")
    args = parser.parse_args(argv)
    console = shutil.which("skcable")
    print(f"{'command':36s} {'median wall [s]':>16s} {'over python -c pass [s]':>24s}  heavy modules loaded")
    for name, code in CODE.items():
        command = (
            [console, "--help"] if name == "skcable --help" and console else [sys.executable, "-c", code]
        )
        _wall(command), _wall(BARE)  # warm the file cache
        pairs = [(_wall(command), _wall(BARE)) for _ in range(args.runs)]
        over = statistics.median(a - b for a, b in pairs)
        wall = statistics.median(a for a, _ in pairs)
        print(f"{name:36s} {wall:16.3f} {over:24.3f}  {_loaded(code)}")
    bare = statistics.median(_wall(BARE) for _ in range(args.runs))
    print(f"{'python -c pass':36s} {bare:16.3f}")


if __name__ == "__main__":
    main()
