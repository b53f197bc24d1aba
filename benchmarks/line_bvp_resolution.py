"""The line BVP's resolution check against the error it flags: the survey's scenes on coarse meshes.

`skcable.mooring.line_bvp.check.unresolved` (the warning of `skcable.errors.ResolutionWarning`)
says a mesh does not resolve a converged line where an element's bend ``θ_e (h_e/L)^(1/4)``
exceeds `RESOLVED_BEND` (``θ_e`` the angle its tangent turns within it). This script measures
what it flags: the scenes of the differential survey (`line_bvp_planes.scenes`, the plane line
without a slack stretch) solved by `skcable.mooring.solve_line_bvp` on ``--meshes`` elements, each
against the same scene on ``--reference`` elements (its end forces' largest difference over the
largest end force: the error), and whether the check flags it. The table is written between the
``line-bvp-resolution`` markers of docs/bvp.md (atomically) with ``--write``; each solve is a row
of ``benchmarks/out/line_bvp_resolution.csv``.

Run:  python benchmarks/line_bvp_resolution.py [--seeds 1 2 3] [--count 60] [--write]
      (about 15 minutes on 2 cores for the defaults)
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from _tables import markdown_table, write_section  # noqa: E402
from line_bvp_planes import scenes  # noqa: E402

from skcable.errors import ConvergenceError, InputError  # noqa: E402
from skcable.mooring.line_bvp.check import RESOLVED_BEND, unresolved  # noqa: E402

PAGE = ROOT / "docs" / "bvp.md"
CSV = ROOT / "benchmarks" / "out" / "line_bvp_resolution.csv"
#: the errors the table counts, of the largest end force
LEVELS = (1e-4, 1e-3)


def end_forces(line) -> np.ndarray:
    """``(H_A, V_A, H_B, V_B)`` (N)."""
    return np.array([line.H_A, line.V_A, line.H_B, line.V_B])


def solved(sc, n):
    """The plane line of ``sc`` on ``n`` elements (the check's warning silenced: it is measured
    here), or None where it fails, is refused or holds a slack stretch (out of the check's scope:
    its end is fitted, not graded)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            line = replace(sc, n_elements=n).solve_plane()
    except (ConvergenceError, InputError):
        return None
    return None if line.problem.slack_end > 0 else line


def bend(line) -> float:
    """The line's largest element bend ``θ_e (h_e/L)^(1/4)`` (the check's measure)."""
    h = np.diff(np.sort(line.problem.mesh.p[0]))
    return float(np.max(line.element_turning * (h / line.problem.L) ** 0.25))


def rows(seeds, count, meshes, reference, progress=False):
    """One row per solve: seed, scene, elements, the error against ``reference`` elements, the
    largest bend and whether the check flags it."""
    out = []
    for seed in seeds:
        for k, sc in enumerate(scenes(seed, count)):
            fine = solved(sc, reference)
            if fine is None:
                continue
            want = end_forces(fine)
            scale = np.abs(want).max()
            for n in meshes:
                line = solved(sc, n)
                if line is None:
                    continue
                error = float(np.abs(end_forces(line) - want).max() / scale)
                flagged = bool(unresolved(line))
                out.append(dict(seed=seed, scene=k, n=n, error=error, bend=bend(line), flagged=flagged))
            if progress:
                print(f"{seed}:{k}", file=sys.stderr, flush=True)
    return out


def table(found, meshes) -> list[str]:
    """The markdown table: per mesh, the solves, those flagged, the largest error of those not
    flagged, and of those off by more than each of `LEVELS`, how many are flagged."""
    body = []
    for n in [*meshes, "all"]:
        mine = [r for r in found if n == "all" or r["n"] == n]
        quiet = [r["error"] for r in mine if not r["flagged"]]
        cells = [n, len(mine), sum(r["flagged"] for r in mine), f"{max(quiet, default=0.0):.1e}"]
        for level in LEVELS:
            off = [r for r in mine if r["error"] > level]
            cells.append(f"{sum(r['flagged'] for r in off)} of {len(off)}")
        body.append(cells)
    header = ["elements", "solves", "flagged", "largest error not flagged"]
    header += [f"off by more than {level:g}: flagged" for level in LEVELS]
    return markdown_table(header, body)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--count", type=int, default=60, help="scenes per seed")
    parser.add_argument("--meshes", type=int, nargs="+", default=[12, 16, 24, 32, 64, 256])
    parser.add_argument("--reference", type=int, default=1024, help="elements of the reference solve")
    parser.add_argument("--write", action="store_true", help="write the table into docs/bvp.md")
    args = parser.parse_args(argv)
    start = time.perf_counter()
    found = rows(args.seeds, args.count, args.meshes, args.reference, progress=True)
    CSV.parent.mkdir(exist_ok=True)
    with CSV.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(found[0]))
        writer.writeheader()
        writer.writerows(found)
    seeds = " ".join(map(str, args.seeds))
    lines = [
        f"`python benchmarks/line_bvp_resolution.py --seeds {seeds} --count {args.count}` "
        f"({time.perf_counter() - start:.0f} s): the survey's scenes without a slack stretch, each on "
        f"{', '.join(map(str, args.meshes))} elements against {args.reference}; the error is the largest "
        "end force's difference over the largest end force, flagged where an element's bend "
        f"θ (h/L)^(1/4) exceeds {RESOLVED_BEND:g} (`ResolutionWarning`).",
        "",
        *table(found, args.meshes),
    ]
    print("\n".join(lines))
    if args.write:
        write_section(PAGE, "line-bvp-resolution", lines)


if __name__ == "__main__":
    main()
