"""One formula, two back ends: ``math`` for scalars, NumPy for arrays.

NumPy ufuncs cost 0.2–1 µs each on a scalar, ``math`` about 0.05 µs; the
closed forms are evaluated dozens of times per call, so scalar calls use
the functions below (same names as NumPy's) and array calls use NumPy.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

scalar_math = SimpleNamespace(
    pi=math.pi,
    sin=math.sin,
    cos=math.cos,
    sinh=math.sinh,
    cosh=math.cosh,
    tanh=math.tanh,
    arcsinh=math.asinh,
    exp=math.exp,
    log=math.log,
    log1p=math.log1p,
    frexp=math.frexp,
    ldexp=math.ldexp,
    sqrt=math.sqrt,
    hypot=math.hypot,
    abs=abs,
    minimum=min,
    maximum=max,
    where=lambda condition, yes, no: yes if condition else no,
)


def namespace(*values):
    """``numpy`` if any of ``values`` is an ndarray, else `scalar_math`."""
    for value in values:
        if isinstance(value, np.ndarray):
            return np
    return scalar_math


def power_of_two_near(size, xp=scalar_math):
    """A power of two within a factor two of ``size`` (> 0, float or array): dividing by it
    is exact and brings ``size`` to order one. ``xp`` is the back end (`namespace`)."""
    return xp.ldexp(0.5, xp.frexp(size)[1])


#: The back ends by the name a pickle stores (a module does not pickle).
_BACKENDS = {"numpy": np, "math": scalar_math}


class PicklesBackend:
    """Pickling for objects that keep their back end (`namespace`'s answer) in ``_xp``.

    NumPy's module does not pickle, so the state stores the back end by name and
    unpickling puts the same object back: ``np`` itself, or `scalar_math` (the
    ``xp is np`` tests of the formulas hold on the copy as on the original).
    """

    def __getstate__(self):
        state = self.__dict__.copy()
        if "_xp" in state:
            state["_xp"] = next(name for name, xp in _BACKENDS.items() if xp is state["_xp"])
        return state

    def __setstate__(self, state):
        if "_xp" in state:
            state = {**state, "_xp": _BACKENDS[state["_xp"]]}
        self.__dict__.update(state)
