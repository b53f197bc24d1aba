"""Comparisons of skcable's numbers with an oracle's, sized by the problem's conditioning."""

from __future__ import annotations

import math

import mpmath
import numpy as np
from mpmath import mp, mpf

from tests.fuzz.mp import DPS, EPS, allowed_error, condition

__all__ = ["check_stiffness", "close", "compare_all", "fd_stiffness", "compare_matrix", "fmt"]


def fmt(value) -> str:
    """A float as Python spells it (``repr``: it round-trips), for the reproducers."""
    return repr(float(value))


def close(name, got, want, allowed) -> str | None:
    """None where ``|got - want| <= allowed``, else the disagreement, oracle first."""
    got = float(got)
    if not math.isfinite(got):
        return f"{name}: skcable {got!r}, oracle {float(want):.17g}"
    error = abs(mpf(got) - want)
    if error <= allowed:
        return None
    rel = float(error / abs(want)) if want != 0 else math.inf
    return (
        f"{name}: oracle {float(want):.17g}, skcable {got!r} "
        f"(off by {float(error):.3g}, rel {rel:.3g}, allowed {allowed:.3g})"
    )


def compare_all(
    result, want: dict, oracle, p, names, scales: dict, *, factor=2.0**10, floor=1e-12
) -> list[str]:
    """Compare ``getattr(result, name)`` with ``want[name]`` for ``names``, each allowed the
    conditioning of the oracle (`condition` of ``oracle`` at ``p``, re-solved from ``want``)
    plus ``floor`` of ``max(|value|, scales[name])``. The conditioning is computed only when
    a first comparison at the floor fails (most agree to round-off)."""
    problems, spread = [], None
    for name in names:
        got = getattr(result, name)
        first = close(
            name, got, want[name], floor * max(abs(float(want[name])), float(scales.get(name, 0.0)))
        )
        if first is None:
            continue
        if spread is None:
            spread = condition(oracle, p, names)
        allowed = allowed_error(want[name], spread[name], scales.get(name, 0.0), factor=factor, floor=floor)
        problem = close(name, got, want[name], allowed)
        if problem:
            problems.append(problem)
    return problems


def fd_stiffness(oracle, p, base, outputs=("H", "V_B"), inputs=(0, 1), rel="1e-15"):
    """``∂(outputs)/∂(p[inputs])`` by central differences of the oracle at `DPS` digits (step
    ``rel`` of the chord, in exact high-precision inputs), re-solved from ``base``."""
    with mp.workdps(DPS):
        chord = mpmath.hypot(mpf(p[0]), mpf(p[1]))
        h = mpf(rel) * chord
        K = mpmath.matrix(len(outputs), len(inputs))
        for j, i in enumerate(inputs):
            plus, minus = [mpf(v) for v in p], [mpf(v) for v in p]
            plus[i] += h
            minus[i] -= h
            up, down = oracle(plus, base), oracle(minus, base)
            for k, name in enumerate(outputs):
                K[k, j] = (up[name] - down[name]) / (2 * h)
        return K


def compare_matrix(name, got, want, rel=1e-8) -> str | None:
    """None where every entry of ``got`` lies within ``rel`` of the largest entry of ``want``."""
    got = np.asarray(got, dtype=float)
    want_f = np.array([[float(want[i, j]) for j in range(want.cols)] for i in range(want.rows)])
    if got.shape != want_f.shape:
        return f"{name}: shape {got.shape}, oracle {want_f.shape}"
    if not np.isfinite(got).all():
        return f"{name}: not finite {got.tolist()}"
    size = np.abs(want_f).max()
    error = np.abs(got - want_f).max()
    if error <= rel * size or (size == 0 and error == 0):
        return None
    return (
        f"{name}: oracle {want_f.tolist()}, skcable {got.tolist()} (off by {error / size:.3g} of the largest)"
    )


def check_stiffness(name, got, oracle, p, base, rel=1e-7, outputs=("H", "V_B"), inputs=(0, 1)) -> str | None:
    """``got`` against the central differences of the oracle's roots (`fd_stiffness`), each
    entry allowed ``rel`` of the largest plus the round-off its own conditioning carries (the
    `condition` of the entries, computed only when the first comparison fails: a taut line's
    stiffness inherits the conditioning of its H, ~1/strain)."""
    K = fd_stiffness(oracle, p, base, outputs, inputs)
    problem = compare_matrix(name, got, K, rel)
    if problem is None:
        return None
    keys = [(i, j) for i in range(len(outputs)) for j in range(len(inputs))]

    def entries(q):
        root = oracle(q, base)
        Kq = fd_stiffness(oracle, q, root, outputs, inputs)
        return {f"{i}{j}": Kq[i, j] for i, j in keys}

    spread = condition(entries, p, [f"{i}{j}" for i, j in keys])
    got = np.asarray(got, dtype=float)
    size = max(abs(float(K[i, j])) for i, j in keys)
    for i, j in keys:
        allowed = 2.0**10 * EPS * spread[f"{i}{j}"] + rel * size
        if not abs(got[i, j] - float(K[i, j])) <= allowed:
            return f"{problem} [entry ({i}, {j}) allowed {allowed:.3g} with its conditioning]"
    return None
