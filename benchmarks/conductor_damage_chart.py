"""Chart of docs/conductors.md: the extra sag of ACSR Drake with broken outer aluminium wires.

Drake (ASTM B232 26/7, `strand.preset("acsr-drake")`) strung intact at H0 = 28 kN, 15 °C on a
level 400 m span; then n = 1 to 4 adjacent outer wires break, the unstressed length L0 kept.
Two axial stiffnesses of the damaged conductor: the section's (`Section.EA`, the net section;
the default of `Conductor.from_strand`) and the finite-element secant of a clamped 2 m specimen
(stick, eccentric net section bending) at the reference strain H0 / EA. Plotted: the extra sag
against temperature; printed: the stiffnesses and the time of the calls.

Run:    python benchmarks/conductor_damage_chart.py
Output: docs/img/conductors_damaged_sag.png, the numbers on stdout.
"""

from __future__ import annotations

import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from skcable import conductors, strand  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "docs" / "img"
SPAN, T0, H0 = 400.0, 15.0, 28e3
TEMPERATURES = np.linspace(-20.0, 100.0, 25)


def main():
    drake = strand.preset("acsr-drake")
    intact = conductors.Conductor.from_strand(drake)
    reference = intact.change_of_state(SPAN, 0.0, t0=T0, H0=H0, t=TEMPERATURES)
    strain = H0 / intact.EA
    fig, ax = plt.subplots(figsize=(7, 4.5))
    print(f"intact: EA = {intact.EA:.6g} N, L0 = {reference.L0:.6f} m, reference strain {strain:.3g}")
    for n in (1, 2, 3, 4):
        start = time.perf_counter()
        broken = conductors.Conductor.from_strand(drake, damage=n)
        result = broken.change_of_state(SPAN, 0.0, t0=T0, length=reference.L0, t=TEMPERATURES)
        elapsed = time.perf_counter() - start
        start = time.perf_counter()
        model = strand.StrandModel(broken.strand, 2.0)
        secant = model.solve(strain).force / strain
        fe_time = time.perf_counter() - start
        fe = conductors.Conductor.from_strand(drake, damage=n, EA=secant)
        fe_result = fe.change_of_state(SPAN, 0.0, t0=T0, length=reference.L0, t=TEMPERATURES)
        extra, extra_fe = result.sag - reference.sag, fe_result.sag - reference.sag
        ax.plot(TEMPERATURES, 100 * extra, "-", color=f"C{n - 1}", label=f"{n} broken: section EA")
        ax.plot(TEMPERATURES, 100 * extra_fe, "--", color=f"C{n - 1}", label=f"{n} broken: FE secant (2 m)")
        print(
            f"{n} broken: section EA {broken.EA:.6g} N ({broken.EA / intact.EA - 1:+.2%}), FE secant "
            f"{secant:.6g} N ({secant / intact.EA - 1:+.2%}); extra sag {100 * extra.min():.1f} to "
            f"{100 * extra.max():.1f} cm (FE {100 * extra_fe.min():.1f} to {100 * extra_fe.max():.1f}); "
            f"from_strand + {TEMPERATURES.size} states {1e3 * elapsed:.1f} ms, FE {1e3 * fe_time:.1f} ms"
        )
    ax.set_xlabel("temperature (°C)")
    ax.set_ylabel("extra sag over the intact conductor (cm)")
    ax.set_title("ACSR Drake, level 400 m span, 28 kN at 15 °C: broken outer wires")
    ax.legend(fontsize=8, ncol=2)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(OUT / "conductors_damaged_sag.png", dpi=110)


if __name__ == "__main__":
    main()
