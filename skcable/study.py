"""Parameter studies: a grid or a sample of cases over a model function, run on Dask.

A study is a list of cases (dicts of keyword arguments) and a model
function that turns one case into a dict of outputs. :func:`run` maps the
function over the cases on a Dask cluster (a local cluster of processes by
default, or any ``dask.distributed`` scheduler address) or serially, and
collects one row per case into a pandas DataFrame:

    case parameters | outputs | status ("ok" / "failed") | error | time_s | key

(an output named like a parameter gets the suffix ``_result``: a cable solved
for a given ``sag`` reports the sag it reached as ``sag_result``).

A failing case (bad parameters, no convergence) is recorded with its error
and does not stop the study. With ``cache=`` every finished case is written
to ``<cache>/<key>.json`` as soon as it ends, and a later run with the same
cache reads it back instead of recomputing: an interrupted study resumes.
The key is a hash of the model's name and the case's parameters.

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

import hashlib
import itertools
import json
import sys
import time
from collections.abc import Callable, Iterable
from pathlib import Path

import numpy as np

from skcable.errors import InputError

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = ["MODELS", "cable_solve", "grid", "load_study", "run", "run_file", "sample", "strand_capacity"]


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

    s = strand.preset(preset)
    s = s.damaged(int(damage)) if damage else s
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


def cable_solve(span: float, w: float, dh: float = 0.0, EA: float | None = None, **constraint) -> dict:
    """Catenary (or, with ``EA``, Irvine's elastic catenary given ``length``): H, T_max,
    length, sag (N, m) and the equilibrium residual."""
    from skcable import cable

    if EA is None:
        sol = cable.catenary(span, dh, w, **constraint)
    else:
        sol = cable.elastic_catenary(span, dh, w, EA, **constraint)
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
        if isinstance(values, str) or not isinstance(values, Iterable):
            raise InputError(name, f"a grid axis must be a list of values, got {values!r}")
    names = list(axes)
    return [dict(zip(names, combo, strict=True)) for combo in itertools.product(*axes.values())]


def sample(n: int, *, seed: int = 0, fixed: dict | None = None, **ranges) -> list[dict]:
    """``n`` cases with each named parameter uniform in its ``(low, high)`` range
    (a reproducible sample: ``seed``), plus the ``fixed`` parameters."""
    if int(n) < 1:
        raise InputError("n", f"must be at least 1, got {n!r}")
    rng = np.random.default_rng(seed)
    draws = {}
    for name, bounds in ranges.items():
        if np.shape(bounds) != (2,) or not bounds[0] < bounds[1]:
            raise InputError(name, f"a sampled parameter needs (low, high) with low < high, got {bounds!r}")
        draws[name] = rng.uniform(bounds[0], bounds[1], int(n))
    return [dict(fixed or {}) | {k: float(v[i]) for k, v in draws.items()} for i in range(int(n))]


def case_key(model: Callable, case: dict) -> str:
    """Hash of the model's name and the case's parameters (the cache file name)."""
    text = json.dumps([model.__module__ + "." + model.__qualname__, case], sort_keys=True, default=str)
    return hashlib.sha1(text.encode()).hexdigest()[:16]


# --- running --------------------------------------------------------------------
def _evaluate(model: Callable, case: dict) -> dict:
    """One case: outputs with status "ok", or the error with status "failed" (never raises:
    one case's failure, whatever it is, must not stop the study; its message is kept)."""
    start = time.perf_counter()
    try:
        outputs = dict(model(**case))
        status, error = "ok", ""
    except Exception as exc:  # noqa: BLE001 - recorded in the table, see above
        outputs, status, error = {}, "failed", f"{type(exc).__name__}: {exc}".splitlines()[0]
    return {"outputs": outputs, "status": status, "error": error, "time_s": time.perf_counter() - start}


def _dask_available() -> bool:
    try:
        import distributed  # noqa: F401
    except ImportError:
        return False
    return True


def run(
    model: Callable[..., dict],
    cases: list[dict],
    *,
    executor: str = "auto",
    scheduler: str | None = None,
    n_workers: int = 2,
    cache=None,
    progress: bool = True,
):
    """Run ``model(**case)`` for every case; return a pandas DataFrame, one row per case.

    Parameters
    ----------
    model : callable
        Returns a dict of scalar outputs; importable by the workers (a module-level function).
    cases : list of dict
        Keyword arguments per case (see :func:`grid` and :func:`sample`).
    executor : {"auto", "dask", "serial"}
        "auto": Dask when installed, else serial.
    scheduler : str, optional
        Address of a running ``dask.distributed`` scheduler (``tcp://host:8786``);
        default: a local cluster of ``n_workers`` single-threaded processes.
    cache : path, optional
        Folder of finished cases (one JSON per case key); finished cases are read, not rerun.
    progress : bool
        A progress bar (stderr); with Dask, the dashboard link is printed too.
    """
    if executor not in ("auto", "dask", "serial"):
        raise InputError("executor", f"must be 'auto', 'dask' or 'serial', got {executor!r}")
    if not callable(model):
        raise InputError("model", f"must be a callable returning a dict, got {model!r}")
    cases = [dict(c) for c in cases]
    if not cases:
        raise InputError("cases", "the study has no cases")
    use_dask = executor == "dask" or (executor == "auto" and _dask_available())
    if use_dask and not _dask_available():
        raise InputError("executor", "'dask' needs the optional extra: pip install 'skcable[cluster]'")
    keys = [case_key(model, c) for c in cases]
    folder = Path(cache) if cache is not None else None
    results: dict[str, dict] = {}
    if folder is not None:
        folder.mkdir(parents=True, exist_ok=True)
        for key in keys:
            stored = folder / f"{key}.json"
            if stored.exists():
                results[key] = json.loads(stored.read_text())
    todo = [(k, c) for k, c in zip(keys, cases, strict=True) if k not in results]
    todo = list(dict(todo).items())  # a case listed twice runs once

    def finish(key, result):
        results[key] = result
        if folder is not None:
            (folder / f"{key}.json").write_text(json.dumps(result))

    from tqdm import tqdm

    with tqdm(total=len(todo), desc="study", unit="case", disable=not progress, file=sys.stderr) as bar:
        if use_dask and todo:
            _run_dask(model, todo, scheduler, n_workers, finish, bar, progress)
        else:
            for key, case in todo:
                finish(key, _evaluate(model, case))
                bar.update()
    return _table(cases, keys, results)


def _run_dask(model, todo, scheduler, n_workers, finish, bar, progress):
    from distributed import Client, LocalCluster, as_completed

    cluster = None
    if scheduler is None:
        cluster = LocalCluster(
            n_workers=int(n_workers), threads_per_worker=1, processes=True, dashboard_address=":0"
        )
        client = Client(cluster)
    else:
        client = Client(scheduler)
    try:
        if progress:
            print(f"dask dashboard: {client.dashboard_link}", file=sys.stderr)
        futures = {
            client.submit(_evaluate, model, case, key=f"skcable-{key}", pure=False): key for key, case in todo
        }
        for future in as_completed(futures):
            finish(futures[future], future.result())
            bar.update()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _table(cases, keys, results):
    import pandas as pd

    rows = []
    for case, key in zip(cases, keys, strict=True):
        result = results[key]
        # an output named like a parameter (a cable's achieved sag for a given sag) gets a suffix
        outputs = {(f"{k}_result" if k in case else k): v for k, v in result["outputs"].items()}
        meta = {"status": result["status"], "error": result["error"], "time_s": result["time_s"], "key": key}
        rows.append(case | outputs | meta)
    return pd.DataFrame(rows)


# --- study files ------------------------------------------------------------------
def load_study(path) -> dict:
    """Read a study file (TOML): ``model``, ``[grid]`` or ``[sample]``, ``[fixed]``,
    ``output`` and ``cache`` (paths relative to the working directory; default output
    ``<file stem>.csv``). Returns ``model``, ``cases``, ``output``, ``cache``.

    ``[sample]`` holds ``n``, ``seed`` and ``(low, high)`` ranges.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("path", f"no study file at {str(path)!r}")
    try:
        spec = tomllib.loads(path.read_text())
    except tomllib.TOMLDecodeError as exc:
        raise InputError("path", f"{path.name} is not valid TOML: {exc}") from None
    name = spec.get("model")
    if name not in MODELS:
        raise InputError("model", f"must be one of {', '.join(MODELS)}, got {name!r}")
    fixed = spec.get("fixed", {})
    if "grid" in spec:
        cases = [fixed | case for case in grid(**spec["grid"])]
    elif "sample" in spec:
        options = dict(spec["sample"])
        n, seed = options.pop("n", None), options.pop("seed", 0)
        if n is None:
            raise InputError("sample", "needs n, the number of cases")
        cases = sample(n, seed=seed, fixed=fixed, **options)
    else:
        raise InputError("grid", "a study file needs a [grid] or a [sample] table")
    output = Path(spec.get("output", path.with_suffix(".csv").name))
    cache = Path(spec["cache"]) if "cache" in spec else None
    return {"model": MODELS[name], "cases": cases, "output": output, "cache": cache}


def run_file(path, *, scheduler=None, executor="auto", n_workers=2, progress=True, output=None, cache=None):
    """Run the study described by a TOML file and write its table (CSV, or Parquet for a
    ``.parquet`` output); ``output`` and ``cache`` override the file's. Returns (table, path)."""
    study = load_study(path)
    study["output"] = Path(output) if output is not None else study["output"]
    study["cache"] = Path(cache) if cache is not None else study["cache"]
    table = run(
        study["model"],
        study["cases"],
        executor=executor,
        scheduler=scheduler,
        n_workers=n_workers,
        cache=study["cache"],
        progress=progress,
    )
    output = study["output"]
    output.parent.mkdir(parents=True, exist_ok=True)
    if output.suffix == ".parquet":
        table.to_parquet(output, index=False)
    else:
        table.to_csv(output, index=False)
    return table, output
