"""Every number a result carries: its public attributes, walked (properties evaluated)."""

from __future__ import annotations

import numbers
import warnings

import numpy as np

from skcable.errors import ConvergenceError, InputError

__all__ = ["non_finite"]

#: Attributes that hold inputs, models or whole systems, not results (not walked further).
_SKIP = {
    "system",
    "model",
    "line",
    "segments",
    "attachments",
    "strand",
    "matrices",
    "materials",
    "wires",
    "state",
}


def _numbers(value):
    """The numbers of a leaf value as a float array, or None where it holds none."""
    if isinstance(value, (bool, np.bool_)):
        return None
    if isinstance(value, numbers.Real):
        return np.array([float(value)])
    if isinstance(value, np.ndarray) and value.dtype.kind in "fiuc":
        return np.asarray(value, dtype=complex if value.dtype.kind == "c" else float).ravel()
    return None


def non_finite(result, depth: int = 2) -> list[str]:
    """Where ``result`` (a number, array, sequence, mapping, DataFrame or result object)
    holds a NaN or an infinity, as ``"path = value"``; a property that raises another
    exception than `InputError`/`ConvergenceError` is reported as ``"untyped: ..."``."""
    out: list[str] = []
    _walk(result, "result", depth, out, set())
    return out


def _walk(value, path, depth, out, seen):
    leaf = _numbers(value)
    if leaf is not None:
        bad = ~np.isfinite(leaf)
        if bad.any():
            out.append(f"{path} = {leaf[bad][:3].tolist()}")
        return
    if value is None or isinstance(value, (str, bytes)) or depth < 0 or id(value) in seen:
        return
    seen.add(id(value))
    if isinstance(value, dict):
        for key, item in value.items():
            _walk(item, f"{path}[{key!r}]", depth - 1, out, seen)
        return
    if isinstance(value, (list, tuple)):
        for i, item in enumerate(value[:64]):
            _walk(item, f"{path}[{i}]", depth - 1, out, seen)
        return
    if hasattr(value, "select_dtypes"):  # a pandas DataFrame
        data = value.select_dtypes("number").to_numpy(dtype=float)
        if not np.isfinite(data).all():
            out.append(f"{path} has non-finite entries")
        return
    if (
        isinstance(value, np.ndarray)
        or callable(value)
        or type(value).__module__.split(".")[0] not in ("skcable",)
    ):
        return
    for name in dir(type(value)) + list(getattr(value, "__dict__", {})):
        if name.startswith("_") or name in _SKIP:
            continue
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error", DeprecationWarning)  # an old name: its new one is walked
                item = getattr(value, name)
        except (InputError, ConvergenceError, DeprecationWarning):
            continue
        except Exception as exc:  # noqa: BLE001
            out.append(f"untyped: {path}.{name} raised {type(exc).__name__}: {exc}")
            continue
        if callable(item) and not isinstance(item, np.ndarray):
            continue
        _walk(item, f"{path}.{name}", depth - 1, out, seen)
