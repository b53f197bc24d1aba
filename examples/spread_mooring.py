"""A spread mooring pushed off station

A floating platform on a three-line spread mooring, pushed off station by a
steady force. Three chain lines, 120 degrees apart, run from anchors on a flat seabed 200 m
deep, 800 m from the platform's centre, to fairleads 20 m from it and 14 m below
the waterline. The platform is a rigid body with its own weight, buoyancy at
the metacentre and a waterplane: the hydrostatics hold it in heave, roll and
pitch, the lines in surge, sway and yaw. A steady wind and current force and
moment push it off station: we find its offset and heel, each line's tensions
and the 6x6 stiffness of the mooring at the offset position. MoorPy (M. Hall's
quasi-static mooring code at NREL) solves the same layout where it is installed,
and its numbers are printed beside ours.

Run:  python examples/spread_mooring.py [--out results/spread_mooring]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from skcable import mooring
from skcable.io._atomic import write_text

DEPTH = 200.0  # m, water depth; anchors on the seabed
ANCHOR_RADIUS, FAIRLEAD_RADIUS, FAIRLEAD_Z = 800.0, 20.0, -14.0  # m
HEADINGS = np.radians([0.0, 120.0, 240.0])  # line headings
LENGTH = 850.0  # m, unstretched
W, EA = 2456.82, 1.2326e9  # studless chain of 120 mm: weight in water (N/m), axial stiffness (N)
MASS, VOLUME = 8.0e6, 8.2e3  # kg, m^3
CG, METACENTRE = (0.0, 0.0, -5.0), (0.0, 0.0, 10.0)  # m, body axes
WATERPLANE = 600.0  # m^2
FORCE = (2.0e6, 0.5e6, 0.0)  # N: steady wind and current
MOMENT = (1.0e6, 1.0e7, 3.0e6)  # N m about the platform's reference point (at the waterline)


def layout():
    """Anchors (3, 3) and fairleads in body axes (3, 3), m."""
    c, s = np.cos(HEADINGS), np.sin(HEADINGS)
    anchors = np.column_stack([ANCHOR_RADIUS * c, ANCHOR_RADIUS * s, np.full(3, -DEPTH)])
    fairleads = np.column_stack([FAIRLEAD_RADIUS * c, FAIRLEAD_RADIUS * s, np.full(3, FAIRLEAD_Z)])
    return anchors, fairleads


def system():
    anchors, fairleads = layout()
    chain = mooring.Line([mooring.Segment(LENGTH, W, EA)], seabed=0.0)  # anchors on the seabed
    platform = mooring.RigidBody(
        fairleads,
        mass=MASS,
        volume=VOLUME,
        center_of_gravity=CG,
        metacentre=METACENTRE,
        waterplane_area=WATERPLANE,
    )
    return mooring.MooringSystem(platform, [chain] * 3, anchors, depth=DEPTH)


def solve():
    """The platform at rest and under the steady force and moment."""
    moored = system()
    return moored.equilibrium(), moored.equilibrium(force=FORCE, moment=MOMENT)


def moorpy_solve(force=FORCE, moment=MOMENT):
    """The same layout in MoorPy: its body position (6,), fairlead tensions (3,) and the 6x6
    stiffness of the lines (``Body.getStiffnessA(lines_only=True)``), or None without MoorPy."""
    try:
        import moorpy
    except ImportError:
        return None
    anchors, fairleads = layout()
    ms = moorpy.System(depth=DEPTH)
    ms.setLineType(dnommm=120, material="chain", name="chain")
    ms.lineTypes["chain"].update(w=W, EA=EA)
    ms.addBody(
        0,
        np.zeros(6),
        m=MASS,
        v=VOLUME,
        rCG=np.array(CG),
        AWP=WATERPLANE,
        rM=np.array(METACENTRE),
        f6Ext=np.concatenate([force, moment]),
    )
    for i in range(3):
        ms.addPoint(1, anchors[i])
        ms.addPoint(1, fairleads[i])
        ms.bodyList[0].attachPoint(2 * i + 2, fairleads[i])
        ms.addLine(LENGTH, "chain", pointA=2 * i + 1, pointB=2 * i + 2)
    ms.initialize()
    ms.solveEquilibrium(tol=1e-8, maxIter=500)
    body = ms.bodyList[0]
    tensions = np.array([line.TB for line in ms.lineList])
    return body.r6.copy(), tensions, body.getStiffnessA(lines_only=True, all_DOFs=True), ms


def report(rest, pushed, peer) -> str:
    out = ["A three-line spread mooring under a steady force and moment (SI units)"]
    names = ("surge x", "sway y", "heave z", "roll", "pitch", "yaw")
    units = ("m", "m", "m", "deg", "deg", "deg")
    out.append(f"{'':12s} {'at rest':>12s} {'pushed':>12s} {'MoorPy':>12s}")
    for i, (name, unit) in enumerate(zip(names, units, strict=True)):
        scale = 1.0 if i < 3 else 180.0 / np.pi
        theirs = f"{peer[0][i] * scale:12.6f}" if peer else f"{'-':>12s}"
        out.append(
            f"{name + ' [' + unit + ']':12s} {rest.position[i] * scale:12.6f} "
            f"{pushed.position[i] * scale:12.6f} {theirs}"
        )
    out.append(f"heel: {np.degrees(pushed.heel):.4f} deg")
    for i, line in enumerate(pushed.lines):
        theirs = f"{peer[1][i] / 1e3:12.3f}" if peer else f"{'-':>12s}"
        out.append(
            f"line {i}: fairlead tension {line.tension_at_fairlead / 1e3:12.3f} kN (MoorPy {theirs} kN), "
            f"on the seabed {line.solution.length_on_seabed:7.2f} m"
        )
    K = pushed.stiffness(lines_only=True)
    out.append("6x6 stiffness of the lines at the offset (N/m, N/rad, N m/rad):")
    out += ["  " + " ".join(f"{k:11.4e}" for k in row) for row in K]
    if peer:
        out.append(
            f"largest difference from MoorPy's stiffness: {np.abs(K - peer[2]).max() / np.abs(K).max():.1e}"
            " of its largest term"
        )
    return "\n".join(out)


def main(out: Path) -> None:
    import matplotlib.pyplot as plt

    from skcable import plot

    rest, pushed = solve()
    peer = moorpy_solve()
    print(report(rest, pushed, peer))
    out.mkdir(parents=True, exist_ok=True)
    pushed.to_vtk(out / "spread_mooring.vtu")
    write_text(out / "spread_mooring_tensions.csv", pushed.tensions().to_csv(index=False))
    ax = plot.mooring_profiles(pushed)
    ax.figure.savefig(out / "spread_mooring_profiles.png", dpi=120)
    plt.close(ax.figure)
    print(f"written: {out}/spread_mooring.vtu, spread_mooring_tensions.csv, spread_mooring_profiles.png")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", type=Path, default=Path("results/spread_mooring"))
    main(parser.parse_args().out)
