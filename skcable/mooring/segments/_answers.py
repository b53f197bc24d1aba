"""The plausibility of a line's answer (`skcable._plausible` holds the limits and their sources):
each segment's strain against what its material survives (`Segment.material`), its tension
against the last point of its strain–tension table, and for
`Line.solve` the uplift angle at its anchor on the seabed; the findings are ``(quantity, reason)``
pairs, as `skcable.mooring._answers`'s for a system.

**Strain and tables.** The tension anywhere on a line differs from its largest end tension by at
most the weights and point loads along it, so that bound (through each segment's law) is checked
first (no table); only where it exceeds a limit are the segments' own largest tensions read
(``tensions()``: at a segment's end for the closed forms, sampled on a BVP's elements).
"""

from __future__ import annotations

import math

import numpy as np

from skcable import _plausible

__all__ = ["check_line", "line_findings"]


def _strains(segments, T) -> np.ndarray:
    """Each segment's strain at tension ``T`` (N: one value, or one per segment)."""
    T = np.broadcast_to(np.asarray(T, dtype=float), (len(segments),))
    return np.array([_strain(seg, t) for seg, t in zip(segments, T, strict=True)])


def _strain(seg, T: float) -> float:
    """A segment's strain at tension ``T``: its law's, or ``T/EA`` (a BVP's segment)."""
    law = getattr(seg, "law", None)
    if law is not None:
        return float(law.strain(np.array(float(T))))
    EA = getattr(seg, "EA", None)
    return float(T) / float(EA) if isinstance(EA, (int, float)) and EA > 0 else 0.0


def _limits(segments) -> np.ndarray:
    return np.array([_plausible.STRAIN_LIMITS[getattr(seg, "material", None)] for seg in segments])


def _material_of_row(segments, length, w):
    """The segment of a table's row (its ``length`` and ``w``: a line turned round lists them
    from its other end)."""
    for seg in segments:
        if math.isclose(seg.length, length, rel_tol=1e-12) and math.isclose(seg.w, w, rel_tol=1e-12):
            return seg
    return None


def _last_tensions(segments) -> np.ndarray:
    """Each segment's last tension (N) of its strain–tension table (`StrainTable`), inf without
    one."""
    tables = (getattr(getattr(seg, "law", None), "table", (None, [np.inf])) for seg in segments)
    return np.array([float(table[1][-1]) for table in tables])


def line_findings(solution, segments, largest_end: float, where: str = "") -> list:
    """The strain and table findings of one solved line: ``segments`` its model's,
    ``largest_end`` its largest end tension (N)."""
    load = sum(abs(seg.w) * seg.length for seg in segments)
    load += float(np.sum(np.abs(getattr(getattr(solution, "line", None), "joint_forces", 0.0))))
    bound = largest_end + load
    strained = np.any(_strains(segments, bound) > _limits(segments))
    if not (strained or np.any(bound > _last_tensions(segments))):
        return []
    table = solution.tensions()
    T = table["T_max"] if "T_max" in table else np.maximum(table["T_lower"], table["T_upper"])
    worst, beyond = None, None
    for length, w, tension in zip(table["length"], table["w"], T, strict=True):
        seg = _material_of_row(segments, float(length), float(w))
        if seg is None:
            continue
        material, tension = getattr(seg, "material", None), float(tension)
        strain, limit = _strain(seg, tension), _plausible.STRAIN_LIMITS[material]
        if strain > limit and (worst is None or strain / limit > worst[0] / worst[1]):
            worst = (strain, limit, material)
        last = float(_last_tensions([seg])[0])
        if tension > last and (beyond is None or tension / last > beyond[0] / beyond[1]):
            beyond = (tension, last)
    found = [] if worst is None else [_plausible.line_strain(worst[0], worst[2], "strain", where)]
    found += [] if beyond is None else [_plausible.beyond_table(*beyond, where)]
    return [f for f in found if f is not None]


def check_line(solution) -> None:
    """Warn the findings of `skcable.mooring.Line.solve`'s answer: its segments' strains and, its
    anchor on the seabed (``seabed=0``), the uplift angle at the anchor."""
    line = solution.line
    findings = line_findings(solution, line.segments, max(solution.T_A, solution.T_B))
    if line.seabed == 0.0 and solution.length_on_seabed == 0.0 and not solution.heap:
        angle = math.atan2(-solution.V_A + 0.0, solution.H_A)
        found = _plausible.anchor_uplift(angle, " at the anchor A")
        if found is not None:
            findings.append(found)
    _plausible.warn_all(findings)
