"""FE loops: the strands of tests/strand/test_cycles.py bent back and forth, with the energies the
docs quote (docs/conductor_vibration.md, "Bending a strand back and forth").

For each run: the vertices of the path, the energy per cycle ∮ R dq, its relative difference to
the summed friction work and to Masing's value of the model's own backbone, and the time
(`time.process_time`, best of ``--repeats``). Also the same 1x7 loop traced without cutting the
steps at the slip events (``exact=False``): how far the trapezoidal rule over the schedule's
steps alone misses the loop's area.

Run:  python benchmarks/strand_loops.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import time

from skcable import strand


def model_of(name, tension, mu, length, n_elements):
    s = strand.preset(name)
    law = strand.LayerSlipLaw(s.section(), mu=mu, tension=tension)
    # both ends clamped, the axial force at x = L: the right end holds all but u(L)
    return strand.StrandModel(s, length, n_elements=n_elements, slip=strand.StageSlip(law), axial="force")


RUNS = {
    "1x7 steel-9.5, end turned ±6 mrad, 20 kN": (
        ("steel-9.5", 20e3, 0.5, 0.3, 32),
        dict(amplitude=0.006, force=20e3, n_steps=2, cycles=2),
    ),
    "1x7 steel-9.5, end moved ±2 mm, 20 kN": (
        ("steel-9.5", 20e3, 0.5, 0.3, 32),
        dict(amplitude=2e-3, dof="v", force=20e3, n_steps=2, cycles=1),
    ),
    "ACSR Drake, end turned ±4 mrad, 28 kN, μ = 0.3": (
        ("acsr-drake", 28e3, 0.3, 0.6, 24),
        dict(amplitude=0.004, force=28e3, n_steps=1, cycles=1),
    ),
    "1x7 steel-9.5, ±6 mrad, schedule's steps only": (
        ("steel-9.5", 20e3, 0.5, 0.3, 32),
        dict(amplitude=0.006, force=20e3, n_steps=2, cycles=1, exact=False),
    ),
}


def main(repeats: int = 3) -> None:
    print("| run | vertices | W per cycle [J] | W/D − 1 | W/Masing − 1 | time [s] |")
    print("|---|---|---|---|---|---|")
    for name, (model_args, kwargs) in RUNS.items():
        model = model_of(*model_args)
        best = float("inf")
        for _ in range(repeats):
            start = time.process_time()
            cycles = strand.bending_cycles(model, **kwargs)
            best = min(best, time.process_time() - start)
        W = cycles.energy_per_cycle[-1]
        D = cycles.friction_per_cycle[-1]
        print(
            f"| {name} | {cycles.drive.size} | {W:.6g} | {W / D - 1:+.1e} | "
            f"{W / cycles.masing_energy - 1:+.1e} | {best:.2f} |"
        )


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    main(parser.parse_args().repeats)
