"""Where the strand solver struggles: friction, step size, mesh, slip rule, near rupture.

Runs capacity curves over friction coefficients 0.05-1 (both slip rules), coarse and fine
step schedules, very coarse and very fine meshes, and the strands whose slip runs are known
to stop (aluminium 10.1 mm), as a skcable.study (a local Dask cluster when available, the
results cached in benchmarks/out/strand_stability_cache so an interrupted run resumes).
For every run: status, where it stopped, and the mitigations the solver used (step
cutbacks, steps whose slip state chattered and was kept lagged).

Run:  python benchmarks/strand_stability.py
Output: benchmarks/out/strand_stability.csv and a markdown table on stdout (docs/stability.md).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from skcable import study

ROOT = Path(__file__).resolve().parents[1]


def capacity_run(preset, damage, slip, mu=0.5, n_steps=None, n_elements=None):
    """One capacity curve with its solver statistics (on_failure="stop": the converged part is kept)."""
    from skcable import strand

    model = strand.StrandModel(
        strand.preset(preset).damaged(damage), 1.0, slip=slip, mu=mu, n_elements=n_elements
    )
    curve = model.capacity_curve(n_steps=n_steps, on_failure="stop")
    return {
        "ruptured": curve.ruptured,
        "last_strain": float(curve.strain[-1]),
        "steps": len(curve.steps),
        "cutbacks": curve.cutbacks,
        "chatter_steps": len(curve.chatter_steps),
        "max_newton_iterations": max(s.iterations for s in curve.steps),
        "K_Leq": curve.K_Leq,
        "failure": curve.failure or "",
    }


def cases():
    out = [
        dict(preset="steel-9.5", damage=1, slip=slip, mu=mu)
        for slip in ("axis", "element")
        for mu in (0.05, 0.1, 0.3, 0.5, 1.0)
    ]
    out += [dict(preset="steel-9.5", damage=1, slip="axis", n_steps=n) for n in (8, 16, 240)]
    out += [dict(preset="steel-9.5", damage=1, slip="axis", n_elements=n) for n in (8, 512)]
    out += [dict(preset="steel-9.5", damage=2, slip="axis", mu=mu) for mu in (0.05, 1.0)]
    out += [dict(preset="aluminium-10.1", damage=1, slip=slip) for slip in ("none", "axis", "element")]
    return out


def main():
    table = study.run(capacity_run, cases(), cache=ROOT / "benchmarks" / "out" / "strand_stability_cache")
    table.to_csv(ROOT / "benchmarks" / "out" / "strand_stability.csv", index=False)
    columns = [
        "preset",
        "damage",
        "slip",
        "mu",
        "n_steps",
        "n_elements",
        "status",
        "ruptured",
        "last_strain",
        "steps",
        "cutbacks",
        "chatter_steps",
        "max_newton_iterations",
        "time_s",
    ]
    shown = table.reindex(columns=columns).replace({np.nan: ""})
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))
    for _, row in shown.iterrows():
        cells = [f"{v:.4g}" if isinstance(v, float) else str(v) for v in row]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
