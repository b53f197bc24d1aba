r"""The closed-form start of a line in space: the 2-D closed form in the vertical plane of its ends.

Anchor ``a`` and fairlead ``b``: the vertical plane through them has the horizontal unit
vector ``e = (b − a)_h/r``, ``r = |(b − a)_h|``, and ``dh = b_z − a_z``. The line of the mean
weight ``w̄ = (W + ΣP)/L`` and the mean compliance (each segment's law at the weight of the line,
`skcable.mooring.axial.StrainLaw.secant_EA`) hangs in that plane as

- Irvine's elastic catenary (H.M. Irvine, "Cable Structures", MIT Press, 1981, ch. 2;
  `skcable.cable.elastic_catenary`; an inextensible line: the catenary) where it stays above
  the seabed;
- else, on a plane seabed under an anchor that lies on it, the sloped closed form
  (`skcable.cable.seabed.sloped_seabed_catenary`, Jonkman's line on the slope along
  ``e``), and on any other seabed Jonkman's grounded line on a flat seabed at the anchor's level
  (J.M. Jonkman, NREL, 2007; `skcable.cable.seabed.elastic_catenary`), lifted onto the
  seabed where it dips below it;

and is mapped into space by ``r = a + x e + y e_z``. Exact for one uniform segment without
current on a flat or plane seabed (up to the discretisation); the Newton iteration takes it
from there. A vertical line (``r = 0``) starts straight.

**In a current** without a seabed the start smears the drag as MoorPy does: the mean force per
length on the straight chord, ``f̄ = (1/L) ∫ f ds − w̄ e_z``, is taken as a uniform load, under
which the line hangs as a catenary of weight ``|f̄|`` in the plane of the chord and ``f̄`` (its
"up" ``−f̄/|f̄|``): exact for a taut straight line in a uniform current, and a start one or two
Newton iterations closer for the others.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._catenary import catenary
from skcable.cable._elastic import elastic_catenary as free_elastic
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.bathymetry import Plane
from skcable.mooring.line_bvp.start import hanging

__all__ = ["closed_form_start", "frame_of", "on_slope", "plane_of", "uniform_line"]


def plane_of(anchor, fairlead):
    """``(r, e, dh)``: the horizontal distance (m), the unit horizontal direction (2,) from the
    anchor to the fairlead (x where they are on one vertical) and the height (m)."""
    d = np.asarray(fairlead, dtype=float) - np.asarray(anchor, dtype=float)
    r = float(np.hypot(d[0], d[1]))
    e = d[:2] / r if r > 0 else np.array([1.0, 0.0])
    return r, e, float(d[2])


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


def _in_plane(problem, r, dh, w, EA, sloped=True):
    """``(x(s), y(s), T(s))`` callables of the line in its plane (A at (0, 0)); ``sloped``: on
    a plane seabed through the anchor, the line on the slope (else the flat grounded line
    lifted onto it)."""
    L, bed = problem.L, problem.seabed
    if np.isinf(EA):
        free = catenary(r, dh, w, length=L)
        stiff = np.inf
    else:
        free, stiff = free_elastic(r, dh, w, EA, length=L), EA
    x, y, T = hanging(float(free.H), float(free.V_A), w, stiff)

    if bed is None:
        return x, y, T
    profile = bed.along(problem.anchor[:2], plane_of(problem.anchor, problem.fairlead)[1])
    s = np.linspace(0.0, L, 65)
    if np.all(y(s) >= profile(x(s)) - problem.anchor[2]):
        return x, y, T
    grounded = _grounded(problem, profile, r, dh, w, EA, sloped)
    if grounded is not None:
        x, y, T = grounded
    return x, lambda s: np.maximum(y(s), profile(x(s)) - problem.anchor[2]), T


def on_slope(problem) -> bool:
    """Whether the start's grounded closed form is the line on the slope: a `Plane` seabed
    through the anchor."""
    bed, a = problem.seabed, problem.anchor
    return isinstance(bed, Plane) and abs(float(bed.height(a[0], a[1])) - a[2]) <= 1e-9 * problem.L


def _grounded(problem, profile, r, dh, w, EA, sloped=True):
    """The grounded closed form in the plane (module docstring), or None where it fails."""
    from skcable.cable.seabed import elastic_catenary as grounded_elastic
    from skcable.cable.seabed import sloped_seabed_catenary

    L, a = problem.L, problem.anchor
    EA = 1e9 * w * L if np.isinf(EA) else EA
    level = float(profile(np.array(0.0))) - a[2]
    try:
        if sloped and isinstance(problem.seabed, Plane) and abs(level) <= 1e-9 * L:
            m = float(profile.slope(np.array(0.0)))
            line = sloped_seabed_catenary(r, dh, w, EA, length=L, seabed_slope=m, friction=problem.friction)
            return (lambda s: line.xy(s)[..., 0]), (lambda s: line.xy(s)[..., 1]), line.T_of_s
        line = grounded_elastic(r, dh, w, EA, length=L, seabed=min(level, 0.0))
        if np.any(line.heap):
            return None
        return line.x_of_s, line.y_of_s, line.T_of_s
    except (InputError, ConvergenceError):
        return None


def closed_form_start(problem, sloped=True) -> np.ndarray:
    """The first iterate on ``problem``'s dofs, ``[x, y, z, T]``, the ends exact (module
    docstring); ``sloped=False``: on a plane seabed through the anchor, the flat grounded line
    lifted onto it instead of the line on the slope (the alternative where Newton finds no
    descent from that one, as the plane line's `skcable.mooring.line_bvp.start.lifted_start`)."""
    a = problem.anchor
    r, _, dh = plane_of(a, problem.fairlead)
    w, EA = uniform_line(problem)
    s, s_t = problem.basis.doflocs[0], problem.tension_points()
    if r == 0.0:  # a vertical line: straight, carrying the weight below each point
        z = a[2] + s * dh / problem.L
        T = np.maximum(w * s_t, 1e-6 * w * problem.L)
        return problem.with_ends([np.full(s.size, a[0]), np.full(s.size, a[1]), z], T)
    e, up, load = frame_of(problem, w)
    chord = problem.fairlead - a
    x, y, T = _in_plane(problem, float(chord @ e), float(chord @ up), load, EA, sloped)
    xs, ys = np.asarray(x(s), dtype=float), np.asarray(y(s), dtype=float)
    X, Y, Z = (a[k] + xs * e[k] + ys * up[k] for k in range(3))
    return problem.with_ends([X, Y, Z], np.asarray(T(s_t), dtype=float))
