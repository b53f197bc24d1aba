"""What automatic model choice saves: bvp.solve(rtol) against always the full model.

Scenes: random spans (chord slope up to ±2, excess length 1e-4 to 0.3, EA 1e5 to 1e9 N) under
self weight with a given unstretched length, the full model being Irvine's elastic catenary;
and a deck load plus self weight 0.1 % to 100 % of it (no closed form), the full model a BVP on
256 P2 elements.
Prints the time per scene of each, the ratio, the models chosen and the largest true error.

Run:  python benchmarks/bench_choice.py [--rtol 1e-3]
"""

from __future__ import annotations

import argparse
import collections
import time

import numpy as np

from skcable import bvp, cable


def timed(fn, *args, repeat=3, **kwargs):
    best = np.inf
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn(*args, **kwargs)
        best = min(best, time.perf_counter() - start)
    return out, best


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rtol", type=float, default=1e-3)
    parser.add_argument("--scenes", type=int, default=200)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(0)
    chosen, t_auto, t_full, worst = collections.Counter(), 0.0, 0.0, 0.0
    for _ in range(args.scenes):
        dh = 100 * rng.uniform(-2, 2)
        length = np.hypot(100, dh) * (1 + 10 ** rng.uniform(-4, -0.5))
        EA = 10 ** rng.uniform(5, 9)
        sol, t1 = timed(bvp.solve, 100.0, dh, bvp.SelfWeight(1.0), length=length, EA=EA, rtol=args.rtol)
        exact, t2 = timed(cable.elastic_catenary, 100.0, dh, 1.0, EA, length=length)
        chosen[sol.model] += 1
        t_auto, t_full = t_auto + t1, t_full + t2
        worst = max(worst, abs(sol.H / exact.H - 1))
    n = args.scenes
    print(f"self weight, elastic, {n} scenes, rtol {args.rtol:g}: models {dict(chosen)}")
    print(
        f"  bvp.solve {1e6 * t_auto / n:8.1f} us/scene   elastic_catenary {1e6 * t_full / n:8.1f} us/scene"
        f"   ratio {t_full / t_auto:5.2f}   largest error in H {worst:.1e}"
    )
    chosen, t_auto, t_full, worst = collections.Counter(), 0.0, 0.0, 0.0
    per_model = collections.defaultdict(list)
    m = max(n // 4, 5)
    for _ in range(m):
        deck, weight = 1.0, 10 ** rng.uniform(-3, 0)  # a bridge's cable: weight 0.1 % to 100 % of the deck
        sag = 100 * rng.uniform(0.02, 0.2)
        loads = [bvp.DeckLoad(deck), bvp.SelfWeight(weight)]
        sol, t1 = timed(bvp.solve, 100.0, 0.0, loads, sag=sag, rtol=args.rtol, repeat=1)
        full, t2 = timed(bvp.solve_bvp, 100.0, 0.0, loads, sag=sag, n_elements=256, repeat=1)
        chosen[sol.model] += 1
        per_model[sol.model].append(t1)
        t_auto, t_full = t_auto + t1, t_full + t2
        worst = max(worst, abs(sol.H / full.H - 1))
    print(f"deck + self weight, {m} scenes: models {dict(chosen)}")
    print(
        f"  bvp.solve {1e3 * t_auto / m:8.2f} ms/scene   BVP 256 P2 {1e3 * t_full / m:8.2f} ms/scene"
        f"   ratio {t_full / t_auto:5.2f}   largest error in H {worst:.1e}"
    )

    for model, times in per_model.items():
        print(f"  when bvp.solve took the {model}: {1e3 * np.mean(times):.2f} ms/scene")


if __name__ == "__main__":
    main()
