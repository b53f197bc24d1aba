"""A catalogue of overhead line conductors: sizes of the ASTM standard tables.

Each entry is a size of one table, cited by standard and code word:

- ACSR, ASTM B232/B232M, "Standard Specification for Concentric-Lay-Stranded Aluminum
  Conductors, Coated-Steel Reinforced (ACSR)", Table 1 (code words of birds);
- AAC, ASTM B231/B231M, "Standard Specification for Concentric-Lay-Stranded Aluminum 1350
  Conductors", Table 1 (flowers);
- AAAC, ASTM B399/B399M, "Standard Specification for Concentric-Lay-Stranded 6201-T81 Aluminum
  Alloy Conductors", Table 1 (towns).

The tables print, per size: the stranding (aluminium and steel wires), the wire diameters and
the outer diameter (in.), the mass (lb/1000 ft) and the rated strength (lbf); the entries keep
those numbers as printed and convert to SI on use (1 in. = 25.4 mm, 1 lb/1000 ft =
1.488164 kg/km, 1 lbf = 4.448222 N). A strand is built from the stranding: a layer of 6 around
the core, each next layer 6 wires more, the core and the first layers steel up to the steel
count; lay ratios (lay length / layer diameter) inside the standards' ranges — steel 19, inner
aluminium 13, outer 11 — the outer layer right-hand and the directions alternating inward.
The 6201-T81 alloy wire (AAAC) takes the 1350 wire's law with the alloy's density, 2690 kg/m³
(ASTM B398): its mass and stiffness hold, its rupture does not.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass

from skcable.errors import InputError

__all__ = ["CatalogueEntry", "ENTRIES", "entry", "layer_counts", "aluminium_layers", "LAY_RATIO", "INCH"]

INCH = 25.4e-3  # m
_IN = INCH
_LB_PER_KFT = 0.45359237 / 304.8  # kg/m
_LBF = 4.4482216152605  # N

_STANDARD = {
    "ACSR": "ASTM B232/B232M, Table 1",
    "AAC": "ASTM B231/B231M, Table 1",
    "AAAC": "ASTM B399/B399M, Table 1",
}


@dataclass(frozen=True)
class CatalogueEntry:
    """One conductor size of a standard table, as printed (inch-pound units).

    ``aluminium`` and ``steel`` are ``(wires, wire diameter in.)`` (steel ``(0, 0)`` for AAC
    and AAAC); ``diameter_in`` the outer diameter, ``mass_lb_kft`` the mass, ``rts_lbf`` the
    rated strength; ``size`` the area in kcmil (or the AWG size as printed). SI: ``diameter``
    (m), ``mass`` (kg/m), ``rts`` (N).
    """

    name: str
    kind: str
    size: str
    aluminium: tuple
    steel: tuple
    diameter_in: float
    mass_lb_kft: float
    rts_lbf: float

    @property
    def source(self) -> str:
        return f"{_STANDARD[self.kind]}, {self.name.split('-', 1)[1].capitalize()}"

    @property
    def diameter(self) -> float:
        return self.diameter_in * _IN

    @property
    def mass(self) -> float:
        return self.mass_lb_kft * _LB_PER_KFT

    @property
    def rts(self) -> float:
        return self.rts_lbf * _LBF

    @property
    def stranding(self) -> str:
        return f"{self.aluminium[0]}/{self.steel[0]}" if self.steel[0] else f"{self.aluminium[0]}"


def _acsr(code, size, al, st, d, mass, rts):
    return CatalogueEntry(f"acsr-{code}", "ACSR", size, al, st, d, mass, rts)


def _aac(code, size, al, d, mass, rts, kind="AAC"):
    return CatalogueEntry(f"{kind.lower()}-{code}", kind, size, al, (0, 0.0), d, mass, rts)


#: name -> CatalogueEntry (code word, size, (wires, in.) aluminium and steel, outer diameter in.,
#: mass lb/1000 ft, rated strength lbf), as the tables print them.
ENTRIES = {
    e.name: e
    for e in (
        _acsr("turkey", "6 AWG", (6, 0.0661), (1, 0.0661), 0.198, 36.0, 1190),
        _acsr("swan", "4 AWG", (6, 0.0834), (1, 0.0834), 0.250, 57.4, 1860),
        _acsr("sparrow", "2 AWG", (6, 0.1052), (1, 0.1052), 0.316, 91.3, 2850),
        _acsr("raven", "1/0 AWG", (6, 0.1327), (1, 0.1327), 0.398, 145.2, 4380),
        _acsr("quail", "2/0 AWG", (6, 0.1490), (1, 0.1490), 0.447, 183.1, 5310),
        _acsr("pigeon", "3/0 AWG", (6, 0.1672), (1, 0.1672), 0.502, 230.6, 6620),
        _acsr("penguin", "4/0 AWG", (6, 0.1878), (1, 0.1878), 0.563, 291.1, 8350),
        _acsr("partridge", "266.8", (26, 0.1013), (7, 0.0788), 0.642, 367.3, 11300),
        _acsr("linnet", "336.4", (26, 0.1137), (7, 0.0884), 0.720, 463.2, 14100),
        _acsr("ibis", "397.5", (26, 0.1236), (7, 0.0961), 0.783, 547.3, 16300),
        _acsr("hawk", "477", (26, 0.1354), (7, 0.1053), 0.858, 656.0, 19500),
        _acsr("dove", "556.5", (26, 0.1463), (7, 0.1138), 0.927, 766.0, 22600),
        _acsr("grosbeak", "636", (26, 0.1564), (7, 0.1216), 0.990, 874.0, 25000),
        _acsr("drake", "795", (26, 0.1749), (7, 0.1360), 1.108, 1094.0, 31500),
        _acsr("rail", "954", (45, 0.1456), (7, 0.0971), 1.165, 1075.0, 25900),
        _acsr("cardinal", "954", (54, 0.1329), (7, 0.1329), 1.196, 1229.0, 33800),
        _acsr("falcon", "1590", (54, 0.1716), (19, 0.1030), 1.545, 2044.0, 54500),
        _aac("tulip", "336.4", (19, 0.1331), 0.666, 316.0, 6150),
        _aac("arbutus", "795", (37, 0.1466), 1.026, 746.0, 13900),
        _aac("magnolia", "954", (37, 0.1606), 1.124, 896.0, 16400),
        _aac("marigold", "1113", (61, 0.1351), 1.216, 1046.0, 19700),
        _aac("alton", "48.69", (7, 0.0834), 0.250, 45.4, 1760, kind="AAAC"),
        _aac("ames", "77.47", (7, 0.1052), 0.316, 72.2, 2800, kind="AAAC"),
        _aac("azusa", "123.3", (7, 0.1327), 0.398, 114.9, 4460, kind="AAAC"),
        _aac("butte", "312.8", (19, 0.1283), 0.642, 291.6, 10500, kind="AAAC"),
        _aac("canton", "394.5", (19, 0.1441), 0.721, 367.9, 13300, kind="AAAC"),
        _aac("darien", "559.5", (19, 0.1716), 0.858, 521.7, 18800, kind="AAAC"),
        _aac("flint", "740.8", (37, 0.1415), 0.990, 690.8, 24400, kind="AAAC"),
        _aac("greeley", "927.2", (37, 0.1583), 1.108, 864.6, 30500, kind="AAAC"),
    )
}

#: Lay ratios (lay length / layer diameter) of the catalogue strands, inside the standards' ranges.
LAY_RATIO = {"steel": 19.0, "inner": 13.0, "outer": 11.0}


def entry(name: str) -> CatalogueEntry:
    """The catalogue entry ``name`` (``"acsr-drake"``, ``"aac-arbutus"``, ``"aaac-greeley"``).

    Raises
    ------
    InputError
        ``name`` unknown, with the nearest names suggested.
    """
    if isinstance(name, str) and name.lower() in ENTRIES:
        return ENTRIES[name.lower()]
    near = difflib.get_close_matches(str(name).lower(), list(ENTRIES), n=4, cutoff=0.5)
    hint = f"; nearest: {', '.join(near)}" if near else f"; known: {', '.join(ENTRIES)}"
    raise InputError("name", f"no conductor {name!r} in the catalogue{hint}")


def layer_counts(total: int) -> list[int]:
    """Wires per helical layer of a concentric stranding of ``total`` wires (1 + 6 + 12 + ...)."""
    return [min(k, total - 1 - done) for k, done in _rings(total - 1, 6)]


def _rings(wires: int, first: int):
    """``(count, wires in the layers before)`` of concentric layers of ``first``, ``first + 6``,
    ... wires until ``wires`` are laid."""
    done, k = 0, first
    while done < wires:
        yield k, done
        done += k
        k += 6


def aluminium_layers(n: int, steel: int) -> list[int]:
    """Aluminium wires per layer over a steel core of ``steel`` wires: the layers of a full
    concentric count, less those the steel takes (26 over 7: 10 and 16; 45: 9, 15, 21)."""
    if steel == 0:
        return layer_counts(n)
    if n == 6:
        return [6]
    first = {26: 10, 45: 9, 54: 12}.get(n)
    if first is None:
        raise InputError("name", f"no layer rule for {n} aluminium wires over {steel} steel")
    return [k for k, _ in _rings(n, first)]
