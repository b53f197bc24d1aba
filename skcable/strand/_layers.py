r"""Layer-by-layer stick/slip bending: each layer of wires slips at its own curvature.

A strand bent to the curvature κ about a principal axis first bends as one section (the wires
stick); its layers then slip one after another, each at a curvature set by its friction and by
the tension it and the layers outside it carry (K.O. Papailiou, "On the bending stiffness of
transmission line conductors", IEEE Trans. Power Delivery 12(4), 1997; A. Cardou, "Stick-slip
mechanical models for overhead electrical conductors in bending", GREMCA, Université Laval,
2013; F. Foti, L. Martinelli, "Mechanical modeling of metallic strands subjected to tension,
torsion and bending", Int. J. Solids Struct. 91, 2016). The law is a `StageLaw` of one stage per
helical layer:

- **Stiffnesses.** The wires' own bending, :math:`EI_{\min} = \sum E_i I_{w,i}\cos\alpha_i`, and
  per layer k the composite share :math:`B_k = \sum_{i\in k} E_i A_i \cos^3\alpha_i\,d_i^2`, d_i
  the wire's distance to the principal axis through the net (modulus-weighted) centroid; the
  straight core's share (not zero when wires are broken) belongs to the first layer, the one that
  slides on it. :math:`EI_{\min} + \sum_k B_k` is the section's stick stiffness
  (`Section.EI_stick`); all secant moduli at the axial strain, as in `BendingLaw`.
- **Pressure.** A helical wire of tension F, helix radius R and lay angle α presses inward with
  :math:`F\sin^2\alpha/R` per unit of its length, so layer j presses on what is inside it with
  :math:`Q_j = \sum_{i\in j} F_i\sin^2\alpha_i/(R_i\cos\alpha_i)` per unit length of strand
  (intact wires: a broken wire carries no tension). A wire of layer k (n_k wires) carries from
  outside :math:`p_k = \cos\alpha_k \sum_{j>k} Q_j / n_k` per unit of its length.
- **Friction.** In full slip a wire's force grows along the helix from the neutral axis as
  :math:`dF/ds = \mu_k (F\sin^2\alpha_k/R_k) + \mu'_k p_k` (its own pressure on the layer below,
  coefficient μ_k, and the pressure of the layers outside), so with θ its angular position from
  the neutral axis (:math:`s = R\theta/\sin\alpha`, the conventions of `BendingLaw`)

  $$
  \Delta F_i(\theta_i) = F_i\left(e^{x_i} - 1\right)
    + \frac{\mu'_k p_k R_k\theta_i}{\sin\alpha_k}\,\frac{e^{x_i} - 1}{x_i},
  \qquad x_i = \mu_k\theta_i\sin\alpha_k,
  $$

  the capstan law of `BendingLaw` plus the outer pressure. The outer pressure's coefficient
  :math:`\mu'_k` is ``outer_friction``'s: ``"foti"`` (default)
  :math:`\mu_k(1 + \mu_{k+1}/(\mu_k + \mu_{k+1}))`, Foti & Martinelli's slip condition (as
  RTE's ``strdcable`` implements it, rte-france/pallas-stranded-cable); ``"inner"``
  :math:`\mu_k`, friction on the face toward the core only (Cardou's SC5); ``"both"``
  :math:`\mu_k + \mu_{k+1}`, full friction on both faces (Cardou's SC2).
- **Knees.** Layer k's residual friction moment
  :math:`M_k = \sum_{i\in k} R_i\cos\alpha_i\,\Delta F_i\sin\theta_i` is its stage's slip moment:
  it slips at :math:`\kappa_k = M_k/B_k`.

With one helical layer (a 1x7 strand, intact or damaged) nothing presses from outside and the
law is `BendingLaw`'s single knee exactly. About an axis without composite bending
(`Section.composite_bending` False) every :math:`B_k` is 0 and the law is linear, EI_min.

Validation: the ACSR Cardinal (54/7) bent at 40 kN, measured (Foti & Martinelli 2018, the data
RTE ships with strdcable), is matched within ±10 % for κ >= 0.0167 1/m at μ = 0.7
(tests/strand/test_layers.py; docs/conductor_vibration.md shows the curve).
"""

from __future__ import annotations

import numpy as np

from skcable._checks import one_of
from skcable.errors import InputError
from skcable.strand._arguments import float_array, is_real_number, real_number
from skcable.strand._bending import BendingLaw
from skcable.strand._choice import axial_force
from skcable.strand._section import axis_pair, checked_section
from skcable.strand._stages import StageLaw

__all__ = ["LayerSlipLaw", "OUTER_FRICTION"]

#: The coefficient μ'_k of the outer layers' pressure on layer k (module text).
OUTER_FRICTION = ("foti", "inner", "both")


def _strain_of_tension(strand, tension: float, top: float) -> float:
    """The axial strain at which the strand's intact wires carry ``tension`` (N), below ``top``."""
    from scipy.optimize import brentq

    most = float(axial_force(strand, top))
    if not 0.0 <= tension < most:
        raise InputError(
            "tension",
            f"must lie in [0, {most:.6g}) N (the axial force at the first rupture strain), got {tension!r}",
        )
    if tension == 0.0:
        return 0.0
    return float(
        brentq(lambda e: float(axial_force(strand, e)) - tension, 0.0, top, xtol=1e-15 * top, rtol=8.9e-16)
    )


def _friction(mu, layers: int) -> np.ndarray:
    if is_real_number(mu):
        return np.full(layers, real_number("mu", mu, lower=0.0))
    values = float_array("mu", mu)
    if values.shape != (layers,) or not np.all(values >= 0):
        raise InputError("mu", f"must be a number >= 0 or one per helical layer ({layers}) >= 0, got {mu!r}")
    return values


def _outer_coefficient(mu: np.ndarray, rule: str) -> np.ndarray:
    """μ'_k per layer (module text); the outermost layer has nothing outside it."""
    above = np.append(mu[1:], 0.0)
    if rule == "inner":
        return mu.copy()
    if rule == "both":
        return mu + above
    total = mu + above
    return mu * (1.0 + np.divide(above, total, out=np.zeros_like(total), where=total > 0))


def _capstan(F, theta, sin, mu, outer, pressure, R):
    """ΔF of every wire (module text), finite at μ_k = 0 (the factor (e^x - 1)/x -> 1)."""
    x = mu * theta * sin
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        grow = np.expm1(x)
        ratio = np.where(x == 0.0, 1.0, grow / np.where(x == 0.0, 1.0, x))
        out = F * grow + outer * pressure * R * theta / np.where(sin > 0, sin, 1.0) * ratio
    if not np.all(np.isfinite(out)):
        raise InputError("mu", "the capstan factor exp(mu·θ·sin α) overflows")
    return out


class LayerSlipLaw(StageLaw):
    """The layer-by-layer stick/slip law of a strand section (the module's text).

    Parameters
    ----------
    section : Section
        The strand section (``strand.section()``), intact or damaged, one material or several.
    mu : float or array_like
        Friction coefficient between the wires, >= 0: one number, or one per helical layer
        (μ_k between layer k and the layer inside it, from the core outward).
    axial_strain, tension : float
        Give exactly one: the strand's axial strain, in ``[0, eps_rupture)``, or the axial force
        its intact wires carry (N, >= 0), whose strain is found from the wire laws.
    outer_friction : {"foti", "inner", "both"}
        The coefficient of the outer layers' pressure (module text); default Foti & Martinelli's.

    Attributes
    ----------
    mu, axial_strain, tension : ndarray (n_layers,), float, float
        As given (one per layer; tension in N), the strain or the tension found from the other.
    wire_force : ndarray (n_wires,)
        Every wire's axial force (N), 0 for a broken one.
    pressure : ndarray (n_layers,)
        p_k, the pressure of the outer layers on one wire of each layer (N/m of wire).
    stiffness, slip_moment, kappa_slip : ndarray (2, n_layers)
        `StageLaw`'s, one stage per helical layer from the core outward.
    """

    def __init__(self, section, *, mu, axial_strain=None, tension=None, outer_friction: str = "foti"):
        checked_section(section)
        one_of("outer_friction", outer_friction, OUTER_FRICTION)
        strand = section.strand
        n_layers = len(strand.layers)
        self.section, self.outer_friction = section, outer_friction
        self.mu = _friction(mu, n_layers)
        top = min(m.eps_rupture for m in strand.materials)
        if (axial_strain is None) == (tension is None):
            raise InputError("axial_strain", "give exactly one of axial_strain and tension")
        if tension is not None:
            axial_strain = _strain_of_tension(strand, real_number("tension", tension, lower=0.0), top)
        # BendingLaw checks the strain and gives the stick/slip split and the wires' angles
        single = BendingLaw(section, mu=0.0, axial_strain=axial_strain)
        self.axial_strain = single.axial_strain
        self.tension = float(axial_force(strand, self.axial_strain))
        stiffness, moment = self._stages(single)
        super().__init__(single.EI_slip, stiffness, moment, name=strand.name)

    def _stages(self, single: BendingLaw):
        """B_k and M_k, (2, n_layers) each (module text)."""
        section, w = self.section, self.section.wires
        layers = len(section.strand.layers)
        cos, sin = np.cos(w.lay_angle), np.sin(w.lay_angle)
        strain = np.array([np.cos(w.lay_angle) ** 2 * self.axial_strain])
        modulus = section.materials.secant(strain.T)[:, 0]
        self.wire_force = np.where(w.intact, w.area * section.materials.stress(strain.T)[:, 0], 0.0)
        helical = w.layer > 0
        radial = np.where(helical, self.wire_force * sin**2 / np.where(helical, w.radius * cos, 1.0), 0.0)
        Q = np.array([radial[w.layer == k].sum() for k in range(1, layers + 1)])
        counts = np.array([layer.count for layer in section.strand.layers])
        outside = np.concatenate([np.cumsum(Q[::-1])[::-1][1:], [0.0]])  # sum over j > k
        self.pressure = np.cos(section.strand.lay_angles) * outside / counts
        outer = _outer_coefficient(self.mu, self.outer_friction)
        k = np.maximum(w.layer, 1) - 1  # the core goes with layer 1
        stiffness, moment = np.zeros((2, layers)), np.zeros((2, layers))
        for axis in (0, 1):
            if not section.composite_bending[axis]:
                continue  # no lever: no composite bending, no slip (the law is linear)
            theta = single.theta(axis)
            composite = np.where(w.intact, modulus * w.area * cos**3 * section.lever(axis) ** 2, 0.0)
            dF = _capstan(self.wire_force, theta, sin, self.mu[k], outer[k], self.pressure[k], w.radius)
            friction = np.where(helical & w.intact, w.radius * cos * dF * np.sin(theta), 0.0)
            stiffness[axis] = np.bincount(k, weights=composite, minlength=layers)
            moment[axis] = np.bincount(k, weights=friction, minlength=layers)
        moment = np.where(stiffness > 0, moment, 0.0)  # every term is >= 0 (θ sin θ, x sin θ >= 0)
        if not (np.all(np.isfinite(stiffness)) and np.all(np.isfinite(moment))):
            raise InputError("section", "its stiffnesses or friction moments are not finite")
        return stiffness, moment

    def __repr__(self):
        knees = ", ".join(f"{value:.4g}" for value in self.kappa_slip[0])
        mu = f"{self.mu[0]:g}" if np.all(self.mu == self.mu[0]) else str(self.mu.tolist())
        return (
            f"LayerSlipLaw({self.section.strand.name or 'strand'!r}, mu={mu}, "
            f"axial_strain={self.axial_strain:.6g}, tension={self.tension:.6g} N: "
            f"EI_max={axis_pair(self.EI_max, 'N·m²')}, EI_min={axis_pair(self.EI_min, 'N·m²')}, "
            f"knees about axis 1 [{knees}] 1/m by layer from the core)"
        )
