"""``skcable frequencies``: in-plane and out-of-plane natural frequencies and mode shapes of
a sagging cable (Irvine's linear theory on finite elements; `skcable.conductors.natural_frequencies`)."""

from __future__ import annotations

from skcable.cli._args import finite, whole
from skcable.cli._output import print_json, quantities, table
from skcable.cli._state import listed, span_flags

__all__ = ["register"]


def _print(values: dict) -> None:
    n = len(values["f_in_plane"])
    symmetric = ["symmetric" if s else "antisymmetric" for s in values["in_plane_symmetric"]]
    table(
        [
            ("mode", range(1, n + 1)),
            ("in-plane f [Hz]", values["f_in_plane"]),
            ("in-plane shape", symmetric),
            ("Irvine in-plane [Hz]", values["irvine_in_plane"]),
            ("out-of-plane f [Hz]", values["f_out_of_plane"]),
            ("Irvine out-of-plane [Hz]", values["irvine_out_of_plane"]),
        ]
    )
    print()
    quantities(
        [
            ("H", values["H"], "N  horizontal tension"),
            ("sag", values["sag"], "m"),
            ("L_e", values["L_e"], "m  Irvine's effective length"),
            ("lambda2", values["lambda2"], "(Irvine's parameter λ²)"),
            *([("vtk", values["vtk"], "")] if "vtk" in values else []),
        ]
    )


def _run(args) -> int:
    from skcable import conductors
    from skcable.cli._output import output_file
    from skcable.cli._status import EXIT_OK

    vtk = output_file("--vtk", args.vtk, args.force) if args.vtk else None
    res = conductors.natural_frequencies(
        args.span, args.dh, args.w, args.EA, H=args.H, sag=args.sag, n_modes=args.n_modes, g=args.g
    )
    values = {
        "f_in_plane": res.f_in_plane,
        "f_out_of_plane": res.f_out_of_plane,
        "in_plane_symmetric": [bool(b) for b in res.in_plane_symmetric],
        "H": res.H,
        "sag": res.sag,
        "L_e": res.L_e,
        "lambda2": res.lambda2,
        "irvine_in_plane": res.irvine["in_plane"],
        "irvine_out_of_plane": res.irvine["out_of_plane"],
    }
    values = listed(values)
    if vtk:
        from skcable.io import write_mode_shapes

        values["vtk"] = str(write_mode_shapes(res, vtk))
    print_json(values) if args.json else _print(values)
    return EXIT_OK


def register(sub, command) -> None:
    fr = command(
        sub,
        "frequencies",
        _run,
        "in-plane and out-of-plane natural frequencies and mode shapes of a sagging cable (Irvine's "
        "linear theory on finite elements; skcable.conductors.natural_frequencies)",
    )
    span_flags(fr)
    fr.add_argument("--w", type=finite, required=True, help="weight per metre of cable [N/m], > 0 (required)")
    fr.add_argument("--H", type=finite, help="horizontal tension [N] (default: none; give --H or --sag)")
    fr.add_argument("--sag", type=finite, help="sag [m] (default: none; give --H or --sag)")
    fr.add_argument("--n-modes", type=whole(1), default=6, help="modes per family, 1 to 60 (default: 6)")
    fr.add_argument("--g", type=finite, default=9.81, help="gravity [m/s²], > 0 (default: 9.81)")
    fr.add_argument(
        "--vtk", metavar="FILE", help="also write the mode shapes to this .vtu or .vtk file (default: none)"
    )
    fr.add_argument("--force", action="store_true", help="overwrite an existing --vtk file (default: refuse)")
    fr.add_argument("--json", action="store_true", help="print one JSON object (default: a table per mode)")
