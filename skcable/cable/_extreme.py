"""A refusal deep inside a cable solve named after the outsized argument that caused it.

The closed forms and the line solvers check their arguments one by one (sign, finiteness);
a value beyond any physical magnitude (a span of 1e308 m, a subnormal EA) passes those checks
and trips a later one, which names the argument *it* checks (``length`` where the catenary's
``cosh`` overflows, ``dh`` where ``span * seabed_slope`` does), or breaks the float arithmetic
(``ZeroDivisionError`` where ``w`` is 1e-300), or stops a Newton solve whose Jacobian's
determinant overflows (`ConvergenceError`). `outsized` re-raises them as an `InputError`
naming the argument whose magnitude lies beyond 10**±`EXTREME` (`extreme`, `blame_extreme`,
which the conductor functions use alike); with no such argument the error passes as it was.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import ConvergenceError, InputError

__all__ = ["EXTREME", "extreme", "blame_extreme", "outsized"]

#: No input of a cable or conductor computation lies beyond 10**±EXTREME (in any unit system a
#: float holds: a span of 1e-100 m or a load of 1e100 N/m is no physical cable).
EXTREME = 100.0

#: Arguments whose domain holds 0 (a subnormal ``dh`` is a level span, no outsized value).
ZERO_OK = frozenset(("dh", "seabed", "friction", "seabed_slope", "point_loads"))

#: What float arithmetic raises on Python floats where NumPy would give inf or NaN.
ARITHMETIC = (ZeroDivisionError, OverflowError, ValueError)


def extreme(**values) -> str | None:
    """The name of the value farthest from 1 in magnitude when it lies beyond 10**±`EXTREME`
    (zeros, non-finite values and None left out), else None. Arrays count by their farthest
    element."""
    farthest, level = None, EXTREME
    for name, value in values.items():
        if value is None:
            continue
        magnitude = np.abs(np.asarray(value, dtype=float))
        magnitude = magnitude[np.isfinite(magnitude) & (magnitude > 0)]
        if magnitude.size:
            distance = float(np.max(np.abs(np.log10(magnitude))))
            if distance > level:
                farthest, level = name, distance
    return farthest


class blame_extreme:  # noqa: N801 - used like a function: ``with blame_extreme(span=..., ...):``
    """Context re-raising an inner `InputError` under the name of the argument whose magnitude
    is beyond any physical one (`extreme`) when there is one and the refusal names another: the
    solvers inside name the argument their own check trips on (``H0`` for a span of 1e308 whose
    catenary overflows), the cause is the outsized one."""

    __slots__ = ("values",)

    def __init__(self, **values):
        self.values = values

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, traceback):
        if kind is None or not issubclass(kind, InputError):
            return False
        name = extreme(**self.values)
        if name is None or name == exc.argument:
            return False
        value = np.ravel(np.asarray(self.values[name], dtype=float))
        magnitude = np.abs(value)
        usable = np.isfinite(magnitude) & (magnitude > 0)
        shown = value[np.argmax(np.where(usable, np.abs(np.log10(np.where(usable, magnitude, 1.0))), -1.0))]
        raise InputError(name, f"{shown:.3g} is beyond any physical magnitude ({exc})") from exc


class outsized(blame_extreme):  # noqa: N801 - used like a function: ``with outsized(span=..., ...):``
    """`blame_extreme`, and an arithmetic error (`ARITHMETIC`) or a solve that does not
    converge (`ConvergenceError`) under the name of the outsized argument (an `InputError`) when
    there is one; otherwise the error passes unchanged. Costs nothing unless an error passes."""

    __slots__ = ()

    def __exit__(self, kind, exc, traceback):
        if kind is None or not issubclass(kind, (InputError, ConvergenceError, *ARITHMETIC)):
            return False
        # an argument whose domain holds 0 is outsized only when large: a tiny one is a zero
        values = {
            name: np.maximum(np.abs(np.asarray(value, dtype=float)), 1.0) if name in ZERO_OK else value
            for name, value in self.values.items()
        }
        if not issubclass(kind, InputError):
            name = extreme(**values)
            if name is None:
                return False
            fails = "the solve" if issubclass(kind, ConvergenceError) else "the float arithmetic"
            raise InputError(
                name, f"is beyond any physical magnitude: {fails} fails ({kind.__name__}: {exc})"
            ) from exc
        return blame_extreme(**values).__exit__(kind, exc, traceback)
