r"""The closure equations of a line on a flat seabed, and the closed-form parts they use.

Anchor A at (0, 0), fairlead B at (span, dh), weight ``w`` per unstretched length,
axial stiffness ``EA``, unstretched length ``L``, friction force ``mu_w = C_B w`` per
unit grounded length. The part ``L_B = L - V_B/w`` rests on the seabed and the rest
hangs as an elastic catenary tangent to the seabed at the touchdown. The closure in
the fairlead forces ``(H, V_B)`` is that of J.M. Jonkman, "Dynamics modeling and loads
analysis of an offshore floating wind turbine", NREL, 2007 (also MoorPy's):

.. math::
    X = L_B + \frac{H}{w}\operatorname{asinh}\frac{V_B}{H} + \frac{H L}{EA}
        + \frac{C_B w}{2EA}\Big[-L_B^2 + (L_B - \tfrac{H}{C_B w})
          \max(L_B - \tfrac{H}{C_B w}, 0)\Big], \qquad
    Z = \frac{H}{w}\Big(\sqrt{1 + (V_B/H)^2} - 1\Big) + \frac{V_B^2}{2 EA w},

written with the tensioned grounded length :math:`\ell = \min(L_B, H/(C_B w))`: the
grounded part stretches by :math:`(H\ell - C_B w \ell^2/2)/EA`, the anchor keeps
:math:`H_A = \max(H - C_B w L_B, 0)`.

With the anchor a height ``d`` above the seabed (no friction) the line first hangs from
A down to a touchdown (its vertex on the seabed): its height
:math:`(T_1 - H)/w + V_1^2/(2 EA w) = d` is a quadratic in :math:`u = T_1 - H`, so
:math:`V_1(H)` is closed-form (`anchor_part`) and the same closure holds with
:math:`x_1(H)` added to X and :math:`s_1 = V_1/w` taken from the grounded length.

Every function takes Python floats (`skcable._xp.scalar_math`) or NumPy arrays.
"""

from __future__ import annotations

import numpy as np

from skcable._xp import namespace, scalar_math

__all__ = ["anchor_part", "grounded_closure", "hanging_length", "tensioned"]


def tensioned(H, L_B, mu_w):
    """Length of the grounded part that carries tension, ``min(L_B, H/(C_B w))`` (m)."""
    if namespace(H, L_B, mu_w) is scalar_math:
        return min(L_B, H / mu_w) if mu_w > 0 else L_B
    with np.errstate(divide="ignore"):
        reach = np.where(mu_w > 0, H / np.where(mu_w > 0, mu_w, 1.0), np.inf)
    return np.minimum(L_B, reach)


def anchor_part(H, w, EA, depth):
    """The part hanging from an anchor ``depth`` above the seabed down to its
    touchdown (vertex on the seabed), in closed form for a given ``H``.

    Its height ``(T_1 - H)/w + V_1^2/(2 EA w) = depth`` with ``u = T_1 - H`` is the
    quadratic ``u^2/(2EA) + u (1 + H/EA) - w depth = 0``. Returns ``V_1`` (the
    vertical reaction at A, N), ``T_1`` (N), its abscissa ``x_1`` (m), the length
    ``s_1 = V_1/w`` (m) and ``dV_1/dH``; all zero for ``depth = 0``.
    """
    xp = namespace(H, w, EA, depth)
    if not (depth if xp is scalar_math else np.any(depth)):  # the anchor on the seabed: no anchor part
        zero = 0.0 * H
        return zero, H, zero, zero, zero
    b = 1.0 + H / EA
    u = 2.0 * w * depth / (b + xp.sqrt(b * b + 2.0 * w * depth / EA))
    T1 = H + u
    V1 = xp.sqrt(u * (u + 2.0 * H))
    s1 = V1 / w
    x1 = H * s1 / EA + H / w * xp.arcsinh(V1 / H)
    # implicit derivative of the height at constant depth
    if xp is scalar_math:
        dV1 = u / ((V1 if V1 > 0 else 1.0) * (1.0 + T1 / EA)) if depth > 0 else 0.0
        return V1, T1, x1, s1, dV1
    with np.errstate(invalid="ignore", divide="ignore"):
        dV1 = np.where(depth > 0, u / (np.where(V1 > 0, V1, 1.0) * (1.0 + T1 / EA)), 0.0)
    return V1, T1, x1, s1, dV1


def grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth=0.0):
    """Residuals ``X(H, V) - span``, ``Z(H, V) - dh`` (m) of the grounded line and
    their Jacobian in ``(H, V)`` (``V`` the vertical force at B, ``mu_w``
    the friction force per unit grounded length). With ``depth > 0`` the anchor
    is that high above the seabed and the line hangs from it down to a first
    touchdown (`anchor_part`); ``dh`` is then measured from A, as always.

    Returns ``f_x, f_z, j_xh, j_xv, j_zh, j_zv``."""
    xp = namespace(span, dh, w, EA, L, mu_w, H, V, depth)
    V1, T1, x1, s1, dV1 = anchor_part(H, w, EA, depth)
    L_B = L - s1 - V / w
    T = xp.hypot(H, V)
    ell = tensioned(H, L_B, mu_w)
    H_A = xp.maximum(H - mu_w * L_B, 0.0)
    asinh = xp.arcsinh(V / H)
    f_x = x1 + L_B + H / w * asinh + H * V / (w * EA) + (H * ell - 0.5 * mu_w * ell * ell) / EA - span
    f_z = V * V / (T + H) / w + V * V / (2.0 * EA * w) - (dh + depth)  # (T - H)/w without cancellation
    j_xh = (asinh - V / T) / w + V / (w * EA) + ell / EA
    # the anchor part: dx_1/dH - ds_1/dH (1 + H_A/EA), ds_1/dH = dV_1/dH / w
    j_xh = j_xh + s1 / EA + (xp.arcsinh(V1 / H) - V1 / T1) / w
    j_xh = j_xh + dV1 * ((H / T1 - 1.0) + (H - H_A) / EA) / w
    j_xv = (-1.0 + H / T + (H - H_A) / EA) / w
    j_zh = -(V * V / (T + H)) / (T * w)  # (H/T - 1)/w
    j_zv = V / (w * T) + V / (w * EA)
    return f_x, f_z, j_xh, j_xv, j_zh, j_zv


def hanging_length(height, w, EA):
    r"""Unstretched length ``l`` (m) of a line hanging vertically (``H = 0``) from a support
    ``height`` above the seabed down to it, its tension ``w u`` at ``u`` above the seabed.

    Its stretched length :math:`l + w l^2/(2 EA)` equals the height (H.M. Irvine,
    "Cable Structures", MIT Press, 1981, the elastic catenary at ``H = 0``); the root
    written without cancellation, :math:`l = 2 d/(1 + \sqrt{1 + 2 w d/EA})`, ``d`` the
    height (m), ``w`` (N/m), ``EA`` (N). 0 at ``height = 0``.
    """
    xp = namespace(height, w, EA)
    return 2.0 * height / (1.0 + xp.sqrt(1.0 + 2.0 * w * height / EA))
