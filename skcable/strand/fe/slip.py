r"""Slip laws: how slip between the wires limits the bending of a strand.

At every quadrature point the helical-wire term resolves the axis curvature into the principal
axes of the net section, :math:`\kappa_k` (k = 1, 2), and asks the slip law for the bending the
wires carry *as one section* about each axis: the composite moment. Two kinds of law:

**Section laws** (the general kind, `SlipLaw.moment`) give that moment and its tangent directly,

.. math:: M_{c,k} = M_{c}(\kappa_k;\ \varepsilon_a, \text{state}), \qquad
          \frac{\partial M_{c,k}}{\partial\kappa_k}, \qquad
          \frac{\partial M_{c,k}}{\partial\varepsilon_a},

from what the section offers at the point's axial strain ε_a (`SlipPoints`: Cardou's EI_stick,
EI_slip, M_rf and κ_m per principal axis, with their derivatives in ε_a). The section moment
about axis k is then :math:`M_{c,k} + EI_{w}\kappa_k`, the wires' own bending
(`WireBending`) added. Cardou's bilinear law (`AxisSlip`; Cardou 2013; S. Pino Vidal, "Rigidez
a flexión en cables: análisis numérico", U. de Chile, 2021, eqs. 3.1–3.16) is

.. math:: M_{c} = (EI_{stick} - EI_{slip})\,\kappa \ \ (|\kappa| \le \kappa_m), \qquad
          M_{c} = \operatorname{sign}(\kappa)\,M_{rf} \ \ (|\kappa| > \kappa_m),

so that the section moment is ``EI_stick κ`` in stick and ``M_rf + EI_slip κ`` beyond κ_m:
`BendingLaw.moment`. A friction moment is not the derivative of an energy: a model with a
section law has no potential and a nonsymmetric tangent (∂M/∂ε_a couples the bending to the
axial strain, and nothing couples back). The wires' strains follow the composite curvature
``κ_c = M_c / (EI_stick − EI_slip)`` (κ_m in full slip: what the wires share as one section).

**Kinematic laws** (``kinematic = True``, `SlipLaw.composite`) give the composite curvature κ_c
instead, and the moment follows from the wire stresses by virtual work (a potential, a
symmetric tangent): `Stick` (κ_c = κ) and the thesis's element rule `ElementSlip` (κ_c = 0 in an
element beyond κ_m anywhere: the lower bound, no friction moment). They see κ_m tabulated in
ε_a (a monotone C¹ interpolant, `critical_curvature_table`).

A law may keep a *state* (which elements slip, a load reversal), frozen within a Newton solve and
updated from the converged curvatures between solves (`SlipLaw.next_state`); `StageSlip`, the
layer-by-layer law, commits its history that way. A section law of one's own subclasses
`SlipLaw` and implements `SlipLaw.moment`.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cached_property

import numpy as np

from skcable.errors import InputError
from skcable.strand._bending import CardouSection, friction

__all__ = ["SlipLaw", "SlipPoints", "Stick", "AxisSlip", "ElementSlip", "slip_law"]


class SlipPoints:
    """What a slip law sees at the quadrature points: the local axial strain and Cardou's law there.

    Arrays of Cardou's law are (2, n_elements, n_quad) over principal axes 1, 2, evaluated on
    first use at the point's axial strain clipped to ``[0, top]`` (κ_m = M_rf = 0 at and below
    zero); their derivatives in the axial strain vanish outside that range.

    Attributes
    ----------
    axial : ndarray (n_elements, n_quad)
        ε_a = u′ + ½(v′² + w′²).
    section, mu : skcable.strand.Section, float
        The strand section and the friction coefficient.
    EI_stick, EI_slip, M_rf, kappa_m : ndarray (2, n_elements, n_quad)
        `BendingLaw`'s stiffnesses (N·m²), friction moment (N·m) and critical curvature (1/m)
        at each point's axial strain.
    d_EI_stick, d_EI_slip, d_M_rf, d_kappa_m : ndarray (2, n_elements, n_quad)
        Their derivatives with respect to ε_a.
    EI_composite, d_EI_composite : ndarray (2, n_elements, n_quad)
        ``EI_stick − EI_slip`` (what the wires add by bending as one section) and its derivative.
    """

    def __init__(self, cardou: CardouSection, axial: np.ndarray, top: float, kappa_m=None):
        self.axial = axial
        self.section, self.mu = cardou.section, cardou.mu
        self._cardou, self._top = cardou, float(top)
        if kappa_m is not None:  # the kinematic laws' tabulated κ_m
            self.__dict__["kappa_m"] = kappa_m

    @cached_property
    def _law(self) -> dict:
        inside = (self.axial > 0.0) & (self.axial < self._top)
        out = self._cardou(np.clip(self.axial, 0.0, self._top), derivatives=True)
        for key in ("d_EI_stick", "d_EI_slip", "d_M_rf", "d_kappa_m"):
            out[key] = out[key] * inside
        return out

    EI_stick = property(lambda self: self._law["EI_stick"])
    EI_slip = property(lambda self: self._law["EI_slip"])
    M_rf = property(lambda self: self._law["M_rf"])
    d_EI_stick = property(lambda self: self._law["d_EI_stick"])
    d_EI_slip = property(lambda self: self._law["d_EI_slip"])
    d_M_rf = property(lambda self: self._law["d_M_rf"])
    d_kappa_m = property(lambda self: self._law["d_kappa_m"])

    @cached_property
    def kappa_m(self) -> np.ndarray:
        return self._law["kappa_m"]

    @property
    def EI_composite(self) -> np.ndarray:
        return self.EI_stick - self.EI_slip

    @property
    def d_EI_composite(self) -> np.ndarray:
        return self.d_EI_stick - self.d_EI_slip


class SlipLaw:
    """Base of the slip laws (module docstring): a section law implements `moment`.

    Parameters
    ----------
    mu : float
        Friction coefficient between wires (Cardou's M_rf and κ_m). A stick law uses it
        only to report κ_m and where the strand *would* slip.

    Attributes
    ----------
    name : str
        Shown in summaries and results.
    kinematic : bool
        True for a law that gives the composite curvature (`composite`) instead of the moment.
    smooth : bool
        False when the moment has kinks in κ (the model then takes semismooth Newton steps).
    layered : bool
        True for a law that holds for strands of several helical layers (`StageSlip`: one
        stage per layer); the others need a single helical layer (1x7-type strands).
    """

    name = "custom"
    kinematic = False
    smooth = True
    layered = False

    def __init__(self, mu: float = 0.5):
        self.mu = friction(mu)

    def __repr__(self) -> str:
        return f"{type(self).__name__}(mu={self.mu:g})"

    def check(self, model) -> None:
        """Refuse (`InputError` naming ``slip``) a model the law does not fit; called when a
        model binds its wires. The default accepts every model."""

    def onset(self, points: SlipPoints) -> np.ndarray:
        """The curvature (1/m) at which the law first slips, (2, ne, nq), for the results:
        Cardou's κ_m by default."""
        return points.kappa_m

    def initial_state(self, shape: tuple):
        """State at the start of a curve (all stick); ``shape`` = (2, n_elements, n_quad). None: stateless."""
        return None

    def next_state(self, kappa: np.ndarray, points: SlipPoints, state):
        """State implied by converged principal curvatures ``kappa`` (2, ne, nq) (1/m)."""
        return state

    def slipping(self, kappa: np.ndarray, points: SlipPoints, state) -> np.ndarray:
        """Boolean (2, ne, nq): points in slip about each principal axis (for results and maps)."""
        return np.abs(kappa) > points.kappa_m

    def moment(self, kappa: np.ndarray, points: SlipPoints, state):
        """``(M_c, ∂M_c/∂κ, ∂M_c/∂ε_a)``, each (2, ne, nq): the composite moment (N·m) about each
        principal axis at principal curvatures ``kappa`` (1/m), the wires' own bending excluded,
        and its derivatives in κ (N·m²) and in the axial strain (N·m)."""
        raise NotImplementedError(f"{type(self).__name__} must implement moment(kappa, points, state)")

    def energy(self, kappa: np.ndarray, points: SlipPoints, state):
        """The potential ψ (J/m) of the moment at fixed ``points``, ``∂ψ/∂κ = M_c`` (2, ne, nq), or
        None (the default). Optional: a model whose path folds (a wire law that softens) passes the
        fold by minimising an energy in which the law's points are frozen (`HelicalWires.frozen`);
        a law without it then stops there."""
        return None

    # --- kinematic laws ---------------------------------------------------------------------
    def composite(self, kappa: np.ndarray, kappa_m: np.ndarray, state):
        """A kinematic law's ``(κ_c, ∂κ_c/∂κ, ∂κ_c/∂κ_m)``, each (2, ne, nq)."""
        raise NotImplementedError(f"{type(self).__name__} is not a kinematic law")

    def second_derivatives(self, kappa: np.ndarray, kappa_m: np.ndarray, state):
        """A kinematic law's ``(∂²κ_c/∂κ², ∂²κ_c/∂κ∂κ_m, ∂²κ_c/∂κ_m²)``, each (2, ne, nq), for the
        consistent tangent of a law curved in κ or κ_m; None (the default) when they vanish,
        as for the piecewise-linear built-in laws."""
        return None


class Stick(SlipLaw):
    """No slip: the wires bend as one section at any curvature (κ_c = κ)."""

    name = "none"
    kinematic = True

    def slipping(self, kappa, points, state):
        return np.zeros(kappa.shape, dtype=bool)

    def composite(self, kappa, kappa_m, state):
        return kappa, np.ones_like(kappa), np.zeros_like(kappa)

    def moment(self, kappa, points, state):
        return points.EI_composite * kappa, points.EI_composite, points.d_EI_composite * kappa

    def energy(self, kappa, points, state):
        return 0.5 * points.EI_composite * kappa**2


class AxisSlip(SlipLaw):
    r"""Cardou's bilinear law at every quadrature point and principal axis (module docstring):
    stateless, with a kink at ±κ_m (``smooth = False``)."""

    name = "axis"
    smooth = False

    def moment(self, kappa, points, state):
        EI, stick = points.EI_composite, np.abs(kappa) <= points.kappa_m
        sign = np.sign(kappa)
        return (
            np.where(stick, EI * kappa, sign * points.M_rf),
            np.where(stick, EI, 0.0),
            np.where(stick, points.d_EI_composite * kappa, sign * points.d_M_rf),
        )

    def energy(self, kappa, points, state):
        """``½ EI_c κ²`` up to κ_m, ``M_rf (|κ| − ½ κ_m)`` beyond (continuous at κ_m)."""
        size, k_m = np.abs(kappa), points.kappa_m
        return np.where(size <= k_m, 0.5 * points.EI_composite * kappa**2, points.M_rf * (size - 0.5 * k_m))


class ElementSlip(SlipLaw):
    """The thesis's element rule (Pino Vidal 2021, eq. 4.8): an element whose curvature exceeds
    κ_m about either principal axis anywhere loses the composite bending altogether (a lower
    bound: no friction moment). Kinematic; the state is one boolean per element."""

    name = "element"
    kinematic = True

    def initial_state(self, shape):
        return np.zeros(shape[1], dtype=bool)

    def next_state(self, kappa, points, state):
        return np.any(np.abs(kappa) > points.kappa_m, axis=(0, 2))

    def slipping(self, kappa, points, state):
        return np.broadcast_to(np.asarray(state)[None, :, None], kappa.shape)

    def composite(self, kappa, kappa_m, state):
        stick = ~np.broadcast_to(np.asarray(state)[None, :, None], kappa.shape)
        return np.where(stick, kappa, 0.0), stick.astype(float), np.zeros_like(kappa)

    def moment(self, kappa, points, state):
        stick = ~np.broadcast_to(np.asarray(state)[None, :, None], kappa.shape)
        EI = np.where(stick, points.EI_composite, 0.0)
        return EI * kappa, EI, np.where(stick, points.d_EI_composite, 0.0) * kappa


_BY_NAME: dict[str, Callable[[float], SlipLaw]] = {"none": Stick, "axis": AxisSlip, "element": ElementSlip}


def slip_law(slip, mu: float = 0.5) -> SlipLaw:
    """A slip law from a name (``"none"``, ``"axis"``, ``"element"``, with friction ``mu``) or a
    [`SlipLaw`][skcable.strand.SlipLaw] instance (returned as it is; ``mu`` is then the law's own)."""
    if isinstance(slip, SlipLaw):
        kind = type(slip)
        if not slip.kinematic and kind.moment is SlipLaw.moment:
            given = kind.composite is not SlipLaw.composite
            hint = " (it gives composite(): set kinematic = True)" if given else ""
            raise InputError("slip", f"{slip!r} implements neither moment() nor a kinematic law{hint}")
        return slip
    if isinstance(slip, str) and slip in _BY_NAME:
        return _BY_NAME[slip](mu)
    raise InputError("slip", f"must be 'none', 'axis', 'element' or a SlipLaw, got {slip!r}")
