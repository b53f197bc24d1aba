"""Cables on surfaces (seed 001 §2.2 and §4).

On a smooth surface with no other load the thread follows a geodesic at
constant tension and presses with ``T/R`` per unit length; with loads the
normal reaction follows eq. (29); on a rough drum the tension grows as
``T0·exp(mu·phi)`` (eq. 32).
"""

from __future__ import annotations

from skcable._checks import nonnegative, positive, real, require
from skcable._xp import namespace

__all__ = ["capstan", "membrane_tension", "smooth_surface_reaction", "sphere_parallel"]


def capstan(T0, mu, angle):
    r"""Tension at the pulled end of a thread about to slip on a rough drum.

    .. math:: T = T_0\,e^{\mu\varphi}

    (seed 001 eq. 32; any convex drum section, thread in a normal section).

    Parameters
    ----------
    T0 : float or array_like
        Tension at the held end (N), > 0.
    mu : float or array_like
        Friction coefficient, >= 0.
    angle : float or array_like
        Wrap angle phi (rad), >= 0.
    """
    T0, mu, angle = positive("T0", T0), nonnegative("mu", mu), nonnegative("angle", angle)
    return T0 * namespace(T0, mu, angle).exp(mu * angle)


def membrane_tension(p, R):
    """Hoop tension per unit length of a cylindrical membrane, ``T = p R``
    (seed 001 example 1)."""
    return positive("p", p) * positive("R", R)


def smooth_surface_reaction(T, R_n, q_N=0.0):
    r"""Normal reaction per unit length on a thread lying on a smooth surface.

    Seed 001 eq. (29): :math:`q_N + Q + T/R_n = 0`, with ``R_n`` the radius
    of the normal section tangent to the thread (signed: positive when its
    centre lies along the surface normal N) and ``q_N`` the load along N.
    With no load the thread is a geodesic at constant tension.
    """
    T, R_n, q_N = positive("T", T), real("R_n", R_n), real("q_N", q_N)
    require("R_n", R_n != 0, "must be non-zero (use a large radius for a flat surface)", R_n)
    return -q_N - T / R_n


def sphere_parallel(q, R, latitude):
    r"""Heavy thread lying on a horizontal parallel of a smooth sphere (seed 001 example 8).

    .. math:: Q = \frac{q}{\sin\alpha}, \qquad
              T = qR\,\frac{\cos^2\alpha}{\sin\alpha} = qR\cos\alpha\cot\alpha

    Parameters
    ----------
    q : float
        Weight per unit length (N/m).
    R : float
        Radius of the sphere (m).
    latitude : float
        Latitude alpha of the parallel (rad), in (0, pi/2): the thread
        needs the sphere's support from below.

    Returns
    -------
    (T, Q) : tension (N) and the sphere's reaction per unit length (N/m).
    """
    q, R, latitude = positive("q", q), positive("R", R), positive("latitude", latitude)
    xp = namespace(q, R, latitude)
    require("latitude", latitude < 0.5 * xp.pi, "must be below pi/2", latitude)
    sin, cos = xp.sin(latitude), xp.cos(latitude)
    return q * R * cos * cos / sin, q / sin
