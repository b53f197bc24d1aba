"""High-precision root finding for the fuzz oracles (mpmath, written here, independent of skcable).

`newton` solves a square system ``F(u; p) = 0`` at ``dps`` digits by Newton's method with a
finite-difference Jacobian (a step of half the digits: the Jacobian keeps about ``dps/2`` of
them, enough for quadratic convergence to the full precision) and backtracking on the scaled
residual. `condition` gives ``sum_i |p_i ∂q/∂p_i|`` of the oracle's answers, from which
`allowed_error` sizes what a double-precision answer may be off by: the round-off a
backward-stable solver leaves, ``eps`` times the sum of ``|p_i ∂u/∂p_i|`` over the inputs,
with a floor of ``1e-12`` of the answer's scale.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import mpmath
from mpmath import mp, mpf

EPS = 2.0**-52

__all__ = ["DPS", "EPS", "NoRoot", "OutOfScope", "allowed_error", "brent", "condition", "newton"]

DPS = 50
FLOOR = mpf("1e-32")


class NoRoot(Exception):
    """The oracle found no root (from the starts it was given)."""


class OutOfScope(NoRoot):
    """The scene has no determinate answer in the model (statically indeterminate, a state
    the closed form does not describe): a refusal of it is honest."""


def _norm(values, scales) -> mpf:
    return max(abs(v) / s for v, s in zip(values, scales, strict=True))


def jacobian(F: Callable, u: Sequence, p: Sequence, f0=None, steps=None) -> mpmath.matrix:
    """Forward differences of ``F`` at ``u`` with relative steps of ``10**(-dps/2)``."""
    f0 = F(u, p) if f0 is None else f0
    n = len(u)
    J = mpmath.matrix(len(f0), n)
    h_rel = mpf(10) ** (-(mp.dps // 2))
    for j in range(n):
        h = h_rel * (abs(u[j]) if steps is None or u[j] != 0 else steps[j])
        if h == 0:
            h = h_rel
        shifted = list(u)
        shifted[j] = u[j] + h
        f1 = F(shifted, p)
        for i in range(len(f0)):
            J[i, j] = (f1[i] - f0[i]) / h
    return J


def newton(
    F: Callable,
    u0: Sequence,
    p: Sequence,
    scales: Sequence,
    *,
    dps: int = 50,
    max_iter: int = 80,
    admissible: Callable | None = None,
) -> list:
    """The root ``u`` of ``F(u; p)`` near ``u0`` at ``dps`` digits, or `NoRoot`.

    ``scales``: the size of each residual's terms (the root is accepted when every
    residual is below ``10**(5 - dps)`` of its scale, or when no step lowers a residual
    already below ``10**-32``: the floor of a closure whose terms cancel by more than 15
    digits); ``admissible(u)``: whether a trial point lies in the closure's domain (the line
    search halves the step until it does)."""
    with mp.workdps(dps):
        u = [mpf(v) for v in u0]
        p = [mpf(v) if isinstance(v, (int, float)) else v for v in p]
        scales = [mpf(s) for s in scales]
        if admissible is not None and not admissible(u):
            raise NoRoot("start outside the domain")
        f = F(u, p)
        norm = _norm(f, scales)
        target = mpf(10) ** (5 - dps)
        for _ in range(max_iter):
            if norm < target:
                return u
            J = jacobian(F, u, p, f)
            try:
                step = mpmath.lu_solve(J, mpmath.matrix([-v for v in f]))
            except ZeroDivisionError:
                raise NoRoot("singular Jacobian") from None
            t = mpf(1)
            for _ in range(60):
                trial = [u[i] + t * step[i] for i in range(len(u))]
                if admissible is None or admissible(trial):
                    f_trial = F(trial, p)
                    n_trial = _norm(f_trial, scales)
                    if n_trial < norm or n_trial < target:
                        break
                t /= 2
            else:
                if norm < FLOOR:
                    return u
                raise NoRoot(f"line search failed at residual {float(norm):.3g}")
            if norm < FLOOR and n_trial > norm / 2:  # at the floor of the closure's round-off
                return trial
            u, f, norm = trial, f_trial, n_trial
        if norm < FLOOR:
            return u
        raise NoRoot(f"no convergence, residual {float(norm):.3g}")


def condition(oracle: Callable, p: Sequence, names: Sequence[str], *, h: str = "1e-20") -> dict:
    """``sum_i |p_i ∂q/∂p_i|`` for each quantity ``q`` in ``names`` of ``oracle(p)`` (a dict),
    by forward differences of relative step ``h`` at the oracle's precision (the inputs that
    are exactly 0 carry no round-off and are left out). ``oracle(p)`` re-solves from its
    own root (the callable closes over it)."""
    with mp.workdps(DPS):
        base = oracle(list(p))
        spread = {name: mpf(0) for name in names}
        step = mpf(h)
        for i, value in enumerate(p):
            if value == 0:
                continue
            shifted = list(p)
            shifted[i] = value * (1 + step)
            moved = oracle(shifted)
            for name in names:
                spread[name] += abs(moved[name] - base[name]) / step
        return {name: float(v) for name, v in spread.items()}


def allowed_error(value, spread: float, scale, *, factor: float = 2.0**10, floor: float = 1e-12) -> float:
    """What a double-precision answer may be off by (absolute): ``factor * eps * spread`` (the
    inputs' round-off carried by the problem's conditioning, `condition`), plus ``floor``
    times ``max(|value|, scale)``."""
    return factor * EPS * float(spread) + floor * max(abs(float(value)), float(scale))


def brent(
    f: Callable, lo: float, hi: float, *, xtol: float = 0.0, rtol: float = 4 * EPS, maxiter=200
) -> float:
    """A root of ``f`` (a float function, possibly evaluated at high precision inside)
    bracketed by ``[lo, hi]``: scipy's Brent method."""
    from scipy.optimize import brentq

    flo, fhi = f(lo), f(hi)
    if flo == 0:
        return lo
    if fhi == 0:
        return hi
    if (flo > 0) == (fhi > 0):
        raise NoRoot("no sign change")
    return brentq(f, lo, hi, xtol=xtol or 1e-300, rtol=rtol, maxiter=maxiter, disp=False)


def expand(f: Callable, x0: float, grow: float, *, limit: float, sign: int) -> float:
    """The first ``x0 * grow**k`` (k = 0, 1, ...) where ``sign * f(x) >= 0``, or `NoRoot`."""
    x = x0
    while abs(x) < limit:
        if sign * f(x) >= 0:
            return x
        x *= grow
    raise NoRoot("no bracket")


def finite(*values) -> bool:
    return all(math.isfinite(float(v)) for v in values)
