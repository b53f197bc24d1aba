"""skcable's moored body against MoorPy's ``System``, same layout, same process.

The layout is the example's three-line spread mooring of a floating platform
(examples/spread_mooring.py): chain lines 850 m long from anchors on a seabed
200 m deep, 800 m out, to fairleads 20 m from the centre; the platform's weight,
buoyancy at the metacentre and waterplane; a steady force and moment. For both
codes: the body's equilibrium position, the fairlead tensions and the 6x6
stiffness of the lines, and the times (minimum over several runs) of

- one line solved between two points in space (skcable: `line_3d` with its 3x3
  stiffness; MoorPy: ``Line.staticSolve``, which also builds its 3x3 end stiffnesses),
  from each code's default start, and warm-started: from the solution at a fairlead
  1.1 m away (both codes alternating between two fairleads) and at the same fairlead,
- the 2-D solve alone, cold and warm, and one scalar `elastic_catenary` on the seabed,
- the body's equilibrium from the undisplaced position (skcable:
  `MooringSystem.equilibrium`, tol 1e-10 on the scaled residual, with the lines
  warm-started from their previous solutions, and again with every line solved from
  its default start through a line model without ``start=``, as the line-model
  protocol was before; MoorPy: ``System.solveEquilibrium(tol=1e-8)``), and the time
  per line solve in that loop (line solves counted in an untimed run),
- the analytic 6x6 stiffness at the equilibrium (skcable: `MooringEquilibrium.stiffness`
  recomputed, i.e. `MooringSystem.stiffness`; MoorPy: ``Body.getStiffnessA``).

Writes the tables into docs/mooring.md between its ``bench_mooring`` markers.

Run:  PYTHONPATH=. python benchmarks/bench_mooring.py [--repeat 7] [--no-write]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import runpy
import sys
import time
from pathlib import Path

import numpy as np

from skcable import cable, mooring
from skcable.mooring.line3d import solve_in_space

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = runpy.run_path(str(ROOT / "examples" / "spread_mooring.py"))
DOCS = ROOT / "docs" / "mooring.md"
sys.path.insert(0, str(ROOT / "benchmarks"))

from _tables import write_section  # noqa: E402


def best_time(call, repeat: int, number: int = 1) -> float:
    """Minimum over ``repeat`` runs of the mean time of ``number`` calls (s)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            call()
        times.append((time.perf_counter() - t0) / number)
    return min(times)


class _ColdModel:
    """A line model without a warm start: ``solve(span, dh)`` only."""

    def __init__(self, line):
        self.line = line

    def solve(self, span, dh):
        return self.line.solve(span, dh)


def _count_calls(owner, name, call) -> int:
    """How many times ``call()`` calls ``owner.<name>`` (an untimed run)."""
    method, count = getattr(owner, name), [0]

    def counted(*args, **kwargs):
        count[0] += 1
        return method(*args, **kwargs)

    setattr(owner, name, counted)
    try:
        call()
    finally:
        delattr(owner, name)
    return count[0]


def _count_line_solves(lines, call) -> int:
    """Line solves of MoorPy's ``Line.staticSolve`` made by ``call()`` (an untimed run)."""
    counts = []
    originals = [line.staticSolve for line in lines]
    for line, method in zip(lines, originals, strict=True):

        def counted(*args, _method=method, **kwargs):
            counts.append(1)
            return _method(*args, **kwargs)

        line.staticSolve = counted
    try:
        call()
    finally:
        for line in lines:
            del line.staticSolve
    return len(counts)


def _recorded_line_solves(call) -> list[tuple]:
    """The arguments of every line solve (`solve_in_space`) that ``call()`` makes, in order."""
    from skcable.mooring import system as system_module

    original, calls = system_module.solve_in_space, []

    def recording(*args):
        calls.append(args)
        return original(*args)

    system_module.solve_in_space = recording
    try:
        call()
    finally:
        system_module.solve_in_space = original
    return calls


def run(repeat: int) -> str:
    system = EXAMPLE["system"]()
    force, moment = np.array(EXAMPLE["FORCE"]), np.array(EXAMPLE["MOMENT"])
    eq = system.equilibrium(force=force, moment=moment)
    r6, tensions, K_moorpy, ms = EXAMPLE["moorpy_solve"]()
    K = system.stiffness(r6, lines_only=True)
    ours_T = np.array([line.tension_at_fairlead for line in eq.lines])
    rows = [
        "| quantity | skcable | MoorPy | difference |",
        "|---|---|---|---|",
    ]
    names = ("surge x [m]", "sway y [m]", "heave z [m]", "roll [rad]", "pitch [rad]", "yaw [rad]")
    for i, name in enumerate(names):
        rows.append(f"| {name} | {eq.position[i]:.9g} | {r6[i]:.9g} | {abs(eq.position[i] - r6[i]):.1e} |")
    for i in range(3):
        rows.append(
            f"| line {i} fairlead tension [N] | {ours_T[i]:.9g} | {tensions[i]:.9g} | "
            f"{abs(ours_T[i] / tensions[i] - 1):.1e} (rel.) |"
        )
    rel_K = np.abs(K - K_moorpy).max() / np.abs(K_moorpy).max()
    rows.append(
        f"| 6x6 stiffness of the lines at MoorPy's position | | | {rel_K:.1e} "
        "(largest difference / largest term) |"
    )
    agreement = "\n".join(rows)

    # -- times ---------------------------------------------------------------------------
    model, anchor = system.lines[0], system.anchors[0]
    here = eq.lines[0].fairlead
    there = here + np.array([1.0, 0.5, -0.2])  # a step of the body's Newton iteration
    mp_line = ms.lineList[0]
    line_here, line_there = mooring.line_3d(model, anchor, here), mooring.line_3d(model, anchor, there)
    mp_here, mp_there = mp_line.rB.copy(), mp_line.rB + (there - here)

    def ours_alternating():  # each solve warm-started from the other fairlead's solution
        mooring.line_3d(model, anchor, here, start=line_there).stiffness()
        mooring.line_3d(model, anchor, there, start=line_here).stiffness()

    def moorpy_alternating():  # staticSolve warm-starts from its last solution
        mp_line.setEndPosition(mp_there, True)
        mp_line.staticSolve()
        mp_line.setEndPosition(mp_here, True)
        mp_line.staticSolve()

    t_line = best_time(lambda: mooring.line_3d(model, anchor, here).stiffness(), repeat, 200)
    t_line_same = best_time(
        lambda: mooring.line_3d(model, anchor, here, start=line_here).stiffness(), repeat, 200
    )
    t_line_near = best_time(ours_alternating, repeat, 100) / 2
    span, dh = line_here.span, line_here.dh
    t_line_2d = best_time(lambda: model.solve(span, dh), repeat, 200)
    t_line_2d_warm = best_time(lambda: model.solve(span, dh, start=line_there.solution), repeat, 200)
    w, EA, L = EXAMPLE["W"], EXAMPLE["EA"], EXAMPLE["LENGTH"]
    t_catenary = best_time(lambda: cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0), repeat, 200)
    t_line_mp_cold = best_time(lambda: mp_line.staticSolve(reset=True), repeat, 200)
    t_line_mp_near = best_time(moorpy_alternating, repeat, 100) / 2
    mp_line.setEndPosition(mp_here, True)
    mp_line.staticSolve()
    t_line_mp = best_time(lambda: mp_line.staticSolve(), repeat, 200)

    # the body's equilibrium; "cold": the same lines behind a model without start= (the
    # line-model protocol before warm starts), each line solved from its own start
    cold_system = mooring.MooringSystem(system.body, [_ColdModel(m) for m in system.lines], system.anchors)
    n_solves = 3 * _count_calls(system, "evaluate", lambda: system.equilibrium(force=force, moment=moment))
    body = ms.bodyList[0]

    def moorpy_system():
        body.setPosition(np.zeros(6))
        ms.solveEquilibrium(tol=1e-8, maxIter=500)

    n_solves_mp = _count_line_solves(ms.lineList, moorpy_system)
    # the line solves of one equilibrium, with their warm starts, replayed alone (3x3 stiffness included)
    replay = _recorded_line_solves(lambda: system.equilibrium(force=force, moment=moment))
    assert len(replay) == n_solves

    def replay_lines():
        for args in replay:
            solve_in_space(*args).stiffness()

    t_replay = best_time(replay_lines, repeat, 5) / len(replay)
    t_sys = best_time(lambda: system.equilibrium(force=force, moment=moment), repeat, 5)
    t_sys_cold = best_time(lambda: cold_system.equilibrium(force=force, moment=moment), repeat, 5)
    t_sys_mp = best_time(moorpy_system, repeat, 5)
    t_k = best_time(lambda: system.stiffness(eq.position, lines_only=True), repeat, 50)
    t_k_mp = best_time(lambda: body.getStiffnessA(lines_only=True, all_DOFs=True), repeat, 50)
    iterations = len(eq.history) - 1
    per_line, per_line_mp = t_sys / n_solves, t_sys_mp / n_solves_mp

    def row(task, ours, theirs=None, digits=3):
        if theirs is None:
            return f"| {task} | {ours * 1e3:.{digits}f} | | |"
        return f"| {task} | {ours * 1e3:.{digits}f} | {theirs * 1e3:.{digits}f} | {theirs / ours:.2f} |"

    times = "\n".join(
        [
            "| task | skcable [ms] | MoorPy [ms] | ratio MoorPy/skcable |",
            "|---|---|---|---|",
            row(
                "one line between two points, forces and 3x3 stiffness, from the default start "
                "(MoorPy: `staticSolve(reset=True)`)",
                t_line,
                t_line_mp_cold,
            ),
            row(
                "the same, warm-started from the solution at a fairlead 1.1 m away (both codes "
                "alternate between the two fairleads)",
                t_line_near,
                t_line_mp_near,
            ),
            row("the same, warm-started from the solution at the same fairlead", t_line_same, t_line_mp),
            row("of which the 2-D line solve (`Line.solve`), from the default start", t_line_2d),
            row("of which the 2-D line solve, warm-started 1.1 m away", t_line_2d_warm),
            row(
                "`elastic_catenary(..., seabed=0)`, one scalar call (the default start of a "
                "one-segment `Line`)",
                t_catenary,
            ),
            row(
                f"body equilibrium from rest (skcable: {iterations} Newton steps, {n_solves} line solves; "
                f"MoorPy: {n_solves_mp} line solves)",
                t_sys,
                t_sys_mp,
                2,
            ),
            row(
                "the same, each line solved from its default start (a line model without `start=`)",
                t_sys_cold,
                t_sys_mp,
                2,
            ),
            row(
                "per line solve in the equilibrium loop: the equilibrium's time / its line solves",
                per_line,
                per_line_mp,
            ),
            row(
                "per line solve in the equilibrium loop: its line solves and 3x3 stiffnesses replayed "
                "alone, against MoorPy's warm-started line (third row)",
                t_replay,
                t_line_mp,
            ),
            row(
                "analytic 6x6 stiffness (skcable re-solves the 3 lines; MoorPy reuses their stored 3x3)",
                t_k,
                t_k_mp,
            ),
        ]
    )
    version = importlib.metadata.version("moorpy")
    return (
        f"Agreement (MoorPy {version}, `solveEquilibrium(tol=1e-8)`, absolute on positions in m, each "
        f"line solved to its default tolerance, 1e-4 m on the catenary's end point):\n\n{agreement}\n\n"
        f"Times: minimum over {repeat} runs, one process, same machine:\n\n{times}\n"
    )


def write_docs(text: str) -> None:
    notice = "<!-- written by benchmarks/bench_mooring.py: do not edit by hand -->"
    write_section(DOCS, "bench_mooring", [notice, "", *text.split("\n")])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--no-write", action="store_true", help="print only, leave docs/mooring.md")
    args = parser.parse_args()
    text = run(args.repeat)
    print(text)
    if not args.no_write:
        write_docs(text)
        print(f"written into {DOCS}")


if __name__ == "__main__":
    main()
