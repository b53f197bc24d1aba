"""``skcable change-of-state``: sag and tension of a span in other states (load, temperature,
wind) at the unstressed length of a reference state (`skcable.conductors.change_of_state`)."""

from __future__ import annotations

from skcable.cli._args import finite
from skcable.cli._output import print_json, quantities

__all__ = ["register", "span_flags"]

#: The states' printed fields: (attribute, unit, meaning).
_FIELDS = (
    ("H", "N", "horizontal tension"),
    ("H_plane", "N", "tension component normal to the load in the cable's plane"),
    ("sag", "m", "largest chord-cable distance along the load"),
    ("T_max", "N", "largest tension"),
    ("length", "m", "loaded length at t"),
    ("blowout", "rad", "angle of the resultant load from the vertical"),
)


def _numbers(values):
    """One number as a float, several as an array (the API broadcasts them)."""
    import numpy as np

    return float(values[0]) if len(values) == 1 else np.asarray(values, dtype=float)


def listed(values: dict) -> dict:
    """Arrays as (nested) lists of floats, each checked finite."""
    import numpy as np

    out = {}
    for key, value in values.items():
        array = np.asarray(value)
        if array.dtype.kind == "f" and not np.all(np.isfinite(array)):
            raise RuntimeError(f"{key} came out with a value that is not finite")
        out[key] = array.tolist() if array.ndim else value
    return out


def _print_states(res, values: dict, w0: float, t0: float) -> None:
    """The reference state, then a table per state."""
    import numpy as np

    print(f"reference state (w0 = {w0:g} N/m, t0 = {t0:g} °C):")
    reference = [
        ("L0", values["L0"], "m  unstressed length at t0"),
        ("H0", values["H0"], "N"),
        ("sag0", values["sag0"], "m"),
    ]
    quantities(reference, indent=2)
    shape = np.shape(res.H)
    w, t, wind = (np.ravel(np.broadcast_to(getattr(res, k), shape)) for k in ("w", "t", "wind"))
    columns = {k: np.ravel(values[k]) for k, _, _ in _FIELDS}
    for i in range(len(w)):
        print(f"\nstate {i + 1} of {len(w)}: w = {w[i]:g} N/m, t = {t[i]:g} °C, wind = {wind[i]:g} N/m")
        quantities(
            ((k, float(columns[k][i]), f"{unit}  {meaning}") for k, unit, meaning in _FIELDS), indent=2
        )


def _run(args) -> int:
    from skcable import conductors
    from skcable.cli._status import EXIT_OK

    res = conductors.change_of_state(
        args.span, args.dh, EA=args.EA, alpha=args.alpha, w0=args.w0, t0=args.t0, H0=args.H0,
        sag0=args.sag0, w=_numbers(args.w), t=_numbers(args.t),
        wind=_numbers(args.wind), model=args.model, rtol=args.rtol,
    )  # fmt: skip
    values = {k: getattr(res, k) for k, _, _ in _FIELDS} | {"L0": res.L0, "H0": res.H0, "sag0": res.sag0}
    values = listed(values | {"model": res.model}) | {"reason": res.reason}
    if args.json:
        print_json(values)
    else:
        _print_states(res, values, args.w0, args.t0)
        if args.model == "auto":
            print(f"\nmodel: {res.reason}")
    return EXIT_OK


def span_flags(p) -> None:
    """``--span``, ``--dh`` and ``--EA`` of a conductor's span."""
    p.add_argument("--span", type=finite, required=True, help="horizontal distance A-B [m], > 0 (required)")
    p.add_argument("--dh", type=finite, default=0.0, help="height of B above A [m] (default: 0)")
    p.add_argument("--EA", type=finite, required=True, help="axial stiffness [N], > 0 (required)")


def reference_flags(p) -> None:
    """A conductor's span and its reference state: `span_flags`, ``--alpha``, ``--w0``, ``--t0``
    and ``--H0`` or ``--sag0``."""
    span_flags(p)
    p.add_argument("--alpha", type=finite, required=True, help="thermal expansion [1/K] (required)")
    p.add_argument(
        "--w0", type=finite, required=True, help="reference weight per unstressed length [N/m] (required)"
    )
    p.add_argument("--t0", type=finite, required=True, help="reference temperature [°C] (required)")
    p.add_argument(
        "--H0", type=finite, help="reference horizontal tension [N] (default: none; give --H0 or --sag0)"
    )
    p.add_argument("--sag0", type=finite, help="reference sag [m] (default: none; give --H0 or --sag0)")


def model_flags(p) -> None:
    """``--model`` and ``--rtol`` of a change of state (`skcable.conductors.change_of_state`)."""
    p.add_argument(
        "--model",
        default="catenary",
        choices=("catenary", "parabola", "auto"),
        help="elastic catenary with thermal strain, the classical parabolic cubic, or auto: the parabola "
        "where its estimated error is within --rtol, else the catenary (default: catenary)",
    )
    p.add_argument(
        "--rtol",
        type=finite,
        default=None,
        help="tolerance of --model auto: relative error [-] (default: 1e-3)",
    )


def register(sub, command) -> None:
    cs = command(
        sub,
        "change-of-state",
        _run,
        "sag and tension of a span in other states (load, temperature, wind) at the unstressed length "
        "of a reference state (skcable.conductors.change_of_state)",
    )
    reference_flags(cs)
    cs.add_argument(
        "--w",
        type=finite,
        nargs="+",
        required=True,
        help="weight per unstressed length of the states, ice included [N/m]; several values broadcast "
        "with --t and --wind (required)",
    )
    cs.add_argument(
        "--t", type=finite, nargs="+", required=True, help="temperatures of the states [°C] (required)"
    )
    cs.add_argument(
        "--wind", type=finite, nargs="+", default=[0.0], help="transverse wind per length [N/m] (default: 0)"
    )
    model_flags(cs)
    cs.add_argument("--json", action="store_true", help="print one JSON object (default: a table per state)")
