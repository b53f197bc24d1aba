"""Speed-up of a parameter study on a local Dask cluster against serial, same process.

The study is Pino Vidal's (2021) 16-run grid (studies/pino_vidal_2021_tables_4_1_4_2.toml): 4 strands x
2 damage patterns x 2 models. Runs it serially, then on a local cluster of 2 single-threaded
worker processes (this machine has 2 cores), checks that both tables are identical (all
columns but the run time) and prints the wall times and their ratio.

Run:  python benchmarks/bench_study.py [--workers 2]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from skcable import study

ROOT = Path(__file__).resolve().parents[1]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--study", default=str(ROOT / "studies" / "seed003_tables_4_1_4_2.toml"))
    args = parser.parse_args(argv)
    spec = study.load_study(args.study)
    times, tables = {}, {}
    for executor in ("serial", "dask"):
        start = time.perf_counter()
        tables[executor] = study.run(
            spec["model"], spec["cases"], executor=executor, n_workers=args.workers, progress=False
        )
        times[executor] = time.perf_counter() - start
    columns = [c for c in tables["serial"].columns if c != "time_s"]
    identical = tables["serial"][columns].equals(tables["dask"][columns])
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    tables["serial"].to_csv(out / "study_serial.csv", index=False)
    busy = tables["serial"].time_s
    print(f"{len(spec['cases'])} cases ({(tables['serial'].status != 'ok').sum()} failed, recorded)")
    print(f"serial:                   {times['serial']:7.1f} s")
    print(f"dask, {args.workers} local processes:  {times['dask']:7.1f} s  (tables identical: {identical})")
    print(f"speed-up serial / dask:   {times['serial'] / times['dask']:7.2f}")
    print(
        f"longest case {busy.max():.1f} s of {busy.sum():.1f} s: ideal speed-up "
        f"{busy.sum() / max(busy.sum() / args.workers, busy.max()):.2f}"
    )


if __name__ == "__main__":
    main()
