"""What the two line BVP drivers share: one solve, the alternative solves, the compression test
and refusal, and the friction diagnosis of a failure.

`LineSolver` is the base of `skcable.mooring.line_bvp.driver.LineBVPSolver` (the plane line) and
`skcable.mooring.line_bvp.space.driver.LineBVP3DSolver` (the line in space). Each driver gives its
scene (``friction``, a dataclass), its Newton options (`skcable.fe.NewtonOptions`), its time
budget (`skcable._budget.Budget`), its ``problem(n)`` on ``n`` elements, its closed forms
``start_forms`` (a module), the type of a solve's ``result`` and its strategy ``unbounded()``;
the base gives the rest once: its one solve ``run(problem, z0)`` and the list of solves from the
closed-form starts, ``starts(problem)``, among them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from functools import cache, partial
from types import ModuleType
from typing import Any

import numpy as np

from skcable._budget import Budget
from skcable.errors import ConvergenceError, ResolutionError
from skcable.fe import NewtonOptions
from skcable.mooring.line_bvp.check import partial_friction, refuse_sliding, slack_on_slope
from skcable.mooring.line_bvp.iterate import solve_on
from skcable.mooring.line_bvp.mesh import COARSE

__all__ = ["SMALLEST_STEP", "LineSolver"]

#: the smallest step of the loads' continuation (`LineSolver.continued`)
SMALLEST_STEP = 1.0 / 64.0


class LineSolver:
    """The mechanisms both line BVP drivers share (module docstring)."""

    #: the public entry's name, in messages
    name = "solve_line_bvp"
    #: the type of a solve's result, built from ``(problem, dofs, history, state)``
    result: Callable[..., Any]
    #: the closed-form starts of the driver's line: its ``closed_form_start``, ``lifted_start``,
    #: ``segmented_start`` and ``on_slope`` (`skcable.mooring.line_bvp.start`,
    #: `skcable.mooring.line_bvp.space.start`)
    start_forms: ModuleType
    scene: Any
    budget: Budget
    options: NewtonOptions
    #: the other solver's strategy, tried where this one's fails
    #: (`skcable.mooring.line_bvp.fallback`): ``fallback(solver)`` gives the line checked, None
    #: where it does not take the scene, or a `ConvergenceError` saying why it failed; None: none
    fallback: Callable[[Any], Any] | None = None

    def __init__(self, scene):
        """Each driver sets up its own (its scene, budget and meshes)."""
        raise NotImplementedError

    @property
    def tolerance(self) -> float:
        """Newton's tolerance on the scaled residual (``options.tol``)."""
        return self.options.tol

    @property
    def arches(self) -> bool:
        """Whether the meshes graded by the line take nodes at the ends of the arches buoys lift
        off the seabed (`skcable.mooring.line_bvp.mesh.arch_ends`): without friction only (with
        friction, a buoy can lie in the slack stretch it holds, where the line's tension is zero
        and no arch ``|P|/w`` long stands; a mesh with nodes there left the plane line's stage with
        friction stagnating in the differential survey, its scene 1:159)."""
        return self.scene.friction == 0

    @staticmethod
    def touches(problem, z0) -> bool:
        """Whether ``z0``, ``problem``'s closed-form start, touches its seabed (where nested
        meshes go first: the active set moves by a few nodes per Newton iteration)."""
        return bool(np.any(problem.gaps(z0) <= 0))

    def problem(self, n: int, *args, **kwargs):
        """The driver's discrete line on ``n`` elements."""
        raise NotImplementedError

    def anchor_above_seabed(self) -> bool:
        """Whether the scene has a seabed and its anchor lies above it (by 1e-12 of the length:
        ``DiscreteLine.anchor_on_seabed``)."""
        problem = self.problem(COARSE)
        return problem.seabed is not None and not problem.anchor_on_seabed

    def edges(self, solved) -> list[float]:
        """The touchdown and the landing of ``solved`` to put nodes at (m of arc length): its
        solution's (`kept`; `edges_of`)."""
        return self.edges_of(self.kept(solved))

    def edges_of(self, solution) -> list[float]:
        """The ``s_touchdown`` and ``s_landing`` of ``solution`` (either line's), where the
        hanging parts' forces are tangent to the seabed
        (`skcable.mooring.line_bvp.fields.LineFields`); none without fitting or contact."""
        if not (self.scene.fit_touchdown and solution.s_touchdown > 0):
            return []
        return [solution.s_touchdown] + ([solution.s_landing] if solution.s_landing > 0 else [])

    def moved_edges(self, solved, fitted, look=True):
        """The touchdown and landing of ``solved`` (`edges`) where they moved more than 1e-9 of
        the length from the nodes ``fitted`` (and ``look``): ``(fitted, moved, settled)``,
        settled when they moved less than 1e-6 of it (the plane line's tension past its slack
        stretch's end is worth a bracket only then)."""
        if not look:
            return fitted, False, True
        L, edges, moved = solved.problem.L, self.edges(solved), np.inf
        if len(edges) == len(fitted):
            moved = max((abs(a - b) for a, b in zip(edges, fitted, strict=True)), default=0.0)
        if moved > 1e-9 * L:
            return edges, True, moved <= 1e-6 * L
        return fitted, False, True

    def run(self, problem, z0, near: bool = False):
        """One solve of ``problem`` from ``z0`` with the driver's Newton options
        (`skcable.mooring.line_bvp.iterate.solve_on`; ``near``: full steps first), counted
        against the budget, the best solve so far remembered (free of compression, then on the
        finest mesh, then the latest): a ``result`` of the problem, the iterate, its merit
        history and its state."""
        self.budget.spend()
        out = solve_on(problem, z0, self.options, near, name=self.name)
        solved = self.result(problem, out.x, list(out.history), out.state)
        history = solved.history
        # what a failure keeps: free of compression, then the finest mesh, then the latest solve
        rank = (not self.compressed(solved), problem.mesh.t.shape[1], self.budget.calls)
        self.budget.record(history[-1] if len(history) else 0.0, solved, rank)
        return solved

    def bounded(self, stage, *args):
        """``stage(*args)`` within the budget (past it, its `ConvergenceError`); a failure's
        ``last`` is what converged (`kept`, not checked): the budget's best solve, the last on
        the finest mesh of those free of compression (of all, where none is; `run`), None where no
        solve converged (a failed Newton's own iterate means nothing without its mesh); the message
        says so."""
        what = f"{self.name} (the measure: the last merit of a solve)"
        try:
            return self.budget.run(what, "solves", stage, *args)
        except ConvergenceError as failed:
            best = self.budget.best[1]
            failed.last = None
            if best is not None:
                failed.last = kept = self.kept(best)
                elements = kept.problem.mesh.t.shape[1]
                failed.args = (
                    f"{failed}; error.last: the line that converged on {elements} elements (not checked)",
                )
            raise

    def kept(self, solved):
        """``solved`` as the public solution a failure keeps (`bounded`)."""
        return solved

    def unbounded(self):
        """The strategy from scratch, without the budget's conversion."""
        raise NotImplementedError

    def from_start(self, problem, z0):
        """One solve of ``problem`` from ``z0``; a `ConvergenceError` where there is no such
        start (None)."""
        if z0 is None:
            raise ConvergenceError(f"{self.name}: no such closed-form start of this line", [])
        return self.run(problem, z0)

    def starts(self, problem, z0=None) -> list:
        """The solves of ``problem`` from its closed-form starts (``start_forms``), in turn: from
        ``z0`` (by default its ``closed_form_start``); from the segment-wise closed form
        (``segmented_start``, where there is one); from ``z0`` with the contact nodes switching
        by the tension (`switched`, on a seabed); on a straight slope through the anchor
        (``on_slope``), whose ``closed_form_start`` is the line on the slope, or on one below A
        (the line touching down on it), from the uniform line lifted onto it (``lifted_start``:
        the line on the slope can leave Newton no descent, the survey's scene 3:234,
        ``benchmarks/line_bvp_planes.py``), fixed and switching."""
        forms = self.start_forms
        first = cache(partial(forms.closed_form_start, problem)) if z0 is None else (lambda: z0)
        attempts = [
            lambda: self.run(problem, first()),
            lambda: self.from_start(problem, forms.segmented_start(problem)),
            lambda: self.switched(problem, first()),
        ]
        if forms.on_slope(problem):
            lifted = cache(partial(forms.lifted_start, problem))
            attempts += [lambda: self.run(problem, lifted()), lambda: self.switched(problem, lifted())]
        return attempts

    def switched(self, problem, z0):
        """One solve of ``problem`` from ``z0`` with its contact nodes switching by the line's
        tension (`DiscreteLine.with_tension_switch`: a taut line's residual forces at its start
        can exceed the switch of a line bent by its weight); a `ConvergenceError` without
        contact."""
        other = problem.with_tension_switch(z0)
        if other is None:
            raise ConvergenceError(f"{self.name}: no contact rows to switch by tension", [])
        return self.run(other, z0)

    def compressed(self, solved) -> bool:
        """Whether the discrete line of ``solved`` (its ``problem`` and ``dofs``) is in
        compression (`DiscreteLine.compressed`)."""
        return solved.problem.compressed(solved.dofs, self.tolerance)

    def refuse_compressed(self, solved, why: str = "", also: str = "") -> None:
        """Where the discrete line of ``solved`` is in compression (`compressed`): an
        ``InputError("friction")`` where that compression lies on a seabed rising from the
        anchor more steeply than friction holds (no equilibrium in tension,
        `skcable.mooring.line_bvp.check.refuse_sliding`), else a `ConvergenceError` with its
        least tension (and ``also``) and ``why``: by default, its elements do not resolve its
        bends (a `skcable.errors.ResolutionError` then: more elements may solve it)."""
        if not self.compressed(solved):
            return
        problem, z = solved.problem, solved.dofs
        refuse_sliding(problem, z, self.tolerance, self.scene.friction)
        T = z[problem.dim * problem.N :]
        error = ConvergenceError if why else ResolutionError
        why = why or f"{problem.mesh.t.shape[1]} elements do not resolve its bends; give more"
        raise error(
            f"{self.name}: the discrete line is in compression (min T = {np.min(T):.3g} N{also}): {why}",
            solved.history,
        )

    def from_fallback(self) -> tuple[Any, str]:
        """``(solution, note)``: the line by ``fallback`` where this solver's strategy failed, or
        None and a note saying why the fallback failed too ("" where there is none or it does not
        take the scene), which the failure's message ends with (`failed_with`)."""
        if self.fallback is None:
            return None, ""
        try:
            return self.fallback(self), ""
        except ConvergenceError as other:
            return None, str(other)
        except Budget.Spent:  # the other solver took what was left: this failure, not the budget's
            return None, "no time was left for the other line BVP's strategy"

    def failed_with(self, failed: ConvergenceError, note: str) -> ConvergenceError:
        """``failed`` diagnosed (`with_diagnosis`: its diagnosis first, the most a user can act
        on), its message ending with the fallback's ``note`` (`from_fallback`)."""
        diagnosed = self.with_diagnosis(failed)
        if note:
            diagnosed.args = (f"{diagnosed}; {note}",)
        return diagnosed

    def continued(self, n, fitted, z0, nodes_at=None):
        """The loads the driver grows (`problem`'s ``load_factor``: the point loads, and in space
        the current's drag) from zero to their full values in steps, each solve from the last, on
        ``n`` elements with nodes at ``fitted`` (on the mesh ``nodes_at`` where given), from
        ``z0`` without them: a quarter first, halved where a step fails, down to
        `SMALLEST_STEP`. A buoy that lifts an arch off the seabed, or a clump that pulls the line
        down onto it, moves the active set far from any closed form's; grown, it moves it a few
        nodes a step."""
        solved = self.run(self.problem(n, fitted, load_factor=0.0, nodes_at=nodes_at), z0)
        factor, step = 0.0, 0.25
        while factor < 1.0:
            trial = min(1.0, factor + step)
            try:
                problem = self.problem(n, fitted, load_factor=trial, nodes_at=nodes_at)
                solved = self.run(problem, solved.dofs)
                factor = trial
            except ConvergenceError:
                step *= 0.5
                if step < SMALLEST_STEP:
                    raise
        return solved

    def within_budget(self, **changes):
        """A solver of this line with ``changes`` to its scene (`dataclasses.replace`), without a
        fallback, within what is left of this solver's budget, with its own record of solves (a
        failure keeps this line's): the line without friction (`with_diagnosis`), without its point
        loads (`skcable.mooring.line_bvp.driver.LineBVPSolver.loads_by_steps`)."""
        other = type(self)(replace(self.scene, **changes))
        other.budget = Budget(time_limit=self.budget.left())
        return other

    def with_diagnosis(self, failed: ConvergenceError) -> ConvergenceError:
        """``failed``, saying where friction fully mobilised may take more than the line's pull
        with its anchor above the seabed (`skcable.mooring.line_bvp.check.partial_friction`),
        from the same line solved without friction by this driver, within what is left of the
        budget (its own record of solves: the failure's ``last`` stays this line's); without
        friction, where the line over a straight slope below both ends may be longer than it
        holds taut (`skcable.mooring.line_bvp.check.slack_on_slope`)."""
        if self.scene.friction == 0:  # over a slope below both ends: maybe longer than it holds taut
            return slack_on_slope(failed, self.problem(COARSE))
        if not self.anchor_above_seabed():
            return failed
        other = self.within_budget(friction=0.0)

        def frictionless():
            try:
                return other.unbounded()
            except Budget.Spent:
                raise ConvergenceError(
                    f"{self.name}: no time left for the line without friction", []
                ) from None

        return partial_friction(failed, self.scene.friction, frictionless)
