"""The system of a MoorDyn file's rows (`skcable.mooring.moordyn.reader` states what each means)."""

from __future__ import annotations

import math

import numpy as np

from skcable.errors import InputError
from skcable.mooring.body import RigidBody, rotation_matrix
from skcable.mooring.moordyn.linetypes import working_curve
from skcable.mooring.rod import Rod, RodBody, Tie
from skcable.mooring.segments import Line, Segment
from skcable.mooring.system import MooringSystem

__all__ = ["build_system"]

#: A rod's axial stiffness is this many times the file's stiffest line type's EA (or 1e8 times its
#: own weight and buoyancy, whichever is larger), over its length (`skcable.mooring.rod.Rod`).
ROD_STIFFNESS = 1e4


def build_system(source, model, options, depth, records, extras) -> None:
    """Build ``model.system`` from the parsed ``records`` (bodies, rods, points, lines) and
    ``extras`` (turbine positions, Syrope initial tensions, external loads)."""
    bodies, rods, points, lines = records
    ic, loads = extras
    try:
        system = MooringSystem(depth=depth, rho=options.rho, g=options.g)
    except InputError as exc:
        raise source.error(None, exc.argument, str(exc).split(": ", 1)[1]) from None
    model.system = system
    _bodies(source, model, bodies, loads)
    ends = _rod_points(source, model, rods, bodies, loads)
    _points(source, model, points, bodies, loads)
    _lines(source, model, lines, ends, ic)
    _rod_bars(source, model, rods)


def _bodies(source, model, bodies, loads) -> None:
    system = model.system
    for number, record in bodies.items():
        if record.kind in ("free", "coupledpinned"):
            # a body whose pitch starts near ±90°, where its Euler angles are singular, gets axes
            # turned to its start (`BodyRecord.frame`): its start angles zero
            turned = abs(math.cos(record.pose[4])) < 0.5
            if turned:
                record.frame = rotation_matrix(*record.pose[3:])
            body = RigidBody(
                mass=record.mass,
                volume=record.volume,
                center_of_gravity=record.frame @ record.cg,
                rho=system.rho,
                g=system.g,
            )
            position = record.pose.copy()
            if turned:
                position[3:] = 0.0
            record.body = system.add_body(body, position=position, pinned=record.kind == "coupledpinned")
            force = loads.get(("body", number))
            if force is not None:
                system.add_point((0.0, 0.0, 0.0), force=force, body=record.body)
        else:
            model.held.append(record.pose)
        model.bodies[number] = record


def _place(source, model, kind, owner, xyz, bodies, line):
    """``(kind, position, body)`` of a point given ``xyz`` with attachment ``kind`` to ``owner``:
    ``"free"``, ``"fixed"``, ``"held"`` (global position: a turbine's already) or ``"body"`` (body
    axes)."""
    if kind == "body":
        if owner not in bodies:
            raise source.error(line, f"Body{owner}", f"there is no body {owner} in BODIES")
        record = bodies[owner]
        if record.body is not None:
            return "body", record.frame @ np.asarray(xyz, dtype=float), record.body
        return "held", record.to_global(xyz), None
    return {"free": "free", "fixed": "fixed", "coupled": "held", "turbine": "held"}[kind], xyz, None


def _add(model, where, mass=0.0, volume=0.0, force=(0.0, 0.0, 0.0)):
    """Add a point placed by `_place` to the system."""
    kind, xyz, body = where
    system = model.system
    if kind == "body":
        return system.add_point(xyz, mass=mass, volume=volume, force=force, body=body)
    if kind == "free":
        return system.add_point(xyz, mass=mass, volume=volume, force=force)
    p = system.add_point(xyz, fixed=True, mass=mass, volume=volume)
    if kind == "held":
        model.held.append(p)
    return p


def _rod_points(source, model, rods, bodies, loads) -> dict:
    """The end points of each rod, ``{number: (A, B)}``: a rod of zero length is one point; a rod
    held on the ground, a coupled or turbine one or one fixed to a body has its ends placed so (a
    bar between them, `_rod_bars`, where they move with a body); a free rod and one turning about
    its end A (pinned) is a `RodBody`, pinned where the ground, a held body or a turbine holds A,
    tied to a free body's point (`skcable.mooring.rod.Tie`) where the body holds it."""
    ends = {}
    for number, rod in rods.items():
        kind = rod.kind
        base = {"pinned": "fixed", "coupledpinned": "coupled"}.get(kind, kind.replace("pinned", ""))
        force = loads.get(("rod", number), np.zeros(3))
        where_a = _place(source, model, base, rod.owner, rod.a, bodies, rod.line)
        if np.array_equal(rod.a, rod.b):
            ends[number] = (
                _add(model, where_a, force=force if where_a[0] == "free" else (0.0, 0.0, 0.0)),
            ) * 2
        elif kind == "free" or kind.endswith("pinned"):
            ends[number] = _rod_body(source, model, rod, where_a, bodies, force)
        else:
            a = _add(model, where_a)
            ends[number] = (a, _add(model, _place(source, model, base, rod.owner, rod.b, bodies, rod.line)))
        rod.points = ends[number]
        model.rods[number] = rod
    return ends


def _rod_body(source, model, rod, where_a, bodies, force) -> tuple:
    """A rod that turns: a `RodBody` from its ends in global axes, pinned at A where A is held."""
    system = model.system
    kind = rod.kind
    on_body = kind == "bodypinned"
    a = bodies[rod.owner].to_global(rod.a) if on_body else np.asarray(rod.a, dtype=float)
    b = bodies[rod.owner].to_global(rod.b) if on_body else np.asarray(rod.b, dtype=float)
    rod_type = rod.type
    bar = Rod(float(np.linalg.norm(b - a)), rod_type.d, rod_type.mass, rho=system.rho, g=system.g)
    body = RodBody(bar, reference="middle" if kind == "free" else "a")
    held = kind != "free" and where_a[0] != "body"
    system.add_body(body, position=body.start(a, b), pinned=held)
    if held and where_a[0] == "held":
        model.held.append(body)
    A = system.add_point(body.end_a, body=body, force=force)
    B = system.add_point(body.end_b, body=body)
    if where_a[0] == "body":  # pinned to a free body: tied to the body's point
        model.ties.append((_add(model, where_a), A, bar))
    rod.body = body
    return A, B


def _points(source, model, points, bodies, loads) -> None:
    for number, p in points.items():
        where = _place(source, model, p.kind, p.owner, p.xyz, bodies, p.line)
        force = p.force + loads.get(("point", number), np.zeros(3))
        model.points[number] = _add(model, where, p.mass, p.volume, force)


def _segment(source, model, record, ic):
    """``(length, Segment)`` of a line row: its type's weight and axial law (a Syrope rope's working
    curve at its initial largest tension)."""
    kind = model.line_types[record.type]
    system = model.system
    length, law = record.length, kind.law
    if kind.syrope is not None:
        if record.id not in ic:
            raise source.error(
                record.line,
                "SYROPE IC",
                f"line {record.id} is a Syrope rope: give its Tmax0 in a SYROPE IC section",
            )
        tmax, _, row = ic[record.id]
        length, law = working_curve(kind.syrope, tmax, record.length, source, row)
    try:
        return Segment(length, kind.weight(system.rho, system.g), law, diameter=kind.d)
    except InputError as exc:
        raise source.error(
            record.line, exc.argument, f"line type {record.type!r}: {str(exc).split(': ', 1)[1]}"
        ) from None


def _lines(source, model, lines, ends, ic) -> None:
    system = model.system
    for record in lines:
        segment = _segment(source, model, record, ic)
        at = []
        for end in record.ends:
            if end[0] == "point":
                at.append(model.points[end[1]])
            else:
                at.append(ends[end[1]][0 if end[2] == "A" else 1])
        if at[0] is at[1]:
            raise source.error(record.line, "AttachB", "both ends of the line are the same point")
        try:
            handle = system.add_line(Line([segment]), at[0], at[1])
        except InputError as exc:
            raise source.error(record.line, exc.argument, str(exc).split(": ", 1)[1]) from None
        model.lines.append(handle)
        model.line_type_of.append(record.type)
        model.segments.append(record.numsegs)


def _rod_bars(source, model, rods) -> None:
    """A `Rod` between the ends of each rod fixed to a free body (its weight and buoyancy on the
    body's points), and the ties of the rods pinned to one."""
    system = model.system
    stiffest = max((_nominal_EA(t.law) for t in model.line_types.values() if t.law is not None), default=0.0)

    def stiffness(d, mass, length) -> float:
        own = (mass * system.g + system.rho * system.g * np.pi / 4 * d**2) * length
        return max(ROD_STIFFNESS * stiffest, 1e8 * own, 1.0) / length

    for rod in rods.values():
        a, b = rod.points
        if a is b or getattr(rod, "body", None) is not None or a.kind != "body":
            continue
        length = float(np.linalg.norm(rod.b - rod.a))
        k = stiffness(rod.type.d, rod.type.mass, length)
        bar = Rod(length, rod.type.d, rod.type.mass, k, rho=system.rho, g=system.g)
        rod.handle = system.add_line(bar, a, b)
    for host, end, bar in model.ties:
        system.add_line(Tie(stiffness(bar.diameter, bar.mass, bar.length)), host, end)


def _nominal_EA(law) -> float:
    if isinstance(law, float):
        return law
    EA = getattr(law, "EA", None)
    if isinstance(EA, float):
        return EA
    return float(law.secant_EA(np.array(1.0)))
