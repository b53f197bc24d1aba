r"""A `skcable.mooring.Line` that hangs straight: its ends on one vertical, or weightless.

**Weightless** (every segment ``w = 0``: no gravity, as a MoorDyn file with ``g = 0`` has), a line
is straight between any two ends, its tension uniform: taut where
:math:`\sum_k L_k (1 + \varepsilon_k(T))` reaches the chord :math:`d`, its stiffness
:math:`K_{aa} = \tfrac{dT}{dd}\,\mathbf u\mathbf u^T + \tfrac{T}{d}(I - \mathbf u\mathbf u^T)`
(``u`` along the chord, :math:`dT/dd = 1/\sum_k L_k c_k(T)`); slack, without tension or
stiffness, where it is longer; a point load between its ends would bend it: refused.

**Ends on one vertical.**

Where one end lies straight above the other (horizontal distance zero) the line has no vertical
plane and the catenary's closed forms have no answer; the line hangs straight, and its statics
are exact in closed form (the limit of the elastic catenary as the horizontal force vanishes,
H.M. Irvine, "Cable Structures", MIT Press, 1981, ch. 2). From the lower end D up, each segment
has weight :math:`w_k` per unstretched length and the joints carry the point loads :math:`P_j`
(down), so that the tension is :math:`T(s) = T_D + W(s)`, :math:`W(s)` the load between D and
``s``. Three states:

- **taut**: :math:`T \ge 0` along the line and its stretched length is the ends' height
  difference :math:`\Delta z`,
  :math:`\sum_k \int_{s_k}^{s_{k+1}} \big(1 + \varepsilon(T(s))\big)\,ds = \Delta z`:
  one equation for :math:`T_D`, monotone (solved by safeguarded Newton; closed form for
  ``ε = T/EA``). The ends' vertical stiffness is :math:`1/C`, :math:`C = \int c(T)\,ds` the
  line's compliance (:math:`c = d\varepsilon/dT`); the lateral one is the limit of the catenary's
  :math:`H/r`, :math:`k = 1/\int (1 + \varepsilon)\,ds/T` (the line's shape under a small offset
  is :math:`T\,x' = H`), zero where the tension vanishes at an end; ends a horizontal distance
  below the round-off of the plane's (`skcable.mooring.between_points`) apart take its first-order force
  :math:`k\,(\mathbf b - \mathbf a)_{xy}`;
- **folded** (the line longer than the height, every segment heavier than water, no point load
  between the ends): both branches hang from a fold at :math:`s^*` where the tension vanishes,
  its height the same from either end, :math:`z_a - S_a(s^*) = z_b - S_b(s^*)`; the ends'
  vertical stiffness :math:`w/(2 + w\,(C_a + C_b))` (``w`` at the fold), no lateral stiffness;
- **on the seabed**: where the fold would lie below the seabed, each branch hangs from its end
  down to the seabed and the rest lies there in a heap, without tension (:math:`w/(1 + w C)`
  vertically, no coupling of the ends, no lateral stiffness).

A folded line with a buoyant segment or a point load between its ends is refused by name (its
fold is not a single point). The forces on the ends are vertical; an end's own attachment load
(``P`` at the end joint) acts on its end point.
"""

from __future__ import annotations

import math

import numpy as np

from skcable.errors import InputError
from skcable.mooring.between_points import StraightBetween
from skcable.mooring.segments.solution import segment_table

__all__ = ["VerticalBetween", "vertical_between", "weightless_between"]

_GAUSS = np.polynomial.legendre.leggauss(12)


def _pieces(law, T0: float, T1: float) -> np.ndarray:
    """Fractions of a segment (0 to 1) split where its tension, linear from T0 to T1, crosses a
    breakpoint of ``law``."""
    cuts = [0.0, 1.0]
    if T1 != T0:
        for Tb in np.asarray(getattr(law, "breakpoints", ()), dtype=float):
            f = (Tb - T0) / (T1 - T0)
            if 0.0 < f < 1.0:
                cuts.append(float(f))
    return np.unique(cuts)


def _integrals(law, T0: float, T1: float, L: float) -> tuple[float, float]:
    """``(∫ε ds, ∫c ds)`` over a segment of length ``L`` whose tension is linear from T0 to T1."""
    x, wt = _GAUSS
    eps = comp = 0.0
    ends = _pieces(law, T0, T1)
    for lo, hi in zip(ends[:-1], ends[1:], strict=True):
        f = lo + (hi - lo) * (x + 1.0) / 2.0
        T = T0 + (T1 - T0) * f
        scale = L * (hi - lo) / 2.0
        eps += scale * float(wt @ law.strain(T))
        comp += scale * float(wt @ law.compliance(T))
    return eps, comp


def _lateral(law, T0: float, T1: float, L: float) -> float:
    """``∫ (1 + ε)/T ds`` over a segment of tension linear from T0 to T1 > 0 (1/N · m): inf where
    an end's tension is zero."""
    lo, hi = min(T0, T1), max(T0, T1)
    if not lo > 0.0:
        return math.inf
    plain = L / lo if hi == lo else L * math.log(hi / lo) / (hi - lo)
    x, wt = _GAUSS
    f = (x + 1.0) / 2.0
    T = T0 + (T1 - T0) * f
    eps_over_T = law.strain(T) / T
    return plain + L / 2.0 * float(wt @ eps_over_T)


class _Hanging:
    """The segments of a line from its lower end up: lengths ``L``, weights ``w``, laws, the point
    loads ``P`` at the joints (down, N; ``P[0]`` at the lower end)."""

    def __init__(self, line, reverse: bool):
        arrays = line.arrays
        order = slice(None, None, -1) if reverse else slice(None)
        self.L = list(arrays.L_list[order])
        self.w = list(arrays.w_list[order])
        self.laws = [seg.law for seg in line.segments][order]
        self.P = list(arrays.P_list[order])
        self.n = len(self.L)

    def tensions(self, T_D: float) -> list:
        """``[(T at the bottom, T at the top)]`` of each segment with ``T_D`` just above the lower
        end's attachment."""
        out, T = [], T_D
        for k in range(self.n):
            if k:
                T += self.P[k]
            out.append((T, T + self.w[k] * self.L[k]))
            T += self.w[k] * self.L[k]
        return out

    def lowest(self) -> float:
        """The least ``T_D`` that keeps the tension >= 0 along the line."""
        return -min(0.0, *(T for ends in self.tensions(0.0) for T in ends))

    def stretched(self, T_D: float) -> tuple[float, float]:
        """``(stretched length, compliance ∫c ds)`` with ``T_D`` at the bottom (m, m/N)."""
        S = C = 0.0
        for k, (T0, T1) in enumerate(self.tensions(T_D)):
            e, c = _integrals(self.laws[k], T0, T1, self.L[k])
            S += self.L[k] + e
            C += c
        return S, C


def _taut_tension(hang: _Hanging, height: float) -> float | None:
    """``T_D`` of the taut line of stretched length ``height``, or None where it cannot be taut."""
    lo = hang.lowest()
    S, C = hang.stretched(lo)
    if S > height * (1.0 + 1e-14):
        return None
    # Newton from the bracket's low end: exact for ε = T/EA
    return _tension_for(hang.stretched, height, lo + (height - S) / C, lo)


def _tension_for(stretched, length: float, T: float, lo: float, bump: float = 1.0) -> float:
    """The tension (N) at which ``stretched(T)[0]`` (increasing; ``[1]`` its derivative) meets
    ``length`` (m), to 1e-14 of it: Newton's method from ``T``, safeguarded by bisection above
    ``lo`` (below the root), at most 100 steps."""
    hi = math.inf
    for _ in range(100):
        S, C = stretched(T)
        if abs(S - length) <= 1e-14 * length:
            break
        lo, hi = (T, hi) if S < length else (lo, T)
        step = T + (length - S) / C
        T = step if lo < step < hi else (lo + hi) / 2.0 if math.isfinite(hi) else 2.0 * T + bump
    return T


class VerticalBetween(StraightBetween):
    """A line solved with its ends on one vertical (module docstring); a `LineBetween` of
    zero horizontal distance: ``end_forces``, ``block(i, j)``, ``tension_a``, ``tension_b``,
    ``state`` (``"taut"``, ``"folded"`` or ``"on the seabed"``).
    """

    span = 0.0

    def __init__(self, line, a, b, state, forces, blocks, tensions_by_segment, grounded=0.0):
        self.line, self.a, self.b, self.state = line, a, b, state
        self.dh = float(b[2] - a[2])
        self.end_forces = forces
        self._blocks = blocks
        self._tensions = tensions_by_segment
        self.length_on_seabed = float(grounded)
        self.model, self.reason = "vertical", ""  # said by `skcable.mooring.choice.solve_between`
        self.is_slack = state != "taut"

    def block(self, i: int, j: int, J=None) -> np.ndarray:
        del J
        return self._blocks[i][j].copy()

    def tensions(self):
        """One row per segment from a to b (`skcable.mooring.segments.solution.segment_table`;
        ``T_lower`` towards a; ``T_max`` the larger end's: a straight segment's tension is
        monotonic along it)."""
        arrays = self.line.arrays
        low, up = zip(*self._tensions, strict=True) if self._tensions else ((), ())
        T_max = np.maximum(np.asarray(low, dtype=float), np.asarray(up, dtype=float))
        return segment_table(arrays.L, arrays.w, arrays.EA, low, up, T_max=T_max, grounded_length=0.0)

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points (n, 3), tension (n,))`` from a to b, the points on the straight chord (a folded
        line's fold drawn at its ends' chord)."""
        t = np.linspace(0.0, 1.0, int(n))
        return self.chord(n), np.interp(t, [0.0, 1.0], [self.tension_a, self.tension_b])

    def __repr__(self):
        return (
            f"VerticalBetween({self.state}, tension_a={self.tension_a:.6g}, tension_b={self.tension_b:.6g})"
        )


def _blocks(k_lat: float, k_aa: float, k_ab: float, k_bb: float) -> list:
    """The 3 × 3 blocks of a vertical line: lateral ``±k_lat`` on x, y and the vertical ones."""
    out = []
    for i in (0, 1):
        row = []
        for j in (0, 1):
            K = np.zeros((3, 3))
            K[0, 0] = K[1, 1] = k_lat if i == j else -k_lat
            K[2, 2] = (k_aa, k_ab, k_bb)[i + j]
            row.append(K)
        out.append(row)
    return out


def vertical_between(line, a, b, depth) -> VerticalBetween:
    """The `skcable.mooring.Line` ``line`` with its ends ``a``, ``b`` (float 3-vectors, m) on one
    vertical over the seabed ``z = -depth`` (None: none): module docstring."""
    reverse = b[2] < a[2]  # the hanging from the lower end D up
    lower, upper = (b, a) if reverse else (a, b)
    hang = _Hanging(line, reverse)
    height = float(upper[2] - lower[2])
    P_low, P_up = hang.P[0], hang.P[-1]
    T_D = _taut_tension(hang, height)
    if T_D is not None:
        tens = hang.tensions(T_D)
        _, C = hang.stretched(T_D)
        lateral = sum(_lateral(hang.laws[k], tens[k][0], tens[k][1], hang.L[k]) for k in range(hang.n))
        k_lat = 0.0 if not math.isfinite(lateral) else 1.0 / lateral
        T_U = tens[-1][1]
        F_low = np.array([0.0, 0.0, T_D - P_low])
        F_up = np.array([0.0, 0.0, -T_U - P_up])
        blocks = _blocks(k_lat, 1.0 / C, -1.0 / C, 1.0 / C)
        forces = np.array([F_up, F_low]) if reverse else np.array([F_low, F_up])
        lateral_offset = np.array([b[0] - a[0], b[1] - a[1], 0.0])  # below round-off of r: first order
        forces[0] += k_lat * lateral_offset
        forces[1] -= k_lat * lateral_offset
        ordered = [(t1, t0) for t0, t1 in reversed(tens)] if reverse else tens
        return VerticalBetween(line, a, b, "taut", forces, blocks, ordered)
    return _slack_vertical(line, a, b, depth, hang, reverse)


def _slack_vertical(line, a, b, depth, hang, reverse) -> VerticalBetween:
    """A vertical line longer than its height: folded, or its fold on the seabed (module
    docstring). A line lighter than water folds upward: its mirror image (z and the loads turned
    over) folds down, without a seabed."""
    heavy, light = all(w > 0 for w in hang.w), all(w < 0 for w in hang.w)
    if not (heavy or light) or any(P != 0 for P in hang.P[1:-1]):
        raise InputError(
            "line",
            "its ends share a vertical and it is slack with segments both heavier and lighter than "
            "water, or a point load between its ends: such a fold is not taken",
        )
    from scipy.optimize import brentq

    sign = 1.0 if heavy else -1.0
    # from a to b: arc length s from a; branch a = [0, s*], branch b = [s*, L]
    flip = (lambda x: list(reversed(x))) if reverse else list
    parts = (flip(hang.L), [sign * w for w in flip(hang.w)], flip(hang.laws))
    P_a, P_b = (hang.P[-1], hang.P[0]) if reverse else (hang.P[0], hang.P[-1])
    total = float(sum(parts[0]))
    za, zb = sign * float(a[2]), sign * float(b[2])

    def gap(s: float) -> float:
        return (za - _hang(parts, 0.0, s, "stop")[0]) - (zb - _hang(parts, s, total, "start")[0])

    s_star = brentq(gap, 0.0, total, xtol=1e-14 * total, rtol=1e-15)
    Sa, Ca, Ta = _hang(parts, 0.0, s_star, "stop")
    if depth is None or not heavy or za - Sa >= -float(depth):
        Sb, Cb, Tb = _hang(parts, s_star, total, "start")
        wk = _weight_at(parts[0], parts[1], s_star)
        k = wk / (2.0 + wk * (Ca + Cb))
        forces = np.array([[0.0, 0.0, -sign * Ta - P_a], [0.0, 0.0, -sign * Tb - P_b]])
        rows = _rows(parts, s_star)
        return VerticalBetween(line, a, b, "folded", forces, _blocks(0.0, k, -k, k), rows)
    return _on_seabed(line, (a, b), parts, (P_a, P_b), -float(depth))


def _hang(parts, lo: float, hi: float, zero_at: str) -> tuple[float, float, float]:
    """``(stretched length, compliance, tension at the other end)`` of the line between the arc
    lengths ``lo`` and ``hi`` hanging straight from a zero tension at its ``zero_at`` end
    (``"start"``: at ``lo``; ``"stop"``: at ``hi``), the tension growing by its weight."""
    L, w, laws = parts
    edges = np.concatenate([[0.0], np.cumsum(L)])
    pieces = [
        (k, max(lo, edges[k]), min(hi, edges[k + 1]))
        for k in range(len(L))
        if min(hi, edges[k + 1]) > max(lo, edges[k])
    ]
    if zero_at == "stop":
        pieces = pieces[::-1]
    S = C = T = 0.0
    for k, p, q in pieces:
        length = q - p
        e, c = _integrals(laws[k], T, T + w[k] * length, length)
        S, C, T = S + length + e, C + c, T + w[k] * length
    return S, C, T


def _weight_at(L, w, s: float) -> float:
    """The weight per length (N/m) of the segment at arc length ``s``."""
    edges = np.cumsum(L)
    k = min(int(np.searchsorted(edges, s)), len(L) - 1)
    return float(w[k])


def _rows(parts, s_star: float) -> list:
    """Per segment from a: ``(T towards a, T towards b)`` of a line folded at ``s_star`` (zero there)."""
    L = parts[0]
    edges = np.concatenate([[0.0], np.cumsum(L)])
    total = float(edges[-1])

    def tension(s: float) -> float:
        return _hang(parts, s, s_star, "stop")[2] if s <= s_star else _hang(parts, s_star, s, "start")[2]

    return [(tension(float(edges[k])), tension(float(min(edges[k + 1], total)))) for k in range(len(L))]


def _on_seabed(line, ends, parts, loads, seabed: float) -> VerticalBetween:
    """Each end's branch hanging down to the seabed, the rest lying there in a heap."""
    from scipy.optimize import brentq

    L, w, _ = parts
    total = float(sum(L))
    forces, ks, hung = [], [], []
    for end, (point, P) in enumerate(zip(ends, loads, strict=True)):
        height = float(point[2]) - seabed
        if height <= 0.0:
            forces.append([0.0, 0.0, -P])
            ks.append(0.0)
            hung.append(0.0)
            continue

        def span(ell, end=end):
            return (0.0, ell, "stop") if end == 0 else (total - ell, total, "start")

        def reach(x, height=height):
            return _hang(parts, *span(x))[0] - height

        ell = brentq(reach, 0.0, total, xtol=1e-14 * total, rtol=1e-15)
        _, C, T = _hang(parts, *span(ell))
        wk = _weight_at(L, w, ell if end == 0 else total - ell)
        forces.append([0.0, 0.0, -T - P])
        ks.append(wk / (1.0 + wk * C))
        hung.append(ell)
    if hung[0] + hung[1] > total:
        raise InputError("line", "its ends share a vertical and its branches overlap on the seabed")
    grounded = total - hung[0] - hung[1]
    rows = [(0.0, 0.0)] * len(L)
    a, b = ends
    return VerticalBetween(
        line, a, b, "on the seabed", np.array(forces), _blocks(0.0, ks[0], 0.0, ks[1]), rows, grounded
    )


def weightless_between(line, a, b) -> VerticalBetween:
    """The `skcable.mooring.Line` ``line`` of weightless segments with its ends at ``a``, ``b``
    (float 3-vectors, m): straight (module docstring)."""
    arrays = line.arrays
    if any(P != 0 for P in arrays.P_list[1:-1]):
        raise InputError(
            "line", "a weightless line with a point load between its ends is not straight: not taken"
        )
    chord = b - a
    d = float(np.linalg.norm(chord))
    if not d > 0:
        raise InputError("b", "is at a: a line between a point and itself")
    u = chord / d
    laws = [seg.law for seg in line.segments]
    L = arrays.L_list

    def stretched(T: float) -> tuple[float, float]:
        S = C = 0.0
        for law, length in zip(laws, L, strict=True):
            S += length * (1.0 + float(law.strain(np.array(T))))
            C += length * float(law.compliance(np.array(T)))
        return S, C

    S0, C0 = stretched(0.0)
    P_a, P_b = arrays.P_list[0], arrays.P_list[-1]
    if S0 >= d:  # slack: no tension, no stiffness
        T, dT = 0.0, 0.0
    else:
        T = _tension_for(stretched, d, (d - S0) / C0, 0.0, bump=0.0)
        dT = 1.0 / stretched(T)[1]
    uu = np.outer(u, u)
    K = dT * uu + (T / d) * (np.eye(3) - uu)
    blocks = [[K, -K], [-K, K]]
    forces = np.array([T * u + [0.0, 0.0, -P_a], -T * u + [0.0, 0.0, -P_b]])
    out = VerticalBetween(line, a, b, "taut" if T > 0 else "slack", forces, blocks, [(T, T)] * arrays.n)
    out.model = "weightless"
    out.span = float(math.hypot(chord[0], chord[1]))
    return out
