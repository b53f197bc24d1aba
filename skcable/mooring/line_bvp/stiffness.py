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

__all__ = ["SLACK_STEP", "fairlead_stiffness"]

#: the move of the slack stretch's end for its central differences, over the length
SLACK_STEP = 1e-6


def _slack_dof(solution) -> int:
    """The global dof of the tension just past the end of the slack stretch."""
    problem = solution.problem
    tb = problem.tbasis
    at = tb.doflocs[0][tb.element_dofs]  # (2, ne)
    element = int(np.argmin(np.abs(at.min(axis=0) - problem.slack_end)))
    local = int(np.argmin(at[:, element]))
    return 2 * problem.N + int(tb.element_dofs[local, element])


def fairlead_stiffness(solution, slack_solver=None) -> np.ndarray:
    """``∂(H_B, V_B)/∂(span, dh)`` (N/m) of ``solution`` (module docstring); ``slack_solver(s0)``
    re-solves its line with the slack stretch ending at ``s0`` (needed where it has one)."""
    K, _, dz = solution.sensitivity  # computed once per solution (a warm start reads it too)
    s0 = solution.problem.slack_end
    if s0 == 0:
        return K.copy()  # the solution keeps its own
    if slack_solver is None:
        raise InputError("solution", "its slack stretch needs the solver that made it for the stiffness")
    step = SLACK_STEP * solution.length
    plus, minus = slack_solver(s0 + step), slack_solver(s0 - step)
    forces = (np.array([plus.H_B, plus.V_B]) - np.array([minus.H_B, minus.V_B])) / (2 * step)
    g_s0 = (slack_tension(plus)[0] - slack_tension(minus)[0]) / (2 * step)
    g_p = dz[_slack_dof(solution)]
    return K - np.outer(forces, g_p / g_s0)
