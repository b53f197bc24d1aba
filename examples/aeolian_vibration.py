"""Aeolian vibration, from friction to fatigue

From the friction between the wires to the fatigue life at a suspension clamp (issue 35).

- **Bending as measured.** The layer-by-layer stick/slip law of an ACSR Cardinal (54/7) at
  40 kN and μ = 0.7 (`skcable.strand.LayerSlipLaw`) beside the 18 measured points (Foti &
  Martinelli 2018, as shipped with RTE's strdcable) and the single-knee law it replaces.
- **Loops.** Masing loops of ACSR Drake at 28 kN (`StageLaw.loop`), the energy per cycle
  (`energy_per_cycle`) and the model's own self-damping exponents (`damping_exponents`).
- **Amplitude.** The antinode amplitude y_max(f) where CIGRE's wind power equals the damping
  (`aeolian_amplitude`), for the intact Drake and with three outer wires broken (both principal
  axes), with the conductor's own damping and with Foti & Martinelli's closed form.
- **Life.** The Poffenberger–Swart stress at the clamp (Y_b peak to peak at 89 mm) and the life
  on the CIGRE Safe Border Line for an assumed 2000 h a year of vibration spread evenly over the
  Strouhal band of winds of 1 to 7 m/s (`aeolian_vibration`): an illustration of the chain, not a
  site's wind statistics.

Prints its numbers and writes four figures (``cardinal_bending.png``, ``loops.png``,
``amplitude.png``, ``life.png``) and a table (``aeolian_vibration.csv``) to ``--out``.

Run:  python examples/aeolian_vibration.py [--out results/aeolian_vibration]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from skcable import conductors, strand

#: ACSR Cardinal at 40 kN: (curvature 1/m, moment N·m), the file FLEXION_CARDINAL_H40kN_mu0.7_FOTI.csv
#: of rte-france/pallas-stranded-cable (commit a5027231), credited to Foti & Martinelli (2018);
#: also tests/strand/data/cardinal_bending_40kN.csv (tests/test_examples.py checks they agree).
CARDINAL_MEASURED = np.array([
    [0.0034717963716, 5.49543855015], [0.0083313678689, 13.0516901422], [0.013206034133, 22.8057397851],
    [0.0166778305046, 28.3011783352], [0.0491127107371, 50.8374765324], [0.0608271932224, 56.4725416757],
    [0.0711491834675, 59.3599818863], [0.0849080634358, 62.6604526543], [0.102788758172, 66.0994179081],
    [0.122727058313, 69.126862081], [0.142665358454, 72.154306254], [0.168093436607, 74.4964480127],
    [0.196952743946, 76.4274460598], [0.238861477212, 78.362029114], [0.304803909545, 79.6164042379],
    [0.368002868006, 81.4194741361], [0.428451748634, 82.8097021614], [0.500581148523, 84.8899497156],
])  # fmt: skip
T_DRAKE = 28e3  # N, 20 % of Drake's rated strength
STROUHAL = 0.185  # f = S V / D
HOURS = 2000.0  # h/year of vibration, spread evenly over the band (an assumption)


def cardinal():
    """The Cardinal's layer law at 40 kN, the single-knee law at the same strain, the errors."""
    s = strand.preset("acsr-cardinal")
    law = strand.LayerSlipLaw(s.section(), mu=0.7, tension=40e3)
    single = s.bending_law(mu=0.7, axial_strain=law.axial_strain)
    kappa, moment = CARDINAL_MEASURED.T
    return law, single, law.moment(kappa, 0) / moment - 1, single.moment(kappa, 0) / moment - 1


def band(diameter):
    """Frequencies of the Strouhal band of winds of 1 to 7 m/s (Hz)."""
    return np.linspace(STROUHAL * 1.0 / diameter, STROUHAL * 7.0 / diameter, 60)


def drake_cases():
    """AeolianVibration of the intact and damaged Drake (axes 1 and 2), own and Foti damping."""
    drake = strand.preset("acsr-drake")
    f = band(drake.diameter)
    hours = np.full(f.size, HOURS / f.size)
    cases = {}
    for label, damage, axis in [("intact", None, 0), ("3 broken, axis 1", 3, 0), ("3 broken, axis 2", 3, 1)]:
        for damping in ("model", "foti"):
            cases[label, damping] = conductors.aeolian_vibration(
                drake, T_DRAKE, f, damage=damage, axis=axis, damping=damping, hours_per_year=hours
            )
    return cases


def _range(values) -> str:
    return f"{100 * values.min():+.1f} % to {100 * values.max():+.1f} %"


def print_numbers(law, errors, single_errors, cases):
    beyond = CARDINAL_MEASURED[:, 0] >= 0.0166
    print(
        "ACSR Cardinal at 40 kN, mu = 0.7: knees by layer from the core (1/m):",
        np.round(law.kappa_slip[0], 4),
    )
    print(f"  against the measurements for kappa >= 0.0167 1/m: layer law {_range(errors[beyond])},")
    print(f"  single-knee law {_range(single_errors[beyond])}")
    intact = cases["intact", "model"]
    drake, m = intact.law, intact.mass
    stiffness = f"EI_max {drake.EI_max[0]:.0f} N·m², EI_min {drake.EI_min[0]:.1f} N·m²"
    print(f"ACSR Drake at {T_DRAKE / 1e3:g} kN: {stiffness},")
    print(f"  knees {np.round(drake.kappa_slip[0], 4)} 1/m, kappa_0 {drake.kappa_0[0]:.4f} 1/m")
    print("  the model's own self-damping exponents P ∝ y^l f^m / T^n at 30 Hz:")
    for y in (8e-3, 1e-2, 1.5e-2, 2e-2, 3e-2):
        l, mm, n = conductors.damping_exponents(drake, y, 30.0, T_DRAKE, m)
        print(f"    y = {1e3 * y:4.1f} mm: l = {l:.2f}, m = {mm:.2f}, n = {n:.2f}")
    print("  published: Noiseux (1991) 2.44, 5.63, 2.76; Kraus & Hagedorn (1991) 2.47, 5.38, 2.80")
    print(f"  life on the Safe Border Line, {HOURS:g} h/year over {intact.f[0]:.1f}-{intact.f[-1]:.1f} Hz:")
    for (label, damping), r in cases.items():
        amplitude = f"y_max/D {r.y_max.min() / r.diameter:.3f}-{r.y_max.max() / r.diameter:.3f}"
        stress = f"sigma_a up to {r.sigma_a.max() / 1e6:5.1f} MPa"
        print(f"    {label:18s} {damping:6s} {amplitude}, {stress}, life {r.life_years:.3g} years")


def figure_cardinal(law, single, path):
    import matplotlib.pyplot as plt

    kappa = np.linspace(0.0, 0.52, 600)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(*CARDINAL_MEASURED.T, "ko", label="measured (Foti & Martinelli 2018)")
    ax.plot(kappa, law.moment(kappa, 0), "C0-", label="layer-by-layer law (LayerSlipLaw)")
    ax.plot(kappa, single.moment(kappa, 0), "C3--", label="single knee (BendingLaw)")
    for knee in law.kappa_slip[0]:
        ax.axvline(knee, color="C0", lw=0.6, alpha=0.5)
    ax.set_xlabel("curvature κ (1/m)")
    ax.set_ylabel("bending moment M (N·m)")
    ax.set_title("ACSR Cardinal at 40 kN, μ = 0.7 (thin lines: each layer's knee)")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def figure_loops(law, path):
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    top = 1.5 * law.kappa_slip[0].max()
    for a in np.array([0.5, 1.0, 1.5, 2.0, 3.0]) * law.kappa_slip[0].min():
        left.plot(*law.loop(min(a, top)), label=f"κa = {min(a, top):.3f} 1/m")
    backbone = np.linspace(-top, top, 400)
    left.plot(backbone, law.moment(backbone), "k:", lw=0.8, label="backbone")
    left.set_xlabel("curvature κ (1/m)")
    left.set_ylabel("M (N·m)")
    left.set_title("Masing loops, ACSR Drake at 28 kN")
    left.legend(fontsize=8)
    a = np.geomspace(1e-3, 1.0, 300)
    right.loglog(a, np.maximum(law.energy_per_cycle(a), 1e-12))
    right.set_ylim(1e-4, None)
    right.set_xlabel("curvature amplitude κa (1/m)")
    right.set_ylabel("energy per cycle W (J/m)")
    right.set_title("W = 4 Σ M_k (κa − κ_k)⁺")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def figure_amplitude(cases, path):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    styles = {"model": "-", "foti": "--"}
    for k, label in enumerate(("intact", "3 broken, axis 1", "3 broken, axis 2")):
        for damping, style in styles.items():
            r = cases[label, damping]
            name = "own damping" if damping == "model" else "Foti & Martinelli"
            ax.plot(r.f, r.y_max / r.diameter, style, color=f"C{k}", label=f"{label}, {name}")
    ax.set_yscale("log")
    ax.set_xlabel("frequency f (Hz)")
    ax.set_ylabel("antinode amplitude y_max / D")
    ax.set_title("ACSR Drake at 28 kN, CIGRE wind: P_wind = P_damping")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def figure_life(cases, path):
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for k, label in enumerate(("intact", "3 broken, axis 1", "3 broken, axis 2")):
        for damping, style in (("model", "-"), ("foti", "--")):
            r = cases[label, damping]
            left.plot(r.f, r.sigma_a / 1e6, style, color=f"C{k}", label=f"{label}, {damping}")
    left.set_xlabel("frequency f (Hz)")
    left.set_ylabel("Poffenberger–Swart σ_a (MPa)")
    left.set_title("clamp stress (Y_b peak to peak at 89 mm)")
    left.legend(fontsize=7)
    short = {"intact": "intact", "3 broken, axis 1": "broken\naxis 1", "3 broken, axis 2": "broken\naxis 2"}
    labels = [f"{short[label]}\n{'own' if damping == 'model' else 'Foti'}" for label, damping in cases]
    colours = [f"C{k // 2}" for k in range(len(cases))]
    right.bar(range(len(cases)), [r.life_years for r in cases.values()], color=colours)
    right.set_yscale("log")
    right.set_xticks(range(len(cases)), labels, fontsize=7)
    right.set_ylabel("life (years)")
    right.set_title(f"Safe Border Line, Miner, {HOURS:g} h/year")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description="Aeolian vibration, from friction to fatigue")
    parser.add_argument("--out", default="results/aeolian_vibration", help="output folder")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    import matplotlib

    matplotlib.use("Agg")
    law, single, errors, single_errors = cardinal()
    cases = drake_cases()
    print_numbers(law, errors, single_errors, cases)
    intact = cases["intact", "model"]
    intact.to_frame().to_csv(out / "aeolian_vibration.csv", index=False)
    for written in (
        figure_cardinal(law, single, out / "cardinal_bending.png"),
        figure_loops(intact.law, out / "loops.png"),
        figure_amplitude(cases, out / "amplitude.png"),
        figure_life(cases, out / "life.png"),
    ):
        print("wrote", written)


if __name__ == "__main__":
    main()
