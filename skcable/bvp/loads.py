r"""Loads on a suspended cable, for `skcable.bvp.solve_bvp`.

Each distributed load tells the graph formulation ``H y'' = q(x, y', H)``
its downward load per unit *horizontal* length ``q`` and the derivatives
``dq/dy'`` and ``dq/dH`` at the quadrature points (method
``graph_terms``). Any object with that method can be passed in the load
list: this is how an analyst adds a term.

Loads given per unit cable length refer to the *unstretched* length (the
weight of a material element does not change when it stretches): an element
of stretched length ``ds = c dx``, ``c = sqrt(1 + y'^2)``, carrying tension
``T = H c`` has unstretched length ``f dx`` with

.. math:: f(c, H) = \frac{c}{1 + H c / EA} \quad (f = c \text{ when inextensible}).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from skcable._checks import one_of, positive_scalar, scalar
from skcable.errors import InputError

__all__ = ["DeckLoad", "DistributedLoad", "PointLoad", "SelfWeight", "unstretched_measure"]


def unstretched_measure(slope, H, EA):
    """``f = c / (1 + H c / EA)`` and its derivatives with respect to y' and H."""
    c = np.sqrt(1.0 + slope * slope)
    if EA is None:
        return c, slope / c, np.zeros_like(c)
    stretch = 1.0 + H * c / EA
    df_dc = 1.0 / stretch**2
    return c / stretch, df_dc * slope / c, -(c * c / EA) / stretch**2


@dataclass(frozen=True)
class _Uniform:
    """A uniform load ``w`` (N/m), one number > 0."""

    w: float

    def __post_init__(self):
        object.__setattr__(self, "w", positive_scalar("w", self.w))


@dataclass(frozen=True)
class SelfWeight(_Uniform):
    """Weight ``w`` (N/m) per unit unstretched cable length, downward."""

    def graph_terms(self, x, slope, H, EA):
        f, df_ds, df_dh = unstretched_measure(slope, H, EA)
        return self.w * f, self.w * df_ds, self.w * df_dh


@dataclass(frozen=True)
class DeckLoad(_Uniform):
    """Load ``w`` (N/m) per unit horizontal length, downward (a deck on hangers)."""

    def graph_terms(self, x, slope, H, EA):
        zero = np.zeros_like(slope)
        return self.w + zero, zero, zero


@dataclass(frozen=True)
class DistributedLoad:
    """A load varying along the span: callables of x (m) returning N/m.

    ``qx``, ``qy`` are the components in global axes (x right, **y up**: a
    weight has ``qy < 0``), per unit unstretched cable length
    (``per="cable"``) or per unit horizontal length (``per="horizontal"``).
    Horizontal components need the arc-length formulation.
    """

    qy: Callable | None = None
    qx: Callable | None = None
    per: str = "cable"

    def __post_init__(self):
        one_of("per", self.per, ("cable", "horizontal"))
        if self.qx is None and self.qy is None:
            raise InputError("qy", "give qy, qx or both")
        for name in ("qx", "qy"):
            value = getattr(self, name)
            if value is not None and not callable(value):
                raise InputError(name, "must be a callable of x returning the load per unit length")

    def _qy(self, x):
        if self.qy is None:
            return np.zeros_like(x)
        values = np.asarray(self.qy(x), dtype=float)
        if not np.all(np.isfinite(values)):
            raise InputError("qy", "returned non-finite values")
        return np.broadcast_to(values, np.shape(x))

    def graph_terms(self, x, slope, H, EA):
        if self.qx is not None:
            raise InputError("load", "horizontal load components need formulation='arc'")
        down = -self._qy(x)
        if self.per == "horizontal":
            zero = np.zeros_like(slope)
            return down + zero, zero, zero
        f, df_ds, df_dh = unstretched_measure(slope, H, EA)
        return down * f, down * df_ds, down * df_dh


@dataclass(frozen=True)
class PointLoad:
    """Vertical point load ``P`` (N, downward) at abscissa ``x`` (m); the mesh
    gets a node there so that the kink is exact."""

    x: float
    P: float

    def __post_init__(self):
        object.__setattr__(self, "x", scalar("x", self.x))
        object.__setattr__(self, "P", scalar("P", self.P))
