r"""Elastic catenary resting on a flat seabed, with Coulomb friction.

Anchor A at (0, 0) on the seabed, fairlead B at (span, dh) above it, weight
``w`` per unstretched length, axial stiffness ``EA``, unstretched length
``L``, friction coefficient ``C_B``. When the freely hanging line would leave
A downwards (upward reaction ``V_A > 0``), the part ``L_B = L - V_B/w`` rests
on the seabed and the rest hangs as an elastic catenary tangent to the
seabed at the touchdown point. The closure equations in the fairlead forces
``(H, V_B)`` are those of J.M. Jonkman, "Dynamics modeling and loads analysis
of an offshore floating wind turbine", NREL, 2007, also used by MoorPy
(M. Hall's quasi-static mooring code at NREL):

.. math::
    X = L_B + \frac{H}{w}\operatorname{asinh}\frac{V_B}{H} + \frac{H L}{EA}
        + \frac{C_B w}{2EA}\Big[-L_B^2 + (L_B - \tfrac{H}{C_B w})
          \max(L_B - \tfrac{H}{C_B w}, 0)\Big], \qquad
    Z = \frac{H}{w}\Big(\sqrt{1 + (V_B/H)^2} - 1\Big) + \frac{V_B^2}{2 EA w},

here written with the tensioned grounded length
:math:`\ell = \min(L_B, H/(C_B w))`: the grounded part stretches by
:math:`(H\ell - C_B w \ell^2/2)/EA` and the anchor keeps
:math:`H_A = \max(H - C_B w L_B, 0)`. With ``L_B <= 0`` the line hangs
freely (H.M. Irvine, "Cable Structures", MIT Press, 1981).

With the anchor a height ``d`` above the seabed and no friction, the line
hangs from A down to a first touchdown (its vertex on the seabed): its height
:math:`(T_1 - H)/w + V_1^2/(2 EA w) = d` is a quadratic in :math:`u = T_1 - H`,
so :math:`V_1(H)` is closed-form and the same two closure equations hold with
:math:`x_1(H)` added to X and :math:`s_1 = V_1/w` taken from the grounded
length (MoorPy splits the line the same way). With friction the grounded part
between two touchdowns is statically indeterminate, and refused.

The fairlead stiffness :math:`\partial(H, V_B)/\partial(X, Z)` is the inverse
of the Jacobian of the closure equations (implicit function theorem).

A line longer than its L-shape, :math:`X \le L - l_A - l_B` with the vertical
hanging lengths :math:`l = 2d/(1 + \sqrt{1 + 2 w d/EA})` over the heights
:math:`d` of B and A above the seabed (the root of :math:`d = l + w l^2/(2EA)`),
has no solution with :math:`H > 0`: its slack lies in a heap on the seabed,
:math:`H = 0`, :math:`V_B = w l_B`, :math:`\partial V_B/\partial Z = w/(1 + w l_B/EA)`
(MoorPy's slack profiles 4 and 5; the elastic catenary of H.M. Irvine,
"Cable Structures", MIT Press, 1981, at :math:`H = 0`).
"""

from __future__ import annotations

import math
from functools import cached_property
from itertools import zip_longest

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, float_range, nonnegative, positive, real, require, whole
from skcable._xp import namespace, scalar_math
from skcable.cable._elastic import ElasticCatenary, elastic_stiffness, inverse_2x2
from skcable.cable._elastic import elastic_catenary as free_elastic_catenary
from skcable.cable._roots import find_root
from skcable.cable._special import asinh_diff, largest_abs
from skcable.cable.solution import CableSolution, checked_closed_form, matrix_2x2
from skcable.errors import ConvergenceError, InputError

__all__ = [
    "SeabedCatenary",
    "SlopedSeabedCatenary",
    "elastic_catenary",
    "grounded_closure",
    "sloped_seabed_catenary",
]

_TOL = 1e-13


def _tensioned(H, L_B, mu_w):
    """Length of the grounded part that carries tension, ``min(L_B, H/(C_B w))``."""
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
    vertical reaction at A), ``T_1``, its abscissa ``x_1``, the length ``s_1 = V_1/w``
    and ``dV_1/dH``; all zero for ``depth = 0``.
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
    """Residuals ``X(H, V) - span``, ``Z(H, V) - dh`` of the grounded line and
    their Jacobian in ``(H, V)`` (``V`` the vertical force at B, ``mu_w``
    the friction force per unit grounded length). With ``depth > 0`` the anchor
    is that high above the seabed and the line hangs from it down to a first
    touchdown (`anchor_part`); ``dh`` is then measured from A, as always."""
    xp = namespace(span, dh, w, EA, L, mu_w, H, V, depth)
    V1, T1, x1, s1, dV1 = anchor_part(H, w, EA, depth)
    L_B = L - s1 - V / w
    T = xp.hypot(H, V)
    ell = _tensioned(H, L_B, mu_w)
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


def _inextensible_guess(span, dh, w, EA, L, H0):
    """Frictionless inextensible touchdown line, lengthened by the strain of
    the free solution (``H0``): ``h = H/w`` from the monotone
    ``X(h) = L - v + h asinh(v/h)``, ``v = sqrt(Z^2 + 2 Z h)``."""
    L1 = L * (1.0 + H0 / EA)
    ok = L1 > dh * (1 + 1e-9)
    h_max = np.where(ok, (L1 * L1 - dh * dh) / (2.0 * np.where(ok, dh, 1.0)), 1.0)

    def f(h, span, dh, L1):
        xp = namespace(h, span)
        v = xp.sqrt(dh * dh + 2.0 * dh * h)
        return L1 - v + h * xp.arcsinh(v / h) - span

    lo, hi = h_max * 1e-12, h_max
    f_lo, f_hi = f(lo, span, dh, L1), f(hi, span, dh, L1)
    inside = ok & (f_lo < 0) & (f_hi > 0)
    h = np.where(f_lo >= 0, lo, hi)
    if inside.any():
        idx = np.flatnonzero(inside)
        args = [v[idx] for v in (lo, hi, span, dh, L1)]
        if idx.size == 1:  # Brent's method on floats: the elementwise search costs ~10 ms a call
            args = [float(v[0]) for v in args]
        # a starting point only: Newton on the full equations refines it
        root, _ = find_root(f, args[0], args[1], tuple(args[2:]), what="seabed guess", xtol=1e-9 * args[1])
        h[idx] = root
    h = np.where(ok, h, H0 / w)
    V = np.where(ok, np.sqrt(dh * dh + 2.0 * dh * h), w * L * (1 - 1e-9))
    return w * h, np.minimum(V * w, w * L * (1 - 1e-9))


def _inextensible_guess_scalar(span, dh, w, EA, L, H0):
    """`_inextensible_guess` of one scene, on Python floats."""
    L1 = L * (1.0 + H0 / EA)
    cap = w * L * (1 - 1e-9)
    if not L1 > dh * (1 + 1e-9):
        return w * (H0 / w), min(cap * w, cap)
    h_max = (L1 * L1 - dh * dh) / (2.0 * dh)

    def f(h):
        v = math.sqrt(dh * dh + 2.0 * dh * h)
        return L1 - v + h * math.asinh(v / h) - span

    lo, hi = h_max * 1e-12, h_max
    f_lo, f_hi = f(lo), f(hi)
    h = lo if f_lo >= 0 else hi
    if f_lo < 0 and f_hi > 0:  # a starting point only: Newton on the full equations refines it
        h, _ = find_root(f, lo, hi, what="seabed guess", xtol=1e-9 * hi)
    V = math.sqrt(dh * dh + 2.0 * dh * h)
    return w * h, min(V * w, cap)


def _solve_grounded_scalar(span, dh, w, EA, L, mu_w, H0, depth):
    """`_solve_grounded` of one scene, on Python floats (the same iteration)."""
    _, _, x1, s1, _ = anchor_part(H0, w, EA, depth)
    H, V = _inextensible_guess_scalar(span - x1, dh + depth, w, EA, L - s1, H0)
    chord = math.hypot(span, dh)
    f_x, f_z, j_xh, j_xv, j_zh, j_zv = grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth)
    norm = max(abs(f_x), abs(f_z)) / chord
    history = [norm]
    polish = 0
    for _ in range(80):
        if norm < _TOL:
            polish += 1  # one more step into the round-off floor
            if polish > 1:
                return H, V, history
        det = j_xh * j_zv - j_xv * j_zh
        if not (det != 0.0 and math.isfinite(det)):
            break
        d_h = -(f_x * j_zv - f_z * j_xv) / det
        d_v = -(j_xh * f_z - j_zh * f_x) / det
        step = 1.0
        for _ in range(40):  # backtrack: H > 0, 0 < V <= wL, residual reduced
            H_new, V_new = H + step * d_h, V + step * d_v
            s1 = anchor_part(H_new if H_new > 0 else 1.0, w, EA, depth)[3]
            valid = H_new > 0 and V_new > 0 and V_new <= w * (L - s1)
            H_try, V_try = (H_new, V_new) if valid else (H, V)
            f_x, f_z, j_xh, j_xv, j_zh, j_zv = grounded_closure(span, dh, w, EA, L, mu_w, H_try, V_try, depth)
            new = max(abs(f_x), abs(f_z)) / chord
            if valid and new < norm * (1.0 - 1e-4 * step) + 4 * _TOL:
                break
            step = 0.5 * step
        H, V, norm = H_try, V_try, new
        history.append(norm)
    raise ConvergenceError("elastic_catenary (seabed): Newton did not converge", history)


def _solve_grounded(span, dh, w, EA, L, mu_w, H0, depth):
    """Newton with backtracking on the grounded closure, arrays of contact elements."""
    _, _, x1, s1, _ = anchor_part(H0, w, EA, depth)
    H, V = _inextensible_guess(span - x1, dh + depth, w, EA, L - s1, H0)
    chord = np.hypot(span, dh)
    f_x, f_z, *jac = grounded_closure(span, dh, w, EA, L, mu_w, H, V, depth)
    norm = np.maximum(np.abs(f_x), np.abs(f_z)) / chord
    history = [largest_abs(norm)]
    polish = 0
    for _ in range(80):
        if history[-1] < _TOL:
            polish += 1  # one more step into the round-off floor
            if polish > 1:
                return H, V, history
        j_xh, j_xv, j_zh, j_zv = jac
        det = j_xh * j_zv - j_xv * j_zh
        d_h = -(f_x * j_zv - f_z * j_xv) / det
        d_v = -(j_xh * f_z - j_zh * f_x) / det
        step = np.ones_like(H)
        for _ in range(40):  # backtrack: H > 0, 0 < V <= wL, residual reduced
            H_new, V_new = H + step * d_h, V + step * d_v
            with np.errstate(invalid="ignore", divide="ignore"):
                s1 = anchor_part(np.where(H_new > 0, H_new, 1.0), w, EA, depth)[3]
            valid = (H_new > 0) & (V_new > 0) & (V_new <= w * (L - s1))
            H_try = np.where(valid, H_new, H)
            V_try = np.where(valid, V_new, V)
            f_x, f_z, *jac = grounded_closure(span, dh, w, EA, L, mu_w, H_try, V_try, depth)
            new = np.maximum(np.abs(f_x), np.abs(f_z)) / chord
            ok = valid & (new < norm * (1.0 - 1e-4 * step) + 4 * _TOL)
            if ok.all():
                break
            step = np.where(ok, step, 0.5 * step)
        H, V, norm = H_try, V_try, new
        history.append(largest_abs(norm))
    raise ConvergenceError("elastic_catenary (seabed): Newton did not converge", history)


class SeabedCatenary(CableSolution):
    """Solution of `elastic_catenary` with a ``seabed``.

    ``H`` is the horizontal tension of the suspended part (the fairlead's),
    ``V_B`` the vertical force at B, ``V_A`` the upward reaction at A (zero
    when the line rests on the seabed there), ``H_A`` the horizontal tension
    at the anchor (``H`` less the friction, never negative), ``T_A, T_B``.
    ``length_on_seabed`` is the unstretched grounded length ``L_B``,
    ``x_touchdown`` the abscissa where the line leaves the seabed towards B
    (0 when it hangs freely). With the anchor above the seabed (frictionless
    only) the line first hangs from A down to the seabed: ``length_to_seabed``
    (unstretched), landing at ``x_landing``; both are 0 otherwise.
    ``suspended`` is the `ElasticCatenary` of the part that rises from the
    seabed (or from A, when nothing touches) to B. ``T_of_s``, ``x_of_s``,
    ``y_of_s`` map the unstretched arc length from A; ``y(x)``,
    ``T(x)``, ``slope(x)`` the abscissa (the grounded part lies on the seabed).

    ``heap`` (bool, an array for array input) marks the state where the line is
    longer than its L-shape and the slack lies in a heap on the seabed: ``H = H_A = 0``;
    the part from B hangs vertically down to the seabed at ``x_touchdown = span``
    over its unstretched length ``l_B`` (`hanging_length` of ``dh - seabed``),
    ``V_B = T_B = w l_B``; with the anchor above the seabed the part from A hangs
    likewise (``V_A = w l_A``, ``x_landing = 0``), else ``V_A = 0``; the rest,
    ``length_on_seabed = L - l_A - l_B >= span``, carries no tension and does not
    stretch (friction plays no part). Statics do not fix where that slack lies: the
    maps draw it spread evenly along the seabed from the landing point to the
    touchdown. ``suspended`` raises there (no catenary hangs).
    """

    def __init__(self, span, dh, w, EA, length, friction, seabed, H, V_t, L_B, V_1=0.0, y_t=0.0, heap=False):
        self.span, self.dh, self.w, self.EA, self.length = span, dh, w, EA, length
        self.friction, self.seabed = friction, seabed
        self.H, self.length_on_seabed = H, L_B
        self.constraint = ("length", length)
        self._xp = namespace(span, dh, w, EA, length, friction, H, V_t, L_B, V_1, y_t)
        self.heap = heap
        """Whether the slack lies in a heap on the seabed (``H = 0``), per element."""
        self._any_heap = bool(np.any(heap))
        # the regular formulae run on every element; at a heap element they get a stand-in
        # H (1 N) and span (1 m) that keep them finite, and every result is replaced there
        self._Hr = _heap_where(heap, 1.0, H)
        self._mu_w = friction * w
        self._V1, self._y_t = V_1, y_t
        self.length_to_seabed = V_1 / w
        """Unstretched length hanging from A down to the seabed (0 unless the anchor is above it)."""
        self._l_B = length - L_B - self.length_to_seabed
        self._hanging = ElasticCatenary(
            _heap_where(heap, 1.0, span - self.x_touchdown),
            dh - y_t,
            w,
            EA,
            self._l_B,
            self._Hr,
            V_t,
            ("length", self._l_B),
        )

    @property
    def suspended(self):
        """The `ElasticCatenary` of the part rising from the seabed (or from A) to B.

        Raises `InputError` (``length``) in a heap state: the part from B then hangs
        vertically (``H = 0``) and is no catenary; use the maps of this solution."""
        if self._any_heap:
            raise InputError(
                "length",
                "leaves the slack in a heap on the seabed (H = 0): the part from B hangs vertically, "
                "no suspended catenary; use x_of_s, y_of_s, T_of_s of the solution",
            )
        return self._hanging

    def _pick(self, heap_value, regular):
        """``regular()`` where the line is taut, ``heap_value()`` at heap elements."""
        if not self._any_heap:
            return regular()
        if np.ndim(self.heap) == 0:
            return heap_value()
        with np.errstate(all="ignore"):  # each branch is finite where it is taken
            taut, heap = regular(), heap_value()
        return _out(np.where(self.heap, heap, taut))

    @cached_property
    def H_A(self):
        """Horizontal tension at the anchor (N)."""
        return self._xp.maximum(self.H - self._mu_w * self.length_on_seabed, 0.0)

    @cached_property
    def _ell(self):
        return _tensioned(self.H, self.length_on_seabed, self._mu_w) + 0.0 * self.H

    # -- the part hanging from an anchor above the seabed (empty otherwise) -----------
    def _left_x(self, s):
        H = self._Hr
        return H * s / self.EA + H / self.w * asinh_diff((self.w * s - self._V1) / H, -self._V1 / H)

    def _left_y(self, s):
        tv, tv_a = self.w * s - self._V1, -self._V1
        rise = (tv - tv_a) * (tv + tv_a) / (np.hypot(self._Hr, tv) + np.hypot(self._Hr, tv_a))
        return s * (0.5 * self.w * s - self._V1) / self.EA + rise / self.w

    @cached_property
    def x_landing(self):
        """Abscissa where the line from an anchor above the seabed lands on it (0 otherwise;
        0 in a heap state: the part from A hangs vertically)."""
        return self._pick(lambda: 0.0 * self.span, lambda: _out(self._left_x(self.length_to_seabed)))

    @cached_property
    def x_touchdown(self):
        """Abscissa where the line leaves the seabed towards B (the grounded line stretched;
        ``span`` in a heap state)."""

        def taut():
            ell = _tensioned(self.H, self.length_on_seabed, self._mu_w)
            grounded = self.length_on_seabed + (self.H * ell - 0.5 * self._mu_w * ell * ell) / self.EA
            return _out(self.x_landing + grounded)

        return self._pick(lambda: self.span + 0.0 * self.H, taut)

    @property
    def V_A(self):
        return self._hanging.V_A + self._V1

    @property
    def V_B(self):
        return self._hanging.V_B

    @cached_property
    def T_A(self):
        return self._xp.hypot(self.H_A, self.V_A)

    @property
    def T_B(self):
        return self._pick(lambda: self.V_B, lambda: self._hanging.T_B)

    @cached_property
    def stretched_length(self):
        """Stretched length of the whole line (anchor part, grounded, suspended)."""
        # heap: the vertical parts span the heights exactly, the slack does not stretch
        heap = self.length_on_seabed + self.dh - 2.0 * self._y_t
        return self._pick(lambda: heap, self._taut_stretched_length)

    def _taut_stretched_length(self):
        H, V1 = self._Hr, self._V1

        def primitive(tv):  # ∫ sqrt(H² + tv²) d(tv)
            return 0.5 * (tv * np.hypot(H, tv) + H * H * np.arcsinh(tv / H))

        left = self.length_to_seabed + (primitive(0.0) - primitive(-V1)) / (self.w * self.EA)
        grounded = self.x_touchdown - self.x_landing
        return _out(left + grounded + self._hanging.stretched_length)

    @property
    def x_vertex(self):
        return self._pick(lambda: self.span + 0.0 * self.H, lambda: self.x_touchdown + self._hanging.x_vertex)

    @property
    def y_vertex(self):
        return self._pick(lambda: self._y_t + 0.0 * self.H, lambda: self._y_t + self._hanging.y_vertex)

    @property
    def x_low(self):
        return self._pick(lambda: self.span + 0.0 * self.H, lambda: self.x_touchdown + self._hanging.x_low)

    @property
    def y_low(self):
        return self._pick(lambda: self._y_t + 0.0 * self.H, lambda: self._y_t + self._hanging.y_low)

    # -- along the line ---------------------------------------------------------------
    def _grounded_tension(self, s):
        """Tension of the grounded part at ``s`` in [0, L_B] from its start: ``H_A + C_B w (s - a)``."""
        a = self.length_on_seabed - self._ell
        return self.H_A + self._mu_w * np.maximum(s - a, 0.0)

    def _taut_T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A, in [0, length]."""
        s = self._arc("s", s)
        s1, L_B = self.length_to_seabed, self.length_on_seabed
        tv = self.w * np.maximum(s - s1 - L_B, 0.0) - self._hanging.V_A
        hang = np.where((s <= s1) & (s1 > 0), np.hypot(self.H, self.w * s - self._V1), np.hypot(self.H, tv))
        ground = self._grounded_tension(np.clip(s - s1, 0.0, L_B))
        # nothing grounded (L_B = 0): the point s1 belongs to the hanging line, whose
        # tension there carries the anchor's vertical pull
        return _out(np.where((s >= s1) & (s <= s1 + L_B) & (L_B > 0), ground, hang))

    def _taut_x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A)."""
        s = self._arc("s", s)
        s1, L_B, ell = self.length_to_seabed, self.length_on_seabed, self._ell
        on = np.clip(s - s1, 0.0, L_B)
        d = np.maximum(on - (L_B - ell), 0.0)
        ground = self.x_landing + on + (self.H_A * d + 0.5 * self._mu_w * d * d) / self.EA
        hang = self.x_touchdown + self._hanging.x_of_s(np.maximum(s - s1 - L_B, 0.0))
        left = self._left_x(np.minimum(s, s1))
        return _out(np.where(s <= s1, left, np.where(s <= s1 + L_B, ground, hang)))

    def _taut_y_of_s(self, s):
        """Height above A of the material point ``s`` (the seabed's height on it)."""
        s = self._arc("s", s)
        s1, L_B = self.length_to_seabed, self.length_on_seabed
        hang = self._y_t + self._hanging.y_of_s(np.maximum(s - s1 - L_B, 0.0))
        left = self._left_y(np.minimum(s, s1))
        return _out(np.where(s <= s1, left, np.where(s <= s1 + L_B, self._y_t, hang)))

    def _arc(self, name, s):
        s = real(name, s)
        require(name, (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def _split(self, x):
        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        x_t = self.x_touchdown
        grounded = x <= x_t
        return x, grounded, np.clip(x - x_t, 0.0, self._hanging.span)

    def _left_s_of_x(self, x):
        """Material point on the anchor part at ``x < x_landing`` (NaN elsewhere)."""
        x1 = self.x_landing
        xb, x1b, Hb, Vb, wb, EAb, s1b = np.broadcast_arrays(
            x, x1, self.H, self._V1, self.w, self.EA, self.length_to_seabed
        )
        out = np.full(xb.shape, np.nan)
        inside = xb < x1b
        if inside.any():

            def f(s, x, H, V1, w, EA):
                return H * s / EA + H / w * asinh_diff((w * s - V1) / H, -V1 / H) - x

            args = [v[inside] for v in (s1b, xb, Hb, Vb, wb, EAb)]
            if args[0].size == 1:  # Brent's method on floats
                args = [float(v[0]) for v in args]
            root, _ = find_root(f, 0.0 * args[0], args[0], tuple(args[1:]), what="s_of_x")
            out[inside] = root
        return out

    def _taut_s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span]."""
        x, grounded, xs = self._split(x)
        s1, L_B, ell = self.length_to_seabed, self.length_on_seabed, self._ell
        # on the seabed x - x_1 - a = d (1 + H_A/EA) + C_B w d^2 / (2 EA), s = s_1 + a + d
        a = L_B - ell
        on = np.maximum(np.minimum(x, self.x_touchdown) - self.x_landing, 0.0)
        c = np.maximum(on - a, 0.0)
        b = 1.0 + self.H_A / self.EA
        d = 2.0 * c / (b + np.sqrt(b * b + 2.0 * self._mu_w * c / self.EA))
        ground = s1 + np.minimum(np.where(on <= a, on, a + d), L_B)
        left = self._left_s_of_x(x)
        hang = s1 + L_B + self._hanging.s_of_x(xs)
        return _out(np.where(x < self.x_landing, left, np.where(grounded, ground, hang)))

    def y(self, x):
        """Height above A at abscissa ``x`` (the seabed's on the grounded part)."""
        s = self.s_of_x(x)
        return self.y_of_s(s)

    def _taut_slope(self, x):
        """dy/dx at ``x`` (0 on the seabed)."""
        s = np.asarray(self.s_of_x(x))
        s1, L_B = self.length_to_seabed, self.length_on_seabed
        tv_right = self.w * np.maximum(s - s1 - L_B, 0.0) - self._hanging.V_A
        tv = np.where(s <= s1, self.w * s - self._V1, np.where(s <= s1 + L_B, 0.0, tv_right))
        return _out(tv / self.H)

    def T(self, x):
        """Tension at abscissa ``x`` (N)."""
        return self.T_of_s(self.s_of_x(x))

    def weight_per_length(self, x, slope):
        return self.w + 0.0 * slope

    # -- checks and stiffness -----------------------------------------------------------
    def _taut__residuals(self):
        xp = self._xp
        chord = xp.hypot(self.span, self.dh)
        hang = self._hanging
        L_s = hang.length
        yield (self.x_touchdown + hang.x_of_s(L_s) - self.span) / chord
        stretch, shape = hang._y_terms(L_s)
        scale = chord + xp.abs(stretch) + xp.abs(shape) + xp.abs(self._y_t)
        yield (self._y_t + stretch + shape - self.dh) / scale
        # the anchor part lands on the seabed
        left = self._left_y(self.length_to_seabed)
        yield (left - self._y_t) * (self._V1 > 0) / (chord + xp.abs(self._y_t))
        weight = self.w * self.length
        # the seabed carries w·L_B: V_A + V_B + w·L_B = w·L
        ground = self.w * self.length_on_seabed
        yield (self.V_A + self.V_B + ground - weight) / (xp.abs(self.V_A) + xp.abs(self.V_B) + weight)
        # friction carries H - H_A, at most C_B w L_B; the anchor never pushes
        slack = self.H - self.H_A - self._mu_w * self.length_on_seabed
        yield xp.maximum(slack, 0.0) / (self.H + self._mu_w * self.length_on_seabed)
        yield xp.minimum(self.H_A, 0.0) / self.H
        # touchdown tangent to the seabed, or no contact with the anchor pulled up
        yield xp.minimum(self.length_on_seabed, 0.0) / self.length
        contact = self.length_on_seabed > 0
        yield xp.abs(hang.V_A) * contact / hang.T_A if xp is np else (hang.V_A / hang.T_A if contact else 0.0)
        for T, H, V in ((self.T_A, self.H_A, self.V_A), (self.T_B, self.H, self.V_B)):
            yield (T - xp.hypot(H, V)) / xp.maximum(T, self.H)

    def _taut_stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(*shape, 2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the Jacobian of the
        closure equations in ``(H, V_B)``, grounded or free, friction included.
        """
        touches = (self.length_on_seabed > 0) | (self._V1 > 0)
        free = elastic_stiffness(self._hanging)
        depth = -self._y_t
        jac = grounded_closure(
            self.span, self.dh, self.w, self.EA, self.length, self._mu_w, self.H, self.V_B, depth
        )[2:]
        ground = inverse_2x2(*jac)
        return np.where(np.asarray(touches)[..., None, None], ground, free)

    # -- the heap state (H = 0): vertical parts at A and B, slack spread on the seabed ----
    def _heap_parts(self, s):
        """``s`` broadcast, the anchor part's length ``s_1``, the grounded ``L_B``, the
        arc length ``sigma`` above the seabed on B's vertical part."""
        s1, L_B = self.length_to_seabed, self.length_on_seabed
        return s1, L_B, np.maximum(s - s1 - L_B, 0.0)

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A, in [0, length].

        In a heap state each vertical part carries the weight below it down to the
        seabed (``w (s_1 - s)`` from A, ``w sigma`` at ``sigma`` above the seabed on
        the part from B); the slack on the seabed carries none."""

        def heap():
            s1, L_B, sigma = self._heap_parts(s)
            return _out(np.where(s <= s1, self.w * (s1 - s), np.where(s <= s1 + L_B, 0.0, self.w * sigma)))

        s = self._arc("s", s)
        return self._pick(heap, lambda: self._taut_T_of_s(s))

    def x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A).

        In a heap state the vertical parts lie at ``x = 0`` and ``x = span``; the
        shape of the slack on the seabed is not determined by statics (it carries no
        tension): it is drawn spread evenly from ``x_landing = 0`` to
        ``x_touchdown = span``, ``x`` linear in ``s``."""

        def heap():
            s1, L_B, _ = self._heap_parts(s)
            spread = np.clip(s - s1, 0.0, L_B) / L_B * self.span
            return _out(spread + 0.0 * s)

        s = self._arc("s", s)
        return self._pick(heap, lambda: self._taut_x_of_s(s))

    def y_of_s(self, s):
        """Height above A of the material point ``s`` (the seabed's height on it).

        In a heap state the part from B carries ``w u`` at ``u`` above its foot, so the
        point ``sigma`` above the foot lies ``sigma + w sigma^2/(2 EA)`` above the seabed;
        the part from A carries ``w (s_1 - s)`` and the point ``s`` lies
        ``s + w (s_1 s - s^2/2)/EA`` below A (H.M. Irvine, "Cable Structures", MIT Press,
        1981, the elastic catenary at ``H = 0``)."""

        def heap():
            s1, L_B, sigma = self._heap_parts(s)
            w, EA = self.w, self.EA
            a = np.minimum(s, s1)
            below_A = 0.0 - (a + w * (s1 * a - 0.5 * a * a) / EA)
            above = self._y_t + sigma * (1.0 + 0.5 * w * sigma / EA)
            return _out(np.where(s <= s1, below_A, np.where(s <= s1 + L_B, self._y_t, above)))

        s = self._arc("s", s)
        return self._pick(heap, lambda: self._taut_y_of_s(s))

    def s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span].

        In a heap state ``x = 0`` is A, ``x = span`` is B (the vertical parts
        project to the ends) and the points between map to the slack spread evenly
        on the seabed (see `x_of_s`)."""

        def heap():
            s1, L_B = self.length_to_seabed, self.length_on_seabed
            spread = s1 + x / self.span * L_B
            return _out(np.where(x <= 0.0, 0.0, np.where(x >= self.span, self.length, spread)))

        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        return self._pick(heap, lambda: self._taut_s_of_x(x))

    def slope(self, x):
        """dy/dx at ``x`` (0 on the seabed).

        In a heap state the line is vertical at ``x = span`` (and at ``x = 0`` with
        the anchor above the seabed): no finite slope there, `InputError` (``x``)."""

        def heap():
            x_b = np.broadcast_to(x, np.broadcast_shapes(np.shape(x), np.shape(self.span)))
            vertical = self.heap & ((x_b >= self.span) | ((x_b <= 0.0) & (self._V1 > 0)))
            if np.any(vertical):
                raise InputError(
                    "x", "the line hangs vertically there (slack in a heap, H = 0): no finite slope"
                )
            return _out(0.0 * x_b)

        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        return self._pick(heap, lambda: self._taut_slope(x))

    def samples(self, n: int = 201) -> dict:
        """One scene's profile at ``n`` equally spaced x (see `CableSolution.samples`).

        In a heap state the points at ``x = 0`` and ``x = span`` are A and B (the
        vertical parts project onto them), with the angle of the vertical tangent there
        (``-pi/2`` leaving A downwards when the anchor is above the seabed, ``pi/2``
        rising to B) and 0 on the seabed between."""
        if not (self._any_heap and np.ndim(self.heap) == 0):
            return super().samples(n)
        x = np.linspace(0.0, float(self.span), whole("n", n, 2))
        angle = np.zeros_like(x)
        angle[-1] = 0.5 * np.pi
        if self._V1 > 0:
            angle[0] = -0.5 * np.pi
        weight = np.full_like(x, float(self.w))
        return {
            "xy": np.column_stack([x, self.y(x)]),
            "tension": np.asarray(self.T(x), dtype=float),
            "angle": angle,
            "load": np.column_stack([np.zeros_like(x), -weight]),
        }

    def _heap_residuals(self):
        """Residuals of a heap state: the vertical parts span their heights, the
        supports and the seabed carry the weight, the slack covers the span."""
        w, EA, y_t = self.w, self.EA, self._y_t
        chord = self._xp.hypot(self.span, self.dh)
        l_A, l_B, L_B = self.length_to_seabed, self._l_B, self.length_on_seabed
        yield (l_B + w * l_B * l_B / (2.0 * EA) - (self.dh - y_t)) / chord
        yield (l_A + w * l_A * l_A / (2.0 * EA) + y_t) / chord
        weight = w * self.length
        yield (self.V_A + self.V_B + w * L_B - weight) / weight
        yield self._xp.minimum(L_B - self.span, 0.0) / self.span
        yield (self.T_A - self.V_A) / weight + (self.T_B - self.V_B) / weight + self.H / weight

    def _residuals(self):
        if not self._any_heap:
            yield from self._taut__residuals()
            return
        if np.ndim(self.heap) == 0:
            yield from self._heap_residuals()
            return
        with np.errstate(all="ignore"):
            taut, heap = list(self._taut__residuals()), list(self._heap_residuals())
        for t, h in zip_longest(taut, heap, fillvalue=0.0):
            yield np.where(self.heap, h, t)

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(*shape, 2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the Jacobian of the
        closure equations in ``(H, V_B)``, grounded or free, friction included.

        In a heap state (``H = 0``) ``V_B = w l_B`` with ``dh - seabed = l_B + w l_B^2/(2EA)``,
        so ``∂V_B/∂dh = w/(1 + w l_B/EA)`` and the other three entries are 0. This is
        the heap side's stiffness, one-sided at the boundary: the line becomes taut
        again (``H > 0``) only when the span exceeds the slack's length on the seabed.
        """

        def heap():
            k22 = self.w / (1.0 + self.w * self._l_B / self.EA)
            zero = 0.0 * k22
            return matrix_2x2(zero, zero, zero, k22)

        if not self._any_heap:
            return self._taut_stiffness()
        if np.ndim(self.heap) == 0:
            return heap()
        with np.errstate(all="ignore"):
            taut = self._taut_stiffness()
        return np.where(np.asarray(self.heap)[..., None, None], heap(), taut)

    def __repr__(self):
        text = super().__repr__()
        if not self._any_heap:
            return text
        if np.ndim(self.heap) == 0:
            return text[:-1] + "; heap: H = 0, the slack lies on the seabed)"
        return text[:-1] + f"; heap at {int(np.count_nonzero(self.heap))} of {np.size(self.heap)} elements)"


def _heap_where(heap, value, taut):
    """``value`` at heap elements, ``taut`` elsewhere (floats stay floats)."""
    if np.ndim(heap) == 0:
        return value if heap else taut
    return np.where(heap, value, taut)


def _out(value):
    """A 0-d result as a Python float (scalar in, scalar out)."""
    return float(value) if np.ndim(value) == 0 else value


def hanging_length(height, w, EA):
    r"""Unstretched length ``l`` of a line hanging vertically (``H = 0``) from a support
    ``height`` above the seabed down to it, its tension ``w u`` at ``u`` above the seabed.

    Its stretched length :math:`l + w l^2/(2 EA)` equals the height (H.M. Irvine,
    "Cable Structures", MIT Press, 1981, the elastic catenary at ``H = 0``); the root
    written without cancellation, :math:`l = 2 d/(1 + \sqrt{1 + 2 w d/EA})`, ``d`` the
    height (m), ``w`` (N/m), ``EA`` (N). 0 at ``height = 0``.
    """
    xp = namespace(height, w, EA)
    return 2.0 * height / (1.0 + xp.sqrt(1.0 + 2.0 * w * height / EA))


def _lifted(span, dh, w, EA, L):
    """Whether the line leaves the anchor upwards (no contact), and the lift-off ``H``.

    At lift-off ``V_A = 0``, ``V_B = wL``: the height equation gives
    ``T + H = P = wL²/D`` with ``D = dh - wL²/(2EA)``, so ``H = (P - (wL)²/P)/2``;
    the line is lifted where ``span`` reaches the lift-off ``X(H, wL)``. With
    ``D <= 0`` the line's own stretch exceeds ``dh`` and it always touches.
    """
    D = dh - w * L * L / (2.0 * EA)
    if namespace(span, dh, w, EA, L) is scalar_math:  # one scene, on floats
        if D <= 0:
            return False, 0.0
        P = w * L * L / D
        H = 0.5 * (P - (w * L) * (w * L / P))
        if not H > 0:
            return True, 0.0
        X = H * L / EA + H / w * math.asinh(w * L / H)
        return span >= X, H
    touches = np.asarray(D <= 0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        P = w * L * L / np.where(touches, 1.0, D)
        H = 0.5 * (P - (w * L) * (w * L / P))
        ok = ~touches & (H > 0)
        H_safe = np.where(ok, H, 1.0)
        X = H_safe * L / EA + H_safe / w * np.arcsinh(w * L / H_safe)
    return ~touches & (~ok | (span >= X)), np.where(ok, H, 0.0)


def elastic_catenary(span, dh, w, EA, *, length, seabed=None, friction=0.0):
    """Elastic (Irvine) catenary from A = (0, 0) to B = (span, dh), optionally on a seabed.

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance A→B (> 0) and height of B above A (m).
    w : float or array_like
        Weight per unit *unstretched* length (N/m), > 0.
    EA : float or array_like
        Axial stiffness (N), > 0.
    length : float or array_like
        Unstretched length (m), > 0; it may be shorter than the chord (the
        cable then stretches to reach B).
    seabed : float or array_like, optional
        Height of a flat seabed relative to A (m), ``<= 0``. With ``seabed=0``
        (the anchor on the seabed) the part of the line that would hang below
        A rests on it (J.M. Jonkman, "Dynamics modeling and loads analysis of
        an offshore floating wind turbine", NREL, 2007). Below A (``seabed < 0``)
        a line that reaches it hangs from A down to the seabed, rests on it and
        rises to B (frictionless only). B must lie above the seabed.
    friction : float or array_like, optional
        Coulomb friction coefficient of the grounded part, ``>= 0``; only with
        a ``seabed``, and 0 where the line touches down between A and B.

    Returns
    -------
    ElasticCatenary
        Without a seabed (H.M. Irvine, "Cable Structures", MIT Press, 1981):
        ``H, V_A, V_B, T_A, T_B, length`` (unstretched), ``stretched_length``,
        ``sag``, the lowest point ``x_low, y_low``, the vertex ``x_vertex,
        y_vertex``, ``y(x), T(x), slope(x), residual()``, ``stiffness()``.
    SeabedCatenary
        With a ``seabed``: the same forces, maps and ``stiffness()``, plus
        ``H_A``, ``length_on_seabed``, ``x_touchdown``, ``length_to_seabed``,
        ``x_landing``, ``T_of_s(s)``, ``suspended``, ``heap``. A line longer than
        its L-shape (``span <= L - l_A - l_B``, `hanging_length`) has no solution
        with ``H > 0``: its slack lies in a heap on the seabed, returned as such
        (``heap`` True, ``H = 0``, see `SeabedCatenary`; MoorPy's slack profiles
        4 and 5).

    Raises
    ------
    InputError
        A non-physical argument, named: a seabed above A, B on or below it,
        friction without a seabed or where it is indeterminate.
    ConvergenceError
        Newton stalled; the error carries the residual history.
    """
    if seabed is None:
        if friction is not None and np.any(np.asarray(friction) != 0.0):
            raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
        return free_elastic_catenary(span, dh, w, EA, length=length)
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    EA = positive("EA", EA)
    L0 = positive("length", length)
    seabed = real("seabed", seabed)
    friction = nonnegative("friction", friction)
    broadcast(span=span, dh=dh, w=w, EA=EA, length=L0, seabed=seabed, friction=friction)
    _plausible.stiffness(EA, w, L0)
    require("seabed", np.asarray(seabed) <= 0, "must be at or below the anchor (A at height 0)", seabed)
    require("dh", np.asarray(dh) > seabed, "must put B above the seabed", dh)
    if all(isinstance(v, float) for v in (span, dh, w, EA, L0, seabed, friction)):
        return _seabed_catenary_scalar(span, dh, w, EA, L0, seabed, friction)
    shape = np.broadcast_shapes(*(np.shape(v) for v in (span, dh, w, EA, L0, seabed, friction)))
    on_bed = np.broadcast_to(np.asarray(seabed) == 0, shape)
    lifted, H_lift = _lifted(span, dh, w, EA, L0)
    contact = np.asarray(on_bed & ~np.broadcast_to(lifted, shape))
    H, V_t, L_B, V_1 = np.zeros(shape), np.zeros(shape), np.zeros(shape), np.zeros(shape)
    guess = np.array(np.broadcast_to(np.where(H_lift > 0, np.minimum(H_lift, w * L0), w * L0), shape))
    depth = np.zeros(shape)
    dips = np.zeros(shape, dtype=bool)
    history = []
    if not contact.all():
        hanging = np.asarray(~contact)
        args = [np.broadcast_to(v, shape)[hanging] for v in (span, dh, w, EA, L0)]
        if shape == ():
            args = [float(v[0]) for v in args]
        free = free_elastic_catenary(*args[:4], length=args[4])
        H[hanging], V_t[hanging] = free.H, free.V_A
        # anchor above the seabed and the free line below it: a touchdown between A and B
        dips[hanging] = np.asarray(free.y_low) < np.broadcast_to(seabed, shape)[hanging]
        if dips.any():
            contact = contact | dips
            depth[dips] = -np.broadcast_to(seabed, shape)[dips]
            guess[dips] = H[dips]
    heap = np.zeros(shape, dtype=bool)
    if contact.any():
        # H -> 0: A and B hold the vertical parts l = V_0/w (`hanging_length`), the rest
        # lies at X_0 = L - l_A - l_B; a shorter span leaves the slack in a heap (H = 0)
        l_A, l_B = hanging_length(depth, w, EA), hanging_length(dh + depth, w, EA)
        heap = contact & np.broadcast_to(span <= L0 - l_A - l_B, shape)
        if dips.any():  # a taut line between two touchdowns: friction indeterminate
            require(
                "friction",
                ~(dips & ~heap) | (np.broadcast_to(friction, shape) == 0),
                "must be 0 where the line touches down between A and B (anchor above the seabed): "
                "the static friction there depends on the history of the motion",
                friction,
            )
        if heap.any():  # the heap state: H = 0, vertical parts at A and B, the slack between
            l_A, l_B = np.broadcast_to(l_A, shape), np.broadcast_to(l_B, shape)
            H[heap], V_t[heap] = 0.0, 0.0
            V_1[heap] = (np.broadcast_to(w, shape) * l_A)[heap]
            L_B[heap] = (np.broadcast_to(L0, shape) - l_A - l_B)[heap]
    taut = contact & ~heap
    if taut.any():
        args = [np.broadcast_to(v, shape)[taut] for v in (span, dh, w, EA, L0, friction * w, guess, depth)]
        if shape == ():  # one scene: the same Newton on Python floats
            args = [float(v[0]) for v in args]
            Hc, Vc, history = _solve_grounded_scalar(*args)
        else:
            Hc, Vc, history = _solve_grounded(*args)
        V1 = anchor_part(Hc, args[2], args[3], args[7])[0]
        H[taut], V_t[taut], V_1[taut] = Hc, 0.0, V1
        L_B[taut] = np.maximum(args[4] - V1 / args[2] - Vc / args[2], 0.0)
    y_t = np.where(contact, np.broadcast_to(seabed, shape), 0.0)
    if shape == ():
        H, V_t, L_B, V_1, y_t = (float(v) for v in (H, V_t, L_B, V_1, y_t))
        heap = bool(heap)
    with float_range("length", "a result"):
        solution = SeabedCatenary(span, dh, w, EA, L0, friction, seabed, H, V_t, L_B, V_1, y_t, heap)
        return checked_closed_form(solution, "length", history)


def _seabed_catenary_scalar(span, dh, w, EA, L0, seabed, friction):
    """`elastic_catenary` with a seabed for one scene (checked Python floats): the same
    steps as the array path without its masks and broadcasts."""
    lifted, H_lift = _lifted(span, dh, w, EA, L0)
    contact = seabed == 0 and not lifted
    guess = min(H_lift, w * L0) if H_lift > 0 else w * L0
    H, V_t, L_B, V_1, depth, history = 0.0, 0.0, 0.0, 0.0, 0.0, []
    dips = heap = False
    if not contact:
        free = free_elastic_catenary(span, dh, w, EA, length=L0)
        H, V_t = free.H, free.V_A
        if free.y_low < seabed:  # anchor above the seabed, the free line below it: a touchdown
            contact, depth, guess, dips = True, -seabed, H, True
    if contact:
        # H -> 0: A and B hold the vertical parts l = V_0/w (`hanging_length`), the rest
        # lies at X_0 = L - l_A - l_B; a shorter span leaves the slack in a heap (H = 0)
        l_A, l_B = hanging_length(depth, w, EA), hanging_length(dh + depth, w, EA)
        heap = span <= L0 - l_A - l_B
        if dips and not heap:  # a taut line between two touchdowns: friction indeterminate
            require(
                "friction",
                friction == 0,
                "must be 0 where the line touches down between A and B (anchor above the seabed): "
                "the static friction there depends on the history of the motion",
                friction,
            )
    if heap:  # the heap state: H = 0, vertical parts at A and B, the slack between
        H, V_t, V_1, L_B = 0.0, 0.0, w * l_A, L0 - l_A - l_B
    elif contact:
        H, Vc, history = _solve_grounded_scalar(span, dh, w, EA, L0, friction * w, guess, depth)
        V_1 = anchor_part(H, w, EA, depth)[0]
        V_t, L_B = 0.0, max(L0 - V_1 / w - Vc / w, 0.0)
    y_t = seabed if contact else 0.0
    with float_range("length", "a result"):
        solution = SeabedCatenary(span, dh, w, EA, L0, friction, seabed, H, V_t, L_B, V_1, y_t, heap)
        return checked_closed_form(solution, "length", history)


class SlopedSeabedCatenary:
    """Solution of `sloped_seabed_catenary` (one scene, scalar attributes).

    ``H`` is the horizontal tension of the suspended part (the fairlead's),
    ``V_B`` the vertical force at B, ``H_A, V_A`` the anchor's reaction
    (the grounded line pulls A along the slope, up it for α > 0: the upward
    reaction is ``V_A = -H_A tan α``; with the
    line lifted off A they are the free line's), ``T_A, T_B`` the end
    tensions, ``length_on_seabed`` the unstretched grounded length
    (0 when the line leaves A above the slope), ``x_touchdown, y_touchdown``
    where it leaves the seabed, ``history`` the closure residuals of the
    Newton (``hybr``) solve.
    """

    def __init__(self, span, dh, w, EA, length, slope, friction, H, L_B, history):
        self.span, self.dh, self.w, self.EA, self.length = span, dh, w, EA, length
        self.seabed_slope, self.friction = slope, friction
        self.H, self.length_on_seabed, self.history = H, L_B, list(history)
        cos = 1.0 / np.hypot(1.0, slope)
        sin = slope * cos
        self._cos, self._sin = cos, sin
        k = w * (sin + friction * cos)  # tension gradient along the grounded line
        T_td = H / cos
        ell = min(L_B, T_td / k) if k > 0 else L_B
        self.T_touchdown = T_td
        self.T_A = max(T_td - k * L_B, 0.0)
        grounded = L_B + (T_td * ell - 0.5 * k * ell * ell) / EA
        self.x_touchdown, self.y_touchdown = grounded * cos, grounded * sin
        self.V_touchdown = H * slope
        self.V_B = self.V_touchdown + w * (length - L_B)
        self.H_A = self.T_A * cos
        self.V_A = -self.T_A * sin  # upward reaction: the grounded line pulls A up the slope
        self.T_B = float(np.hypot(H, self.V_B))

    def closure(self):
        """``(X - span, Z - dh)`` (m) of the grounded solution: what the solve drove to zero."""
        if self.length_on_seabed == 0.0:
            return 0.0, 0.0  # the free line: `elastic_catenary` checked its own residual
        return _sloped_closure(
            self.span,
            self.dh,
            self.w,
            self.EA,
            self.length,
            self.seabed_slope,
            self.friction,
            self.H,
            self.length_on_seabed,
        )

    def residual(self):
        """Largest closure residual over the chord."""
        fx, fz = self.closure()
        return float(max(abs(fx), abs(fz)) / np.hypot(self.span, self.dh))


def _sloped_closure(span, dh, w, EA, L, m, mu, H, L_B):
    """Closure residuals of the line grounded on the slope ``y = m x`` over ``L_B`` from A."""
    cos = 1.0 / np.hypot(1.0, m)
    sin = m * cos
    k = w * (sin + mu * cos)
    T_td = H / cos
    ell = min(L_B, T_td / k) if k > 0 else L_B
    grounded = L_B + (T_td * ell - 0.5 * k * ell * ell) / EA
    L_s = L - L_B
    V_t = H * m
    V_B = V_t + w * L_s
    X = H * L_s / EA + H / w * (np.arcsinh(V_B / H) - np.arcsinh(V_t / H))
    Z = (np.hypot(H, V_B) - np.hypot(H, V_t)) / w + (V_B * V_B - V_t * V_t) / (2.0 * EA * w)
    return grounded * cos + X - span, grounded * sin + Z - dh


def sloped_seabed_catenary(span, dh, w, EA, *, length, seabed_slope, friction=0.0):
    r"""Elastic catenary from an anchor A = (0, 0) lying on a sloped seabed ``y = x tan α``.

    The grounded part lies straight along the slope from A; its tension
    grows towards the fairlead by :math:`dT/ds = w(\sin\alpha + \mu\cos\alpha)`
    (the weight's component along the slope, and Coulomb friction on the
    normal force :math:`w\cos\alpha`, fully mobilised towards the anchor);
    the suspended part leaves the seabed tangentially, with
    :math:`V_t = H\tan\alpha` and :math:`T_t = H/\cos\alpha`, and hangs as an
    elastic catenary to B (H.M. Irvine, "Cable Structures", MIT Press, 1981).
    With :math:`k = w(\sin\alpha + \mu\cos\alpha)` and the tensioned grounded
    length :math:`\ell = \min(L_B, T_t/k)` (:math:`\ell = L_B` when
    :math:`k \le 0`), the closure equations in ``(H, L_B)`` are

    .. math::
        \Big[L_B + \frac{T_t\ell - k\ell^2/2}{EA}\Big]\cos\alpha
          + \frac{H L_s}{EA} + \frac{H}{w}\Big(\operatorname{asinh}\frac{V_B}{H}
          - \operatorname{asinh}\frac{V_t}{H}\Big) = X, \\
        \Big[L_B + \frac{T_t\ell - k\ell^2/2}{EA}\Big]\sin\alpha
          + \frac{\sqrt{H^2 + V_B^2} - \sqrt{H^2 + V_t^2}}{w}
          + \frac{V_B^2 - V_t^2}{2 EA w} = Z,

    :math:`L_s = L - L_B`, :math:`V_B = V_t + w L_s`: J.M. Jonkman's
    seabed line ("Dynamics modeling and loads analysis of an offshore
    floating wind turbine", NREL, 2007) on a slope, as in MoorPy's
    ``catenary(..., alpha=...)`` (which takes the friction force as
    :math:`\mu w` instead of :math:`\mu w\cos\alpha`; equal without friction).
    Exact: no approximation beyond the model's (straight seabed through A,
    friction fully mobilised).

    Parameters
    ----------
    span, dh : float
        Fairlead B relative to A (m); B above the seabed, ``dh > span·seabed_slope``.
    w, EA : float
        Weight per unstretched length (N/m) and axial stiffness (N), > 0.
    length : float
        Unstretched length (m).
    seabed_slope : float
        ``tan α`` (rise of the seabed per unit x towards B; negative: it falls).
    friction : float
        Coulomb coefficient μ >= 0.

    Returns
    -------
    SlopedSeabedCatenary
        ``H, V_B, H_A, V_A, T_A, T_B, length_on_seabed, x_touchdown, y_touchdown``.
        When the free line leaves A above the slope (no contact) the free
        `elastic_catenary`'s forces with ``length_on_seabed = 0``.

    Raises
    ------
    InputError
        Non-physical data, named: B on or below the seabed; a grounded line
        whose anchor end would need a zero-tension stretch that friction
        cannot hold on the slope (``μ < tan α``); slack in a heap.
    ConvergenceError
        The closure solve did not reach 1e-12 of the chord (with its history).
    """
    from scipy.optimize import root

    span, dh = positive("span", span), real("dh", dh)
    w, EA, L = positive("w", w), positive("EA", EA), positive("length", length)
    m = real("seabed_slope", seabed_slope)
    mu = nonnegative("friction", friction)
    for name, value in (("span", span), ("dh", dh), ("w", w), ("EA", EA), ("length", L), ("seabed_slope", m)):
        if not isinstance(value, float):
            raise InputError(name, "sloped_seabed_catenary solves one scene: give scalars")
    if not isinstance(mu, float):
        raise InputError("friction", "sloped_seabed_catenary solves one scene: give a scalar")
    require("dh", dh > m * span, "must put B above the seabed (dh > span * seabed_slope)", dh)
    free = free_elastic_catenary(span, dh, w, EA, length=L)
    if -free.V_A / free.H >= m:  # the free line leaves A at or above the slope: no contact
        result = SlopedSeabedCatenary(span, dh, w, EA, L, m, mu, free.H, 0.0, [0.0])
        result.V_B, result.T_B, result.x_touchdown, result.y_touchdown = free.V_B, free.T_B, 0.0, 0.0
        result.H_A, result.V_A, result.T_A = free.H, free.V_A, free.T_A
        return result
    chord = float(np.hypot(span, dh))
    # start: the flat line of the same data in the frame of the slope
    cos = 1.0 / np.hypot(1.0, m)
    sin = m * cos
    along, across = span * cos + dh * sin, dh * cos - span * sin
    try:
        flat = elastic_catenary(along, across, w * cos, EA, length=L, seabed=0.0)
        H0, L_B0 = flat.H * cos, flat.length_on_seabed
    except (InputError, ConvergenceError):
        H0, L_B0 = free.H, 0.5 * L
    if not H0 > 1e-6 * w * L:  # the flat line lies in a heap: the slope may still pull it taut
        H0, L_B0 = w * L, 0.5 * L
    scale = np.array([H0, L])
    history = []

    def f(u):
        H, L_B = u * scale
        if not (H > 0 and 0 <= L_B < L):
            return np.array([1e3 * chord, 1e3 * chord])
        r = np.array(_sloped_closure(span, dh, w, EA, L, m, mu, H, L_B))
        history.append(float(np.max(np.abs(r)) / chord))
        return r / chord

    def solved(start):
        sol = root(f, start / scale, method="hybr", options={"xtol": 1e-15})
        H, L_B = sol.x * scale
        if H > 0 and 0 <= L_B < L and np.max(np.abs(f(sol.x))) <= 1e-12:
            return H, L_B
        return None

    # the closure has one root (H > 0, 0 <= L_B < L); hybr from the flat line's start finds it
    # mostly, and from a few others where the slope bends the line away from that start
    starts = [(H0, min(max(L_B0, 0.0), 0.999 * L))]
    starts += [(H0 * a, b * L) for a in (1.0, 0.1, 10.0, 0.01) for b in (0.05, 0.5, 0.9, 0.99)]
    for start in starts:
        found = solved(np.array(start))
        if found is not None:
            break
    else:
        height = dh - m * span  # B above the slope, vertically
        if L >= span / cos + float(hanging_length(height, w, EA)):
            raise InputError(
                "length",
                "leaves slack line lying in a heap on the sloped seabed (H -> 0): give a shorter "
                "line or a longer span",
            )
        raise ConvergenceError("sloped_seabed_catenary: the closure equations did not converge", history)
    H, L_B = found
    k = w * (sin + mu * cos)
    if k > 0 and H / cos - k * L_B < 0 and mu < m:
        raise InputError(
            "friction",
            "the grounded line would need a slack stretch near the anchor that friction cannot hold "
            "on this slope (friction < seabed_slope)",
        )
    return SlopedSeabedCatenary(span, dh, w, EA, L, m, mu, float(H), float(L_B), history)
