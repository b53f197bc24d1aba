"""``skcable strand section`` and ``skcable strand capacity``: a preset strand's section
properties and its force-strain curve to rupture (Pino Vidal 2021, ch. 4)."""

from __future__ import annotations

import math
import sys

from skcable.cli._args import finite, whole
from skcable.cli._output import output_dir, print_json, quantities

__all__ = ["curve_files", "mesh_flags", "register", "run_curve", "stopped", "summary", "write_staged"]

_PRESETS = ("steel-9.5", "aluminium-10.1", "steel-12.7", "aluminium-14.3")
#: The section's printed fields: (key, unit, value of a `skcable.strand.Section`).
_SECTION = (
    ("area_m2", "m²", lambda s: s.area),
    ("centroid_y_m", "m", lambda s: s.centroid[0]),
    ("centroid_z_m", "m", lambda s: s.centroid[1]),
    ("principal_angle_deg", "deg", lambda s: math.degrees(s.principal_angle)),
    ("EA_N", "N", lambda s: s.EA),
    ("EI_stick_1_Nm2", "N·m²", lambda s: s.EI_stick[0]),
    ("EI_stick_2_Nm2", "N·m²", lambda s: s.EI_stick[1]),
    ("EI_slip_1_Nm2", "N·m²", lambda s: s.EI_slip[0]),
    ("EI_slip_2_Nm2", "N·m²", lambda s: s.EI_slip[1]),
)
#: The curve summary's units, by key.
_CURVE_UNITS = {
    "K_Leq_N": "N",
    "elastic_limit": "(strain)",
    "toughness_N": "N (force times strain, to rupture)",
    "rupture_strain": "",
    "last_strain": "",
    "rupture_force_N": "N",
    "last_force_N": "N",
    "max_slip_fraction": "(of the quadrature points)",
    "D_r": "(damage index 1 - U_T/U_T0)",
}
_FIGURES = ("capacity.png", "slip_fraction.png")


def _strand(args):
    from skcable import strand

    s = strand.preset(args.preset)
    return s.damaged(args.damage) if args.damage else s


def _section(args) -> int:
    from skcable.cli._status import EXIT_OK

    section = _strand(args).section()
    values = {key: float(value(section)) for key, _, value in _SECTION}
    print_json(values) if args.json else quantities((key, values[key], unit) for key, unit, _ in _SECTION)
    return EXIT_OK


def run_curve(model, label: str, n_steps, progress: bool):
    """Capacity curve with a progress bar (stderr) over the strain schedule; a step that does
    not converge ends the curve (``failure`` set) instead of raising."""
    from tqdm import tqdm

    with tqdm(total=100, desc=label, unit="%", disable=not progress, file=sys.stderr, leave=True) as bar:

        def advance(step, done):
            bar.update(round(100 * done) - bar.n)
            bar.set_postfix(strain=f"{step.strain:.4f}", slip=f"{100 * step.slip_fraction:.0f}%")

        curve = model.capacity_curve(n_steps=n_steps, callback=advance, on_failure="stop")
        if curve.failure is None:
            bar.update(bar.total - bar.n)  # the curve ends at rupture, before the schedule's end
        return curve


def summary(curve) -> tuple[dict, str | None]:
    """The curve's numbers, and why one of them is missing (None when none is)."""
    import numpy as np

    from skcable.errors import ConvergenceError

    out = {
        "K_Leq_N": curve.K_Leq,
        "elastic_limit": curve.elastic_limit,
        "toughness_N": curve.toughness,
        "ruptured": curve.ruptured,
        "rupture_strain" if curve.ruptured else "last_strain": float(curve.strain[-1]),
        "rupture_force_N" if curve.ruptured else "last_force_N": float(curve.force[-1]),
        "max_slip_fraction": float(np.max(curve.slip_fraction)),
    }
    missing = None
    if curve.ruptured:
        try:
            out["D_r"] = curve.D_r
        except ConvergenceError as exc:
            missing = f"D_r: the intact strand's reference curve did not converge: {exc}"
    return out, missing


def curve_files(names) -> list[str]:
    """Glob patterns of the files `write_staged` writes for curves ``names``."""
    per = ("{}.csv", "{}.pvd", "{}_[0-9][0-9][0-9][0-9].vtu", "{}_wires*", "{}_curvature.png")
    return [*_FIGURES, *(pattern.format(name) for name in names for pattern in per)]


def _nearest_step(curve, strain) -> int:
    """The step of ``curve`` whose strain is nearest ``strain``."""
    import numpy as np

    return int(np.argmin([abs(s.strain - strain) for s in curve.steps]))


def _write_results(curves: dict, out, at: float | None = None) -> list:
    """CSV per curve, VTK time series (strand and wires), and PNG figures, into ``out``: the wires
    and the curvature along the strand at the step nearest the strain ``at`` in every curve (so
    that the models are compared at one strain), else at the last step and at the peak curvature."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from skcable import plot

    written = []
    for name, curve in curves.items():
        written.append(curve.to_csv(out / f"{name}.csv"))
        written.extend(curve.to_vtk(out / f"{name}.pvd", wires=True))
        step = -1 if at is None else _nearest_step(curve, at)
        written.append(plot.render_strand(curve, out / f"{name}_wires.png", step=step))
    labels = list(curves)
    for figure, draw in (("capacity", plot.capacity_curves), ("slip_fraction", plot.slip_fraction)):
        ax = draw(list(curves.values()), labels)
        written.append(out / f"{figure}.png")
        ax.figure.savefig(written[-1], dpi=120)
        plt.close(ax.figure)
    for name, curve in curves.items():
        peak = int(np.argmax([np.max(np.abs(s.curvature)) for s in curve.steps]))
        ax = plot.curvature_along(curve, peak if at is None else _nearest_step(curve, at))
        written.append(out / f"{name}_curvature.png")
        ax.figure.savefig(written[-1], dpi=120)
        plt.close(ax.figure)
    return written


def write_staged(curves: dict, out, force: bool, at: float | None = None) -> list[str]:
    """`_write_results` into a stage inside ``out``, then moved into ``out`` file by file."""
    from pathlib import Path

    from skcable.cli._output import staged

    with staged(out, force) as stage:
        written = _write_results(curves, stage, at)
    return [str(out / Path(p).relative_to(stage)) for p in written]


def stopped(curves: dict, out) -> str | None:
    """The one-line report of the curves that did not reach rupture, or None."""
    failed = [f"{name}: {c.failure}" for name, c in curves.items() if c.failure is not None]
    if not failed:
        return None
    where = f"; the curves up to the last converged step are in {out}/" if out is not None else ""
    return "; ".join(failed) + where


def _name(args) -> str:
    name = f"{args.preset}_damage{args.damage}_{args.slip}"
    return name + ("_sinusoidal" if args.damage_load == "sinusoidal" else "")


def _capacity(args) -> int:
    from skcable import strand
    from skcable.cli._status import EXIT_OK
    from skcable.errors import ConvergenceError

    out = output_dir("--out", args.out, args.force, curve_files([_name(args)])) if args.out else None
    model = strand.StrandModel(
        _strand(args),
        slip=args.slip,
        mu=args.mu,
        length=args.length,
        n_elements=args.n_elements,
        damage_load=args.damage_load,
    )
    curve = run_curve(model, args.slip, args.n_steps, not args.no_progress)
    if not curve.steps:
        raise ConvergenceError(f"strand capacity: not one step converged: {curve.failure}")
    values, missing = summary(curve)
    if out is not None:
        values["written"] = write_staged({_name(args): curve}, out, args.force)
    if args.json:
        print_json(values)
    else:
        rows = [(k, v, _CURVE_UNITS.get(k, "")) for k, v in values.items() if k != "written"]
        quantities(rows)
        for path in values.get("written", ()):
            print(f"wrote {path}")
    problem = stopped({"strand capacity": curve}, out) or missing
    if problem:
        raise ConvergenceError(problem)
    return EXIT_OK


def mesh_flags(p) -> None:
    p.add_argument(
        "--n-elements",
        type=whole(),
        metavar="N",
        help="beam elements along the strand, >= 2 (default: 16 per lay length, at least 64)",
    )
    p.add_argument(
        "--n-steps", type=whole(4), metavar="N", help="strain increments of the schedule, >= 4 (default: 60)"
    )


def _capacity_flags(cap) -> None:
    cap.add_argument(
        "--slip",
        default="axis",
        choices=("none", "axis", "element"),
        help="none: stick (wires bonded); axis: Cardou's law per quadrature point and principal axis; "
        "element: Pino Vidal's (2021) element rule (default: axis)",
    )
    cap.add_argument("--mu", type=finite, default=0.5, help="friction coefficient [-], >= 0 (default: 0.5)")
    cap.add_argument(
        "--damage-load",
        default="eccentricity",
        choices=("eccentricity", "sinusoidal"),
        help="broken wires as a helical eccentricity, or Pino Vidal's (2021) prismatic section + sinusoidal "
        "loads (default: eccentricity)",
    )
    cap.add_argument("--length", type=finite, default=1.0, help="clamp to clamp [m], > 0 (default: 1)")
    mesh_flags(cap)
    cap.add_argument("--out", metavar="DIR", help="folder for CSV, VTK and PNG files (default: none written)")
    cap.add_argument(
        "--force", action="store_true", help="overwrite earlier files in --out (default: refuse)"
    )
    cap.add_argument("--no-progress", action="store_true", help="no progress bar on stderr (default: shown)")


def register(sub, command) -> None:
    s = sub.add_parser("strand", help="strand sections and capacity curves").add_subparsers(
        dest="strand_command", metavar="command"
    )
    section = command(s, "section", _section, "section properties of a preset strand, intact or damaged")
    cap = command(
        s,
        "capacity",
        _capacity,
        "force-strain curve of a preset strand pulled to rupture (Pino Vidal 2021, ch. 4)",
    )
    for p in (section, cap):
        p.add_argument(
            "--preset", default="steel-9.5", help=f"1x7 strand: {', '.join(_PRESETS)} (default: steel-9.5)"
        )
        p.add_argument("--damage", type=whole(), default=0, help="broken outer wires, >= 0 (default: 0)")
        p.add_argument(
            "--json", action="store_true", help="print one JSON object (default: a table with units)"
        )
    _capacity_flags(cap)
