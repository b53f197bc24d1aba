r"""The Jacobians of the end forces of the closed forms, in the span and the ends' heights.

For a line solved from its lower end A (`skcable.mooring.choice`), each function gives
``∂(H_A, V_A, H_B, V_B)/∂(span, y_A, y_B)`` (4 × 3) with the seabed fixed; an end resting on the
seabed has no derivative in its height (it cannot move into the seabed): its column is that of
the end and the seabed moved together (a rigid shift, as MoorPy's end stiffnesses assume).
"""

from __future__ import annotations

import math

import numpy as np

from skcable.cable.seabed import anchor_part, grounded_closure

__all__ = [
    "free_jacobian",
    "grounded_jacobian",
    "of_free",
    "of_grounded",
    "of_own",
    "of_sloped",
    "sloped_jacobian",
    "touchdown_jacobian",
]


def _rows_B(k) -> np.ndarray:
    """``∂(H_B, V_B)/∂(span, y_A, y_B)`` from the fairlead stiffness ``k = ∂(H_B, V_B)/∂(span, dh)``."""
    (k_hh, k_hv), (k_vh, k_vv) = np.asarray(k, dtype=float).tolist()
    return np.array([[k_hh, -k_hv, k_hv], [k_vh, -k_vv, k_vv]])


def free_jacobian(k) -> np.ndarray:
    """Nothing touches: ``H_A = H_B``, ``V_A = W - V_B``, a function of ``y_B - y_A``."""
    rows_B = _rows_B(k)
    return np.vstack([rows_B[0], -rows_B[1], rows_B])


def grounded_jacobian(k, friction, H_A) -> np.ndarray:
    """Grounded at A: ``V_A`` constant, ``H_A = max(H - C_B (W - V_B - P_A), 0)``; A and the seabed
    move together (the height columns opposite)."""
    J = np.vstack([np.zeros((2, 3)), _rows_B(k)])
    if H_A > 0:
        J[0] = J[2] + friction * J[3]
    return J


def touchdown_jacobian(solution) -> np.ndarray:
    r"""The touchdown between the ends of one uniform segment (`elastic_catenary`, ``seabed < 0``).

    Its closure (`skcable.cable.seabed.closure.grounded_closure`) at the lower end's
    height ``d`` above the seabed adds the part hanging from A, whose height
    :math:`u^2/(2EA) + u(1 + H/EA) = w d` (:math:`u = T_1 - H`) gives, at constant ``H``,
    :math:`\partial u/\partial d = w/(1 + T_1/EA)`, :math:`\partial V_1/\partial d = T_1 u_d/V_1`
    and, the grounded length shortened by :math:`V_1/w`,
    :math:`\partial f_x/\partial d = (H - T_1)/(V_1 (1 + T_1/EA))`, :math:`\partial f_z/\partial d = -1`
    (at constant ``dh``). Then ``∂(H, V_B)/∂d = -J⁻¹ ∂f/∂d``, ``V_A = V_1(H, d)``, ``H_A = H``;
    in the heights, ``∂/∂y_B = ∂/∂dh`` and ``∂/∂y_A = ∂/∂d - ∂/∂dh``.
    """
    s = solution
    H, V_B, w, EA, depth = float(s.H), float(s.V_B), float(s.w), float(s.EA), -float(s.seabed)
    k = np.asarray(s.stiffness(), dtype=float)
    if bool(s.heap):  # vertical parts at A and B: V = w l, dV/dheight = w / (1 + w l/EA)
        l_A = float(s.length_to_seabed)
        return np.array([[0.0] * 3, [0.0, w / (1.0 + w * l_A / EA), 0.0], [0.0] * 3, [0.0, 0.0, k[1, 1]]])
    V1, T1, _, _, dV1_dH = anchor_part(H, w, EA, depth)
    j = grounded_closure(s.span, s.dh, w, EA, s.length, 0.0, H, V_B, depth)[2:]
    fx_d, fz_d = (H - T1) / (V1 * (1.0 + T1 / EA)), -1.0
    det = j[0] * j[3] - j[1] * j[2]
    dH_d = -(j[3] * fx_d - j[1] * fz_d) / det
    dV_d = -(-j[2] * fx_d + j[0] * fz_d) / det
    dV1_d = T1 * w / (V1 * (1.0 + T1 / EA))
    row_H = [k[0, 0], dH_d - k[0, 1], k[0, 1]]
    row_V = [k[1, 0], dV_d - k[1, 1], k[1, 1]]
    row_VA = [dV1_dH * r for r in row_H]
    row_VA[1] += dV1_d
    return np.array([row_H, row_VA, row_H, row_V])


def sloped_jacobian(solution, k2) -> np.ndarray:
    """``∂(H_A, V_A, H_B, V_B)/∂(span, y_A, y_B)`` of a grounded `SlopedSeabedCatenary` (module
    docstring), from its fairlead stiffness ``k2``."""
    rows_B = _rows_B(k2)
    m = float(solution.seabed_slope)
    cos = 1.0 / math.hypot(1.0, m)
    sin = m * cos
    k = solution.w * (sin + solution.friction * cos)
    dT = np.zeros(3)
    if solution.T_A > 0:
        dT = rows_B[0] / cos + k / solution.w * (rows_B[1] - m * rows_B[0])
    return np.vstack([cos * dT, -sin * dT, rows_B])


# -- the Jacobian of a solution, deferred: ``functools.partial(of_..., solution)`` pickles -------------
def of_free(solution) -> np.ndarray:
    """`free_jacobian` of ``solution``'s stiffness."""
    return free_jacobian(solution.stiffness())


def of_grounded(solution, friction, H_A) -> np.ndarray:
    """`grounded_jacobian` of ``solution``'s stiffness."""
    return grounded_jacobian(solution.stiffness(), friction, H_A)


def of_sloped(solution) -> np.ndarray:
    """`sloped_jacobian` of ``solution`` and its stiffness."""
    return sloped_jacobian(solution, solution.stiffness())


def of_own(solution) -> np.ndarray:
    """The Jacobian ``solution.jacobian()`` gives itself (a line lying on the seabed, a BVP line)."""
    return solution.jacobian()
