"""A line in space as an arc-length BVP: segments with axial laws, current drag, bathymetry.

`solve_line_bvp_3d` solves one line from its anchor to its fairlead (3-vectors, z up) in the
arc-length form of the plane line BVP (`skcable.mooring.line_bvp`) in three dimensions: positions
``r(s)`` P2, tension P1-DG, on the unstretched arc length; multi-segment lines (each segment its
length, weight, axial law `skcable.mooring.axial`, diameter and drag coefficients) with clump
weights and buoys at the joints; loads as cable terms (`skcable.bvp.terms`: the weight, the
current's drag ``½ρ C_d d |v_n| v_n`` normal and tangential, the analyst's); the seabed
(`skcable.mooring.bathymetry`: a plane, a depth function, a grid) as unilateral contact with
Coulomb friction along the line. One concern per module:

- `inputs`: the segments (`LineSegment`, the plane line's), the attachments and every argument,
  checked into a `Scene3D`;
- `loads`: the current's drag on the segments as a cable term (`SegmentDrag`);
- `problem`: one discrete line in space — its properties, the current's drag and the analyst's
  terms bound to it, and its seabed's contact rows (the plane line's,
  `skcable.mooring.line_bvp.contact`, in three dimensions), on the line law of
  `skcable.mooring.line_bvp.discrete` (the plane line's, in three dimensions);
- `start`: the closed form in the vertical plane of the ends;
- `vertical_plane`: a line that hangs in the vertical plane of its ends as the plane line's
  scene, and the plane line's solution in space;
- `driver`: the strategy `LineBVP3DSolver` — the starts, the current and point loads by steps,
  nested and graded
  meshes, fitting, checks; each solve the plane line's (`skcable.mooring.line_bvp.iterate`);
- `stiffness`: the 3 × 3 fairlead stiffness from the converged tangent, static or dynamic;
- `solution`: `LineBVP3DSolution` (its fields the plane line's,
  `skcable.mooring.line_bvp.fields`);
- `model`: `solve_line_bvp_3d` and `LineBVP3D`, a line model, whose solver falls back on the
  plane line's strategy for a line that hangs in the vertical plane of its ends
  (`skcable.mooring.line_bvp.fallback`).

Data flow one way: ``inputs → driver → (start, problem, loads) →
(`skcable.mooring.line_bvp`: iterate, fitting, fields, check) → solution → stiffness``.
"""

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.mooring.line_bvp.space.driver import LineBVP3DSolver
    from skcable.mooring.line_bvp.space.inputs import LineSegment
    from skcable.mooring.line_bvp.space.model import LineBVP3D, solve_line_bvp_3d
    from skcable.mooring.line_bvp.space.problem import LineProblem3D
    from skcable.mooring.line_bvp.space.solution import LineBVP3DSolution
    from skcable.mooring.line_bvp.space.stiffness import FairleadStiffness

#: Where each public name lives (imported on first use, PEP 562): the models import the plane
#: line's fallback (`skcable.mooring.line_bvp.fallback`), which imports this package's driver, so
#: this package imports none of its modules until a name is asked for.
_NAMES = {
    ".driver": ("LineBVP3DSolver",),
    ".inputs": ("LineSegment",),
    ".model": ("LineBVP3D", "solve_line_bvp_3d"),
    ".problem": ("LineProblem3D",),
    ".solution": ("LineBVP3DSolution",),
    ".stiffness": ("FairleadStiffness",),
}

__getattr__, __dir__ = attach(__name__, names=_NAMES)

__all__ = [
    "FairleadStiffness",
    "LineBVP3D",
    "LineBVP3DSolution",
    "LineBVP3DSolver",
    "LineProblem3D",
    "LineSegment",
    "solve_line_bvp_3d",
]
