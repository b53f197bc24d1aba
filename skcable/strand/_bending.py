r"""Cardou's bilinear stick/slip moment–curvature law (Pino Vidal (2021), §3.1, eqs. 3.1–3.16).

Per principal axis k, with the stick and full-slip bending stiffnesses
``EI_stick``, ``EI_slip`` (eqs. 3.11–3.12, secant modulus at the axial strain)
and the residual friction moment (eq. 3.14, Papailiou's capstan law along
the helix)

$$
M_{rf} = \sum_i R_i F_i \cos\alpha_i \left(e^{\mu\theta_i\sin\alpha_i} - 1\right)\sin\theta_i,
\qquad \kappa_m = \frac{M_{rf}}{EI_\mathrm{stick} - EI_\mathrm{slip}},
$$

the law is ``M = EI_stick κ`` for ``|κ| <= κ_m`` and
``M = M_m + EI_slip (κ - κ_m)``, ``M_m = EI_stick κ_m``, beyond (odd in κ).

Conventions (the thesis leaves them open): ``F_i = A_i σ(cos²α_i · ε)`` is
the wire force under the strand's axial strain ε (no twist); θ_i is the
wire's angular position about the core centre measured from the bending
neutral axis (principal axis k), taken in [-π/2, π/2] (a wire of the far half
maps by θ → π - θ, so that the capstan gain grows away from the neutral axis
on both sides); R_i is its helix radius. The capstan term is not odd in θ
(``e^{x} - 1`` against ``1 - e^{-x}``), so M_rf depends on which side of the
neutral axis counts θ > 0: it is the side away from the net centroid (the side
of the missing wires), or, where the centroid lies on the neutral axis, the side
where the third moment ``sum A across³`` of the intact helical wires is negative
(where that vanishes too, the orientation of `Section.principal_axes` decides;
no such asymmetric section is known among 1x7 and 1+6+12 patterns). This makes
the law of a damage pattern that of any rotation or mirror image of it (the
same damage) and keeps the values of ``damaged(n)``; the law is taken odd in κ
with this one M_rf. The thesis's Table 3.5 is not
reproduced by these (nor by eq. 3.16 literally, `BendingLaw.kappa_m_eq_3_16`):
docs/strand_sections.md shows both beside the table.

**No composite bending about an axis** (every intact wire on one line through the core centre:
`Section.composite_bending` False): no wire has a lever or a friction lever (θ = 0) about it, no
interwire shear arises, and the law is linear, ``M = EI_slip κ`` (``BendingLaw.linear``), with
``M_rf = 0`` and ``κ_m = 2 ε_rupture / d_max`` (the smallest ``2 ε_rupture,i / d_i`` over the
intact wires): the curvature at which the thickest wire would break by its own bending, finite
and independent of μ and ε.

**Several materials** (`Layer.material`): every wire's secant modulus and stress are its own
material's, ``EI_stick = sum E_sec,i (A_i cos^3 α_i d_i^2 + I_w,i cos α_i)`` about the
modulus-weighted centroid, ``F_i = A_i σ_i(cos²α_i ε)``, below the smallest rupture strain.

Axes as in `Section`: index 0 (an ``axis`` of 0) is principal axis 1.

References: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico",
Universidad de Chile, 2021; A. Cardou, "Stick-slip mechanical models for
overhead electrical conductors in bending", GREMCA, Université Laval, 2013;
K. O. Papailiou, "On the bending stiffness of transmission line conductors",
IEEE Trans. Power Delivery 12(4), 1997.
"""

from __future__ import annotations

import numpy as np

from skcable._checks import one_of
from skcable._show import Shown
from skcable.errors import InputError
from skcable.strand._arguments import float_array, is_real_number, principal_axis, real_number
from skcable.strand._section import Section, axis_pair, checked_section

__all__ = ["BendingLaw", "CardouSection", "MAX_FRICTION", "critical_curvature", "friction"]

#: the largest friction coefficient between wires taken: measured wire-on-wire coefficients lie
#: between about 0.1 and 1 (Cardou 2013; Pino Vidal 2021 uses 0.3 to 0.7), and the capstan gain
#: exp(μ π sin α) of a larger one sends the wire forces of the friction moment beyond any wire's
#: strength
MAX_FRICTION = 2.0


def friction(mu) -> float:
    """``mu`` checked: a real number in ``[0, MAX_FRICTION]`` (`InputError` naming ``mu``)."""
    mu = real_number("mu", mu, lower=0.0)
    if mu > MAX_FRICTION:
        raise InputError(
            "mu",
            f"must lie in [0, {MAX_FRICTION:g}] (friction between wires: about 0.1 to 1; Cardou 2013 and "
            f"Pino Vidal 2021 use 0.3 to 0.7), got {mu!r}",
        )
    return mu


def _strains(section: Section, axial_strain, *, scalar: bool) -> np.ndarray:
    top = min(m.eps_rupture for m in section.strand.materials)
    if scalar:
        if not is_real_number(axial_strain):
            raise InputError(
                "axial_strain",
                f"must be a single real number, got {axial_strain!r:.80}; for many strains at once "
                "use critical_curvature(section, mu, axial_strain_array)",
            )
        strain = np.array([real_number("axial_strain", axial_strain)])
    else:
        strain = float_array("axial_strain", axial_strain)
    bad = ~((strain >= 0) & (strain < top))
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f" at index {index}" if strain.ndim and not scalar else ""
        raise InputError(
            "axial_strain", f"must lie in [0, eps_rupture={top!r}), got {float(strain[index])!r}{where}"
        )
    return strain


def _side(section: Section, axis: int) -> float:
    """+1 or -1: the sign that puts θ > 0 on the side of the neutral axis away from the net
    centroid (the side of the missing wires); see `BendingLaw.theta`."""
    w = section.wires
    t = section.principal_axes[axis]
    across = -w.y * t[1] + w.z * t[0]  # about the core centre, positive to the left of t
    weights = np.where(w.intact & (w.layer > 0), w.area, 0.0)
    reach = float(np.max(w.radius))
    for power in (1, 3):  # first moment (the centroid's side); where it vanishes, the third
        moment = float(weights @ across**power)
        if abs(moment) > 1e-9 * float(weights.sum()) * reach**power:
            return -1.0 if moment > 0 else 1.0
    return 1.0


def _theta(section: Section, axis: int) -> np.ndarray:
    """Angular position of every wire about the core centre from principal axis ``axis``,
    mapped into [-π/2, π/2], positive away from the net centroid."""
    w = section.wires
    t = section.principal_axes[axis]
    along, across = w.y * t[0] + w.z * t[1], -w.y * t[1] + w.z * t[0]
    theta = np.arctan2(across, along)
    theta = np.where(theta > np.pi / 2, np.pi - theta, np.where(theta < -np.pi / 2, -np.pi - theta, theta))
    return _side(section, axis) * theta


class CardouSection:
    r"""Cardou's law of one section and friction at any axial strains: its strain-independent
    per-wire factors (levers, capstan gains) formed once, the strain-dependent ones (secant
    moduli, wire forces) per call, with their derivatives on request; ``section`` and ``mu`` as
    `BendingLaw` takes them.

    Notes
    -----
    ``section(strain)`` returns a dict of ``EI_stick``, ``EI_slip``, ``M_rf``, ``kappa_m``, each
    (2, *strain.shape) over principal axes 1, 2 (the module's law, unchecked strains); with
    ``derivatives=True`` also ``d_EI_stick``, ``d_EI_slip``, ``d_M_rf``, ``d_kappa_m``, their
    derivatives with respect to the axial strain (per unit strain): with ``e_i = cos²α_i ε``,

    .. math:: \frac{dE_{sec,i}}{d\varepsilon} = \cos^2\alpha_i\,\frac{E_t(e_i) - E_{sec}(e_i)}{e_i},
              \qquad \frac{dF_i}{d\varepsilon} = A_i\cos^2\alpha_i\,E_t(e_i),
              \qquad \frac{d\kappa_m}{d\varepsilon} = \frac{M_{rf}' - \kappa_m (EI_{stick} - EI_{slip})'}
              {EI_{stick} - EI_{slip}}

    (0 at ε = 0 for the modulus, whose law starts linear; 0 about an axis without composite
    bending, whose κ_m is a constant).
    """

    def __init__(self, section: Section, mu: float):
        self.section, self.mu = section, float(mu)
        w = section.wires
        alive, composite = w.intact, section.composite_bending
        helical = alive & (w.layer > 0)
        cos, sin = np.cos(w.lay_angle), np.sin(w.lay_angle)
        levers = np.array([section.lever(k) for k in (0, 1)])  # (2, wires)
        theta = np.array([_theta(section, k) for k in (0, 1)])
        # strain-independent per-wire factors; nothing composite about a lever-less axis
        self._stick = np.where(alive & composite[:, None], w.area * cos**3 * levers**2, 0.0)
        self._own = np.where(alive, w.inertia * cos, 0.0)
        with np.errstate(over="ignore", invalid="ignore"):
            capstan = np.where(
                helical & composite[:, None], w.radius * cos * np.expm1(mu * theta * sin) * np.sin(theta), 0.0
            )
        if not np.all(np.isfinite(capstan)):
            raise InputError("mu", f"the capstan factor exp(mu·θ·sin α) overflows for mu = {mu!r}")
        self._capstan = capstan
        self._cos2 = cos**2
        self._area = w.area
        self._composite = composite
        materials = section.materials
        if materials.uniform:
            self._no_lever = 2.0 * materials.materials[0].eps_rupture / float(np.max(w.diameter[alive]))
        else:  # the intact wire that breaks first by its own bending
            self._no_lever = float(np.min(2.0 * materials.take("eps_rupture")[alive] / w.diameter[alive]))

    def __call__(self, strain: np.ndarray, derivatives: bool = False) -> dict:
        materials = self.section.materials
        strain = np.asarray(strain, dtype=float)
        flat = strain.reshape(-1)
        wire_strain = np.multiply.outer(self._cos2, flat)  # (wires, n)
        modulus = materials.secant(wire_strain)  # secant modulus per wire, its own material
        force = self._area[:, None] * materials.stress(wire_strain)
        composite_part = self._stick @ modulus  # (2, n)
        slip = np.broadcast_to(self._own @ modulus, composite_part.shape)
        M_rf = self._capstan @ force
        composite = self._composite[:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            kappa = np.where(composite, M_rf / composite_part, self._no_lever)
        out = dict(EI_stick=composite_part + slip, EI_slip=slip.copy(), M_rf=M_rf, kappa_m=kappa)
        if derivatives:
            tangent = materials.stress_and_tangent(wire_strain)[1]
            safe = np.where(wire_strain > 0.0, wire_strain, 1.0)
            d_modulus = np.where(wire_strain > 0.0, self._cos2[:, None] * (tangent - modulus) / safe, 0.0)
            d_force = (self._area * self._cos2)[:, None] * tangent
            d_composite = self._stick @ d_modulus
            d_slip = np.broadcast_to(self._own @ d_modulus, d_composite.shape)
            d_M_rf = self._capstan @ d_force
            with np.errstate(divide="ignore", invalid="ignore"):
                d_kappa = np.where(composite, (d_M_rf - kappa * d_composite) / composite_part, 0.0)
            out.update(
                d_EI_stick=d_composite + d_slip, d_EI_slip=d_slip.copy(), d_M_rf=d_M_rf, d_kappa_m=d_kappa
            )
        for key, value in out.items():
            if not np.all(np.isfinite(value)):
                raise InputError(
                    "section", f"{key} is not finite: wire sizes or moduli beyond floating point?"
                )
            out[key] = value.reshape((2, *strain.shape))
        return out


def critical_curvature(section, mu: float, axial_strain) -> np.ndarray:
    """Critical curvatures κ_m (1/m) of Cardou's law at many axial strains in one call:
    ``BendingLaw(section, mu=mu, axial_strain=e).kappa_m`` for each strain e of
    ``axial_strain`` (any shape, not empty; at 0, κ_m = 0: no tension, no friction), as an
    array (2, *axial_strain.shape) over principal axes 1, 2."""
    section = checked_section(section)
    mu = friction(mu)
    return CardouSection(section, mu)(_strains(section, axial_strain, scalar=False))["kappa_m"]


class BendingLaw(Shown):
    """Stick/slip bending law of a strand section at friction ``mu`` and axial strain.

    Parameters
    ----------
    section : Section
        The strand section (``strand.section()``).
    mu : float
        Friction coefficient between wires, >= 0.
    axial_strain : float
        Axial strain of the strand, in ``[0, eps_rupture)`` (a single number; for
        many strains at once use `critical_curvature`).

    Attributes
    ----------
    EI_stick, EI_slip : ndarray (2,)
        Secant stick and full-slip stiffnesses about principal axes 1, 2 (N·m²).
    M_rf : ndarray (2,)
        Residual friction moments (N·m).
    kappa_m : ndarray (2,)
        Critical (mean) curvatures (1/m).
    M_m : ndarray (2,)
        Moments at the stick/slip transition (N·m).
    linear : ndarray of bool (2,)
        True about an axis without composite bending: ``EI_stick == EI_slip``,
        ``M_rf = 0``, ``κ_m = 2 ε_rupture / d_max`` (the module's documentation).
    """

    def __init__(self, section, *, mu: float, axial_strain: float):
        self.section = checked_section(section)
        self.mu = friction(mu)
        self.axial_strain = float(_strains(section, axial_strain, scalar=True)[0])
        law = CardouSection(section, self.mu)(np.array([self.axial_strain]))
        self.EI_stick, self.EI_slip, self.M_rf, self.kappa_m = (
            law[k][:, 0] for k in ("EI_stick", "EI_slip", "M_rf", "kappa_m")
        )
        self.linear = ~section.composite_bending

    @property
    def M_m(self) -> np.ndarray:
        """Moments ``EI_stick κ_m`` at the stick/slip transition, principal axes 1, 2 (N·m)."""
        return self.EI_stick * self.kappa_m

    def theta(self, axis: int) -> np.ndarray:
        """Angular position θ (rad) of every wire about the core centre from the neutral axis
        ``axis``, in [-π/2, π/2], positive away from the net centroid (the module's conventions)."""
        return _theta(self.section, principal_axis(axis))

    @property
    def kappa_m_eq_3_16(self) -> np.ndarray:
        """Pino Vidal (2021), eq. 3.16, read literally (1x7 strands), per principal axis (1/m):
        ``(1/3)(eps/R) sum (e^{mu theta sin(alpha)} - 1) sin(theta) / cos^2(alpha)`` over the
        intact wires of the outer layer (R, α of that layer); 0 about an axis without
        composite bending (every θ is 0 there)."""
        w, strand = self.section.wires, self.section.strand
        outer = w.intact & (w.layer == len(strand.layers))
        R, alpha = float(strand.helix_radii[-1]), float(strand.lay_angles[-1])
        out = []
        for k in (0, 1):
            theta = _theta(self.section, k)[outer]
            total = np.sum(np.expm1(self.mu * theta * np.sin(alpha)) * np.sin(theta))
            out.append(self.axial_strain / (3.0 * R) * total / np.cos(alpha) ** 2)
        return np.where(self.linear, 0.0, out)

    def moment(self, kappa, axis: int):
        """Bending moment (N·m) at curvature ``kappa`` (1/m, any shape) about principal axis ``axis``."""
        axis = principal_axis(axis)
        kappa = float_array("kappa", kappa)
        k_m, ei_stick, ei_slip = self.kappa_m[axis], self.EI_stick[axis], self.EI_slip[axis]
        size = np.abs(kappa)
        out = np.copysign(
            np.where(size <= k_m, ei_stick * size, ei_stick * k_m + ei_slip * (size - k_m)), kappa
        )
        return out[()] if out.ndim == 0 else out

    def bending_stiffness(self, kappa, axis: int, kind: str = "secant"):
        """``M/κ`` (``kind="secant"``) or ``dM/dκ`` (``"tangent"``) at ``kappa`` (N·m²) about ``axis``."""
        axis = principal_axis(axis)
        one_of("kind", kind, ("secant", "tangent"))
        kappa = float_array("kappa", kappa)
        size = np.abs(kappa)
        stick = size <= self.kappa_m[axis]
        if kind == "tangent":
            out = np.where(stick, self.EI_stick[axis], self.EI_slip[axis])
        else:
            safe = np.where(size == 0.0, 1.0, size)
            out = np.where(stick, self.EI_stick[axis], np.abs(self.moment(safe, axis)) / safe)
        return out[()] if out.ndim == 0 else out

    def __repr__(self):
        linear = [k + 1 for k in (0, 1) if self.linear[k]]
        note = f", linear about principal axis {' and '.join(map(str, linear))}" if linear else ""
        return (
            f"BendingLaw({self.section.strand.name or 'strand'!r}, mu={self.mu:g}, "
            f"axial_strain={self.axial_strain:g}: EI_stick={axis_pair(self.EI_stick, 'N·m²')}, "
            f"EI_slip={axis_pair(self.EI_slip, 'N·m²')}, M_rf={axis_pair(self.M_rf, 'N·m')}, "
            f"kappa_m={axis_pair(self.kappa_m, '1/m')}{note})"
        )
