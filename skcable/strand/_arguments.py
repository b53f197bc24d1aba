"""Argument checks of `skcable.strand`: single real numbers (with an optional lower bound),
principal-axis indices, float arrays and names, each refusing what it does not
take with an `~skcable.errors.InputError` naming the argument."""

from __future__ import annotations

import numbers

import numpy as np

from skcable.errors import InputError

__all__ = ["float_array", "is_real_number", "name_text", "principal_axis", "real_number"]


def is_real_number(value) -> bool:
    """A real number (a 0-d array included), not a bool."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    return isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))


def real_number(name: str, value, *, lower: float | None = None, strict: bool = False) -> float:
    """``value`` as a finite float, refusing booleans, strings, arrays and non-finite numbers.

    With ``lower``, also refuse values below it (``strict``: at or below it).
    """
    if not is_real_number(value):
        if isinstance(value, (np.ndarray, list, tuple)):
            raise InputError(name, f"must be a single real number, got an array of shape {np.shape(value)}")
        raise InputError(name, f"must be a real number, got {value!r}")
    out = float(value)
    if out != out or out in (float("inf"), float("-inf")):
        raise InputError(name, f"must be finite, got {out!r}")
    if lower is not None and (out <= lower if strict else out < lower):
        raise InputError(name, f"must be {'>' if strict else '>='} {lower:g}, got {out!r}")
    return out


def principal_axis(value) -> int:
    """A principal-axis index: the int 0 (principal axis 1) or 1 (principal axis 2)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) or value not in (0, 1):
        raise InputError(
            "axis", f"must be the int 0 (principal axis 1) or 1 (principal axis 2), got {value!r}"
        )
    return int(value)


def float_array(name: str, value, *, finite: bool = True, empty: bool = False) -> np.ndarray:
    """``value`` as a float ndarray (any shape), refusing strings, booleans, objects,
    non-finite entries (unless ``finite=False``) and empty arrays (unless ``empty``)."""
    if isinstance(value, (str, bytes, bool, np.bool_)) or value is None:
        raise InputError(name, f"must be a real number or an array of them, got {value!r}")
    try:
        raw = np.asarray(value)
    except ValueError as exc:  # ragged nested sequences
        raise InputError(name, f"must be a real number or a regular array of them ({exc})") from None
    if raw.dtype.kind not in "iuf":
        raise InputError(
            name, f"must be a real number or an array of them, got dtype {raw.dtype} ({value!r:.60})"
        )
    if raw.size == 0 and not empty:
        raise InputError(name, "must not be empty")
    arr = raw.astype(float, copy=False)
    if finite:
        bad = ~np.isfinite(arr)
        if bad.any():
            index = tuple(int(i) for i in np.argwhere(bad)[0])
            where = f" at index {index}" if arr.ndim else ""
            raise InputError(name, f"must be finite, got {arr[index]!r}{where}")
    return arr


def name_text(value) -> str:
    if not isinstance(value, str):
        raise InputError("name", f"must be a str, got {value!r}")
    return value
