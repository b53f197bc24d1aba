"""Regimes of overhead conductors: `change_of_state` (one span and the line path), the
sag-tension table and `tension_section`, against the 50-digit oracles of `tests.fuzz.state`.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
from mpmath import mp, mpf

from tests.fuzz import state as oracle
from tests.fuzz.catenary import free_line
from tests.fuzz.compare import close, fmt
from tests.fuzz.harness import Case
from tests.fuzz.mp import DPS, EPS, condition
from tests.fuzz.scenes import log_uniform, pick

__all__ = ["REGIMES"]

STATE_NAMES = frozenset(
    {
        "span",
        "dh",
        "EA",
        "alpha",
        "w0",
        "t0",
        "H0",
        "sag0",
        "w",
        "t",
        "wind",
        "model",
        "temperatures",
        "load_cases",
        "spans",
        "insulator_length",
        "insulator_weight",
    }
)


def _conductor(rng):
    """A span and a conductor in SI units: span, dh, EA, alpha, w0, t0 and the reference value."""
    span = log_uniform(rng, 5.0, 2000.0)
    dh = 0.0 if rng.uniform() < 0.3 else span * math.tan(rng.uniform(-0.6, 0.6))
    w0 = log_uniform(rng, 2.0, 40.0)
    EA = w0 * log_uniform(rng, 1e5, 1e7)
    alpha = rng.uniform(1e-5, 2.5e-5)
    t0 = rng.uniform(-10.0, 30.0)
    ratio = log_uniform(rng, 1e-3, 0.15)  # sag / span
    if rng.uniform() < 0.6:
        ref = ("H0", w0 * span / (8 * ratio))
    else:
        ref = ("sag0", ratio * span)
    return span, dh, EA, alpha, w0, t0, ref


def _states(rng, w0, m):
    w = [w0 * pick(rng, [1.0, rng.uniform(1.0, 3.0)]) for _ in range(m)]
    t = [rng.uniform(-30.0, 100.0) for _ in range(m)]
    wind = [0.0 if rng.uniform() < 0.5 else w0 * rng.uniform(0.0, 2.0) for _ in range(m)]
    return w, t, wind


def _list(values) -> str:
    return "[" + ", ".join(fmt(v) for v in values) + "]"


def _reference(span, dh, w0, EA, ref):
    return oracle.reference_length(span, dh, w0, EA, **{ref[0]: ref[1]})


def _state_problems(got: dict, want: dict, names, scale: dict, where: str, spread=None) -> list[str]:
    problems = []
    for name in names:
        allowed = 1e-12 * max(abs(float(want[name])), scale.get(name, 0.0))
        if spread is not None:
            allowed += 2.0**10 * EPS * spread.get(name, 0.0)
        problem = close(f"{where}{name}", got[name], want[name], allowed)
        if problem:
            problems.append(problem)
    return problems


def _chain_check(span, dh, EA, alpha, w0, t0, ref, state, got: dict, where: str) -> list[str]:
    """The oracle's disagreements with ``got`` (the numbers of one state ``(w, t, wind)``),
    each allowed the round-off the chain (reference length, then the state) carries."""
    L0 = _reference(span, dh, w0, EA, ref)[0]
    want = oracle.state(span, dh, *state, EA, alpha, t0, L0)
    names = list(got)
    first = _state_problems(got, want, names, {"sag": span * 1e-3}, where)
    if not first:
        return []

    def chain(p):
        L0p = _reference(p[0], p[1], p[2], p[3], (ref[0], p[4]))[0]
        return oracle.state(p[0], p[1], p[5], p[6], p[7], p[3], p[8], p[9], L0p)

    spread = condition(chain, [span, dh, w0, EA, ref[1], *state, alpha, t0], names)
    # the reference length is an intermediate every solver rounds to a double: its round-off too
    spread_L0 = condition(lambda p: oracle.state(span, dh, *state, EA, alpha, t0, p[0]), [L0], names)
    spread = {name: spread[name] + spread_L0[name] for name in names}
    return _state_problems(got, want, names, {"sag": span * 1e-3}, where, spread)


def _catenary_check(span, dh, EA, alpha, w0, t0, ref, w, t, wind, res, index):
    """The oracle's disagreements with ``res`` (a `ChangeOfState`) at state ``index``."""
    L0 = _reference(span, dh, w0, EA, ref)[0]
    problems = _state_problems({"L0": np.ravel(res.L0)[0]}, {"L0": L0}, ["L0"], {}, "")
    got = {name: np.ravel(getattr(res, name))[index] for name in ("H", "H_plane", "sag", "T_max", "length")}
    state = (w[index], t[index], wind[index])
    return problems + _chain_check(span, dh, EA, alpha, w0, t0, ref, state, got, f"state {index}: ")


def change_of_state(rng) -> Case:
    """One span in up to four states (catenary or parabola) against the oracle."""
    span, dh, EA, alpha, w0, t0, ref = _conductor(rng)
    m = int(rng.integers(1, 5))
    w, t, wind = _states(rng, w0, m)
    model = "parabola" if rng.uniform() < 0.2 else "catenary"
    expr = (
        f"conductors.change_of_state({fmt(span)}, {fmt(dh)}, EA={fmt(EA)}, alpha={fmt(alpha)}, w0={fmt(w0)}, "
        f"t0={fmt(t0)}, {ref[0]}={fmt(ref[1])}, w={_list(w)}, t={_list(t)}, wind={_list(wind)}, "
        f"model={model!r})"
    )

    def check(res, caught):
        index = int(rng_index(len(w), span))
        if model == "catenary":
            return _catenary_check(span, dh, EA, alpha, w0, t0, ref, w, t, wind, res, index)
        H0, sag0 = (ref[1], None) if ref[0] == "H0" else (None, ref[1])
        want = oracle.parabola_state(span, dh, EA, alpha, w0, t0, H0, sag0, w[index], t[index], wind[index])
        got = {
            name: np.ravel(getattr(res, name))[index] for name in ("H", "H_plane", "sag", "T_max", "length")
        }
        got.update(L0=res.L0, H0=res.H0, sag0=res.sag0)
        return _state_problems(got, want, list(got), {}, f"state {index}: ")

    return Case("change_of_state", expr, STATE_NAMES, check, None)


def rng_index(n, salt) -> int:
    """A state to check, chosen from the data (deterministic)."""
    return int(abs(math.frexp(salt)[0] * 1e6)) % n


def change_of_state_line(rng) -> Case:
    """The line path: spans (n,) and states (m,) at once; elements checked against the
    one-span oracle."""
    n, m = int(rng.integers(2, 6)), int(rng.integers(1, 4))
    span0, dh0, EA, alpha, w0, t0, ref = _conductor(rng)
    spans = [span0 * rng.uniform(0.3, 1.5) for _ in range(n)]
    dhs = [s * math.tan(rng.uniform(-0.5, 0.5)) for s in spans]
    w, t, wind = _states(rng, w0, m)
    refs = [ref[1] * (s / span0) ** (2 if ref[0] == "sag0" else 0) for s in spans]
    expr = (
        f"conductors.change_of_state(np.array({_list(spans)}), np.array({_list(dhs)}), "
        f"EA={fmt(EA)}, alpha={fmt(alpha)}, w0={fmt(w0)}, t0={fmt(t0)}, "
        f"{ref[0]}=np.array({_list(refs)}), w={_list(w)}, t={_list(t)}, wind={_list(wind)})"
    )

    def check(res, caught):
        i, j = rng_index(n, span0), rng_index(m, EA)
        got = {name: np.asarray(getattr(res, name))[i, j] for name in ("H", "sag", "T_max", "length")}
        state = (w[j], t[j], wind[j])
        return _chain_check(
            spans[i], dhs[i], EA, alpha, w0, t0, (ref[0], refs[i]), state, got, f"span {i}, state {j}: "
        )

    return Case("change_of_state/line", expr, STATE_NAMES, check, None)


def sag_tension_table(rng) -> Case:
    """The table's rows against the oracle (a row per case and temperature)."""
    span, dh, EA, alpha, w0, t0, ref = _conductor(rng)
    cases = {
        f"case{i}": (w0 * rng.uniform(1.0, 2.5), pick(rng, [0.0, w0 * rng.uniform(0, 1.5)])) for i in range(3)
    }
    temps = [rng.uniform(-20.0, 90.0) for _ in range(int(rng.integers(1, 4)))]
    cases_expr = "{" + ", ".join(f"{k!r}: ({fmt(a)}, {fmt(b)})" for k, (a, b) in cases.items()) + "}"
    expr = (
        f"conductors.sag_tension_table({fmt(span)}, {fmt(dh)}, EA={fmt(EA)}, alpha={fmt(alpha)}, "
        f"w0={fmt(w0)}, t0={fmt(t0)}, {ref[0]}={fmt(ref[1])}, temperatures={_list(temps)}, "
        f"load_cases={cases_expr})"
    )

    def check(table, caught):
        name = list(cases)[rng_index(len(cases), span)]
        temp = temps[rng_index(len(temps), EA)]
        row = table.loc[(name, temp)]
        got = {k: float(row[k]) for k in ("H", "sag", "T_max", "length")}
        state = (cases[name][0], temp, cases[name][1])
        return _chain_check(span, dh, EA, alpha, w0, t0, ref, state, got, f"row ({name}, {temp!r}): ")

    return Case("sag_tension_table", expr, STATE_NAMES, check, None)


def tension_section(rng) -> Case:
    """`tension_section` recounted: each span's catenary from its reference length at the
    returned clamps, and every string's moment balance."""
    n = int(rng.integers(2, 7))
    span0, _, EA, alpha, w0, t0, ref = _conductor(rng)
    spans = [span0 * rng.uniform(0.4, 1.6) for _ in range(n)]
    dhs = [s * math.tan(rng.uniform(-0.3, 0.3)) for s in spans]
    H0 = w0 * span0 / (8 * log_uniform(rng, 5e-3, 0.08))
    lam = [pick(rng, [0.0, rng.uniform(0.5, 5.0)]) for _ in range(n - 1)]
    W = [rng.uniform(0.0, 2000.0) for _ in range(n - 1)]
    m = int(rng.integers(1, 4))
    w, t, _ = _states(rng, w0, m)
    expr = (
        f"conductors.tension_section({_list(spans)}, {_list(dhs)}, EA={fmt(EA)}, alpha={fmt(alpha)}, "
        f"w0={fmt(w0)}, "
        f"t0={fmt(t0)}, H0={fmt(H0)}, w={_list(w)}, t={_list(t)}, insulator_length={_list(lam)}, "
        f"insulator_weight={_list(W)})"
    )

    def check(res, caught):
        j = rng_index(m, span0)
        with mp.workdps(DPS):
            k = 1 + mpf(alpha) * (mpf(t[j]) - mpf(t0))
            problems, sols = [], []
            H_max = float(np.max(np.asarray(res.H)[j]))
            for i in range(n):
                L0 = oracle.reference_length(spans[i], dhs[i], w0, EA, H0=H0)[0]
                sp, dz = float(np.asarray(res.span)[j, i]), float(np.asarray(res.dh)[j, i])
                sol = free_line([sp, dz, mpf(w[j]) / k, EA * k, L0 * k])
                sols.append(sol)
                for name in ("H", "V_A", "V_B"):
                    got = float(np.asarray(getattr(res, name))[j, i])
                    problem = close(f"state {j} span {i} {name}", got, sol[name], 1e-9 * H_max)
                    problems += [problem] if problem else []
            for i in range(n - 1):
                if lam[i] == 0:
                    continue
                phi = mpf(float(np.asarray(res.swing_angle)[j, i]))
                dH = sols[i + 1]["H"] - sols[i]["H"]
                V = sols[i]["V_B"] + sols[i + 1]["V_A"] + mpf(W[i]) / 2
                balance = dH * mpmath.cos(phi) - V * mpmath.sin(phi)
                if abs(balance) > 1e-8 * H_max:
                    problems.append(
                        f"state {j} string {i}: moment balance {float(balance):.3g} N (max H {H_max:.3g})"
                    )
                swing = float(np.asarray(res.swing)[j, i])
                if abs(swing - lam[i] * math.sin(float(phi))) > 1e-12 * lam[i] + 1e-15:
                    problems.append(
                        f"state {j} string {i}: swing {swing!r}, "
                        f"lambda sin(phi) {lam[i] * math.sin(float(phi))!r}"
                    )
            delta = [0.0] + [float(v) for v in np.asarray(res.swing)[j]] + [0.0]
            for i in range(n):
                want_span = spans[i] + delta[i + 1] - delta[i]
                if abs(float(np.asarray(res.span)[j, i]) - want_span) > 1e-12 * spans[i]:
                    problems.append(
                        f"state {j} span {i}: {float(np.asarray(res.span)[j, i])!r}, "
                        f"clamps give {want_span!r}"
                    )
        return problems

    return Case("tension_section", expr, STATE_NAMES, check, None, timeout=60.0)


REGIMES = {
    "change_of_state": change_of_state,
    "change_of_state/line": change_of_state_line,
    "sag_tension_table": sag_tension_table,
    "tension_section": tension_section,
}
