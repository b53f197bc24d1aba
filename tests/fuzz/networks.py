"""Multi-body mooring networks (issue 31): 2-3 point bodies at the surface, 12-18 chains, some
shared between two bodies, some through a free point; an independent recount of the balance.

`network(seed)` builds a seeded scene; `recount(system, eq, loads)` re-solves every line at the
returned positions by the seabed closed form (`skcable.cable.elastic_catenary`, not the
system's line solves) and sums, at every body and free point, the lines' forces, the bodies'
own loads written here (weight, buoyancy, the waterplane's heave restoring) and the external
force: the net force left, over the largest force there (a line's tension, the body's weight,
buoyancy or external force), the scale of the equilibrium's own tolerance
(`skcable.mooring.MooringSystem.equilibrium`'s ``tol``: net forces over the largest of the line
tensions, weights, buoyancies and external forces). Over the line tensions alone, a body of
4000 t whose net force met that tolerance (1.5e-3 N) was 1.3e-8 of its lines' tension, which the
long run counted as wrong (seed 47, its case 66).
"""

from __future__ import annotations

import math

import numpy as np

from skcable import cable, mooring
from tests.fuzz.harness import Case

__all__ = ["REGIMES", "network", "recount", "solve"]

RHO, G = 1025.0, 9.81


def _chain(rng, length):
    return mooring.Line(
        [mooring.Segment(length, float(rng.uniform(500.0, 2500.0)), float(rng.uniform(5e8, 2e9)))]
    )


def network(seed: int, shared: bool = True, free: bool = True, buoyed: bool = True):
    """``(system, loads, data)``: a seeded network and the external force on each body; without
    the lines ``shared`` between bodies or the ``free`` points, if asked; a free point's buoy
    lifts it unless not ``buoyed`` (then it sinks towards the seabed, where a free point has no
    contact: no equilibrium, a search that stalls or runs out of its budget)."""
    rng = np.random.default_rng(seed)
    depth = float(rng.uniform(100.0, 300.0))
    system = mooring.MooringSystem(depth=depth)
    n_bodies = int(rng.integers(2, 4))
    n_lines = int(rng.integers(12, 19))
    bodies, centres, data = [], [], {"depth": depth, "bodies": []}
    for k in range(n_bodies):
        centre = np.array([350.0 * k, float(rng.uniform(-50.0, 50.0)), 0.0])
        volume = float(rng.uniform(2e3, 8e3))
        area = volume / float(rng.uniform(8.0, 15.0))  # an 8-15 m draft
        body = mooring.PointBody(mass=0.8 * RHO * volume, volume=volume, waterplane_area=area)
        bodies.append(system.add_body(body, position=centre))
        centres.append(centre)
        data["bodies"].append((0.8 * RHO * volume, volume, area))
    attach = [system.add_point((0.0, 0.0, 0.0), body=b) for b in bodies]
    lines = 0
    for k in range(n_bodies - 1 if shared else 0):  # shared lines between neighbours
        span = float(np.linalg.norm(centres[k + 1] - centres[k]))
        system.add_line(_chain(rng, span * float(rng.uniform(1.01, 1.05))), attach[k], attach[k + 1])
        lines += 1
    n_free, free = 0, free
    while lines < n_lines:
        k = int(rng.integers(n_bodies))
        heading = float(rng.uniform(0.0, 2.0 * math.pi))
        radius = float(rng.uniform(2.5, 4.0)) * depth
        ring = np.array([math.cos(heading), math.sin(heading), 0.0])
        anchor = system.add_point(centres[k] + radius * ring - [0.0, 0.0, depth], fixed=True)
        reach = math.hypot(radius, depth)
        through = rng.uniform() < 0.3
        if free and through and lines + 2 <= n_lines:  # through a free point: a subsea buoy
            mid = centres[k] + 0.5 * radius * ring - [0.0, 0.0, 0.5 * depth]
            lower = _chain(rng, 0.55 * reach * float(rng.uniform(1.01, 1.05)))
            upper = _chain(rng, 0.5 * reach * float(rng.uniform(1.01, 1.05)))
            # a point with no lift sinks to the seabed, where a free point has no contact: its
            # buoy lifts 1.5 to 3 times the lines' weight (it floats between the two lines)
            hung = sum(seg.w * seg.length for line in (lower, upper) for seg in line.segments)
            lift = float(rng.uniform(1.5, 3.0)) * hung
            point = system.add_point(mid, volume=lift / (RHO * G) if buoyed else 0.0)
            system.add_line(lower, anchor, point)
            system.add_line(upper, point, attach[k])
            lines, n_free = lines + 2, n_free + 1
        else:
            system.add_line(_chain(rng, reach * float(rng.uniform(1.1, 1.4))), anchor, attach[k])
            lines += 1
    loads = {b: (float(rng.uniform(-1, 1)) * 5e4, float(rng.uniform(-1, 1)) * 5e4, 0.0) for b in bodies}
    data.update(n_bodies=n_bodies, n_lines=n_lines, free=n_free)
    return system, loads, data


def _line_forces(line, a, b, depth):
    """The forces (N, global axes) of one single-segment line on its ends ``a`` and ``b`` (m),
    by the seabed closed form solved from the lower end."""
    (seg,) = line.segments
    low, high, flip = (a, b, False) if a[2] <= b[2] else (b, a, True)
    d = high - low
    span = math.hypot(d[0], d[1])
    sol = cable.elastic_catenary(
        span, d[2], seg.w, seg.EA, length=seg.length, seabed=min(-depth - low[2], 0.0)
    )
    u = np.array([d[0], d[1], 0.0]) / span
    on_low = float(sol.H_A) * u + np.array([0.0, 0.0, -float(sol.V_A)])
    on_high = -float(sol.H) * u + np.array([0.0, 0.0, -float(sol.V_B)])
    return (on_high, on_low) if flip else (on_low, on_high)


def recount(system, eq, loads) -> float:
    """The largest net force left at a body or free point of ``eq`` over the largest force there,
    every line re-solved here (module docstring)."""
    P = {p.index: np.array(p.position, dtype=float) for p in eq.points}
    net: dict = {}
    scale: dict = {}
    for handle in eq.handles:
        fa, fb = _line_forces(handle.model, P[handle.a.index], P[handle.b.index], system.depth)
        for end, f in ((handle.a, fa), (handle.b, fb)):
            if end.kind == "fixed":
                continue
            key = ("body", id(end.body)) if end.kind == "body" else ("point", end.index)
            net[key] = net.get(key, np.zeros(3)) + f
            scale[key] = max(scale.get(key, 0.0), float(np.linalg.norm(f)))
    for state in eq.bodies:
        body = state.body
        own = np.array(
            [
                0.0,
                0.0,
                RHO * G * body.volume - body.mass * G - RHO * G * body.waterplane_area * state.offset[2],
            ]
        )
        key = ("body", id(body))
        external = np.asarray(loads.get(body, (0.0, 0.0, 0.0)))
        net[key] = net[key] + own + external
        own_forces = (RHO * G * body.volume, body.mass * G, float(np.linalg.norm(external)))
        scale[key] = max(scale[key], *own_forces)
    for point in eq.points:
        if point.kind == "free":
            key = ("point", point.index)
            net[key] = net[key] + np.array([0.0, 0.0, (RHO * point.point.volume - point.point.mass) * G])
            scale[key] = max(scale[key], RHO * point.point.volume * G, point.point.mass * G)
    return max(float(np.linalg.norm(net[k])) / max(scale[k], 1.0) for k in net)


#: The time budget of a network's equilibrium in the fuzz (s); the harness's own limit is above it.
BUDGET = 5.0


def solve(seed: int, shared: bool = True, free: bool = True, buoyed: bool = True, time_limit: float = BUDGET):
    """``(system, eq, loads)``: the equilibrium of `network`'s scene under its time budget."""
    system, loads, _ = network(seed, shared, free, buoyed)
    return system, system.equilibrium(force=loads, time_limit=time_limit), loads


def network_case(rng) -> Case:
    """A `Case` of `tests.fuzz.harness`: a network's equilibrium within `BUDGET` seconds (the
    harness's time limit, 30 s, makes a search that ignores its budget a hang), an answer
    balanced at every body and free point by `recount`; a `ConvergenceError` is an honest
    refusal (no independent solver judges it)."""
    seed, free, buoyed = int(rng.integers(2**31)), bool(rng.uniform() < 0.8), bool(rng.uniform() < 0.8)

    def check(result, caught):
        system, eq, loads = result
        left = recount(system, eq, loads)
        return [] if left < 1e-8 else [f"recounted net force {left:.3g} of the largest force there"]

    expr = f"__import__('tests.fuzz.networks', fromlist=['solve']).solve({seed}, True, {free}, {buoyed})"
    return Case("network", expr, frozenset({"force", "time_limit", "start"}), check, timeout=BUDGET + 25.0)


REGIMES = {"network": network_case}
