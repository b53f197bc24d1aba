r"""Elastic catenary resting on a flat seabed, with Coulomb friction.

Anchor A at (0, 0) on the seabed, fairlead B at (span, dh) above it, weight
``w`` per unstretched length, axial stiffness ``EA``, unstretched length
``L``, friction coefficient ``C_B``. When the freely hanging line would leave
A downwards (upward reaction ``V_A > 0``), the part ``L_B = L - V_B/w`` rests
on the seabed and the rest hangs as an elastic catenary tangent to the
seabed at the touchdown point. The closure equations in the fairlead forces
``(H, V_B)`` are those of J.M. Jonkman, "Dynamics modeling and loads analysis
of an offshore floating wind turbine", NREL, 2007 (§4.2), also used by MoorPy
(M. Hall, "MoorPy: quasi-static mooring analysis in Python", NREL, 2021):

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

The fairlead stiffness :math:`\partial(H, V_B)/\partial(X, Z)` is the inverse
of the Jacobian of the closure equations (implicit function theorem).
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from skcable._checks import float_range, real, require
from skcable._xp import namespace
from skcable.cable._elastic import ElasticCatenary
from skcable.cable._roots import find_root
from skcable.cable._special import largest_abs
from skcable.cable._stiffness import elastic_stiffness, inverse_2x2
from skcable.cable.solution import ACCEPT, CableSolution, checked_closed_form
from skcable.errors import ConvergenceError, InputError

__all__ = ["SeabedCatenary", "grounded_closure", "seabed_catenary"]

_TOL = 1e-13


def _tensioned(H, L_B, mu_w):
    """Length of the grounded part that carries tension, ``min(L_B, H/(C_B w))``."""
    with np.errstate(divide="ignore"):
        reach = np.where(mu_w > 0, H / np.where(mu_w > 0, mu_w, 1.0), np.inf)
    return np.minimum(L_B, reach)


def grounded_closure(span, dh, w, EA, L, mu_w, H, V):
    """Residuals ``X(H, V) - span``, ``Z(H, V) - dh`` of the grounded line and
    their Jacobian in ``(H, V)`` (``V`` the vertical force at B, ``mu_w``
    the friction force per unit grounded length)."""
    L_B = L - V / w
    T = np.hypot(H, V)
    ell = _tensioned(H, L_B, mu_w)
    H_A = np.maximum(H - mu_w * L_B, 0.0)
    asinh = np.arcsinh(V / H)
    f_x = L_B + H / w * asinh + H * V / (w * EA) + (H * ell - 0.5 * mu_w * ell * ell) / EA - span
    f_z = V * V / (T + H) / w + V * V / (2.0 * EA * w) - dh  # (T - H)/w without cancellation
    j_xh = (asinh - V / T) / w + V / (w * EA) + ell / EA
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


def _solve_grounded(span, dh, w, EA, L, mu_w, H0):
    """Newton with backtracking on the grounded closure, arrays of contact elements."""
    H, V = _inextensible_guess(span, dh, w, EA, L, H0)
    chord = np.hypot(span, dh)
    f_x, f_z, *jac = grounded_closure(span, dh, w, EA, L, mu_w, H, V)
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
            valid = (H_new > 0) & (V_new > 0) & (V_new <= w * L)
            H_try = np.where(valid, H_new, H)
            V_try = np.where(valid, V_new, V)
            f_x, f_z, *jac = grounded_closure(span, dh, w, EA, L, mu_w, H_try, V_try)
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
    ``x_touchdown`` the abscissa where the line leaves the seabed (0 when it
    hangs freely). ``suspended`` is the `ElasticCatenary` of the hanging part
    (from the touchdown point to B). ``T_of_s``, ``x_of_s``, ``y_of_s`` map
    the unstretched arc length from A; ``y(x)``, ``T(x)``, ``slope(x)`` the
    abscissa (the grounded part lies on the seabed).
    """

    def __init__(self, span, dh, w, EA, length, friction, seabed, H, V_t, L_B):
        self.span, self.dh, self.w, self.EA, self.length = span, dh, w, EA, length
        self.friction, self.seabed = friction, seabed
        self.H, self.length_on_seabed = H, L_B
        self.constraint = ("length", length)
        self._xp = namespace(span, dh, w, EA, length, friction, H, V_t, L_B)
        self._mu_w = friction * w
        self.suspended = ElasticCatenary(
            span - self.x_touchdown, dh, w, EA, length - L_B, H, V_t, ("length", length - L_B)
        )

    @cached_property
    def H_A(self):
        """Horizontal tension at the anchor (N)."""
        return self._xp.maximum(self.H - self._mu_w * self.length_on_seabed, 0.0)

    @cached_property
    def _ell(self):
        return _tensioned(self.H, self.length_on_seabed, self._mu_w) + 0.0 * self.H

    @cached_property
    def x_touchdown(self):
        """Abscissa of the touchdown point (the grounded line stretched)."""
        ell = _tensioned(self.H, self.length_on_seabed, self._mu_w)
        out = self.length_on_seabed + (self.H * ell - 0.5 * self._mu_w * ell * ell) / self.EA
        return out if self._xp is np else float(out)

    @property
    def V_A(self):
        return self.suspended.V_A

    @property
    def V_B(self):
        return self.suspended.V_B

    @cached_property
    def T_A(self):
        return self._xp.hypot(self.H_A, self.V_A)

    @property
    def T_B(self):
        return self.suspended.T_B

    @cached_property
    def stretched_length(self):
        """Stretched length of the whole line (grounded plus suspended)."""
        return self.x_touchdown + self.suspended.stretched_length - (self.length - self.length_on_seabed)

    @property
    def x_vertex(self):
        return self.x_touchdown + self.suspended.x_vertex

    @property
    def y_vertex(self):
        return self.suspended.y_vertex

    @property
    def x_low(self):
        return self.x_touchdown + self.suspended.x_low

    @property
    def y_low(self):
        return self.suspended.y_low

    # -- along the line ---------------------------------------------------------------
    def _grounded_tension(self, s):
        """Tension of the grounded part at ``s`` in [0, L_B]: ``H_A + C_B w (s - a)``."""
        a = self.length_on_seabed - self._ell
        return self.H_A + self._mu_w * np.maximum(s - a, 0.0)

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A, in [0, length]."""
        s = self._arc("s", s)
        L_B = self.length_on_seabed
        hang = self.suspended
        tv = self.w * np.maximum(s - L_B, 0.0) - hang.V_A
        return _out(np.where(s <= L_B, self._grounded_tension(np.minimum(s, L_B)), np.hypot(self.H, tv)))

    def x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A)."""
        s = self._arc("s", s)
        L_B, ell = self.length_on_seabed, self._ell
        d = np.maximum(np.minimum(s, L_B) - (L_B - ell), 0.0)
        ground = np.minimum(s, L_B) + (self.H_A * d + 0.5 * self._mu_w * d * d) / self.EA
        hang = self.suspended.x_of_s(np.maximum(s - L_B, 0.0))
        return _out(np.where(s <= L_B, ground, self.x_touchdown + hang))

    def y_of_s(self, s):
        """Height above A of the material point ``s`` (0 on the seabed)."""
        s = self._arc("s", s)
        L_B = self.length_on_seabed
        return _out(np.where(s <= L_B, 0.0, self.suspended.y_of_s(np.maximum(s - L_B, 0.0))))

    def _arc(self, name, s):
        s = real(name, s)
        require(name, (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def _split(self, x):
        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        x_t = self.x_touchdown
        grounded = x <= x_t
        return x, grounded, np.clip(x - x_t, 0.0, self.suspended.span)

    def s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span]."""
        x, grounded, xs = self._split(x)
        # on the seabed x - a = d (1 + H_A/EA) + C_B w d^2 / (2 EA), s = a + d
        L_B, ell = self.length_on_seabed, self._ell
        a = L_B - ell
        c = np.maximum(np.minimum(x, self.x_touchdown) - a, 0.0)
        b = 1.0 + self.H_A / self.EA
        d = 2.0 * c / (b + np.sqrt(b * b + 2.0 * self._mu_w * c / self.EA))
        ground = np.minimum(np.where(x <= a, x, a + d), L_B)
        return _out(np.where(grounded, ground, L_B + self.suspended.s_of_x(xs)))

    def y(self, x):
        """Height above A at abscissa ``x`` (0 on the seabed)."""
        x, grounded, xs = self._split(x)
        return _out(np.where(grounded, 0.0, self.suspended.y(xs)))

    def slope(self, x):
        x, grounded, xs = self._split(x)
        return _out(np.where(grounded, 0.0, self.suspended.slope(xs)))

    def T(self, x):
        """Tension at abscissa ``x`` (N)."""
        return self.T_of_s(self.s_of_x(x))

    def weight_per_length(self, x, slope):
        return self.w + 0.0 * slope

    # -- checks and stiffness -----------------------------------------------------------
    def _residuals(self):
        xp = self._xp
        chord = xp.hypot(self.span, self.dh)
        hang = self.suspended
        L_s = self.length - self.length_on_seabed
        yield (self.x_touchdown + hang.x_of_s(L_s) - self.span) / chord
        stretch, shape = hang._y_terms(L_s)
        yield (stretch + shape - self.dh) / (chord + xp.abs(stretch) + xp.abs(shape))
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

    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed, shape ``(*shape, 2, 2)``.

        Rows ``(H, V_B)``, columns ``(span, dh)``: the inverse of the Jacobian of the
        closure equations in ``(H, V_B)``, grounded or free, friction included.
        """
        grounded = self.length_on_seabed > 0
        free = elastic_stiffness(self.suspended)
        jac = grounded_closure(
            self.span, self.dh, self.w, self.EA, self.length, self._mu_w, self.H, self.V_B
        )[2:]
        ground = inverse_2x2(*jac)
        return np.where(np.asarray(grounded)[..., None, None], ground, free)


def _out(value):
    """A 0-d result as a Python float (scalar in, scalar out)."""
    return float(value) if np.ndim(value) == 0 else value


def _lifted(span, dh, w, EA, L):
    """Whether the line leaves the anchor upwards (no contact), and the lift-off ``H``.

    At lift-off ``V_A = 0``, ``V_B = wL``: the height equation gives
    ``T + H = P = wL²/D`` with ``D = dh - wL²/(2EA)``, so ``H = (P - (wL)²/P)/2``;
    the line is lifted where ``span`` reaches the lift-off ``X(H, wL)``. With
    ``D <= 0`` the line's own stretch exceeds ``dh`` and it always touches.
    """
    D = dh - w * L * L / (2.0 * EA)
    touches = np.asarray(D <= 0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        P = w * L * L / np.where(touches, 1.0, D)
        H = 0.5 * (P - (w * L) * (w * L / P))
        ok = ~touches & (H > 0)
        H_safe = np.where(ok, H, 1.0)
        X = H_safe * L / EA + H_safe / w * np.arcsinh(w * L / H_safe)
    return ~touches & (~ok | (span >= X)), np.where(ok, H, 0.0)


def seabed_catenary(span, dh, w, EA, L0, seabed, friction):
    """The checked arguments of `elastic_catenary` with a ``seabed``; see there."""
    from skcable.cable._elastic import elastic_catenary

    require("seabed", np.asarray(seabed) <= 0, "must be at or below the anchor (A at height 0)", seabed)
    require("dh", np.asarray(dh) > seabed, "must put B above the seabed", dh)
    shape = np.broadcast_shapes(*(np.shape(v) for v in (span, dh, w, EA, L0, seabed, friction)))
    on_bed = np.broadcast_to(np.asarray(seabed) == 0, shape)
    lifted, H_lift = _lifted(span, dh, w, EA, L0)
    contact = np.asarray(on_bed & ~np.broadcast_to(lifted, shape))
    H, V_t, L_B = np.zeros(shape), np.zeros(shape), np.zeros(shape)
    history = []
    if not contact.all():
        hanging = np.asarray(~contact)
        args = [np.broadcast_to(v, shape)[hanging] for v in (span, dh, w, EA, L0)]
        if shape == ():
            args = [float(v[0]) for v in args]
        free = elastic_catenary(*args[:4], length=args[4])
        below = np.asarray(free.y_low) < np.broadcast_to(seabed, shape)[hanging]
        if below.any():
            raise InputError(
                "seabed",
                "lies above the low point of the freely hanging line with the anchor above it: "
                "a touchdown between A and B is not supported (put the anchor on the seabed, seabed=0)",
            )
        H[hanging], V_t[hanging] = free.H, free.V_A
    if contact.any():
        # H -> 0: B holds the hanging V_0 (Z = V/w + V^2/(2 EA w)) and the rest lies at
        # X_0 = L - V_0/w; a shorter span leaves line in a heap on the seabed (H = 0)
        v_0 = 2.0 * w * dh / (1.0 + np.sqrt(1.0 + 2.0 * w * dh / EA))
        heap = contact & np.broadcast_to(span <= L0 - v_0 / w, shape)
        if heap.any():
            raise InputError(
                "length",
                "leaves slack line lying in a heap on the seabed (span <= length - hanging length, "
                "H = 0): give a shorter line or a longer span",
            )
        strain_guess = np.where(H_lift > 0, np.minimum(H_lift, w * L0), w * L0)
        args = [np.broadcast_to(v, shape)[contact] for v in (span, dh, w, EA, L0, friction * w, strain_guess)]
        Hc, Vc, history = _solve_grounded(*args)
        H[contact], V_t[contact] = Hc, 0.0
        L_B[contact] = np.maximum(args[4] - Vc / args[2], 0.0)
    if shape == ():
        H, V_t, L_B = float(H), float(V_t), float(L_B)
    with float_range("length", "a result"):
        solution = SeabedCatenary(span, dh, w, EA, L0, friction, seabed, H, V_t, L_B)
        return checked_closed_form(solution, "length", history)


assert ACCEPT > _TOL
