"""Strand geometry: a straight core wire and layers of helical wires.

Cross-section axes (seed 003 Fig. 3.6): y horizontal, z vertical, origin at
the core's centre. Wire j of a layer of n wires sits at the angle
``psi_j = phase + 2 pi j / n`` measured from +z toward +y, on the helix
radius R of its layer. Helix radii follow from radial contact: layer 1
touches the core, ``R_1 = (d_core + d_1)/2``; layer k touches layer k-1,
``R_k = R_{k-1} + (d_{k-1} + d_k)/2`` (the thesis's ``R = d`` for a 1x7
strand of equal wires). Lay angle alpha and lay length p are tied by
``tan(alpha) = 2 pi R / p``.

Damage (REFERENCE.md §2, the convention that reproduces seed 003 annex A):
``damaged(n)`` breaks n adjacent wires of the outer layer placed
symmetrically about +z, so that the net section stays symmetric about z.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from math import pi, radians

import numpy as np

from skcable._checks import positive
from skcable.errors import InputError
from skcable.strand._material import Material, material

__all__ = ["Layer", "Strand", "Wires", "preset"]


@dataclass(frozen=True)
class Layer:
    """A layer of ``count`` helical wires of diameter ``wire_diameter`` (m).

    Give the lay as ``lay_angle`` (rad, to the strand axis) or as
    ``lay_length`` (m, the pitch), not both. ``direction`` is +1 for a
    right-hand lay, -1 for left. ``phase`` (rad) rotates the layer.
    """

    count: int
    wire_diameter: float
    lay_angle: float | None = None
    lay_length: float | None = None
    direction: int = 1
    phase: float = 0.0

    def __post_init__(self):
        if not (isinstance(self.count, (int, np.integer)) and self.count >= 1):
            raise InputError("count", f"must be a positive integer, got {self.count!r}")
        positive("wire_diameter", self.wire_diameter)
        if (self.lay_angle is None) == (self.lay_length is None):
            raise InputError("lay_angle", "give exactly one of lay_angle and lay_length")
        if self.lay_angle is not None and not 0 < self.lay_angle < pi / 2:
            raise InputError("lay_angle", f"must lie in (0, pi/2) rad, got {self.lay_angle!r}")
        if self.lay_length is not None:
            positive("lay_length", self.lay_length)
        if self.direction not in (1, -1):
            raise InputError("direction", f"must be +1 (right lay) or -1 (left lay), got {self.direction!r}")


@dataclass(frozen=True)
class Wires:
    """Flat arrays, one entry per wire (core first), of a strand's wires."""

    y: np.ndarray  #: position in the section (m)
    z: np.ndarray
    psi: np.ndarray  #: angular position from +z toward +y (rad); 0 for the core
    radius: np.ndarray  #: helix radius R (m); 0 for the core
    lay_angle: np.ndarray  #: alpha (rad); 0 for the core
    direction: np.ndarray  #: +1 / -1 lay; 0 for the core
    diameter: np.ndarray  #: wire diameter (m)
    layer: np.ndarray  #: 0 for the core, k for layer k
    intact: np.ndarray  #: False for broken wires

    @property
    def area(self) -> np.ndarray:
        """Wire cross-section areas (m²)."""
        return pi * self.diameter**2 / 4

    @property
    def inertia(self) -> np.ndarray:
        """Own second moments of area of the wires, pi r^4 / 4 (m^4)."""
        return pi * self.diameter**4 / 64


@dataclass(frozen=True)
class Strand:
    """A strand: core wire plus helical layers, with broken wires.

    Parameters
    ----------
    core_diameter : float
        Diameter of the straight core wire (m).
    layers : tuple of Layer
        From the core outward.
    material : Material
        Wire material (all wires).
    broken : frozenset of (layer, index)
        Broken wires: layer number (1 = first helical layer) and wire index.
    name : str
        Label (presets: ``"steel-9.5"`` ...).
    """

    core_diameter: float
    layers: tuple[Layer, ...]
    material: Material
    broken: frozenset = field(default_factory=frozenset)
    name: str = ""

    def __post_init__(self):
        positive("core_diameter", self.core_diameter)
        if not self.layers:
            raise InputError("layers", "a strand needs at least one helical layer")
        for layer_index, wire in self.broken:
            if not 1 <= layer_index <= len(self.layers) or not 0 <= wire < self.layers[layer_index - 1].count:
                raise InputError("wires", f"no wire {wire} in layer {layer_index}")

    # --- geometry ---------------------------------------------------------
    @property
    def helix_radii(self) -> np.ndarray:
        """Helix radius of every layer (m), from radial contact."""
        radii, radius, previous = [], 0.0, self.core_diameter
        for layer in self.layers:
            radius += (previous + layer.wire_diameter) / 2
            radii.append(radius)
            previous = layer.wire_diameter
        return np.array(radii)

    @property
    def lay_angles(self) -> np.ndarray:
        """Lay angle of every layer (rad)."""
        return np.array(
            [
                layer.lay_angle if layer.lay_angle is not None else np.arctan(2 * pi * R / layer.lay_length)
                for layer, R in zip(self.layers, self.helix_radii, strict=True)
            ]
        )

    @property
    def lay_lengths(self) -> np.ndarray:
        """Lay length (pitch) of every layer (m)."""
        return 2 * pi * self.helix_radii / np.tan(self.lay_angles)

    @property
    def diameter(self) -> float:
        """Outer diameter of the strand (m)."""
        return float(2 * self.helix_radii[-1] + self.layers[-1].wire_diameter)

    def wires(self) -> Wires:
        """Position, lay and state of every wire, core first."""
        columns = {
            k: [v]
            for k, v in dict(
                y=0.0,
                z=0.0,
                psi=0.0,
                radius=0.0,
                lay_angle=0.0,
                direction=0,
                diameter=self.core_diameter,
                layer=0,
                intact=True,
            ).items()
        }
        for k, (layer, R, alpha) in enumerate(
            zip(self.layers, self.helix_radii, self.lay_angles, strict=True), 1
        ):
            psi = layer.phase + 2 * pi * np.arange(layer.count) / layer.count
            values = dict(
                y=R * np.sin(psi),
                z=R * np.cos(psi),
                psi=psi,
                radius=np.full(layer.count, R),
                lay_angle=np.full(layer.count, alpha),
                direction=np.full(layer.count, layer.direction),
                diameter=np.full(layer.count, layer.wire_diameter),
                layer=np.full(layer.count, k),
                intact=np.array([(k, j) not in self.broken for j in range(layer.count)]),
            )
            for key, value in values.items():
                columns[key].extend(np.atleast_1d(value).tolist())
        return Wires(**{k: np.array(v) for k, v in columns.items()})

    # --- damage -----------------------------------------------------------
    def damaged(self, n: int | None = None, *, wires=None) -> Strand:
        """A copy with wires broken.

        Parameters
        ----------
        n : int, optional
            Break n adjacent wires of the outer layer, placed symmetrically
            about +z (the outer layer is rotated so; seed 003 Table 3.2).
        wires : iterable of (layer, index), optional
            Break exactly these wires (layer 1 is the first helical layer),
            without rotating anything.
        """
        if (n is None) == (wires is None):
            raise InputError("n", "give exactly one of n and wires")
        if wires is not None:
            return replace(self, broken=frozenset(self.broken | {tuple(map(int, w)) for w in wires}))
        outer = self.layers[-1]
        if not (isinstance(n, (int, np.integer)) and 0 <= n < outer.count):
            raise InputError("n", f"must be an integer in [0, {outer.count - 1}], got {n!r}")
        # wires 0..n-1 straddle +z: psi_j = (j - (n-1)/2) * 2 pi / count
        phase = -(n - 1) / 2 * 2 * pi / outer.count
        layers = (*self.layers[:-1], replace(outer, phase=phase))
        top = len(self.layers)
        return replace(
            self,
            layers=layers,
            broken=frozenset({(top, j) for j in range(n)}),
            name=f"{self.name} damage {n}".strip(),
        )

    def section(self):
        """Section properties of this strand (see :class:`~skcable.strand.Section`)."""
        from skcable.strand._section import Section

        return Section(self)

    def bending_law(self, mu: float = 0.5, axial_strain: float = 0.004):
        """Cardou's bilinear stick/slip moment–curvature law (see :class:`~skcable.strand.BendingLaw`)."""
        from skcable.strand._bending import BendingLaw

        return BendingLaw(self.section(), mu=mu, axial_strain=axial_strain)


#: Seed 003 Table 3.1: wire diameter (m), material, nominal strand diameter (m), lay angle (deg).
_TABLE_3_1 = {
    "steel-9.5": (3.1e-3, "steel", 9.5e-3, 7.5),
    "aluminium-10.1": (3.37e-3, "aluminium", 10.1e-3, 8.0),
    "steel-12.7": (4.19e-3, "steel", 12.7e-3, 8.0),
    "aluminium-14.3": (4.77e-3, "aluminium", 14.3e-3, 7.0),
}


def preset(name: str) -> Strand:
    """A 1x7 strand of seed 003 Table 3.1: ``"steel-9.5"``, ``"aluminium-10.1"``,
    ``"steel-12.7"`` or ``"aluminium-14.3"`` (equal wires, helix radius d)."""
    try:
        d, mat, _nominal, alpha = _TABLE_3_1[name]
    except KeyError:
        raise InputError("name", f"unknown strand {name!r}; known: {', '.join(_TABLE_3_1)}") from None
    return Strand(d, (Layer(6, d, lay_angle=radians(alpha)),), material(mat), name=name)
