r"""Cardou's bilinear stick/slip moment–curvature law (seed 003 §3.1, eqs. 3.1–3.16).

Per principal axis k, with the stick and full-slip bending stiffnesses
``EI_max``, ``EI_min`` (eqs. 3.11–3.12, secant modulus at the axial strain)
and the residual friction moment (eq. 3.14, Papailiou's capstan law along
the helix)

.. math::
    M_{rf} = \sum_i R_i F_i \cos\alpha_i \left(e^{\mu\theta_i\sin\alpha_i} - 1\right)\sin\theta_i,
    \qquad \kappa_m = \frac{M_{rf}}{EI_\mathrm{max} - EI_\mathrm{min}},

the law is ``M = EI_max κ`` for ``|κ| <= κ_m`` and
``M = M_m + EI_min (κ - κ_m)``, ``M_m = EI_max κ_m``, beyond (odd in κ).

Conventions (stated because seed 003 leaves them open, REFERENCE.md §2):
``F_i = A_i σ(cos²α_i · ε)`` is the wire force under the strand's axial
strain ε (no twist); θ_i is the wire's angular position about the core
centre measured from the bending neutral axis (principal axis k), taken in
[-π/2, π/2] (a wire of the far half maps by θ → π - θ, so that the capstan
gain grows away from the neutral axis on both sides); R_i is its helix
radius. Seed 003's Table 3.5 is not reproduced by these (nor by eq. 3.16
literally, :attr:`BendingLaw.kappa_m_eq_3_16`): docs/strand_sections.md
shows both beside the table.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from skcable._checks import nonnegative, real
from skcable.errors import InputError

__all__ = ["BendingLaw"]


class BendingLaw:
    """Stick/slip bending law of a strand section at friction ``mu`` and axial strain.

    Attributes
    ----------
    EI_max, EI_min : ndarray (2,)
        Secant stick and full-slip stiffnesses about principal axes 1, 2 (N·m²).
    M_rf : ndarray (2,)
        Residual friction moments (N·m).
    kappa_m : ndarray (2,)
        Critical (mean) curvatures (1/m).
    M_m : ndarray (2,)
        Moments at the stick/slip transition (N·m).
    """

    def __init__(self, section, *, mu: float, axial_strain: float):
        self.section = section
        self.mu = float(nonnegative("mu", mu))
        self.axial_strain = float(real("axial_strain", axial_strain))
        material, wires = section.strand.material, section.wires
        if not 0 < self.axial_strain < material.eps_rupture:
            raise InputError(
                "axial_strain", f"must lie in (0, eps_rupture={material.eps_rupture}), got {axial_strain!r}"
            )
        cos = np.cos(wires.lay_angle)
        self._wire_strain = cos**2 * self.axial_strain
        self._modulus = material.secant(self._wire_strain)  # per wire
        self._force = wires.area * material.stress(self._wire_strain)

    def _stiffnesses(self, axis):
        s, w = self.section, self.section.wires
        alive = w.intact
        cos = np.cos(w.lay_angle)
        stick = np.sum(np.where(alive, self._modulus * w.area * cos**3 * s.lever(axis) ** 2, 0.0))
        own = np.sum(np.where(alive, self._modulus * w.inertia * cos, 0.0))
        return stick + own, own

    @cached_property
    def EI_max(self) -> np.ndarray:
        return np.array([self._stiffnesses(k)[0] for k in (0, 1)])

    @cached_property
    def EI_min(self) -> np.ndarray:
        return np.array([self._stiffnesses(k)[1] for k in (0, 1)])

    def theta(self, axis: int) -> np.ndarray:
        """Angular position of every wire from the neutral axis, in [-π/2, π/2] (rad)."""
        w = self.section.wires
        t = self.section.principal_axes[axis]
        along, across = w.y * t[0] + w.z * t[1], -w.y * t[1] + w.z * t[0]
        theta = np.arctan2(across, along)
        return np.where(theta > np.pi / 2, np.pi - theta, np.where(theta < -np.pi / 2, -np.pi - theta, theta))

    @cached_property
    def M_rf(self) -> np.ndarray:
        w = self.section.wires
        helical = w.intact & (w.layer > 0)
        sin_a, cos_a = np.sin(w.lay_angle), np.cos(w.lay_angle)
        out = []
        for k in (0, 1):
            theta = self.theta(k)
            with np.errstate(over="ignore"):
                terms = w.radius * self._force * cos_a * np.expm1(self.mu * theta * sin_a) * np.sin(theta)
            out.append(np.sum(np.where(helical, terms, 0.0)))
        if not np.all(np.isfinite(out)):
            raise InputError("mu", f"the capstan factor exp(mu·θ·sin α) overflows for mu = {self.mu!r}")
        return np.array(out)

    @cached_property
    def kappa_m(self) -> np.ndarray:
        return self.M_rf / (self.EI_max - self.EI_min)

    @property
    def M_m(self) -> np.ndarray:
        return self.EI_max * self.kappa_m

    @cached_property
    def kappa_m_eq_3_16(self) -> np.ndarray:
        """Seed 003 eq. 3.16 read literally (1x7 strands):
        ``(1/3)(eps/R) sum (e^{mu theta sin(alpha)} - 1) sin(theta) / cos^2(alpha)``, per axis."""
        w = self.section.wires
        outer = w.intact & (w.layer == w.layer.max())
        R, alpha = w.radius[outer][0], w.lay_angle[outer][0]
        out = []
        for k in (0, 1):
            theta = self.theta(k)[outer]
            total = np.sum(np.expm1(self.mu * theta * np.sin(alpha)) * np.sin(theta))
            out.append(self.axial_strain / (3.0 * R) * total / np.cos(alpha) ** 2)
        return np.array(out)

    def _check_axis(self, axis):
        if axis not in (0, 1):
            raise InputError("axis", f"must be 0 or 1 (principal axis 1 or 2), got {axis!r}")

    def moment(self, kappa, axis: int):
        """Bending moment (N·m) at curvature ``kappa`` (1/m) about principal axis ``axis``."""
        self._check_axis(axis)
        kappa = np.asarray(real("kappa", kappa), dtype=float)
        k_m, ei_max, ei_min = self.kappa_m[axis], self.EI_max[axis], self.EI_min[axis]
        size = np.abs(kappa)
        out = np.copysign(np.where(size <= k_m, ei_max * size, ei_max * k_m + ei_min * (size - k_m)), kappa)
        return out[()] if out.ndim == 0 else out

    def bending_stiffness(self, kappa, axis: int, kind: str = "secant"):
        """``M/κ`` (secant) or ``dM/dκ`` (tangent) at ``kappa`` (N·m²)."""
        self._check_axis(axis)
        kappa = np.asarray(real("kappa", kappa), dtype=float)
        size = np.abs(kappa)
        stick = size <= self.kappa_m[axis]
        if kind == "tangent":
            out = np.where(stick, self.EI_max[axis], self.EI_min[axis])
        elif kind == "secant":
            safe = np.where(size == 0.0, 1.0, size)
            out = np.where(stick, self.EI_max[axis], np.abs(self.moment(safe, axis)) / safe)
        else:
            raise InputError("kind", f"must be 'secant' or 'tangent', got {kind!r}")
        return out[()] if out.ndim == 0 else out
