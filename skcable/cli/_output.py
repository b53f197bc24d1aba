"""What the ``skcable`` commands print and write.

Printing: every number is checked finite; ``--json`` prints one object (numbers only,
keys as before), the table prints each quantity with its unit, arrays as labelled
columns. Writing: output paths are checked before computing (`skcable.io._atomic`): a
missing parent folder is refused and never created, a folder that takes no new file is
refused naming the path as given, and no earlier file is overwritten without
``--force``. Files appear whole (written to a temporary name, then renamed).
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import shutil
import tempfile
from collections.abc import Iterable, Sequence
from pathlib import Path

from skcable.cli._status import Usage

__all__ = ["check_finite", "output_dir", "output_file", "print_json", "quantities", "staged", "table"]

VTK_SUFFIXES = (".vtu", ".vtk")


def check_finite(values: dict) -> dict:
    """``values`` with every float (nested in lists too) checked finite."""

    def finite(key, value):
        if isinstance(value, float) and not math.isfinite(value):
            raise RuntimeError(f"{key} came out as {value}, not a finite number")
        if isinstance(value, (list, tuple)):
            for item in value:
                finite(key, item)

    for key, value in values.items():
        finite(key, value)
    return values


def print_json(values: dict) -> None:
    print(json.dumps(check_finite(values)))


def _shown(value) -> str:
    if isinstance(value, bool) or not isinstance(value, float):
        return str(value)
    return f"{value:.10g}"


def quantities(rows: Iterable[tuple[str, object, str]], indent: int = 0) -> None:
    """One ``name = value unit`` line per row, the names right-aligned."""
    rows = list(rows)
    check_finite({name: value for name, value, _ in rows})
    width = max(len(name) for name, _, _ in rows)
    for name, value, unit in rows:
        print(f"{' ' * indent}{name:>{width}s} = {_shown(value)}{' ' + unit if unit else ''}".rstrip())


def table(columns: Sequence[tuple[str, Sequence]], indent: int = 0) -> None:
    """Columns ``(header with unit, values)`` side by side, right-aligned, one row per value."""
    check_finite({header: list(values) for header, values in columns})
    cells = [[header, *(_shown(v) for v in values)] for header, values in columns]
    widths = [max(len(c) for c in column) for column in cells]
    for row in zip(*cells, strict=True):
        print(" " * indent + "  ".join(f"{c:>{w}s}" for c, w in zip(row, widths, strict=True)))


# --- output paths ------------------------------------------------------------------
def _refuse_overwrite(flag: str, existing: Sequence[Path]) -> None:
    if existing:
        shown = ", ".join(repr(str(p)) for p in existing[:3]) + (" ..." if len(existing) > 3 else "")
        raise Usage(f"{flag}: would overwrite {shown}: give --force to overwrite, or another {flag}")


def output_file(flag: str, path, force: bool, suffixes=VTK_SUFFIXES) -> Path:
    """The file ``path`` of ``flag`` if it can be written (checked before computing)."""
    from skcable.io._atomic import writable_file

    path = writable_file(flag.lstrip("-"), path, suffixes, create_parents=False)
    _refuse_overwrite(flag, [path] if path.exists() and not force else [])
    return path


def output_dir(flag: str, path, force: bool, patterns: Iterable[str] = ()) -> Path:
    """The folder ``path`` of ``flag`` (created if only it is missing) if it can be written
    and, without ``force``, holds no file matching ``patterns`` (the files to be written)."""
    from skcable.io._atomic import writable_dir

    path = writable_dir(flag.lstrip("-"), path, create_parents=False)
    if path.is_dir() and not force:
        _refuse_overwrite(flag, sorted({p for pattern in patterns for p in path.glob(pattern)}))
    return path


@contextlib.contextmanager
def staged(out: Path, force: bool):
    """A hidden folder inside ``out`` to write into; on a clean exit every file is moved
    into ``out`` with os.replace (each file appears whole; without ``force`` none replaces
    an earlier file); the folder is removed."""
    out.mkdir(exist_ok=True)  # its parent exists: checked by output_dir
    stage = Path(tempfile.mkdtemp(prefix=".skcable-", dir=out))
    try:
        yield stage
        moves = [(p, out / p.relative_to(stage)) for p in sorted(stage.rglob("*")) if p.is_file()]
        _refuse_overwrite("--out", [] if force else [target for _, target in moves if target.exists()])
        for path, target in moves:
            target.parent.mkdir(exist_ok=True)
            os.replace(path, target)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
