"""A polyester line in a sheared current

A semi-taut mooring line of chain, polyester rope and chain, with a clump weight where the
bottom chain meets the rope, runs from an anchor on a sloped seabed 200 m deep to a fairlead
15 m below the waterline. The polyester's stiffness grows with its load: its strain is a
working curve of (strain, tension) points (`skcable.mooring.axial.StrainTable`). A sheared
current, 1.1 m/s at the surface falling to 0.3 m/s at the seabed by a one-seventh power law,
flows 40 degrees off the line's heading and drags the line out of its vertical plane.

`mooring.line_3d` sees the current and the slope and solves the line by the 3-D line BVP on
scikit-fem, started from the closed form in the plane of the ends, and says so: which model
ran, why, and its estimated error. We print the end forces, the drag's pull across the line,
the clump's height above the seabed and the equilibrium residual, and draw the line from
above and from the side, against the same line in still water (on the slope: the 3-D BVP
again, and it says why).

Run:  python examples/polyester_in_current.py [--out results/polyester_in_current]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from skcable import mooring
from skcable.bvp.current import ProfileCurrent
from skcable.mooring.axial import StrainTable
from skcable.mooring.bathymetry import Plane

DEPTH = 200.0  # m, at the anchor
SLOPE = (0.04, 0.01)  # the seabed rises towards the fairlead
ANCHOR, FAIRLEAD = (0.0, 0.0, -DEPTH), (620.0, 0.0, -15.0)  # m
CHAIN = dict(w=1800.0, EA=1.5e9, diameter=0.17, cd_normal=2.4, cd_tangential=0.4)  # 120 mm studless
ROPE_CURVE = StrainTable([0.0, 0.01, 0.02, 0.03, 0.05], [0.0, 1.2e6, 3.0e6, 5.2e6, 1.0e7])  # polyester
ROPE = dict(w=60.0, diameter=0.16, cd_normal=1.2, cd_tangential=0.01)
LENGTHS = (150.0, 460.0, 40.0)  # m: bottom chain, rope, top chain
CLUMP = 6.0e4  # N in water, at the chain-rope joint
FRICTION = 0.6  # Coulomb's coefficient of the chain on the seabed
SURFACE_SPEED, BOTTOM_SPEED, HEADING = 1.1, 0.3, np.radians(40.0)


def speed(z):
    """The current's speed (m/s) at height ``z`` (m): a 1/7 power law from the seabed up."""
    z = np.asarray(z, dtype=float)
    share = np.clip((z + DEPTH) / DEPTH, 0.0, 1.0)
    return BOTTOM_SPEED + (SURFACE_SPEED - BOTTOM_SPEED) * share ** (1.0 / 7.0)


def current(z):
    """``(Ux, Uy)`` (m/s) at height ``z``: `speed` along the heading."""
    u = speed(z)
    return u * np.cos(HEADING), u * np.sin(HEADING)


def line(in_current: bool = True) -> mooring.Line:
    """The line from the anchor on the slope, in the current or in still water."""
    chain = {k: v for k, v in CHAIN.items() if k != "EA"}
    segments = [
        mooring.Segment(LENGTHS[0], EA=CHAIN["EA"], **chain),
        mooring.Segment(LENGTHS[1], EA=ROPE_CURVE, **ROPE),
        mooring.Segment(LENGTHS[2], EA=CHAIN["EA"], **chain),
    ]
    clump = [mooring.ClumpWeight(1, CLUMP)]
    seabed = Plane(-DEPTH, SLOPE, origin=ANCHOR[:2])
    if not in_current:
        return mooring.Line(segments, clump, seabed=seabed, friction=FRICTION)
    return mooring.Line(segments, clump, seabed=seabed, friction=FRICTION, current=ProfileCurrent(current))


def solve():
    """The line in the current, and in still water, on the slope."""
    return mooring.line_3d(line(True), ANCHOR, FAIRLEAD), mooring.line_3d(line(False), ANCHOR, FAIRLEAD)


def report(sea, still) -> str:
    Fa, Fb = sea.force_on_anchor, sea.force_on_fairlead
    clump = sea.solution.xyz(np.array(LENGTHS[0]))
    bed = float(line(True).bathymetry.height(clump[0], clump[1]))
    rows = [
        f"model: {sea.model}",
        f"still water: {still.model}",
        f"force on the fairlead: ({Fb[0]:.6g}, {Fb[1]:.6g}, {Fb[2]:.6g}) N, "
        f"tension {sea.tension_at_fairlead:.6g} N (still water {still.tension_at_fairlead:.6g} N)",
        f"force on the anchor:   ({Fa[0]:.6g}, {Fa[1]:.6g}, {Fa[2]:.6g}) N",
        f"the drag pulls the fairlead across the line by {Fb[1]:.6g} N",
        f"clump at ({clump[0]:.2f}, {clump[1]:.2f}, {clump[2]:.2f}) m, "
        f"{clump[2] - bed:.2f} m above the seabed",
        f"equilibrium residual {sea.equilibrium_residual:.3g} N/m "
        f"(bound {sea.solution.residual_bound:.3g} N/m)",
    ]
    return "\n".join(rows)


def figure(sea, still):
    """Plan view and side view of the line in the current, with the line in still water."""
    import matplotlib.pyplot as plt

    fig, (top, side) = plt.subplots(2, 1, figsize=(8.0, 8.0))
    for solved, label, style in ((sea, "in the current, on the slope", "-"), (still, "still water", "--")):
        p = solved.profile(301)
        top.plot(p[:, 0], p[:, 1], style, label=label)
        side.plot(p[:, 0], p[:, 2], style, label=label)
    joints = sea.solution.xyz(np.cumsum([0.0, *LENGTHS]))
    top.plot(joints[1, 0], joints[1, 1], "ks", label="clump")
    side.plot(joints[1, 0], joints[1, 2], "ks")
    x = np.linspace(0.0, FAIRLEAD[0], 50)
    side.plot(x, line(True).bathymetry.height(x, 0.0 * x), color="saddlebrown", label="seabed under y = 0")
    heading = f"{np.degrees(HEADING):.0f}°"
    top.set(xlabel="x (m)", ylabel="y (m)", title=f"from above (the current flows {heading} off +x)")
    side.set(xlabel="x (m)", ylabel="z (m)", title="from the side")
    for ax in (top, side):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def main(out: Path) -> None:
    import matplotlib.pyplot as plt

    sea, still = solve()
    print(report(sea, still))
    out.mkdir(parents=True, exist_ok=True)
    fig = figure(sea, still)
    fig.savefig(out / "polyester_in_current.png", dpi=120)
    plt.close(fig)
    sea.solution.to_vtk(out / "polyester_in_current.vtu")
    print(f"written: {out}/polyester_in_current.png, polyester_in_current.vtu")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", type=Path, default=Path("results/polyester_in_current"))
    main(parser.parse_args().out)
