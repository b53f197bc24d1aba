r"""`write_moordyn`: a system (or a `MoorDynModel`) written as a MoorDyn v2 input file."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from skcable.errors import InputError
from skcable.mooring.body import PointBody, RigidBody
from skcable.mooring.moordyn.model import MoorDynModel
from skcable.mooring.moordyn.options import IGNORED, USED
from skcable.mooring.moordyn.rewrite import float_text, rewritten_text
from skcable.mooring.segments import Line
from skcable.mooring.system import MooringSystem

__all__ = ["moordyn_text", "write_moordyn"]

OPTIONS = frozenset(IGNORED) | frozenset(USED)


# -- writing ------------------------------------------------------------------------------------------
def _rule(name: str) -> str:
    return f"{'-' * 22} {name} {'-' * max(3, 60 - len(name))}"


def _default_columns(segment) -> list[str]:
    """``BA/-zeta EI Cd Ca CdAx CaAx`` of a segment: MoorDyn's usual damping and added mass, the
    segment's drag coefficients where it has them (``Cd`` on the frontal area ``d l`` as
    `skcable.mooring.Segment`'s ``cd_normal``; ``CdAx`` on the surface ``π d l``, so that
    ``CdAx = cd_tangential/π``: MoorDyn's and MoorPy's tangential drag ``½ ρ CdAx π d |u_t| u_t``),
    else MoorDyn's chain defaults (1.6, 0.05)."""
    if segment.cd_normal > 0 or segment.cd_tangential > 0:
        cd, cd_ax = float_text(segment.cd_normal), float_text(segment.cd_tangential / math.pi)
    else:
        cd, cd_ax = "1.6", "0.05"
    return ["-1", "0", cd, "1", cd_ax, "0.5"]


class _Writer:
    """The tables of a MoorDyn v2 file from a system (see `write_moordyn`)."""

    def __init__(self, model, num_segs, diameter, equilibrium=None):
        self.model = model if isinstance(model, MoorDynModel) else MoorDynModel(model)
        self.system = system = self.model.system
        if not isinstance(system, MooringSystem):
            raise InputError(
                "model", f"must be a MooringSystem or a MoorDynModel, got {type(system).__name__}"
            )
        if equilibrium is not None and getattr(equilibrium, "system", None) is not system:
            raise InputError("equilibrium", "must be an equilibrium of the system written")
        q = None if equilibrium is None else equilibrium.position
        self.at = [system.point_position(p, q) for p in system.points]  # each point where it is written
        self.poses = (
            {id(b): s.position for b, s in zip(system.bodies, equilibrium.bodies, strict=True)}
            if q is not None
            else {}
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
            rest = list(raw.rest) if raw is not None and name == hint else _default_columns(segment)
            EA_text = raw.EA if raw is not None and name == hint else float_text(segment.EA)
            self.types[key] = name
            self.type_rows.append([name, float_text(d), float_text(mass), EA_text, *rest])
        return self.types[key]

    def bodies(self):
        ids: dict[int, object] = {}
        for body in self.system.bodies:
            if body.waterplane_area > 0 or isinstance(body, RigidBody) and np.any(body.metacentre != 0):
                raise InputError(
                    "body", "has a waterplane or a metacentre, which a MoorDyn body does not take"
                )
            q = self.poses.get(id(body), self.system.start_position(body))
            if isinstance(body, PointBody):
                ids[id(body)] = ("point", body)
                continue
            ids[id(body)] = len(self.body_rows) + 1
            cg = "|".join(float_text(v) for v in body.center_of_gravity)
            pose = [*q[:3], *np.degrees(q[3:])]
            self.body_rows.append(
                [
                    str(ids[id(body)]),
                    "free",
                    *map(float_text, pose),
                    float_text(body.mass),
                    cg,
                    "0",
                    float_text(body.volume),
                    "0",
                    "0",
                ]
            )
        return ids

    def point_row(self, kind, xyz, mass, volume):
        self.point_rows.append(
            [
                str(len(self.point_rows) + 1),
                kind,
                *map(float_text, xyz),
                float_text(mass),
                float_text(volume),
                "0",
                "0",
            ]
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
                    start = self.at[p.index]
                    shared[id(p.body)] = self.point_row("Free", start, p.body.mass, p.body.volume)
                ids[p.index] = shared[id(p.body)]
                continue
            kind = {"fixed": "Coupled" if id(p) in self.held else "Fixed", "free": "Free"}.get(p.kind)
            kind = kind or f"Body{bodies[id(p.body)]}"
            where = self.at[p.index] if p.kind == "free" else p.position
            ids[p.index] = self.point_row(kind, where, p.mass, p.volume)
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
            a, b = self.at[handle.a.index], self.at[handle.b.index]
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
                        float_text(segment.length),
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
                row[5], row[6] = float_text(float(row[5]) + mass), float_text(float(row[6]) + volume)


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


def moordyn_text(model, *, num_segs: int = 20, diameter=None, options=None, equilibrium=None) -> str:
    """The text of the MoorDyn v2 file of a system or a `MoorDynModel` (see `write_moordyn`)."""
    writer = _Writer(model, num_segs, diameter, equilibrium)
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
        out.append(f"{float_text(system.depth)}  WtrDpth  water depth (m)")
    out += [
        f"{float_text(system.rho)}  rho  water density (kg/m^3)",
        f"{float_text(system.g)}  g  gravity (m/s^2)",
    ]
    out += [f"{value}  {key}" for key, value in settings.items()]
    out += [_rule("OUTPUTS"), *model.outputs, "END", _rule("need this line"), ""]
    return "\n".join(out)


def write_moordyn(model, path, *, equilibrium=None, num_segs: int = 20, diameter=None, options=None) -> Path:
    """Write a system (or a `MoorDynModel`) as a MoorDyn input file, atomically; returns the path.

    A `MoorDynModel` read from a file is written as that file, its free parts where
    ``equilibrium`` (a `skcable.mooring.MooringEquilibrium` of its system) puts them
    (`skcable.mooring.moordyn.rewrite`). A system (or a model built on one) is written as a
    MoorDyn v2 file, its free points and bodies at the ``equilibrium`` where one is given.

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

    if isinstance(model, MoorDynModel) and model.text and options is None:
        return write_text(Path(path), rewritten_text(model, equilibrium))
    text = moordyn_text(model, num_segs=num_segs, diameter=diameter, options=options, equilibrium=equilibrium)
    return write_text(Path(path), text)
