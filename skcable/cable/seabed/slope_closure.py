r"""The closure of a line grounded on a sloped seabed ``y = x tan α`` and its Jacobian.

Unknowns: the horizontal tension ``H`` of the suspended part and the unstretched grounded
length ``L_B`` from the anchor. With :math:`k = w(\sin\alpha + \mu\cos\alpha)`, the
touchdown tension :math:`T_t = H/\cos\alpha`, the tensioned grounded length
:math:`\ell = \min(L_B, T_t/k)` (:math:`\ell = L_B` when :math:`k \le 0`), the grounded
stretched length :math:`G = L_B + (T_t\ell - k\ell^2/2)/EA`, :math:`L_s = L - L_B`,
:math:`V_t = H\tan\alpha`, :math:`V_B = V_t + w L_s`:

.. math::
    X = G\cos\alpha + \frac{H L_s}{EA} + \frac{H}{w}\Big(\operatorname{asinh}\frac{V_B}{H}
        - \operatorname{asinh}\frac{V_t}{H}\Big), \qquad
    Z = G\sin\alpha + \frac{T_B - T_t}{w} + \frac{V_B^2 - V_t^2}{2 EA w}

(J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore floating wind turbine",
NREL, 2007, on a slope; H.M. Irvine, "Cable Structures", MIT Press, 1981, for the suspended
part). Differentiating, with :math:`\operatorname{asinh}(V_t/H) = \operatorname{asinh}\tan\alpha`
constant and :math:`\partial V_B/\partial H = \tan\alpha`, :math:`\partial V_B/\partial L_B = -w`:

.. math::
    \frac{\partial X}{\partial H} = G_H\cos\alpha + \frac{L_s}{EA}
        + \frac{1}{w}\Big(\operatorname{asinh}\frac{V_B}{H} - \operatorname{asinh}\tan\alpha\Big)
        - \frac{L_s}{T_B}, \qquad
    \frac{\partial X}{\partial L_B} = G_L\cos\alpha - \frac{H}{EA} - \frac{H}{T_B},

.. math::
    \frac{\partial Z}{\partial H} = G_H\sin\alpha
        + \frac{1}{w}\Big(\frac{H + V_B\tan\alpha}{T_B} - \frac{1}{\cos\alpha}\Big)
        + \frac{L_s\tan\alpha}{EA}, \qquad
    \frac{\partial Z}{\partial L_B} = G_L\sin\alpha - \frac{V_B}{T_B} - \frac{V_B}{EA},

with :math:`G_H = L_B/(EA\cos\alpha)`, :math:`G_L = 1 + (T_t - kL_B)/EA` where the grounded
part is tensioned throughout (:math:`\ell = L_B`) and :math:`G_H = T_t/(k\,EA\cos\alpha)`,
:math:`G_L = 1` where its anchor end is slack.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._special import asinh_step

__all__ = ["sloped_closure", "sloped_jacobian", "slope_frame"]


def slope_frame(m):
    """``(cos α, sin α)`` of the slope ``tan α = m``."""
    cos = 1.0 / np.hypot(1.0, m)
    return cos, m * cos


def sloped_closure(span, dh, w, EA, L, m, mu, H, L_B):
    """Closure residuals ``(X - span, Z - dh)`` (m) of the line grounded on the slope ``y = m x``
    over ``L_B`` from A (module docstring)."""
    cos, sin = slope_frame(m)
    k = w * (sin + mu * cos)
    T_td = H / cos
    ell = min(L_B, T_td / k) if k > 0 else L_B
    grounded = L_B + (T_td * ell - 0.5 * k * ell * ell) / EA
    L_s = L - L_B
    V_t = H * m
    V_B = V_t + w * L_s
    # the suspended part from the step w L_s/H formed directly (D1 of issue 26), and
    # (T_B - T_t)/w = L_s (V_B + V_t)/(T_B + T_t), (V_B² - V_t²)/(2 EA w) = L_s (V_B + V_t)/(2 EA)
    X = H * L_s / EA + H / w * asinh_step(m, w * L_s / H)
    Z = L_s * (V_B + V_t) / (np.hypot(H, V_B) + np.hypot(H, V_t)) + L_s * (V_B + V_t) / (2.0 * EA)
    return grounded * cos + X - span, grounded * sin + Z - dh


def sloped_jacobian(w, EA, L, m, mu, H, L_B):
    """``∂(X, Z)/∂(H, L_B)`` of `sloped_closure` as ``((X_H, X_L), (Z_H, Z_L))`` (module docstring)."""
    cos, sin = slope_frame(m)
    k = w * (sin + mu * cos)
    T_td = H / cos
    if k > 0 and T_td / k < L_B:  # the anchor end of the grounded part slack
        G_H, G_L = T_td / (k * EA * cos), 1.0
    else:
        G_H, G_L = L_B / (EA * cos), 1.0 + (T_td - k * L_B) / EA
    L_s = L - L_B
    V_B = H * m + w * L_s
    T_B = np.hypot(H, V_B)
    X_H = G_H * cos + L_s / EA + asinh_step(m, w * L_s / H) / w - L_s / T_B
    X_L = G_L * cos - H / EA - H / T_B
    Z_H = G_H * sin + ((H + V_B * m) / T_B - 1.0 / cos) / w + L_s * m / EA
    Z_L = G_L * sin - V_B / T_B - V_B / EA
    return (X_H, X_L), (Z_H, Z_L)
