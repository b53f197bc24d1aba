"""Regimes of moored bodies: `MooringSystem.equilibrium` (balance recounted, stiffness by
central differences, stability from the eigenvalues, a refusal judged by an independent
solver), its invariance under a turn about the vertical and a mirror, and the net force and
stiffness at a given position.
"""

from __future__ import annotations

import math

import numpy as np
from mpmath import mp

from tests.fuzz import bodies
from tests.fuzz.compare import compare_matrix, fmt
from tests.fuzz.harness import Case
from tests.fuzz.mp import NoRoot
from tests.fuzz.multi import line_data, line_expr
from tests.fuzz.scenes import log_uniform, pick
from tests.fuzz.segments import segments_line

__all__ = ["REGIMES"]

NAMES = frozenset(
    {
        "body",
        "lines",
        "anchors",
        "depth",
        "force",
        "moment",
        "start",
        "tol",
        "max_iter",
        "fairleads",
        "mass",
        "volume",
        "center_of_gravity",
        "metacentre",
        "waterplane_area",
        "rho",
        "g",
        "position",
        "segments",
        "attachments",
        "seabed",
        "friction",
        "span",
        "dh",
        "model",
        "fairlead",
        "anchor",
    }
)


def _vec(v) -> str:
    return "(" + ", ".join(fmt(x) for x in v) + ")"


def random_scene(rng):
    """A body on 1-6 lines from anchors on the seabed: geometry, lines, body, loads (dict)."""
    depth = log_uniform(rng, 5.0, 2000.0)
    n = int(pick(rng, [1, 2, 3, 3, 3, 4, 4, 6])) if rng.uniform() < 0.1 else int(pick(rng, [3, 3, 4, 6]))
    radius = depth * rng.uniform(1.5, 8.0)
    r_f = depth * log_uniform(rng, 5e-3, 0.1)
    z_f = -depth * rng.uniform(0.0, 0.05)
    spread = 2 * math.pi / n
    headings = [i * spread + rng.uniform(-0.3, 0.3) * spread for i in range(n)]
    fairleads = [(r_f * math.cos(h), r_f * math.sin(h), z_f) for h in headings]
    anchors = [(radius * math.cos(h), radius * math.sin(h), -depth) for h in headings]
    w = log_uniform(rng, 50.0, 3000.0)
    chord = math.hypot(radius - r_f, depth + z_f)
    L = pick(
        rng, [chord * (1 + log_uniform(rng, 1e-4, 2e-2)), (radius - r_f + depth) * rng.uniform(0.8, 1.08)]
    )
    if rng.uniform() < 0.25:  # chain, wire, chain with a clump
        a, b = rng.uniform(0.1, 0.4), rng.uniform(0.1, 0.4)
        segments = [(L * a, w, w * L * 1e5), (L * (1 - a - b), w * 0.1, w * L * 5e4), (L * b, w, w * L * 1e5)]
        attachments = [("ClumpWeight", 1, w * L * rng.uniform(0.01, 0.2))]
    else:
        segments, attachments = [(L, w, w * L * log_uniform(rng, 1e3, 1e6))], []
    weight = n * w * L
    rho, g = 1025.0, 9.81
    kind = "rigid" if rng.uniform() < 0.75 else "point"
    if rng.uniform() < 0.15:  # a wild body: any buoyancy, any waterplane
        volume = log_uniform(rng, 0.5, 5.0) * weight / (rho * g)
        mass = max(rho * volume - weight / g * rng.uniform(0.2, 1.0), 0.0)
        area = 0.0 if rng.uniform() < 0.3 else math.pi * r_f**2 * log_uniform(rng, 0.05, 2.0)
    else:  # floating near its waterline: net buoyancy about the lines' pull, heave within ~depth/20
        data = line_data(segments, attachments, 0.0, 0.0)
        pull = 0.0
        for f, a in zip(fairleads, anchors, strict=True):
            try:
                pull += float(segments_line(data, math.hypot(f[0] - a[0], f[1] - a[1]), f[2] - a[2])["V_B"])
            except NoRoot:
                pull += w * L
        volume = log_uniform(rng, 1.5, 6.0) * pull / (rho * g)
        mass = rho * volume - pull * rng.uniform(0.9, 1.1) / g
        area = pull * log_uniform(rng, 0.2, 5.0) / (rho * g * 0.05 * depth)
    z_G = -r_f * rng.uniform(-0.5, 1.0)
    cog = (0.0, 0.0, z_G) if rng.uniform() < 0.7 else (r_f * rng.uniform(-0.2, 0.2), 0.0, z_G)
    meta = (0.0, 0.0, z_G + r_f * rng.uniform(-0.3, 2.0))
    heading = rng.uniform(-math.pi, math.pi)
    F = weight * pick(rng, [0.0, log_uniform(rng, 1e-3, 0.3)])
    force = (F * math.cos(heading), F * math.sin(heading), 0.0)
    moment = (
        (0.0, 0.0, 0.0)
        if kind == "point" or rng.uniform() < 0.5
        else (0.0, 0.0, F * r_f * rng.uniform(-1, 1))
    )
    return dict(
        kind=kind,
        fairleads=fairleads,
        anchors=anchors,
        segments=segments,
        attachments=attachments,
        mass=mass,
        volume=volume,
        cog=cog,
        meta=meta,
        area=area,
        rho=rho,
        g=g,
        force=force,
        moment=moment,
        depth=depth,
    )


def turn(v, angle, mirror=False, pseudo=False):
    """``v`` mirrored in y (if ``mirror``; a pseudo-vector such as a moment also changes sign)
    and turned about z by ``angle``."""
    x, y, z = v
    if mirror:
        x, y, z = (-x, y, -z) if pseudo else (x, -y, z)
    c, s = math.cos(angle), math.sin(angle)
    return (c * x - s * y, s * x + c * y, z)


def _turned(scene, angle, mirror=False):
    """The scene turned about z by ``angle`` (and mirrored in y first)."""
    out = dict(scene)
    for key in ("fairleads", "anchors"):
        out[key] = [turn(v, angle, mirror) for v in scene[key]]
    for key in ("cog", "meta", "force"):
        out[key] = turn(scene[key], angle, mirror)
    out["moment"] = turn(scene["moment"], angle, mirror, pseudo=True)
    return out


def system_expr(sc) -> str:
    model = line_expr(sc["segments"], sc["attachments"], 0.0, 0.0)
    anchors = "[" + ", ".join(_vec(a) for a in sc["anchors"]) + "]"
    own = (
        f"mass={fmt(sc['mass'])}, volume={fmt(sc['volume'])}, waterplane_area={fmt(sc['area'])}, "
        f"rho={fmt(sc['rho'])}, g={fmt(sc['g'])}"
    )
    if sc["kind"] == "rigid":
        fl = "[" + ", ".join(_vec(f) for f in sc["fairleads"]) + "]"
        body = (
            f"mooring.RigidBody({fl}, {own}, center_of_gravity={_vec(sc['cog'])}, "
            f"metacentre={_vec(sc['meta'])})"
        )
    else:
        body = f"mooring.PointBody({own})"
    n = len(sc["anchors"])
    return f"(lambda line: mooring.MooringSystem({body}, [line] * {n}, {anchors}))({model})"


def oracle_scene(sc) -> bodies.Scene:
    data = line_data(sc["segments"], sc["attachments"], 0.0, 0.0)
    # each anchor's line: A on the seabed at the anchor (the walk measures from A)
    return bodies.Scene(
        sc["kind"],
        sc["fairleads"],
        sc["anchors"],
        [data] * len(sc["anchors"]),
        mass=sc["mass"],
        volume=sc["volume"],
        cog=sc["cog"],
        meta=sc["meta"],
        area=sc["area"],
        rho=sc["rho"],
        g=sc["g"],
        force=sc["force"],
        moment=sc["moment"],
    )


def _eq_call(sc) -> str:
    load = f"force={_vec(sc['force'])}" + (f", moment={_vec(sc['moment'])}" if sc["kind"] == "rigid" else "")
    return f"{system_expr(sc)}.equilibrium({load})"


def _recounted(scene, q):
    """``(G, sols, scale, sizes)``: the oracle's net load at the dofs ``q``, its line solutions, its
    force scale and each dof's size (the scale, times the arm for a moment); inside
    ``mp.workdps(bodies.DPS)``."""
    G, sols = bodies.recount(scene, *bodies.at(scene, q))
    scale = bodies.force_scale(scene, sols)
    return G, sols, scale, [scale * (float(scene.arm) if i >= 3 else 1.0) for i in range(len(G))]


def check_equilibrium(eq, sc, caught) -> tuple[list[str], object, float]:
    """Balance, fairlead forces, stiffness and stability of ``eq`` against the recount."""
    scene = oracle_scene(sc)
    q = [float(v) for v in eq.position]
    with mp.workdps(bodies.DPS):
        G, sols, scale, sizes = _recounted(scene, q)
        problems = []
        for i, (value, size) in enumerate(zip(G, sizes, strict=True)):
            if abs(float(value)) > 1e-8 * size:
                problems.append(
                    f"balance: recounted net load[{i}] = {float(value):.6g} at the returned position "
                    f"(scale {size:.3g})"
                )
        for i, sol in enumerate(sols):
            for name in ("H", "V_B"):
                got = eq.lines[i].H if name == "H" else eq.lines[i].V_B
                if abs(got - float(sol[name])) > 1e-9 * scale:
                    problems.append(f"line {i} {name}: oracle {float(sol[name]):.17g}, skcable {got!r}")
        if problems:
            return problems, None, scale
        K = bodies.fd_stiffness(scene, q)
    problem = compare_matrix("stiffness()", eq.stiffness(), K, 1e-6)
    problems += [problem] if problem else []
    lam = bodies.eigenvalues(scene, K)
    stable = bool(lam[0] >= -1e-8 * np.abs(lam).max())
    if stable != bool(eq.positive_definite) and abs(lam[0]) > 1e-6 * np.abs(lam).max():
        problems.append(
            f"positive_definite: oracle {stable} (eigenvalues {lam.tolist()}), skcable {eq.positive_definite}"
        )
    if not eq.positive_definite and not any("unstable" in str(w.message) for w in caught):
        problems.append("an unstable equilibrium returned without a warning")
    return problems, lam, scale


def _judge(sc):
    def judge(exc):
        scene = oracle_scene(sc)
        n = scene.n_dof
        starts = [np.zeros(n)]
        F = np.array(sc["force"])
        direction = F / np.linalg.norm(F) if np.linalg.norm(F) > 0 else np.array([1.0, 0.0, 0.0])
        radius = float(np.hypot(*np.array(sc["anchors"])[0, :2]))
        for frac in (0.01, 0.05, 0.15):
            start = np.zeros(n)
            start[:3] = direction * frac * radius
            starts.append(start)
        q, g = bodies.equilibrium(scene, starts)
        K = bodies.fd_stiffness(scene, q)
        lam = bodies.eigenvalues(scene, K)
        if lam[0] > 1e-9 * np.abs(lam).max():  # strictly: a neutral direction is no isolated equilibrium
            return (
                f"a stable equilibrium at {np.round(q, 9).tolist()} (scaled residual {np.abs(g).max():.2g})"
            )
        return None

    return judge


def mooring(rng) -> Case:
    """`MooringSystem.equilibrium` against the recount (balance, stiffness, stability)."""
    return mooring_case(random_scene(rng))


def mooring_case(sc) -> Case:
    """The case of `MooringSystem.equilibrium` on a scene of `random_scene`'s form."""

    def check(eq, caught):
        return check_equilibrium(eq, sc, caught)[0]

    return Case("mooring", _eq_call(sc), NAMES, check, _judge(sc), timeout=60.0)


def mooring_turned(rng, mirror=False) -> Case:
    """The same scene turned about z (or mirrored in y and turned): the equilibrium turns with it."""
    sc = random_scene(rng)
    angle = rng.uniform(-math.pi, math.pi)
    other = _turned(sc, angle, mirror)
    expr = f"({_eq_call(sc)}, {_eq_call(other)})"

    def check(result, caught):
        first, second = result
        problems, lam, force = check_equilibrium(first, sc, caught)
        if problems or not first.stable or not second.stable:
            return problems
        want = np.array(turn(first.offset.tolist(), angle, mirror))
        scale = max(1.0, float(np.abs(np.array(sc["anchors"])).max()))
        soft = 1e-8 * force / max(float(lam[0]), 1e-300)
        allowed = 1e-9 * scale + soft
        if (
            np.abs(second.offset - want).max() > allowed
            or abs(second.heel - first.heel) > allowed / scale + 1e-9
        ):
            problems.append(
                f"{'mirrored and ' if mirror else ''}turned by {angle:.6g} rad: offset "
                f"{second.offset.tolist()}, heel {second.heel!r}; expected {want.tolist()}, "
                f"heel {first.heel!r} (allowed {allowed:.3g} m)"
            )
        return problems

    regime = "mooring/mirror" if mirror else "mooring/turned"
    return Case(regime, expr, NAMES, check, _judge(sc), timeout=120.0, calls=2)


def mooring_at(rng) -> Case:
    """`MooringSystem.net_force` and `stiffness` at a given position against the recount."""
    sc = random_scene(rng)
    n = 6 if sc["kind"] == "rigid" else 3
    radius = float(np.hypot(*np.array(sc["anchors"])[0, :2]))
    q = [rng.uniform(-0.1, 0.1) * radius, rng.uniform(-0.1, 0.1) * radius, rng.uniform(-0.02, 0.02) * radius]
    q += [rng.uniform(-0.2, 0.2) for _ in range(n - 3)]
    system = system_expr(sc)
    load = f"force={_vec(sc['force'])}" + (f", moment={_vec(sc['moment'])}" if sc["kind"] == "rigid" else "")
    expr = f"(lambda s: (s.net_force({_vec(q)}, {load}), s.stiffness({_vec(q)})))({system})"

    def check(result, caught):
        G_got, K_got = result
        scene = oracle_scene(sc)
        with mp.workdps(bodies.DPS):
            G, _, _, sizes = _recounted(scene, q)
            problems = []
            for i, (value, size) in enumerate(zip(G, sizes, strict=True)):
                if abs(G_got[i] - float(value)) > 1e-9 * size:
                    problems.append(f"net_force[{i}]: oracle {float(value):.17g}, skcable {G_got[i]!r}")
            K = bodies.fd_stiffness(scene, q)
        problem = compare_matrix("stiffness()", K_got, K, 1e-6)
        return problems + ([problem] if problem else [])

    return Case("mooring/at", expr, NAMES, check, None, timeout=60.0, calls=2)


REGIMES = {
    "mooring": mooring,
    "mooring/turned": mooring_turned,
    "mooring/mirror": lambda rng: mooring_turned(rng, mirror=True),
    "mooring/at": mooring_at,
}
