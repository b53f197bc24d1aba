"""``skcable mooring FILE``: the equilibrium of a mooring system from a MoorDyn input file or a
TOML system file (`skcable.mooring.system_file`): the bodies' and free points' positions, each
line's end tensions and model, the anchor loads and uplift, and the bodies' stiffness."""

from __future__ import annotations

from skcable.cli._cables import output_flags, vtk_path
from skcable.cli._output import print_json, quantities, table
from skcable.errors import ConvergenceError

__all__ = ["register"]


def _solve(args):
    """``(equilibrium, notes)`` of a TOML system file (``.toml``) or a MoorDyn file (any other):
    the TOML file's loads applied; a MoorDyn file's system as `MoorDynModel.equilibrium` solves it
    (its ``notes``: what the statics leave aside, the neutral directions held)."""
    from pathlib import Path

    from skcable import mooring
    from skcable.errors import InputError
    from skcable.mooring.system_file import read_system

    path = args.file
    if not Path(path).is_file():
        raise InputError("FILE", f"{path!r} is no file")
    if Path(path).suffix.lower() == ".toml":
        described = read_system(path)
        system: mooring.MooringSystem = described.system  # type: ignore[assignment]
        return system.equilibrium(force=described.force, moment=described.moment), {}
    turbines = {k + 1: xyz for k, xyz in enumerate(args.turbine)} if args.turbine else None
    model = mooring.read_moordyn(path, turbines=turbines)
    eq = model.equilibrium()
    return eq, {"ignored": dict(model.ignored), "neutral": list(eq.neutral)}


def _values(eq) -> dict:
    """The numbers of an equilibrium, as lists (JSON-ready)."""
    anchors, lines = eq.anchor_loads(), eq.line_checks()
    values = {
        "iterations": len(eq.history) - 1,
        "stable": bool(eq.stable),
        "bodies": [[float(v) for v in b.position] for b in eq.bodies],
        "free_points": {str(p.index): [float(v) for v in p.position] for p in eq.points if p.kind == "free"},
        "lines": [
            {
                "line": int(r.line),
                "model": str(r.model),
                "T_a": float(r.T_a),
                "T_b": float(r.T_b),
                "grounded_length": float(r.grounded_length),
                "lower_angle_deg": float(r.lower_angle_deg),
            }
            for r in lines.itertuples()
        ],
        "anchors": [
            {
                "point": int(r.point),
                "horizontal": float(r.horizontal),
                "vertical": float(r.vertical),
                "uplift_angle_deg": float(r.uplift_angle_deg),
            }
            for r in anchors.itertuples()
        ],
    }
    if eq.bodies:
        try:
            values["stiffness"] = eq.stiffness(condensed=True).tolist()
        except ConvergenceError:  # free points that nothing holds alone (a neutral direction)
            values["stiffness"] = None
    return values


def _print(values) -> None:
    names = ("x [m]", "y [m]", "z [m]", "roll [rad]", "pitch [rad]", "yaw [rad]")
    rows = [("iterations", values["iterations"], ""), ("stable", values["stable"], "")]
    for i, q in enumerate(values["bodies"]):
        rows += [
            (f"body {i} {name.split()[0]}", v, name.split()[1][1:-1])
            for name, v in zip(names, q, strict=False)
        ]
    for j, xyz in values["free_points"].items():
        rows += [(f"point {j} {axis}", v, "m") for axis, v in zip("xyz", xyz, strict=True)]
    quantities(rows)
    lines = values["lines"]
    print()
    table(
        [
            ("line", [r["line"] for r in lines]),
            ("model", [r["model"] for r in lines]),
            ("T_a [N]", [r["T_a"] for r in lines]),
            ("T_b [N]", [r["T_b"] for r in lines]),
            ("grounded [m]", [r["grounded_length"] for r in lines]),
            ("angle at lower end [deg]", [r["lower_angle_deg"] for r in lines]),
        ]
    )
    if values["anchors"]:
        a = values["anchors"]
        print()
        columns = [
            ("anchor (point)", "point"),
            ("horizontal [N]", "horizontal"),
            ("vertical [N]", "vertical"),
            ("uplift [deg]", "uplift_angle_deg"),
        ]
        table([(header, [r[key] for r in a]) for header, key in columns])
    if values.get("stiffness") is not None:
        print("\nstiffness of the bodies, free points condensed out (N/m, N/rad, N m/rad):")
        for row in values["stiffness"]:
            print("  " + " ".join(f"{k:12.5e}" for k in row))
    for what in values.get("neutral", ()):
        print(f"\nneutral (nothing acts along it: held where the file starts it): {what}")
    if values.get("ignored"):
        print("\nleft aside by the statics:")
        for name, why in values["ignored"].items():
            print(f"  {name}: {why}")


def _run(args) -> int:
    """Solve the file's system at equilibrium under its loads; print or write what it gives."""
    from skcable.cli._status import EXIT_OK

    vtk = vtk_path(args)
    eq, notes = _solve(args)
    values = _values(eq)
    values.update(notes)
    if vtk:
        values["vtk"] = str(eq.to_vtk(vtk))
    if args.json:
        print_json(values)
    else:
        _print(values)
    return EXIT_OK


def register(sub, command) -> None:
    p = command(
        sub,
        "mooring",
        _run,
        "equilibrium of a mooring system (bodies, points, lines) read from a MoorDyn v2 input file or a "
        "TOML system file (.toml): positions, each line's end tensions and model, anchor loads and "
        "uplift, the bodies' stiffness",
    )
    p.add_argument("file", metavar="FILE", help="a MoorDyn input file (v1 or v2), or a .toml system file")
    p.add_argument(
        "--turbine",
        nargs=3,
        type=float,
        action="append",
        metavar=("X", "Y", "Z"),
        help="a FAST.Farm turbine's position (m), turbine 1 first, for a farm-level MoorDyn file's Turbine# "
        "attachments (repeat for each turbine) (default: none)",
    )
    output_flags(p, "the system (lines, seabed, bodies, free points)")
