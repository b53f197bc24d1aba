"""Overhead-line conductors: the conductor of a strand, change of state with temperature, ice and
wind, ruling span and tension sections, natural frequencies, whole lines at array speed,
conductor temperature from current and weather (linerate, imported only when a rating is made),
the damaged-conductor chain (residual strength, Poffenberger–Swart, fatigue), a conductor
catalogue and stress–strain conductor models.

One concern per module:

- `_conductor`: `Conductor`, a conductor's EA, weight and expansion, from a strand or given;
- `_state`: the change of state of one span (`change_of_state`, `sag_tension_table`) and the
  thermal catenary;
- `_spans`: the ruling span and the exact tension section over suspension insulators;
- `_frequencies`: natural frequencies of a suspended cable, FE beside Irvine's closed forms;
- `_lines`, `_solve_z`, `_parabola`, `_inputs`, `_reference`: whole lines at array speed (the
  line path of `change_of_state`, in rows of `skcable.cable._scratch`; `_solve_z` the z-form
  solve, checked by the one closure `skcable.cable.closure`);
- `_rating`: conductor temperature from current and weather (IEEE 738, CIGRE 601);
- `_strength`, `_fatigue`: residual strength, Poffenberger–Swart (and the clamp amplitude of a
  vibration loop), Wöhler curves and Miner;
- `_damping`, `_wind`, `_aeolian`: aeolian vibration: self-damping (the conductor's own, from its
  layer-by-layer bending law, Foti & Martinelli's, power laws), wind power input, and the energy
  balance to the antinode amplitude, the clamp stress and a fatigue life;
- `_catalogue`: a conductor catalogue; `_stress_strain`: stress–strain conductor models.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.conductors._aeolian import AeolianVibration, aeolian_amplitude, aeolian_vibration
    from skcable.conductors._catalogue import catalogue
    from skcable.conductors._conductor import Conductor
    from skcable.conductors._damping import (
        DAMPING_EXPONENTS,
        damping_exponents,
        foti_damping,
        power_law_damping,
        self_damping,
    )
    from skcable.conductors._fatigue import (
        ClampStress,
        WohlerCurve,
        clamp_amplitude,
        clamp_stress,
        fatigue_life,
        miner_damage,
        poffenberger_swart,
    )
    from skcable.conductors._frequencies import NaturalFrequencies, irvine_frequencies, natural_frequencies
    from skcable.conductors._rating import ThermalRating, clearance_ampacity, sag_at_current
    from skcable.conductors._spans import TensionSection, ruling_span, tension_section
    from skcable.conductors._state import (
        ChangeOfState,
        ThermalCatenary,
        change_of_state,
        sag_tension_table,
        thermal_catenary,
    )
    from skcable.conductors._strength import ResidualStrength, layer_rrts, residual_strength, wire_strengths
    from skcable.conductors._stress_strain import (
        ComponentCurve,
        CreepLaw,
        History,
        StressStrainModel,
        aa_coefficients,
        level_span_states,
    )
    from skcable.conductors._wind import WIND_MODELS, wind_band, wind_power

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    "._aeolian": ("AeolianVibration", "aeolian_amplitude", "aeolian_vibration"),
    "._catalogue": ("catalogue",),
    "._conductor": ("Conductor",),
    "._damping": (
        "DAMPING_EXPONENTS",
        "damping_exponents",
        "foti_damping",
        "power_law_damping",
        "self_damping",
    ),
    "._fatigue": (
        "ClampStress",
        "WohlerCurve",
        "clamp_amplitude",
        "clamp_stress",
        "fatigue_life",
        "miner_damage",
        "poffenberger_swart",
    ),
    "._frequencies": ("NaturalFrequencies", "irvine_frequencies", "natural_frequencies"),
    "._rating": ("ThermalRating", "clearance_ampacity", "sag_at_current"),
    "._spans": ("TensionSection", "ruling_span", "tension_section"),
    "._state": (
        "ChangeOfState",
        "ThermalCatenary",
        "change_of_state",
        "sag_tension_table",
        "thermal_catenary",
    ),
    "._strength": ("ResidualStrength", "layer_rrts", "residual_strength", "wire_strengths"),
    "._wind": ("WIND_MODELS", "wind_band", "wind_power"),
    "._stress_strain": (
        "ComponentCurve",
        "CreepLaw",
        "History",
        "StressStrainModel",
        "aa_coefficients",
        "level_span_states",
    ),
}

__getattr__, __dir__ = attach(__name__, names=_NAMES)

__all__ = [
    "AeolianVibration",
    "DAMPING_EXPONENTS",
    "ChangeOfState",
    "ClampStress",
    "ComponentCurve",
    "Conductor",
    "CreepLaw",
    "History",
    "NaturalFrequencies",
    "ResidualStrength",
    "StressStrainModel",
    "TensionSection",
    "ThermalCatenary",
    "ThermalRating",
    "WIND_MODELS",
    "WohlerCurve",
    "aa_coefficients",
    "aeolian_amplitude",
    "aeolian_vibration",
    "catalogue",
    "change_of_state",
    "clamp_amplitude",
    "clamp_stress",
    "clearance_ampacity",
    "damping_exponents",
    "fatigue_life",
    "foti_damping",
    "irvine_frequencies",
    "layer_rrts",
    "level_span_states",
    "miner_damage",
    "natural_frequencies",
    "poffenberger_swart",
    "power_law_damping",
    "residual_strength",
    "ruling_span",
    "sag_at_current",
    "sag_tension_table",
    "self_damping",
    "tension_section",
    "thermal_catenary",
    "wind_band",
    "wind_power",
    "wire_strengths",
]
