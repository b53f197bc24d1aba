"""The cases of a study: grids and samples of parameters, their keys, and their check against the model.

A case is a dict of keyword arguments of the model function. `grid` and `sample` build
lists of cases; `case_key` names a case in the cache; `check_cases` refuses, before any
computing, a case the model's signature cannot take.

Examples
--------
>>> grid(span=[100.0, 200.0], sag=[5.0])
[{'span': 100.0, 'sag': 5.0}, {'span': 200.0, 'sag': 5.0}]
>>> len(grid(span=[100.0, 200.0], sag=[5.0, 10.0], w=[1.0, 2.0, 3.0]))
12
>>> describe({"span": 100.0, "sag": 5.0})
'span=100.0, sag=5.0'
"""

from __future__ import annotations

import hashlib
import inspect
import itertools
import json
import math
from collections.abc import Callable, Iterable

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError

__all__ = ["case_key", "check_cases", "describe", "grid", "model_name", "parameters", "sample"]


def grid(**axes) -> list[dict]:
    """Every combination of the given values (the last axis varies fastest).

    Parameters
    ----------
    **axes : list
        For each parameter, its values (a non-empty list; a string is not a list).

    Returns
    -------
    list of dict
        One case per combination, ``len = product of the axes' lengths``.

    Raises
    ------
    InputError
        An axis that is not a list of values, or an empty one (named by the parameter).
    """
    for name, values in axes.items():
        if isinstance(values, (str, bytes, dict)) or not isinstance(values, Iterable):
            raise InputError(name, f"a grid axis must be a list of values, got {values!r}")
        axes[name] = list(values)
        if not axes[name]:
            raise InputError(name, "a grid axis needs at least one value, got an empty list")
    names = list(axes)
    return [dict(zip(names, combo, strict=True)) for combo in itertools.product(*axes.values())]


def _bounds(name: str, bounds) -> tuple[float, float]:
    try:
        low, high = (float(b) for b in bounds)
        ok = math.isfinite(low) and math.isfinite(high) and low < high
    except (TypeError, ValueError):
        ok = False
    if isinstance(bounds, (str, bytes)) or not ok:
        raise InputError(name, f"a sampled parameter needs [low, high], finite, low < high; got {bounds!r}")
    return low, high


def sample(n: int, *, seed: int = 0, fixed: dict | None = None, **ranges) -> list[dict]:
    """``n`` cases, each sampled parameter uniform in its range, plus the fixed ones.

    Parameters
    ----------
    n : int
        Number of cases, >= 1.
    seed : int
        Seed of `numpy.random.default_rng` (>= 0): the same seed gives the same cases.
    fixed : dict, optional
        Parameters with the same value in every case.
    **ranges : (float, float)
        For each sampled parameter, its ``(low, high)`` range (finite, low < high).

    Returns
    -------
    list of dict
        ``n`` cases.

    Raises
    ------
    InputError
        ``n`` or ``seed`` not an integer in range, a bad range, or a parameter both sampled
        and fixed.

    Examples
    --------
    >>> cases = sample(3, seed=1, fixed={"w": 10.0}, span=(100.0, 200.0))
    >>> len(cases), cases[0]["w"], all(100.0 <= c["span"] < 200.0 for c in cases)
    (3, 10.0, True)
    """
    n = whole("n", n, 1)
    seed = whole("seed", seed, 0)
    fixed = dict(fixed or {})
    for name in ranges:
        if name in fixed:
            raise InputError(name, "is both sampled and fixed; give it in one place")
    rng = np.random.default_rng(seed)
    draws = {name: rng.uniform(*_bounds(name, bounds), n) for name, bounds in ranges.items()}
    return [fixed | {k: float(v[i]) for k, v in draws.items()} for i in range(n)]


def model_name(model: Callable) -> str:
    """``module.qualname`` of a model function, e.g. ``"skcable.study.cable_solve"`` (how entries name it)."""
    return f"{getattr(model, '__module__', '?')}.{getattr(model, '__qualname__', repr(model))}"


def case_key(model: Callable, case: dict) -> str:
    """The cache name of a case: 16 hexadecimal digits of the SHA-1 of the model's name and the
    case's parameters (``<cache>/<key>.json`` holds the case's result).
    """
    text = json.dumps([model_name(model), case], sort_keys=True, default=str)
    return hashlib.sha1(text.encode()).hexdigest()[:16]


def describe(case: dict) -> str:
    """A case as ``name=value, ...`` in the case's order (how a failed case is named to the user)."""
    return ", ".join(f"{k}={v}" for k, v in case.items())


def parameters(model: Callable) -> tuple[list[str] | None, list[str]]:
    """What a model's signature takes.

    Returns
    -------
    accepted : list of str or None
        The keyword names it accepts (None: any, it takes ``**kwargs`` or has no signature).
    required : list of str
        The names it needs (no default).
    """
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


def check_cases(model: Callable, cases: list[dict]) -> None:
    """Refuse the cases the model cannot take, before any is computed.

    A misspelt or missing parameter would otherwise fail every case the same way after the
    study had been scheduled.

    Raises
    ------
    InputError
        ``cases``: the first case with an unknown or a missing parameter, named by its index
        and parameters.
    """
    accepted, required = parameters(model)
    name = getattr(model, "__name__", repr(model))
    for i, case in enumerate(cases):
        unknown = [k for k in case if accepted is not None and k not in accepted]
        missing = [k for k in required if k not in case]
        if unknown or missing:
            what = f"unknown parameter {unknown[0]!r}" if unknown else f"missing parameter {missing[0]!r}"
            options = f" (its parameters: {', '.join(accepted)})" if accepted is not None else ""
            raise InputError("cases", f"case {i} ({describe(case)}): {what} for {name}(){options}")
