"""Broken wires to fatigue life (ACSR Drake)

ACSR Drake with 0 to 4 broken outer wires, from the section to the fatigue life.

A 400 m level span of ACSR Drake (795 kcmil 26/7, ASTM B232 rated strength 140.1 kN) strung at
28 kN (20 % RTS) at 15 °C. Outer aluminium wires break (adjacent, at the top of the section);
the conductor keeps its unstressed length. For each case:

- ``EA`` of the net section (the intact wires) and the sag at 75 °C (`Conductor.change_of_state`
  with the intact conductor's unstressed length);
- the Poffenberger–Swart stress at a suspension clamp for a bending amplitude Y_b = 0.5 mm at
  the everyday tension (15 °C), with the slip bending stiffness of the damaged section (the
  larger stress; the stick one bounds it from below);
- the life ratio at that amplitude on the CIGRE Safe Border Line (multi-layer), against the
  intact conductor's;
- the residual rated strength: the layer rule (the broken wires' share of the rated strength)
  and the strand finite element's capacity curve to the first wire rupture.

One table (printed, and ``damaged_conductor_fatigue.csv``) and one figure
(``damaged_conductor_fatigue.png``).

Run:  python examples/damaged_conductor_fatigue.py [--out results/damaged_conductor_fatigue]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from skcable import conductors, strand
from skcable.conductors import WohlerCurve, clamp_stress, residual_strength

SPAN = 400.0  # m, level
T0, H0 = 15.0, 28e3  # °C, N: the everyday state of the intact conductor (20 % RTS)
RTS = 140.1e3  # N, ASTM B232 rated strength of Drake
Y_B = 0.5e-3  # m, bending amplitude at 89 mm from the clamp
BROKEN = range(5)


def table():
    """One row per number of broken outer wires (pandas DataFrame)."""
    import pandas as pd

    drake = strand.preset("acsr-drake")
    intact = conductors.Conductor.from_strand(drake, rts=RTS)
    L0 = intact.change_of_state(SPAN, t0=T0, H0=H0, t=T0).L0
    sbl = WohlerCurve.safe_border_line(layers=2)
    rows = []
    for n in BROKEN:
        damaged = drake.damaged(n) if n else drake
        conductor = conductors.Conductor.from_strand(drake, damage=n or None, rts=RTS)
        states = conductor.change_of_state(SPAN, t0=T0, length=L0, t=[T0, 75.0])
        stress = clamp_stress(damaged, Y_B, float(states.H[0]))
        rows.append(
            dict(
                broken=n,
                EA_MN=conductor.EA / 1e6,
                H_15C_kN=states.H[0] / 1e3,
                sag_75C_m=states.sag[1],
                sigma_slip_MPa=stress.high / 1e6,
                sigma_stick_MPa=stress.low / 1e6,
                cycles=sbl.cycles(stress.high),
                rrts_layers_kN=residual_strength(drake, n, rts=RTS).rrts / 1e3 if n else RTS / 1e3,
                rrts_fe_kN=residual_strength(drake, n, rts=RTS, method="capacity").rrts / 1e3
                if n
                else RTS / 1e3,
            )
        )
    frame = pd.DataFrame(rows).set_index("broken")
    frame["life_ratio"] = frame["cycles"] / frame["cycles"].iloc[0]
    frame["T_15C_per_rrts"] = frame["H_15C_kN"] / frame["rrts_fe_kN"]
    return frame


def figure(frame, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = frame.index.to_numpy()
    fig, axes = plt.subplots(2, 2, figsize=(9, 6.5), sharex=True)
    axes[0, 0].plot(n, frame["EA_MN"], "o-")
    axes[0, 0].set_ylabel("EA (MN)")
    axes[0, 1].plot(n, frame["sag_75C_m"], "o-", color="C1")
    axes[0, 1].set_ylabel("sag at 75 °C (m)")
    axes[1, 0].plot(n, frame["sigma_slip_MPa"], "o-", color="C3", label="slip EI (upper)")
    axes[1, 0].plot(n, frame["sigma_stick_MPa"], "s--", color="C3", alpha=0.6, label="stick EI (lower)")
    axes[1, 0].set_ylabel("P–S stress at Y_b = 0.5 mm (MPa)")
    axes[1, 0].legend()
    axes[1, 1].semilogy(n, frame["life_ratio"], "o-", color="C2", label="life ratio (SBL)")
    axes[1, 1].set_ylabel("life / intact life")
    axes[1, 1].legend(loc="lower left")
    twin = axes[1, 1].twinx()
    twin.plot(n, frame["rrts_layers_kN"], "^-", color="C4", label="RRTS, layer rule")
    twin.plot(n, frame["rrts_fe_kN"], "v--", color="C5", label="RRTS, capacity curve")
    twin.set_ylabel("residual strength (kN)")
    twin.legend(loc="upper right")
    for ax in axes[1]:
        ax.set_xlabel("broken outer wires")
    fig.suptitle("ACSR Drake, 400 m span at 28 kN: broken wires to fatigue life")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description="Broken wires to fatigue life (ACSR Drake)")
    parser.add_argument("--out", default="results/damaged_conductor_fatigue", help="output folder")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    frame = table()
    with np.printoptions(precision=4):
        print(frame.round(4).to_string())
    frame.to_csv(out / "damaged_conductor_fatigue.csv")
    print("wrote", figure(frame, out / "damaged_conductor_fatigue.png"))


if __name__ == "__main__":
    main()
