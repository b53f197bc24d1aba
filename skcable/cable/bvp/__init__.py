"""Suspended cables as 1D nonlinear boundary-value problems on scikit-fem.

One concern per module:

- `forms`: the weak forms of both formulations as
  scikit-fem forms (the reference the fast assembly is tested against);
- `elements`: the line elements (and a scikit-fem
  workaround for hierarchical ones);
- `assembly`, `bordered`, `probes`: deprecated, moved to `skcable.fe` (`Assembly`,
  `BorderedSolver`, `skcable.fe.probes`) and served there for one release;
- `base`: what both solutions share;
- `section`: the tension's part of the arc-length forms' section law (the arc form and the line);
- `graph`: the graph form y(x), H global;
- `arc`: the arc-length form, L0 global;
- `solve`: `solve_bvp`, which checks the
  arguments, picks the formulation and runs `skcable.fe.newton`;
- `line`: `solve_line_bvp` and the line model `LineBVP`, a mooring line in the arc form (segments,
  w(s), point loads) with unilateral seabed contact of any shape;
- `line3d`: `solve_line_bvp_3d` and the line model `LineBVP3D`, a line in space (current drag,
  bathymetry, axial laws, clumps and buoys, the 3 x 3 fairlead stiffness).
"""

from skcable.cable.bvp.arc import ArcSolution
from skcable.cable.bvp.forms import (
    arc_constitutive,
    arc_equilibrium_x,
    arc_equilibrium_y,
    graph_dH,
    graph_residual,
    graph_tangent,
)
from skcable.cable.bvp.graph import BVPSolution
from skcable.cable.bvp.line import BVPSegment, LineBVP, LineBVPSolution, solve_line_bvp
from skcable.cable.bvp.line3d import LineBVP3D, LineBVP3DSolution, LineSegment, solve_line_bvp_3d
from skcable.cable.bvp.solve import solve_bvp

__all__ = [
    "ArcSolution",
    "BVPSegment",
    "BVPSolution",
    "LineBVP",
    "LineBVP3D",
    "LineBVP3DSolution",
    "LineBVPSolution",
    "LineSegment",
    "arc_constitutive",
    "arc_equilibrium_x",
    "arc_equilibrium_y",
    "graph_dH",
    "graph_residual",
    "graph_tangent",
    "solve_bvp",
    "solve_line_bvp",
    "solve_line_bvp_3d",
]
