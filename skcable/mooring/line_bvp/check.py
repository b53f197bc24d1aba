r"""The equilibrium residual of a solved line BVP, by an assembly independent of the solve's.

`equilibrium_field` assembles the weak residual of the converged fields with scikit-fem's own
``asm`` and forms (``LinearForm``, ``BilinearForm``) from the fields interpolated by scikit-fem
(``Basis.interpolate``), not the solve's `skcable.fe.Assembly`, and returns the Galerkin
projection ``ρ`` of ``d(T t)/ds + q`` at the quadrature points with its round-off floor
(`skcable.mooring.line_bvp.fields`), in the plane or in space; `strong_residual` the pointwise
``|d(T t)/ds + q|`` inside the elements, ``d(T t)/ds = T' t + T (I − t tᵀ) r''/|r'|``
(``r''`` constant in a P2 element). `refuse_sliding` refuses a line whose compression lies on
the seabed from the anchor (it has no equilibrium in tension); `refuse_slack_on_slope` one
longer than a frictionless straight slope holds taut between two ends above it (its slack heaps
at the slope's foot: `skcable.cable.seabed.taut_length_on_slope`, exact for one uniform segment);
`partial_friction` says in a failure's message where friction, fully mobilised, may take more
than a line's pull (the model does not describe that line), `slack_on_slope` where a line over
such a slope may be longer than it holds taut. `unresolved` says where the mesh does not resolve a
converged line (an element that turns through a bend within itself, or a weight that varies
within an element), and `warn_unresolved` warns it from a public solve.
"""

from __future__ import annotations

import warnings

import numpy as np
from skfem import BilinearForm, LinearForm, asm

from skcable import _plausible
from skcable.bvp.terms import CableState
from skcable.cable.seabed import refuse_slack_on_slope as refuse_uniform_slack
from skcable.cable.seabed import taut_length_on_slope
from skcable.errors import ConvergenceError, InputError, ResolutionWarning
from skcable.mooring.line_bvp.mesh import composite_gauss
from skcable.mooring.line_bvp.start import uniform_on_slope

__all__ = [
    "RESOLVED_BEND",
    "RESOLVED_WEIGHT",
    "element_bends",
    "equilibrium_field",
    "partial_friction",
    "refuse_slack_on_slope",
    "refuse_sliding",
    "slack_on_slope",
    "strong_residual",
    "unresolved",
    "unresolved_bend",
    "unresolved_weight",
    "warn_unresolved",
    "weight_quadrature_error",
]

EPS = float(np.finfo(float).eps)
#: how close to the longest length a frictionless slope holds taut (a fraction of it) a failing
#: line is said to be nearly slack there (`slack_on_slope`)
NEARLY_SLACK = 0.02
#: how much steeper than μ the seabed must rise at the anchor (the line's discrete tangent there,
#: a slope) for `refuse_sliding` to refuse: a flat seabed's round-off slope never does
SLOPE_TOL = 1e-6
#: the largest bend ``θ_e (h_e/L)^(1/4)`` of an element in a line whose end forces its mesh resolves
#: (`unresolved`; calibrated by `benchmarks/line_bvp_resolution.py`)
RESOLVED_BEND = 0.14
#: the largest share of a line's weight its mesh's quadrature may misplace in a line whose end
#: forces its mesh resolves (`unresolved_weight`), and the Gauss–Legendre points of the reference
#: on each half of an element (`weight_quadrature_error`)
RESOLVED_WEIGHT, WEIGHT_POINTS = 1e-5, 8


@LinearForm
def _weak(v, w):
    return w["Te"] * v.grad[0] - w["f"] * v


@BilinearForm
def _mass(u, v, w):
    return u * v


def _fields(solution):
    """``(r, a, T, T', f)`` at the quadrature points in scikit-fem's layout (…, ne, nq)."""
    problem, z = solution.problem, solution.dofs
    basis, N, dim = problem.basis, problem.N, problem.dim
    fields = [basis.interpolate(z[k * N : (k + 1) * N]) for k in range(dim)]
    tension = problem.tbasis.interpolate(z[dim * N :])
    r = np.array([np.asarray(f) for f in fields])
    a = np.array([f.grad[0] for f in fields])
    T, dT = np.asarray(tension), tension.grad[0]
    s = np.asarray(basis.global_coordinates())[0]
    f = np.zeros_like(r)
    f[-1] = -problem.w_q.T
    state = CableState.at(r, s, a, T)
    for term in problem.terms:
        f = f + term.forces(state).f
    return r, a, T, dT, f


def equilibrium_field(solution):
    """``(|ρ|, floor)``: the projected residual's size (N/m) at the quadrature points (ne, nq)
    and its round-off floor (N/m)."""
    import scipy.sparse.linalg as spla

    problem = solution.problem
    basis, N, dim = problem.basis, problem.N, problem.dim
    _, a, T, _, f = _fields(solution)
    e = a / np.sqrt(np.sum(a * a, axis=0))
    R = np.array([asm(_weak, basis, Te=T * e[k], f=f[k]) for k in range(dim)])
    np.add.at(R[-1], problem.point_rows - (dim - 1) * N, problem.point_values)
    rows, terms = problem.contact_rows, solution.state.terms
    if rows is not None:
        normal, friction = rows.forces(terms)  # the seabed's forces at its nodes
        R[:, rows.nodes] -= normal + friction
    inner = problem.free[problem.free < N]
    M = asm(_mass, basis).tocsr()
    block = M[inner][:, inner].tocsc()
    rho = np.zeros((dim, N))
    rho[:, inner] = spla.spsolve(block, -R[:, inner].T).T
    at_points = np.array([np.asarray(basis.interpolate(rho[k])) for k in range(dim)])
    # the floor: every dof moved by its rounding changes the rows by ε |J| |z| (N), over the mass
    rounding = problem.rounding(solution.state)[: dim * N].reshape(dim, N)
    lumped = np.asarray(abs(M).sum(axis=1)).ravel()
    floor = 64.0 * float(np.max(np.sqrt(np.sum(rounding[:, inner] ** 2, axis=0)) / lumped[inner]))
    return np.sqrt(np.sum(at_points * at_points, axis=0)), floor


def strong_residual(solution) -> np.ndarray:
    """``|d(T t)/ds + f|`` (N/m) at the quadrature points (ne, nq), the seabed's and the point
    loads' forces aside (they act at nodes)."""
    _, a, T, dT, f = _fields(solution)
    problem, z = solution.problem, solution.dofs
    # r'' per element of P2, from its end and middle values: 4 (r_0 − 2 r_m + r_1)/h²
    dofs, N, dim = problem.basis.element_dofs, problem.N, problem.dim
    h = np.diff(problem.mesh.p[0, problem.mesh.t], axis=0)[0]
    da = np.array(
        [
            4.0 * (zk[dofs[0]] - 2.0 * zk[dofs[2]] + zk[dofs[1]]) / (h * h)
            for zk in z[: dim * N].reshape(dim, N)
        ]
    )
    da = np.broadcast_to(da[:, :, None], a.shape)
    n = np.sqrt(np.sum(a * a, axis=0))
    t = a / n
    bend = da - np.sum(t * da, axis=0) * t  # (I − t tᵀ) r''
    r = dT * t + T * bend / n + f
    return np.sqrt(np.sum(r * r, axis=0))


def refuse_sliding(problem, z, tol, friction) -> None:
    """Raise ``InputError("friction")`` where the discrete line ``z`` of ``problem`` is in
    compression on the seabed from the anchor (`DiscreteLine.sliding_to_anchor`) and the seabed
    rises there more steeply than ``friction`` holds (``tan α > μ`` + `SLOPE_TOL`): the scene has no
    equilibrium with the line in tension, whatever the mesh; ``tol`` Newton's tolerance. (Where
    ``tan α ≤ μ`` friction can hold a slack stretch near the anchor, which both lines model.)"""
    slope = problem.sliding_to_anchor(z, tol)
    if slope is None or not slope > friction + SLOPE_TOL:
        return
    T = z[problem.dim * problem.N :]
    raise InputError(
        "friction",
        f"μ = {friction:g} does not hold the line lying on the seabed from the anchor, which rises "
        f"along it (tan α = {slope:.3g} there): its weight along the slope pushes it against the "
        f"anchor (min T = {np.min(T):.3g} N in the discrete line), and it would slide down; the scene "
        "has no equilibrium with the line in tension (more friction, a shorter line or a seabed "
        "that does not rise from the anchor)",
    )


def partial_friction(failed, friction, without_friction) -> ConvergenceError:
    """``failed`` (the solve with friction's `skcable.ConvergenceError`), its message saying
    where, on the same line solved without friction (``without_friction()``, None where the
    anchor lies on the seabed: there both lines model the slack stretch), ``μ`` times the
    seabed's normal force exceeds the tension at the touchdown: friction fully mobilised along
    the grounded stretch (J.M. Jonkman, NREL, 2007: the model of both lines) may then take the
    whole pull before the landing, and the line rest with its friction partly mobilised, a state
    that depends on how it was laid and that this model does not describe. A diagnosis, not a
    proof (such a line may still have a solution with friction fully mobilised, its touchdown
    moved): the error stays a `ConvergenceError`, with ``failed``'s history and last iterate;
    ``failed`` as it is where the line without friction fails too."""
    if without_friction is None or not friction > 0:
        return failed
    try:
        frictionless = without_friction()
    except ConvergenceError:
        return failed
    on = frictionless.in_contact
    if not on.any():
        return failed
    normal = float(np.sum(frictionless.normal_force[on]))
    s_touchdown = float(np.max(frictionless.contact_s[on]))
    pull = float(frictionless.T_of_s(np.array([s_touchdown]))[0])
    if not (pull > 0 and friction * normal > pull):
        return failed
    message = str(failed).rsplit(" (last ", 1)[0] if failed.history else str(failed)
    taken = friction * normal
    return ConvergenceError(
        f"{message}; fully mobilised (μ = {friction:g}), friction would take μN = {taken:.4g} N "
        f"on the stretch the line lies on the seabed, {taken / pull:.3g} times the pull at its "
        f"touchdown without friction ({pull:.4g} N): with its anchor above the "
        "seabed the line may rest with friction partly mobilised, which this model (Coulomb friction "
        "fully mobilised along the line) does not describe; friction=0 gives the line without it",
        failed.history,
        last=failed.last,
        attempts=failed.attempts,
    )


def refuse_slack_on_slope(scene) -> None:
    """``InputError("length")`` where the plane line's ``scene`` (`skcable.mooring.line_bvp.inputs.Scene`)
    is one uniform segment without friction, point loads or cable terms between two ends above a
    straight sloped seabed (``Seabed.straight``) and longer than that slope holds taut
    (`skcable.cable.seabed.refuse_slack_on_slope`): it has no equilibrium in tension, and the
    solve would stagnate on its slack."""
    bed, segments = scene.seabed, scene.segments
    if bed is None or bed.straight is None or scene.friction > 0 or scene.point_loads or scene.terms:
        return
    level, slope = bed.straight
    L = sum(seg.length for seg in segments)
    w = segments[0].w
    if len(segments) != 1 or slope == 0.0 or callable(w) or not w > 0 or not level < -1e-12 * L:
        return
    law = segments[0].law
    EA = np.inf if law is None else float(law.EA)
    refuse_uniform_slack(scene.span, scene.dh, float(w), EA, L, seabed=level, seabed_slope=slope)


def _taut_length(problem) -> float | None:
    """The longest uniform line of ``problem``'s mean weight and compliance that its straight
    seabed sloping below A holds taut without friction (m; `skcable.mooring.line_bvp.start.uniform_on_slope`),
    or None where the seabed is not such a slope or the line is not heavy, or the problem is not a
    plane line's (a line in space's seabed is a `skcable.mooring.bathymetry.Bathymetry`, without
    ``straight``)."""
    scene = None if getattr(problem.seabed, "straight", None) is None else uniform_on_slope(problem)
    if scene is None:
        return None
    w, EA, level, slope = scene
    return taut_length_on_slope(problem.span, problem.dh, w, EA, seabed=level, seabed_slope=slope)


def slack_on_slope(failed, problem) -> ConvergenceError:
    """``failed``, saying where the frictionless line of ``problem`` over a straight slope below
    both ends is longer than its uniform line of the same mean weight and compliance could hang
    taut there (`skcable.cable.seabed.taut_length_on_slope`; `refuse_slack_on_slope` refuses one
    uniform segment): its slack may slide to the slope's foot and heap there, a state without
    tension that the solve cannot reach; or within `NEARLY_SLACK` of that length, nearly slack
    where it lands on the slope's lower side. A diagnosis, not a proof (segments of other weights hang
    otherwise, and a buoy's arch takes up slack: the message says so where the line has buoys; in
    the differential survey, seeds 1–3, the minimum of the lumped line's energy,
    ``benchmarks/line_energy_minimum.py``, had no taut state for 14 of the 18 lines so diagnosed,
    was marginal for 1 and taut for 3: two with buoys, and one said to be nearly slack, whose
    least tension is 10 N): the error stays a `ConvergenceError`, with ``failed``'s history and
    last iterate."""
    longest = _taut_length(problem)
    if longest is None or not problem.L > (1.0 - NEARLY_SLACK) * longest:
        return failed
    message = str(failed).rsplit(" (last ", 1)[0] if failed.history else str(failed)
    uniform = f"its uniform line (its mean weight, {problem.start_weight:.4g} N/m)"
    if problem.L > longest:
        why = (
            f"{uniform} is longer than the {longest:.6g} m this frictionless slope holds taut between its "
            "ends: the line may have no taut state, its slack sliding down to the slope's foot to lie there "
            "in a heap"
        )
        if np.any(problem.point_values < 0):  # a buoy's arch can take the slack up
            why += ", unless its buoys hold it taut (their arches take up length the uniform line has not)"
    else:
        why = (
            f"{uniform} is within {100.0 * (1.0 - problem.L / longest):.2g} % of the {longest:.6g} m this "
            "frictionless slope holds taut between its ends: it is nearly slack where it lands on the "
            "slope's lower side, which Newton may not resolve"
        )
    return ConvergenceError(f"{message}; {why}", failed.history, last=failed.last, attempts=failed.attempts)


def unresolved(solution) -> str:
    """Why the mesh does not resolve the converged line ``solution`` (a
    `skcable.mooring.line_bvp.fields.LineFields`), else ``""``: a bend (`unresolved_bend`), a
    weight varying along the line (`unresolved_weight`), or both. The equilibrium residual and the
    contact checks do not see either: the discrete equations hold to round-off on the coarse
    mesh. On the survey's scenes solved on 12 to 256 elements against 1024
    (`benchmarks/line_bvp_resolution.py`, its table in docs/bvp.md) the two flag every line off
    by more than 1e-4 of its largest end force (125 of 125) and pass none off by more than 3.2e-5;
    a quarter of the lines they flag are within 1e-5 (65 of 257): a warning says the mesh may be
    too coarse, and more elements settle it."""
    return "; ".join(filter(None, (unresolved_bend(solution), unresolved_weight(solution.problem))))


def element_bends(solution) -> tuple[np.ndarray, np.ndarray]:
    """``(bends, nodes)``: each element's bend ``θ_e (h_e/L)^(1/4)`` (`unresolved_bend`), the
    elements in order along the line, and the mesh's nodes (m of arc length, sorted)."""
    nodes = np.sort(solution.problem.mesh.p[0])
    return solution.element_turning * (np.diff(nodes) / solution.problem.L) ** 0.25, nodes


def unresolved_bend(solution) -> str:
    """Why the mesh does not resolve a bend of ``solution``, where an element's bend
    ``θ_e (h_e/L)^(1/4)`` exceeds `RESOLVED_BEND` (``θ_e`` the angle its tangent turns within it,
    ``element_turning``; ``h_e`` its length, ``L`` the line's: `element_bends`), else ``""``.

    P2 elements follow a bend of a few tenths of a radian each; a short element can turn through
    more at a small cost to the end forces (a chain's bend of 1 cm radius at its lowest point, in
    an element of 9 mm of a 415 m line, turns 0.75 rad, and its end forces are 2e-6 from those on
    four times the elements: the survey's scene 3:160 on 256 elements), hence the element's share
    of the line to a small power. The measure and its bound are empirical
    (`benchmarks/line_bvp_resolution.py`): a line it flags may be close (2:117 on 64 elements,
    3.4e-6 off; the table counts those)."""
    bends, nodes = element_bends(solution)
    worst = int(np.argmax(bends))
    if not bends[worst] > RESOLVED_BEND:
        return ""
    turning = solution.element_turning[worst]
    return (
        f"the mesh's {bends.size} elements (n_elements and the nodes fitted) do not resolve a bend of "
        f"the line: the element from s = {nodes[worst]:.4g} m to {nodes[worst + 1]:.4g} m turns "
        f"{turning:.2g} rad within itself, a bend θ (h/L)^(1/4) = {bends[worst]:.2g} beyond the "
        f"{RESOLVED_BEND:g} of a resolved line, and the end forces may be off by up to several per "
        "cent of the largest (benchmarks/line_bvp_resolution.py): give more elements"
    )


def weight_quadrature_error(problem) -> np.ndarray:
    """The error (N) of each element's weight as the solve integrates it (at its quadrature
    points, ``problem.w_q``) against `WEIGHT_POINTS`-point Gauss–Legendre on each half of the
    element (`skcable.mooring.line_bvp.mesh.composite_gauss`), the elements in the mesh's order:
    zeros where every segment's weight is a number (integrated exactly)."""
    if not any(callable(seg.w) for seg in problem.segments):
        return np.zeros(problem.mesh.t.shape[1])
    left, right = np.sort(problem.mesh.p[0, problem.mesh.t], axis=0)
    s, h = composite_gauss(left, right, 2, WEIGHT_POINTS)
    reference = (problem.weight_at(s.ravel()).reshape(s.shape) * h).sum(axis=(1, 2))
    return np.sum(problem.w_q * problem.assembly.dx, axis=0) - reference


def unresolved_weight(problem) -> str:
    """Why the mesh of the discrete line ``problem`` does not resolve its weight varying along
    it, where the solve's quadrature misplaces more than `RESOLVED_WEIGHT` of the line's weight
    (`weight_quadrature_error`, summed over the elements against the sum of their weights' sizes),
    else ``""``: a weight that varies within an element (a wavelength of 8.5 m in an element of
    17 m, the survey's scene 3:53 on 32 elements) is a load the solve does not apply, and the end
    forces are off by about as much (4.4e-3 there)."""
    error = np.abs(weight_quadrature_error(problem))
    share = float(np.sum(error)) / float(np.sum(np.abs(problem.w_q * problem.assembly.dx)))
    if not share > RESOLVED_WEIGHT:
        return ""
    left, right = np.sort(problem.mesh.p[0, problem.mesh.t], axis=0)
    worst = int(np.argmax(error))
    return (
        f"the mesh's {error.size} elements (n_elements and the nodes fitted) do not resolve the weight "
        "varying along the line: the solve's "
        f"quadrature misplaces {share:.2g} of the line's weight (the most in the element from s = "
        f"{left[worst]:.4g} m to {right[worst]:.4g} m), beyond the {RESOLVED_WEIGHT:g} of a resolved "
        "line, and the end forces may be off by about as much: give more elements"
    )


def warn_unresolved(solution, stacklevel: int = 3) -> None:
    """Warn (`skcable.errors.ResolutionWarning`, naming ``n_elements``) where the mesh does not
    resolve ``solution`` (its ``unresolved()``: `unresolved`, computed once), from the outermost
    public call only (`skcable._plausible.outermost`: the solves inside a mooring system's
    equilibrium or a design are trial states, not answers); ``stacklevel`` as `warnings.warn`'s,
    counted from here (3: the line that called the public solve which calls this)."""
    if not _plausible.outermost():
        return
    why = solution.unresolved()
    if why:
        warnings.warn(ResolutionWarning("n_elements", why), stacklevel=stacklevel)
