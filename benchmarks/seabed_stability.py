"""Stability map of the seabed-line solvers, skcable's and MoorPy's, one process.

A grid of scenes of a line anchored on a flat seabed (A at (0, 0), fairlead B at
(span, dh), span 100 m, w = 1 N/m), with Coulomb friction (J.M. Jonkman, "Dynamics
modeling and loads analysis of an offshore floating wind turbine", NREL, 2007):

- dh/span from 0.05 to 10 (nearly horizontal to nearly vertical),
- slack s = (L - chord)/(span + dh - chord) from 1e-6 (taut) to 0.999 (almost all on the
  seabed), 1 (the L-shape) and 1.3 (more line than the L: the excess lies in a heap, no
  solution with H > 0),
- friction 0, 0.5 and 5, EA = 1e3 and 1e7 times the line's weight.

Methods: skcable's closed form (`elastic_catenary(seabed=0)`), its multi-segment `Line` with
one segment, its arc-length BVP with unilateral contact (`solve_line_bvp`, the mesh doubled
from 80 elements until two meshes agree within 1e-10, at most 1280, or until their change stops
falling: the round-off regime of a taut line), MoorPy's `catenary()`.

Each run's fairlead forces (H, V_B) are compared with a 40-digit mpmath solution of
Jonkman's equations (grounded) or Irvine's (lifted off the anchor), and classified:

- right: |(H, V_B) - exact| / |T_B| <= max(1e-8, 8 eps cond), cond = S/(2(S - c)) as in
  benchmarks/stability_map.py (the chord rounded to double precision carries eps·cond);
- wrong: returned numbers farther than that (a slack heap answer H = 0 counts as wrong only
  where a solution with H > 0 exists);
- failed: raised or flagged an error where a solution exists;
- refused: raised where no solution with H > 0 exists (the heap) — the right answer;
- heap: returned the heap answer H = 0 where no solution with H > 0 exists.

Run:  python benchmarks/seabed_stability.py          (about a minute)
Output: the table on stdout and in docs/stability.md between the seabed markers;
benchmarks/out/seabed_stability.csv (every run and its message).
"""

from __future__ import annotations

import contextlib
import csv
import io
import itertools
import sys
import warnings
from collections import Counter
from pathlib import Path

import mpmath as mp
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _reference import jonkman_grounded  # noqa: E402
from _tables import write_section  # noqa: E402

from skcable import cable, mooring  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SPAN, W = 100.0, 1.0
DH_OVER_SPAN = (0.05, 0.3, 1.0, 3.0, 10.0)
SLACK = (1e-6, 1e-3, 0.1, 0.5, 0.9, 0.999, 1.0, 1.3)
FRICTION = (0.0, 0.5, 5.0)
EA_OVER_WEIGHT = (1e3, 1e7)
TOL = 1e-8
STATUSES = ("right", "wrong", "failed", "refused", "heap")


def scenes():
    for ratio, s, cb, k in itertools.product(DH_OVER_SPAN, SLACK, FRICTION, EA_OVER_WEIGHT):
        dh = ratio * SPAN
        chord = float(np.hypot(SPAN, dh))
        L = chord + s * (SPAN + dh - chord)
        yield ratio, s, cb, k, dh, L, k * W * L


def exact(dh, L, EA, cb, starts):
    """(H, V_B) at 40 digits, or None where no solution with H > 0 is found from any start."""
    mp.mp.dps = 40
    span, dh, w, EA, L, cb = (mp.mpf(repr(float(v))) for v in (SPAN, dh, W, EA, L, cb))

    grounded = jonkman_grounded(span, dh, w, EA, L, cb)

    def lifted(H, V):  # Irvine, V the vertical force at B; the anchor pulls down by wL - V
        tva, tvb = V - w * L, V
        X = H * L / EA + H / w * (mp.asinh(tvb / H) - mp.asinh(tva / H))
        Z = (tvb**2 - tva**2) / (2 * w * EA) + (mp.hypot(H, tvb) - mp.hypot(H, tva)) / w
        return [X - span, Z - dh]

    for H0, V0 in starts:
        for f, ok in ((grounded, lambda V: V <= w * L), (lifted, lambda V: V > w * L)):
            try:
                H, V = mp.findroot(f, (mp.mpf(H0), mp.mpf(V0)), tol=mp.mpf(10) ** -30, maxsteps=200)
            except (ValueError, ZeroDivisionError):
                continue
            if (
                mp.im(H) == 0
                and mp.im(V) == 0
                and H > 0
                and V > 0
                and ok(V)
                and max(map(abs, f(H, V))) < 1e-25
            ):
                return float(H), float(V)
    return None


def skcable_closed(dh, L, EA, cb):
    r = cable.elastic_catenary(SPAN, dh, W, EA, length=L, seabed=0.0, friction=cb)
    return float(r.H), float(r.V_B)


def skcable_line(dh, L, EA, cb):
    r = mooring.Line([mooring.Segment(L, W, EA)], seabed=0.0, friction=cb).solve(SPAN, dh)
    return float(r.H), float(r.V_B)


def skcable_bvp(dh, L, EA, cb):
    """The arc-length BVP with unilateral contact, the mesh doubled from 80 elements until two
    meshes agree within 1e-10 (at most 1280), or until their change stops falling: a taut line's
    round-off grows with the mesh (n eps times the condition number of H) and outgrows its
    discretisation error; then the coarser of the last two meshes."""
    before, change = None, np.inf
    for n in (80, 160, 320, 640, 1280):
        r = mooring.solve_line_bvp(SPAN, dh, [(L, W, EA)], seabed=0.0, friction=cb, n_elements=n)
        now = np.array([r.H, r.V_B])
        if before is not None:
            moved = np.hypot(*(now - before)) / np.hypot(*now)
            if moved <= 1e-10:
                return float(r.H), float(r.V_B)
            if moved >= change:
                return float(before[0]), float(before[1])
            change = moved
        before = now
    raise RuntimeError("no mesh agreement within 1e-10 by 1280 elements")


def moorpy_catenary(dh, L, EA, cb):
    from moorpy.Catenary import catenary

    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):  # MoorPy prints
        warnings.simplefilter("ignore")
        fAH, fAV, fBH, fBV, info = catenary(SPAN, dh, L, EA, W, CB=cb, Tol=1e-12, MaxIter=500)
    if info["ProfileType"] < 0 or info.get("error"):
        raise RuntimeError(f"ProfileType {info['ProfileType']}")
    return -float(fBH), -float(fBV)


def methods():
    out = {
        "skcable elastic_catenary(seabed=0)": skcable_closed,
        "skcable Line (one segment)": skcable_line,
        "skcable solve_line_bvp (arc form, contact)": skcable_bvp,
    }
    try:
        import moorpy  # noqa: F401
    except ImportError:
        print("MoorPy not installed: its rows are left out", file=sys.stderr)
    else:
        out["MoorPy catenary()"] = moorpy_catenary
    return out


def run():
    rows = []
    fns = methods()
    for ratio, s, cb, k, dh, L, EA in scenes():
        answers = {}
        for name, fn in fns.items():
            try:
                answers[name] = fn(dh, L, EA, cb)
            except Exception as exc:  # noqa: BLE001 - a peer's failure is data here
                answers[name] = f"{type(exc).__name__}: {exc}".splitlines()[0][:160]
        starts = [a for a in answers.values() if isinstance(a, tuple) and a[0] > 0]
        starts += [(0.5 * W * SPAN, W * dh), (5.0 * W * SPAN, W * L)]
        ref = exact(dh, L, EA, cb, starts)
        chord = float(np.hypot(SPAN, dh))
        allowed = max(TOL, 8 * np.finfo(float).eps * L / (2 * max(L - chord, 1e-300)))
        for name, answer in answers.items():
            error, message = "", ""
            if isinstance(answer, str):
                status, message = ("refused" if ref is None else "failed"), answer
            elif not all(np.isfinite(answer)):
                status, message = "failed", f"returned {answer}"
            elif ref is None:
                status = "heap" if answer[0] == 0 else "wrong"
            else:
                error = float(np.hypot(answer[0] - ref[0], answer[1] - ref[1]) / np.hypot(*ref))
                status = "right" if error <= allowed else "wrong"
            rows.append((ratio, s, cb, k, name, status, error, message))
    return rows


def table(rows):
    names = list(dict.fromkeys(r[4] for r in rows))
    lines = [
        "| method | " + " | ".join(STATUSES) + " |",
        "|---|" + "---|" * len(STATUSES),
    ]
    for name in names:
        counts = [sum(r[4] == name and r[5] == s for r in rows) for s in STATUSES]
        lines.append(f"| {name} | " + " | ".join(map(str, counts)) + " |")
    return "\n".join(lines)


def notes(rows):
    out = []
    for name in dict.fromkeys(r[4] for r in rows):
        bad = [r for r in rows if r[4] == name and r[5] in ("wrong", "failed")]
        if not bad:
            out.append(f"- {name}: no wrong or failed run.")
            continue
        kinds = Counter(
            r[7].split(":")[0] + (f" ({r[7].split(':')[1].strip()})" if r[7].startswith("InputError") else "")
            if r[7]
            else r[5]
            for r in bad
        )
        listed = "; ".join(f"{count} {kind}" for kind, count in kinds.most_common())
        cells = sorted({(r[0], r[1]) for r in bad})
        where = ", ".join(f"({a:g}, {b:g})" for a, b in cells[:8]) + (" ..." if len(cells) > 8 else "")
        out.append(f"- {name}: {len(bad)} wrong or failed: {listed}; at (dh/span, slack) {where}.")
    return "\n".join(out)


def main():
    rows = run()
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    with open(out / "seabed_stability.csv", "w", newline="") as f:
        csv.writer(f).writerows(
            [("dh_over_span", "slack", "friction", "EA_over_weight", "method", "status", "error", "message")]
            + rows
        )
    body = f"{table(rows)}\n\n{notes(rows)}"
    print(body)
    write_section(ROOT / "docs" / "stability.md", "seabed-stability", body.split("\n"))


if __name__ == "__main__":
    main()
