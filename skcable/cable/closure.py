r"""Irvine's elastic catenary closure: one elastic segment, hanging or partly on the seabed.

A segment of unstretched length :math:`L` (m), weight :math:`w` per unstretched length (N/m)
and axial stiffness :math:`EA` (N) carries the horizontal tension :math:`H` (N) and, at its
lower end, the vertical tension component :math:`V_b` (N; upward along the line positive, so
``V_b = -V_A`` for a free line whose anchor pulls down with ``V_A``); at its upper end
:math:`V_t = V_b + wL`. Along it, at the unstretched length :math:`s` from the lower end
(H.M. Irvine, "Cable Structures", MIT Press, 1981, §2.2),

.. math::
    x(s) = \frac{Hs}{EA} + \frac{H}{w}\big(\operatorname{asinh} p_s - \operatorname{asinh} q\big),
    \qquad
    y(s) = \frac{s\,(V_b + ws/2)}{EA} + s\,\frac{p_s + q}{r_s + r_q},

with :math:`q = V_b/H`, the step :math:`d = ws/H` formed directly, :math:`p_s = q + d` and
:math:`r = \sqrt{1 + (\cdot)^2}` (the second term is :math:`(T(s) - T_b)/w` rationalised;
:math:`\operatorname{asinh} p_s - \operatorname{asinh} q` by
`skcable.cable._special.asinh_step_parts`): every operation free of cancellation, so taut
steep lines keep their digits. On a flat (or sloped) seabed the segment may rest on it from
its anchor end and rise tangentially to its upper end; along the grounded part the tension falls by the
Coulomb friction :math:`\mu_w = C_B w` per unit length (J.M. Jonkman, "Dynamics modeling and
loads analysis of an offshore floating wind turbine", NREL, 2007).

This module is that closure, once, for every model that closes a line on it: the cables'
`elastic_catenary`, the lines on a seabed (`skcable.cable.seabed`), each segment of a
multi-segment line (`skcable.mooring.segments`) and the check of the conductors' change of
state (`skcable.conductors`). `check` and `check_into` evaluate it by other formulas than the
solves', so that a check never shares the round-off of the solve it checks. Every function but
the ``*_into`` ones (in place on many spans) takes Python floats or NumPy arrays: ``xp`` is the
back end (`skcable._xp.namespace`: ``scalar_math`` for floats, ``numpy``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from skcable._xp import namespace, scalar_math
from skcable.cable._special import asinh_step_parts, exp_asinh, sinhc_m1

__all__ = [
    "CHECK_ROWS",
    "CHECK_ULPS",
    "anchor_part",
    "check",
    "check_into",
    "check_residual",
    "closure",
    "end_ratios",
    "grounded",
    "grounded_closure",
    "hanging",
    "hanging_length",
    "on_seabed",
    "on_slope",
    "positions",
    "ratio_of_ends",
    "segment",
    "slope_frame",
    "stretched_length",
    "stretched_length_into",
    "tension_into",
    "tensioned",
]

_EPS = float(np.finfo(float).eps)
#: The bound of `check_into`: this many ulps of the closure's terms.
CHECK_ULPS = 64.0
#: Rows of scratch `check_into` fills (the first seven are named in its docstring).
CHECK_ROWS = 10


def end_ratios(H, Vb, w, L, xp=scalar_math):
    """``(q, d, p, r_q, r_p)``: the vertical tensions at the ends over ``H``, ``q = V_b/H``,
    ``p = q + d``, their step ``d = wL/H`` formed directly, and ``r = sqrt(1 + (.)^2)``."""
    q, d = Vb / H, w * L / H
    p = q + d
    return q, d, p, xp.hypot(1.0, q), xp.hypot(1.0, p)


def _x_h_core(S, A, p, q, rr):
    r""":math:`A - \sinh A/(r_p r_q)` (the geometric part of :math:`w\,\partial x/\partial H`) on
    arrays, without cancellation: below :math:`|A| = 2` as
    :math:`S(p^2 + q^2 + p^2q^2)/((r_pr_q + 1)r_pr_q) - (\sinh A - A)`, above it directly
    (`hanging` writes the same on floats)."""
    out = np.empty(np.shape(A))
    below = np.abs(A) < 2.0
    S_, A_, p_, q_, rr_ = S[below], A[below], p[below], q[below], rr[below]
    p2, q2 = p_ * p_, q_ * q_
    out[below] = S_ * (p2 + q2 + p2 * q2) / ((rr_ + 1.0) * rr_) - A_ * sinhc_m1(A_)
    above = ~below
    out[above] = A[above] - S[above] / rr[above]
    return out


def hanging(H, Vb, w, EA, L, xp=scalar_math):
    r"""Run and rise (m) of a hanging piece and their derivatives (module text).

    With :math:`A = \operatorname{asinh} p - \operatorname{asinh} q` and :math:`S = \sinh A`
    (`skcable.cable._special.asinh_step_parts`):

    .. math::
        x = \frac{HL}{EA} + \frac{H}{w}A, \qquad
        y = \frac{L(V_b + wL/2)}{EA} + L\,\frac{p + q}{r_p + r_q},

    :math:`\partial x/\partial H = L/EA + (A - S/(r_pr_q))/w` (below :math:`|A| = 2` as
    :math:`L/EA + (S(p^2 + q^2 + p^2q^2)/((r_pr_q + 1)r_pr_q) - (\sinh A - A))/w`, free of
    cancellation), :math:`\partial x/\partial V_b = \partial y/\partial H = -d\,(p + q)/((r_p +
    r_q)r_pr_q w)`, :math:`\partial y/\partial V_b = L/EA + S/(r_pr_q w)` (at constant ``L``) and
    :math:`\partial x/\partial L = H/EA + 1/r_p`, :math:`\partial y/\partial L = p\,\partial x/\partial L`
    (at constant ``V_b``: a piece from a tangent touchdown, ``V_b = 0``, lengthens with ``V_t``).

    Parameters
    ----------
    H, Vb : float or ndarray
        Horizontal tension (N, > 0) and the vertical tension component at the lower end (N).
    w, EA, L : float or ndarray
        Weight per unstretched length (N/m; < 0 buoyant), axial stiffness (N), length (m).
    xp : namespace
        ``skcable._xp.scalar_math`` for Python floats (the default), ``numpy`` for arrays.

    Returns
    -------
    tuple
        ``x, y, x_H, x_V, y_V, x_L, y_L, T_b, T_t``: the run and rise, ``∂x/∂H``,
        ``∂x/∂V_b`` (= ``∂y/∂H``), ``∂y/∂V_b``, ``∂x/∂L``, ``∂y/∂L`` and the end tensions (N).
    """
    q, d, p, rq, rp = end_ratios(H, Vb, w, L, xp)
    rsum, rr = rp + rq, rp * rq
    if xp is np:
        S, A = asinh_step_parts(q, d, p, rq, rp, np)
        core = _x_h_core(S, A, p, q, rr)
    else:  # `asinh_step_parts` and `_x_h_core` on floats, inlined (the hot scalar path)
        S = d * (p + q) / (p * rq + q * rp) if p * q > 0 else p * rq - q * rp
        A = xp.arcsinh(S)
        if -2.0 < A < 2.0:
            p2, q2 = p * p, q * q
            core = S * (p2 + q2 + p2 * q2) / ((rr + 1.0) * rr) - A * sinhc_m1(A)
        else:
            core = A - S / rr
    compliance = L / EA
    x_L = H / EA + 1.0 / rp
    return (
        H * L / EA + H / w * A,
        L * (Vb + 0.5 * w * L) / EA + L * (p + q) / rsum,
        compliance + core / w,
        -d * (p + q) / (rsum * rr * w),
        compliance + S / (rr * w),
        x_L,
        p * x_L,
        H * rq,
        H * rp,
    )


_NAN8 = (float("nan"),) * 8


def closure(H, Vb, span, dh, w, EA, L):
    """Irvine's closure of a free segment from A = (0, 0) to B = ``(span, dh)`` in the form of
    `skcable._newton2.solve2`: ``X - span``, ``Y - dh`` (m), their Jacobian in ``(H, V_b)``
    (`hanging`) and the sizes of their terms (m), whose few ulps are their round-off. Python
    floats or arrays; ``H <= 0`` gives NaN."""
    xp: Any = scalar_math
    if type(H) is not float:
        H, xp = np.where(H > 0, H, np.nan), np
    elif not H > 0:
        return _NAN8
    x, y, x_H, x_V, y_V, _, _, T_b, T_t = hanging(H, Vb, w, EA, L, xp)
    # the sizes: the terms summed, and the operands of the differences V_b + wL/2 and T_t - T_b
    size_y = L * (0.5 * w * L + abs(Vb)) / EA + L * (abs(Vb) + abs(Vb + w * L)) / (T_b + T_t) + abs(dh)
    return x - span, y - dh, x_H, x_V, x_V, y_V, x + span, size_y


def positions(H, Vb, w, EA, s, xp=scalar_math):
    """``(x, y)`` (m) of the point at the unstretched length ``s`` (m) from the lower end of a
    hanging piece, relative to that end (module text; the run and rise of `hanging`)."""
    q, d, p, rq, rp = end_ratios(H, Vb, w, s, xp)
    A = asinh_step_parts(q, d, p, rq, rp, xp)[1]
    return H * s / EA + H / w * A, s * (Vb + 0.5 * w * s) / EA + s * (p + q) / (rp + rq)


def stretched_length(H, Vb, w, EA, L, xp=scalar_math):
    r"""Length (m) of the loaded piece, :math:`L + \int_0^L T\,ds/EA` (Irvine 1981, §2.2).

    :math:`\int_0^L T\,ds = \frac{H^2}{2w}\,(J + A)` with :math:`J = p r_p - q r_q`, which is
    :math:`d\,(r_p + q (p + q)/(r_p + r_q))` where p and q share a sign (no cancellation);
    ``L`` where ``L = 0``.
    """
    q, d, p, rq, rp = end_ratios(H, Vb, w, L, xp)
    A = asinh_step_parts(q, d, p, rq, rp, xp)[1]
    same = p * q > 0
    if xp is not np:
        J = d * (rp + q * (p + q) / (rp + rq)) if same else p * rp - q * rq
    else:
        J = np.where(same, d * (rp + q * (p + q) / (rp + rq)), p * rp - q * rq)
    return L + 0.5 * (H / EA) * (H / w) * (J + A)


def tensioned(T, l, mu_w):
    """Length (m) of a grounded piece of length ``l`` that carries tension: ``min(l, T/mu_w)``,
    ``T`` (N) at its upper end falling by ``mu_w`` (N/m) per unit length towards the anchor."""
    if not isinstance(T, np.ndarray) and not isinstance(l, np.ndarray) and not isinstance(mu_w, np.ndarray):
        return min(l, T / mu_w) if mu_w > 0 else l
    with np.errstate(divide="ignore"):
        reach = np.where(mu_w > 0, T / np.where(mu_w > 0, mu_w, 1.0), np.inf)
    return np.minimum(l, reach)


def grounded(T, l, mu_w, EA, xp=scalar_math):
    r"""Stretch (m) of a grounded piece and its derivatives.

    The piece of unstretched length ``l`` (m) lies on the seabed under the tension ``T`` (N) at
    its upper end, falling by the friction ``mu_w = C_B w`` (N/m) per unit length towards the
    anchor, down to 0 where friction takes it all (Jonkman 2007):
    :math:`e = (T l - \mu_w l^2/2)/EA` while :math:`T > \mu_w l`, else :math:`T^2/(2 \mu_w EA)`.

    Returns ``e, ∂e/∂T, ∂e/∂l, T_low``: the stretch, its derivatives and the tension at the
    lower end (N; exactly 0 where friction takes it all).
    """
    if xp is not np:
        if mu_w == 0 or T - mu_w * l > 0:
            low = T - mu_w * l
            return (T * l - 0.5 * mu_w * l * l) / EA, l / EA, low / EA, low
        return 0.5 * T * T / (mu_w * EA), T / (mu_w * EA), 0.0 * T, 0.0 * T
    taut = (mu_w == 0) | (T - mu_w * l > 0)  # the tension reaches the lower end
    with np.errstate(divide="ignore", invalid="ignore"):
        stretch = np.where(taut, (T * l - 0.5 * mu_w * l * l) / EA, 0.5 * T * T / (mu_w * EA))
        e_T = np.where(taut, l / EA, T / (mu_w * EA))
    low = np.where(taut, T - mu_w * l, 0.0)
    return stretch, e_T, low / EA, low


def anchor_part(H, w, EA, depth, xp=None):
    """The part hanging from an anchor ``depth`` (m) above the seabed down to its touchdown
    (vertex on the seabed), in closed form for a given ``H`` (N).

    Its height ``(T_1 - H)/w + V_1^2/(2 EA w) = depth`` with ``u = T_1 - H`` is the
    quadratic ``u^2/(2EA) + u (1 + H/EA) - w depth = 0``. Returns ``V_1`` (the vertical
    reaction at A, N), ``T_1`` (N), its abscissa ``x_1`` (m), the length ``s_1 = V_1/w`` (m)
    and ``dV_1/dH``; all zero for ``depth = 0``. ``xp``: the back end, if the caller knows it.
    """
    xp = namespace(H, w, EA, depth) if xp is None else xp
    floats = xp is not np
    if not (depth if floats else np.any(depth)):  # the anchor on the seabed: no anchor part
        zero = 0.0 * H
        return zero, H, zero, zero, zero
    b = 1.0 + H / EA
    u = 2.0 * w * depth / (b + xp.sqrt(b * b + 2.0 * w * depth / EA))
    T1 = H + u
    V1 = xp.sqrt(u * (u + 2.0 * H))
    s1 = V1 / w
    x1 = H * s1 / EA + H / w * xp.arcsinh(V1 / H)
    # implicit derivative of the height at constant depth
    if floats:
        dV1 = u / ((V1 if V1 > 0 else 1.0) * (1.0 + T1 / EA)) if depth > 0 else 0.0
        return V1, T1, x1, s1, dV1
    with np.errstate(invalid="ignore", divide="ignore"):
        dV1 = np.where(depth > 0, u / (np.where(V1 > 0, V1, 1.0) * (1.0 + T1 / EA)), 0.0)
    return V1, T1, x1, s1, dV1


def hanging_length(height, w, EA):
    r"""Unstretched length ``l`` (m) of a line hanging vertically (``H = 0``) from a support
    ``height`` (m) above the seabed down to it, its tension ``w u`` at ``u`` above the seabed.

    Its stretched length :math:`l + w l^2/(2 EA)` equals the height (Irvine 1981, the elastic
    catenary at ``H = 0``); the root written without cancellation,
    :math:`l = 2 d/(1 + \sqrt{1 + 2 w d/EA})`, ``d`` the height. 0 at ``height = 0``.
    """
    return 2.0 * height / (1.0 + namespace(height, w, EA).sqrt(1.0 + 2.0 * w * height / EA))


def on_seabed(H, V, w, EA, L, mu_w, depth=0.0, xp=scalar_math):
    r"""Run and rise (m) from A of a segment resting on the seabed and rising tangentially to B,
    and their Jacobian in the fairlead forces ``(H, V)`` (N).

    The part ``L_B = L - s_1 - V/w`` rests on the seabed and stretches by `grounded` (tension
    ``H`` at the touchdown); the part ``V/w`` hangs from the touchdown (`hanging` with
    ``V_b = 0``). With the anchor ``depth`` (m) above the seabed (no friction) the line first
    hangs from A to a first touchdown (`anchor_part`, ``s_1 = V_1/w``); the rise is then from
    A, the seabed ``depth`` below it. This is the closure of Jonkman (2007) (MoorPy's):

    .. math::
        X = L_B + \frac{H}{w}\operatorname{asinh}\frac{V}{H} + \frac{H V}{w EA}
            + \frac{H\ell - \mu_w\ell^2/2}{EA} + x_1, \qquad
        Z = \frac{H}{w}\Big(\sqrt{1 + (V/H)^2} - 1\Big) + \frac{V^2}{2 EA w} - d,

    :math:`\ell = \min(L_B, H/\mu_w)` (`tensioned`). Returns ``X, Z, X_H, X_V, Z_H, Z_V``.
    """
    V1, T1, x1, s1, dV1 = anchor_part(H, w, EA, depth, xp)
    L_B = L - s1 - V / w
    x, z, x_H, z_H, _, x_L, z_L, _, _ = hanging(H, 0.0 * V, w, EA, V / w, xp)
    e, e_T, e_l, H_A = grounded(H, L_B, mu_w, EA, xp)
    X = x1 + L_B + x + e
    X_H = x_H + e_T
    if np.any(depth) if xp is np else depth:
        # the anchor part: dx_1/dH - ds_1/dH (1 + H_A/EA), ds_1/dH = dV_1/dH / w
        X_H = X_H + s1 / EA + (xp.arcsinh(V1 / H) - V1 / T1) / w
        X_H = X_H + dV1 * ((H / T1 - 1.0) + (H - H_A) / EA) / w
    return X, z - depth, X_H, (x_L - 1.0 - e_l) / w, z_H, z_L / w


def grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth=0.0):
    """Residuals ``X(H, V) - span``, ``Z(H, V) - dh`` (m) of the line resting on the seabed
    (`on_seabed`) and their Jacobian in ``(H, V)``, ``V`` the vertical force at B; with
    ``depth > 0`` the anchor is that high above the seabed (``dh`` measured from A, as
    always). Returns ``f_x, f_z, j_xh, j_xv, j_zh, j_zv``."""
    X, Z, *jac = on_seabed(H, V, w, EA, L, mu_w, depth, namespace(span, dh, w, EA, L, mu_w, H, V, depth))
    return (X - span, Z - dh, *jac)


def slope_frame(m, xp=scalar_math):
    """``(cos α, sin α)`` of the slope ``tan α = m``."""
    cos = 1.0 / xp.hypot(1.0, m)
    return cos, m * cos


def on_slope(H, L_B, w, EA, L, m, mu, xp=scalar_math):
    r"""Run and rise (m) from A of a segment resting over ``L_B`` (m) on a straight seabed
    ``y = x tan α`` through A, ``tan α = m``, and rising tangentially to B, and their Jacobian
    in ``(H, L_B)``.

    The grounded part is a `grounded` piece under the touchdown tension :math:`T_t = H/\cos\alpha`
    falling towards A by :math:`k = w(\sin\alpha + \mu\cos\alpha)` per unit length (the
    weight's component along the slope and Coulomb friction on :math:`w\cos\alpha`; ``k <= 0``:
    the tension grows towards A), of stretched length :math:`G = L_B + e`; the rest hangs from
    the touchdown (`hanging`, :math:`V_b = H\tan\alpha`, length :math:`L - L_B`):

    .. math:: X = G\cos\alpha + x, \qquad Z = G\sin\alpha + y

    (Jonkman 2007 on a slope, as MoorPy's ``catenary(..., alpha=...)``, which takes the friction
    force as :math:`\mu w`). By the chain rule, with :math:`V_b = H\tan\alpha`:
    :math:`X_H = e_T + x_H + m\,x_V`, :math:`X_L = (1 + e_l)\cos\alpha - x_L`,
    :math:`Z_H = m\,e_T + y_H + m\,y_V`, :math:`Z_L = (1 + e_l)\sin\alpha - y_L`.
    Returns ``X, Z, X_H, X_L, Z_H, Z_L``.
    """
    cos, sin = slope_frame(m, xp)
    e, e_T, e_l, _ = grounded(H / cos, L_B, w * (sin + mu * cos), EA, xp)
    x, z, x_H, x_V, z_V, x_L, z_L = hanging(H, H * m, w, EA, L - L_B, xp)[:7]
    G = L_B + e
    # e_T is ∂e/∂T_t: ∂G/∂H = e_T/cos α
    return (
        G * cos + x,
        G * sin + z,
        e_T + x_H + m * x_V,
        (1.0 + e_l) * cos - x_L,
        m * e_T + x_V + m * z_V,
        (1.0 + e_l) * sin - z_L,
    )


def segment(H, V, w, EA, L, mu_w, contact, xp=scalar_math):
    """The run and rise (m) of one segment from its anchor A to its upper end B and their
    Jacobian in the forces ``(H, V)`` at B (N): hanging (`hanging`, ``V_b = V - wL``), or, with
    ``contact`` (a seabed through A) where ``V < wL``, resting on the seabed from A up to a
    tangent touchdown (`on_seabed` with the anchor on the seabed). Returns
    ``X, Z, X_H, X_V, Z_H, Z_V``; ``X`` is NaN where no state exists (``H <= 0``, the whole
    segment on the seabed)."""
    below = V - w * L  # the vertical force at A's end of the segment
    touches = (below < 0) & contact
    with np.errstate(invalid="ignore", divide="ignore"):
        L_B = xp.where(touches, -below / w, 0.0)  # the grounded length
        x, z, x_H, x_V, z_V, x_L, z_L = hanging(H, xp.where(touches, 0.0, below), w, EA, L - L_B, xp)[:7]
        e, e_T, e_l, _ = grounded(H, L_B, mu_w, EA, xp)
        X = xp.where((H <= 0) | (touches & (V <= 0)), float("nan"), x + xp.where(touches, L_B + e, 0.0))
        X_V = xp.where(touches, (x_L - 1.0 - e_l) / w, x_V)
        return X, z, x_H + xp.where(touches, e_T, 0.0), X_V, x_V, xp.where(touches, z_L / w, z_V)


def check(H, Vb, w, EA, L, span, dh, xp=scalar_math, ratios=None):
    r"""The closure of a hanging piece from ``(0, 0)`` to ``(span, dh)`` by other formulas than
    `hanging`'s: ``(r_x, r_y)``, each residual over the sum of its terms' magnitudes (its
    round-off is a few ulps). ``ratios``: `end_ratios` of the piece, if the caller has them.

    With :math:`e_v = v + \sqrt{1 + v^2} = e^{\operatorname{asinh} v}` (each a sum of positive
    terms, :math:`1/(r_v - v)` for negative ``v``),
    :math:`u = e^A - 1 = d\,(e_p + e_q)/((r_p + r_q)\,e_q)`; the arc :math:`A = \operatorname{log1p} u`
    and the rise :math:`(T_t - T_b)/w = (H/w)(p + q)\tanh(A/2)`, :math:`\tanh(A/2) = u/(u + 2)`.
    """
    q, d, p, rq, rp = end_ratios(H, Vb, w, L, xp) if ratios is None else ratios
    e_q = exp_asinh(q, rq, xp)
    u = d * (exp_asinh(p, rp, xp) + e_q) / ((rp + rq) * e_q)
    stretch, shape = H * L / EA, H / w * xp.log1p(u)
    half = H / w * (u / (u + 2.0))
    operands = L * (0.5 * abs(w) * L + abs(Vb)) / EA + abs(half) * (abs(p) + abs(q)) + abs(dh)
    return (
        (stretch + shape - span) / (abs(stretch) + abs(shape) + span),
        (L * (Vb + 0.5 * w * L) / EA + half * (p + q) - dh) / operands,
    )


def tension_into(tv, H_sq, T, P):
    """The tension ``T = sqrt(T_v² + H²)`` and ``P = |T_v| + T`` of an end into ``T`` and ``P``,
    from its vertical tension ``tv`` and ``H_sq = H²``, in place."""
    np.multiply(tv, tv, out=T)
    T += H_sq
    np.sqrt(T, out=T)
    np.abs(tv, out=P)
    P += T


def ratio_of_ends(tv_a, tv_b, P_a, P_b, H2, out):
    """``e_p/e_q`` (`check`'s notation) into ``out`` from ``P = T + |T_v|`` at the ends:
    ``P_A P_B/H²`` where the slopes at the ends have opposite signs, ``P_B/P_A`` where both
    rise, ``P_A/P_B`` where both fall."""
    np.multiply(P_a, P_b, out=out)
    out /= H2
    for ends, over, under in ((tv_a >= 0.0, P_b, P_a), (tv_b < 0.0, P_a, P_b)):
        if ends.any():  # the few spans whose vertex lies beyond an end: by index
            at = np.flatnonzero(ends)
            out[at] = over[at] / under[at]
    return out


def check_into(H, m, w, EA, L, a, h, rows):
    r"""`check` of many spans at once, in place in ``rows`` (`CHECK_ROWS` rows of the elements'
    size; flat float arrays of one size, or floats that broadcast), in the mean vertical tension
    :math:`m = (V_b + V_t)/2 = V_b + wL/2` (N) instead of ``V_b``: the same formulas in
    forces, :math:`P = T + |T_v|` for :math:`H e_v`, :math:`u = wL\,(1 + e_p/e_q)/(T_A + T_B)`.

    Fills 0 ``T_v,A``, 1 ``T_v,B``, 2 ``T_A``, 3 ``T_B``, 4 the arc ``A``, 5 the larger of
    ``|f_x|, |f_y|`` and 6 the larger sum of the magnitudes of their terms (m); rows 7 to 9 are
    scratch. Returns ``ok``, per element: row 5 at most `CHECK_ULPS` ulps of row 6 (the check's
    own round-off is a few) and ``H > 0`` (NaN fails).
    """
    tv_a, tv_b, T_A, T_B, arc, res, terms, u, v, y = rows
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        np.multiply(w, L, out=u)  # wL
        np.multiply(u, 0.5, out=v)
        np.subtract(m, v, out=tv_a)
        np.add(m, v, out=tv_b)
        np.multiply(H, H, out=v)
        tension_into(tv_a, v, T_A, res)
        tension_into(tv_b, v, T_B, terms)
        ratio_of_ends(tv_a, tv_b, res, terms, v, out=arc)
        arc += 1.0
        arc *= u
        np.add(T_A, T_B, out=v)
        arc /= v  # u = e^A - 1
        np.add(arc, 2.0, out=y)
        np.divide(arc, y, out=y)  # tanh(A/2)
        np.log1p(arc, out=arc)
        np.multiply(H, L, out=res)
        res /= EA
        np.divide(H, w, out=terms)
        terms *= arc
        res += terms  # HL/EA + (H/w) A
        np.subtract(res, a, out=u)
        np.abs(u, out=u)  # |f_x|
        res += a
        y *= m
        y += y
        y /= w  # (H/w)(p + q) tanh(A/2), p + q = 2m/H
        np.multiply(L, m, out=terms)
        terms /= EA  # Lm/EA
        np.abs(terms, out=v)
        terms += y
        terms -= h
        np.abs(terms, out=terms)  # |f_y|
        np.maximum(u, terms, out=u)
        np.abs(y, out=y)
        v += y
        np.abs(h, out=y)
        v += y
        np.maximum(res, v, out=terms)
        np.copyto(res, u)
        np.multiply(terms, CHECK_ULPS * _EPS, out=v)
        ok = res <= v
        ok &= H > 0.0
    return ok


def stretched_length_into(H, w, EA, L, rows, out):
    r"""`stretched_length` of many spans into ``out``, from `check_into`'s rows 0 to 4 (rows 5
    and 6 are overwritten): :math:`L + (J + H^2 A)/(2wEA)` with
    :math:`J = T_{v,B}T_B - T_{v,A}T_A = wL\,(T_B + T_{v,A}(T_{v,A} + T_{v,B})/(T_A + T_B))`
    (`stretched_length`'s rationalised form, here for every sign of the slopes: where they
    differ its two terms do not cancel by more than a factor two)."""
    tv_a, tv_b, T_A, T_B, arc, u, v = rows[:7]
    np.add(tv_a, tv_b, out=out)
    out *= tv_a
    np.add(T_A, T_B, out=u)
    out /= u
    out += T_B
    np.multiply(w, L, out=u)
    out *= u  # J
    np.multiply(H, H, out=v)
    v *= arc
    out += v
    out /= w
    out /= EA
    out *= 0.5
    out += L
    return out


def check_residual(H, m, w, EA, L, span, dh):
    """Relative closure residual of solved spans and its round-off bound, ``(residual,
    bound)``, arrays (`check_into` over the chord)."""
    H, m, w, EA, L, span, dh = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (H, m, w, EA, L, span, dh))
    )
    rows = np.empty((CHECK_ROWS, *H.shape))
    check_into(H, m, w, EA, L, span, dh, rows)
    chord = np.hypot(span, dh)
    return rows[5] / chord, CHECK_ULPS * _EPS * rows[6] / chord
