"""Why aluminium capacity curves used to stop, and how the solver passes (docs/stability.md).

The printed aluminium law (Pino Vidal 2021, Table B.1) has a C¹ cubic blend that softens
(dσ/dε < 0 for 0.0083 < ε < 0.0094). Near the clamps, where the damage bends the strand most,
a few wires enter that window: the strand's tangent loses positive definiteness and the
equilibrium path under imposed strain folds (a snap). For the four cases that stopped before,
on default settings this prints:

- plain Newton (the same model with a term that has no potential, so the solver cannot
  minimise the energy): where it stops and why;
- the default solver (energy minimisation, tangent shifted where it is not positive
  definite): rupture, and the strains where the path snapped (``CapacityCurve.snaps``);
- at the first snap: the wire quadrature points inside the softening window, where they are
  along the strand, and the force on either side.

Run:  python benchmarks/aluminium_fold.py
"""

from __future__ import annotations

import time

import numpy as np

from skcable import strand

CASES = [
    ("aluminium-10.1", 2, "none"),
    ("aluminium-14.3", 1, "none"),
    ("aluminium-14.3", 2, "none"),
    ("aluminium-10.1", 1, "axis"),
]


class BendingWithoutPotential(strand.WireBending):
    """The wires' own bending, reported without its energy: the model then solves by plain Newton."""

    def section(self, g, step):
        S, D, _ = super().section(g, step)
        return S, D, {}


def main():
    window = strand.material("aluminium").softening_range
    print(f"aluminium softening window: {window[0]:.5f} < ε < {window[1]:.5f}")
    for name, damage, slip in CASES:
        s = strand.preset(name).damaged(damage)
        print(f"\n{name}, damage {damage}, slip={slip!r} (default mesh and steps)")
        physics = strand.default_physics(slip)
        plain = [BendingWithoutPotential() if isinstance(t, strand.WireBending) else t for t in physics]
        start = time.perf_counter()
        stopped = strand.StrandModel(s, physics=plain).capacity_curve(on_failure="stop")
        t_plain = time.perf_counter() - start
        start = time.perf_counter()
        model = strand.StrandModel(s, slip=slip)
        curve = model.capacity_curve()
        t_min = time.perf_counter() - start
        print(f"  plain Newton: {'rupture' if stopped.ruptured else stopped.failure} ({t_plain:.2f} s)")
        snaps = ", ".join(f"{e:.5f}" for e in curve.snaps) or "none"
        print(
            f"  energy minimisation: {'rupture' if curve.ruptured else curve.failure} at ε = "
            f"{curve.strain[-1]:.5f} ({t_min:.2f} s); snaps at ε = {snaps}"
        )
        if not curve.snaps:
            continue
        k = next(i for i, st in enumerate(curve.steps) if st.shifted)
        before, after = curve.steps[k - 1], curve.steps[k]
        alive = ~after.layout.wire_broken
        inside = (after.wire_strain[alive] > window[0]) & (after.wire_strain[alive] < window[1])
        x = np.broadcast_to(after.x, after.wire_strain[alive].shape)[inside]
        where = f"at x = {np.min(x):.3f} … {np.max(x):.3f} m" if x.size else "none"
        print(
            f"  first snap, ε = {before.strain:.5f} → {after.strain:.5f}: {int(inside.sum())} wire "
            f"quadrature points in the window ({where}); force {before.force:.1f} → {after.force:.1f} N"
        )


if __name__ == "__main__":
    main()
