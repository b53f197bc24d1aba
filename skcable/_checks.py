"""Argument checks shared by the public functions.

Each check returns the argument as a Python float (scalar input, which
keeps scalar calls fast, see `skcable._xp`) or as a float array, and raises
`skcable.errors.InputError` naming the argument otherwise. Numbers are
Python or NumPy integers and floats (or arrays of them); strings, ``None``,
booleans and complex numbers are refused rather than converted.
"""

from __future__ import annotations

from typing import overload

import numpy as np

from skcable.errors import InputError

_INF = float("inf")

#: Smallest positive normal float: below it a result has lost relative precision.
TINY = float(np.finfo(float).tiny)

_NOT_REAL = (str, bytes, bool, np.bool_, complex, np.complexfloating)


def _first_bad(arr: np.ndarray, bad: np.ndarray) -> str:
    index = np.argwhere(bad)[0]
    value = f"{float(arr[tuple(index)]):.17g}"
    return value if arr.ndim == 0 else f"{value} at index {tuple(int(i) for i in index)}"


def _not_real(name: str, value, detail: str = "") -> InputError:
    shown = repr(value)
    shown = shown if len(shown) <= 60 else shown[:57] + "..."
    return InputError(name, f"must be a real number or an array of them, got {shown}{detail}")


def _holds_bool(value) -> bool:
    """A bool inside a (nested) list or tuple: numpy would read it as 0 or 1."""
    if isinstance(value, (bool, np.bool_)):
        return True
    return isinstance(value, (list, tuple)) and any(_holds_bool(item) for item in value)


def _as_float_array(name: str, value) -> np.ndarray:
    if (
        value is None
        or isinstance(value, _NOT_REAL)
        or (isinstance(value, (list, tuple)) and _holds_bool(value))
    ):
        raise _not_real(name, value)
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError) as exc:  # ragged nesting, objects numpy refuses
        raise _not_real(name, value) from exc
    kind = raw.dtype.kind
    if kind == "f" and raw.dtype == np.float64:
        return raw
    if kind in "fiu":
        return raw.astype(float)
    if kind == "O":
        if any(item is None or isinstance(item, _NOT_REAL) for item in raw.flat):
            raise _not_real(name, value)
        try:
            return raw.astype(float)
        except (TypeError, ValueError, OverflowError) as exc:
            raise _not_real(name, value, f" ({exc})") from exc
    raise _not_real(name, value, f" (array of dtype {raw.dtype})")


@overload
def real(name: str, value: float) -> float: ...
@overload
def real(name: str, value: object) -> np.ndarray | float: ...
def real(name: str, value) -> np.ndarray | float:
    """Return ``value`` as a float (scalar input) or float array, raising if
    it is not a finite real number (or array of them)."""
    if isinstance(value, (float, int)) and not isinstance(value, bool):
        try:
            value = float(value)
        except OverflowError as exc:  # a Python integer beyond the float range
            raise InputError(name, f"must be finite, got an integer of {value.bit_length()} bits") from exc
        if value != value or value in (float("inf"), float("-inf")):
            raise InputError(name, f"must be finite, got {value!r}")
        return value
    arr = _as_float_array(name, value)
    if arr.size and -_INF < arr.min() and arr.max() < _INF:  # two reductions; NaN fails them
        return float(arr) if arr.ndim == 0 else arr
    bad = ~np.isfinite(arr)
    if bad.any():
        raise InputError(name, f"must be finite, got {_first_bad(arr, bad)}")
    return float(arr) if arr.ndim == 0 else arr


@overload
def positive(name: str, value: float) -> float: ...
@overload
def positive(name: str, value: object) -> np.ndarray | float: ...
def positive(name: str, value) -> np.ndarray | float:
    """Return ``value`` as float, raising unless it is finite and > 0."""
    arr = real(name, value)
    if not isinstance(arr, np.ndarray):
        if not arr > 0:
            raise InputError(name, f"must be > 0, got {arr!r}")
        return arr
    if arr.size and arr.min() > 0:  # finite already: one reduction
        return arr
    bad = ~(arr > 0)
    if bad.any():
        raise InputError(name, f"must be > 0, got {_first_bad(arr, bad)}")
    return arr


def within(name: str, value, low: float, high: float, reason: str, shown=None) -> None:
    """Raise ``InputError(name, reason)`` unless every element of the float or float array
    ``value`` lies in ``[low, high]`` (``shown``, default ``value``, is what the message
    quotes); two reductions on arrays, the elementwise test only to name the first bad one."""
    if not isinstance(value, np.ndarray):
        if not low <= value <= high:
            require(name, False, reason, value if shown is None else shown)
        return
    if value.size and low <= value.min() and value.max() <= high:
        return
    require(name, (value >= low) & (value <= high), reason, value if shown is None else shown)


@overload
def nonnegative(name: str, value: float) -> float: ...
@overload
def nonnegative(name: str, value: object) -> np.ndarray | float: ...
def nonnegative(name: str, value) -> np.ndarray | float:
    """Return ``value`` as float, raising unless it is finite and >= 0."""
    arr = real(name, value)
    require(name, arr >= 0, "must be >= 0", arr)
    return arr


def scalar(name: str, value) -> float:
    """Return ``value`` as a finite Python float, raising if it is an array of
    more than one element (or not a real number)."""
    value = real(name, value)
    if isinstance(value, np.ndarray):
        if value.size != 1:
            raise InputError(name, f"must be a single number, got an array of shape {value.shape}")
        value = float(value.reshape(()))
    return value


def positive_scalar(name: str, value) -> float:
    """`scalar`, raising unless it is > 0."""
    return positive(name, scalar(name, value))


def whole(name: str, value, low: int | None = None, high: int | None = None) -> int:
    """``value`` as an int, raising unless it is an integer (not a bool, not a float such as
    2.0) within ``[low, high]`` (either bound optional)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise InputError(name, f"must be an integer, got {value!r}")
    if (low is not None and value < low) or (high is not None and value > high):
        bounds = (
            f"in [{low}, {high}]"
            if low is not None and high is not None
            else (f">= {low}" if low is not None else f"<= {high}")
        )
        raise InputError(name, f"must be an integer {bounds}, got {value!r}")
    return int(value)


def one_of(name: str, value, choices, alternative: str = "") -> str:
    """``value`` where it is one of the strings ``choices``, raising `InputError` naming ``name``
    otherwise (``alternative``: what else the caller takes, said in the message); a value of any
    other type, unhashable ones included, is refused."""
    if isinstance(value, str) and value in choices:
        return value
    listed = ", ".join(repr(choice) for choice in choices)
    raise InputError(name, f"must be one of {listed}{alternative}, got {value!r}")


def require(name: str, ok, reason: str, value) -> None:
    """Raise ``InputError(name, reason)`` where the boolean ``ok`` is False."""
    if ok is True or (not isinstance(ok, np.ndarray) and ok):
        return
    ok = np.asarray(ok)
    if not ok.all():
        arr = np.broadcast_to(np.asarray(value, dtype=float), ok.shape)
        raise InputError(name, f"{reason}, got {_first_bad(arr, ~ok)}")


def point(name: str, value) -> np.ndarray:
    """``value`` as a finite float 3-vector ``(x, y, z)`` (m), raising `InputError` naming ``name``
    otherwise."""
    arr = real(name, value)
    if np.shape(arr) != (3,):
        raise InputError(name, f"must be a point (x, y, z) of 3 numbers, got shape {np.shape(arr)}")
    return np.array(arr, dtype=float)


def broadcast(**values) -> tuple[int, ...]:
    """Shape the (already checked) arguments broadcast to.

    Scalars broadcast with anything. Raises `InputError` naming the
    first array argument that is empty or whose shape does not broadcast
    with the shapes of the arguments before it.
    """
    shape: tuple[int, ...] = ()
    for name, value in values.items():
        if not isinstance(value, np.ndarray):
            continue
        if value.size == 0:
            raise InputError(name, f"is an empty array (shape {value.shape}); give at least one value")
        try:
            shape = np.broadcast_shapes(shape, value.shape)
        except ValueError:
            before = ", ".join(k for k in values if k != name and isinstance(values[k], np.ndarray))
            raise InputError(
                name, f"has shape {value.shape}, which does not broadcast with shape {shape} (of {before})"
            ) from None
    return shape


class float_range:  # noqa: N801 - used like a function: ``with float_range(name, what):``
    """Context turning the ``OverflowError``, ``ZeroDivisionError`` and "math
    domain error" that ``math`` and Python floats raise at extreme magnitudes
    (where NumPy would return inf or NaN) into ``InputError(name, ...)``.

    A class rather than a generator: it guards hot scalar paths.
    """

    __slots__ = ("name", "what")

    def __init__(self, name: str, what: str):
        self.name, self.what = name, what

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, traceback):
        if kind is None:
            return False
        domain = issubclass(kind, ValueError) and not issubclass(kind, InputError) and "domain" in str(exc)
        if domain or issubclass(kind, (OverflowError, ZeroDivisionError)):
            raise InputError(self.name, f"gives {self.what} outside the range of a float ({exc})") from exc
        return False


def exactly_one(**constraints) -> tuple[str, object]:
    """Return the one keyword whose value is not None, raising otherwise."""
    given = [(k, v) for k, v in constraints.items() if v is not None]
    if len(given) != 1:
        names = ", ".join(constraints)
        got = ", ".join(k for k, _ in given) or "none"
        raise InputError("constraint", f"give exactly one of {names} (the 'fourth equation'); got {got}")
    return given[0]
