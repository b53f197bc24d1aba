r"""A small library of mooring line components: nominal diameter → weight in water, EA, MBL.

Each `Component` holds the published property formulas of one kind of line as functions of its
nominal diameter ``d`` (m): the mass per length :math:`m = c_m d^2` (kg/m), the axial stiffness
:math:`EA = c_{EA} d^2` (N), the minimum breaking load ``MBL(d)`` (N) and the volume-equivalent
diameter :math:`d_v = k_v d` whose displaced water gives the buoyancy, so that the weight in water
per length is

.. math:: w = g\,\big(m - \rho\,\tfrac{\pi}{4} d_v^2\big).

The formulas and their sources:

- **chain**, studless and studlink: the mass, stiffness and volume-equivalent diameter of
  Orcina Ltd., *OrcaFlex Manual* (line type wizard, "Chain"; the same numbers in the current
  OrcaFlex help): :math:`m = 19.9\,d^2` and :math:`21.9\,d^2` t/m, :math:`EA = 0.854\times 10^8 d^2`
  and :math:`1.01\times 10^8 d^2` kN, :math:`d_v = 1.80\,d` and :math:`1.89\,d` (d in m); the MBL of
  the offshore grades, :math:`c\,d^2 (44 - 0.08\,d)` kN with d in mm and ``c`` = 0.0223 (R3), 0.0249
  (R3S), 0.0274 (R4), of Det Norske Veritas, *DNV-OS-E302 Offshore Mooring Chain*, 2008
  (the same for studless and studlink chain);
- **six-strand wire rope** with a fibre core and with an independent wire rope core (IWRC):
  Orcina Ltd., *OrcaFlex Manual*, version 9 (line type wizard, "Wire rope"):
  :math:`m = 3.6109\,d^2` and :math:`3.9897\,d^2` t/m, :math:`EA = 3.67\times 10^7 d^2` and
  :math:`4.04\times 10^7 d^2` kN, :math:`MBL = 584175\,d^2` and :math:`633358\,d^2` kN,
  :math:`d_v = 0.82\,d` and :math:`0.80\,d`;
- **polyester and nylon rope**: the same manual (line type wizard, "Rope"): :math:`m = 0.7978\,d^2`
  and :math:`0.6476\,d^2` t/m, :math:`EA = 1.09\times 10^6 d^2` and :math:`1.18\times 10^5 d^2` kN,
  :math:`MBL = 170466\,d^2` and (wet nylon) :math:`139357\,d^2` kN, :math:`d_v = 0.86\,d` and
  :math:`0.85\,d`. A synthetic rope's EA depends on the load and the loading rate: these are
  single representative values, to be replaced by the maker's.

Users add their own with `register_component` (or build a `Component` and call its ``segment``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from skcable import _plausible
from skcable._checks import positive, scalar
from skcable.errors import InputError
from skcable.mooring.segments import Segment

__all__ = ["ChainMBL", "Component", "MBLPerD2", "component", "components", "register_component"]

_KN = 1.0e3  # N
_TE = 1.0e3  # kg


@dataclass(frozen=True)
class Component:
    """A kind of mooring line, its properties as functions of its nominal diameter (module docstring).

    Parameters
    ----------
    name : str
        Its name in the library.
    mass_per_d2 : float
        ``c_m``: mass per length over the diameter squared (kg/m per m², d in m).
    EA_per_d2 : float
        ``c_EA``: axial stiffness over the diameter squared (N per m²).
    mbl : callable
        ``MBL(d)``: the minimum breaking load (N) at the nominal diameter ``d`` (m).
    volume_diameter : float
        ``k_v``: the volume-equivalent diameter over the nominal one.
    source : str
        Where the formulas come from (author, title, year).
    diameters : (float, float), optional
        The range of nominal diameters (m) the formulas hold for; outside it `properties`
        raises `InputError`.
    """

    name: str
    mass_per_d2: float
    EA_per_d2: float
    mbl: Callable[[float], float]
    volume_diameter: float
    source: str
    diameters: tuple = (0.0, math.inf)

    def properties(self, diameter, *, rho: float = 1025.0, g: float = 9.81) -> dict:
        """``{"diameter", "mass", "w", "EA", "MBL", "volume_diameter"}`` (SI) at the nominal
        ``diameter`` (m) in water of density ``rho`` (kg/m³), gravity ``g`` (m/s²)."""
        d = scalar("diameter", positive("diameter", diameter))
        _plausible.gravity(scalar("g", positive("g", g)))
        low, high = self.diameters
        if not low <= d <= high:
            raise InputError(
                "diameter",
                f"{d:g} m is outside the range of the {self.name!r} formulas, [{low:g}, {high:g}] m",
            )
        rho, g = scalar("rho", positive("rho", rho)), scalar("g", positive("g", g))
        mass = self.mass_per_d2 * d * d
        d_v = self.volume_diameter * d
        w = g * (mass - rho * math.pi / 4.0 * d_v * d_v)
        mbl = float(self.mbl(d))
        if not (math.isfinite(mbl) and mbl > 0):
            raise InputError(
                "diameter", f"gives the {self.name!r} an MBL of {mbl:g} N: outside its formula's range"
            )
        return {
            "diameter": d,
            "mass": mass,
            "w": w,
            "EA": self.EA_per_d2 * d * d,
            "MBL": mbl,
            "volume_diameter": d_v,
        }

    def segment(self, length, diameter, *, rho: float = 1025.0, g: float = 9.81) -> Segment:
        """A `Segment` of this component: ``length`` (m) at the nominal ``diameter`` (m), its weight in
        water, EA and MBL from the formulas."""
        p = self.properties(diameter, rho=rho, g=g)
        material = next((m for key, m in _MATERIALS if key in self.name), None)
        return Segment(
            length, p["w"], p["EA"], mbl=p["MBL"], diameter=p["volume_diameter"], material=material
        )


#: The material of a component, by a word of its name (`Segment`'s ``material``).
_MATERIALS = (("chain", "chain"), ("wire", "wire rope"), ("rope", "synthetic rope"))


@dataclass(frozen=True)
class ChainMBL:
    """DNV-OS-E302's breaking load of chain, ``c d² (44 - 0.08 d)`` kN with d in mm, called with
    ``d`` in m (N); ``c`` is the grade's factor (a picklable `Component.mbl`)."""

    c: float

    def __call__(self, d):
        mm = 1000.0 * d
        return self.c * mm * mm * (44.0 - 0.08 * mm) * _KN


@dataclass(frozen=True)
class MBLPerD2:
    """A breaking load ``c d²`` kN with d in m, called with ``d`` in m (N) (a picklable `Component.mbl`)."""

    c: float

    def __call__(self, d):
        return self.c * d * d * _KN


_ORCAFLEX = "Orcina Ltd., OrcaFlex Manual (line type wizard)"
_DNV = "Det Norske Veritas, DNV-OS-E302 Offshore Mooring Chain, 2008"
_LIBRARY: dict[str, Component] = {}
for _link, _mass, _EA, _kv in (("studless", 19.9, 0.854e8, 1.80), ("studlink", 21.9, 1.01e8, 1.89)):
    for _grade, _c in (("R3", 0.0223), ("R3S", 0.0249), ("R4", 0.0274)):
        _name = f"{_link} chain {_grade}"
        _LIBRARY[_name] = Component(
            _name,
            _mass * _TE,
            _EA * _KN,
            ChainMBL(_c),
            _kv,
            f"{_ORCAFLEX} ('Chain'); MBL: {_DNV}",
            diameters=(0.0, 0.5),  # 44 - 0.08 d > 0 below 550 mm
        )
for _name, _mass, _EA, _mbl, _kv, _what in (
    ("six-strand wire rope, fibre core", 3.6109, 3.67e7, 584175.0, 0.82, "Wire rope"),
    ("six-strand wire rope, IWRC", 3.9897, 4.04e7, 633358.0, 0.80, "Wire rope"),
    ("polyester rope", 0.7978, 1.09e6, 170466.0, 0.86, "Rope"),
    ("nylon rope", 0.6476, 1.18e5, 139357.0, 0.85, "Rope; the MBL wet"),
):
    _LIBRARY[_name] = Component(
        _name, _mass * _TE, _EA * _KN, MBLPerD2(_mbl), _kv, f"{_ORCAFLEX} ('{_what}')"
    )


def components() -> dict:
    """The library: ``{name: Component}`` (a copy; `register_component` adds to it)."""
    return dict(_LIBRARY)


def component(name: str) -> Component:
    """The library's component ``name`` (`components` lists them); `InputError` naming ``name`` if
    there is none."""
    try:
        return _LIBRARY[name]
    except (KeyError, TypeError):
        known = ", ".join(sorted(_LIBRARY))
        raise InputError("name", f"no component {name!r} in the library (known: {known})") from None


def register_component(item: Component, *, replace: bool = False) -> Component:
    """Add a user's `Component` to the library under its ``name`` (``replace`` to overwrite one);
    returns it."""
    if not isinstance(item, Component):
        raise InputError("item", f"must be a mooring.Component, got {type(item).__name__}")
    if not item.source or not isinstance(item.source, str):
        raise InputError("item", "give the component's source (author, title, year) as Component(source=...)")
    if item.name in _LIBRARY and not replace:
        raise InputError(
            "item", f"{item.name!r} is already in the library: give replace=True to overwrite it"
        )
    _LIBRARY[item.name] = item
    return item
