"""A mooring line as an arc-length BVP: segments, w(s), point loads and unilateral seabed contact.

`solve_line_bvp` solves one line from the anchor A = (0, 0) to the fairlead B = (span, dh) in
the arc-length form on the unstretched arc length, positions P2 and tension P1-DG, optionally
on a seabed of any shape with Coulomb friction. One concern per module:

- `inputs`: the segments (`LineSegment`, also `BVPSegment`, the line in space's too), the point
  loads and every argument, checked into a `Scene`;
- `contact`: the seabed and the semismooth (primal–dual active set) contact rows with Coulomb
  friction, one set for the plane line and the line in space;
- `mesh`: uniform, graded (equidistributed turning), fitted and nested meshes;
- `discrete`: what the plane line and the line in space (`space`) write
  once, parametrised by the dimension: the line law (section forces, loads, axial laws, residual
  and tangent: every call of its assembly), mesh, bases, dofs, merit and its round-off floor, the
  generalized Jacobian's banded solves and the ends' sensitivities (`DiscreteLine`);
- `loads`: the cable terms' force and derivatives, checked, in the plane and in space;
- `pointwise`: the fields at any arc length, through each element's own basis (`LinePoints`);
- `fitting`: the touchdown and the landing from the balance of forces, in the plane and in
  space;
- `check`: the equilibrium residual of a solution by scikit-fem's own assembly, the refusal of a
  line with no equilibrium in tension, the diagnosis of a failure with friction and whether the
  mesh resolves the line;
- `resolution`: ``n_elements="auto"``, the elements a line needs (more while `check` says the
  mesh does not resolve it), the plane line's and the line in space's;
- `fields`: what the solutions in the plane and in space share: the state, tension, tangent,
  weight, segment end tensions and samples at any arc length (`LineFields`);
- `problem`: one discrete line in the plane — its properties, the scales, the point loads at any
  arc length and its seabed's contact rows (with friction and the slack stretch);
- `start`: the closed-form starts (elastic catenary, grounded where it dips below the seabed,
  on a slope, lifted, segment-wise, smeared), the line in space's too;
- `iterate`: one solve — damped semismooth Newton, its rescue with the active set held, full
  steps and the polish (`skcable.fe.newton`'s options, as the line in space's);
- `slack`: Jonkman's slack stretch near the anchor;
- `solver`: what the two drivers share (`LineSolver`: the alternative solves, the compression
  test, the friction diagnosis);
- `driver`: the continuation `LineBVPSolver` — levels, gradings, friction, fitting, checks;
- `solution`: `LineBVPSolution`, the end forces, contact and fields;
- `stiffness`: the fairlead stiffness from the converged tangent (implicit function theorem);
- `model`: `solve_line_bvp` and `LineBVP`, a line model for `line_3d` and `MooringSystem`;
- `space`: the line in space (`solve_line_bvp_3d`), on the same discrete line law, meshes,
  solves and checks, with its own strategy (its package's docstring);
- `fallback`: each solver's fallback on the other, for a line that hangs in the vertical plane
  of its ends (the plane line by the line in space's strategy, and the other way).

Data flow one way: ``inputs → driver → (mesh, start, problem ⇄ contact) → iterate → solution
(fields, pointwise)``; ``model → fallback → (driver, space.driver)``, ``model → resolution → check``.
"""

from skcable.mooring.line_bvp.driver import LineBVPSolver
from skcable.mooring.line_bvp.inputs import BVPSegment
from skcable.mooring.line_bvp.model import LineBVP, solve_line_bvp
from skcable.mooring.line_bvp.problem import LineProblem, LineState
from skcable.mooring.line_bvp.solution import LineBVPSolution

__all__ = [
    "BVPSegment",
    "LineBVP",
    "LineBVPSolution",
    "LineBVPSolver",
    "LineProblem",
    "LineState",
    "solve_line_bvp",
]
