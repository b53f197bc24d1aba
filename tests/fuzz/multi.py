"""Regimes of multi-segment lines (`mooring.Line`: clumps, buoys, seabed, friction, heaps; warm
starts, mirror and unit scale, `line_3d` in space) and of the sloped seabed.

Oracles: the independent walk of `tests.fuzz.segments` and the sloped closure of
`tests.fuzz.sloped`, at 50 digits; stiffnesses by central differences of them.
"""

from __future__ import annotations

import math

import mpmath
from mpmath import mp, mpf

from skcable.errors import ResolutionWarning
from tests.fuzz.compare import check_stiffness, close, compare_all, compare_matrix, fmt
from tests.fuzz.harness import Case
from tests.fuzz.mp import DPS, EPS, NoRoot, OutOfScope, condition
from tests.fuzz.scenes import log_uniform, pick
from tests.fuzz.segments import LineData, segments_line
from tests.fuzz.sloped import sloped_line

__all__ = ["REGIMES", "random_line", "line_expr"]

LINE_NAMES = frozenset(
    {
        "segments",
        "attachments",
        "seabed",
        "friction",
        "span",
        "dh",
        "start",
        "length",
        "w",
        "EA",
        "joint",
        "weight",
        "buoyancy",
    }
)
NAMES = ("H", "V_B", "V_A", "H_A", "length_on_seabed")


def random_line(rng, *, seabed="any"):
    """``(segments, attachments, seabed, friction, span, dh)`` of a random mooring line: 1-4
    segments of different weights (chain, wire, rope), clumps and buoys at joints."""
    n = int(rng.integers(1, 5))
    scale = log_uniform(rng, 1.0, 3e3)
    w0 = log_uniform(rng, 1e-1, 3e3)
    segments = []
    for _ in range(n):
        L = scale * log_uniform(rng, 0.05, 1.0)
        w = w0 * log_uniform(rng, 0.02, 50.0)
        segments.append((L, w, w * L * log_uniform(rng, 3e1, 1e9)))
    total = sum(s[0] for s in segments)
    weight = sum(s[0] * s[1] for s in segments)
    attachments = []
    for _ in range(int(rng.integers(0, 3))):
        joint = int(rng.integers(1, n)) if n > 1 and rng.uniform() < 0.85 else int(pick(rng, [0, n]))
        size = weight * log_uniform(rng, 1e-3, 0.5)
        attachments.append(("ClumpWeight" if rng.uniform() < 0.6 else "Buoy", joint, size))
    kind = pick(rng, ["free", "contact", "contact", "below"]) if seabed == "any" else seabed
    if kind == "contact":
        bed, friction = 0.0, (0.0 if rng.uniform() < 0.3 else log_uniform(rng, 1e-3, 2.0))
        depth = total * rng.uniform(0.05, 0.9)
        span = math.sqrt(max(total**2 - depth**2, 1e-6 * total**2)) * rng.uniform(0.5, 1.05)
        dh = depth
    else:
        bed, friction = (None, 0.0) if kind == "free" else (-total * rng.uniform(0.05, 2.0), 0.0)
        angle = rng.uniform(-1.3, 1.3) if kind == "free" else rng.uniform(-0.2, 1.3)
        chord = total * pick(rng, [1 - log_uniform(rng, 1e-6, 1e-2), rng.uniform(0.5, 1.0)])
        span, dh = chord * math.cos(angle), chord * math.sin(angle)
        if bed is not None and dh <= bed:
            dh = bed * rng.uniform(-1.0, 0.5)
    return segments, attachments, bed, friction, span, dh


def line_expr(segments, attachments, seabed, friction) -> str:
    segs = ", ".join(f"mooring.Segment({fmt(L)}, {fmt(w)}, {fmt(EA)})" for L, w, EA in segments)
    atts = ", ".join(f"mooring.{kind}({j}, {fmt(size)})" for kind, j, size in attachments)
    bed = "" if seabed is None else f", seabed={fmt(seabed)}, friction={fmt(friction)}"
    return f"mooring.Line([{segs}], [{atts}]{bed})"


def line_data(segments, attachments, seabed, friction) -> LineData:
    P = [0.0] * (len(segments) + 1)
    for kind, j, size in attachments:
        P[j] += size if kind == "ClumpWeight" else -size
    return LineData(
        [s[0] for s in segments], [s[1] for s in segments], [s[2] for s in segments], P, seabed, friction
    )


def _start(result):
    return {"H": result.H, "V": result.V_B - result.joint_forces[-1]} if result.H > 0 else None


def _line_problems(result, data, span, dh, K_rel=1e-7):
    want = segments_line(data, span, dh, _start(result))

    def oracle(q, base=want):
        return segments_line(data, q[0], q[1], {"H": base["H"], "V": base["V"]} if base["H"] > 0 else None)

    force = float(want["H"] + data.weight + sum(abs(p) for p in data.P))
    scales = dict.fromkeys(NAMES, force) | {"length_on_seabed": float(data.length)}
    problems = compare_all(result, want, oracle, [span, dh], NAMES, scales)
    if bool(result.heap) != (want["regime"] == "heap"):
        problems.append(f"heap: oracle {want['regime']}, skcable heap={result.heap}")
    if not problems:
        problem = check_stiffness(
            f"stiffness() ({want['regime']})", result.stiffness(), oracle, [span, dh], want, K_rel
        )
        problems += [problem] if problem else []
    return problems, want, oracle


def _judge_line(data, span, dh):
    def judge(exc):
        want = segments_line(data, span, dh)
        finite = all(abs(float(want[n])) < 1e300 for n in NAMES)
        return (
            f"{want['regime']}: H = {float(want['H']):.17g}, V_B = {float(want['V_B']):.17g}"
            if finite
            else None
        )

    return judge


def line(rng) -> Case:
    """`Line.solve` against the independent walk (free, on the seabed with friction, heaps)."""
    segments, attachments, bed, friction, span, dh = random_line(rng)
    data = line_data(segments, attachments, bed, friction)
    expr = f"{line_expr(segments, attachments, bed, friction)}.solve({fmt(span)}, {fmt(dh)})"

    def check(result, caught):
        return _line_problems(result, data, span, dh)[0]

    return Case("line", expr, LINE_NAMES, check, _judge_line(data, span, dh))


def line_warm(rng) -> Case:
    """A warm start from a nearby solution gives the cold solution (the oracle's) to round-off."""
    segments, attachments, bed, friction, span, dh = random_line(rng)
    data = line_data(segments, attachments, bed, friction)
    span0, dh0 = span * (1 + rng.uniform(-0.05, 0.05)), dh + abs(span) * rng.uniform(-0.05, 0.05)
    if bed is not None:
        dh0 = max(dh0, bed + 0.5 * (dh - bed))
    expr = (
        f"(lambda line: line.solve({fmt(span)}, {fmt(dh)}, start=line.solve({fmt(span0)}, {fmt(dh0)})))"
        f"({line_expr(segments, attachments, bed, friction)})"
    )

    def check(result, caught):
        return _line_problems(result, data, span, dh)[0]

    def judge(exc):  # the start's solve runs first: its scene must be solvable too
        segments_line(data, span0, dh0)
        return _judge_line(data, span, dh)(exc)

    return Case("line/warm", expr, LINE_NAMES, check, judge, calls=2)


def line_scaled(rng) -> Case:
    """Other units: lengths x 10^a, forces x 10^b give H, V x 10^b (to 1e-12 and the round-off)."""
    segments, attachments, bed, friction, span, dh = random_line(rng)
    data = line_data(segments, attachments, bed, friction)
    lam, mu = 10.0 ** int(rng.integers(-3, 4)), 10.0 ** int(rng.integers(-3, 7))
    scaled_segments = [(L * lam, w * mu / lam, EA * mu) for L, w, EA in segments]
    scaled_atts = [(kind, j, size * mu) for kind, j, size in attachments]
    bed2 = None if bed is None else bed * lam
    expr = (
        f"({line_expr(segments, attachments, bed, friction)}.solve({fmt(span)}, {fmt(dh)}), "
        f"{line_expr(scaled_segments, scaled_atts, bed2, friction)}"
        f".solve({fmt(span * lam)}, {fmt(dh * lam)}))"
    )

    def judge(exc):  # both scenes: the scaled one is the same line in other units
        return _judge_line(data, span, dh)(exc)

    def check(result, caught):
        first, scaled = result
        problems, want, oracle = _line_problems(first, data, span, dh)
        force = float(want["H"] + data.weight + sum(abs(p) for p in data.P))
        spread = None
        for name in ("H", "V_B"):
            got, ref = getattr(scaled, name) / mu, getattr(first, name)
            if close(name, got, mpf(ref), 1e-12 * max(abs(ref), force)) is None:
                continue
            spread = spread or condition(oracle, [span, dh], ("H", "V_B"))
            allowed = 2.0**11 * EPS * spread[name] + 1e-12 * max(abs(ref), force)
            problem = close(f"scaled x{lam:g} m, x{mu:g} N: {name}/{mu:g}", got, mpf(ref), allowed)
            problems += [problem] if problem else []
        return problems

    return Case("line/scaled", expr, LINE_NAMES, check, _judge_line(data, span, dh), calls=2)


def _fairlead_force(data, anchor, fairlead, base):
    """``F_b = (-H e, -V_B)`` from the 2-D oracle in the line's vertical plane (mp)."""
    d = [fairlead[i] - anchor[i] for i in range(3)]
    r = mpmath.hypot(d[0], d[1])
    start = None if base is None or not base["H"] > 0 else {"H": base["H"], "V": base["V"]}
    sol = segments_line(data, r, d[2], start)
    return [-sol["H"] * d[0] / r, -sol["H"] * d[1] / r, -sol["V_B"]], sol


def line3d(rng) -> Case:
    """`line_3d` in space: the fairlead force and its 3x3 stiffness against the 2-D walk in the
    line's vertical plane and central differences of it."""
    segments, attachments, bed, friction, span, dh = random_line(rng)
    data = line_data(segments, attachments, bed, friction)
    heading = rng.uniform(-math.pi, math.pi)
    anchor = [log_uniform(rng, 1.0, 1e3) * rng.choice([-1, 1]) for _ in range(3)]
    fairlead = [anchor[0] + span * math.cos(heading), anchor[1] + span * math.sin(heading), anchor[2] + dh]
    model = line_expr(segments, attachments, bed, friction)
    expr = f"mooring.line_3d({model}, {[fmt(v) for v in anchor]}, {[fmt(v) for v in fairlead]})".replace(
        "'", ""
    )

    def check(result, caught):
        with mp.workdps(DPS):
            a, b = [mpf(v) for v in anchor], [mpf(v) for v in fairlead]
            F, base = _fairlead_force(data, a, b, _start(result.solution))
            scale = float(base["H"] + data.weight + sum(abs(p) for p in data.P))
            problems = [
                close(f"force_on_fairlead[{i}]", result.force_on_fairlead[i], F[i], 1e-9 * scale)
                for i in range(3)
            ]
            problems = [p for p in problems if p]
            if problems:
                return problems
            h = mpf("1e-15") * (abs(span) + abs(dh))
            K = mpmath.matrix(3, 3)
            for j in range(3):
                plus, minus = list(b), list(b)
                plus[j] += h
                minus[j] -= h
                up, down = _fairlead_force(data, a, plus, base)[0], _fairlead_force(data, a, minus, base)[0]
                for i in range(3):
                    K[i, j] = -(up[i] - down[i]) / (2 * h)
        problem = compare_matrix(f"stiffness() ({base['regime']})", result.stiffness(), K, 1e-7)
        return [problem] if problem else []

    names = LINE_NAMES | {"model", "anchor", "fairlead"}
    return Case("line_3d", expr, names, check, _judge_line(data, math.hypot(span, 0.0), dh))


def sloped(rng) -> Case:
    """`sloped_seabed_catenary` against the sloped closure at 50 digits (MoorPy and a grid of
    starts for the refusals)."""
    span = log_uniform(rng, 1e-1, 1e4)
    w = log_uniform(rng, 1e-2, 1e4)
    m = math.tan(rng.uniform(-0.6, 0.6))
    dh = span * m + span * log_uniform(rng, 1e-3, 3.0)
    friction = 0.0 if rng.uniform() < 0.4 else log_uniform(rng, 1e-3, 2.0)
    L = (span + dh - span * m) * rng.uniform(0.6, 1.3)
    EA = w * L * log_uniform(rng, 1e1, 1e11)
    p = [span, dh, w, EA, L, m, friction]
    expr = (
        f"cable.sloped_seabed_catenary({fmt(span)}, {fmt(dh)}, {fmt(w)}, {fmt(EA)}, length={fmt(L)}, "
        f"seabed_slope={fmt(m)}, friction={fmt(friction)})"
    )

    def check(result, caught):
        start = {"H": result.H, "V_A": result.V_A, "length_on_seabed": result.length_on_seabed}
        start["free"] = result.free is not None
        want = sloped_line(p, start)

        def oracle(q, base=want):
            return sloped_line(q, {**base, "free": base["regime"] == "free"})

        force = float(want["H"] + w * L)
        scales = dict.fromkeys(NAMES, force) | {"length_on_seabed": L}
        problems = compare_all(result, want, oracle, p, ("H", "V_B", "length_on_seabed"), scales)
        if not problems:
            problem = check_stiffness(f"stiffness() ({want['regime']})", result.stiffness(), oracle, p, want)
            problems += [problem] if problem else []
        return problems

    def judge(exc):
        want = sloped_line(p)
        return f"{want['regime']}: H = {float(want['H']):.17g}, V_B = {float(want['V_B']):.17g}"

    names = frozenset({"span", "dh", "w", "EA", "length", "seabed_slope", "friction"})
    return Case("sloped_seabed", expr, names, check, judge)


REGIMES = {
    "line": line,
    "line/warm": line_warm,
    "line/scaled": line_scaled,
    "line_3d": line3d,
    "sloped_seabed": sloped,
}


BVP_NAMES = frozenset(
    {
        "span",
        "dh",
        "segments",
        "seabed",
        "seabed_slope",
        "friction",
        "point_loads",
        "n_elements",
        "fit_touchdown",
        "rtol",
        "max_iter",
        "length",
    }
)


def line_bvp(rng) -> Case:
    """`solve_line_bvp` (finite elements) against the walk: free and on the seabed, clumps and
    buoys as point loads at the joints; agreement to 1e-6 of the force scale (the mesh's error
    is of order 1e-8 with the touchdown fitted). The walk's scope is narrower than the BVP's (a
    buoy lifting the grounded line, a second touchdown): there the oracle says nothing."""
    segments, attachments, bed, friction, span, dh = random_line(rng, seabed=pick(rng, ["free", "contact"]))
    attachments = [a for a in attachments if 0 < a[1] < len(segments)]
    return bvp_case(segments, attachments, bed, friction, span, dh)


def line_bvp_auto(rng) -> Case:
    """`line_bvp`'s scenes with ``n_elements="auto"`` (`skcable.mooring.line_bvp.resolution`: 64
    elements, more while the mesh does not resolve the line): the same oracle, and the elements
    taken one of 64, 256, 1024."""
    segments, attachments, bed, friction, span, dh = random_line(rng, seabed=pick(rng, ["free", "contact"]))
    attachments = [a for a in attachments if 0 < a[1] < len(segments)]
    return bvp_case(segments, attachments, bed, friction, span, dh, n_elements="auto")


def bvp_case(segments, attachments, bed, friction, span, dh, n_elements=None) -> Case:
    """The case of `solve_line_bvp` on a line (`random_line`'s data; attachments at inner joints),
    on its default elements or ``n_elements``."""
    data = line_data(segments, attachments, bed, friction)
    joints = [sum(s[0] for s in segments[:j]) for j in range(len(segments) + 1)]
    loads = [(joints[j], size if kind == "ClumpWeight" else -size) for kind, j, size in attachments]
    segs = ", ".join(f"({fmt(L)}, {fmt(w)}, {fmt(EA)})" for L, w, EA in segments)
    pl = ", ".join(f"({fmt(s)}, {fmt(P)})" for s, P in loads)
    bed_kw = "" if bed is None else f", seabed={fmt(bed)}, friction={fmt(friction)}"
    mesh_kw = "" if n_elements is None else f", n_elements={n_elements!r}"
    expr = f"mooring.solve_line_bvp({fmt(span)}, {fmt(dh)}, [{segs}]{bed_kw}, point_loads=[{pl}]{mesh_kw})"

    def check(result, caught):
        try:
            want = segments_line(data, span, dh, {"H": result.H, "V": result.V_B} if result.H > 0 else None)
        except OutOfScope as why:
            raise NoRoot(f"outside the walk's model ({why}): unchecked") from None
        force = float(want["H"] + data.weight + sum(abs(p) for p in data.P))
        out = [close(name, getattr(result, name), want[name], 1e-6 * force) for name in ("H", "V_B", "H_A")]
        if n_elements is not None and result.n_elements not in (64, 256, 1024):
            out.append(f"n_elements='auto' took {result.n_elements} elements")
        return [o for o in out if o]

    return Case(
        "solve_line_bvp", expr, BVP_NAMES, check, _bvp_judge(data, span, dh, expr, check), timeout=60.0
    )


#: What `solve_line_bvp` documents it refuses, though the walk may solve it: a slack stretch that
#: ends at a point load resting on the seabed, its friction partly mobilised (`InputError`
#: naming ``point_loads``, or in space ``attachments`` for a clump at a joint; `mooring.Line`
#: solves it).
OUTSIDE_BVP = "this BVP does not model that state"
#: The advice of its refusal of a discrete line in compression (its bends unresolved).
MORE_ELEMENTS = "elements do not resolve its bends; give more"


def _bvp_judge(data, span, dh, expr, check):
    """The judge of a line BVP's refusal of ``expr`` (the line ``data`` at ``(span, dh)`` in its
    vertical plane): honest for a heap (documented: the BVP refuses it, `Line` and
    `elastic_catenary` return it), else `_bvp_verdict` against the walk's line."""

    def judge(exc):
        want = segments_line(data, span, dh)
        if want["regime"] == "heap":
            return None
        verdict = f"{want['regime']}: H = {float(want['H']):.17g}, V_B = {float(want['V_B']):.17g}"
        return _bvp_verdict(exc, expr, check, verdict)

    return judge


def _bvp_verdict(exc, expr, check, verdict):
    """The judgement of a refusal of `solve_line_bvp` where the walk solves the line: honest
    (None) where it is a documented limit of the BVP (`OUTSIDE_BVP`), or where it says to give
    more elements and 1024 elements give the walk's answer (the advice works); else ``verdict``."""
    from skcable import InputError, mooring
    from skcable.errors import ConvergenceError

    text = str(exc)
    if isinstance(exc, InputError) and exc.argument in ("point_loads", "attachments") and OUTSIDE_BVP in text:
        return None
    if isinstance(exc, ConvergenceError) and MORE_ELEMENTS in text and "n_elements=" not in expr:
        try:
            finer = eval(expr[:-1] + ", n_elements=1024)", {"mooring": mooring})  # noqa: S307 - our own call
        except (InputError, ConvergenceError) as again:
            return f"{verdict}; with 1024 elements: {type(again).__name__}: {again}"
        problems = check(finer, [])
        return f"{verdict}; with 1024 elements: {'; '.join(problems)}" if problems else None
    return verdict


def line_bvp_3d(rng) -> Case:
    """`solve_line_bvp_3d` of `line_bvp`'s lines on a flat seabed, friction mostly (its slack
    stretch near the anchor where friction would take more than the pull), the chord at a random
    heading: the fairlead's force against the walk in the chord's vertical plane (``-H e``,
    ``-V_B``, to 1e-6 of the force scale, as `line_bvp`; to the several per cent its
    `skcable.errors.ResolutionWarning` allows where it warns that its mesh does not resolve the
    line), none across it, the anchor's force ``H_A e``."""
    segments, attachments, bed, friction, span, dh = random_line(rng, seabed="contact")
    attachments = [a for a in attachments if 0 < a[1] < len(segments)]
    data = line_data(segments, attachments, bed, friction)
    heading = rng.uniform(-math.pi, math.pi)
    e = (math.cos(heading), math.sin(heading))
    segs = ", ".join(f"({fmt(L)}, {fmt(w)}, {fmt(EA)})" for L, w, EA in segments)
    loads = [(j, size if kind == "ClumpWeight" else -size) for kind, j, size in attachments]
    atts = ", ".join(f"({j}, {fmt(P)})" for j, P in loads)
    fairlead = f"({fmt(span * e[0])}, {fmt(span * e[1])}, {fmt(dh)})"
    expr = (
        f"mooring.solve_line_bvp_3d((0.0, 0.0, 0.0), {fairlead}, [{segs}], attachments=[{atts}], "
        f"seabed={fmt(bed)}, friction={fmt(friction)})"
    )

    def check(result, caught):
        H, V = math.hypot(*result.force_on_fairlead[:2]), -result.force_on_fairlead[2]
        try:
            want = segments_line(data, span, dh, {"H": H, "V": V} if H > 0 else None)
        except OutOfScope as why:
            raise NoRoot(f"outside the walk's model ({why}): unchecked") from None
        force = float(want["H"] + data.weight + sum(abs(p) for p in data.P))
        warned = any(issubclass(w.category, ResolutionWarning) for w in caught)
        tol = (5e-2 if warned else 1e-6) * force
        F_b, F_a = result.force_on_fairlead, result.force_on_anchor
        out = [
            close("force_on_fairlead along", -(F_b[0] * e[0] + F_b[1] * e[1]), want["H"], tol),
            close("force_on_fairlead across", F_b[1] * e[0] - F_b[0] * e[1], 0.0, 1e-9 * force),
            close("force_on_fairlead[2]", -F_b[2], want["V_B"], tol),
            close("force_on_anchor along", F_a[0] * e[0] + F_a[1] * e[1], want["H_A"], tol),
        ]
        return [o for o in out if o]

    names = BVP_NAMES | {"anchor", "fairlead", "attachments"}
    return Case(
        "solve_line_bvp_3d", expr, names, check, _bvp_judge(data, span, dh, expr, check), timeout=60.0
    )


REGIMES["solve_line_bvp"] = line_bvp
REGIMES["solve_line_bvp/auto"] = line_bvp_auto
REGIMES["solve_line_bvp_3d"] = line_bvp_3d
