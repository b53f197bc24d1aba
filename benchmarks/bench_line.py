"""Multi-segment lines (`mooring.Line`): time per solve, outcome of random scenes, MoorPy agreement.

    python benchmarks/bench_line.py            # 2000 random scenes (seed 0) + 40 MoorPy scenes

Random scenes: 1-3 segments (20-600 m, w 30-3000 N/m, EA 1e7-1e10 N), clump weights and
buoys at the inner joints, no seabed / anchor on the seabed with friction 0-2 / anchor
1-100 m above it. Every scene either solves (residual reported) or raises InputError /
ConvergenceError; the counts are printed by reason.

MoorPy: chain-wire-chain, frictionless (MoorPy 1.x System lines carry no seabed friction),
a clump weight or a buoy on a free joint, solved by `System.solveEquilibrium(tol=1e-9)`.
"""

from __future__ import annotations

import collections
import time

import numpy as np

from skcable import mooring
from skcable.errors import ConvergenceError, InputError


def random_scenes(count, seed=0):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        n = int(rng.integers(1, 4))
        segments = [
            mooring.Segment(rng.uniform(20, 600), 10 ** rng.uniform(1.5, 3.5), 10 ** rng.uniform(7, 10))
            for _ in range(n)
        ]
        att = []
        for j in range(1, n):
            kind = rng.integers(0, 3)
            if kind == 1:
                att.append(mooring.ClumpWeight(j, 10 ** rng.uniform(3, 5.5)))
            elif kind == 2:
                att.append(mooring.Buoy(j, 10 ** rng.uniform(3, 5)))
        L = sum(s.length for s in segments)
        seabed = [None, 0.0, -rng.uniform(1, 100)][int(rng.integers(0, 3))]
        mu = rng.uniform(0, 2) if seabed == 0.0 else 0.0
        span = L * rng.uniform(0.05, 1.2)
        dh = L * rng.uniform(0.02, 0.9) * (1 if seabed is not None else rng.choice([-1, 1]))
        yield mooring.Line(segments, att, seabed=seabed, friction=mu), span, dh


def sweep(count=2000):
    outcome = collections.Counter()
    worst = 0.0
    start = time.perf_counter()
    for line, span, dh in random_scenes(count):
        try:
            sol = line.solve(span, dh)
            sol.stiffness()
        except InputError as exc:
            outcome[f"InputError({exc.argument!r})"] += 1
            continue
        except ConvergenceError:
            outcome["ConvergenceError"] += 1
            continue
        outcome["solved"] += 1
        worst = max(worst, sol.residual())
    elapsed = time.perf_counter() - start
    print(f"{count} random scenes in {elapsed:.2f} s ({1e3 * elapsed / count:.2f} ms per scene)")
    for key, value in outcome.most_common():
        print(f"  {value:5d} {key}")
    print(f"  largest residual of the solved scenes: {worst:.1e}")


def moorpy_comparison(count=40, seed=1):
    from moorpy import System

    rng = np.random.default_rng(seed)
    g, rho = 9.81, 1025.0
    worst, resting, t_sk, t_mp, done = 0.0, [], 0.0, 0.0, 0
    for _ in range(count):
        lengths = rng.uniform([300, 200, 100], [500, 400, 200])
        segments = [
            mooring.Segment(lengths[0], 1000.0, 7.5e8),
            mooring.Segment(lengths[1], 150.0, 6.0e8),
            mooring.Segment(lengths[2], 1000.0, 7.5e8),
        ]
        joint = int(rng.integers(1, 3))
        att = (
            mooring.ClumpWeight(joint, rng.uniform(5e3, 5e4)) if rng.random() < 0.5 else mooring.Buoy(2, 6e4)
        )
        line = mooring.Line(segments, [att], seabed=0.0)
        L = line.length
        dh = rng.uniform(0.2, 0.6) * L
        span = rng.uniform(0.75, 0.95) * np.sqrt(L * L - dh * dh)
        start = time.perf_counter()
        try:
            sol = line.solve(span, dh)
        except (InputError, ConvergenceError):
            continue
        t_sk += time.perf_counter() - start
        start = time.perf_counter()
        ms = System(depth=dh + 100.0, g=g, rho=rho)
        z0 = -(dh + 100.0)
        ms.addPoint(1, [0.0, 0.0, z0])
        for j in (1, 2):
            P = float(line.joint_forces[j])
            m, v = (P / g, 0.0) if P >= 0 else (0.0, -P / (rho * g))
            frac = lengths[:j].sum() / L
            ms.addPoint(0, [frac * span, 0.0, z0 + frac * dh], m=m, v=v)
        ms.addPoint(1, [span, 0.0, z0 + dh])
        for i, seg in enumerate(segments):
            props = dict(name=f"t{i}", d_vol=0.0, m=seg.w / g, w=seg.w, EA=seg.EA, d_nom=0.1)
            ms.setLineType(name=f"t{i}", lineType=props)
            ms.addLine(seg.length, f"t{i}", pointA=i + 1, pointB=i + 2)
        ms.initialize()
        try:
            ms.solveEquilibrium(tol=1e-9, maxIter=2000)
        except Exception as exc:  # noqa: BLE001 - a peer's failure is counted, not fatal
            print(f"  MoorPy failed: {exc}")
            continue
        f = ms.pointList[-1].getForces()
        t_mp += time.perf_counter() - start
        done += 1
        diff = max(abs(sol.H + f[0]) / sol.H, abs(sol.V_B + f[2]) / abs(sol.V_B))
        on_bed = sol.length_on_seabed > 0 and sol.y_joints[joint] == 0.0 and line.joint_forces[joint] > 0
        if on_bed:  # a clump resting on the seabed: MoorPy points have no seabed contact
            resting.append((diff, ms.pointList[joint].r[2] - z0))
        else:
            worst = max(worst, diff)
    print(f"MoorPy: {done} scenes, {done - len(resting)} with every joint clear of the seabed or the clump")
    print(f"  suspended: largest relative difference in (H, V_B): {worst:.1e}")
    for diff, height in resting:
        if height < 1e-6:
            print(f"  clump resting on the seabed in both codes: relative difference {diff:.1e}")
            continue
        print(
            f"  clump resting on the seabed (skcable): MoorPy differs by {diff:.1e}, its clump hovers "
            f"{height:.3f} m above the seabed, held by a grounded catenary that does not reach it"
        )
    per = 1e3 / max(done, 1)
    print(f"  time per line: skcable {per * t_sk:.2f} ms, MoorPy {per * t_mp:.1f} ms")


if __name__ == "__main__":
    sweep()
    try:
        moorpy_comparison()
    except ImportError:
        print("MoorPy not installed: comparison skipped")
