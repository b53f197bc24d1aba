"""Oracle of a multi-segment mooring line with clump weights and buoys: an independent walk.

From the fairlead forces ``(H, V)`` (``V`` the vertical tension just below B's joint) the walk
goes down the line segment by segment (H.M. Irvine, "Cable Structures", 1981, for each hanging
piece): the vertical tension falls by ``w_i L_i`` along segment ``i`` and by the point force
``P_j`` at joint ``j`` (a clump weight ``P > 0``, a buoy ``P < 0``). On a seabed through the
anchor the line rests on it from A up to the touchdown: inside a segment, where the vertical
tension reaches zero, or at a joint whose clump the seabed partly carries. Along the grounded
part the tension falls towards A by Coulomb friction ``μ w_i`` per metre and ``μ R_j`` at a
grounded clump (J.M. Jonkman, NREL 2007, piece by piece). The closure is ``X(H, V) = span``,
``Z(H, V) = dh``, solved at 50 digits.

What the walk finds outside the closed form's model raises `OutOfScope`: a buoy on the
grounded part, a suspended part that dips to the seabed again (a second touchdown), a line
clear of a seabed below the anchor that dips below it, slack in a heap with buoys between
the ends. Heaps (``H = 0``) are solved from the vertical part hanging from B.
"""

from __future__ import annotations

import mpmath
from mpmath import mp, mpf

from tests.fuzz.catenary import digits, nested_start, solve_from
from tests.fuzz.mp import DPS, NoRoot, OutOfScope

__all__ = ["LineData", "line_walk", "segments_line"]


class LineData:
    """A line: per segment ``L, w, EA`` (from A), per joint ``P`` (n + 1, downward positive),
    ``seabed`` (None, 0 or below A) and ``friction``."""

    def __init__(self, L, w, EA, P, seabed=None, friction=0.0):
        self.L, self.w, self.EA = [mpf(v) for v in L], [mpf(v) for v in w], [mpf(v) for v in EA]
        self.P = [mpf(v) for v in P]
        self.n = len(self.L)
        self.seabed = None if seabed is None else mpf(seabed)
        self.mu = mpf(friction)
        self.contact = seabed is not None and seabed == 0
        self.floats = _Floats(self)

    @property
    def length(self):
        return sum(self.L)

    @property
    def weight(self):
        return sum(wi * Li for wi, Li in zip(self.w, self.L, strict=True))


class _Floats:
    """The same line on Python floats (the walk on `math`, for a start)."""

    def __init__(self, line):
        self.L, self.w, self.EA = ([float(v) for v in seq] for seq in (line.L, line.w, line.EA))
        self.P, self.n, self.mu, self.contact = (
            [float(v) for v in line.P],
            line.n,
            float(line.mu),
            line.contact,
        )
        self.length, self.floats = float(line.length), self


def _verticals(line, V):
    """The vertical tension at the top and bottom of every segment (walking down from B)."""
    top, bot = [mpf(0)] * line.n, [mpf(0)] * line.n
    v = V
    for i in reversed(range(line.n)):
        top[i] = v
        bot[i] = v - line.w[i] * line.L[i]
        v = bot[i] - line.P[i]
    return top, bot


def _piece(H, Vt, Vb, l, w, EA, xp):
    """Run and rise of a hanging piece of unstretched length ``l`` from ``Vb`` to ``Vt``."""
    dx = H * l / EA + H / w * (xp.asinh(Vt / H) - xp.asinh(Vb / H))
    dy = l * (Vt + Vb) / (2 * EA) + (xp.hypot(H, Vt) - xp.hypot(H, Vb)) / w
    return dx, dy


def line_walk(u, line, xp=mpmath):
    """The walk at ``u = (H, V)``: a dict with ``X, Z``, the touchdown segment ``k`` (or None),
    the grounded length, ``H_A``, ``V_A``, the lowest height of the suspended part ``y_min``
    (above its lowest end) and whether a buoy lies on the grounded part; None where the whole
    line would lie on the seabed."""
    H, V = u
    line = line if xp is mpmath else line.floats
    top, bot = _verticals(line, V)
    contact = line.contact and bot[0] < 0
    k, a = 0, 0 * H
    if contact:
        up = [i for i in range(line.n) if top[i] > 0]
        if not up:
            return None
        k = up[0]
        a = -bot[k] / line.w[k] if bot[k] < 0 else 0 * H
    X = Z = y = y_min = 0 * H
    for i in range(k, line.n):  # the suspended pieces, from the bottom up
        Vb = 0 * H if (i == k and a > 0) else bot[i]
        l = line.L[i] - (a if i == k else 0)
        if Vb < 0 < top[i]:  # a vertex inside the piece
            y_min = min(y_min, y + _piece(H, 0 * H, Vb, -Vb / line.w[i], line.w[i], line.EA[i], xp)[1])
        dx, dy = _piece(H, top[i], Vb, l, line.w[i], line.EA[i], xp)
        X, Z, y = X + dx, Z + dy, y + dy
        y_min = min(y_min, y) if i < line.n - 1 else y_min
    out = {"X": X, "Z": Z, "k": k if contact else None, "y_min": y_min, "buoy_grounded": False}
    if not contact:
        out.update(grounded=0 * H, H_A=H, V_A=-bot[0] + line.P[0])
        return out
    T, grounded = H, 0 * H
    for i in range(k, -1, -1):  # the grounded pieces, from the touchdown towards A
        if i < k:  # the joint above piece i lies on the seabed: friction on what it carries there
            j = i + 1
            R = line.P[j] - max(bot[k], 0 * H) if j == k else line.P[j]
            if line.P[j] < 0:
                out["buoy_grounded"] = True
            T = max(T - line.mu * max(R, 0 * H), 0 * H)
        l = a if i == k else line.L[i]
        if l == 0:
            continue
        m = line.mu * line.w[i]
        if m == 0 or T - m * l > 0:
            X += l + (T * l - m * l * l / 2) / line.EA[i]
            T = T - m * l
        else:
            X += l + T * T / (2 * m * line.EA[i])
            T = 0 * H
        grounded += l
    out.update(X=X, grounded=grounded, H_A=T, V_A=line.P[0])
    return out


def _closure(line):
    def F(u, p, xp=mpmath):
        walk = line_walk(u, line, xp)
        if walk is None:  # the whole line on the seabed (outside the closure's domain)
            return [line.floats.length - p[0] if xp is not mpmath else line.length - p[0], -p[1]]
        return [walk["X"] - p[0], walk["Z"] - p[1]]

    return F


def _heap(line, span, dh):
    """The heap state (``H = 0``) or None: the part from B hangs vertically down to the seabed
    (the walk at ``H = 0``: each piece rises by its stretched length), the rest lies slack."""
    if not line.contact:
        return None

    def hang(V):
        top, bot = _verticals(line, V)
        Z, l_hang = 0 * V, 0 * V
        for i in reversed(range(line.n)):
            if top[i] <= 0:
                break
            if bot[i] < 0:  # reaches the seabed inside segment i
                l = top[i] / line.w[i]
                return Z + l + l * top[i] / (2 * line.EA[i]), l_hang + l
            Z += line.L[i] + line.L[i] * (top[i] + bot[i]) / (2 * line.EA[i])
            l_hang += line.L[i]
            if i > 0 and bot[i] - line.P[i] <= 0:  # a clump on the seabed
                return Z, l_hang
        return Z, l_hang

    lo, hi = mpf(0), 4 * (line.weight + sum(abs(p) for p in line.P))
    if hang(hi)[0] < dh:  # B out of reach of the line hanging vertically
        return None
    for _ in range(mp.prec + 8):  # bisection to the working precision (Z increases with V)
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if hang(mid)[0] < dh else (lo, mid)
    V = hi
    Z, l_hang = hang(V)
    if span > line.length - l_hang:
        return None
    if any(p < 0 for p in line.P[1:-1]):  # a buoy would lift the slack: no heap state; the caller
        return "buoyed"  # looks for a taut one (H > 0)
    return {"regime": "heap", "H": mpf(0), "V": V, "length_on_seabed": line.length - l_hang, "H_A": mpf(0)}


def segments_line(line: LineData, span, dh, start=None):
    """``H, V_B, V_A, H_A, length_on_seabed``, ``regime`` (free, grounded, heap) of ``line``
    between A = (0, 0) and B = (span, dh); `OutOfScope` outside the closed form's model."""
    with mp.workdps(DPS):
        span, dh = mpf(span), mpf(dh)
        heap = _heap(line, span, dh)
        if isinstance(heap, dict):
            heap.update(V_B=heap["V"] + line.P[-1], V_A=line.P[0])
            return heap
        F = _closure(line)
        W = line.weight + sum(abs(p) for p in line.P)

        def admissible(u):
            return u[0] > 0 and line_walk(u, line) is not None

        def own():
            return nested_start(
                lambda u, p, xp: F(u, p, xp),
                [span, dh, W, mpf(1), mpf(1)],
                lambda H: -4 * float(W),
                lambda H: 4 * float(W),
                +1,
            )

        first = None if start is None or not start.get("H", 0) > 0 else [mpf(start["H"]), mpf(start["V"])]
        scales = [abs(span) + line.length + abs(dh)] * 2
        dps = digits(min(line.EA), min(wi * Li for wi, Li in zip(line.w, line.L, strict=True)))
        try:
            H, V = solve_from(F, [first, own], [span, dh], scales, admissible, dps)
        except NoRoot:
            if heap == "buoyed":
                raise OutOfScope("slack in a heap on the seabed with a buoy between the ends") from None
            raise
        walk = line_walk([H, V], line)
        if walk["buoy_grounded"]:
            raise OutOfScope("a buoy on the grounded part")
        floor = (line.seabed if line.seabed is not None else -mpmath.inf) - mpf("1e-9") * scales[0]
        if (line.contact and walk["y_min"] < -mpf("1e-9") * scales[0]) or (
            not line.contact and walk["y_min"] < floor
        ):
            raise OutOfScope(
                f"the suspended line dips to the seabed (lowest point {float(walk['y_min']):.6g})"
            )
        regime = "grounded" if walk["k"] is not None else "free"
        return {
            "regime": regime,
            "H": H,
            "V": V,
            "V_B": V + line.P[-1],
            "V_A": walk["V_A"],
            "H_A": walk["H_A"],
            "length_on_seabed": walk["grounded"],
        }
