"""The scene of one line in space, checked: segments, attachments, seabed, current, options.

`LineSegment` is one segment (length, weight, axial law, diameter and drag coefficients), the
plane line's (`skcable.mooring.line_bvp.inputs`);
`scene` checks every argument of `solve_line_bvp_3d` (each refusal an `skcable.InputError`
naming the argument as the public API spells it) and returns a `Scene3D`, which the solver
(`skcable.mooring.line_bvp.space.driver`) takes as it is.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, one_of, point, positive, scalar, whole
from skcable.bvp.current import Current, current_of
from skcable.errors import InputError
from skcable.fe import NewtonOptions
from skcable.mooring.bathymetry import Bathymetry, Plane, bathymetry_of
from skcable.mooring.line_bvp.check import refuse_slack_on_slope
from skcable.mooring.line_bvp.inputs import (
    LINE_OPTIONS,
    LineSegment,
    newton_options_of,
    point_loads_of,
    segments_of,
    terms_of,
)
from skcable.mooring.line_bvp.resolution import elements_option
from skcable.mooring.line_bvp.space.vertical_plane import plane_scene

__all__ = [
    "MESHES",
    "LineSegment",
    "Scene3D",
    "attachments_of",
    "checked_options",
    "mesh_of",
    "point",
    "scene",
    "segments_of",
]

#: the meshes of a line on a seabed (`solve_line_bvp_3d`'s ``mesh``)
MESHES = ("graded", "uniform")


def attachments_of(attachments, n_segments: int) -> list[tuple[int, float]]:
    """Point loads at the joints as ``(joint, P)`` pairs, ``P`` downward (N; negative for a buoy):
    from ``(joint, P)`` pairs or objects with ``joint`` and ``force`` (`skcable.mooring.ClumpWeight`,
    `skcable.mooring.Buoy`); joints 1 to ``n_segments − 1`` (the ends are supports)."""
    out = []
    try:
        items = list(attachments)
    except TypeError:
        raise InputError("attachments", f"must be a sequence of (joint, P), got {attachments!r}") from None
    for item in items:
        if hasattr(item, "joint") and hasattr(item, "force"):
            joint, P = item.joint, item.force
        else:
            try:
                joint, P = item
            except (TypeError, ValueError) as exc:
                raise InputError(
                    "attachments", f"each is (joint, P) or a ClumpWeight/Buoy, got {item!r}"
                ) from exc
        joint = whole("attachments", joint, 1, n_segments - 1) if n_segments > 1 else None
        if joint is None:
            raise InputError("attachments", "a line of one segment has no inner joint to attach to")
        out.append((int(joint), float(scalar("attachments", P))))
    return out


@dataclass(frozen=True)
class Scene3D:
    """A checked scene and the solver's options (the arguments of `solve_line_bvp_3d`)."""

    anchor: np.ndarray
    fairlead: np.ndarray
    segments: list
    attachments: list
    loads: list
    seabed: Bathymetry | None
    friction: float
    current: Current | None
    rho_water: float
    terms: tuple
    n_elements: int
    fit_touchdown: int
    mesh: str
    options: NewtonOptions = LINE_OPTIONS
    time_limit: float = 60.0

    @property
    def length(self) -> float:
        """Unstretched length of the line (m)."""
        return float(sum(seg.length for seg in self.segments))

    @property
    def joints(self) -> np.ndarray:
        """Arc length of every joint from the anchor (m), ends included."""
        return np.concatenate([[0.0], np.cumsum([seg.length for seg in self.segments])])

    @property
    def point_loads(self) -> list[tuple[float, float]]:
        """Every point load as ``(s, P)``: the attachments at the arc length of their joint, then
        the point loads given by arc length (m); downward force (N)."""
        return [(float(self.joints[k]), P) for k, P in self.attachments] + self.loads


def checked_options(segments, options: dict) -> dict:
    """The arguments of `solve_line_bvp_3d` but the ends, checked: the segments (`segments_of`),
    the attachments, the point loads, seabed, friction, current, density, terms and solver options
    (the Newton options as the plane line's, `skcable.mooring.line_bvp.inputs.newton_options_of`:
    ``options``, ``rtol``, ``max_iter`` and the other fields of `skcable.fe.NewtonOptions` in
    ``newton_options``)."""
    segs = segments_of(segments)
    bed = bathymetry_of(options["seabed"])
    friction = scalar("friction", nonnegative("friction", options["friction"]))
    _plausible.friction(friction)
    if friction > 0 and bed is None:
        raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
    current = current_of(options["current"])
    if current is not None and not any(seg.drags for seg in segs):
        raise InputError("current", "drags no segment: give the segments a diameter and drag coefficients")
    return dict(
        segments=segs,
        attachments=attachments_of(options["attachments"], len(segs)),
        loads=point_loads_of(options.get("point_loads", ()), sum(seg.length for seg in segs)),
        seabed=bed,
        friction=friction,
        current=current,
        rho_water=scalar("rho_water", positive("rho_water", options["rho_water"])),
        terms=terms_of(options["terms"]),
        n_elements=elements_option(options["n_elements"]),
        fit_touchdown=whole("fit_touchdown", options["fit_touchdown"], 0, 10),
        mesh=mesh_of(options.get("mesh", "graded")),
        options=newton_options_of(
            options.get("options"),
            rtol=options.get("rtol"),
            max_iter=options.get("max_iter"),
            **options.get("newton_options", {}),
        ),
        time_limit=scalar("time_limit", positive("time_limit", options.get("time_limit", 60.0))),
    )


def mesh_of(mesh) -> str:
    """``mesh``, checked: ``"graded"`` or ``"uniform"`` (`solve_line_bvp_3d`)."""
    return one_of("mesh", mesh, MESHES)


def scene(anchor, fairlead, checked: dict) -> Scene3D:
    """The scene between ``anchor`` and ``fairlead`` of the `checked_options` ``checked``."""
    a, b = point("anchor", anchor), point("fairlead", fairlead)
    if not np.hypot(*(b[:2] - a[:2])) > 0 and not b[2] > a[2]:
        raise InputError("fairlead", "must lie above the anchor where it is not beside it")
    bed = checked["seabed"]
    if bed is not None:
        at_a = float(bed.height(a[0], a[1]))
        if a[2] < at_a - 1e-9 * max(1.0, abs(at_a)):
            raise InputError(
                "seabed", f"must be at or below the anchor (z = {a[2]:g} m), got {at_a:g} m there"
            )
        if not b[2] > float(bed.height(b[0], b[1])):
            raise InputError("fairlead", "must lie above the seabed")
    out = Scene3D(anchor=a, fairlead=b, **checked)
    plane = plane_scene(out, out.time_limit) if isinstance(bed, Plane) else None
    if plane is not None:  # in its vertical plane: the plane line's refusals of the data hold
        refuse_slack_on_slope(plane)
    return out
