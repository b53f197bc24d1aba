"""The sources' worked examples

The worked examples of the sources, published values beside skcable's. The lecture notes
"Cables": examples 1-4; J.M. Goicolea, "Cálculo de cables" (UPM, 2012): examples 4, 5
and 7. Units as in the sources (kN, m; kg for Goicolea). The figure shows, for each row,
the largest relative difference between a published value and skcable's beside half a
unit of the last digit the source prints: a difference below that mark is the source's
rounding.

Run: ``python examples/worked_examples.py [--out results/worked_examples]``.
"""

import argparse
from pathlib import Path

import numpy as np

from skcable import cable


def rows():
    f1 = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    yield "000 ex.1 tensions [kN]", "233.04 205.38 205.66 237.85", " ".join(f"{t:.2f}" for t in f1.T)
    yield "000 ex.1 angles [deg]", "-26.7 -8.3 20.0 37.7", " ".join(f"{a:.1f}" for a in np.degrees(f1.angles))
    f2 = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    yield "000 ex.2 H, V_A, V_B [kN]", "28.511 80.851 39.149", f"{f2.H:.3f} {f2.V_A:.3f} {f2.V_B:.3f}"
    yield "000 ex.2 tensions [kN]", "85.731 42.008 28.523 48.43", " ".join(f"{t:.3f}" for t in f2.T)
    p3 = cable.parabola(800, -20, 20, low=-30)
    yield "000 ex.3 x_m, H, f", "507.18 85743.7 18.66", f"{p3.x_low:.2f} {p3.H:.1f} {p3.sag:.2f}"
    yield "000 ex.3 T_A, T_B, S", "86341.7 85943.5 801.408", f"{p3.T_A:.1f} {p3.T_B:.1f} {p3.length:.3f}"
    c4 = cable.catenary(800, -20, 20, low=-30)
    yield "000 ex.4 x_m, H (the notes stopped early)", "507.107 85818.7", f"{c4.x_low:.3f} {c4.H:.1f}"
    yield "000 ex.4 T_A, T_B, S", "86418.7 86018.7 801.409", f"{c4.T_A:.1f} {c4.T_B:.1f} {c4.length:.3f}"
    p4 = cable.parabola(200, 0, 1, sag=20)
    yield "001 ex.4 T0, Tmax, S", "250.0 269.26 205.2121", f"{p4.H:.1f} {p4.T_max:.2f} {p4.length:.4f}"
    c5 = cable.catenary(200, 0, 1, sag=20)
    yield "001 ex.5 T0, Tmax, S", "253.2649 273.2649 205.2374", f"{c5.H:.4f} {c5.T_max:.4f} {c5.length:.4f}"
    c7 = cable.catenary(2.0, 0.0, 1.0, H=1 / np.arcsinh(0.05))
    k7 = cable.geometric_stiffness(c7) * 2.0 / (c7.w * c7.length)
    yield "001 ex.7 a/x, k_G [Q/L]", "20.00832744 12021.99", f"{c7.a:.8f} {k7:.5f}"


def agreement(table):
    """Per row: the largest relative difference, and half a unit of the last printed digit."""
    out = []
    for label, published, ours in table:
        pub, our = np.array(published.split(), float), np.array(ours.split(), float)
        digits = [len(p.split(".")[1]) if "." in p else 0 for p in published.split()]
        rounding = 0.5 * 10.0 ** -np.array(digits, float) / np.abs(pub)
        out.append((label, float(np.max(np.abs(our / pub - 1))), float(np.max(rounding))))
    return out


def figure(table):
    import matplotlib.pyplot as plt

    rows_ = agreement(table)
    fig, ax = plt.subplots(figsize=(9, 5), layout="constrained")
    y = np.arange(len(rows_))
    floor = 1e-9  # left edge of the axis
    ax.barh(y, [max(d, floor) for _, d, _ in rows_], color="C0", label="|skcable / published - 1|, largest")
    for yi, (_, d, _) in zip(y, rows_, strict=True):
        if d == 0.0:
            ax.text(1.5 * floor, yi, "equal in every printed digit", va="center", fontsize="small")
    ax.plot([r for *_, r in rows_], y, "|", color="C3", ms=14, mew=2, label="half a unit of the last digit")
    ax.set(yticks=y, yticklabels=[label for label, *_ in rows_], xscale="log", xlabel="relative difference")
    ax.set_xlim(left=floor)
    ax.invert_yaxis()
    ax.set_title("skcable against the sources' worked examples")
    ax.legend(loc="lower right", fontsize="small")
    return fig


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", type=Path, default=Path("results/worked_examples"))
    out = parser.parse_args().out
    table = list(rows())
    for label, published, ours in table:
        print(f"{label:38s} published: {published:30s} skcable: {ours}")
    import matplotlib.pyplot as plt

    fig = figure(table)
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "agreement.png", dpi=120)
    plt.close(fig)
    print("wrote", out / "agreement.png")
