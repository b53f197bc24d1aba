"""A transmission span with ice on part of it

An ACSR conductor hangs between towers at different heights. Ice forms on
the first 150 m only: a load no closed form takes. The conductor keeps its
unstretched length, so the extra weight stretches it and pulls the lowest
point toward the iced part. The bare span is checked against Irvine's
elastic catenary (closed form); the iced span is solved as a BVP with a
mesh node at the ice edge. Writes both profiles for ParaView and a figure of
the two profiles, their lowest points and the tension along the span.

Run:  python examples/transmission_ice.py [--out results/transmission_ice]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from skcable import bvp, cable

SPAN, DH = 400.0, 10.0  # m
WEIGHT = 15.97  # N/m, ACSR "Drake" conductor
EA = 2.9e7  # N
ICE = 12.0  # N/m, radial ice of about 12 mm
ICE_END = 150.0  # m, iced from the first tower to here
LENGTH = 401.2  # m, unstretched


def iced(x):
    """Downward ice load (y up, so negative) per metre of conductor."""
    return np.where(x <= ICE_END, -ICE, 0.0)


def solve():
    mesh = np.union1d(np.linspace(0.0, SPAN, 401), [ICE_END])
    bare_bvp = bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(WEIGHT)], length=LENGTH, EA=EA, mesh=mesh)
    bare = cable.elastic_catenary(SPAN, DH, WEIGHT, EA, length=LENGTH)
    ice = bvp.solve_bvp(
        SPAN, DH, [bvp.SelfWeight(WEIGHT), bvp.DistributedLoad(qy=iced)], length=LENGTH, EA=EA, mesh=mesh
    )
    return bare, bare_bvp, ice


def table(bare, bare_bvp, ice) -> str:
    lines = [f"{'case':34s} {'H [kN]':>9s} {'T_max [kN]':>11s} {'sag [m]':>8s} {'x_low [m]':>10s}"]
    for name, sol in (
        ("bare, Irvine closed form", bare),
        ("bare, BVP", bare_bvp),
        ("ice on 0-150 m, BVP", ice),
    ):
        lines.append(
            f"{name:34s} {sol.H / 1e3:9.4f} {sol.T_max / 1e3:11.4f} {sol.sag:8.3f} {sol.x_low:10.2f}"
        )
    lines.append(f"bare: BVP vs closed form, relative difference in H {abs(bare_bvp.H / bare.H - 1):.1e}")
    return "\n".join(lines)


def figure(bare, ice):
    """Both profiles with their lowest points, and their tension along the span (kN)."""
    import matplotlib.pyplot as plt

    fig, (ax_y, ax_t) = plt.subplots(1, 2, figsize=(11, 4), layout="constrained")
    for name, sol in (("bare", bare), ("ice on 0-150 m", ice)):
        samples = sol.samples(401)
        x, y = samples["xy"].T
        line = ax_y.plot(x, y, label=name)[0]
        ax_y.plot(sol.x_low, np.interp(sol.x_low, x, y), "v", color=line.get_color())
        ax_t.plot(x, samples["tension"] / 1e3, label=name)
    for ax in (ax_y, ax_t):
        ax.axvspan(0.0, ICE_END, color="C0", alpha=0.08, label="iced part" if ax is ax_y else None)
        ax.set_xlabel("x [m]")
        ax.grid(alpha=0.3)
    ax_y.set(ylabel="y [m]", title="profiles (v: lowest point)")
    ax_t.set(ylabel="tension [kN]", title="tension along the span")
    ax_y.legend()
    return fig


def main(argv=None):
    import matplotlib.pyplot as plt

    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", default="results/transmission_ice", type=Path)
    args = parser.parse_args(argv)
    bare, bare_bvp, ice = solve()
    print(table(bare, bare_bvp, ice))
    for name, sol in (("bare", bare), ("iced", ice)):
        print("wrote", sol.to_vtk(args.out / f"{name}.vtu"))
    fig = figure(bare, ice)
    fig.savefig(args.out / "profiles.png", dpi=120)
    plt.close(fig)
    print("wrote", args.out / "profiles.png")


if __name__ == "__main__":
    main()
