r"""The parts of a mooring system and its unknowns: points, line handles, the dofs of bodies and points.

A system (`skcable.mooring.MooringSystem`) holds bodies, points and lines:

- a **fixed** point (an anchor) stays where it is given;
- a **free** point has three dofs, its position (m), and its own constant load: its weight
  ``m g`` down, its buoyancy ``rho g V`` up and a given force (a clump weight, a buoy, a
  junction of a bridle);
- a point **on a body** is fixed in the body's axes (relative to the body's reference point)
  and moves with it; its own load acts on the body there;
- a **line** connects any two points, in any order.

The unknowns ``q`` are the dofs of every body (6 of a `RigidBody`: position and roll, pitch,
yaw; 3 of a `PointBody`), then three of every free point. `Layout` maps them: where each body's
and free point's dofs start, the bodies' points in body axes, the fixed points; the positions at
``q`` are formed by `skcable.mooring.net_loads.Assembler` (vectorised over the bodies).
"""

from __future__ import annotations

import numpy as np

from skcable._checks import nonnegative, scalar
from skcable.errors import InputError
from skcable.mooring.body import PointBody, RigidBody
from skcable.mooring.line3d import point

__all__ = ["Layout", "MooringLine", "MooringPoint", "end_forces", "largest_end_tension"]


class MooringPoint:
    """A point of a mooring system (`MooringSystem.add_point`).

    Attributes
    ----------
    index : int
        Its number in the system.
    position : ndarray, shape (3,)
        Where it is given (m): global axes, or body axes for a point on a body.
    fixed : bool
        An anchor: it does not move.
    body : RigidBody, PointBody or None
        The body it is fixed to.
    mass, volume : float
        Its mass (kg) and displaced volume (m^3).
    force : ndarray, shape (3,)
        A constant force on it (N), global axes.
    own_force : ndarray, shape (3,)
        ``(0, 0, -m g + rho g V) + force`` (N).
    """

    def __init__(self, index, position, fixed, mass, volume, force, body, rho, g):
        self.index, self.fixed, self.body = index, bool(fixed), body
        self.position = point("position", position)
        self.mass = scalar("mass", nonnegative("mass", mass))
        self.volume = scalar("volume", nonnegative("volume", volume))
        self.force = point("force", force)
        rho, g = scalar("rho", nonnegative("rho", rho)), scalar("g", nonnegative("g", g))
        self.own_force = self.force + np.array([0.0, 0.0, rho * g * self.volume - self.mass * g])

    @property
    def kind(self) -> str:
        """``"fixed"``, ``"body"`` or ``"free"``."""
        return "fixed" if self.fixed else ("body" if self.body is not None else "free")

    def __repr__(self):
        where = f", body={type(self.body).__name__}" if self.body is not None else ""
        return f"MooringPoint({self.index}, {self.kind}, position={self.position.tolist()}{where})"


class MooringLine:
    """A line of a mooring system (`MooringSystem.add_line`): its model and its ends.

    Attributes
    ----------
    index : int
        Its number in the system.
    model : object
        A `skcable.mooring.Line` (solved over the system's seabed, either end higher:
        `skcable.mooring.line_between`) or another line model (``solve(span, dh)``, solved as
        given with ``a`` its anchor A: `skcable.mooring.line_3d`).
    a, b : MooringPoint
        Its ends, in the order of the model's segments.
    managed : bool
        Whether the system picks the line's model over the seabed (a `skcable.mooring.Line`).
    warm : bool
        Whether its model takes the previous solution as its start (``solve(..., start=)``).
    sea : tuple or None
        A line in the sea (a `skcable.mooring.Line` in a current, on a `Bathymetry` or with a
        nonlinear axial law, `skcable.mooring.sea_line`): ``(placed, reverse)``, the line
        solved from its fixed end (`skcable.mooring.sea_line.placed_line`) and whether that
        end is b; None otherwise.
    """

    def __init__(self, index, model, a, b, managed, warm=True, sea=None):
        self.index, self.model, self.a, self.b, self.managed = index, model, a, b, managed
        self.warm, self.sea = warm, sea

    def __repr__(self):
        model = type(self.model).__name__
        return f"MooringLine({self.index}, a={self.a.index}, b={self.b.index}, model={model})"


class Layout:
    """The dofs of a system: where each body's and free point's dofs start, the points' positions,
    the arms of the bodies' points (module docstring). Built once per set of bodies and points."""

    def __init__(self, bodies, points):
        self.bodies, self.points = list(bodies), list(points)
        start, self.body_start = 0, []
        for body in self.bodies:
            self.body_start.append(start)
            start += body.n_dof
        self.point_start = {}
        for p in self.points:
            if p.kind == "free":
                self.point_start[p.index] = start
                start += 3
        self.n_dof = start
        self.units = None  # the dofs' consistent units (`MooringSystem.dof_units`), once asked
        # per body: its points (indices) and their positions in body axes
        self.body_points = [[p.index for p in self.points if p.body is b] for b in self.bodies]
        self.local = [
            np.array([self.points[j].position for j in idx]).reshape(-1, 3) for idx in self.body_points
        ]
        fixed = np.array([p.position if p.kind == "fixed" else np.zeros(3) for p in self.points]).reshape(
            -1, 3
        )
        self.fixed_positions = fixed
        self.free = np.array([j for j, p in enumerate(self.points) if p.kind == "free"], dtype=int)
        self.free_starts = np.array([self.point_start[j] for j in self.free], dtype=int)

    def body_q(self, q, i):
        s = self.body_start[i]
        return q[s : s + self.bodies[i].n_dof]

    def initial(self, body_positions) -> np.ndarray:
        """The dof vector of the bodies at ``body_positions`` and the free points where given."""
        q = np.zeros(self.n_dof)
        for i, qb in enumerate(body_positions):
            q[self.body_start[i] : self.body_start[i] + len(qb)] = qb
        for j, s in zip(self.free, self.free_starts, strict=True):
            q[s : s + 3] = self.points[j].position
        return q

    def rate_map(self, q) -> np.ndarray:
        """``∂(displacements, rotation vectors)/∂q``: each body's `rate_map`, identity on points."""
        return self.times_rate_map(np.eye(self.n_dof), q)

    def times_rate_map(self, K, q) -> np.ndarray:
        """``K @ rate_map(q)`` block by block: each body's columns times its `rate_map`, the free
        points' columns as they are."""
        out = np.array(K, dtype=float)
        for i, body in enumerate(self.bodies):
            s, n = self.body_start[i], body.n_dof
            out[:, s : s + n] = K[:, s : s + n] @ body.rate_map(self.body_q(q, i))
        return out

    def rotation_dofs(self) -> np.ndarray:
        """Indices of the rotation dofs (roll, pitch, yaw of each rigid body)."""
        out = [
            np.arange(s + 3, s + 6) for s, b in zip(self.body_start, self.bodies, strict=True) if b.n_dof == 6
        ]
        return np.concatenate(out) if out else np.zeros(0, dtype=int)

    def describe(self, k: int) -> str:
        """The dof ``k`` in words (``"body 0 surge"``, ``"point 3 z"``)."""
        names = ("surge", "sway", "heave", "roll", "pitch", "yaw")
        for i, s in enumerate(self.body_start):
            if s <= k < s + self.bodies[i].n_dof:
                return f"body {i} {names[k - s]}"
        for j, s in self.point_start.items():
            if s <= k < s + 3:
                return f"point {j} {'xyz'[k - s]}"
        raise InputError("k", f"no dof {k}")


def check_body(body):
    """``body`` if it is a `RigidBody` or `PointBody`, else `InputError` naming ``body``."""
    if not isinstance(body, (RigidBody, PointBody)):
        raise InputError("body", f"must be a RigidBody or a PointBody, got {type(body).__name__}")
    return body


def end_forces(line) -> np.ndarray:
    """The forces (2, 3) of a solved line on its ends a and b (N, global axes): its
    ``end_forces``, or a one-body shortcut's line's ``force_on_anchor`` and ``force_on_fairlead``."""
    ends = getattr(line, "end_forces", None)
    return np.asarray(
        ends if ends is not None else [line.force_on_anchor, line.force_on_fairlead], dtype=float
    )


def largest_end_tension(line) -> float:
    """The larger of the tensions at the ends of a solved line (N): the norms of its `end_forces`."""
    return float(np.linalg.norm(end_forces(line), axis=1).max())
