r"""A `skcable.mooring.Line` between two points in space, over a flat seabed, either end higher.

Ends :math:`\mathbf a` and :math:`\mathbf b` (m, z up), the seabed the plane ``z = -depth``
(or none). The line hangs in the vertical plane through its ends: horizontal distance
:math:`r = |\mathbf b_{xy} - \mathbf a_{xy}| > 0`, unit direction :math:`\mathbf e` from a to b.
`skcable.mooring.choice.solve_in_plane` solves it in that plane, from its lower end,
with the model its position over the seabed takes (and the reason), and gives the forces at
both ends and their Jacobian :math:`J = \partial(H_a, V_a, H_b, V_b)/\partial(r, z_a, z_b)`.
The line's forces on its ends are

.. math:: \mathbf F_a = (H_a\,\mathbf e,\; -V_a), \qquad \mathbf F_b = (-H_b\,\mathbf e,\; -V_b),

and their stiffness, :math:`K = -\partial(\mathbf F_a, \mathbf F_b)/\partial(\mathbf a, \mathbf b)`
(6 × 6), follows with
:math:`\partial r/\partial\mathbf b_{xy} = \mathbf e^T = -\partial r/\partial\mathbf a_{xy}`
and :math:`\partial\mathbf e/\partial\mathbf b_{xy} = (I - \mathbf e\mathbf e^T)/r
= -\partial\mathbf e/\partial\mathbf a_{xy}`: for ends ``X, Y`` with signs :math:`s_a = 1, s_b = -1`
(the force's direction) and :math:`t_a = -1, t_b = 1` (the span's),

.. math::
    -K_{XY} = \begin{pmatrix} s_X t_Y\big(\partial_r H_X\,\mathbf e\mathbf e^T
        + \tfrac{H_X}{r}(I - \mathbf e\mathbf e^T)\big)
        & s_X\,\partial_{z_Y} H_X\,\mathbf e \\
        -t_Y\,\partial_r V_X\,\mathbf e^T & -\partial_{z_Y} V_X \end{pmatrix}.

``K_bb`` is the fairlead stiffness of `skcable.mooring.line_3d` (J.M. Jonkman, "Dynamics modeling
and loads analysis of an offshore floating wind turbine", NREL, 2007); for a line that touches
nothing ``K = [[K_bb, -K_bb], [-K_bb, K_bb]]``.
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import Protocol

import numpy as np

from skcable._checks import whole
from skcable._show import Shown
from skcable.errors import InputError
from skcable.mooring.segments import LineSolution

__all__ = ["EndTensions", "LineBetween", "StraightBetween", "plane_of"]


class _WithEndForces(Protocol):
    @property
    def end_forces(self) -> np.ndarray: ...


class EndTensions:
    """The end tensions of a line between two points from its ``end_forces`` (N, (2, 3): its
    forces on a and on b): ``tension_a``, ``tension_b`` their norms, ``max_end_tension`` the
    larger (N)."""

    @property
    def tension_a(self: _WithEndForces) -> float:
        return float(np.linalg.norm(self.end_forces[0]))

    @property
    def tension_b(self: _WithEndForces) -> float:
        return float(np.linalg.norm(self.end_forces[1]))

    @property
    def max_end_tension(self: _WithEndForces) -> float:
        return max(float(np.linalg.norm(self.end_forces[0])), float(np.linalg.norm(self.end_forces[1])))


class StraightBetween(EndTensions):
    """A solved line between ``a`` and ``b`` drawn on its chord, its stiffness from its 3 × 3
    blocks ``block(i, j)`` (`skcable.mooring.straight`, `skcable.mooring.rod`): its own
    ``solution``, no plane, nothing on the seabed."""

    plane = None
    is_slack = False
    length_on_seabed = 0.0
    a: np.ndarray
    b: np.ndarray
    end_forces: np.ndarray

    @property
    def solution(self):
        return self

    def block(self, i: int, j: int, J=None) -> np.ndarray:
        """``K_ij = -∂F_i/∂p_j`` (N/m), 3 × 3, for ends ``i, j`` in (0: a, 1: b)."""
        raise NotImplementedError

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points (n, 3), tension (n,))`` from a to b (m, N)."""
        raise NotImplementedError

    def b_values(self) -> list:
        """The force on b (3) and ``K_bb`` (3 × 3, by rows), flat."""
        return [*self.end_forces[1].tolist(), *self.block(1, 1).ravel().tolist()]

    def stiffness(self) -> np.ndarray:
        """``K = -∂(F_a, F_b)/∂(a, b)`` (N/m), (6, 6)."""
        return np.block([[self.block(i, j) for j in (0, 1)] for i in (0, 1)])

    def chord(self, n: int) -> np.ndarray:
        """``n`` points (m) evenly spaced on the chord from a to b, (n, 3)."""
        return self.a + np.outer(np.linspace(0.0, 1.0, int(n)), self.b - self.a)

    def profile(self, n: int = 101) -> np.ndarray:
        return self.profile_with_tension(n)[0]


class LineBetween(Shown):
    """A line solved between two points in space (module docstring).

    Attributes
    ----------
    a, b : ndarray, shape (3,)
        The ends (m), z up, in the order given.
    span, dh : float
        Horizontal distance (m, > 0) and height of b above a (m).
    plane : PlaneLine
        The solution in the line's vertical plane (``model``, ``reason``, forces by end).
    model, reason : str
        Which model the line took, and why (`skcable.mooring.choice`).
    """

    def __init__(self, line, a, b, plane, span, direction):
        if plane.seabed_slope != 0.0:  # `block` moves an end along a seabed fixed in the plane
            raise InputError(
                "plane",
                "a line between two points in space is solved over a flat seabed: its stiffness "
                "would not move the seabed under an end that moves over a slope",
            )
        self.line, self.a, self.b, self.plane = line, a, b, plane
        self.span, self.dh = span, float(b[2] - a[2])
        self._e = (float(direction[0]), float(direction[1]))
        self.model, self.reason = plane.model, plane.reason

    @cached_property
    def direction(self) -> np.ndarray:
        """The unit horizontal vector ``e`` from a towards b."""
        return np.array([*self._e, 0.0])

    @cached_property
    def end_forces(self) -> np.ndarray:
        """The line's forces on a and on b (N), global axes, (2, 3)."""
        (ex, ey), plane = self._e, self.plane
        H_a, V_a, H_b, V_b = plane.H_A, plane.V_A, plane.H_B, plane.V_B
        return np.array([[H_a * ex, H_a * ey, -V_a], [-H_b * ex, -H_b * ey, -V_b]])

    @cached_property
    def tension_a(self) -> float:
        """The tension at a (N): the norm of the end force (as the checks and tables give it)."""
        return float(np.linalg.norm(self.end_forces[0]))

    @cached_property
    def tension_b(self) -> float:
        """The tension at b (N): the norm of the end force."""
        return float(np.linalg.norm(self.end_forces[1]))

    @property
    def solution(self):
        """The 2-D solution of the line from its lower end (`PlaneLine.solution`)."""
        return self.plane.solution

    @property
    def max_end_tension(self) -> float:
        """The larger of the end tensions (N), from the solution in the plane (``hypot(H, V)``: the
        same to round-off as ``tension_a``, ``tension_b``)."""
        return max(self.plane.T_A, self.plane.T_B)

    def block(self, i: int, j: int, J=None) -> np.ndarray:
        """``K_ij = -∂F_i/∂p_j`` (N/m), 3 × 3, for ends ``i, j`` in (0: a, 1: b)."""
        J = self.plane.jacobian() if J is None else J
        ex, ey = self._e
        st, s, t = (1.0 if i == j else -1.0), (1.0, -1.0)[i], (-1.0, 1.0)[j]
        c = (self.plane.H_A, self.plane.H_B)[i] / self.span
        row_H, row_V = J[2 * i].tolist(), J[2 * i + 1].tolist()
        dH_r, dV_r, dH_z, dV_z = row_H[0], row_V[0], row_H[1 + j], row_V[1 + j]
        exx, exy, eyy = ex * ex, ex * ey, ey * ey
        return np.array(
            [
                [st * (dH_r * exx + c * (1.0 - exx)), st * (dH_r * exy - c * exy), -s * dH_z * ex],
                [st * (dH_r * exy - c * exy), st * (dH_r * eyy + c * (1.0 - eyy)), -s * dH_z * ey],
                [t * dV_r * ex, t * dV_r * ey, dV_z],
            ]
        )

    def b_block(self) -> np.ndarray:
        """``K_bb`` (N/m), 3 × 3: the block of an end b that moves with a fixed (`block`). Where the
        solution runs from a, from its 2 × 2 stiffness directly (the fairlead stiffness of
        `skcable.mooring.line_3d`), else from the Jacobian."""
        return np.array(self.b_values()[3:]).reshape(3, 3)

    def b_values(self) -> list:
        """The force on b (3) and `b_block` (3 × 3, by rows), flat: 12 floats (N, N/m)."""
        ex, ey = self._e
        force = [-self.plane.H_B * ex, -self.plane.H_B * ey, -self.plane.V_B]
        if self.plane.reversed:
            return [*force, *self.block(1, 1).ravel().tolist()]
        solution = self.plane.solution
        if type(solution) is LineSolution:  # the closed forms' common case, on floats
            k_hh, k_hv, k_vh, k_vv = solution.stiffness_values()
        else:
            k_hh, k_hv, k_vh, k_vv = np.asarray(solution.stiffness(), dtype=float).ravel().tolist()
        exx, exy, eyy = ex * ex, ex * ey, ey * ey
        c = self.plane.H_B / self.span
        return [
            *force,
            *(k_hh * exx + c * (1.0 - exx), k_hh * exy - c * exy, k_hv * ex),
            *(k_hh * exy - c * exy, k_hh * eyy + c * (1.0 - eyy), k_hv * ey),
            *(k_vh * ex, k_vh * ey, k_vv),
        ]

    def stiffness(self) -> np.ndarray:
        """``K = -∂(F_a, F_b)/∂(a, b)`` (N/m), shape (6, 6): rows and columns ``(a_xyz, b_xyz)``, the
        seabed fixed (an end resting on the seabed moves with it: `skcable.mooring.jacobians`)."""
        J = self.plane.jacobian()
        return np.block([[self.block(i, j, J) for j in (0, 1)] for i in (0, 1)])

    def to_global(self, xy) -> np.ndarray:
        """Points ``(..., 2)`` of the line's plane (a at the origin, y up) in global axes."""
        xy = np.asarray(xy, dtype=float)
        return (
            self.a
            + np.multiply.outer(xy[..., 0], self.direction)
            + np.multiply.outer(xy[..., 1], [0.0, 0.0, 1.0])
        )

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` (m) from a."""
        return self.plane.T_of_s(s)

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points (n, 3), tension (n,))`` at ``n`` points evenly spaced in unstretched arc length
        from a to b (m, N)."""
        n = whole("n", n, 2)
        s = np.linspace(0.0, self.plane.length, n)
        points = self.to_global(self.plane.xy(s))
        tension = np.broadcast_to(np.asarray(self.plane.T_of_s(s), dtype=float), (n,)).copy()
        if not (np.isfinite(points).all() and np.isfinite(tension).all()):
            raise InputError("line", "the line's solution returned a non-finite profile")
        return points, tension

    def profile(self, n: int = 101) -> np.ndarray:
        """Positions ``(n, 3)`` (m) from a to b, evenly spaced in unstretched arc length."""
        return self.profile_with_tension(n)[0]

    def tensions(self):
        """One row per segment from a to b (`PlaneLine.tensions`: ``T_lower`` towards a, ``T_max``,
        ``grounded_length``)."""
        return self.plane.tensions()

    def __repr__(self):
        return (
            f"LineBetween(a={self.a.tolist()}, b={self.b.tolist()}, model={self.model!r}, "
            f"tension_a={self.tension_a:.6g}, tension_b={self.tension_b:.6g})"
        )


def plane_of(a, b):
    """``(r, dz, az, e)`` of the vertical plane through float 3-vectors ``a`` and ``b``: the horizontal
    distance, the height of b above a, a's height (m) and the unit horizontal vector ``e`` from a
    to b; None where b lies on the vertical of a (the plane undefined)."""
    (ax, ay, az), (bx, by, bz) = a.tolist(), b.tolist()
    dx, dy, dz = bx - ax, by - ay, bz - az
    r = math.hypot(dx, dy)
    if not r > 1e-9 * max(1.0, abs(dx), abs(dy), abs(dz)):
        return None
    return r, dz, az, (dx / r, dy / r)
