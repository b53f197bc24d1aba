"""Suspended cables: closed forms, stiffness, end conditions, surfaces.

Conventions: x to the right, y up, support A at (0, 0),
support B at (span, dh); distributed loads w > 0 act downward; H > 0 is the
horizontal tension; V_A, V_B are the upward support reactions. SI units by
default (m, N, N/m); any consistent system works.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.cable._catenary import Catenary, catenary
    from skcable.cable._choice import solve
    from skcable.cable._conductor import Conductor
    from skcable.cable._elastic import ElasticCatenary
    from skcable.cable._frequencies import NaturalFrequencies, irvine_frequencies, natural_frequencies
    from skcable.cable._funicular import Funicular, FunicularVertical, funicular, funicular_vertical
    from skcable.cable._loads import DeckLoad, DistributedLoad, PointLoad, SelfWeight
    from skcable.cable._parabola import Parabola, parabola
    from skcable.cable._spans import TensionSection, ruling_span, tension_section
    from skcable.cable._state import (
        ChangeOfState,
        ThermalCatenary,
        change_of_state,
        sag_tension_table,
        thermal_catenary,
    )
    from skcable.cable._stiffness import fairlead_stiffness, geometric_stiffness, geometric_stiffness_series
    from skcable.cable._supports import SlidingLoad, anchor_block_weight, ring_on_rod, sliding_load
    from skcable.cable._surfaces import capstan, membrane_tension, smooth_surface_reaction, sphere_parallel
    from skcable.cable.bvp import (
        ArcSolution,
        BVPSegment,
        BVPSolution,
        LineBVP,
        LineBVPSolution,
        solve_bvp,
        solve_line_bvp,
    )
    from skcable.cable.conductors import (
        ClampStress,
        ComponentCurve,
        CreepLaw,
        ResidualStrength,
        StressStrainModel,
        ThermalRating,
        WohlerCurve,
        clamp_stress,
        clearance_ampacity,
        fatigue_life,
        level_span_states,
        miner_damage,
        poffenberger_swart,
        residual_strength,
        sag_at_current,
    )
    from skcable.cable.lines import (
        Buoy,
        ClumpWeight,
        Line,
        Line3D,
        LineSolution,
        MooringEquilibrium,
        MooringSystem,
        PointBody,
        RigidBody,
        SeabedCatenary,
        Segment,
        SlopedSeabedCatenary,
        elastic_catenary,
        line_3d,
        rotation_matrix,
        sloped_seabed_catenary,
    )
    from skcable.cable.solution import CableSolution
    from skcable.cable.terms import Buoyancy, CableForce, CableState, CableTerm, CurrentDrag, WindDrag

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    "._catenary": ("Catenary", "catenary"),
    "._choice": ("solve",),
    "._conductor": ("Conductor",),
    "._elastic": ("ElasticCatenary",),
    "._frequencies": ("NaturalFrequencies", "irvine_frequencies", "natural_frequencies"),
    "._funicular": ("Funicular", "FunicularVertical", "funicular", "funicular_vertical"),
    "._loads": ("DeckLoad", "DistributedLoad", "PointLoad", "SelfWeight"),
    "._parabola": ("Parabola", "parabola"),
    "._spans": ("TensionSection", "ruling_span", "tension_section"),
    "._state": (
        "ChangeOfState",
        "ThermalCatenary",
        "change_of_state",
        "sag_tension_table",
        "thermal_catenary",
    ),
    "._stiffness": ("fairlead_stiffness", "geometric_stiffness", "geometric_stiffness_series"),
    "._supports": ("SlidingLoad", "anchor_block_weight", "ring_on_rod", "sliding_load"),
    "._surfaces": ("capstan", "membrane_tension", "smooth_surface_reaction", "sphere_parallel"),
    ".bvp": (
        "ArcSolution",
        "BVPSegment",
        "BVPSolution",
        "LineBVP",
        "LineBVPSolution",
        "solve_bvp",
        "solve_line_bvp",
    ),
    ".lines": (
        "Buoy",
        "ClumpWeight",
        "Line",
        "Line3D",
        "LineSolution",
        "MooringEquilibrium",
        "MooringSystem",
        "PointBody",
        "RigidBody",
        "SeabedCatenary",
        "Segment",
        "SlopedSeabedCatenary",
        "elastic_catenary",
        "line_3d",
        "rotation_matrix",
        "sloped_seabed_catenary",
    ),
    ".conductors": (
        "ClampStress",
        "ComponentCurve",
        "CreepLaw",
        "ResidualStrength",
        "StressStrainModel",
        "ThermalRating",
        "WohlerCurve",
        "clamp_stress",
        "clearance_ampacity",
        "fatigue_life",
        "level_span_states",
        "miner_damage",
        "poffenberger_swart",
        "residual_strength",
        "sag_at_current",
    ),
    ".solution": ("CableSolution",),
    ".terms": ("Buoyancy", "CableForce", "CableState", "CableTerm", "CurrentDrag", "WindDrag"),
}
#: The weak forms, for extending the BVPs, live in `skcable.cable.bvp.forms`.
_MOVED = {
    name: f"skcable.cable.bvp.forms.{name}"
    for name in (
        "arc_constitutive",
        "arc_equilibrium_x",
        "arc_equilibrium_y",
        "graph_dH",
        "graph_residual",
        "graph_tangent",
    )
}

__getattr__, __dir__ = attach(
    __name__,
    submodules=("axial", "bathymetry", "bvp", "conductors", "current", "lines", "solution", "terms"),
    names=_NAMES,
    moved=_MOVED,
)

__all__ = [
    "ClampStress",
    "ComponentCurve",
    "CreepLaw",
    "ResidualStrength",
    "StressStrainModel",
    "ThermalRating",
    "WohlerCurve",
    "clamp_stress",
    "clearance_ampacity",
    "fatigue_life",
    "level_span_states",
    "miner_damage",
    "poffenberger_swart",
    "residual_strength",
    "sag_at_current",
    "Buoyancy",
    "CableForce",
    "CableState",
    "CableTerm",
    "CurrentDrag",
    "WindDrag",
    "ArcSolution",
    "BVPSegment",
    "LineBVP",
    "LineBVPSolution",
    "SlopedSeabedCatenary",
    "sloped_seabed_catenary",
    "solve_line_bvp",
    "BVPSolution",
    "DeckLoad",
    "DistributedLoad",
    "PointLoad",
    "SelfWeight",
    "solve_bvp",
    "CableSolution",
    "ChangeOfState",
    "ThermalCatenary",
    "change_of_state",
    "sag_tension_table",
    "thermal_catenary",
    "Catenary",
    "ElasticCatenary",
    "SeabedCatenary",
    "Funicular",
    "NaturalFrequencies",
    "irvine_frequencies",
    "natural_frequencies",
    "FunicularVertical",
    "Parabola",
    "SlidingLoad",
    "anchor_block_weight",
    "capstan",
    "catenary",
    "elastic_catenary",
    "fairlead_stiffness",
    "funicular",
    "funicular_vertical",
    "geometric_stiffness",
    "geometric_stiffness_series",
    "membrane_tension",
    "parabola",
    "ring_on_rod",
    "sliding_load",
    "solve",
    "smooth_surface_reaction",
    "sphere_parallel",
    "Conductor",
    "TensionSection",
    "ruling_span",
    "tension_section",
    "Buoy",
    "ClumpWeight",
    "Line",
    "LineSolution",
    "Segment",
    "Line3D",
    "MooringEquilibrium",
    "MooringSystem",
    "PointBody",
    "RigidBody",
    "line_3d",
    "rotation_matrix",
]
