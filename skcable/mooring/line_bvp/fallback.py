r"""Each line BVP solver's fallback on the other, for a line that hangs in the vertical plane of its ends.

The plane line (`skcable.mooring.line_bvp.driver.LineBVPSolver`) and the line in space
(`skcable.mooring.line_bvp.space.driver.LineBVP3DSolver`) discretise the same equations
(`skcable.mooring.line_bvp.discrete.DiscreteLine`) on meshes graded alike, but reach them by
different strategies (the plane line: nested levels, friction's slack stretch; the line in
space: its starts, the current and point loads by steps, the uniform mesh where the graded ones fail). Where
one fails on a line that hangs in the vertical plane of its ends, the other's strategy is run
within what is left of the budget; its line, mapped onto the first solver's dofs on the same
mesh, is a discrete solution of the first solver's problem up to round-off, so one Newton
(a step or two) takes it there, and the first solver grades, fits and checks it as its own:

- `plane_for_space`: a line in space without current or cable terms, on no seabed or a `Plane`
  sloping along its chord, with constant stiffnesses
  (`skcable.mooring.line_bvp.space.vertical_plane.plane_scene`), by the plane line;
- `space_for_plane`: a plane line without cable terms (they act in the plane's own axes), by the
  line in space over its seabed's profile, the same across the plane (`space_scene`).

The models set them (`skcable.mooring.line_bvp.model`, `skcable.mooring.line_bvp.space.model`):
``LineSolver.fallback`` is the extension point, a callable of the failed solver. The solver run
as a fallback has none itself. In the differential survey of the two
(``benchmarks/line_bvp_planes.py``) the line in space solves scenes 2:191 and 3:34 this way, and
the plane line the scenes only the line in space solved before (its table says which).
"""

from __future__ import annotations

from functools import partial

import numpy as np

from skcable.errors import ConvergenceError, InputError
from skcable.fe import first_converged
from skcable.mooring.bathymetry import Bathymetry, DepthFunction, Plane
from skcable.mooring.line_bvp.contact import Seabed
from skcable.mooring.line_bvp.driver import LineBVPSolver
from skcable.mooring.line_bvp.inputs import Scene
from skcable.mooring.line_bvp.space.driver import LineBVP3DSolver
from skcable.mooring.line_bvp.space.inputs import Scene3D
from skcable.mooring.line_bvp.space.solution import LineBVP3DSolution
from skcable.mooring.line_bvp.space.vertical_plane import in_space, plane_of, plane_scene

__all__ = [
    "in_plane",
    "plane_for_space",
    "plane_meshes",
    "profile_in_space",
    "space_for_plane",
    "space_scene",
]

#: the water's density of a line in space without current (read by no load)
_NO_CURRENT_RHO = 1025.0


def _by_the_other(solver, scene_of, other, failing: str):
    """The other strategy's solution (its solver ``other`` over ``scene_of(solver.scene,
    seconds left)``, with no fallback of its own), or None where it does not take the scene or no
    time is left; a `ConvergenceError` saying ``failing`` and why where it fails."""
    left = solver.budget.left()
    scene = scene_of(solver.scene, left) if left > 0 else None
    if scene is None:
        return None
    try:
        return other(scene).solve()
    except (ConvergenceError, InputError) as failed:
        raise _other_failed(failed, failing) from None


def _plane_scene_of(scene: Scene3D, time_limit: float) -> Scene | None:
    """`plane_scene` where the plane line's meshes are the scene's (`plane_meshes`), else None."""
    return plane_scene(scene, time_limit) if plane_meshes(scene) else None


def _other_failed(failed: Exception, what: str) -> ConvergenceError:
    reason = str(failed.args[0]).split("; error.last")[0]
    history = getattr(failed, "history", [])
    return ConvergenceError(f"in the vertical plane of its ends {what} ({reason})", history)


def plane_for_space(solver: LineBVP3DSolver) -> LineBVP3DSolution | None:
    """The line in space of ``solver`` that hangs in the vertical plane of its ends (module
    docstring), solved by the plane line's strategy within what is left of the budget, then in
    space on that mesh from it, fitted and checked; None where the line does not hang in that
    plane or asks for meshes the plane line does not make (`plane_meshes`), a `ConvergenceError`
    saying why where that fails (the plane line refusing or failing)."""
    solution = _by_the_other(solver, _plane_scene_of, LineBVPSolver, "the plane line's strategy failed too")
    if solution is None:
        return None
    old = solution.problem
    nodes = np.sort(old.mesh.p[0])
    solver.slack_end = old.slack_end  # friction's slack stretch, laid as the plane line's ends
    problem = solver.problem(nodes.size - 1, solver.edges_of(solution), nodes_at=nodes)
    try:
        solved = solver.run(problem, in_space(problem, old, solution.dofs), near=True)
        return solver.checked(solver.slackened(solver.fitted(solved)))  # no pass without fit_touchdown
    except ConvergenceError as failed:
        raise _other_failed(failed, "the plane line solved it, but not the line in space from it") from None


def plane_meshes(scene: Scene3D) -> bool:
    """Whether the plane line's meshes are ``scene``'s (`plane_for_space`): uniform without
    fitting, graded on a seabed with ``mesh="graded"``; not where the scene asks for uniform
    meshes, on a seabed (``mesh="uniform"``) or without one, with a fitted touchdown (the plane
    line grades its meshes by the start there)."""
    return scene.fit_touchdown == 0 or (scene.seabed is not None and scene.mesh == "graded")


def space_for_plane(solver: LineBVPSolver):
    """The plane line of ``solver`` (module docstring) solved by the line in space's strategy
    within what is left of the budget (`space_scene`), then in the plane on that mesh from it
    (`in_plane`: its mesh graded alike and fitted at its touchdown and landing by the same
    balance) and checked, else graded, fitted and checked as a level of the plane line from it
    (`LineBVPSolver.level`); None where the line in space does not take the scene, a
    `ConvergenceError` saying why where that fails."""
    solution = _by_the_other(solver, space_scene, LineBVP3DSolver, "the line in space's strategy failed too")
    if solution is None:
        return None
    old = solution.problem
    nodes = np.sort(old.mesh.p[0])
    s0 = old.slack_end  # friction's slack stretch, the plane line's node at its end too
    fitted = [*old.fitted, s0] if s0 > 0 else list(old.fitted)
    problem = solver.problem(nodes.size - 1, fitted, s0, nodes_at=nodes)
    try:
        first = solver.run(problem, in_plane(problem, old, solution.dofs), near=True)
        regraded = partial(solver.level, solver.scene.n_elements, first)
        return first_converged([lambda: solver.checked(first), lambda: solver.checked(regraded())])
    except ConvergenceError as failed:
        raise _other_failed(failed, "the line in space solved it, but not the plane line from it") from None


def space_scene(scene: Scene, time_limit: float) -> Scene3D | None:
    """The line in space of the plane line's ``scene``, solved within ``time_limit`` (s): from
    ``(0, 0, 0)`` to ``(span, 0, dh)``, its seabed the plane line's profile ``b(x)``, the same
    across the plane (a `Plane` where it is flat or straight, ``Seabed.straight``; else a
    `DepthFunction` of its height, slope and curvature, `profile_in_space`), its point loads by
    arc length, graded meshes (the plane line's); None where it has cable terms (they act in the
    plane's own axes)."""
    bed = scene.seabed
    if scene.terms:
        return None
    seabed: Bathymetry | None
    if bed is None:
        seabed = None
    elif bed.straight is not None:
        seabed = Plane(float(bed.straight[0]), (float(bed.straight[1]), 0.0))
    else:
        seabed = profile_in_space(bed)
    return Scene3D(
        anchor=np.zeros(3),
        fairlead=np.array([scene.span, 0.0, scene.dh]),
        segments=list(scene.segments),
        attachments=[],
        loads=list(scene.point_loads),
        seabed=seabed,
        friction=scene.friction,
        current=None,
        rho_water=_NO_CURRENT_RHO,
        terms=(),
        n_elements=scene.n_elements,
        fit_touchdown=scene.fit_touchdown,
        mesh="graded",
        options=scene.options,
        time_limit=time_limit,
    )


def profile_in_space(bed: Seabed) -> DepthFunction:
    """The plane line's seabed ``b(x)`` as the seabed ``b(x, y) = b(x)`` in space: its gradient
    ``(b', 0)``, its Hessian ``((b'', 0), (0, 0))`` (`Seabed.slope`, `Seabed.curvature`)."""

    def height(x, y):
        return np.broadcast_to(bed(np.asarray(x)), np.broadcast_shapes(np.shape(x), np.shape(y)))

    def gradient(x, y):
        slope = np.broadcast_to(bed.slope(np.asarray(x)), np.broadcast_shapes(np.shape(x), np.shape(y)))
        return slope, np.zeros_like(slope)

    def hessian(x, y):
        curvature = np.broadcast_to(
            bed.curvature(np.asarray(x)), np.broadcast_shapes(np.shape(x), np.shape(y))
        )
        zero = np.zeros_like(curvature)
        return (curvature, zero), (zero, zero)

    return DepthFunction(height, gradient, hessian)


def in_plane(problem, old, z) -> np.ndarray:
    """The dofs ``z`` of ``old``, a line in space that hangs in the vertical plane of its ends, on
    ``problem``'s dofs (the plane line on the same mesh): ``x = (r − a)·e``, ``y = z − a_z`` at its
    nodes, tensions just inside its elements, the ends exact (the mirror of
    `skcable.mooring.line_bvp.space.vertical_plane.in_space`)."""
    a, (_, e, _) = old.anchor, plane_of(old.anchor, old.fairlead)
    position = old.state_at(z, problem.basis.doflocs[0]).position
    x = (position[0] - a[0]) * e[0] + (position[1] - a[1]) * e[1]
    return problem.with_ends([x, position[2] - a[2]], old.tension_at(z, problem.tension_points()))
