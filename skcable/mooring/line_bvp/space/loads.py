r"""The loads of a line in space as cable terms: the current's drag on its segments.

`SegmentDrag` is Morison's drag (`skcable.bvp.terms.CurrentDrag`, the same formula,
`skcable.bvp.terms.morison`) with each segment's diameter and coefficients, found from the
arc length ``s`` of each point (a term that reads ``state.s``):

.. math:: \mathbf f = \tfrac12\rho\,d(s)\,|a|\left(C_n(s)|\mathbf v_n|\mathbf v_n
          + C_t(s)|\mathbf v_t|\mathbf v_t\right)

(J.R. Morison, M.P. O'Brien, J.W. Johnson, S.A. Schaaf, "The force exerted by surface waves on
piles", Petroleum Transactions AIME, 1950; J.M. Jonkman, NREL, 2007). ``scale`` multiplies the
force (and its derivatives): the driver's continuation on the current.
"""

from __future__ import annotations

import numpy as np

from skcable.bvp.current import Current
from skcable.bvp.terms import CableForce, CableTerm, morison

__all__ = ["SegmentDrag"]


class SegmentDrag(CableTerm):
    """Morison's drag of ``current`` on segments with per-segment ``diameter``, ``cd_normal``,
    ``cd_tangential`` (arrays over the segments; 0 where a segment has no drag), ``joints`` the
    arc lengths of the segments' ends (m), ``rho`` the water's density (kg/m³)."""

    uses_s = True

    def __init__(
        self, current: Current, joints, diameter, cd_normal, cd_tangential, *, rho: float, scale=1.0
    ):
        self.current, self.joints = current, np.asarray(joints, dtype=float)
        self.k = 0.5 * rho * np.asarray(diameter, dtype=float)
        self.cn, self.ct = np.asarray(cd_normal, dtype=float), np.asarray(cd_tangential, dtype=float)
        self.rho, self.scale = float(rho), float(scale)

    def owner(self, s) -> np.ndarray:
        """The segment of each arc length ``s`` (the upper one at a joint but the last)."""
        n = self.joints.size - 1
        return np.clip(np.searchsorted(self.joints, s, side="right") - 1, 0, n - 1)

    def forces(self, state):
        k = self.owner(state.s)
        v, dv_dh = self.current.velocity(state.height), self.current.gradient(state.height)
        zero = np.zeros((1, *np.shape(state.T)))
        v, dv_dh = np.concatenate([v, zero]), np.concatenate([dv_dh, zero])
        out = morison(v, dv_dh, state.a, self.k[k] * self.scale, self.cn[k], self.ct[k])
        return CableForce(out.f, df_dr=out.df_dr, df_da=out.df_da)

    def outputs(self, state, force):
        return {"CurrentDrag_force_N_per_m": np.asarray(force.f, dtype=float)}

    def __repr__(self):
        return f"SegmentDrag({self.current!r}, {self.k.size} segments, rho={self.rho:g})"
