"""Metallic strands: wire geometry, asymmetric damage, section properties,
wire materials and the stick/slip bending law (seed 003 chapters 2-3,
annexes A and B). SI units: m, N, Pa.
"""

from skcable.strand._bending import BendingLaw
from skcable.strand._capacity import CapacityCurve, capacity_curve
from skcable.strand._choice import Analysis, ClosedFormCurve, analyse, axial_force
from skcable.strand._geometry import Layer, Strand, Wires, preset
from skcable.strand._material import Material, material
from skcable.strand._model import StepResult, StrandModel, geometric_block, material_block, section_residual
from skcable.strand._section import Section

__all__ = [
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
    "geometric_block",
    "material",
    "material_block",
    "preset",
    "section_residual",
]
