"""Wall time of a study serially, on ``executor="auto"`` and on local Dask clusters, same process.

Studies:

- ``seed``: Pino Vidal's (2021) 16-case grid (studies/pino_vidal_2021_tables_4_1_4_2.toml),
  4 strands x 2 damage patterns x 2 models, about 0.15 s a case;
- ``tiny``: 8 closed-form catenaries (`skcable.study.cable_solve`), about 1 ms a case;
- ``long`` (only with ``--long N``): N capacity cases, the seed grid repeated with other
  lengths, to see ``auto`` move to worker processes where they pay.

Each study runs ``--repeat`` times on each way, the ways interleaved (each first in turn); the
medians are printed with their ratio to the serial run, and the tables are checked identical
(every column but ``time_s``). The ways:

- ``serial``: ``executor="serial"``;
- ``auto``: the default, serial until a cluster pays (`skcable.study.executors.dask_pays`);
- ``dask processes``: ``executor="dask"``, a local cluster of ``--workers`` single-threaded
  processes, started and stopped by the run;
- ``dask threads``: a local cluster of ``--workers`` single-threaded worker *threads*
  (``processes=False``), started, used through ``scheduler=`` and stopped, all timed.

The last lines give the measured cluster cost (the process cluster on the tiny study: start,
the workers' imports, stop) and the parallel efficiency on the seed study, the two figures
behind `skcable.study.executors.CLUSTER_COST` and `EFFICIENCY`.

Run:  python benchmarks/bench_study.py [--repeat 5] [--workers 2] [--long 240]
"""

from __future__ import annotations

import argparse
import json
import logging
import statistics
import time
from pathlib import Path

from skcable import study

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "studies" / "pino_vidal_2021_tables_4_1_4_2.toml"
WAYS = ("serial", "auto", "dask processes", "dask threads")


def studies(long: int) -> dict:
    seed = study.load_study(SEED)
    found = {
        "seed": (seed["model"], seed["cases"]),
        "tiny": (study.cable_solve, study.grid(span=[100.0 * k for k in range(1, 9)], sag=[5.0], w=[10.0])),
    }
    if long:
        lengths = [1.0 + 0.01 * i for i in range(-(-long // 16))]
        cases = [case | {"length": length} for length in lengths for case in seed["cases"]][:long]
        found["long"] = (seed["model"], cases)
    return found


def run_once(way: str, model, cases, workers: int):
    start = time.perf_counter()
    if way == "dask threads":
        from distributed import LocalCluster

        with LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=False, dashboard_address=":0"
        ) as cluster:
            table = study.run(model, cases, scheduler=cluster.scheduler_address, progress=False)
    else:
        executor = {"serial": "serial", "auto": "auto", "dask processes": "dask"}[way]
        table = study.run(model, cases, executor=executor, n_workers=workers, progress=False)
    return time.perf_counter() - start, table


def measure(model, cases, repeat: int, workers: int) -> tuple[dict, dict, bool]:
    times = {way: [] for way in WAYS}
    tables = {}
    for i in range(repeat):
        for way in WAYS[i % len(WAYS) :] + WAYS[: i % len(WAYS)]:  # each way first in turn
            elapsed, tables[way] = run_once(way, model, cases, workers)
            times[way].append(elapsed)
    columns = [c for c in tables["serial"].columns if c != "time_s"]
    identical = all(tables[way][columns].equals(tables["serial"][columns]) for way in WAYS)
    return {way: statistics.median(t) for way, t in times.items()}, tables, identical


def seconds(t: float) -> str:
    return f"{t:.2f} s" if t >= 1.0 else f"{1e3 * t:.1f} ms"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--long", type=int, default=0, metavar="N", help="also a study of N capacity cases")
    args = parser.parse_args(argv)
    logging.getLogger("distributed").setLevel(logging.ERROR)
    report = {"workers": args.workers, "repeat": args.repeat, "studies": {}}
    print(f"| study | cases | {' | '.join(WAYS)} |")
    print(f"|---|---|{'---|' * len(WAYS)}")
    for name, (model, cases) in studies(args.long).items():
        medians, tables, identical = measure(model, cases, args.repeat, args.workers)
        serial = medians["serial"]
        cells = " | ".join(f"{seconds(medians[w])} ({medians[w] / serial:.2f})" for w in WAYS)
        print(f"| {name} | {len(cases)} | {cells} |" + ("" if identical else "  TABLES DIFFER"))
        busy = float(tables["serial"].time_s.sum())
        auto = tables["auto"].attrs["executor"]
        report["studies"][name] = {
            "cases": len(cases),
            "median_s": medians,
            "identical": identical,
            "busy_s": busy,
            "auto_ran": auto,
        }
    seed, tiny = report["studies"]["seed"], report["studies"]["tiny"]
    cost = tiny["median_s"]["dask processes"]
    parallel = seed["median_s"]["dask processes"] - cost
    efficiency = seed["busy_s"] / (args.workers * parallel) if parallel > 0 else float("nan")
    print(f"\n(median of {args.repeat}; in brackets the ratio to serial; {args.workers} workers)")
    print(f"cluster cost (dask processes on the tiny study): {cost:.2f} s")
    print(
        f"seed study: {seed['busy_s']:.2f} s of computing; on the cluster, beyond its cost, {parallel:.2f} s"
    )
    print(f"parallel efficiency on the seed study: {efficiency:.2f}")
    for name, found in report["studies"].items():
        print(f"auto on {name}: {found['auto_ran']}")
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    report.update(cluster_cost_s=cost, efficiency=efficiency)
    (out / "bench_study.json").write_text(json.dumps(report, indent=1) + "\n")
    if not all(found["identical"] for found in report["studies"].values()):
        raise SystemExit("the tables differ between the ways of running")


if __name__ == "__main__":
    main()
