"""Strand geometry: a straight core wire and layers of helical wires.

Cross-section axes (Pino Vidal (2021), Fig. 3.6): y horizontal, z vertical, origin at
the core's centre. Wire j of a layer of n wires sits at the angle
``psi_j = phase + 2 pi j / n`` measured from +z toward +y, on the helix
radius R of its layer. Helix radii follow from radial contact: layer 1
touches the core, ``R_1 = (d_core + d_1)/2``; layer k touches layer k-1,
``R_k = R_{k-1} + (d_{k-1} + d_k)/2`` (the thesis's ``R = d`` for a 1x7
strand of equal wires). Lay angle alpha and lay length p are tied by
``tan(alpha) = 2 pi R / p``.

Damage: `Strand.damaged` (the convention that reproduces the thesis's annex A).

Reference: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico",
Universidad de Chile, 2021 (the thesis; its tables and equations are cited by
number).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from math import pi, radians

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError
from skcable.strand._arguments import name_text, real_number
from skcable.strand._catalogue import ENTRIES, INCH, LAY_RATIO, aluminium_layers, entry, layer_counts
from skcable.strand._material import Material, WireMaterials, material

__all__ = ["Layer", "Strand", "Wires", "lay_rates", "preset"]


@dataclass(frozen=True)
class Layer:
    """A layer of ``count`` helical wires of diameter ``wire_diameter`` (m).

    Parameters
    ----------
    count : int
        Number of wires, >= 1.
    wire_diameter : float
        Wire diameter (m), > 0.
    lay_angle, lay_length : float
        The lay, as the angle to the strand axis (rad, in (0, π/2)) or as the
        lay length (m, the pitch, > 0): give exactly one.
    direction : int
        +1 for a right-hand lay, -1 for left.
    phase : float
        Rotation of the layer (rad): wire j sits at ``phase + 2 pi j / count`` from +z.
    material : Material or None
        The material of this layer's wires; None (default): the strand's ``material``.
        A conductor such as ACSR has aluminium layers around a steel core.

    Notes
    -----
    Every number must be finite; booleans, strings and arrays are refused
    (InputError naming the argument). Numbers are stored as Python int/float.
    """

    count: int
    wire_diameter: float
    lay_angle: float | None = None
    lay_length: float | None = None
    direction: int = 1
    phase: float = 0.0
    material: Material | None = None

    def __post_init__(self):
        count = whole("count", self.count)
        if count < 1:
            raise InputError("count", f"must be a positive integer, got {count!r}")
        values = dict(
            count=count,
            wire_diameter=real_number("wire_diameter", self.wire_diameter, lower=0.0, strict=True),
        )
        if (self.lay_angle is None) == (self.lay_length is None):
            raise InputError("lay_angle", "give exactly one of lay_angle and lay_length")
        if self.lay_angle is not None:
            alpha = real_number("lay_angle", self.lay_angle)
            if not 0 < alpha < pi / 2:
                raise InputError("lay_angle", f"must lie in (0, pi/2) rad, got {alpha!r}")
            values["lay_angle"] = alpha
        else:
            values["lay_length"] = real_number("lay_length", self.lay_length, lower=0.0, strict=True)
        if isinstance(self.direction, (bool, np.bool_)) or not isinstance(self.direction, (int, np.integer)):
            raise InputError(
                "direction", f"must be the int +1 (right lay) or -1 (left lay), got {self.direction!r}"
            )
        if self.direction not in (1, -1):
            raise InputError("direction", f"must be +1 (right lay) or -1 (left lay), got {self.direction!r}")
        values["direction"] = int(self.direction)
        values["phase"] = real_number("phase", self.phase)
        if self.material is not None and not isinstance(self.material, Material):
            raise InputError("material", f"must be a Material or None (the strand's), got {self.material!r}")
        for key, value in values.items():  # plain Python numbers
            object.__setattr__(self, key, value)


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
    material: np.ndarray  #: index of the wire's material in `Strand.materials`

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
        From the core outward (a list is stored as a tuple).
    material : Material
        Wire material: of every wire whose layer names none (and of the core unless
        ``core_material`` is given). The reference modulus of the section's
        transformed (modular-ratio) inertias.
    broken : frozenset of (layer, index)
        Broken wires: layer number (1 = first helical layer; the core cannot
        break) and wire index (0 to the layer's count - 1), integers only (not
        2.0). A set or list of pairs is stored as a frozenset; a pair listed
        twice raises InputError.
    name : str
        Label (presets: ``"steel-9.5"`` ...).
    core_material : Material or None
        The core wire's material; None (default): ``material``. With `Layer.material`,
        a material per layer (multi-material strands: ACSR's steel core and aluminium layers).
    """

    core_diameter: float
    layers: tuple[Layer, ...]
    material: Material
    broken: frozenset = field(default_factory=frozenset)
    name: str = ""
    core_material: Material | None = None

    def __post_init__(self):
        object.__setattr__(
            self, "core_diameter", real_number("core_diameter", self.core_diameter, lower=0.0, strict=True)
        )
        layers = self.layers
        if isinstance(layers, Layer) or not isinstance(layers, (tuple, list)):
            raise InputError("layers", f"must be a tuple of Layer (core outward), got {layers!r}")
        if not layers:
            raise InputError("layers", "a strand needs at least one helical layer")
        for k, layer in enumerate(layers, 1):
            if not isinstance(layer, Layer):
                raise InputError("layers", f"layer {k} must be a Layer, got {layer!r}")
        object.__setattr__(self, "layers", tuple(layers))
        if not isinstance(self.material, Material):
            raise InputError(
                "material", f"must be a Material (e.g. strand.material('steel')), got {self.material!r}"
            )
        object.__setattr__(self, "broken", frozenset(self._wire_set("broken", self.broken)))
        name_text(self.name)
        if self.core_material is not None and not isinstance(self.core_material, Material):
            raise InputError(
                "core_material", f"must be a Material or None (the strand's), got {self.core_material!r}"
            )

    # --- materials --------------------------------------------------------
    @property
    def layer_materials(self) -> tuple[Material, ...]:
        """The material of the core (entry 0) and of every layer (entries 1, 2, ...)."""
        core = self.core_material if self.core_material is not None else self.material
        return (core, *(layer.material or self.material for layer in self.layers))

    @property
    def materials(self) -> tuple[Material, ...]:
        """The distinct wire materials, in order of first appearance from the core outward."""
        out = []
        for item in self.layer_materials:
            if item not in out:
                out.append(item)
        return tuple(out)

    def wire_materials(self) -> WireMaterials:
        """Every wire's material (core first), grouped for vectorised evaluation."""
        materials = self.materials
        per_layer = np.array([materials.index(m) for m in self.layer_materials])
        counts = [1, *(layer.count for layer in self.layers)]
        return WireMaterials(materials, np.repeat(per_layer, counts))

    def _wire_set(self, argument: str, wires) -> list[tuple[int, int]]:
        """Validated (layer, index) pairs of ``wires`` (a set, list or tuple of pairs, as
        ``broken`` takes them), or InputError naming ``argument``."""
        if isinstance(wires, (str, bytes)) or not isinstance(wires, (set, frozenset, list, tuple)):
            raise InputError(argument, f"must be a set or list of (layer, index) pairs, got {wires!r}")
        out = []
        for item in wires:
            if not isinstance(item, (tuple, list)) or len(item) != 2:
                raise InputError(
                    argument, f"each wire must be a (layer, index) pair, got {item!r} (in {wires!r})"
                )
            try:
                layer, index = whole(argument, item[0]), whole(argument, item[1])
            except InputError:
                raise InputError(argument, f"layer and index must be integers, got {tuple(item)!r}") from None
            if not 1 <= layer <= len(self.layers):
                raise InputError(
                    argument,
                    f"no layer {layer} in {tuple(item)!r}: helical layers are 1..{len(self.layers)} "
                    "(the core, layer 0, cannot break)",
                )
            count = self.layers[layer - 1].count
            if not 0 <= index < count:
                raise InputError(
                    argument,
                    f"no wire {index} in layer {layer} ({tuple(item)!r}): indices are 0..{count - 1}",
                )
            if (layer, index) in out:
                raise InputError(argument, f"wire {(layer, index)!r} is listed twice")
            out.append((layer, index))
        return out

    def __repr__(self):
        def m(x):
            return f"{x:.4g} m"

        rows = [
            f"layer {k}: {layer.count} x {m(layer.wire_diameter)}, R = {m(R)}, "
            f"lay {np.degrees(alpha):.4g}° {'right' if layer.direction > 0 else 'left'}"
            for k, (layer, R, alpha) in enumerate(
                zip(self.layers, self.helix_radii, self.lay_angles, strict=True), 1
            )
        ]
        if len(rows) > 4:
            rows = [*rows[:2], f"... ({len(rows) - 3} more layers)", rows[-1]]
        broken = sorted(self.broken)
        shown = ", ".join(map(str, broken[:6])) + (", ..." if len(broken) > 6 else "")
        per_layer = ["1", *(str(layer.count) for layer in self.layers)]
        if len(per_layer) > 5:
            per_layer = [*per_layer[:3], "...", per_layer[-1]]
        counts = f"{'+'.join(per_layer)} = {1 + sum(layer.count for layer in self.layers)}"
        return (
            f"Strand({self.name or 'strand'!r}: {counts} wires, diameter {m(self.diameter)}, "
            f"core {m(self.core_diameter)}; {'; '.join(rows)}; "
            f"{len(broken)} broken{': ' + shown if broken else ''}; "
            f"material {'/'.join(m.name or 'custom' for m in self.materials)!r})"
        )

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
        core = dict(y=0.0, z=0.0, psi=0.0, radius=0.0, lay_angle=0.0, direction=0, layer=0, intact=True)
        columns = {k: [v] for k, v in (core | {"diameter": self.core_diameter}).items()}
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
        arrays = {k: np.array(v) for k, v in columns.items()}
        arrays["material"] = np.array(self.wire_materials().index)
        return Wires(**arrays)

    # --- damage -----------------------------------------------------------
    def damaged(self, n: int | None = None, *, wires=None) -> Strand:
        """A copy with wires broken.

        Parameters
        ----------
        n : int, optional
            Break n adjacent wires of the outer layer, placed symmetrically
            about +z (the outer layer is rotated so; Pino Vidal (2021), Table 3.2),
            so that the net section stays symmetric about z; ``0 <= n < count`` of the
            outer layer. Only for a strand without broken wires (the rotation would move
            them); ``n = 0`` returns the strand unrotated.
        wires : list or set of (layer, index), optional
            Break exactly these wires (layer 1 is the first helical layer, indices
            from 0), without rotating anything, in addition to those already broken.
            Integers only; a wire already broken or listed twice raises InputError.
        """
        if (n is None) == (wires is None):
            raise InputError("n", "give exactly one of n and wires")
        if wires is not None:
            new = self._wire_set("wires", wires)
            again = sorted(set(new) & self.broken)
            if again:
                raise InputError("wires", f"wire {again[0]!r} is already broken")
            return replace(self, broken=self.broken | frozenset(new))
        outer = self.layers[-1]
        n = whole("n", n)
        if not 0 <= n < outer.count:
            raise InputError("n", f"must be an integer in [0, {outer.count - 1}], got {n!r}")
        if self.broken:
            raise InputError(
                "n",
                f"damaged(n) rotates the outer layer and needs a strand without broken wires; this one has "
                f"{sorted(self.broken)} (use damaged(wires=...) to add breaks)",
            )
        name = f"{self.name} damage {n}".strip()
        if n == 0:
            return replace(self, name=name)
        # wires 0..n-1 straddle +z: psi_j = (j - (n-1)/2) * 2 pi / count
        phase = -(n - 1) / 2 * 2 * pi / outer.count
        layers = (*self.layers[:-1], replace(outer, phase=phase))
        top = len(self.layers)
        return replace(self, layers=layers, broken=frozenset({(top, j) for j in range(n)}), name=name)

    def section(self):
        """Section properties of this strand (see [Section][skcable.strand.Section])."""
        from skcable.strand._section import Section

        return Section(self)

    def bending_law(self, mu: float = 0.5, axial_strain: float = 0.004):
        """Cardou's bilinear stick/slip moment–curvature law at friction ``mu`` and axial
        strain ``axial_strain`` (see [BendingLaw][skcable.strand.BendingLaw])."""
        from skcable.strand._bending import BendingLaw

        return BendingLaw(self.section(), mu=mu, axial_strain=axial_strain)


def lay_rates(strand: Strand, wires: Wires) -> np.ndarray:
    """Every wire's lay rate dψ/dx = ±2π/p of its layer (rad/m), 0 for the core."""
    helical = wires.layer > 0
    lay_length = np.ones_like(wires.radius)
    lay_length[helical] = strand.lay_lengths[wires.layer[helical] - 1]
    return np.where(helical, wires.direction * 2 * pi / lay_length, 0.0)


#: Pino Vidal (2021), Table 3.1: wire diameter (m), material, nominal strand diameter (m), lay angle (deg).
_TABLE_3_1 = {
    "steel-9.5": (3.1e-3, "steel", 9.5e-3, 7.5),
    "aluminium-10.1": (3.37e-3, "aluminium", 10.1e-3, 8.0),
    "steel-12.7": (4.19e-3, "steel", 12.7e-3, 8.0),
    "aluminium-14.3": (4.77e-3, "aluminium", 14.3e-3, 7.0),
}


#: ACSR conductors of ASTM B232/B232M-17, "Standard Specification for Concentric-Lay-Stranded
#: Aluminum Conductors, Coated-Steel Reinforced (ACSR)": code word -> (steel wire diameter (m),
#: aluminium wire diameter (m), aluminium wires per layer from the core outward) over a 1+6 steel
#: core. The standard bounds the lay ratios (steel 16-26, inner aluminium 10-16, outer 10-13):
#: `LAY_RATIO` takes 19, 13 and 11, the outer layer right-hand, alternating inward (its rule).
_ACSR = {
    "acsr-drake": (3.454e-3, 4.442e-3, (10, 16)),  # 795 kcmil 26/7, outer diameter 28.14 mm
    "acsr-hawk": (2.675e-3, 3.439e-3, (10, 16)),  # 477 kcmil 26/7, outer diameter 21.79 mm
}


def _stranded(name: str, core: tuple, specs: list, strand_material: Material) -> Strand:
    """The strand of a stranding: the core ``(diameter, material)`` and the layers ``(count,
    diameter, material)`` from the core outward, at the lay ratios of `_ACSR`."""
    layers, outside = [], core[0]
    for k, (count, d, wire_material) in enumerate(specs):
        outside = outside + 2 * d
        kind = "steel" if wire_material.name == "steel" else ("outer" if k == len(specs) - 1 else "inner")
        direction = 1 if (len(specs) - 1 - k) % 2 == 0 else -1
        layers.append(
            Layer(count, d, lay_length=LAY_RATIO[kind] * outside, direction=direction, material=wire_material)
        )
    return Strand(core[0], tuple(layers), strand_material, name=name, core_material=core[1])


def _acsr(name: str) -> Strand:
    steel_d, al_d, counts = _ACSR[name]
    steel, aluminium = material("steel"), material("aluminium")
    specs = [(6, steel_d, steel)] + [(n, al_d, aluminium) for n in counts]
    return _stranded(name, (steel_d, steel), specs, aluminium)


def catalogue_strand(name: str) -> Strand:
    """The `Strand` of a catalogue entry (module text: layers, lay ratios, materials)."""
    e = entry(name)
    steel_m, al_m = material("steel"), material("aluminium")
    if e.kind == "AAAC":
        al_m = replace(al_m, density=2690.0, name="aluminium 6201-T81 (1350 law)")
    n_st, d_st = e.steel[0], e.steel[1] * INCH
    n_al, d_al = e.aluminium[0], e.aluminium[1] * INCH
    if n_st:
        specs = [(c, d_st, steel_m) for c in layer_counts(n_st)] + [
            (c, d_al, al_m) for c in aluminium_layers(n_al, n_st)
        ]
        return _stranded(e.name, (d_st, steel_m), specs, al_m)
    return _stranded(e.name, (d_al, al_m), [(c, d_al, al_m) for c in layer_counts(n_al)], al_m)


def preset(name: str) -> Strand:
    """A preset strand.

    The 1x7 strands of Pino Vidal (2021), Table 3.1: ``"steel-9.5"``, ``"aluminium-10.1"``,
    ``"steel-12.7"`` or ``"aluminium-14.3"`` (equal wires, helix radius d, one material).

    Multi-material conductors, ACSR 26/7 of ASTM B232/B232M-17 (a 1+6 steel core under 10 and 16
    aluminium wires): ``"acsr-drake"`` (795 kcmil) and ``"acsr-hawk"`` (477 kcmil), lay ratios 19,
    13 and 11; the strand's ``material`` is aluminium, ``core_material`` and the first layer's
    steel (`material`).

    Every size of the conductor catalogue (ACSR of ASTM B232, AAC of B231, AAAC of B399:
    ``"acsr-partridge"``, ``"aac-arbutus"``, ``"aaac-greeley"`` ...; see
    `skcable.conductors.catalogue`), built from its stranding. An unknown name is refused
    with the nearest known names.
    """
    if isinstance(name, str) and name in _ACSR:
        return _acsr(name)
    if not isinstance(name, str) or name not in _TABLE_3_1:
        if isinstance(name, str) and name.lower() in ENTRIES:
            return catalogue_strand(name)
        import difflib

        known = [*_TABLE_3_1, *_ACSR, *ENTRIES]
        near = difflib.get_close_matches(str(name).lower(), known, n=4, cutoff=0.5)
        hint = f"nearest: {', '.join(near)}" if near else f"known: {', '.join(known)}"
        raise InputError("name", f"unknown strand {name!r}; {hint}")
    d, mat, _nominal, alpha = _TABLE_3_1[name]
    return Strand(d, (Layer(6, d, lay_angle=radians(alpha)),), material(mat), name=name)
