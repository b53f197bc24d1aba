"""Aeolian amplitude over a frequency band: y_max at 100 frequencies for one conductor.

ACSR Drake at 28 kN, CIGRE's wind without turbulence, 100 frequencies from 5 to 60 Hz, with
Foti & Martinelli's damping and with the conductor's own (`self_damping` of its layer law).
Prints the best time of `conductors.aeolian_amplitude` over the band (target: 50 ms for the
100 frequencies, issue 35) beside a frequency-by-frequency loop of scipy's brentq on the same
balance (the way a scalar root finder does it; its roots to xtol 1e-15 m), and the largest
relative difference between the two.

Run:  python benchmarks/bench_aeolian.py [--repeat 7]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from scipy.optimize import brentq

from skcable import conductors, strand

TARGET = 0.050  # s, 100 frequencies for one conductor (issue 35)


def best(fn, repeat):
    out, times = None, []
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return out, min(times)


def scalar_loop(f, D, damping, top):
    """brentq frequency by frequency between 1e-6 D and the top of CIGRE's band."""
    out = []
    for fi in f:
        balance = lambda y, fi=fi: (  # noqa: E731
            (0.0 if y >= top else conductors.wind_power(y, fi, D)) - float(damping(y, fi))
        )
        out.append(brentq(balance, 1e-6 * D, top, xtol=1e-15, rtol=8.9e-16))
    return np.array(out)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args(argv)
    drake = strand.preset("acsr-drake")
    conductor = conductors.Conductor.from_strand(drake)
    m, D, T = conductor.w / 9.80665, conductor.diameter, 28e3
    law = strand.LayerSlipLaw(drake.section(), mu=0.7, tension=T)
    f = np.linspace(5.0, 60.0, 100)
    top = conductors.wind_band()[1] * D
    dampings = {
        "Foti & Martinelli": lambda y, f: conductors.foti_damping(y, f, T, m, law.EI_max[0], law.kappa_0[0]),
        "the conductor's own": lambda y, f: conductors.self_damping(law, y, f, T, m),
    }
    band = f"{f.size} frequencies {f[0]:g}-{f[-1]:g} Hz"
    print(f"ACSR Drake, {T / 1e3:g} kN, CIGRE wind, {band} (best of {args.repeat})")
    for name, damping in dampings.items():
        y, t = best(lambda damping=damping: conductors.aeolian_amplitude(f, D, m, T, damping), args.repeat)
        y_loop, t_loop = best(
            lambda damping=damping: scalar_loop(f, D, damping, top), max(1, args.repeat // 3)
        )
        ok = "within" if t <= TARGET else "OVER"
        print(
            f"  {name:20s} aeolian_amplitude {1e3 * t:7.2f} ms ({ok} the {1e3 * TARGET:g} ms target)   "
            f"brentq loop {1e3 * t_loop:8.2f} ms   ratio {t_loop / t:5.1f}   "
            f"max |Δy/y| {np.max(np.abs(y / y_loop - 1)):.1e}"
        )


if __name__ == "__main__":
    main()
