"""The plausibility of a mooring equilibrium (`skcable._plausible` holds the limits and their
sources): each line's strain (`skcable.mooring.segments._answers`), the uplift angle at each
anchor on the seabed, a body clear of the water that keeps its buoyancy, a body's point or a
free point below the seabed. Each function returns its findings, ``(quantity, reason)`` pairs;
an equilibrium with a finding is not ``stable`` (not physically admissible).
"""

from __future__ import annotations

import math

import numpy as np

from skcable import _plausible
from skcable.mooring.checks import anchor_forces
from skcable.mooring.network import largest_end_tension
from skcable.mooring.segments._answers import line_findings

__all__ = ["equilibrium_findings"]


def _bodies(eq) -> list:
    found = []
    for state in eq.bodies:
        body = state.body
        points = [state.offset]
        if len(state.local_points):
            points.append(state.offset + state.local_points @ state.rotation.T)
        cog = getattr(body, "center_of_gravity", None)
        if cog is not None:
            points.append(state.offset + state.rotation @ cog)
        z = float(np.concatenate([np.atleast_2d(p)[:, 2] for p in points]).min())
        where = f"body {state.index}"
        found.append(
            _plausible.body_height(z, float(state.offset[2]), body.volume, body.waterplane_area, where)
        )
        found.append(_plausible.below_seabed(z, eq.depth, f"a point of {where}"))
    found += [
        _plausible.below_seabed(float(p.position[2]), eq.depth, f"free point {p.index}")
        for p in eq.points
        if p.kind == "free"
    ]
    return [f for f in found if f is not None]


def _anchors(eq) -> list:
    """The uplift at each fixed point on the seabed (``z = -depth``) that holds a line (a fixed
    point in the water takes any direction)."""
    if eq.depth is None:
        return []
    found = [
        _plausible.anchor_uplift(math.atan2(F[2], math.hypot(F[0], F[1])), f" at anchor point {j}")
        for j, (F, _) in anchor_forces(eq).items()
        if not abs(float(eq.points[j].position[2]) + eq.depth) > 1e-9 * eq.depth
    ]
    return [f for f in found if f is not None]


def equilibrium_findings(eq) -> list:
    """The findings of a `skcable.mooring.MooringEquilibrium`: each line's strain, the anchors on the
    seabed, the bodies and the free points."""
    findings = []
    for k, handle, line in zip(eq.line_indices, eq.handles, eq.lines, strict=True):
        segments = getattr(handle.model, "segments", None)
        if segments is None:
            continue
        findings += line_findings(line, segments, largest_end_tension(line), f" on line {k}")
    return findings + _anchors(eq) + _bodies(eq)
