"""Accuracy against wall time of the strand model: meshes and step counts.

Steel 9.5 mm, one broken wire, 1 m, stick and stick-slip (slip="axis"). For every
(n_elements, n_steps) pair the capacity curve is timed and its K_Leq and peak curvature
(largest |curvature| over the strand and the load history) compared with a reference run
on 384 elements and 160 steps.

Run:  python benchmarks/strand_accuracy_speed.py
Output: benchmarks/out/strand_accuracy_speed.csv, docs/img/strand_accuracy_speed.png
"""

from __future__ import annotations

import csv
import time
from pathlib import Path

import numpy as np

from skcable import strand

ROOT = Path(__file__).resolve().parents[1]
MESHES = (16, 32, 64, 128, 256)
STEPS = (20, 40, 80)
REFERENCE = (384, 160)


def measure(slip, n_elements, n_steps):
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 1.0, slip=slip, n_elements=n_elements)
    start = time.perf_counter()
    curve = model.capacity_curve(n_steps=n_steps)  # raises (with its history) if a run fails
    seconds = time.perf_counter() - start
    peak = max(float(np.max(np.abs(s.curvature))) for s in curve.steps)
    return curve.K_Leq, peak, seconds


def main():
    rows = []
    for slip in ("none", "axis"):
        K_ref, peak_ref, t_ref = measure(slip, *REFERENCE)
        print(
            f"{slip}: reference {REFERENCE}: K_Leq {K_ref:.6e} N, peak curvature {peak_ref:.5g} 1/m,", end=" "
        )
        print(f"{t_ref:.1f} s")
        for n_steps in STEPS:
            for n_elements in MESHES:
                K, peak, seconds = measure(slip, n_elements, n_steps)
                row = (slip, n_elements, n_steps, seconds, abs(K / K_ref - 1), abs(peak / peak_ref - 1))
                rows.append(row)
                print(
                    f"  {slip:4s} {n_elements:4d} elements {n_steps:4d} steps {seconds:7.2f} s"
                    f"  K_Leq error {row[4]:.2e}  peak curvature error {row[5]:.2e}"
                )
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "strand_accuracy_speed.csv", "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(
            ("slip", "n_elements", "n_steps", "seconds", "rel_error_K_Leq", "rel_error_peak_curvature")
        )
        writer.writerows(rows)
    chart(rows, ROOT / "docs" / "img" / "strand_accuracy_speed.png")


def chart(rows, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, column, label in ((axes[0], 4, "K_Leq"), (axes[1], 5, "peak curvature")):
        for slip, marker in (("none", "o"), ("axis", "s")):
            for n_steps, colour in zip(STEPS, ("C0", "C1", "C2"), strict=True):
                pts = [r for r in rows if r[0] == slip and r[2] == n_steps]
                ax.loglog(
                    [r[3] for r in pts],
                    [max(r[column], 1e-16) for r in pts],
                    marker=marker,
                    color=colour,
                    ls="-" if slip == "none" else "--",
                    label=f"{'stick' if slip == 'none' else 'stick-slip'}, {n_steps} steps",
                )
        ax.set(xlabel="wall time per capacity curve [s]", title=f"relative error in {label}")
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("relative error vs 384 elements, 160 steps")
    axes[0].legend(fontsize=7)
    fig.suptitle("steel 9.5 mm, one broken wire, 1 m: meshes 16-256 elements (markers, left to right)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
