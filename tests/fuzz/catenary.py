"""Oracles of one elastic line: Irvine's free catenary and Jonkman's seabed line, at 50 digits.

Written from the equations, not from skcable's code (H.M. Irvine, "Cable Structures", MIT
Press, 1981, §2.2; J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore
floating wind turbine", NREL, 2007). Anchor A = (0, 0), fairlead B = (span, dh), weight
``w`` per unstretched length, axial stiffness ``EA``, unstretched length ``L``.

Free line, unknowns ``(H, V_A)`` (``V_A`` the upward reaction at A)::

    X = H L/EA + (H/w) [asinh((wL - V_A)/H) + asinh(V_A/H)]
    Y = (wL²/2 - V_A L)/EA + [sqrt(H² + (wL - V_A)²) - sqrt(H² + V_A²)]/w

Anchor on a flat seabed (``seabed = 0``), Coulomb friction ``μ``, unknowns ``(H, V_B)``:
lifted (``V_B >= wL``) it is the free line with ``V_A = wL - V_B``; else the part
``L_B = L - V_B/w`` is grounded, its tension falling from ``H`` towards A by ``μw`` per
metre, and the rest hangs tangent to the seabed::

    X = L_B + ∫T/EA + H L_s/EA + (H/w) asinh(V_B/H),   Z = (T_B - H)/w + V_B²/(2 w EA)

Anchor a depth ``d`` above the seabed (no friction): the line hangs free unless it dips below
the seabed; then it hangs from A down to a landing, lies on the seabed and rises to B, and the
closure is one equation in ``H``. A line longer than its L-shape lies in a heap (``H = 0``).

Each oracle takes the data as a list ``p`` and an optional ``start`` (a dict of an answer to
check, or an earlier oracle answer: Newton starts there, else from the harness's own nested
bracketing) and returns a dict of mpmath numbers with the names skcable uses, and ``regime``.
"""

from __future__ import annotations

import math

import mpmath
from mpmath import mp, mpf

from tests.fuzz.mp import DPS, NoRoot, OutOfScope, brent, newton

__all__ = ["free_line", "seabed_line", "hanging_length", "free_closure", "seabed_closure", "solve_from"]


def free_closure(u, p, xp=mpmath):
    """Irvine's closure ``(X - span, Y - dh)`` at ``u = (H, V_A)``, data ``p = (span, dh, w, EA, L)``
    (``xp``: `mpmath`, or `math` on floats for a start)."""
    H, V = u
    span, dh, w, EA, L = p[:5]
    W = w * L
    X = H * L / EA + H / w * (xp.asinh((W - V) / H) + xp.asinh(V / H))
    Y = (W * L / 2 - V * L) / EA + (xp.hypot(H, W - V) - xp.hypot(H, V)) / w
    return [X - span, Y - dh]


def _grounded_stretch(H, L_B, mu_w, EA):
    """``∫ T/EA`` over a grounded length ``L_B`` with ``T`` falling from ``H`` by ``mu_w`` per metre."""
    if mu_w == 0 or H - mu_w * L_B >= 0:
        return (H * L_B - mu_w * L_B * L_B / 2) / EA
    return H * H / (2 * mu_w * EA)


def seabed_closure(u, p, xp=mpmath):
    """The closure of a line anchored on the seabed, ``u = (H, V_B)``, ``p = (span, dh, w, EA, L, mu)``."""
    H, VB = u
    span, dh, w, EA, L, mu = p[:6]
    W = w * L
    if VB >= W:  # lifted: the free line, V_A = wL - V_B <= 0
        return free_closure([H, W - VB], p, xp)
    L_B = L - VB / w
    L_s = VB / w
    X = L_B + _grounded_stretch(H, L_B, mu * w, EA) + H * L_s / EA + H / w * xp.asinh(VB / H)
    Z = (xp.hypot(H, VB) - H) / w + VB * VB / (2 * w * EA)
    return [X - span, Z - dh]


def hanging_length(d, w, EA):
    """Unstretched length that hangs vertically (H = 0) over a height ``d``: ``l + w l²/(2EA) = d``."""
    return 2 * d / (1 + mpmath.sqrt(1 + 2 * w * d / EA))


def _scales(p):
    span, dh, L = p[0], p[1], p[4]
    return [abs(span) + L + abs(dh)] * 2


def nested_start(closure, p, inner_lo, inner_hi, inner_sign):
    """A start ``(H, V)`` by nested bracketing on floats (the closure on `math`): ``V(H)`` from
    the second equation (monotone in V: ``inner_sign`` +1 increasing), then ``H`` from the
    first (increasing in H). A start only: Newton at full precision polishes it."""
    pf = [float(v) for v in p]

    def second(V, H):
        return inner_sign * float(closure([H, V], pf, math)[1])

    def V_of(H):
        lo, hi = float(inner_lo(H)), float(inner_hi(H))
        for _ in range(400):
            if second(lo, H) <= 0:
                break
            lo = lo * 4 if lo < 0 else lo / 4
        for _ in range(400):
            if second(hi, H) >= 0:
                break
            hi *= 4
        return brent(lambda V: second(V, H), lo, hi, rtol=1e-10, maxiter=100)

    def run(logH):
        H = math.exp(logH)
        return float(closure([H, V_of(H)], pf, math)[0])

    lo = hi = math.log(max(pf[2] * pf[4], 1e-300))
    for _ in range(400):
        if run(lo) <= 0:
            break
        lo -= 2.0
    for _ in range(400):
        if run(hi) >= 0:
            break
        hi += 2.0
    H = math.exp(brent(run, lo, hi, rtol=1e-12, maxiter=100))
    return [mpf(H), mpf(V_of(H))]


def digits(EA, W):
    """Working digits: `DPS` plus those a taut line's closure cancels (``H/(wL)`` is at most
    about ``EA/(wL)``: the asinh and the tensions differ by ``wL/H`` of their size)."""
    ratio = float(EA) / float(W)
    return DPS + max(0, min(80, math.ceil(math.log10(ratio)) + 2 if ratio > 1 else 0))


def solve_from(closure, starts, p, scales, admissible, dps=DPS):
    """Newton at ``dps`` digits from the first of ``starts`` (points, or callables giving one)
    that converges; `NoRoot` if none does."""
    error = None
    for start in starts:
        if start is None:
            continue
        try:
            point = start() if callable(start) else start
            return newton(closure, point, p, scales, dps=dps, admissible=admissible)
        except (NoRoot, ZeroDivisionError, ValueError, OverflowError) as exc:
            error = exc
    raise NoRoot(f"no root from any start ({error})")


def _given(start, *names):
    """``[start[name] ...]`` when ``start`` has them all (with ``H > 0``), else None."""
    if start is None or not all(name in start for name in names) or not start["H"] > 0:
        return None
    return [mpf(start[name]) for name in names]


def free_line(p, start=None):
    """Irvine's elastic catenary at `DPS` digits, ``p = (span, dh, w, EA, L)``: ``H, V_A, V_B,
    T_A, T_B``, the lowest point ``y_low``."""
    with mp.workdps(DPS):
        p = [mpf(v) for v in p[:5]]
        W = p[2] * p[4]

        def own():
            return nested_start(free_closure, p, lambda H: -(float(W) + H), lambda H: float(W) + H, -1)

        H, V = solve_from(
            free_closure, [_given(start, "H", "V_A"), own], p, _scales(p), lambda u: u[0] > 0, digits(p[3], W)
        )
        out = {"regime": "free", "H": H, "V_A": V, "V_B": W - V, "H_A": H, "length_on_seabed": mpf(0)}
        out["T_A"], out["T_B"] = mpmath.hypot(H, V), mpmath.hypot(H, W - V)
        if 0 < V / p[2] < p[4]:  # the vertex T_v = w s - V_A = 0 lies on the line
            out["y_low"] = -(V / p[2]) * V * (1 / (2 * p[3]) + 1 / (H + out["T_A"]))
        else:
            out["y_low"] = min(mpf(0), p[1])
        return out


def _heap(p, depth):
    span, dh, w, EA, L = p[:5]
    l_A = hanging_length(depth, w, EA) if depth > 0 else mpf(0)
    l_B = hanging_length(dh + depth, w, EA)
    return l_A, l_B, span <= L - l_A - l_B


def _on_seabed(p, start):
    span, dh, w, EA, L, mu = p
    W = w * L
    l_A, l_B, heap = _heap(p, 0)
    if heap:
        return {
            "regime": "heap",
            "H": mpf(0),
            "V_B": w * l_B,
            "V_A": mpf(0),
            "H_A": mpf(0),
            "length_on_seabed": L - l_B,
        }

    def own():
        return nested_start(seabed_closure, p, lambda H: float(W) * 1e-30, lambda H: float(W), +1)

    H, VB = solve_from(
        seabed_closure,
        [_given(start, "H", "V_B"), own],
        p,
        _scales(p),
        lambda u: u[0] > 0 and u[1] > 0,
        digits(EA, W),
    )
    out = {"H": H, "V_B": VB}
    if VB >= W:
        out.update(regime="lifted", V_A=W - VB, H_A=H, length_on_seabed=mpf(0))
    else:
        L_B = L - VB / w
        out.update(regime="grounded", V_A=mpf(0), H_A=max(H - mu * w * L_B, mpf(0)), length_on_seabed=L_B)
    return out


def _part(H, height, w, EA):
    """``(V, l, x)`` of the part hanging from a support ``height`` above its landing (vertex on
    the seabed) at horizontal tension ``H``: ``(T - H)/w + V²/(2 w EA) = height``, a quadratic in
    ``T - H``."""
    b = 1 + H / EA
    t = 2 * w * height / (b + mpmath.sqrt(b * b + 2 * w * height / EA))
    V = mpmath.sqrt(t * (t + 2 * H))
    l = V / w
    return V, l, H * l / EA + H / w * mpmath.asinh(V / H)


def _touchdown_closure(u, p):
    """``X(H) - span`` of a line hanging from A (``d`` above the seabed) to a landing, lying
    on the seabed (no friction) and rising to B."""
    (H,) = u
    span, dh, w, EA, L, d = p
    _, l_A, x_A = _part(H, d, w, EA)
    _, l_B, x_B = _part(H, dh + d, w, EA)
    return [x_A + x_B + (L - l_A - l_B) * (1 + H / EA) - span]


def _above_seabed(p, start):
    """The anchor a depth ``d = -seabed > 0`` above the seabed (frictionless where it touches down)."""
    span, dh, w, EA, L, mu, seabed = p
    d = -seabed
    free = free_line(p[:5], start if start is not None and start.get("H", 0) > 0 else None)
    if free["y_low"] >= seabed:
        return free
    l_A, l_B, heap = _heap(p, d)
    if heap:
        return {
            "regime": "heap",
            "H": mpf(0),
            "V_B": w * l_B,
            "V_A": w * l_A,
            "H_A": mpf(0),
            "length_on_seabed": L - l_A - l_B,
        }
    if mu != 0:
        raise OutOfScope("friction where the line touches down between A and B: statically indeterminate")
    q = [span, dh, w, EA, L, d]
    first = [mpf(start["H"])] if start is not None and start.get("H", 0) > 0 else None
    (H,) = solve_from(
        _touchdown_closure,
        [first, [free["H"]], [w * L]],
        q,
        [span + L],
        lambda u: u[0] > 0,
        digits(EA, w * L),
    )
    V_A, l_A, _ = _part(H, d, w, EA)
    V_B, l_B, _ = _part(H, dh + d, w, EA)
    L_g = L - l_A - l_B
    if L_g < 0:
        raise NoRoot("a touchdown with a negative grounded length")
    return {"regime": "touchdown", "H": H, "H_A": H, "V_A": V_A, "V_B": V_B, "length_on_seabed": L_g}


def seabed_line(p, start=None):
    """Jonkman's line on a flat seabed at `DPS` digits, ``p = (span, dh, w, EA, L, seabed,
    friction)``: ``H, V_B, V_A, H_A, length_on_seabed`` and ``regime`` (lifted, grounded, heap;
    with the anchor above the seabed: free, touchdown, heap)."""
    with mp.workdps(DPS):
        span, dh, w, EA, L, seabed, mu = (mpf(v) for v in p)
        if seabed == 0:
            start = start if start is None or start.get("regime") not in ("heap",) else None
            return _on_seabed([span, dh, w, EA, L, mu], start)
        return _above_seabed([span, dh, w, EA, L, mu, seabed], start)
