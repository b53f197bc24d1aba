"""The worked examples of the sources, published values beside skcable's.

The lecture notes "Cables": examples 1-4; J.M. Goicolea, "Cálculo de cables" (UPM, 2012):
examples 4, 5 and 7. Units as in the sources (kN, m; kg for Goicolea).
Run: ``python examples/worked_examples.py``.
"""

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


if __name__ == "__main__":
    for label, published, ours in rows():
        print(f"{label:38s} published: {published:30s} skcable: {ours}")
