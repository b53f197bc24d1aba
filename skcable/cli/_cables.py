"""``skcable catenary | parabola | elastic-catenary | funicular``: one cable in closed form."""

from __future__ import annotations

from skcable.cli._args import finite
from skcable.cli._output import output_file, print_json, quantities, table

__all__ = ["register"]

#: The printed fields of a closed form: (attribute, unit, meaning).
_FIELDS = (
    ("H", "N", "horizontal tension"),
    ("V_A", "N", "upward reaction at A"),
    ("V_B", "N", "upward reaction at B"),
    ("T_A", "N", "tension at A"),
    ("T_B", "N", "tension at B"),
    ("length", "m", "cable length"),
    ("sag", "m", "largest vertical chord-cable distance"),
    ("x_low", "m", "x of the lowest point"),
    ("y_low", "m", "y of the lowest point, relative to A"),
)
_WHAT = {
    "catenary": "inextensible catenary from A = (0, 0) to B = (span, dh), given exactly one of "
    "--length, --sag, --H, --low, --T-max",
    "parabola": "parabolic cable (weight per horizontal metre) from A = (0, 0) to B = (span, dh), "
    "given exactly one of --length, --sag, --H, --low, --T-max",
    "elastic-catenary": "elastic (Irvine) catenary from A = (0, 0) to B = (span, dh) given its "
    "unstretched --length",
}


def output_flags(p, what: str = "the cable") -> None:
    """``--vtk``, ``--force`` and ``--json``."""
    p.add_argument(
        "--vtk", metavar="FILE", help=f"also write {what} to this .vtu or .vtk file (default: none)"
    )
    p.add_argument("--force", action="store_true", help="overwrite an existing output file (default: refuse)")
    p.add_argument("--json", action="store_true", help="print one JSON object (default: a table with units)")


def vtk_path(args):
    return output_file("--vtk", args.vtk, args.force) if args.vtk else None


def _closed_form(args) -> int:
    from skcable import cable
    from skcable.cli._status import EXIT_OK

    vtk = vtk_path(args)
    if args.command == "elastic-catenary":
        sol = cable.elastic_catenary(args.span, args.dh, args.w, args.EA, length=args.length)
    else:
        constraint = {k: getattr(args, k) for k in ("length", "sag", "H", "low", "T_max")}
        constraint = {k: v for k, v in constraint.items() if v is not None}
        solver = {"catenary": cable.catenary, "parabola": cable.parabola}[args.command]
        sol = solver(args.span, args.dh, args.w, **constraint)
    values = {k: float(getattr(sol, k)) for k, _, _ in _FIELDS} | {"residual": sol.residual()}
    if vtk:
        values["vtk"] = str(sol.to_vtk(vtk))
    if args.json:
        print_json(values)
        return EXIT_OK
    units = {k: unit for k, unit, _ in _FIELDS} | {"residual": "(largest relative residual)"}
    quantities((k, v, units.get(k, "")) for k, v in values.items())
    return EXIT_OK


def _pairs(name: str, values, width: int = 2):
    import numpy as np

    from skcable.errors import InputError

    if values is None or len(values) % width:
        raise InputError(name, f"needs {width} numbers per entry, got {values!r}")
    return np.reshape(values, (-1, width))


def _funicular(args) -> int:
    import numpy as np

    from skcable import cable
    from skcable.cli._status import EXIT_OK

    vtk = vtk_path(args)
    sol = cable.funicular(args.B, args.lengths, _pairs("loads", args.loads))
    values = {
        "T": sol.T.tolist(),
        "angles_deg": np.degrees(sol.angles).tolist(),
        "nodes": sol.nodes.tolist(),
        "residual": sol.residual(),
    }
    if not np.isfinite(np.concatenate([values["T"], values["angles_deg"], np.ravel(values["nodes"])])).all():
        raise RuntimeError("the funicular polygon came out with a non-finite value")
    if vtk:
        values["vtk"] = str(sol.to_vtk(vtk))
    if args.json:
        print_json(values)
        return EXIT_OK
    n = len(values["T"])
    table([("segment", range(1, n + 1)), ("T [N]", values["T"]), ("angle [deg]", values["angles_deg"])])
    x, y = zip(*values["nodes"], strict=True)
    table([("joint", ["A", *range(1, n), "B"]), ("x [m]", x), ("y [m]", y)])
    written = [("vtk", values["vtk"], "")] if "vtk" in values else []
    quantities([("residual", values["residual"], "(largest relative residual)"), *written])
    return EXIT_OK


def _closed_form_flags(p, name: str) -> None:
    per = "horizontal metre" if name == "parabola" else "metre of cable"
    unstretched = " (unstretched)" if name == "elastic-catenary" else ""
    p.add_argument(
        "--w", type=finite, required=True, help=f"weight per {per}{unstretched} [N/m], > 0 (required)"
    )
    if name == "elastic-catenary":
        p.add_argument("--EA", type=finite, required=True, help="axial stiffness [N], > 0 (required)")
        p.add_argument("--length", type=finite, required=True, help="unstretched length [m] (required)")
        return
    one = "; give exactly one of the five"
    p.add_argument("--length", type=finite, help=f"cable length [m], > chord (default: none{one})")
    p.add_argument("--sag", type=finite, help="largest vertical chord-cable distance [m] (default: none)")
    p.add_argument("--H", type=finite, help="horizontal tension [N] (default: none)")
    p.add_argument(
        "--low", type=finite, help="y of the lowest point relative to A [m], < min(0, dh) (default: none)"
    )
    p.add_argument(
        "--T-max", dest="T_max", type=finite, help="tension at the higher support [N] (default: none)"
    )


def register(sub, command) -> None:
    """The four cable commands."""
    for name, what in _WHAT.items():
        p = command(sub, name, _closed_form, what)
        p.add_argument(
            "--span", type=finite, required=True, help="horizontal distance A-B [m], > 0 (required)"
        )
        p.add_argument("--dh", type=finite, default=0.0, help="height of B above A [m] (default: 0)")
        _closed_form_flags(p, name)
        output_flags(p)
    f = command(sub, "funicular", _funicular, "weightless cable of given segment lengths under joint loads")
    f.add_argument(
        "--B",
        type=finite,
        nargs=2,
        required=True,
        metavar=("X", "Y"),
        help="support B [m], A at (0, 0) (required)",
    )
    f.add_argument(
        "--lengths", type=finite, nargs="+", required=True, help="segment lengths from A to B [m] (required)"
    )
    f.add_argument(
        "--loads", type=finite, nargs="+", required=True, help="Px Py per joint [N], y up (required)"
    )
    output_flags(f, "the polygon")
