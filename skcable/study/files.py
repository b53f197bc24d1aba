"""Study files: a study described in TOML, run, and its table written as CSV or Parquet.

A study file holds ``model`` (a name of `skcable.study.tasks.MODELS`), ``[grid]`` (each
parameter's values) or ``[sample]`` (``n``, ``seed`` and each parameter's ``[low, high]``),
``[fixed]`` (parameters common to every case), ``output`` (the table, ``.csv`` or
``.parquet``; default ``<file stem>.csv``) and ``cache`` (a folder); paths are relative to
the working directory. Anything else is refused, never ignored:

    model = "strand_capacity"
    output = "results/pino_vidal_2021_tables_4_1_4_2.csv"
    cache = "results/pino_vidal_2021_cache"

    [grid]
    preset = ["steel-9.5", "aluminium-10.1", "steel-12.7", "aluminium-14.3"]
    damage = [1, 2]
    slip = ["none", "element"]

    [fixed]
    mu = 0.5
    length = 1.0
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from skcable._checks import one_of
from skcable.errors import InputError
from skcable.io._atomic import atomic_path, writable_dir, writable_file
from skcable.study.cases import grid, parameters, sample
from skcable.study.runner import run
from skcable.study.table import StudyTable
from skcable.study.tasks import MODELS

__all__ = ["FILE_KEYS", "TABLE_SUFFIXES", "check_output", "load_study", "run_file", "write_table"]

#: Table formats a study's output may have.
TABLE_SUFFIXES = (".csv", ".parquet")
#: The keys a study file may hold.
FILE_KEYS = ("model", "output", "cache", "grid", "sample", "fixed")


def _read(path: Path) -> dict:
    if not path.is_file():
        raise InputError("path", f"no study file at {str(path)!r}")
    try:
        spec = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputError("path", f"{path.name} is not valid TOML: {exc}") from None
    for key in spec:
        if key not in FILE_KEYS:
            raise InputError(key, f"unknown key in {path.name}; a study file holds {', '.join(FILE_KEYS)}")
    if "grid" in spec and "sample" in spec:
        raise InputError("sample", f"{path.name} has both [grid] and [sample]; a study is one or the other")
    for table in ("grid", "sample", "fixed"):
        if table in spec and not isinstance(spec[table], dict):
            raise InputError(table, f"must be a table [{table}], got {spec[table]!r}")
    return spec


def _check_names(model, model_name: str, table: str, names, fixed: dict) -> None:
    accepted, _ = parameters(model)
    for name in list(names) + list(fixed):
        if accepted is not None and name not in accepted:
            where = table if name in names else "fixed"
            raise InputError(
                where, f"{name!r} is not a parameter of {model_name} (its parameters: {', '.join(accepted)})"
            )
    for name in names:
        if name in fixed:
            raise InputError("fixed", f"{name!r} is in both [fixed] and [{table}]; give it in one of them")


def _cases(spec: dict, model, name: str, filename: str) -> list[dict]:
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
        raise InputError("grid", f"{filename} needs a [grid] or a [sample] table")
    missing = [k for k in parameters(model)[1] if k not in cases[0]]
    if missing:
        raise InputError(
            "fixed", f"{name} needs {', '.join(missing)}: give it in [fixed], [grid] or [sample]"
        )
    return cases


def load_study(path) -> dict:
    """Read a study file (TOML; see the module's notes).

    Parameters
    ----------
    path : path
        The study file.

    Returns
    -------
    dict
        ``model`` (the function), ``cases`` (list of dict), ``output`` (Path) and
        ``cache`` (Path or None).

    Raises
    ------
    InputError
        No such file, not TOML, an unknown key, both ``[grid]`` and ``[sample]``, an
        unknown model, a parameter given twice, one the model does not take or a missing
        one, an empty grid axis, a bad ``n``, an output that is not ``.csv`` or
        ``.parquet`` (named by the key).

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> text = 'model = "cable_solve"\\n[grid]\\nspan = [100.0, 200.0]\\n[fixed]\\nw = 10.0\\nsag = 5.0\\n'
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = Path(folder) / "spans.toml"
    ...     _ = path.write_text(text)
    ...     spec = load_study(path)
    >>> spec["cases"]
    [{'w': 10.0, 'sag': 5.0, 'span': 100.0}, {'w': 10.0, 'sag': 5.0, 'span': 200.0}]
    >>> str(spec["output"]), spec["cache"]
    ('spans.csv', None)
    """
    path = Path(path)
    spec = _read(path)
    name = one_of("model", spec.get("model"), MODELS)
    model = MODELS[name]
    cases = _cases(spec, model, name, path.name)
    for key in ("output", "cache"):
        if key in spec and (not isinstance(spec[key], str) or not spec[key].strip()):
            raise InputError(key, f"must be a path (a string), got {spec[key]!r}")
    output = Path(spec.get("output", path.with_suffix(".csv").name))
    if output.suffix.lower() not in TABLE_SUFFIXES:
        raise InputError("output", f"unknown extension {output.suffix or '(none)'!r}; use .csv or .parquet")
    cache = Path(spec["cache"]) if "cache" in spec else None
    return {"model": model, "cases": cases, "output": output, "cache": cache}


def check_output(name: str, path) -> Path:
    """``path`` as a Path if a study table (``.csv`` or ``.parquet``) can be written there.

    Raises
    ------
    InputError
        ``name`` (the argument's name: ``"output"``, ``"out"``, ...): a folder, an unknown
        extension, an unwritable place, or a ``.parquet`` without pyarrow.
    """
    path = writable_file(name, path, TABLE_SUFFIXES)
    if path.suffix.lower() == ".parquet":
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise InputError(name, "a .parquet table needs pyarrow: pip install 'skcable[cluster]'") from None
    return path


def write_table(table: StudyTable, path: Path) -> None:
    """Write ``table`` to ``path`` atomically: Parquet for ``.parquet``, CSV otherwise (no index)."""
    with atomic_path(path) as temp:
        if path.suffix.lower() == ".parquet":
            table.to_parquet(temp, index=False)
        else:
            table.to_csv(temp, index=False)


def run_file(
    path, *, scheduler=None, executor="auto", n_workers=None, progress=True, output=None, cache=None
):
    """Run the study a TOML file describes (`load_study`) and write its table atomically; every
    path is checked before computing.

    Parameters
    ----------
    path : path
        The study file.
    scheduler, executor, n_workers, progress
        As for `skcable.study.run`.
    output : path, optional
        The table (``.csv`` or ``.parquet``), instead of the file's ``output``.
    cache : path, optional
        The cache folder, instead of the file's ``cache``.

    Returns
    -------
    table : StudyTable
    output : Path
        Where the table was written.

    Raises
    ------
    InputError
        A bad study file, path or argument, before computing.
    """
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
    write_table(table, output)
    return table, output
