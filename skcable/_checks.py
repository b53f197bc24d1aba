"""Argument checks shared by the public functions.

Each check returns the argument as a Python float (scalar input, which
keeps scalar calls fast, see :mod:`skcable._xp`) or as a float array, and raises
:class:`skcable.errors.InputError` naming the argument otherwise.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import InputError


def _first_bad(arr: np.ndarray, bad: np.ndarray) -> str:
    index = np.argwhere(bad)[0]
    value = f"{float(arr[tuple(index)]):.17g}"
    return value if arr.ndim == 0 else f"{value} at index {tuple(int(i) for i in index)}"


def real(name: str, value) -> np.ndarray | float:
    """Return ``value`` as a float (scalar input) or float array, raising if
    it is not finite."""
    if isinstance(value, (float, int)) and not isinstance(value, bool):
        value = float(value)
        if value != value or value in (float("inf"), float("-inf")):
            raise InputError(name, f"must be finite, got {value!r}")
        return value
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(name, f"must be a real number or array of them, got {value!r}") from exc
    bad = ~np.isfinite(arr)
    if bad.any():
        raise InputError(name, f"must be finite, got {_first_bad(arr, bad)}")
    return float(arr) if arr.ndim == 0 else arr


def positive(name: str, value) -> np.ndarray | float:
    """Return ``value`` as float, raising unless it is finite and > 0."""
    arr = real(name, value)
    if not isinstance(arr, np.ndarray):
        if not arr > 0:
            raise InputError(name, f"must be > 0, got {arr!r}")
        return arr
    bad = ~(arr > 0)
    if bad.any():
        raise InputError(name, f"must be > 0, got {_first_bad(arr, bad)}")
    return arr


def nonnegative(name: str, value) -> np.ndarray | float:
    """Return ``value`` as float, raising unless it is finite and >= 0."""
    arr = real(name, value)
    require(name, arr >= 0, "must be >= 0", arr)
    return arr


def require(name: str, ok, reason: str, value) -> None:
    """Raise ``InputError(name, reason)`` where the boolean ``ok`` is False."""
    if ok is True or (not isinstance(ok, np.ndarray) and ok):
        return
    ok = np.asarray(ok)
    if not ok.all():
        arr = np.broadcast_to(np.asarray(value, dtype=float), ok.shape)
        raise InputError(name, f"{reason}, got {_first_bad(arr, ~ok)}")


def exactly_one(**constraints) -> tuple[str, object]:
    """Return the one keyword whose value is not None, raising otherwise."""
    given = [(k, v) for k, v in constraints.items() if v is not None]
    if len(given) != 1:
        names = ", ".join(constraints)
        got = ", ".join(k for k, _ in given) or "none"
        raise InputError("constraint", f"give exactly one of {names} (the 'fourth equation'); got {got}")
    return given[0]
