"""Whole lines at array speed: the change of state of 1000 spans × 10 temperatures, and tension
sections of 5 to 5000 spans, measured in one process.

- skcable's line path, ``change_of_state(spans, dh, ...)`` (exact elastic catenary, every element
  residual-checked), beside mechaphlowers' change of state on the same grid (its catenary span
  model for the reference length, then its vectorised parabolic cubic, ``approx_parameter``,
  with its default cubic solver) and skcable's one-span path called span by span;
- ``change_of_state(..., model="auto", rtol=4e-3)``: the model no more than the line needs at
  mechaphlowers' accuracy (its H is 4.0e-3 from the exact one on this grid): the parabola on
  every span whose estimated error is within rtol, the exact catenary elsewhere; its true error
  against the exact model beside the estimate;
- ``tension_section`` at 5, 50, 500 and 5000 spans (banded Newton), with the scaling exponent.

Times are the minimum and the median of ``--repeats`` runs, the peers interleaved run by run
(the machine may be shared: the minimum is the unloaded time, the median the typical one); the
ratios also in the thread's CPU time, which the scheduler of a shared machine does not stretch.

Run:  python benchmarks/bench_lines.py [--repeats 21]   (mechaphlowers: pip install ".[bench]")
      rewrites its section of docs/speed_targets.md (between the conductors markers)
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

from skcable import conductors

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

from _tables import write_section as write_markers  # noqa: E402

#: ACSR Drake (the acsr-drake preset's EA, weight and alpha, rounded), a line of 1000 spans
CONDUCTOR = dict(EA=3.4e7, alpha=1.9e-5, w0=15.97, t0=15.0)
H0 = 28e3
TEMPERATURES = np.linspace(-20.0, 90.0, 10)


def line_grid(n=1000, seed=24):
    rng = np.random.default_rng(seed)
    spans = rng.uniform(150.0, 600.0, n)
    return spans, rng.uniform(-0.1, 0.1, n) * spans


def mechaphlowers_change_of_state(spans, dh, temperatures):
    """mechaphlowers' change of state: L0 from its catenary span at H0 (mean-tension strain,
    thermal strain from 0 °C as its deformation model), the parabolic cubic at each state."""
    from mechaphlowers.core.models.balance.models.model_ducloux import approx_parameter
    from mechaphlowers.core.models.cable.span import CatenarySpan

    w0, EA, alpha, t0 = (CONDUCTOR[k] for k in ("w0", "EA", "alpha", "t0"))
    n, m = spans.size, temperatures.size
    span = CatenarySpan(
        span_length=spans,
        elevation_difference=dh,
        parameter=np.full(n, H0 / w0),
        linear_weight=np.float64(w0),
    )
    span.compute_values()
    L0 = span.compute_L() / (1 + alpha * t0 + span.T_mean() / EA)
    p = approx_parameter(
        np.repeat(spans, m), np.repeat(dh, m), np.repeat(L0, m), np.ones(n * m), np.float64(1.0),
        np.float64(w0), np.float64(EA), np.float64(alpha), np.tile(temperatures, n),
    )  # fmt: skip
    return (p * w0).reshape(n, m)


def skcable_line(spans, dh, temperatures):
    return conductors.change_of_state(spans, dh, **CONDUCTOR, H0=H0, w=CONDUCTOR["w0"], t=temperatures).H


#: The tolerance of the model choice: mechaphlowers' distance from the exact H on this grid.
RTOL = 4e-3


def skcable_auto(spans, dh, temperatures):
    return conductors.change_of_state(
        spans, dh, **CONDUCTOR, H0=H0, w=CONDUCTOR["w0"], t=temperatures, model="auto", rtol=RTOL
    )


def skcable_span_by_span(spans, dh, temperatures):
    return np.array(
        [
            conductors.change_of_state(
                float(a), float(h), **CONDUCTOR, H0=H0, w=CONDUCTOR["w0"], t=temperatures
            ).H
            for a, h in zip(spans, dh, strict=True)
        ]
    )


def interleaved(functions, repeats, runs=None, cpu=None):
    """{name: (min, median)} of each function, run in turn ``repeats`` times (``runs``, a dict,
    receives each function's list of times; ``cpu`` its list of the thread's CPU times, which a
    shared machine's scheduler does not stretch: a run taken off the processor for a 4 ms slice
    stretches the wall time alone)."""
    times = {name: [] for name in functions}
    cpu_times = {name: [] for name in functions}
    for _ in range(repeats):
        for name, fn in functions.items():
            start, start_cpu = time.perf_counter(), time.thread_time()
            fn()
            times[name].append(time.perf_counter() - start)
            cpu_times[name].append(time.thread_time() - start_cpu)
    if runs is not None:
        runs.update(times)
    if cpu is not None:
        cpu.update(cpu_times)
    return {name: (min(t), float(np.median(t))) for name, t in times.items()}


def section_scene(n, seed=5):
    rng = np.random.default_rng(seed + n)
    spans, dh = rng.uniform(200.0, 500.0, n), rng.uniform(-20.0, 20.0, n)
    kw = dict(**CONDUCTOR, H0=H0, w=CONDUCTOR["w0"], t=75.0, insulator_length=3.0, insulator_weight=700.0)
    return lambda: conductors.tension_section(spans, dh, **kw)


def measure(repeats):
    rows = []
    spans, dh = line_grid()
    exact = skcable_line(spans, dh, TEMPERATURES)
    start = time.perf_counter()
    one = skcable_span_by_span(spans, dh, TEMPERATURES)
    t_loop = time.perf_counter() - start
    gap = float(np.max(np.abs(exact / one - 1)))
    functions = {"skcable": lambda: skcable_line(spans, dh, TEMPERATURES)}
    try:
        mech = mechaphlowers_change_of_state(spans, dh, TEMPERATURES)
        functions["mechaphlowers"] = lambda: mechaphlowers_change_of_state(spans, dh, TEMPERATURES)
    except ImportError:
        mech = None
    runs, cpu = {}, {}
    t = interleaved(functions, repeats, runs, cpu)
    grid = f"{spans.size} spans × {TEMPERATURES.size} temperatures"
    note = f"median {t['skcable'][1] * 1e3:.2f} ms; H within {gap:.1e} of the one-span path"
    rows.append((f"change_of_state, line path, {grid}", f"{t['skcable'][0] * 1e3:.2f} ms", note))
    rows.append((f"change_of_state, one span a call, {grid}", f"{t_loop:.2f} s",
                 f"{t_loop / t['skcable'][0]:.0f}x the line path"))  # fmt: skip
    if mech is not None:
        err = float(np.max(np.abs(mech / exact - 1)))
        ratio = t["skcable"][0] / t["mechaphlowers"][0]
        rows.append((f"mechaphlowers change of state (parabolic cubic), {grid}",
                     f"{t['mechaphlowers'][0] * 1e3:.2f} ms",
                     f"median {t['mechaphlowers'][1] * 1e3:.2f} ms; {err:.1e} from the exact H, "
                     f"{int(np.sum(mech <= 0))} H <= 0"))  # fmt: skip
        rows.append(("time ratio skcable exact / mechaphlowers (minimum)", f"{ratio:.2f}", "target <= 1"))
        paired = float(np.median(np.divide(runs["skcable"], runs["mechaphlowers"])))
        rows.append(
            (
                "time ratio skcable exact / mechaphlowers (median of the paired runs)",
                f"{paired:.2f}",
                "target <= 1",
            )
        )
        paired_cpu = np.divide(cpu["skcable"], cpu["mechaphlowers"])
        rows.append(
            (
                "time ratio skcable exact / mechaphlowers (CPU time, median of the paired runs)",
                f"{float(np.median(paired_cpu)):.2f}",
                f"runs {float(np.min(paired_cpu)):.2f}–{float(np.max(paired_cpu)):.2f}; target <= 1",
            )
        )
    rows.extend(_auto_rows(spans, dh, repeats, mech, grid))
    sizes = (5, 50, 500, 5000)
    t_sec = {
        n: interleaved({"s": section_scene(n)}, max(3, repeats // (1 if n < 5000 else 4)))["s"] for n in sizes
    }
    for n in sizes:
        target = {500: "target <= 50 ms", 5000: "target <= 0.5 s"}.get(n, "")
        note = f"median {t_sec[n][1] * 1e3:.1f} ms; {t_sec[n][0] / n * 1e6:.0f} µs/span {target}"
        rows.append((f"tension_section, {n} spans, one state", f"{t_sec[n][0] * 1e3:.1f} ms", note))
    slope = np.log(t_sec[5000][0] / t_sec[500][0]) / np.log(10.0)
    rows.append(("tension_section scaling exponent, 500 → 5000 spans", f"{slope:.2f}", "linear: <= 1"))
    for lo, hi in ((50, 500), (500, 5000)):
        extra = (t_sec[hi][0] - t_sec[lo][0]) / (hi - lo) * 1e6
        rows.append(
            (f"tension_section, cost of a span from {lo} to {hi} spans", f"{extra:.1f} µs", "linear: equal")
        )
    return rows


def _auto_rows(spans, dh, repeats, mech, grid):
    """The rows of ``model="auto"`` at `RTOL`: its time, what it chose and why, its true error
    against the exact model beside its estimate, and its time against mechaphlowers' (the two
    interleaved by themselves)."""
    functions = {"auto": lambda: skcable_auto(spans, dh, TEMPERATURES)}
    if mech is not None:
        functions["mechaphlowers"] = lambda: mechaphlowers_change_of_state(spans, dh, TEMPERATURES)
    runs, cpu = {}, {}
    t = interleaved(functions, repeats, runs, cpu)
    auto = skcable_auto(spans, dh, TEMPERATURES)
    exact = conductors.change_of_state(spans, dh, **CONDUCTOR, H0=H0, w=CONDUCTOR["w0"], t=TEMPERATURES)
    error = max(
        float(np.max(np.abs(getattr(auto, k) / getattr(exact, k) - 1))) for k in ("H", "sag", "T_max")
    )
    rows = [
        (
            f"change_of_state(model='auto', rtol={RTOL:g}), {grid}",
            f"{t['auto'][0] * 1e3:.2f} ms",
            f"median {t['auto'][1] * 1e3:.2f} ms; {auto.reason}; true error in H, sag, T_max "
            f"{error:.1e} (estimate {float(np.max(auto.error_estimate)):.1e})",
        )
    ]
    if mech is not None:
        ratios = np.divide(runs["auto"], runs["mechaphlowers"])
        cpu_ratios = np.divide(cpu["auto"], cpu["mechaphlowers"])
        rows.append(
            (
                f"time ratio skcable auto / mechaphlowers at rtol {RTOL:g} (CPU time, median of the "
                "paired runs)",
                f"{float(np.median(cpu_ratios)):.2f}",
                f"runs {float(np.min(cpu_ratios)):.2f}–{float(np.max(cpu_ratios)):.2f}; target <= 1",
            )
        )
        rows.append(
            (
                f"time ratio skcable auto / mechaphlowers at rtol {RTOL:g} (median of the paired runs)",
                f"{float(np.median(ratios)):.2f}",
                f"runs {float(np.min(ratios)):.2f}–{float(np.max(ratios)):.2f}; minima "
                f"{t['auto'][0] / t['mechaphlowers'][0]:.2f} (mechaphlowers "
                f"{t['mechaphlowers'][0] * 1e3:.2f} ms, median {t['mechaphlowers'][1] * 1e3:.2f} ms, in "
                "turn with auto only); target <= 1",
            )
        )
    return rows


def write_section(rows, repeats):
    lines = [
        "## Whole lines (conductors)",
        "",
        f"Generated by `python benchmarks/bench_lines.py --repeats {repeats}` (minimum of the runs, the "
        f"peers interleaved) on {platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}, NumPy {np.__version__}.",
        "",
        "| measure | value | note |",
        "|---|---|---|",
        *(f"| {a} | {b} | {c} |" for a, b, c in rows),
    ]
    page = ROOT / "docs" / "speed_targets.md"
    return write_markers(page, "conductors", lines, new_page="# Speed targets\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=21, help="runs per measure (default: 21)")
    parser.add_argument("--no-write", action="store_true", help="print only")
    args = parser.parse_args(argv)
    rows = measure(args.repeats)
    for row in rows:
        print(" | ".join(row))
    if not args.no_write:
        print("wrote", write_section(rows, args.repeats))
    return 0


if __name__ == "__main__":
    sys.exit(main())
