r"""A mooring system: bodies, points and lines, their net loads and stiffness.

Points are fixed (anchors), free (three dofs, with their own weight, buoyancy and force) or
fixed to a body; lines connect any two points (`skcable.mooring.network`), each solved by the
model its position takes (`MooringSystem.add_line`, `skcable.mooring.choice`). The one-body
constructor ``MooringSystem(body, lines, anchors)`` builds such a system: one body, an anchor per
line, the fairleads on the body, each line solved as given.

At the dofs :math:`\mathbf q` (bodies, then free points) the net generalised force is

.. math:: \mathbf G(\mathbf q) = \sum_{\text{line ends } e} T_e^T\,\mathbf f_e
    + \sum_{\text{points}} T_p^T\,\mathbf f_p + \sum_{\text{bodies}}\mathbf G_\text{own}
    + \mathbf G_\text{ext},

:math:`\mathbf f_e` a line's force on its end, :math:`\mathbf f_p` a point's own load and
:math:`T` the map of the dofs to a point's displacement: the identity for a free point,
:math:`[I, -[\mathbf r]_\times]` for a body's point at arm :math:`\mathbf r` (so that
:math:`T^T\mathbf f = (\mathbf f, \mathbf r\times\mathbf f)`). The stiffness
:math:`K = -\partial\mathbf G/\partial(\mathbf x, \delta\boldsymbol\theta)` (translations and small
rotation vectors about global axes, as MoorPy's ``getStiffnessA``, M. Hall, NREL) is assembled
from each line's end stiffness :math:`K_{ij} = -\partial\mathbf f_i/\partial\mathbf p_j`:

.. math:: K = \sum_{\text{lines}}\sum_{i, j} T_i^T K_{ij} T_j
    - \sum_{\text{body ends}} [\mathbf f_e]_\times[\mathbf r_e]_\times + K_\text{own},

the term :math:`-[\mathbf f]_\times[\mathbf r]_\times` from the arm turning under a force (it
makes ``K`` unsymmetric where the forces have a net moment). A body's own ends and own loads are
summed vectorised over the bodies (`skcable.mooring.net_loads`); the coupling of two moving ends of
one line (a shared line, a bridle) is added block by block. The equilibrium ``G = 0`` is solved by
`skcable.mooring.equilibrium`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, one_of, positive, real, scalar
from skcable.errors import InputError
from skcable.mooring import failure
from skcable.mooring.between_points import LineBetween
from skcable.mooring.body import PointBody, RigidBody, skew
from skcable.mooring.choice import (
    BATCH,
    is_line,
    on_seabed_tolerance,
    solve_between,
    solve_line_in_sea,
    solve_many_between,
    solved_in_sea,
)
from skcable.mooring.equilibrium import MooringEquilibrium, solve_equilibrium, warn_implausible
from skcable.mooring.line3d import (
    Line3D,
    line_3d,
    line_model,
    point,
    solve_in_plane_of_ends,
    solve_in_space,
    takes_start,
)
from skcable.mooring.net_loads import Assembler
from skcable.mooring.network import Layout, MooringLine, MooringPoint, check_body
from skcable.mooring.rod import RodBetween
from skcable.mooring.sea_line import LineInSeaBetween, placed_line

__all__ = ["MooringEquilibrium", "MooringSystem"]


def _line_list(lines) -> list:
    """``lines`` as a list of line models: a sequence of them (a list, a tuple), not one model,
    a string, a mapping or a scalar; else `InputError` naming ``lines``."""
    if callable(getattr(lines, "solve", None)):
        raise InputError("lines", "is one line model: give a list of them, one per anchor (e.g. [line] * 3)")
    if isinstance(lines, (str, bytes, Mapping)) or not isinstance(lines, Iterable):
        raise InputError(
            "lines", f"must be a list of line models, one per anchor, got {type(lines).__name__}"
        )
    return list(lines)


def _shortcut_parts(body, lines, anchors):
    """The checked arguments of the one-body constructor: ``(body, lines, anchors)``."""
    for name, value in (("body", body), ("lines", lines), ("anchors", anchors)):
        if value is None:
            raise InputError(
                name,
                "is missing: give body, lines and anchors together, or build the system with "
                "add_body, add_point and add_line",
            )
    check_body(body)
    lines = _line_list(lines)
    for i, model in enumerate(lines):
        if not callable(getattr(model, "solve", None)):
            raise InputError("lines", f"line {i} ({type(model).__name__}) has no solve(span, dh) method")
    if not lines:
        raise InputError("lines", "give at least one line")
    anchors = real("anchors", anchors)
    if np.shape(anchors) != (len(lines), 3):
        raise InputError(
            "anchors",
            f"must be one point (x, y, z) per line, shape ({len(lines)}, 3), got shape {np.shape(anchors)}",
        )
    if isinstance(body, RigidBody) and len(body.fairleads) != len(lines):
        raise InputError(
            "body", f"has {len(body.fairleads)} fairleads for {len(lines)} lines: give one per line"
        )
    return body, lines, np.array(anchors, dtype=float)


class MooringSystem:
    """Bodies, points and lines: a mooring system (module docstring).

    Build it with ``MooringSystem(depth=...)`` and `add_body`, `add_point`, `add_line`, or, for
    one body held by lines from fixed anchors, ``MooringSystem(body, lines, anchors)``.

    Parameters
    ----------
    body : RigidBody or PointBody, optional
        The one-body shortcut: the moored body; a `RigidBody` carries the fairleads (body
        axes), one per line, a `PointBody` takes every line at its point.
    lines : sequence of line models, optional
        The shortcut's lines, one per anchor: objects with ``solve(span, dh)`` (see
        `skcable.mooring.line3d`), each solved as given, anchor A at its anchor. A model
        whose ``solve`` also takes ``start=`` is warm-started in the equilibrium iterations.
    anchors : array_like, shape (n, 3), optional
        The shortcut's anchors in global axes (m), z up.
    depth : float, optional
        Water depth (m), > 0: the seabed is the plane z = -depth. The `skcable.mooring.Line`
        lines of `add_line` rest on it where they reach it; the shortcut's line models hold
        their own seabed (``depth`` then only draws it).
    rho, g : float, optional
        Water density (kg/m^3) and gravity (m/s^2) of the points' buoyancy and weight, >= 0
        (zero gravity: weightless lines, straight between their ends).

    Examples
    --------
    >>> from skcable import mooring
    >>> import numpy as np
    >>> angles = np.radians([0.0, 120.0, 240.0])
    >>> anchors = np.column_stack([800 * np.cos(angles), 800 * np.sin(angles), np.full(3, -200.0)])
    >>> fairleads = np.column_stack([20 * np.cos(angles), 20 * np.sin(angles), np.full(3, -10.0)])
    >>> chain = mooring.Line([mooring.Segment(850.0, 1000.0, 5e8)], seabed=0.0)
    >>> body = mooring.RigidBody(fairleads, waterplane_area=500.0)
    >>> system = mooring.MooringSystem(body, [chain] * 3, anchors)
    >>> eq = system.equilibrium(force=(1e5, 0.0, 0.0))
    >>> bool(eq.offset[0] > 0), bool(abs(eq.offset[1]) < 1e-6)
    (True, True)

    The same with `add_body`, `add_point` and `add_line`, the seabed the system's:

    >>> system = mooring.MooringSystem(depth=200.0)
    >>> hull = system.add_body(mooring.RigidBody(waterplane_area=500.0))
    >>> for anchor, fairlead in zip(anchors, fairleads):
    ...     a, b = system.add_point(anchor, fixed=True), system.add_point(fairlead, body=hull)
    ...     _ = system.add_line(chain, a, b)
    >>> eq2 = system.equilibrium(force=(1e5, 0.0, 0.0))
    >>> bool(np.allclose(eq2.bodies[0].position, eq.position, atol=1e-8))
    True
    """

    def __init__(self, body=None, lines=None, anchors=None, *, depth=None, rho=1025.0, g=9.81):
        self.depth = None if depth is None else scalar("depth", positive("depth", depth))
        self.rho, self.g = scalar("rho", nonnegative("rho", rho)), scalar("g", nonnegative("g", g))
        _plausible.gravity(self.g)
        self.bodies, self.points, self.mooring_lines = [], [], []
        self._body_positions, self._layout, self.shortcut = [], None, False
        self._pinned: list = []  # the pinned bodies (`add_body`)
        self._cold = None  # the lines last solved with no start: (layout, dofs, (line, model) pairs, lines)
        if body is None and lines is None and anchors is None:
            return
        body, lines, anchors = _shortcut_parts(body, lines, anchors)
        self._add_body(body, None)
        local = body.fairleads if isinstance(body, RigidBody) else np.zeros((len(lines), 3))
        for model, anchor, fairlead in zip(lines, anchors, local, strict=True):
            self._add_line(model, self.add_point(anchor, fixed=True), self._body_point(fairlead, body), False)
        self.shortcut = True

    # -- building ---------------------------------------------------------------------------------
    def _add_body(self, body, position):
        check_body(body)
        if any(b is body for b in self.bodies):
            raise InputError("body", "is already in this system: add each body once")
        q = np.zeros(body.n_dof) if position is None else body.check_position("position", position)
        self.bodies.append(body)
        self._body_positions.append(q)
        self._layout = None
        return body

    def add_body(self, body, *, position=None, pinned=False):
        """Add a `RigidBody` or `PointBody`; returns it. Attach points to it with ``add_point(...,
        body=body)``.

        ``position``: where its reference point starts, ``(x, y, z, roll, pitch, yaw)`` (m, rad) of
        a rigid body, ``(x, y, z)`` of a point body; default zeros. ``pinned``: a rigid body whose
        reference point is held where it starts, free to turn about it (a pin: MoorDyn's pinned
        rods and ``CoupledPinned`` bodies); its translations are no unknowns of the equilibrium."""
        check_body(body)
        if isinstance(body, RigidBody) and len(body.fairleads):
            raise InputError(
                "body",
                "has fairleads: in a system built point by point, attach them with "
                "add_point(position, body=body), in body axes",
            )
        if pinned and not isinstance(body, RigidBody):
            raise InputError("pinned", "a pinned body turns about its pin: give a RigidBody")
        self._add_body(body, position)
        if pinned:
            self._pinned.append(body)
        return body

    @property
    def held_dofs(self) -> np.ndarray:
        """The dofs held where they start: the translations of the pinned bodies (`add_body`)."""
        layout = self.layout
        held = [
            layout.body_start[i] + k
            for i, b in enumerate(self.bodies)
            if any(b is p for p in self._pinned)
            for k in range(3)
        ]
        return np.array(held, dtype=int)

    def _new_point(self, position, fixed, mass, volume, force, body):
        p = MooringPoint(len(self.points), position, fixed, mass, volume, force, body, self.rho, self.g)
        self.points.append(p)
        self._layout = None
        return p

    def _body_point(self, position, body):
        return self._new_point(position, False, 0.0, 0.0, (0.0, 0.0, 0.0), body)

    def add_point(self, position, fixed=False, mass=0.0, volume=0.0, force=(0.0, 0.0, 0.0), body=None):
        """Add a point; returns it (a `MooringPoint`).

        Parameters
        ----------
        position : array_like, shape (3,)
            Global axes (m), z up; in the body's axes, relative to its reference point, for a
            point on a ``body`` (``(0, 0, 0)`` on a `PointBody`).
        fixed : bool
            An anchor: it does not move (not with a ``body``).
        mass, volume : float
            Mass (kg) and displaced volume (m^3): weight ``m g`` down, buoyancy ``rho g V`` up.
        force : array_like, shape (3,)
            A constant force on the point (N), global axes.
        body : RigidBody or PointBody, optional
            A body of this system the point is fixed to.
        """
        if body is not None:
            if not any(b is body for b in self.bodies):
                raise InputError("body", "is not in this system: add it with add_body first")
            if fixed:
                raise InputError("fixed", "a point on a body moves with it: give fixed=False with body=")
            if isinstance(body, PointBody) and np.any(point("position", position) != 0):
                raise InputError("position", "a point on a PointBody is its point: give (0, 0, 0)")
        elif self.depth is not None:
            z = float(point("position", position)[2])
            if z < -self.depth - on_seabed_tolerance(0.0, z, self.depth):
                raise InputError("position", f"lies below the seabed (z = {z:.6g} m, depth {self.depth:g} m)")
        return self._new_point(position, fixed, mass, volume, force, body)

    def _point(self, name, p) -> MooringPoint:
        if not isinstance(p, MooringPoint) or p.index >= len(self.points) or self.points[p.index] is not p:
            raise InputError(name, f"must be a point of this system (from add_point), got {p!r}")
        return p

    def _add_line(self, model, a, b, managed):
        sea = None
        if managed and solved_in_sea(model):  # the choice of `skcable.mooring.choice`
            sea, managed = self._sea_placement(model, a, b), False
        warm = managed or sea is not None or takes_start(model)
        handle = MooringLine(len(self.mooring_lines), model, a, b, managed, warm, sea)
        self.mooring_lines.append(handle)
        self._layout = None
        return handle

    def _sea_placement(self, line, a, b):
        """``(placed, reverse)`` of a line in the sea from ``a`` to ``b`` (`MooringLine.sea`): solved
        from its fixed end; `InputError` naming ``line`` where both ends move."""
        if not (a.fixed or b.fixed):
            reason = line.off_plane[1]
            raise InputError(
                "line",
                f"line {len(self.mooring_lines)} (point {a.index} to point {b.index}) is a line in the sea "
                f"({reason}) with both ends moving: such a line is solved from a fixed end (an anchor), "
                "and the 6 x 6 stiffness of a 3-D line BVP with both ends free is not built; fix one "
                "of its ends",
            )
        reverse = not a.fixed
        return placed_line(line, self.depth, reverse), reverse

    def add_line(self, line, a, b):
        """Add a line from point ``a`` to point ``b``; returns its handle (a `MooringLine`).

        ``line``: a `skcable.mooring.Line`, its segments from ``a`` to ``b``, solved over the
        system's seabed from whichever end is lower (its own ``seabed`` is not used; its
        ``friction`` is); or another line model, solved as given with ``a`` its anchor A (``a``
        must then be fixed).

        A `skcable.mooring.Line` in the sea (a ``current``, a `skcable.mooring.bathymetry.Bathymetry`
        or a nonlinear axial law) is solved by `skcable.mooring.line_3d`'s choice of model
        (`skcable.mooring.choice`) from its fixed end, ``a`` or ``b``, as its anchor: over
        its own `Bathymetry` where it has one, else over the system's flat seabed; its force and
        3 x 3 stiffness at its moving end enter the system's. One of its ends must be fixed
        (`InputError` naming ``line`` otherwise: the both-ends stiffness of such a line is not
        built).

        A model with ``solve_between(a, b, depth, start)`` (the extension point of models solved
        between two points in space, either end moving: `skcable.mooring.rod.Rod`) is solved by
        it, its ends' forces ``end_forces`` and 3 x 3 blocks ``block(i, j)`` entering the
        system's as a `skcable.mooring.Line`'s do."""
        a, b = self._point("a", a), self._point("b", b)
        if a is b:
            raise InputError("b", f"is point {a.index}, the same as a: a line from a point to itself")
        if is_line(line):
            if line.seabed is not None and self.depth is None:
                raise InputError("depth", "the line is given a seabed: give the system its depth= instead")
            return self._add_line(line, a, b, True)
        if callable(getattr(line, "solve_between", None)):
            return self._add_line(line, a, b, True)
        line_model("line", line)
        if not a.fixed:
            raise InputError(
                "a", "a line model other than mooring.Line is solved with a as its anchor: a must be fixed"
            )
        return self._add_line(line, a, b, False)

    # -- the one-body views ----------------------------------------------------------------------------
    @property
    def body(self):
        """The system's body (a one-body system)."""
        if len(self.bodies) != 1:
            raise InputError("body", f"the system has {len(self.bodies)} bodies: use bodies[i]")
        return self.bodies[0]

    @property
    def lines(self) -> list:
        """The line models, in the order of the lines."""
        return [h.model for h in self.mooring_lines]

    @property
    def anchors(self) -> np.ndarray:
        """The fixed points (m), shape (n, 3): the anchors of the one-body constructor, in order."""
        return np.array([p.position for p in self.points if p.fixed]).reshape(-1, 3)

    @property
    def layout(self) -> Layout:
        """The dofs of the bodies and the free points (`skcable.mooring.network.Layout`)."""
        if self._layout is None:
            self._layout = Layout(self.bodies, self.points)
            self._assembler = Assembler(self.bodies, self.points, self._layout)
        return self._layout

    def frame(self, q) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(P, R, arms)`` at the dofs ``q``: every point's global position ``(n, 3)`` (m), the
        bodies' rotation matrices ``(n_bodies, 3, 3)`` and the arms (global axes) of the bodies'
        points, then of each body's centre of gravity and metacentre (`Assembler.body_arms`)."""
        layout = self.layout
        xyz, R = self._assembler.frames(q)
        arms = self._assembler.body_arms(R)
        P = layout.fixed_positions.copy()
        index = self._assembler.body_point_index
        if len(index):
            P[index] = xyz[self._assembler.body_point_owner] + arms[: len(index)]
        if layout.free.size:
            P[layout.free] = q[layout.free_starts[:, None] + np.arange(3)]
        return P, R, arms

    @property
    def n_dof(self) -> int:
        return self.layout.n_dof

    # -- positions and loads ---------------------------------------------------------------------------
    def _position(self, name, position):
        layout = self.layout
        if position is None:
            return layout.initial(self._body_positions)
        if self.shortcut:
            return self.body.check_position(name, position)
        q = real(name, position)
        if np.shape(q) != (layout.n_dof,):
            raise InputError(
                name, f"must hold the {layout.n_dof} dofs of the bodies and free points, got {np.shape(q)}"
            )
        return np.array(q, dtype=float)

    def _target(self, name, key):
        """The first dof of a body or free point named in a load mapping."""
        layout = self.layout
        if isinstance(key, MooringPoint) and self._point(name, key).kind == "free":
            return layout.point_start[key.index], None
        i = next((i for i, b in enumerate(self.bodies) if b is key), None)  # not by id(): a copy holds others
        if i is not None:
            return layout.body_start[i], key
        raise InputError(name, f"takes bodies and free points of this system as keys, got {key!r}")

    def _loads(self, force, moment):
        """The external load on the dofs (N, N m): one body's ``(3,)`` force and moment, or mappings
        ``{body or free point: (3,)}``."""
        if self.shortcut:
            force, moment = point("force", force), point("moment", moment)
            if self.n_dof == 3:
                if np.any(moment != 0):
                    raise InputError(
                        "moment", "a point body takes no moment: leave it out or use a RigidBody"
                    )
                return force
            return np.concatenate([force, moment])
        external = np.zeros(self.n_dof)
        for name, value, offset in (("force", force, 0), ("moment", moment, 3)):
            items = value.items() if isinstance(value, Mapping) else [(None, value)]
            for key, vector in items:
                vector = point(name, vector)
                if key is None:
                    if not np.any(vector):
                        continue
                    if len(self.bodies) != 1:
                        raise InputError(
                            name, f"with {len(self.bodies)} bodies: give a mapping {{body: (x, y, z)}}"
                        )
                    key = self.bodies[0]
                start, body = self._target(name, key)
                if offset and (body is None or body.n_dof == 3):
                    if np.any(vector):
                        raise InputError(name, "a point or a point body takes no moment")
                    continue
                external[start + offset : start + offset + 3] += vector
        return external

    # -- lines ---------------------------------------------------------------------------------------
    def _active(self, without):
        return [h for h in self.mooring_lines if h.index not in without]

    def _solve_at(self, P, handles, start):
        """Every line of ``handles`` solved with its ends at ``P`` (n, 3); ``start`` their previous
        solutions or None."""
        start = [None] * len(handles) if start is None else start
        solved: list = []
        latest: dict = {}
        depth = self.depth
        together = self._solve_together(P, handles, start)
        for k, (handle, previous) in enumerate(zip(handles, start, strict=True)):
            a, b = P[handle.a.index], P[handle.b.index]
            model = handle.model
            line: Any
            if k in together:
                line = together[k]
            elif handle.managed:
                line = solve_between(model, a, b, depth, previous or latest.get(id(model)))
            elif handle.sea is not None:
                line = _solve_sea(handle, a, b, previous)
            else:
                r = _reach(model, a, b)
                if handle.warm and previous is None:  # a line of the same model, solved just now
                    previous = latest.get(id(model))
                line = solve_in_space(model, a, b, r, previous if handle.warm else None)
            latest[id(model)] = line
            solved.append(line)
        return solved

    def _solve_together(self, P, handles, start) -> dict:
        """The warm-started `skcable.mooring.Line` lines of one model solved together
        (`solve_many_between`): ``{position in handles: LineBetween}``."""
        groups: dict = {}
        for k, (handle, previous) in enumerate(zip(handles, start, strict=True)):
            if handle.managed and previous is not None:
                groups.setdefault(id(handle.model), []).append(k)
        together = {}
        for ks in groups.values():
            if len(ks) < BATCH:
                continue
            model = handles[ks[0]].model
            ends = [(P[handles[k].a.index], P[handles[k].b.index]) for k in ks]
            for k, line in zip(
                ks, solve_many_between(model, ends, self.depth, [start[k] for k in ks]), strict=True
            ):
                if line is not None:
                    together[k] = line
        return together

    def _checked_start(self, start, handles):
        if start is None:
            return None
        if len(start) != len(handles) or not all(
            isinstance(s, (Line3D, LineBetween, LineInSeaBetween, RodBetween)) for s in start
        ):
            raise InputError("start", f"must be a list of {len(handles)} solved lines, one per line")
        return list(start)

    def solve_lines(self, position, start=None, *, without=()) -> list:
        """Every line solved with the bodies and free points at ``position`` (the dofs: m, rad).

        ``start``: the lines solved at another position (one per line), each a warm start of its
        own (the same solution as without it: to round-off in closed form and for the line in
        space, whose meshes are its ends'; for the plane line BVP, whose meshes are graded from its
        start, to its touchdown fitting: within 1e-9 of the end forces where its mesh resolves the
        line, `tests/mooring/test_line_bvp_model.py`). Without it, a line of a model
        solved for an earlier line of this call (lines of one model, e.g. a spread mooring)
        starts from that solution. Returns `skcable.mooring.Line3D` (line models solved as given)
        and `skcable.mooring.LineBetween` (`skcable.mooring.Line`) objects."""
        q = self._position("position", position)
        handles = self._active(without)
        return self._solve_at(self.frame(q)[0], handles, self._checked_start(start, handles))

    def evaluate(self, q, external, *, lines_only=False, start=None, without=()):
        """Net load ``G(q)`` (N, N m), stiffness ``K(q)`` and the solved lines at the checked dofs
        ``q`` under the ``external`` load (one value per dof), the lines warm-started from
        ``start`` (their solutions at another position), if given.

        ``lines_only``: ``G`` and ``K`` of the lines alone (no own loads, no external load)."""
        handles = self._active(without)
        P, R, arms = self.frame(q)
        lines = self._solve_at(P, handles, self._remembered(q, handles) if start is None else start)
        if start is None:
            self._cold = (self._layout, q.copy(), [(h, h.model) for h in handles], lines)
        G, K = self.assemble(q, (R, arms), handles, lines, external, lines_only)
        return G, K, lines

    def _remembered(self, q, handles):
        """The lines last solved without a start, if that was at these very dofs ``q`` with these
        lines (an equilibrium from rest, run again): their warm starts (Newton from a line's own
        solution stops at once: the same solution). MoorPy's lines, likewise, start each solve
        from their last forces (``HF0``, ``VF0``). None otherwise."""
        cold = self._cold
        if cold is None or cold[0] is not self._layout or not np.array_equal(cold[1], q):
            return None
        same = len(cold[2]) == len(handles) and all(
            h is g and h.model is m for (g, m), h in zip(cold[2], handles, strict=True)
        )
        return cold[3] if same else None

    def assemble(self, q, frame, handles, lines, external, lines_only=False):
        """``(G, K)`` from the solved ``lines`` of ``handles`` at ``q``, ``frame`` the bodies' rotation
        matrices and their points' arms there (`frame`; module docstring)."""
        R, arms = frame
        index: list = []
        values: list = []  # per moving end: its force (3) and its stiffness (3 x 3), flat
        cross: list = []
        for handle, line in zip(handles, lines, strict=True):
            if handle.managed:
                _managed_ends(handle, line, index, values, cross, self._assembler, arms)
                continue
            moving = handle.a if handle.sea is not None and line.reversed else handle.b
            if moving.kind != "fixed":  # a line in the sea or one solved as given: its moving end
                index.append(moving.index)
                values.append([*line.force_on_fairlead.tolist(), *line.stiffness().ravel().tolist()])
        ends = np.array(values, dtype=float).reshape(-1, 12)
        forces, stiffness = ends[:, :3], ends[:, 3:].reshape(-1, 3, 3)
        return self._assembler.assemble(q, R, arms, index, forces, stiffness, cross, external, lines_only)

    def net_force(self, position, *, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0)) -> np.ndarray:
        """Net load on the dofs at ``position``: lines, own loads and the external ``force`` and
        ``moment`` (N, N m, global axes; a body's moment about its reference point)."""
        return self.evaluate(self._position("position", position), self._loads(force, moment))[0]

    def stiffness(self, position, *, lines_only=False) -> np.ndarray:
        """Stiffness ``-∂G/∂(x, rotation vector)`` at ``position`` (N/m, N, N m/rad), (n_dof, n_dof).

        ``lines_only``: the lines alone (MoorPy's ``lines_only=True``); otherwise the bodies'
        hydrostatic stiffness is added."""
        q = self._position("position", position)
        return self.evaluate(q, 0.0, lines_only=lines_only)[1]

    # -- what the equilibrium solver asks ----------------------------------------------------------------
    def dof_units(self) -> np.ndarray:
        """Consistent units of the dofs: 1 for translations, a body's largest arm (at least 1 m) for
        its rotations."""
        layout = self.layout
        if layout.units is None:  # once per layout
            units = np.ones(layout.n_dof)
            for i, body in enumerate(self.bodies):
                if body.n_dof == 6:
                    arm = max(1.0, float(np.abs(layout.local[i]).max())) if len(layout.local[i]) else 1.0
                    units[layout.body_start[i] + 3 : layout.body_start[i] + 6] = arm
            layout.units = units
        return layout.units.copy()

    def step_cap(self, q, without=()) -> np.ndarray:
        """The largest Newton step of each dof: a quarter of the shortest horizontal span of the lines
        of its body or point (m; of a line steeper than 45°, its height), 0.2 rad."""
        P = self.frame(q)[0].tolist()
        starts = self._assembler.group_start.tolist()  # each point's body or free point: its first dof, or -1
        shortest: dict = {}
        longest = 1.0  # with no line at all
        for k, h in enumerate(self._active(without)):
            (ax, ay, az), (bx, by, bz) = P[h.a.index], P[h.b.index]
            r = max(math.hypot(bx - ax, by - ay), 0.1 * abs(bz - az))  # a steep line: a tenth of its height
            if r == 0.0:  # a tie of two points (`skcable.mooring.rod.Tie`): no reach
                continue
            longest = r if k == 0 else max(longest, r)
            for end in (h.a.index, h.b.index):
                if starts[end] >= 0 and not r >= shortest.get(starts[end], math.inf):
                    shortest[starts[end]] = r
        cap = np.full(self.layout.n_dof, 0.2)
        for first in self._assembler.groups.tolist():  # a group with no line: the longest span
            cap[first : first + 3] = 0.25 * shortest.get(first, longest)
        return cap

    def force_scale(self, external) -> float:
        """A force scale of the loads other than the lines' (N): weights, buoyancies, point loads,
        external forces."""
        self.layout  # noqa: B018 - builds the assembler
        assembler = self._assembler
        pushed = float(np.linalg.norm(external[assembler.group_xyz], axis=1).max(initial=0.0))
        return max(assembler.own_scale, pushed)

    @staticmethod
    def tension_scale(lines) -> float:
        """The largest tension at a moving end of the lines (N)."""
        tensions = [
            line.max_end_tension
            if type(line) is LineBetween or hasattr(line, "max_end_tension")
            else line.tension_at_fairlead
            for line in lines
        ]
        return max(tensions, default=0.0)

    def check(self, without=(), alone: bool = False):
        """Refuse a system that cannot be solved, naming the part: no body or free point, a free
        point or body with no line (of those left, ``without`` the lines given). ``alone``: a body
        or point with no line is no error (its own loads may hold it, or leave it neutral: the
        equilibrium with ``neutral="hold"`` judges it)."""
        handles = self._active(without)
        if self.n_dof == 0:
            raise InputError("points", "the system has no body and no free point: nothing to solve for")
        if alone:
            return
        used = {p.index for h in handles for p in (h.a, h.b)}
        for p in self.points:  # an anchor left alone by a failure is no error
            if p.index not in used and (p.kind == "free" or p.kind == "fixed" and not without):
                raise InputError(
                    "points", f"point {p.index} ({p.kind}) has no line: connect it or leave it out"
                )
        held = {int(self._assembler.owner[j]) for j in used if self.points[j].kind == "body"}
        for i in range(len(self.bodies)):
            if i not in held:
                raise InputError("bodies", f"body {i} has no line: connect a line to one of its points")

    @_plausible.answer(warn_implausible)
    def equilibrium(
        self,
        *,
        force=(0.0, 0.0, 0.0),
        moment=(0.0, 0.0, 0.0),
        start=None,
        tol: float = 1e-10,
        max_iter: int = 60,
        without=(),
        time_limit: float = 60.0,
        neutral: str = "raise",
    ) -> MooringEquilibrium:
        """Static equilibrium of every body and free point under constant external loads.

        Parameters
        ----------
        force, moment : array_like, shape (3,), or mapping
            External force (N) and moment (N m, about the reference point), global axes: of the
            one body, or ``{body or free point: (x, y, z)}``.
        start : array_like or MooringEquilibrium, optional
            The starting dofs (bodies, then free points; m, rad); default: where the bodies and
            points were added (all zeros for the one-body constructor). Or an earlier equilibrium
            of this system: its position, and its lines as warm starts of the first line solves.
        tol : float
            Convergence when every net force over the force scale (the largest of the line
            tensions, the weights, the buoyancies and the external forces), and every net moment
            over that scale times its body's largest arm, are below ``tol``.
        max_iter : int
            Newton iterations at most, in each of the runs (the start, the start pushed along the
            net load, the restarts towards a stable branch: a bounded number).
        without : sequence of MooringLine, optional
            Lines left out (a line failure): the damaged system's equilibrium.
        time_limit : float
            Seconds at most (> 0, default 60): past them the search stops with a
            `ConvergenceError` whose ``history`` is every scaled residual evaluated and whose
            ``last`` is the best point reached (the dofs).
        neutral : {"raise", "hold"}
            A direction along which the loads do not change (a body whose lines all meet at
            its reference point turns freely): ``"raise"`` refuses the equilibrium as not unique;
            ``"hold"`` keeps it where it starts and names it in the result's ``neutral``.

        Returns
        -------
        MooringEquilibrium
            With ``bodies``, ``points``, ``lines``, ``stable`` and the stiffness ``eigenvalues``.

        Raises
        ------
        InputError
            Bad arguments, a point or body with no line, a starting position where a line cannot be
            solved.
        ConvergenceError
            No equilibrium within ``max_iter`` iterations or ``time_limit`` seconds, or a direction
            nothing restrains (named); carries the history of the scaled residual.
        """
        without = self._without(without)
        self.check(without, alone=neutral == "hold")
        external = self._loads(force, moment)
        warm_lines = None
        if isinstance(start, MooringEquilibrium):
            if start.system is not self:
                raise InputError("start", "is the equilibrium of another MooringSystem")
            q = start.position.copy()
            warm_lines = start.lines if start.without == without else None
        else:
            q = self._position("start", start)
        tol = scalar("tol", positive("tol", tol))
        if isinstance(max_iter, bool) or not isinstance(max_iter, (int, np.integer)) or max_iter < 1:
            raise InputError("max_iter", f"must be an integer >= 1, got {max_iter!r}")
        time_limit = scalar("time_limit", positive("time_limit", time_limit))
        one_of("neutral", neutral, ("raise", "hold"))
        return solve_equilibrium(
            self,
            q,
            external,
            warm_lines,
            tol,
            max_iter,
            without=without,
            neutral=neutral,
            time_limit=time_limit,
        )

    def _without(self, without) -> frozenset:
        if isinstance(without, (MooringLine, str, bytes)) or not isinstance(without, Iterable):
            raise InputError("without", "must be a list of the system's lines (from add_line)")
        out = set()
        for h in without:
            if (
                isinstance(h, (int, np.integer))
                and not isinstance(h, bool)
                and 0 <= h < len(self.mooring_lines)
            ):
                h = self.mooring_lines[int(h)]
            if not isinstance(h, MooringLine) or self.mooring_lines[h.index] is not h:
                raise InputError("without", f"holds {h!r}, not a line of this system (from add_line)")
            out.add(h.index)
        return frozenset(out)

    def start_position(self, body) -> np.ndarray:
        """The dofs of ``body`` where it was added (`add_body`'s ``position``; zeros by default)."""
        for b, q in zip(self.bodies, self._body_positions, strict=True):
            if b is body:
                return q.copy()
        raise InputError("body", "is not in this system")

    def point_position(self, p, position=None) -> np.ndarray:
        """The global position (m) of the point ``p`` with the dofs at ``position`` (default: the start)."""
        p = self._point("point", p)
        return self.frame(self._position("position", position))[0][p.index].copy()

    def replaced(self, *, models=None, positions=None) -> MooringSystem:
        """A copy of this system with some lines' models and some points' positions replaced:
        ``models`` maps line handles to line models, ``positions`` points to their new position (as
        `add_point` takes it). The bodies are the same objects, at the same starts."""
        models, positions = dict(models or {}), dict(positions or {})
        other = MooringSystem(depth=self.depth, rho=self.rho, g=self.g)
        for body, q in zip(self.bodies, self._body_positions, strict=True):
            other._add_body(body, q)
        other._pinned = list(self._pinned)
        for p in self.points:
            where = positions.get(p, p.position)
            other._new_point(where, p.fixed, p.mass, p.volume, p.force, p.body)
        for h in self.mooring_lines:
            model = models.get(h, h.model)
            managed = h.managed or h.sea is not None
            other._add_line(model, other.points[h.a.index], other.points[h.b.index], managed)
        other.shortcut = self.shortcut
        return other

    def failure(self, lines, **options):
        """The equilibrium without ``lines`` (a line failure) beside the intact one, under the same
        loads (``options``: those of `equilibrium`): a `skcable.mooring.failure.FailureCase`
        with ``intact``, ``damaged``, ``redistribution()`` and ``offsets()``."""
        return failure.failure_case(self, lines, **options)

    def failure_cases(self, **options) -> list:
        """Each line failing alone (`failure`), from one intact equilibrium."""
        return failure.failure_cases(self, **options)

    def __repr__(self):
        return (
            f"MooringSystem({len(self.bodies)} bodies, {len(self.points)} points, "
            f"{len(self.mooring_lines)} lines, depth={self.depth!r})"
        )


def _solve_sea(handle, a, b, previous) -> LineInSeaBetween:
    """A line in the sea (`MooringLine.sea`) solved with its ends at ``a`` and ``b`` from its fixed end,
    warm-started from ``previous`` (its solution at other positions) or None."""
    placed, reverse = handle.sea
    anchor, moving = (b, a) if reverse else (a, b)
    r = _reach(placed, anchor, moving)
    start = previous.sea if isinstance(previous, LineInSeaBetween) else None
    sea = solve_line_in_sea(placed, anchor, moving, r, start, solve_in_plane_of_ends)
    return LineInSeaBetween(handle.model, sea, reverse)


def _reach(model, anchor, moving) -> float:
    """The horizontal distance (m) from ``anchor`` to ``moving``; where it is no span (a moving end
    not finite, or on the anchor's vertical) `line_3d` refuses it, naming the point."""
    r = math.hypot(float(moving[0] - anchor[0]), float(moving[1] - anchor[1]))
    if not (np.isfinite(moving).all() and r > 1e-9 * max(1.0, float(np.abs(moving - anchor).max()))):
        line_3d(model, anchor, moving)  # raises, naming the point
    return r


def _managed_ends(handle, line, index, values, cross, assembler, arms):
    """The ends of a `skcable.mooring.Line` line that move (their points into ``index``, their force and
    stiffness, flat, into ``values``), and their coupling where both do."""
    moving = (handle.a.kind != "fixed", handle.b.kind != "fixed")
    if not any(moving):
        return
    if not moving[0]:  # the common case: an anchor and a moving fairlead
        index.append(handle.b.index)
        values.append(line.b_values())
        return
    J = line.plane.jacobian() if line.plane is not None else None
    for i, p in enumerate((handle.a, handle.b)):
        if moving[i]:
            index.append(p.index)
            values.append([*line.end_forces[i].tolist(), *line.block(i, i, J).ravel().tolist()])
    if all(moving):
        (sa, Ta), (sb, Tb) = (_point_map(assembler, arms, p) for p in (handle.a, handle.b))
        cross.append((sa, Ta, sb, Tb, line.block(0, 1, J), line.block(1, 0, J)))


def _point_map(assembler, arms, p):
    """``(first dof, T)`` with ``δp = T δq`` for a moving point ``p`` (module docstring)."""
    if p.kind == "free":
        return int(assembler.free_start[p.index]), np.eye(3)
    i = int(assembler.owner[p.index])
    start = int(assembler.start[i])
    if not assembler.rigid[i]:
        return start, np.eye(3)
    r = arms[assembler.row[p.index]]
    return start, np.hstack([np.eye(3), -skew(r)])
