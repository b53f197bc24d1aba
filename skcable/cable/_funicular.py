r"""Funicular polygons: weightless cables under point loads (seed 000 §1).

:func:`funicular` (§1.a) takes segments of fixed lengths and loads of any
direction at the joints. Node equilibrium :math:`\mathbf t_{i+1} = \mathbf t_i
- \mathbf P_i` makes every segment force a function of the first one,
:math:`\mathbf t_1`; the seed's 2n+2 unknowns reduce to the two components
of :math:`\mathbf t_1`, fixed by the closure
:math:`\sum_j L_j\,\mathbf t_j/|\mathbf t_j| = \mathbf B`, solved by Newton's
method (analytic Jacobian :math:`\sum_j L_j (I - e_j e_j^T)/|t_j|`).

:func:`funicular_vertical` (§1.b) takes vertical loads at given abscissae
and applies the general cable theorem :math:`H\,y_c(x) = M(x)`: ``H`` times
the depth below the chord equals the bending moment of a simply supported
beam of the same span.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import positive, real, require
from skcable.errors import ConvergenceError, InputError

__all__ = ["Funicular", "FunicularVertical", "funicular", "funicular_vertical"]


@dataclass(frozen=True)
class Funicular:
    """Solution of :func:`funicular`.

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

    def to_vtk(self, path):
        """Write the polygon as VTK (see :func:`skcable.io.funicular_mesh`); returns the path."""
        from skcable.io import funicular_mesh, write

        return write(funicular_mesh(self), path)

    def residual(self) -> float:
        """Largest of the joint force imbalance (relative to the largest
        tension) and the segment-length / closure error (relative to the total
        length)."""
        imbalance = self.forces[1:] - self.forces[:-1] + self.loads
        segments = np.hypot(*np.diff(self.nodes, axis=0).T) - self.lengths
        force_scale, length_scale = self.T.max(), self.lengths.sum()
        return float(
            max(np.abs(imbalance).max(initial=0.0) / force_scale, np.abs(segments).max() / length_scale)
        )


def funicular(B, lengths, loads, *, tol: float = 1e-13, max_iter: int = 100) -> Funicular:
    """Weightless cable of fixed segment lengths under joint loads (seed 000 §1.a).

    Parameters
    ----------
    B : (float, float)
        Support B relative to A = (0, 0) (m).
    lengths : array_like (n+1,)
        Segment lengths from A to B (m), > 0, with ``sum(lengths) > |B|``.
    loads : array_like (n, 2)
        Load ``(Px, Py)`` at each joint, in global axes (y up: a weight has
        ``Py < 0``), N.

    Returns
    -------
    Funicular
        ``T`` (segment tensions), ``angles`` (rad), ``nodes`` (n+2, 2).

    Raises
    ------
    InputError
        Bad lengths or loads, or a span the segments cannot reach.
    ConvergenceError
        Newton failed (for instance a segment that would go slack).

    Examples
    --------
    Seed 000, example 1:

    >>> f = funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    >>> np.round(f.T, 2)
    array([233.04, 205.38, 205.66, 237.85])
    """
    B = real("B", B)
    require("B", np.shape(B) == (2,), "must be a point (x, y)", 0.0)
    lengths = positive("lengths", np.atleast_1d(lengths))
    loads = real("loads", loads)
    loads = np.asarray(loads, dtype=float).reshape(-1, 2) if np.size(loads) else np.zeros((0, 2))
    if lengths.ndim != 1 or len(lengths) != len(loads) + 1:
        raise InputError(
            "lengths", f"need one more segment than loads: {len(lengths)} segments, {len(loads)} loads"
        )
    total, reach = lengths.sum(), float(np.hypot(*B))
    require("lengths", total > reach, f"must add up to more than the distance A-B ({reach:.6g})", total)
    offsets = np.vstack([np.zeros(2), np.cumsum(loads, axis=0)])  # t_j = t_1 - offsets_j

    # start: a parabola-like guess, H from the total load, V sharing the weight
    scale = max(np.abs(loads).sum(), 1e-300)
    t1 = np.array([scale, -0.5 * loads[:, 1].sum() - 0.5 * loads[:, 0].sum() + B[1] / total * scale])
    history = []

    def closure(t1):
        forces = t1 - offsets
        norms = np.hypot(forces[:, 0], forces[:, 1])
        units = forces / norms[:, None]
        return forces, norms, units, units.T @ lengths - B

    forces, norms, units, error = closure(t1)
    for _ in range(max_iter):
        history.append(float(np.abs(error).max() / total))
        if history[-1] < tol:
            break
        jac = np.einsum("j,jab->ab", lengths / norms, np.eye(2) - units[:, :, None] * units[:, None, :])
        try:
            step = -np.linalg.solve(jac, error)
        except np.linalg.LinAlgError as exc:
            raise ConvergenceError(f"funicular: singular Jacobian ({exc})", history) from exc
        alpha = 1.0
        for _ in range(40):  # backtracking on the closure error
            trial = closure(t1 + alpha * step)
            if np.all(trial[1] > 0) and np.abs(trial[3]).max() < np.abs(error).max() * (1 - 1e-4 * alpha):
                break
            alpha *= 0.5
        t1 = t1 + alpha * step
        forces, norms, units, error = trial
    else:
        raise ConvergenceError("funicular: Newton did not converge", history)
    nodes = np.vstack([np.zeros(2), np.cumsum(lengths[:, None] * units, axis=0)])
    nodes[-1] = B
    angles = np.arctan2(forces[:, 1], forces[:, 0])
    return Funicular(norms, angles, nodes, forces, loads, lengths, history)


@dataclass(frozen=True)
class FunicularVertical:
    """Solution of :func:`funicular_vertical`.

    Attributes
    ----------
    H, V_A, V_B : float
        Horizontal tension and upward support reactions (N).
    T : ndarray (n+1,)
        Segment tensions.
    nodes : ndarray (n+2, 2)
        A, the load points, B.
    """

    H: float
    V_A: float
    V_B: float
    T: np.ndarray
    nodes: np.ndarray
    loads: np.ndarray

    def to_vtk(self, path):
        """Write the polygon as VTK (see :func:`skcable.io.funicular_mesh`); returns the path."""
        from skcable.io import funicular_mesh, write

        return write(funicular_mesh(self), path)

    def residual(self) -> float:
        """Largest joint force imbalance relative to the largest tension."""
        dx, dy = np.diff(self.nodes, axis=0).T
        vertical = self.H * dy / dx  # vertical force component in each segment
        joint = vertical[1:] - vertical[:-1] - self.loads[:, 1]
        ends = [vertical[0] + self.V_A, vertical[-1] - self.V_B]
        return float(np.abs(np.concatenate([joint, ends])).max() / self.T.max())


def funicular_vertical(span, dh, loads, *, through=None, H=None) -> FunicularVertical:
    """Weightless cable under vertical point loads (seed 000 §1.b).

    Parameters
    ----------
    span, dh : float
        B = (span, dh) (m).
    loads : array_like (n, 2)
        ``(x, P)`` pairs: abscissa in (0, span) and downward load P (N).
    through : (float, float), optional
        A point (x, y) the cable passes through, x in (0, span).
    H : float, optional
        Horizontal tension. Give exactly one of ``through`` and ``H``.

    Examples
    --------
    Seed 000, example 2 (D at x = 3 m, 5 m below A):

    >>> f = funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    >>> round(f.H, 3), round(f.V_A, 3)
    (28.511, 80.851)
    """
    span = positive("span", span)
    dh = real("dh", dh)
    loads = np.asarray(real("loads", loads), dtype=float).reshape(-1, 2)
    order = np.argsort(loads[:, 0])
    x, P = loads[order, 0], loads[order, 1]
    require("loads", (x > 0) & (x < span), "load abscissae must lie strictly inside (0, span)", x)

    def moment(at):  # simply supported beam of the same span
        at = np.asarray(at, dtype=float)
        reaction_a = (P * (span - x)).sum() / span
        return reaction_a * at - (P * np.clip(at[..., None] - x, 0.0, None)).sum(axis=-1)

    if (through is None) == (H is None):
        raise InputError("constraint", "give exactly one of through=(x, y) and H")
    if H is None:
        xd, yd = real("through", through)
        require("through", 0 < xd < span, "x must lie strictly inside (0, span)", xd)
        depth = dh * xd / span - yd
        require("through", depth > 0, "the point must lie below the chord AB", yd)
        H = float(moment(xd)) / depth
        require("through", H > 0, "needs a positive beam moment there (downward loads)", H)
    H = float(positive("H", H))
    xs = np.concatenate([[0.0], x, [span]])
    ys = dh * xs / span - moment(xs) / H
    V_A = (P * (span - x)).sum() / span - H * dh / span
    V_B = P.sum() - V_A
    vertical = V_A - np.concatenate([[0.0], np.cumsum(P)])
    T = np.hypot(H, vertical)
    return FunicularVertical(H, float(V_A), float(V_B), T, np.column_stack([xs, ys]), np.column_stack([x, P]))
