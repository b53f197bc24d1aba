r"""`Line`: a mooring line of segments in series, with clump weights and buoys, in closed form.

A line runs from the anchor A = (0, 0) to the fairlead B = (span, dh) through segments
``0 .. n-1`` (from A), each an elastic catenary with its own unstretched length ``L_i``,
weight in water per unstretched length ``w_i > 0`` and axial stiffness ``EA_i``
(`skcable.mooring.segments.parts`). Joint ``j`` lies between segments ``j-1`` and
``j`` and may carry a point force ``P_j``. With no horizontal point load the horizontal
tension ``H`` of the suspended part is the same in every segment; the closure
``X(H, V) = span``, ``Z(H, V) = dh`` of `skcable.mooring.segments.state` (H.M.
Irvine, "Cable Structures", MIT Press, 1981; J.M. Jonkman, "Dynamics modeling and loads
analysis of an offshore floating wind turbine", NREL, 2007, for the grounded part) is
solved by Newton's method with its analytic Jacobian, from a previous solution (a warm
start), else from the uniform line of the same length, weight and compliance, else from
nested bracketing (``Z`` increases with ``V`` at fixed ``H``; then ``X`` in ``H``); every path
ends polishing the same root to round-off. A line longer than its L-shape lies in a heap
(`skcable.mooring.segments.heap`). The solution is a `LineSolution`.
"""

from __future__ import annotations

import math

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, positive, real, require, scalar
from skcable._newton2 import solve2
from skcable.bvp.current import current_of
from skcable.cable._roots import find_root
from skcable.cable.seabed import elastic_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.bathymetry import Bathymetry
from skcable.mooring.segments._answers import check_line
from skcable.mooring.segments.arrays import line_arrays
from skcable.mooring.segments.heap import heap_state
from skcable.mooring.segments.law import LawLineSolution, solve_law_line
from skcable.mooring.segments.parts import Buoy, ClumpWeight, Segment
from skcable.mooring.segments.solution import CLOSURE_TOLERANCE, LineSolution
from skcable.mooring.segments.state import closure_state

__all__ = ["Line"]


def _height_left(V, line, H, dh):
    """``Z(H, V) - dh`` of ``line`` (m); ``-dh`` where the whole line would lie on the seabed."""
    st = line.state(H, V)
    return -dh if st is None else st.Z - dh


def _bracket_end(sign, scale, args) -> float:
    """The end of the bracket of ``V`` on the side ``sign``: ``sign scale`` doubled until
    ``sign (Z - dh) >= 0`` (`_height_left`)."""
    V = sign * scale
    while sign * _height_left(V, *args) < 0:
        V *= 2.0
        if sign * V > 1e12 * scale:
            raise ConvergenceError("Line.solve: no bracket for the fairlead's vertical force")
    return V


def _closure(H, V, line, span, dh, sizes, state):
    """The closure ``(X - span, Z - dh)`` (m) of ``line`` at ``(H, V)``, its Jacobian and the
    ``sizes`` (m) of its terms, then the `ClosureState` (the closure of
    `skcable._newton2.solve2`); ``state`` is reused at its own ``(H, V)``. Outside the closed
    form's domain (``H <= 0``, the whole line on the seabed) it raises ``ValueError``: the line
    search halves the step."""
    st = state if (H == state.H and V == state.V) else line._trial_state(H, V)
    if st is None:
        raise ValueError("no state of the closed form here")
    j11, j12, j21, j22 = st.jac
    return st.X - span, st.Z - dh, j11, j12, j21, j22, sizes[0], sizes[1], st


def _run_left(H, line, span, dh):
    """``X(H, V(H)) - span`` of ``line`` (m), ``V(H)`` the vertical force that meets ``dh``."""
    V = line.vertical_force(H, dh)
    return line.state(H, V).X - span


class Line:
    """A mooring line of segments in series, with clump weights and buoys at the joints.

    Parameters
    ----------
    segments : sequence of Segment
        From the anchor (segment 0) to the fairlead.
    attachments : sequence of ClumpWeight or Buoy, optional
        Point forces at the joints; joint ``j`` joins segments ``j-1`` and ``j``,
        joint 0 is the anchor A, joint ``n = len(segments)`` the fairlead B. A force
        at an end joint is carried by the support there (it enters ``V_A`` or ``V_B``).
        Several attachments at one joint add up.
    seabed : float or Bathymetry, optional
        Height of a flat seabed relative to A (m), ``<= 0``, as in `elastic_catenary`.
        With ``seabed=0`` the line may rest on it from A up to a touchdown; with
        ``seabed < 0`` the line must stay clear of it (a touchdown between A and B
        raises). Or a shaped seabed in global coordinates (`skcable.mooring.bathymetry`:
        `Plane`, `DepthFunction`, `Grid`; m, z up), which only `skcable.mooring.line_3d` solves
        (by the 3-D line BVP; a flat `Plane` through the anchor by the closed form).
    friction : float, optional
        Coulomb coefficient ``C_B >= 0`` of the grounded part (only with ``seabed``).
    current : (Ux, Uy), callable or Current, optional
        The current (m/s; `skcable.bvp.current.current_of`): a constant horizontal vector,
        a callable ``z -> (Ux, Uy)`` of the height ``z`` (m, the surface at 0) or a `Current`.
        It drags the segments with a ``diameter`` and drag coefficients; a line in a current
        is solved in space by `skcable.mooring.line_3d` (the 3-D line BVP).
    rho_water : float, optional
        Density of the water (kg/m³), > 0, for the current's drag.
    """

    def __init__(
        self, segments, attachments=(), *, seabed=None, friction=0.0, current=None, rho_water=1025.0
    ):
        for name, value in (("segments", segments), ("attachments", attachments)):
            if isinstance(value, (Segment, ClumpWeight, Buoy)) or not hasattr(value, "__iter__"):
                raise InputError(name, f"must be a sequence (a list) of them, got {value!r}")
        segments, attachments = list(segments), list(attachments)
        if not segments or not all(isinstance(s, Segment) for s in segments):
            raise InputError("segments", "must be a non-empty sequence of mooring.Segment")
        n = len(segments)
        if not all(isinstance(a, (ClumpWeight, Buoy)) for a in attachments):
            raise InputError("attachments", "must be mooring.ClumpWeight or mooring.Buoy objects")
        P = np.zeros(n + 1)
        for att in attachments:
            if att.joint > n:
                raise InputError("joint", f"{att!r}: joint must lie in [0, {n}] for {n} segments")
            P[att.joint] += att.force
        self.bathymetry = None
        """The shaped seabed (a `skcable.mooring.bathymetry.Bathymetry`, global coordinates), or None."""
        if seabed is None:
            friction = 0.0 if friction is None else friction
            if real("friction", friction) != 0.0:
                raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
        elif isinstance(seabed, Bathymetry):
            self.bathymetry, seabed = seabed, None
        else:
            seabed = scalar("seabed", seabed)
            require("seabed", seabed <= 0, "must be at or below the anchor (A at height 0)", seabed)
        self.current = current_of(current)
        """The current (a `skcable.bvp.current.Current`), or None."""
        if self.current is not None and not any(seg.drags for seg in segments):
            raise InputError("current", "drags no segment: give the segments a diameter and cd_normal")
        self.rho_water = scalar("rho_water", positive("rho_water", rho_water))
        self.friction = scalar("friction", nonnegative("friction", friction))
        _plausible.friction(self.friction)
        self.seabed = seabed
        self.segments = tuple(segments)
        self.attachments = tuple(attachments)
        self.arrays = line_arrays(segments, P)
        """The per-segment and per-joint numbers, read-only (`LineArrays`)."""
        self.joint_forces = P
        """Downward point force at each joint (N), ``n + 1`` values (buoys negative)."""
        self.contact = seabed is not None and seabed == 0.0
        """Whether the line may rest on a seabed through its anchor (``seabed=0``)."""
        self._buoyed = bool((P[1:n] < 0).any() or (self.arrays.w < 0).any())  # buoys, buoyant segments

    def variant(self, *, reverse: bool = False, contact: bool = False) -> Line:
        """This line as seen from one end, with or without a seabed through that end (cached).

        ``reverse``: the line given from its other end (segments in reverse order, an
        attachment at joint ``j`` moved to joint ``n - j``). ``contact``: a flat seabed through
        the anchor (``seabed=0``) and this line's ``friction``; else no seabed (and no
        friction). The solutions of a variant are those of the same physical line with its
        ends named the other way round (`skcable.mooring.choice` picks the variant
        that suits a line's position over the seabed). A line in a current, on a `Bathymetry` or
        with a nonlinear axial law has none (`InputError` naming ``current``, ``seabed`` or
        ``EA``): it is solved in space (`skcable.mooring.line_3d`)."""
        if self.off_plane is not None:  # no variant of the plane closed forms
            name, reason = self.off_plane
            raise InputError(
                name,
                f"{reason}: this line is solved by mooring.line_3d (and in a MooringSystem with one "
                "end fixed), not in the vertical plane of its ends",
            )
        key = (bool(reverse), bool(contact))
        cache = self.__dict__.setdefault("_variants", {})
        if key not in cache:
            segments, attachments = list(self.segments), list(self.attachments)
            if reverse:
                n = len(segments)
                segments = segments[::-1]
                attachments = [type(a)(n - a.joint, abs(a.force)) for a in attachments]
            seabed, friction = (0.0, self.friction) if contact else (None, 0.0)
            cache[key] = Line(segments, attachments, seabed=seabed, friction=friction)
        return cache[key]

    def variant_with_seabed(self, seabed) -> Line:
        """This line in still water over the flat ``seabed`` (m relative to A, or None), this
        line's ``friction`` (none without a seabed): itself where that is what it is (cached)."""
        if self.current is None and self.bathymetry is None and seabed == self.seabed:
            return self
        cache = self.__dict__.setdefault("_variants", {})
        key = ("seabed", seabed)
        if key not in cache:
            friction = 0.0 if seabed is None else self.friction
            cache[key] = Line(list(self.segments), list(self.attachments), seabed=seabed, friction=friction)
        return cache[key]

    @property
    def length(self):
        """Total unstretched length (m)."""
        return self.arrays.total_length

    @property
    def weight(self):
        """Total weight in water of the segments and the attachments (N)."""
        return self.arrays.total_weight

    def __repr__(self):
        seabed = self.seabed if self.bathymetry is None else self.bathymetry
        extra = "" if self.current is None else f", current={self.current!r}, rho_water={self.rho_water!r}"
        return (
            f"Line(segments={list(self.segments)!r}, attachments={list(self.attachments)!r}, "
            f"seabed={seabed!r}, friction={self.friction!r}{extra})"
        )

    def _trial_state(self, H, V):
        """`_state` at a Newton iterate, None where it is no state: ``H <= 0``, the whole line
        on the seabed, or forces so small that a product of them underflows to a division
        by zero (the Python floats of a one-segment line raise there)."""
        if not H > 0:
            return None
        try:
            return closure_state(self.arrays, self.friction, self.contact, H, V)
        except ZeroDivisionError:
            return None

    def state(self, H, V):
        """The closed form at fairlead forces ``(H, V)`` (N; ``V`` just below the fairlead's
        joint): a `ClosureState` with the closure ``(X, Z)`` and its Jacobian, or None where
        the whole line would lie on the seabed (`closure_state`)."""
        return closure_state(self.arrays, self.friction, self.contact, H, V)

    def vertical_force(self, H, dh):
        """``V`` with ``Z(H, V) = dh`` (``Z`` increases with ``V``), by bracketing."""
        arrays = self.arrays
        scale = float(arrays.abs_segment_weight + arrays.abs_joint_forces)
        args = (self, H, dh)
        lo, hi = (_bracket_end(sign, scale, args) for sign in (-1.0, 1.0))  # V < 0: a buoyant line held down
        if _height_left(lo, *args) >= 0:
            return lo
        return find_root(_height_left, lo, hi, args, what="Line.solve, V at fixed H", xtol=1e-12 * hi)[0]

    def _guess(self, span, dh):
        """``(H, V)`` of the uniform line of the same length, weight and compliance, or None."""
        L = self.length
        arrays = self.arrays
        W = float(arrays.w @ arrays.L + self.joint_forces[1:-1].sum())
        w = W / L if W != 0 else float(arrays.w @ arrays.L) / L
        EA = L / float(np.sum(arrays.L / arrays.EA))
        seabed = 0.0 if self.contact else None
        sign = 1.0
        if not w > 0:  # a buoyant line: the mirror image (y -> -y) of a heavy one, V_B -> -V_B
            if self.contact or w == 0:
                return None
            w, dh, sign = -w, -dh, -1.0
        try:
            with _plausible.quiet():  # a guess, not an answer
                ref = elastic_catenary(span, dh, w, EA, length=L, seabed=seabed, friction=0.0)
        except (InputError, ConvergenceError):
            return None
        return float(ref.H), sign * float(ref.V_B)

    def _newton(self, span, dh, H, V, chord, iterations, state=None):
        """Newton's method with the analytic Jacobian and backtracking on ``max|residual|``
        (`skcable._newton2.solve2` on Python floats), to the closure's round-off floor.

        Returns ``(state, norm, history)``: the closed form at the last iterate, its largest
        residual over the chord and the history (the caller checks the residual reached).
        ``state``: the closed form already evaluated at ``(H, V)`` (a previous solution's)."""
        H, V = float(H), float(V)
        st = self._trial_state(H, V) if state is None else state
        if st is None:
            return None, np.inf, []
        # the sizes of the closure's terms: its pieces' runs and rises are at most their
        # stretched lengths, ~ the line's length
        sizes = (self.arrays.total_length + span, self.arrays.total_length + abs(dh))
        result = solve2(_closure, H, V, (self, span, dh, sizes, st), max_iter=iterations, strict=False)
        st = result.last[8]
        if st is state:  # no step from a previous solution's state: a state of its own
            st = self.state(result.x, result.y)
        f1, f2 = result.last[:2]
        return st, max(abs(f1), abs(f2)) / chord, result.history

    def _bracketed(self, span, dh):
        """``(H, V)`` by nested bracketing: ``V(H)`` from the height, then ``H`` from the run."""
        W = float(self.arrays.abs_segment_weight)
        args = (self, span, dh)
        H_lo = 1e-10 * W
        if _run_left(H_lo, *args) >= 0:
            if self.contact:  # buoys: a heap state raises in `heap_state`, else none of this form
                heap_state(self.arrays, span, dh)
                raise InputError(
                    "attachments",
                    "leave slack line on the seabed with H -> 0 that is no heap state of this closed "
                    "form (buoys lift it): solve it with mooring.solve_line_bvp",
                )
            raise ConvergenceError("Line.solve: the run exceeds the span at H -> 0")
        H_hi = W
        while _run_left(H_hi, *args) < 0:
            H_hi *= 4.0
            if H_hi > 1e16 * W:
                raise InputError("span", "is out of reach of the line (tension beyond the float range)")
        H, hist = find_root(_run_left, H_lo, H_hi, args, what="Line.solve, H", xtol=1e-10 * H_hi)
        return H, self.vertical_force(H, dh), hist

    @_plausible.answer(check_line)
    def solve(self, span, dh, start=None):
        """Static equilibrium with A at (0, 0) and B at (span, dh).

        Parameters
        ----------
        span : float
            Horizontal distance A→B (m), > 0.
        dh : float
            Height of B above A (m); above the seabed when one is given.
        start : LineSolution or (float, float), optional
            A warm start: a previous solution of this line (typically at a nearby
            ``(span, dh)``, as in the Newton iterations of a moored body), or the pair
            ``(H, V_B)`` (N, ``H > 0``): Newton's method starts from its fairlead forces, the
            cold path (module docstring) where it does not converge from there. No fallback of
            results: the closure has one root, which every path polishes and checks the same
            way, so that warm and cold solutions agree to round-off.

        Returns
        -------
        LineSolution
            With ``seabed=0`` and a line longer than its L-shape, the heap state
            (``heap`` True, ``H = 0``: the part from B hangs vertically, the slack lies
            on the seabed; see `LineSolution`).

        Raises
        ------
        InputError
            ``span``/``dh`` not finite or out of range; ``attachments`` when a buoy
            between the ends meets a line whose slack lies in a heap on the seabed, when
            a buoy would rest on the grounded part or the suspended line would dip
            to the seabed again (a second touchdown: solve it with `mooring.solve_line_bvp`);
            ``seabed`` when the line would touch a seabed below the anchor; ``start``
            when it is neither a solution of this line nor a pair ``(H, V_B)`` of
            finite numbers with ``H > 0``. An elastic line always reaches B by
            stretching, so a short line is not an error.
        ConvergenceError
            Bracketing or Newton failed; carries the residual history.
        """
        if any(seg.w == 0.0 for seg in self.segments):
            raise InputError(
                "w", "a segment of w = 0 is weightless: it has no catenary (line_between takes it)"
            )
        span = scalar("span", positive("span", span))
        dh = scalar("dh", real("dh", dh))
        return self.solve_checked(span, dh, start)

    def solve_checked(self, span: float, dh: float, start=None):
        """`solve` for a caller that has checked ``span`` and ``dh`` (finite floats, ``span > 0``):
        a system's line solved at every Newton iterate of its equilibrium."""
        if self.in_space is not None:
            raise InputError(
                self.in_space[0], f"{self.in_space[1]}: solve the line in space with mooring.line_3d"
            )
        if self.seabed is not None:
            require("dh", dh > self.seabed, "must put B above the seabed", dh)
        if self.nonlinear:
            return self._solve_law(span, dh, start)
        chord = math.hypot(span, dh)
        st, norm, history = None, np.inf, []
        if start is not None:  # Newton from the previous solution (its closed form known)
            H0, V0, state = self._start(start)
            if H0 > 0:  # a heap state (H = 0) is no start for Newton
                st, norm, history = self._newton(span, dh, H0, V0, chord, 40, state)
        if not norm < CLOSURE_TOLERANCE and not self._buoyed:  # the slack in a heap on the seabed (H = 0)?
            heap = heap_state(self.arrays, span, dh) if self.contact else None
            if heap is not None:
                st, norm = heap, 0.0
        if not norm < CLOSURE_TOLERANCE:  # Newton from the equivalent uniform line
            guess = self._guess(span, dh)
            if guess is not None:
                st, norm, more = self._newton(span, dh, guess[0], guess[1], chord, 40)
                history = [*history, *more]
        if not norm < CLOSURE_TOLERANCE:  # nested bracketing, then Newton polish
            H, V, hist = self._bracketed(span, dh)
            st, norm, more = self._newton(span, dh, H, V, chord, 20)
            history = [*history, *hist, *more]
        if not norm < CLOSURE_TOLERANCE:
            raise ConvergenceError("Line.solve: closure not met", history)
        solution = LineSolution(self, span, dh, st)
        solution.validate()
        return solution

    @property
    def nonlinear(self) -> bool:
        """Whether a segment has a nonlinear axial law (`skcable.mooring.segments.law`)."""
        return any(seg.nonlinear for seg in self.segments)

    @property
    def in_space(self) -> tuple[str, str] | None:
        """``(argument, reason)`` where only the 3-D line BVP solves this line (a current, a shaped
        seabed), else None: `skcable.mooring.line_3d` reports the reason with the model it ran."""
        if self.current is not None:
            return "current", "a current drags the line out of the closed forms' vertical plane"
        if self.bathymetry is not None and self.bathymetry.flat is None:
            return "seabed", "a shaped seabed (not flat) has no closed form of a line on it"
        if self.bathymetry is not None:
            return "seabed", "a flat Bathymetry is given in global coordinates, which only line_3d places"
        return None

    @property
    def off_plane(self) -> tuple[str, str] | None:
        """``(argument, reason)`` where the plane closed forms of the line's vertical plane do not
        take this line (`in_space`, or a nonlinear axial law), else None."""
        if self.in_space is not None:
            return self.in_space
        return ("EA", "a nonlinear axial law") if self.nonlinear else None

    def _solve_law(self, span, dh, start):
        """The closed form with the laws' exact elongation integrals (`solve_law_line`)."""
        pair: tuple | None
        if isinstance(start, LawLineSolution):
            if start.line is not self:
                raise InputError("start", "is a solution of another line: give one of this line or (H, V_B)")
            pair = (start.H, start.V)
        elif start is not None:
            H0, V0, _ = self._start(start)
            pair = (H0, V0)
        else:
            guess = self._guess(span, dh)
            pair = None if guess is None else (guess[0], guess[1] - self.arrays.P_end[1])
        return solve_law_line(self, span, dh, pair)

    def _start(self, start):
        """``(H, V, state)`` of a warm start: fairlead forces (``V`` below the fairlead's
        joint) and the closed form evaluated there (None for a pair ``(H, V_B)``)."""
        if isinstance(start, LineSolution):
            if start.line is not self:
                raise InputError("start", "is a solution of another line: give one of this line or (H, V_B)")
            state = start.state
            return state.H, state.V, state
        try:
            H, V_B = start
        except (TypeError, ValueError):
            raise InputError(
                "start", f"must be a LineSolution of this line or a pair (H, V_B), got {start!r}"
            ) from None
        H = scalar("start", positive("start", H))
        V_B = scalar("start", real("start", V_B))
        return H, V_B - self.arrays.P_end[1], None
