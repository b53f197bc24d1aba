"""Oracles of a moored body: the net force recounted line by line, its stiffness by central
differences, an independent equilibrium solver.

The body's own loads follow their statement in MoorPy's ``Body`` (M. Hall, NREL) and J.N.
Newman, "Marine Hydrodynamics", 1977, ch. 6: weight ``m g`` at the centre of gravity,
buoyancy ``rho g V`` at the metacentre, heave restoring ``-rho g A_WP z``; its attitude
``R = Rz(yaw) Ry(pitch) Rx(roll)``. Each line is solved in its vertical plane by the walk of
`tests.fuzz.segments` at 50 digits, its force on the fairlead ``(-H e, -V_B)``. Nothing here
calls skcable.
"""

from __future__ import annotations

import mpmath
import numpy as np
from mpmath import mp, mpf

from tests.fuzz.mp import NoRoot
from tests.fuzz.segments import segments_line

__all__ = ["Scene", "rotation", "recount", "fd_stiffness", "eigenvalues", "equilibrium"]

DPS = 40


class Scene:
    """A moored body: ``kind`` ("rigid" or "point"), ``fairleads`` (body axes), ``anchors``,
    ``lines`` (`tests.fuzz.segments.LineData`, one per anchor), ``mass, volume, cog, meta,
    area, rho, g``, the external ``force`` and ``moment``."""

    def __init__(
        self, kind, fairleads, anchors, lines, *, mass, volume, cog, meta, area, rho, g, force, moment
    ):
        self.kind, self.lines = kind, lines
        self.fairleads = [[mpf(v) for v in f] for f in fairleads]
        self.anchors = [[mpf(v) for v in a] for a in anchors]
        self.mass, self.volume, self.area, self.rho, self.g = (mpf(v) for v in (mass, volume, area, rho, g))
        self.cog, self.meta = [mpf(v) for v in cog], [mpf(v) for v in meta]
        self.force, self.moment = [mpf(v) for v in force], [mpf(v) for v in moment]
        self.n_dof = 6 if kind == "rigid" else 3
        self.cache = [None] * len(lines)  # each line's last root: the next solve's start
        self.arm = max([mpf(1)] + [abs(v) for f in self.fairleads for v in f]) if kind == "rigid" else mpf(1)


def _mat(rows):
    return mpmath.matrix(rows)


def rotation(roll, pitch, yaw):
    """``Rz(yaw) Ry(pitch) Rx(roll)``."""
    c, s = mpmath.cos, mpmath.sin
    Rx = _mat([[1, 0, 0], [0, c(roll), -s(roll)], [0, s(roll), c(roll)]])
    Ry = _mat([[c(pitch), 0, s(pitch)], [0, 1, 0], [-s(pitch), 0, c(pitch)]])
    Rz = _mat([[c(yaw), -s(yaw), 0], [s(yaw), c(yaw), 0], [0, 0, 1]])
    return Rz * Ry * Rx


def _rotvec(theta):
    """Rodrigues: the rotation by the vector ``theta`` (rad)."""
    angle = mpmath.sqrt(sum(t * t for t in theta))
    if angle == 0:
        return mpmath.eye(3)
    k = [t / angle for t in theta]
    Kx = _mat([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return mpmath.eye(3) + mpmath.sin(angle) * Kx + (1 - mpmath.cos(angle)) * Kx * Kx


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _apply(R, v):
    return [sum(R[i, j] * v[j] for j in range(3)) for i in range(3)]


def line_forces(scene, x, R, remember=True):
    """Each line's force on its fairlead (global axes) and arm, at reference point ``x``,
    attitude ``R``; the 2-D solutions (dicts of the walk)."""
    forces, arms, sols = [], [], []
    for i, (line, anchor) in enumerate(zip(scene.lines, scene.anchors, strict=True)):
        arm = _apply(R, scene.fairleads[i]) if scene.kind == "rigid" else [mpf(0)] * 3
        b = [x[k] + arm[k] for k in range(3)]
        d = [b[k] - anchor[k] for k in range(3)]
        r = mpmath.hypot(d[0], d[1])
        base = scene.cache[i]
        start = None if base is None or not base["H"] > 0 else {"H": base["H"], "V": base["V"]}
        sol = segments_line(line, r, d[2], start)
        if remember:
            scene.cache[i] = sol
        forces.append([-sol["H"] * d[0] / r, -sol["H"] * d[1] / r, -sol["V_B"]])
        arms.append(arm)
        sols.append(sol)
    return forces, arms, sols


def recount(scene, x, R, remember=True):
    """The net force (and moment about the reference point) on the body at ``x``, ``R``:
    lines, own loads, external load; and the line solutions."""
    with mp.workdps(DPS):
        forces, arms, sols = line_forces(scene, x, R, remember)
        G = [sum(f[k] for f in forces) + scene.force[k] for k in range(3)]
        W, B = scene.mass * scene.g, scene.rho * scene.g * scene.volume
        G[2] += B - W - scene.rho * scene.g * scene.area * x[2]
        if scene.kind == "point":
            return G, sols
        M = [scene.moment[k] for k in range(3)]
        for f, arm in zip(forces, arms, strict=True):
            M = [M[k] + c for k, c in enumerate(_cross(arm, f))]
        M = [M[k] + c for k, c in enumerate(_cross(_apply(R, scene.cog), [0, 0, -W]))]
        M = [M[k] + c for k, c in enumerate(_cross(_apply(R, scene.meta), [0, 0, B]))]
        return G + M, sols


def at(scene, q):
    """``(x, R)`` of a position ``q`` (x, y, z, roll, pitch, yaw) or (x, y, z)."""
    q = [mpf(v) for v in q]
    R = rotation(q[3], q[4], q[5]) if scene.kind == "rigid" else mpmath.eye(3)
    return q[:3], R


def fd_stiffness(scene, q, rel="1e-12"):
    """``K = -∂G/∂(x, rotation vector)`` by central differences (rotations about global axes
    applied to the attitude), at `DPS` digits."""
    with mp.workdps(DPS):
        x, R = at(scene, q)
        n = scene.n_dof
        K = mpmath.matrix(n, n)
        hx = mpf(rel) * max(mpf(1), max(abs(v) for a in scene.anchors for v in a))
        hr = mpf(rel)
        for j in range(n):
            pair = []
            for sign in (1, -1):
                if j < 3:
                    xs = list(x)
                    xs[j] += sign * hx
                    pair.append(recount(scene, xs, R, remember=False)[0])
                else:
                    theta = [mpf(0)] * 3
                    theta[j - 3] = sign * hr
                    pair.append(recount(scene, x, _rotvec(theta) * R, remember=False)[0])
            h = hx if j < 3 else hr
            for i in range(n):
                K[i, j] = -(pair[0][i] - pair[1][i]) / (2 * h)
        return K


def eigenvalues(scene, K):
    """Eigenvalues of the symmetric part of ``K`` in consistent units (rotations times the
    largest arm), ascending, as floats."""
    n = scene.n_dof
    units = [1.0] * 3 + [float(scene.arm)] * (n - 3)
    A = np.array([[float(K[i, j]) / units[i] / units[j] for j in range(n)] for i in range(n)])
    return np.linalg.eigvalsh(0.5 * (A + A.T))


def force_scale(scene, sols):
    """The scale of the net force: the largest fairlead tension, weight, buoyancy, external force."""
    tensions = [mpmath.hypot(s["H"], s["V_B"]) for s in sols]
    own = [scene.mass * scene.g, scene.rho * scene.g * scene.volume, mpmath.norm(scene.force)]
    return float(max(tensions + own + [mpf("1e-300")]))


def equilibrium(scene, starts, tol=1e-9):
    """An equilibrium found by MINPACK's hybrid method on the recounted net force from each of
    ``starts`` in turn (the oracle's own solver): ``(q, G, scale)``, or `NoRoot`."""
    from scipy.optimize import root

    def residual(q):
        try:
            G, sols = recount(scene, *at(scene, q))
        except NoRoot:
            return np.full(scene.n_dof, 1e3)
        scale = force_scale(scene, sols)
        g = np.array([float(v) for v in G]) / scale
        g[3:] /= float(scene.arm)
        return g

    for start in starts:
        scene.cache = [None] * len(scene.lines)
        sol = root(residual, np.asarray(start, dtype=float), method="hybr", options={"xtol": 1e-13})
        g = residual(sol.x)
        if np.all(np.isfinite(g)) and np.max(np.abs(g)) < tol:
            return sol.x, g
    raise NoRoot("no equilibrium from the oracle's starts")
