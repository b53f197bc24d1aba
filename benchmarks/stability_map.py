"""Stability map of the suspended-cable solvers, skcable's and the peers', one process.

A grid of scenes, span 100 m, w = 1 N/m: length/chord from 1 + 1e-9 to 100 and dh/span from
-100 to 100 (nearly vertical spans included), inextensible and elastic (EA = 1e3 times the
cable's weight). Every method's H is compared with a 40-digit mpmath solution (Irvine's
equations, or the inextensible catenary) and each run is classified:

- right: converged, |H / H_exact - 1| <= max(1e-8, 8 eps cond), cond = S / (2 (S - c)) the
  condition number of H in the length (S the length, c the chord): the data themselves
  (the chord hypot(span, dh) rounded to double precision) carry an error of eps·cond in H,
  which no double-precision solver can beat; the strict count (1e-8 alone) is printed too;
- wrong: returned an answer farther than that;
- failed: raised (the message is kept in the CSV);
- n/a: the method does not model the scene (the peers are elastic solvers: they are run on
  the elastic half only).

Methods: skcable closed form (catenary / elastic_catenary), skcable BVP graph form and arc
form (P2, the mesh doubled from 64 elements until two meshes agree within 1e-10, at most 4096),
skcable line BVP (`solve_line_bvp`: the arc form on meshes graded by the line's turning, the
mesh doubled alike, or until the change between meshes stops falling: the round-off regime),
skcable bvp.solve(rtol=1e-9), MoorPy catenary(), pycatenary MooringLine, OpenSeesPy
CatenaryCable.

Run:  python benchmarks/stability_map.py            (about 15 minutes)
      python benchmarks/stability_map.py --replot   (counts and chart again from the CSV)
Output: benchmarks/out/stability_map.csv, docs/img/stability_map.png, counts on stdout.
"""

from __future__ import annotations

import csv
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _peers import moorpy_H, opensees_catenary_cable_H, pycatenary_H  # noqa: E402
from _reference import catenary_H, irvine_H  # noqa: E402

from skcable import bvp, cable, mooring  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SPAN, W = 100.0, 1.0
EXCESS = (1e-9, 1e-7, 1e-5, 1e-3, 1e-1, 1.0, 10.0, 99.0)  # length/chord - 1
DH_OVER_SPAN = (-100.0, -10.0, -1.0, -0.1, 0.0, 0.1, 1.0, 10.0, 100.0)
TOL = 1e-8
STATUSES = ("right", "wrong", "failed", "n/a")


def tolerance(dh, length):
    """1e-8, or the round-off floor eps·cond of the data when larger (see the module text)."""
    chord = float(np.hypot(SPAN, dh))
    return max(TOL, 8 * np.finfo(float).eps * length / (2 * (length - chord)))


def bvp_converged(dh, length, EA, formulation):
    """Mesh doubled until two successive H agree within 1e-10 (at most 4096 elements)."""
    n, previous = 64, None
    while n <= 4096:
        sol = bvp.solve_bvp(
            SPAN, dh, bvp.SelfWeight(W), length=length, EA=EA, n_elements=n, formulation=formulation
        )
        if previous is not None and abs(sol.H / previous - 1) < 1e-10:
            return sol.H
        previous, n = sol.H, 2 * n
    raise RuntimeError(f"mesh not converged at 4096 elements (last H {previous:.12g})")


def line_bvp_converged(dh, length, EA):
    """`solve_line_bvp` (graded P2 arc form), the mesh doubled from 64 elements until two
    successive H agree within 1e-10, or until their change stops falling (at most 4096): the
    round-off of a nearly taut line's H grows with the mesh (the positions carry eps L each, H
    amplifies the length by cond = S/(2(S - c)): n eps cond on n elements) and outgrows its
    discretisation error; then the coarser of the last two meshes."""
    n, previous, change = 64, None, np.inf
    while n <= 4096:
        H = mooring.solve_line_bvp(SPAN, dh, [(length, W, EA)], n_elements=n).H
        if previous is not None:
            now = abs(H / previous - 1)
            if now < 1e-10:
                return H
            if now >= change:
                return previous
            change = now
        previous, n = H, 2 * n
    raise RuntimeError(f"mesh not converged at 4096 elements (last H {previous:.12g})")


def methods(elastic):
    closed = (
        (lambda dh, L, EA: cable.elastic_catenary(SPAN, dh, W, EA, length=L).H)
        if elastic
        else (lambda dh, L, EA: cable.catenary(SPAN, dh, W, length=L).H)
    )
    ours = {
        "skcable closed form": closed,
        "skcable BVP graph": lambda dh, L, EA: bvp_converged(dh, L, EA, "graph"),
        "skcable BVP arc": lambda dh, L, EA: bvp_converged(dh, L, EA, "arc"),
        "skcable line BVP": line_bvp_converged,
        "skcable solve(rtol=1e-9)": lambda dh, L, EA: (
            bvp.solve(SPAN, dh, bvp.SelfWeight(W), length=L, EA=EA, rtol=1e-9).H
        ),
    }
    peers = {
        "MoorPy": lambda dh, L, EA: moorpy_H(SPAN, dh, W, EA, L),
        "pycatenary": lambda dh, L, EA: pycatenary_H(SPAN, dh, W, EA, L),
        "OpenSees CatenaryCable": lambda dh, L, EA: opensees_catenary_cable_H(SPAN, dh, W, EA, L),
    }
    return ours, peers


def run():
    rows = []
    for elastic in (False, True):
        ours, peers = methods(elastic)
        for ratio in DH_OVER_SPAN:
            dh = ratio * SPAN
            for excess in EXCESS:
                length = float(np.hypot(SPAN, dh) * (1.0 + excess))
                EA = 1e3 * W * length if elastic else None
                exact = irvine_H(SPAN, dh, W, EA, length) if elastic else catenary_H(SPAN, dh, W, length)
                for name, fn in {**ours, **peers}.items():
                    if name in peers and not elastic:
                        rows.append((elastic, ratio, excess, name, "n/a", "", ""))
                        continue
                    try:
                        with warnings.catch_warnings():
                            warnings.simplefilter("ignore")
                            H = float(fn(dh, length, EA))
                        error = abs(H / exact - 1)
                        status = "right" if error <= tolerance(dh, length) else "wrong"
                        message = ""
                    except Exception as exc:  # noqa: BLE001 - a peer's failure is data here
                        status, error, message = (
                            "failed",
                            "",
                            f"{type(exc).__name__}: {exc}".splitlines()[0][:160],
                        )
                    if status == "wrong" and not np.isfinite(H):
                        status, message = "failed", f"returned {H}"
                    rows.append((elastic, ratio, excess, name, status, error, message))
    return rows


def chart(rows, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    names = list(dict.fromkeys(r[3] for r in rows))
    colours = ListedColormap(["#2a9d55", "#e9a23b", "#d1495b", "#dddddd"])
    fig, axes = plt.subplots(2, len(names), figsize=(2.6 * len(names), 6.2), sharex=True, sharey=True)
    for row, elastic in enumerate((False, True)):
        for col, name in enumerate(names):
            grid = np.full((len(DH_OVER_SPAN), len(EXCESS)), 3)
            for e, ratio, excess, n, status, *_ in rows:
                if e == elastic and n == name:
                    grid[DH_OVER_SPAN.index(ratio), EXCESS.index(excess)] = STATUSES.index(status)
            ax = axes[row, col]
            ax.imshow(grid, cmap=colours, vmin=0, vmax=3, origin="lower", aspect="auto")
            if row == 0:
                ax.set_title(name, fontsize=8)
            ax.set_xticks(range(len(EXCESS)), [f"{e:g}" for e in EXCESS], rotation=90, fontsize=6)
            ax.set_yticks(range(len(DH_OVER_SPAN)), [f"{d:g}" for d in DH_OVER_SPAN], fontsize=6)
        axes[row, 0].set_ylabel(("elastic" if elastic else "inextensible") + "\ndh / span")
    for ax in axes[1]:
        ax.set_xlabel("length/chord - 1", fontsize=7)
    handles = [plt.Rectangle((0, 0), 1, 1, color=colours(i)) for i in range(4)]
    fig.legend(
        handles,
        ["right (1e-8, or the round-off floor)", "wrong", "failed", "n/a"],
        loc="upper right",
        ncol=4,
        fontsize=8,
    )
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(path, dpi=110)


def read(path):
    rows = []
    with open(path) as fh:
        for elastic, ratio, excess, name, status, error, message in list(csv.reader(fh))[1:]:
            ratio, excess = float(ratio), float(excess)
            if status in ("right", "wrong"):
                length = float(np.hypot(SPAN, ratio * SPAN) * (1.0 + excess))
                status = "right" if float(error) <= tolerance(ratio * SPAN, length) else "wrong"
            rows.append((elastic == "True", ratio, excess, name, status, error, message))
    return rows


def main(argv=None):
    out = ROOT / "benchmarks" / "out"
    replot = "--replot" in (sys.argv[1:] if argv is None else argv)
    rows = read(out / "stability_map.csv") if replot else run()
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "stability_map.csv", "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(
            (
                "elastic",
                "dh_over_span",
                "length_over_chord_minus_1",
                "method",
                "status",
                "rel_error_H",
                "error",
            )
        )
        writer.writerows(rows)
    chart(rows, ROOT / "docs" / "img" / "stability_map.png")
    names = list(dict.fromkeys(r[3] for r in rows))
    print(f"{'method':28s} " + " ".join(f"{s:>7s}" for s in STATUSES))
    for name in names:
        counts = [sum(1 for r in rows if r[3] == name and r[4] == s) for s in STATUSES]
        strict = sum(1 for r in rows if r[3] == name and r[4] in ("right", "wrong") and float(r[5]) <= TOL)
        print(f"{name:28s} " + " ".join(f"{c:7d}" for c in counts) + f"   (right at 1e-8 strictly: {strict})")
    for r in rows:
        if r[3].startswith("skcable") and r[4] in ("wrong", "failed"):
            print("skcable not right:", r)


if __name__ == "__main__":
    main()
