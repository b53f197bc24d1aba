"""Wall time of a study serially, on ``executor="auto"`` and on local Dask clusters, same process.

Studies:

- ``seed``: Pino Vidal's (2021) 16-case grid (studies/pino_vidal_2021_tables_4_1_4_2.toml),
  4 strands x 2 damage patterns x 2 models, about 0.15 s a case;
- ``tiny``: 8 closed-form catenaries (`skcable.study.cable_solve`), about 1 ms a case;
- ``long`` (only with ``--long N``): N capacity cases, the seed grid repeated with other
  lengths, to see ``auto`` move to worker processes where they pay (run once on each way).

Each study runs ``--repeat`` times on each way, the ways interleaved (each first in turn); the
medians are printed with their ratio to the serial run, and the tables are checked identical
(every column but ``time_s``). The ways:

- ``serial``: ``executor="serial"``;
- ``auto``: the default, serial until a cluster pays (`skcable.study.executors.dask_pays`);
- ``dask processes``: ``executor="dask"``, a local cluster of ``--workers`` single-threaded
  processes, started and stopped by the run;
- ``dask threads``: a local cluster of ``--workers`` single-threaded worker *threads*
  (``processes=False``), started, used through ``scheduler=`` and stopped, all timed.

Writes the table into docs/studies.md between its ``bench_study`` markers (not with
``--no-docs``) and the numbers into benchmarks/out/bench_study.json. The last lines give the
measured cluster cost (the process cluster on the tiny study: start,
the workers' imports, stop) and the parallel efficiency on the seed study, the two figures
behind `skcable.study.executors.CLUSTER_COST` and `EFFICIENCY`.

Run:  python benchmarks/bench_study.py [--repeat 5] [--workers 2] [--long 240] [--no-docs]
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import statistics
import sys
import time
from pathlib import Path

from skcable import study

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "studies" / "pino_vidal_2021_tables_4_1_4_2.toml"
DOCS = ROOT / "docs" / "studies.md"
sys.path.insert(0, str(ROOT / "benchmarks"))

from _tables import write_section  # noqa: E402

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


def collect(args) -> dict:
    """Every study on every way: medians, tables identical, where auto ran; the derived figures."""
    report = {
        "workers": args.workers,
        "repeat": args.repeat,
        "load_before": os.getloadavg()[0],
        "studies": {},
    }
    for name, (model, cases) in studies(args.long).items():
        repeat = 1 if name == "long" else args.repeat  # the long study once: it takes minutes
        medians, tables, identical = measure(model, cases, repeat, args.workers)
        report["studies"][name] = {
            "cases": len(cases),
            "median_s": medians,
            "identical": identical,
            "busy_s": float(tables["serial"].time_s.sum()),
            "auto_ran": tables["auto"].attrs["executor"],
        }
        print(f"{name}: {medians}", flush=True)
    seed, tiny = report["studies"]["seed"], report["studies"]["tiny"]
    cost = tiny["median_s"]["dask processes"]
    parallel = seed["median_s"]["dask processes"] - cost
    efficiency = seed["busy_s"] / (args.workers * parallel) if parallel > 0 else float("nan")
    report.update(
        cluster_cost_s=cost, parallel_s=parallel, efficiency=efficiency, load_after=os.getloadavg()[0]
    )
    return report


def render(report: dict) -> str:
    """The report as Markdown: the table of medians and the figures behind the auto policy."""
    lines = [
        f"| study | cases | {' | '.join(WAYS)} |",
        f"|---|---|{'---|' * len(WAYS)}",
    ]
    for name, found in report["studies"].items():
        medians, serial = found["median_s"], found["median_s"]["serial"]
        cells = " | ".join(f"{seconds(medians[w])} ({medians[w] / serial:.2f})" for w in WAYS)
        lines.append(
            f"| {name} | {found['cases']} | {cells} |" + ("" if found["identical"] else " TABLES DIFFER")
        )
    seed = report["studies"]["seed"]
    lines += [
        "",
        f"Median of {report['repeat']} runs of each way (the long study: one), the ways interleaved, one "
        f"process, {report['workers']} workers; ratio to serial in brackets; every way's table identical "
        f"to the serial one: {all(f['identical'] for f in report['studies'].values())}. Load average "
        f"{report['load_before']:.1f} before, {report['load_after']:.1f} after (2 cores).",
        "",
        f"- cluster cost (the process cluster on the tiny study): {report['cluster_cost_s']:.2f} s",
        f"- seed study: {seed['busy_s']:.2f} s of computing, {report['parallel_s']:.2f} s on the cluster "
        f"beyond its cost: parallel efficiency {report['efficiency']:.2f}",
    ]
    lines += [f"- `auto` on {name}: {found['auto_ran']}" for name, found in report["studies"].items()]
    return "\n".join(lines)


def write_docs(markdown: str) -> None:
    notice = "<!-- written by benchmarks/bench_study.py: do not edit by hand -->"
    write_section(DOCS, "bench_study", [notice, "", *markdown.split("\n")])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--long", type=int, default=0, metavar="N", help="also a study of N capacity cases")
    parser.add_argument("--no-docs", action="store_true", help="do not write the table into docs/studies.md")
    args = parser.parse_args(argv)
    logging.getLogger("distributed").setLevel(logging.ERROR)
    report = collect(args)
    markdown = render(report)
    print(markdown)
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_study.json").write_text(json.dumps(report, indent=1) + "\n")
    if not all(found["identical"] for found in report["studies"].values()):
        raise SystemExit("the tables differ between the ways of running")
    if not args.no_docs:
        write_docs(markdown)


if __name__ == "__main__":
    main()
