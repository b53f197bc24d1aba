"""``skcable conductor vibration``: aeolian vibration of a catalogue conductor over a frequency
band, from its layer-by-layer bending law to the clamp stress and a fatigue life
(`skcable.conductors.aeolian_vibration`).

`add_vibration` adds the ``vibration`` command to the ``conductor`` command group
(`skcable.cli._conductor`).
"""

from __future__ import annotations

from skcable.cli._args import finite, whole
from skcable.cli._output import print_json, quantities, table

__all__ = ["WIND_MODELS", "add_vibration"]

#: Strouhal number of the band's default: f = S V / D for winds of 1 to 7 m/s.
_STROUHAL, _WINDS = 0.185, (1.0, 7.0)
#: `skcable.conductors.WIND_MODELS`, spelled out so that the parser imports no model (a test
#: checks they agree).
WIND_MODELS = ("cigre", "diana-falco-1971", "rawlins-1983", "brika-laneville-1995")


def _band(args, diameter: float):
    import numpy as np

    from skcable.cli._status import Usage

    low = args.f_min if args.f_min is not None else _STROUHAL * _WINDS[0] / diameter
    high = args.f_max if args.f_max is not None else _STROUHAL * _WINDS[1] / diameter
    if not 0 < low <= high:
        raise Usage(f"--f-min, --f-max: need 0 < f_min <= f_max, got {low:g} and {high:g}")
    return np.linspace(low, high, args.n_frequencies) if high > low else np.array([low])


def _run(args) -> int:
    import numpy as np

    from skcable import conductors, strand
    from skcable.cli._status import EXIT_OK

    s = strand.preset(args.preset)
    f = _band(args, s.diameter)
    hours = None if args.hours_per_year is None else np.full(f.size, args.hours_per_year / f.size)
    result = conductors.aeolian_vibration(
        s, args.tension, f, mu=args.mu, damage=args.damage or None, damping=args.damping, wind=args.wind,
        turbulence=args.turbulence, axis=args.axis - 1, clamp_EI=args.clamp_EI, hours_per_year=hours,
    )  # fmt: skip
    axis = args.axis - 1
    law = result.law
    values = {
        "f_Hz": result.f.tolist(),
        "y_max_m": result.y_max.tolist(),
        "Y_b_peak_to_peak_m": result.Y_b.tolist(),
        "sigma_a_Pa": result.sigma_a.tolist(),
        "cycles_to_failure": result.cycles.tolist(),
        "EI_max_Nm2": float(law.EI_max[axis]),
        "EI_min_Nm2": float(law.EI_min[axis]),
        "knees_per_m": law.kappa_slip[axis].tolist(),
        "kappa_0_per_m": float(law.kappa_0[axis]),
        "mass_kg_per_m": result.mass,
        "diameter_m": result.diameter,
        "EI_clamp_Nm2": result.EI_clamp,
    }
    if result.life_years is not None:
        values["damage_per_year"] = result.damage_per_year
        if result.life_years != float("inf"):
            values["life_years"] = result.life_years
    print_json(values) if args.json else _print(values)
    return EXIT_OK


def _print(values: dict) -> None:
    table(
        [
            ("f [Hz]", values["f_Hz"]),
            ("y_max [m]", values["y_max_m"]),
            ("Y_b p-p [m]", values["Y_b_peak_to_peak_m"]),
            ("sigma_a [Pa]", values["sigma_a_Pa"]),
            ("cycles to failure", values["cycles_to_failure"]),
        ]
    )
    print()
    rows = [
        ("EI_max", values["EI_max_Nm2"], "N·m²  (stick)"),
        ("EI_min", values["EI_min_Nm2"], "N·m²  (full slip)"),
        ("knees", ", ".join(f"{k:.6g}" for k in values["knees_per_m"]), "1/m  (by layer, from the core)"),
        ("kappa_0", values["kappa_0_per_m"], "1/m  (the single-knee equivalent)"),
        ("mass", values["mass_kg_per_m"], "kg/m"),
        ("diameter", values["diameter_m"], "m"),
        ("EI_clamp", values["EI_clamp_Nm2"], "N·m²  (Poffenberger–Swart)"),
    ]
    if "damage_per_year" in values:
        rows.append(("damage", values["damage_per_year"], "per year (Miner, Safe Border Line)"))
    if "life_years" in values:
        rows.append(("life", values["life_years"], "years"))
    quantities(rows)


def add_vibration(conductor_commands, command) -> None:
    """Add ``vibration`` to the ``conductor`` command group (its subparsers)."""
    p = command(
        conductor_commands,
        "vibration",
        _run,
        "aeolian vibration of a catalogue conductor over a frequency band: antinode amplitude where "
        "the wind's power equals the self-damping, clamp stress (Poffenberger–Swart, Y_b peak to "
        "peak at 89 mm) and cycles to failure on the CIGRE Safe Border Line "
        "(skcable.conductors.aeolian_vibration)",
    )
    p.add_argument("--preset", default="acsr-drake", help="catalogue conductor (default: acsr-drake)")
    p.add_argument("--tension", type=finite, required=True, help="conductor tension [N], > 0 (required)")
    p.add_argument(
        "--f-min", type=finite, help="lowest frequency [Hz] (default: 0.185 × 1 m/s / diameter, Strouhal)"
    )
    p.add_argument(
        "--f-max", type=finite, help="highest frequency [Hz] (default: 0.185 × 7 m/s / diameter, Strouhal)"
    )
    p.add_argument("--n-frequencies", type=whole(1), default=40, help="frequencies in the band (default: 40)")
    p.add_argument(
        "--mu", type=finite, default=0.7, help="friction between the wires [-], >= 0 (default: 0.7)"
    )
    p.add_argument("--damage", type=whole(0), default=0, help="broken outer wires, >= 0 (default: 0)")
    p.add_argument(
        "--axis", type=int, choices=(1, 2), default=1, help="principal axis of bending (default: 1)"
    )
    p.add_argument(
        "--damping",
        choices=("model", "foti"),
        default="model",
        help="the conductor's own self-damping or Foti & Martinelli's (default: model)",
    )
    p.add_argument("--wind", choices=WIND_MODELS, default="cigre", help="wind power model (default: cigre)")
    p.add_argument(
        "--turbulence", type=finite, default=0.0, help="turbulence intensity [-], >= 0 (default: 0)"
    )
    p.add_argument(
        "--clamp-EI",
        dest="clamp_EI",
        choices=("min", "max"),
        default="min",
        help="bending stiffness at the clamp: the law's EI_min or EI_max (default: min)",
    )
    p.add_argument(
        "--hours-per-year",
        type=finite,
        help="hours of vibration per year, spread evenly over the band [h]: Miner's damage and the "
        "life (default: none)",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object (default: a table)")
