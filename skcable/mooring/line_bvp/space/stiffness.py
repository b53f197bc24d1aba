r"""The fairlead stiffness of a line in space, from its converged tangent.

``K = ∂S_B/∂r_B`` (N/m, 3 × 3, global axes): the growth of the fairlead's reaction on the line
``S_B`` as the fairlead moves by ``δr_B``, the anchor fixed (``K = −∂F_b/∂r_B``, ``F_b = −S_B``
the force the line exerts on the fairlead: the sign of `skcable.mooring.Line3D.stiffness` and
MoorPy's). By the implicit function theorem on the discrete equations ``F(z; r_B) = 0`` at the
converged state, the active contact set held: ``J_ff ∂z_f/∂r_B = −J_fB`` (one banded
factorisation, three right-hand sides), ``K = J_Bf ∂z_f/∂r_B + J_BB``
(`skcable.mooring.line_bvp.discrete.DiscreteLine.end_sensitivities`). The anchor's reaction moves
by ``∂S_A/∂r_B`` (the coupling a mooring system needs).

**Static or dynamic.** The static stiffness takes each segment's quasi-static compliance
``dε/dT``; the dynamic one, about the converged (mean) state, takes the laws' dynamic compliance
(`skcable.mooring.axial.StaticDynamicRope`: ``1/(α + β T_mean)`` at the local mean tension; the
static one for every other law). The result says which it is.

**The slack stretch.** Where friction holds a slack stretch near the anchor, laid on the seabed
towards the fairlead (`skcable.mooring.line_bvp.space.problem.LineProblem3D.lay_slack`), it turns
with the chord as the fairlead moves across: its held positions' derivatives enter the right-hand
sides (`DiscreteLine.end_sensitivities`). Its end ``s0`` moves too, but that moves the fairlead's
force at second order only: the piece laid or lifted between ``s0`` and ``s0 + δ`` carries a
tension of order ``μ w δ`` (zero at the converged end), so it changes the line's geometry by
``O(δ²)`` (the line re-solved with its end moved by ``±1e-6`` of the length gave the same
fairlead force to the last bit on a flat seabed). The anchor's reaction, zero, does not move.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import one_of
from skcable.errors import ConvergenceError

__all__ = ["KINDS", "FairleadStiffness", "fairlead_stiffness_3d"]

#: the stiffnesses a line gives
KINDS = ("static", "dynamic")


@dataclass(frozen=True)
class FairleadStiffness:
    """A fairlead stiffness (module docstring); an array-like 3 × 3 matrix (N/m).

    Attributes
    ----------
    matrix : ndarray (3, 3)
        ``∂S_B/∂r_B`` (N/m).
    anchor : ndarray (3, 3)
        ``∂S_A/∂r_B`` (N/m), the anchor's reaction on the line.
    kind : str
        ``"static"`` or ``"dynamic"``.
    """

    matrix: np.ndarray
    anchor: np.ndarray
    kind: str

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self.matrix, dtype=dtype)

    def __repr__(self):
        diagonal = ", ".join(f"{v:.6g}" for v in np.diag(self.matrix))
        return f"FairleadStiffness({self.kind}, diagonal=[{diagonal}] N/m)"


def fairlead_stiffness_3d(solution, kind: str = "static") -> FairleadStiffness:
    """The fairlead stiffness of a `LineBVP3DSolution` (module docstring)."""
    one_of("kind", kind, KINDS)
    problem = solution.problem
    if kind == "dynamic":
        K_B, K_A, _ = problem.end_sensitivities(problem.assemble(solution.dofs, dynamic=True))
    else:
        K_B, K_A = (K.copy() for K in solution.sensitivity[:2])  # the solution keeps its own
    if (
        problem.slack_end > 0
    ):  # the seabed holds the stretch and the anchor's node: the anchor carries nothing
        K_A = np.zeros((3, 3))
    if not (np.all(np.isfinite(K_B)) and np.all(np.isfinite(K_A))):
        raise ConvergenceError("fairlead stiffness: non-finite sensitivities", solution.history)
    return FairleadStiffness(K_B, K_A, kind)
