"""Charts of docs/conductors.md: the parabolic change of state against the exact one, and the
natural frequencies against Irvine's closed forms across lambda^2.

Conductor: an ACSR of w0 = 15.97 N/m, EA = 2.94e7 N, alpha = 19.3e-6 /K (typical of a
"Zebra"-class conductor), level spans; reference at 15 °C, bare, with the reference sag
giving sag/span from 0.5 % to 12 %. Three states: bare at 75 °C, ice (2 w0) at -5 °C,
wind 10 N/m at 15 °C. Plotted: |H_parabola / H_exact - 1| and |sag_parabola / sag_exact - 1|
against the exact sag/span of the state.

Run:    python benchmarks/conductor_charts.py
Output: docs/img/conductors_parabola_error.png, docs/img/conductors_frequencies.png,
        the numbers on stdout.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from skcable import conductors  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "docs" / "img"
W0, EA, ALPHA = 15.97, 2.94e7, 19.3e-6
STATES = {
    "bare, 75 °C": (W0, 75.0, 0.0),
    "ice 2 w0, -5 °C": (2 * W0, -5.0, 0.0),
    "wind 10 N/m, 15 °C": (W0, 15.0, 10.0),
}


def parabola_error():
    span = 400.0
    ratios = np.geomspace(0.005, 0.12, 24)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharex=True)
    for name, (w, t, wind) in STATES.items():
        rows = []
        for ratio in ratios:
            kw = dict(EA=EA, alpha=ALPHA, w0=W0, t0=15.0, sag0=ratio * span, w=w, t=t, wind=wind)
            e = conductors.change_of_state(span, 0.0, **kw)
            p = conductors.change_of_state(span, 0.0, **kw, model="parabola")
            rows.append((e.sag / span, abs(p.H / e.H - 1), abs(p.sag / e.sag - 1)))
        rows = np.array(rows)
        axes[0].loglog(rows[:, 0], rows[:, 1], "o-", ms=3, label=name)
        axes[1].loglog(rows[:, 0], rows[:, 2], "o-", ms=3, label=name)
        print(name, "\n", np.array2string(rows, precision=4))
    axes[0].set_ylabel("|H_parabola / H_exact − 1|")
    axes[1].set_ylabel("|sag_parabola / sag_exact − 1|")
    for ax in axes:
        ax.set_xlabel("sag / span of the state (exact)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend()
    fig.suptitle(f"Parabolic vs exact change of state, level span {span:.0f} m, reference bare at 15 °C")
    fig.tight_layout()
    fig.savefig(OUT / "conductors_parabola_error.png", dpi=110)


def frequencies():
    L, w, H = 100.0, 10.0, 12500.0  # sag/span 1 %
    d = w * L**2 / (8 * H)
    L_e = L * (1 + 8 * (d / L) ** 2)
    c = np.sqrt(H * 9.81 / w)
    lam2 = np.geomspace(0.1, 2000, 60)
    fe = []
    irv = []
    for l2 in lam2:
        EA_ = l2 * H * L_e / ((w * L / H) ** 2 * L)
        r = conductors.natural_frequencies(L, 0.0, w, EA_, H=H, n_modes=4)
        fe.append(r.f_in_plane * L / c)
        irv.append(r.irvine["in_plane"] * L / c)
    fe, irv = np.array(fe), np.array(irv)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for j in range(4):
        ax.semilogx(lam2, irv[:, j], "-", color=f"C{j}", label=f"Irvine, in-plane mode {j + 1}")
        ax.semilogx(lam2[::3], fe[::3, j], "o", color=f"C{j}", ms=4, mfc="none")
    ax.axvline(4 * np.pi**2, color="k", ls="--", lw=0.8)
    ax.text(4 * np.pi**2 * 1.08, 0.55, "λ² = 4π²", fontsize=9)
    ax.set_xlabel("Irvine's λ²")
    ax.set_ylabel("f L / c,  c = √(H/m)")
    ax.set_title("In-plane frequencies: FE (circles) and Irvine's closed form (lines), sag/span 1 %")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(OUT / "conductors_frequencies.png", dpi=110)
    print("largest |FE / Irvine - 1| over lambda^2:", float(np.max(np.abs(fe / irv - 1))))


if __name__ == "__main__":
    parabola_error()
    frequencies()
