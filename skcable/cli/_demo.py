"""``skcable demo``: stick against stick–slip capacity of the steel 9.5 mm strand with one
broken wire (Pino Vidal 2021, §4.3), written as CSV, VTK for ParaView and PNG figures.

The force curves of the two models lie on top of each other; what slip changes is the
stiffness at small strain. ``stiffness.png`` shows it beside the force: the secant
F/(EA ε) with the fraction of the length in slip and where the strand re-sticks, and the
summary prints both numbers, read from the curves. The wires (``*_wires.png``) and the
curvature along the strand (``*_curvature.png``) of both models are drawn at one strain, `_AT`,
where slip makes them differ (at rupture they look the same)."""

from __future__ import annotations

from skcable.cli._strand import curve_files, mesh_flags

__all__ = ["register"]

_LABELS = {"none": "stick", "axis": "stick-slip"}
#: The figure of the secant stiffness beside the force.
_STIFFNESS = "stiffness.png"
#: The strain at which the summary compares the secant stiffnesses (inside the elastic range).
_AT = 0.002


def _stiffness_figure(curves: dict, out, force: bool):
    """Force and secant stiffness side by side (`skcable.plot`), written into ``out`` whole."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from skcable import plot
    from skcable.cli._output import staged

    fig, (left, right) = plt.subplots(1, 2, figsize=(12.0, 4.2), layout="constrained")
    plot.capacity_curves(curves.values(), list(curves), ax=left)
    plot.secant_stiffness(curves.values(), list(curves), ax=right, at=_AT)
    with staged(out, force) as stage:
        fig.savefig(stage / _STIFFNESS, dpi=120)
    plt.close(fig)
    return out / _STIFFNESS


def _the_point(curves: dict) -> list[str]:
    """What the figure shows, in words, with the curves' own numbers."""

    secants = [
        f"{label} {curve.secant(_AT) / curve.model.EA:.3f}"
        for label, curve in curves.items()
        if curve.strain[-1] >= _AT
    ]
    lines = [f"secant stiffness F/(EA ε) at ε = {_AT:g}: {', '.join(secants)} (slip softens the strand)"]
    slipping = curves["stick-slip"]
    first = 100 * float(slipping.slip_fraction[1])
    cliff = slipping.restick()
    if cliff is None:
        lines.append(f"stick-slip: {first:.0f} % of the length slips at the first step and never re-sticks")
    else:
        before, after = 100 * cliff.fraction_before, 100 * cliff.fraction_after
        lines.append(
            f"stick-slip: {first:.0f} % of the length slips at the first step, {before:.0f} % at ε = "
            f"{cliff.strain_before:.4f} and {after:.0f} % at ε = {cliff.strain_after:.4f}: the critical "
            "curvature κ_m grows with the axial strain (the wires' tension presses them together) and "
            "there passes the curvature the broken wires impose, so the strand re-sticks"
        )
    return lines


def _run(args) -> int:
    from skcable import strand
    from skcable.cli._output import output_dir
    from skcable.cli._status import EXIT_OK
    from skcable.cli._strand import run_curve, stopped, summary, write_staged
    from skcable.errors import ConvergenceError

    out = output_dir("--out", args.out, args.force, [*curve_files(_LABELS.values()), _STIFFNESS])
    damaged = strand.preset("steel-9.5").damaged(1)
    curves = {}
    for slip, label in _LABELS.items():
        model = strand.StrandModel(damaged, slip=slip, n_elements=args.n_elements)
        curves[label] = run_curve(model, label, args.n_steps, not args.no_progress)
        if not curves[label].steps:
            raise ConvergenceError(f"demo, {label}: not one step converged: {curves[label].failure}")
    write_staged(curves, out, args.force, at=_AT)
    _stiffness_figure(curves, out, args.force)
    print(f"steel 9.5 mm, one broken wire, 1 m between clamps: results in {out}/")
    print(f"{'model':12s} {'K_Leq [MN]':>11s} {'last strain':>12s} {'force [kN]':>11s} {'D_r':>7s}")
    problems = []
    for label, curve in curves.items():
        row, missing = summary(curve)
        problems += [f"{label}, {missing}"] if missing else []
        strain, force = float(curve.strain[-1]), float(curve.force[-1])
        d_r = f"{row['D_r']:7.4f}" if "D_r" in row else f"{'-':>7s}"
        print(f"{label:12s} {row['K_Leq_N'] / 1e6:11.4f} {strain:12.5f} {force / 1e3:11.2f} {d_r}")
    for line in _the_point(curves):
        print(line)
    print(
        f"open {out / 'stick-slip.pvd'} in ParaView (Warp By Vector on 'transverse_displacement_m'); "
        f"figures: {out}/*.png ({_STIFFNESS}: the secant stiffness beside the force; the wires and the "
        f"curvatures of both models at ε = {_AT:g})"
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
