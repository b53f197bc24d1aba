"""Regimes of one elastic line: free (Irvine), on a flat seabed (Jonkman: friction, heaps, an
anchor above the seabed), with their mirror and unit-scale invariances and stiffnesses.

Each function takes a seeded generator and returns a `Case` whose oracle is
`tests.fuzz.catenary` at 50 digits and whose refusal judge solves the scene there from the
harness's own start (a refusal is spurious where it finds the answer in the float range).
"""

from __future__ import annotations

import math

from tests.fuzz.catenary import free_line, seabed_line
from tests.fuzz.compare import check_stiffness, close, compare_all, fmt
from tests.fuzz.harness import Case
from tests.fuzz.mp import EPS, condition
from tests.fuzz.scenes import log_uniform, pick, slack_length

__all__ = ["REGIMES"]

FREE_NAMES = frozenset({"span", "dh", "w", "EA", "length"})
SEABED_NAMES = FREE_NAMES | {"seabed", "friction"}


def _in_float_range(want, names) -> bool:
    return all(math.isfinite(float(want[n])) and abs(float(want[n])) < 1e300 for n in names)


def _free_call(span, dh, w, EA, L):
    return f"cable.elastic_catenary({fmt(span)}, {fmt(dh)}, {fmt(w)}, {fmt(EA)}, length={fmt(L)})"


def _free_problems(result, p, K_rel=1e-7):
    """The oracle's disagreements with one free elastic catenary ``result`` of data ``p``."""
    want = free_line(p, start={"H": result.H, "V_A": result.V_A})

    def oracle(q, base=want):
        return free_line(q, start=base)

    force = float(want["H"] + p[2] * p[4])
    problems = compare_all(
        result, want, oracle, p, ["H", "V_A", "V_B"], {"H": 0.0, "V_A": force, "V_B": force}
    )
    if not problems:
        problem = check_stiffness("stiffness()", result.stiffness(), oracle, p, want, K_rel)
        problems += [problem] if problem else []
    return problems, want, oracle


def _free_data(rng):
    span = log_uniform(rng, 1e-1, 1e4)
    dh = 0.0 if rng.uniform() < 0.1 else span * math.tan(rng.uniform(-1.45, 1.45))
    w = log_uniform(rng, 1e-2, 1e4)
    L = slack_length(rng, math.hypot(span, dh))
    EA = w * L * log_uniform(rng, 1e1, 1e13)
    return [span, dh, w, EA, L]


def _judge_free(p):
    def judge(exc):
        want = free_line(p)
        if _in_float_range(want, ("H", "V_A", "T_A", "T_B")):
            return f"H = {float(want['H']):.17g}, V_A = {float(want['V_A']):.17g}"
        return None

    return judge


def elastic_free(rng) -> Case:
    """A free elastic catenary against the 50-digit root of Irvine's equations."""
    return free_case(_free_data(rng))


def free_case(p) -> Case:
    """The case of a free elastic catenary of data ``p = [span, dh, w, EA, L]``."""

    def check(result, caught):
        return _free_problems(result, p)[0]

    return Case("elastic_catenary", _free_call(*p), FREE_NAMES, check, _judge_free(p))


def _pair_problem(name, got, want, spread, scale) -> str | None:
    """An invariance: ``got`` (the transformed call's) within 1e-12 of ``scale`` plus the
    conditioning's round-off of ``want`` (the first call's, transformed)."""
    return close(name, got, want, 2.0**10 * EPS * spread + 1e-12 * max(abs(float(want)), scale))


def elastic_mirror(rng) -> Case:
    """The same line seen from B: ``(span, -dh)`` has the same H and V_A and V_B exchanged."""
    p = _free_data(rng)
    q = [p[0], -p[1], *p[2:]]
    expr = f"({_free_call(*p)}, {_free_call(*q)})"

    def check(result, caught):
        first, mirrored = result
        problems, want, oracle = _free_problems(first, p)
        spread = condition(oracle, p, ["H", "V_A", "V_B"])
        force = float(want["H"] + p[2] * p[4])
        for name, other in (("H", "H"), ("V_A", "V_B"), ("V_B", "V_A")):
            problem = _pair_problem(
                f"mirror {name}", getattr(mirrored, name), getattr(first, other), spread[other], force
            )
            problems += [problem] if problem else []
        return problems

    return Case("elastic_catenary/mirror", expr, FREE_NAMES, check, _judge_free(p), calls=2)


def elastic_scaled(rng) -> Case:
    """The same line in other units: lengths times 10^a, forces times 10^b: H and V times 10^b."""
    p = _free_data(rng)
    a, b = int(rng.integers(-3, 4)), int(rng.integers(-3, 7))
    lam, mu = 10.0**a, 10.0**b
    q = [p[0] * lam, p[1] * lam, p[2] * mu / lam, p[3] * mu, p[4] * lam]
    expr = f"({_free_call(*p)}, {_free_call(*q)})"

    def check(result, caught):
        first, scaled = result
        problems, want, oracle = _free_problems(first, p)
        spread = condition(oracle, p, ["H", "V_A"])
        force = float(want["H"] + p[2] * p[4])
        for name in ("H", "V_A"):
            problem = _pair_problem(
                f"scaled x{lam:g} m, x{mu:g} N: {name}/{mu:g}",
                getattr(scaled, name) / mu,
                getattr(first, name),
                spread[name],
                force,
            )
            problems += [problem] if problem else []
        return problems

    return Case("elastic_catenary/scaled", expr, FREE_NAMES, check, _judge_free(p), calls=2)


def _seabed_data(rng, above: bool):
    span = log_uniform(rng, 1e-1, 1e4)
    w = log_uniform(rng, 1e-2, 1e4)
    if above:  # the anchor above the seabed
        seabed = -span * log_uniform(rng, 1e-3, 3.0)
        dh = seabed + (span * math.tan(rng.uniform(0.0, 1.45)) - seabed) * rng.uniform(0.05, 1.5)
        friction = 0.0 if rng.uniform() < 0.8 else log_uniform(rng, 1e-2, 1.0)
    else:
        seabed = 0.0
        dh = span * math.tan(rng.uniform(0.01, 1.45))
        friction = 0.0 if rng.uniform() < 0.3 else log_uniform(rng, 1e-3, 3.0)
    reach = span + abs(dh) - seabed
    L = pick(rng, [slack_length(rng, math.hypot(span, dh)), reach * rng.uniform(0.7, 1.6)])
    EA = w * L * log_uniform(rng, 1e1, 1e12)
    return [span, dh, w, EA, L, seabed, friction]


def _seabed_call(span, dh, w, EA, L, seabed, friction):
    return (
        f"cable.elastic_catenary({fmt(span)}, {fmt(dh)}, {fmt(w)}, {fmt(EA)}, length={fmt(L)}, "
        f"seabed={fmt(seabed)}, friction={fmt(friction)})"
    )


def seabed(rng, above: bool = False) -> Case:
    """A line on a flat seabed (lifted, grounded with friction, heap; with ``above``, the anchor
    above the seabed: free, touching down, heap) against Jonkman's closure at 50 digits."""
    return seabed_case(_seabed_data(rng, above))


def seabed_case(p) -> Case:
    """The case of a seabed line of data ``p = [span, dh, w, EA, L, seabed, friction]``."""
    above = p[5] < 0
    names = ["H", "V_B", "V_A", "H_A", "length_on_seabed"]

    def check(result, caught):
        start = {
            "H": result.H,
            "V_B": result.V_B,
            "V_A": result.V_A,
            "regime": "heap" if result.heap else None,
        }
        want = seabed_line(p, start if result.H > 0 else None)

        def oracle(q, base=want):
            return seabed_line(q, base)

        force = float(want["H"] + p[2] * p[4])
        scales = {"H": force, "V_B": force, "V_A": force, "H_A": force, "length_on_seabed": p[4]}
        problems = compare_all(result, want, oracle, p, names, scales)
        if bool(result.heap) != (want["regime"] == "heap"):
            problems.append(f"heap: oracle {want['regime']}, skcable heap={result.heap}")
        if not problems:
            problem = check_stiffness(f"stiffness() ({want['regime']})", result.stiffness(), oracle, p, want)
            problems += [problem] if problem else []
        return problems

    def judge(exc):
        want = seabed_line(p)
        if _in_float_range(want, names):
            return f"{want['regime']}: H = {float(want['H']):.17g}, V_B = {float(want['V_B']):.17g}"
        return None

    return Case("seabed/above" if above else "seabed", _seabed_call(*p), SEABED_NAMES, check, judge)


REGIMES = {
    "elastic_catenary": elastic_free,
    "elastic_catenary/mirror": elastic_mirror,
    "elastic_catenary/scaled": elastic_scaled,
    "seabed": seabed,
    "seabed/above": lambda rng: seabed(rng, above=True),
}
