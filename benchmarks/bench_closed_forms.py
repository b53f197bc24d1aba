"""Speed and accuracy of skcable's closed forms against the peers, one process.

Case of issue #2: span 800 m, dh -20 m, w 20 kN/m, EA 1e12 kN, unstretched
length 801.409 m. Each solver is timed over repeated calls (median of 5
batches, per call) and its H compared with a 40-digit mpmath solution of
Irvine's equations. Peers that are not installed are reported as such. mechaphlowers' span
model takes the catenary parameter H/w as input (its length solve lives in
its change-of-state machinery), so it is compared on the vectorised
forward evaluation, given H.

Run:  python benchmarks/bench_closed_forms.py            (table on stdout, and into docs/benchmarks.md
                                                         between its closed-forms-peers markers)
      python benchmarks/bench_closed_forms.py --csv out.csv [--no-write]
Peers: pip install ".[bench]"  (OpenSeesPy also needs Debian's libblas3 liblapack3)
"""

from __future__ import annotations

import argparse
import csv
import datetime
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import mpmath as mp
import numpy as np

from skcable import cable

sys.path.insert(0, str(Path(__file__).parent))
from _peers import available, moorpy_H, opensees_catenary_cable_H, pycatenary_H  # noqa: E402
from _tables import markdown_table, write_section  # noqa: E402

SPAN, DH, W, EA, L0 = 800.0, -20.0, 20.0, 1e12, 801.409


def reference_H() -> tuple[float, float]:
    """(H elastic, H inextensible) to 40 digits."""
    mp.mp.dps = 40
    span, dh, w, ea, L0 = (mp.mpf(v) for v in (SPAN, DH, W, EA, "801.409"))

    def closure(H, VA):
        tva, tvb = -VA, w * L0 - VA
        x = H * L0 / ea + H / w * (mp.asinh(tvb / H) - mp.asinh(tva / H))
        y = L0 * (w * L0 / 2 - VA) / ea + (mp.hypot(H, tvb) - mp.hypot(H, tva)) / w
        return x - span, y - dh

    guess = cable.elastic_catenary(SPAN, DH, W, EA, length=L0)
    H, _ = mp.findroot(closure, (mp.mpf(guess.H), mp.mpf(guess.V_A)))
    r = mp.sqrt(L0**2 - dh**2) / span
    z = mp.findroot(lambda z: mp.sinh(z) / z - r, mp.mpf(0.13))
    return float(H), float(w * span / (2 * z))


def newton_floor(span, dh, w, length, rtol=1e-8):
    """The floor of vectorised ``catenary(length=)``: a plain NumPy Newton that computes H alone.

    ``sinh(z)/z = r``, ``r = sqrt(S² - dh²)/span``, by Newton's method from the shallow-cable
    start ``z = sqrt(6 (r - 1))``, all elements stepping together until the largest relative
    step is below ``rtol``; then ``H = w span / (2 z)``. No other output, no check, no care for
    cancellation (``sinh(z)/z - r`` costs it digits on taut spans)."""
    r = np.sqrt(length * length - dh * dh) / span
    z = np.sqrt(6.0 * (r - 1.0))
    for _ in range(100):
        s, c = np.sinh(z), np.cosh(z)
        step = (s / z - r) / ((z * c - s) / (z * z))
        z = z - step
        if np.all(np.abs(step) <= rtol * z):
            return w * span / (2.0 * z)
    raise RuntimeError("the floor's Newton did not converge")


def timed(fn, number: int) -> float:
    """Seconds a call: the median of 5 batches of ``number`` calls (the machine may be shared)."""
    fn()
    batches = []
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(number):
            fn()
        batches.append((time.perf_counter() - start) / number)
    return statistics.median(batches)


def peers():
    """(name, callable returning H, or None when the peer is not installed)."""
    args = (SPAN, DH, W, EA, L0)
    return [
        ("MoorPy catenary()", available(moorpy_H, *args)),
        ("pycatenary MooringLine", available(pycatenary_H, *args)),
        ("OpenSeesPy CatenaryCable (build+solve)", available(opensees_catenary_cable_H, *args)),
    ]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", help="write the table as CSV here")
    parser.add_argument("--spans", type=int, default=1_000_000, help="size of the vectorised batch")
    parser.add_argument("--no-write", action="store_true", help="print only")
    args = parser.parse_args(argv)

    H_elastic, H_rigid = reference_H()
    rows = []

    def row(name, kind, fn, ref, number=2000):
        if fn is None:
            rows.append((name, kind, "not installed", "", ""))
            return
        H = float(fn())
        t = timed(fn, number)
        rows.append((name, kind, f"{t * 1e6:.1f}", f"{abs(H / ref - 1):.1e}", ""))

    row(
        "skcable catenary(length=)",
        "inextensible",
        lambda: cable.catenary(SPAN, DH, W, length=L0).H,
        H_rigid,
        20000,
    )
    row(
        "skcable elastic_catenary",
        "elastic",
        lambda: cable.elastic_catenary(SPAN, DH, W, EA, length=L0).H,
        H_elastic,
    )
    for name, fn in peers():
        row(name, "elastic", fn, H_elastic, 200)

    # vectorised: a batch of different spans, each checked by its residual
    rng = np.random.default_rng(0)
    spans = rng.uniform(100.0, 1000.0, args.spans)
    lengths = np.hypot(spans, DH) * (1.0 + rng.uniform(1e-6, 0.5, args.spans))
    t = timed(lambda: cable.catenary(spans, DH, W, length=lengths), 1)
    sol = cable.catenary(spans, DH, W, length=lengths)
    rows.append(
        (
            "skcable catenary, vectorised",
            "inextensible",
            f"{t * 1e6 / args.spans:.3f}",
            f"residual {sol.residual():.1e}",
            f"{args.spans / t:.3g} spans/s",
        )
    )
    t = timed(lambda: newton_floor(spans, DH, W, lengths), 1)
    gap = np.max(np.abs(newton_floor(spans, DH, W, lengths) / sol.H - 1))
    rows.append(
        (
            "NumPy Newton floor (H alone), vectorised",
            "inextensible",
            f"{t * 1e6 / args.spans:.3f}",
            f"H vs skcable {gap:.0e}",
            f"{args.spans / t:.3g} spans/s",
        )
    )

    # given H (the catenary parameter), vectorised: mechaphlowers' span model
    # takes the parameter as input, so this is the like-for-like comparison
    params = rng.uniform(500.0, 5000.0, args.spans)
    t = timed(lambda: cable.catenary(spans, DH, W, H=W * params).length, 1)
    rows.append(
        (
            "skcable catenary(H=), vectorised",
            "inextensible",
            f"{t * 1e6 / args.spans:.3f}",
            "",
            f"{args.spans / t:.3g} spans/s",
        )
    )
    try:
        from mechaphlowers.core.models.cable.span import CatenarySpan

        heights = np.full(args.spans, DH)

        def mecha():
            span = CatenarySpan(
                span_length=spans, elevation_difference=heights, parameter=params, linear_weight=W
            )
            return span.compute_L(), span.T_h()

        t = timed(mecha, 1)
        gap = np.max(np.abs(mecha()[0] / cable.catenary(spans, DH, W, H=W * params).length - 1))
        rows.append(
            (
                "mechaphlowers CatenarySpan, vectorised",
                "inextensible",
                f"{t * 1e6 / args.spans:.3f}",
                f"length vs skcable {gap:.1e}",
                f"{args.spans / t:.3g} spans/s",
            )
        )
    except ImportError:
        rows.append(("mechaphlowers CatenarySpan, vectorised", "inextensible", "not installed", "", ""))

    # ratio to skcable solving the same model in the same way
    baseline = {
        "MoorPy catenary()": "skcable elastic_catenary",
        "pycatenary MooringLine": "skcable elastic_catenary",
        "OpenSeesPy CatenaryCable (build+solve)": "skcable elastic_catenary",
        "mechaphlowers CatenarySpan, vectorised": "skcable catenary(H=), vectorised",
        "NumPy Newton floor (H alone), vectorised": "skcable catenary, vectorised",
    }
    times = {r[0]: r[2] for r in rows}
    header = ("solver", "model", "µs per call (per span)", "rel. error in H", "note", "time / skcable")
    table = []
    for r in rows:
        own, ref = r[2], times.get(baseline.get(r[0], r[0]))
        ratio = f"{float(own) / float(ref):.2f}" if own != "not installed" else ""
        table.append((*r, ratio))
    lines = markdown_table(header, table)
    print("\n".join(lines))
    if not args.no_write:
        moorpy = times.get("MoorPy catenary()", "")
        note = f"; MoorPy took {moorpy} µs a call here" if moorpy not in ("", "not installed") else ""
        head = (
            f"Generated by `python benchmarks/bench_closed_forms.py` on {datetime.date.today()}, "
            f"{platform.machine()}, {os.cpu_count()} cores shared with other jobs, Python "
            f"{platform.python_version()}, NumPy {np.__version__}{note}; batches of "
            f"{args.spans:,} spans:"
        )
        print("wrote", write_table([head, "", *lines]))
    if args.csv:
        with open(args.csv, "w", newline="") as fh:
            csv.writer(fh).writerows([header, *table])


PAGE = Path(__file__).resolve().parents[1] / "docs" / "benchmarks.md"


def write_table(lines, page=PAGE):
    """Replace the table between the closed-forms-peers markers of ``page`` (atomic:
    `_tables.write_section`)."""
    return write_section(page, "closed-forms-peers", lines)


if __name__ == "__main__":
    main()
