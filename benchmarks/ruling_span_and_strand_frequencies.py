"""Numbers of docs/conductors.md: the ruling-span approximation against the exact tension
section, and the bending frequencies of a steel strand, intact and damaged, stick and slip.

Tension section: an ACSR of w0 = 15.97 N/m, EA = 2.94e7 N, alpha = 19.3e-6 /K ("Zebra"
class), reference 15 °C bare at H0 = 25 kN in every span; spans 250, 450, 300, 400, 200 m
(level, then with heights); suspension strings of 3 m and 700 N (I-strings of a 400 kV line).
States: bare at -20, 50 and 80 °C; ice (2 w0) at -5 °C. Printed: each span's H and sag, the
string swings, and the gaps H_ruling / H - 1, sag_ruling / sag - 1; the time per state.

Strand: the steel 9.5 mm 1x7 preset, density 7850 kg/m³ (mass per length = density x the
section's area, the damaged one's for the damaged strand), 1 m between clamps, tensions 1
and 10 kN: the first three frequencies with the stick and slip EI, intact and with one
broken wire (both principal axes).

Run:    python benchmarks/ruling_span_and_strand_frequencies.py
"""

from __future__ import annotations

import time

import numpy as np

from skcable import conductors, strand

W0, EA, ALPHA = 15.97, 2.94e7, 19.3e-6
SPANS = [250.0, 450.0, 300.0, 400.0, 200.0]
STATES = {
    "bare -20 °C": (W0, -20.0),
    "bare 50 °C": (W0, 50.0),
    "bare 80 °C": (W0, 80.0),
    "ice 2w0 -5 °C": (2 * W0, -5.0),
}


def section(dh):
    w = np.array([v[0] for v in STATES.values()])
    t = np.array([v[1] for v in STATES.values()])
    start = time.perf_counter()
    res = conductors.tension_section(
        SPANS, dh, EA=EA, alpha=ALPHA, w0=W0, t0=15.0, H0=25e3, w=w, t=t,
        insulator_length=3.0, insulator_weight=700.0,
    )  # fmt: skip
    elapsed = (time.perf_counter() - start) / len(w)
    print(f"spans {SPANS}, dh {dh}: ruling span {res.ruling_span:.1f} m, {1e3 * elapsed:.1f} ms per state")
    for i, name in enumerate(STATES):
        print(
            f"  {name:14s} H [kN] {np.round(res.H[i] / 1e3, 2).tolist()}  "
            f"H_ruling {res.H_ruling[i] / 1e3:.2f}"
        )
        print(
            f"  {'':14s} sag [m] {np.round(res.sag[i], 2).tolist()}  "
            f"swing [mm] {np.round(1e3 * res.swing[i], 0).tolist()}"
        )
        print(f"  {'':14s} H gap [%] {np.round(100 * res.H_gap[i], 2).tolist()}")
        print(f"  {'':14s} sag gap [%] {np.round(100 * res.sag_gap[i], 2).tolist()}")
    print(
        f"  largest |H gap| {100 * np.abs(res.H_gap).max():.2f} %, "
        f"|sag gap| {100 * np.abs(res.sag_gap).max():.2f} %"
    )


def strand_table():
    intact = strand.preset("steel-9.5")
    m = 7850.0 * intact.section().area
    print(f"steel 9.5 mm, m = {m:.4f} kg/m, 1 m between clamps")
    for N in (1e3, 1e4):
        base = strand.strand_bending_frequencies(intact.section(), N, 1.0, m, n_modes=3)
        rows = [("intact", base)]
        damaged = intact.damaged(1).section()
        m_damaged = 7850.0 * damaged.area  # the broken wire's mass is gone too
        rows += [(f"1 broken, axis {a + 1}",
                  strand.strand_bending_frequencies(damaged, N, 1.0, m_damaged, axis=a, n_modes=3))
                 for a in (0, 1)]  # fmt: skip
        for label, r in rows:
            print(
                f"  N = {N / 1e3:4.0f} kN {label:17s} EI stick/slip {r.EI_stick:6.2f}/{r.EI_slip:5.2f} N m²  "
                f"f_stick {np.round(r.f_stick, 2).tolist()} Hz  f_slip {np.round(r.f_slip, 2).tolist()} Hz  "
                f"drop vs intact stick {np.round(100 * (1 - r.f_slip / base.f_stick), 1).tolist()} %"
            )


if __name__ == "__main__":
    section(0.0)
    section([0.0, 30.0, -20.0, 15.0, -10.0])
    strand_table()
