r"""Section properties of an intact or damaged strand (seed 003 §3.1–3.2, annex A).

With every helical wire a fibre of area A at (y, z) inclined at the lay
angle alpha (the core straight, alpha = 0), seed 003 eqs. 3.11–3.13 give

.. math::
    I_\mathrm{max} = \sum_i A_i d_i^2 \cos^3\alpha_i + \sum_i I_{w,i}\cos\alpha_i,
    \qquad I_\mathrm{min} = \sum_i I_{w,i}\cos\alpha_i, \qquad I_w = \pi r^4/4,

where d_i is the distance to the bending axis through the net centroid
(stick: the wires act as one section), and ``I_min`` is the full-slip value
(every wire bends about its own axis). The centroid uses plain wire areas
(Table 3.2: ``z_c = -r/3`` for one broken wire, ``-r sqrt(12/25)`` for two).
Principal axes diagonalise the stick tensor; principal axis 1 carries the
larger ``I_max``. ``EA = E sum A cos^3 alpha`` (Papailiou eq. 2.20).

Seed 003's annex A "Iyy" column is principal axis 1 here; its "Izz" column
applies the lay factor cos^3 alpha to the core's parallel-axis term as well
(a difference of ``A z_c^2 (1 - cos^3 alpha)``, 0.03–1 %); the rows for three
broken wires of the 3.1 and 3.37 mm strands are typos (tests/strand).
"""

from __future__ import annotations

from functools import cached_property
from math import pi

import numpy as np

from skcable.errors import InputError

__all__ = ["Section"]


class Section:
    """Section properties of ``strand`` (SI units: m, m², m⁴, N, N·m²).

    Attributes
    ----------
    area : float
        Net area (intact wires), m².
    centroid : (float, float)
        (y_c, z_c) of the net section, plain areas.
    principal_angle : float
        Angle from +y to principal axis 1, toward +z (rad).
    principal_axes : ndarray (2, 2)
        Rows: unit vectors (y, z) of principal axes 1 and 2.
    I_max, I_min : ndarray (2,)
        Stick and full-slip second moments about principal axes 1 and 2,
        lay factors included (m⁴).
    EA, EI_max, EI_min : float, ndarray (2,), ndarray (2,)
        The same times the elastic modulus E_e.
    axial_torsion_coupling, torsional_stiffness : float
        ``sum E A R sin(alpha) cos^2(alpha)`` (signed by lay direction, N·m)
        and ``sum E A R^2 sin^2(alpha) cos(alpha) + sum G J_w cos(alpha)``
        (N·m²), from the wire strain ``cos^2(alpha) eps + R sin(alpha) cos(alpha) phi'``.
    """

    def __init__(self, strand):
        self.strand = strand
        self.wires = w = strand.wires()
        self._alive = w.intact
        cos = np.cos(w.lay_angle)
        self._axial_factor = cos**3
        self._own_factor = cos

    def _sum(self, values):
        return float(np.sum(np.where(self._alive, values, 0.0)))

    @cached_property
    def area(self) -> float:
        return self._sum(self.wires.area)

    @cached_property
    def centroid(self) -> tuple[float, float]:
        a = np.where(self._alive, self.wires.area, 0.0)
        return float(a @ self.wires.y / a.sum()), float(a @ self.wires.z / a.sum())

    @cached_property
    def _stick_tensor(self) -> np.ndarray:
        """sum A cos^3(alpha) [dy, dz]^T [dy, dz] about the centroid."""
        y_c, z_c = self.centroid
        weights = np.where(self._alive, self.wires.area * self._axial_factor, 0.0)
        offsets = np.column_stack([self.wires.y - y_c, self.wires.z - z_c])
        return (offsets * weights[:, None]).T @ offsets

    @cached_property
    def _own(self) -> float:
        return self._sum(self.wires.inertia * self._own_factor)

    @cached_property
    def _principal(self):
        values, vectors = np.linalg.eigh(self._stick_tensor)  # ascending
        lever_1, lever_2 = vectors[:, 1], vectors[:, 0]
        if values[1] - values[0] <= 1e-12 * values[1]:  # isotropic: axis 1 = y
            lever_1, lever_2 = np.array([0.0, 1.0]), np.array([1.0, 0.0])
            values = np.array([values[1], values[1]])
        rotate = np.array([[0.0, 1.0], [-1.0, 0.0]])  # lever (height) -> axis direction
        axes = np.vstack([rotate @ lever_1, rotate @ lever_2])
        axes[axes @ np.array([1.0, 1e-9]) < 0] *= -1  # orientation: toward +y (or +z)
        return np.array([values[1], values[0]]), axes

    @property
    def principal_axes(self) -> np.ndarray:
        return self._principal[1]

    @property
    def principal_angle(self) -> float:
        y, z = self.principal_axes[0]
        return float(np.arctan2(z, y))

    def lever(self, axis: int) -> np.ndarray:
        """Signed distance of every wire from principal axis ``axis`` (0 or 1),
        measured through the centroid (m)."""
        if axis not in (0, 1):
            raise InputError("axis", f"must be 0 or 1 (principal axis 1 or 2), got {axis!r}")
        t = self.principal_axes[axis]
        normal = np.array([-t[1], t[0]])
        y_c, z_c = self.centroid
        return (self.wires.y - y_c) * normal[0] + (self.wires.z - z_c) * normal[1]

    @property
    def I_max(self) -> np.ndarray:
        return self._principal[0] + self._own

    @property
    def I_min(self) -> np.ndarray:
        return np.array([self._own, self._own])

    @property
    def E(self) -> float:
        return self.strand.material.E_e

    @property
    def EA(self) -> float:
        return self.E * self._sum(self.wires.area * self._axial_factor)

    @property
    def EI_max(self) -> np.ndarray:
        return self.E * self.I_max

    @property
    def EI_min(self) -> np.ndarray:
        return self.E * self.I_min

    @property
    def axial_torsion_coupling(self) -> float:
        w = self.wires
        return self.E * self._sum(
            w.direction * w.area * w.radius * np.sin(w.lay_angle) * np.cos(w.lay_angle) ** 2
        )

    @property
    def torsional_stiffness(self) -> float:
        w = self.wires
        helical = self.E * self._sum(w.area * w.radius**2 * np.sin(w.lay_angle) ** 2 * np.cos(w.lay_angle))
        own = self.strand.material.G * self._sum(2.0 * w.inertia * self._own_factor)
        return helical + own

    # --- Lanteigne (1985) / Papailiou (1997), eqs. 2.12-2.13 -----------------
    def _require_intact(self):
        if not self._alive.all():
            raise InputError("strand", "the Lanteigne/Papailiou formulas hold for undamaged strands only")

    @property
    def EI_max_lanteigne(self) -> float:
        """Eq. 2.12: ``sum n E A (R^2 + r^2/2)/2 cos^3(beta)`` over core and layers."""
        self._require_intact()
        w = self.wires
        r = w.diameter / 2
        return self.E * float(np.sum(pi * r**2 * (w.radius**2 + r**2 / 2) / 2 * np.cos(w.lay_angle) ** 3))

    @property
    def EI_min_lanteigne(self) -> float:
        """Eq. 2.13: ``sum n E I cos(beta)``."""
        self._require_intact()
        return self.E * self._own

    def __repr__(self):
        return (
            f"Section({self.strand.name or 'strand'}: area={self.area:.6g} m2, centroid={self.centroid}, "
            f"I_max={self.I_max}, I_min={self.I_min})"
        )
