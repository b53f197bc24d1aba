"""Mooring lines and systems: multi-segment lines, lines in the sea, moored bodies, MoorDyn.

Conventions as in :mod:`skcable.cable`: anchor A at (0, 0), fairlead B at
(span, dh), y up, weights per unstretched length act downward. One elastic line on a flat or
sloped seabed in closed form (Irvine's and Jonkman's) is `skcable.cable.elastic_catenary`
(`skcable.cable.seabed`); everything built on it is here.

One concern per module (the packages split further, see their docstrings):

- `segments`: `Line`, a multi-segment line with clump weights and buoys (parts, the
  line's read-only arrays, closure, heap state, line, solution);
- `axial`: axial laws of ropes (a constant EA, strain–tension tables, static–dynamic ropes);
- `bathymetry`: seabeds of any shape (a plane, a depth function, a grid);
- `line_bvp`: the line BVP: a line as an arc-length BVP in its plane (segments, w(s), point
  loads, seabed contact of any shape with friction) and, in `line_bvp.space`, in space (current
  drag, bathymetry, axial laws), each solver falling back on the other where the line hangs in
  the vertical plane of its ends;
- `choice`: the model a `Line` takes in its scene, and why, for every scene: in the vertical
  plane of its ends (free, grounded, touchdown between the ends or on a slope, lying on the seabed, on a
  slope, or the line BVP), between two points in space, in the sea (closed form or the 3-D
  line BVP), in a system; `line_in_plane` and `line_between`;
- the models it chooses among and their results: `plane_line` (the solved line in its plane,
  `PlaneLine`, forces by end), `line_on_seabed` (both ends on the seabed), `slope` (the closed
  form on a sloped seabed as a line model), `bvp_model` (the plane line BVP as a line
  solution), `jacobians` (the closed forms' end-force Jacobians), `straight` (a line whose
  ends share a vertical, or a weightless one), `between_points` (`LineBetween`: the line
  between two points in space, its 6 x 6 end stiffness), `sea_line` (`LineInSea`: a line in
  the sea, its `ModelChoice`);
- `line3d`: a line model between two points in 3-D, in its vertical plane, as given;
- `rod`: rigid rods (MoorDyn's), as a line between two points or a body of the equilibrium;
- `body`: point and rigid bodies (6 dofs) with their own loads;
- `network`: the points, line handles and dofs of a system;
- `net_loads`: the net loads and the stiffness of a system, vectorised over its line ends;
- `system`: `MooringSystem`, bodies, points and lines: net loads, stiffness;
- `equilibrium`: its static equilibrium (Newton, a start from slack lines, the stable
  branch) and `MooringEquilibrium`;
- `failure`: the system without some lines, beside the intact one;
- `checks`: anchor loads, line angles and grounded lengths, segments against their MBL;
- `library`: the component library (chain, wire rope, fibre rope: diameter to w, EA, MBL);
- `design`: a line's length or a segment's property to reach a target, bracketed;
- `moordyn`: MoorDyn input files (v1 and v2, as MoorDyn reads them) read and written;
  `system_file`: the TOML system file.

Data flow: segments and seabed solutions (2-D), the line BVPs → ``choice`` (the model, in the
plane or in space) → ``system`` (bodies and points) → ``equilibrium`` → the writers and plots,
which only read the results.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.mooring.between_points import LineBetween
    from skcable.mooring.body import PointBody, RigidBody, rotation_matrix
    from skcable.mooring.choice import line_between, line_in_plane
    from skcable.mooring.design import Design, design_line, design_pattern
    from skcable.mooring.library import Component, component, components, register_component
    from skcable.mooring.line3d import Line3D, line_3d
    from skcable.mooring.line_bvp import BVPSegment, LineBVP, LineBVPSolution, solve_line_bvp
    from skcable.mooring.line_bvp.space import LineBVP3D, LineBVP3DSolution, LineSegment, solve_line_bvp_3d
    from skcable.mooring.moordyn import MoorDynModel, read_moordyn, write_moordyn
    from skcable.mooring.network import MooringLine, MooringPoint
    from skcable.mooring.plane_line import PlaneLine
    from skcable.mooring.sea_line import LineInSea, ModelChoice
    from skcable.mooring.segments import Buoy, ClumpWeight, Line, LineSolution, Segment
    from skcable.mooring.segments.law import LawLineSolution
    from skcable.mooring.system import MooringEquilibrium, MooringSystem

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    ".between_points": ("LineBetween",),
    ".body": ("PointBody", "RigidBody", "rotation_matrix"),
    ".choice": ("line_between", "line_in_plane"),
    ".design": ("Design", "design_line", "design_pattern"),
    ".library": ("Component", "component", "components", "register_component"),
    ".line3d": ("Line3D", "line_3d"),
    ".line_bvp": ("BVPSegment", "LineBVP", "LineBVPSolution", "solve_line_bvp"),
    ".line_bvp.space": ("LineBVP3D", "LineBVP3DSolution", "LineSegment", "solve_line_bvp_3d"),
    ".moordyn": ("MoorDynModel", "read_moordyn", "write_moordyn"),
    ".network": ("MooringLine", "MooringPoint"),
    ".plane_line": ("PlaneLine",),
    ".sea_line": ("LineInSea", "ModelChoice"),
    ".segments": ("Buoy", "ClumpWeight", "Line", "LineSolution", "Segment"),
    ".segments.law": ("LawLineSolution",),
    ".system": ("MooringEquilibrium", "MooringSystem"),
}

SUBMODULES = (
    "axial",
    "bathymetry",
    "between_points",
    "body",
    "bvp_model",
    "checks",
    "choice",
    "design",
    "equilibrium",
    "failure",
    "jacobians",
    "library",
    "line3d",
    "line_bvp",
    "line_on_seabed",
    "moordyn",
    "net_loads",
    "network",
    "plane_line",
    "rod",
    "sea_line",
    "segments",
    "slope",
    "straight",
    "system",
    "system_file",
)

__getattr__, __dir__ = attach(__name__, submodules=SUBMODULES, names=_NAMES)

__all__ = [
    "LineBetween",
    "line_between",
    "PointBody",
    "RigidBody",
    "rotation_matrix",
    "Design",
    "design_line",
    "design_pattern",
    "line_in_plane",
    "LineInSea",
    "ModelChoice",
    "Component",
    "component",
    "components",
    "register_component",
    "Line3D",
    "line_3d",
    "BVPSegment",
    "LineBVP",
    "LineBVPSolution",
    "solve_line_bvp",
    "LineBVP3D",
    "LineBVP3DSolution",
    "LineSegment",
    "solve_line_bvp_3d",
    "MoorDynModel",
    "read_moordyn",
    "write_moordyn",
    "MooringLine",
    "MooringPoint",
    "PlaneLine",
    "Buoy",
    "ClumpWeight",
    "Line",
    "LineSolution",
    "Segment",
    "LawLineSolution",
    "MooringEquilibrium",
    "MooringSystem",
]
