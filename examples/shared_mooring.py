"""Two floating turbines on a shared mooring

Two floating wind turbines 1400 m apart, each held by two chain lines to anchors on a seabed
200 m deep, share a third line between them: a light chain that sags onto the seabed midway. A
steady wind and current force pushes the first turbine towards the second. We find where both
turbines settle, each line's tensions and the model each line takes (the shared line touches
down between its two suspended ends: a closed form), the anchor loads and uplift, each segment's
tension against the breaking load of its chain (DNV-OS-E302's grade R3 formula) and the 12 x 12
stiffness of the two hulls. Then the first turbine's upwind line fails: the damaged system's
equilibrium beside the intact one, and how the tensions redistribute.

Run:  python examples/shared_mooring.py [--out results/shared_mooring]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from skcable import mooring
from skcable.io._atomic import write_text

DEPTH, SPACING = 200.0, 1400.0  # m
HULL = dict(
    mass=8.0e6, volume=8.2e3, center_of_gravity=(0, 0, -5.0), metacentre=(0, 0, 10.0), waterplane_area=600.0
)
FORCE = (1.5e6, 3.0e5, 0.0)  # N: wind and current on the first turbine
SAFETY = 1.67  # the safety factor checked (a design code's, for the condition checked)


def system():
    """The two turbines, their four anchor lines and the shared line; returns (system, turbines, lines)."""
    chain = mooring.component("studless chain R3")
    anchor_line = mooring.Line([chain.segment(850.0, 0.12)], seabed=0.0, friction=0.6)
    shared = mooring.Line([chain.segment(1500.0, 0.076)])  # no friction: it touches down between its ends
    moored = mooring.MooringSystem(depth=DEPTH)
    turbines, lines = [], []
    for i, x0 in enumerate((0.0, SPACING)):
        hull = moored.add_body(mooring.RigidBody(**HULL), position=[x0, 0.0, 0.0, 0.0, 0.0, 0.0])
        turbines.append(hull)
        for heading in np.radians((120.0, 240.0) if i == 0 else (60.0, -60.0)):
            c, s = np.cos(heading), np.sin(heading)
            anchor = moored.add_point([x0 + 800 * c, 800 * s, -DEPTH], fixed=True)
            lines.append(
                moored.add_line(anchor_line, anchor, moored.add_point([20 * c, 20 * s, -14.0], body=hull))
            )
    a = moored.add_point([20.0, 0.0, -14.0], body=turbines[0])
    b = moored.add_point([-20.0, 0.0, -14.0], body=turbines[1])
    lines.append(moored.add_line(shared, a, b))
    return moored, turbines, lines


def solve():
    """The intact equilibrium and the failure of the first turbine's first line."""
    moored, turbines, lines = system()
    loads = {turbines[0]: FORCE}
    return moored, moored.failure([lines[0]], force=loads)


def report(case) -> str:
    intact = case.intact
    out = ["Two turbines on a shared mooring (SI units)"]
    for body in intact.bodies:
        x, y, z = body.offset
        out.append(
            f"turbine {body.index}: x = {x:9.3f} m, y = {y:8.3f} m, z = {z:7.4f} m, heel "
            f"{np.degrees(body.heel):.3f} deg"
        )
    for k, line in zip(intact.line_indices, intact.lines, strict=True):
        out.append(
            f"line {k}: {line.model:27s} T_a = {line.tension_a / 1e3:9.1f} kN, "
            f"T_b = {line.tension_b / 1e3:9.1f} kN"
        )
    anchors = intact.anchor_loads()
    for row in anchors.itertuples():
        out.append(
            f"anchor at point {row.point}: horizontal {row.horizontal / 1e3:8.1f} kN, uplift angle "
            f"{row.uplift_angle_deg:.2f} deg"
        )
    checks = intact.segment_checks(safety_factor=SAFETY)
    worst = checks.loc[checks["utilisation"].idxmax()]
    out.append(
        f"largest utilisation {worst['utilisation']:.3f} (line {int(worst['line'])}, safety factor {SAFETY})"
    )
    K = intact.stiffness(condensed=True)
    out.append(
        f"stiffness of the two hulls: 12 x 12, surge terms {K[0, 0]:.4e} and {K[6, 6]:.4e} N/m, "
        f"coupling {K[0, 6]:.4e} N/m"
    )
    out.append("after line 0 fails:")
    for row in case.redistribution().itertuples():
        state = "failed" if row.failed else f"{row.T_damaged / 1e3:9.1f} kN ({row.ratio:5.2f} x)"
        out.append(f"  line {row.line}: {row.T_intact / 1e3:9.1f} kN -> {state}")
    moved = case.offsets()
    out.append("  turbines move by " + ", ".join(f"{d:.2f} m" for d in moved["distance"]))
    return "\n".join(out)


def main(out: Path) -> None:
    import matplotlib.pyplot as plt

    from skcable import plot

    _, case = solve()
    print(report(case))
    out.mkdir(parents=True, exist_ok=True)
    case.intact.to_vtk(out / "shared_mooring.vtu")
    write_text(out / "shared_mooring_tensions.csv", case.intact.tensions().to_csv(index=False))
    fig = plot.mooring_overview(case.intact)
    fig.savefig(out / "shared_mooring.png", dpi=110)
    plt.close(fig)
    print(f"written: {out}/shared_mooring.vtu, shared_mooring_tensions.csv, shared_mooring.png")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", type=Path, default=Path("results/shared_mooring"))
    main(parser.parse_args().out)
