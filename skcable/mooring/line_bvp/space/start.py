r"""The closed-form starts of a line in space: the plane line's, in the vertical plane of its ends.

Anchor ``a`` and fairlead ``b``: the vertical plane through them has the horizontal unit
vector ``e = (b − a)_h/r``, ``r = |(b − a)_h|``, and ``dh = b_z − a_z``. The line of the mean
weight ``w̄ = (W + ΣP)/L`` (``W/L`` where a buoy makes that negative) and the mean compliance
(each segment's law at the weight of the line, `skcable.mooring.axial.StrainLaw.secant_EA`),
seen in that plane by `InPlane` (its seabed the profile under the chord,
`skcable.mooring.bathymetry.Bathymetry.along`), takes the plane line's starts
(`skcable.mooring.line_bvp.start`):

- `closed_form_start`: Irvine's elastic catenary (H.M. Irvine, "Cable Structures", MIT Press,
  1981, ch. 2; an inextensible line: the catenary) where it stays above the seabed; on a straight
  slope through the anchor the line on the slope (`skcable.cable.seabed.sloped_seabed_catenary`,
  Jonkman's line on the slope, with the scene's friction); on one below the anchor, the line
  touching down on it (`skcable.cable.seabed.slope_touchdown`); elsewhere
  Jonkman's grounded line on a flat seabed at the anchor's level (J.M. Jonkman, NREL, 2007),
  lifted onto the seabed where it dips below it; a line whose slack would lie in a heap on a flat
  seabed refused (``InputError("length")``);
- `lifted_start`: the lifted line on a sloped plane seabed too
  (`skcable.mooring.line_bvp.start.lifted_start`);
- `segmented_start`: the multi-segment closed form `skcable.mooring.Line` of the segments with
  their clump weights and buoys at the joints, on a flat seabed (`skcable.mooring.line_bvp.start
  .segmented_start`), for segments of constant weight and stiffness.

Each is mapped into space by ``r = a + x e + y e_z``: exact for one uniform segment without
current on a flat or plane seabed (up to the discretisation); the Newton iteration takes it from
there. A vertical line (``r = 0``) starts straight.

**In a current** without a seabed the start smears the drag as MoorPy does: the mean force per
length on the straight chord, ``f̄ = (1/L) ∫ f ds − w̄ e_z``, is taken as a uniform load, under
which the line hangs as a catenary of weight ``|f̄|`` in the plane of the chord and ``f̄`` (its
"up" ``−f̄/|f̄|``): exact for a taut straight line in a uniform current, and a start one or two
Newton iterations closer for the others.
"""

from __future__ import annotations

import numpy as np

from skcable.errors import InputError
from skcable.mooring.bathymetry import Plane
from skcable.mooring.line_bvp import start as plane_start
from skcable.mooring.line_bvp.space.vertical_plane import plane_of, plane_seabed

__all__ = [
    "InPlane",
    "closed_form_start",
    "frame_of",
    "in_plane",
    "lifted_start",
    "on_slope",
    "plane_of",
    "segmented_start",
    "uniform_line",
]


def uniform_line(problem):
    """``(w̄, EA)``: the mean weight (N/m) with the point loads, and the mean stiffness (N; inf
    for an inextensible line) at the line's weight."""
    L = problem.L
    w = (problem.weight + float(np.sum(problem.point_values))) / L
    if not w > 0:
        w = problem.weight / L
    if not w > 0:
        raise InputError("segments", f"the line's mean weight must be > 0 (downward), got {w:g} N/m")
    compliance = 0.0
    for seg in problem.segments:
        if seg.law is not None:
            compliance += seg.length / float(seg.law.secant_EA(np.array(w * L)))
    return w, (L / compliance if compliance > 0 else np.inf)


def frame_of(problem, w):
    """``(e, up, w)``: the plane of the start (its horizontal and upward unit vectors, (3,)) and
    the load per length in it (module docstring: the vertical plane, or the plane of the chord
    and the smeared load in a current without seabed)."""
    r, e, _ = plane_of(problem.anchor, problem.fairlead)
    vertical = (np.array([e[0], e[1], 0.0]), np.array([0.0, 0.0, 1.0]), w)
    if not problem.terms or problem.seabed is not None:
        return vertical
    f = np.sum(problem.chord_forces(w * problem.L) * problem.assembly.dx, axis=(1, 2)) / problem.L
    f[2] -= w
    size = float(np.linalg.norm(f))
    up = -f / size
    chord = problem.fairlead - problem.anchor
    across = chord - (chord @ up) * up
    if not np.linalg.norm(across) > 1e-6 * problem.L:  # the chord along the load: keep the vertical plane
        return vertical
    return across / np.linalg.norm(across), up, size


def on_slope(problem) -> bool:
    """Whether the start's grounded closed form is the line on the slope or touching down on it:
    a sloped `Plane` seabed (the plane line's `skcable.mooring.line_bvp.start.on_slope`)."""
    return isinstance(problem.seabed, Plane) and bool(np.any(problem.seabed.slope))


class InPlane:
    """A line in space seen in the plane of its start (`frame_of`): what the plane line's starts
    (`skcable.mooring.line_bvp.start`) read of a `skcable.mooring.line_bvp.problem.LineProblem`.

    The span and height of the fairlead in the plane (``e``, ``up``), the uniform line's load
    ``w`` and stiffness ``EA`` (`uniform_line`), the seabed under the chord relative to the
    anchor (`plane_seabed`: the profile, flat where the bathymetry is), the segments, point
    loads, friction and cable terms; `with_ends` maps the plane's ``[x, y]`` back into space."""

    def __init__(self, problem, e, up, w, EA):
        self.space, self.e, self.up = problem, e, up
        #: the line's cable terms (the current's drag among them): a line they load is not the
        #: uniform closed form's, whose heap is then no verdict on it
        self.terms = tuple(problem.terms)
        a = problem.anchor
        chord = problem.fairlead - a
        self.span, self.dh, self.L = float(chord @ e), float(chord @ up), problem.L
        self.start_weight = w
        self.compliance = 0.0 if np.isinf(EA) else problem.L / EA
        self.basis, self.tbasis = problem.basis, problem.tbasis
        self.segments, self.joints, self.weight = problem.segments, problem.joints, problem.weight
        self.point_loads, self.friction = problem.point_loads, problem.friction
        self.seabed = None
        bed = problem.seabed
        if bed is not None and up[2] == 1.0:
            self.seabed = plane_seabed(bed, a, e, problem.L)

    @property
    def constant(self) -> bool:
        """Whether every segment's stiffness is constant (what `skcable.mooring.Line` takes)."""
        return all(seg.law is None or seg.law.kind == "constant" for seg in self.segments)

    def tension_points(self) -> np.ndarray:
        """The tension dofs' arc lengths (`DiscreteLine.tension_points`)."""
        return self.space.tension_points()

    def with_ends(self, xy, T) -> np.ndarray:
        """The dofs in space of ``[x, y]`` in the plane and ``T``, the ends exact."""
        x, y = (np.asarray(c, dtype=float) for c in xy)
        a = self.space.anchor
        return self.space.with_ends([a[k] + x * self.e[k] + y * self.up[k] for k in range(3)], T)


def in_plane(problem) -> InPlane:
    """``problem`` seen in the plane of its start (`InPlane`)."""
    w, EA = uniform_line(problem)
    e, up, load = frame_of(problem, w)
    return InPlane(problem, e, up, load, EA)


def closed_form_start(problem) -> np.ndarray:
    """The first iterate on ``problem``'s dofs, ``[x, y, z, T]``, the ends exact (module
    docstring): the plane line's `skcable.mooring.line_bvp.start.closed_form_start` in the plane
    of the ends."""
    return _in_space(problem, plane_start.closed_form_start)


def lifted_start(problem) -> np.ndarray:
    """`closed_form_start`'s alternative on a sloped plane seabed: the flat grounded line lifted
    onto it (the plane line's `skcable.mooring.line_bvp.start.lifted_start` in the plane of the
    ends)."""
    return _in_space(problem, plane_start.lifted_start)


def _in_space(problem, start) -> np.ndarray:
    """The plane line's closed form ``start`` of ``problem`` seen in the plane of its ends; a
    vertical line (``r = 0``) straight, carrying the weight below each point."""
    a = problem.anchor
    r, _, dh = plane_of(a, problem.fairlead)
    if r == 0.0:
        w, _ = uniform_line(problem)
        s, s_t = problem.basis.doflocs[0], problem.tension_points()
        z = a[2] + s * dh / problem.L
        T = np.maximum(w * s_t, 1e-6 * w * problem.L)
        return problem.with_ends([np.full(s.size, a[0]), np.full(s.size, a[1]), z], T)
    return start(in_plane(problem))


def segmented_start(problem):
    """The start from the multi-segment closed form (`skcable.mooring.Line`, the plane line's
    `segmented_start`) in the vertical plane of the ends, or None where it does not describe the
    line (varying weights or strain laws, point loads between joints, a seabed that is not flat,
    a current without seabed, a vertical line)."""
    if plane_of(problem.anchor, problem.fairlead)[0] == 0.0:
        return None
    view = in_plane(problem)
    if not view.constant or view.up[2] != 1.0:
        return None
    return plane_start.segmented_start(view)
