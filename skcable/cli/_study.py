"""``skcable study run``: a study file (TOML) computed serially or on Dask, its table written."""

from __future__ import annotations

import sys

from skcable.cli._args import whole
from skcable.cli._status import Usage

__all__ = ["register"]


def _check(args):
    """The study file and every output path, checked before computing; returns the spec."""
    from skcable import study
    from skcable.cli._output import output_dir, output_file
    from skcable.errors import InputError
    from skcable.io._atomic import writable_dir

    try:  # the study file's own mistakes are named by the file and its key, not by a flag
        spec = study.load_study(args.path)
        if args.out is None:  # a rerun rewrites its own table (its cache makes that cheap)
            study.check_output("output", spec["output"])
        if args.cache is None and spec["cache"] is not None:
            writable_dir("cache", spec["cache"])  # a study file's folders are created as needed
    except InputError as exc:
        raise Usage(f"{args.path}: {exc}") from None
    if args.serial and args.scheduler is not None:
        raise Usage("--scheduler: a Dask scheduler address; --serial runs without Dask: give one of them")
    if args.serial and args.workers is not None:
        raise Usage("--workers: sizes the local Dask cluster; --serial runs without Dask: give one of them")
    if args.out is not None:
        study.check_output("out", output_file("--out", args.out, args.force, study.TABLE_SUFFIXES))
    if args.cache is not None:
        output_dir("--cache", args.cache, force=True)  # a cache is meant to be reused
    return spec


def _run(args) -> int:
    import logging

    from skcable import study
    from skcable.cli._status import EXIT_CASES_FAILED, EXIT_OK

    spec = _check(args)
    logging.getLogger("distributed").setLevel(logging.ERROR)
    table, output = study.run_file(
        args.path,
        scheduler=args.scheduler,
        executor="serial" if args.serial else "auto",
        n_workers=args.workers,
        progress=not args.no_progress,
        output=args.out,
        cache=args.cache,
    )
    failed = table[table.status != "ok"]
    busy = table.time_s.sum()
    cached = table.attrs.get("from_cache", 0)
    print(
        f"{len(table)} cases: {len(table) - len(failed)} ok, {len(failed)} failed "
        f"({cached} read from the cache, {busy:.1f} s of computing); table: {output}"
    )
    parameters = [c for c in table.columns if c in set().union(*(case.keys() for case in spec["cases"]))]
    for _, row in failed.head(20).iterrows():
        print(f"  failed {study.describe({k: row[k] for k in parameters})}: {row.error}")
    if len(failed) > 20:
        print(f"  ... and {len(failed) - 20} more: see the status and error columns of {output}")
    if len(failed):
        print(f"skcable: {len(failed)} of {len(table)} cases failed", file=sys.stderr)
        return EXIT_CASES_FAILED
    return EXIT_OK


def register(sub, command) -> None:
    group = sub.add_parser("study", help="parameter studies on Dask").add_subparsers(
        dest="study_command", metavar="command"
    )
    st = command(group, "run", _run, "run a study file (TOML) and write its table")
    st.add_argument("path", help="study file, e.g. studies/pino_vidal_2021_tables_4_1_4_2.toml")
    st.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="address of a running dask.distributed scheduler, e.g. tcp://host:8786 "
        "(default: a local cluster of --workers processes)",
    )
    st.add_argument("--serial", action="store_true", help="no Dask: one case after the other (default: Dask)")
    st.add_argument(
        "--workers", type=whole(1), metavar="N", help="processes of the local Dask cluster, >= 1 (default: 2)"
    )
    st.add_argument(
        "--out", metavar="FILE", help="table path, .csv or .parquet (default: the study file's output)"
    )
    st.add_argument(
        "--cache", metavar="DIR", help="folder of finished cases (default: the study file's cache, if any)"
    )
    st.add_argument(
        "--force",
        action="store_true",
        help="overwrite an existing --out table (default: refuse; the study file's own output is "
        "rewritten by a rerun)",
    )
    st.add_argument("--no-progress", action="store_true", help="no progress bar on stderr (default: shown)")
