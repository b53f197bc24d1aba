"""Metallic strands: wire geometry, asymmetric damage, section properties,
wire materials and the stick/slip bending law (Pino Vidal 2021, chapters 2-3,
annexes A and B). SI units: m, N, Pa.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.strand._bending import BendingLaw, critical_curvature
    from skcable.strand._choice import Analysis, ClosedFormCurve, analyse, axial_force
    from skcable.strand._geometry import Layer, Strand, Wires, preset
    from skcable.strand._layers import LayerSlipLaw
    from skcable.strand._material import Material, material
    from skcable.strand._section import Section
    from skcable.strand._stages import CurvaturePath, StageLaw, StageResponse
    from skcable.strand._vibration import (
        BeamFrequencies,
        StrandFrequencies,
        beam_frequencies,
        pinned_beam_frequencies,
        strand_bending_frequencies,
    )
    from skcable.strand.capacity import CapacityCurve, StepResult, StrandLayout, capacity_curve
    from skcable.strand.fe import (
        DOFS,
        END_CONDITIONS,
        FIELDS,
        STRAINS,
        AnnexE,
        AxisSlip,
        ElasticFoundation,
        ElementSlip,
        FieldAssembly,
        FieldTerm,
        FollowerForce,
        HelicalWires,
        NodalSpring,
        PointForce,
        PointMoment,
        RigidCylinder,
        SectionTerm,
        SinusoidalDamageLoads,
        SlipLaw,
        SlipPoints,
        Step,
        Stick,
        StrandModel,
        StrandSupports,
        TensionlessFoundation,
        Term,
        TransverseLoad,
        WireBending,
        default_physics,
    )

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    "._bending": ("BendingLaw", "critical_curvature"),
    "._choice": ("Analysis", "ClosedFormCurve", "analyse", "axial_force"),
    "._geometry": ("Layer", "Strand", "Wires", "preset"),
    "._layers": ("LayerSlipLaw",),
    "._material": ("Material", "material"),
    "._section": ("Section",),
    "._stages": ("CurvaturePath", "StageLaw", "StageResponse"),
    "._vibration": (
        "BeamFrequencies",
        "StrandFrequencies",
        "beam_frequencies",
        "pinned_beam_frequencies",
        "strand_bending_frequencies",
    ),
    ".capacity": ("CapacityCurve", "StepResult", "StrandLayout", "capacity_curve"),
    ".fe": (
        "DOFS",
        "END_CONDITIONS",
        "FIELDS",
        "STRAINS",
        "AnnexE",
        "AxisSlip",
        "ElasticFoundation",
        "ElementSlip",
        "FieldAssembly",
        "FieldTerm",
        "FollowerForce",
        "HelicalWires",
        "NodalSpring",
        "PointForce",
        "PointMoment",
        "RigidCylinder",
        "SectionTerm",
        "SinusoidalDamageLoads",
        "SlipLaw",
        "SlipPoints",
        "Step",
        "Stick",
        "StrandModel",
        "StrandSupports",
        "TensionlessFoundation",
        "Term",
        "TransverseLoad",
        "WireBending",
        "default_physics",
    ),
}

__getattr__, __dir__ = attach(__name__, submodules=("fe", "capacity"), names=_NAMES)

__all__ = [
    "TransverseLoad",
    "DOFS",
    "END_CONDITIONS",
    "FIELDS",
    "STRAINS",
    "FieldAssembly",
    "FollowerForce",
    "PointForce",
    "PointMoment",
    "RigidCylinder",
    "StrandSupports",
    "TensionlessFoundation",
    "AnnexE",
    "AxisSlip",
    "ElasticFoundation",
    "ElementSlip",
    "FieldTerm",
    "HelicalWires",
    "NodalSpring",
    "SectionTerm",
    "SinusoidalDamageLoads",
    "SlipLaw",
    "SlipPoints",
    "Step",
    "Stick",
    "StrandLayout",
    "Term",
    "WireBending",
    "default_physics",
    "Analysis",
    "ClosedFormCurve",
    "analyse",
    "axial_force",
    "BendingLaw",
    "CapacityCurve",
    "CurvaturePath",
    "Layer",
    "LayerSlipLaw",
    "Material",
    "Section",
    "StageLaw",
    "StageResponse",
    "StepResult",
    "Strand",
    "StrandModel",
    "Wires",
    "capacity_curve",
    "critical_curvature",
    "material",
    "preset",
    "BeamFrequencies",
    "StrandFrequencies",
    "beam_frequencies",
    "pinned_beam_frequencies",
    "strand_bending_frequencies",
]
