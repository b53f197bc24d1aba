r"""Whole lines at array speed: Irvine's elastic catenary over many spans and states at once.

The closure of a span of unstressed length :math:`L`, weight :math:`w` per unstressed length and
axial stiffness :math:`EA` between A = (0, 0) and B = (span, dh) (H.M. Irvine, "Cable
Structures", MIT Press, 1981, §2.2) is written here in the horizontal tension :math:`H` and the
mean vertical tension :math:`m = (T_{v,A} + T_{v,B})/2 = wL/2 - V_A`, with
:math:`T_{v,A} = m - wL/2`, :math:`T_{v,B} = m + wL/2` and the end tensions
:math:`T = \sqrt{H^2 + T_v^2}`:

.. math::
    f_x = \frac{HL}{EA} + \frac{H}{w}\left[\operatorname{asinh}\frac{T_{v,B}}{H}
          - \operatorname{asinh}\frac{T_{v,A}}{H}\right] - \text{span}, \qquad
    f_y = L\,m\left(\frac{1}{EA} + \frac{2}{T_A + T_B}\right) - dh,

the second using :math:`T_B - T_A = 2wLm/(T_A + T_B)`. The difference of the two inverse
hyperbolic sines is formed as one, :math:`\operatorname{asinh}X`, with
:math:`X = (T_{v,B}T_A - T_{v,A}T_B)/H^2` when the ends' slopes have opposite signs and
:math:`X = wL(|T_{v,A}| + |T_{v,B}|)/(|T_{v,B}|T_A + |T_{v,A}|T_B)` when they have the same
sign: every term is positive, ``wL`` enters as itself (not as a difference of rounded ratios),
and nothing cancels.

`reference_lengths` solves the closure for :math:`(m, L)` at a given :math:`H` (the reference
state of a change of state), `solve_spans` for :math:`(H, m)` at a given :math:`L`, both by an
elementwise Newton with the analytic Jacobian and backtracking that keeps :math:`H > 0`. Every
result is then checked by `closure_residual`, which evaluates the same two conditions by other
formulas — the arc as :math:`\ln(p_B/p_A)` with :math:`p = u + \sqrt{1 + u^2}` through ``log1p``,
and :math:`T_B - T_A` as the plain difference — so that the check does not share the solve's
round-off; its bound is a few ulps of the terms it adds.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from skcable.errors import ConvergenceError

__all__ = ["reference_lengths", "solve_spans", "closure_residual", "sag_of", "stretched_length_of"]

_EPS = float(np.finfo(float).eps)
_MAX_ITER = 50
#: The closure's arguments ``H, m, w, EA, L, span, dh`` (arrays).
_Closure = tuple[Any, Any, Any, Any, Any, Any, Any]
_STEP_TOL = 1e-9  # relative Newton step after which the iterate is at round-off (quadratic rate)
#: The check's bound: this many ulps of the closure's terms (the check's own round-off is a few).
CHECK_ULPS = 64.0


def _arc(tv_a, tv_b, T_A, T_B, H, wL):
    """``asinh(tv_b/H) - asinh(tv_a/H)`` (``tv_b - tv_a = wL > 0``) without cancellation."""
    same = tv_a * tv_b > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        opposite = (tv_b * T_A - tv_a * T_B) / (H * H)
        a, b = np.abs(tv_a), np.abs(tv_b)
        along = wL * (a + b) / (b * T_A + a * T_B)
    return np.arcsinh(np.where(same, along, opposite))


def _tension(H, tv):
    """``sqrt(H² + tv²)`` (three times faster than ``np.hypot``; an overflow beyond 1e154 N
    gives inf, which every check refuses)."""
    return np.sqrt(H * H + tv * tv)


def _closure(H, m, w, EA, L, span, dh):
    """The residuals and the pieces of their Jacobian."""
    wL = w * L
    tv_a, tv_b = m - 0.5 * wL, m + 0.5 * wL
    T_A, T_B = _tension(H, tv_a), _tension(H, tv_b)
    arc = _arc(tv_a, tv_b, T_A, T_B, H, wL)
    f_x = H * L / EA + H / w * arc - span
    f_y = L * m * (1.0 / EA + 2.0 / (T_A + T_B)) - dh
    return f_x, f_y, (T_A, T_B, tv_a, tv_b, arc)


def _norm(f_x, f_y, chord):
    return np.maximum(np.abs(f_x), np.abs(f_y)) / chord


def _floor(H, m, w, EA, L, span, dh, parts, chord):
    """A few ulps of the closure's terms over the chord: the residual no Newton goes below.

    The terms are those `_closure` adds (:math:`f_y` as :math:`L m (1/EA + 2/(T_A + T_B))`, not
    the plain difference :math:`(T_B - T_A)/w` of the check, whose operands are larger by
    :math:`(T_A + T_B)/(wL)`: sized by those, the floor stopped taut spans ~100 ulps short of
    their root)."""
    T_A, T_B, _, _, arc = parts
    terms_x = H * L / EA + H / w * np.abs(arc) + span
    terms_y = L * np.abs(m) * (1.0 / EA + 2.0 / (T_A + T_B)) + np.abs(dh)
    return (8.0 * _EPS) * np.maximum(terms_x, terms_y) / chord


def _newton(unknowns, jacobian, args: Callable[[Any, Any], _Closure], chord, what):
    """Elementwise damped Newton on the closure in two unknowns.

    ``unknowns`` = (p, q) as arrays, ``jacobian(p, q, parts) -> (a, b, c, d)`` the matrix
    ``[[dfx/dp, dfx/dq], [dfy/dp, dfy/dq]]``; ``args(p, q)`` the closure's arguments. The
    first unknown is positive (H or L) and kept so (a step at most 90 % of it down). A trial
    that does not reduce the residual is halved, element by element. Converged when the
    relative step falls below 1e-9 (the error of the new iterate is then its square, at the
    rate's constant) or the residual below the round-off of its terms.
    """
    p, q = unknowns
    f_x, f_y, parts = _closure(*args(p, q))
    norm = _norm(f_x, f_y, chord)
    floor = _floor(*args(p, q), parts, chord)
    history = [float(np.max(norm))]
    for _ in range(_MAX_ITER):
        a, b, c, d = jacobian(p, q, parts)
        det = a * d - b * c
        dp = (f_y * b - f_x * d) / det
        dq = (c * f_x - a * f_y) / det
        down = dp < -0.9 * p
        t = np.where(down, -0.9 * p / np.where(down, dp, -1.0), 1.0) if down.any() else 1.0
        for _ in range(40):
            p_new, q_new = p + t * dp, q + t * dq
            with np.errstate(over="ignore", invalid="ignore"):
                fx_new, fy_new, parts_new = _closure(*args(p_new, q_new))
                new = _norm(fx_new, fy_new, chord)
            ok = (new < norm * (1.0 - 1e-4 * t)) | (new <= 4.0 * floor)
            if ok.all():
                break
            t = np.where(ok, t, 0.5 * t)
        else:
            raise ConvergenceError(f"{what}: line search found no descent", history)
        step = np.maximum(np.abs(dp) / p, np.abs(dq) / (np.abs(q) + p)) * t
        p, q, f_x, f_y, parts, norm = p_new, q_new, fx_new, fy_new, parts_new, new
        history.append(float(np.max(norm)))
        if np.all((step <= _STEP_TOL) | (norm <= floor)):
            return p, q, parts
    raise ConvergenceError(f"{what}: Newton did not converge", history)


def reference_lengths(span, dh, w, EA, H):
    """Unstressed length ``L`` and mean vertical tension ``m`` of the spans with horizontal
    tension ``H`` (arrays, broadcast): the closure solved for ``(m, L)``.

    Started from the inextensible catenary of that ``H`` (its length shortened by the mean
    strain). Raises `ConvergenceError` if a Newton stalls; the caller checks the result.
    """
    span, dh, w, EA, H = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (span, dh, w, EA, H)))
    chord = np.hypot(span, dh)
    with np.errstate(over="ignore"):
        half = 2.0 * H / w * np.sinh(0.5 * w * span / H)
    S = np.hypot(dh, half)  # inextensible catenary's length
    T_mean = np.sqrt(H * H + (0.5 * w * S) ** 2 + (H * dh / span) ** 2)
    L = S / (1.0 + T_mean / EA)
    m = dh / (L * (1.0 / EA + 1.0 / T_mean))

    def args(L_, m_):
        return H, m_, w, EA, L_, span, dh

    def jacobian(L_, m_, parts):
        T_A, T_B, tv_a, tv_b, _ = parts
        ha, hb, ga, gb = H / T_A, H / T_B, tv_a / T_A, tv_b / T_B
        return H / EA + 0.5 * (ha + hb), (hb - ha) / w, m_ / EA + 0.5 * (ga + gb), L_ / EA + (gb - ga) / w

    L, m, _ = _newton((L, m), jacobian, args, chord, "reference length")
    return L, m


def solve_spans(span, dh, w, EA, L, H=None, m=None):
    """``(H, m)`` of spans of unstressed length ``L`` (arrays, broadcast): the closure solved.

    ``H``, ``m`` are the start (the caller's estimate, e.g. the parabolic change of state);
    by default that of a parabola. Raises `ConvergenceError` if a Newton stalls; the caller
    checks the result with `closure_residual`.
    """
    span, dh, w, EA, L = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (span, dh, w, EA, L)))
    chord = np.hypot(span, dh)
    if H is None:
        H = start_tension(span, dh, w, EA, L)
    H = np.broadcast_to(H, span.shape).astype(float)
    if m is None:
        T_mean = np.sqrt(H * H + (0.5 * w * L) ** 2 + (H * dh / span) ** 2)
        m = dh / (L * (1.0 / EA + 1.0 / T_mean))
    m = np.broadcast_to(m, span.shape).astype(float)

    def args(H_, m_):
        return H_, m_, w, EA, L, span, dh

    stretch = L / EA

    def jacobian(H_, m_, parts):
        T_A, T_B, tv_a, tv_b, arc = parts
        ia, ib = 1.0 / T_A, 1.0 / T_B
        slopes = (tv_b * ib - tv_a * ia) / w
        cross = H_ * (ib - ia) / w
        return stretch + arc / w - slopes, cross, cross, stretch + slopes

    H, m, _ = _newton((H, m), jacobian, args, chord, "span closure")
    return H, m


def parabolic_cubic(b, d, rtol=4e-16):
    """The positive root of ``H³ + b H² - d = 0`` (``d > 0``), elementwise: Newton from above.

    Both ``max(0, -b) + d^(1/3)`` and, for ``b > 0``, ``(d/b)^(1/2)`` bound the root from
    above, and the cubic is convex there: Newton from the smaller one decreases to the root.
    """
    H = np.maximum(0.0, -b) + np.cbrt(d)
    with np.errstate(divide="ignore"):
        H = np.where(b > 0, np.minimum(H, np.sqrt(d / np.where(b > 0, b, 1.0))), H)
    history = []
    for _ in range(200):
        step = (H**3 + b * H**2 - d) / (3 * H**2 + 2 * b * H)
        H = H - step
        history.append(float(np.max(np.abs(step / H))))
        if history[-1] < rtol:
            return H
    raise ConvergenceError("parabolic change of state: Newton on the cubic did not converge", history)


def start_tension(span, dh, w, EA, L):
    r"""The parabola's horizontal tension for spans of unstressed length ``L``: the positive root
    of :math:`c(1 + (w\,\text{span}\cos\psi)^2/24H^2) = L(1 + H/(EA\cos\psi))` (chord :math:`c`,
    :math:`\cos\psi = \text{span}/c`), a start for `solve_spans`."""
    chord = np.hypot(span, dh)
    cos = span / chord
    b = (L - chord) * EA * cos / L
    d = chord * (w * span * cos) ** 2 * EA * cos / (24.0 * L)
    return parabolic_cubic(b, d, rtol=1e-9)


def closure_residual(H, m, w, EA, L, span, dh):
    """Relative closure residual of solved spans, by formulas other than the solve's, and its
    round-off bound: ``(residual, bound)``, arrays.

    The arc is :math:`\\ln(p_B/p_A) = \\operatorname{log1p}(wL (p_A + p_B)/((T_A + T_B) p_A))` with
    :math:`p = (T_v + T)/H`, formed as :math:`H/(T - T_v)` where :math:`T_v < 0`; the rise is the
    plain difference :math:`T_B - T_A`.
    """
    wL = w * L
    tv_a, tv_b = m - 0.5 * wL, m + 0.5 * wL
    T_A, T_B = np.hypot(H, tv_a), np.hypot(H, tv_b)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        p_a = np.where(tv_a >= 0, (tv_a + T_A) / H, H / (T_A - tv_a))
        p_b = np.where(tv_b >= 0, (tv_b + T_B) / H, H / (T_B - tv_b))
        arc = np.log1p(wL * (p_a + p_b) / ((T_A + T_B) * p_a))
        stretch_x, shape_x = H * L / EA, H / w * arc
        r_x = np.abs(stretch_x + shape_x - span)
        stretch_y, shape_y = L * m / EA, (T_B - T_A) / w
        r_y = np.abs(stretch_y + shape_y - dh)
        terms = np.maximum(stretch_x + shape_x + span, np.abs(stretch_y) + (T_A + T_B) / w + np.abs(dh))
    chord = np.hypot(span, dh)
    return np.maximum(r_x, r_y) / chord, CHECK_ULPS * _EPS * terms / chord


def sag_of(H, m, w, EA, L, span, dh):
    """Largest vertical distance chord–cable: at the material point whose slope is the chord's."""
    tv_a = m - 0.5 * w * L
    tv_s = H * dh / span
    s = (tv_s - tv_a) / w
    T_A, T_s = _tension(H, tv_a), _tension(H, tv_s)
    x = H * s / EA + H / w * _arc(tv_a, tv_s, T_A, T_s, H, w * s)
    y = s * (tv_s + tv_a) * (0.5 / EA + 1.0 / (T_s + T_A))
    return dh * x / span - y


def stretched_length_of(H, m, w, EA, L):
    r"""Loaded length :math:`L + \int T/EA\,ds = L + (T_{v,B}T_B - T_{v,A}T_A + H^2\,\text{arc})/(2wEA)`."""
    wL = w * L
    tv_a, tv_b = m - 0.5 * wL, m + 0.5 * wL
    T_A, T_B = _tension(H, tv_a), _tension(H, tv_b)
    arc = _arc(tv_a, tv_b, T_A, T_B, H, wL)
    return L + (tv_b * T_B - tv_a * T_A + H * H * arc) / (2.0 * w * EA)
