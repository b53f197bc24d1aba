"""Command line of skcable.

``skcable demo`` is the README's main job: the stick and stick–slip capacity
curves of the damaged steel 9.5 mm strand written to ``results/`` (CSV,
VTK for ParaView, PNG). ``skcable examples`` (also ``seeds``) prints the
worked examples of the sources beside skcable's values; ``catenary``,
``parabola``, ``elastic-catenary`` and ``funicular`` solve one cable;
``line`` one mooring line (segments, clump weights, buoys, seabed and
friction); ``change-of-state`` and ``frequencies`` a conductor's span;
``strand section`` and ``strand capacity`` analyse a strand; ``study run``
runs a study file. Every command takes ``--json`` where it prints numbers.

Errors are one line on stderr naming the flag, never a traceback; the exit
status says what happened (`EXIT_STATUS`, also in ``skcable --help``).
Output paths are checked before computing and files are written atomically.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import shutil
import sys
import tempfile
import warnings
from pathlib import Path

import numpy as np

from skcable import __version__, cable
from skcable.errors import ConvergenceError, InputError
from skcable.io._atomic import atomic_path, writable_dir, writable_file

EXIT_OK, EXIT_CASES_FAILED, EXIT_USAGE, EXIT_NO_CONVERGENCE, EXIT_ERROR, EXIT_INTERRUPTED = 0, 1, 2, 3, 4, 130
#: Exit statuses of ``skcable``.
EXIT_STATUS = {
    EXIT_OK: "done",
    EXIT_CASES_FAILED: "a study ran but some of its cases failed (listed; the table says why)",
    EXIT_USAGE: "bad usage: a bad flag, value or study file, an output path that cannot be written "
    "(all checked before computing), or no command (the help is printed)",
    EXIT_NO_CONVERGENCE: "a computation did not converge; what converged is printed and written",
    EXIT_ERROR: "a file could not be written, or an unexpected error (a bug: please report it)",
    EXIT_INTERRUPTED: "interrupted (Ctrl-C); a study's finished cases stay in its cache",
}

_NOTES = 'the lecture notes "Cables"'
_GOICOLEA = 'J.M. Goicolea, "Cálculo de cables", UPM, 2012'
_PINO_VIDAL = 'S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico", Universidad de Chile, 2021'

#: Worked examples of the sources: (source, label, published value, function returning ours).
_EXAMPLES = [
    (
        _NOTES,
        "ex. 1 funicular T1 [kN]",
        233.04,
        lambda: cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)]).T[0],
    ),
    (
        _NOTES,
        "ex. 2 funicular H [kN]",
        28.511,
        lambda: cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5)).H,
    ),
    (_NOTES, "ex. 3 parabola H [kN]", 85743.7, lambda: cable.parabola(800, -20, 20, low=-30).H),
    (_NOTES, "ex. 3 parabola S [m]", 801.408, lambda: cable.parabola(800, -20, 20, low=-30).length),
    (_NOTES, "ex. 4 catenary H [kN]", 85818.7, lambda: cable.catenary(800, -20, 20, low=-30).H),
    (_NOTES, "ex. 4 catenary T_A [kN]", 86418.7, lambda: cable.catenary(800, -20, 20, low=-30).T_A),
    (_NOTES, "ex. 4 catenary S [m]", 801.409, lambda: cable.catenary(800, -20, 20, low=-30).length),
    (_GOICOLEA, "ex. 4 parabola Tmax [kg]", 269.26, lambda: cable.parabola(200, 0, 1, sag=20).T_max),
    (_GOICOLEA, "ex. 5 catenary T0 [kg]", 253.2649, lambda: cable.catenary(200, 0, 1, sag=20).H),
    (_GOICOLEA, "ex. 5 catenary S [m]", 205.2374, lambda: cable.catenary(200, 0, 1, sag=20).length),
]
#: Library argument names whose flag is spelled otherwise.
_FLAG_OF = {"n": "damage", "name": "preset", "n_workers": "workers"}
_CABLE_FIELDS = ("H", "V_A", "V_B", "T_A", "T_B", "length", "sag", "x_low", "y_low")
_PRESETS = ("steel-9.5", "aluminium-10.1", "steel-12.7", "aluminium-14.3")
_VTK_SUFFIXES = (".vtu", ".vtk")


class _Usage(Exception):
    """A usage error whose message is complete (exit status 2)."""


def _print(values: dict, as_json: bool) -> None:
    for key, value in values.items():
        if isinstance(value, float) and not math.isfinite(value):
            raise RuntimeError(f"{key} came out as {value}, not a finite number")
    if as_json:
        print(json.dumps(values))
        return
    for key, value in values.items():
        shown = f"{value:.10g}" if isinstance(value, float) else str(value)
        print(f"{key:>24s} = {shown}")


@contextlib.contextmanager
def _staged(out: Path):
    """A hidden folder inside ``out`` to write into; on a clean exit every file is moved
    into ``out`` with os.replace (each file appears whole); the folder is removed."""
    out.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=".skcable-", dir=out))
    try:
        yield stage
        for path in sorted(stage.rglob("*")):
            if path.is_file():
                target = out / path.relative_to(stage)
                target.parent.mkdir(parents=True, exist_ok=True)
                os.replace(path, target)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


# --- cables ---------------------------------------------------------------------
def _examples(args) -> int:
    print(f"{'worked example':28s} {'published':>12s} {'skcable':>16s} {'rel. diff':>10s}")
    source = None
    for where, label, published, compute in _EXAMPLES:
        if where != source:
            source = where
            print(f"{source[0].upper()}{source[1:]}:")
        ours = float(compute())
        print(f"  {label:26s} {published:12.10g} {ours:16.10g} {abs(ours / published - 1):10.1e}")
    note = "ex. 4: the published iteration stopped early; full precision gives H = 85819.2 kN"
    print(f"({_NOTES[0].upper()}{_NOTES[1:]}, {note})")
    return EXIT_OK


def _vtk_path(args):
    return writable_file("vtk", args.vtk, _VTK_SUFFIXES) if args.vtk else None


def _write_vtk(solution, path: Path) -> str:
    with atomic_path(path) as temp:
        solution.to_vtk(temp)
    return str(path)


def _cable(args) -> int:
    vtk = _vtk_path(args)
    if args.command == "elastic-catenary":
        sol = cable.elastic_catenary(args.span, args.dh, args.w, args.EA, length=args.length)
    else:
        constraint = {k: getattr(args, k) for k in ("length", "sag", "H", "low", "T_max")}
        constraint = {k: v for k, v in constraint.items() if v is not None}
        solver = {"catenary": cable.catenary, "parabola": cable.parabola}[args.command]
        sol = solver(args.span, args.dh, args.w, **constraint)
    values = {k: float(getattr(sol, k)) for k in _CABLE_FIELDS} | {"residual": sol.residual()}
    if vtk:
        values["vtk"] = _write_vtk(sol, vtk)
    _print(values, args.json)
    return EXIT_OK


def _pairs(name: str, values, width: int = 2) -> np.ndarray:
    if values is None or len(values) % width:
        raise InputError(name, f"needs {width} numbers per entry, got {values!r}")
    return np.reshape(values, (-1, width))


def _funicular(args) -> int:
    vtk = _vtk_path(args)
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
        values["vtk"] = _write_vtk(sol, vtk)
    _print(values, args.json)
    return EXIT_OK


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
        "EI_stick_1_Nm2": float(section.EI_stick[0]),
        "EI_stick_2_Nm2": float(section.EI_stick[1]),
        "EI_slip_1_Nm2": float(section.EI_slip[0]),
        "EI_slip_2_Nm2": float(section.EI_slip[1]),
    }
    _print(values, args.json)
    return EXIT_OK


def _run_curve(model, label: str, n_steps, progress: bool):
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


def _summary(curve) -> tuple[dict, str | None]:
    """The curve's numbers, and why one of them is missing (None when none is)."""
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


def _write_results(curves: dict, out: Path) -> list[Path]:
    """CSV per curve, VTK time series (strand and wires), and PNG figures, into ``out``."""
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


def _write_staged(curves: dict, out: Path) -> list[str]:
    with _staged(out) as stage:
        written = _write_results(curves, stage)
    return [str(out / Path(p).relative_to(stage)) for p in written]


def _stopped(curves: dict, out: Path | None) -> str | None:
    """The one-line report of the curves that did not reach rupture, or None."""
    stopped = [f"{name}: {c.failure}" for name, c in curves.items() if c.failure is not None]
    if not stopped:
        return None
    where = f"; the curves up to the last converged step are in {out}/" if out is not None else ""
    return "; ".join(stopped) + where


def _capacity(args) -> int:
    from skcable import strand

    out = writable_dir("out", args.out) if args.out else None
    model = strand.StrandModel(
        _strand(args),
        slip=args.slip,
        mu=args.mu,
        length=args.length,
        n_elements=args.n_elements,
        damage_load=args.damage_load,
    )
    curve = _run_curve(model, args.slip, args.n_steps, not args.no_progress)
    if not curve.steps:
        raise ConvergenceError(f"strand capacity: not one step converged: {curve.failure}")
    values, missing = _summary(curve)
    if out is not None:
        name = f"{args.preset}_damage{args.damage}_{args.slip}"
        name += "_sinusoidal" if args.damage_load == "sinusoidal" else ""
        values["written"] = _write_staged({name: curve}, out)
    _print(values, args.json)
    problem = _stopped({"strand capacity": curve}, out) or missing
    if problem:
        raise ConvergenceError(problem)
    return EXIT_OK


def _demo(args) -> int:
    """Stick vs stick–slip capacity of steel 9.5 mm, one broken wire (Pino Vidal 2021, §4.3)."""
    from skcable import strand

    out = writable_dir("out", args.out)
    damaged = strand.preset("steel-9.5").damaged(1)
    curves = {}
    for slip in ("none", "axis"):
        label = "stick" if slip == "none" else "stick-slip"
        model = strand.StrandModel(damaged, slip=slip, n_elements=args.n_elements)
        curves[label] = _run_curve(model, label, args.n_steps, not args.no_progress)
        if not curves[label].steps:
            raise ConvergenceError(f"demo, {label}: not one step converged: {curves[label].failure}")
    _write_staged(curves, out)
    print(f"steel 9.5 mm, one broken wire, 1 m between clamps: results in {out}/")
    print(f"{'model':12s} {'K_Leq [MN]':>11s} {'last strain':>12s} {'force [kN]':>11s} {'D_r':>7s}")
    problems = []
    for label, curve in curves.items():
        row, missing = _summary(curve)
        problems += [f"{label}, {missing}"] if missing else []
        strain, force = float(curve.strain[-1]), float(curve.force[-1])
        d_r = f"{row['D_r']:7.4f}" if "D_r" in row else f"{'-':>7s}"
        print(f"{label:12s} {row['K_Leq_N'] / 1e6:11.4f} {strain:12.5f} {force / 1e3:11.2f} {d_r}")
    print(
        f"open {out / 'stick-slip.pvd'} in ParaView (Warp By Vector on 'displacement'); figures: {out}/*.png"
    )
    problem = "; ".join(filter(None, [_stopped(curves, out), *problems]))
    if problem:
        raise ConvergenceError(problem)
    return EXIT_OK


# --- studies --------------------------------------------------------------------
def _study(args) -> int:
    import logging

    from skcable import study

    try:  # the study file's own mistakes are named by the file and its key, not by a flag
        spec = study.load_study(args.path)
        if args.out is None:
            study.check_output("output", spec["output"])
        if args.cache is None and spec["cache"] is not None:
            writable_dir("cache", spec["cache"])
    except InputError as exc:
        raise _Usage(f"{args.path}: {exc}") from None
    if args.serial and args.scheduler is not None:
        raise _Usage("--scheduler: a Dask scheduler address; --serial runs without Dask: give one of them")
    if args.serial and args.workers is not None:
        raise _Usage("--workers: sizes the local Dask cluster; --serial runs without Dask: give one of them")
    if args.out is not None:
        study.check_output("out", args.out)
    if args.cache is not None:
        writable_dir("cache", args.cache)
    logging.getLogger("distributed").setLevel(logging.ERROR)
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
    cached = table.attrs.get("from_cache", 0)
    print(
        f"{len(table)} cases: {len(table) - len(failed)} ok, {len(failed)} failed "
        f"({cached} read from the cache, {busy:.1f} s of computing); table: {output}"
    )
    parameters = [c for c in table.columns if c in set().union(*(case.keys() for case in spec["cases"]))]
    for _, row in failed.head(20).iterrows():
        print(f"  failed {study.describe({k: row[k] for k in parameters})}: {row.error}")
    if len(failed) > 20:
        print(f"  ... and {len(failed) - 20} more: see the status and error columns of {output}")
    if len(failed):
        print(f"skcable: {len(failed)} of {len(table)} cases failed", file=sys.stderr)
        return EXIT_CASES_FAILED
    return EXIT_OK


# --- parser ---------------------------------------------------------------------
class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2, no usage dump)."""

    def error(self, message):
        self.exit(EXIT_USAGE, f"skcable: error: {message}\n")


def _finite(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"must be a finite number, got {text!r}")
    return value


def _whole(minimum: int | None = None):
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a whole number, got {text!r}") from None
        if minimum is not None and value < minimum:
            raise argparse.ArgumentTypeError(f"must be at least {minimum}, got {value}")
        return value

    return parse


def _epilog() -> str:
    import textwrap

    statuses = "\n".join(
        textwrap.fill(text, 78, initial_indent=f"  {code:3d}  ", subsequent_indent=" " * 7)
        for code, text in EXIT_STATUS.items()
    )
    sources = (
        f"SI units (m, N, Pa) unless a flag says otherwise. Sources of the worked examples and of the "
        f"strand model: {_NOTES}; {_GOICOLEA}; {_PINO_VIDAL}."
    )
    debug = "SKCABLE_DEBUG=1 shows the traceback of an unexpected error."
    return f"exit status:\n{statuses}\n\n{textwrap.fill(sources, 80)}\n{debug}"


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="skcable",
        description="skcable: structural cables and metallic strands on scikit-fem.",
        epilog=_epilog(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"skcable {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="command")

    def command(subparsers, name, handler, help_text, **kw):
        p = subparsers.add_parser(name, help=help_text, description=help_text, **kw)
        p.set_defaults(handler=handler, active=p)
        return p

    demo = command(
        sub,
        "demo",
        _demo,
        "stick vs stick-slip capacity curves of the steel 9.5 mm strand with one broken wire "
        "(Pino Vidal 2021, §4.3): CSV, VTK for ParaView and PNG figures in --out",
    )
    demo.add_argument(
        "--out", default="results", metavar="DIR", help="folder of the results (default: results)"
    )
    _mesh_flags(demo)
    demo.add_argument(
        "--no-progress", action="store_true", help="no progress bars on stderr (default: shown)"
    )
    command(
        sub,
        "examples",
        _examples,
        f"worked examples of the {_NOTES.lower()} and of {_GOICOLEA}: published values beside skcable's",
        aliases=["worked-examples", "seeds"],
    )
    for name in ("catenary", "parabola", "elastic-catenary"):
        what = {
            "catenary": "inextensible catenary from A = (0, 0) to B = (span, dh), given exactly one of "
            "--length, --sag, --H, --low, --T-max",
            "parabola": "parabolic cable (weight per horizontal metre) from A = (0, 0) to B = (span, dh), "
            "given exactly one of --length, --sag, --H, --low, --T-max",
            "elastic-catenary": "elastic (Irvine) catenary from A = (0, 0) to B = (span, dh) given its "
            "unstretched --length",
        }[name]
        p = command(sub, name, _cable, what)
        p.add_argument(
            "--span", type=_finite, required=True, help="horizontal distance A-B [m], > 0 (required)"
        )
        p.add_argument("--dh", type=_finite, default=0.0, help="height of B above A [m] (default: 0)")
        per = "horizontal metre" if name == "parabola" else "metre of cable"
        unstretched = " (unstretched)" if name == "elastic-catenary" else ""
        p.add_argument(
            "--w", type=_finite, required=True, help=f"weight per {per}{unstretched} [N/m], > 0 (required)"
        )
        if name == "elastic-catenary":
            p.add_argument("--EA", type=_finite, required=True, help="axial stiffness [N], > 0 (required)")
            p.add_argument("--length", type=_finite, required=True, help="unstretched length [m] (required)")
        else:
            one = "; give exactly one of the five"
            p.add_argument("--length", type=_finite, help=f"cable length [m], > chord (default: none{one})")
            p.add_argument(
                "--sag", type=_finite, help="largest vertical chord-cable distance [m] (default: none)"
            )
            p.add_argument("--H", type=_finite, help="horizontal tension [N] (default: none)")
            p.add_argument(
                "--low",
                type=_finite,
                help="y of the lowest point relative to A [m], < min(0, dh) (default: none)",
            )
            p.add_argument(
                "--T-max",
                dest="T_max",
                type=_finite,
                help="tension at the higher support [N] (default: none)",
            )
        _output_flags(p)
    f = command(sub, "funicular", _funicular, "weightless cable of given segment lengths under joint loads")
    f.add_argument(
        "--B",
        type=_finite,
        nargs=2,
        required=True,
        metavar=("X", "Y"),
        help="support B [m], A at (0, 0) (required)",
    )
    f.add_argument(
        "--lengths", type=_finite, nargs="+", required=True, help="segment lengths from A to B [m] (required)"
    )
    f.add_argument(
        "--loads", type=_finite, nargs="+", required=True, help="Px Py per joint [N], y up (required)"
    )
    _output_flags(f)
    _line_parser(sub, command)
    study = sub.add_parser("study", help="parameter studies on Dask").add_subparsers(
        dest="study_command", metavar="command"
    )
    st = command(study, "run", _study, "run a study file (TOML) and write its table")
    st.add_argument("path", help="study file, e.g. studies/pino_vidal_2021_tables_4_1_4_2.toml")
    st.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="address of a running dask.distributed scheduler, e.g. tcp://host:8786 "
        "(default: a local cluster of --workers processes)",
    )
    st.add_argument("--serial", action="store_true", help="no Dask: one case after the other (default: Dask)")
    st.add_argument(
        "--workers",
        type=_whole(1),
        metavar="N",
        help="processes of the local Dask cluster, >= 1 (default: 2)",
    )
    st.add_argument(
        "--out", metavar="FILE", help="table path, .csv or .parquet (default: the study file's output)"
    )
    st.add_argument(
        "--cache", metavar="DIR", help="folder of finished cases (default: the study file's cache, if any)"
    )
    st.add_argument("--no-progress", action="store_true", help="no progress bar on stderr (default: shown)")
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
        p.add_argument("--damage", type=_whole(), default=0, help="broken outer wires, >= 0 (default: 0)")
    cap.add_argument(
        "--slip",
        default="axis",
        choices=("none", "axis", "element"),
        help="none: stick (wires bonded); axis: Cardou's law per quadrature point and principal axis; "
        "element: Pino Vidal's (2021) element rule (default: axis)",
    )
    cap.add_argument("--mu", type=_finite, default=0.5, help="friction coefficient [-], >= 0 (default: 0.5)")
    cap.add_argument(
        "--damage-load",
        default="eccentricity",
        choices=("eccentricity", "sinusoidal"),
        help="broken wires as a helical eccentricity, or Pino Vidal's (2021) prismatic section + sinusoidal "
        "loads "
        "(default: eccentricity)",
    )
    cap.add_argument("--length", type=_finite, default=1.0, help="clamp to clamp [m], > 0 (default: 1)")
    _mesh_flags(cap)
    cap.add_argument("--out", metavar="DIR", help="folder for CSV, VTK and PNG files (default: none written)")
    for p in (section, cap):
        p.add_argument("--json", action="store_true", help="print one JSON object (default: a table)")
    cap.add_argument("--no-progress", action="store_true", help="no progress bar on stderr (default: shown)")
    _state_and_frequency_commands(sub, command)
    return parser


def _mesh_flags(p) -> None:
    p.add_argument(
        "--n-elements",
        type=_whole(),
        metavar="N",
        help="beam elements along the strand, >= 2 (default: 16 per lay length, at least 64)",
    )
    p.add_argument(
        "--n-steps",
        type=_whole(4),
        metavar="N",
        help="strain increments of the schedule, >= 4 (default: 60)",
    )


def _output_flags(p) -> None:
    p.add_argument(
        "--vtk", metavar="FILE", help="also write the cable to this .vtu or .vtk file (default: none)"
    )
    p.add_argument("--json", action="store_true", help="print one JSON object (default: a table)")


# --- change of state and natural frequencies -------------------------------------
_STATE_FIELDS = ("H", "H_plane", "sag", "T_max", "length", "blowout")


def _numbers(values) -> float | np.ndarray:
    """One number as a float, several as an array (the API broadcasts them)."""
    return float(values[0]) if len(values) == 1 else np.asarray(values, dtype=float)


def _listed(values: dict) -> dict:
    """Arrays as (nested) lists of floats, each checked finite."""
    out = {}
    for key, value in values.items():
        array = np.asarray(value)
        if array.dtype.kind == "f" and not np.all(np.isfinite(array)):
            raise RuntimeError(f"{key} came out with a value that is not finite")
        out[key] = array.tolist() if array.ndim else value
    return out


def _change_of_state(args) -> int:
    res = cable.change_of_state(
        args.span, args.dh, EA=args.EA, alpha=args.alpha, w0=args.w0, t0=args.t0, H0=args.H0,
        sag0=args.sag0, w=_numbers(args.w), t=_numbers(args.t),
        wind=_numbers(args.wind), model=args.model,
    )  # fmt: skip
    values = {k: getattr(res, k) for k in _STATE_FIELDS} | {"L0": res.L0, "H0": res.H0, "sag0": res.sag0}
    _print(_listed(values), args.json)
    return EXIT_OK


def _frequencies(args) -> int:
    from skcable.io import write_mode_shapes

    vtk = writable_file("vtk", args.vtk, _VTK_SUFFIXES) if args.vtk else None
    res = cable.natural_frequencies(
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
    values = _listed(values)
    if vtk:
        values["vtk"] = str(write_mode_shapes(res, vtk))
    _print(values, args.json)
    return EXIT_OK


# --- mooring line ---------------------------------------------------------------
_LINE_FIELDS = ("H", "V_B", "V_A", "H_A", "T_B", "length_on_seabed", "x_touchdown")


def _line(args) -> int:
    """One 2-D mooring line: fairlead and anchor forces, grounded length, 2x2 stiffness."""
    vtk = _vtk_path(args)
    n = len(args.length)
    for name in ("w", "EA"):
        if len(getattr(args, name)) not in (1, n):
            raise InputError(
                name, f"takes one value or one per segment ({n}), got {len(getattr(args, name))}"
            )
    w, EA = (v if len(v) == n else v * n for v in (args.w, args.EA))
    segments = [cable.Segment(*values) for values in zip(args.length, w, EA, strict=True)]
    attachments = [cable.ClumpWeight(_joint("clump", j), f) for j, f in args.clump or ()]
    attachments += [cable.Buoy(_joint("buoy", j), f) for j, f in args.buoy or ()]
    model = cable.Line(segments, attachments, seabed=args.seabed, friction=args.friction)
    sol = model.solve(args.span, args.dh)
    k = np.asarray(sol.stiffness(), dtype=float)
    values = {name: float(getattr(sol, name)) for name in _LINE_FIELDS}
    values |= {
        "k_H_span": float(k[0, 0]),
        "k_H_dh": float(k[0, 1]),
        "k_VB_span": float(k[1, 0]),
        "k_VB_dh": float(k[1, 1]),
        "residual": sol.residual(),
    }
    table = sol.tensions()
    values |= {
        f"segment_{c}": [float(v) for v in table[c]] for c in ("T_lower", "T_upper", "grounded_length")
    }
    if vtk:
        from skcable.io import write_lines

        values["vtk"] = str(
            write_lines([cable.line_3d(model, (0.0, 0.0, 0.0), (args.span, 0.0, args.dh))], vtk)
        )
    _print(values, args.json)
    return EXIT_OK


def _state_and_frequency_commands(sub, command) -> None:
    """``skcable change-of-state`` and ``skcable frequencies``."""
    cs = command(
        sub,
        "change-of-state",
        _change_of_state,
        "sag and tension of a span in other states (load, temperature, wind) at the unstressed length "
        "of a reference state (skcable.cable.change_of_state)",
    )
    fr = command(
        sub,
        "frequencies",
        _frequencies,
        "in-plane and out-of-plane natural frequencies and mode shapes of a sagging cable (Irvine's "
        "linear theory on finite elements; skcable.cable.natural_frequencies)",
    )
    for p in (cs, fr):
        p.add_argument(
            "--span", type=_finite, required=True, help="horizontal distance A-B [m], > 0 (required)"
        )
        p.add_argument("--dh", type=_finite, default=0.0, help="height of B above A [m] (default: 0)")
        p.add_argument("--EA", type=_finite, required=True, help="axial stiffness [N], > 0 (required)")
    cs.add_argument("--alpha", type=_finite, required=True, help="thermal expansion [1/K] (required)")
    cs.add_argument(
        "--w0", type=_finite, required=True, help="reference weight per unstressed length [N/m] (required)"
    )
    cs.add_argument("--t0", type=_finite, required=True, help="reference temperature [°C] (required)")
    cs.add_argument(
        "--H0", type=_finite, help="reference horizontal tension [N] (default: none; give --H0 or --sag0)"
    )
    cs.add_argument("--sag0", type=_finite, help="reference sag [m] (default: none; give --H0 or --sag0)")
    cs.add_argument(
        "--w",
        type=_finite,
        nargs="+",
        required=True,
        help="weight per unstressed length of the states, ice included [N/m]; several values broadcast "
        "with --t and --wind (required)",
    )
    cs.add_argument(
        "--t", type=_finite, nargs="+", required=True, help="temperatures of the states [°C] (required)"
    )
    cs.add_argument(
        "--wind", type=_finite, nargs="+", default=[0.0], help="transverse wind per length [N/m] (default: 0)"
    )
    cs.add_argument(
        "--model",
        default="catenary",
        choices=("catenary", "parabola"),
        help="elastic catenary with thermal strain, or the classical parabolic cubic (default: catenary)",
    )
    cs.add_argument("--json", action="store_true", help="print one JSON object (default: a table)")
    fr.add_argument(
        "--w", type=_finite, required=True, help="weight per metre of cable [N/m], > 0 (required)"
    )
    fr.add_argument("--H", type=_finite, help="horizontal tension [N] (default: none; give --H or --sag)")
    fr.add_argument("--sag", type=_finite, help="sag [m] (default: none; give --H or --sag)")
    fr.add_argument("--n-modes", type=_whole(1), default=6, help="modes per family, 1 to 60 (default: 6)")
    fr.add_argument("--g", type=_finite, default=9.81, help="gravity [m/s²], > 0 (default: 9.81)")
    fr.add_argument(
        "--vtk", metavar="FILE", help="also write the mode shapes to this .vtu or .vtk file (default: none)"
    )
    fr.add_argument("--json", action="store_true", help="print one JSON object (default: a table)")


def _joint(flag: str, value: float) -> int:
    if not float(value).is_integer():
        raise InputError(flag, f"takes JOINT FORCE with JOINT a whole number, got {value!r}")
    return int(value)


def _line_parser(sub, command) -> None:
    """``skcable line``: a multi-segment line from the anchor A = (0, 0) to the fairlead B = (span, dh)."""
    p = command(
        sub,
        "line",
        _line,
        "mooring line of one or several segments, with clump weights and buoys, from the anchor "
        "A = (0, 0) to the fairlead B = (span, dh), optionally on a flat seabed with friction "
        "(Jonkman 2007): fairlead and anchor forces, grounded length, each segment's end tensions "
        "and the 2x2 fairlead stiffness d(H, V_B)/d(span, dh)",
    )
    p.add_argument("--span", type=_finite, required=True, help="horizontal distance A-B [m], > 0 (required)")
    p.add_argument("--dh", type=_finite, required=True, help="height of B above A [m] (required)")
    p.add_argument(
        "--length",
        type=_finite,
        nargs="+",
        required=True,
        help="unstretched length of each segment from the anchor to the fairlead [m], > 0 (required)",
    )
    p.add_argument(
        "--w",
        type=_finite,
        nargs="+",
        required=True,
        help="weight in water per unstretched metre [N/m], > 0: one value, or one per segment (required)",
    )
    p.add_argument(
        "--EA",
        type=_finite,
        nargs="+",
        required=True,
        help="axial stiffness [N], > 0: one value, or one per segment (required)",
    )
    p.add_argument(
        "--clump",
        type=_finite,
        nargs=2,
        action="append",
        metavar=("JOINT", "WEIGHT"),
        help="clump weight [N] at a joint (0 the anchor, n the fairlead); repeat for more (default: none)",
    )
    p.add_argument(
        "--buoy",
        type=_finite,
        nargs=2,
        action="append",
        metavar=("JOINT", "BUOYANCY"),
        help="buoy (net upward force [N]) at a joint; repeat for more (default: none)",
    )
    p.add_argument(
        "--seabed",
        type=_finite,
        help="height of a flat seabed relative to A [m], <= 0; 0: the anchor on the seabed "
        "(default: none, the line hangs free)",
    )
    p.add_argument(
        "--friction", type=_finite, default=0.0, help="seabed friction coefficient [-], >= 0 (default: 0)"
    )
    _output_flags(p)


# --- main -----------------------------------------------------------------------
def _flag(active, argument: str) -> str | None:
    """The command-line flag of a library argument name, if the command has one."""
    dest = _FLAG_OF.get(argument, argument)
    for action in active._actions if active is not None else ():
        if action.dest == dest and action.option_strings:
            return max(action.option_strings, key=len)
    return None


def _input_message(args, exc: InputError) -> str:
    active = getattr(args, "active", None)
    reason = str(exc).split(": ", 1)[1] if ": " in str(exc) else str(exc)
    if exc.argument == "constraint" and active is not None:  # name the flags, not the API's keywords
        for dest in ("length", "sag", "H", "low", "T_max"):
            flag = _flag(active, dest)
            if flag:
                reason = reason.replace(f" {dest},", f" {flag},").replace(f" {dest} ", f" {flag} ")
        reason = reason.replace("T_max", "--T-max")
        return f"{args.command}: {reason}"
    flag = _flag(active, exc.argument)
    return f"{flag or exc.argument}: {reason}"


def _given_numbers(args) -> str:
    active = getattr(args, "active", None)
    shown = []
    for action in active._actions if active is not None else ():
        value = getattr(args, action.dest, None)
        if action.option_strings and isinstance(value, float):
            shown.append(f"{max(action.option_strings, key=len)} {value:g}")
    return ", ".join(shown)


def _run(parser, argv) -> tuple[int, str | None]:
    """Parse and run; returns the exit status and the one-line error message (or None)."""
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, or a usage error argparse printed
        return (exc.code if isinstance(exc.code, int) else EXIT_USAGE), None
    if not hasattr(args, "handler"):
        if args.command == "strand":
            return EXIT_USAGE, "strand: choose 'section' or 'capacity' (skcable strand --help)"
        if args.command == "study":
            return EXIT_USAGE, "study: choose 'run' (skcable study --help)"
        return EXIT_USAGE, "choose a command (skcable --help)"
    try:
        return args.handler(args), None
    except _Usage as exc:
        return EXIT_USAGE, str(exc)
    except InputError as exc:
        return EXIT_USAGE, _input_message(args, exc)
    except ConvergenceError as exc:
        return EXIT_NO_CONVERGENCE, f"no convergence: {exc}"
    except KeyboardInterrupt:
        return EXIT_INTERRUPTED, "interrupted"
    except BrokenPipeError:  # stdout closed early (`skcable examples | head -1`): stop quietly
        with contextlib.suppress(OSError, ValueError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_ERROR, None
    except (OverflowError, ZeroDivisionError, FloatingPointError) as exc:
        if os.environ.get("SKCABLE_DEBUG"):
            raise
        given = _given_numbers(args)
        return EXIT_USAGE, (
            f"{args.command}: these inputs are beyond double precision ({given}): {type(exc).__name__}: {exc}"
        )
    except OSError as exc:
        if os.environ.get("SKCABLE_DEBUG"):
            raise
        return EXIT_ERROR, f"{type(exc).__name__}: {exc}"
    except Exception as exc:  # noqa: BLE001 - no traceback on the command line, see EXIT_STATUS
        if os.environ.get("SKCABLE_DEBUG"):
            raise
        return EXIT_ERROR, f"internal error, please report it: {type(exc).__name__}: {exc}"


def main(argv=None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); returns the exit status.

    Without arguments, prints the help and returns 2. Numpy's floating-point warnings are
    not shown (the results are checked); skcable's own warnings are one line each.
    """
    parser = _parser()
    argv = sys.argv[1:] if argv is None else [str(a) for a in argv]
    if not argv:
        parser.print_help()
        return EXIT_USAGE
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        status, message = _run(parser, argv)
    seen = set()
    for warning in caught:
        text = " ".join(str(warning.message).split())
        if warning.category.__module__.startswith("skcable") and text not in seen:
            seen.add(text)
            print(f"skcable: warning: {text}", file=sys.stderr)
    if message is not None:
        print(f"skcable: error: {' '.join(message.split())}", file=sys.stderr)
    return status


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
