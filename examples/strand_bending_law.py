"""Bending law of damaged 1x7 strands

The stick/slip bending law of damaged 1x7 strands, after S. Pino Vidal (2021),
Figs. 3.9-3.18 and Tables 3.5-3.7. Writes M-kappa and EI-kappa families (several
friction coefficients, several axial strains, both principal axes) as PNG files and
prints Pino Vidal (2021) Tables 3.5-3.7 beside skcable's values.

Run:  python examples/strand_bending_law.py [--out results/strand_bending]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from skcable import strand  # noqa: E402

TABLE_3_5 = {0.3: 2.38e-5, 0.5: 3.98e-5, 0.7: 5.58e-5}  # 1/mm
TABLE_3_6 = {0.3: (0.299, 3888.953), 0.5: (0.431, 5035.554), 0.7: (0.516, 5782.535)}  # N, N mm
TABLE_3_7 = {0.3: (69.50, 77.23), 0.5: (100.00, 100.00), 0.7: (119.76, 114.83)}  # % of mu = 0.5
KAPPA_MAX = 2e-4  # 1/mm: range of the curves (the thesis's figures do not state theirs)


def _row(cells) -> str:
    return "| " + " | ".join(str(c) for c in cells) + " |"


def friction_family(damage: int, axis: int):
    s = strand.preset("steel-9.5").damaged(damage)
    kappa = np.linspace(0.0, KAPPA_MAX * 1e3, 801)  # 1/m
    return {mu: s.bending_law(mu=mu, axial_strain=0.004) for mu in TABLE_3_5}, kappa


def tables():
    laws, kappa = friction_family(1, 0)
    head = ["mu", "Table 3.5 kappa_m [1/mm]", "skcable axis 1", "skcable axis 2", "eq. 3.16 literal, axis 1"]
    rows = [_row([*head, "ratio axis 1 / table"]), _row(["---"] * 6)]
    for mu, law in laws.items():
        k = law.kappa_m * 1e-3
        literal = law.kappa_m_eq_3_16[0] * 1e-3
        rows.append(
            _row(
                [
                    mu,
                    f"{TABLE_3_5[mu]:.3g}",
                    f"{k[0]:.3g}",
                    f"{k[1]:.3g}",
                    f"{literal:.3g}",
                    f"{k[0] / TABLE_3_5[mu]:.2f}",
                ]
            )
        )
    head = [
        "mu",
        "Table 3.6 M-kappa [N]",
        "skcable [N]",
        "Table 3.7 [%]",
        "skcable [%]",
        "Table 3.6 EI-kappa [N mm]",
        "skcable [N mm]",
        "Table 3.7 [%]",
        "skcable [%]",
    ]
    rows += [
        "",
        f"Areas under the axis-1 curves for kappa in [0, {KAPPA_MAX:g}] 1/mm (Tables 3.6-3.7):",
        "",
        _row(head),
        _row(["---"] * 9),
    ]
    k_mm = kappa * 1e-3
    areas = {}
    for mu, law in laws.items():
        moment = law.moment(kappa, 0) * 1e3  # N mm
        stiffness = law.bending_stiffness(kappa, 0) * 1e6  # N mm^2
        areas[mu] = (np.trapezoid(moment, k_mm), np.trapezoid(stiffness, k_mm))
    ours_ref = areas[0.5]
    for mu in laws:
        t, o, printed = TABLE_3_6[mu], areas[mu], TABLE_3_7[mu]
        percent = [printed[0], 100 * o[0] / ours_ref[0], printed[1], 100 * o[1] / ours_ref[1]]
        rows.append(
            _row(
                [
                    mu,
                    t[0],
                    f"{o[0]:.3f}",
                    f"{percent[0]:.2f}",
                    f"{percent[1]:.2f}",
                    t[1],
                    f"{o[1]:.1f}",
                    f"{percent[2]:.2f}",
                    f"{percent[3]:.2f}",
                ]
            )
        )
    return "\n".join(rows)


def figures(out: Path) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    written = []
    # Figs. 3.9-3.10: friction family, damage 1, axial strain 0.004
    laws, kappa = friction_family(1, 0)
    fig, (ax_m, ax_ei) = plt.subplots(1, 2, figsize=(10, 4))
    for mu, law in laws.items():
        ax_m.plot(kappa * 1e-3, law.moment(kappa, 0) * 1e3, label=f"mu = {mu}")
        ax_ei.plot(kappa * 1e-3, law.bending_stiffness(kappa, 0) * 1e6, label=f"mu = {mu}")
    ax_m.set(
        xlabel="curvature [1/mm]", ylabel="moment [N mm]", title="steel 9.5, damage 1, axis 1, eps = 0.004"
    )
    ax_ei.set(xlabel="curvature [1/mm]", ylabel="secant EI [N mm2]")
    for ax in (ax_m, ax_ei):
        ax.legend()
        ax.grid(alpha=0.3)
    fig.tight_layout()
    written.append(out / "friction_family.png")
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)
    # Figs. 3.11-3.18: axial-strain family, damage 1 and 2, both axes, mu = 0.5
    s = strand.preset("steel-9.5")
    kappa = np.linspace(0.0, 0.6, 801)  # 1/m
    for damage in (1, 2):
        fig, axes = plt.subplots(2, 2, figsize=(10, 7))
        for axis in (0, 1):
            for eps in (0.002, 0.004, 0.006, 0.01, 0.03):
                law = s.damaged(damage).bending_law(mu=0.5, axial_strain=eps)
                axes[0, axis].plot(kappa * 1e-3, law.moment(kappa, axis) * 1e3, label=f"eps = {eps}")
                axes[1, axis].plot(
                    kappa * 1e-3, law.bending_stiffness(kappa, axis) * 1e6, label=f"eps = {eps}"
                )
            axes[0, axis].set(title=f"damage {damage}, principal axis {axis + 1}", ylabel="moment [N mm]")
            axes[1, axis].set(xlabel="curvature [1/mm]", ylabel="secant EI [N mm2]")
        for ax in axes.flat:
            ax.grid(alpha=0.3)
        axes[0, 0].legend(fontsize=8)
        fig.tight_layout()
        written.append(out / f"strain_family_damage{damage}.png")
        fig.savefig(written[-1], dpi=120)
        plt.close(fig)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--out", default="results/strand_bending", type=Path)
    args = parser.parse_args(argv)
    print(tables())
    for path in figures(args.out):
        print("wrote", path)


if __name__ == "__main__":
    main()
