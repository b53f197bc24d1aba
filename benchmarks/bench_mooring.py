"""skcable's moored body against MoorPy's ``System``, same layout, same process.

The layout is the example's three-line spread mooring of a floating platform
(examples/spread_mooring.py): chain lines 850 m long from anchors on a seabed
200 m deep, 800 m out, to fairleads 20 m from the centre; the platform's weight,
buoyancy at the metacentre and waterplane; a steady force and moment. For both
codes: the body's equilibrium position, the fairlead tensions and the 6x6
stiffness of the lines, and the times (minimum over several runs) of

- one line solved between two points in space (skcable: `line_3d` with its 3x3
  stiffness; MoorPy: ``Line.staticSolve``, which also builds its 3x3 end stiffnesses),
- the body's equilibrium from the undisplaced position (skcable:
  `MooringSystem.equilibrium`, tol 1e-10 on the scaled residual; MoorPy:
  ``System.solveEquilibrium(tol=1e-8)``),
- the analytic 6x6 stiffness at the equilibrium (skcable: `MooringEquilibrium.stiffness`
  recomputed, i.e. `MooringSystem.stiffness`; MoorPy: ``Body.getStiffnessA``).

Writes the tables into docs/mooring.md between its ``bench_mooring`` markers.

Run:  python benchmarks/bench_mooring.py [--repeat 7] [--no-write]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import runpy
import time
from pathlib import Path

import numpy as np

from skcable import cable
from skcable.io._atomic import write_text

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = runpy.run_path(str(ROOT / "examples" / "spread_mooring.py"))
DOCS = ROOT / "docs" / "mooring.md"
START, END = "<!-- bench_mooring:start -->", "<!-- bench_mooring:end -->"


def best_time(call, repeat: int, number: int = 1) -> float:
    """Minimum over ``repeat`` runs of the mean time of ``number`` calls (s)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            call()
        times.append((time.perf_counter() - t0) / number)
    return min(times)


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
    model, anchor, fairlead = system.lines[0], system.anchors[0], eq.lines[0].fairlead
    t_line = best_time(lambda: cable.line_3d(model, anchor, fairlead).stiffness(), repeat, 200)
    t_line_2d = best_time(lambda: model.solve(eq.lines[0].span, eq.lines[0].dh), repeat, 200)
    mp_line = ms.lineList[0]
    t_line_mp = best_time(lambda: mp_line.staticSolve(), repeat, 200)
    t_line_mp_cold = best_time(lambda: mp_line.staticSolve(reset=True), repeat, 200)

    def ours_system():
        system.equilibrium(force=force, moment=moment)

    body = ms.bodyList[0]

    def moorpy_system():
        body.setPosition(np.zeros(6))
        ms.solveEquilibrium(tol=1e-8, maxIter=500)

    t_sys = best_time(ours_system, repeat, 5)
    t_sys_mp = best_time(moorpy_system, repeat, 5)
    t_k = best_time(lambda: system.stiffness(eq.position, lines_only=True), repeat, 50)
    t_k_mp = best_time(lambda: body.getStiffnessA(lines_only=True, all_DOFs=True), repeat, 50)
    iterations = len(eq.history) - 1
    times = "\n".join(
        [
            "| task | skcable [ms] | MoorPy [ms] | ratio MoorPy/skcable |",
            "|---|---|---|---|",
            "| one line between two points, forces and 3x3 stiffness (MoorPy warm-starts from its last "
            f"solution) | {t_line * 1e3:.3f} | "
            f"{t_line_mp * 1e3:.3f} | {t_line_mp / t_line:.2f} |",
            f"| the same, MoorPy from its default start (`staticSolve(reset=True)`) | {t_line * 1e3:.3f} | "
            f"{t_line_mp_cold * 1e3:.3f} | {t_line_mp_cold / t_line:.2f} |",
            f"| of which the 2-D line solve (`elastic_catenary` on the seabed) | {t_line_2d * 1e3:.3f} | | |",
            f"| body equilibrium from rest (skcable: {iterations} Newton steps) | {t_sys * 1e3:.2f} | "
            f"{t_sys_mp * 1e3:.2f} | {t_sys_mp / t_sys:.2f} |",
            "| analytic 6x6 stiffness (skcable re-solves the 3 lines; MoorPy reuses their stored 3x3) | "
            f"{t_k * 1e3:.3f} | {t_k_mp * 1e3:.3f} | "
            f"{t_k_mp / t_k:.2f} |",
        ]
    )
    version = importlib.metadata.version("moorpy")
    return (
        f"Agreement (MoorPy {version}, `solveEquilibrium(tol=1e-8)`, absolute on positions in m, each "
        f"line solved to its default tolerance, 1e-4 m on the catenary's end point):\n\n{agreement}\n\n"
        f"Times: minimum over {repeat} runs, one process, same machine:\n\n{times}\n"
    )


def write_docs(text: str) -> None:
    page = DOCS.read_text(encoding="utf-8")
    head, rest = page.split(START, 1)
    _, tail = rest.split(END, 1)
    block = f"{START}\n<!-- written by benchmarks/bench_mooring.py: do not edit by hand -->\n\n{text}\n{END}"
    write_text(DOCS, head + block + tail)


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
