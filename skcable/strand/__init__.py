"""Metallic strands: wire geometry, asymmetric damage, section properties,
wire materials and the stick/slip bending law (Pino Vidal 2021, chapters 2-3,
annexes A and B). SI units: m, N, Pa.
"""

from skcable.strand._bending import BendingLaw, critical_curvature
from skcable.strand._choice import Analysis, ClosedFormCurve, analyse, axial_force
from skcable.strand._geometry import Layer, Strand, Wires, preset
from skcable.strand._material import Material, material
from skcable.strand._section import Section
from skcable.strand._vibration import (
    BeamFrequencies,
    StrandFrequencies,
    beam_frequencies,
    pinned_beam_frequencies,
    strand_bending_frequencies,
)
from skcable.strand.capacity import CapacityCurve, StepResult, StrandLayout, capacity_curve
from skcable.strand.fe import (
    AnnexE,
    AxisSlip,
    DistributedLoad,
    ElasticFoundation,
    ElementSlip,
    FieldTerm,
    HelicalWires,
    NodalSpring,
    SectionTerm,
    SinusoidalDamageLoads,
    SlipLaw,
    Step,
    Stick,
    StrandModel,
    Term,
    WireBending,
    default_physics,
)

__all__ = [
    "AnnexE",
    "AxisSlip",
    "DistributedLoad",
    "ElasticFoundation",
    "ElementSlip",
    "FieldTerm",
    "HelicalWires",
    "NodalSpring",
    "SectionTerm",
    "SinusoidalDamageLoads",
    "SlipLaw",
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
    "Layer",
    "Material",
    "Section",
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
