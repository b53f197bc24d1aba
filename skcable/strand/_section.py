r"""Section properties of an intact or damaged strand (Pino Vidal (2021), §3.1–3.2, annex A).

With every helical wire a fibre of area A at (y, z) inclined at the lay
angle alpha (the core straight, alpha = 0), Pino Vidal (2021), eqs. 3.11–3.13, give

$$
I_\mathrm{stick} = \sum_i A_i d_i^2 \cos^3\alpha_i + \sum_i I_{w,i}\cos\alpha_i,
\qquad I_\mathrm{slip} = \sum_i I_{w,i}\cos\alpha_i, \qquad I_w = \pi r^4/4,
$$

d_i the distance to the bending axis through the net centroid: the stick value (the wires act
as one section; the thesis's "I máx") and the full-slip value (every wire bends about its own
axis; "I mín"), both about the two principal axes of the stick section (not a largest and a
smallest principal inertia). The centroid uses plain wire areas (Table 3.2: ``z_c = -r/3`` for
one broken wire, ``-r sqrt(12/25)`` for two); principal axis 1 carries the larger stick inertia.
``EA = E sum A cos^3 alpha`` (Papailiou (1997), eq. 2.20 of the thesis).

**Several materials** (e.g. ACSR's steel core under aluminium layers): the transformed section
of composite beam theory (J.M. Gere and S.P. Timoshenko, "Mechanics of Materials", §6.3), each
wire's area scaled by ``n_i = E_i / E`` against the strand's ``E = strand.material.E_e``
(exactly 1 with one material): centroid, principal axes and inertias of the areas ``n_i A_i``,
``EA = sum E_i A_i cos^3 alpha_i``, and the torsion terms with each wire's own E_i and G_i.

Axes are numbered 1 and 2 (the CLI's and the VTK files' ``curvature_1``); arrays over the axes
and the ``axis`` arguments index them from 0: index 0 is principal axis 1. Where every intact
wire lies on one line, no wire has a lever about the principal axis along it
(`Section.composite_bending` False, ``I_stick == I_slip`` exactly).

The thesis's annex A "Iyy" column is principal axis 1 here; its "Izz" column
applies the lay factor cos^3 alpha to the core's parallel-axis term as well
(a difference of ``A z_c^2 (1 - cos^3 alpha)``, 0.03–1 %); the rows for three
broken wires of the 3.1 and 3.37 mm strands are typos (tests/strand).

References: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico",
Universidad de Chile, 2021; K. O. Papailiou, "On the bending stiffness of
transmission line conductors", IEEE Trans. Power Delivery 12(4), 1997;
J. Lanteigne, "Theoretical estimation of the response of helically armored
cables to tension, torsion, and bending", J. Appl. Mech. 52, 1985.
"""

from __future__ import annotations

from functools import cached_property
from math import pi

import numpy as np

from skcable._show import Shown
from skcable.errors import InputError
from skcable.strand._arguments import principal_axis

__all__ = ["Section", "axis_pair", "checked_section"]

#: a principal stick inertia at or below this fraction of the tensor's trace is a
#: round-off of zero (all intact wires on one line); a discrete wire geometry has no
#: genuine values this small
_DEGENERATE = 1e-12


def axis_pair(values, unit: str) -> str:
    """Two values over principal axes 1, 2 as ``(v1, v2) unit`` (for the results' text)."""
    return f"({values[0]:.4g}, {values[1]:.4g}) {unit}"


def checked_section(section) -> Section:
    """``section`` if it is a `Section`, else `InputError` naming ``section``."""
    if not isinstance(section, Section):
        raise InputError("section", f"must be a Section (strand.section()), got {section!r:.80}")
    return section


class Section(Shown):
    """Section properties of ``strand`` (intact or with broken wires; SI units: m, m², m⁴, N,
    N·m²), each a property below (the module docstring)."""

    def __init__(self, strand):
        # duck-typed: the geometry module builds sections, not the other way round
        if not (callable(getattr(strand, "wires", None)) and hasattr(strand, "material")):
            raise InputError("strand", f"must be a Strand (e.g. strand.preset('steel-9.5')), got {strand!r}")
        self.strand = strand
        self.wires = w = strand.wires()
        self._alive = w.intact
        cos = np.cos(w.lay_angle)
        self.materials = strand.wire_materials()
        # modular ratios E_i / E against the reference material (exactly 1.0 with one material)
        self._modular = self.materials.take("E_e") / strand.material.E_e
        self._shear_ratio = self.materials.take("G") / strand.material.G
        self._axial_factor = cos**3 * self._modular
        self._own_factor = cos * self._modular

    def _sum(self, values):
        return float(np.sum(np.where(self._alive, values, 0.0)))

    @cached_property
    def area(self) -> float:
        """Net area of the intact wires (m²)."""
        return self._sum(self.wires.area)

    @cached_property
    def centroid(self) -> tuple[float, float]:
        """(y_c, z_c) of the net section (m): plain wire areas, each times its modular ratio
        ``E_i / E`` when the strand has several materials (the transformed section)."""
        a = np.where(self._alive, self.wires.area * self._modular, 0.0)
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
        tensor = self._stick_tensor
        values, vectors = np.linalg.eigh(tensor)  # ascending
        lever_1, lever_2 = vectors[:, 1], vectors[:, 0]
        if values[1] - values[0] <= 1e-12 * values[1]:  # isotropic (or no lever at all): axis 1 = y
            lever_1, lever_2 = np.array([0.0, 1.0]), np.array([1.0, 0.0])
            values = np.array([values[1], values[1]])
        rotate = np.array([[0.0, 1.0], [-1.0, 0.0]])  # lever (height) -> axis direction
        axes = np.vstack([rotate @ lever_1, rotate @ lever_2])
        axes[axes @ np.array([1.0, 1e-9]) < 0] *= -1  # orientation: toward +y (or +z)
        principal = np.array([values[1], values[0]])
        composite = principal > _DEGENERATE * np.trace(tensor)
        return np.where(composite, principal, 0.0), axes, composite

    @property
    def principal_axes(self) -> np.ndarray:
        """Unit vectors (y, z) of principal axes 1 and 2 (rows 0 and 1)."""
        return self._principal[1]

    @property
    def principal_angle(self) -> float:
        """Angle from +y to principal axis 1, toward +z (rad)."""
        y, z = self.principal_axes[0]
        return float(np.arctan2(z, y))

    @property
    def composite_bending(self) -> np.ndarray:
        """Per principal axis, whether some intact wire has a lever about it (False: the wires'
        own bending only, ``I_stick == I_slip``)."""
        return self._principal[2].copy()

    def lever(self, axis: int) -> np.ndarray:
        """Signed distance (m) of every wire from principal axis ``axis`` through the centroid,
        positive along the axis direction turned by +90°."""
        t = self.principal_axes[principal_axis(axis)]
        normal = np.array([-t[1], t[0]])
        y_c, z_c = self.centroid
        return (self.wires.y - y_c) * normal[0] + (self.wires.z - z_c) * normal[1]

    @property
    def I_stick(self) -> np.ndarray:
        """Stick second moments about principal axes 1 and 2 (m⁴), lay factors included; of the
        transformed section with several materials."""
        return self._principal[0] + self._own

    @property
    def I_slip(self) -> np.ndarray:
        """Full-slip second moments (the wires' own, lay factor cos α) about principal axes 1, 2, m⁴."""
        return np.array([self._own, self._own])

    @property
    def E(self) -> float:
        """Elastic modulus ``E_e`` (Pa) of the strand's material: of every wire with one material,
        the reference modulus of the transformed inertias with several."""
        return self.strand.material.E_e

    @property
    def EA(self) -> float:
        """Axial stiffness ``sum E_i A_i cos^3 alpha_i`` of the intact wires (N)."""
        return self.E * self._sum(self.wires.area * self._axial_factor)

    @property
    def EI_stick(self) -> np.ndarray:
        """``E_e I_stick`` about principal axes 1 and 2 (index 0, 1), N·m²."""
        return self.E * self.I_stick

    @property
    def EI_slip(self) -> np.ndarray:
        """``E_e I_slip`` about principal axes 1 and 2 (index 0, 1), N·m²."""
        return self.E * self.I_slip

    @property
    def axial_torsion_coupling(self) -> float:
        """``sum E A R sin(alpha) cos^2(alpha)``, signed by the lay direction (N·m), from the wire
        strain ``cos^2(alpha) eps + R sin(alpha) cos(alpha) phi'``."""
        w = self.wires
        return self.E * self._sum(
            w.direction * w.area * w.radius * np.sin(w.lay_angle) * np.cos(w.lay_angle) ** 2 * self._modular
        )

    @property
    def torsional_stiffness(self) -> float:
        """``sum E A R^2 sin^2(alpha) cos(alpha) + sum G J_w cos(alpha)`` (N·m²)."""
        w = self.wires
        helical = self.E * self._sum(
            w.area * w.radius**2 * np.sin(w.lay_angle) ** 2 * np.cos(w.lay_angle) * self._modular
        )
        own = self.strand.material.G * self._sum(2.0 * w.inertia * np.cos(w.lay_angle) * self._shear_ratio)
        return helical + own

    # --- Lanteigne (1985) / Papailiou (1997): Pino Vidal (2021), eqs. 2.12-2.13 ------
    def _require_intact(self):
        if not self._alive.all():
            raise InputError("strand", "the Lanteigne/Papailiou formulas hold for undamaged strands only")

    @property
    def EI_stick_lanteigne(self) -> float:
        """Eq. 2.12: ``sum n E A (R^2 + r^2/2)/2 cos^3(beta)`` over core and layers (N·m², intact strands)."""
        self._require_intact()
        w = self.wires
        r = w.diameter / 2
        return self.E * float(
            np.sum(pi * r**2 * (w.radius**2 + r**2 / 2) / 2 * np.cos(w.lay_angle) ** 3 * self._modular)
        )

    @property
    def EI_slip_lanteigne(self) -> float:
        """Eq. 2.13: ``sum n E I cos(beta)`` (N·m², intact strands)."""
        self._require_intact()
        return self.E * self._own

    def __repr__(self):
        w = self.wires
        y_c, z_c = self.centroid
        label = self.strand.name or "strand"
        return (
            f"Section({label!r}: {int(w.intact.sum())} of {w.intact.size} wires intact, "
            f"area={self.area:.4g} m², centroid=({y_c:.4g}, {z_c:.4g}) m, "
            f"principal axis 1 at {np.degrees(self.principal_angle):.4g}° from +y, "
            f"I_stick={axis_pair(self.I_stick, 'm⁴')}, I_slip={axis_pair(self.I_slip, 'm⁴')}, "
            f"EA={self.EA:.4g} N)"
        )
