"""Metallic strands: wire geometry, asymmetric damage, section properties,
wire materials and the stick/slip bending law (seed 003 chapters 2-3,
annexes A and B). SI units: m, N, Pa.
"""

from skcable.strand._bending import BendingLaw
from skcable.strand._geometry import Layer, Strand, Wires, preset
from skcable.strand._material import Material, material
from skcable.strand._section import Section

__all__ = ["BendingLaw", "Layer", "Material", "Section", "Strand", "Wires", "material", "preset"]
