"""A mooring system's equilibrium against MoorPy's ``System.solveEquilibrium``, same scenes, one process.

Three scenes of the same chain lines (120 mm studless chain, 850 m, anchors 800 m out on a seabed
200 m deep, fairleads 20 m from the centre and 14 m down) holding floating bodies (weight,
buoyancy at the metacentre, waterplane) pushed by a steady force:

- one body on 3 lines;
- one body on 48 lines;
- 16 bodies on 3 lines each (a 4 x 4 farm, 2 km apart: 48 lines, 96 dofs).

skcable's system is built with ``MooringSystem(depth=...)``, ``add_body``, ``add_point`` and
``add_line``; MoorPy's with ``addBody``, ``addPoint``, ``attachPoint`` and ``addLine``. Both start
from rest each run; skcable solves to its default tolerance (1e-10 on the scaled residual),
MoorPy ``solveEquilibrium(tol=1e-8)`` on the positions. The runs alternate between the two codes
(``--repeat`` rounds; each round times ``--block`` runs of each code in a row, their mean the
round's time, then one run of each) and the table gives the median times of the blocks and the
medians of the per-round ratios, in blocks and run by run;
both run on one BLAS thread (threadpoolctl: on a shared machine more threads only contend).
``--cpu`` times each run by the process's CPU time (``time.process_time``) instead of the wall
clock: on a loaded machine the wall clock also counts the time the process waits for a core, which
weighs most on the shortest runs. Run by run, each code starts from the caches the other one
filled, which weighs most on the shorter run; in a block, each code runs warm, as a loop of its
own calls does. The agreement column is the largest difference of the bodies'
positions (m). Both codes keep their lines' last solutions between runs (MoorPy starts each
catenary from the line's last ``HF``, ``VF``; skcable's lines solved at the start are the warm
starts of the next solve from there).

Writes the table into docs/mooring.md between its ``bench_system`` markers.

Run:  PYTHONPATH=. python benchmarks/bench_system.py [--repeat 15] [--cpu] [--block 10] [--no-write]
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.metadata
import io
import sys
import time
import warnings
from pathlib import Path

import numpy as np

from skcable import mooring

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "mooring.md"
sys.path.insert(0, str(ROOT / "benchmarks"))

from _tables import write_section  # noqa: E402

W, EA, LENGTH, DEPTH = 2456.82, 1.2326e9, 850.0, 200.0
OWN = dict(
    mass=8e6,
    volume=8.2e3,
    center_of_gravity=(0.0, 0.0, -5.0),
    metacentre=(0.0, 0.0, 10.0),
    waterplane_area=600.0,
)
FORCE = (2.0e6, 5.0e5, 0.0)
SPACING = 2000.0
SCENES = (
    ("one body, 3 lines", 1, 3),
    ("one body, 48 lines", 1, 48),
    ("16 bodies, 3 lines each (48 lines)", 4, 3),
)


def _layout(rows, n_lines):
    """``(body origin, [(anchor, fairlead in body axes)])`` of each body."""
    headings = np.radians(np.arange(n_lines) * 360.0 / n_lines)
    for i in range(rows):
        for j in range(rows):
            x0, y0 = i * SPACING, j * SPACING
            ends = [
                (
                    [x0 + 800 * np.cos(h), y0 + 800 * np.sin(h), -DEPTH],
                    [20 * np.cos(h), 20 * np.sin(h), -14.0],
                )
                for h in headings
            ]
            yield (x0, y0), ends


def skcable_scene(rows, n_lines):
    system = mooring.MooringSystem(depth=DEPTH)
    line = mooring.Line([mooring.Segment(LENGTH, W, EA)])
    loads = {}
    for (x0, y0), ends in _layout(rows, n_lines):
        body = system.add_body(mooring.RigidBody(**OWN), position=[x0, y0, 0.0, 0.0, 0.0, 0.0])
        loads[body] = FORCE
        for anchor, fairlead in ends:
            system.add_line(line, system.add_point(anchor, fixed=True), system.add_point(fairlead, body=body))
    return system, loads


def moorpy_scene(rows, n_lines):
    import moorpy

    ms = moorpy.System(depth=DEPTH)
    ms.setLineType(dnommm=120, material="chain", name="chain")
    ms.lineTypes["chain"].update(w=W, EA=EA)
    origins = []
    for (x0, y0), ends in _layout(rows, n_lines):
        origins.append(np.array([x0, y0, 0.0, 0.0, 0.0, 0.0]))
        body = ms.addBody(
            0,
            origins[-1].copy(),
            m=OWN["mass"],
            v=OWN["volume"],
            rCG=np.array(OWN["center_of_gravity"]),
            AWP=OWN["waterplane_area"],
            rM=np.array(OWN["metacentre"]),
            f6Ext=np.r_[FORCE, 0, 0, 0],
        )
        for anchor, fairlead in ends:
            ms.addPoint(1, anchor)
            a = len(ms.pointList)
            ms.addPoint(1, fairlead)
            body.attachPoint(len(ms.pointList), fairlead)
            ms.addLine(LENGTH, "chain", pointA=a, pointB=len(ms.pointList))
    ms.initialize()
    return ms, origins


def _moorpy_solve(ms, origins):
    for body, origin in zip(ms.bodyList, origins, strict=True):
        body.setPosition(origin)
    with contextlib.redirect_stdout(io.StringIO()):
        ms.solveEquilibrium(tol=1e-8, maxIter=500)


def _alternated(system, loads, ms, origins, repeat, clock, block):
    """Per-run times (s) of both codes, ``repeat`` rounds of ``block`` runs of each in a row."""
    ours, theirs = [], []
    for _ in range(repeat):
        t0 = clock()
        for _ in range(block):
            system.equilibrium(force=loads)
        t1 = clock()
        for _ in range(block):
            _moorpy_solve(ms, origins)
        t2 = clock()
        ours.append((t1 - t0) / block)
        theirs.append((t2 - t1) / block)
    return np.array(ours), np.array(theirs)


def run(repeat: int, clock=time.perf_counter, block: int = 10) -> str:
    from threadpoolctl import threadpool_limits

    rows = [
        f"| scene | dofs | skcable [ms] | MoorPy [ms] | ratio MoorPy/skcable, blocks of {block} (median) "
        "| ratio, run by run (median) | positions agree to [m] |",
        "|---|---|---|---|---|---|---|",
    ]
    with threadpool_limits(1), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name, n_rows, n_lines in SCENES:
            system, loads = skcable_scene(n_rows, n_lines)
            ms, origins = moorpy_scene(n_rows, n_lines)
            eq = system.equilibrium(force=loads)
            _moorpy_solve(ms, origins)
            diff = max(
                float(np.abs(b.position[:3] - mb.r6[:3]).max())
                for b, mb in zip(eq.bodies, ms.bodyList, strict=True)
            )
            ours, theirs = _alternated(system, loads, ms, origins, repeat, clock, block)
            one_ours, one_theirs = _alternated(system, loads, ms, origins, repeat, clock, 1)
            rows.append(
                f"| {name} | {system.n_dof} | {np.median(ours) * 1e3:.2f} | {np.median(theirs) * 1e3:.2f} | "
                f"{np.median(theirs / ours):.2f} | {np.median(one_theirs / one_ours):.2f} | {diff:.1e} |"
            )
    version = importlib.metadata.version("moorpy")
    timed = "CPU time" if clock is time.process_time else "wall clock"
    return (
        f"MoorPy {version}, `solveEquilibrium(tol=1e-8)`; skcable's default tolerance; {repeat} rounds, one "
        f"process, one BLAS thread, {timed}; each round times {block} runs of each code in a row (the "
        "times: their mean), then one run of each (the last column):\n\n" + "\n".join(rows) + "\n"
    )


def write_docs(text: str) -> None:
    notice = "<!-- written by benchmarks/bench_system.py: do not edit by hand -->"
    write_section(DOCS, "bench_system", [notice, "", *text.split("\n")])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument("--cpu", action="store_true", help="time by the process's CPU time")
    parser.add_argument("--no-write", action="store_true", help="print only, leave docs/mooring.md")
    parser.add_argument("--block", type=int, default=10, help="runs of each code in a row per round")
    args = parser.parse_args()
    text = run(args.repeat, time.process_time if args.cpu else time.perf_counter, args.block)
    print(text)
    if not args.no_write:
        write_docs(text)
        print(f"written into {DOCS}")


if __name__ == "__main__":
    main()
