r"""Many scenes of one single-segment line at once: Newton's method on arrays, one closure for all.

A mooring system's lines are often of one model (a spread mooring: the same chain from every
anchor). Solving them one by one runs a Python-float Newton per line; here the closure of
`skcable.mooring.segments.state` for a line of **one segment** without attachments,
from an anchor on a flat seabed (``contact``) or hanging free, is evaluated over the array of
scenes, and `skcable._newton2.solve2` runs one Newton per element on its array back end
(H.M. Irvine, "Cable Structures", MIT Press, 1981; J.M. Jonkman, "Dynamics modeling and loads
analysis of an offshore floating wind turbine", NREL, 2007, for the grounded part with
Coulomb friction; `skcable.cable.closure.segment`).

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
from skcable.cable.closure import segment
from skcable.mooring.segments.solution import CLOSURE_TOLERANCE, LineSolution
from skcable.mooring.segments.state import closure_state

__all__ = ["batchable", "solve_batch"]


def batchable(line) -> bool:
    """Whether `solve_batch` takes scenes of ``line``: one heavy segment of constant ``EA``, no
    attachments, no current or shaped seabed."""
    arrays = line.arrays
    return arrays.n == 1 and arrays.w_list[0] > 0 and not np.any(arrays.P) and line.off_plane is None


class _Closure:
    """The closure ``(X - span, Z - dh)``, its Jacobian and the sizes of its terms over arrays of
    ``(H, V)`` (the closure of `solve2`'s array back end): one segment of the one closure,
    `skcable.cable.closure.segment`. Outside the closed form's domain (``H <= 0``, the whole
    line on the seabed) the residual is NaN."""

    def __init__(self, line):
        arrays = line.arrays
        self.L, self.w, self.EA = arrays.L_list[0], arrays.w_list[0], arrays.EA_list[0]
        self.contact, self.m = line.contact, line.friction * arrays.w_list[0]

    def __call__(self, H, V, span, dh, size1, size2):
        X, Z, *jac = segment(H, V, self.w, self.EA, self.L, self.m, self.contact, np)
        return (X - span, Z - dh, *jac, size1, size2)


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
