"""Command line of skcable.

``skcable demo`` is the README's main job: the stick and stick–slip capacity
curves of the damaged steel 9.5 mm strand written to ``results/`` (CSV,
VTK for ParaView, PNG). ``skcable seeds`` prints the seeds' worked examples
beside skcable's values; ``catenary``, ``parabola``, ``elastic-catenary``
and ``funicular`` solve one cable; ``strand section`` and ``strand
capacity`` analyse a strand. Every command takes ``--json`` where it
prints numbers. Bad arguments print one line naming the argument and exit
with status 2, with no traceback.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from skcable import cable
from skcable.errors import ConvergenceError, InputError

#: Seed worked examples: (label, published value, function returning ours).
_SEEDS = [
    (
        "000 ex.1 funicular T1 [kN]",
        233.04,
        lambda: cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)]).T[0],
    ),
    (
        "000 ex.2 H [kN]",
        28.511,
        lambda: cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5)).H,
    ),
    ("000 ex.3 parabola H [kN]", 85743.7, lambda: cable.parabola(800, -20, 20, low=-30).H),
    ("000 ex.3 parabola S [m]", 801.408, lambda: cable.parabola(800, -20, 20, low=-30).length),
    ("000 ex.4 catenary H [kN]", 85818.7, lambda: cable.catenary(800, -20, 20, low=-30).H),
    ("000 ex.4 catenary T_A [kN]", 86418.7, lambda: cable.catenary(800, -20, 20, low=-30).T_A),
    ("000 ex.4 catenary S [m]", 801.409, lambda: cable.catenary(800, -20, 20, low=-30).length),
    ("001 ex.4 parabola Tmax [kg]", 269.26, lambda: cable.parabola(200, 0, 1, sag=20).T_max),
    ("001 ex.5 catenary T0 [kg]", 253.2649, lambda: cable.catenary(200, 0, 1, sag=20).H),
    ("001 ex.5 catenary S [m]", 205.2374, lambda: cable.catenary(200, 0, 1, sag=20).length),
]
#: API argument names whose command-line flag is spelled otherwise.
_FLAG_OF = {"n": "--damage", "name": "--preset"}
_CABLE_FIELDS = ("H", "V_A", "V_B", "T_A", "T_B", "length", "sag", "x_low", "y_low")


def _print(values: dict, as_json: bool) -> None:
    if as_json:
        print(json.dumps(values))
        return
    for key, value in values.items():
        shown = f"{value:.10g}" if isinstance(value, float) else str(value)
        print(f"{key:>24s} = {shown}")


# --- cables ---------------------------------------------------------------------
def _seeds(args) -> int:
    print(f"{'seed example':32s} {'published':>12s} {'skcable':>16s} {'rel. diff':>10s}")
    for label, published, compute in _SEEDS:
        ours = float(compute())
        print(f"{label:32s} {published:12.6g} {ours:16.10g} {abs(ours / published - 1):10.1e}")
    print("(000 ex.4: the seed stopped its iteration early; full precision gives H = 85819.2 kN)")
    return 0


def _cable(args) -> int:
    if args.command == "elastic-catenary":
        sol = cable.elastic_catenary(args.span, args.dh, args.w, args.EA, length=args.length)
    else:
        constraint = {k: getattr(args, k) for k in ("length", "sag", "H", "low", "T_max")}
        constraint = {k: v for k, v in constraint.items() if v is not None}
        solver = {"catenary": cable.catenary, "parabola": cable.parabola}[args.command]
        sol = solver(args.span, args.dh, args.w, **constraint)
    values = {k: float(getattr(sol, k)) for k in _CABLE_FIELDS} | {"residual": sol.residual()}
    if args.vtk:
        values["vtk"] = str(sol.to_vtk(args.vtk))
    _print(values, args.json)
    return 0


def _pairs(name: str, values, width: int = 2) -> np.ndarray:
    if values is None or len(values) % width:
        raise InputError(name, f"needs {width} numbers per entry, got {values!r}")
    return np.reshape(values, (-1, width))


def _funicular(args) -> int:
    sol = cable.funicular(args.B, args.lengths, _pairs("loads", args.loads))
    values = {
        "T": sol.T.tolist(),
        "angles_deg": np.degrees(sol.angles).tolist(),
        "nodes": sol.nodes.tolist(),
        "residual": sol.residual(),
    }
    if args.vtk:
        values["vtk"] = str(sol.to_vtk(args.vtk))
    _print(values, args.json)
    return 0


# --- strands --------------------------------------------------------------------
def _strand(args):
    from skcable import strand

    s = strand.preset(args.preset)
    return s.damaged(args.damage) if args.damage else s


def _section(args) -> int:
    section = _strand(args).section()
    values = {
        "area_m2": float(section.area),
        "centroid_y_m": float(section.centroid[0]),
        "centroid_z_m": float(section.centroid[1]),
        "principal_angle_deg": float(np.degrees(section.principal_angle)),
        "EA_N": float(section.EA),
        "EI_stick_1_Nm2": float(section.EI_max[0]),
        "EI_stick_2_Nm2": float(section.EI_max[1]),
        "EI_slip_1_Nm2": float(section.EI_min[0]),
        "EI_slip_2_Nm2": float(section.EI_min[1]),
    }
    _print(values, args.json)
    return 0


def _run_curve(model, label: str, n_steps, progress: bool):
    """Capacity curve with a progress bar (stderr) over the strain schedule."""
    from tqdm import tqdm

    with tqdm(total=100, desc=label, unit="%", disable=not progress, file=sys.stderr, leave=True) as bar:

        def advance(step, done):
            bar.update(round(100 * done) - bar.n)
            bar.set_postfix(strain=f"{step.strain:.4f}", slip=f"{100 * step.slip_fraction:.0f}%")

        curve = model.capacity_curve(n_steps=n_steps, callback=advance)
        bar.update(bar.total - bar.n)  # the curve ends at rupture, before the schedule's end
        return curve


def _summary(curve) -> dict:
    out = {
        "K_Leq_N": curve.K_Leq,
        "elastic_limit": curve.elastic_limit,
        "toughness_N": curve.toughness,
        "ruptured": curve.ruptured,
        "rupture_strain": float(curve.strain[-1]),
        "rupture_force_N": float(curve.force[-1]),
        "max_slip_fraction": float(np.max(curve.slip_fraction)),
    }
    if curve.ruptured:
        out["D_r"] = curve.D_r
    return out


def _write_results(curves: dict, out: Path) -> list[Path]:
    """CSV per curve, VTK time series (strand and wires), and PNG figures."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from skcable import plot

    written = []
    for name, curve in curves.items():
        written.append(curve.to_csv(out / f"{name}.csv"))
        written.extend(curve.to_vtk(out / f"{name}.pvd", wires=True))
        written.append(plot.render_strand(curve, out / f"{name}_wires.png"))
    labels = list(curves)
    for figure, draw in (("capacity", plot.capacity_curves), ("slip_fraction", plot.slip_fraction)):
        ax = draw(list(curves.values()), labels)
        written.append(out / f"{figure}.png")
        ax.figure.savefig(written[-1], dpi=120)
        plt.close(ax.figure)
    for name, curve in curves.items():
        peak = int(np.argmax([np.max(np.abs(s.curvature)) for s in curve.steps]))
        ax = plot.curvature_along(curve, peak)
        written.append(out / f"{name}_curvature.png")
        ax.figure.savefig(written[-1], dpi=120)
        plt.close(ax.figure)
    return written


def _capacity(args) -> int:
    from skcable import strand

    model_kw = dict(
        slip=args.slip,
        mu=args.mu,
        length=args.length,
        n_elements=args.n_elements,
        damage_load=args.damage_load,
    )
    curve = _run_curve(
        strand.StrandModel(_strand(args), **model_kw), args.slip, args.n_steps, not args.no_progress
    )
    values = _summary(curve)
    if args.out:
        name = f"{args.preset}_damage{args.damage}_{args.slip}"
        name += "_sinusoidal" if args.damage_load == "sinusoidal" else ""
        values["written"] = [str(p) for p in _write_results({name: curve}, Path(args.out))]
    _print(values, args.json)
    return 0


def _demo(args) -> int:
    """Stick vs stick–slip capacity of steel 9.5 mm, one broken wire (seed 003 §4.3)."""
    from skcable import strand

    damaged = strand.preset("steel-9.5").damaged(1)
    curves = {}
    for slip in ("none", "axis"):
        label = "stick" if slip == "none" else "stick-slip"
        curves[label] = _run_curve(strand.StrandModel(damaged, slip=slip), label, None, not args.no_progress)
    out = Path(args.out)
    _write_results(curves, out)
    print(f"steel 9.5 mm, one broken wire, 1 m between clamps: results in {out}/")
    print(f"{'model':12s} {'K_Leq [MN]':>11s} {'rupture strain':>15s} {'force [kN]':>11s} {'D_r':>7s}")
    for label, curve in curves.items():
        row = _summary(curve)
        print(
            f"{label:12s} {row['K_Leq_N'] / 1e6:11.4f} {row['rupture_strain']:15.5f} "
            f"{row['rupture_force_N'] / 1e3:11.2f} {row.get('D_r', float('nan')):7.4f}"
        )
    print(
        f"open {out / 'stick-slip.pvd'} in ParaView (Warp By Vector on 'displacement'); figures: {out}/*.png"
    )
    return 0


def _study(args) -> int:
    from skcable import study

    table, output = study.run_file(
        args.path,
        scheduler=args.scheduler,
        executor="serial" if args.serial else "auto",
        n_workers=args.workers,
        progress=not args.no_progress,
        output=args.out,
        cache=args.cache,
    )
    failed = table[table.status != "ok"]
    busy = table.time_s.sum()
    print(f"{len(table)} cases, {len(failed)} failed, {busy:.1f} s of computing; table: {output}")
    for _, row in failed.iterrows():
        print(f"  failed {row.key}: {row.error}")
    return 0


# --- parser ---------------------------------------------------------------------
class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2, no usage dump)."""

    def error(self, message):
        self.exit(2, f"skcable: error: {message}\n")


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="skcable", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command")
    demo = sub.add_parser(
        "demo", help="stick vs stick-slip capacity of a damaged strand, written to results/"
    )
    demo.add_argument("--out", default="results")
    demo.add_argument("--no-progress", action="store_true")
    sub.add_parser("seeds", help="seed worked examples: published values beside skcable's")
    for name in ("catenary", "parabola", "elastic-catenary"):
        p = sub.add_parser(name, help=f"closed-form {name.replace('-', ' ')} (SI units)")
        p.add_argument("--span", type=float, required=True, help="horizontal distance A-B [m]")
        p.add_argument("--dh", type=float, default=0.0, help="height of B above A [m]")
        p.add_argument("--w", type=float, required=True, help="distributed weight [N/m]")
        keys = ("length",) if name == "elastic-catenary" else ("length", "sag", "H", "low", "T_max")
        for key in keys:
            p.add_argument(
                f"--{key.replace('_', '-')}", dest=key, type=float, required=name == "elastic-catenary"
            )
        if name == "elastic-catenary":
            p.add_argument("--EA", type=float, required=True, help="axial stiffness [N]")
        p.add_argument("--vtk", help="also write the profile to this VTK file")
        p.add_argument("--json", action="store_true")
    f = sub.add_parser("funicular", help="weightless cable of given segment lengths under joint loads")
    f.add_argument("--B", type=float, nargs=2, required=True, metavar=("X", "Y"), help="support B [m]")
    f.add_argument("--lengths", type=float, nargs="+", required=True, help="segment lengths A to B [m]")
    f.add_argument("--loads", type=float, nargs="+", required=True, help="Px Py per joint [N], y up")
    f.add_argument("--vtk")
    f.add_argument("--json", action="store_true")
    study = sub.add_parser("study", help="parameter studies on Dask").add_subparsers(dest="study_command")
    st = study.add_parser("run", help="run a study file (TOML) and write its table")
    st.add_argument("path", help="study file, e.g. studies/seed003_tables_4_1_4_2.toml")
    st.add_argument("--scheduler", help="address of a dask.distributed scheduler, e.g. tcp://host:8786")
    st.add_argument("--serial", action="store_true", help="no Dask: one case after the other")
    st.add_argument("--workers", type=int, default=2, help="processes of the local cluster")
    st.add_argument("--out", help="table path (.csv or .parquet), overrides the file's")
    st.add_argument("--cache", help="cache folder, overrides the file's")
    st.add_argument("--no-progress", action="store_true")
    s = sub.add_parser("strand", help="strand sections and capacity curves").add_subparsers(
        dest="strand_command"
    )
    for name in ("section", "capacity"):
        p = s.add_parser(name)
        p.add_argument(
            "--preset", default="steel-9.5", help="steel-9.5, aluminium-10.1, steel-12.7, aluminium-14.3"
        )
        p.add_argument("--damage", type=int, default=0, help="broken outer wires")
        p.add_argument("--json", action="store_true")
    cap = s.choices["capacity"]
    cap.add_argument("--slip", default="axis", choices=("none", "axis", "element"))
    cap.add_argument("--mu", type=float, default=0.5)
    cap.add_argument(
        "--damage-load",
        default="eccentricity",
        choices=("eccentricity", "sinusoidal"),
        help="broken wires as a helical eccentricity, or the thesis's prismatic section + sinusoidal loads",
    )
    cap.add_argument("--length", type=float, default=1.0, help="clamp to clamp [m]")
    cap.add_argument("--n-elements", type=int)
    cap.add_argument("--n-steps", type=int)
    cap.add_argument("--out", help="folder for CSV, VTK and PNG")
    cap.add_argument("--no-progress", action="store_true")
    return parser


def main(argv=None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    commands = {
        "demo": _demo,
        "seeds": _seeds,
        "catenary": _cable,
        "parabola": _cable,
        "elastic-catenary": _cable,
        "funicular": _funicular,
    }
    try:
        if args.command == "strand":
            if args.strand_command is None:
                parser.error("strand: choose 'section' or 'capacity'")
            return {"section": _section, "capacity": _capacity}[args.strand_command](args)
        if args.command == "study":
            if args.study_command is None:
                parser.error("study: choose 'run'")
            return _study(args)
        if args.command is None:
            args = parser.parse_args(["demo"])
        return commands[args.command](args)
    except InputError as exc:
        flag = _FLAG_OF.get(exc.argument)
        message = str(exc) if flag is None else f"{flag}: {str(exc).split(': ', 1)[1]}"
        print(f"skcable: error: {message}", file=sys.stderr)
        return 2
    except ConvergenceError as exc:
        print(f"skcable: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
