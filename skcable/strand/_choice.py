r"""Model no more than a strand needs: closed form, stick, or stick–slip.

`analyse` picks the cheapest model that represents the strand:

1. **closed form** for an undamaged strand in tension: it stays straight
   and untwisted (clamped ends, symmetric section), so every wire carries
   the strain :math:`\cos^2\alpha_j\,\varepsilon` and

   .. math:: F(\varepsilon) = \sum_j A_j \cos\alpha_j\,\sigma(\cos^2\alpha_j\,\varepsilon)

   (the FE model's section force with zero curvature and twist; ``EA`` in
   the linear range, Papailiou eq. 2.20); the curve ends when the core
   reaches its rupture strain;
2. **stick** FE model for a damaged strand whose stick curvature stays below
   the critical curvature κ_m everywhere and at every step;
3. **stick–slip** FE model (``slip="axis"``) when a stick run's curvature
   reaches κ_m somewhere: the step and place are reported.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import positive
from skcable._show import Shown, counted, quantity
from skcable.errors import InputError

__all__ = ["Analysis", "ClosedFormCurve", "analyse", "axial_force"]


@dataclass
class ClosedFormCurve(Shown):
    """Axial force–strain curve of an undamaged strand (no FE): ``strain``,
    ``force`` (N), ``K_Leq`` (N, the secant at the elastic limit), ``toughness``
    (N), ``ruptured`` (True), ``D_r`` (0: undamaged by definition)."""

    strand: object
    strain: np.ndarray
    force: np.ndarray
    ruptured: bool = True

    @property
    def K_Leq(self) -> float:
        """Secant stiffness at the strain where the core leaves the linear branch (N)."""
        limit = first_wire_strain(self.strand, "eps_y1")
        return float(axial_force(self.strand, limit) / limit)

    @property
    def toughness(self) -> float:
        return float(np.trapezoid(self.force, self.strain))

    @property
    def D_r(self) -> float:
        return 0.0

    @property
    def slip_fraction(self) -> np.ndarray:
        return np.zeros_like(self.strain)

    def __repr__(self) -> str:
        name = getattr(self.strand, "name", "") or "strand"
        return f"ClosedFormCurve({name!r}, {counted([len(self.strain)], 'point')}: {key_numbers(self)})"


def key_numbers(curve) -> str:
    """The end of a capacity curve (closed form or FE), its K_Leq and toughness, as ``name=value unit``."""
    last = "rupture" if curve.ruptured else "last"
    return ", ".join(
        (
            quantity(f"{last}_strain", curve.strain[-1]),
            quantity(f"{last}_force", curve.force[-1], "N"),
            quantity("K_Leq", curve.K_Leq, "N"),
            quantity("toughness", curve.toughness, "N"),
        )
    )


def first_wire_strain(strand, attribute: str) -> float:
    """The strand strain at which the first intact wire reaches its material's limit strain
    ``attribute`` ("eps_y1" or "eps_rupture"): ``min_j limit_j / cos²α_j`` (the straight core,
    α = 0, when every wire has one material)."""
    wires = strand.wires()
    limit = strand.wire_materials().take(attribute)[wires.intact]
    return float(np.min(limit / np.cos(wires.lay_angle[wires.intact]) ** 2))


def axial_force(strand, strain):
    """``Σ A_j cos α_j σ_j(cos²α_j ε)`` over the intact wires (N), for any array of strains;
    σ_j the law of wire j's own material."""
    wires = strand.wires()
    strain = np.asarray(strain, dtype=float)
    cos = np.cos(wires.lay_angle)[wires.intact]
    area = wires.area[wires.intact]
    materials = strand.wire_materials().subset(wires.intact)
    stress = materials.stress(np.multiply.outer(strain, cos**2), axis=-1)
    return np.sum(area * cos * stress, axis=-1)


@dataclass
class Analysis(Shown):
    """Result of `analyse`: the ``curve`` of the chosen ``model``
    ("closed form", "stick" or "stick-slip"), the ``reason``, and the stick curve
    used to decide (``stick``, None for the closed form)."""

    model: str
    reason: str
    curve: object
    stick: object = None

    def __repr__(self) -> str:
        return f"Analysis({self.model}: {key_numbers(self.curve)}; {self.reason})"


def analyse(
    strand, length: float = 1.0, *, mu: float = 0.5, n_points: int = 200, **model_options
) -> Analysis:
    """Capacity of ``strand`` with the cheapest adequate model (the module text): ``model_options``
    go to `StrandModel` and `capacity_curve` (``n_elements``, ``n_steps``...); ``n_points``
    samples the closed-form curve."""
    from skcable.strand.fe.model import StrandModel

    positive("length", length)
    if int(n_points) < 2:
        raise InputError("n_points", f"must be at least 2, got {n_points!r}")
    if not strand.broken:
        top = first_wire_strain(strand, "eps_rupture")  # one material: the straight core
        strain = np.linspace(0.0, top, int(n_points))
        reason = "undamaged strand in tension: straight and untwisted, F = Σ A cos α σ(cos²α ε) (no FE)"
        return Analysis("closed form", reason, ClosedFormCurve(strand, strain, axial_force(strand, strain)))
    curve_options = {k: model_options.pop(k) for k in ("n_steps", "max_strain") if k in model_options}
    stick = StrandModel(strand, length, slip="none", mu=mu, **model_options).capacity_curve(**curve_options)
    ratios = [float(np.max(np.abs(s.curvature) / np.maximum(s.kappa_m, 1e-300))) for s in stick.steps]
    beyond = np.flatnonzero(np.array(ratios) >= 1.0)
    if beyond.size == 0:
        reason = f"damaged; the stick curvature peaks at {max(ratios):.2f} κ_m: the wires never slip"
        return Analysis("stick", reason, stick, stick)
    first = stick.steps[int(beyond[0])]
    where = np.unravel_index(np.argmax(np.abs(first.curvature) / first.kappa_m), first.curvature.shape)
    reason = (
        f"damaged; the stick curvature reaches κ_m at axial strain {first.strain:.3g} "
        f"(x = {first.x[where[1], where[2]]:.3g} m, principal axis {where[0] + 1}): slip switched on"
    )
    slip = StrandModel(strand, length, slip="axis", mu=mu, **model_options).capacity_curve(**curve_options)
    return Analysis("stick-slip", reason, slip, stick)
