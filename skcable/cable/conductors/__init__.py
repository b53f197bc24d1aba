"""Overhead line conductors beyond one span (issue 24): whole lines at array speed (the line path
of `skcable.cable.change_of_state`), conductor temperature from current and weather (linerate,
imported only when a rating is made), the damaged-conductor chain (residual strength,
Poffenberger–Swart, fatigue), a conductor catalogue and stress–strain conductor models.
"""

from skcable.cable.conductors._catalogue import catalogue
from skcable.cable.conductors._fatigue import (
    ClampStress,
    WohlerCurve,
    clamp_stress,
    fatigue_life,
    miner_damage,
    poffenberger_swart,
)
from skcable.cable.conductors._rating import ThermalRating, clearance_ampacity, sag_at_current
from skcable.cable.conductors._strength import ResidualStrength, layer_rrts, residual_strength, wire_strengths
from skcable.cable.conductors._stress_strain import (
    ComponentCurve,
    CreepLaw,
    History,
    StressStrainModel,
    aa_coefficients,
    level_span_states,
)

__all__ = [
    "ClampStress",
    "ComponentCurve",
    "CreepLaw",
    "History",
    "ResidualStrength",
    "StressStrainModel",
    "ThermalRating",
    "WohlerCurve",
    "aa_coefficients",
    "catalogue",
    "clamp_stress",
    "clearance_ampacity",
    "fatigue_life",
    "layer_rrts",
    "level_span_states",
    "miner_damage",
    "poffenberger_swart",
    "residual_strength",
    "sag_at_current",
    "wire_strengths",
]
