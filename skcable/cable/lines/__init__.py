"""Mooring and anchor lines: seabed contact, multi-segment lines, lines in 3-D, moored bodies.

Conventions as in :mod:`skcable.cable`: anchor A at (0, 0), fairlead B at
(span, dh), y up, weights per unstretched length act downward.

One concern per module (the two packages split further, see their docstrings):

- `seabed`: one elastic line on a flat or sloped seabed, in closed form (closure,
  regimes free/grounded/heap, the dispatcher, the solution, the sloped seabed);
- `segments`: `Line`, a multi-segment line with clump weights and buoys (parts, the
  line's read-only arrays, closure, heap state, line, solution);
- `arc_samples`: a line's profile sampled along its arc length, for the VTK writer;
- `line3d`: a line model between two points in 3-D, in its vertical plane, as given;
- `geometry`: a `Line` between two ends over a flat seabed, either end higher: the model
  its position takes and why (free, grounded, touchdown between the ends, lying on the
  seabed, or the line BVP), with the forces at both ends and their Jacobian;
  `lying` (both ends on the seabed), `slope` (a sloped seabed), `bvp_model` (the line BVP
  as a line solution), `plane` (the solved line in its plane, `PlaneLine`) and `jacobians`
  (the closed forms' end-force Jacobians);
- `between`: that line between two points in space, its 6 x 6 end stiffness;
- `body`: point and rigid bodies (6 dofs) with their own loads;
- `network`: the points, line handles and dofs of a system;
- `assembly`: the net loads and the stiffness of a system, vectorised over its line ends;
- `system`: `MooringSystem`, bodies, points and lines: net loads, stiffness;
- `equilibrium`: its static equilibrium (Newton, a start from slack lines, the stable
  branch) and `MooringEquilibrium`;
- `failure`: the system without some lines, beside the intact one;
- `checks`: anchor loads, line angles and grounded lengths, segments against their MBL;
- `library`: the component library (chain, wire rope, fibre rope: diameter to w, EA, MBL);
- `design`: a line's length or a segment's property to reach a target, bracketed;
- `moordyn`: MoorDyn v2 input files read and written; `system_file`: the TOML system file.

Data flow: segments and seabed solutions (2-D) → ``geometry`` / ``line3d`` → ``between`` (in
space) → ``system`` (bodies and points) → ``equilibrium`` → the writers and plots, which only
read the results.
"""

from skcable.cable.lines.between import LineBetween, line_between
from skcable.cable.lines.body import PointBody, RigidBody, rotation_matrix
from skcable.cable.lines.design import Design, design_line, design_pattern
from skcable.cable.lines.geometry import line_in_plane
from skcable.cable.lines.library import Component, component, components, register_component
from skcable.cable.lines.line3d import Line3D, line_3d
from skcable.cable.lines.moordyn import MoorDynModel, read_moordyn, write_moordyn
from skcable.cable.lines.network import MooringLine, MooringPoint
from skcable.cable.lines.plane import PlaneLine
from skcable.cable.lines.seabed import (
    SeabedCatenary,
    SlopedSeabedCatenary,
    elastic_catenary,
    sloped_seabed_catenary,
)
from skcable.cable.lines.segments import Buoy, ClumpWeight, Line, LineSolution, Segment
from skcable.cable.lines.system import MooringEquilibrium, MooringSystem

__all__ = [
    "Buoy",
    "ClumpWeight",
    "Component",
    "Design",
    "Line",
    "Line3D",
    "LineBetween",
    "LineSolution",
    "MooringEquilibrium",
    "MooringLine",
    "MooringPoint",
    "MoorDynModel",
    "MooringSystem",
    "PlaneLine",
    "PointBody",
    "RigidBody",
    "SeabedCatenary",
    "Segment",
    "SlopedSeabedCatenary",
    "component",
    "components",
    "design_line",
    "design_pattern",
    "elastic_catenary",
    "line_3d",
    "line_between",
    "line_in_plane",
    "read_moordyn",
    "register_component",
    "rotation_matrix",
    "sloped_seabed_catenary",
    "write_moordyn",
]
