r"""The grounded regime: the line rests on the seabed from the anchor (or from a first
touchdown) and rises to the fairlead; its fairlead forces ``(H, V_B)`` solve the
closure of `skcable.cable.closure.on_seabed` (J.M. Jonkman, "Dynamics modeling and
loads analysis of an offshore floating wind turbine", NREL, 2007).

The iteration starts from the frictionless inextensible touchdown line (a monotone
equation in ``h = H/w``, bracketed) and runs Newton's method with the closure's analytic
Jacobian (`skcable._newton2.solve2`), backtracking so that ``H > 0``, ``0 < V_B <= w L``
and the residual falls, until the residual reaches its round-off floor (a few ulps of
the lengths that enter it). One scene runs on Python floats, arrays elementwise with NumPy.
"""

from __future__ import annotations

import numpy as np

from skcable._newton2 import solve2
from skcable._xp import namespace
from skcable.cable._roots import find_root
from skcable.cable.closure import anchor_part, grounded_closure

__all__ = ["inextensible_guess", "solve_grounded"]


def _touchdown_run(h, span, dh, L1):
    """``X(h) - span`` of the frictionless inextensible touchdown line, ``h = H/w`` (m):
    ``X(h) = L_1 - v + h asinh(v/h)``, ``v = sqrt(dh^2 + 2 dh h)``, increasing in ``h``."""
    xp = namespace(h)
    v = xp.sqrt(dh * dh + 2.0 * dh * h)
    return L1 - v + h * xp.arcsinh(v / h) - span


def inextensible_guess(span, dh, w, EA, L, H0, xp=np):
    """Frictionless inextensible touchdown line, lengthened by the strain of the free solution
    (``H0``): ``h = H/w`` from the monotone `_touchdown_run`. Returns the starting ``(H, V_B)``
    (N); Python floats (``xp`` `skcable._xp.scalar_math`) or arrays."""
    L1 = L * (1.0 + H0 / EA)
    cap = w * L * (1 - 1e-9)
    ok = L1 > dh * (1 + 1e-9)  # else dh > 0: every expression below stays finite
    h_max = xp.where(ok, (L1 * L1 - dh * dh) / (2.0 * xp.where(ok, dh, 1.0)), 1.0)
    lo, hi = h_max * 1e-12, h_max
    f_lo, f_hi = _touchdown_run(lo, span, dh, L1), _touchdown_run(hi, span, dh, L1)
    inside = ok & (f_lo < 0) & (f_hi > 0)
    h = xp.where(f_lo >= 0, lo, hi)
    if xp is not np and inside:  # a starting point only: Newton on the full equations refines it
        h = find_root(_touchdown_run, lo, hi, (span, dh, L1), what="seabed guess", xtol=1e-9 * hi)[0]
    elif xp is np and inside.any():
        idx = np.flatnonzero(inside)
        args = [v[idx] for v in (lo, hi, span, dh, L1)]
        if idx.size == 1:  # Brent's method on floats: the elementwise search costs ~10 ms a call
            args = [float(v[0]) for v in args]
        xtol = 1e-9 * float(args[1]) if idx.size == 1 else None  # Brent's, as on floats
        h[idx] = find_root(_touchdown_run, args[0], args[1], tuple(args[2:]), what="seabed guess", xtol=xtol)[
            0
        ]
    h = xp.where(ok, h, H0 / w)
    V = xp.where(ok, xp.sqrt(dh * dh + 2.0 * dh * h), cap)
    return w * h, xp.minimum(V * w, cap)


def _closure(H, V, span, dh, w, EA, L, mu_w, depth, size_x, size_z):
    """The grounded closure (m) at ``(H, V)``, its Jacobian and the sizes of its terms (the
    closure of `skcable._newton2.solve2`). Outside the domain ``H > 0``, ``V > 0``,
    ``L_B >= 0`` the residuals are NaN (arrays) or ``ValueError`` is raised (floats): the line
    search halves the step."""
    if not isinstance(H, np.ndarray):
        if not (H > 0 and V > 0 and V <= w * (L - anchor_part(H, w, EA, depth)[3])):
            raise ValueError("outside the grounded closure's domain")
        return (*grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth), size_x, size_z)
    with np.errstate(invalid="ignore", divide="ignore"):
        s1 = anchor_part(np.where(H > 0, H, 1.0), w, EA, depth)[3]
        valid = (H > 0) & (V > 0) & (V <= w * (L - s1))
        terms = grounded_closure(span, dh, w, EA, L, mu_w, np.where(valid, H, 1.0), V, depth)
    f_x, f_z = (np.where(valid, t, np.nan) for t in terms[:2])
    return (f_x, f_z, *terms[2:], size_x, size_z)


def _solve(span, dh, w, EA, L, mu_w, H, V, depth):
    """`skcable._newton2.solve2` on the grounded closure from ``(H, V)``, to its round-off: a
    few ulps of the lengths that enter each equation (the run and the grounded and hanging
    lengths, at most the line's; the heights)."""
    xp = namespace(span, H)
    V = xp.minimum(V, w * (L - anchor_part(H, w, EA, depth)[3]))  # the start inside the domain: L_B >= 0
    sizes = (L + span, L + xp.abs(dh) + depth)
    args = (span, dh, w, EA, L, mu_w, depth, *sizes)
    result = solve2(_closure, H, V, args, max_iter=80, halvings=40, what="elastic_catenary (seabed)")
    return result.x, result.y, result.history


def solve_grounded(span, dh, w, EA, L, mu_w, H0, depth):
    """Newton with backtracking on the grounded closure (`skcable._newton2.solve2`) from
    `inextensible_guess`, to its round-off: one scene on Python floats, or arrays of contact
    elements.

    Returns ``(H, V_B, history)``: the fairlead forces (N) and the largest scaled
    residual at each iteration."""
    xp = namespace(span, H0)
    _, _, x1, s1, _ = anchor_part(H0, w, EA, depth)
    H, V = inextensible_guess(span - x1, dh + depth, w, EA, L - s1, H0, xp)
    return _solve(span, dh, w, EA, L, mu_w, H, V, depth)
