r"""Funicular polygons: weightless cables under point loads (the lecture notes "Cables" §1).

`funicular` (§1.a) takes segments of fixed lengths and loads of any
direction at the joints. Node equilibrium :math:`\mathbf t_{i+1} = \mathbf t_i
- \mathbf P_i` makes every segment force a function of the first one,
:math:`\mathbf t_1`; the notes' 2n+2 unknowns reduce to the two components
of :math:`\mathbf t_1`, fixed by the closure
:math:`\sum_j L_j\,\mathbf t_j/|\mathbf t_j| = \mathbf B`, solved by Newton's
method (analytic Jacobian :math:`\sum_j L_j (I - e_j e_j^T)/|t_j|`).

`funicular_vertical` (§1.b) takes vertical loads at given abscissae
and applies the general cable theorem :math:`H\,y_c(x) = M(x)`: ``H`` times
the depth below the chord equals the bending moment of a simply supported
beam of the same span. Loads at the same abscissa act as one load, their sum.

Both problems are homogeneous: forces scale with the loads and positions
with the lengths. They are solved with loads and lengths divided by powers
of two near their sizes (exact), so that magnitudes from 1e-300 to 1e300
neither over- nor underflow on the way; the result is residual-checked
(`ACCEPT`) before it is returned.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from skcable._checks import positive, real, require, scalar, whole
from skcable._newton2 import solve2
from skcable._show import Shown, counted, quantity
from skcable._xp import power_of_two_near
from skcable.cable.solution import ACCEPT, checked
from skcable.errors import InputError

__all__ = ["Funicular", "FunicularVertical", "funicular", "funicular_vertical"]


_EPS = float(np.finfo(float).eps)


def _closure(tx, ty, offsets, L, target, total):
    """Closure error ``(Σ L_j t_j/|t_j| - B)/Σ L_j`` of the first segment force ``(tx, ty)``,
    its Jacobian ``Σ L_j (I - e_j e_jᵀ)/|t_j|`` (over ``Σ L_j``) and the sizes (1: relative to
    the total length), then the segment forces, their norms and directions; NaN where a
    segment would go slack."""
    forces = np.array([tx, ty]) - offsets
    norms = np.hypot(forces[:, 0], forces[:, 1])
    if not np.all(norms > 0):
        return (math.nan,) * 6 + (1.0, 1.0, forces, norms, forces)
    units = forces / norms[:, None]
    error = (units.T @ L - target) / total
    jac = np.einsum("j,jab->ab", L / norms, np.eye(2) - units[:, :, None] * units[:, None, :]) / total
    return (*(float(v) for v in (*error, *jac.ravel())), 1.0, 1.0, forces, norms, units)


def _finite(name, what, *arrays):
    for array in arrays:
        if not np.all(np.isfinite(array)):
            raise InputError(name, f"gives {what} outside the range of a float (the data are too extreme)")


def _pairs(loads, what):
    """``loads`` as an array of shape (n, 2) of ``what`` pairs (n may be 0)."""
    loads = np.atleast_1d(real("loads", loads))
    if loads.size == 0:
        return np.zeros((0, 2))
    if loads.ndim == 1 and loads.size == 2:
        loads = loads.reshape(1, 2)
    if loads.ndim != 2 or loads.shape[1] != 2:
        raise InputError("loads", f"must be {what} pairs, an array of shape (n, 2); got shape {loads.shape}")
    return loads


class _Polygon(Shown):
    """What both polygons share: their VTK output."""

    def to_vtk(self, path):
        """Write the polygon as VTK (see `skcable.io.funicular_mesh`); returns the path."""
        from skcable.io import funicular_mesh, write

        return write(funicular_mesh(self), path)


@dataclass(frozen=True)
class Funicular(_Polygon):
    """Solution of `funicular`.

    Attributes
    ----------
    T : ndarray (n+1,)
        Segment tensions.
    angles : ndarray (n+1,)
        Segment inclinations to the horizontal (rad, counter-clockwise).
    nodes : ndarray (n+2, 2)
        Support A, the joints, support B.
    forces : ndarray (n+1, 2)
        Segment force vectors (pulling toward B).
    loads : ndarray (n, 2)
        The joint loads.
    lengths : ndarray (n+1,)
        The segment lengths.
    history : list of float
        Closure error (relative to the total length) per Newton iteration.
    """

    T: np.ndarray
    angles: np.ndarray
    nodes: np.ndarray
    forces: np.ndarray
    loads: np.ndarray
    lengths: np.ndarray
    history: list

    def __repr__(self) -> str:
        shown = ", ".join(
            (
                quantity("T", self.T, "N"),
                quantity("angles", self.angles, "rad"),
                quantity("lengths", self.lengths, "m"),
                quantity("B", self.nodes[-1], "m"),
            )
        )
        return f"Funicular({counted([len(self.T)], 'segment')}: {shown})"

    def residual(self) -> float:
        """Largest relative residual: joint equilibrium (relative to the
        largest tension plus the loads, whose running sums the forces carry),
        segment lengths and directions against the forces (relative to the
        total length, the size of the node coordinates)."""
        # exact rescaling: no overflow below
        F, L = power_of_two_near(self.T.max()), power_of_two_near(self.lengths.max())
        forces, loads, T = self.forces / F, self.loads / F, self.T / F
        nodes, lengths = self.nodes / L, self.lengths / L
        force_scale = T.max() + np.abs(loads).sum()
        length_scale = lengths.sum()
        imbalance = forces[1:] - forces[:-1] + loads
        sides = np.diff(nodes, axis=0)
        segments = np.hypot(sides[:, 0], sides[:, 1]) - lengths
        # a side along its force: cross(side, force)/|force| is the side's offset from that line
        offset = (sides[:, 0] * forces[:, 1] - sides[:, 1] * forces[:, 0]) / T
        return float(
            max(
                np.abs(imbalance).max(initial=0.0) / force_scale,
                np.abs(segments).max() / length_scale,
                np.abs(offset).max() / length_scale,
            )
        )


def funicular(B, lengths, loads, *, tol: float = 1e-13, max_iter: int = 100) -> Funicular:
    """Weightless cable of fixed segment lengths under joint loads (the lecture notes "Cables" §1.a).

    Parameters
    ----------
    B : (float, float)
        Support B relative to A = (0, 0) (m).
    lengths : array_like (n+1,)
        Segment lengths from A to B (m), > 0, with ``sum(lengths) > |B|``.
    loads : array_like (n, 2)
        Load ``(Px, Py)`` at each joint, in global axes (y up: a weight has
        ``Py < 0``), N; not all zero.
    tol : float
        Newton stops when the closure error is below ``tol`` times the
        total length; the returned polygon's `residual` is
        checked against ``max(1e-9, 2·tol)``.
    max_iter : int
        Largest number of Newton iterations.

    Returns
    -------
    Funicular
        ``T`` (segment tensions), ``angles`` (rad), ``nodes`` (n+2, 2).

    Raises
    ------
    InputError
        Bad lengths or loads, or a span the segments cannot reach.
    ConvergenceError
        Newton failed (for instance a segment that would go slack), or the
        residual of the polygon is above tolerance.

    Examples
    --------
    The lecture notes "Cables", example 1:

    >>> f = funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    >>> np.round(f.T, 2)
    array([233.04, 205.38, 205.66, 237.85])
    """
    B = real("B", B)
    require("B", np.shape(B) == (2,), "must be a point (x, y)", 0.0)
    lengths = positive("lengths", np.atleast_1d(real("lengths", lengths)))
    loads = _pairs(loads, "(Px, Py)")
    if lengths.ndim != 1 or len(lengths) != len(loads) + 1:
        raise InputError(
            "lengths", f"need one more segment than loads: {len(lengths)} segments, {len(loads)} loads"
        )
    tol = scalar("tol", tol)
    require("tol", tol > 0, "must be > 0", tol)
    max_iter = whole("max_iter", max_iter, 1)
    largest = np.abs(loads).max(initial=0.0)
    if not largest > 0:
        raise InputError(
            "loads", "give at least one non-zero load: an unloaded weightless cable has no shape"
        )
    # homogeneous problem: solve in units where the loads and lengths are of order one
    force_unit, length_unit = power_of_two_near(largest), power_of_two_near(lengths.max())
    P, L, target = loads / force_unit, lengths / length_unit, B / length_unit
    total, reach = L.sum(), float(np.hypot(*target))
    if not total > reach:
        raise InputError(
            "lengths",
            f"must add up to more than the distance A-B ({reach:.6g} x {length_unit:g}), "
            f"got {total:.6g} x {length_unit:g}",
        )
    offsets = np.vstack([np.zeros(2), np.cumsum(P, axis=0)])  # t_j = t_1 - offsets_j

    # start: a parabola-like guess, H from the total load, V sharing the weight
    scale = np.abs(P).sum()
    t1 = (scale, -0.5 * P[:, 1].sum() - 0.5 * P[:, 0].sum() + target[1] / total * scale)
    # the closure's round-off: a few ulps of the n + 1 terms it sums, relative to the total length
    floor = max(tol, 4.0 * _EPS * len(L))
    args = (offsets, L, target, total)
    result = solve2(_closure, *t1, args, floor=floor, slack=0.0, what="funicular", max_iter=max_iter)
    forces, norms, units = result.last[8:]
    history = result.history
    nodes = np.vstack([np.zeros(2), np.cumsum(L[:, None] * units, axis=0)]) * length_unit
    nodes[-1] = B
    forces = forces * force_unit
    T = np.hypot(forces[:, 0], forces[:, 1])
    _finite("loads", "the segment forces", forces, T)
    require("loads", T > 0, "are so small that the segment forces underflow", T)
    angles = np.arctan2(forces[:, 1], forces[:, 0])
    solution = Funicular(T, angles, nodes, forces, loads, lengths, history)
    return checked(solution, history, max(ACCEPT, 2.0 * tol))


@dataclass(frozen=True)
class FunicularVertical(_Polygon):
    """Solution of `funicular_vertical`.

    Attributes
    ----------
    H, V_A, V_B : float
        Horizontal tension and upward support reactions (N).
    T : ndarray (n+1,)
        Segment tensions.
    nodes : ndarray (n+2, 2)
        A, the load points, B.
    loads : ndarray (n, 2)
        The ``(x, P)`` pairs in increasing x, loads at the same abscissa
        summed into one.
    constraint : tuple
        ``("through", (x, y))`` or ``("H", H)``.
    """

    H: float
    V_A: float
    V_B: float
    T: np.ndarray
    nodes: np.ndarray
    loads: np.ndarray
    constraint: tuple = ("H", None)

    def __repr__(self) -> str:
        shown = ", ".join(
            (
                quantity("H", self.H, "N"),
                quantity("V_A", self.V_A, "N"),
                quantity("V_B", self.V_B, "N"),
                quantity("T", self.T, "N"),
                quantity("B", self.nodes[-1], "m"),
            )
        )
        return f"FunicularVertical({counted([len(self.T)], 'segment')}: {shown})"

    def residual(self) -> float:
        """Largest relative residual, each term divided by the size of what cancels in it.

        Segment directions against the segment forces (``H dy + v dx = 0``,
        v the vertical force from ``V_A`` and the loads; relative to the
        tension times the node coordinates, whose differences give dx and
        dy), the tensions (``T = hypot(H, v)``), vertical equilibrium and
        moment about A of the whole cable, and the point the cable was
        asked to pass through.
        """
        # exact rescaling by powers of two, so that nothing below overflows
        F, L = power_of_two_near(self.T.max()), power_of_two_near(np.abs(self.nodes).max())
        H, V_A, V_B, T = self.H / F, self.V_A / F, self.V_B / F, self.T / F
        nodes, x, P = self.nodes / L, self.loads[:, 0] / L, self.loads[:, 1] / F
        span, dh = nodes[-1]
        vertical = V_A - np.concatenate([[0.0], np.cumsum(P)])
        carried = abs(V_A) + np.concatenate([[0.0], np.cumsum(np.abs(P))])
        dx, dy = np.diff(nodes, axis=0).T
        size = np.abs(nodes).sum(axis=1)
        # a segment below the resolution of the scene's coordinates (both ends
        # rounded to the same point) has no direction to check: 0/0 counts as 0
        cross, scale = H * dy + vertical * dx, T * (size[:-1] + size[1:]) + carried * np.abs(dx)
        direction = np.divide(cross, scale, out=np.zeros_like(cross), where=scale > 0)
        tension = (T - np.hypot(H, vertical)) / T
        weight = np.abs(P).sum()
        vertical_sum = (V_A + V_B - P.sum()) / (abs(V_A) + abs(V_B) + weight)
        moment_terms = (V_B * span, H * dh, (P * x).sum())
        moment = (moment_terms[0] - moment_terms[1] - moment_terms[2]) / (
            abs(moment_terms[0]) + abs(moment_terms[1]) + (np.abs(P) * x).sum()
        )
        terms = [np.abs(direction).max(), np.abs(tension).max(), abs(vertical_sum), abs(moment)]
        if self.constraint[0] == "through":
            xd, yd = self.constraint[1][0] / L, self.constraint[1][1] / L
            j = int(np.searchsorted(nodes[:, 0], xd)) - 1
            j = min(max(j, 0), len(dx) - 1)
            y_at = nodes[j, 1] + dy[j] * (xd - nodes[j, 0]) / dx[j]
            terms.append(abs(y_at - yd) / (size[j] + size[j + 1] + abs(xd) + abs(yd)))
        values = np.array(terms, dtype=float)
        return float("nan") if np.isnan(values).any() else float(values.max())


def funicular_vertical(span, dh, loads, *, through=None, H=None) -> FunicularVertical:
    """Weightless cable under vertical point loads (the lecture notes "Cables" §1.b).

    Parameters
    ----------
    span, dh : float
        B = (span, dh) (m).
    loads : array_like (n, 2)
        ``(x, P)`` pairs: abscissa in (0, span) and downward load P (N).
        Loads at the same abscissa are one load, their sum.
    through : (float, float), optional
        A point (x, y) the cable passes through, x in (0, span).
    H : float, optional
        Horizontal tension. Give exactly one of ``through`` and ``H``.

    Raises
    ------
    InputError
        A bad argument (named), or data so extreme that a result leaves
        the range of a float.
    ConvergenceError
        The residual of the polygon exceeds 1e-9 (a bug, reported loudly).

    Examples
    --------
    The lecture notes "Cables", example 2 (D at x = 3 m, 5 m below A):

    >>> f = funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    >>> round(f.H, 3), round(f.V_A, 3)
    (28.511, 80.851)
    """
    span = scalar("span", span)
    require("span", span > 0, "must be > 0", span)
    dh = scalar("dh", dh)
    loads = _pairs(loads, "(x, P)")
    if (through is None) == (H is None):
        raise InputError("constraint", "give exactly one of through=(x, y) and H")
    x, inverse = np.unique(loads[:, 0], return_inverse=True)  # sorted; coincident loads summed
    P = np.bincount(inverse.ravel(), weights=loads[:, 1], minlength=len(x))
    require("loads", (x > 0) & (x < span), "load abscissae must lie strictly inside (0, span)", x)
    require("dh", abs(dh) <= 1e150 * span, "must satisfy |dh| <= 1e150·span", dh)
    # homogeneous problem: lengths and forces divided by powers of two near their sizes
    length_unit = power_of_two_near(max(span, abs(dh)))
    largest = float(np.abs(P).max(initial=0.0))
    force_unit = power_of_two_near(largest) if largest > 0 else 1.0
    span_, dh_, x_, P_ = span / length_unit, dh / length_unit, x / length_unit, P / force_unit
    reaction_a = float((P_ * (span_ - x_)).sum() / span_)

    def moment(at):  # simply supported beam of the same span
        at = np.asarray(at, dtype=float)
        return reaction_a * at - (P_ * np.clip(at[..., None] - x_, 0.0, None)).sum(axis=-1)

    if H is None:
        through = real("through", through)
        require("through", np.shape(through) == (2,), "must be a point (x, y)", 0.0)
        xd, yd = float(through[0]), float(through[1])
        require("through", 0 < xd < span, "x must lie strictly inside (0, span)", xd)
        depth = dh_ * (xd / length_unit) / span_ - yd / length_unit
        require("through", depth > 0, "the point must lie below the chord AB", yd)
        H_ = float(moment(xd / length_unit)) / depth
        require("through", H_ > 0, "needs a positive beam moment there (downward loads)", H_ * force_unit)
        H = H_ * force_unit
        require("through", math.isfinite(H) and H > 0, "gives an H outside the range of a float", H)
        constraint = ("through", (xd, yd))
    else:
        H = scalar("H", H)
        require("H", H > 0, "must be > 0", H)
        H_ = H / force_unit
        constraint = ("H", H)
    xs = np.concatenate([[0.0], x_, [span_]])
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        ys = dh_ * xs / span_ - moment(xs) / H_
        ys[0], ys[-1] = 0.0, dh_  # the supports, exactly
        V_A_ = reaction_a - H_ * dh_ / span_
        vertical = V_A_ - np.concatenate([[0.0], np.cumsum(P_)])
        nodes = np.column_stack([xs, ys]) * length_unit
        V_A, V_B = float(V_A_ * force_unit), float((P_.sum() - V_A_) * force_unit)
        T = np.hypot(H_, vertical) * force_unit
    blame = "through" if constraint[0] == "through" else "H"
    _finite(blame, "the cable's shape", nodes)
    _finite("loads", "the reactions and tensions", V_A, V_B, T)
    require("loads", T > 0, "are so small that the tensions underflow", T)
    solution = FunicularVertical(H, V_A, V_B, T, nodes, np.column_stack([x, P]), constraint)
    return checked(solution, [])
