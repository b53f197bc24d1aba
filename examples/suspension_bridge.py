"""Suspension-bridge main cable

A suspension bridge's main cable under the deck load plus its own weight.

The deck hangs from the cable at a constant load per horizontal metre
(``DeckLoad``); the cable's own weight acts per metre of cable
(``SelfWeight``). Neither closed form takes both: the parabola takes the
deck, the catenary the weight. The BVP solves the exact case; the parabola
with the cable weight smeared over the span is the designer's usual
estimate, shown beside it. Writes the profile for ParaView and a figure: the
profile, and the tension along the span of the three models (the deck-only
parabola misses the cable's weight; smeared over the span, the weight brings the
parabola within a fraction of a per cent of the exact cable).

Run:  python examples/suspension_bridge.py [--out results/suspension_bridge]
"""

from __future__ import annotations

import argparse
from pathlib import Path

from skcable import bvp, cable

SPAN = 1000.0  # m, main span
SAG = 100.0  # m, sag ratio 1/10
DECK = 100e3  # N/m per cable, deck and traffic per horizontal metre
WEIGHT = 15e3  # N/m, cable weight per unstretched metre
EA = 2.0e11 * 0.6  # N, steel wires, 0.6 m^2 of steel


def solve():
    """The exact BVP and two closed-form estimates, as one dict of solutions."""
    loads = [bvp.DeckLoad(DECK), bvp.SelfWeight(WEIGHT)]
    exact = bvp.solve_bvp(SPAN, 0.0, loads, sag=SAG, EA=EA, n_elements=200)
    deck_only = cable.parabola(SPAN, 0.0, DECK, sag=SAG)
    # weight smeared per horizontal metre with the parabola's length
    smeared = cable.parabola(SPAN, 0.0, DECK + WEIGHT * deck_only.length / SPAN, sag=SAG)
    return {
        "BVP (deck + weight, elastic)": exact,
        "parabola, deck only": deck_only,
        "parabola, weight smeared": smeared,
    }


def table(solutions) -> str:
    exact = solutions["BVP (deck + weight, elastic)"]
    lines = [f"{'model':30s} {'H [MN]':>10s} {'T_max [MN]':>11s} {'length [m]':>11s} {'H vs BVP':>9s}"]
    for name, sol in solutions.items():
        H, T_max = sol.H / 1e6, sol.T_max / 1e6
        lines.append(f"{name:30s} {H:10.3f} {T_max:11.3f} {sol.length:11.3f} {sol.H / exact.H - 1:+9.2%}")
    lines.append(f"BVP equilibrium residual {exact.residual():.1e}, Newton iterations {exact.iterations}")
    return "\n".join(lines)


def figure(solutions):
    """The exact profile, and the tension along the span of every model (MN)."""
    import matplotlib.pyplot as plt

    from skcable import plot

    fig, (ax_y, ax_t) = plt.subplots(1, 2, figsize=(11, 4), layout="constrained")
    plot.cable_profile(solutions["BVP (deck + weight, elastic)"], ax=ax_y, tension=False)
    ax_y.set(title="main cable, 1000 m span, sag 100 m")
    for name, sol in solutions.items():
        samples = sol.samples(201)
        ax_t.plot(samples["xy"][:, 0], samples["tension"] / 1e6, label=name)
    ax_t.set(xlabel="x [m]", ylabel="tension [MN]", title="tension along the span")
    ax_t.grid(alpha=0.3)
    ax_t.legend()
    return fig


def main(argv=None):
    import matplotlib.pyplot as plt

    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", default="results/suspension_bridge", type=Path)
    args = parser.parse_args(argv)
    solutions = solve()
    print(table(solutions))
    print("wrote", solutions["BVP (deck + weight, elastic)"].to_vtk(args.out / "main_cable.vtu"))
    fig = figure(solutions)
    fig.savefig(args.out / "main_cable.png", dpi=120)
    plt.close(fig)
    print("wrote", args.out / "main_cable.png")


if __name__ == "__main__":
    main()
