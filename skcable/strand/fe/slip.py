r"""Slip laws: how slip between the wires limits the composite bending of a strand.

At every quadrature point the helical-wire term resolves the axis curvature
into the principal axes of the net section, :math:`\kappa_k` (k = 1, 2), and
asks the slip law for the curvature the wires still share *as one section*,

.. math:: \kappa_{c,k} = \kappa_{c}(\kappa_k, \kappa_{m,k}(\varepsilon_a)),

with its derivatives :math:`\partial\kappa_c/\partial\kappa` and
:math:`\partial\kappa_c/\partial\kappa_m` (the tangent of the strand follows
from them). :math:`\kappa_m` is Cardou's critical curvature of the section at
the local axial strain (Cardou 2013; S. Pino Vidal, "Rigidez a flexión en
cables: análisis numérico", U. de Chile, 2021, eqs. 3.14–3.16), see
[`BendingLaw`][skcable.strand.BendingLaw]. What exceeds the composite share is
carried by the wires' own bending, so ``M = M_rf + EI_slip κ`` beyond κ_m.

A law may keep a *state* (which points or elements slip): it is frozen within
a Newton solve and updated from the converged curvatures between solves, until
it settles (`SlipLaw.next_state`). A law written outside the library
subclasses `SlipLaw` and implements `SlipLaw.composite`; a
stateless smooth law needs nothing else.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable

import numpy as np

from skcable._checks import nonnegative
from skcable.errors import InputError

__all__ = ["SlipLaw", "Stick", "AxisSlip", "ElementSlip", "slip_law"]


class SlipLaw(ABC):
    """Base of the slip laws.

    Parameters
    ----------
    mu : float
        Friction coefficient between wires (Cardou's κ_m). A stick law uses it
        only to report κ_m and where the strand *would* slip.
    """

    #: name shown in summaries and results
    name = "custom"

    def __init__(self, mu: float = 0.5):
        self.mu = float(nonnegative("mu", mu))

    def __repr__(self) -> str:
        return f"{type(self).__name__}(mu={self.mu:g})"

    def initial_state(self, shape: tuple):
        """State at the start of a curve (all stick); ``shape`` = (2, n_elements, n_quad). None: stateless."""
        return None

    def next_state(self, kappa: np.ndarray, kappa_m: np.ndarray, state):
        """State implied by converged principal curvatures ``kappa`` and ``kappa_m`` (2, ne, nq)."""
        return state

    def slipping(self, kappa: np.ndarray, kappa_m: np.ndarray, state) -> np.ndarray:
        """Boolean (2, ne, nq): points in slip about each principal axis (for results and maps)."""
        return np.abs(kappa) > kappa_m

    @abstractmethod
    def composite(self, kappa: np.ndarray, kappa_m: np.ndarray, state):
        """``(κ_c, ∂κ_c/∂κ, ∂κ_c/∂κ_m)``, each (2, ne, nq), at principal curvatures ``kappa`` (1/m)."""

    def second_derivatives(self, kappa: np.ndarray, kappa_m: np.ndarray, state):
        """``(∂²κ_c/∂κ², ∂²κ_c/∂κ∂κ_m, ∂²κ_c/∂κ_m²)``, each (2, ne, nq), for the consistent
        tangent of a law that is curved in κ or κ_m; None (the default) when they vanish,
        as for the piecewise-linear built-in laws."""
        return None


class Stick(SlipLaw):
    """No slip: the wires bend as one section at any curvature."""

    name = "none"

    def slipping(self, kappa, kappa_m, state):
        return np.zeros(kappa.shape, dtype=bool)

    def composite(self, kappa, kappa_m, state):
        return kappa, np.ones_like(kappa), np.zeros_like(kappa)


class AxisSlip(SlipLaw):
    r"""Cardou's bilinear law at every quadrature point and principal axis.

    Where :math:`|\kappa_k| > \kappa_{m,k}` the composite curvature saturates
    at :math:`\pm\kappa_{m,k}` (the friction moment is spent); the state is
    the boolean mask of saturated (axis, element, point) triples.
    """

    name = "axis"

    def initial_state(self, shape):
        return np.zeros(shape, dtype=bool)

    def next_state(self, kappa, kappa_m, state):
        return np.abs(kappa) > kappa_m

    def slipping(self, kappa, kappa_m, state):
        return np.asarray(state)

    def composite(self, kappa, kappa_m, state):
        sign = np.sign(kappa)
        return (
            np.where(state, sign * kappa_m, kappa),
            np.where(state, 0.0, 1.0),
            np.where(state, sign, 0.0),
        )


class ElementSlip(SlipLaw):
    """The thesis's element rule (Pino Vidal 2021, eq. 4.8): an element whose curvature
    exceeds κ_m about either principal axis anywhere loses the composite bending
    altogether; its wires bend about their own axes. The state is one boolean per element.
    """

    name = "element"

    def initial_state(self, shape):
        return np.zeros(shape[1], dtype=bool)

    def next_state(self, kappa, kappa_m, state):
        return np.any(np.abs(kappa) > kappa_m, axis=(0, 2))

    def slipping(self, kappa, kappa_m, state):
        return np.broadcast_to(np.asarray(state)[None, :, None], kappa.shape)

    def composite(self, kappa, kappa_m, state):
        stick = ~np.broadcast_to(np.asarray(state)[None, :, None], kappa.shape)
        return np.where(stick, kappa, 0.0), stick.astype(float), np.zeros_like(kappa)


_BY_NAME: dict[str, Callable[[float], SlipLaw]] = {"none": Stick, "axis": AxisSlip, "element": ElementSlip}


def slip_law(slip, mu: float = 0.5) -> SlipLaw:
    """A slip law from a name (``"none"``, ``"axis"``, ``"element"``, with friction ``mu``) or a
    [`SlipLaw`][skcable.strand.SlipLaw] instance (returned as it is; ``mu`` is then the law's own)."""
    if isinstance(slip, SlipLaw):
        return slip
    if isinstance(slip, str) and slip in _BY_NAME:
        return _BY_NAME[slip](mu)
    raise InputError("slip", f"must be 'none', 'axis', 'element' or a SlipLaw, got {slip!r}")
