r"""A rigid rod between two points of a mooring system: its weight, its buoyancy, its length.

A rod (MoorDyn's ``RODS``: a rigid cylinder of diameter ``d``, mass ``m`` per length and length
``L``) joins two points of a `skcable.mooring.MooringSystem`, its ends A and B: fixed points, free
points or points on a body, as the rod is fixed, pinned or free. The lines attached to its ends
attach to those points. As a line of the system (``add_line(rod, a, b)``) it gives its ends

.. math:: \mathbf F_a = N\,\mathbf u + \mathbf f_a, \qquad \mathbf F_b = -N\,\mathbf u + \mathbf f_b,

:math:`\mathbf u = (\mathbf b - \mathbf a)/\ell` along the rod, :math:`\ell` its length. Its
distributed loads act on its ends as a rigid body's: their resultant and their moment about
either end are the loads' (a pin-jointed bar: the lever rule). The weight :math:`m g L` acts
at the middle, half on each end; the buoyancy is that of the rod's displaced volume, its
cross-sections' submerged area along its axis (`skcable.mooring.rod_waterline`: a disc normal to
the axis cut by the still water line ``z = 0`` in a chord): all of :math:`\rho g \tfrac{\pi}{4}
d^2 L` for a rod below the water line, none above it, for a vertical rod crossing it the
submerged length of its axis, for a horizontal one the circular segment of its section, at the
centre of that volume along the axis, shared on the ends by the lever rule. The axial force
:math:`N = k\,(\ell - L)` holds the length: ``k`` is
``axial_stiffness`` (N/m), stiff enough that the rod's change of length under the loads is below
the solver's tolerance on its ends (`Rod` takes it from the lines' stiffness; the equilibrium's
``RodBetween.stretch`` reports it). A rod does not touch the seabed: an end below it is refused.

The stiffness :math:`K = -\partial(\mathbf F_a, \mathbf F_b)/\partial(\mathbf a, \mathbf b)` is
the bar's, :math:`\pm\big(k\,\mathbf u\mathbf u^T + \tfrac{N}{\ell}(I - \mathbf u\mathbf u^T)\big)`,
plus, for a rod crossing the surface, the change of its buoyancy with the heights of its ends and
with its inclination (`skcable.mooring.rod_waterline.waterline_shares`).

A rod of zero length (MoorDyn's connector rods) is a single point: the system holds no rod then
(`skcable.mooring.moordyn`).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from skcable._checks import nonnegative, one_of, positive, scalar
from skcable.errors import InputError
from skcable.mooring.between_points import StraightBetween
from skcable.mooring.body import RigidBody, skew
from skcable.mooring.rod_waterline import waterline_shares
from skcable.mooring.segments.solution import segment_table

__all__ = ["Rod", "RodBetween", "RodBody", "Tie", "TieBetween", "rod_frame"]


class Rod:
    """A rigid rod (module docstring), a line model of a `skcable.mooring.MooringSystem`.

    Parameters
    ----------
    length : float
        Its length (m), > 0.
    diameter : float
        Its diameter (m), > 0: its volume per length is ``π d²/4``.
    mass : float
        Mass per length (kg/m), >= 0.
    axial_stiffness : float, optional
        ``k`` (N/m), > 0: the axial force per change of length, where the rod is a line between
        two points (``add_line``); None for a rod that is a body (`RodBody`).
    rho, g : float
        Water density (kg/m³) and gravity (m/s²), >= 0.
    """

    def __init__(self, length, diameter, mass, axial_stiffness=None, *, rho=1025.0, g=9.80665):
        self.length = scalar("length", positive("length", length))
        self.diameter = scalar("diameter", positive("diameter", diameter))
        self.mass = scalar("mass", nonnegative("mass", mass))
        self.axial_stiffness = (
            None
            if axial_stiffness is None
            else scalar("axial_stiffness", positive("axial_stiffness", axial_stiffness))
        )
        self.rho = scalar("rho", nonnegative("rho", rho))
        self.g = scalar("g", nonnegative("g", g))
        self.weight = self.mass * self.g * self.length
        self.buoyancy_per_length = self.rho * self.g * math.pi / 4.0 * self.diameter**2

    def solve_between(self, a, b, depth, start=None) -> RodBetween:
        """The rod with its ends at the float 3-vectors ``a`` and ``b`` (m) over the seabed
        ``z = -depth`` (None: none); ``start`` is not used (the rod has no unknowns)."""
        del start
        if self.axial_stiffness is None:
            raise InputError("axial_stiffness", "a rod between two points needs its axial stiffness")
        if depth is not None:
            low = min(float(a[2]), float(b[2]))
            if low < -depth * (1.0 + 1e-12):
                raise InputError(
                    "rod", f"an end at z = {low:.6g} m lies below the seabed (depth {depth:g} m)"
                )
        return RodBetween(self, a, b)

    def __repr__(self):
        stiff = "" if self.axial_stiffness is None else f", axial_stiffness={self.axial_stiffness:g}"
        return f"Rod(length={self.length!r}, diameter={self.diameter!r}, mass={self.mass!r}{stiff})"


class RodBetween(StraightBetween):
    """A rod with its ends at ``a`` and ``b`` (module docstring).

    Attributes
    ----------
    a, b : ndarray, shape (3,)
        Its ends (m).
    axial_force : float
        ``N`` (N), > 0 in tension.
    stretch : float
        ``ℓ - L`` (m): the change of its length under the loads.
    end_forces : ndarray, shape (2, 3)
        Its forces on a and on b (N).
    model, reason : str
        ``"rod"`` and what holds it.
    """

    model = "rod"
    reason = "a rigid rod: its weight and buoyancy on its ends, its length held by its axial stiffness"

    def __init__(self, rod, a, b):
        self.line, self.a, self.b = rod, np.array(a, dtype=float), np.array(b, dtype=float)
        d = self.b - self.a
        self.span = float(math.hypot(d[0], d[1]))
        self.length = float(np.linalg.norm(d))
        if not self.length > 0.0:
            raise InputError("rod", "its ends coincide: a rod needs a direction")
        self.u = d / self.length
        self.stretch = self.length - rod.length
        self.axial_force = rod.axial_stiffness * self.stretch
        shares = waterline_shares(rod.buoyancy_per_length * rod.length, 0.5 * rod.diameter, self.a, self.b)
        self._dbuoyancy = shares.grad
        half = 0.5 * rod.weight
        self.loads = np.array([[0.0, 0.0, shares.fa - half], [0.0, 0.0, shares.fb - half]])
        pull = self.axial_force * self.u
        self.end_forces = np.array([pull + self.loads[0], -pull + self.loads[1]])

    @cached_property
    def _axial_block(self) -> np.ndarray:
        u = self.u
        uu = np.outer(u, u)
        return self.line.axial_stiffness * uu + (self.axial_force / self.length) * (np.eye(3) - uu)

    def block(self, i: int, j: int, J=None) -> np.ndarray:
        del J
        K = (self._axial_block if i == j else -self._axial_block).copy()
        K[2] -= self._dbuoyancy[i, j]
        return K

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points (n, 3), axial force (n,))`` along the rod (m, N)."""
        return self.chord(n), np.full(int(n), self.axial_force)

    def tensions(self):
        """One row (`skcable.mooring.segments.solution.segment_table`): the rod's length, its
        weight in water per length where submerged, its axial stiffness times its length, and its
        axial force at both ends."""
        rod, N = self.line, abs(self.axial_force)
        w = rod.mass * rod.g - rod.buoyancy_per_length
        EA = rod.axial_stiffness * rod.length
        return segment_table([rod.length], [w], [EA], [N], [N], T_max=[N], grounded_length=0.0)

    def __repr__(self):
        return (
            f"RodBetween(a={self.a.tolist()}, b={self.b.tolist()}, axial_force={self.axial_force:.6g}, "
            f"stretch={self.stretch:.3g})"
        )


def rod_frame(direction) -> tuple[np.ndarray, float, float]:
    """``(R0, roll, yaw)``: axes of a rod along the unit ``direction`` with body y along it, body x
    horizontal (global x for a vertical rod), and their roll and yaw (pitch zero: ``R0`` is
    ``Rz(yaw) Rx(roll)``). A rod turning about its own axis turns about body y: its pitch, whose
    singular value ±π/2 it never needs."""
    u = np.asarray(direction, dtype=float)
    x = np.cross(u, [0.0, 0.0, 1.0])
    x = np.array([1.0, 0.0, 0.0]) if not np.linalg.norm(x) > 1e-12 else x / np.linalg.norm(x)
    z = np.cross(x, u)
    R0 = np.column_stack([x, u, z])
    return R0, math.atan2(R0[2, 1], R0[2, 2]), math.atan2(R0[1, 0], R0[0, 0])


class RodBody(RigidBody):
    r"""A rigid rod as a body of the equilibrium: 6 dofs, its body y axis along it (`rod_frame`),
    its reference point at end A (``reference="a"``: a rod pinned there) or at its middle
    (``"middle"``: a free rod), its ends at ``end_a`` and ``end_b`` in its axes (:math:`(0, L, 0)`
    from A).

    Its weight :math:`m g L` acts at its middle (its centre of gravity); its buoyancy, that of its
    displaced volume (module docstring), acts on its ends A and B as `RodBetween`'s does, changing
    with its pose where it crosses the still water line: ``posed_loads`` gives that force and
    moment and their stiffness to the assembly (`skcable.mooring.net_loads`). Its turning about
    its own axis changes nothing: a neutral direction of the equilibrium (``neutral="hold"``). A
    free rod's reference point is its middle, where its weight and (under water) its buoyancy act:
    their net force has no moment about it, so the equilibrium's step along a direction nothing
    restrains (a rod rising through the water) lifts it level instead of turning it about an end.

    Parameters
    ----------
    rod : Rod
        Its length, diameter, mass per length, water density and gravity.
    reference : {"a", "middle"}
        Where its reference point (its position's ``x, y, z``) lies.
    """

    def __init__(self, rod, reference="a"):
        one_of("reference", reference, ("a", "middle"))
        self.rod, self.reference = rod, reference
        half = 0.5 * rod.length
        self.end_a = np.array([0.0, 0.0 if reference == "a" else -half, 0.0])
        self.end_b = self.end_a + np.array([0.0, rod.length, 0.0])
        super().__init__(
            mass=rod.mass * rod.length,
            center_of_gravity=(0.0, half if reference == "a" else 0.0, 0.0),
            rho=rod.rho,
            g=rod.g,
        )

    def start(self, a, b) -> np.ndarray:
        """The position ``(x, y, z, roll, pitch, yaw)`` with its ends at ``a`` and ``b`` (m)."""
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        d = b - a
        length = float(np.linalg.norm(d))
        if not length > 0 or abs(length - self.rod.length) > 1e-9 * self.rod.length:
            raise InputError("b", f"the rod's ends are {length:g} m apart, its length {self.rod.length:g} m")
        _, roll, yaw = rod_frame(d / length)
        return np.array([*(a if self.reference == "a" else 0.5 * (a + b)), roll, 0.0, yaw])

    def posed_loads(self, q) -> tuple[np.ndarray, np.ndarray]:
        """``(G (6,), K (6, 6))``: the buoyancy on the ends at the position ``q`` as (force, moment
        about the reference point) and its stiffness ``-∂/∂(x, rotation vector)``."""
        R = self.rotation(q)
        arms = (R @ self.end_a, R @ self.end_b)
        x = np.asarray(q[:3], dtype=float)
        rod = self.rod
        shares = waterline_shares(
            rod.buoyancy_per_length * rod.length, 0.5 * rod.diameter, x + arms[0], x + arms[1]
        )
        forces = (np.array([0.0, 0.0, shares.fa]), np.array([0.0, 0.0, shares.fb]))
        G = np.zeros(6)
        G[2] = shares.fa + shares.fb
        G[3:] = np.cross(arms[0], forces[0]) + np.cross(arms[1], forces[1])
        # -∂f_i/∂p_j (f_i along z) carried to the dofs by T_i = [I, -[r_i]x]:
        # -Σ_ij (T_i^T e_z) (∇_j f_i)^T T_j, and the arms' turning, -[f_i]x[r_i]x
        T = np.stack([np.hstack([np.eye(3), -skew(r)]) for r in arms])
        K = -np.einsum("ik,ijl,jlm->km", T[:, 2, :], shares.grad, T)
        for f, r in zip(forces, arms, strict=True):
            K[3:, 3:] -= skew(f) @ skew(r)
        return G, K


class Tie:
    """Two points held together by a stiff spring of zero length, ``F_a = k (b - a)``: a pin joining
    a rod's end to a body (MoorDyn's ``Body#Pinned`` rods). ``stiffness`` ``k`` (N/m), > 0: the
    points' gap is the force over it (`TieBetween.gap`; 6e-8 m in MoorDyn's ``BodiesAndRods.dat``).
    The equilibrium reaches a system with ties through its ties softened
    (`skcable.mooring.equilibrium`)."""

    def __init__(self, stiffness):
        self.stiffness = scalar("stiffness", positive("stiffness", stiffness))

    def solve_between(self, a, b, depth, start=None) -> TieBetween:
        del depth, start
        return TieBetween(self, a, b)

    def __repr__(self):
        return f"Tie(stiffness={self.stiffness:g})"


class TieBetween(StraightBetween):
    """A `Tie` between ``a`` and ``b``: ``end_forces`` ``k (b - a)`` on a, its opposite on b;
    ``gap`` (m)."""

    model = "tie"
    reason = "a pin: the two points held together"

    def __init__(self, tie, a, b):
        self.line, self.a, self.b = tie, np.array(a, dtype=float), np.array(b, dtype=float)
        pull = tie.stiffness * (self.b - self.a)
        self.end_forces = np.array([pull, -pull])
        self.gap = float(np.linalg.norm(self.b - self.a))
        self.span = float(math.hypot(*(self.b - self.a)[:2]))

    def block(self, i: int, j: int, J=None) -> np.ndarray:
        del J
        k = self.line.stiffness
        return (k if i == j else -k) * np.eye(3)

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        return self.chord(n), np.full(int(n), self.max_end_tension)

    def tensions(self):
        T = self.max_end_tension
        return segment_table([0.0], [0.0], [0.0], [T], [T], T_max=[T], grounded_length=0.0)
