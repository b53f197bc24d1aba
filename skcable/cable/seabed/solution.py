"""`SeabedCatenary`: the solution of one line on a flat seabed in each of its regimes (free,
grounded, heap: `skcable.cable.seabed`), mapped along the line (arc length and abscissa),
checked (residuals), and its fairlead stiffness, the inverse of the closure's Jacobian
(implicit function theorem).
"""

from __future__ import annotations

from functools import cached_property, partial
from itertools import zip_longest

import numpy as np

from skcable._checks import whole
from skcable._xp import namespace
from skcable.cable._elastic import ElasticCatenary, elastic_stiffness, inverse_2x2
from skcable.cable._roots import find_root
from skcable.cable.arc_samples import arc_samples
from skcable.cable.closure import grounded, grounded_closure, positions, stretched_length, tensioned
from skcable.cable.seabed import heap as heap_state
from skcable.cable.seabed.heap import as_float as _out
from skcable.cable.solution import CableSolution
from skcable.errors import InputError

__all__ = ["SeabedCatenary"]


def _left_run(s, x, H, V1, w, EA):
    """Abscissa of the point ``s`` on the part hanging from an anchor above the seabed, less ``x``."""
    return positions(H, -V1, w, EA, s, namespace(s, H))[0] - x


def _catenary_y_terms(hang, s):
    """The stretch and inextensible terms (m) of the height of the elastic catenary ``hang``
    at ``s``: ``s (w s/2 - V_A)/EA`` and ``(T(s) - T_A)/w``, written without cancellation:
    ``(T(s)² - T_A²)/(w (T(s) + T_A)) = s (w s - 2 V_A)/(T(s) + T_A)``, the difference of the
    vertical forces ``w s`` taken as it is, not as ``(w s - V_A) - (-V_A)`` (which keeps only the
    digits of ``w s`` that ``V_A`` leaves, none on a taut line with ``|V_A| >> w L``)."""
    ws = hang.w * s
    xp = namespace(s, ws)
    rise = s * (ws - 2.0 * hang.V_A) / (xp.hypot(hang.H, ws - hang.V_A) + hang.T_A)
    return s * (0.5 * ws - hang.V_A) / hang.EA, rise


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
    longer than its L-shape and the slack lies in a heap on the seabed
    (`skcable.cable.seabed.heap`): ``H = H_A = 0``, ``x_touchdown = span``,
    ``V_B = T_B = w l_B``, ``V_A = w l_A`` (0 with the anchor on the seabed),
    ``x_landing = 0``, ``length_on_seabed = L - l_A - l_B >= span``; ``suspended``
    raises there (no catenary hangs).
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
        return tensioned(self.H, self.length_on_seabed, self._mu_w) + 0.0 * self.H

    # -- the part hanging from an anchor above the seabed (empty otherwise) -----------
    def _left(self, s):
        """``(x, y)`` of the point ``s`` on the part hanging from an anchor above the seabed."""
        return positions(self._Hr, -self._V1, self.w, self.EA, s, namespace(s, self._Hr, self._V1))

    @cached_property
    def x_landing(self):
        """Abscissa where the line from an anchor above the seabed lands on it (0 otherwise;
        0 in a heap state: the part from A hangs vertically)."""
        return self._pick(lambda: 0.0 * self.span, lambda: _out(self._left(self.length_to_seabed)[0]))

    @cached_property
    def x_touchdown(self):
        """Abscissa where the line leaves the seabed towards B (the grounded line stretched;
        ``span`` in a heap state)."""
        return self._pick(lambda: self.span + 0.0 * self.H, self._taut_x_touchdown)

    def _taut_x_touchdown(self):
        stretch = grounded(self.H, self.length_on_seabed, self._mu_w, self.EA, self._xp)[0]
        return _out(self.x_landing + self.length_on_seabed + stretch)

    @property
    def H_B(self):
        """Horizontal tension at B (N): ``H``, the suspended part's (the result protocol,
        `skcable.results`)."""
        return self.H

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
        return self._pick(partial(getattr, self, "V_B"), partial(getattr, self._hanging, "T_B"))

    @cached_property
    def stretched_length(self):
        """Stretched length of the whole line (anchor part, grounded, suspended)."""
        # heap: the vertical parts span the heights exactly, the slack does not stretch
        heap = self.length_on_seabed + self.dh - 2.0 * self._y_t
        return self._pick(lambda: heap + 0.0, self._taut_stretched_length)

    def _taut_stretched_length(self):
        left = 0.0 * self.H
        if np.any(self._V1 > 0):  # the part hanging from an anchor above the seabed
            with np.errstate(invalid="ignore", divide="ignore"):
                hang = stretched_length(self._Hr, -self._V1, self.w, self.EA, self.length_to_seabed, self._xp)
            left = self._xp.where(self._V1 > 0, hang, left)
        return _out(left + self.x_touchdown - self.x_landing + self._hanging.stretched_length)

    def _at_b(self):
        """``span`` broadcast: where a heap state puts its vertex and lowest point."""
        return self.span + 0.0 * self.H

    def _on_seabed(self):
        """The seabed's height broadcast: the height of a heap state's vertex and lowest point."""
        return self._y_t + 0.0 * self.H

    @property
    def x_vertex(self):
        return self._pick(self._at_b, lambda: self.x_touchdown + self._hanging.x_vertex)

    @property
    def y_vertex(self):
        return self._pick(self._on_seabed, lambda: self._y_t + self._hanging.y_vertex)

    @property
    def x_low(self):
        return self._pick(self._at_b, lambda: self.x_touchdown + self._hanging.x_low)

    @property
    def y_low(self):
        return self._pick(self._on_seabed, lambda: self._y_t + self._hanging.y_low)

    # -- along the line ---------------------------------------------------------------
    def _grounded_tension(self, s):
        """Tension of the grounded part at ``s`` in [0, L_B] from its start: ``H_A + C_B w (s - a)``."""
        a = self.length_on_seabed - self._ell
        return self.H_A + self._mu_w * np.maximum(s - a, 0.0)

    def _taut_T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A, in [0, length]."""
        s1, L_B = self.length_to_seabed, self.length_on_seabed
        tv = self.w * np.maximum(s - s1 - L_B, 0.0) - self._hanging.V_A
        hang = np.where((s <= s1) & (s1 > 0), np.hypot(self.H, self.w * s - self._V1), np.hypot(self.H, tv))
        ground = self._grounded_tension(np.clip(s - s1, 0.0, L_B))
        # nothing grounded (L_B = 0): the point s1 belongs to the hanging line, whose
        # tension there carries the anchor's vertical pull
        return _out(np.where((s >= s1) & (s <= s1 + L_B) & (L_B > 0), ground, hang))

    def _taut_x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A)."""
        s1, L_B, ell = self.length_to_seabed, self.length_on_seabed, self._ell
        on = np.clip(s - s1, 0.0, L_B)
        d = np.maximum(on - (L_B - ell), 0.0)
        ground = self.x_landing + on + (self.H_A * d + 0.5 * self._mu_w * d * d) / self.EA
        hang = self.x_touchdown + self._hanging.x_of_s(np.maximum(s - s1 - L_B, 0.0))
        left = self._left(np.minimum(s, s1))[0]
        return _out(np.where(s <= s1, left, np.where(s <= s1 + L_B, ground, hang)))

    def _taut_y_of_s(self, s):
        """Height above A of the material point ``s`` (the seabed's height on it)."""
        s1, L_B = self.length_to_seabed, self.length_on_seabed
        hang = self._y_t + self._hanging.y_of_s(np.maximum(s - s1 - L_B, 0.0))
        left = self._left(np.minimum(s, s1))[1]
        return _out(np.where(s <= s1, left, np.where(s <= s1 + L_B, self._y_t, hang)))

    def _left_s_of_x(self, x):
        """Material point on the anchor part at ``x < x_landing`` (NaN elsewhere)."""
        x1 = self.x_landing
        xb, x1b, Hb, Vb, wb, EAb, s1b = np.broadcast_arrays(
            x, x1, self.H, self._V1, self.w, self.EA, self.length_to_seabed
        )
        out = np.full(xb.shape, np.nan)
        inside = xb < x1b
        if inside.any():
            args: list = [v[inside] for v in (s1b, xb, Hb, Vb, wb, EAb)]
            if args[0].size == 1:  # Brent's method on floats
                args = [float(v[0]) for v in args]
            root, _ = find_root(_left_run, 0.0 * args[0], args[0], tuple(args[1:]), what="s_of_x")
            out[inside] = root
        return out

    def _taut_s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span]."""
        x_t = self.x_touchdown
        grounded, xs = x <= x_t, np.clip(x - x_t, 0.0, self._hanging.span)
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

    # -- checks and stiffness -----------------------------------------------------------
    def _taut__residuals(self):
        xp = self._xp
        chord = xp.hypot(self.span, self.dh)
        hang = self._hanging
        L_s = hang.length
        yield (self.x_touchdown + hang.x_of_s(L_s) - self.span) / chord
        stretch, shape = _catenary_y_terms(hang, L_s)
        scale = chord + xp.abs(stretch) + xp.abs(shape) + xp.abs(self._y_t)
        yield (self._y_t + stretch + shape - self.dh) / scale
        # the anchor part lands on the seabed
        left = self._left(self.length_to_seabed)[1]
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
        """`stiffness` where the line is taut."""
        touches = (self.length_on_seabed > 0) | (self._V1 > 0)
        free = elastic_stiffness(self._hanging)
        depth = -self._y_t
        jac = grounded_closure(
            self.span, self.dh, self.w, self.EA, self.length, self._mu_w, self.H, self.V_B, depth
        )[2:]
        ground = inverse_2x2(*jac)
        return np.where(np.asarray(touches)[..., None, None], ground, free)

    # -- the heap state (H = 0): vertical parts at A and B, slack spread on the seabed ----
    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A, in [0, length] (in a heap state
        `skcable.cable.seabed.heap.heap_T_of_s`)."""
        s = self._arc(s)
        heap = partial(heap_state.heap_T_of_s, s, self.length_to_seabed, self.length_on_seabed, self.w)
        return self._pick(heap, partial(self._taut_T_of_s, s))

    def x_of_s(self, s):
        """Abscissa of the material point ``s`` (unstretched arc length from A; in a heap state
        `skcable.cable.seabed.heap.heap_x_of_s`)."""
        s = self._arc(s)
        heap = partial(heap_state.heap_x_of_s, s, self.length_to_seabed, self.length_on_seabed, self.span)
        return self._pick(heap, partial(self._taut_x_of_s, s))

    def y_of_s(self, s):
        """Height above A of the material point ``s`` (the seabed's height on it; in a heap
        state `skcable.cable.seabed.heap.heap_y_of_s`)."""
        s = self._arc(s)
        parts = (self.length_to_seabed, self.length_on_seabed, self.w, self.EA, self._y_t)
        heap = partial(heap_state.heap_y_of_s, s, *parts)
        return self._pick(heap, partial(self._taut_y_of_s, s))

    def s_of_x(self, x):
        """Material point at abscissa ``x`` in [0, span] (in a heap state
        `skcable.cable.seabed.heap.heap_s_of_x`)."""
        x = self._abscissa(x)
        heap = partial(
            heap_state.heap_s_of_x, x, self.length_to_seabed, self.length_on_seabed, self.span, self.length
        )
        return self._pick(heap, partial(self._taut_s_of_x, x))

    def slope(self, x):
        """dy/dx at ``x`` (0 on the seabed; in a heap state `skcable.cable.seabed.heap.heap_slope`,
        which refuses the vertical parts)."""
        x = self._abscissa(x)
        heap = partial(heap_state.heap_slope, x, self.span, self.heap, self._V1)
        return self._pick(heap, partial(self._taut_slope, x))

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
        return arc_samples(x, self.y(x), self.T(x), angle, float(self.w))

    def _heap_residuals(self):
        """Residuals of a heap state (`skcable.cable.seabed.heap.heap_residuals`)."""
        forces = (self.V_A, self.V_B, self.T_A, self.T_B, self.H)
        lengths = (self.length_to_seabed, self._l_B, self.length_on_seabed, self.length)
        line = (self.span, self.dh, self.w, self.EA, self._y_t)
        return heap_state.heap_residuals(self._xp, *line, *lengths, forces)

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
        closure equations in ``(H, V_B)``, grounded or free, friction included. In a heap state
        `skcable.cable.seabed.heap.heap_stiffness`, one-sided at the boundary: the line
        becomes taut again (``H > 0``) only when the span exceeds the slack's length on the seabed.
        """
        if not self._any_heap:
            return self._taut_stiffness()
        heap = heap_state.heap_stiffness(self.w, self.EA, self._l_B)
        if np.ndim(self.heap) == 0:
            return heap
        with np.errstate(all="ignore"):
            taut = self._taut_stiffness()
        return np.where(np.asarray(self.heap)[..., None, None], heap, taut)

    def xy(self, s):
        """Positions ``(..., 2)`` (m) of the material points at unstretched arc length ``s`` from A."""
        return np.stack(np.broadcast_arrays(self.x_of_s(s), self.y_of_s(s)), axis=-1)

    def __repr__(self):
        if np.ndim(self.H) != 0:
            text = super().__repr__()
        else:
            shown = ("H", "H_A", "V_A", "V_B", "T_A", "T_B", "length", "length_on_seabed", "x_touchdown")
            numbers = ", ".join(f"{name}={float(getattr(self, name)):.9g}" for name in shown)
            text = f"SeabedCatenary(span={self.span:g}, dh={self.dh:g}, w={self.w:g}: {numbers})"
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
