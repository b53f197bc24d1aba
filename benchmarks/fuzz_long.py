"""The long fuzz run: every regime of `tests.fuzz` for N minutes, every call classified.

The regimes, scene generators, oracles and classification are those of the CI test
(`tests/test_fuzz.py`, `tests/fuzz/`). Cases run in a worker process, the regimes taking
turns so that each gets about the same wall time; each call under its own time limit (SIGALRM)
and the worker under a watchdog (a call stuck in C code is killed, counted as a hang, and the
run goes on in a new worker). Every call is classified ok, silent-wrong, non-finite, untyped,
hang, spurious refusal, honest refusal (or oracle-failed, the oracle's own failure);
failures that a defect owned by another branch explains are marked with it
(`tests.fuzz.known`), whose probes are rerun to tell which of them are fixed.

The report, counts per regime and each failing call as a one-line reproducer, is written
atomically (a temporary file, then a rename) to ``docs/fuzz_report.md`` every minute and at
the end: a run that is stopped keeps what it found.

Run:   python benchmarks/fuzz_long.py --minutes 25 --seed 26
       python benchmarks/fuzz_long.py --case seabed:26:47     (one case, verbose)
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import platform
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tests.fuzz import known as known_defects  # noqa: E402
from tests.fuzz.harness import FAILURES, OUTCOMES, namespace, reproducer, run_case  # noqa: E402
from tests.fuzz.regimes import REGIMES, case  # noqa: E402

#: A worker silent for this long (s) is stuck beyond its calls' own time limits: killed.
WATCHDOG = 600.0


def _summary(outcome, index) -> dict:
    c = outcome.case
    known = known_defects.match(outcome)
    return {
        "regime": c.where[0],
        "sub": c.regime,
        "index": index,
        "kind": outcome.kind,
        "detail": outcome.detail,
        "seconds": outcome.seconds,
        "calls": c.calls,
        "repro": reproducer(c),
        "known": None if known is None else known.key,
    }


def _worker(conn, seed, names, next_index, spent, deadline):
    """Run cases until ``deadline``: the regime with the least time spent goes next."""
    import warnings

    warnings.simplefilter("ignore")
    ns = namespace()
    while time.time() < deadline:
        regime = min(names, key=lambda r: spent[r])
        index = next_index[regime]
        conn.send(("start", regime, index))
        start = time.perf_counter()
        try:
            outcome = run_case(case(regime, seed, index), ns)
            message = _summary(outcome, index)
        except Exception as exc:  # noqa: BLE001 - a generator's own failure is reported, not fatal
            message = {
                "regime": regime,
                "sub": regime,
                "index": index,
                "kind": "oracle-failed",
                "calls": 0,
                "detail": f"the scene generator failed: {type(exc).__name__}: {exc}",
                "seconds": 0.0,
                "repro": f"python benchmarks/fuzz_long.py --case {regime}:{seed}:{index}",
                "known": None,
            }
        message["wall"] = time.perf_counter() - start
        spent[regime] += message["wall"]
        next_index[regime] = index + 1
        conn.send(("done", message))
    conn.send(("end",))


class Run:
    """The state of a run: counts, failures, the schedule."""

    def __init__(self, seed, names, minutes):
        self.seed, self.names, self.minutes = seed, names, minutes
        self.counts = defaultdict(Counter)
        self.calls = Counter()
        self.seconds = Counter()
        self.wall = Counter()
        self.failures = []
        self.oracle_failed = []
        self.next_index = dict.fromkeys(names, 0)
        self.spent = dict.fromkeys(names, 0.0)
        self.started = time.time()

    def record(self, m):
        self.counts[m["sub"]][m["kind"]] += 1
        self.calls[m["sub"]] += max(1, m["calls"])
        self.seconds[m["sub"]] += m["seconds"]
        self.wall[m["sub"]] += m.get("wall", m["seconds"])
        self.next_index[m["regime"]] = m["index"] + 1
        self.spent[m["regime"]] += m.get("wall", m["seconds"])
        if m["kind"] in FAILURES:
            self.failures.append(m)
        elif m["kind"] == "oracle-failed":
            self.oracle_failed.append(m)

    def hang(self, regime, index):
        """A worker killed by the watchdog: its case counts as a hang."""
        c = case(regime, self.seed, index)
        self.record(
            {
                "regime": regime,
                "sub": c.regime,
                "index": index,
                "kind": "hang",
                "calls": 1,
                "seconds": WATCHDOG,
                "detail": f"the worker was silent for {WATCHDOG:g} s (stuck beyond the call's time limit)",
                "repro": reproducer(c),
                "known": None,
            }
        )


def run(seed, minutes, names, out, progress=True) -> Run:
    state = Run(seed, names, minutes)
    deadline = state.started + 60.0 * minutes
    context = multiprocessing.get_context("fork")
    last_write = time.time()
    while time.time() < deadline:
        parent, child = context.Pipe()
        proc = context.Process(
            target=_worker, args=(child, seed, names, state.next_index, state.spent, deadline)
        )
        proc.start()
        current = None
        while True:
            if not parent.poll(WATCHDOG):
                proc.kill()
                proc.join()
                if current is not None:
                    state.hang(*current)
                break
            message = parent.recv()
            if message[0] == "start":
                current = message[1:]
            elif message[0] == "done":
                state.record(message[1])
                current = None
            else:
                proc.join()
                break
            if time.time() - last_write > 60.0:
                write_report(state, out, final=False)
                last_write = time.time()
                if progress:
                    total = sum(sum(c.values()) for c in state.counts.values())
                    print(
                        f"{(time.time() - state.started) / 60:5.1f} min: {total} cases, "
                        f"{len(state.failures)} failures",
                        flush=True,
                    )
    return state


def _probes() -> list[tuple]:
    """Each known defect's probes rerun: ``(known, outcome kinds, fixed)``."""
    ns = namespace()
    rows = []
    for defect in known_defects.KNOWN:
        kinds = [run_case(build(), ns).kind for build in defect.probes]
        rows.append((defect, kinds, all(k not in FAILURES for k in kinds)))
    return rows


def _commit() -> str:
    try:
        sha = subprocess.run(
            ["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True, text=True
        )
        dirty = subprocess.run(
            ["git", "-C", str(ROOT), "status", "--porcelain", "--", "skcable"], capture_output=True, text=True
        )
        return sha.stdout.strip() + (" (with local changes to skcable/)" if dirty.stdout.strip() else "")
    except OSError:
        return "unknown"


def _table(state) -> list[str]:
    head = ["regime", "calls", *OUTCOMES, "s in calls", "s in all"]
    rows = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    total = Counter()
    for sub in sorted(state.counts):
        counts = state.counts[sub]
        total.update(counts)
        cells = [
            f"`{sub}`",
            str(state.calls[sub]),
            *(str(counts.get(k, 0)) for k in OUTCOMES),
            f"{state.seconds[sub]:.1f}",
            f"{state.wall[sub]:.0f}",
        ]
        rows.append("| " + " | ".join(cells) + " |")
    cells = [
        "**all**",
        str(sum(state.calls.values())),
        *(f"**{total.get(k, 0)}**" for k in OUTCOMES),
        f"{sum(state.seconds.values()):.0f}",
        f"{sum(state.wall.values()):.0f}",
    ]
    rows.append("| " + " | ".join(cells) + " |")
    return rows


def _failure_lines(failures, limit) -> list[str]:
    out = []
    for m in failures[:limit]:
        detail = m["detail"].replace("\n", " ")
        detail = detail if len(detail) < 600 else detail[:600] + " ..."
        out.append(f"- **{m['kind']}** `{m['sub']}` (case {m['index']}): {detail}")
        out.append(f"  ```sh\n  {m['repro']}\n  ```")
    if len(failures) > limit:
        out.append(
            f"- ... and {len(failures) - limit} more of this kind: rerun one with "
            f"`python benchmarks/fuzz_long.py --case REGIME:SEED:INDEX`; their cases: "
            + ", ".join(f"{m['regime']}:{m['index']}" for m in failures[limit : limit + 200])
        )
    return out


def report_text(state, final, probes) -> str:
    elapsed = (time.time() - state.started) / 60.0
    total = Counter()
    for counts in state.counts.values():
        total.update(counts)
    lines = [
        "# Fuzz report",
        "",
        "The last run of the long fuzz harness, `benchmarks/fuzz_long.py` (issue 26: nothing silent). Every "
        "call of a seeded scene goes through an oracle independent of the function under test (50-digit "
        "roots of Irvine's and Jonkman's equations, an independent walk along multi-segment lines, force "
        "recounts on moored bodies, central differences, Chebyshev collocation of Irvine's vibration theory, "
        "wire-by-wire section sums) and is classified; refusals are judged by an independent solver. The "
        "regimes, generators and oracles are those of the CI test `tests/test_fuzz.py` (`tests/fuzz/`).",
        "",
        f"- command: `python benchmarks/fuzz_long.py --minutes {state.minutes:g} --seed {state.seed}`"
        + ("" if final else " (**run in progress**: this page is rewritten every minute)"),
        f"- commit: `{_commit()}`; Python {platform.python_version()} on {platform.machine()}, "
        f"{os.cpu_count()} cores (shared)",
        f"- elapsed: {elapsed:.1f} min; {sum(sum(c.values()) for c in state.counts.values())} cases, "
        f"{sum(state.calls.values())} calls",
        "",
        "## Totals",
        "",
        " ".join(f"{k}: **{total.get(k, 0)}**;" for k in OUTCOMES).rstrip(";"),
        "",
        "## Per regime",
        "",
        *_table(state),
        "",
        "A case is one scene; an invariance case calls the function twice (the scene and its mirrored, "
        "turned or rescaled twin), which *calls* counts. *s in calls*: the time in skcable's calls; *s in "
        "all*: with the oracles and the independent solvers (the regimes take turns by that time).",
        "",
    ]
    lines += _known_section(state, probes)
    new = [m for m in state.failures if m["known"] is None]
    lines += ["## New failures (no known defect explains them)", ""]
    lines += _failure_lines(new, 100) if new else ["None."]
    lines += [
        "",
        "## Oracle failures (the oracle could not decide: not counted against skcable)",
        "",
        "Mostly `solve_line_bvp` results outside the independent walk's model (a buoy lifting the grounded "
        "line, a second touchdown): returned, finite, unchecked.",
        "",
    ]
    lines += _failure_lines(state.oracle_failed, 20) if state.oracle_failed else ["None."]
    return "\n".join(lines) + "\n"


def _known_section(state, probes) -> list[str]:
    lines = [
        "## Known defects",
        "",
        "Each defect the fuzz found, the branch whose code it was found in, and whether its fix has "
        "landed (*fix landed*: then it explains no failure, which counts as new; its probes still rerun).",
        "",
    ]
    lines += [
        "| defect | issue | branch | what | fix landed | failures in this run | probes |",
        "|---|---|---|---|---|---|---|",
    ]
    by_key = defaultdict(list)
    for m in state.failures:
        if m["known"] is not None:
            by_key[m["known"]].append(m)
    for defect, kinds, fixed in probes or [(d, [], None) for d in known_defects.KNOWN]:
        status = (
            "not rerun"
            if fixed is None
            else ("**fixed**" if fixed else "still failing") + f" ({', '.join(kinds)})"
        )
        lines.append(
            f"| {defect.key} | {defect.issue} | `{defect.branch}` | {defect.summary} | "
            f"{'yes' if defect.fixed else 'no'} | {len(by_key.get(defect.key, []))} | {status} |"
        )
    lines.append("")
    for key, failures in sorted(by_key.items()):
        lines += [f"### {key}: its failures in this run", ""]
        lines += _failure_lines(failures, 12)
        lines.append("")
    return lines


def write_report(state, out, final, probes=None) -> None:
    """Write the report atomically: a temporary file beside it, then a rename."""
    text = report_text(state, final, probes)
    out = Path(out)
    fd, tmp = tempfile.mkstemp(prefix=".fuzz_report.", suffix=".md", dir=out.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, out)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def one_case(spec: str) -> None:
    regime, seed, index = spec.rsplit(":", 2)
    c = case(regime, int(seed), int(index))
    outcome = run_case(c)
    print(f"{outcome.kind} ({outcome.seconds:.3f} s): {outcome.detail}")
    print(reproducer(c))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=25.0)
    parser.add_argument("--seed", type=int, default=26)
    parser.add_argument("--regimes", default="", help="comma-separated regime names (default: all)")
    parser.add_argument("--out", default=str(ROOT / "docs" / "fuzz_report.md"))
    parser.add_argument("--case", help="run one case REGIME:SEED:INDEX and print its outcome")
    args = parser.parse_args(argv)
    if args.case:
        one_case(args.case)
        return 0
    names = [r for r in args.regimes.split(",") if r] or list(REGIMES)
    unknown = [r for r in names if r not in REGIMES]
    if unknown:
        parser.error(f"unknown regimes {unknown}; known: {', '.join(REGIMES)}")
    state = run(args.seed, args.minutes, names, args.out)
    write_report(state, args.out, final=True, probes=_probes())
    total = Counter()
    for counts in state.counts.values():
        total.update(counts)
    print(" ".join(f"{k}={total.get(k, 0)}" for k in OUTCOMES))
    print(f"report: {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
