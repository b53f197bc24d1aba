"""Suspended cables as 1-D nonlinear boundary-value problems on scikit-fem, with their terms.

One concern per module:

- `loads`: the loads of the closed forms' scenes (`SelfWeight`, `DeckLoad`,
  `DistributedLoad`, `PointLoad`);
- `terms`: cable terms, a force per unstretched length as a function of the state with its
  derivatives (`CableTerm`; `Buoyancy`, `WindDrag`, `CurrentDrag` are built that way);
- `current`: current profiles, the flow that `CurrentDrag` and the lines in the sea read;
- `forms`: the weak forms of both formulations as scikit-fem forms (the reference the fast
  assembly is tested against);
- `elements`: the line elements (and a scikit-fem workaround for hierarchical ones);
- `base`: what both solutions share;
- `section`: the tension's part of the arc-length forms' section law (the arc form and the
  mooring line BVPs);
- `graph`: the graph form y(x), H global;
- `arc`: the arc-length form, L0 global;
- `formulation`: `solve_bvp`, which checks the arguments, picks the formulation and runs
  `skcable.fe.newton`;
- `choice`: `solve`, the cheapest model (parabola, catenary, elastic catenary or the BVP)
  whose estimated error is below a tolerance, with its reason.

A line on the seabed (contact, friction, segments, in the plane or in space) is a mooring line:
`skcable.mooring.solve_line_bvp` and `skcable.mooring.line_bvp.space`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.bvp.arc import ArcSolution
    from skcable.bvp.choice import solve
    from skcable.bvp.current import Current, ProfileCurrent, TabulatedCurrent, UniformCurrent
    from skcable.bvp.forms import (
        arc_constitutive,
        arc_equilibrium_x,
        arc_equilibrium_y,
        graph_dH,
        graph_residual,
        graph_tangent,
    )
    from skcable.bvp.formulation import solve_bvp
    from skcable.bvp.graph import BVPSolution
    from skcable.bvp.loads import DeckLoad, DistributedLoad, PointLoad, SelfWeight
    from skcable.bvp.terms import Buoyancy, CableForce, CableState, CableTerm, CurrentDrag, WindDrag

SUBMODULES = (
    "arc",
    "base",
    "choice",
    "current",
    "elements",
    "forms",
    "formulation",
    "graph",
    "loads",
    "section",
    "terms",
)

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    ".arc": ("ArcSolution",),
    ".choice": ("solve",),
    ".current": ("Current", "ProfileCurrent", "TabulatedCurrent", "UniformCurrent"),
    ".formulation": ("solve_bvp",),
    ".forms": (
        "arc_constitutive",
        "arc_equilibrium_x",
        "arc_equilibrium_y",
        "graph_dH",
        "graph_residual",
        "graph_tangent",
    ),
    ".graph": ("BVPSolution",),
    ".loads": ("DeckLoad", "DistributedLoad", "PointLoad", "SelfWeight"),
    ".terms": ("Buoyancy", "CableForce", "CableState", "CableTerm", "CurrentDrag", "WindDrag"),
}

__getattr__, __dir__ = attach(
    __name__,
    submodules=SUBMODULES,
    names=_NAMES,
)

__all__ = [
    "ArcSolution",
    "solve",
    "Current",
    "ProfileCurrent",
    "TabulatedCurrent",
    "UniformCurrent",
    "solve_bvp",
    "arc_constitutive",
    "arc_equilibrium_x",
    "arc_equilibrium_y",
    "graph_dH",
    "graph_residual",
    "graph_tangent",
    "BVPSolution",
    "DeckLoad",
    "DistributedLoad",
    "PointLoad",
    "SelfWeight",
    "Buoyancy",
    "CableForce",
    "CableState",
    "CableTerm",
    "CurrentDrag",
    "WindDrag",
]
