"""``skcable line``: a mooring line of one or several segments, with clump weights and buoys,
from the anchor A = (0, 0) to the fairlead B = (span, dh), on a flat seabed with friction or
free (Jonkman 2007)."""

from __future__ import annotations

from typing import Any

from skcable.cli._args import finite
from skcable.cli._cables import output_flags, vtk_path
from skcable.cli._output import print_json, quantities, table

__all__ = ["register"]

#: The printed forces and lengths: (attribute, unit).
_FIELDS = (
    ("H", "N"),
    ("V_B", "N"),
    ("V_A", "N"),
    ("H_A", "N"),
    ("T_B", "N"),
    ("length_on_seabed", "m"),
    ("x_touchdown", "m"),
)
_STIFFNESS = (("k_H_span", "N/m"), ("k_H_dh", "N/m"), ("k_VB_span", "N/m"), ("k_VB_dh", "N/m"))
_SEGMENT = (("T_lower", "N"), ("T_upper", "N"), ("grounded_length", "m"))


def _joint(flag: str, value: float) -> int:
    from skcable.errors import InputError

    if not float(value).is_integer():
        raise InputError(flag, f"takes JOINT FORCE with JOINT a whole number, got {value!r}")
    return int(value)


def _model(args):
    from skcable import mooring
    from skcable.errors import InputError

    n = len(args.length)
    for name in ("w", "EA"):
        if len(getattr(args, name)) not in (1, n):
            raise InputError(
                name, f"takes one value or one per segment ({n}), got {len(getattr(args, name))}"
            )
    w, EA = (v if len(v) == n else v * n for v in (args.w, args.EA))
    segments = [mooring.Segment(*values) for values in zip(args.length, w, EA, strict=True)]
    attachments: list[mooring.ClumpWeight | mooring.Buoy] = [
        mooring.ClumpWeight(_joint("clump", j), f) for j, f in args.clump or ()
    ]
    attachments += [mooring.Buoy(_joint("buoy", j), f) for j, f in args.buoy or ()]
    return mooring.Line(segments, attachments, seabed=args.seabed, friction=args.friction)


def _run(args) -> int:
    """Fairlead and anchor forces, grounded length, 2x2 stiffness, each segment's tensions."""
    import numpy as np

    from skcable.cli._status import EXIT_OK

    vtk = vtk_path(args)
    model = _model(args)
    sol = model.solve(args.span, args.dh)
    k = np.asarray(sol.stiffness(), dtype=float)
    values: dict[str, Any] = {name: float(getattr(sol, name)) for name, _ in _FIELDS}  # JSON's object
    values |= dict(zip((name for name, _ in _STIFFNESS), k.ravel().tolist(), strict=True))
    values["residual"] = sol.residual()
    frame = sol.tensions()
    values |= {f"segment_{c}": [float(v) for v in frame[c]] for c, _ in _SEGMENT}
    if vtk:  # the API's 2-D file: the x-y plane, y up, as every 2-D line (docs/howto.md)
        values["vtk"] = str(sol.to_vtk(vtk))
    if args.json:
        print_json(values)
        return EXIT_OK
    units = dict(_FIELDS + _STIFFNESS) | {"residual": "(largest relative residual)", "vtk": ""}
    quantities((key, values[key], units[key]) for key in units if key in values)
    columns = [(f"{c} [{u}]", values[f"segment_{c}"]) for c, u in _SEGMENT]
    print()
    table([("segment (from A)", range(1, len(frame) + 1)), *columns])
    return EXIT_OK


def register(sub, command) -> None:
    p = command(
        sub,
        "line",
        _run,
        "mooring line of one or several segments, with clump weights and buoys, from the anchor "
        "A = (0, 0) to the fairlead B = (span, dh), optionally on a flat seabed with friction "
        "(Jonkman 2007): fairlead and anchor forces, grounded length, each segment's end tensions "
        "and the 2x2 fairlead stiffness d(H, V_B)/d(span, dh)",
    )
    p.add_argument("--span", type=finite, required=True, help="horizontal distance A-B [m], > 0 (required)")
    p.add_argument("--dh", type=finite, required=True, help="height of B above A [m] (required)")
    per_segment = (
        (
            "--length",
            "unstretched length of each segment from the anchor to the fairlead [m], > 0 (required)",
        ),
        ("--w", "weight in water per unstretched metre [N/m], > 0: one value, or one per segment (required)"),
        ("--EA", "axial stiffness [N], > 0: one value, or one per segment (required)"),
    )
    for flag, text in per_segment:
        p.add_argument(flag, type=finite, nargs="+", required=True, help=text)
    attached = (
        ("--clump", "WEIGHT", "clump weight [N] at a joint (0 the anchor, n the fairlead); repeat for more "
         "(default: none)"),
        ("--buoy", "BUOYANCY", "buoy (net upward force [N]) at a joint; repeat for more (default: none)"),
    )  # fmt: skip
    for flag, what, text in attached:
        p.add_argument(flag, type=finite, nargs=2, action="append", metavar=("JOINT", what), help=text)
    p.add_argument(
        "--seabed",
        type=finite,
        help="height of a flat seabed relative to A [m], <= 0; 0: the anchor on the seabed "
        "(default: none, the line hangs free)",
    )
    p.add_argument(
        "--friction", type=finite, default=0.0, help="seabed friction coefficient [-], >= 0 (default: 0)"
    )
    output_flags(p, "the line")
