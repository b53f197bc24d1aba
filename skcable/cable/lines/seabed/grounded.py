r"""The grounded regime: the line rests on the seabed from the anchor (or from a first
touchdown) and rises to the fairlead; its fairlead forces ``(H, V_B)`` solve the
closure of `skcable.cable.lines.seabed.closure` (J.M. Jonkman, "Dynamics modeling and
loads analysis of an offshore floating wind turbine", NREL, 2007).

The iteration starts from the frictionless inextensible touchdown line (a monotone
equation in ``h = H/w``, bracketed) and runs Newton's method with the closure's analytic
Jacobian, backtracking so that ``H > 0``, ``0 < V_B <= w L`` and the residual falls;
one more step is taken once the residual is below ``1e-13`` of the chord, into the
round-off floor. One scene runs on Python floats, arrays elementwise with NumPy.
"""

from __future__ import annotations

import math

import numpy as np

from skcable._xp import namespace
from skcable.cable._roots import find_root
from skcable.cable._special import largest_abs
from skcable.cable.lines.seabed.closure import anchor_part, grounded_closure
from skcable.errors import ConvergenceError

__all__ = ["solve_grounded", "solve_grounded_scalar"]

_TOL = 1e-13


def _touchdown_run(h, span, dh, L1):
    """``X(h) - span`` of the frictionless inextensible touchdown line, ``h = H/w`` (m):
    ``X(h) = L_1 - v + h asinh(v/h)``, ``v = sqrt(dh^2 + 2 dh h)``, increasing in ``h``."""
    xp = namespace(h, span)
    v = xp.sqrt(dh * dh + 2.0 * dh * h)
    return L1 - v + h * xp.arcsinh(v / h) - span


def _touchdown_run_scalar(h, span, dh, L1):
    """`_touchdown_run` on Python floats."""
    v = math.sqrt(dh * dh + 2.0 * dh * h)
    return L1 - v + h * math.asinh(v / h) - span


def inextensible_guess(span, dh, w, EA, L, H0):
    """Frictionless inextensible touchdown line, lengthened by the strain of
    the free solution (``H0``): ``h = H/w`` from the monotone `_touchdown_run`.
    Returns the starting ``(H, V_B)`` (N), arrays."""
    L1 = L * (1.0 + H0 / EA)
    ok = L1 > dh * (1 + 1e-9)
    h_max = np.where(ok, (L1 * L1 - dh * dh) / (2.0 * np.where(ok, dh, 1.0)), 1.0)
    lo, hi = h_max * 1e-12, h_max
    f_lo, f_hi = _touchdown_run(lo, span, dh, L1), _touchdown_run(hi, span, dh, L1)
    inside = ok & (f_lo < 0) & (f_hi > 0)
    h = np.where(f_lo >= 0, lo, hi)
    if inside.any():
        idx = np.flatnonzero(inside)
        args = [v[idx] for v in (lo, hi, span, dh, L1)]
        if idx.size == 1:  # Brent's method on floats: the elementwise search costs ~10 ms a call
            args = [float(v[0]) for v in args]
        # a starting point only: Newton on the full equations refines it
        root, _ = find_root(
            _touchdown_run, args[0], args[1], tuple(args[2:]), what="seabed guess", xtol=1e-9 * args[1]
        )
        h[idx] = root
    h = np.where(ok, h, H0 / w)
    V = np.where(ok, np.sqrt(dh * dh + 2.0 * dh * h), w * L * (1 - 1e-9))
    return w * h, np.minimum(V * w, w * L * (1 - 1e-9))


def inextensible_guess_scalar(span, dh, w, EA, L, H0):
    """`inextensible_guess` of one scene, on Python floats."""
    L1 = L * (1.0 + H0 / EA)
    cap = w * L * (1 - 1e-9)
    if not L1 > dh * (1 + 1e-9):
        return w * (H0 / w), min(cap * w, cap)
    h_max = (L1 * L1 - dh * dh) / (2.0 * dh)
    lo, hi = h_max * 1e-12, h_max
    f_lo, f_hi = _touchdown_run_scalar(lo, span, dh, L1), _touchdown_run_scalar(hi, span, dh, L1)
    h = lo if f_lo >= 0 else hi
    if f_lo < 0 and f_hi > 0:  # a starting point only: Newton on the full equations refines it
        h, _ = find_root(_touchdown_run_scalar, lo, hi, (span, dh, L1), what="seabed guess", xtol=1e-9 * hi)
    V = math.sqrt(dh * dh + 2.0 * dh * h)
    return w * h, min(V * w, cap)


def solve_grounded_scalar(span, dh, w, EA, L, mu_w, H0, depth):
    """`solve_grounded` of one scene, on Python floats (the same iteration)."""
    _, _, x1, s1, _ = anchor_part(H0, w, EA, depth)
    H, V = inextensible_guess_scalar(span - x1, dh + depth, w, EA, L - s1, H0)
    chord = math.hypot(span, dh)
    f_x, f_z, j_xh, j_xv, j_zh, j_zv = grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth)
    norm = max(abs(f_x), abs(f_z)) / chord
    history = [norm]
    polish = 0
    for _ in range(80):
        if norm < _TOL:
            polish += 1  # one more step into the round-off floor
            if polish > 1:
                return H, V, history
        det = j_xh * j_zv - j_xv * j_zh
        if not (det != 0.0 and math.isfinite(det)):
            break
        d_h = -(f_x * j_zv - f_z * j_xv) / det
        d_v = -(j_xh * f_z - j_zh * f_x) / det
        step = 1.0
        for _ in range(40):  # backtrack: H > 0, 0 < V <= wL, residual reduced
            H_new, V_new = H + step * d_h, V + step * d_v
            s1 = anchor_part(H_new if H_new > 0 else 1.0, w, EA, depth)[3]
            valid = H_new > 0 and V_new > 0 and V_new <= w * (L - s1)
            H_try, V_try = (H_new, V_new) if valid else (H, V)
            f_x, f_z, j_xh, j_xv, j_zh, j_zv = grounded_closure(span, dh, w, EA, L, mu_w, H_try, V_try, depth)
            new = max(abs(f_x), abs(f_z)) / chord
            if valid and new < norm * (1.0 - 1e-4 * step) + 4 * _TOL:
                break
            step = 0.5 * step
        H, V, norm = H_try, V_try, new
        history.append(norm)
    raise ConvergenceError("elastic_catenary (seabed): Newton did not converge", history)


def solve_grounded(span, dh, w, EA, L, mu_w, H0, depth):
    """Newton with backtracking on the grounded closure, arrays of contact elements.

    Returns ``(H, V_B, history)``: the fairlead forces (N) and the largest scaled
    residual at each iteration."""
    _, _, x1, s1, _ = anchor_part(H0, w, EA, depth)
    H, V = inextensible_guess(span - x1, dh + depth, w, EA, L - s1, H0)
    chord = np.hypot(span, dh)
    f_x, f_z, *jac = grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth)
    norm = np.maximum(np.abs(f_x), np.abs(f_z)) / chord
    history = [largest_abs(norm)]
    polish = 0
    for _ in range(80):
        if history[-1] < _TOL:
            polish += 1  # one more step into the round-off floor
            if polish > 1:
                return H, V, history
        j_xh, j_xv, j_zh, j_zv = jac
        det = j_xh * j_zv - j_xv * j_zh
        d_h = -(f_x * j_zv - f_z * j_xv) / det
        d_v = -(j_xh * f_z - j_zh * f_x) / det
        step = np.ones_like(H)
        for _ in range(40):  # backtrack: H > 0, 0 < V <= wL, residual reduced
            H_new, V_new = H + step * d_h, V + step * d_v
            with np.errstate(invalid="ignore", divide="ignore"):
                s1 = anchor_part(np.where(H_new > 0, H_new, 1.0), w, EA, depth)[3]
            valid = (H_new > 0) & (V_new > 0) & (V_new <= w * (L - s1))
            H_try = np.where(valid, H_new, H)
            V_try = np.where(valid, V_new, V)
            f_x, f_z, *jac = grounded_closure(span, dh, w, EA, L, mu_w, H_try, V_try, depth)
            new = np.maximum(np.abs(f_x), np.abs(f_z)) / chord
            ok = valid & (new < norm * (1.0 - 1e-4 * step) + 4 * _TOL)
            if ok.all():
                break
            step = np.where(ok, step, 0.5 * step)
        H, V, norm = H_try, V_try, new
        history.append(largest_abs(norm))
    raise ConvergenceError("elastic_catenary (seabed): Newton did not converge", history)
