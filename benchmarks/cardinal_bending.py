"""The ACSR Cardinal bent at 40 kN: the layer-by-layer law against the 18 measured points.

The measurements (Foti & Martinelli 2018, as shipped with RTE's strdcable; the file and its
source: tests/strand/data/cardinal_bending_40kN.csv) beside `skcable.strand.LayerSlipLaw` at
μ = 0.7 for the catalogue preset ``acsr-cardinal`` (ASTM B232 wires of 3.376 mm, lay ratios 19,
13, 11), with each rule of the outer layers' friction, and for the same conductor with 3.34 mm
wires and the middle of EN 50182's lay-ratio ranges (21, 13, 13, 12; the geometry strdcable
takes): how much of the agreement is the friction rule and how much the geometry. Also the
single-knee law of the preset (`BendingLaw`).

Prints a table in Markdown (docs/conductor_vibration.md shows it).

Run:  python benchmarks/cardinal_bending.py
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from skcable import strand

DATA = Path(__file__).resolve().parents[1] / "tests" / "strand" / "data" / "cardinal_bending_40kN.csv"


def en50182_cardinal():
    """The Cardinal with 3.34 mm wires and the middle of EN 50182's lay ratios."""
    preset = strand.preset("acsr-cardinal")
    d, ratios, outside, layers = 3.34e-3, (21.0, 13.0, 13.0, 12.0), 3.34e-3, []
    for layer, ratio in zip(preset.layers, ratios, strict=True):
        outside += 2 * d
        layers.append(replace(layer, wire_diameter=d, lay_length=ratio * outside, lay_angle=None))
    return replace(preset, core_diameter=d, layers=tuple(layers))


def main():
    kappa, measured = np.loadtxt(DATA, delimiter=",", comments="#", skiprows=9).T
    preset = strand.preset("acsr-cardinal")
    laws = {
        f"preset, {rule}": strand.LayerSlipLaw(preset.section(), mu=0.7, tension=40e3, outer_friction=rule)
        for rule in ("foti", "inner", "both")
    }
    en50182 = en50182_cardinal().section()
    laws["EN 50182 lay, 3.34 mm, foti"] = strand.LayerSlipLaw(en50182, mu=0.7, tension=40e3)
    single = preset.bending_law(mu=0.7, axial_strain=laws["preset, foti"].axial_strain)
    columns = {name: law.moment(kappa, 0) / measured - 1 for name, law in laws.items()}
    columns["preset, single knee"] = single.moment(kappa, 0) / measured - 1
    print("| κ [1/m] | measured M [N·m] | " + " | ".join(columns) + " |")
    print("|---|---|" + "---|" * len(columns))
    for i, (k, m) in enumerate(zip(kappa, measured, strict=True)):
        cells = " | ".join(f"{100 * c[i]:+.1f} %" for c in columns.values())
        print(f"| {k:.4f} | {m:.2f} | {cells} |")
    beyond = kappa >= 0.0166
    ranges = [(100 * c[beyond].min(), 100 * c[beyond].max()) for c in columns.values()]
    cells = " | ".join(f"{low:+.1f} to {high:+.1f} %" for low, high in ranges)
    print(f"| κ >= 0.0167 | range | {cells} |")
    for name, law in laws.items():
        print(f"{name}: knees {np.round(law.kappa_slip[0], 4).tolist()} 1/m, EI_max {law.EI_max[0]:.0f} N·m²")


if __name__ == "__main__":
    main()
