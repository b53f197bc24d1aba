r"""A line in space that hangs in the vertical plane of its ends, as the plane line's scene.

Anchor ``a`` and fairlead ``b`` span the vertical plane of the horizontal unit vector
``e = (b − a)_h/r`` (`plane_of`). A line whose loads all lie
in that plane, and whose seabed does not slope across it, hangs in it: without a current and
cable terms, on no seabed, or on a `skcable.mooring.bathymetry.Plane` whose gradient is along
``e`` (``∇b · e⊥ = 0``), with segments of constant stiffness (the plane line's). Its plane
problem (`skcable.mooring.line_bvp`) has the span ``r``, the height ``dh = b_z − a_z`` and the
seabed's profile under the chord, relative to the anchor (`plane_seabed`); a plane solution maps
into space by ``r(s) = a + x(s) e + y(s) e_z`` (`in_space`), the tension unchanged: on the same
mesh it is the line in space's discrete solution up to round-off, since both discretise the
same equations (`skcable.mooring.line_bvp.discrete.DiscreteLine`).
"""

from __future__ import annotations

import numpy as np

from skcable.mooring.bathymetry import Bathymetry, Plane
from skcable.mooring.line_bvp.contact import Seabed
from skcable.mooring.line_bvp.inputs import Scene

__all__ = ["in_space", "plane_of", "plane_scene", "plane_seabed"]


def plane_of(anchor, fairlead):
    """``(r, e, dh)``: the horizontal distance (m), the unit horizontal direction (2,) from the
    anchor to the fairlead (x where they are on one vertical) and the height (m)."""
    d = np.asarray(fairlead, dtype=float) - np.asarray(anchor, dtype=float)
    r = float(np.hypot(d[0], d[1]))
    e = d[:2] / r if r > 0 else np.array([1.0, 0.0])
    return r, e, float(d[2])


def plane_seabed(bed: Bathymetry, anchor, e, length: float) -> Seabed:
    """The seabed ``bed`` under the horizontal line from ``anchor`` along the unit ``e`` (m),
    relative to the anchor's height: the plane line's `Seabed` (flat where ``bed`` is; its
    curvature by differences of the profile's slope over 1e-6 of the ``length``)."""
    a = np.asarray(anchor, dtype=float)
    profile = bed.along(a[:2], e[:2])
    flat = getattr(bed, "flat", None)
    straight = None
    if isinstance(bed, Plane):  # a plane is straight along any line
        straight = (float(profile(np.zeros(1))[0]) - a[2], float(bed.slope @ np.asarray(e[:2], dtype=float)))
    return Seabed(
        function=lambda x: profile(x) - a[2],
        slope_fn=profile.slope,
        flat=None if flat is None else flat - a[2],
        step=1e-6 * length,
        straight=straight,
    )


def plane_scene(scene, time_limit: float) -> Scene | None:
    """The plane line's `Scene` of the line in space ``scene`` (a ``Scene3D``) in the vertical
    plane of its ends (module docstring), solved within ``time_limit`` (s); None where the line
    does not hang in that plane (a current or cable terms, a seabed that is not a `Plane`
    sloping along the chord, a strain law that is not a constant stiffness) or is vertical."""
    a = scene.anchor
    r, e, dh = plane_of(a, scene.fairlead)
    if not r > 0 or scene.current is not None or scene.terms:
        return None
    if not all(seg.law is None or seg.law.kind == "constant" for seg in scene.segments):
        return None
    bed = scene.seabed
    seabed = None
    if bed is not None:
        if not isinstance(bed, Plane):
            return None
        across = float(bed.slope @ np.array([-e[1], e[0]]))
        if not abs(across) <= 1e-12 * (1.0 + float(np.hypot(*bed.slope))):
            return None
        seabed = plane_seabed(bed, a, e, scene.length)
    return Scene(
        span=r,
        dh=dh,
        segments=scene.segments,
        point_loads=scene.point_loads,
        seabed=seabed,
        friction=scene.friction,
        n_elements=scene.n_elements,
        fit_touchdown=scene.fit_touchdown,
        options=scene.options,
        time_limit=time_limit,
    )


def in_space(problem, old, z) -> np.ndarray:
    """The plane line ``old``'s dofs ``z`` on ``problem``'s dofs (a line in space on the same
    ends): positions ``a + x e + y e_z`` at its nodes, tensions just inside its elements
    (`skcable.mooring.line_bvp.start.restart`'s interpolation), the ends exact."""
    a, (_, e, _) = problem.anchor, plane_of(problem.anchor, problem.fairlead)
    x, y = old.state_at(z, problem.basis.doflocs[0]).position
    position = [a[0] + x * e[0], a[1] + x * e[1], a[2] + y]
    return problem.with_ends(position, old.tension_at(z, problem.tension_points()))
