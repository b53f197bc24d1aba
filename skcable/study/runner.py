"""Running a study: check the arguments, read the cache, share the cases with other runs, compute the rest.

`run` is the study's entry point; the executors (`skcable.study.executors`) compute, the
cache (`skcable.study.cache`) keeps what was computed, and `skcable.study.table` makes the
table.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterable

from skcable._checks import whole
from skcable.errors import InputError
from skcable.io._atomic import writable_dir
from skcable.study.cache import Cache, canonical
from skcable.study.cases import case_key, check_cases, model_name
from skcable.study.executors import Auto, Dask, Serial, check_scheduler, dask_available
from skcable.study.spawn import GUARD, reimporting_main
from skcable.study.table import StudyTable, make_table

__all__ = ["POLL", "run"]

#: Seconds between looks at the cases another run is computing.
POLL = 0.1
_EXTRA = "needs Dask, the optional extra: pip install 'skcable[cluster]'"


def _checked_cases(model, cases) -> list[dict]:
    if not callable(model):
        raise InputError("model", f"must be a callable returning a dict, got {model!r}")
    if isinstance(cases, dict) or not isinstance(cases, Iterable):
        raise InputError("cases", f"must be a list of dicts, got {type(cases).__name__}")
    cases = list(cases)
    if not all(isinstance(c, dict) for c in cases):
        raise InputError("cases", "must be a list of dicts (keyword arguments of the model)")
    if not cases:
        raise InputError("cases", "the study has no cases")
    cases = [dict(c) for c in cases]
    check_cases(model, cases)
    return cases


def _executor(executor, scheduler, n_workers, progress):
    """The executor the arguments ask for (checked: nothing is started yet)."""
    if executor not in ("auto", "dask", "serial"):
        raise InputError("executor", f"must be 'auto', 'dask' or 'serial', got {executor!r}")
    if executor == "dask" and not dask_available():
        raise InputError("executor", "'dask' " + _EXTRA)
    if scheduler is not None:
        if executor == "serial":
            raise InputError("scheduler", "executor='serial' runs in this process; drop one of them")
        if not dask_available():
            raise InputError("scheduler", _EXTRA)
        check_scheduler(scheduler)
    if n_workers is not None:
        n_workers = whole("n_workers", n_workers, 1)
        if scheduler is not None:
            raise InputError("n_workers", "sizes the local Dask cluster; the scheduler's cluster has its own")
    n_workers = 2 if n_workers is None else n_workers
    if executor == "serial":
        return Serial()
    if executor == "dask" or scheduler is not None:
        return Dask(scheduler, n_workers, progress)
    return Auto(n_workers, progress)


def run(
    model: Callable[..., dict],
    cases: list[dict],
    *,
    executor: str = "auto",
    scheduler: str | None = None,
    n_workers: int | None = None,
    cache=None,
    progress: bool = True,
) -> StudyTable:
    """Run ``model(**case)`` for every case; return a `StudyTable`, one row per case.

    A case that fails (bad parameters, no convergence, any exception) is a row with
    ``status = "failed"`` and its error, and the study goes on. A case listed twice is
    computed once.

    Parameters
    ----------
    model : callable
        Returns a dict of scalar outputs. With worker processes it must be importable by
        them (a module-level function) or defined in the main program (Dask sends those by
        value).
    cases : list of dict
        Keyword arguments per case (see `grid` and `sample`); a case the model's
        signature cannot take (misspelt or missing parameter) is refused before computing.
    executor : {"auto", "dask", "serial"}
        ``"serial"``: in this process (`skcable.study.executors.Serial`). ``"dask"``: on a
        local Dask cluster of ``n_workers`` single-threaded processes, or on ``scheduler``'s
        (`skcable.study.executors.Dask`). ``"auto"`` (default): on ``scheduler``'s cluster if
        one is given; otherwise serially until a local cluster pays
        (`skcable.study.executors.Auto`).
    scheduler : str, optional
        Address of a running ``dask.distributed`` scheduler (``tcp://host:8786``).
    n_workers : int, optional
        Workers of the local cluster (default 2), >= 1; not with ``scheduler``.
    cache : path, optional
        Folder of finished cases (`skcable.study.cache`): finished cases are read, not
        rerun (an interrupted study resumes); runs sharing the folder split the cases.
    progress : bool
        A progress bar (stderr); with Dask, the dashboard link is printed too.

    Returns
    -------
    StudyTable
        One row per case, in the cases' order; ``attrs["from_cache"]`` counts the cases read
        from the cache, ``attrs["executor"]`` says where the others ran (``"serial"``,
        ``"serial, then dask, a local cluster of 2 worker processes"``, ...).

    Raises
    ------
    InputError
        A bad argument, before any case is computed.
    RuntimeError
        The call comes from a worker process re-importing the program's unguarded script.

    Examples
    --------
    >>> from skcable import study
    >>> cases = study.grid(span=[100.0, 200.0], sag=[5.0, -1.0], w=[10.0])
    >>> table = study.run(study.cable_solve, cases, executor="serial", progress=False)
    >>> table.status.tolist()
    ['ok', 'failed', 'ok', 'failed']
    """
    if reimporting_main():
        raise RuntimeError(
            f"skcable.study.run: a worker process is re-importing the program, which starts a study "
            f"outside `{GUARD}`; put the study under `{GUARD}`"
        )
    cases = _checked_cases(model, cases)
    chosen = _executor(executor, scheduler, n_workers, progress)
    folder = None if cache is None else writable_dir("cache", cache)
    keys = [case_key(model, c) for c in cases]
    unique = dict(zip(keys, cases, strict=True))
    try:
        results, from_cache = _compute(model, unique, chosen, folder, progress)
    finally:
        chosen.close()
    table = make_table(cases, keys, results, model=model_name(model), from_cache=from_cache)
    table.attrs["executor"] = chosen.description
    return table


def _compute(model, unique: dict, executor, folder, progress: bool) -> tuple[dict, int]:
    """Results of every case (read or computed), and how many were read from the cache."""
    from tqdm import tqdm

    store = Cache(folder, model) if folder is not None else None
    results: dict[str, dict] = {}
    try:
        pending = dict(unique)
        if store is not None:
            for key, case in unique.items():
                cached = store.read(key, case)
                if cached is not None:
                    results[key] = cached
                    del pending[key]
        from_cache = len(results)
        with tqdm(
            total=len(pending), desc="study", unit="case", disable=not progress, file=sys.stderr
        ) as bar:

            def finish(key, result):
                result = canonical(result)  # a fresh result reads as a cached one
                if store is not None:
                    store.write(key, unique[key], result)
                    store.locks.release(key)
                results[key] = result
                bar.update()

            if store is None:
                executor.map(model, list(pending.items()), finish)
            else:
                _share(store, pending, executor, model, finish, results, bar)
    finally:
        if store is not None:
            store.close()
    return results, from_cache


def _share(store: Cache, pending: dict, executor, model, finish, results: dict, bar) -> None:
    """Compute the pending cases no other run is computing; then collect the others' (or
    take over those whose run died)."""
    waited = False
    while pending:
        mine, theirs = [], {}
        for key, case in pending.items():
            result = store.read(key, case)
            if result is None and store.locks.acquire(key):
                result = store.read(key, case)  # finished by another run since the first look
                if result is None:
                    mine.append((key, case))
                    continue
                store.locks.release(key)
            if result is not None:
                results[key] = result
                bar.update()
            else:
                theirs[key] = case
        if mine:
            executor.map(model, mine, finish)
        elif theirs:
            if not waited:
                waited = True
                bar.set_description("study (waiting for cases another run is computing)")
            time.sleep(POLL)
        pending = theirs
