"""Overhead line conductors beyond one span (issue 24): whole lines at array speed, conductor
temperature from current and weather (linerate), the damaged-conductor chain (residual strength,
Poffenberger–Swart, fatigue) and a conductor catalogue.

The public names load their modules on first use (``linerate`` only with the rating).
"""

from importlib import import_module

_NAMES = {
    "ThermalRating": "_rating",
    "sag_at_current": "_rating",
    "clearance_ampacity": "_rating",
    "poffenberger_swart": "_fatigue",
    "ClampStress": "_fatigue",
    "clamp_stress": "_fatigue",
    "WohlerCurve": "_fatigue",
    "miner_damage": "_fatigue",
    "fatigue_life": "_fatigue",
    "layer_rrts": "_strength",
    "wire_strengths": "_strength",
    "ResidualStrength": "_strength",
    "residual_strength": "_strength",
    "catalogue": "_catalogue",
    "ComponentCurve": "_stress_strain",
    "StressStrainModel": "_stress_strain",
    "History": "_stress_strain",
    "CreepLaw": "_stress_strain",
    "aa_coefficients": "_stress_strain",
    "level_span_states": "_stress_strain",
}

__all__ = sorted(_NAMES)


def __getattr__(name):
    if name in _NAMES:
        return getattr(import_module(f"{__name__}.{_NAMES[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
