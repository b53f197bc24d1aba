r"""The strategy that takes a line in space from its closed-form start to the converged solution.

`LineBVP3DSolver(scene).solve()` runs, each solve by `skcable.mooring.line_bvp.iterate.solve_on`
(the plane line's: damped semismooth Newton, full steps, the polish):

1. **On a seabed, with ``fit_touchdown`` (and ``mesh="graded"``, the default), meshes graded as the
   plane line's** (`LineBVP3DSolver.from_graded_start`, then `LineBVP3DSolver.graded`): the first
   mesh graded by the closed-form start's turning (`skcable.mooring.line_bvp.mesh.graded_nodes` of
   the start on the uniform mesh, its elements at most `REFINEMENT` times finer than the uniform
   mesh's, else ``REFINEMENT²`` times), the line solved there from its closed-form starts (2), then
   on meshes graded by its own turning, pass by pass
   (`skcable.mooring.line_bvp.mesh.grading_passes`, the plane line's): graded as the plane line's
   meshes are (whose first mesh is graded by its start's angle in closed form,
   `skcable.mooring.line_bvp.mesh.start_nodes`), so that in its vertical plane the two answers
   agree to their discretisation errors (the uniform mesh left the bend where the line lands on the
   seabed in one or two elements: the differential survey `benchmarks/line_bvp_planes.py` found end
   forces up to 2 % off at 64 elements). Each mesh is a function of the ends alone, the start's and
   then the line's: a warm start (`LineBVP3DSolver.solve` from a solution at nearby ends) solves
   the same meshes from its start moved (`LineBVP3DSolver.moved`), so it gives the solve from
   scratch to round-off wherever the solve from scratch converges on the first of them. Where this
   fails or ends in compression, or without a seabed, or with ``mesh="uniform"``,
2. **a level on the uniform mesh** (`LineBVP3DSolver.level`): the line from its closed-form
   starts (`LineSolver.starts`, the plane line's list, of the starts
   `skcable.mooring.line_bvp.space.start`): the start, the segment-wise closed form, on a seabed the
   start with the contact nodes switching by the tension, on a plane seabed through the anchor
   the flat grounded line lifted onto it too; where those fail,
3. **the current and the point loads by steps** (`LineSolver.continued`, the plane line's too):
   the line in still water without its point loads, then the drag and the loads grown to their
   full values in steps (a quarter first, halved where a step fails, down to 1/64), each from
   the last; where that fails too (or a fine mesh's start touches the seabed),
4. **nested meshes** (`LineBVP3DSolver.nested`, by the plane line's
   `skcable.mooring.line_bvp.mesh.solve_nested`): from `skcable.mooring.line_bvp.mesh.COARSE`
   elements up, each solution interpolated onto the doubled mesh (the active set moves by a
   few nodes per Newton iteration, so a fine mesh does not find its contact set from the start),
   a level that fails so solved from scratch (its closed-form starts and the loads by steps,
   2–3, `LineBVP3DSolver.from_starts`), a coarse one that fails even so skipped; the meshes
   graded by the start (1) nest the same way (`LineBVP3DSolver.on_mesh`); on a
   seabed without the graded meshes of 1 (``mesh="uniform"`` or no ``fit_touchdown``), where
   every one of these fails, the starts on the mesh graded by the start (1). A line in
   compression on the uniform mesh is graded by its turning as in 1. Without a seabed the
   uniform mesh is kept, and a warm start solves on its start's mesh.
5. **Fitting** (`LineBVP3DSolver.fitted`): a node at the touchdown and the landing the balance of
   forces gives (`skcable.mooring.line_bvp.fitting`), ``fit_touchdown`` passes while they move
   more than 1e-9 of the length; where friction fully mobilised puts the line in compression on
   the seabed from the anchor, which friction can hold (``tan α ≤ μ``), **the slack stretch**
   (`LineBVP3DSolver.slackened`): laid on the seabed from the anchor and held there
   (`skcable.mooring.line_bvp.space.problem.LineProblem3D.lay_slack`), its end moved by the
   plane line's steps until the tension past it is zero, the touchdown refitted with it; a line
   in compression after it (a node at the touchdown left a bend in one element) graded again and
   fitted again.
6. **Checks** (`LineBVP3DSolver.checked`): every number finite, the line not in compression (a
   line in compression on the seabed from the anchor, the seabed rising more steeply than
   friction holds, has no equilibrium in tension: ``InputError("friction")``,
   `skcable.mooring.line_bvp.check.refuse_sliding`), its equilibrium residual within its bound
   (`skcable.mooring.line_bvp.space.solution.LineBVP3DSolution.check`); with a slack stretch, no
   load across the line at its end (`refuse_across`: ``InputError`` naming ``current``,
   ``terms`` or ``seabed``), friction holding each of its nodes (``InputError("friction")``) and
   none lifted by a buoy; where its end is at a clump resting on the seabed (friction partly
   mobilised there, which no line BVP models), ``InputError`` naming ``point_loads`` or
   ``attachments``.
7. **In its vertical plane** (the ``fallback`` where the model gives one,
   `skcable.mooring.line_bvp.fallback.plane_for_space`): where 1–6 fail, a line that
   hangs in the vertical plane of its ends (no current or cable terms; no seabed, or a `Plane`
   sloping along the chord; constant stiffnesses: `skcable.mooring.line_bvp.space.vertical_plane`)
   on meshes the plane line grades alike is solved by the
   plane line's strategy (`skcable.mooring.line_bvp.driver`) within what is left of the budget,
   then in space on its mesh from it (one discrete line: Newton takes a step or two), fitted (5)
   and checked (6). In the differential survey this solves scenes 2:191 and 3:34, which end in
   compression in space.

A failure raises the uniform level's `skcable.ConvergenceError` (2–4: the first attempt's of
those), with its history, where the graded meshes failed too, and says where the plane line's
strategy failed too (7); with friction
and the anchor above the seabed, saying where friction fully mobilised may take more than the
pull (`LineBVP3DSolver.with_diagnosis`). Every solve
counts against the scene's ``time_limit`` (`skcable._budget.Budget`): past it, a
`ConvergenceError` with the last merit of every solve. A failure keeps what converged: its
``last`` is the solve on the finest mesh reached (`LineSolver.bounded`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache, partial

import numpy as np

from skcable._budget import Budget
from skcable.errors import ConvergenceError, InputError
from skcable.fe import first_converged
from skcable.mooring.bathymetry import OffGrid
from skcable.mooring.line_bvp.check import SLOPE_TOL
from skcable.mooring.line_bvp.loads import term_load
from skcable.mooring.line_bvp.mesh import (
    COARSE,
    REFINEMENT,
    fixed_nodes,
    graded_nodes,
    grading_passes,
    solve_nested,
)
from skcable.mooring.line_bvp.slack import (
    BUOY_ON_STRETCH,
    SLACK_PASSES,
    buoy_on_stretch,
    secant_slack_end,
    slack_tension,
    tension_zero,
)
from skcable.mooring.line_bvp.solver import LineSolver
from skcable.mooring.line_bvp.space import start as closed_forms
from skcable.mooring.line_bvp.space.loads import SegmentDrag
from skcable.mooring.line_bvp.space.problem import LineProblem3D
from skcable.mooring.line_bvp.space.solution import LineBVP3DSolution
from skcable.mooring.line_bvp.space.start import closed_form_start
from skcable.mooring.line_bvp.start import restart

__all__ = ["ACROSS", "LineBVP3DSolver"]

#: the load across a grounded line at the end of its slack stretch, over ``μ w`` there, above
#: which the line in space refuses the stretch (`LineBVP3DSolver.refuse_across`)
ACROSS = 1e-6


@dataclass
class Solved:
    """A converged solve: the problem, its iterate, the merit history and the state there."""

    problem: object
    dofs: np.ndarray
    history: list = field(default_factory=list)
    state: object = None


class LineBVP3DSolver(LineSolver):
    """The solver of one line in space: the strategy of the module docstring over a `Scene3D`;
    ``fallback(solver)`` tried where it fails (`LineSolver.fallback`)."""

    def __init__(self, scene, fallback=None):
        self.scene, self.fallback = scene, fallback
        self.budget = Budget(time_limit=getattr(scene, "time_limit", 60.0))
        #: the nodes every mesh keeps (joints, point loads)
        self.fixed = fixed_nodes(scene.joints, scene.point_loads)
        #: the Newton options of every solve (the scene's: `solve_line_bvp_3d`'s ``options``)
        self.options = scene.options
        #: the end of the slack stretch the problems are built with (m; 0: none; `slackened`)
        self.slack_end = 0.0

    name = "solve_line_bvp_3d"

    @property
    def graded_first(self) -> bool:
        """Whether the line is solved on meshes graded by the start and the line first (module
        docstring, 1): on a seabed, with ``fit_touchdown`` and ``mesh="graded"`` (a start clear
        of the seabed is no sign: clump weights can take the line down to it)."""
        sc = self.scene
        return sc.seabed is not None and sc.fit_touchdown > 0 and sc.mesh == "graded"

    @property
    def fits_touchdown(self) -> bool:
        """Whether nodes are fitted at the touchdown and the landing: on a seabed, with
        ``fit_touchdown`` passes (module docstring, 5)."""
        return self.scene.seabed is not None and self.scene.fit_touchdown > 0

    def problem(self, n, fitted=(), load_factor=1.0, nodes_at=None, slack_end=None) -> LineProblem3D:
        """The discrete line on ``n`` elements (on the mesh ``nodes_at`` where given), nodes at
        ``fitted``, the drag and the point loads times ``load_factor``, its slack stretch laid
        up to ``slack_end`` (by default the solver's `slack_end`)."""
        s0 = self.slack_end if slack_end is None else slack_end
        return LineProblem3D(
            self.scene, n, fitted=fitted, nodes_at=nodes_at, load_factor=load_factor, slack_end=s0
        )

    #: what a solve gives (`LineSolver.run`)
    result = Solved
    #: the closed-form starts (`LineSolver.starts`)
    start_forms = closed_forms

    def solve(self, start: LineBVP3DSolution | None = None) -> LineBVP3DSolution:
        """The line (module docstring); from ``start`` (a solution of the same line at other
        ends, moved to these) where given, from scratch where that fails; within the budget."""
        return self.bounded(self.unbounded, start)

    def kept(self, solved) -> LineBVP3DSolution:
        """``solved`` as the solution a failure keeps (`LineSolver.bounded`), not checked."""
        return LineBVP3DSolution(solved.problem, solved.dofs, solved.history, solved.state)

    def unbounded(self, start: LineBVP3DSolution | None = None) -> LineBVP3DSolution:
        """`solve` without the budget's conversion; where the strategy fails, the line by the
        ``fallback`` (module docstring, 7); a failure with friction and the anchor above the
        seabed diagnosed (`with_diagnosis`)."""
        try:
            return self.strategy(start)
        except ConvergenceError as failed:
            solution, note = self.from_fallback()
            if solution is None:
                raise self.failed_with(failed, note) from None
            return solution

    def strategy(self, start: LineBVP3DSolution | None = None) -> LineBVP3DSolution:
        """The strategy of the module docstring, from ``start`` where given."""
        fit = self.fits_touchdown
        n, solved = self.scene.n_elements, None
        if self.graded_first:  # graded by the start, then by the line (module docstring, 1)
            try:
                first = self.from_graded_start(n, start=start)
                solved = self.graded(first, or_from_start=start is not None)
            except ConvergenceError:
                solved = None
        elif start is not None:
            try:
                solved = self.run(*self.warm(start), near=True)
            except ConvergenceError:
                solved = None
        if solved is None or (self.graded_first and self.compressed(solved)):
            kept = solved  # a line in compression on the graded meshes, for the checks' verdict
            try:
                solved = self.graded(self.level(n), or_from_start=not self.graded_first)
            except ConvergenceError:
                if kept is None:
                    raise
            if kept is not None and (solved is kept or self.compressed(solved)):
                solved = kept
        if fit:
            solved = self.fitted(solved)
        solved = self.slackened(solved)
        if self.compressed(solved):  # a node at the touchdown left a bend in one element: graded, refitted
            solved = self.graded(solved, or_from_start=not self.graded_first)
            solved = self.fitted(solved) if fit else solved
            solved = self.slackened(solved)  # its stretch's end, on the new mesh
        return self.checked(solved)

    def held_by_friction(self, solved) -> bool:
        """Whether ``solved`` (friction fully mobilised along the seabed) is in compression on the
        seabed from the anchor where friction can hold a slack stretch instead: the seabed rising
        from the anchor no more steeply than friction holds (``tan α ≤ μ``; steeper,
        `skcable.mooring.line_bvp.check.refuse_sliding` refuses the scene)."""
        friction = self.scene.friction
        if not (friction > 0 and solved.problem.anchor_on_seabed and solved.problem.slack_end == 0):
            return False
        slope = solved.problem.sliding_to_anchor(solved.dofs, self.tolerance)
        return slope is not None and slope <= friction + SLOPE_TOL

    def compressed(self, solved) -> bool:
        """`LineSolver.compressed`, but for a line whose compression friction holds as a slack
        stretch (`held_by_friction`: its mesh is not at fault; `slackened` lays the stretch)."""
        return super().compressed(solved) and not self.held_by_friction(solved)

    def slackened(self, solved) -> Solved:
        """``solved`` with its slack stretch near the anchor (J.M. Jonkman, "Dynamics modeling and
        loads analysis of an offshore floating wind turbine", NREL, 2007), where friction fully
        mobilised would take more than the pull (`held_by_friction`), or where ``solved`` has one
        (the plane line's, in space by the fallback; a line graded again): the stretch laid on the
        seabed up to ``s0``
        (`skcable.mooring.line_bvp.space.problem.LineProblem3D.lay_slack`) and ``s0`` moved, as
        the plane line's (`skcable.mooring.line_bvp.slack`): first where the fully mobilised
        line's tension rises through zero (`tension_zero`), then by Newton steps on the tension
        just past it (`slack_tension`, slope ``μ w``), secant steps once two are known, kept in
        the bracket of those tried (`next_slack_end`), until that tension is zero to the solve's
        tolerance of the force scale; the touchdown refitted at each pass. ``solved`` as it is
        where friction holds no stretch."""
        s0 = solved.problem.slack_end
        if s0 == 0:
            if not self.held_by_friction(solved):
                return solved
            s0 = tension_zero(self.kept(solved), 1e3 * self.tolerance * solved.problem.load_scale)
            self.refuse_across(solved, s0)
        placed, tried = list(solved.problem.fitted), []
        for _ in range(SLACK_PASSES + self.scene.fit_touchdown):
            self.refuse_buoy(s0, solved.problem)
            self.slack_end = s0
            try:
                solved = self.refit(solved, placed)
            except ConvergenceError as failed:
                failed.args = (f"{failed} (with the slack stretch near the anchor laid up to {s0:.6g} m)",)
                raise
            line = self.kept(solved)
            if s0 == 0:  # the tension stays positive down to the anchor: no stretch after all
                return solved
            moved = False
            if self.fits_touchdown:
                placed, moved, _ = self.moved_edges(solved, placed)
            g, slope = slack_tension(line)
            tol = self.tolerance * solved.problem.load_scale
            if abs(g) <= tol and not moved:
                return solved
            if abs(g) > tol:
                tried.append((s0, g))
                s0 = secant_slack_end(tried, slope, line.s_touchdown)
        clump = self.clump_at_slack_end(solved, tried, placed)
        if clump is not None:
            raise InputError(
                self.load_name(clump),
                f"the slack stretch near the anchor ends at the point load at s = {clump:.6g} m, which "
                "rests on the seabed with its friction only partly mobilised: this BVP does not model "
                "that state (mooring.Line solves it in closed form)",
            )
        past = (
            f"tension {tried[-1][1]:.3g} N past it after {len(tried)} updates"
            if tried
            else "its touchdown moving"
        )
        raise ConvergenceError(
            f"{self.name}: the end of the slack stretch near the anchor was not found ({past})",
            solved.history,
        )

    def clump_at_slack_end(self, solved, tried, placed) -> float | None:
        """The arc length (m) of a clump weight where the slack stretch ends, or None: the tension
        past the stretch's end negative for every end tried before it, positive with the end just
        past it (the clump laid with the stretch), or the clump at the touchdown. A clump on the
        seabed can end the stretch itself, its friction only partly mobilised (the plane line's
        `skcable.mooring.line_bvp.driver.LineBVPSolver.clump_at_slack_end`): the tension past the
        end then has no zero, and the passes cannot settle."""
        below = max((s0 for s0, g in tried if g < 0), default=0.0)
        step, s_td = 1e-6 * solved.problem.L, self.kept(solved).s_touchdown
        for s, P in self.scene.point_loads:
            if not (P > 0 and below < s <= s_td + step):
                continue
            if s >= s_td - step:  # the clump at the touchdown: past it the line hangs, in tension
                return float(s)
            self.slack_end = s + step
            try:
                past = self.kept(self.refit(solved, placed))
            except ConvergenceError:
                continue
            if slack_tension(past)[0] > 0:
                return float(s)
        return None

    def load_name(self, s) -> str:
        """The argument that gave the point load at arc length ``s``: ``"attachments"`` (at a
        joint) or ``"point_loads"``."""
        joints = self.scene.joints
        return "attachments" if any(s == joints[j] for j, _ in self.scene.attachments) else "point_loads"

    def warm(self, start: LineBVP3DSolution) -> tuple[LineProblem3D, np.ndarray]:
        """The problem and the first iterate of a warm start on the uniform mesh (module
        docstring, 2–4): ``start``'s line moved (`moved`), on ``start``'s mesh with nodes at the
        touchdown and the landing of the moved line (the balance of
        `skcable.mooring.line_bvp.fitting` on it, its supports' reactions moved with it), else at
        ``start``'s."""
        z, points = self.moved(start), list(start.problem.fitted)
        if points and self.scene.fit_touchdown:
            try:
                guess = self.edges(Solved(start.problem, z, [], start.problem.assemble(z)))
            except (OffGrid, ConvergenceError):  # off the seabed's grid, or no balance: the start's nodes
                guess = []
            points = guess if len(guess) == len(points) else points
        problem = self.problem(self.scene.n_elements, points, nodes_at=start.problem.nodes_at)
        if not np.array_equal(problem.mesh.p, start.problem.mesh.p):  # other fitted nodes, a slack end
            z = restart(start.problem, z, problem)
        return problem, z

    def moved(self, start: LineBVP3DSolution) -> np.ndarray:
        """``start``'s line on its mesh, moved to the new ends: along its tangent ``∂z/∂r_B``
        (`LineBVP3DSolution.sensitivity`, the active set held) for the fairlead's move, in
        proportion to the arc length for the anchor's."""
        problem, anchor, fairlead = start.problem, self.scene.anchor, self.scene.fairlead
        move_a, move_b = anchor - start.anchor, fairlead - start.fairlead
        z = start.dofs + start.sensitivity[2] @ move_b if np.any(move_b) else start.dofs.copy()
        N, share = problem.N, problem.basis.doflocs[0] / problem.L
        for k, (end_a, end_b) in enumerate(zip(anchor, fairlead, strict=True)):
            z[k * N : (k + 1) * N] += move_a[k] * (1.0 - share)
            z[k * N + problem.end_a], z[k * N + problem.end_b] = end_a, end_b
        return z

    def level(self, n, fitted=()) -> Solved:
        """The line on ``n`` elements from the closed-form starts, by steps of the current, on
        nested meshes (`on_mesh`), or (without the graded meshes first, `graded_first`) on a mesh
        graded by the start (module docstring, 2–4)."""
        problem, attempts = self.on_mesh(n, fitted)
        if problem.contact_rows is not None and not self.graded_first:  # else tried before (`strategy`)
            attempts.append(lambda: self.from_graded_start(n, fitted))
        return first_converged(attempts)

    def on_mesh(self, n, fitted=(), mesh=None) -> tuple[LineProblem3D, list]:
        """``(problem, attempts)``: the line on ``mesh(n)`` (the uniform mesh by default) from
        its closed-form starts (`from_starts`) and, above ``2·COARSE`` elements, on the nested
        meshes ``mesh(size)`` (`nested`; first where the start touches the seabed: the active set
        moves by a few nodes per Newton iteration, so a fine mesh does not find its contact set
        from the start), in turn."""
        mesh = mesh or (lambda size: self.problem(size, fitted))
        problem = mesh(n)
        z0 = closed_form_start(problem)
        attempts = [lambda: first_converged(self.from_starts(problem, n, fitted, z0))]
        if n > 2 * COARSE:
            attempts.insert(0 if self.touches(problem, z0) else 1, lambda: self.nested(n, fitted, mesh))
        return problem, attempts

    def from_starts(self, problem, size, fitted, z0) -> list:
        """The solves of ``problem`` (on ``size`` elements, nodes at ``fitted``) from its
        closed-form starts (`starts`), then, where the line has terms or point loads, by steps of
        the current and the point loads (`LineSolver.continued`), in turn."""
        attempts = self.starts(problem, z0)
        if problem.terms or self.scene.point_loads:
            attempts.append(lambda: self.continued(size, fitted, z0, nodes_at=problem.nodes_at))
        return attempts

    def nested(self, n, fitted, mesh) -> Solved:
        """Nested meshes ``mesh(size)`` (nodes at ``fitted``) up to ``n`` elements (module
        docstring, 4; `solve_nested`): each from the coarser one interpolated, else from its
        closed-form starts (`from_starts`)."""

        def level(size, coarser):
            problem = mesh(size)
            if coarser is not None:
                return self.run(problem, restart(coarser.problem, coarser.dofs, problem))
            return first_converged(self.from_starts(problem, size, fitted, closed_form_start(problem)))

        return solve_nested(n, level)

    def fitted(self, solved) -> Solved:
        """Nodes at the touchdown and the landing, moved until they settle (module docstring, 5):
        from the nodes ``solved``'s mesh has, none left where the line no longer touches."""
        placed = list(solved.problem.fitted)
        for _ in range(self.scene.fit_touchdown):
            try:
                placed, moved, _ = self.moved_edges(solved, placed)
            except ConvergenceError:  # no balance near the contact edge: the checks say why (a
                break  # line in compression, a slack stretch) or refuse it (`LineFields.check`)
            if not moved:
                break
            solved = self.refit(solved, placed)
        return solved

    def refit(self, solved, points) -> Solved:
        """The line with nodes at ``points`` on ``solved``'s mesh (graded or uniform), from
        ``solved`` interpolated, else from the closed-form starts on that mesh, else (a graded
        mesh's last resort) from scratch on the uniform mesh."""
        n = self.scene.n_elements
        problem = self.problem(n, points, nodes_at=solved.problem.nodes_at)
        return first_converged(
            [
                lambda: self.run(problem, restart(solved.problem, solved.dofs, problem), near=True),
                lambda: first_converged(self.starts(problem)),
                lambda: self.level(n, points),
            ]
        )

    def graded(self, solved, or_from_start=True) -> Solved:
        """Where ``solved`` is in compression (its mesh does not resolve its bends) or on a mesh
        graded by its start (`from_graded_start`, whose elements are graded for the start's
        shape, not the line's): the line on meshes graded by its turning, pass by pass, as the
        plane line's (module docstring, 1; `skcable.mooring.line_bvp.mesh.grading_passes`), from
        ``solved``, else (``or_from_start``: where ``solved`` is not that mesh's cold solve) from
        the mesh graded by the start, else (with buoys, without friction) from ``solved`` without
        nodes at the buoys' arch ends (`skcable.mooring.line_bvp.mesh.arch_ends`: a clump just
        past an arch's end bends the line there to a radius of centimetres, scene 2:136 of the
        survey); ``solved`` as it is where all fail (the check then refuses it in compression)."""
        if not (self.compressed(solved) or solved.problem.nodes_at is not None):
            return solved
        n = self.scene.n_elements

        def resolve(nodes, last):
            problem = self.problem(n, last.problem.fitted, nodes_at=nodes)
            return self.run(problem, restart(last.problem, last.dofs, problem), near=True)

        def passes(first, arches=self.arches):
            last = grading_passes(first, n, self.fixed, resolve, self.compressed, True, arches)[0]
            if self.compressed(last):
                raise ConvergenceError("solve_line_bvp_3d: in compression on every graded mesh", last.history)
            return last

        alternatives = [lambda: passes(solved)]
        if or_from_start:
            alternatives.append(lambda: passes(self.from_graded_start(n)))
        if self.arches and any(P < 0 for _, P in self.scene.point_loads):
            alternatives.append(lambda: passes(solved, arches=False))
        try:
            return first_converged(alternatives)
        except ConvergenceError:
            return solved

    def from_graded_start(self, n, fitted=(), start: LineBVP3DSolution | None = None) -> Solved:
        """The line on a mesh graded by the closed-form start's turning (the plane line's first
        mesh; `skcable.mooring.line_bvp.mesh.graded_nodes` of the start on the uniform mesh), its
        elements at most `REFINEMENT` times finer than the uniform mesh's, else ``REFINEMENT²``
        times: the uniform mesh of a line that lands on the seabed from an anchor above it leaves
        the bend of the landing in one or two elements, and its solve ends in compression or
        fails. On that mesh: from a warm ``start`` (a solution at other ends) moved (`moved`)
        where given; from the closed-form starts (`starts`); by steps of the current where the
        line has terms (`continued`); above ``2·COARSE`` elements, by nested meshes each graded
        by the start (`skcable.mooring.line_bvp.mesh.solve_nested`; first where the start touches
        the seabed: the active set moves by a few nodes per Newton iteration). The mesh depends
        on the ends alone, whichever of these solves it."""

        def graded_problem(size, refinement):
            uniform = self.problem(size, fitted)
            z0 = closed_form_start(uniform)  # not an equilibrium: no arches of buoys
            nodes = graded_nodes(uniform, z0, size, self.fixed, refinement, arches=False)[0]
            return self.problem(size, fitted, nodes_at=nodes)

        moved = None if start is None else self.moved(start)

        def graded_by_start(refinement):
            problem, attempts = self.on_mesh(n, fitted, cache(partial(graded_problem, refinement=refinement)))
            if start is not None:
                attempts.insert(
                    0, lambda: self.run(problem, restart(start.problem, moved, problem), near=True)
                )
            return first_converged(attempts)

        return first_converged([lambda: graded_by_start(REFINEMENT), lambda: graded_by_start(REFINEMENT**2)])

    def checked(self, solved) -> LineBVP3DSolution:
        """The solution, once its checks hold (module docstring, 6)."""
        problem, z = solved.problem, solved.dofs
        if not (np.all(np.isfinite(z)) and np.all(np.isfinite(solved.state.R0))):
            raise ConvergenceError("solve_line_bvp_3d: non-finite result", solved.history)
        self.refuse_compressed(solved, self.friction_reason(solved))
        solution = LineBVP3DSolution(problem, z, solved.history, solved.state)
        solution.check()
        if problem.slack_end > 0:  # where the stretch ended up: no load across, held by friction
            self.refuse_buoy(problem.slack_end, problem)
            g = slack_tension(solution)[0]
            if not abs(g) <= self.tolerance * problem.load_scale:
                raise ConvergenceError(
                    f"{self.name}: the tension past the slack stretch near the anchor is {g:.3g} N, not "
                    "zero, on the line's final mesh",
                    solved.history,
                )
            self.refuse_across(solved, problem.slack_end)
            self.refuse_sliding_stretch(solution)
        return solution

    def refuse_buoy(self, s0, problem) -> None:
        """``InputError`` naming ``attachments`` or ``point_loads`` where a buoy lies on a slack
        stretch ending at ``s0`` or within the line it lifts past it
        (`skcable.mooring.line_bvp.slack.buoy_on_stretch`): checked at every end the passes try,
        so that no mesh gets to lift it (a Newton that stagnates on the lifted bight would hide
        the reason)."""
        buoy = buoy_on_stretch(self.scene.point_loads, s0, problem.weight_at)
        if buoy is not None:
            raise InputError(self.load_name(buoy), BUOY_ON_STRETCH.format(s=buoy))

    def friction_reason(self, solved) -> str:
        """Why a line with friction on a seabed is in compression, where friction is the reason
        (`LineSolver.refuse_compressed`; else "", its mesh): with the anchor above the seabed,
        friction partly mobilised may hold it (the plane line's reason); from an anchor on the
        seabed, where no slack stretch was laid (`slackened`: its compression leaves the seabed,
        or the line rises vertically from the anchor)."""
        problem, z = solved.problem, solved.dofs
        if not (self.scene.friction > 0 and problem.seabed is not None):
            return ""
        if not problem.anchor_on_seabed:
            return "fully mobilised friction with the anchor above the seabed"
        if problem.slack_end == 0 and problem.in_compression(z, self.tolerance)[0]:
            return (
                "fully mobilised friction takes more than the pull near the anchor, where no slack "
                "stretch lies on the seabed along the line (its compression leaves the seabed, or the "
                "line rises vertically from the anchor)"
            )
        return ""

    def refuse_across(self, solved, s0) -> None:
        """``InputError`` where the line's load across it, in the seabed's plane, at the end
        ``s0`` of its slack stretch exceeds `ACROSS` times the friction ``μ w`` there: a current
        across the line (``"current"``; ``"terms"`` for the analyst's), or the seabed sloping
        across it (``"seabed"``, the weight's share).

        The contact rows' friction acts along the line only, so the tension holds the load across
        a grounded line, ``T κ = q``; past the stretch's end the tension grows from zero
        (``T ≈ μ w (s - s0)``), and the line would turn through ``(q/μw) ln(s - s0)``: no solution,
        and the discrete lines' answers drift with the mesh (a chain in a 0.2 m/s current across
        it, ``q/μw`` = 1.5 %: its fairlead force across the chord moved 0.3 % between 64 and 512
        elements; in a current along the line its end forces moved 5.7e-9 between 64 and 256,
        as a line's without current do: `tests/mooring/test_line3d_slack.py`)."""
        problem, z = solved.problem, solved.dofs
        s = np.array([min(s0 + 1e-6 * problem.L, problem.L)])
        state = problem.state_at(z, s)
        t = state.a[:, 0] / np.linalg.norm(state.a[:, 0])
        r = state.position[:, 0]
        normal = np.array([*(-np.asarray(problem.seabed.gradient(r[0], r[1]), dtype=float).ravel()), 1.0])
        across = np.cross(normal, t)
        across /= np.linalg.norm(across)
        w = float(problem.weight_at(s)[0])
        across_of = {"seabed": -w * float(across[2])}  # the weight's share: a seabed sloping across
        for term in problem.terms:  # the current's drag, the analyst's terms (N/m)
            f = term_load([term], state.position, state.s, state.a, state.T).f[:, 0]
            name = "current" if isinstance(term, SegmentDrag) else "terms"
            across_of[name] = across_of.get(name, 0.0) + float(f @ across)
        bound = ACROSS * self.scene.friction * w
        total = abs(sum(across_of.values()))  # what the tension would hold: the net load across
        if total <= bound:
            return
        name = max(across_of, key=lambda key: abs(across_of[key]))  # the largest part names it
        raise InputError(
            name,
            f"loads the line across it by {total:.3g} N/m ({total / (self.scene.friction * w):.2g} of μw) "
            f"where friction holds a slack stretch near the anchor (its end at {s0:.6g} m): the 3-D "
            "line's friction acts along the line only, and its tension, zero at the stretch's end, "
            "cannot hold a load across it (a current along the line, or a seabed that does not slope "
            "across it, can be solved)",
        )

    def refuse_sliding_stretch(self, solution) -> None:
        """``InputError("friction")`` where friction cannot hold the slack stretch: at a node of
        it (the anchor's included) the seabed's force along the seabed exceeds ``μ`` times its
        force across it (a seabed sloping down from the anchor more steeply than friction holds,
        a current's drag), beyond the solve's tolerance of the force scale."""
        problem, R0 = solution.problem, solution.state.R0
        N, nodes = problem.N, np.append(problem.laid_nodes, problem.end_a)
        force = np.array([R0[k * N + nodes] for k in range(3)])  # the seabed's force on each node
        r = solution.dofs[: 3 * N].reshape(3, N)[:, nodes]
        normal = np.vstack([-problem.seabed.gradient(r[0], r[1]), np.ones(nodes.size)])
        normal /= np.sqrt(np.sum(normal * normal, axis=0))
        pressing = np.sum(force * normal, axis=0)
        along = np.sqrt(np.sum((force - pressing * normal) ** 2, axis=0))
        tol = self.tolerance * problem.load_scale
        if np.any(pressing < -tol):  # buoyant, or lifted by a term: no tension holds it down
            k = int(np.argmin(pressing))
            s = float(problem.basis.doflocs[0][nodes[k]])
            name = "segments" if float(problem.weight_at(np.array([s]))[0]) < 0 else "terms"
            raise InputError(
                name,
                f"lift the slack stretch near the anchor off the seabed at s = {s:.6g} m (no tension "
                "holds it down there; the line in space lays it on the seabed)",
            )
        if np.any(along > self.scene.friction * pressing + tol):
            raise InputError(
                "friction",
                f"too weak to hold the slack stretch near the anchor (the seabed's force along it "
                f"reaches {float(np.max(along - self.scene.friction * pressing)):.3g} N more than μN at a "
                "node): the line would slide",
            )
