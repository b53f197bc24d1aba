"""Parameter studies: a grid or a sample of cases over a model function, run on Dask.

A study is a list of cases (dicts of keyword arguments) and a model
function that turns one case into a dict of outputs. `run` maps the
function over the cases on a Dask cluster (a local cluster of processes by
default, or any ``dask.distributed`` scheduler address) or serially, and
collects one row per case into a `StudyTable` (a pandas DataFrame that
prints as a short summary):

    case parameters | outputs | status ("ok" / "failed") | error | time_s | key

(an output named like a parameter gets the suffix ``_result``: a cable solved
for a given ``sag`` reports the sag it reached as ``sag_result``).

A failing case (bad parameters, no convergence) is recorded with its error
and does not stop the study. With ``cache=`` every finished case is written
to ``<cache>/<key>.json`` as soon as it ends, and a later run with the same
cache reads it back instead of recomputing: an interrupted study resumes.
The key is a hash of the model's name and the case's parameters; an entry
records the model, the parameters, the skcable version and a checksum, and
is verified when read: a damaged, hand-edited or foreign entry is recomputed
with a `CacheWarning` naming the file. Entries are written atomically,
and a case in progress is locked (``<key>.lock``), so two runs sharing a cache
neither compute a case twice nor leave a torn file.

Dask and distributed are the optional extra ``skcable[cluster]``; without
them ``executor="auto"`` runs serially and gives the same table.

Examples
--------
>>> cases = grid(span=[100.0, 200.0], sag=[5.0, 10.0, -1.0], w=[10.0])
>>> table = run(cable_solve, cases, executor="serial", progress=False)
>>> table.shape[0], table.status.tolist()
(6, ['ok', 'ok', 'failed', 'ok', 'ok', 'failed'])
>>> table.error[2]
'InputError: sag: must be > 0, got -1.0'
"""

from __future__ import annotations

import contextlib
import hashlib
import inspect
import itertools
import json
import math
import os
import secrets
import socket
import sys
import threading
import time
import warnings
from collections.abc import Callable, Iterable
from pathlib import Path

import numpy as np
import pandas as pd

from skcable.errors import InputError
from skcable.io._atomic import TEMP_GLOB, atomic_path, writable_dir, writable_file, write_text

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = [
    "MODELS",
    "CacheWarning",
    "StudyTable",
    "cable_solve",
    "case_key",
    "describe",
    "grid",
    "load_study",
    "run",
    "run_file",
    "sample",
    "strand_capacity",
]

#: Table formats a study's output may have.
TABLE_SUFFIXES = (".csv", ".parquet")


class CacheWarning(UserWarning):
    """A cache entry could not be used (damaged, edited, foreign or stale) and is recomputed."""


def _integer(name: str, value, minimum: int | None = None) -> int:
    """``value`` as an int, raising unless it is a whole number (>= ``minimum``)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(name, f"must be a whole number, got {value!r}")
    if not float(value).is_integer():
        raise InputError(name, f"must be a whole number, got {value!r}")
    if minimum is not None and value < minimum:
        raise InputError(name, f"must be at least {minimum}, got {value!r}")
    return int(value)


# --- model functions ------------------------------------------------------------
def strand_capacity(
    preset: str = "steel-9.5",
    damage: int = 0,
    slip: str = "none",
    mu: float = 0.5,
    length: float = 1.0,
    n_elements: int | None = None,
    n_steps: int | None = None,
    damage_load: str = "eccentricity",
) -> dict:
    """Capacity curve of a preset strand: K_Leq (N), D_r, toughness (N), rupture strain and
    force (N), peak curvature (1/m), slip onset strain (first step with slip; None when
    the strand never slips) and the largest slip fraction."""
    from skcable import strand

    damage = _integer("damage", damage, 0)
    n_elements = None if n_elements is None else _integer("n_elements", n_elements)
    n_steps = None if n_steps is None else _integer("n_steps", n_steps, 4)  # 0 would mean "the default"
    s = strand.preset(preset)
    s = s.damaged(damage) if damage else s
    model = strand.StrandModel(s, length, slip=slip, mu=mu, n_elements=n_elements, damage_load=damage_load)
    curve = model.capacity_curve(n_steps=n_steps)
    slipping = np.flatnonzero(curve.slip_fraction > 0)
    return {
        "K_Leq": curve.K_Leq,
        "D_r": curve.D_r,
        "toughness": curve.toughness,
        "rupture_strain": float(curve.strain[-1]),
        "rupture_force": float(curve.force[-1]),
        "peak_curvature": float(max(np.max(np.abs(st.curvature)) for st in curve.steps)),
        "slip_onset_strain": float(curve.strain[slipping[0]]) if slipping.size else None,
        "max_slip_fraction": float(np.max(curve.slip_fraction)),
    }


def cable_solve(
    span: float,
    w: float,
    dh: float = 0.0,
    EA: float | None = None,
    length: float | None = None,
    sag: float | None = None,
    H: float | None = None,
    low: float | None = None,
    T_max: float | None = None,
) -> dict:
    """Catenary given one of ``length, sag, H, low, T_max`` (or, with ``EA``, Irvine's
    elastic catenary given ``length``): H, T_max, length, sag (N, m) and the equilibrium
    residual."""
    from skcable import cable

    given = {"length": length, "sag": sag, "H": H, "low": low, "T_max": T_max}
    constraint = {k: v for k, v in given.items() if v is not None}
    if EA is None:
        sol = cable.catenary(span, dh, w, **constraint)
    else:
        if set(constraint) != {"length"}:
            raise InputError(
                "EA", f"the elastic catenary is solved for a given length only, got {constraint}"
            )
        sol = cable.elastic_catenary(span, dh, w, EA, length=length)
    return {
        "H": float(sol.H),
        "T_max": float(sol.T_max),
        "length": float(sol.length),
        "sag": float(sol.sag),
        "residual": sol.residual(),
    }


#: Model functions a study file may name.
MODELS: dict[str, Callable[..., dict]] = {"strand_capacity": strand_capacity, "cable_solve": cable_solve}


# --- describing cases -----------------------------------------------------------
def grid(**axes) -> list[dict]:
    """Every combination of the given values (the last axis varies fastest)."""
    for name, values in axes.items():
        if isinstance(values, (str, bytes, dict)) or not isinstance(values, Iterable):
            raise InputError(name, f"a grid axis must be a list of values, got {values!r}")
        axes[name] = list(values)
        if not axes[name]:
            raise InputError(name, "a grid axis needs at least one value, got an empty list")
    names = list(axes)
    return [dict(zip(names, combo, strict=True)) for combo in itertools.product(*axes.values())]


def sample(n: int, *, seed: int = 0, fixed: dict | None = None, **ranges) -> list[dict]:
    """``n`` cases with each named parameter uniform in its ``(low, high)`` range
    (a reproducible sample: ``seed``), plus the ``fixed`` parameters."""
    n = _integer("n", n, 1)
    seed = _integer("seed", seed, 0)
    fixed = dict(fixed or {})
    for name in ranges:
        if name in fixed:
            raise InputError(name, "is both sampled and fixed; give it in one place")
    rng = np.random.default_rng(seed)
    draws = {}
    for name, bounds in ranges.items():
        try:
            low, high = (float(b) for b in bounds)
            ok = math.isfinite(low) and math.isfinite(high) and low < high
        except (TypeError, ValueError):
            ok = False
        if isinstance(bounds, (str, bytes)) or not ok:
            raise InputError(
                name, f"a sampled parameter needs [low, high], finite, low < high; got {bounds!r}"
            )
        draws[name] = rng.uniform(low, high, n)
    return [fixed | {k: float(v[i]) for k, v in draws.items()} for i in range(n)]


def _model_name(model: Callable) -> str:
    return f"{getattr(model, '__module__', '?')}.{getattr(model, '__qualname__', repr(model))}"


def case_key(model: Callable, case: dict) -> str:
    """Hash of the model's name and the case's parameters (the cache file name)."""
    text = json.dumps([_model_name(model), case], sort_keys=True, default=str)
    return hashlib.sha1(text.encode()).hexdigest()[:16]


def describe(case: dict) -> str:
    """A case as ``name=value, ...`` (how failed cases are named to the user)."""
    return ", ".join(f"{k}={v}" for k, v in case.items())


def _parameters(model: Callable) -> tuple[list[str] | None, list[str]]:
    """(names the model accepts, or None for any; names it requires), from its signature."""
    try:
        signature = inspect.signature(model)
    except (TypeError, ValueError):
        return None, []
    kinds = (inspect.Parameter.POSITIONAL_OR_KEYWORD, inspect.Parameter.KEYWORD_ONLY)
    params = signature.parameters.values()
    names = [p.name for p in params if p.kind in kinds]
    required = [p.name for p in params if p.kind in kinds and p.default is inspect.Parameter.empty]
    if any(p.kind is inspect.Parameter.VAR_KEYWORD for p in params):
        return None, required
    return names, required


def _check_cases(model: Callable, cases: list[dict]) -> None:
    """Refuse cases the model cannot take (a misspelt or missing parameter): otherwise every
    case would fail the same way after the study had been scheduled."""
    accepted, required = _parameters(model)
    name = getattr(model, "__name__", repr(model))
    for i, case in enumerate(cases):
        unknown = [k for k in case if accepted is not None and k not in accepted]
        missing = [k for k in required if k not in case]
        if unknown or missing:
            what = f"unknown parameter {unknown[0]!r}" if unknown else f"missing parameter {missing[0]!r}"
            options = f" (its parameters: {', '.join(accepted)})" if accepted is not None else ""
            raise InputError("cases", f"case {i} ({describe(case)}): {what} for {name}(){options}")


# --- one case ---------------------------------------------------------------------
def _plain(name: str, value):
    """An output as a JSON scalar (numpy scalars unwrapped), raising for anything else."""
    if isinstance(value, np.generic):
        value = value.item()
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    raise TypeError(f"output {name!r} must be a number, a string, a bool or None, got {type(value).__name__}")


def _evaluate(model: Callable, case: dict) -> dict:
    """One case: outputs with status "ok", or the error with status "failed" (never raises:
    one case's failure, whatever it is, must not stop the study; its message is kept)."""
    start = time.perf_counter()
    try:
        outputs = {str(k): _plain(str(k), v) for k, v in dict(model(**case)).items()}
        status, error = "ok", ""
    except Exception as exc:  # noqa: BLE001 - recorded in the table, see above
        outputs, status, error = {}, "failed", _first_line(exc)
    return {"outputs": outputs, "status": status, "error": error, "time_s": time.perf_counter() - start}


def _first_line(exc: BaseException) -> str:
    return (f"{type(exc).__name__}: {exc}".splitlines() or [type(exc).__name__])[0]


# --- the cache --------------------------------------------------------------------
SCHEMA = "skcable.study cache entry"
SCHEMA_VERSION = 1
#: A lock not refreshed for this long (s) belongs to a run that died.
STALE_AFTER = 60.0
_HEARTBEAT = 10.0  # s between refreshes of the locks a run holds
_POLL = 0.1  # s between looks at cases another run is computing
_HOST = socket.gethostname()


def _canonical(value):
    """``value`` as it reads back from JSON (how parameters and results are compared)."""
    return json.loads(json.dumps(value, sort_keys=True, default=str))


def _checksum(entry: dict) -> str:
    body = {k: v for k, v in entry.items() if k != "checksum"}
    text = json.dumps(body, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def _pid_alive(pid) -> bool:
    if os.name == "nt":  # os.kill(pid, 0) would terminate it: rely on the lock's age
        return True
    if isinstance(pid, bool) or not isinstance(pid, int) or pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # exists, not ours to signal
        return True
    return True


class _Cache:
    """A folder of verified entries, one per case key, and the locks of cases in progress."""

    def __init__(self, folder: Path, model: Callable):
        from skcable import __version__

        self.folder = folder
        self.model = _model_name(model)
        self.version = __version__
        self.held: dict[str, str] = {}  # key -> token of the locks this run holds
        self.warned: set[str] = set()
        self._stop = threading.Event()
        self._heart: threading.Thread | None = None
        folder.mkdir(parents=True, exist_ok=True)
        for temp in folder.glob(TEMP_GLOB):  # left by a killed writer (writes take milliseconds)
            with contextlib.suppress(OSError):
                if time.time() - temp.stat().st_mtime > 600:
                    temp.unlink()
        for lock in folder.glob("*.lock"):  # left by a killed run
            with contextlib.suppress(OSError):
                if self._stale(lock):
                    lock.unlink()

    def entry_path(self, key: str) -> Path:
        return self.folder / f"{key}.json"

    def lock_path(self, key: str) -> Path:
        return self.folder / f"{key}.lock"

    # entries
    def read(self, key: str, case: dict) -> dict | None:
        """The verified result of ``case``, or None (no entry, or one that cannot be used:
        warned about once, then recomputed)."""
        path = self.entry_path(key)
        try:
            raw = path.read_bytes()
        except FileNotFoundError:
            return None
        except OSError as exc:
            result, problem = None, f"cannot be read ({exc.strerror})"
        else:
            result, problem = self._verify(raw, case)
        if problem is not None:
            if str(path) not in self.warned:
                self.warned.add(str(path))
                message = f"study cache: {path} {problem}; recomputing that case ({describe(case)})"
                warnings.warn(message, CacheWarning, stacklevel=2)
            return None
        return result

    def _verify(self, raw: bytes, case: dict) -> tuple[dict | None, str | None]:
        if not raw.strip():
            return None, f"is empty ({len(raw)} bytes)"
        try:
            entry = json.loads(raw.decode("utf-8"))
        except UnicodeDecodeError:
            return None, "is not UTF-8 text"
        except json.JSONDecodeError as exc:
            return None, f"is not valid JSON, truncated or damaged ({exc.msg}, line {exc.lineno})"
        if not isinstance(entry, dict) or entry.get("schema") != SCHEMA:
            return None, f"is not a {SCHEMA}"
        if entry.get("schema_version") != SCHEMA_VERSION:
            return (
                None,
                f"has schema version {entry.get('schema_version')!r}; this skcable reads {SCHEMA_VERSION}",
            )
        if entry.get("checksum") != _checksum(entry):
            return None, "does not match its checksum (edited or damaged)"
        if entry.get("skcable_version") != self.version:
            return None, f"was computed by skcable {entry.get('skcable_version')}, this is {self.version}"
        if entry.get("model") != self.model:
            return None, f"belongs to model {entry.get('model')}, not {self.model}"
        if entry.get("parameters") != _canonical(case):
            return None, f"holds the parameters {entry.get('parameters')}, not this case's"
        result = entry.get("result")
        if (
            not isinstance(result, dict)
            or result.get("status") not in ("ok", "failed")
            or not isinstance(result.get("outputs"), dict)
            or not isinstance(result.get("error"), str)
            or not isinstance(result.get("time_s"), (int, float))
        ):
            return None, "holds a malformed result"
        return result, None

    def write(self, key: str, case: dict, result: dict) -> None:
        entry = {
            "schema": SCHEMA,
            "schema_version": SCHEMA_VERSION,
            "skcable_version": self.version,
            "model": self.model,
            "key": key,
            "parameters": _canonical(case),
            "result": result,
        }
        entry["checksum"] = _checksum(entry)
        write_text(self.entry_path(key), json.dumps(entry, indent=1, sort_keys=True) + "\n")

    # locks
    def acquire(self, key: str) -> bool:
        """Lock ``key`` for this run; False when a live run holds it."""
        path = self.lock_path(key)
        token = secrets.token_hex(8)
        for _ in range(3):
            try:
                fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                if not self._stale(path):
                    return False
                with contextlib.suppress(FileNotFoundError):
                    path.unlink()  # a dead run's lock
                continue
            with os.fdopen(fd, "w") as handle:
                json.dump({"host": _HOST, "pid": os.getpid(), "token": token}, handle)
            self.held[key] = token
            self._beat()
            return True
        return False

    def _stale(self, path: Path) -> bool:
        try:
            age = time.time() - path.stat().st_mtime
            raw = path.read_bytes()
        except FileNotFoundError:
            return True
        if age > STALE_AFTER:
            return True
        try:
            owner = json.loads(raw)
        except ValueError:
            return False  # created a moment ago and not yet filled
        return isinstance(owner, dict) and owner.get("host") == _HOST and not _pid_alive(owner.get("pid"))

    def release(self, key: str) -> None:
        token = self.held.pop(key, None)
        if token is None:
            return
        path = self.lock_path(key)
        with contextlib.suppress(OSError, ValueError):
            if json.loads(path.read_bytes()).get("token") == token:
                path.unlink()

    def _beat(self) -> None:
        if self._heart is None:
            self._heart = threading.Thread(target=self._refresh, name="skcable-cache-locks", daemon=True)
            self._heart.start()

    def _refresh(self) -> None:
        while not self._stop.wait(_HEARTBEAT):
            for key in list(self.held):
                with contextlib.suppress(OSError):
                    os.utime(self.lock_path(key))

    def close(self) -> None:
        for key in list(self.held):
            self.release(key)
        self._stop.set()


# --- executors ----------------------------------------------------------------------
def _dask_available() -> bool:
    try:
        import distributed  # noqa: F401
    except ImportError:
        return False
    return True


def _check_scheduler(scheduler: str) -> None:
    """Refuse an address no dask scheduler can have (before any computing)."""
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


class _Runner:
    """Computes batches of cases serially or on Dask (a cluster started once, on first use)."""

    def __init__(self, model, use_dask: bool, scheduler, n_workers: int, progress: bool):
        self.model, self.use_dask, self.scheduler = model, use_dask, scheduler
        self.n_workers, self.progress = n_workers, progress
        self.client = self.cluster = None

    def compute(self, todo, finish, bar) -> None:
        if not self.use_dask:
            for key, case in todo:
                finish(key, _evaluate(self.model, case))
                bar.update()
            return
        from distributed import as_completed

        client = self._connect()
        futures = {
            client.submit(
                _evaluate, self.model, case, key=f"skcable-{key}-{secrets.token_hex(4)}", pure=False
            ): key
            for key, case in todo
        }
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as exc:  # noqa: BLE001 - a worker died or the task could not be sent
                result = {"outputs": {}, "status": "failed", "error": _first_line(exc), "time_s": 0.0}
            finish(futures[future], result)
            bar.update()

    def _connect(self):
        if self.client is not None:
            return self.client
        from distributed import Client, LocalCluster

        if self.scheduler is None:
            self.cluster = LocalCluster(
                n_workers=self.n_workers, threads_per_worker=1, processes=True, dashboard_address=":0"
            )
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

    def close(self) -> None:
        if self.client is not None:
            self.client.close()
        if self.cluster is not None:
            self.cluster.close()


# --- running --------------------------------------------------------------------
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

    Parameters
    ----------
    model : callable
        Returns a dict of scalar outputs; importable by the workers (a module-level function).
    cases : list of dict
        Keyword arguments per case (see `grid` and `sample`); a case the model's
        signature cannot take (misspelt or missing parameter) is refused before computing.
    executor : {"auto", "dask", "serial"}
        "auto": Dask when installed, else serial.
    scheduler : str, optional
        Address of a running ``dask.distributed`` scheduler (``tcp://host:8786``);
        default: a local cluster of ``n_workers`` single-threaded processes.
    n_workers : int, optional
        Processes of the local cluster (default 2), >= 1; not with ``scheduler``.
    cache : path, optional
        Folder of finished cases (one verified JSON entry per case key); finished cases are
        read, not rerun; runs sharing the folder split the cases between them.
    progress : bool
        A progress bar (stderr); with Dask, the dashboard link is printed too.

    Raises
    ------
    InputError
        A bad argument, before any case is computed.
    """
    if executor not in ("auto", "dask", "serial"):
        raise InputError("executor", f"must be 'auto', 'dask' or 'serial', got {executor!r}")
    if not callable(model):
        raise InputError("model", f"must be a callable returning a dict, got {model!r}")
    if isinstance(cases, dict) or not isinstance(cases, Iterable):
        raise InputError("cases", f"must be a list of dicts, got {type(cases).__name__}")
    cases = list(cases)
    if not all(isinstance(c, dict) for c in cases):
        raise InputError("cases", "must be a list of dicts (keyword arguments of the model)")
    cases = [dict(c) for c in cases]
    if not cases:
        raise InputError("cases", "the study has no cases")
    _check_cases(model, cases)
    use_dask = executor == "dask" or (executor == "auto" and _dask_available())
    if use_dask and not _dask_available():
        what = "executor" if executor == "dask" else "scheduler"
        raise InputError(what, "Dask needs the optional extra: pip install 'skcable[cluster]'")
    if scheduler is not None:
        if executor == "serial":
            raise InputError("scheduler", "executor='serial' runs in this process; drop one of them")
        if not use_dask:
            raise InputError("scheduler", "needs Dask, the optional extra: pip install 'skcable[cluster]'")
        _check_scheduler(scheduler)
    if n_workers is not None:
        n_workers = _integer("n_workers", n_workers, 1)
        if scheduler is not None:
            raise InputError("n_workers", "sizes the local Dask cluster; the scheduler's cluster has its own")
    folder = None if cache is None else writable_dir("cache", cache)

    keys = [case_key(model, c) for c in cases]
    unique = dict(zip(keys, cases, strict=True))  # a case listed twice runs once
    results: dict[str, dict] = {}
    store = _Cache(folder, model) if folder is not None else None
    runner = _Runner(model, use_dask, scheduler, 2 if n_workers is None else n_workers, progress)
    from tqdm import tqdm

    def finish(key, result):
        result = _canonical(result)  # a fresh result reads as a cached one
        if store is not None:
            store.write(key, unique[key], result)
            store.release(key)
        results[key] = result

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
            if store is None:
                runner.compute(list(pending.items()), finish, bar)
            else:
                _share(store, pending, runner, finish, results, bar)
    finally:
        if store is not None:
            store.close()
        runner.close()
    table = _table(cases, keys, results)
    table.attrs.update(model=_model_name(model), from_cache=from_cache)
    return table


def _share(store: _Cache, pending: dict, runner: _Runner, finish, results: dict, bar) -> None:
    """Compute the pending cases no other run is computing; then collect the others' (or
    take over those whose run died)."""
    waited = False
    while pending:
        mine, theirs = [], {}
        for key, case in pending.items():
            result = store.read(key, case)
            if result is None and store.acquire(key):
                result = store.read(key, case)  # finished by another run since the first look
                if result is None:
                    mine.append((key, case))
                    continue
                store.release(key)
            if result is not None:
                results[key] = result
                bar.update()
            else:
                theirs[key] = case
        if mine:
            runner.compute(mine, finish, bar)
        elif theirs:
            if not waited:
                waited = True
                bar.set_description("study (waiting for cases another run is computing)")
            time.sleep(_POLL)
        pending = theirs


class StudyTable(pd.DataFrame):
    """A study's table: a pandas DataFrame that prints as a short summary (a header with
    the number of cases, ok and failed, then at most 10 rows and 8 columns, without
    ``time_s`` and ``key``). The full table: ``table.to_string()``."""

    @property
    def _constructor(self):
        return StudyTable

    def summary(self) -> str:
        model = str(self.attrs.get("model", "")).rsplit(".", 1)[-1]
        head = f"skcable study{' of ' + model if model else ''}: {len(self)} cases"
        if "status" in self.columns:
            failed = int((self["status"] != "ok").sum())
            head += f", {len(self) - failed} ok, {failed} failed"
        shown = pd.DataFrame(self).drop(columns=["time_s", "key"], errors="ignore")
        body = shown.to_string(max_rows=10, min_rows=10, max_cols=8, max_colwidth=28)
        tail = f"[{len(self)} rows x {len(self.columns)} columns: the full table is table.to_string()]"
        return f"{head}\n{body}\n{tail}"

    def __repr__(self) -> str:
        return self.summary()


def _table(cases, keys, results) -> StudyTable:
    rows = []
    for case, key in zip(cases, keys, strict=True):
        result = results[key]
        # an output named like a parameter (a cable's achieved sag for a given sag) gets a suffix
        outputs = {(f"{k}_result" if k in case else k): v for k, v in result["outputs"].items()}
        meta = {"status": result["status"], "error": result["error"], "time_s": result["time_s"], "key": key}
        rows.append(case | outputs | meta)
    return StudyTable(rows)


# --- study files ------------------------------------------------------------------
_FILE_KEYS = ("model", "output", "cache", "grid", "sample", "fixed")


def load_study(path) -> dict:
    """Read a study file (TOML): ``model``, ``[grid]`` or ``[sample]``, ``[fixed]``,
    ``output`` and ``cache`` (paths relative to the working directory; default output
    ``<file stem>.csv``). Returns ``model``, ``cases``, ``output``, ``cache``.

    ``[sample]`` holds ``n``, ``seed`` and ``[low, high]`` ranges. Unknown keys, both
    ``[grid]`` and ``[sample]``, a parameter given twice or one the model does not take
    are refused (`skcable.InputError`), never ignored.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("path", f"no study file at {str(path)!r}")
    try:
        spec = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputError("path", f"{path.name} is not valid TOML: {exc}") from None
    for key in spec:
        if key not in _FILE_KEYS:
            raise InputError(key, f"unknown key in {path.name}; a study file holds {', '.join(_FILE_KEYS)}")
    name = spec.get("model")
    if name not in MODELS:
        raise InputError("model", f"must be one of {', '.join(MODELS)}, got {name!r}")
    model = MODELS[name]
    if "grid" in spec and "sample" in spec:
        raise InputError("sample", f"{path.name} has both [grid] and [sample]; a study is one or the other")
    for table in ("grid", "sample", "fixed"):
        if table in spec and not isinstance(spec[table], dict):
            raise InputError(table, f"must be a table [{table}], got {spec[table]!r}")
    fixed = spec.get("fixed", {})
    if "grid" in spec:
        axes = spec["grid"]
        if not axes:
            raise InputError("grid", "is empty: give at least one parameter and its values")
        _check_names(model, name, "grid", axes, fixed)
        cases = [fixed | case for case in grid(**axes)]
    elif "sample" in spec:
        options = dict(spec["sample"])
        if "n" not in options:
            raise InputError("sample", "needs n, the number of cases")
        n, seed = options.pop("n"), options.pop("seed", 0)
        _check_names(model, name, "sample", options, fixed)
        cases = sample(n, seed=seed, fixed=fixed, **options)
    else:
        raise InputError("grid", f"{path.name} needs a [grid] or a [sample] table")
    accepted, required = _parameters(model)
    missing = [k for k in required if k not in cases[0]]
    if missing:
        raise InputError(
            "fixed", f"{name} needs {', '.join(missing)}: give it in [fixed], [grid] or [sample]"
        )
    for key in ("output", "cache"):
        if key in spec and (not isinstance(spec[key], str) or not spec[key].strip()):
            raise InputError(key, f"must be a path (a string), got {spec[key]!r}")
    output = Path(spec.get("output", path.with_suffix(".csv").name))
    if output.suffix.lower() not in TABLE_SUFFIXES:
        raise InputError("output", f"unknown extension {output.suffix or '(none)'!r}; use .csv or .parquet")
    cache = Path(spec["cache"]) if "cache" in spec else None
    return {"model": model, "cases": cases, "output": output, "cache": cache}


def _check_names(model, model_name: str, table: str, names, fixed: dict) -> None:
    accepted, _ = _parameters(model)
    for name in list(names) + list(fixed):
        if accepted is not None and name not in accepted:
            where = table if name in names else "fixed"
            raise InputError(
                where, f"{name!r} is not a parameter of {model_name} (its parameters: {', '.join(accepted)})"
            )
    for name in names:
        if name in fixed:
            raise InputError("fixed", f"{name!r} is in both [fixed] and [{table}]; give it in one of them")


def check_output(name: str, path) -> Path:
    """``path`` as a Path if a study table (CSV or Parquet) can be written there, refused with
    ``InputError(name, ...)`` otherwise."""
    path = writable_file(name, path, TABLE_SUFFIXES)
    if path.suffix.lower() == ".parquet":
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise InputError(name, "a .parquet table needs pyarrow: pip install 'skcable[cluster]'") from None
    return path


def run_file(
    path, *, scheduler=None, executor="auto", n_workers=None, progress=True, output=None, cache=None
):
    """Run the study described by a TOML file and write its table (CSV, or Parquet for a
    ``.parquet`` output; written atomically); ``output`` and ``cache`` override the file's.
    Every path is checked before computing. Returns (table, path)."""
    study = load_study(path)
    output = check_output("output", output if output is not None else study["output"])
    cache = cache if cache is not None else study["cache"]
    if cache is not None:
        cache = writable_dir("cache", cache)
    table = run(
        study["model"],
        study["cases"],
        executor=executor,
        scheduler=scheduler,
        n_workers=n_workers,
        cache=cache,
        progress=progress,
    )
    with atomic_path(output) as temp:
        if output.suffix.lower() == ".parquet":
            table.to_parquet(temp, index=False)
        else:
            table.to_csv(temp, index=False)
    return table, output
