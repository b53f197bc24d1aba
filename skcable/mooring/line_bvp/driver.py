r"""The continuation that takes a line from its closed-form start to the converged, fitted solution.

`LineBVPSolver(scene).solve()` runs one strategy, stage by stage; each stage is a method, and
each solve (`skcable.mooring.line_bvp.iterate.solve_on`) starts from the last stage's solution:

1. **Levels** (`LineBVPSolver.solve`). A mesh of more than ``2·COARSE`` elements whose start
   touches the seabed (or, on a seabed, whose one level fails) is reached by nested solves, from
   `COARSE`-odd elements up, each finished solution starting the doubled mesh (the active set
   moves by a few nodes per Newton iteration, so a fine mesh does not find its contact set from
   the coarse start; `skcable.mooring.line_bvp.mesh.solve_nested`, the line in space's too). A
   level that fails from the coarser solution is solved from scratch; a coarse level that fails
   even so is skipped (the next level starts from scratch). Where the finest level fails, the
   **point loads by steps** (`LineBVPSolver.loads_by_steps`): the line without them by this
   strategy, then on its mesh with them grown in steps (`LineSolver.continued`, the line in
   space's too), then stages 3–5 from there; its failure leaves the first one standing.
2. **First solve** (`LineBVPSolver.first_attempts`): frictionless, on a mesh graded by the
   closed-form start's angle (`skcable.mooring.line_bvp.mesh.start_nodes`), from that start
   (`skcable.mooring.line_bvp.start.closed_form_start`, the uniform line), else from the
   segment-wise closed form (`skcable.mooring.line_bvp.start.segmented_start`), else from the
   first start with the contact nodes switching by the line's tension (`LineBVPSolver.switched`:
   a taut line's residual forces at its start can exceed the switch of a line bent by its
   weight); on a straight slope through the anchor, whose start is the line on the slope, or
   below it, whose start is the line touching down on it, else from the uniform line lifted onto
   it (`skcable.mooring.line_bvp.start.lifted_start`), fixed and switching; else from the
   closed-form start on the uniform mesh; with clump weights, else
   from the uniform line under their weight smeared
   (`skcable.mooring.line_bvp.start.smeared_start`), on the graded mesh, then on the uniform one;
   else on the line in space's first mesh (graded by the discrete start's turning,
   `skcable.mooring.line_bvp.mesh.graded_nodes`), from the closed form, the segment-wise one and
   switching. As a last resort (the requested mesh only), where the stages after it fail from the first
   solve that converges, they go on from the next (`LineBVPSolver.level`).
3. **Passes of grading** (`LineBVPSolver.graded`): the mesh graded by the last solution's angle
   (`skcable.mooring.line_bvp.mesh.graded_nodes`), again while the elements of the bends could
   shrink no more than ``REFINEMENT`` times at one pass (the start then puts the touchdown a
   node or two off: nodal contact moves a few nodes per Newton iteration) or while the discrete
   line is in compression (its bends not resolved), `GRADE_PASSES` at most.
4. **Friction** (`LineBVPSolver.with_friction`): the frictionless line tells where friction
   takes the whole pull (the slack stretch's first estimate,
   `skcable.mooring.line_bvp.slack.slack_estimate`); the line is solved again with friction, with
   a node at the touchdown too where that fails (μ = 5 on a nearly L-shaped line: friction takes
   the whole pull 0.1–2 mm before the touchdown).
5. **Fitting** (`LineBVPSolver.fitted`): a node at the touchdown and the landing the vertical
   balance gives (``LineBVPSolution.s_touchdown``, ``s_landing``), ``fit_touchdown`` passes
   while it moves more than 1e-9 of the length; and the end of the slack stretch moved
   (`skcable.mooring.line_bvp.slack.next_slack_end`) until the tension past it is zero to ``rtol``
   of the total load, `SLACK_PASSES` more at most, then `SLACK_PASSES` secant steps at most
   (`LineBVPSolver.secant_slack`); with friction, graded and fitted once more where the mesh is
   too coarse for the line with friction (`LineBVPSolver.regraded`).
6. **Checks** (`LineBVPSolver.checked`): no buoy on a slack stretch (``InputError("point_loads")``:
   no tension holds it down, `skcable.mooring.line_bvp.slack.buoy_on_stretch`), the friction that
   holds a slack stretch on a slope at most μN, every number finite, the discrete line not in
   compression (where the compression lies on the seabed from the anchor,
   ``InputError("friction")``: the line has no equilibrium in tension,
   `skcable.mooring.line_bvp.check.refuse_sliding`).
7. **Refusal, or the line in space** (`LineBVPSolver.solve`): a failure where the segment-wise
   closed form's slack stretch ends at a clump weight on the seabed becomes
   ``InputError("point_loads")`` (`LineBVPSolver.clump_at_slack_end`); else the ``fallback``
   where the model gives one: the line in space's strategy, its line then solved in the plane on
   its mesh, graded, fitted and checked as a level from it
   (`skcable.mooring.line_bvp.fallback.space_for_plane`); where that fails too, one with
   friction and the anchor above the seabed says where friction fully mobilised may take more
   than the pull (`LineBVPSolver.with_diagnosis`).

**A warm start** (`LineBVPSolver.solve_from`, `LineBVP.solve(start=)`): the previous solution,
moved to the new fairlead on its own mesh (`LineBVPSolver.moved`), is the start of one level
(stages 3 and 5, with friction from the start); from scratch where that fails.

**Bounded.** Every solve counts against the scene's ``time_limit`` (`skcable._budget.Budget`):
past it `solve` and `solve_from` raise a `ConvergenceError` with the last merit of every solve.
The number of solves is bounded by the stages. A failure keeps what converged: its ``last`` is
the solve on the finest mesh reached (`LineSolver.bounded`).

**Retries.** Every solve on a new mesh starts from the last solution interpolated onto it, else
from the closed-form start (on a nearly L-shaped line the bend at the touchdown has the radius
H/w, a thousandth of the length, and the interpolated bend of a coarser or differently graded
mesh can start Newton farther off than the closed form does), else from the segment-wise one.
Each retry is an alternative passed to `skcable.fe.first_converged`, which raises the first
alternative's error when every one fails (a solve's own fallbacks from its start are
`skcable.fe.newton`'s options: `skcable.mooring.line_bvp.iterate`).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache, partial

import numpy as np

from skcable._budget import Budget
from skcable.errors import ConvergenceError, InputError
from skcable.fe import first_converged
from skcable.mooring.line_bvp import start as closed_forms
from skcable.mooring.line_bvp.inputs import Scene
from skcable.mooring.line_bvp.mesh import (
    COARSE,
    GRADE_PASSES,
    fixed_nodes,
    graded_nodes,
    grading_passes,
    joints_of,
    solve_nested,
    start_nodes,
)
from skcable.mooring.line_bvp.problem import LineProblem
from skcable.mooring.line_bvp.slack import (
    BUOY_ON_STRETCH,
    SLACK_PASSES,
    buoy_on_stretch,
    next_slack_end,
    secant_slack_end,
    slack_estimate,
    slack_tension,
    tension_zero,
)
from skcable.mooring.line_bvp.solution import LineBVPSolution
from skcable.mooring.line_bvp.solver import LineSolver
from skcable.mooring.line_bvp.start import (
    closed_form_start,
    on_dofs,
    restart,
    segmented_solution,
    segmented_start,
    slack_end_of,
    smeared_start,
    start_form,
)

__all__ = ["GRADE_PASSES", "STIFFNESS_TIME", "LineBVPSolver"]

#: the time (s) the stiffness's two re-solves of a line with a slack stretch may take, each a few
#: Newton steps from the converged line (`LineBVPSolver.at_slack_end`): a public solve's default
STIFFNESS_TIME = 60.0


def _with(s0, fitted=()):
    """The points to fit: ``fitted`` and the end of the slack stretch, if any."""
    return list(fitted) + ([s0] if s0 > 0 else [])


class LineBVPSolver(LineSolver):
    """The solver of one line BVP: the continuation of the module docstring over a `Scene`.

    Parameters
    ----------
    scene : Scene
        The checked scene and options (`skcable.mooring.line_bvp.inputs.scene`).
    fallback : callable, optional
        ``fallback(solver)``, tried where the strategy fails (`LineSolver.fallback`).
    """

    def __init__(self, scene: Scene, fallback=None):
        self.scene, self.fallback = scene, fallback
        lengths = np.array([seg.length for seg in scene.segments])
        self.length = float(joints_of(lengths)[-1])
        #: the nodes every mesh keeps (joints, point loads)
        self.fixed = fixed_nodes(joints_of(lengths), scene.point_loads)
        self.budget = Budget(time_limit=scene.time_limit)
        #: the Newton options of every solve (the scene's: `solve_line_bvp`'s ``options``)
        self.options = scene.options

    # --- the pieces: a problem, a solve, a solve on a new mesh --------------------------------
    def problem(self, n, fitted=(), slack_end=0.0, mu=None, nodes_at=None, load_factor=1.0) -> LineProblem:
        """The discrete line on ``n`` elements (μ the scene's unless given), its point loads times
        ``load_factor`` (`LineSolver.continued`)."""
        sc = self.scene
        mu = sc.friction if mu is None else mu
        loads = sc.point_loads if load_factor == 1.0 else [(s, load_factor * P) for s, P in sc.point_loads]
        return LineProblem(
            sc.span, sc.dh, sc.segments, loads, sc.seabed, mu, n,
            fitted=fitted, slack_end=slack_end, nodes_at=nodes_at, terms=sc.terms,
        )  # fmt: skip

    #: what a solve gives (`LineSolver.run`)
    result = LineBVPSolution
    #: the closed-form starts (`LineSolver.starts`)
    start_forms = closed_forms

    def from_segments(self, problem) -> LineBVPSolution:
        """The line of ``problem`` from the segment-wise closed-form start (`segmented_start`);
        a `ConvergenceError` where there is none."""
        return self.from_start(problem, segmented_start(problem))

    def rerun(self, problem, solution) -> LineBVPSolution:
        """The line on ``problem``'s mesh from ``solution`` interpolated onto it, else from the
        closed-form start, else from the segment-wise one."""
        return first_converged(
            [
                lambda: self.run(problem, restart(solution.problem, solution.dofs, problem)),
                lambda: self.run(problem, closed_form_start(problem)),
                lambda: self.from_segments(problem),
            ]
        )

    # --- the stages ---------------------------------------------------------------------------
    def solve(self) -> LineBVPSolution:
        """The line on the scene's mesh: one level, or nested levels (module docstring, 1); a
        failure where the slack stretch ends at a clump weight on the seabed refused
        (`clump_at_slack_end`); within the budget."""
        return self.bounded(self.unbounded)

    def unbounded(self) -> LineBVPSolution:
        """`solve` without the budget's conversion (a stage of `solve_from` too)."""
        try:
            return self.levels()
        except ConvergenceError as failed:
            clump = self.clump_at_slack_end()
            if clump is None:
                solution, note = self.from_fallback()
                if solution is None:
                    raise self.failed_with(failed, note) from None
                return solution
            raise InputError(
                "point_loads",
                f"the slack stretch near the anchor ends at the point load at s = {clump:.6g} m, which "
                "rests on the seabed with its friction only partly mobilised: this BVP does not model "
                "that state (mooring.Line solves it in closed form)",
            ) from None

    def solve_from(self, previous) -> LineBVPSolution:
        """The line from ``previous``, a solution of the same line at another fairlead: moved to
        this one on its mesh (`moved`), then graded and fitted as a level from it; from
        scratch (`solve`) where that fails; within the budget."""
        return self.bounded(self.from_previous, previous)

    def from_previous(self, previous) -> LineBVPSolution:
        """`solve_from` without the budget's conversion."""
        try:
            return self.checked(self.level(self.scene.n_elements, self.moved(previous)))
        except ConvergenceError:
            return self.unbounded()

    def moved(self, previous) -> LineBVPSolution:
        """``previous`` solved again at this scene's fairlead on its own mesh (its slack stretch
        kept), from its dofs moved along their tangent ``∂z/∂r_B`` (the active set held,
        `DiscreteLine.end_sensitivities`, as the line in space's warm start)."""
        sc, old = self.scene, previous.problem
        nodes = np.sort(old.mesh.p[0])
        problem = self.problem(nodes.size - 1, _with(old.slack_end), old.slack_end, sc.friction, nodes)
        dz = previous.sensitivity[2]  # ∂z/∂r_B, the active set held (its stiffness's too)
        z = previous.dofs + dz @ np.array([sc.span - previous.span, sc.dh - previous.dh])
        return self.run(problem, restart(old, z, problem))

    def clump_at_slack_end(self):
        """The arc length (m) of the downward point load where the segment-wise closed form's
        slack stretch ends, or None (no friction, no such load, or no closed form).

        A clump weight resting on the seabed near the anchor can end the slack stretch itself:
        the tension jumps there by the friction the clump mobilises, only partly (the share of
        ``μN`` that the pull needs). The BVP's slack stretch ends at a node where the friction is
        fully mobilised beyond it (`skcable.mooring.line_bvp.slack`): the tension past its end has
        no zero then (negative for every end before the clump, positive after it), and the solve
        fails. `skcable.mooring.Line` (Jonkman's grounded pieces, applied piece by piece) gives
        that state.
        """
        sc = self.scene
        loads = [s for s, P in sc.point_loads if P > 0]
        if not (sc.friction > 0 and sc.seabed is not None and loads):
            return None
        line = segmented_solution(self.problem(COARSE), sc.friction)
        if line is None:
            return None
        step = 1e-9 * self.length
        for s in loads:
            if line.T_of_s(s - step) <= 0.0 < line.T_of_s(s + step):
                return float(s)
        return None

    def levels(self) -> LineBVPSolution:
        """One level, or nested levels (module docstring, 1), checked: nested first where the
        start touches the seabed, else where one level fails (the uniform start above a sloping
        seabed while the line's clump weight rests on it), as the line in space does; where all
        fail, the point loads by steps (`loads_by_steps`)."""
        n, bed = self.scene.n_elements, self.scene.seabed
        every_start = partial(self.level, n, every_start=True)  # the last resort (`level`)
        attempts: list[Callable[[], LineBVPSolution]]
        if n > 2 * COARSE and bed is not None:
            probe = self.problem(n, mu=0.0)
            if self.touches(probe, closed_form_start(probe)):
                attempts = [lambda: self.nested(n), every_start]
            else:
                attempts = [lambda: self.level(n), lambda: self.nested(n), every_start]
        else:
            attempts = [every_start]
        try:
            return self.checked(first_converged(attempts))
        except ConvergenceError as failed:  # the first failure stands where the loads' steps fail too
            try:
                return self.checked(self.loads_by_steps())
            except ConvergenceError:
                raise failed from None

    def loads_by_steps(self) -> LineBVPSolution:
        """The line without its point loads by this strategy (`levels`), then its loads grown on
        that line's mesh in steps (`LineSolver.continued`), then graded, fitted and checked as a
        level from it (stages 3–5; module docstring, 1): a buoy lifting an arch off a slope or a
        clump pulling the line onto it moves the contact set far from every closed-form start's.
        A `ConvergenceError` where the line has no point loads."""
        sc = self.scene
        if not any(P != 0.0 for _, P in sc.point_loads):
            raise ConvergenceError(f"{self.name}: no point loads to grow", [])
        unloaded = self.within_budget(point_loads=[(s, 0.0) for s, _ in sc.point_loads])
        try:
            base = unloaded.levels()
        except Budget.Spent:
            raise ConvergenceError(
                f"{self.name}: no time left for the line without its point loads", []
            ) from None
        except InputError as refused:  # a verdict on another line (its heap, say): not this one's
            raise ConvergenceError(f"{self.name}: without its point loads, {refused}", []) from None
        old, fitted = base.problem, self.edges_of(base)
        nodes = np.sort(old.mesh.p[0])
        start = self.problem(nodes.size - 1, fitted, nodes_at=nodes, load_factor=0.0)
        solved = self.continued(nodes.size - 1, fitted, restart(old, base.dofs, start), nodes_at=nodes)
        return self.level(sc.n_elements, solved)

    def nested(self, n) -> LineBVPSolution:
        """Nested levels up to ``n`` elements, each from the last (module docstring, 1)."""
        return solve_nested(n, self.level)

    def level(self, n, start=None, every_start=False) -> LineBVPSolution:
        """The line on ``n`` elements, from scratch or from ``start`` (the finished solution on
        a coarser mesh): stages 2–5, from the first of the first solve's starts that converges
        (`first_attempts`). With ``every_start``, where the stages after it fail (a spurious
        branch that grading cannot take to the line), they go on from the next start that
        converges, the first failure raised where none leads to the line: the last resort of
        `levels` only (on a coarse mesh of nested solves a level that fails is better skipped
        than solved on another branch, which the finer levels would follow)."""
        if start is not None:
            return self.stages(n, start, start.problem.slack_end, self.edges(start), from_scratch=False)
        failures = []
        for attempt in self.first_attempts(n):
            try:
                solution = attempt()
            except ConvergenceError as failed:
                failures.append(failed)
                continue
            try:
                return self.stages(n, solution, 0.0, [], from_scratch=True)
            except ConvergenceError as failed:
                if not every_start:
                    raise
                failures.append(failed)
        raise failures[0]

    def stages(self, n, solution, s0, fitted, from_scratch) -> LineBVPSolution:
        """Stages 3–5 from ``solution`` (a first solve, else a coarser mesh's finished line with
        its slack stretch's end ``s0`` and its ``fitted`` points)."""
        mu_now = 0.0 if from_scratch else self.scene.friction
        graded = None
        if self.scene.fit_touchdown:
            solution, graded = self.graded(n, solution, fitted, s0, mu_now)
        elif not from_scratch:
            solution = self.rerun(self.problem(n, _with(s0), s0), solution)
        if from_scratch and self.scene.friction > 0:
            solution, s0, fitted = self.with_friction(n, solution, graded)
            solution = self.fitted(n, solution, s0, fitted, graded)
            return self.regraded(n, solution)
        return self.fitted(n, solution, s0, fitted, graded)

    def regraded(self, n, solution) -> LineBVPSolution:
        """The line with friction graded again and fitted again, where its mesh (graded by the
        frictionless line) is too coarse for it: where its own grading asks for elements more
        than ``REFINEMENT`` times smaller somewhere (a heavy chain whose friction holds a light
        rope: the bend at the touchdown tightened from 0.4 m to 6 cm of radius)."""
        if not self.scene.fit_touchdown:
            return solution
        if not graded_nodes(solution.problem, solution.dofs, n, self.fixed, arches=self.arches)[1]:
            return solution
        s0, fitted, mu = solution.problem.slack_end, self.edges(solution), self.scene.friction
        solution, graded = self.graded(n, solution, fitted, s0, mu)
        return self.fitted(n, solution, s0, fitted, graded)

    def first_attempts(self, n) -> list:
        """The frictionless line's first solves (module docstring, 2), in turn: from the
        closed-form starts (`LineSolver.starts`: the start, the segment-wise closed form,
        switching, and on a straight slope through the anchor the lifted line), on a mesh graded
        by the start when the touchdown is fitted; on the uniform mesh where every start fails on the
        graded one (its scene 3:172); with clump weights, from the uniform line under their
        weight smeared (`skcable.mooring.line_bvp.start.smeared_start`), on the graded mesh,
        then on the uniform one (its scene 2:40); with a fitted touchdown, on the line in space's
        first mesh, graded by the discrete start's turning, from the closed-form start, the
        segment-wise one and switching (7 scenes of the survey that the line in space solved and
        the plane line failed, 1:79 among them: a wire landing 2.5 m from an anchor 2.1 m above
        the seabed and a chain rising to the fairlead, whose first grading pass from the mesh
        graded by the start's closed-form angle found no descent). Each solve that leaves the
        discrete line in compression (a spurious branch: a clump weight at the bottom of a
        U-shaped line under a uniform start) gives way to the segment-wise start's where that one
        does not."""
        uniform = problem = self.problem(n, mu=0.0)
        if self.scene.fit_touchdown:
            problem = self.problem(n, mu=0.0, nodes_at=start_nodes(start_form(problem), self.fixed, n))
        solves = self.starts(problem)
        if problem is not uniform:  # the start's grading can leave Newton no descent: the uniform mesh
            solves.append(lambda: self.run(uniform, closed_form_start(uniform)))
        if any(P > 0 for _, P in self.scene.point_loads):  # clump weights that hold the line down
            solves.append(lambda: self.from_start(problem, smeared_start(problem)))
            if problem is not uniform:
                solves.append(lambda: self.from_start(uniform, smeared_start(uniform)))
        attempts = [partial(self.uncompressed, solve, problem) for solve in solves]
        if self.scene.fit_touchdown:  # the line in space's first mesh, built where these run

            @cache
            def by_start():
                nodes = graded_nodes(uniform, closed_form_start(uniform), n, self.fixed, arches=False)[0]
                return self.problem(n, mu=0.0, nodes_at=nodes)

            attempts += [partial(self.on_problem, k, by_start) for k in range(3)]
        return attempts

    def on_problem(self, k, problem) -> LineBVPSolution:
        """`uncompressed` of the ``k``-th of the solves from the closed-form starts (`starts`)
        on the problem ``problem()`` builds (where the attempt runs)."""
        return self.uncompressed(self.starts(problem())[k], problem())

    def uncompressed(self, solve, problem) -> LineBVPSolution:
        """``solve()``, or where it leaves the discrete line in compression, the segment-wise
        start's solve of ``problem`` where that one does not."""
        solution = solve()
        if self.compressed(solution):
            other = first_converged([lambda: self.from_segments(problem), lambda: solution])
            solution = solution if self.compressed(other) else other
        return solution

    def graded(self, n, solution, fitted, s0, mu):
        """Passes of grading by the last solution's angle (module docstring, 3): the solution and
        the last graded nodes (`skcable.mooring.line_bvp.mesh.grading_passes`)."""

        def resolve(nodes, last):
            return self.rerun(self.problem(n, _with(s0, fitted), s0, mu, nodes), last)

        return grading_passes(solution, n, self.fixed, resolve, self.compressed, arches=self.arches)

    def with_friction(self, n, frictionless, graded):
        """The line with friction from the frictionless one (module docstring, 4): the solution,
        the end of the slack stretch and the points fitted. Three alternatives, in turn
        (`first_converged`): from the frictionless line on its mesh, with a node at its
        touchdown too, from the segment-wise closed form with friction."""
        anchored = frictionless.problem.anchor_on_seabed
        s0 = slack_estimate(frictionless, self.scene.friction) if anchored else 0.0
        solution, s0, fitted = first_converged(
            [
                lambda: self.from_frictionless(n, frictionless, graded, s0, []),
                lambda: self.from_frictionless(n, frictionless, graded, s0, self.edges(frictionless)),
                lambda: self.from_closed_friction(n, frictionless, graded),
            ]
        )
        if s0 == 0 and anchored:
            s0 = tension_zero(solution, 1e3 * self.tolerance * solution.problem.load_scale)
        return solution, s0, fitted

    def from_frictionless(self, n, frictionless, graded, s0, fitted):
        """``(solution, s0, fitted)``: the line with friction and a slack stretch ending at
        ``s0`` from the frictionless line, nodes at ``fitted``."""
        problem = self.problem(n, _with(s0, fitted), s0, self.scene.friction, graded)
        return self.rerun(problem, frictionless), s0, fitted

    def from_closed_friction(self, n, frictionless, graded):
        """``(solution, s0, fitted)``: the line with friction from the segment-wise closed form
        with friction and its slack stretch (`slack_end_of`), a node at the frictionless
        touchdown; a `ConvergenceError` where there is no such closed form."""
        line = segmented_solution(frictionless.problem, self.scene.friction)
        if line is None:
            raise ConvergenceError("solve_line_bvp: no segment-wise closed form of this line", [])
        end = slack_end_of(line, self.length) if frictionless.problem.anchor_on_seabed else 0.0
        fitted = self.edges(frictionless)
        problem = self.problem(n, _with(end, fitted), end, self.scene.friction, graded)
        return self.run(problem, on_dofs(problem, line)), end, fitted

    def fitted(self, n, solution, s0, fitted, graded) -> LineBVPSolution:
        """Nodes at the touchdown and landing, and the end of the slack stretch, moved until they
        settle (module docstring, 5)."""
        fit = self.scene.fit_touchdown
        slack_tol = self.tolerance * solution.problem.load_scale
        edge_passes = 0
        tried: list[tuple[float, float]] = []  # (end, tension past it) of the settled solves
        for _ in range(fit + SLACK_PASSES):
            fitted, edges_moved, settled = self.moved_edges(solution, fitted, edge_passes < fit or s0 > 0)
            edge_passes += edges_moved
            s0, end_moved = self.moved_slack_end(solution, s0, tried, settled, slack_tol)
            if not (edges_moved or end_moved):
                break
            problem = self.problem(n, _with(s0, fitted), s0, self.scene.friction, graded)
            solution = self.rerun(problem, solution)
        if s0 > 0 and not abs(slack_tension(solution)[0]) <= slack_tol:
            solution = self.secant_slack(n, solution, fitted, graded, slack_tol)
        if solution.problem.slack_end > 0:
            g, _ = slack_tension(solution)
            if not abs(g) <= slack_tol:
                raise ConvergenceError(
                    "solve_line_bvp: the end of the slack stretch near the anchor was not found "
                    f"(tension {g:.3g} N there after {len(tried)} updates)",
                    solution.history,
                )
        return solution

    def secant_slack(self, n, solution, fitted, graded, tol) -> LineBVPSolution:
        """More passes on the end of the slack stretch, each a secant step on the last two (end,
        tension past it) pairs, bracketed as in `next_slack_end`, with the touchdown fitted
        until it settles as well (`SLACK_PASSES` plus ``fit_touchdown`` at most).

        The Newton step of the first passes takes the tension's growth with the end from the
        friction alone, ``μ w``; where the end moves the whole line (a compliant rope at the
        anchor under a heavy chain: H grew from 850 N to 1480 N while the end moved 2.5 m) the
        tension past it falls by a constant factor per pass instead, and the secant restores
        the superlinear convergence. Where the stretch vanishes (the secant passes the anchor),
        the touchdown is fitted anew for the line without it."""
        pairs = []
        for _ in range(SLACK_PASSES + self.scene.fit_touchdown):
            fitted, moved, _ = self.moved_edges(solution, fitted, True)
            s0, step = solution.problem.slack_end, False
            if s0 > 0:
                g, slope = slack_tension(solution)
                if abs(g) > tol:
                    pairs.append((s0, g))
                    s0, step = secant_slack_end(pairs, slope, solution.s_touchdown), True
            if not (step or moved):
                break
            problem = self.problem(n, _with(s0, fitted), s0, self.scene.friction, graded)
            solution = self.rerun(problem, solution)
        return solution

    def moved_slack_end(self, solution, s0, tried, settled, tol):
        """The next end of the slack stretch (`next_slack_end`) where the tension past the one
        ``solution`` was solved with exceeds ``tol``, or where ``s0`` is not yet that one:
        ``(s0, moved)``; a settled solution's (end, tension) goes into ``tried``."""
        slack_end = solution.problem.slack_end
        if not (s0 > 0 or slack_end > 0):
            return s0, False
        if slack_end != s0:
            return s0, True
        g, slope = slack_tension(solution)
        if not abs(g) > tol:
            return s0, False
        s0 = next_slack_end([*tried, (s0, g)], slope, solution.s_touchdown)
        if settled:
            tried.append((slack_end, g))
        return s0, True

    def checked(self, solution) -> LineBVPSolution:
        """The solution, once its checks hold (module docstring, 6)."""
        problem, friction = solution.problem, self.scene.friction
        slack_tol = self.tolerance * problem.load_scale
        s0 = problem.slack_end
        buoy = buoy_on_stretch(self.scene.point_loads, s0, problem.weight_at)
        if buoy is not None:
            raise InputError("point_loads", BUOY_ON_STRETCH.format(s=buoy))
        if s0 > 0:
            # the friction that holds the slack stretch (its tangential force) is at most μN
            on = solution.contact_s < s0
            slope = problem.seabed.slope(solution.contact_xy[on, 0])
            force = solution.contact_force[on]
            tangential = np.abs(force[:, 0] + slope * force[:, 1]) / np.sqrt(1.0 + slope * slope)
            if np.any(tangential > friction * solution.normal_force[on] + slack_tol):
                raise InputError(
                    "friction",
                    "too weak to hold the slack stretch near the anchor on the sloping seabed "
                    "(the line would slide down it)",
                )
        values = (solution.H, solution.V_B, solution.H_A, solution.V_A)
        if not all(np.isfinite(values)) or not np.all(np.isfinite(solution.dofs)):
            raise ConvergenceError("solve_line_bvp: non-finite result", solution.history)
        above = friction > 0 and not problem.anchor_on_seabed
        why = "fully mobilised friction with the anchor above the seabed" if above else ""
        self.refuse_compressed(solution, why, also=f", H = {solution.H:.3g} N")
        solution.check()
        solution.slack_solver = partial(self.at_slack_end, solution) if s0 > 0 else None
        return solution

    def at_slack_end(self, solution, s0) -> LineBVPSolution:
        """``solution``'s line re-solved from it on its mesh with the slack stretch ending at
        ``s0`` instead (its node moved there): for the stiffness along the slack end, asked for
        after the solve, so on a budget of its own (`STIFFNESS_TIME`; the solve's may be spent by
        then, and with ``n_elements="auto"`` its ``time_limit`` is what was left of the user's)."""
        self.budget = Budget(time_limit=STIFFNESS_TIME)
        nodes = np.sort(solution.problem.mesh.p[0])
        problem = self.problem(nodes.size - 1, [s0], s0, self.scene.friction, nodes)
        return self.rerun(problem, solution)
