"""``skcable conductor``: a conductor's sag-tension table (`skcable.conductors.sag_tension_table`),
a tension section's ruling span (`skcable.conductors.ruling_span`), its thermal rating
(`skcable.conductors.ThermalRating`, linerate's IEEE 738 or CIGRE 601 heat balance) and its
aeolian vibration (`skcable.cli._vibration`)."""

from __future__ import annotations

from skcable.cli._args import finite
from skcable.cli._output import print_json, quantities, table
from skcable.cli._status import Usage
from skcable.cli._vibration import add_vibration

__all__ = ["register"]

#: The table's columns: (column, unit).
_COLUMNS = (("w", "N/m"), ("wind", "N/m"), ("H", "N"), ("sag", "m"), ("T_max", "N"), ("length", "m"))


def _table(args) -> int:
    import numpy as np

    from skcable import conductors
    from skcable.cli._status import EXIT_OK

    cases = {"bare": (args.w0, 0.0)} if not args.case else {}
    for name, w, wind in args.case or ():
        if name in cases:
            raise Usage(f"conductor table: --case {name} given twice")
        try:
            cases[name] = (float(w), float(wind))
        except ValueError:
            raise Usage(
                f"--case: give NAME W WIND (two numbers after the name), got {name} {w} {wind}"
            ) from None
    frame = conductors.sag_tension_table(
        args.span, args.dh, EA=args.EA, alpha=args.alpha, w0=args.w0, t0=args.t0, H0=args.H0,
        sag0=args.sag0, temperatures=args.temperatures, load_cases=cases, model=args.model, rtol=args.rtol,
    )  # fmt: skip
    rows = [(str(case), float(t)) for case, t in frame.index]
    if args.json:
        out = {"case": [r[0] for r in rows], "t": [r[1] for r in rows]}
        out |= {name: [float(v) for v in frame[name]] for name, _ in _COLUMNS}
        out |= {"model": np.asarray(frame.attrs["model"]).tolist(), "reason": frame.attrs["reason"]}
        print_json(out)
        return EXIT_OK
    columns: list[tuple[str, list]] = [("case", [r[0] for r in rows]), ("t [°C]", [r[1] for r in rows])]
    columns += [(f"{name} [{unit}]", [float(v) for v in frame[name]]) for name, unit in _COLUMNS]
    table(columns)
    if args.model == "auto":
        print(f"model: {frame.attrs['reason']}")
    return EXIT_OK


def _ruling(args) -> int:
    import numpy as np

    from skcable import conductors
    from skcable.cli._status import EXIT_OK

    spans = np.asarray(args.spans, dtype=float)
    value = float(conductors.ruling_span(spans))
    if args.json:
        print_json({"ruling_span": value, "spans": spans.tolist()})
    else:
        quantities([("ruling_span", value, "m  sqrt(sum L^3 / sum L) of the section's spans")])
    return EXIT_OK


def _rating(args) -> int:
    import numpy as np

    from skcable import conductors
    from skcable.cli._status import EXIT_OK

    try:
        import linerate
    except ImportError:
        raise Usage("conductor rating: needs linerate: pip install 'skcable[rating]'") from None
    (t1, r1), (t2, r2) = args.resistance[:2], args.resistance[2:]
    wire = linerate.Conductor(
        core_diameter=args.core_diameter, conductor_diameter=args.diameter,
        outer_layer_strand_diameter=args.strand_diameter, emissivity=args.emissivity,
        solar_absorptivity=args.absorptivity, temperature1=t1, temperature2=t2,
        resistance_at_temperature1=r1, resistance_at_temperature2=r2,
        aluminium_cross_section_area=float("nan"), constant_magnetic_effect=1.0,
        current_density_proportional_magnetic_effect=0.0, max_magnetic_core_relative_resistance_increase=1.0,
    )  # fmt: skip
    half = 0.5 * args.span / 111_320.0  # degrees of latitude either side: the span runs north-south
    towers = [
        linerate.Tower(latitude=args.latitude + d, longitude=0.0, altitude=args.altitude)
        for d in (-half, half)
    ]
    span = linerate.Span(conductor=wire, start_tower=towers[0], end_tower=towers[1], num_conductors=1)
    weather = linerate.Weather(
        air_temperature=args.air_temperature, wind_direction=np.radians(args.wind_direction),
        wind_speed=args.wind_speed, ground_albedo=args.albedo, clearness_ratio=args.clearness,
    )  # fmt: skip
    try:
        when = np.datetime64(args.time)
    except ValueError:
        raise Usage(f"--time: give a date and time as 2016-10-03T14:00, got {args.time!r}") from None
    rating = conductors.ThermalRating(span, weather, when, standard=args.standard)
    values = {}
    if args.current is not None:
        values["temperature"] = float(rating.temperature(args.current))
    if args.max_temperature is not None:
        values["ampacity"] = float(rating.ampacity(args.max_temperature))
    if args.json:
        print_json(values)
    else:
        units = {
            "temperature": "°C  steady state at --current",
            "ampacity": "A  steady state at --max-temperature",
        }
        quantities([(k, v, units[k]) for k, v in values.items()])
    return EXIT_OK


def _table_flags(p) -> None:
    from skcable.cli._state import model_flags, reference_flags

    reference_flags(p)
    p.add_argument(
        "--temperatures",
        type=finite,
        nargs="+",
        required=True,
        help="the table's temperatures [°C] (required)",
    )
    p.add_argument(
        "--case", nargs=3, action="append", metavar=("NAME", "W", "WIND"),
        help="a load case: its name, weight per length with ice [N/m] and transverse wind [N/m]; "
        "repeat for more (default: one case 'bare', W = --w0, no wind)",
    )  # fmt: skip
    model_flags(p)


def _rating_flags(p) -> None:
    p.add_argument("--span", type=finite, default=400.0, help="span length [m] (default: 400)")
    p.add_argument("--diameter", type=finite, required=True, help="conductor diameter [m] (required)")
    p.add_argument("--core-diameter", type=finite, default=0.0, help="steel core diameter [m] (default: 0)")
    p.add_argument(
        "--strand-diameter", type=finite, required=True, help="outer layer's wire diameter [m] (required)"
    )
    p.add_argument(
        "--resistance", type=finite, nargs=4, required=True, metavar=("T1", "R1", "T2", "R2"),
        help="AC resistance per length at two temperatures [°C, ohm/m, °C, ohm/m] (required)",
    )  # fmt: skip
    p.add_argument("--emissivity", type=finite, default=0.8, help="[-] (default: 0.8)")
    p.add_argument("--absorptivity", type=finite, default=0.8, help="solar absorptivity [-] (default: 0.8)")
    p.add_argument("--air-temperature", type=finite, required=True, help="[°C] (required)")
    p.add_argument("--wind-speed", type=finite, required=True, help="[m/s] (required)")
    p.add_argument(
        "--wind-direction", type=finite, default=90.0,
        help="angle between the wind and the span (north-south) [deg] (default: 90, across)",
    )  # fmt: skip
    p.add_argument("--albedo", type=finite, default=0.1, help="ground albedo [-] (default: 0.1)")
    p.add_argument("--clearness", type=finite, default=0.5, help="clearness ratio [-] (default: 0.5)")
    p.add_argument("--latitude", type=finite, default=50.0, help="[deg] (default: 50)")
    p.add_argument("--altitude", type=finite, default=0.0, help="[m] (default: 0)")
    p.add_argument(
        "--time",
        default="2016-06-21T12:00",
        help="date and time, the sun's position (default: 2016-06-21T12:00)",
    )
    p.add_argument(
        "--standard", default="ieee738", choices=("ieee738", "cigre601"), help="(default: ieee738)"
    )
    p.add_argument(
        "--current", type=finite, help="current [A]: print the steady-state temperature (default: none)"
    )
    p.add_argument(
        "--max-temperature",
        type=finite,
        help="highest conductor temperature [°C]: print the steady-state ampacity (default: none)",
    )


def register(sub, command) -> None:
    group = sub.add_parser(
        "conductor", help="a conductor's sag-tension table, ruling span, rating and aeolian vibration"
    )
    c = group.add_subparsers(dest="conductor_command", metavar="command")
    t = command(c, "table", _table, "sag-tension table over load cases and temperatures "
                "(skcable.conductors.sag_tension_table)")  # fmt: skip
    _table_flags(t)
    r = command(
        c, "ruling-span", _ruling, "ruling span of a tension section (skcable.conductors.ruling_span)"
    )
    r.add_argument(
        "--spans", type=finite, nargs="+", required=True, help="the section's span lengths [m] (required)"
    )
    a = command(c, "rating", _rating, "steady-state temperature at a current, or ampacity at a temperature "
                "(skcable.conductors.ThermalRating, linerate; pip install 'skcable[rating]')")  # fmt: skip
    _rating_flags(a)
    for p in (t, r, a):
        p.add_argument(
            "--json", action="store_true", help="print one JSON object (default: a table with units)"
        )
    add_vibration(c, command)
