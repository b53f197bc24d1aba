r"""`read_moordyn`: a MoorDyn input file (v1 or v2) into a `skcable.mooring.MooringSystem`.

The sections are found as MoorDyn-C finds them (`skcable.mooring.moordyn.text`); what each row
means is MoorDyn-C's (``MoorDyn2.cpp``) and MoorDyn-F's where only it has it (FAST.Farm's
``Turbine#``, ``EXTERNAL LOADS``):

- **bodies** ``ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca``: ``Free`` a
  `RigidBody` (its mass at ``CG``, the buoyancy of ``Volume`` at its reference point, no
  waterplane: a MoorDyn body's own loads); ``Fixed``/``Anchor``, ``Coupled``/``Vessel`` and
  ``Turbine#`` (FAST.Farm, relative to turbine ``#``) held where given; ``CoupledPinned`` a rigid
  body whose reference point is held and which turns freely about it;
- **rods** ``ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs Outputs``: a rigid
  `skcable.mooring.rod.Rod` between its end points A and B: ``Fixed``/``Anchor``, ``Coupled``
  and ``Turbine#`` rods hold both ends, ``Body#`` ones are fixed to the body (in its axes),
  ``Pinned``, ``Body#Pinned`` and ``CoupledPinned`` ones hold end A (on the ground, the body, or
  where given) and turn about it, ``Free`` ones have both ends free; a rod of zero length is a
  point;
- **points** ``ID Attachment X Y Z Mass Volume CdA Ca`` (v2) or ``Node Type X Y Z M V FX FY FZ
  CdA Ca`` (v1: 12 columns, a constant force): ``Fixed``/``Anchor`` anchors, ``Coupled``/
  ``Vessel``/``Fairlead`` held where given, ``Free``/``Point``/``Connect`` free points (their mass
  and volume: clump weights and buoys), ``Body#``/``B#`` points of body ``#`` (its axes),
  ``Turbine#``/``T#`` points of FAST.Farm's turbine ``#``;
- **lines** ``ID LineType AttachA AttachB UnstrLen NumSegs Outputs`` (v2) or ``Line LineType
  UnstrLen NumSegs NodeAnch NodeFair Flags`` (v1, told by its column names): a
  `skcable.mooring.Line` of one `Segment` of the line type (`skcable.mooring.moordyn.linetypes`)
  from end A to end B; an end is a point's number (``C#``, ``P#``, ``Con#``, ``Point#`` too) or a
  rod's end, ``R#A``/``R#B``;
- **external loads** (MoorDyn-F) ``ID Object Fext Blin Bquad CSys``: the constant force
  ``Fext`` on ``Body#`` (at its reference point, global axes), ``Point#`` or ``Rod#`` (at its end
  A); the damping is the dynamics';
- **SYROPE IC** ``Line(s) Tmax0 Tmean0``: the largest mean tension that sets a Syrope rope's
  working curve;
- the **water depth** is MoorDyn-C's: the ``WtrDpth`` option's (0 when absent), at least as deep
  as the lowest point (`skcable.mooring.moordyn.options.water_depth`).

The IDs of bodies, rods, points and lines run 1, 2, 3, ... as MoorDyn requires. What the statics
leave aside (options, hydrodynamic columns, FAILURE, OUTPUTS) is kept in the model and listed in
its ``ignored``. Anything the file says that these statics cannot take as said is refused by name
(`InputError` with the file and the line), never read as something else.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

from skcable._checks import real
from skcable.errors import InputError
from skcable.mooring.body import rotation_matrix
from skcable.mooring.moordyn.build import build_system
from skcable.mooring.moordyn.linetypes import read_line_types, read_rod_types
from skcable.mooring.moordyn.model import MoorDynModel
from skcable.mooring.moordyn.options import read_options, water_depth
from skcable.mooring.moordyn.text import InputFile

__all__ = ["read_moordyn"]

_IDENTITY = np.eye(3)  # a body's axes as the file gives them (`BodyRecord.frame`)


def decompose(word: str) -> tuple[str, str, str, str, str]:
    """MoorDyn's ``decomposeString``: ``(letters, digits, letters, digits, rest)`` of ``word``,
    upper-cased (``"Body1Pinned"`` gives ``("BODY", "1", "PINNED", "", "")``)."""
    match = re.match(r"([A-Z]*)(\d*)([A-Z]*)(\d*)(.*)$", word.upper())
    assert match is not None  # the pattern matches any string
    return match.groups()  # type: ignore[return-value]


@dataclass
class BodyRecord:
    """A body row: ``kind`` (free, fixed, coupled, coupledpinned, turbine), its global ``pose``
    ``(x, y, z, roll, pitch, yaw)`` (m, rad), ``mass``, ``cg``, ``volume``, the system's ``body``
    (None where held), and ``frame``: the file's body axes in the system body's (the identity, or
    the start rotation for a body whose pitch starts near ±90°: its system angles start at zero)."""

    id: int
    kind: str
    pose: np.ndarray
    mass: float
    cg: np.ndarray
    volume: float
    line: int
    body: object = None
    frame: np.ndarray = field(default_factory=lambda: _IDENTITY)

    def to_global(self, local) -> np.ndarray:
        """A point in the body's axes, in global axes at its pose (m)."""
        return self.pose[:3] + rotation_matrix(*self.pose[3:]) @ np.asarray(local, dtype=float)


@dataclass
class RodRecord:
    """A rod row: ``type`` (a `RodType`), ``kind`` (fixed, coupled, turbine, body, bodypinned,
    pinned, coupledpinned, free), ``owner`` (its body or turbine number), its ends ``a``, ``b`` as
    given, ``numsegs``; once built, its end ``points`` and its ``handle`` in the system (None for a
    rod of zero length or one the ground holds)."""

    id: int
    type: object
    kind: str
    owner: int | None
    a: np.ndarray
    b: np.ndarray
    numsegs: int
    line: int
    points: tuple = ()
    handle: object = None
    body: object = None
    offset: np.ndarray = field(default_factory=lambda: np.zeros(3))  # a turbine's position


@dataclass
class PointRecord:
    """A point row: ``kind`` (fixed, coupled, free, body, turbine), ``owner``, ``xyz`` as given,
    ``mass``, ``volume``, ``force``."""

    id: int
    kind: str
    owner: int | None
    xyz: np.ndarray
    mass: float
    volume: float
    force: np.ndarray
    line: int


@dataclass
class LineRecord:
    """A line row: ``type`` name, its ends ``("point", n)`` or ``("rod", n, "A" | "B")``, ``length``,
    ``numsegs``."""

    id: int
    type: str
    ends: list
    length: float
    numsegs: int
    line: int
    extra: list = field(default_factory=list)


def _numbered(source, section, counts, what: str):
    """``(row, ID)`` of each row of ``section`` (none where the file has none), its columns one of
    the ``counts``, its ID the next of 1, 2, 3, ... as MoorDyn requires."""
    for k, row in enumerate(() if section is None else section.rows):
        source.columns(row, counts, section.name)
        number = source.integer(row, 0, "ID")
        if number != k + 1:
            raise source.error(
                row.line, "ID", f"{what} ID {number}: MoorDyn's IDs run 1, 2, 3, ... (expected {k + 1})"
            )
        yield row, number


#: MoorDyn's words of each attachment (``decomposeString``'s first letters, no number after them).
_FIXED = ("ANCHOR", "FIXED", "FIX")
_COUPLED = ("VESSEL", "VES", "COUPLED", "CPLD", "FAIRLEAD")
_COUPLEDPINNED = ("VESSELPINNED", "VESPIN", "CPLDPIN", "COUPLEDPINNED")
_FREE = ("FREE", "POINT", "CON", "CONNECT")
#: Each row's attachments with no number, ``{kind: words}``, and the words numbered by an owner.
_BODY = {"free": _FREE, "fixed": _FIXED, "coupled": _COUPLED, "coupledpinned": _COUPLEDPINNED}
_POINT = {"fixed": _FIXED, "coupled": _COUPLED, "free": _FREE}
_ROD = {
    "fixed": _FIXED,
    "pinned": ("PINNED", "PIN"),
    "coupled": _COUPLED[:-1],  # no FAIRLEAD rod
    "coupledpinned": _COUPLEDPINNED,
    "free": ("POINT", "CON", "FREE"),
}
_OWNERS = ("BODY", "B", "TURBINE", "T")


def _attachment(source, row, word, what, plain, numbered, pinned=False) -> tuple[str, int | None]:
    """``(kind, number)`` of the attachment ``word`` of a ``what`` row: a word of ``plain``
    (``{kind: words}``) with no number (nor anything after it, but on a body's row), or one of
    ``numbered`` with its body's or turbine's number (a rod's followed by ``PINNED``/``PIN`` where
    ``pinned``)."""
    let1, num1, let2, _, rest = decompose(word)
    if not (num1 or let2 or rest and what != "body"):
        for kind, words in plain.items():
            if let1 in words:
                return kind, None
    if let1 in numbered and num1 and not rest:
        base = "body" if let1 in ("BODY", "B") else "turbine"
        if not let2:
            return base, int(num1)
        if pinned and let2 in ("PINNED", "PIN"):
            return base + "pinned", int(num1)
    raise source.error(row.line, word, f"unknown MoorDyn {what} attachment {word!r}")


def _turbine(source, row, turbines, n) -> np.ndarray:
    if turbines is None or n not in turbines:
        raise source.error(
            row.line,
            "turbines",
            f"attached to Turbine{n}: give the turbines' positions (FAST.Farm's WT_X, WT_Y, WT_Z), "
            "read_moordyn(path, turbines={...})",
        )
    return turbines[n]


def _bodies(source, section, turbines) -> dict:
    out: dict = {}
    for row, number in _numbered(source, section, (14,), "body"):
        kind, owner = _attachment(
            source, row, source.word(row, 1, "Attachment"), "body", _BODY, ("TURBINE", "T")
        )
        pose = np.array(
            [source.number(row, k, c) for k, c in enumerate(("X0", "Y0", "Z0", "r0", "p0", "y0"), start=2)]
        )
        pose[3:] = np.radians(pose[3:])
        if kind == "turbine":
            pose[:3] += _turbine(source, row, turbines, owner)
        cg = [source.number(row, 9, "CG", text=t) for t in source.word(row, 9, "CG").split("|")]
        if len(cg) not in (1, 3):
            raise source.error(row.line, "CG", "CG has 1 (z) or 3 numbers")
        mass, volume = source.number(row, 8, "Mass"), source.number(row, 11, "Volume")
        if mass < 0 or volume < 0:
            raise source.error(row.line, "Mass" if mass < 0 else "Volume", "must be >= 0")
        cg3 = np.array([0.0, 0.0, cg[0]] if len(cg) == 1 else cg)
        out[number] = BodyRecord(number, kind, pose, mass, cg3, volume, row.line)
    return out


def _points(source, section, turbines) -> dict:
    """The POINTS rows; a turbine's point placed in global axes (its turbine's position added)."""
    out: dict = {}
    for row, number in _numbered(source, section, (9, 12), "point"):
        kind, owner = _attachment(source, row, source.word(row, 1, "Attachment"), "point", _POINT, _OWNERS)
        xyz = np.array([source.number(row, k, c) for k, c in zip((2, 3, 4), "XYZ", strict=True)])
        mass, volume = source.number(row, 5, "Mass"), source.number(row, 6, "Volume")
        if mass < 0 or volume < 0:
            raise source.error(row.line, "Mass" if mass < 0 else "Volume", "must be >= 0")
        if kind == "turbine":
            xyz = xyz + _turbine(source, row, turbines, owner)
        force = np.zeros(3)
        if len(row.tokens) == 12:  # v1: FX FY FZ (N)
            force = np.array([source.number(row, k, c) for k, c in enumerate(("FX", "FY", "FZ"), start=7)])
        out[number] = PointRecord(number, kind, owner, xyz, mass, volume, force, row.line)
    return out


def _rods(source, section, rod_types, turbines) -> dict:
    """The RODS rows; a turbine's rod placed in global axes."""
    out: dict = {}
    for row, number in _numbered(source, section, (11,), "rod"):
        name = source.word(row, 1, "RodType")
        if name not in rod_types:
            raise source.error(row.line, name, f"no rod type {name!r} in ROD TYPES")
        word = source.word(row, 2, "Attachment")
        kind, owner = _attachment(source, row, word, "rod", _ROD, _OWNERS, pinned=True)
        ends = [source.number(row, k, c) for k, c in enumerate(("Xa", "Ya", "Za", "Xb", "Yb", "Zb"), start=3)]
        numsegs = source.integer(row, 9, "NumSegs")
        offset = _turbine(source, row, turbines, owner) if kind.startswith("turbine") else np.zeros(3)
        a, b = np.array(ends[:3]) + offset, np.array(ends[3:]) + offset
        out[number] = RodRecord(number, rod_types[name], kind, owner, a, b, numsegs, row.line, offset=offset)
    return out


def _end(source, row, word, column, points, rods) -> tuple:
    let1, num1, let2, _, rest = decompose(word)
    if not num1 or rest:
        raise source.error(row.line, word, f"{column} {word!r} is no point number nor rod end (R#A, R#B)")
    n = int(num1)
    if let1 in ("R", "ROD"):
        if let2 not in ("A", "B"):
            raise source.error(row.line, word, f"{column} {word!r}: a rod end is R#A or R#B")
        if n not in rods:
            raise source.error(row.line, word, f"{column} {word}: there is no rod {n}")
        return ("rod", n, let2)
    if let1 in ("", "C", "CON", "P", "POINT") and not let2:
        if n not in points:
            raise source.error(
                row.line, word, f"{column} {word}: there is no point {n} (the file has {len(points)})"
            )
        return ("point", n)
    raise source.error(row.line, word, f"{column} {word!r}: unknown line end")


def _is_v1_lines(section) -> bool:
    """Whether the LINES table has MoorDyn v1's columns (``Line LineType UnstrLen NumSegs NodeAnch
    NodeFair Flags``), told by its column names."""
    names = [c.lower() for c in section.columns]
    return len(names) >= 5 and names[2].startswith("unstr") and names[4].startswith("node")


def _lines(source, section, points, rods, types) -> list:
    out: list = []
    if section is None:
        return out
    v1 = _is_v1_lines(section)
    order = (2, 3, 4, 5) if v1 else (4, 5, 2, 3)  # UnstrLen, NumSegs, end A, end B
    for row, number in _numbered(source, section, (7,), "line"):
        name = source.word(row, 1, "LineType")
        if name not in types:
            raise source.error(row.line, name, f"no line type {name!r} in LINE TYPES")
        length = source.number(row, order[0], "UnstrLen")
        if not length > 0:
            raise source.error(row.line, "UnstrLen", f"{row.tokens[order[0]]!r}: a line's length must be > 0")
        numsegs = source.integer(row, order[1], "NumSegs")
        ends = [
            _end(source, row, source.word(row, k, c), c, points, rods)
            for k, c in ((order[2], "AttachA"), (order[3], "AttachB"))
        ]
        out.append(LineRecord(number, name, ends, length, numsegs, row.line, list(row.tokens[6:])))
    return out


def read_moordyn(path, *, turbines=None) -> MoorDynModel:
    """Read a MoorDyn input file (v1 or v2; module docstring) into a `MoorDynModel`.

    Parameters
    ----------
    path : str or Path
        The file.
    turbines : mapping or sequence of (x, y, z), optional
        FAST.Farm's turbine positions (m, its ``WT_X WT_Y WT_Z``): ``{number: (x, y, z)}`` or a
        list, turbine 1 first. Needed where the file attaches to ``Turbine#``.

    Returns
    -------
    MoorDynModel
        Its ``system``, and what the statics leave aside (``ignored``).

    Raises
    ------
    InputError
        With ``path`` and ``line`` (the file's line) and the reason: a truncated file, a row with
        the wrong number of columns, an unknown attachment, a line naming a point or rod the file
        does not have, a byte that is not UTF-8, a value that is no number or overflows.
    """
    source = InputFile(path)
    sections = source.sections()
    if not any(name in sections for name in ("LINE TYPES", "BODIES", "RODS", "POINTS", "LINES")):
        raise source.error(
            None,
            "path",
            "no MoorDyn section (LINE TYPES, BODIES, RODS, POINTS, LINES): not a MoorDyn input file",
        )
    options = read_options(source, sections.get("OPTIONS"))
    types = read_line_types(source, sections["LINE TYPES"]) if "LINE TYPES" in sections else {}
    rod_types = read_rod_types(source, sections.get("ROD TYPES"))
    turbines = _turbine_positions(turbines)
    bodies = _bodies(source, sections.get("BODIES"), turbines)
    rods = _rods(source, sections.get("RODS"), rod_types, turbines)
    points = _points(source, sections.get("POINTS"), turbines)
    lines = _lines(source, sections.get("LINES"), points, rods, types)
    model = MoorDynModel(None, options=options, path=str(path), header=source.front_matter())  # type: ignore[arg-type]
    model.text, model.records = list(source.lines), {"points": points, "lines": lines}
    model.line_types, model.rod_types = types, rod_types
    model.ignored.update(options.ignored)
    columns = {
        "LINE TYPES": (
            "LINE TYPES BA/-zeta, EI, Cd, Ca, CdAx, CaAx",
            "damping, bending stiffness and "
            "hydrodynamic coefficients: the statics of a cable take its weight and axial law",
        ),
        "ROD TYPES": ("ROD TYPES Cd, Ca, CdEnd, CaEnd", "hydrodynamic coefficients (dynamics)"),
        "BODIES": ("BODIES I, CdA, Ca", "inertia and hydrodynamic coefficients (dynamics)"),
        "POINTS": ("POINTS CdA, Ca", "hydrodynamic coefficients (dynamics)"),
        "LINES": (
            "LINES NumSegs, Outputs",
            "the dynamics' discretisation and outputs: the statics solve each line whole, in closed form",
        ),
    }
    for name, (what, why) in columns.items():
        if name in sections and sections[name].rows:
            model.ignored[what] = why
    for name in ("FAILURE", "OUTPUTS"):
        if name in sections:
            model.ignored[name] = (
                "the dynamics' line failures" if name == "FAILURE" else "output channels of the dynamics"
            )
    model.outputs = [" ".join(r.tokens) for r in sections["OUTPUTS"].rows] if "OUTPUTS" in sections else []
    if model.outputs and model.outputs[-1].upper() == "END":
        model.outputs.pop()
    ic = _syrope_ic(source, sections.get("SYROPE IC"), lines)
    depth = water_depth(options.depth, _lowest(bodies, points, source))
    loads = _external_loads(source, sections.get("EXTERNAL LOADS"), bodies, points, rods)
    if loads:
        model.ignored["EXTERNAL LOADS Blin, Bquad"] = "damping (dynamics)"
    build_system(source, model, options, depth, (bodies, rods, points, lines), (ic, loads))
    return model


def _turbine_positions(turbines) -> dict | None:
    if turbines is None:
        return None
    items = turbines.items() if isinstance(turbines, dict) else enumerate(turbines, start=1)
    out = {}
    for n, xyz in items:
        value = np.asarray(real("turbines", xyz), dtype=float)
        if value.shape != (3,):
            raise InputError("turbines", f"turbine {n}: give (x, y, z), got {xyz!r}")
        out[int(n)] = np.array(value, dtype=float)
    return out


def _lowest(bodies, points, source) -> float:
    """The lowest z of the points (m), global: MoorDyn-C's floor of the water depth."""
    lowest = 0.0
    for p in points.values():
        z = p.xyz[2]
        if p.kind == "body":
            if p.owner not in bodies:
                raise source.error(p.line, f"Body{p.owner}", f"there is no body {p.owner} in BODIES")
            z = bodies[p.owner].to_global(p.xyz)[2]
        lowest = min(lowest, float(z))
    return lowest


def _syrope_ic(source, section, lines) -> dict:
    """``{line number: (Tmax0, Tmean0, row)}`` of the SYROPE IC section."""
    out: dict = {}
    for row in () if section is None else section.rows:
        source.columns(row, (3,), "SYROPE IC")
        tmax, tmean = source.number(row, 1, "Tmax0"), source.number(row, 2, "Tmean0")
        for word in source.word(row, 0, "Line(s)").split(","):
            try:
                n = int(word)
            except ValueError:
                raise source.error(row.line, "Line(s)", f"{word!r} is no line number") from None
            if not 1 <= n <= len(lines):
                raise source.error(row.line, "Line(s)", f"there is no line {n}")
            out[n] = (tmax, tmean, row)
    return out


def _external_loads(source, section, bodies, points, rods) -> dict:
    """The constant forces of MoorDyn-F's EXTERNAL LOADS: ``{("body" | "point" | "rod", n): force}``
    (N, global axes; a rod's at its end A)."""
    out: dict = {}
    for row in () if section is None else section.rows:
        source.columns(row, (6,), "EXTERNAL LOADS")
        word = source.word(row, 1, "Object")
        let1, num1, let2, _, rest = decompose(word)
        parts = source.word(row, 2, "Fext").split("|")
        if len(parts) != 3:
            raise source.error(row.line, "Fext", "Fext is fx|fy|fz")
        force = np.array([source.number(row, 2, "Fext", text=t) for t in parts])
        csys = source.word(row, 5, "CSys").upper()
        n = int(num1) if num1 else -1
        table = {"BODY": ("body", bodies), "POINT": ("point", points), "ROD": ("rod", rods)}
        if let1 not in table or let2 or rest or n not in table[let1][1]:
            raise source.error(row.line, word, f"{word!r} is no body, point or rod of the file")
        kind = table[let1][0]
        if kind == "body" and csys == "L":
            raise source.error(
                row.line,
                "CSys",
                "a force in the body's axes turns with it: these statics take global (G) ones",
            )
        out[(kind, n)] = out.get((kind, n), np.zeros(3)) + force
    return out
