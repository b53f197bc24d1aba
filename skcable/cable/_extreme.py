"""A refusal deep inside a cable solve named after the outsized argument that caused it.

The closed forms and the line solvers check their arguments one by one (sign, finiteness);
a value beyond any physical magnitude (a span of 1e308 m, a subnormal EA) passes those checks
and trips a later one, which names the argument *it* checks (``length`` where the catenary's
``cosh`` overflows, ``dh`` where ``span * seabed_slope`` does), or breaks the float arithmetic
(``ZeroDivisionError`` where ``w`` is 1e-300). `outsized` re-raises both as an `InputError`
naming the argument whose magnitude lies beyond 10**±100
(`skcable.cable.conductors.blame_extreme`); with no such argument the error passes as it was.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import InputError

__all__ = ["outsized"]

#: Arguments whose domain holds 0 (a subnormal ``dh`` is a level span, no outsized value).
ZERO_OK = frozenset(("dh", "seabed", "friction", "seabed_slope", "point_loads"))

#: What float arithmetic raises on Python floats where NumPy would give inf or NaN.
ARITHMETIC = (ZeroDivisionError, OverflowError, ValueError)


class outsized:  # noqa: N801 - used like a function: ``with outsized(span=..., ...):``
    """`blame_extreme`, and an arithmetic error (`ARITHMETIC`) under the name of the outsized
    argument (an `InputError`) when there is one; otherwise the error passes unchanged.
    Costs nothing unless an error passes (the conductors' checks are imported then: they
    import the closed forms)."""

    __slots__ = ("values",)

    def __init__(self, **values):
        self.values = values

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, traceback):
        if kind is None or not issubclass(kind, (InputError, *ARITHMETIC)):
            return False
        from skcable.cable.conductors._inputs import blame_extreme, extreme

        # an argument whose domain holds 0 is outsized only when large: a tiny one is a zero
        values = {
            name: np.maximum(np.abs(np.asarray(value, dtype=float)), 1.0) if name in ZERO_OK else value
            for name, value in self.values.items()
        }
        if not issubclass(kind, InputError):
            name = extreme(**values)
            if name is None:
                return False
            raise InputError(
                name, f"is beyond any physical magnitude: the float arithmetic fails ({kind.__name__}: {exc})"
            ) from exc
        return blame_extreme(**values).__exit__(kind, exc, traceback)
