"""The seeded fuzz of issue 26, in CI: every regime of `tests.fuzz` over a fixed set of scenes.

Each scene's call is checked by an oracle independent of the function under test (see
`tests/fuzz/`): a silent wrong number, a non-finite one, an untyped exception, a hang or a
spurious refusal fails the test, unless a defect owned by another branch explains it
(`tests.fuzz.known`, each with its issue and branch; `benchmarks/fuzz_long.py` reruns their
probes and reports which are fixed). The same regimes run for 25 minutes in
`benchmarks/fuzz_long.py`; its last report is `docs/fuzz_report.md`.
"""

from __future__ import annotations

import pytest

from skcable import cable
from skcable.errors import ConvergenceError
from tests.fuzz import known, lines
from tests.fuzz.harness import Case, namespace, reproducer, run_case
from tests.fuzz.regimes import REGIMES, case

SEED = 26

#: Scenes per regime: a budget of about 40 s for the whole test on 2 cores (the oracles at 50
#: digits and the independent solvers dominate; a moored body costs ~100 times a closed form).
COUNTS = {
    "mooring": 3,
    "mooring/turned": 2,
    "mooring/mirror": 2,
    "mooring/at": 3,
    "network": 3,
    "solve_line_bvp": 6,
    "solve_line_bvp/auto": 6,
    "solve_line_bvp_3d": 6,
    "sloped_seabed": 12,
    "line_3d": 12,
    "tension_section": 10,
    "natural_frequencies": 10,
    "natural_frequencies/invariant": 6,
    "cli/frequencies": 6,
    "edges": 300,
}
DEFAULT = 25


@pytest.fixture(scope="module")
def ns():
    return namespace()


@pytest.mark.parametrize("regime", sorted(REGIMES))
def test_fuzz_regime(regime, ns):
    """Every scene of the regime: ok, or an honest refusal, or a known defect of another branch."""
    outcomes = [run_case(case(regime, SEED, i), ns) for i in range(COUNTS.get(regime, DEFAULT))]
    new = [o for o in outcomes if o.failed and known.match(o) is None]
    report = "\n".join(
        f"[{o.kind}] {o.case.where}: {o.detail[:400]}\n    {reproducer(o.case)}" for o in new[:10]
    )
    assert not new, f"{len(new)} new failures:\n{report}"
    assert any(o.kind == "ok" for o in outcomes), f"no scene of {regime} was checked by its oracle"


def _fake(result, **scaled):
    """A result whose attributes ``name`` are multiplied by ``scaled[name]``."""

    class Fake:
        def __getattr__(self, name):
            value = getattr(result, name)
            return value * scaled[name] if name in scaled else value

    return Fake()


def test_the_oracle_sees_a_wrong_H():
    """An H off by 1e-9 (D1 was 1.8e-2) is silent-wrong; off by 1e-15, ok: the free line's check
    is sized to the round-off, not wider."""
    p = [300.0, 40.0, 10.0, 1e8, 320.0]
    c = lines.free_case(p)
    result = cable.elastic_catenary(*p[:4], length=p[4])
    assert c.check(_fake(result, H=1.0 + 1e-9), []) != []
    assert c.check(_fake(result, H=1.0 + 1e-15), []) == []


def test_the_harness_classifies_what_it_catches(ns):
    """Untyped exceptions, a misnamed argument, a hang, a non-finite number and a spurious
    refusal are failures; an InputError naming an argument of a call the oracle cannot solve
    is an honest refusal."""

    def outcome(expr, **kw):
        return run_case(Case("test", expr, frozenset({"span", "length"}), **kw), ns)

    assert outcome("1 / 0").kind == "untyped"
    assert outcome("int('x')").kind == "untyped"  # a bare ValueError
    assert outcome("cable.elastic_catenary(-1.0, 0.0, 1.0, 1e6, length=2.0)").kind == "honest-refusal"
    misnamed = Case("test", "cable.elastic_catenary(-1.0, 0.0, 1.0, 1e6, length=2.0)", frozenset({"length"}))
    assert run_case(misnamed, ns).kind == "untyped"  # 'span' is not among the names allowed
    assert outcome("float('nan')").kind == "non-finite"
    assert outcome("__import__('time').sleep(5)", timeout=0.2).kind == "hang"

    def refuse():
        raise ConvergenceError("did not converge", [1.0])

    ns = dict(ns, refuse=refuse)
    spurious = Case("test", "refuse()", frozenset(), judge=lambda exc: "H = 1.0")
    assert run_case(spurious, ns).kind == "spurious-refusal"


def test_known_defects_name_their_branch():
    """Every known defect says whose it is and has a probe the long run reruns."""
    for defect in known.KNOWN:
        assert defect.branch and defect.issue and defect.probes, defect.key
