r"""A uniform line touching down between its ends on a frictionless straight slope below both.

From the end on the slope's lower side (A where ``tan α > 0``), the line hangs to a tangent
touchdown with the horizontal force :math:`H_1` and the tension :math:`T_1 = H_1/\cos\alpha`,
lies straight on the slope over ``ℓ``, its tension growing uphill to
:math:`T_2 = T_1 + w\ell\sin\alpha` (no friction: the weight's component along the slope), and
hangs tangentially from there with :math:`H_2 = T_2\cos\alpha` to the other end. The closure in
:math:`(H_2, \ell, s_1)`, ``s_1`` the length of the first hanging part: the first touchdown on the
slope and the other end reached. The hanging parts are Irvine's elastic catenary
(`skcable.cable.closure.hanging`; H.M. Irvine, "Cable Structures", MIT Press, 1981), the lying
part and the part past it Jonkman's line on a slope without friction
(`skcable.cable.closure.on_slope`; J.M. Jonkman, NREL, 2007).

`slope_touchdown` solves it by MINPACK's ``hybr`` along a continuation in the slope, turned about
the foot of the slope under the lower end (else about the point where the free line dips deepest
below it), from the flat seabed through that point's three-part line
(`skcable.cable.seabed.elastic_catenary` with ``seabed < 0``, exact at ``tan α = 0``); a line
longer than the slope holds taut (`skcable.cable.seabed.taut_length_on_slope`) has no such state.
`SlopeTouchdownLine` is the solution (the result protocol, `skcable.results`).
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import NamedTuple

import numpy as np

from skcable._checks import positive, scalar, whole
from skcable.cable.arc_samples import arc_samples, write_profile
from skcable.cable.closure import hanging, on_slope, slope_frame
from skcable.cable.seabed.sloped import taut_length_on_slope
from skcable.cable.seabed.solve import elastic_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.results import ProfileMixin

__all__ = ["SlopeTouchdown", "SlopeTouchdownLine", "slope_touchdown", "touchdown_on_slope"]

#: the closure's residual (over the length) at which its root is taken
RESIDUAL = 1e-12
#: the move of the span and the ends' heights (over the scene's size) for the Jacobian's differences
STEP = 1e-6


class SlopeTouchdown(NamedTuple):
    """The three-part line (module docstring) from the end on the slope's lower side: the
    horizontal force ``H_low`` of its part hanging from there (N), that part's length ``s_low``,
    the length ``lying`` on the slope (m, unstretched), and whether that end is B (``from_b``: the
    arc lengths run from B)."""

    H_low: float
    s_low: float
    lying: float
    from_b: bool


def _from_low_end(span, dh, seabed, slope):
    """The scene seen from the end on the slope's lower side: ``(span, dh, seabed, slope, from_b)``,
    the slope rising from there."""
    if slope < 0:
        return span, -dh, seabed + slope * span - dh, -slope, True
    return span, dh, seabed, slope, False


def _closure(span, dh, w, EA, L, b, m):
    """The residual (over ``L``) of the three-part line at ``(H_2, ℓ, s_1)`` from its lower end
    (``m > 0``), a large one off ``H_2 > 0, ℓ > 0, s_1 > 0, s_1 + ℓ < L`` and a positive tension
    at the lower touchdown."""
    cos, sin = slope_frame(m)

    def residual(u):
        H2, ell, s1 = u
        T1 = H2 / cos - w * sin * ell
        if not (H2 > 0 and ell > 0 and s1 > 0 and s1 + ell < L and T1 > 0):
            return np.full(3, 1e3)
        H1 = T1 * cos
        run, rise = on_slope(H2, ell, w, EA, L - s1, m, 0.0)[:2]  # the lower touchdown to the far end
        x, z = hanging(H1, -H1 * m, w, EA, s1)[:2]  # the lower touchdown to the near end, mirrored
        return np.array([-z - (b + m * x), x + run - span, -z + rise - dh]) / L

    return residual


def _root(residual, u):
    """``hybr``'s root of ``residual`` from ``u``, or None where it ends off it (`RESIDUAL`)."""
    from scipy.optimize import root

    sol = root(residual, u, method="hybr", options={"xtol": 1e-14})
    return sol.x if np.max(np.abs(residual(sol.x))) <= RESIDUAL else None


def _touchdown(u, w, m, from_b) -> SlopeTouchdown:
    """The `SlopeTouchdown` of the closure's unknowns ``u = (H_2, ℓ, s_1)``."""
    H2, ell, s1 = (float(v) for v in u)
    cos, sin = slope_frame(m)
    return SlopeTouchdown((H2 / cos - w * sin * ell) * cos, s1, ell, from_b)


def _unknowns(touchdown: SlopeTouchdown, w, m) -> np.ndarray:
    """The closure's unknowns ``(H_2, ℓ, s_1)`` of ``touchdown`` (the inverse of `_touchdown`)."""
    cos, sin = slope_frame(m)
    H2 = (touchdown.H_low / cos + w * sin * touchdown.lying) * cos
    return np.array([H2, touchdown.lying, touchdown.s_low])


def slope_touchdown(span, dh, w, EA, length, *, seabed, seabed_slope) -> SlopeTouchdown | None:
    """The three-part line (module docstring) from A = (0, 0) to B = (span, dh) over the
    frictionless slope ``y = seabed + x tan α`` below both, or None where it has no such state (it
    clears the slope, or it is at least `skcable.cable.seabed.taut_length_on_slope` long) or where
    the continuation does not reach it.

    Parameters
    ----------
    span, dh : float
        B relative to A (m), ``span > 0``.
    w, EA : float
        Weight per unstretched length (N/m) and axial stiffness (N), > 0.
    length : float
        Unstretched length (m).
    seabed, seabed_slope : float
        The seabed under A relative to A (m, < 0) and ``tan α`` (nonzero), B above it.
    """
    longest = taut_length_on_slope(span, dh, w, EA, seabed=seabed, seabed_slope=seabed_slope)  # checks
    length = scalar("length", positive("length", length))
    return _below(span, dh, w, EA, length, seabed, seabed_slope, longest)


def _below(span, dh, w, EA, length, seabed, seabed_slope, longest) -> SlopeTouchdown | None:
    """`slope_touchdown` of a checked scene whose `taut_length_on_slope` is ``longest`` (m)."""
    if length >= longest:
        return None
    span, dh, b, m, from_b = _from_low_end(float(span), float(dh), float(seabed), float(seabed_slope))
    u = _continued(span, dh, w, EA, length, b, m, 0.0)  # about the foot under the lower end
    if u is None:
        deepest = _pivot(span, dh, w, EA, length, b, m)  # else where the free line dips deepest
        u = None if deepest is None else _continued(span, dh, w, EA, length, b, m, deepest)
    return None if u is None else _touchdown(u, w, m, from_b)


def _continued(span, dh, w, EA, length, b, m, pivot) -> np.ndarray | None:
    """The closure's root ``(H_2, ℓ, s_1)`` by continuation in the slope turned about ``x =
    pivot`` from the flat seabed through the slope there (`slope_touchdown`), or None where that
    flat seabed's line does not touch it or a step of 1/256 fails."""
    level = b + m * pivot
    try:
        flat = elastic_catenary(span, dh, w, EA, length=length, seabed=level)
    except (InputError, ConvergenceError):
        return None
    if not (0.0 < flat.length_on_seabed < length and flat.H > 0 and flat.V_A > 0):
        return None  # no three-part line on the flat seabed to continue from
    u = np.array([float(flat.H), float(flat.length_on_seabed), float(flat.V_A) / w])
    done, step = 0.0, 0.25
    while done < 1.0:
        trial = min(1.0, done + step)  # the slope turned about the pivot: trial m from level there
        found = _root(_closure(span, dh, w, EA, length, level - trial * m * pivot, trial * m), u)
        if found is not None:
            u, done, step = found, trial, min(2.0 * step, 0.25)
        else:
            step *= 0.5
            if step < 1.0 / 256.0:
                return None
    return u


def _pivot(span, dh, w, EA, length, b, m) -> float | None:
    """Where (x, m) the free line dips deepest below the slope ``b + m x``: the slope turns about
    it from the flat seabed there (`slope_touchdown`), which the free line dips below too; None
    where it clears the slope, or where that flat seabed would not lie below the lower end."""
    from skcable.cable._elastic import elastic_catenary as free_catenary

    try:
        free = free_catenary(span, dh, w, EA, length=length)
    except (InputError, ConvergenceError):
        return None
    xy = np.asarray(free.xy(np.linspace(0.0, length, 513)), dtype=float)
    below = b + m * xy[:, 0] - xy[:, 1]
    k = int(np.argmax(below))
    if not below[k] > 0.0 or not b + m * xy[k, 0] < 0.0:
        return None
    return float(xy[k, 0])


def _three_parts(touchdown: SlopeTouchdown, w, EA, slope, s):
    """``(x, y, T, angle)`` at the arc lengths ``s`` (m) from the end on the slope's lower side of
    ``touchdown`` (that end at the origin, the slope rising by ``|slope|`` away from it): hanging
    (Irvine's elastic catenary), lying straight with ``dT/ds = w sin α``, hanging again; the
    angle (rad) of the line above the horizontal along its direction of travel."""
    m = abs(slope)
    cos, sin = slope_frame(m)
    H1, s1, ell = touchdown.H_low, touchdown.s_low, touchdown.lying
    T1 = H1 / cos
    s = np.asarray(s, dtype=float)

    def piece(H, V0, r):
        """Run, rise (Irvine's elastic catenary, `skcable.cable.closure.hanging`), tension and
        angle of a hanging piece at ``r`` (m) from its start, whose vertical tension there is
        ``V0`` (N, along its direction of travel)."""
        r = np.asarray(r, dtype=float)
        flat = np.atleast_1d(r).ravel()
        x, y = (
            v.reshape(r.shape)
            for v in hanging(np.full_like(flat, H), np.full_like(flat, V0), w, EA, flat, np)[:2]
        )
        return x, y, np.hypot(H, V0 + w * r), np.arctan2(V0 + w * r, H)

    near = piece(H1, H1 * m - w * s1, np.minimum(s, s1))
    x1, y1 = (float(v) for v in piece(H1, H1 * m - w * s1, np.array(s1))[:2])
    u = np.clip(s - s1, 0.0, ell)
    G = u + (T1 * u + 0.5 * w * sin * u * u) / EA
    G2 = ell + (T1 * ell + 0.5 * w * sin * ell * ell) / EA
    H2 = (T1 + w * sin * ell) * cos
    r = np.maximum(s - s1 - ell, 0.0)
    far = piece(H2, H2 * m, r)
    x = np.where(s <= s1, near[0], np.where(r > 0, x1 + G2 * cos + far[0], x1 + G * cos))
    y = np.where(s <= s1, near[1], np.where(r > 0, y1 + G2 * sin + far[1], y1 + G * sin))
    T = np.where(s <= s1, near[2], np.where(r > 0, far[2], T1 + w * sin * u))
    angle = np.where(s <= s1, near[3], np.where(r > 0, far[3], math.atan(m)))
    return x, y, T, angle


def touchdown_on_slope(span, dh, w, EA, *, length, seabed, seabed_slope) -> SlopeTouchdownLine:
    """The `SlopeTouchdownLine` of `slope_touchdown`'s scene (``EA`` finite). ``InputError("length")``
    where the line is longer than the slope holds taut (`skcable.cable.seabed.refuse_slack_on_slope`),
    ``InputError("seabed")`` where the free line does not dip below the slope at any of 513 points
    evenly spaced along it (no touchdown: the free elastic catenary is the line), else a
    `ConvergenceError` where the continuation does not reach it."""
    from skcable.cable.seabed.sloped import refuse_slack_on_slope

    length = scalar("length", positive("length", length))
    EA = scalar("EA", positive("EA", EA))  # finite: the flat seabed's closed form it continues from
    longest = refuse_slack_on_slope(span, dh, w, EA, length, seabed=seabed, seabed_slope=seabed_slope)
    touchdown = _below(span, dh, w, EA, length, seabed, seabed_slope, longest)  # the scene checked
    if touchdown is None:
        span_l, dh_l, b_l, m_l, _ = _from_low_end(float(span), float(dh), float(seabed), float(seabed_slope))
        if _pivot(span_l, dh_l, w, EA, length, b_l, m_l) is None:
            raise InputError(
                "seabed",
                "the free line does not dip below the slope at any of 513 points along it (or only where "
                "the slope lies above the lower end): no touchdown; the free elastic catenary is the line",
            )
        raise ConvergenceError(
            "touchdown_on_slope: the continuation in the slope from the flat seabed's line did not reach "
            "the line on the slope",
            [],
        )
    scene = (float(span), float(dh), float(w), float(EA), float(length), float(seabed), float(seabed_slope))
    return SlopeTouchdownLine(*scene, touchdown)


class SlopeTouchdownLine(ProfileMixin):
    """The three-part line (module docstring) from A = (0, 0) to B = (span, dh).

    Attributes
    ----------
    H_A, V_A, H_B, V_B, T_A, T_B : float
        End forces by end (N): horizontal tension (each part's own: friction-free, the slope's
        normal reaction changes it), upward reaction, tension.
    length, length_on_seabed : float
        Unstretched length (m) and the part lying on the slope (m).
    touchdown : SlopeTouchdown
        The closure's root, from the end on the slope's lower side.
    """

    heap = False

    def __init__(self, span, dh, w, EA, length, seabed, slope, touchdown: SlopeTouchdown):
        self.span, self.dh, self.w, self.EA, self.length = span, dh, w, EA, length
        self.seabed, self.seabed_slope, self.touchdown = seabed, slope, touchdown
        m = abs(slope)
        cos, sin = slope_frame(m)
        H1, s1, ell = touchdown.H_low, touchdown.s_low, touchdown.lying
        H2 = (H1 / cos + w * sin * ell) * cos
        low: tuple[float, float] = (H1, w * s1 - H1 * m)
        high: tuple[float, float] = (H2, H2 * m + w * (length - s1 - ell))
        (self.H_A, self.V_A), (self.H_B, self.V_B) = (high, low) if touchdown.from_b else (low, high)
        self.T_A, self.T_B = math.hypot(self.H_A, self.V_A), math.hypot(self.H_B, self.V_B)
        self.length_on_seabed = ell
        if not all(map(math.isfinite, (self.H_A, self.V_A, self.H_B, self.V_B))):
            raise ConvergenceError("touchdown_on_slope: non-finite end forces", [])

    def _parts(self, s):
        """``(x, y, T, angle)`` at the arc lengths ``s`` from A (`_three_parts`)."""
        s = np.asarray(s, dtype=float)
        if self.touchdown.from_b:  # its arc lengths and frame from B: x' = span - x, y' = y - dh
            x, y, T, angle = _three_parts(self.touchdown, self.w, self.EA, self.seabed_slope, self.length - s)
            return self.span - x, self.dh + y, T, -angle
        return _three_parts(self.touchdown, self.w, self.EA, self.seabed_slope, s)

    def xy(self, s):
        """Positions ``(..., 2)`` (m) relative to A at unstretched arc length ``s`` from A."""
        x, y = self._parts(s)[:2]
        return np.stack([x, y], axis=-1)

    def samples(self, n: int = 201) -> dict:
        """``n`` points evenly spaced in unstretched arc length, the input of `to_vtk`: ``xy``
        (n, 2) m, ``tension`` (N), ``angle`` (rad above the horizontal), ``load`` (n, 2) N/m."""
        x, y, T, angle = self._parts(np.linspace(0.0, self.length, whole("n", n, 2)))
        return arc_samples(x, y, T, angle, self.w)

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A."""
        return self._parts(s)[2]

    @cached_property
    def _jacobian(self) -> np.ndarray:
        """``∂(H_A, V_A, H_B, V_B)/∂(span, y_A, y_B)`` (N/m), the slope fixed: central differences
        of the closure re-solved from this root (`STEP` of the scene's size)."""
        h = STEP * max(self.span, abs(self.dh), abs(self.seabed))
        moves = ((h, 0.0, 0.0), (0.0, -h, -h), (0.0, h, 0.0))  # span; y_A (dh and seabed by -h); y_B
        columns = []
        for d_span, d_dh, d_seabed in moves:
            ends = [self._moved(sign * d_span, sign * d_dh, sign * d_seabed) for sign in (1.0, -1.0)]
            columns.append((ends[0] - ends[1]) / (2.0 * h))
        return np.array(columns).T

    def _moved(self, d_span, d_dh, d_seabed) -> np.ndarray:
        """``(H_A, V_A, H_B, V_B)`` of the line with its span, height and seabed moved."""
        span, dh, b, m, from_b = _from_low_end(
            self.span + d_span, self.dh + d_dh, self.seabed + d_seabed, self.seabed_slope
        )
        found = _root(
            _closure(span, dh, self.w, self.EA, self.length, b, m), _unknowns(self.touchdown, self.w, m)
        )
        if found is None:
            raise ConvergenceError(
                "touchdown_on_slope: the stiffness's neighbouring line did not converge", []
            )
        scene = (self.span + d_span, self.dh + d_dh, self.w, self.EA, self.length, self.seabed + d_seabed)
        moved = SlopeTouchdownLine(*scene, self.seabed_slope, _touchdown(found, self.w, m, from_b))
        return np.array([moved.H_A, moved.V_A, moved.H_B, moved.V_B])

    def jacobian(self) -> np.ndarray:
        """``∂(H_A, V_A, H_B, V_B)/∂(span, y_A, y_B)`` (N/m), shape (4, 3), the slope fixed."""
        return self._jacobian.copy()

    def stiffness(self) -> np.ndarray:
        """``∂(H_B, V_B)/∂(span, dh)`` (N/m) with A and the slope fixed, shape (2, 2)."""
        return self._jacobian[2:][:, [0, 2]].copy()

    def tensions(self):
        """One row: ``segment, length, w, EA`` (SI), ``T_lower``, ``T_upper``, ``H_lower``,
        ``H_upper`` (N, at the ends towards A and B), ``T_max`` (N: the tension is largest at an end)
        and ``grounded_length`` (m)."""
        import pandas as pd

        return pd.DataFrame(
            {
                "segment": [0], "length": [self.length], "w": [self.w], "EA": [self.EA],
                "T_lower": [self.T_A], "T_upper": [self.T_B], "H_lower": [self.H_A], "H_upper": [self.H_B],
                "T_max": [max(self.T_A, self.T_B)], "grounded_length": [self.length_on_seabed],
            }
        )  # fmt: skip

    def to_vtk(self, path, n: int = 201):
        """Write the profile as a VTK polyline (see `skcable.io.cable_mesh`); returns the path."""
        return write_profile(self, path, n)

    def __repr__(self):
        shown = ("H_A", "V_A", "H_B", "V_B", "T_A", "T_B", "length", "length_on_seabed")
        numbers = ", ".join(f"{name}={float(getattr(self, name)):.9g}" for name in shown)
        scene = f"span={self.span:g}, dh={self.dh:g}, seabed_slope={self.seabed_slope:g}"
        return f"SlopeTouchdownLine({scene}: {numbers})"
