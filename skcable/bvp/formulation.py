"""``solve_bvp``: arguments checked, the formulation chosen, one Newton run, the result checked."""

from __future__ import annotations

from functools import partial

import numpy as np

from skcable._checks import (
    exactly_one,
    nonnegative,
    one_of,
    positive,
    positive_scalar,
    real,
    require,
    scalar,
    whole,
)
from skcable.bvp.arc import ArcProblem, ArcSolution, arc_guess
from skcable.bvp.graph import BVPSolution, GraphProblem, initial_guess
from skcable.cable.solution import ACCEPT
from skcable.errors import ConvergenceError, InputError
from skcable.fe import newton

__all__ = ["solve_bvp"]


def _choose_formulation(formulation, loads):
    one_of("formulation", formulation, ("auto", "graph", "arc"))
    if formulation != "auto":
        return formulation
    from skcable.bvp.terms import CableTerm

    horizontal = any(getattr(ld, "qx", None) is not None for ld in loads)
    terms = [ld for ld in loads if isinstance(ld, CableTerm)]
    return "arc" if horizontal or any(not t.vertical or t.uses_s for t in terms) else "graph"


#: Newton stops, raising, when the merit has not halved in this many iterations: a damped
#: start on a slack cable can crawl for 4 (a uniform arc mesh on a cable 100 times its chord)
STAGNATION_WINDOW = 8


def _newton(problem, dofs, value, *, rtol, max_iter, merit, name, atol=0.0, line_search=True, callback=None):
    """`skcable.fe.newton` on ``x = [dofs, value]`` (value: H or L0, kept > 0)."""
    size = len(dofs)
    visited = []  # merit of every state an increment was taken from: the history so far

    def increment(state):
        visited.append(state.merit)
        return problem.increment(state)

    try:
        return newton(
            lambda x: problem.assemble(x[:size], x[size]),
            np.append(dofs, value),
            norm=lambda state: state.merit,
            increment=increment,
            tol=rtol,
            max_iter=max_iter,
            merit=merit,
            admissible=lambda x: x[size] > 0,
            stagnation_window=STAGNATION_WINDOW,
            name=name,
            atol=atol,
            absolute=lambda state: problem.absolute(state, rtol),
            line_search=line_search,
            callback=callback,
        )
    except ConvergenceError as exc:
        if exc.history:
            raise
        raise ConvergenceError(f"{name}: {exc}", visited) from exc


def _checked(solution, rtol):
    """The solution if its residual meets the requested ``rtol`` (plus round-off), else raise.

    Newton stopped with every scaled residual below ``rtol``; the check
    recomputes them with the closure terms, which differ by round-off
    (`skcable.cable.solution.ACCEPT`).
    """
    residual = solution.residual()
    limit = rtol + ACCEPT
    if not residual <= limit:
        raise ConvergenceError(
            f"{type(solution).__name__}: residual {residual:.3e} above {limit:.3e} after Newton stopped",
            solution.history,
        )
    return solution


def solve_bvp(
    span,
    dh,
    load,
    *,
    length=None,
    sag=None,
    H=None,
    low=None,
    T_max=None,
    EA=None,
    n_elements: int = 64,
    degree: int = 2,
    mesh=None,
    rtol: float = 1e-10,
    max_iter: int = 50,
    formulation: str = "auto",
    seabed=None,
    friction: float = 0.0,
    atol: float = 0.0,
    line_search=True,
    callback=None,
    end_force=None,
):
    """Suspended cable under any loads, solved by finite elements.

    Parameters
    ----------
    span, dh : float
        B = (span, dh) relative to A = (0, 0) (m).
    load : load or list of loads
        `SelfWeight`, `DeckLoad`, `DistributedLoad`, `PointLoad`, a cable term
        (`skcable.bvp.terms`: `Buoyancy`, `WindDrag`, `CurrentDrag` or an analyst's own
        `CableTerm`), or any object with ``graph_terms``. Point loads at the same x add up.
    length, sag, H, low, T_max : float
        Exactly one constraint, as in `catenary`; with
        ``EA``, ``length`` is the unstretched length. ``T_max`` is the larger
        end tension.
    EA : float, optional
        Axial stiffness (N); inextensible when omitted.
    n_elements, degree : int
        Uniform mesh size and polynomial degree (1 to 6) of y.
    mesh : MeshLine or array, optional
        Node abscissae from 0 to span, instead of ``n_elements`` (distinct
        nodes; a repeated node raises).
    rtol : float
        Newton stops when the interior residual (relative to the total load)
        and the constraint residual are both below ``rtol``; the returned
        solution's `residual` is below ``rtol`` plus round-off (1e-9).
    max_iter : int
        Newton iterations at most; Newton also stops, raising, when the
        residual stagnates (less than halved in 8 iterations) or no step
        length along the Newton direction reduces it.
    atol : float
        Also converged when every force residual is below ``atol`` (N) and the constraint
        and stretch rows meet ``rtol``; 0 for none.
    line_search : bool or {"residual", "none"}
        Backtracking on the residual norm (default), or full Newton steps.
    callback : callable, optional
        ``callback(iteration, residual_norm, step_norm)`` after every Newton step; an
        exception it raises stops the solve as an `InputError` naming it.
    end_force : (float, float), optional
        A force (N, y up) on a free end B instead of B's position: ``(span, dh)`` is then
        B's starting position only, the constraint must be ``length`` and the arc form is
        used; the solution's ``span``, ``dh`` are where B came to rest, ``H_B``, ``V_B`` the
        force.
    formulation : {"auto", "graph", "arc"}
        ``"graph"``: y(x) with H a global unknown (any degree, point loads);
        ``"arc"``: position and tension along the unstretched arc length
        (`skcable.bvp.arc`: any shape, horizontal loads, P2/P1).
        ``"auto"`` takes the arc form when a load has a horizontal
        component, the graph form otherwise: started from the catenary of
        the same weight it converges from 1e-9 to 99 times the chord and
        for spans down to 1e-3 of the height difference, and it is the more
        accurate per element (docs/bvp.md maps both).
    seabed, friction
        Refused: a line on the seabed is a mooring line, solved by
        `skcable.mooring.solve_line_bvp` (0.2.0 handed it on from here).

    Returns
    -------
    BVPSolution or ArcSolution
        ``formulation`` tells which was used.

    Raises
    ------
    InputError
        Bad data (named argument).
    ConvergenceError
        Newton stalled; ``history`` holds the merit per iteration.
    """
    if seabed is not None or friction != 0.0:
        raise InputError(
            "seabed" if seabed is not None else "friction",
            "a line on the seabed is a mooring line: solve it with skcable.mooring.solve_line_bvp "
            "(segments [(length, w, EA)], seabed=, friction=)",
        )
    span, dh = positive("span", span), real("dh", dh)
    if not isinstance(span, float) or not isinstance(dh, float):
        raise InputError("span", "solve_bvp solves one scene: give scalar span and dh")
    loads = list(load) if isinstance(load, (list, tuple)) else [load]
    if not loads:
        raise InputError("load", "give at least one load")
    EA = None if EA is None else positive("EA", EA)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    value = real(name, value) if name == "low" else positive(name, value)
    if name == "low":
        require("low", value < min(0.0, dh), "must lie below both supports, low < min(0, dh)", value)
    rtol = float(positive_scalar("rtol", rtol))
    max_iter = whole("max_iter", max_iter, 1)
    whole("n_elements", n_elements, 1)
    settings = dict(atol=float(nonnegative("atol", scalar("atol", atol))), callback=_callback(callback))
    settings["line_search"] = _line_search(line_search)
    if end_force is not None:
        end_force = _end_force(end_force, name, formulation)
        formulation = "arc"
    formulation = _choose_formulation(formulation, loads)
    if formulation == "arc":
        problem = ArcProblem(span, dh, loads, EA, (name, value), n_elements, degree, end_force=end_force)
        return _solve_arc(problem, value, rtol, int(max_iter), settings)
    graph = GraphProblem(span, dh, loads, EA, (name, value), mesh, n_elements, degree)
    return _solve_graph(graph, rtol, int(max_iter), settings)


def _solve_arc(problem: ArcProblem, value, rtol: float, max_iter: int, settings: dict) -> ArcSolution:
    """The arc form's Newton run from `arc_guess` (the unstretched length ``value`` when it is
    fixed) and its checked solution."""
    z, L0 = arc_guess(problem)
    if problem.fixed_length:
        L0 = float(value)
    run = (rtol, max_iter, settings, lambda state: state.merit, "solve_bvp(formulation='arc')")
    return _solved(problem, z, L0, *run, ArcSolution)


def _solve_graph(problem: GraphProblem, rtol: float, max_iter: int, settings: dict) -> BVPSolution:
    """The graph form's Newton run from `initial_guess` and its checked solution."""
    dofs, H0 = initial_guess(problem)
    run = (rtol, max_iter, settings, lambda state: state.descent, "solve_bvp")
    return _solved(problem, dofs, H0, *run, partial(BVPSolution, resolver=resolve))


def _solved(problem, start, unknown, rtol, max_iter, settings, merit, name, solution):
    """Newton (`_newton`) from the field ``start`` and the global ``unknown`` (H or L0), and the
    checked ``solution(problem, field, unknown, history, state)``."""
    result = _newton(
        problem, start, unknown, rtol=rtol, max_iter=max_iter, merit=merit, name=name, **settings
    )
    size = len(start)
    return _checked(solution(problem, result.x[:size], result.x[size], result.history, result.state), rtol)


def resolve(solution, span, dh):
    """``solution``'s graph-form problem solved again with B at ``(span, dh)`` and the same
    unstretched length (nodes scaled with the span), to rtol 1e-13: the re-solves of
    `BVPSolution.stiffness`."""
    problem = solution.problem
    nodes = np.sort(problem.mesh.p[0]) * (span / problem.span)
    nodes[-1] = span
    return solve_bvp(
        span,
        dh,
        problem.loads,
        length=solution.length,
        EA=problem.EA,
        mesh=nodes,
        degree=problem.degree,
        rtol=1e-13,
        formulation="graph",
    )


def _line_search(value) -> bool:
    if value in (True, "residual"):
        return True
    if value in (False, "none"):
        return False
    raise InputError(
        "line_search", f"must be True/'residual' or False/'none' (a cable BVP has no energy), got {value!r}"
    )


def _callback(value):
    if value is not None and not callable(value):
        raise InputError("callback", f"must be callable(iteration, residual_norm, step_norm), got {value!r}")
    return value


def _end_force(value, constraint, formulation):
    force = np.asarray(real("end_force", value), dtype=float)
    if force.shape != (2,):
        raise InputError("end_force", f"must be (Fx, Fy) in N, got {value!r}")
    if constraint != "length":
        raise InputError(
            "end_force", "a free end is given with the cable's length: give length=, not " + constraint
        )
    if formulation == "graph":
        raise InputError("formulation", "a free end loaded by a force is solved in the arc form")
    return force
