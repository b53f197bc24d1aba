"""The line BVP's resolution check against the error it flags: the survey's scenes on coarse meshes.

`skcable.mooring.line_bvp.check.unresolved` (the warning of `skcable.errors.ResolutionWarning`)
says a mesh does not resolve a converged line where an element's bend ``θ_e (h_e/L)^(1/4)``
exceeds `RESOLVED_BEND` (``θ_e`` the angle its tangent turns within it), or where the solve's
quadrature misplaces more than `RESOLVED_WEIGHT` of a weight varying along it. This script measures
what it flags: the scenes of the differential survey (`line_bvp_planes.scenes`, the plane line
without a slack stretch) solved by `skcable.mooring.solve_line_bvp` on ``--meshes`` elements, each
against the same scene on ``--reference`` elements (its end forces' largest difference over the
largest end force: the error), and whether the check flags it; and each scene with
``n_elements="auto"`` (`skcable.mooring.line_bvp.resolution`: more elements while the check flags
the line), its error and the elements it took. The tables are written between the
``line-bvp-resolution`` markers of docs/bvp.md (atomically) with ``--write``; each solve is a row
of ``benchmarks/out/line_bvp_resolution.csv``.

Run:  python benchmarks/line_bvp_resolution.py [--seeds 1 2 3] [--count 60] [--write]
      (about 15 minutes on 2 cores for the defaults; ``--report``: the table of the last CSV)
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
from skcable.mooring.line_bvp.check import (  # noqa: E402
    RESOLVED_BEND,
    RESOLVED_WEIGHT,
    element_bends,
    unresolved,
)
from skcable.mooring.line_bvp.resolution import AUTO  # noqa: E402

PAGE = ROOT / "docs" / "bvp.md"
CSV = ROOT / "benchmarks" / "out" / "line_bvp_resolution.csv"
#: the errors the table counts, of the largest end force
LEVELS = (1e-4, 1e-3)
#: a flagged line within this of the reference is counted as close (a warning it did not need)
CLOSE = 1e-5


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


def rows(seeds, count, meshes, reference, progress=False):
    """One row per solve: seed, scene, elements (``n``: a number of ``meshes``, or ``"auto"``), the
    elements it took, the error against ``reference`` elements, the largest bend and whether the
    check flags it."""
    out = []
    for seed in seeds:
        for k, sc in enumerate(scenes(seed, count)):
            fine = solved(sc, reference)
            if fine is None:
                continue
            want = end_forces(fine)
            scale = np.abs(want).max()
            for n in [*meshes, AUTO]:
                line = solved(sc, n)
                if line is None:
                    continue
                error = float(np.abs(end_forces(line) - want).max() / scale)
                flagged, bend = bool(unresolved(line)), float(np.max(element_bends(line)[0]))
                row = dict(seed=seed, scene=k, n=n, taken=line.n_elements, error=error, bend=bend)
                out.append({**row, "flagged": flagged})
            if progress:
                print(f"{seed}:{k}", file=sys.stderr, flush=True)
    return out


def table(found, meshes) -> list[str]:
    """The markdown table: per mesh, the solves, those flagged (and of them, those within
    `CLOSE` and their median error), the largest error of those not flagged, and of those off by
    more than each of `LEVELS`, how many are flagged."""
    body = []
    for n in [*meshes, "all"]:
        mine = [r for r in found if r["n"] == n or n == "all" and r["n"] != AUTO]
        quiet = [r["error"] for r in mine if not r["flagged"]]
        flagged = [r["error"] for r in mine if r["flagged"]]
        median = f"{np.median(flagged):.1e}" if flagged else "-"
        close = sum(e <= CLOSE for e in flagged)
        cells = [n, len(mine), len(flagged), close, median, f"{max(quiet, default=0.0):.1e}"]
        for level in LEVELS:
            off = [r for r in mine if r["error"] > level]
            cells.append(f"{sum(r['flagged'] for r in off)} of {len(off)}")
        body.append(cells)
    header = ["elements", "solves", "flagged", f"flagged within {CLOSE:g}", "median error flagged"]
    header += ["largest error not flagged", *(f"off by more than {level:g}: flagged" for level in LEVELS)]
    return markdown_table(header, body)


def auto_table(found) -> list[str]:
    """The markdown table of the ``"auto"`` solves: how many took each number of elements, the
    largest and median errors of those, and how many are off by more than each of `LEVELS`."""
    auto = [r for r in found if r["n"] == AUTO]
    body = []
    for taken in sorted({r["taken"] for r in auto}):
        errors = [r["error"] for r in auto if r["taken"] == taken]
        cells = [taken, len(errors), sum(r["flagged"] for r in auto if r["taken"] == taken)]
        cells += [f"{np.median(errors):.1e}", f"{max(errors):.1e}"]
        cells += [sum(e > level for e in errors) for level in LEVELS]
        body.append(cells)
    header = ["elements taken (auto)", "solves", "flagged still", "median error", "largest error"]
    return markdown_table(header + [f"off by more than {level:g}" for level in LEVELS], body)


def read_rows(path=CSV) -> list[dict]:
    """The rows of a previous run's CSV (``--report``)."""

    def n_of(text):
        return text if text == AUTO else int(text)

    with path.open(newline="") as fh:
        return [
            dict(seed=int(r["seed"]), scene=int(r["scene"]), n=n_of(r["n"]),
                 taken=int(r.get("taken") or r["n"]), error=float(r["error"]), bend=float(r["bend"]),
                 flagged=r["flagged"] == "True")
            for r in csv.DictReader(fh)
        ]  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--count", type=int, default=60, help="scenes per seed")
    parser.add_argument("--meshes", type=int, nargs="+", default=[12, 16, 24, 32, 64, 256])
    parser.add_argument("--reference", type=int, default=1024, help="elements of the reference solve")
    parser.add_argument("--write", action="store_true", help="write the table into docs/bvp.md")
    parser.add_argument("--report", action="store_true", help="the table of the last run's CSV, no solve")
    args = parser.parse_args(argv)
    start = time.perf_counter()
    if args.report:
        found = read_rows()
    else:
        found = rows(args.seeds, args.count, args.meshes, args.reference, progress=True)
        CSV.parent.mkdir(exist_ok=True)
        temp = CSV.with_suffix(".csv.tmp")
        with temp.open("w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=list(found[0]))
            writer.writeheader()
            writer.writerows(found)
        temp.replace(CSV)
    seeds = " ".join(map(str, args.seeds))
    when = "its last CSV, --report" if args.report else f"{time.perf_counter() - start:.0f} s"
    lines = [
        f"`python benchmarks/line_bvp_resolution.py --seeds {seeds} --count {args.count}` "
        f"({when}): the survey's scenes without a slack stretch, each on "
        f"{', '.join(map(str, args.meshes))} elements against {args.reference}; the error is the largest "
        "end force's difference over the largest end force, flagged where an element's bend "
        f"θ (h/L)^(1/4) exceeds {RESOLVED_BEND:g} or the quadrature misplaces more than "
        f"{RESOLVED_WEIGHT:g} of the line's weight (`ResolutionWarning`).",
        "",
        *table(found, args.meshes),
        "",
        f'The same scenes with `n_elements="auto"` (64 elements, four times as many while the check '
        f"flags the line, up to 1024), against {args.reference}:",
        "",
        *auto_table(found),
    ]
    print("\n".join(lines))
    if args.write:
        write_section(PAGE, "line-bvp-resolution", lines)


if __name__ == "__main__":
    main()
