r"""MoorDyn v2 input files: read one into a `skcable.mooring.MooringSystem`, write a system as one.

The format is MoorDyn v2's (M. Hall et al., MoorDyn documentation, "Input Files: the V2 input
file"): sections headed by a line of dashes around their name, in this order: ``LINE TYPES``,
``BODIES`` (optional), ``POINTS``, ``LINES``, ``OPTIONS``, ``OUTPUTS`` (optional), each table
after two lines of column names and units; ``!``, ``#`` and ``%`` start a comment in a data row.
What the statics take:

- **line types**: ``TypeName Diam Mass/m EA ...``: each line is one uniform `Segment`, its weight
  in water per length :math:`w = g\,(m - \rho\,\tfrac{\pi}{4} d^2)` (``d`` the volume-equivalent
  diameter, ``rho`` and ``g`` the options'), its EA the static one (the first of ``EA_s|EA_d``);
  the hydrodynamic columns are kept for writing back only;
- **bodies**: ``ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca``: a ``free`` body is a
  `RigidBody` (mass at ``CG``, buoyancy of ``Volume`` at its reference point, no waterplane, as a
  MoorDyn body); a ``coupled``, ``vessel`` or ``fixed`` body is held where it is given (its points
  fixed there: an outside program drives a coupled body);
- **points**: ``ID Attachment X Y Z Mass Volume CdA Ca``: ``fixed``/``anchor`` (an anchor),
  ``free``/``point``/``connect`` (a free point with its mass and volume), ``coupled``/``vessel``
  (held where given), ``body#`` (fixed to body ``#``, in its axes);
- **lines**: ``ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs``;
- **options**: ``value key``: ``WtrDpth`` (the depth), ``rho``/``rhoW``, ``g`` are used; the other
  known MoorDyn options (time steps, seabed stiffness, initial-condition settings, ...; the v1 names
  ``kb``, ``cb``, ``ICDfac``, ``ICthresh``, ``ICTmax`` too) concern the dynamics and are kept for
  writing back.

An unknown section, option, attachment or column value is refused by name (`InputError` naming
the file's keyword), as are the parts MoorDyn has and these statics do not (rods, a line end at a
rod, failures, controls, external loads, a nonlinear EA table).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from skcable.errors import InputError
from skcable.mooring.body import PointBody, RigidBody
from skcable.mooring.segments import Line, Segment

if TYPE_CHECKING:
    from skcable.mooring.system import MooringSystem

__all__ = ["MoorDynModel", "read_moordyn", "write_moordyn"]

#: MoorDyn v2's options (MoorDyn-C and MoorDyn-F), lower case.
OPTIONS = frozenset(
    s.lower()
    for s in (
        "writeLog",
        "dtM",
        "CFL",
        "tScheme",
        "g",
        "rho",
        "rhoW",
        "WtrDpth",
        "depth",
        "kBot",
        "cBot",
        "dtIC",
        "TmaxIC",
        "CdScaleIC",
        "threshIC",
        "WaveKin",
        "dtWave",
        "waveKin_rampT",
        "Currents",
        "UnifyCurrentGrid",
        "WriteUnits",
        "FrictionCoefficient",
        "FricDamp",
        "StatDynFricScale",
        "dtOut",
        "SeafloorFile",
        "ICgenDynamic",
        "disableOutput",
        "disableOutTime",
        "WaterKin",
        "MU_KT",
        "MU_KA",
        "MC",
        "CV",
        "inertialF",
        "inertialF_rampT",
        "OutSwitch",
        "Echo",
        "WtrDnsty",
        "gravity",
        "kb",
        "cb",
        "ICDfac",
        "ICthresh",
        "ICTmax",  # the v1 names, still written by MoorPy
    )
)
SECTIONS = ("LINE TYPES", "BODIES", "POINTS", "LINES", "OPTIONS", "OUTPUTS")
UNSUPPORTED = ("ROD TYPES", "RODS", "FAILURE", "CONTROL", "EXTERNAL LOADS")
V1 = (
    "LINE DICTIONARY",
    "NODE PROPERTIES",
    "POINT PROPERTIES",
    "CONNECTION PROPERTIES",
    "LINE PROPERTIES",
    "SOLVER OPTIONS",
)
FIXED, FREE, HELD = ("fixed", "anchor"), ("free", "point", "connect"), ("coupled", "vessel")


@dataclass
class MoorDynModel:
    """A MoorDyn v2 file read into a system, with what the statics leave aside.

    Attributes
    ----------
    system : MooringSystem
    line_types : dict
        ``{name: (Diam, Mass/m, EA text, the other columns as text)}``.
    line_type_of : list of str
        Each line's type name.
    segments : list of int
        Each line's ``NumSegs``.
    held : list
        The points and bodies held where given (``coupled``/``vessel``/``fixed`` in the file).
    options : dict
        ``{key: value text}`` of the OPTIONS section.
    outputs : list of str
        The OUTPUTS channels.
    header : str
        The free text at the top.
    """

    system: MooringSystem
    line_types: dict = field(default_factory=dict)
    line_type_of: list = field(default_factory=list)
    segments: list = field(default_factory=list)
    held: list = field(default_factory=list)
    options: dict = field(default_factory=dict)
    outputs: list = field(default_factory=list)
    header: str = ""


# -- reading ------------------------------------------------------------------------------------------
def _section_name(line: str):
    """The section name of a header line (dashes around words), or None."""
    text = line.strip()
    if not text.startswith("---"):
        return None
    name = " ".join(text.strip("-").split()).upper()
    return name or None


def _header(name, number, sections, order):
    """Check a section header ``name`` (line ``number``); returns the name to read rows into (an
    unsupported section's rows are refused once read: an empty one is no error)."""
    if name in UNSUPPORTED:
        sections.setdefault(name, [])
        return name
    if name in V1:
        raise InputError(name, f"line {number}: a MoorDyn v1 section: give a v2 input file")
    if name not in SECTIONS:
        raise InputError(name, f"line {number}: unknown MoorDyn section {name!r}")
    if name in sections:
        raise InputError(name, f"line {number}: the {name} section appears twice")
    order.append(name)
    sections[name] = []
    return name


def _rows(text: str) -> dict:
    """``{section: [(line number, tokens)]}``, the front matter under ``""``: the table rows after
    their two header lines, comments cut; unknown and unsupported sections refused by name. The
    OUTPUTS section ends at the next header line or ``END``, and the file with it."""
    sections: dict[str, list] = {"": []}
    current, skip = "", 0
    order: list[str] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        name = _section_name(raw)
        if current == "OUTPUTS" and (name is not None or raw.strip().upper() == "END"):
            break
        if name is not None:
            if current == "" and name.startswith("MOORDYN"):  # the title rule of the front matter
                continue
            current = _header(name, number, sections, order)
            skip = 0 if name in ("OPTIONS", "OUTPUTS") else 2
            continue
        if skip:
            skip -= 1
            continue
        if current == "":
            sections[""].append((number, raw.rstrip()))
            continue
        data = raw
        for mark in ("!", "#", "%"):
            data = data.split(mark, 1)[0]
        if data.split():
            sections[current].append((number, data.split()))
    for name in UNSUPPORTED:
        if sections.get(name):
            number = sections[name][0][0]
            raise InputError(name, f"line {number}: the {name} section is not supported by these statics")
    if [s for s in SECTIONS if s in order] != order:
        raise InputError("sections", f"out of MoorDyn's order {', '.join(SECTIONS)}: {', '.join(order)}")
    for required in ("LINE TYPES", "POINTS", "LINES"):
        if required not in sections:
            raise InputError(required, "the file has no such section: it is required")
    return sections


def _number(keyword, number, text):
    try:
        value = float(text)
    except ValueError:
        raise InputError(keyword, f"line {number}: {text!r} is not a number") from None
    if not math.isfinite(value):
        raise InputError(keyword, f"line {number}: {text!r} is not finite")
    return value


def _columns(section, number, tokens, count):
    if len(tokens) < count:
        raise InputError(section, f"line {number}: {len(tokens)} columns, {count} expected")
    return tokens


def _options(rows) -> dict:
    out = {}
    for number, tokens in rows:
        if len(tokens) < 2:
            raise InputError("OPTIONS", f"line {number}: an option is 'value key', got {' '.join(tokens)!r}")
        key = tokens[1]
        if key.lower() not in OPTIONS:
            raise InputError(key, f"line {number}: unknown MoorDyn option {key!r}")
        out[key] = tokens[0]
    return out


def _option(options, names, default, number_of="OPTIONS"):
    for key, value in options.items():
        if key.lower() in names:
            return _number(key, number_of, value)
    return default


def _line_types(rows, rho, g) -> tuple[dict, dict]:
    """``({name: raw columns}, {name: (w, EA, d)})``."""
    raw, props = {}, {}
    for number, tokens in rows:
        tokens = _columns("LINE TYPES", number, tokens, 3)
        name = tokens[0]
        d, m = _number("Diam", number, tokens[1]), _number("Mass/m", number, tokens[2])
        EA_text = tokens[3] if len(tokens) > 3 else ""
        try:
            EA = float(EA_text.split("|")[0])
        except ValueError:
            raise InputError(
                "EA", f"line {number}: {EA_text!r}: a nonlinear EA table is not supported"
            ) from None
        w = g * (m - rho * math.pi / 4.0 * d * d)
        raw[name], props[name] = (d, m, EA_text, tokens[4:]), (w, EA, d)
    return raw, props


def _attachment(word, number):
    low = word.lower()
    if low in FIXED:
        return "fixed", None
    if low in FREE:
        return "free", None
    if low in HELD:
        return "held", None
    if low.startswith("body") and low[4:].isdigit():
        return "body", int(low[4:])
    raise InputError(word, f"line {number}: unknown MoorDyn point attachment {word!r}")


def _bodies(system, rows, model):
    """Add the BODIES: ``{id: (body or None, position (6,))}`` (None: held where given)."""
    out = {}
    for number, tokens in rows:
        tokens = _columns("BODIES", number, tokens, 12)
        kind = tokens[1].lower()
        pose = np.array([_number("X0", number, t) for t in tokens[2:8]])
        pose[3:] = np.radians(pose[3:])
        mass, volume = _number("Mass", number, tokens[8]), _number("Volume", number, tokens[11])
        cg = [_number("CG", number, t) for t in tokens[9].split("|")]
        cg = [0.0, 0.0, cg[0]] if len(cg) == 1 else cg
        if kind == "free":
            body = RigidBody(mass=mass, volume=volume, center_of_gravity=cg, rho=system.rho, g=system.g)
            out[int(tokens[0])] = (system.add_body(body, position=pose), pose)
        elif kind in ("coupled", "vessel", "fixed"):
            out[int(tokens[0])] = (None, pose)
        else:
            raise InputError(tokens[1], f"line {number}: unknown MoorDyn body attachment {tokens[1]!r}")
    return out


def _points(system, rows, bodies, model) -> dict:
    from skcable.mooring.body import rotation_matrix

    points = {}
    for number, tokens in rows:
        tokens = _columns("POINTS", number, tokens, 7)
        kind, body_id = _attachment(tokens[1], number)
        xyz = np.array([_number(c, number, t) for c, t in zip("XYZ", tokens[2:5], strict=True)])
        mass, volume = _number("Mass", number, tokens[5]), _number("Volume", number, tokens[6])
        if kind == "body":
            if body_id not in bodies:
                raise InputError(tokens[1], f"line {number}: no body {body_id} in the BODIES section")
            body, pose = bodies[body_id]
            if body is not None:
                points[int(tokens[0])] = system.add_point(xyz, mass=mass, volume=volume, body=body)
                continue
            kind, xyz = "held", pose[:3] + rotation_matrix(*pose[3:]) @ xyz
        p = system.add_point(xyz, fixed=kind in ("fixed", "held"), mass=mass, volume=volume)
        if kind == "held":
            model.held.append(p)
        points[int(tokens[0])] = p
    return points


def _lines(system, rows, types, points, model):
    for number, tokens in rows:
        tokens = _columns("LINES", number, tokens, 5)
        name = tokens[1]
        if name not in types:
            raise InputError(name, f"line {number}: no line type {name!r} in LINE TYPES")
        ends = []
        for column, word in (("AttachA", tokens[2]), ("AttachB", tokens[3])):
            if not word.isdigit():
                raise InputError(
                    word, f"line {number}: {column} {word!r}: a line end at a rod is not supported"
                )
            if int(word) not in points:
                raise InputError(word, f"line {number}: {column} {word}: no such point")
            ends.append(points[int(word)])
        w, EA, d = types[name]
        L = _number("UnstrLen", number, tokens[4])
        try:
            segment = Segment(L, w, EA, diameter=d)
        except InputError as err:
            raise InputError(name, f"line {number}: line type {name!r}: {err}") from None
        system.add_line(Line([segment]), *ends)
        model.line_type_of.append(name)
        model.segments.append(int(_number("NumSegs", number, tokens[5])) if len(tokens) > 5 else 20)


def read_moordyn(path) -> MoorDynModel:
    """Read a MoorDyn v2 input file (module docstring) into a `MoorDynModel` (its ``system``).

    Raises `InputError` naming the file's keyword: an unknown or unsupported section, option or
    attachment, a value that is no number, a missing part."""
    from skcable.mooring.system import MooringSystem

    text = Path(path).read_text(encoding="utf-8")
    sections = _rows(text)
    options = _options(sections.get("OPTIONS", []))
    depth = _option(options, ("wtrdpth", "depth"), None)
    rho = _option(options, ("rho", "rhow", "wtrdnsty"), 1025.0)
    g = _option(options, ("g", "gravity"), 9.80665)
    system = MooringSystem(depth=depth if depth and depth > 0 else None, rho=rho, g=g)
    model = MoorDynModel(system, options=options, header="\n".join(t for _, t in sections[""]))
    model.line_types, types = _line_types(sections["LINE TYPES"], rho, g)
    bodies = _bodies(system, sections.get("BODIES", []), model)
    model.held += [pose for _, (body, pose) in sorted(bodies.items()) if body is None]
    points = _points(system, sections["POINTS"], bodies, model)
    _lines(system, sections["LINES"], types, points, model)
    model.outputs = [" ".join(tokens) for _, tokens in sections.get("OUTPUTS", [])]
    return model


# -- writing ------------------------------------------------------------------------------------------
def _rule(name: str) -> str:
    return f"{'-' * 22} {name} {'-' * max(3, 60 - len(name))}"


def _fmt(value) -> str:
    """The shortest text that reads back as the same float."""
    return repr(float(value))


def _default_columns(segment) -> list[str]:
    """``BA/-zeta EI Cd Ca CdAx CaAx`` of a segment: MoorDyn's usual damping and added mass, the
    segment's drag coefficients where it has them (``Cd`` on the frontal area ``d l`` as
    `skcable.mooring.Segment`'s ``cd_normal``; ``CdAx`` on the surface ``π d l``, so that
    ``CdAx = cd_tangential/π``: MoorDyn's and MoorPy's tangential drag ``½ ρ CdAx π d |u_t| u_t``),
    else MoorDyn's chain defaults (1.6, 0.05)."""
    if segment.cd_normal > 0 or segment.cd_tangential > 0:
        cd, cd_ax = _fmt(segment.cd_normal), _fmt(segment.cd_tangential / math.pi)
    else:
        cd, cd_ax = "1.6", "0.05"
    return ["-1", "0", cd, "1", cd_ax, "0.5"]


class _Writer:
    """The tables of a MoorDyn v2 file from a system (see `write_moordyn`)."""

    def __init__(self, model, num_segs, diameter):
        from skcable.mooring.system import MooringSystem

        self.model = model if isinstance(model, MoorDynModel) else MoorDynModel(model)
        self.system = system = self.model.system
        if not isinstance(system, MooringSystem):
            raise InputError(
                "model", f"must be a MooringSystem or a MoorDynModel, got {type(system).__name__}"
            )
        self.num_segs, self.diameter = num_segs, diameter
        self.types, self.type_rows, self.point_rows, self.line_rows, self.body_rows = {}, [], [], [], []
        self.extra = {p.index: [0.0, 0.0] for p in system.points}  # end-joint mass (kg), volume (m^3)
        self.held = {id(p) for p in self.model.held}

    def type_name(self, segment, hint):
        d = segment.diameter if segment.diameter is not None else self.diameter
        if d is None:
            raise InputError("diameter", f"{segment!r} has no diameter: give Segment(diameter=) or diameter=")
        system = self.system
        mass = segment.w / system.g + system.rho * math.pi / 4.0 * d * d
        key = (segment.w, segment.EA, d, segment.cd_normal, segment.cd_tangential)
        if key not in self.types:
            raw = self.model.line_types.get(hint)
            name = (
                hint if raw is not None and hint not in self.types.values() else f"type{len(self.types) + 1}"
            )
            rest = list(raw[3]) if raw is not None and name == hint else _default_columns(segment)
            EA_text = raw[2] if raw is not None and name == hint else _fmt(segment.EA)
            self.types[key] = name
            self.type_rows.append([name, _fmt(d), _fmt(mass), EA_text, *rest])
        return self.types[key]

    def bodies(self):
        ids: dict[int, object] = {}
        for body in self.system.bodies:
            if body.waterplane_area > 0 or isinstance(body, RigidBody) and np.any(body.metacentre != 0):
                raise InputError(
                    "body", "has a waterplane or a metacentre, which a MoorDyn body does not take"
                )
            q = self.system.start_position(body)
            if isinstance(body, PointBody):
                ids[id(body)] = ("point", body)
                continue
            ids[id(body)] = len(self.body_rows) + 1
            cg = "|".join(_fmt(v) for v in body.center_of_gravity)
            pose = [*q[:3], *np.degrees(q[3:])]
            self.body_rows.append(
                [
                    str(ids[id(body)]),
                    "free",
                    *map(_fmt, pose),
                    _fmt(body.mass),
                    cg,
                    "0",
                    _fmt(body.volume),
                    "0",
                    "0",
                ]
            )
        return ids

    def point_row(self, kind, xyz, mass, volume):
        self.point_rows.append(
            [str(len(self.point_rows) + 1), kind, *map(_fmt, xyz), _fmt(mass), _fmt(volume), "0", "0"]
        )
        return len(self.point_rows)

    def points(self, bodies):
        system, ids, shared = self.system, {}, {}
        for p in system.points:
            if np.any(p.force):
                raise InputError(
                    "points", f"point {p.index} has a constant force, which a MoorDyn point does not take"
                )
            if p.kind == "body" and isinstance(p.body, PointBody):
                if id(p.body) not in shared:
                    start = system.point_position(p)
                    shared[id(p.body)] = self.point_row("Free", start, p.body.mass, p.body.volume)
                ids[p.index] = shared[id(p.body)]
                continue
            kind = {"fixed": "Coupled" if id(p) in self.held else "Fixed", "free": "Free"}.get(p.kind)
            kind = kind or f"Body{bodies[id(p.body)]}"
            ids[p.index] = self.point_row(kind, p.position, p.mass, p.volume)
        return ids

    def lines(self, ids):
        system = self.system
        for k, handle in enumerate(system.mooring_lines):
            line = handle.model
            if not isinstance(line, Line):
                raise InputError(
                    "lines", f"line {k} is a {type(line).__name__}: only mooring.Line is written"
                )
            if line.off_plane is not None:
                raise InputError(
                    "lines",
                    f"line {k}: {line.off_plane[1]}, which a MoorDyn v2 file does not hold with the "
                    "line (its LINE TYPES take one constant EA; a current or a bathymetry goes in files "
                    "of their own): not written",
                )
            a, b = system.point_position(handle.a), system.point_position(handle.b)
            s = line.arrays.s_joint / line.length
            joints = [ids[handle.a.index]]
            for j in range(1, len(line.segments)):
                P = float(line.joint_forces[j])
                mass, volume = (P / system.g, 0.0) if P >= 0 else (0.0, -P / (system.rho * system.g))
                joints.append(self.point_row("Free", a + s[j] * (b - a), mass, volume))
            joints.append(ids[handle.b.index])
            hint = self.model.line_type_of[k] if k < len(self.model.line_type_of) else ""
            segs = self.model.segments[k] if k < len(self.model.segments) else self.num_segs
            for i, segment in enumerate(line.segments):
                name = self.type_name(segment, hint)
                self.line_rows.append(
                    [
                        str(len(self.line_rows) + 1),
                        name,
                        str(joints[i]),
                        str(joints[i + 1]),
                        _fmt(segment.length),
                        str(segs),
                        "-",
                    ]
                )
            for joint, end in ((0, handle.a), (len(line.segments), handle.b)):
                P = float(line.joint_forces[joint])
                if P:
                    self.extra[end.index][0 if P > 0 else 1] += (
                        abs(P) / system.g / (1.0 if P > 0 else system.rho)
                    )

    def end_loads(self, ids):
        for index, (mass, volume) in self.extra.items():
            if mass or volume:
                row = self.point_rows[ids[index] - 1]
                row[5], row[6] = _fmt(float(row[5]) + mass), _fmt(float(row[6]) + volume)


_TYPE_COLUMNS = (
    "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx",
    "(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)",
)
_BODY_COLUMNS = (
    "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*",
    "(#) (word) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)",
)
_POINT_COLUMNS = ("ID Attachment X Y Z Mass Volume CdA Ca", "(#) (word/ID) (m) (m) (m) (kg) (m^3) (m^2) (-)")
_LINE_COLUMNS = (
    "ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs",
    "(#) (name) (ID) (ID) (m) (-) (-)",
)


def _table(name, columns, units, rows) -> list[str]:
    out = [_rule(name), "  ".join(columns.split()), "  ".join(units.split())]
    out += ["  ".join(row) for row in rows]
    return out


def moordyn_text(model, *, num_segs: int = 20, diameter=None, options=None) -> str:
    """The text of the MoorDyn v2 file of a system or a `MoorDynModel` (see `write_moordyn`)."""
    writer = _Writer(model, num_segs, diameter)
    bodies = writer.bodies()
    ids = writer.points(bodies)
    writer.lines(ids)
    writer.end_loads(ids)
    system, model = writer.system, writer.model
    own = ("wtrdpth", "depth", "rho", "rhow", "wtrdnsty", "g", "gravity")
    settings = {k: v for k, v in model.options.items() if k.lower() not in own}
    settings.update({k: str(v) for k, v in (options or {}).items()})
    for key in settings:
        if key.lower() not in OPTIONS:
            raise InputError(key, f"unknown MoorDyn option {key!r}")
    head = [_rule("MoorDyn Input File"), model.header or "written by skcable (quasi-static mooring system)"]
    out = head + _table("LINE TYPES", *_TYPE_COLUMNS, writer.type_rows)
    if writer.body_rows:
        out += _table("BODIES", *_BODY_COLUMNS, writer.body_rows)
    out += _table("POINTS", *_POINT_COLUMNS, writer.point_rows)
    out += _table("LINES", *_LINE_COLUMNS, writer.line_rows)
    out.append(_rule("OPTIONS"))
    if system.depth is not None:
        out.append(f"{_fmt(system.depth)}  WtrDpth  water depth (m)")
    out += [f"{_fmt(system.rho)}  rho  water density (kg/m^3)", f"{_fmt(system.g)}  g  gravity (m/s^2)"]
    out += [f"{value}  {key}" for key, value in settings.items()]
    out += [_rule("OUTPUTS"), *model.outputs, "END", _rule("need this line"), ""]
    return "\n".join(out)


def write_moordyn(model, path, *, num_segs: int = 20, diameter=None, options=None) -> Path:
    """Write a system (or a `MoorDynModel`) as a MoorDyn v2 input file, atomically; returns the path.

    Each `skcable.mooring.Line` segment becomes a MoorDyn line (the joints of a multi-segment line
    free points with its clump weights as mass and its buoys as volume; an attachment at a line's
    end joins its end point), each rigid body a ``free`` body, a point body a free point, a model's
    held points ``Coupled``. ``num_segs``: the lines' ``NumSegs`` (a model's own where it has them).
    ``diameter``: the volume-equivalent diameter (m) of the segments that have none (MoorDyn needs
    one; the mass per length is set so that the weight in water is the segment's). ``options``:
    more MoorDyn options ``{key: value}``. Refuses what MoorDyn does not take: a body with a
    waterplane or a metacentre, a point with a constant force, another line model than
    `skcable.mooring.Line`, a line in a current, on a bathymetry or with a nonlinear axial law, an
    unknown option. A segment's drag coefficients become the type's ``Cd`` and ``CdAx``
    (``cd_tangential/π``: MoorDyn's axial drag acts on the surface ``π d l``)."""
    from skcable.io._atomic import write_text

    return write_text(Path(path), moordyn_text(model, num_segs=num_segs, diameter=diameter, options=options))
