"""``skcable demo``: stick against stick–slip capacity of the steel 9.5 mm strand with one
broken wire (Pino Vidal 2021, §4.3), written as CSV, VTK for ParaView and PNG figures."""

from __future__ import annotations

from skcable.cli._strand import curve_files, mesh_flags

__all__ = ["register"]

_LABELS = {"none": "stick", "axis": "stick-slip"}


def _run(args) -> int:
    from skcable import strand
    from skcable.cli._output import output_dir
    from skcable.cli._status import EXIT_OK
    from skcable.cli._strand import run_curve, stopped, summary, write_staged
    from skcable.errors import ConvergenceError

    out = output_dir("--out", args.out, args.force, curve_files(_LABELS.values()))
    damaged = strand.preset("steel-9.5").damaged(1)
    curves = {}
    for slip, label in _LABELS.items():
        model = strand.StrandModel(damaged, slip=slip, n_elements=args.n_elements)
        curves[label] = run_curve(model, label, args.n_steps, not args.no_progress)
        if not curves[label].steps:
            raise ConvergenceError(f"demo, {label}: not one step converged: {curves[label].failure}")
    write_staged(curves, out, args.force)
    print(f"steel 9.5 mm, one broken wire, 1 m between clamps: results in {out}/")
    print(f"{'model':12s} {'K_Leq [MN]':>11s} {'last strain':>12s} {'force [kN]':>11s} {'D_r':>7s}")
    problems = []
    for label, curve in curves.items():
        row, missing = summary(curve)
        problems += [f"{label}, {missing}"] if missing else []
        strain, force = float(curve.strain[-1]), float(curve.force[-1])
        d_r = f"{row['D_r']:7.4f}" if "D_r" in row else f"{'-':>7s}"
        print(f"{label:12s} {row['K_Leq_N'] / 1e6:11.4f} {strain:12.5f} {force / 1e3:11.2f} {d_r}")
    print(
        f"open {out / 'stick-slip.pvd'} in ParaView (Warp By Vector on 'transverse_displacement_m'); "
        f"figures: {out}/*.png"
    )
    problem = "; ".join(filter(None, [stopped(curves, out), *problems]))
    if problem:
        raise ConvergenceError(problem)
    return EXIT_OK


def register(sub, command) -> None:
    demo = command(
        sub,
        "demo",
        _run,
        "stick vs stick-slip capacity curves of the steel 9.5 mm strand with one broken wire "
        "(Pino Vidal 2021, §4.3): CSV, VTK for ParaView and PNG figures in --out",
    )
    demo.add_argument(
        "--out", default="results", metavar="DIR", help="folder of the results (default: results)"
    )
    demo.add_argument(
        "--force", action="store_true", help="overwrite earlier results in --out (default: refuse)"
    )
    mesh_flags(demo)
    demo.add_argument(
        "--no-progress", action="store_true", help="no progress bars on stderr (default: shown)"
    )
