"""skcable's seabed line against MoorPy's ``Catenary.catenary``, side by side, one process.

Random scenes (seeded) of a line anchored on a flat seabed with Coulomb
friction (Jonkman, "Dynamics modeling and loads analysis of an offshore
floating wind turbine", NREL, 2007): span 20-1500 m, fairlead 1-400 m above
the seabed, unstretched length between the chord and the L-shape span + dh
(a few beyond it, where the slack lies in a heap), w 50-3000 N/m, EA 1e6-1e10 N,
friction 0-5. For each scene: the fairlead forces H, V_B, the anchor's H_A, the
grounded length and the 2x2 fairlead stiffness of both codes; where they
differ by more than 1e-6, a 40-digit mpmath solution of the same equations
says which one is right. Times: per line for a Python loop of scalar calls
(both codes), and per line for skcable's one vectorised call. A second
table: the anchor 5-100 m above a frictionless seabed (MoorPy's CB < 0), where
the line may hang down to the seabed, rest on it and rise to B.

Run:  python benchmarks/bench_moorpy.py [--n 500] [--seed 0]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
import time
import warnings
from pathlib import Path

import mpmath as mp
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _reference import jonkman_grounded  # noqa: E402

from skcable import cable
from skcable.errors import ConvergenceError, InputError


def scenes(n: int, seed: int):
    rng = np.random.default_rng(seed)
    span = rng.uniform(20.0, 1500.0, n)
    dh = rng.uniform(1.0, 400.0, n)
    chord = np.hypot(span, dh)
    L = chord + rng.uniform(-0.002, 1.05, n) * (span + dh - chord)
    w = rng.uniform(50.0, 3000.0, n)
    EA = 10 ** rng.uniform(6.0, 10.0, n)
    cb = rng.choice([0.0, 0.05, 0.3, 1.0, 5.0], n)
    return span, dh, w, EA, L, cb


def mp_solution(span, dh, w, EA, L, cb, H0, V0):
    """(H, V_B) of Jonkman's closure equations at 40 digits (the reference's max() form)."""
    mp.mp.dps = 40
    f = jonkman_grounded(span, dh, w, EA, L, cb)
    H, V = mp.findroot(f, (mp.mpf(H0), mp.mpf(V0)), tol=mp.mpf(10) ** -30)
    return float(H), float(V)


def mp_anchor_above(span, dh, w, EA, L, d, H0, V10, VB0):
    """(H, V_A, V_B) of the three-part line (A down to the seabed, grounded, up to B), 40 digits."""
    mp.mp.dps = 40
    span, dh, w, EA, L, d = (mp.mpf(float(v)) for v in (span, dh, w, EA, L, d))

    def height(H, V):
        return (mp.sqrt(H**2 + V**2) - H) / w + V**2 / (2 * EA * w)

    def run(H, V):
        return H * V / (w * EA) + H / w * mp.asinh(V / H)

    def f(H, V1, VB):
        L_B = L - V1 / w - VB / w
        return [
            height(H, V1) - d,
            height(H, VB) - (dh + d),
            run(H, V1) + L_B * (1 + H / EA) + run(H, VB) - span,
        ]

    return [float(v) for v in mp.findroot(f, (mp.mpf(H0), mp.mpf(V10), mp.mpf(VB0)), tol=mp.mpf(10) ** -30)]


def anchor_above(n: int, seed: int, catenary) -> None:
    rng = np.random.default_rng(seed + 1)
    span, dh, w, EA, L, _ = scenes(n, seed + 1)
    depth = rng.uniform(5.0, 100.0, n)
    agree = touching = 0
    notes = []
    for i in range(n):
        try:
            r = cable.elastic_catenary(span[i], dh[i], w[i], EA[i], length=L[i], seabed=-depth[i])
        except (InputError, ConvergenceError) as err:
            notes.append(f"  scene {i}: skcable {type(err).__name__}({err.args[0][:50]})")
            continue
        touching += r.length_on_seabed > 0
        try:
            with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
                warnings.simplefilter("ignore")
                fAH, fAV, fBH, fBV, info = catenary(
                    span[i], dh[i], L[i], EA[i], w[i], CB=-depth[i], Tol=1e-12, MaxIter=500
                )
        except Exception as err:  # noqa: BLE001 - MoorPy raises plain Exception
            notes.append(f"  scene {i}: MoorPy {type(err).__name__}; skcable solved")
            continue
        scale = np.hypot(r.H, r.V_B)
        if max(abs(r.H + fBH), abs(r.V_B + fBV), abs(r.V_A + fAV)) / scale <= 1e-6:
            agree += 1
            continue
        if r.length_on_seabed > 0 or r.length_to_seabed > 0:
            H, V1, VB = mp_anchor_above(span[i], dh[i], w[i], EA[i], L[i], depth[i], r.H, r.V_A, r.V_B)
            err_sk = max(abs(r.H - H), abs(r.V_B - VB), abs(r.V_A - V1)) / np.hypot(H, VB)
            err_mp = max(abs(-fBH - H), abs(-fBV - VB), abs(-fAV - V1)) / np.hypot(H, VB)
            notes.append(
                f"  scene {i}: 40-digit mpmath says skcable off by {err_sk:.1e}, MoorPy by {err_mp:.1e}"
            )
        else:
            notes.append(f"  scene {i}: no contact, MoorPy differs by {abs(r.H + fBH) / scale:.1e}")
    print(f"\nanchor 5-100 m above a frictionless seabed: {n} scenes, {touching} touching")
    wrong = [n for n in notes if "mpmath" in n]
    worst_sk = max((float(n.split("skcable off by ")[1].split(",")[0]) for n in wrong), default=0.0)
    moorpy_off = sum(float(n.split("MoorPy by ")[1]) > 1e-6 for n in wrong)
    print(f"  forces agree to 1e-6 on {agree}; on {len(wrong)} they differ: mpmath puts skcable within")
    print(f"  {worst_sk:.1e} of the 40-digit solution, MoorPy off by more than 1e-6 on {moorpy_off};")
    print(f"  {sum(': skcable ' in n for n in notes)} refused by skcable,")
    print(f"  {sum(': MoorPy ' in n for n in notes)} MoorPy errors. Listed:")
    print("\n".join(notes[:15]) + (f"\n  ... {len(notes) - 15} more" if len(notes) > 15 else ""))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=500)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    from moorpy.Catenary import catenary

    data = scenes(args.n, args.seed)
    sk, mp_ = [], []
    sk_fail, mp_fail = {}, {}
    t_sk = t_mp = 0.0
    for i, (span, dh, w, EA, L, cb) in enumerate(zip(*data, strict=True)):
        start = time.perf_counter()
        try:
            r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0, friction=cb)
            K = r.stiffness()
            sk.append((i, r.H, r.V_B, r.H_A, r.length_on_seabed, K, bool(r.heap)))
        except (InputError, ConvergenceError) as err:
            sk_fail[i] = f"{type(err).__name__}({err.args[0][:60]})"
        t_sk += time.perf_counter() - start
        start = time.perf_counter()
        try:
            with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):  # MoorPy prints
                warnings.simplefilter("ignore")
                fAH, fAV, fBH, fBV, info = catenary(span, dh, L, EA, w, CB=cb, Tol=1e-12, MaxIter=500)
            if info["ProfileType"] < 0 or info.get("error"):
                mp_fail[i] = f"ProfileType {info['ProfileType']}"
            mp_.append(
                (i, -fBH, -fBV, fAH, info["LBot"], np.asarray(info["stiffnessB"]), info["ProfileType"])
            )
        except Exception as err:  # noqa: BLE001 - MoorPy raises plain Exception
            mp_fail[i] = f"{type(err).__name__}({str(err)[:60]})"
        t_mp += time.perf_counter() - start

    mine = {row[0]: row for row in sk}
    theirs = {row[0]: row for row in mp_ if row[0] not in mp_fail}
    both = sorted(set(mine) & set(theirs))
    names = ("H", "V_B", "H_A", "L_B")
    worst = dict.fromkeys((*names, "K", "K_heap_VV"), 0.0)
    disagree = []
    for i in both:
        a, b = mine[i], theirs[i]
        scale = np.hypot(a[1], a[2])
        for k, name in enumerate(names, start=1):
            ref = data[4][i] if name == "L_B" else scale
            worst[name] = max(worst[name], abs(a[k] - b[k]) / ref)
        if a[6]:  # a heap (H = 0): statics give dH/dspan = 0, MoorPy regularises it (slack_kx)
            worst["K_heap_VV"] = max(worst["K_heap_VV"], abs(a[5][1, 1] - b[5][1, 1]) / a[5][1, 1])
        else:
            worst["K"] = max(worst["K"], np.abs(a[5] - b[5]).max() / np.abs(a[5]).max())
        if max(abs(a[1] - b[1]), abs(a[2] - b[2])) / scale > 1e-6:
            disagree.append(i)

    print(f"{args.n} random scenes (seed {args.seed}) with contact and friction")
    print(f"both converged: {len(both)}")
    heaps = [i for i in both if mine[i][6]]
    profile4 = [i for i in heaps if theirs[i][6] == 4]
    print(f"of which heaps (H = 0, the excess slack on the seabed): {len(heaps)}, ", end="")
    print(f"MoorPy's profile 4: {len(profile4)}")
    print("largest difference skcable - MoorPy (forces / |T_B|, L_B / L, K / max|K| off the heaps,")
    print("dV_B/ddh on the heaps):")
    for name, value in worst.items():
        print(f"  {name:4s} {value:.2e}")
    for i in disagree:
        span, dh, w, EA, L, cb = (d[i] for d in data)
        H, V = mp_solution(span, dh, w, EA, L, cb, mine[i][1], mine[i][2])
        err_sk = max(abs(mine[i][1] - H), abs(mine[i][2] - V)) / np.hypot(H, V)
        err_mp = max(abs(theirs[i][1] - H), abs(theirs[i][2] - V)) / np.hypot(H, V)
        print(f"  scene {i}: 40-digit mpmath says skcable off by {err_sk:.1e}, MoorPy by {err_mp:.1e}")

    print(f"skcable refused {len(sk_fail)}:")
    for i, msg in sk_fail.items():
        print(f"  scene {i}: {msg}")
    print(f"MoorPy failed or flagged {len(mp_fail)}:")
    for i, msg in sorted(mp_fail.items()):
        if i in mine:
            span, dh, w, EA, L, cb = (d[i] for d in data)
            H, V = mp_solution(span, dh, w, EA, L, cb, mine[i][1], mine[i][2])
            err = max(abs(mine[i][1] - H), abs(mine[i][2] - V)) / np.hypot(H, V)
            print(f"  scene {i}: {msg}; skcable solved, off the 40-digit solution by {err:.1e}")
        else:
            print(f"  scene {i}: {msg}; skcable: {sk_fail[i]}")

    ok = np.array(sorted(mine))
    sub = [np.ascontiguousarray(d[ok]) for d in data]
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        r = cable.elastic_catenary(*sub[:4], length=sub[4], seabed=0.0, friction=sub[5])
        r.stiffness()
        best = min(best, time.perf_counter() - start)
    print("time per line (forces + stiffness):")
    print(f"  skcable scalar loop     {1e6 * t_sk / args.n:8.1f} us")
    print(f"  MoorPy scalar loop      {1e6 * t_mp / args.n:8.1f} us")
    print(f"  skcable vectorised      {1e6 * best / ok.size:8.1f} us  ({ok.size} lines in one call)")
    anchor_above(args.n // 5, args.seed, catenary)


if __name__ == "__main__":
    main()
