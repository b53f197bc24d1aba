"""Run one fuzzed call under a timeout and classify it.

A `Case` is a Python expression (its own reproducer: it is what runs), the argument names an
`InputError` of it may name, an oracle ``check`` of its result and a ``judge`` of a refusal.
`run_case` evaluates it with warnings recorded and classifies the outcome as one of
`OUTCOMES`:

- ``ok``: a result, every number in it finite, the oracle agreeing;
- ``silent-wrong``: a result the oracle disagrees with (beyond the error the problem's
  conditioning allows), or an unstable state not flagged;
- ``non-finite``: a NaN or an infinity among the returned numbers;
- ``untyped``: an exception other than `InputError` naming an argument of the call and
  `ConvergenceError` with a history (a bare ``ValueError``, ``TypeError``,
  ``ZeroDivisionError``, ``OverflowError``, ``LinAlgError``, ``AttributeError`` ...), or an
  `InputError` naming no argument of the call, or another argument than the one an edge
  case made invalid;
- ``hang``: the call ran past its timeout;
- ``spurious-refusal``: a refusal where the independent solver finds the answer;
- ``honest-refusal``: a refusal the independent solver confirms (no answer, or none the
  model describes);
- ``oracle-failed``: the oracle could not decide (not counted against skcable; reported).
"""

from __future__ import annotations

import contextlib
import io
import math
import signal
import time
import traceback
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from skcable.errors import ConvergenceError, InputError
from tests.fuzz.mp import NoRoot, OutOfScope

__all__ = [
    "Case",
    "Hang",
    "RefusedByCli",
    "Outcome",
    "OUTCOMES",
    "FAILURES",
    "run_case",
    "namespace",
    "reproducer",
    "time_limit",
]

OUTCOMES = (
    "ok",
    "silent-wrong",
    "non-finite",
    "untyped",
    "hang",
    "spurious-refusal",
    "honest-refusal",
    "oracle-failed",
)
FAILURES = ("silent-wrong", "non-finite", "untyped", "hang", "spurious-refusal")
PREAMBLE = "from skcable import bvp, cable, cli, conductors, io, mooring, strand; import numpy as np"


class RefusedByCli(Exception):
    """A command line refused what the library call it stands for solves (a spurious refusal)."""


class Hang(BaseException):
    """The call ran past its time limit (a BaseException: no ``except Exception`` of the code
    under test swallows it)."""


@dataclass
class Case:
    """One fuzzed call.

    ``expr``: a Python expression in `namespace` (``bvp``, ``cable``, ``cli``, ``conductors``,
    ``io``, ``mooring``, ``strand``, ``np``), evaluated as is. ``names``: the arguments an
    `InputError` may name (``None``: any argument name the expression spells as a keyword or
    documents). ``check(result,
    warnings)``: the oracle, a list of disagreements (empty: ok) or `NoRoot`. ``judge(exc)``:
    None where the refusal is honest, else why it is spurious (the independent solver's
    answer); ``must_name``: the argument an edge case made invalid (then the refusal must
    name it). ``where``: the fuzz coordinates (regime, seed, index)."""

    regime: str
    expr: str
    names: frozenset
    check: Callable | None = None
    judge: Callable | None = None
    must_name: str | tuple | None = None
    timeout: float = 30.0
    where: tuple = ()
    note: str = ""
    shell: str | None = None  # a command line: the expression runs `cli.main`, output captured
    calls: int = 1  # calls of the function under test in the expression (2 for an invariance pair)


@dataclass
class Outcome:
    kind: str
    case: Case
    detail: str = ""
    seconds: float = 0.0
    exc_type: str = ""
    warnings: list = field(default_factory=list)

    @property
    def failed(self) -> bool:
        return self.kind in FAILURES


def namespace() -> dict:
    from skcable import bvp, cable, cli, conductors, io, mooring, strand

    return {
        "bvp": bvp,
        "cable": cable,
        "conductors": conductors,
        "mooring": mooring,
        "cli": cli,
        "io": io,
        "strand": strand,
        "np": np,
        "inf": math.inf,
        "nan": math.nan,
    }


def reproducer(case: Case) -> str:
    """The one-line shell command that repeats the call."""
    if case.shell is not None:
        return case.shell
    code = f"{PREAMBLE}; print({case.expr})"
    return "python -c " + _shell_quote(code)


def _shell_quote(text: str) -> str:
    return "'" + text.replace("'", "'\"'\"'") + "'"


class time_limit:  # noqa: N801 - a context manager used like a function
    """Raise `Hang` in the main thread after ``seconds`` (SIGALRM; no-op off the main thread)."""

    def __init__(self, seconds: float):
        self.seconds = seconds

    def __enter__(self):
        try:
            self.old = signal.signal(signal.SIGALRM, self._fire)
        except ValueError:  # not the main thread
            self.old = None
            return self
        signal.setitimer(signal.ITIMER_REAL, self.seconds)
        return self

    @staticmethod
    def _fire(signum, frame):
        raise Hang()

    def __exit__(self, *exc):
        if self.old is not None:
            signal.setitimer(signal.ITIMER_REAL, 0.0)
            signal.signal(signal.SIGALRM, self.old)
        return False


def _refusal(case: Case, exc: BaseException) -> tuple[str, str]:
    """``(kind, detail)`` of an exception: untyped, or a refusal to judge."""
    name = type(exc).__name__
    if isinstance(exc, InputError):
        if not isinstance(getattr(exc, "argument", None), str):
            return "untyped", f"InputError without an argument name: {exc}"
        wanted = (case.must_name,) if isinstance(case.must_name, str) else case.must_name
        if wanted is not None and exc.argument not in wanted:
            return "untyped", f"InputError names {exc.argument!r} where {wanted[0]!r} is invalid: {exc}"
        if case.names and exc.argument not in case.names:
            return "untyped", f"InputError names {exc.argument!r}, no argument of the call: {exc}"
        return "refusal", f"InputError: {exc}"
    if isinstance(exc, ConvergenceError):
        if not isinstance(getattr(exc, "history", None), list):
            return "untyped", f"ConvergenceError without a history: {exc}"
        return "refusal", f"ConvergenceError: {exc}"
    where = traceback.extract_tb(exc.__traceback__)[-1]
    return "untyped", f"{name}: {exc} (at {where.filename.split('/')[-1]}:{where.lineno})"


def _judge(case: Case, exc: BaseException, detail: str) -> tuple[str, str]:
    if case.judge is None:
        return "honest-refusal", detail
    try:
        with time_limit(max(60.0, 4 * case.timeout)), warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            verdict = case.judge(exc)
    except OutOfScope as why:
        return "honest-refusal", f"{detail} [oracle: {why}]"
    except NoRoot as why:
        return "honest-refusal", f"{detail} [oracle finds none: {why}]"
    except Hang:
        return "oracle-failed", f"{detail} [the independent solver ran out of time]"
    except Exception as oops:  # noqa: BLE001 - an oracle's own failure is reported, not raised
        return "oracle-failed", f"{detail} [judge failed: {type(oops).__name__}: {oops}]"
    if verdict:
        return "spurious-refusal", f"{detail} [independent solver: {verdict}]"
    return "honest-refusal", detail


def _check(case: Case, result, caught) -> tuple[str, str]:
    from tests.fuzz.values import non_finite

    bad = non_finite(result)
    if bad:
        kind = "untyped" if bad[0].startswith("untyped:") else "non-finite"
        return kind, "; ".join(bad[:4])
    if case.check is None:
        return "ok", ""
    try:
        with time_limit(max(60.0, 4 * case.timeout)), warnings.catch_warnings(record=True):
            warnings.simplefilter("always")
            problems = case.check(result, caught)
    except RefusedByCli as why:
        return "spurious-refusal", str(why)
    except OutOfScope as why:
        return "silent-wrong", f"a result where the model has none: {why}"
    except NoRoot as why:
        return "oracle-failed", f"oracle: {why}"
    except Hang:
        return "oracle-failed", "the oracle ran out of time"
    except (InputError, ConvergenceError) as exc:  # a method of the result refused
        return _judge(case, exc, f"a method of the result refused: {type(exc).__name__}: {exc}")
    except Exception as exc:  # noqa: BLE001
        if _from_skcable(exc):
            return "untyped", f"a method of the result: {type(exc).__name__}: {exc}"
        return "oracle-failed", f"oracle failed: {type(exc).__name__}: {exc} ({_where(exc)})"
    if problems:
        return "silent-wrong", "; ".join(problems)
    return "ok", ""


def _where(exc) -> str:
    frames = traceback.extract_tb(exc.__traceback__)
    return " <- ".join(f"{f.filename.split('/')[-1]}:{f.lineno}" for f in frames[-3:])


def _from_skcable(exc) -> bool:
    """Whether the innermost frame of ``exc`` lies in the skcable package."""
    frames = traceback.extract_tb(exc.__traceback__)
    return bool(frames) and "/skcable/" in frames[-1].filename.replace("\\", "/")


def _evaluate(case: Case, ns: dict):
    """The value of ``case.expr``; for a command line, ``(status, stdout, stderr)``."""
    if case.shell is None:
        return eval(case.expr, ns)  # noqa: S307 - the case is the harness's own expression
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = eval(case.expr, ns)  # noqa: S307
    return status, out.getvalue(), err.getvalue()


def run_case(case: Case, ns: dict | None = None) -> Outcome:
    """Evaluate ``case.expr`` under its time limit and classify the outcome."""
    ns = namespace() if ns is None else ns
    start = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            with time_limit(case.timeout):
                result = _evaluate(case, ns)
        except Hang:
            return Outcome("hang", case, f"no answer within {case.timeout:g} s", time.perf_counter() - start)
        except Exception as exc:  # noqa: BLE001 - every exception is classified
            seconds = time.perf_counter() - start
            kind, detail = _refusal(case, exc)
            if kind == "refusal":
                kind, detail = _judge(case, exc, detail)
            return Outcome(kind, case, detail, seconds, type(exc).__name__, [str(w.message) for w in caught])
    seconds = time.perf_counter() - start
    kind, detail = _check(case, result, list(caught))
    return Outcome(kind, case, detail, seconds, "", [str(w.message) for w in caught])
