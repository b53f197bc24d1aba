r"""Anchor and line checks of a mooring system at equilibrium: anchor loads, uplift, grounded length, MBL.

From a `skcable.mooring.MooringEquilibrium` (only its lines' end forces and tables are read):

- **anchor loads**: at each fixed point, the sum of the forces its lines exert on it,
  :math:`\mathbf F`; its horizontal load :math:`|\mathbf F_{xy}|`, its vertical load
  :math:`F_z` (positive upwards: uplift) and the uplift angle
  :math:`\operatorname{atan2}(F_z, |\mathbf F_{xy}|)`, the load's elevation above the horizontal;
- **each line**: its end tensions, grounded (unstretched) length and the touchdown's horizontal
  distance from its lower end, and its angle above the horizontal at its lower end (the
  direction of its tension there: 0 where it rests on the seabed up to a touchdown); for a line
  in the sea (`skcable.mooring.sea_line.LineInSeaBetween`) the lower end is its fixed one
  and the model the one `skcable.mooring.line_3d` chose;
- **each segment with a minimum breaking load**: its largest tension ``T_max`` against its
  ``MBL`` with a safety factor ``SF``: the utilisation :math:`SF\,T_{\max}/MBL` (at most 1 passes).
  The factor is the design code's for the condition checked (intact or damaged, quasi-static or
  dynamic): give it; none is assumed.
"""

from __future__ import annotations

import math

import numpy as np

from skcable._checks import positive, scalar
from skcable.errors import InputError
from skcable.mooring.network import end_forces

__all__ = ["anchor_forces", "anchor_loads", "line_checks", "segment_checks"]


def anchor_loads(eq):
    """One row per fixed point that holds a line: ``point``, ``lines`` (how many), ``Fx, Fy, Fz``
    (the lines' force on it, N, global axes), ``horizontal``, ``vertical`` (N; upwards positive:
    uplift), ``uplift_angle`` (rad) and ``uplift_angle_deg``, a `pandas.DataFrame`."""
    import pandas as pd

    rows = []
    for j, (F, count) in anchor_forces(eq).items():
        horizontal = math.hypot(F[0], F[1])
        angle = math.atan2(F[2], horizontal) + 0.0  # + 0.0: no -0
        row = {"point": j, "lines": count, "Fx": F[0], "Fy": F[1], "Fz": F[2], "horizontal": horizontal}
        row.update(vertical=F[2], uplift_angle=angle, uplift_angle_deg=math.degrees(angle))
        rows.append(row)
    return pd.DataFrame(rows)


def anchor_forces(eq) -> dict:
    """``{fixed point: (F, n)}`` in the order of the points: the sum ``F`` (N, global axes) of the
    forces of the ``n`` lines of the equilibrium ``eq`` that hold it."""
    totals: dict = {}
    for handle, line in zip(eq.handles, eq.lines, strict=True):
        for end, force in zip((handle.a, handle.b), end_forces(line), strict=True):
            if end.kind == "fixed":
                F, n = totals.get(end.index, (0.0, 0))
                totals[end.index] = (F + force, n + 1)
    return dict(sorted(totals.items()))


def _lower_angle(line, lower) -> float:
    """The line's angle above the horizontal at its lower end (rad): the direction of its pull there."""
    F = end_forces(line)[lower]  # the line's force on its lower end points along the line
    return math.atan2(F[2], math.hypot(F[0], F[1])) + 0.0  # + 0.0: no -0


def line_checks(eq):
    """One row per line: ``line``, ``model``, ``T_a``, ``T_b`` (N), ``lower_end`` (``"a"`` or
    ``"b"``), ``grounded_length`` (m, unstretched), ``x_touchdown`` (m, the touchdown's horizontal
    distance from the lower end; 0 where the line does not rest on the seabed) and ``lower_angle``
    (rad) with ``lower_angle_deg``: the line's angle above the horizontal at its lower end."""
    import pandas as pd

    rows = []
    for k, line in zip(eq.line_indices, eq.lines, strict=True):
        F = end_forces(line)
        plane = getattr(line, "plane", None)
        sea = getattr(line, "sea", None)  # a line in the sea: its lower end is its fixed one
        lower = int(plane.reversed if plane is not None else line.reversed if sea is not None else 0)
        solution = line if sea is not None else line.solution
        grounded = float(getattr(solution, "length_on_seabed", 0.0))
        touchdown = float(getattr(solution, "x_touchdown", 0.0)) if grounded > 0 else 0.0
        angle = _lower_angle(line, lower)
        row = {"line": k, "model": line.model if plane is not None or sea is not None else "as given"}
        row.update(T_a=float(np.linalg.norm(F[0])), T_b=float(np.linalg.norm(F[1])), lower_end="ab"[lower])
        row.update(grounded_length=grounded, x_touchdown=touchdown, lower_angle=angle)
        row.update(lower_angle_deg=math.degrees(angle))
        rows.append(row)
    return pd.DataFrame(rows)


def _segments_of(line):
    """The segments of a solved line from its end a (those of its `skcable.mooring.Line`, in order)."""
    plane = getattr(line, "plane", None)
    if plane is not None:
        segments = plane.solution_line.segments
        return segments[::-1] if plane.reversed else segments
    return getattr(getattr(line, "line", None) or line.model, "segments", ())  # a LineInSea: its Line


def segment_checks(eq, safety_factor):
    """One row per segment with a minimum breaking load (``Segment(mbl=...)``): ``line``,
    ``segment`` (from a), ``T_max`` (N), ``mbl`` (N), ``safety_factor``, ``utilisation``
    (``safety_factor * T_max / mbl``) and ``ok`` (utilisation at most 1).

    Raises `InputError` naming ``safety_factor`` (not > 0) or ``mbl`` (no segment has one)."""
    import pandas as pd

    sf = scalar("safety_factor", positive("safety_factor", safety_factor))
    rows = []
    for k, line in zip(eq.line_indices, eq.lines, strict=True):
        table = line.tensions()
        T_max = table["T_max"] if "T_max" in table else np.maximum(table["T_lower"], table["T_upper"])
        for i, segment in enumerate(_segments_of(line)):
            if getattr(segment, "mbl", None) is None:
                continue
            T = float(T_max.iloc[i])
            row = {"line": k, "segment": i, "T_max": T, "mbl": segment.mbl, "safety_factor": sf}
            row.update(utilisation=sf * T / segment.mbl, ok=sf * T <= segment.mbl)
            rows.append(row)
    if not rows:
        raise InputError(
            "mbl", "no segment of the lines has a minimum breaking load: give Segment(..., mbl=)"
        )
    return pd.DataFrame(rows)
