r"""The fairlead stiffness of a line BVP solution, from its converged tangent.

``K = ∂(H_B, V_B)/∂(span, dh)`` (N/m, rows H_B and V_B, columns span and dh, the anchor fixed)
by the implicit function theorem on the discrete equations ``F(z; span, dh) = 0`` at the
converged state, the active contact set held: one factorisation of the generalized Jacobian,
two right-hand sides (`skcable.mooring.line_bvp.discrete.DiscreteLine.end_sensitivities`). The
touchdown's fitted node is held too: the error of a node off the touchdown grows with the square
of its distance, so holding it changes the derivative by nothing at first order.

**The slack stretch.** Its end ``s0`` is not held but solved for, by ``g(z, s0) = 0``, ``g`` the
tension just past it (`skcable.mooring.line_bvp.slack`): with the sensitivities at fixed ``s0``
(``K_0``, ``∂g/∂p``) and the total ones along ``s0`` (``∂(H_B, V_B)/∂s0``, ``∂g/∂s0``, central
differences of the line re-solved with its end moved by ``±1e-6 L``, two solves from the
solution),

.. math::
    K = K_0 + \frac{\partial (H_B, V_B)}{\partial s_0}\,\frac{d s_0}{d p}, \qquad
    \frac{d s_0}{d p} = -\frac{\partial g/\partial p}{\partial g/\partial s_0}.

Where a transition between contact and free spans is not fitted (a line that leaves a bump and
lands again: nodal contact there), the derivative is that of the discrete line's branch, which
the re-solved lines' differences follow within the discretisation error only.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import InputError
from skcable.mooring.line_bvp.slack import slack_tension

__all__ = ["SLACK_STEP", "fairlead_stiffness", "slack_correction"]

#: the move of the slack stretch's end for its central differences, over the length
SLACK_STEP = 1e-6


def _slack_dof(solution) -> int:
    """The global dof of the tension just past the end of the slack stretch."""
    problem = solution.problem
    tb = problem.tbasis
    at = tb.doflocs[0][tb.element_dofs]  # (2, ne)
    element = int(np.argmin(np.abs(at.min(axis=0) - problem.slack_end)))
    local = int(np.argmin(at[:, element]))
    return problem.dim * problem.N + int(tb.element_dofs[local, element])


def slack_correction(solution, slack_solver, end_force) -> np.ndarray:
    """The stiffness's change as the end ``s0`` of ``solution``'s slack stretch moves with the
    fairlead (module docstring): ``(∂F/∂s0) ⊗ ds0/dp``, ``F = end_force(line)`` the end force the
    stiffness differentiates, ``slack_solver(s0)`` the line re-solved with its stretch ending at
    ``s0``; for a line in space too (`skcable.mooring.line_bvp.space.stiffness`)."""
    if slack_solver is None:
        raise InputError("solution", "its slack stretch needs the solver that made it for the stiffness")
    s0, step = solution.problem.slack_end, SLACK_STEP * solution.length
    plus, minus = slack_solver(s0 + step), slack_solver(s0 - step)
    forces = (end_force(plus) - end_force(minus)) / (2 * step)
    g_s0 = (slack_tension(plus)[0] - slack_tension(minus)[0]) / (2 * step)
    g_p = solution.sensitivity[2][_slack_dof(solution)]
    return -np.outer(forces, g_p / g_s0)


def fairlead_stiffness(solution, slack_solver=None) -> np.ndarray:
    """``∂(H_B, V_B)/∂(span, dh)`` (N/m) of ``solution`` (module docstring); ``slack_solver(s0)``
    re-solves its line with the slack stretch ending at ``s0`` (needed where it has one)."""
    K = solution.sensitivity[0]  # computed once per solution (a warm start reads it too)
    if solution.problem.slack_end == 0:
        return K.copy()  # the solution keeps its own
    return K + slack_correction(solution, slack_solver, lambda line: np.array([line.H_B, line.V_B]))
