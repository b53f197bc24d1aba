"""A mooring system described in a TOML file: line types, bodies, points, lines and loads.

The file (TOML, read with the standard library's ``tomllib``)::

    depth = 200.0                      # m; rho (kg/m^3) and g (m/s^2) too, optional

    [types.chain]                      # a line type: w (N/m in water) and EA (N), mbl, diameter
    w = 2456.82
    EA = 1.2326e9
    [types.rope]                       # or a component of the library at a nominal diameter (m)
    component = "polyester rope"
    diameter = 0.16

    [[bodies]]                         # a RigidBody (kind = "point": a PointBody)
    name = "hull"
    mass = 8.0e6
    volume = 8.2e3
    center_of_gravity = [0, 0, -5]
    metacentre = [0, 0, 10]
    waterplane_area = 600.0
    position = [0, 0, 0, 0, 0, 0]
    force = [2.0e6, 5.0e5, 0.0]        # a steady external force (N) and moment (N m)
    moment = [0, 0, 0]

    [[points]]
    name = "a1"
    position = [800, 0, -200]
    fixed = true                       # or body = "hull" (body axes), or free with mass, volume, force

    [[lines]]
    a = "a1"
    b = "f1"
    segments = [{ type = "chain", length = 850.0 }]
    friction = 0.5                     # optional; clumps = [{ joint = 1, weight = 2e4 }], buoys likewise

Every table and key is checked: an unknown key, a missing one, a name used twice or never
defined is refused by name (`InputError` naming the key or the name).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from skcable.errors import InputError
from skcable.mooring.body import PointBody, RigidBody
from skcable.mooring.library import component
from skcable.mooring.segments import Buoy, ClumpWeight, Line, Segment
from skcable.mooring.system import MooringSystem

__all__ = ["SystemFile", "read_system"]

_TOP = {"depth", "rho", "g", "types", "bodies", "points", "lines"}
_TYPE = {"w", "EA", "mbl", "diameter", "component"}
_BODY = {
    "name",
    "kind",
    "mass",
    "volume",
    "center_of_gravity",
    "metacentre",
    "waterplane_area",
    "position",
    "force",
    "moment",
}
_POINT = {"name", "position", "fixed", "body", "mass", "volume", "force"}
_LINE = {"name", "a", "b", "segments", "friction", "clumps", "buoys"}


@dataclass
class SystemFile:
    """A system read from a TOML file: the ``system``, the external ``force`` and ``moment``
    mappings of `MooringSystem.equilibrium`, and the names of its bodies, points and lines."""

    system: object
    force: dict = field(default_factory=dict)
    moment: dict = field(default_factory=dict)
    bodies: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    lines: dict = field(default_factory=dict)


def _keys(where: str, table, allowed, required=()):
    if not isinstance(table, dict):
        raise InputError(where, f"must be a table, got {type(table).__name__}")
    for key in table:
        if key not in allowed:
            raise InputError(key, f"in {where}: unknown key {key!r} (known: {', '.join(sorted(allowed))})")
    for key in required:
        if key not in table:
            raise InputError(key, f"in {where}: missing")
    return table


def _named(where, items, kind):
    out = {}
    for i, item in enumerate(items):
        name = item.get("name", f"{kind}{i}")
        if name in out:
            raise InputError(name, f"in {where}: the name {name!r} is used twice")
        out[name] = item
    return out


def _types(data) -> dict:
    out: dict[str, tuple] = {}
    for name, spec in data.get("types", {}).items():
        _keys(f"types.{name}", spec, _TYPE)
        if "component" in spec:
            if "diameter" not in spec:
                raise InputError("diameter", f"in types.{name}: a component needs its nominal diameter (m)")
            out[name] = ("component", component(spec["component"]), spec["diameter"])
        else:
            _keys(f"types.{name}", spec, _TYPE, ("w", "EA"))
            out[name] = ("given", spec)
    return out


def _segment(types, where, spec):
    _keys(where, spec, {"type", "length"}, ("type", "length"))
    kind = types.get(spec["type"])
    if kind is None:
        raise InputError(spec["type"], f"in {where}: no line type {spec['type']!r} in [types]")
    if kind[0] == "component":
        return kind[1].segment(spec["length"], kind[2])
    t = kind[1]
    return Segment(spec["length"], t["w"], t["EA"], mbl=t.get("mbl"), diameter=t.get("diameter"))


def _line(types, where, spec):
    segments = [_segment(types, f"{where}.segments", s) for s in spec["segments"]]
    attachments = [
        kind(_keys(f"{where}.{key}", c, {"joint", size}, ("joint", size))["joint"], c[size])
        for key, kind, size in (("clumps", ClumpWeight, "weight"), ("buoys", Buoy, "buoyancy"))
        for c in spec.get(key, [])
    ]
    friction = spec.get("friction", 0.0)
    return Line(segments, attachments, seabed=0.0 if friction else None, friction=friction)


def _bodies(system, data, out):
    for name, spec in _named("bodies", data.get("bodies", []), "body").items():
        _keys(f"bodies.{name}", spec, _BODY)
        own = {k: spec[k] for k in ("mass", "volume", "waterplane_area") if k in spec}
        body: PointBody | RigidBody
        if spec.get("kind", "rigid") == "point":
            body = PointBody(**own)
        elif spec.get("kind", "rigid") == "rigid":
            own |= {k: spec[k] for k in ("center_of_gravity", "metacentre") if k in spec}
            body = RigidBody(**own)
        else:
            raise InputError("kind", f"in bodies.{name}: 'rigid' or 'point', got {spec['kind']!r}")
        out.bodies[name] = system.add_body(body, position=spec.get("position"))
        for key, target in (("force", out.force), ("moment", out.moment)):
            if key in spec:
                target[body] = spec[key]


def _points(system, data, out):
    for name, spec in _named("points", data.get("points", []), "point").items():
        _keys(f"points.{name}", spec, _POINT, ("position",))
        body = spec.get("body")
        if body is not None and body not in out.bodies:
            raise InputError(body, f"in points.{name}: no body {body!r} in [[bodies]]")
        own = {k: spec[k] for k in ("mass", "volume", "force") if k in spec}
        p = system.add_point(
            spec["position"], fixed=spec.get("fixed", False), body=out.bodies.get(body), **own
        )
        out.points[name] = p


def read_system(path) -> SystemFile:
    """Read a mooring system from a TOML file (module docstring); returns a `SystemFile`."""
    import tomllib

    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as err:
        raise InputError("path", f"{path}: not a TOML file: {err}") from None
    _keys("the file", data, _TOP)
    system = MooringSystem(depth=data.get("depth"), rho=data.get("rho", 1025.0), g=data.get("g", 9.81))
    out = SystemFile(system)
    types = _types(data)
    _bodies(system, data, out)
    _points(system, data, out)
    for name, spec in _named("lines", data.get("lines", []), "line").items():
        _keys(f"lines.{name}", spec, _LINE, ("a", "b", "segments"))
        ends = []
        for end in ("a", "b"):
            if spec[end] not in out.points:
                raise InputError(spec[end], f"in lines.{name}: no point {spec[end]!r} in [[points]]")
            ends.append(out.points[spec[end]])
        out.lines[name] = system.add_line(_line(types, f"lines.{name}", spec), *ends)
    return out
