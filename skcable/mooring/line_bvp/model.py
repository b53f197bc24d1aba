"""The public entry points of the line BVP: `solve_line_bvp`, and `LineBVP`, a line model."""

from __future__ import annotations

from functools import partial

from skcable import _plausible
from skcable._checks import nonnegative, positive, scalar, whole
from skcable.cable._extreme import outsized
from skcable.errors import InputError
from skcable.mooring.line_bvp.check import warn_unresolved
from skcable.mooring.line_bvp.driver import LineBVPSolver
from skcable.mooring.line_bvp.fallback import space_for_plane
from skcable.mooring.line_bvp.inputs import (
    magnitudes,
    newton_options_of,
    plane_segments,
    point_loads_of,
    scene,
    terms_of,
)
from skcable.mooring.line_bvp.resolution import elements_option, solve_resolved
from skcable.mooring.line_bvp.solution import LineBVPSolution

__all__ = ["LineBVP", "solve_line_bvp"]


def solve_line_bvp(
    span,
    dh,
    segments,
    *,
    seabed=None,
    seabed_slope=None,
    friction: float = 0.0,
    point_loads=(),
    n_elements: int | str = 64,
    fit_touchdown: int = 3,
    rtol: float | None = None,
    max_iter: int | None = None,
    terms=(),
    options=None,
    time_limit: float = 60.0,
    **newton_options,
) -> LineBVPSolution:
    """A mooring line from anchor A = (0, 0) to fairlead B = (span, dh), by finite elements,
    optionally resting on a seabed of any shape (see `skcable.mooring.line_bvp`).

    Parameters
    ----------
    span, dh : float
        Fairlead position relative to the anchor (m), ``span > 0``.
    segments : list of BVPSegment or (length, w, EA) tuples
        From A to B: unstretched length (m), weight per unstretched length
        (N/m, or a callable of the arc length s from A) and axial stiffness
        (N, None for inextensible). Joints are mesh nodes.
    seabed : float or callable, optional
        Seabed height ``b`` relative to A (m): a number (flat, or straight with
        ``seabed_slope``) or a callable ``b(x)`` (array in, array out). A must lie
        on or above it, B above it.
    seabed_slope : float or callable, optional
        With a number ``seabed``, the slope ``tan α`` of the straight seabed
        ``b(x) = seabed + x tan α``; with a callable, ``b'(x)`` (central
        differences of ``b``, step 1e-5 span, otherwise).
    friction : float
        Coulomb coefficient μ of the grounded line, fully mobilised towards
        the anchor (Jonkman's model); needs a seabed.
    point_loads : sequence of (s, P)
        Downward force ``P`` (N; negative for a buoy) at arc length ``s``
        from A (a mesh node is put there).
    n_elements : int or "auto"
        Elements over the whole line, shared among segments by length (at
        least one each); ``"auto"``: the elements the line needs, 64 then four times as many
        while the mesh does not resolve the line, up to 1024
        (`skcable.mooring.line_bvp.resolution`; the solution's ``n_elements`` says how many).
        A mesh that does not resolve the line warns (`skcable.errors.ResolutionWarning`).
    fit_touchdown : int
        Passes of touchdown fitting (and, when > 0, meshes graded by the
        line's curvature: `skcable.mooring.line_bvp.mesh`): after a solve that touches the seabed,
        a mesh node is put at the touchdown (and the landing, for an anchor
        above the seabed) the vertical balance gives
        (`LineBVPSolution.s_touchdown`, ``s_landing``: the nearest inner node moves there
        when it is closer than a quarter of an element, else a node is
        inserted) and the line is solved again from the previous solution,
        until the touchdown moves less than 1e-9 of the length. Nodal contact
        otherwise misplaces the touchdown by up to half an element, an error
        in H of order (that distance)² that jumps with the mesh; 0 turns it off.
        Three passes by default, as the line in space's (`solve_line_bvp_3d`).
    rtol : float
        Newton stops when every scaled residual (forces over the total load,
        the stretch over the length, the complementarity rows over the total
        load) is below ``rtol`` (default 1e-10; ``tol`` of `skcable.fe.NewtonOptions`). The
        total load counts the weight, the point loads and the cable terms' force on the
        straight chord.
    max_iter : int
        Newton iterations at most per solve (default 50); the continuation's solves are bounded
        by its stages (`skcable.mooring.line_bvp.driver`).
    time_limit : float
        Seconds at most for the whole continuation (default 60): past them a
        `ConvergenceError` whose ``history`` holds the last merit of every solve.
    terms : CableTerm or list of CableTerm
        Loads that see the line's whole state, with their tangents (`skcable.bvp.terms`:
        `Buoyancy` varying with depth, `CurrentDrag`, `WindDrag`, or an analyst's own
        `CableTerm`), besides the segments' self weight; a term reading ``s`` gets the
        unstretched arc length from A. Their force enters the residual and the exact tangent
        (and so `LineBVPSolution.stiffness`); what they name (`CableTerm.outputs`) appears in
        ``samples()["outputs"]``, `LineBVPSolution.to_frame` and the VTK files. A slack stretch
        near the anchor (friction holding more than the pull) takes vertical terms on a flat
        seabed only.
    options : NewtonOptions, optional
        The Newton options of every solve (`skcable.fe.NewtonOptions`); the line BVP's defaults
        are ``tol=1e-10, max_iter=50, line_search="residual", stagnation_window=8``.
    **newton_options
        Any field of `skcable.fe.NewtonOptions`, over ``options``: ``atol`` (N: converged also
        when every force residual is below it and the stretch rows meet ``rtol``),
        ``line_search`` (``"residual"``/True or ``"auto"``: backtracking on the merit, with a
        full-step retry where it stalls; ``"none"``/False: full steps; ``"energy"`` is
        refused: the line has no potential), ``callback(iteration, residual_norm,
        step_norm)`` (after every step of every solve of the continuation, numbered from 1 in
        each; the last solve's merits are the solution's ``history``), ``max_halvings``,
        ``stagnation_window``, and ``tol`` (``rtol``'s other name). An unknown name is an
        `InputError` naming it.

    Returns
    -------
    LineBVPSolution

    Raises
    ------
    InputError
        Bad data, named; an argument beyond any physical magnitude (beyond 10**±100) is the one
        named, whatever step inside trips on it; friction too weak to hold a slack stretch on a
        sloping seabed; a term that returns arrays of the wrong shape or non-finite
        values (``terms``); a callback that raised (``callback``, with the iteration).
        ``point_loads``: a slack stretch near the anchor that ends at a point load resting on the
        seabed with its friction only partly mobilised, a state this BVP does not model (its
        slack stretch ends where the tension, not a node's friction, vanishes); `skcable.mooring.Line`
        solves it in closed form.
    ConvergenceError
        Newton stalled (``history`` holds the merit per iteration); the end
        of a slack stretch not found; the discrete line in compression (its
        bends not resolved by the mesh, a `skcable.errors.ResolutionError`: the message says so,
        and more ``n_elements`` may solve it).
        Its ``last`` keeps what converged: the `LineBVPSolution` on the finest mesh reached (of
        the nested levels and grading passes, not checked), None where no solve converged; with
        ``n_elements="auto"``, where a refined solve fails, the coarser line (checked, not
        resolved).

    Notes
    -----
    The continuation (levels, gradings, friction, touchdown fitting, the slack stretch, the point
    loads by steps and the retries) is `skcable.mooring.line_bvp.driver.LineBVPSolver`'s. Where it
    fails, a line without cable terms is solved by the line in space's strategy within what is
    left of ``time_limit``, then in the plane from it on its mesh
    (`skcable.mooring.line_bvp.fallback.space_for_plane`); a failure of both says so.
    """
    model = LineBVP(
        segments, seabed=seabed, seabed_slope=seabed_slope, friction=friction, point_loads=point_loads,
        n_elements=n_elements, fit_touchdown=fit_touchdown, rtol=rtol, max_iter=max_iter, terms=terms,
        options=options, time_limit=time_limit, **newton_options,
    )  # fmt: skip
    solution = model._solution(span, dh)
    warn_unresolved(solution)  # the caller's line named
    solution.model = None  # no model of the caller's: no warm start from it
    return solution


class LineBVP:
    """A mooring line solved by `solve_line_bvp`, as a line model: everything but the fairlead's
    position, checked once; ``solve(span, dh, start=None)`` gives a `LineBVPSolution`.

    A line model is what `skcable.mooring.line_3d` and `skcable.mooring.MooringSystem` take (see
    `skcable.mooring.line3d`): `skcable.mooring.Line` in closed form, or this one where the
    closed form does not hold (a shaped seabed, a weight that varies along the line, point loads
    between joints, a line that lands twice).

    Parameters
    ----------
    segments, seabed, seabed_slope, friction, point_loads, n_elements, fit_touchdown, rtol
        As for `solve_line_bvp`.
    max_iter, time_limit
        As for `solve_line_bvp` (``time_limit`` bounds each `solve`).
    terms, options, **newton_options
        As for `solve_line_bvp`: the cable terms and the Newton options of every solve. The
        terms act in the line's own vertical plane, x from the anchor towards the fairlead: in
        `line_3d` or a `MooringSystem` a horizontal term (`CurrentDrag`, `WindDrag`) is along
        each line's own span, not a current or a wind in global axes.

    Examples
    --------
    >>> from skcable.mooring import LineBVP
    >>> chain = LineBVP([(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.3)
    >>> line = chain.solve(780.0, 186.0)
    >>> round(line.H_B), round(line.V_B)  # mooring.Line: 234402 N and 348843 N
    (234402, 348843)
    """

    def __init__(
        self,
        segments,
        *,
        seabed=None,
        seabed_slope=None,
        friction: float = 0.0,
        point_loads=(),
        n_elements: int | str = 64,
        fit_touchdown: int = 3,
        rtol: float | None = None,
        max_iter: int | None = None,
        terms=(),
        options=None,
        time_limit: float = 60.0,
        **newton_options,
    ):
        self.segments = plane_segments(segments)
        if seabed is None and seabed_slope is not None:
            raise InputError("seabed_slope", "applies to a seabed: give seabed= as well")
        if not (seabed is None or callable(seabed)):
            seabed = scalar("seabed", seabed)
        self.seabed, self.seabed_slope = seabed, seabed_slope
        self.friction = scalar("friction", nonnegative("friction", friction))
        _plausible.friction(self.friction)
        if self.friction > 0 and seabed is None:
            raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
        self.point_loads = point_loads_of(point_loads, self.length)
        self.n_elements = elements_option(n_elements)
        self.fit_touchdown = whole("fit_touchdown", fit_touchdown, 0, 10)
        #: the Newton options of every solve (`skcable.fe.NewtonOptions`)
        self.options = newton_options_of(options, rtol=rtol, max_iter=max_iter, **newton_options)
        #: the cable terms (`skcable.bvp.terms`)
        self.terms = terms_of(terms)
        #: seconds at most for each solve
        self.time_limit = scalar("time_limit", positive("time_limit", time_limit))

    @property
    def rtol(self) -> float:
        """Newton's tolerance relative to the total load (``options.tol``)."""
        return self.options.tol

    @property
    def max_iter(self) -> int:
        """Newton iterations at most per solve (``options.max_iter``)."""
        return self.options.max_iter

    @property
    def length(self) -> float:
        """Unstretched length (m)."""
        return float(sum(seg.length for seg in self.segments))

    def solve(self, span, dh, start=None) -> LineBVPSolution:
        """The line with its anchor at (0, 0) and its fairlead at ``(span, dh)`` (m).

        Parameters
        ----------
        span, dh : float
            The fairlead relative to the anchor (m).
        start : LineBVPSolution, optional
            A solution of this model at a nearby fairlead (a moored body's previous position):
            the solve starts from it, moved to the new ends, on its mesh, and is graded and
            fitted from there; from scratch where that fails.

        Raises
        ------
        InputError
            Bad ``span``/``dh``, the arguments of `solve_line_bvp` it refuses; ``start`` that is
            no solution of this model.
        ConvergenceError
            As `solve_line_bvp`.
        """
        solution = self._solution(span, dh, start)
        warn_unresolved(solution)  # the caller's line named
        return solution

    def _solution(self, span, dh, start=None) -> LineBVPSolution:
        """`solve` but for its resolution warning (`solve_line_bvp` warns itself)."""
        if start is not None and not (isinstance(start, LineBVPSolution) and start.model is self):
            raise InputError("start", f"must be a solution of this LineBVP, got {type(start).__name__}")
        solution = solve_resolved(partial(self._on, span, dh, start), self.n_elements, self.time_limit)
        solution.model = self
        return solution

    def _on(self, span, dh, start, n_elements: int, time_limit: float) -> LineBVPSolution:
        """The line on ``n_elements`` within ``time_limit`` (s), from ``start`` where given."""
        checked = scene(
            span,
            dh,
            self.segments,
            seabed=self.seabed,
            seabed_slope=self.seabed_slope,
            friction=self.friction,
            point_loads=self.point_loads,
            n_elements=n_elements,
            fit_touchdown=self.fit_touchdown,
            options=self.options,
            terms=self.terms,
            time_limit=time_limit,
        )
        solver = LineBVPSolver(checked, fallback=space_for_plane)
        with outsized(**magnitudes(checked)):  # as in solve_line_bvp
            return solver.solve() if start is None else solver.solve_from(start)

    def __repr__(self):
        return (
            f"LineBVP({len(self.segments)} segments, length={self.length:g}, seabed={self.seabed!r}, "
            f"friction={self.friction:g}, n_elements={self.n_elements!r}"
            + (f", terms={list(self.terms)!r}" if self.terms else "")
            + ")"
        )
