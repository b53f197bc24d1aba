"""Capacity study of a damaged strand, exported for ParaView.

The pipeline of the strand model: strand → model → capacity curve → files.
Steel 9.5 mm with two broken outer wires, stick and stick–slip (Cardou's
law per quadrature point and principal axis). Writes per model a CSV of
the curve, a ParaView time series of the strand axis (displacement, twist,
curvatures, axial force, moments; slip state and EI in use per element)
and of the wires on the deformed axis, and PNG figures.

Run:  python examples/strand_capacity_paraview.py [--out results/strand_capacity]
Then open ``stick-slip.pvd`` (and ``stick-slip_wires.pvd``) in ParaView,
apply *Warp By Vector* on ``displacement``, and play the time steps.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from skcable import plot, strand  # noqa: E402


def curves(length: float = 1.0):
    damaged = strand.preset("steel-9.5").damaged(2)
    return {
        label: strand.StrandModel(damaged, length, slip=slip).capacity_curve()
        for label, slip in (("stick", "none"), ("stick-slip", "axis"))
    }


def export(results, out: Path):
    written = []
    for label, curve in results.items():
        written.append(curve.to_csv(out / f"{label}.csv"))
        written.extend(curve.to_vtk(out / f"{label}.pvd", wires=True))
    ax = plot.capacity_curves(results.values(), list(results))
    written.append(out / "capacity.png")
    ax.figure.savefig(written[-1], dpi=120)
    plt.close(ax.figure)
    written.append(
        plot.render_strand(
            results["stick-slip"], out / "stick-slip_wires.png", step=len(results["stick-slip"].steps) // 3
        )
    )
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", default="results/strand_capacity", type=Path)
    args = parser.parse_args(argv)
    results = curves()
    for label, curve in results.items():
        print(
            f"{label:10s} K_Leq = {curve.K_Leq / 1e6:.4f} MN, rupture at strain {curve.strain[-1]:.5f}, "
            f"force {curve.force[-1] / 1e3:.2f} kN, D_r = {curve.D_r:.4f}"
        )
    for path in export(results, args.out):
        print("wrote", path)


if __name__ == "__main__":
    main()
