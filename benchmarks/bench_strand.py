"""Time per capacity curve of the strand model, mesh-converged in K_Leq.

Steel 9.5, one broken wire, 1 m, 40 load steps to rupture; for each model
(stick, the thesis's element slip rule, the per-point axis rule) the mesh is
refined until K_Leq changes by less than 0.5 % against the finest mesh, and
the time of one full curve on that mesh is reported (best of 3).

Run:  python benchmarks/bench_strand.py
"""

from __future__ import annotations

import time

from skcable import strand

MESHES = (8, 16, 32, 64, 128)


def curve(slip, n):
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 1.0, n_elements=n, slip=slip)
    return model.capacity_curve(n_steps=40)


def main():
    print("| model | elements | K_Leq [kN] | change vs 128 | time per curve [s] | Newton iterations |")
    print("|---|---|---|---|---|---|")
    for slip in ("none", "element", "axis"):
        reference = curve(slip, MESHES[-1]).K_Leq
        for n in MESHES:
            best, result = float("inf"), None
            for _ in range(3):
                start = time.perf_counter()
                result = curve(slip, n)
                best = min(best, time.perf_counter() - start)
            change = abs(result.K_Leq / reference - 1)
            iterations = sum(s.iterations for s in result.steps)
            cells = [slip, n, f"{result.K_Leq / 1e3:.1f}", f"{100 * change:.2f} %", f"{best:.2f}", iterations]
            print("| " + " | ".join(str(c) for c in cells) + " |")


if __name__ == "__main__":
    main()
