"""Record the strand model's numbers (K_Leq, D_r, rupture, slip fraction, peak curvature and the
whole force–strain curve) on a few coarse cases, so a restructured model can be checked against
the code that produced them: ``python benchmarks/pin_strand_numbers.py`` writes
``tests/strand/data/pinned_strand.json`` with the commit it ran on, every solve converged to 1e-13.
``tests/strand/test_pinned.py`` recomputes every case and compares. ``--slip axis --reason ...``
(or ``--preset NAME``) re-pins the cases of one slip law (or preset) only, when what they compute
changed, recording the commit and the reason in the file.
"""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from skcable import strand  # noqa: E402

#: (preset, damage, slip, damage_load): coarse meshes, few steps; aluminium is pulled to 0.008
#: only (below the softening range of its printed blend, where its curves stopped at this commit)
CASES = [
    ("steel-9.5", 1, "none", "eccentricity"),
    ("steel-9.5", 1, "axis", "eccentricity"),
    ("steel-9.5", 1, "element", "eccentricity"),
    ("steel-9.5", 2, "none", "eccentricity"),
    ("steel-9.5", 2, "axis", "eccentricity"),
    ("steel-9.5", 2, "element", "eccentricity"),
    ("aluminium-10.1", 1, "none", "eccentricity"),
    ("aluminium-10.1", 1, "element", "eccentricity"),
    ("steel-12.7", 2, "element", "sinusoidal"),
    ("steel-12.7", 2, "none", "sinusoidal"),
]
N_ELEMENTS, N_STEPS, MU, ALUMINIUM_TOP = 16, 24, 0.5, 0.008
#: every Newton solve converged this far (the pins are the model's equations, not a stopping rule)
TOL = 1e-13


def run(preset, damage, slip, damage_load):
    s = strand.preset(preset).damaged(damage)
    model = strand.StrandModel(s, 1.0, n_elements=N_ELEMENTS, slip=slip, mu=MU, damage_load=damage_load)
    top = ALUMINIUM_TOP if preset.startswith("aluminium") else None
    curve = model.capacity_curve(top, n_steps=N_STEPS, tol=TOL)
    peak = max(float(np.max(np.abs(st.curvature))) for st in curve.steps)
    # the steps up to rupture: the last step of this commit lies beyond the rupture strain
    inside = curve.steps[:-1] if curve.ruptured else curve.steps
    peak_inside = max(float(np.max(np.abs(st.curvature))) for st in inside)
    return {
        "preset": preset,
        "damage": damage,
        "slip": slip,
        "damage_load": damage_load,
        "K_Leq": curve.K_Leq,
        "max_strain": top,
        "ruptured": curve.ruptured,
        "D_r": curve.D_r if curve.ruptured else None,
        "rupture_strain": float(curve.strain[-1]),
        "rupture_force": float(curve.force[-1]),
        "max_slip_fraction": float(np.max(curve.slip_fraction)),
        "peak_curvature": peak,
        "peak_curvature_before_rupture": peak_inside,
        "strain": curve.strain.tolist(),
        "force": curve.force.tolist(),
        "slip_fraction": curve.slip_fraction.tolist(),
    }


def main(argv=None):
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--slip", help="re-pin only the cases of this slip law (the others are kept as recorded)"
    )
    parser.add_argument("--preset", help="re-pin only the cases of this preset (with --slip: of both)")
    parser.add_argument("--reason", default="", help="why the cases of --slip move (kept in the file)")
    args = parser.parse_args(argv)
    commit = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True, cwd=ROOT).stdout
    path = ROOT / "tests" / "strand" / "data" / "pinned_strand.json"
    if args.slip or args.preset:
        out = json.loads(path.read_text())
        chosen = [
            case
            for case in CASES
            if (args.slip is None or case[2] == args.slip) and (args.preset is None or case[0] == args.preset)
        ]
        if not chosen:
            raise SystemExit(f"no case has slip {args.slip!r} and preset {args.preset!r}")
        fresh = {tuple(case): run(*case) for case in chosen}
        out["cases"] = [
            fresh.get((c["preset"], c["damage"], c["slip"], c["damage_load"]), c) for c in out["cases"]
        ]
        out.setdefault("repinned", []).append(
            {
                "slip": args.slip,
                "preset": args.preset,
                "commit": commit.strip(),
                "tol": TOL,
                "reason": args.reason,
            }
        )
        path.write_text(json.dumps(out, indent=1))
        print(f"re-pinned {len(chosen)} cases in {path} at {commit[:10]}")
        return
    out = {
        "commit": commit.strip(),
        "n_elements": N_ELEMENTS,
        "n_steps": N_STEPS,
        "mu": MU,
        "cases": [run(*case) for case in CASES],
    }
    path.write_text(json.dumps(out, indent=1))
    print(f"wrote {path} ({len(CASES)} cases) at {out['commit'][:10]}")


if __name__ == "__main__":
    main()
