r"""Bodies a mooring holds: a point (3 dofs) or a rigid body (6 dofs), with their own loads.

Rigid body position :math:`\mathbf q = (x, y, z, \phi, \theta, \psi)`: the body's
reference point in global axes (m, z up) and its roll, pitch and yaw (rad), z-y'-x''
intrinsic Tait-Bryan angles,

.. math:: R = R_z(\psi)\,R_y(\theta)\,R_x(\phi),

any size of rotation (the parametrisation of MoorPy's ``rotationMatrix``; singular
only at pitch :math:`\pm\pi/2`). A point fixed in the body at :math:`\mathbf p`
(body axes) is at :math:`\mathbf x + R\mathbf p`. Forces and moments are in global
axes, moments about the reference point. A small rotation of the body is the
rotation vector :math:`\delta\boldsymbol\theta` about global axes
(:math:`\delta R = [\delta\boldsymbol\theta]_\times R`); the Euler-angle rates map
to it through

.. math:: \boldsymbol\omega = T\,\dot{\boldsymbol\alpha}, \qquad
    T = \big[R_zR_y\,\mathbf e_x,\; R_z\,\mathbf e_y,\; \mathbf e_z\big].

The body's own loads are those of a floating body as in MoorPy's ``Body`` (M. Hall,
NREL): weight :math:`mg` at the centre of gravity :math:`R\,\mathbf r_G`, buoyancy
:math:`\rho g V` at the metacentre :math:`R\,\mathbf r_M` (constant forces, whose
moments give the hydrostatic restoring in roll and pitch,
:math:`\rho g V\,\overline{GM}` to first order), and the heave restoring
:math:`-\rho g A_{WP}\, z` (J.N. Newman, "Marine Hydrodynamics", MIT Press, 1977,
ch. 6). Their stiffness about the current position (assembled with the lines' in
`skcable.mooring.net_loads`),
:math:`-\partial(\mathbf F, \mathbf M)/\partial(\mathbf x, \delta\boldsymbol\theta)`, is

.. math:: K_{\theta\theta} = -[\mathbf W]_\times[R\mathbf r_G]_\times
    - [\mathbf B]_\times[R\mathbf r_M]_\times, \qquad K_{zz} = \rho g A_{WP}.
"""

from __future__ import annotations

import math

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, real, scalar
from skcable.errors import InputError
from skcable.mooring.line3d import point

__all__ = ["PointBody", "RigidBody", "angular_velocity_map", "rotation_matrix", "skew", "skews"]


def skew(v) -> np.ndarray:
    """The cross-product matrix ``[v]x`` with ``[v]x u = v x u``."""
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def rotation_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` (angles in rad): body axes to global axes."""
    c1, s1 = np.cos(yaw), np.sin(yaw)
    c2, s2 = np.cos(pitch), np.sin(pitch)
    c3, s3 = np.cos(roll), np.sin(roll)
    return np.array(
        [
            [c1 * c2, c1 * s2 * s3 - c3 * s1, s1 * s3 + c1 * c3 * s2],
            [c2 * s1, c1 * c3 + s1 * s2 * s3, c3 * s1 * s2 - c1 * s3],
            [-s2, c2 * s3, c2 * c3],
        ]
    )


def angular_velocity_map(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """``T`` with ``omega = T d(roll, pitch, yaw)/dt``, omega the angular velocity in global axes."""
    c1, s1 = math.cos(yaw), math.sin(yaw)
    c2, s2 = math.cos(pitch), math.sin(pitch)
    return np.array([[c1 * c2, -s1, 0.0], [s1 * c2, c1, 0.0], [-s2, 0.0, 1.0]])


class _Hydrostatics:
    """Weight, buoyancy and waterplane of a body (shared checks)."""

    def _own(self, mass, volume, waterplane_area, rho, g):
        self.mass = scalar("mass", nonnegative("mass", mass))
        self.volume = scalar("volume", nonnegative("volume", volume))
        self.waterplane_area = scalar("waterplane_area", nonnegative("waterplane_area", waterplane_area))
        self.rho = scalar("rho", nonnegative("rho", rho))
        self.g = scalar("g", nonnegative("g", g))
        _plausible.gravity(self.g)
        self.weight = np.array([0.0, 0.0, -self.mass * self.g])
        self.buoyancy = np.array([0.0, 0.0, self.rho * self.g * self.volume])
        self.heave_stiffness = self.rho * self.g * self.waterplane_area


class RigidBody(_Hydrostatics):
    """A rigid body with 6 dofs ``(x, y, z, roll, pitch, yaw)`` (see module docstring).

    Parameters
    ----------
    fairleads : array_like, shape (n, 3), optional
        Where the lines of the one-body `MooringSystem` constructor attach, in body axes
        relative to the reference point (m); one per line, in the order of the lines. Leave
        it out for a body of a system built with ``add_point(..., body=body)``.
    mass : float, optional
        Mass (kg), >= 0, at ``center_of_gravity``.
    volume : float, optional
        Displaced volume (m^3), >= 0; its buoyancy acts at ``metacentre``.
    center_of_gravity, metacentre : array_like, shape (3,), optional
        Body axes (m). Buoyancy at the metacentre gives the linear roll and pitch
        restoring ``rho g V GM`` (as in MoorPy's ``Body``).
    waterplane_area : float, optional
        Waterplane area (m^2), >= 0: heave restoring ``-rho g A_WP z``, z of the
        reference point, zero at the still waterline.
    rho, g : float, optional
        Water density (kg/m^3) and gravity (m/s^2).
    """

    n_dof = 6

    def __init__(
        self,
        fairleads=None,
        *,
        mass=0.0,
        volume=0.0,
        center_of_gravity=(0.0, 0.0, 0.0),
        metacentre=(0.0, 0.0, 0.0),
        waterplane_area=0.0,
        rho=1025.0,
        g=9.81,
    ):
        given = fairleads is not None
        fairleads = real("fairleads", fairleads) if given else np.zeros((0, 3))
        if np.ndim(fairleads) != 2 or np.shape(fairleads)[1] != 3 or (given and len(fairleads) == 0):
            raise InputError(
                "fairleads", f"must be an (n, 3) array of points, got shape {np.shape(fairleads)}"
            )
        self.fairleads = np.array(fairleads, dtype=float)
        self.center_of_gravity = point("center_of_gravity", center_of_gravity)
        self.metacentre = point("metacentre", metacentre)
        self._own(mass, volume, waterplane_area, rho, g)

    def check_position(self, name: str, position) -> np.ndarray:
        q = real(name, position)
        if np.shape(q) != (6,):
            raise InputError(name, f"must be (x, y, z, roll, pitch, yaw), 6 numbers, got shape {np.shape(q)}")
        q = np.array(q, dtype=float)
        if not abs(np.cos(q[4])) > 1e-6:
            raise InputError(name, f"pitch {q[4]!r} rad is at +-pi/2, where roll and yaw are not defined")
        return q

    def rotation(self, q) -> np.ndarray:
        return rotation_matrix(q[3], q[4], q[5])

    def own_force(self, q) -> np.ndarray:
        """Weight, buoyancy and heave restoring as (force, moment) in global axes, shape (6,)."""
        R = self.rotation(q)
        out = np.zeros(6)
        out[:3] = self.weight + self.buoyancy
        out[2] -= self.heave_stiffness * q[2]
        # r x f as [r]x f: np.cross costs more than the products on 3-vectors
        out[3:] = skew(R @ self.center_of_gravity) @ self.weight + skew(R @ self.metacentre) @ self.buoyancy
        return out

    def rate_map(self, q) -> np.ndarray:
        """``∂(x, rotation vector)/∂q``: identity on translations, `angular_velocity_map` on angles."""
        M = np.eye(6)
        M[3:, 3:] = angular_velocity_map(q[3], q[4], q[5])
        return M


def skews(v) -> np.ndarray:
    """`skew` of each row of ``v`` (n, 3), shape (n, 3, 3)."""
    out = np.zeros((len(v), 3, 3))
    out[:, 0, 1], out[:, 0, 2], out[:, 1, 2] = -v[:, 2], v[:, 1], -v[:, 0]
    return out - out.transpose(0, 2, 1)


class PointBody(_Hydrostatics):
    """A point body with 3 dofs ``(x, y, z)``: every line attaches at the point itself.

    Parameters
    ----------
    mass, volume, waterplane_area, rho, g : float, optional
        As for `RigidBody`: weight ``m g`` down, buoyancy ``rho g V`` up, heave
        restoring ``-rho g A_WP z`` (SI units).
    """

    n_dof = 3

    def __init__(self, *, mass=0.0, volume=0.0, waterplane_area=0.0, rho=1025.0, g=9.81):
        self._own(mass, volume, waterplane_area, rho, g)

    def check_position(self, name: str, position) -> np.ndarray:
        return point(name, position)

    def rotation(self, q) -> np.ndarray:
        return np.eye(3)

    def own_force(self, q) -> np.ndarray:
        out = self.weight + self.buoyancy
        out[2] -= self.heave_stiffness * q[2]
        return out

    def rate_map(self, q) -> np.ndarray:
        return np.eye(3)
