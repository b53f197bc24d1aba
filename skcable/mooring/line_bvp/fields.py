"""The fields of a converged line BVP at any arc length, in the plane and in space.

`LineFields` is what the plane line's solution (`skcable.mooring.line_bvp.solution`) and the line
in space's (`skcable.mooring.line_bvp_3d.solution`) share: the arc lengths checked, the state
(positions, tangent, tension) through `skcable.mooring.line_bvp.discrete.DiscreteLine.state_at`,
the tension field, the weight, the tensions at the segments' ends and the samples the writers
read. Each solution adds its view of the ends: ``H`` and ``V`` in the plane, force vectors in
space.
"""

from __future__ import annotations

import numpy as np

from skcable._checks import real, require, whole
from skcable.bvp.terms import CableState, term_outputs
from skcable.mooring.line_bvp.discrete import DiscreteLine

__all__ = ["LineFields"]


class LineFields:
    """The fields of a converged discrete line (module docstring): a solution sets ``problem``
    (a `skcable.mooring.line_bvp.discrete.DiscreteLine`), ``dofs`` and ``length`` (m)."""

    problem: DiscreteLine
    dofs: np.ndarray
    length: float

    def arc(self, s) -> np.ndarray:
        """``s`` (m) as an array, checked to lie on the line ``[0, length]``."""
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def state_at(self, s) -> CableState:
        """The line's `skcable.bvp.terms.CableState` at arc lengths ``s`` (m), flattened."""
        return self.problem.state_at(self.dofs, self.arc(s).ravel())

    def positions(self, s) -> np.ndarray:
        """Position (m) at unstretched arc lengths ``s`` from the anchor: ``(*s.shape, dim)``."""
        s = self.arc(s)
        state = self.state_at(s)
        return state.position.T.reshape(*s.shape, -1)

    def tangent(self, s) -> np.ndarray:
        """The unit tangent towards the fairlead at ``s``: ``(*s.shape, dim)``."""
        s = self.arc(s)
        a = self.state_at(s).a
        return (a / np.sqrt(np.sum(a * a, axis=0))).T.reshape(*s.shape, -1)

    def T_of_s(self, s):
        """The tension field (N) at unstretched arc lengths ``s`` (m): P1-DG, the value of the
        element containing ``s``, accurate to O(h²) at the nodes; `T_A` and `T_B` (the supports'
        reactions) are the accurate end values."""
        s = self.arc(s)
        return self.problem.tension_at(self.dofs, s).reshape(s.shape)[()]

    @property
    def weight(self) -> float:
        """Total weight of the line and its point loads (N, downward)."""
        problem = self.problem
        return problem.weight + float(np.sum(problem.point_values))

    def end_tensions(self, T_A: float, T_B: float) -> tuple[np.ndarray, np.ndarray]:
        """``(T_lower, T_upper)`` per segment (N): the tension field just inside each segment at
        its ends (1e-9 of its length in), the supports' reactions ``T_A`` and ``T_B`` at the
        line's ends."""
        joints = self.problem.joints
        inside = 1e-9 * np.diff(joints)
        T_lower = np.atleast_1d(np.array(self.T_of_s(joints[:-1] + inside), dtype=float))
        T_upper = np.atleast_1d(np.array(self.T_of_s(joints[1:] - inside), dtype=float))
        T_lower[0], T_upper[-1] = T_A, T_B
        return T_lower, T_upper

    def sampled(self, n: int) -> tuple[np.ndarray, CableState, np.ndarray, dict]:
        """``(s, state, load, outputs)`` at ``n`` points evenly spaced in unstretched arc length:
        the state there, the distributed load (n, dim) (N/m: the weight and the cable terms'
        force, `DiscreteLine.forces_at`) and what the cable terms name (`CableTerm.outputs`, the
        points first: their force ``<Term>_force_N_per_m`` (n, dim) at least)."""
        s = np.linspace(0.0, self.length, whole("n", n, 2))
        state = self.state_at(s)
        load = self.problem.forces_at(self.dofs, s).T
        terms = self.problem.terms
        outputs = {k: np.moveaxis(np.asarray(v), -1, 0) for k, v in term_outputs(terms, state).items()}
        return s, state, load, outputs
