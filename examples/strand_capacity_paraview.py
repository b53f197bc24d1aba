"""Capacity of a damaged strand, for ParaView

The pipeline of the strand model: strand → model → capacity curve → files.
Steel 9.5 mm with two broken outer wires, stick and stick–slip (Cardou's
law per quadrature point and principal axis). Writes per model a CSV of
the curve, a ParaView time series of the strand axis (displacement, twist,
curvatures, axial force, moments; slip state and EI in use per element)
and of the wires on the deformed axis, and PNG figures.

The force curves of the two models lie on top of each other: what slip changes
is the stiffness at small strain. The first figure shows, beside the force, the
secant stiffness ``F / (EA ε)`` (``EA`` of the damaged section: 1 is a strand
without bending) and the fraction of the length in slip
(``skcable.plot.secant_stiffness``). Slipping wires soften the strand at small
strain. The critical curvature κ_m, where the wires start to slip, grows with the
axial strain (the friction grips harder as the wires' tension rises); where it
passes the curvature the broken wires impose, the strand re-sticks and the slip
fraction falls from about 90 % to a few per cent (``CapacityCurve.restick``: the
figure marks it, the script prints its strains). The second figure is the pyvista
render of the wires at a third of the curve, not to scale: the length is drawn at
1/20 and the displacements 10 times (``RENDER_SCALES``, printed on the picture),
coloured by wire stress.

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

RENDER_SCALES = {"xscale": 0.05, "scale": 10.0}  # the render: length x 1/20, displacements x 10


def curves(length: float = 1.0):
    damaged = strand.preset("steel-9.5").damaged(2)
    return {
        label: strand.StrandModel(damaged, length, slip=slip).capacity_curve()
        for label, slip in (("stick", "none"), ("stick-slip", "axis"))
    }


def capacity_figure(results):
    """Force beside the secant stiffness F/(EA ε), with the slip fraction and where the strand
    re-sticks (`skcable.plot.secant_stiffness`)."""
    fig, (ax_f, ax_k) = plt.subplots(1, 2, figsize=(12, 4.2), layout="constrained")
    plot.capacity_curves(results.values(), list(results), ax=ax_f)
    plot.secant_stiffness(results.values(), list(results), ax=ax_k, at=0.002)
    return fig


def export(results, out: Path):
    written = []
    for label, curve in results.items():
        written.append(curve.to_csv(out / f"{label}.csv"))
        written.extend(curve.to_vtk(out / f"{label}.pvd", wires=True))
    fig = capacity_figure(results)
    written.append(out / "capacity.png")
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)
    written.append(
        plot.render_strand(
            results["stick-slip"],
            out / "stick-slip_wires.png",
            step=len(results["stick-slip"].steps) // 3,
            **RENDER_SCALES,
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
    for label, curve in results.items():
        cliff = curve.restick()
        print(
            f"{label:10s} F/(EA eps) at eps = 0.002: {curve.secant(0.002) / curve.model.EA:.3f}"
            + (
                f"; re-sticks between strain {cliff.strain_before:.4f} and {cliff.strain_after:.4f}"
                if cliff
                else ""
            )
        )
    for path in export(results, args.out):
        print("wrote", path)


if __name__ == "__main__":
    main()
