"""The plausibility of a closed-form cable's answer (`skcable._plausible` holds the limits):
its largest strain ``T/EA`` against the loosest material's (a closed form knows no material),
and, on a seabed, the uplift angle at an anchor that lies on it."""

from __future__ import annotations

import numpy as np

from skcable import _plausible

__all__ = ["check_catenary"]


def _first(values, where) -> float:
    """The value of ``values`` at the first True of ``where`` (arrays or floats)."""
    return float(np.ravel(np.broadcast_to(values, np.shape(where)))[np.flatnonzero(np.ravel(where))[0]])


def check_catenary(solution) -> None:
    """Warn where an elastic catenary (free or on a seabed) is a state no real line is in: its
    largest strain ``max(T_A, T_B)/EA`` beyond any material's (`skcable._plausible.line_strain`),
    or, its anchor on the seabed (``seabed == 0``), an uplift angle ``atan2(-V_A, H_A)`` beyond
    what a drag anchor takes. Arrays: the first element at fault is named. Floats take a fast
    path of float comparisons (no NumPy call: a closed form's answer costs microseconds)."""
    T_A, T_B, EA = solution.T_A, solution.T_B, solution.EA
    seabed = getattr(solution, "seabed", None)
    if type(T_A) is float and type(T_B) is float and type(EA) is float:
        quiet = not max(T_A, T_B) > _plausible.STRAIN_LIMITS[None] * EA
        if quiet and (seabed is None or seabed != 0.0 or not solution.V_A < 0.0):
            return  # the common answer: no strain beyond the limit, no anchor pulled up
    findings = []
    with np.errstate(invalid="ignore", divide="ignore"):
        strain = np.maximum(solution.T_A, solution.T_B) / solution.EA
    finding = _plausible.line_strain(strain if isinstance(strain, float) else np.asarray(strain))
    if finding is not None:
        findings.append(finding)
    seabed = getattr(solution, "seabed", None)
    if seabed is not None:
        on_bed = np.asarray(seabed) == 0.0
        angle = np.arctan2(-np.asarray(solution.V_A, dtype=float), np.asarray(solution.H_A, dtype=float))
        pulled = on_bed & (angle > _plausible.ANCHOR_UPLIFT)
        if np.any(pulled):
            found = _plausible.anchor_uplift(_first(angle, pulled), " at the anchor (V_A < 0: pulled up)")
            findings.append(found)
    _plausible.warn_all(f for f in findings if f is not None)
