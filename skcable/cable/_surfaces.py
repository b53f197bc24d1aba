"""Cables on surfaces (Goicolea 2012, §2.2 and §4).

On a smooth surface with no other load the thread follows a geodesic at
constant tension and presses with ``T/R`` per unit length; with loads the
normal reaction follows eq. (29); on a rough drum the tension grows as
``T0·exp(mu·phi)`` (eq. 32).

Every function broadcasts over its arguments and returns finite numbers:
products and quotients are formed from mantissas and binary exponents
apart (`power_product`), so that only a
result that itself leaves the range of a float raises
`InputError`.
"""

from __future__ import annotations

import math

import numpy as np

from skcable import _plausible
from skcable._checks import TINY, broadcast, nonnegative, positive, real, require
from skcable._xp import namespace
from skcable.cable._special import ldexp_sum, power_product
from skcable.errors import InputError

__all__ = ["capstan", "membrane_tension", "smooth_surface_reaction", "sphere_parallel"]

_EXP_STEP = 700.0  # exp(700) = 1e304: largest chunk of an exponent taken at once


def _in_range(names: str, value, what: str, *, positive_result: bool = True):
    """Raise ``InputError(names, ...)`` unless ``value`` is finite and, for a
    quantity that cannot vanish, at least the smallest normal float."""
    if isinstance(value, np.ndarray):
        bad = ~np.isfinite(value) | ((np.abs(value) < TINY) if positive_result else False)
        if bad.any():
            raise InputError(names, f"give {what} outside the range of a float (over- or underflow)")
        return value
    if not math.isfinite(value) or (positive_result and abs(value) < TINY):
        raise InputError(names, f"give {what} = {value!r}, outside the range of a float (over- or underflow)")
    return value


def capstan(T0, mu, angle):
    r"""Tension at the pulled end of a thread about to slip on a rough drum.

    .. math:: T = T_0\,e^{\mu\varphi}

    (Goicolea 2012, eq. 32; any convex drum section, thread in a normal section).

    Parameters
    ----------
    T0 : float or array_like
        Tension at the held end (N), > 0.
    mu : float or array_like
        Friction coefficient, >= 0.
    angle : float or array_like
        Wrap angle phi (rad), >= 0.

    Raises
    ------
    InputError
        A bad argument, or a tension beyond the largest float.
    """
    T0, mu, angle = positive("T0", T0), nonnegative("mu", mu), nonnegative("angle", angle)
    _plausible.friction(mu, "mu")
    broadcast(T0=T0, mu=mu, angle=angle)
    exponent = mu * angle  # may be inf: then so is the tension
    # T0·e^x in chunks of at most e^700, each partial product below the
    # result: a tiny T0 times a factor beyond the float range stays
    # representable when the result is (T0 >= 5e-324 needs x < 1455)
    T, rest = T0, exponent
    if isinstance(T, np.ndarray) or isinstance(rest, np.ndarray):
        with np.errstate(over="ignore", invalid="ignore"):
            for _ in range(3):
                step = np.minimum(rest, _EXP_STEP)
                T, rest = T * np.exp(step), rest - step
            T = np.where(rest > 0, np.inf, T)
    else:
        for _ in range(3):
            step = min(rest, _EXP_STEP)
            T, rest = T * math.exp(step), rest - step
        T = math.inf if rest > 0 else T
    return _in_range("T0, mu, angle", T, "T0·exp(mu·angle)")


def membrane_tension(p, R):
    """Hoop tension per unit length of a cylindrical membrane, ``T = p R``
    (Goicolea 2012, example 1)."""
    p, R = positive("p", p), positive("R", R)
    broadcast(p=p, R=R)
    return _in_range("p, R", p * R, "p·R")


def smooth_surface_reaction(T, R_n, q_N=0.0):
    r"""Normal reaction per unit length on a thread lying on a smooth surface.

    Goicolea (2012) eq. (29): :math:`q_N + Q + T/R_n = 0`, with ``R_n`` the radius
    of the normal section tangent to the thread (signed: positive when its
    centre lies along the surface normal N) and ``q_N`` the load along N.
    With no load the thread is a geodesic at constant tension.
    """
    T, R_n, q_N = positive("T", T), real("R_n", R_n), real("q_N", q_N)
    require("R_n", R_n != 0, "must be non-zero (use a large radius for a flat surface)", R_n)
    broadcast(T=T, R_n=R_n, q_N=q_N)
    xp = namespace(T, R_n, q_N)
    pressure = ldexp_sum(power_product(1.0, (T, 1), (xp.abs(R_n), -1)))  # T/|R_n|, no intermediate overflow
    _in_range("T, R_n", pressure, "T/R_n")
    sign = R_n / xp.abs(R_n)
    return _in_range("T, R_n, q_N", -q_N - sign * pressure, "q_N + T/R_n", positive_result=False)


def sphere_parallel(q, R, latitude):
    r"""Heavy thread lying on a horizontal parallel of a smooth sphere (Goicolea 2012, example 8).

    .. math:: Q = \frac{q}{\sin\alpha}, \qquad
              T = qR\,\frac{\cos^2\alpha}{\sin\alpha} = qR\cos\alpha\cot\alpha

    Parameters
    ----------
    q : float or array_like
        Weight per unit length (N/m), > 0.
    R : float or array_like
        Radius of the sphere (m), > 0.
    latitude : float or array_like
        Latitude alpha of the parallel (rad), in (0, pi/2): the thread
        needs the sphere's support from below.

    Returns
    -------
    (T, Q) : tension (N) and the sphere's reaction per unit length (N/m).

    Raises
    ------
    InputError
        A bad argument, or a result beyond the range of a float (a parallel
        so close to the pole or equator, or data so large or small, that T
        or Q over- or underflows).
    """
    q, R, latitude = positive("q", q), positive("R", R), positive("latitude", latitude)
    broadcast(q=q, R=R, latitude=latitude)
    xp = namespace(q, R, latitude)
    require("latitude", latitude < 0.5 * xp.pi, "must be below pi/2", latitude)
    sin, cos = xp.sin(latitude), xp.cos(latitude)  # both > 0 on (0, pi/2) in floating point
    T = ldexp_sum(power_product(1.0, (q, 1), (R, 1), (cos, 2), (sin, -1)))
    Q = ldexp_sum(power_product(1.0, (q, 1), (sin, -1)))
    return _in_range("q, R, latitude", T, "T"), _in_range("q, latitude", Q, "Q")
