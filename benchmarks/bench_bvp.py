"""Accuracy against time: closed forms, the scikit-fem BVP and the peers, one process.

Catenaries of span 100 m, level supports, w = 1 N/m, EA = 1e8 N, whose
unstretched length is that of the inextensible catenary with sag/span 0.01,
0.1 and 0.5. Every method's H is compared with a 40-digit mpmath solution of
Irvine's equations; times are the best of several repeats in this process.

Methods: skcable elastic_catenary (closed form); the parabola of the same
length used as an approximation; solve_bvp graph form P1/P2/P3 and arc form
P2 over a mesh sequence; MoorPy catenary(); pycatenary MooringLine;
OpenSeesPy CatenaryCable; OpenSeesPy chain of n corotational trusses (each
link's unstretched length set to L0/n through an initial strain, gravity
lumped at the nodes, 10 load steps of Newton).

Run:  python benchmarks/bench_bvp.py                 (chart + CSV + 10k-element timing)
      python benchmarks/bench_bvp.py --large         (only the 10k-element timing)
      python benchmarks/bench_bvp.py --stability     (where each formulation converges)
      python benchmarks/bench_bvp.py --seabed        (solve_line_bvp on a seabed: error and time)
      python benchmarks/bench_bvp.py --warm          (warm starts against cold solves, plane and
                                                      space; the cost of the equilibrium check)
      python benchmarks/bench_bvp.py --space-mesh    (the line in space on a seabed, its graded
                                                      and uniform meshes: error against time)
      python benchmarks/bench_bvp.py --auto [--write] (n_elements="auto" against fixed meshes:
                                                      error against time; --write: docs/bvp.md)
Output: benchmarks/out/bvp_accuracy_time.csv, docs/img/bvp_accuracy_time.png
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
from functools import partial
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the skcable of this checkout
from _peers import available, moorpy_H, opensees_catenary_cable_H, pycatenary_H  # noqa: E402
from _reference import irvine_H  # noqa: E402

from skcable import bvp, cable  # noqa: E402
from skcable.errors import ConvergenceError, InputError  # noqa: E402

SPAN, DH, W, EA = 100.0, 0.0, 1.0, 1e8
RATIOS = (0.01, 0.1, 0.5)
ROOT = Path(__file__).resolve().parents[1]


def best_time(fn, budget=0.3):
    fn()
    start = time.perf_counter()
    fn()
    once = time.perf_counter() - start
    repeats = max(1, min(200, int(budget / max(once, 1e-6))))
    best = once
    for _ in range(3):
        start = time.perf_counter()
        for _ in range(repeats):
            fn()
        best = min(best, (time.perf_counter() - start) / repeats)
    return best


def _timed(fn):
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def truss_chain(n, L0):
    import openseespy.opensees as ops

    guess = cable.parabola(SPAN, DH, W * L0 / SPAN, length=L0)
    xs = np.linspace(0, SPAN, 4001)
    ys = guess.y(xs)
    arc = np.concatenate([[0], np.cumsum(np.hypot(np.diff(xs), np.diff(ys)))])
    target = np.linspace(0, arc[-1], n + 1)
    X, Y = np.interp(target, arc, xs), np.interp(target, arc, ys)
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for i in range(n + 1):
        ops.node(i + 1, X[i], Y[i])
    ops.fix(1, 1, 1)
    ops.fix(n + 1, 1, 1)
    segment, unstretched = np.hypot(np.diff(X), np.diff(Y)), L0 / n
    ops.uniaxialMaterial("Elastic", 1, EA)
    for i in range(n):
        ops.uniaxialMaterial("InitStrainMaterial", 10 + i, 1, segment[i] / unstretched - 1.0)
        ops.element("corotTruss", i + 1, i + 1, i + 2, 1.0, 10 + i)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for i in range(1, n):
        ops.load(i + 1, 0.0, -W * unstretched)
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-12 * SPAN, 200)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    if ops.analyze(10) != 0:
        raise ConvergenceError("OpenSees truss chain did not converge")
    ops.reactions()
    return -ops.nodeReaction(1)[0]


def methods(L0):
    """(method, parameter, callable returning H)."""
    out = [
        ("skcable elastic_catenary", "", lambda: cable.elastic_catenary(SPAN, DH, W, EA, length=L0).H),
        ("parabola approximation", "", lambda: cable.parabola(SPAN, DH, W * L0 / SPAN, length=L0).H),
    ]
    for degree in (1, 2, 3):
        for n in (4, 16, 64, 256, 1024):
            out.append(
                (
                    f"solve_bvp graph P{degree}",
                    n,
                    lambda n=n, d=degree: (
                        bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), EA=EA, length=L0, n_elements=n, degree=d).H
                    ),
                )
            )
    for n in (8, 32, 128, 512):
        out.append(
            (
                "solve_bvp arc P2/P1dg",
                n,
                lambda n=n: (
                    bvp.solve_bvp(
                        SPAN, DH, bvp.SelfWeight(W), EA=EA, length=L0, n_elements=n, formulation="arc"
                    ).H
                ),
            )
        )
    args = (SPAN, DH, W, EA, L0)
    for name, function in (
        ("MoorPy catenary()", moorpy_H),
        ("pycatenary MooringLine", pycatenary_H),
        ("OpenSeesPy CatenaryCable", opensees_catenary_cable_H),
    ):
        runner = available(function, *args)
        if runner is not None:
            out.append((name, "", runner))
    if available(opensees_catenary_cable_H, *args) is not None:
        for n in (8, 32, 128, 512):
            out.append(("OpenSeesPy corotTruss chain", n, lambda n=n: truss_chain(n, L0)))
    return out


def chart(rows, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(RATIOS), figsize=(15, 5.4), sharey=True)
    names = sorted({r[1] for r in rows})
    markers = dict(zip(names, "os^vD<>pPhX*", strict=False))
    for ax, ratio in zip(axes, RATIOS, strict=True):
        for name in names:
            pts = [(r[3], max(r[4], 1e-17)) for r in rows if r[0] == ratio and r[1] == name and r[4] == r[4]]
            if pts:
                t, e = zip(*pts, strict=True)
                ax.loglog(
                    np.array(t) * 1e3,
                    e,
                    marker=markers[name],
                    label=name,
                    linestyle="-" if len(pts) > 1 else "",
                )
        ax.set(title=f"sag/span = {ratio}", xlabel="time per solve [ms]")
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("relative error in H")
    handles, labels = axes[-1].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=5, fontsize=8)
    fig.tight_layout(rect=(0, 0.13, 1, 1))
    fig.savefig(path, dpi=110)


def accuracy_time(args):
    rows = []
    for ratio in RATIOS:
        L0 = cable.catenary(SPAN, DH, W, sag=ratio * SPAN).length
        reference = irvine_H(SPAN, DH, W, EA, L0)
        for name, parameter, fn in methods(L0):
            try:
                H = float(fn())
                seconds = best_time(fn)
                error = abs(H / reference - 1)
            except (ConvergenceError, InputError) as exc:
                seconds, error = float("nan"), float("nan")
                print(f"  {name} {parameter}: {exc}", file=sys.stderr)
            rows.append((ratio, name, parameter, seconds, error))
            print(f"{ratio:5} {name:40s} {parameter!s:>6} {seconds * 1e3:10.3f} ms  {error:9.2e}")
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "bvp_accuracy_time.csv", "w", newline="") as fh:
        csv.writer(fh).writerows([("sag_over_span", "method", "elements", "seconds", "rel_error_H"), *rows])
    chart(rows, ROOT / "docs" / "img" / "bvp_accuracy_time.png")
    large(args)


def large(args):
    """The issue's target: a 10,000-element catenary converged to 1e-10 (graph form, P2).

    Self weight alone starts from its own closed form, so also time deck + self
    weight, where Newton has to travel (no closed form). Each case runs
    ``--repeats`` times; the minimum is the measure (the machine is shared)."""
    ref = cable.catenary(800.0, -20.0, 20.0, low=-30.0)
    cases = [
        ("catenary", bvp.SelfWeight(20.0), {"length": ref.length}),
        ("catenary", bvp.SelfWeight(20.0), {"sag": ref.sag}),
        ("deck + self weight", [bvp.DeckLoad(20.0), bvp.SelfWeight(5.0)], {"length": 830.0}),
        ("deck + self weight", [bvp.DeckLoad(20.0), bvp.SelfWeight(5.0)], {"sag": 40.0}),
    ]
    for label, load, kw in cases:
        fn = lambda load=load, kw=kw: bvp.solve_bvp(800.0, -20.0, load, n_elements=10_000, **kw)  # noqa: E731
        solution = fn()
        times = np.sort([_timed(fn) for _ in range(args.repeats)])
        print(
            f"10k P2 elements, {label}, {list(kw)[0]}: {times[0] * 1e3:6.1f} ms "
            f"(min of {args.repeats}; median {np.median(times) * 1e3:.1f} ms), "
            f"{solution.iterations} Newton iterations, merit history "
            + " ".join(f"{h:.0e}" for h in solution.history)
        )


def stability(args):
    """Both formulations over span/|dh| x length/chord x B above/below A."""
    rows, counts = [], {}
    for ratio in (1e-3, 1e-1, 1.0, 10.0, 1e3):
        for excess in (1e-9, 1e-6, 1e-2, 1.0, 99.0):
            for sign in (1.0, -1.0):
                dh, span = sign * 100.0, ratio * 100.0
                length = float(np.hypot(span, dh) * (1 + excess))
                T_exact = cable.catenary(span, dh, 1.0, length=length).T_A
                for formulation in ("graph", "arc"):
                    try:
                        b = bvp.solve_bvp(
                            span,
                            dh,
                            bvp.SelfWeight(1.0),
                            length=length,
                            n_elements=256,
                            formulation=formulation,
                        )
                        error = abs(b.T_A / T_exact - 1)
                        # converged; "coarse": the discretisation error at 256 elements exceeds 1e-6
                        status = "right" if error < 1e-6 else "coarse"
                    except ConvergenceError:
                        status, error = "failed", float("nan")
                    counts[(formulation, status)] = counts.get((formulation, status), 0) + 1
                    rows.append((ratio, excess, sign, formulation, status, error))
                    if status != "right":
                        scene = f"span/|dh|={ratio:g} excess={excess:g} sign={sign:+g}"
                        print(f"{scene} {formulation}: {status} {error:.1e}")
    for key in sorted(counts):
        print(key, counts[key])
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "bvp_stability.csv", "w", newline="") as fh:
        csv.writer(fh).writerows(
            [("span_over_dh", "excess", "sign", "formulation", "status", "rel_error_T_A"), *rows]
        )


def seabed(args):
    """`solve_line_bvp` on a flat seabed (with and without friction) and on a slope, against
    the closed forms: error in H and time per solve (touchdown fitted, the default), by mesh."""
    from skcable.cable.seabed import sloped_seabed_catenary
    from skcable.mooring import solve_line_bvp

    span, dh, w, ea, length = 400.0, 100.0, 1000.0, 5e8, 440.0
    cases = [
        ("flat, frictionless", cable.elastic_catenary(span, dh, w, ea, length=length, seabed=0.0), {}),
        (
            "flat, friction 0.2",
            cable.elastic_catenary(span, dh, w, ea, length=length, seabed=0.0, friction=0.2),
            {"friction": 0.2},
        ),
        (
            "slope 0.05, friction 0.1",
            sloped_seabed_catenary(span, dh, w, ea, length=length, seabed_slope=0.05, friction=0.1),
            {"seabed": lambda x: 0.05 * x, "seabed_slope": lambda x: 0.05 + 0 * x, "friction": 0.1},
        ),
    ]
    for label, ref, kw in cases:
        kw = {"seabed": 0.0, **kw}
        for n in (40, 80, 160, 320, 1280):
            for fit in (0, 2):
                fn = lambda n=n, fit=fit, kw=kw: solve_line_bvp(  # noqa: E731
                    span, dh, [(length, w, ea)], n_elements=n, fit_touchdown=fit, **kw
                )
                b = fn()
                times = np.sort([_timed(fn) for _ in range(args.repeats // 3 or 1)])
                print(
                    f"{label:26s} n={n:5d} fit_touchdown={fit}: |H/H_ref - 1| = {abs(b.H / ref.H - 1):.1e}, "
                    f"|H_A/H_A,ref - 1| = {abs(b.H_A / ref.H_A - 1):.1e}, "
                    f"{times[0] * 1e3:6.1f} ms (min; median {np.median(times) * 1e3:.1f} ms), "
                    f"{b.iterations} Newton iterations in the last pass"
                )


def warm(args):
    """Warm starts against solves from scratch over a sweep of ten fairlead steps, for the plane
    line and the line in space (`LineBVP.solve(start=)`, `LineBVP3D.solve(start=)`): time per
    step (median of the repeats) and the largest difference of the fairlead's force between the
    two sweeps' last solutions, over its largest component; then
    the cost of the equilibrium check of the last solution (`skcable.mooring.line_bvp.check`,
    which every solve runs) against the time of a solve from scratch."""
    from skcable.mooring import LineBVP
    from skcable.mooring.line_bvp.check import equilibrium_field
    from skcable.mooring.line_bvp.space import LineBVP3D

    segments = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    chain = [(850.0, 1000.0, 5e8)]

    def plane_ends(k):
        return (800.0 + 0.5 * k, 150.0 + 0.2 * k)

    def space_ends(k):
        return ((0.0, 0.0, 0.0), (800.0 + 0.5 * k, 0.3 * k, 150.0 + 0.2 * k))

    lines = [
        ("plane, 3 segments on a slope", LineBVP(segments, seabed=lambda x: -0.02 * x), plane_ends),
        ("plane, chain, friction 0.5", LineBVP(chain, seabed=0.0, friction=0.5, n_elements=80), plane_ends),
        ("space, 3 segments on a flat seabed", LineBVP3D(segments, seabed=0.0), space_ends),
    ]

    def force(solution):
        if hasattr(solution, "force_on_fairlead"):
            return np.asarray(solution.force_on_fairlead)
        return np.array([solution.H_B, solution.V_B])

    def sweep(model, ends, from_last):
        solution = model.solve(*ends(0))
        for k in range(1, 11):
            solution = model.solve(*ends(k), start=solution if from_last else None)
        return solution

    def per_step(model, ends, from_last):
        runs = [_timed(partial(sweep, model, ends, from_last)) for _ in range(args.repeats // 6 or 1)]
        return np.median(runs) / 10

    print("| line | warm: ms per step | cold: ms per step | warm/cold | fairlead force, warm vs cold |")
    print("|---|---|---|---|---|")
    for label, model, ends in lines:
        w_sol, c_sol = sweep(model, ends, True), sweep(model, ends, False)
        t_w, t_c = per_step(model, ends, True), per_step(model, ends, False)
        gap = np.max(np.abs(force(w_sol) - force(c_sol))) / np.max(np.abs(force(c_sol)))
        print(f"| {label} | {t_w * 1e3:.1f} | {t_c * 1e3:.1f} | {t_w / t_c:.2f} | {gap:.1e} |")
    print()
    print("| line | equilibrium check, ms | solve from scratch, ms | share |")
    print("|---|---|---|---|")
    for label, model, ends in lines:
        solution = model.solve(*ends(0))
        t_check = np.median([_timed(partial(equilibrium_field, solution)) for _ in range(args.repeats)])
        t_solve = np.median([_timed(partial(model.solve, *ends(0))) for _ in range(args.repeats // 3 or 1)])
        print(f"| {label} | {t_check * 1e3:.2f} | {t_solve * 1e3:.1f} | {t_check / t_solve:.1%} |")


def space_mesh(args):
    """The line in space on a seabed (`LineBVP3D`, its ``mesh``), on meshes graded as the plane
    line's (the default) and uniform: the end forces' error over the largest against the plane
    line's on 2048 graded elements (the other driver, `LineBVP`), and the time per solve (median
    of the repeats), by number of elements. Three scenes in the vertical plane x-z: a rope landing
    on a flat seabed 27 m below its anchor (``benchmarks/line_bvp_planes.py``'s scene 1:180, its
    weight varying ±16 %); chain, wire and chain anchored on a flat seabed (``--warm``'s line); two
    segments on a falling slope through the anchor with a clump (scene 3:140)."""
    from skcable.mooring import LineBVP
    from skcable.mooring.bathymetry import Plane
    from skcable.mooring.line_bvp.space import LineBVP3D

    def varying(s):
        return 16.355186173293895 * (
            1 + 0.15633141545904777 * np.sin(2 * np.pi * s / 625.231210775148 + 1.828396669699145)
        )

    slope = -0.031951459312359695
    scenes = [  # (label, span, dh, segments, plane seabed options, space seabed, point loads)
        ("landing from 27 m above a flat seabed", 1673.3775969545588, 68.78822221302812,
         [(1770.4204098171263, varying, 84360307.05301091)], {"seabed": -26.786311588569824},
         -26.786311588569824, []),
        ("chain-wire-chain anchored on a flat seabed", 800.0, 150.0,
         [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)], {"seabed": 0.0}, 0.0, []),
        ("two segments and a clump on a slope of -0.032", 1175.4443507194756, 818.6305574786969,
         [(1548.0073463380697, 80.6837038178888, 6026221207.206553),
          (450.94426865580664, 68.63531752172263, 164908758.06173596)],
         {"seabed": lambda x: slope * np.asarray(x), "seabed_slope": lambda x: np.full(np.shape(x), slope)},
         Plane(0.0, (slope, 0.0)), [(1113.9380968528765, 2128.104285596925)]),
    ]  # fmt: skip
    print("| scene | mesh | elements | end forces off | ms per solve |")
    print("|---|---|---|---|---|")
    for label, span, dh, segments, plane_bed, space_bed, loads in scenes:
        ref = LineBVP(segments, point_loads=loads, n_elements=2048, **plane_bed).solve(span, dh)
        want = np.array([ref.H_A, -ref.V_A, -ref.H_B, -ref.V_B])
        for mesh in ("graded", "uniform"):
            for n in (64, 256, 1024):
                model = LineBVP3D(segments, point_loads=loads, seabed=space_bed, n_elements=n, mesh=mesh)
                ends = ((0.0, 0.0, 0.0), (span, 0.0, dh))
                line = model.solve(*ends)
                got = np.array([*line.force_on_anchor[[0, 2]], *line.force_on_fairlead[[0, 2]]])
                off = np.abs(got - want).max() / np.abs(want).max()
                t = np.median([_timed(partial(model.solve, *ends)) for _ in range(args.repeats // 6 or 1)])
                print(f"| {label} | {mesh} | {n} | {off:.1e} | {t * 1e3:.0f} |")


def auto(args):
    """``n_elements="auto"`` (`skcable.mooring.line_bvp.resolution`) against fixed meshes of 64,
    256 and 1024 elements: the end forces' error over the largest against the line in space on
    2048 elements, and the time per solve (median of ``max(3, repeats // 10)``), the plane line
    (`solve_line_bvp`) and the line in space (`solve_line_bvp_3d`) in the vertical plane x-z.
    Two scenes of the differential survey (``benchmarks/line_bvp_planes.py``): 3:160, a chain
    hanging almost vertically to a clump, whose bend 64 elements do not resolve (the resolution
    check flags it), and 1:180, a rope landing on a flat seabed, which 64 resolve. With
    ``--write`` the table goes between the ``bvp-auto`` markers of docs/bvp.md."""
    import warnings
    from dataclasses import replace

    from _tables import markdown_table, write_section
    from line_bvp_planes import scenes

    def space_forces(r):  # as the plane line's (H_A, V_A, H_B, V_B)
        return [r.force_on_anchor[0], -r.force_on_anchor[2], -r.force_on_fairlead[0], -r.force_on_fairlead[2]]

    chosen = [("3:160, a chain hanging to a clump", 3, 160), ("1:180, a rope landing on the seabed", 1, 180)]
    body = []
    for label, seed, k in chosen:
        sc = scenes(seed, k + 1)[k]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the coarse meshes' ResolutionWarning: measured here
            ref = replace(sc, n_elements=2048).solve_space()
            want = np.array(space_forces(ref))
            for n in (64, 256, 1024, "auto"):
                for kind, solve, forces in (
                    ("plane", replace(sc, n_elements=n).solve_plane, lambda r: [r.H_A, r.V_A, r.H_B, r.V_B]),
                    ("space", replace(sc, n_elements=n).solve_space, space_forces),
                ):
                    line = solve()
                    off = np.abs(np.array(forces(line)) - want).max() / np.abs(want).max()
                    t = np.median([_timed(solve) for _ in range(max(3, args.repeats // 10))])
                    taken = f"auto: {line.n_elements}" if n == "auto" else str(n)
                    body.append([label, kind, taken, f"{off:.1e}", f"{t * 1e3:.0f}"])
                    print(*body[-1], sep=" | ", flush=True)
    lines = [
        "`python benchmarks/bench_bvp.py --auto`: each line on fixed meshes and with "
        '`n_elements="auto"` (the elements it took), its end forces\' error over the largest against '
        "the line in space on 2048 elements, and the time per solve (median); measured on x86_64, 2 cores "
        "(shared).",
        "",
        *markdown_table(["scene", "line", "elements", "end forces off", "ms per solve"], body),
    ]
    print("\n".join(lines))
    if args.write:
        write_section(ROOT / "docs" / "bvp.md", "bvp-auto", lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stability", action="store_true", help="map where each formulation converges")
    parser.add_argument("--large", action="store_true", help="only the 10,000-element timings")
    parser.add_argument("--seabed", action="store_true", help="solve_line_bvp on a seabed: error, time")
    parser.add_argument("--warm", action="store_true", help="warm against cold starts; check cost")
    parser.add_argument("--space-mesh", action="store_true", help="the line in space: graded or uniform")
    parser.add_argument("--auto", action="store_true", help='n_elements="auto" against fixed meshes')
    parser.add_argument("--write", action="store_true", help="with --auto: its table into docs/bvp.md")
    parser.add_argument("--repeats", type=int, default=30, help="runs of each 10,000-element case")
    args = parser.parse_args(argv)
    if args.auto:
        return auto(args)
    if args.seabed:
        return seabed(args)
    if args.warm:
        return warm(args)
    if args.space_mesh:
        return space_mesh(args)
    (stability if args.stability else large if args.large else accuracy_time)(args)


if __name__ == "__main__":
    main()
