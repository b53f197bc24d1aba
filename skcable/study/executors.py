"""Where a study's cases run: in this process (`Serial`), on Dask (`Dask`), serially until Dask pays (`Auto`).

An executor maps `skcable.study.tasks.evaluate` over a batch of ``(key, case)`` pairs and
hands each result to a ``finish(key, result)`` callback as it ends. The figures behind
`CLUSTER_COST` and `EFFICIENCY` come from ``benchmarks/bench_study.py`` (docs/studies.md).
"""

from __future__ import annotations

import contextlib
import importlib.util
import logging
import math
import os
import secrets
import statistics
import sys
from typing import TYPE_CHECKING

from skcable.errors import InputError
from skcable.study import tasks
from skcable.study._warn import warn
from skcable.study.spawn import main_problem

if TYPE_CHECKING:  # pragma: no cover - distributed is imported where a cluster starts
    from distributed import Client, LocalCluster

__all__ = [
    "CLUSTER_COST",
    "EFFICIENCY",
    "Auto",
    "Dask",
    "Serial",
    "WorkerWarning",
    "check_scheduler",
    "dask_available",
    "dask_pays",
    "free_cores",
    "start_method",
    "usable_cores",
]

#: Seconds a local cluster of 2 worker processes takes to start, take its first cases
#: (the workers import skcable) and stop: 4 to 15 s measured by benchmarks/bench_study.py
#: on 2 cores shared with other work.
CLUSTER_COST = 10.0
#: The fraction of the ideal speed-up a local cluster reaches on the cases themselves, on
#: cores left free: 0.54 to 0.63 measured at a moderate load (down to 0.22 on a busy
#: machine, where `free_cores` keeps a study serial).
EFFICIENCY = 0.6


class WorkerWarning(RuntimeWarning):
    """Worker processes cannot start from this program; the study runs serially or on threads."""


def dask_available() -> bool:
    """Whether ``distributed`` (the optional extra ``skcable[cluster]``) is installed, looked for
    without importing it (an import takes about a second, which a serial study need not pay).
    """
    return importlib.util.find_spec("distributed") is not None


def usable_cores() -> int:
    """The CPU cores (>= 1) this process may run on (its affinity where the system tells it)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def start_method() -> str:
    """How a local cluster starts workers: ``"spawn"`` (Dask's default), ``"forkserver"`` or ``"fork"``."""
    import dask
    import distributed  # noqa: F401 - registers its configuration

    return str(dask.config.get("distributed.worker.multiprocessing-method"))


def free_cores() -> int:
    """The usable cores (>= 1) that other work leaves free, this process's own included.

    The 1-minute load average counts the runnable processes, this one among them (it is
    computing a case when asked): ``usable_cores() - (load - 1)``, rounded, between 1 and the
    usable cores. Where the system has no load average, the usable cores.
    """
    cores = usable_cores()
    try:
        load = os.getloadavg()[0]
    except (AttributeError, OSError):
        return cores
    return max(1, min(cores, math.floor(cores - max(0.0, load - 1.0) + 0.5)))


def check_scheduler(scheduler) -> None:
    """Refuse an address no Dask scheduler can have (such as ``tcp://host:8786``), before any computing.

    Raises
    ------
    InputError
        ``scheduler``: not a string, an unknown scheme, or no ``host:port``.
    """
    from distributed.comm import parse_address
    from distributed.comm.addressing import parse_host_port
    from distributed.comm.registry import get_backend

    if not isinstance(scheduler, str) or not scheduler.strip():
        raise InputError("scheduler", f"must be an address such as tcp://host:8786, got {scheduler!r}")
    try:
        scheme, location = parse_address(scheduler)
        get_backend(scheme)
        if scheme in ("tcp", "tls", "ws", "wss"):
            parse_host_port(location)
    except (ValueError, TypeError) as exc:
        raise InputError("scheduler", f"{scheduler!r} is not a scheduler address: {exc}") from None


def dask_pays(case_time: float, left: int, workers: int) -> bool:
    """Whether a new local cluster would finish the cases left sooner than this process.

    With ``t`` s a case, ``n`` cases left and ``W`` workers able to run at once, serially the
    cases take ``n t``; on a new cluster ``CLUSTER_COST + ceil(n / W) t / EFFICIENCY``.

    Parameters
    ----------
    case_time : float
        Seconds a case takes (s).
    left : int
        Cases left.
    workers : int
        Workers that can run at once (`Auto` gives the cluster's workers, at most
        `free_cores`).

    Examples
    --------
    >>> dask_pays(0.2, 14, 2), dask_pays(0.2, 1000, 2), dask_pays(60.0, 1, 2)
    (False, True, False)
    """
    if workers < 2 or left < 2:
        return False
    on_cluster = CLUSTER_COST + math.ceil(left / workers) * case_time / EFFICIENCY
    return on_cluster < left * case_time


class Serial:
    """Computes the cases one after the other in this process."""

    #: Where the cases ran (a study table's ``attrs["executor"]``).
    description = "serial"

    def map(self, model, todo, finish) -> None:
        """Compute the ``(key, case)`` pairs of ``todo`` with ``model``, calling ``finish(key, result)``
        after each case with the record of `skcable.study.tasks.evaluate`.
        """
        for key, case in todo:
            finish(key, tasks.evaluate(model, case))

    def close(self) -> None:
        """Nothing to release."""


class Dask:
    """Computes the cases on a ``dask.distributed`` cluster: a running scheduler's, or a local
    cluster started on first use (single-threaded worker processes; worker threads where the
    program cannot start worker processes, see `skcable.study.spawn`).

    Parameters
    ----------
    scheduler : str, optional
        Address of a running scheduler; default: a local cluster.
    n_workers : int
        Workers of the local cluster (single-threaded).
    progress : bool
        Print the dashboard's address (stderr) on connecting.
    """

    def __init__(self, scheduler: str | None = None, n_workers: int = 2, progress: bool = False):
        self.scheduler, self.n_workers, self.progress = scheduler, n_workers, progress
        self.client: Client | None = None
        self.cluster: LocalCluster | None = None
        where = f"the scheduler at {scheduler}" if scheduler is not None else "a local cluster"
        #: Where the cases ran (a study table's ``attrs["executor"]``).
        self.description = f"dask, {where}"

    def map(self, model, todo, finish) -> None:
        """`Serial.map` on the cluster. A case whose task is lost (a worker died, the model could not
        be sent) is recorded as failed with the error, like a case that raised.
        """
        from distributed import as_completed

        client = self.connect()
        futures = {
            client.submit(
                tasks.evaluate, model, case, key=f"skcable-{key}-{secrets.token_hex(4)}", pure=False
            ): key
            for key, case in todo
        }
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as exc:  # noqa: BLE001 - a worker died or the task could not be sent
                result = tasks.failure(tasks.first_line(exc))
            finish(futures[future], result)

    def connect(self):
        """The ``distributed.Client`` of the cluster, connected (or the local cluster started) on the
        first call; `InputError` (``scheduler``) when no scheduler answers at the address.
        """
        if self.client is not None:
            return self.client
        from distributed import Client

        if self.scheduler is None:
            self.cluster = self._local_cluster()
            self.client = Client(self.cluster)
        else:
            try:
                self.client = Client(self.scheduler)
            except (OSError, TimeoutError) as exc:
                raise InputError(
                    "scheduler", f"no dask scheduler answers at {self.scheduler!r}: {exc}"
                ) from None
        if self.progress:
            print(f"dask dashboard: {self.client.dashboard_link}", file=sys.stderr)
        return self.client

    def _local_cluster(self):
        from distributed import LocalCluster

        problem = main_problem(start_method())
        if problem is not None:
            warn(
                f"skcable.study runs on {self.n_workers} worker threads, not processes: {problem}",
                WorkerWarning,
            )
        kind = "processes" if problem is None else "threads"
        self.description = f"dask, a local cluster of {self.n_workers} worker {kind}"
        return LocalCluster(
            n_workers=self.n_workers,
            threads_per_worker=1,
            processes=problem is None,
            dashboard_address=":0",
            # errors only: a worker whose heartbeat meets the scheduler already closing logs a
            # warning with a traceback (a race at shutdown on a loaded machine), not a failure
            silence_logs=SHUTDOWN_LOG_LEVEL,
        )

    def close(self) -> None:
        """Close the client and the local cluster, if any, printing only ``distributed``'s errors.

        A local cluster's ``silence_logs`` ends inside its own ``close``, before its event loop
        stops: a comm that the closing scheduler cut then logged its ``CommClosedError`` at INFO,
        traceback and all, on the stderr of a study that had succeeded (worker threads, on a
        loaded machine). The same level holds here until the loop has stopped.
        """
        with _errors_only(logging.getLogger("distributed")):
            if self.client is not None:
                self.client.close()
            if self.cluster is not None:
                self.cluster.close()


#: The level of ``distributed``'s logs while skcable starts and stops a local cluster:
#: a worker's heartbeat or a batched comm meeting the scheduler already closing logs a warning
#: or an INFO record with a traceback (a race at shutdown on a loaded machine), not a failure.
SHUTDOWN_LOG_LEVEL = logging.ERROR


@contextlib.contextmanager
def _errors_only(logger: logging.Logger):
    """Hold ``logger`` at `SHUTDOWN_LOG_LEVEL` (its level, not its handlers': a cluster's close
    restores its handlers' levels before its loop stops), restoring the level after."""
    level = logger.level
    logger.setLevel(max(logger.getEffectiveLevel(), SHUTDOWN_LOG_LEVEL))
    try:
        yield
    finally:
        logger.setLevel(level)


class Auto:
    """Computes serially, and moves the rest to a local cluster of processes when that pays.

    After each case (from the second on) `dask_pays` is asked with the median time of the
    cases computed so far (the first left out: it carries the imports) and the cluster's
    workers, at most the cores other work leaves free (`free_cores`): on a busy machine the
    workers would only take turns with the others. A small study never starts a cluster, so
    it is never slower than the serial run. Where worker processes cannot start
    (`skcable.study.spawn.main_problem`) the study stays serial, with one `WorkerWarning`
    saying what to add.

    Parameters
    ----------
    n_workers : int
        Workers of the local cluster, if one is started.
    progress : bool
        Print the dashboard's address when a cluster starts.
    """

    def __init__(self, n_workers: int = 2, progress: bool = False):
        self.n_workers, self.progress = n_workers, progress
        self.times: list[float] = []
        self.dask: Dask | None = None
        self.stay_serial = not dask_available()

    @property
    def description(self) -> str:
        """Where the cases ran: ``"serial"``, or ``"serial, then dask, ..."``."""
        return "serial" if self.dask is None else f"serial, then {self.dask.description}"

    def map(self, model, todo, finish) -> None:
        """`Serial.map`, serially until `dask_pays`, then on a local cluster."""
        todo, done = list(todo), 0
        while done < len(todo) and self.dask is None:
            key, case = todo[done]
            result = tasks.evaluate(model, case)
            done += 1
            self.times.append(result["time_s"])
            finish(key, result)
            if done < len(todo) and self._switch(len(todo) - done):
                self.dask = self._start()
        if done < len(todo):
            assert self.dask is not None  # the serial loop stopped on a started cluster
            self.dask.map(model, todo[done:], finish)

    def _start(self) -> Dask | None:
        """A started local cluster, or None (warned) if it cannot start: the study goes on serially."""
        cluster = Dask(None, self.n_workers, self.progress)
        try:
            cluster.connect()
        except Exception as exc:  # noqa: BLE001 - the cluster was this executor's idea, not the user's
            cluster.close()
            self.stay_serial = True
            warn(f"skcable.study runs serially: a local Dask cluster did not start ({exc})", WorkerWarning)
            return None
        return cluster

    def _switch(self, left: int) -> bool:
        if (
            self.stay_serial
            or len(self.times) < 2
            or not dask_pays(statistics.median(self.times[1:]), left, min(self.n_workers, free_cores()))
        ):
            return False
        problem = main_problem(start_method())
        if problem is not None:
            self.stay_serial = True
            warn(f"skcable.study runs serially: {problem}", WorkerWarning)
        return problem is None

    def close(self) -> None:
        """Close the cluster, if one was started."""
        if self.dask is not None:
            self.dask.close()
