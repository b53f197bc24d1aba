"""Whether a scene of ``benchmarks/line_bvp_planes.py`` has a taut equilibrium, by the minimum of
its potential energy: an oracle independent of both line BVPs for the scenes they fail.

Method. The line is a chain of straight, tension-only elastic elements (SI units throughout: m,
N) from the anchor A = (0, 0) to the fairlead B = (span, dh), both fixed; nodes are uniform in
the arc length s within each stretch between the segments' joints and the point loads (which
are nodes). An element of unstretched length l and stiffness EA stores
``EA/(2 l) max(d - l, 0)**2``, d the distance of its nodes; each node carries half its
elements' weight (5-point Gauss on each element for a `Varying` weight) and its point load, a
potential linear in the heights. The seabed ``y = h + m x`` is straight, frictionless and
unilateral: every node on or above it, by an augmented Lagrangian on a penalty of stiffness
``max EA/l`` (multipliers updated until no node is deeper than 1e-11 L). Damped Newton
(Levenberg-Marquardt) on the exact gradient and the exact block-tridiagonal Hessian
(`scipy.linalg.solveh_banded`): on n nodes from the minimum on n/2 (its shape and its seabed
reaction), down to fewer than 128 nodes from the inextensible catenary.

Convexity. d is a norm of a linear map of the coordinates, so convex; ``max(t - l, 0)**2`` is
convex and nondecreasing in t, so each element's energy is convex; gravity is linear and the
contact set an intersection of half planes. Any equilibrium (a stationary point with the contact
conditions) is then a global minimum. Between two minima the energy is constant, so each convex
term is affine along the segment joining them; a taut element (d > l, where the energy is
strictly convex in d) cannot change its stretch there, so every minimum has the same tensions and
the same slack elements. A minimum with a slack element (d <= l: the line folds or heaps on a
frictionless slope) means no equilibrium of the chain has every element in tension.

Precision. The unknowns are the nodes' displacements from the start (`_Chain.reset`), so an
element's stretch is as precise as the element is short, not as its coordinates are large; Newton
stops when the sum of the nodal force residuals (the most they can move an end force) is below
1e-10 of the total load, or stops falling at round-off.

Verdict (`verdict`): the scene solved on n and 2n nodes: ``taut`` where both minima have every
element's strain above `SLACK_STRAIN`, ``no taut state`` where both have a slack one,
``marginal`` where they disagree, or where the least tension falls below `FALLING` of itself on
doubling the nodes: the continuous line's least tension is then zero at a point (a fold on the
seabed, whose tip a node may hold by its weight, O(w l), or a hang at H = 0), and the mesh decides.
Slack is strain <= 1e-12 (the strain's round-off is about 1e-15): on the 41 frictionless failed
scenes of ``planes_s9`` at 2000 and 4000 nodes every slack element had strain below -2e-3 (a fold),
the least strain of a minimum without one was 1.2e-9 (scene 1:231, least tension 0.23 N, EA 2e8 N)
and taut elements beside a fold went down to 1.1e-11: any threshold from -1e-3 to 1e-11 gives the
same verdicts (1e-9 would too, barely).

Run:  python benchmarks/line_energy_minimum.py [--csv benchmarks/out/line_bvp_planes.csv]
          [--outcomes "both fail" ...] [--n 2000] [--only SEED:SCENE ...]
      python benchmarks/line_energy_minimum.py --check   (the closed forms; non-zero exit past `CHECK_BOUND`)
Output: benchmarks/out/line_energy_minimum.csv (a row per frictionless scene of those outcomes,
rebuilt by `line_bvp_planes.scenes`), the counts of outcome x verdict and the scenes by verdict.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
import time
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.linalg import solveh_banded
from scipy.optimize import brentq

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).parent))
from _tables import counts_table, markdown_table  # noqa: E402
from line_bvp_planes import Scene, Varying, scenes  # noqa: E402

#: an element whose strain (d - l)/l is at most this is slack (module docstring: its calibration)
SLACK_STRAIN = 1e-12
#: taut on both meshes, but the least tension on 2n nodes below this share of that on n: marginal
FALLING = 0.7
VERDICTS = ("taut", "marginal", "no taut state")
FAILED = ("both fail", "plane fails only", "space fails only")
#: `check`: the largest end-force error allowed, over the largest end force, at 2000 nodes (measured 8.7e-7)
CHECK_BOUND = 2e-6
GX, GW = np.polynomial.legendre.leggauss(5)
EPS = np.finfo(float).eps


@dataclass
class Minimum:
    """The energy minimum on one mesh: end forces (N; ``H_A, V_A`` at the anchor as
    `mooring.solve_line_bvp` reports them, ``H_B, V_B`` at the fairlead), the least strain and
    tension (N), ``taut``, ``slack`` (where the slack elements are: arc length s and x, m),
    ``gradient`` (the sum of the nodal force residuals' components over the total load),
    ``seconds`` (with the coarser meshes), the nodes' ``s`` and positions (m), the seabed's
    reaction at the inner nodes per unit length (N/m)."""

    n_elements: int
    H_A: float
    V_A: float
    H_B: float
    V_B: float
    min_strain: float
    min_tension: float
    taut: bool
    slack: str
    gradient: float
    seconds: float
    s: np.ndarray
    nodes: np.ndarray
    contact: np.ndarray

    def forces(self):
        return np.array([self.H_A, self.V_A, self.H_B, self.V_B])


class _Chain:
    """The discrete line: its energy terms, gradient and banded Hessian in the inner nodes'
    displacements ``X = (x1, y1, x2, y2, ...)`` (m) from a reference (`reset`)."""

    def __init__(self, scene: Scene, n_nodes: int):
        lengths = np.array([seg[0] for seg in scene.segments], float)
        joints = np.concatenate([[0.0], np.cumsum(lengths)])
        self.length = total = joints[-1]
        cuts = np.unique(np.concatenate([joints, [s for s, _ in scene.point_loads]]))
        cuts = cuts[np.concatenate([[True], np.diff(cuts) > 1e-6 * total])]
        cuts[-1] = total
        count = np.maximum(1, np.round((n_nodes - 1) * np.diff(cuts) / total).astype(int))
        pieces = [
            np.linspace(a, b, k, endpoint=False) for a, b, k in zip(cuts[:-1], cuts[1:], count, strict=True)
        ]
        self.s = s = np.concatenate([*pieces, [total]])
        self.l = l = np.diff(s)
        mid = 0.5 * (s[:-1] + s[1:])
        owner = np.clip(np.searchsorted(joints, mid) - 1, 0, len(lengths) - 1)
        self.k = np.array([seg[2] for seg in scene.segments], float)[owner] / l  # N/m
        weight = np.empty_like(l)
        for j, (_, w, _) in enumerate(scene.segments):  # a loop over the segments, not the nodes
            e = owner == j
            if isinstance(w, Varying):
                weight[e] = 0.5 * l[e] * (w(mid[e, None] + 0.5 * l[e, None] * GX) @ GW)
            else:
                weight[e] = float(w) * l[e]
        self.half = 0.5 * weight[[0, -1]]  # of the end elements, N
        self.load = np.zeros(len(s))  # downward nodal loads, N
        self.load[:-1] += 0.5 * weight
        self.load[1:] += 0.5 * weight
        for sp, p in scene.point_loads:
            self.load[np.argmin(np.abs(s - sp))] += p
        self.ends = np.array([[0.0, 0.0], [scene.span, scene.dh]])
        self.bed = scene.seabed is not None
        h, m = scene.seabed if self.bed else (0.0, 0.0)
        self.normal = np.array([-m, 1.0]) / math.hypot(m, 1.0)  # the seabed's, upward
        self.tangent = np.array([1.0, m]) / math.hypot(m, 1.0)
        self.c = h / math.hypot(m, 1.0)
        self.penalty = float(self.k.max())
        self.lam = np.zeros(len(s) - 2)  # contact multipliers, N

    def reset(self, P):
        """Take the nodes ``P`` (m) as the reference: the unknowns ``X`` are the inner nodes'
        displacements from it, so that the element vectors and the seabed gaps are as precise as
        the elements are short, not as the coordinates are large (a stiff element's tension
        would otherwise be quantised by ``EA/l`` times the coordinates' last bit)."""
        self.P0 = np.vstack([self.ends[0], P[1:-1], self.ends[1]])
        self.E0 = np.diff(self.P0, axis=0)
        self.g0 = self.P0[1:-1] @ self.normal - self.c

    def nodes(self, X):
        return self.P0 + np.vstack([[0.0, 0.0], X.reshape(-1, 2), [0.0, 0.0]])

    def gap(self, X):
        """Height of the inner nodes above the seabed along its normal (m)."""
        return self.g0 + X.reshape(-1, 2) @ self.normal

    def contact(self, X):
        """The contact forces of the augmented Lagrangian (N)."""
        return np.maximum(self.lam - self.penalty * self.gap(X), 0.0) if self.bed else 0.0 * self.lam

    def state(self, X):
        """(element tensions (N), unit vectors, lengths (m))."""
        dX = self.E0 + np.diff(np.vstack([[0.0, 0.0], X.reshape(-1, 2), [0.0, 0.0]]), axis=0)
        d = np.linalg.norm(dX, axis=1)
        return self.k * np.maximum(d - self.l, 0.0), dX / np.where(d > 0, d, 1.0)[:, None], d

    def terms(self, X):
        """Energy terms (J), to difference term by term (the total is far larger than a step's change)."""
        T, _, _ = self.state(X)
        z = self.contact(X)
        return np.concatenate(
            [T**2 / (2 * self.k), self.load[1:-1] * X[1::2], (z**2 - self.lam**2) / (2 * self.penalty)]
        )

    def gradient(self, X):
        T, u, _ = self.state(X)
        g = np.zeros((len(T) + 1, 2))
        g[:-1] -= T[:, None] * u
        g[1:] += T[:, None] * u
        g[:, 1] += self.load
        g[1:-1] -= self.contact(X)[:, None] * self.normal
        return g[1:-1].ravel()

    def hessian(self, X):
        """The upper banded form of the Hessian (`scipy.linalg.solveh_banded`, 3 off-diagonals)."""
        T, u, d = self.state(X)
        uu = u[:, :, None] * u[:, None, :]
        K = self.k[:, None, None] * uu + (T / np.where(d > 0, d, 1.0))[:, None, None] * (np.eye(2) - uu)
        K *= (T > 0)[:, None, None]  # a slack element has no stiffness
        D = K[:-1] + K[1:]
        if self.bed:
            D += (self.contact(X) > 0)[:, None, None] * self.penalty * np.outer(self.normal, self.normal)
        O = -K[1:-1]
        ab = np.zeros((4, 2 * len(D)))
        ab[3, 0::2], ab[3, 1::2], ab[2, 1::2] = D[:, 0, 0], D[:, 1, 1], D[:, 0, 1]
        ab[1, 2::2], ab[0, 3::2], ab[2, 2::2], ab[1, 3::2] = O[:, 0, 0], O[:, 0, 1], O[:, 1, 0], O[:, 1, 1]
        return ab


def _newton(chain, X, scale, tol=1e-10, max_iter=20000):
    """Levenberg-Marquardt-damped Newton until the nodal residuals' sum (N, the most they can move
    an end force) is below ``tol`` of ``scale``, or 20 steps at round-off do not halve it; (X, the
    residual reached over ``scale``)."""
    kmax = float(chain.k.max())
    mu, best, stale = 1e-8 * kmax, np.inf, 0
    g, ab = chain.gradient(X), chain.hessian(X)
    for _ in range(max_iter):
        gn = np.abs(g).sum() / scale
        if gn < tol or stale >= 20 or mu > 1e8 * kmax:
            break
        A = ab.copy()
        A[3] += mu
        try:
            p = -solveh_banded(A, g, check_finite=False)
        except np.linalg.LinAlgError:
            mu *= 10
            continue
        predicted = -0.5 * (g @ p - mu * (p @ p))  # the quadratic model's: (H + mu) p = -g
        before, after = chain.terms(X), chain.terms(X + p)
        change = float(np.sum(after - before))
        g_new = chain.gradient(X + p)
        rho = -change / predicted if predicted > 0 else -1.0
        small = abs(predicted) <= 1e3 * EPS * float(np.abs(before).sum() + np.abs(after).sum())  # round-off
        stale, best = stale + 1 if small and gn > 0.5 * best else 0, min(best, gn)
        if rho > 0.01 or (small and np.abs(g_new).sum() / scale < gn):
            X, g, ab = X + p, g_new, chain.hessian(X + p)
            mu = max(mu / 5, 1e-14 * kmax) if rho > 0.5 or small else mu
        else:
            mu *= 8
    return X, max(tol, np.abs(g).sum() / scale)


def _catenary(scene, s, length):
    """Nodes on the inextensible catenary of the line's length (the chord if it is no longer)."""
    span, dh = scene.span, scene.dh
    P = np.outer(s / length, [span, dh])
    if length > math.hypot(span, dh) * (1 + 1e-9):
        q = math.sqrt(length**2 - dh**2)
        c = brentq(lambda c: 2 * c * math.sinh(min(span / (2 * c), 700.0)) - q, span / 1400, 1e3 * length)
        x0 = brentq(lambda x: c * (math.cosh((span - x) / c) - math.cosh(x / c)) - dh,
                    max(-700 * c + span, -10 * length), min(700 * c, span + 10 * length))  # fmt: skip
        x = x0 + c * np.arcsinh(s / c + math.sinh(-x0 / c))
        P = np.stack([x, c * (np.cosh((x - x0) / c) - math.cosh(x0 / c))], 1)
    if scene.seabed is not None:
        P[1:-1, 1] = np.maximum(P[1:-1, 1], scene.seabed[0] + scene.seabed[1] * P[1:-1, 0])
    return P


def energy_minimum(scene: Scene, n_nodes: int, start: Minimum | None = None) -> Minimum:
    """The minimum of the potential energy of ``scene`` on about ``n_nodes`` nodes (module
    docstring), from the shape of ``start`` (a coarser minimum), else from the minimum on half
    as many nodes (from the inextensible catenary below 128 nodes). Frictionless scenes only:
    ``ValueError`` for ``friction > 0``."""
    if scene.friction > 0:
        raise ValueError(f"friction {scene.friction}: the energy minimum is frictionless only")
    t0 = time.perf_counter()
    if start is None and n_nodes >= 128:
        start = energy_minimum(scene, n_nodes // 2)
    chain = _Chain(scene, n_nodes)
    s = chain.s
    P = _catenary(scene, s, chain.length) if start is None else np.stack(
        [np.interp(s, start.s, start.nodes[:, 0]), np.interp(s, start.s, start.nodes[:, 1])], 1
    )  # fmt: skip
    chain.reset(P)
    share = 0.5 * (chain.l[:-1] + chain.l[1:])  # of the line at the inner nodes, m
    if start is not None:  # the seabed's reaction per unit length (N/m) as the first multipliers
        chain.lam = np.interp(s[1:-1], start.s[1:-1], start.contact) * share
    X, scale = np.zeros(2 * len(s) - 4), float(np.abs(chain.load).sum())
    for _ in range(8 if chain.bed else 1):  # the augmented Lagrangian's updates
        X, tol = _newton(chain, X, scale)
        lam = chain.contact(X)
        deep = -min(0.0, float(chain.gap(X).min(initial=0.0)))
        done = deep < 1e-11 * chain.length and np.abs(lam - chain.lam).sum() <= tol * scale
        chain.lam = lam
        if done:
            break
    gradient = float(np.abs(chain.gradient(X)).sum()) / scale
    (T, u, d), P = chain.state(X), chain.nodes(X)
    strain = (d - chain.l) / chain.l
    gap = np.concatenate([[-chain.c], chain.gap(X), [chain.ends[1] @ chain.normal - chain.c]])
    on_bed = chain.bed & (gap < 1e-9 * chain.length)
    ends = np.zeros((2, 2))
    ends[:, 1] = -chain.half  # the end elements' half weight, on the seabed along it only
    for i, (end, inner) in enumerate(((0, 1), (-1, -2))):
        if on_bed[end] and on_bed[inner]:
            ends[i] = (ends[i] @ chain.tangent) * chain.tangent
    ends[:, 1] -= chain.load[[0, -1]] - chain.half  # point loads at the ends
    on_a, on_b = T[0] * u[0] + ends[0], -T[-1] * u[-1] + ends[1]  # the line's force on A, on B
    slack = strain <= SLACK_STRAIN
    return Minimum(
        len(chain.l), on_a[0], -on_a[1], -on_b[0], -on_b[1], float(strain.min()), float(T.min()),
        not slack.any(), _where(slack, s, P, on_bed, scene.span), gradient, time.perf_counter() - t0, s, P,
        chain.lam / share,
    )  # fmt: skip


def _where(slack, s, P, on_bed, span, most=3):
    """The slack runs: arc length, x, relative to the ends, on the seabed or not."""
    edges = np.diff(np.concatenate([[0], slack.astype(int), [0]]))
    runs = list(zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1), strict=True))  # a..b-1
    out = []
    for a, b in runs[:most]:
        xa, xb = P[a, 0], P[b, 0]
        side = " behind A" if max(xa, xb) < 0 else " beyond B" if min(xa, xb) > span else ""
        bed = on_bed[a : b + 1]
        where = "on the seabed" if bed.all() else "partly on the seabed" if bed.any() else "suspended"
        out.append(f"s {s[a]:.2f}-{s[b]:.2f} m, x {xa:.2f}-{xb:.2f} m{side}, {where}")
    return "; ".join(out) + (f"; +{len(runs) - most} more" if len(runs) > most else "")


def verdict(scene: Scene, n: int = 2000):
    """(verdict, the minimum on n nodes, on 2n nodes): module docstring."""
    one = energy_minimum(scene, n)
    two = energy_minimum(scene, 2 * n, one)
    if one.taut != two.taut or (two.taut and two.min_tension < FALLING * one.min_tension):
        return "marginal", one, two
    return ("taut" if one.taut else "no taut state"), one, two


def check(n=2000):
    """Relative end-force errors against closed forms: the elastic catenary without a seabed
    (`skcable.cable.elastic_catenary`), one on a flat seabed below A, and a line of three
    segments with a clump and a buoy at the joints (`skcable.mooring.Line`)."""
    from skcable import mooring
    from skcable.cable import elastic_catenary

    segs = ((150.0, 1000.0, 5e9), (250.0, 80.0, 5e8), (180.0, 20.0, 5e7))
    piecewise = mooring.Line(
        [mooring.Segment(*seg) for seg in segs], [mooring.ClumpWeight(1, 2e4), mooring.Buoy(2, 1.5e4)]
    ).solve(500.0, 60.0)
    uniform = {  # name: (span, dh, (length, w, EA), seabed under A)
        "elastic catenary": (400.0, 80.0, (450.0, 900.0, 1e9), None),
        "soft rope": (300.0, -40.0, (320.0, 20.0, 1e5), None),
        "on a seabed 30 m below A": (300.0, 100.0, (400.0, 80.0, 5e8), -30.0),
    }
    cases = {
        name: (
            Scene(a, h, (seg,), seabed=None if b is None else (b, 0.0)),
            elastic_catenary(a, h, seg[1], seg[2], length=seg[0], seabed=b),
        )
        for name, (a, h, seg, b) in uniform.items()
    }
    cases["3 segments, clump, buoy"] = (Scene(500.0, 60.0, segs, ((150.0, 2e4), (400.0, -1.5e4))), piecewise)
    worst = 0.0
    for name, (scene, ref) in cases.items():
        got = energy_minimum(scene, n)
        want = np.array([float(ref.H), float(ref.V_A), float(ref.H), float(ref.V_B)])
        error = float(np.abs(got.forces() - want).max() / np.abs(want).max())
        worst = max(worst, error)
        print(f"{name}: relative error {error:.1e} (n {n}, gradient {got.gradient:.0e}, {got.seconds:.2f} s)")
    print(f"largest {worst:.1e}, bound {CHECK_BOUND:g}")
    return worst <= CHECK_BOUND


COLUMNS = (
    "seed", "scene", "outcome", "verdict", "slack", "H_A", "V_A", "H_B", "V_B", "min_tension",
    "min_strain_n", "min_strain_2n", "gradient", "seconds",
)  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--csv", default=str(ROOT / "benchmarks" / "out" / "line_bvp_planes.csv"))
    parser.add_argument("--outcomes", nargs="+", default=list(FAILED))
    parser.add_argument("--n", type=int, default=2000, help="nodes of the coarser minimum")
    parser.add_argument("--only", nargs="+", help="SEED:SCENE: these scenes, whatever their outcome")
    parser.add_argument("--check", action="store_true", help="the closed forms; exit 1 past CHECK_BOUND")
    args = parser.parse_args(argv)
    if args.check:
        sys.exit(0 if check(args.n) else 1)
    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if args.only:
        survey = [r for r in rows if f"{r['seed']}:{r['scene']}" in args.only]
        args.outcomes = list(dict.fromkeys([*args.outcomes, *(r["outcome"] for r in survey)]))
    else:
        survey = [r for r in rows if r["outcome"] in args.outcomes]
    skipped = [r for r in survey if float(r["friction"]) > 0]
    survey = [r for r in survey if float(r["friction"]) == 0]
    drawn = {seed: scenes(seed, 1 + max(int(r["scene"]) for r in survey if int(r["seed"]) == seed))
             for seed in {int(r["seed"]) for r in survey}}  # fmt: skip
    rows = []
    for r in survey:
        sc = drawn[int(r["seed"])][int(r["scene"])]
        if abs(sc.tags["ratio"] - float(r["ratio"])) > 1e-4 or sc.tags["kind"] != r["kind"]:
            print(f"{r['seed']}:{r['scene']}: not the CSV's scene (the survey's draw changed): skipped")
            continue
        said, one, two = verdict(sc, args.n)
        slack = two.slack or one.slack
        rows.append(dict(zip(COLUMNS, (
            r["seed"], r["scene"], r["outcome"], said, slack, *(f"{v:.9g}" for v in two.forces()),
            f"{two.min_tension:.4g}", f"{one.min_strain:.3g}", f"{two.min_strain:.3g}",
            f"{max(one.gradient, two.gradient):.1e}", f"{one.seconds + two.seconds:.1f}",
        ), strict=True)))  # fmt: skip
        print(f"{r['seed']}:{r['scene']} ({r['outcome']}): {said}  {slack}", flush=True)
    out = ROOT / "benchmarks" / "out" / "line_energy_minimum.csv"
    out.parent.mkdir(exist_ok=True)
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    counts = Counter((r["outcome"], r["verdict"]) for r in rows)
    print(f"\n{len(rows)} frictionless scenes; {len(skipped)} with friction skipped (frictionless only)\n")
    print("\n".join(counts_table("outcome", args.outcomes, VERDICTS, counts)))
    table = [[v, " ".join(f"{r['seed']}:{r['scene']}" for r in rows if r["verdict"] == v)] for v in VERDICTS]
    print("\n" + "\n".join(markdown_table(("verdict", "scenes"), table)))


if __name__ == "__main__":
    main()
