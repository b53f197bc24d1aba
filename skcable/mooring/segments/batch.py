r"""Many scenes of one single-segment line at once: Newton's method on arrays, one closure for all.

A mooring system's lines are often of one model (a spread mooring: the same chain from every
anchor). Solving them one by one runs a Python-float Newton per line; here the closure of
`skcable.mooring.segments.closure` for a line of **one segment** without attachments,
from an anchor on a flat seabed (``contact``) or hanging free, is evaluated over the array of
scenes, and `skcable._newton2.solve2` runs one Newton per element on its array back end
(H.M. Irvine, "Cable Structures", MIT Press, 1981; J.M. Jonkman, "Dynamics modeling and loads
analysis of an offshore floating wind turbine", NREL, 2007, for the grounded part with
Coulomb friction):

.. math::
    X = \Delta x(H, V, L - a) + a + e_g, \qquad Z = \Delta y(H, V, L - a),

with ``a = max(-(V - wL)/w, 0)`` the grounded length where the line touches down (``V < wL``)
and ``e_g`` its stretch under the friction ``C_B w`` per unit length (`closure.grounded_piece`).

Each converged element is then taken as the scalar closed form at its ``(H, V)``
(`closure_state`) and checked as `Line.solve` checks its solutions: its closure residual over
the chord below `CLOSURE_TOLERANCE` and `LineSolution.validate`. An element that does not
converge here, or fails that check, is returned as None: the caller solves it alone (the same
closure, the same root: this is a faster evaluation of the same Newton, not another model).
"""

from __future__ import annotations

import math

import numpy as np

from skcable._newton2 import solve2
from skcable.mooring.segments.closure import closure_state, grounded_piece, piece_terms
from skcable.mooring.segments.solution import CLOSURE_TOLERANCE, LineSolution

__all__ = ["batchable", "solve_batch"]


def batchable(line) -> bool:
    """Whether `solve_batch` takes scenes of ``line``: one heavy segment of constant ``EA``, no
    attachments, no current or shaped seabed."""
    arrays = line.arrays
    return arrays.n == 1 and arrays.w_list[0] > 0 and not np.any(arrays.P) and line.off_plane is None


class _Closure:
    """The closure ``(X - span, Z - dh)``, its Jacobian and the sizes of its terms over arrays of
    ``(H, V)`` (the closure of `solve2`'s array back end; module docstring). Outside the closed
    form's domain (``H <= 0``, the whole line on the seabed) the residual is NaN."""

    def __init__(self, line):
        arrays = line.arrays
        self.L, self.w, self.EA = arrays.L_list[0], arrays.w_list[0], arrays.EA_list[0]
        self.contact, self.m = line.contact, line.friction * arrays.w_list[0]

    def __call__(self, H, V, span, dh, size1, size2):
        L, w, EA, m = self.L, self.w, self.EA, self.m
        below = V - w * L  # the vertical force at the anchor's end of the segment
        touches = below < 0 if self.contact else np.zeros(np.shape(V), dtype=bool)
        a = np.where(touches, -below / w, 0.0)  # grounded length
        Vb = np.where(touches, 0.0, below)
        dx, dy, x_h, x_v, y_h, y_v = piece_terms(
            np, H, V, Vb, np.hypot(H, V), np.hypot(H, Vb), L - a, w, EA, np.where(touches, 0.0, 1.0)
        )
        # the grounded piece: tension H at the touchdown, falling by m per unit length to the anchor
        da = np.where(a > 0, -1.0 / w, 0.0)  # ∂a/∂V
        stretch, g_h, g_v = grounded_piece(np, H, 1.0, 0.0, a, da, m, EA)[:3]
        X = dx + np.where(touches, a + stretch, 0.0)
        outside = ~(H > 0) | (touches & ~(V > 0))
        f1 = np.where(outside, np.nan, X - span)
        jxh, jxv = x_h + np.where(touches, g_h, 0.0), x_v + np.where(touches, g_v, 0.0)
        return f1, dy - dh, jxh, jxv, y_h, y_v, size1, size2


def solve_batch(line, spans, dhs, starts) -> list:
    """Scenes ``(spans[i], dhs[i])`` of ``line`` (`batchable`; m, ``span > 0``, B above A) from
    the warm starts ``starts[i]`` (its `LineSolution` elsewhere, ``H > 0``): a `LineSolution` per
    scene, validated as `Line.solve` validates its own, or None where the scene is left to
    `Line.solve` (module docstring)."""
    spans, dhs = np.asarray(spans, dtype=float), np.asarray(dhs, dtype=float)
    H0 = np.array([s.state.H for s in starts])
    V0 = np.array([s.state.V for s in starts])
    total = line.arrays.total_length
    result = solve2(
        _Closure(line), H0, V0, (spans, dhs, total + spans, total + np.abs(dhs)), max_iter=40, strict=False
    )
    out: list = []
    for H, V, span, dh, ok in zip(
        result.x.tolist(),
        result.y.tolist(),
        spans.tolist(),
        dhs.tolist(),
        result.converged.tolist(),
        strict=True,
    ):
        out.append(_checked(line, span, dh, H, V) if ok else None)
    return out


def _checked(line, span, dh, H, V):
    """The `LineSolution` of the closed form at ``(H, V)`` where it closes the scene as `Line.solve`
    asks (residual over the chord below `CLOSURE_TOLERANCE`, `LineSolution.validate`), else None."""
    st = closure_state(line.arrays, line.friction, line.contact, H, V) if H > 0 else None
    if st is None or not max(abs(st.X - span), abs(st.Z - dh)) < CLOSURE_TOLERANCE * math.hypot(span, dh):
        return None
    solution = LineSolution(line, span, dh, st)
    solution.validate()
    return solution
