r"""A mooring line as an arc-length BVP: segments, w(s), point loads and unilateral seabed contact.

The arc-length form of `skcable.cable.bvp.arc` (Goicolea 2012, eq. (3)) on
the *unstretched* arc length ``s ∈ [0, L]`` itself: positions ``r(s) = (x,
y)`` P2, tension ``T(s)`` discontinuous P1, ``a = dr/ds``, ``n = |a|``,
``e = a/n``; the length is given (a mooring line), so there is no global
unknown. With the weight ``w(s)`` per unstretched length (N/m, any sign: a
buoyant segment has ``w < 0``) and the axial stiffness ``EA(s)`` per element:

.. math::
    R_{\mathbf r} = \int_0^L T\,\mathbf e\cdot\delta\mathbf r'\,ds
        + \int_0^L w\,\delta y\,ds + \sum_k P_k\,\delta y(s_k)
        - \sum_i \lambda_i (\mathbf n_i - \mu\,\mathbf t_i)\cdot\delta\mathbf r_i = 0,
    \qquad R_T = \int_0^L \big(n - 1 - T/EA\big)\,\delta T\,ds = 0,

``P_k`` the downward point loads (clump weights ``P > 0``, buoys ``P < 0``)
at mesh nodes ``s_k``.

**Seabed.** The line stays above the seabed, ``g_i = y_i - b(x_i) >= 0``,
at every position node ``i`` (vertices and mid-side nodes of the P2
elements, the ends excepted: they are supports). ``λ_i >= 0`` is the
multiplier of ``g_i``: the seabed pushes with ``λ_i n_i``, ``n_i = (-b'(x_i),
1)`` (normal to the seabed, of length ``sqrt(1 + b'^2)``, so the normal force
is ``N_i = λ_i |n_i|``). With Coulomb friction fully mobilised (Jonkman's
model: the line is being dragged towards the fairlead, so friction pulls it
back towards the anchor) the force is ``-μ N_i`` along the unit tangent
``t_i/|t_i|``, ``t_i = (1, b'(x_i))``, i.e. ``-μ λ_i t_i``. The contact
conditions are exact at the nodes: ``λ_i >= 0, g_i >= 0, λ_i g_i = 0``,
solved by a semismooth (primal–dual active set) Newton method
(M. Hintermüller, K. Ito, K. Kunisch, "The primal-dual active set strategy
as a semismooth Newton method", SIAM J. Optim., 2002) on the system where
``λ_i`` is eliminated: with ``R⁰`` the residual without contact,
``λ_i = n_i·R⁰_i / |n_i|²``, each node's two rows become

.. math::
    \mathbf t_i\cdot\mathbf R^0_i + \mu\,\mathbf n_i\cdot\mathbf R^0_i = 0
    \quad\text{(tangential equilibrium)}, \qquad
    \min(\lambda_i,\ c\,g_i) = 0 \quad\text{(complementarity)},

``c`` any positive constant (here the total load over the length, times the
node's element length over the mean one). Its
generalized Jacobian takes ``c ∇g_i`` on the nodes where ``λ_i > c g_i``
(active) and ``∇λ_i`` elsewhere: near the solution Newton's method identifies the active
set in finitely many steps and converges quadratically.
The seabed is ``y = b(x)``: a float (flat) or a callable; its slope ``b'``
is the callable ``seabed_slope`` if given, central differences of ``b``
otherwise, and ``b''`` (Jacobian only) central differences of ``b'``.

Support reactions come from ``R⁰`` at the supports: ``H_A = -R⁰_x(A)``,
``V_A = R⁰_y(A)``, ``H_B = R⁰_x(B)``, ``V_B = R⁰_y(B)``. With the anchor on
the seabed, A is a contact node as well: the seabed takes its push
``λ_A = max(n_A·R⁰_A/|n_A|², 0)`` (friction included) and the anchor the
rest, so that a line grounded at A has ``V_A = 0`` and ``H_A = H - μ·(normal
forces)`` as in Jonkman's closed form.

**Slack stretch.** Where friction fully mobilised would take more than the
pull, the grounded line near the anchor is slack (J.M. Jonkman, "Dynamics
modeling and loads analysis of an offshore floating wind turbine", NREL,
2007: ``H_A = 0``, tension ``max(H - μ w (L_B - s), 0)``): friction is only
partly mobilised there. Its end ``s0`` is a mesh node found like the
touchdown: on ``[0, s0]`` the friction holds the line's own tangential
weight (the tangential row becomes ``t_i·(R⁰_i - R_ext,i) = 0``: no friction
on a flat seabed), beyond it friction is fully mobilised (at the node ``s0``
for the share of its weight beyond), and ``s0`` is moved (a Newton step on
the tension just past it, with slope ``μ w``, kept in the bracket of the
tensions tried) until that tension is zero to ``rtol`` of the total load.
With P2 positions and P1 tension the grounded line's exact solution (T
linear, x quadratic in s) is then represented exactly; the friction that
holds a slack stretch on a slope is checked against ``μN``.

**Meshes.** The first solve is on a mesh graded by the start's curvature
(`_guess_nodes`), each later one on a mesh graded by the last solution's
(`_graded_nodes`: ``1 + L|dθ/ds|`` equidistributed, neighbouring elements
within a factor 1.5, no element more than four times smaller than the
last solution's there), until the grading settles; fine meshes are reached
by nested solves from 32 elements up, each finished solution (graded mesh,
touchdown, slack stretch) starting the doubled mesh.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from scipy.optimize import brentq
from skfem import Basis, ElementLineP1DG, ElementLineP2, MeshLine

from skcable._checks import nonnegative, positive, real, require, whole
from skcable.cable._elastic import elastic_catenary as free_catenary
from skcable.cable.bvp.arc import _AX, _AY, _STRAINS, _T
from skcable.cable.bvp.assembly import LineAssembly
from skcable.cable.bvp.elements import end_dofs
from skcable.cable.bvp.probes import gradient_probes
from skcable.cable.lines.seabed import elastic_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.fe import newton

__all__ = ["BVPSegment", "LineBVPSolution", "solve_line_bvp"]

#: elements of the first solve of a fine mesh whose start touches the seabed
COARSE = 32
#: Newton steps past rtol at most, while the merit falls tenfold
POLISH = 2
#: gradings of the mesh at most, and how much finer an element may get at one
GRADE_PASSES = 10
REFINEMENT = 4.0
#: growth of the element size per length away from small elements (neighbours differ by 1.5 at most)
GROWTH = 0.5
#: the monitor's tail term only on lines whose cos θ (= H/T on a catenary) varies more than tenfold
TAIL_RATIO = float(np.log(10.0))
#: updates of the end of the slack stretch at most (secant on the tension there)
SLACK_PASSES = 12


def _full_steps(problem, z0, rtol, max_iter):
    """Semismooth Newton with full steps (halved only where the tangent collapses): (z, state,
    history) once the merit is below ``rtol``, None if it is not within ``max_iter`` steps or
    grows a thousandfold."""
    state = problem.assemble(z0)
    z, history = z0, [state.merit]
    for _ in range(max_iter):
        if state.merit < rtol:
            return z, state, history
        if not state.merit < 1e3 * history[0]:
            return None
        dz, t = problem.increment(state), 1.0
        for _ in range(12):
            trial = problem.assemble(z + t * dz)
            if np.isfinite(trial.merit):
                break
            t *= 0.5
        else:
            return None
        z, state = z + t * dz, trial
        history.append(state.merit)
    return (z, state, history) if state.merit < rtol else None


def _graded_nodes(solution, n_elements, refinement=REFINEMENT):
    """Mesh nodes (unstretched arc length, m) equidistributing
    ``1 + L max(|dθ/ds|, |d ln cos θ/ds|)`` over the line, no element smaller than
    ``1/refinement`` of the solution's element there; and whether that bound held anywhere
    (another pass would refine further).

    θ(s) is the solution's angle to the horizontal, so the density is one per length plus the
    turning of the line per length: a slack line's elements gather where it bends, near its
    touchdown or its lowest point, instead of lying on the seabed where it is straight (the
    equidistribution of a monitor function: W. Huang, R.D. Russell, "Adaptive Moving Mesh
    Methods", Springer, 2011, ch. 2). Where the line is steeper than 45° the second term,
    ``|d ln cos θ/ds| = |tan θ| |dθ/ds|``, takes over: past the bend of a nearly L-shaped line
    (radius ``r = H/w``) the catenary's ``x = r asinh(σ/r)`` grows like ``r ln σ`` (σ the
    arc length past the touchdown) while ``|dθ/ds| = r/σ²`` falls fast; ``cos θ = r/σ`` there,
    so the second term is ``1/σ``, a geometric grading that interpolates the logarithm (the
    horizontal closure that sets H) instead of leaving its P2 error at ``r`` times a constant
    (H converged like h, 3e-4 of H at 80 elements, before it). The term is used only on a line
    whose ``cos θ`` varies more than tenfold (``ln`` of the ratio above ``TAIL_RATIO``): taut
    and ordinary lines keep the turning monitor. The bound keeps each solve's
    start (the previous solution interpolated) within a node or two of its contact set. Each
    stretch between joints and point loads gets its share (at least one element) of the
    ``n_elements``.
    """
    p = solution._problem
    L = p.L
    old = solution.mesh.p[0]
    old = np.sort(old)
    h_old = np.diff(old)
    cells = 16  # per element of the solution: its turning is measured inside each element, so
    # that the kink of a point load or a joint (a node of every mesh) draws no elements
    fraction = (np.arange(cells) + 0.5) / cells
    inside = old[:-1, None] + fraction[None, :] * h_old[:, None]  # (ne, cells)
    theta = np.unwrap(solution.angle(inside.ravel()).reshape(inside.shape), axis=1)
    turning = np.abs(np.gradient(theta, axis=1)) / (h_old[:, None] / cells)
    cosine = np.log(np.maximum(np.abs(np.cos(theta)), 1e-12))
    stretching = np.abs(np.gradient(cosine, axis=1)) / (h_old[:, None] / cells)
    ds = np.repeat(h_old / cells, cells)
    if np.sum(stretching.ravel() * ds) <= TAIL_RATIO:  # cos θ = H/T varies less than tenfold
        stretching = 0.0
    rho = (1.0 + L * np.maximum(turning, stretching)).ravel()
    h_old = np.repeat(h_old, cells)
    s = np.concatenate([[0.0], np.cumsum(ds)])
    s[-1] = L

    def density(scale):  # elements per length: the monitor over scale, at most refinement / h_old
        return np.minimum(rho / scale, refinement / h_old)

    total = np.sum(rho * ds)
    if np.sum(refinement / h_old * ds) <= n_elements:
        scale = 0.0
    else:
        scale = brentq(lambda c: np.sum(density(c) * ds) - n_elements, 1e-12 * total / n_elements, total)
    rate = density(scale) if scale > 0 else refinement / h_old
    capped = bool(np.any(rho / max(scale, 1e-300) > refinement / h_old * (1 + 1e-9)))
    rate = _smoothed(s, rate, n_elements)
    mass = np.concatenate([[0.0], np.cumsum(rate * ds)])
    return _equidistributed(p, s, mass, n_elements), capped


def _smoothed(s, rate, n_elements, growth=None):
    """Elements per length ``rate`` on the intervals of ``s``, raised where the element size
    ``h = 1/rate`` would grow faster than ``growth`` per length away from small elements (a mesh
    whose neighbouring elements differ by a factor ``1 + growth`` at most), and scaled back to
    ``n_elements`` in all: ``h_i = min_j (h_j + growth |m_i - m_j|)``, m the midpoints, two running
    minima."""
    growth = GROWTH if growth is None else growth
    m = 0.5 * (s[1:] + s[:-1])
    ds = np.diff(s)
    for _ in range(3):
        h = 1.0 / rate
        forward = growth * m + np.minimum.accumulate(h - growth * m)
        backward = -growth * m + np.minimum.accumulate((h + growth * m)[::-1])[::-1]
        rate = 1.0 / np.minimum(forward, backward)
        rate *= n_elements / np.sum(rate * ds)
    return rate


def _equidistributed(problem, s, mass, n_elements):
    """Nodes at equal steps of ``mass(s)`` (increasing, sampled at ``s``), each stretch between
    joints and point loads getting its share (at least one element) of ``n_elements``."""
    fixed = np.unique(np.concatenate([problem.joints, [s_p for s_p, _ in problem.point_loads]]))
    at_fixed = np.interp(fixed, s, mass)
    share = np.diff(at_fixed) / at_fixed[-1]
    counts = np.maximum(1, np.round(n_elements * share)).astype(int)
    inner = [  # the nodes inside each stretch; its ends are the fixed nodes themselves
        np.interp(np.linspace(a, b, k + 1)[1:-1], mass, s)
        for a, b, k in zip(at_fixed[:-1], at_fixed[1:], counts, strict=True)
    ]
    inner = np.unique(np.concatenate(inner))
    near = np.abs(inner[:, None] - fixed[None, :]).min(axis=1, initial=np.inf) <= 1e-9 * problem.L
    inner = inner[~near & np.concatenate([[True], np.diff(inner) > 1e-9 * problem.L])]  # no slivers
    return np.unique(np.concatenate([inner, fixed]))


def _guess_nodes(problem, n_elements):
    """Mesh nodes for the first solve: ``1 + L |dθ/ds|`` equidistributed over the start's shape
    (`_guess`), whose angle is known in closed form, ``tan θ = w (s - s_v) / H`` (zero on the
    grounded part): the elements gather at its touchdown or lowest point down to the bend's
    radius ``H/w``, which a uniform mesh of a nearly L-shaped line cannot see."""
    H, w, s_v, grounded = _guess(problem, shape=True)
    L = problem.L

    def angle(s):
        v = w * (s - s_v)
        return np.arctan((np.maximum(v, 0.0) if grounded else v) / H)

    turns = np.linspace(angle(0.0), angle(L), 32 * n_elements + 1)
    s = np.unique(
        np.concatenate(
            [np.linspace(0.0, L, 16 * n_elements + 1), np.clip(s_v + H / w * np.tan(turns), 0.0, L)]
        )
    )
    m = 0.5 * (s[1:] + s[:-1])
    v = w * (m - s_v)
    turning = np.where(grounded & (v < 0), 0.0, (w / H) / (1.0 + (v / H) ** 2))  # dθ/ds
    monitor = 1.0 + L * turning
    rate = _smoothed(s, n_elements * monitor / np.sum(monitor * np.diff(s)), n_elements)
    mass = np.concatenate([[0.0], np.cumsum(rate * np.diff(s))])
    return _equidistributed(problem, s, mass, n_elements)


def _next_slack_end(tried, slope, s_touchdown):
    """The next end ``s0`` of the slack stretch from the (s0, tension just past s0) pairs tried.

    The tension there grows with s0 by about the friction force per length, ``slope`` (N/m): a
    Newton step on the last pair with that slope, kept inside the bracket of the earlier pairs
    (the largest s0 with a negative tension and the smallest with a positive one; bisection when
    the step leaves it), and below the touchdown; 0 when the step passes the anchor and no
    negative tension was tried (friction does not take the whole pull after all).
    """
    s_last, g_last = tried[-1]
    if not slope > 0:
        raise ConvergenceError(
            "solve_line_bvp: the tension does not grow away from the slack stretch",
            [abs(g) for _, g in tried],
        )
    lo = max((s for s, g in tried if g < 0), default=0.0)
    hi = min((s for s, g in tried if g > 0), default=s_touchdown)
    s_next = s_last - g_last / slope
    if s_next <= 0 and not any(g < 0 for _, g in tried):
        return 0.0  # the tension stays positive down to the anchor: no slack stretch
    if not lo < s_next < hi:
        s_next = 0.5 * (lo + hi)
    return float(s_next)


@dataclass(frozen=True)
class BVPSegment:
    """One segment of a line for `solve_line_bvp`, listed from the anchor A.

    Attributes
    ----------
    length : float
        Unstretched length (m), > 0.
    w : float or callable
        Weight per unit unstretched length (N/m, downward; negative for a
        buoyant segment), or a callable of the arc length ``s`` from A (m,
        over the whole line) returning it: a weight that varies continuously.
    EA : float or None
        Axial stiffness (N), > 0; ``None`` for an inextensible segment.
    """

    length: float
    w: float | Callable
    EA: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "length", positive("length", self.length))
        if not callable(self.w):
            object.__setattr__(self, "w", real("w", self.w))
            if isinstance(self.w, np.ndarray):
                raise InputError("w", "one number per segment (or a callable of s)")
        if self.EA is not None:
            object.__setattr__(self, "EA", positive("EA", self.EA))


def _segments(segments):
    if isinstance(segments, BVPSegment):
        segments = [segments]
    try:
        items = list(segments)
    except TypeError as exc:
        raise InputError("segments", "give a list of BVPSegment or (length, w, EA) tuples") from exc
    if not items:
        raise InputError("segments", "give at least one segment")
    out = []
    for item in items:
        if isinstance(item, BVPSegment):
            out.append(item)
        elif isinstance(item, (tuple, list)) and len(item) in (2, 3):
            out.append(BVPSegment(*item))
        else:
            raise InputError("segments", f"each segment is a BVPSegment or (length, w[, EA]), got {item!r}")
    return out


@dataclass(frozen=True)
class Seabed:
    """The seabed ``y = b(x)`` (m), with its slope and curvature at any x."""

    height: Callable
    slope_fn: Callable | None
    flat: float | None
    step: float

    def __call__(self, x):
        if self.flat is not None:
            return np.full_like(x, self.flat)
        return self._checked(self.height, x, "seabed")

    def _checked(self, fn, x, name):
        try:
            value = np.asarray(fn(x), dtype=float)
        except (TypeError, ValueError) as exc:
            raise InputError(name, f"must be a callable of x (array in, array out): {exc}") from exc
        if value.shape != np.shape(x):
            if value.ndim != 0:
                raise InputError(name, f"returned shape {value.shape} for x of shape {np.shape(x)}")
            value = np.full(np.shape(x), float(value))
        if not np.all(np.isfinite(value)):
            raise InputError(name, "returned non-finite values")
        return value

    def slope(self, x):
        if self.flat is not None:
            return np.zeros_like(x)
        if self.slope_fn is not None:
            return self._checked(self.slope_fn, x, "seabed_slope")
        h = self.step
        return (self(x + h) - self(x - h)) / (2.0 * h)

    def curvature(self, x):
        if self.flat is not None:
            return np.zeros_like(x)
        h = self.step
        return (self.slope(x + h) - self.slope(x - h)) / (2.0 * h)


def _seabed(seabed, seabed_slope, span):
    if seabed is None:
        if seabed_slope is not None:
            raise InputError("seabed_slope", "applies to a seabed: give seabed= as well")
        return None
    step = 1e-5 * span
    if callable(seabed):
        if seabed_slope is not None and not callable(seabed_slope):
            raise InputError("seabed_slope", "must be a callable of x returning db/dx")
        return Seabed(seabed, seabed_slope, None, step)
    if seabed_slope is not None:
        raise InputError("seabed_slope", "a flat seabed (a number) has no slope to give")
    if isinstance(seabed, (np.ndarray, list, tuple)) and np.size(seabed) != 1:
        raise InputError("seabed", "a height (m) or a callable b(x); one scene at a time")
    flat = real("seabed", seabed)
    return Seabed(lambda x: np.full_like(x, flat), None, float(np.asarray(flat)), step)


class LineProblem:
    """Mesh, bases, properties per quadrature point and the assembly of one line."""

    def __init__(
        self,
        span,
        dh,
        segments,
        point_loads,
        seabed,
        friction,
        n_elements,
        fitted=(),
        slack_end=0.0,
        nodes_at=None,
    ):
        self.span, self.dh, self.seabed, self.friction = span, dh, seabed, friction
        self.slack_end = float(slack_end)
        self.segments = segments
        lengths = np.array([seg.length for seg in segments])
        self.joints = np.concatenate([[0.0], np.cumsum(lengths)])
        self.L = float(self.joints[-1])
        n = positive("n_elements", n_elements)
        require("n_elements", n == int(n), "must be a whole number", n)
        per = np.maximum(1, np.round(int(n) * lengths / self.L)).astype(int)
        nodes = [
            np.linspace(a, b, k + 1) for a, b, k in zip(self.joints[:-1], self.joints[1:], per, strict=True)
        ]
        self.point_loads = point_loads
        nodes = np.unique(np.concatenate([*nodes, [s for s, _ in point_loads]]))
        if nodes_at is not None:  # a graded mesh: joints and point loads stay nodes
            nodes = np.unique(np.concatenate([nodes_at, self.joints, [s for s, _ in point_loads]]))
        placed = []
        for s_fit in fitted:  # a node at s_fit: move the nearest inner node there, or insert one
            k = int(np.argmin(np.abs(nodes - s_fit)))
            spacing = np.min(np.diff(nodes[max(k - 1, 0) : k + 2]))  # of the elements at that node
            movable = 0 < k < len(nodes) - 1 and not np.any(np.isclose(nodes[k], self.joints))
            movable = movable and not any(
                np.isclose(nodes[k], s) for s in [*placed, *(s for s, _ in point_loads)]
            )
            placed.append(s_fit)
            if movable and abs(nodes[k] - s_fit) < 0.25 * spacing:
                nodes[k] = s_fit
            elif np.min(np.abs(nodes - s_fit)) > 1e-9 * self.L:
                nodes = np.sort(np.append(nodes, s_fit))
        self.mesh = MeshLine(nodes)
        self.basis = Basis(self.mesh, ElementLineP2(), intorder=6)
        self.tbasis = self.basis.with_element(ElementLineP1DG())
        N, M = self.basis.N, self.tbasis.N
        self.N, self.M = N, M
        self.assembly = LineAssembly({"x": self.basis, "y": self.basis, "T": self.tbasis}, _STRAINS)
        self.end_a, self.end_b, inner = end_dofs(self.basis)
        self.free = np.concatenate([inner, N + inner, 2 * N + np.arange(M)])
        self.system = self.assembly.banded(self.free)
        self._force_rows = self.free[self.free < 2 * N]
        self._stretch_rows = self.free[self.free >= 2 * N]
        # properties at the quadrature points: the element's segment by its midpoint
        s_q = self.assembly.x
        middle = self.mesh.p[0, self.mesh.t].mean(axis=0)
        owner = np.clip(np.searchsorted(self.joints, middle) - 1, 0, len(segments) - 1)
        self.w_q = np.empty_like(s_q)
        self.compliance_q = np.empty_like(s_q)
        for k, seg in enumerate(segments):
            cols = owner == k
            if callable(seg.w):
                values = np.asarray(seg.w(s_q[:, cols]), dtype=float)
                try:
                    values = np.broadcast_to(values, s_q[:, cols].shape)
                except ValueError as exc:
                    raise InputError("w", f"the callable returned shape {values.shape}") from exc
                if not np.all(np.isfinite(values)):
                    raise InputError("w", "the callable returned non-finite values")
                self.w_q[:, cols] = values
            else:
                self.w_q[:, cols] = seg.w
            self.compliance_q[:, cols] = 0.0 if seg.EA is None else 1.0 / seg.EA
        self.weight = float(np.sum(self.w_q * self.assembly.dx))
        s_dof = self.basis.doflocs[0]
        self.point_rows = np.array([N + int(np.argmin(np.abs(s_dof - s))) for s, _ in point_loads], dtype=int)
        self.point_values = np.array([P for _, P in point_loads], dtype=float)
        self.load_scale = float(
            np.sum(np.abs(self.w_q) * self.assembly.dx) + np.sum(np.abs(self.point_values))
        )
        self.length_scale = self.L
        self.stiffness = self.load_scale / self.L  # c of the complementarity function (N/m)
        self.contact = inner if seabed is not None else np.zeros(0, dtype=int)
        # c per contact node: the total load per length, times the node's element length over the
        # mean one (uniform on a uniform mesh), so that λ_i ~ w h_i switches at a gap ~ h_i / h̄·h̄
        element_length = np.diff(self.mesh.p[0, self.mesh.t], axis=0)[0]
        node_length = np.zeros(N)
        np.maximum.at(node_length, self.basis.element_dofs.ravel(), np.tile(element_length, 3))
        self.stiffness_nodes = self.stiffness * node_length[self.contact] / (self.L / element_length.size)
        # the external load vector (weight and point loads), and per contact node the share of its
        # weight that lies beyond the slack stretch [0, slack_end] (where friction is fully mobilised)
        zero = np.zeros_like(self.w_q)
        self.external = self.assembly.vector(np.stack([zero, zero, zero, self.w_q, zero]))
        np.add.at(self.external, self.point_rows, self.point_values)
        sliding_q = np.where((middle > self.slack_end)[None, :], self.w_q, 0.0)
        sliding = self.assembly.vector(np.stack([zero, zero, zero, sliding_q, zero]))[N + self.contact]
        own = self.assembly.vector(np.stack([zero, zero, zero, self.w_q, zero]))[N + self.contact]
        self.sliding_share = np.ones(self.contact.size)
        if self.slack_end > 0:
            self.sliding_share = np.divide(sliding, own, out=np.ones_like(own), where=own != 0)
            self.sliding_share[self.basis.doflocs[0][self.contact] < self.slack_end] = 0.0
        #: friction coefficient per contact node: μ where it slides, 0 on the slack stretch
        self.mu_nodes = friction * self.sliding_share
        #: A lies on the seabed (to 1e-12 of the length): the seabed, not the anchor, carries its push
        self.anchor_on_seabed = (
            seabed is not None and abs(float(seabed(np.array([0.0]))[0])) <= 1e-12 * self.L
        )

    # --- residual and tangent -----------------------------------------------------------
    def internal(self, z):
        """``R⁰`` (no contact) and the element tangents, or None for a collapsed tangent."""
        asmb = self.assembly
        g = asmb.interpolate(z)
        ax, ay, T = g[_AX], g[_AY], g[_T]
        n = np.sqrt(ax * ax + ay * ay)
        if not np.all(n > 0):
            return None
        ex, ey = ax / n, ay / n
        c = self.compliance_q
        zero = np.zeros_like(n)
        S = np.stack([T * ex, T * ey, zero, self.w_q, n - 1.0 - T * c])
        D = np.zeros((5, 5, *n.shape))
        Tn = T / n
        D[_AX, _AX] = Tn * (1.0 - ex * ex)
        D[_AX, _AY] = D[_AY, _AX] = -Tn * ex * ey
        D[_AY, _AY] = Tn * (1.0 - ey * ey)
        D[_AX, _T] = D[_T, _AX] = ex
        D[_AY, _T] = D[_T, _AY] = ey
        D[_T, _T] = -c
        R = asmb.vector(S)
        np.add.at(R, self.point_rows, self.point_values)
        return R, asmb.element_matrices(D)

    def gaps(self, z):
        """Height of every contact node above the seabed (m)."""
        i = self.contact
        return z[self.N + i] - self.seabed(z[i])

    def contact_terms(self, z, R0):
        """Per contact node: slope, curvature, gap, multiplier λ, active flag."""
        i, N = self.contact, self.N
        x, y = z[i], z[N + i]
        bp, bpp = self.seabed.slope(x), self.seabed.curvature(x)
        gap = y - self.seabed(x)
        Rx, Ry = R0[i], R0[N + i]
        norm2 = 1.0 + bp * bp
        lam = (Ry - bp * Rx) / norm2
        active = lam > self.stiffness_nodes * gap
        return bp, bpp, gap, lam, active, Rx, Ry

    def assemble(self, z):
        out = self.internal(z)
        if out is None:
            return _REJECTED
        R0, Ke = out
        F = R0.copy()
        terms = None
        if self.contact.size:
            terms = self.contact_terms(z, R0)
            bp, _, gap, lam, active, Rx, Ry = terms
            mu, stuck = self.mu_nodes, 1.0 - self.sliding_share
            i, N = self.contact, self.N
            # on the slack stretch friction holds the line's own tangential weight (stuck)
            F[i] = (1.0 - mu * bp) * Rx + (bp + mu) * Ry - stuck * bp * self.external[N + i]
            F[N + i] = np.where(active, self.stiffness_nodes * gap, lam)
        force = np.abs(F[self._force_rows]) / self.load_scale
        stretch = np.abs(F[self._stretch_rows]) / self.length_scale
        merit = max(float(np.max(force, initial=0.0)), float(np.max(stretch, initial=0.0)))
        return LineState(F, R0, Ke, terms, merit)

    def tangent(self, state):
        """The generalized Jacobian of ``F``: element matrices with the contact rows mixed in,
        and the terms they cannot carry (sparse, or None)."""
        Ke = state.Ke
        extra = None
        if self.contact.size:
            Ke = Ke.copy()
            bp, bpp, _, lam, active, Rx, Ry = state.terms
            mu, i, N = self.mu_nodes, self.contact, self.N
            norm2 = 1.0 + bp * bp
            # row mixing per position dof: x row -> a Kx + b Ky, y row -> c Kx + d Ky
            a, b = np.ones(N), np.zeros(N)
            c, d = np.zeros(N), np.ones(N)
            a[i], b[i] = 1.0 - mu * bp, bp + mu
            c[i] = np.where(active, 0.0, -bp / norm2)
            d[i] = np.where(active, 0.0, 1.0 / norm2)
            ed = self.basis.element_dofs  # (3, ne): local position dofs 0..2 (x) and 3..5 (y)
            nb = ed.shape[0]
            Kx, Ky = state.Ke[:nb], state.Ke[nb : 2 * nb]
            Ke[:nb] = a[ed][:, None, :] * Kx + b[ed][:, None, :] * Ky
            Ke[nb : 2 * nb] = c[ed][:, None, :] * Kx + d[ed][:, None, :] * Ky
            # what the element matrices cannot carry: derivatives of b'(x_i) and the active rows
            stuck_y = (1.0 - self.sliding_share) * self.external[N + i]
            dtx = bpp * (Ry - mu * Rx - stuck_y)  # d(tangential row)/dx_i through b'
            dlx = bpp * (-Rx / norm2 - lam * 2.0 * bp / norm2)  # dλ/dx_i through b'
            k = self.stiffness_nodes
            rows = np.concatenate([i, N + i, N + i])
            cols = np.concatenate([i, i, N + i])
            vals = np.concatenate([dtx, np.where(active, -k * bp, dlx), np.where(active, k, 0.0)])
            extra = sp.coo_matrix((vals, (rows, cols)), shape=(self.assembly.N, self.assembly.N))
        return Ke, extra

    def jacobian(self, state):
        """The generalized Jacobian as a CSR matrix over all dofs (for inspection; Newton uses the band)."""
        Ke, extra = self.tangent(state)
        J = self.assembly.matrix(Ke)
        return J if extra is None else (J + extra).tocsr()

    def increment(self, state):
        """Newton increment: the banded solve of the generalized Jacobian."""
        Ke, extra = self.tangent(state)
        system = self.system
        ab = system.add_elements(system.band(), Ke)
        if extra is not None:
            system.add_sparse(ab, extra)
        step = np.zeros(self.assembly.N)
        step[self.free] = system.solve(ab, -state.F[self.free])
        return step

    def reactions(self, R0):
        N = self.N
        return -R0[self.end_a], R0[N + self.end_a], R0[self.end_b], R0[N + self.end_b]


@dataclass
class LineState:
    F: np.ndarray | None
    R0: np.ndarray | None
    Ke: np.ndarray | None
    terms: tuple | None
    merit: float


_REJECTED = LineState(None, None, None, None, np.inf)


def _guess(problem: LineProblem, shape=False):
    """The elastic catenary of the mean weight and stiffness, on the flat seabed at the
    anchor's level when the free one dips below the seabed; positions lifted onto the seabed.
    With ``shape``: ``(H, w, s_v, grounded)`` of that catenary instead, its vertical force
    ``w (s - s_v)`` (zero where grounded)."""
    span, dh, L = problem.span, problem.dh, problem.L
    w = problem.weight / L
    if not w > 0:
        raise InputError("segments", f"the line's mean weight must be > 0 (downward), got {w:g} N/m")
    c = float(np.sum(problem.compliance_q * problem.assembly.dx)) / L
    EA = 1.0 / c if c > 0 else 1e6 * w * L
    s_dof, s_t = problem.basis.doflocs[0], problem.tbasis.doflocs[0]
    free = free_catenary(span, dh, w, EA, length=L)
    u_a = -free.V_A / free.H

    def free_x(s):
        return free.H * s / EA + free.H / w * (np.arcsinh(u_a + w * s / free.H) - np.arcsinh(u_a))

    def free_y(s):
        t0, t1 = np.hypot(1.0, u_a), np.hypot(1.0, u_a + w * s / free.H)
        return (free.H / w) * (t1 - t0) + (-free.V_A * s + 0.5 * w * s * s) / EA

    x, y = free_x(s_dof), free_y(s_dof)
    T = np.hypot(free.H, -free.V_A + w * s_t)
    form = (float(free.H), w, float(free.V_A) / w, False)
    bed = problem.seabed
    if bed is not None and np.any(y < bed(x)):
        level = min(float(bed(np.array([0.0]))[0]), 0.0)
        level = min(level, dh - 1e-3 * abs(span))
        try:
            grounded = elastic_catenary(span, dh, w, EA, length=L, seabed=level)
            if np.any(grounded.heap):  # H = 0: the arc form has no tension to solve for
                raise InputError(
                    "length",
                    "leaves slack line lying in a heap on the seabed (H = 0): elastic_catenary(seabed=...) "
                    "and cable.Line return that state",
                )
            x, y, T = grounded.x_of_s(s_dof), grounded.y_of_s(s_dof), grounded.T_of_s(s_t)
            form = (float(grounded.H), w, L - float(grounded.V_B) / w, True)
        except (InputError, ConvergenceError):
            if bed.flat is not None:  # on a flat seabed the closed form's refusal (slack in a heap) holds
                raise
        y = np.maximum(y, bed(x))  # a curved seabed: the free line lifted onto it, if nothing better
    if shape:
        return form
    x[problem.end_a], y[problem.end_a] = 0.0, 0.0
    x[problem.end_b], y[problem.end_b] = span, dh
    return np.concatenate([x, y, T])


class LineBVPSolution:
    """Solution of `solve_line_bvp`.

    Attributes
    ----------
    H, V_B : float
        Horizontal and vertical force at the fairlead B (N), as in
        `skcable.cable.elastic_catenary` (``H`` is the fairlead's, ``H_B``).
    H_A, V_A : float
        Horizontal and upward vertical reaction at the anchor A (N).
    T_A, T_B : float
        End tensions (N).
    length : float
        Unstretched length (m).
    contact_s, contact_xy : ndarray
        Arc length from A (m) and position (m) of every contact node.
    normal_force : ndarray
        Seabed normal force ``N_i >= 0`` at each contact node (N).
    contact_force : ndarray (n, 2)
        Force of the seabed on the line at each contact node, friction
        included (N): ``λ_i (n_i - μ t_i)`` where the line slides, on a slack
        stretch near the anchor the friction that holds its tangential weight
        (none on a flat seabed).
    gap : ndarray
        Height of each contact node above the seabed (m), ``>= 0`` to round-off.
    in_contact : ndarray of bool
        The nodes on the seabed (the final active set).
    s_touchdown, x_touchdown : float
        Where the line leaves the seabed for the last time towards B: the
        unstretched arc length from A (m) at which the suspended part's
        vertical balance ``V_B - ∫_s^L w - ΣP = H b'(x(s))`` holds (a point
        between mesh nodes, not the last contact node), and its abscissa; 0
        without contact.
    s_landing : float
        Where a line hanging from an anchor above the seabed first lands
        (the balance of the part hanging from A, as for ``s_touchdown``); 0
        when A lies on the seabed.
    length_on_seabed : float
        ``s_touchdown - s_landing`` (m): the unstretched length between the
        first landing and the last touchdown (where the line lifts off a bump
        in between, that free stretch is included).
    history, iterations
        Newton's merit per iteration.
    """

    def __init__(self, problem: LineProblem, z, history, state: LineState):
        self._problem, self.dofs, self._state = problem, z, state
        self.span, self.dh, self.length = problem.span, problem.dh, problem.L
        self.mesh, self.basis = problem.mesh, problem.basis
        self.history = [float(h) for h in history]
        self.iterations = len(self.history) - 1
        self.friction = problem.friction
        H_A, V_A, H_B, V_B = (float(v) for v in problem.reactions(state.R0))
        self.H, self.V_B, self.H_B = H_B, V_B, H_B
        i, N = problem.contact, problem.N
        order = np.argsort(problem.basis.doflocs[0][i], kind="stable")
        i = i[order]
        self.contact_s = problem.basis.doflocs[0][i]
        self.contact_xy = np.column_stack([z[i], z[N + i]])
        self.anchor_on_seabed = problem.anchor_on_seabed
        if i.size:
            bp, _, gap, lam, active, _, _ = state.terms
            bp, gap, lam, active = bp[order], gap[order], lam[order], active[order]
            mu = problem.mu_nodes[order]
            # friction that holds the slack stretch: its own tangential weight, t·R_ext / |t|²
            held = (1.0 - problem.sliding_share[order]) * bp * problem.external[N + i] / (1.0 + bp * bp)
            if self.anchor_on_seabed:
                # the seabed under the anchor takes the anchor's downward push, friction included
                slope = float(problem.seabed.slope(np.array([0.0]))[0])
                lam_a = max((V_A + slope * H_A) / (1.0 + slope * slope), 0.0)  # n·R⁰_A / |n|², R⁰_x(A) = -H_A
                mu_a = problem.friction if problem.slack_end == 0 else 0.0  # the anchor holds a slack stretch
                H_A, V_A = H_A + lam_a * (-slope - mu_a), V_A - lam_a * (1.0 - mu_a * slope)
                self.contact_s = np.concatenate([[0.0], self.contact_s])
                self.contact_xy = np.vstack([[0.0, 0.0], self.contact_xy])
                bp, gap = np.concatenate([[slope], bp]), np.concatenate([[0.0], gap])
                lam, active = np.concatenate([[lam_a], lam]), np.concatenate([[lam_a > 0], active])
                mu, held = np.concatenate([[mu_a], mu]), np.concatenate([[0.0], held])
            self.normal_force = lam * np.sqrt(1.0 + bp * bp)
            self.contact_force = lam[:, None] * np.column_stack([-bp - mu, 1.0 - mu * bp]) + held[
                :, None
            ] * np.column_stack([np.ones_like(bp), bp])
            self.gap, self.in_contact = gap, active
        else:
            self.normal_force, self.gap = np.zeros(0), np.zeros(0)
            self.contact_force, self.in_contact = np.zeros((0, 2)), np.zeros(0, dtype=bool)
        self.H_A, self.V_A = H_A, V_A

    @property
    def T_A(self):
        return float(np.hypot(self.H_A, self.V_A))

    @property
    def T_B(self):
        return float(np.hypot(self.H, self.V_B))

    @property
    def weight(self):
        """Total weight of the line and its point loads (N, downward)."""
        p = self._problem
        return p.weight + float(np.sum(p.point_values))

    def _fields(self):
        N = self._problem.N
        return self.dofs[:N], self.dofs[N : 2 * N], self.dofs[2 * N :]

    def xy(self, s):
        """Position (x, y) (m) at unstretched arc length ``s`` from A, array ``(..., 2)``."""
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        probes = self.basis.probes(s.reshape(1, -1))
        xd, yd, _ = self._fields()
        return np.stack([probes @ xd, probes @ yd], axis=-1).reshape(*s.shape, 2)

    def tension(self, s):
        """Tension (N) at unstretched arc length ``s`` (P1-DG: the value of the element containing s)."""
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        T = self._fields()[2]
        return (self._problem.tbasis.probes(s.reshape(1, -1)) @ T).reshape(s.shape)[()]

    def angle(self, s):
        """Angle of the line to the horizontal (rad) at ``s``."""
        s = np.atleast_1d(np.asarray(real("s", s), dtype=float))
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        G = gradient_probes(self.basis, s.reshape(1, -1))
        xd, yd, _ = self._fields()
        return np.arctan2(G @ yd, G @ xd)

    def _weight_before(self, s):
        """Weight of the line over [0, s] and of the point loads before s (N)."""
        p = self._problem
        s_nodes = self.mesh.p[0]
        k = int(np.clip(np.searchsorted(s_nodes, s) - 1, 0, len(s_nodes) - 2))
        fraction = (s - s_nodes[k]) / (s_nodes[k + 1] - s_nodes[k])
        before = self._cumulative_weight
        points = sum(P for s_p, P in p.point_loads if s_p < s)
        return before[k] + fraction * (before[k + 1] - before[k]) + points

    @cached_property
    def _cumulative_weight(self):
        p = self._problem
        order = np.argsort(self.mesh.p[0, self.mesh.t].mean(axis=0))
        return np.concatenate([[0.0], np.cumsum(np.sum(p.w_q * p.assembly.dx, axis=0)[order])])

    def _transition(self, balance, near):
        """Root of ``balance(s)`` between the mesh nodes around ``near`` (a contact node)."""
        s_nodes = self.mesh.p[0]
        h = np.max(np.diff(s_nodes))
        grid = s_nodes[(s_nodes >= near - 2 * h) & (s_nodes <= near + 2 * h)]
        values = np.array([balance(s) for s in grid])
        zero = np.flatnonzero(values == 0.0)
        if zero.size:
            return float(grid[zero[0]])
        change = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
        if not change.size:
            raise ConvergenceError(
                "solve_line_bvp: no sign change of the vertical balance near the contact edge", self.history
            )
        k = int(change[np.argmin(np.abs(grid[change] - near))])
        return float(brentq(balance, grid[k], grid[k + 1], xtol=1e-12 * self.length))

    def _slope_at(self, s):
        x = self.xy(np.array(s))[0]
        return float(self._problem.seabed.slope(np.array([x]))[0])

    @cached_property
    def _touchdown(self):
        """(s, x) of the last touchdown: ``V_B - (W - W(s)) = H b'(x(s))`` (the suspended part's
        vertical balance, the line leaving the seabed tangentially)."""
        if not self.in_contact[self.contact_s > 0].any():
            return 0.0, 0.0
        total = self._weight_before(self.length)

        def balance(s):
            return self.V_B - (total - self._weight_before(s)) - self.H * self._slope_at(s)

        s_td = self._transition(balance, self.contact_s[self.in_contact][-1])
        return s_td, float(self.xy(np.array(s_td))[0])

    @cached_property
    def s_landing(self):
        """Where a line hanging from an anchor above the seabed first lands on it: the unstretched
        arc length from A (m) where ``W(s) - V_A = H_A b'(x(s))`` (the balance of the part
        hanging from A); 0 when A lies on the seabed or nothing touches."""
        if self.anchor_on_seabed or not self.in_contact.any():
            return 0.0

        def balance(s):
            return self._weight_before(s) - self.V_A - self.H_A * self._slope_at(s)

        return self._transition(balance, self.contact_s[self.in_contact][0])

    @property
    def s_touchdown(self):
        return self._touchdown[0]

    @property
    def x_touchdown(self):
        return self._touchdown[1]

    @property
    def length_on_seabed(self):
        if not self.in_contact.any():
            return 0.0
        return self.s_touchdown - self.s_landing

    def _tension_profile(self):
        """The P1-DG tension per element, sorted along the line: (s_left, s_right, T_left, T_right)."""
        tb = self._problem.tbasis
        dofs = tb.element_dofs  # (2, ne)
        at = tb.doflocs[0][dofs]
        T = self._fields()[2][dofs]
        first = np.argmin(at, axis=0)
        cols = np.arange(dofs.shape[1])
        s_l, s_r = at[first, cols], at[1 - first, cols]
        T_l, T_r = T[first, cols], T[1 - first, cols]
        order = np.argsort(s_l)
        return s_l[order], s_r[order], T_l[order], T_r[order]

    def _tension_zero(self, tol):
        """Where the tension of a line grounded at A last rises through zero (m of arc length): the
        end of Jonkman's slack stretch estimated from a solve with friction fully mobilised
        everywhere; 0 when the tension is nowhere below ``-tol`` (N)."""
        s_l, s_r, T_l, T_r = self._tension_profile()
        s, T = np.column_stack([s_l, s_r]).ravel(), np.column_stack([T_l, T_r]).ravel()
        negative = np.flatnonzero(T < -tol)
        if not negative.size:
            return 0.0
        k = int(negative[-1])
        if k + 1 >= T.size or s[k + 1] == s[k] or T[k + 1] <= T[k]:
            zero = s[min(k + 1, T.size - 1)]
        else:
            zero = s[k] - T[k] * (s[k + 1] - s[k]) / (T[k + 1] - T[k])
        return float(min(zero, 0.99 * self.s_touchdown))

    def _slack_estimate(self, friction):
        """The end ``s0`` of the slack stretch (m) that friction ``μ`` fully mobilised from the
        touchdown towards A would give a frictionless solution's grounded line on a flat seabed:
        ``μ (W(s_td) - W(s0)) = T(s_td)``, W the weight from A; 0 when friction cannot take the pull."""
        if not self.in_contact[self.contact_s > 0].any():
            return 0.0
        s_td = self.s_touchdown
        slope = self._slope_at(s_td)
        pull = self.H * np.sqrt(1.0 + slope * slope) / friction  # the tension at the touchdown / μ
        if self._weight_before(s_td) <= pull:
            return 0.0
        return float(brentq(lambda s: self._weight_before(s_td) - self._weight_before(s) - pull, 0.0, s_td))

    def _slack_tension(self):
        """Tension (N) just past the end ``s0`` of the slack stretch, and its slope (N/m) there:
        the first element that starts at s0."""
        s_l, s_r, T_l, T_r = self._tension_profile()
        k = int(np.argmin(np.abs(s_l - self._problem.slack_end)))
        friction_force = self.friction * (self._weight_before(s_r[k]) - self._weight_before(s_l[k]))
        return float(T_l[k]), float(friction_force / (s_r[k] - s_l[k]))

    def residual(self):
        """Largest scaled residual (forces over the total load, stretch over the length)."""
        return self._state.merit

    def __repr__(self):
        return (
            f"LineBVPSolution(span={self.span:g}, dh={self.dh:g}, {self.mesh.t.shape[1]} elements: "
            f"H={self.H:.9g}, V_B={self.V_B:.9g}, H_A={self.H_A:.9g}, V_A={self.V_A:.9g}, "
            f"{int(self.in_contact.sum())} nodes on the seabed, iterations={self.iterations})"
        )


def solve_line_bvp(
    span,
    dh,
    segments,
    *,
    seabed=None,
    seabed_slope=None,
    friction: float = 0.0,
    point_loads=(),
    n_elements: int = 64,
    fit_touchdown: int = 2,
    rtol: float = 1e-10,
    max_iter: int = 50,
):
    """A mooring line from anchor A = (0, 0) to fairlead B = (span, dh), by finite elements,
    optionally resting on a seabed of any shape (see `skcable.cable.bvp.line`).

    Parameters
    ----------
    span, dh : float
        Fairlead position relative to the anchor (m), ``span > 0``.
    segments : list of BVPSegment or (length, w, EA) tuples
        From A to B: unstretched length (m), weight per unstretched length
        (N/m, or a callable of the arc length s from A) and axial stiffness
        (N, None for inextensible). Joints are mesh nodes.
    seabed : float or callable, optional
        Seabed height ``b`` relative to A (m): a number (flat) or a callable
        ``b(x)`` (array in, array out). A must lie on or above it, B above it.
    seabed_slope : callable, optional
        ``b'(x)``; central differences of ``b`` (step 1e-5 span) otherwise.
    friction : float
        Coulomb coefficient μ of the grounded line, fully mobilised towards
        the anchor (Jonkman's model); needs a seabed.
    point_loads : sequence of (s, P)
        Downward force ``P`` (N; negative for a buoy) at arc length ``s``
        from A (a mesh node is put there).
    n_elements : int
        Elements over the whole line, shared among segments by length (at
        least one each).
    fit_touchdown : int
        Passes of touchdown fitting (and, when > 0, meshes graded by the
        line's curvature: module docstring): after a solve that touches the seabed,
        a mesh node is put at the touchdown (and the landing, for an anchor
        above the seabed) the vertical balance gives
        (`LineBVPSolution.s_touchdown`, ``s_landing``: the nearest inner node moves there
        when it is closer than a quarter of an element, else a node is
        inserted) and the line is solved again from the previous solution,
        until the touchdown moves less than 1e-9 of the length. Nodal contact
        otherwise misplaces the touchdown by up to half an element, an error
        in H of order (that distance)² that jumps with the mesh; 0 turns it off.
    rtol : float
        Newton stops when every scaled residual (forces over the total load,
        the stretch over the length, the complementarity rows over the total
        load) is below ``rtol``.
    max_iter : int
        Newton iterations at most.

    Returns
    -------
    LineBVPSolution

    Raises
    ------
    InputError
        Bad data, named; friction too weak to hold a slack stretch on a
        sloping seabed.
    ConvergenceError
        Newton stalled (``history`` holds the merit per iteration); the end
        of a slack stretch not found; the discrete line in compression (its
        bends not resolved by the mesh).
    """
    span, dh = positive("span", span), real("dh", dh)
    if not isinstance(span, float) or not isinstance(dh, float):
        raise InputError("span", "solve_line_bvp solves one scene: give scalar span and dh")
    segs = _segments(segments)
    bed = _seabed(seabed, seabed_slope, span)
    friction = nonnegative("friction", friction)
    if not isinstance(friction, float):
        raise InputError("friction", "one coefficient for the whole line")
    if friction > 0 and bed is None:
        raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
    if bed is not None:
        ends = bed(np.array([0.0, span]))
        require("seabed", ends[0] <= 0.0, "must be at or below the anchor A = (0, 0)", ends[0])
        require("dh", dh > ends[1], "must put B above the seabed", dh)
    L = sum(seg.length for seg in segs)
    loads = []
    try:
        items = list(point_loads)
    except TypeError:
        raise InputError("point_loads", f"must be a sequence of (s, P) pairs, got {point_loads!r}") from None
    for item in items:
        try:
            s, P = item
        except (TypeError, ValueError) as exc:
            raise InputError("point_loads", f"each is (s, P), got {item!r}") from exc
        s, P = real("point_loads", s), real("point_loads", P)
        if np.ndim(s) or np.ndim(P):
            raise InputError("point_loads", f"each is (s, P) with two numbers, got {item!r}")
        require("point_loads", 0.0 < s < L, "s must lie strictly inside the line (0, length)", s)
        loads.append((float(s), float(P)))
    whole("n_elements", n_elements, 1)
    whole("fit_touchdown", fit_touchdown, 0, 10)
    whole("max_iter", max_iter, 1)
    rtol = positive("rtol", rtol)
    name = "solve_line_bvp"

    def run(problem, z0):
        try:
            result = newton(
                problem.assemble,
                z0,
                norm=lambda state: state.merit,
                increment=problem.increment,
                tol=rtol,
                max_iter=int(max_iter),
                stagnation_window=8,
                name=name,
            )
            z, state, history = result.x, result.state, list(result.history)
        except ConvergenceError as failed:
            # the max-norm merit of a semismooth system can refuse every damped step where full
            # steps identify the active set and converge: try them before giving up
            out = _full_steps(problem, z0, rtol, int(max_iter))
            if out is None:
                raise failed from None
            z, state, history = out
        # past rtol, full Newton steps while the merit still falls tenfold: quadratic convergence
        # takes the solution to its round-off floor for one or two more solves
        for _ in range(POLISH):
            trial_z = z + problem.increment(state)
            trial = problem.assemble(trial_z)
            if not trial.merit < 0.1 * state.merit:
                break
            z, state = trial_z, trial
            history.append(state.merit)
        return LineBVPSolution(problem, z, history, state)

    def restart(solution, problem):  # the previous solution interpolated on a new mesh
        xy = solution.xy(problem.basis.doflocs[0])
        tension = solution.tension(np.clip(problem.tbasis.doflocs[0], 0.0, L))
        return np.concatenate([xy[:, 0], xy[:, 1], tension])

    def rerun(problem, solution):
        """The line on ``problem``'s mesh from ``solution`` interpolated onto it; else from the
        closed-form start (`_guess`): on a nearly L-shaped line the bend at the touchdown has the
        radius H/w, a thousandth of the length, and the interpolated bend of a coarser or
        differently graded mesh can start Newton farther off than the closed form does."""
        try:
            return run(problem, restart(solution, problem))
        except ConvergenceError as failed:
            try:
                return run(problem, _guess(problem))
            except ConvergenceError:
                raise failed from None

    def build(n, fitted=(), slack_end=0.0, mu=friction, nodes_at=None):
        return LineProblem(
            span, dh, segs, loads, bed, mu, n, fitted=fitted, slack_end=slack_end, nodes_at=nodes_at
        )

    def edges_of(solution):  # the touchdown and landing to put nodes at
        if not (fit_touchdown and solution.in_contact[solution.contact_s > 0].any()):
            return []
        return [solution.s_touchdown] + ([solution.s_landing] if solution.s_landing > 0 else [])

    def solve_level(n, start=None):
        """The line on n elements, from scratch or from ``start``, the finished solution on n/2."""
        s0, fitted, graded, tried = 0.0, [], None, []
        if start is None:
            # with friction, the frictionless line first: it tells where friction takes the pull
            problem = build(n, mu=0.0)
            if fit_touchdown:
                problem = build(n, mu=0.0, nodes_at=_guess_nodes(problem, n))
            solution = run(problem, _guess(problem))
        else:
            solution, s0, fitted = start, start._problem.slack_end, edges_of(start)
        mu_now = friction if start is not None else 0.0
        if fit_touchdown:
            # the mesh graded by the solution's curvature; again while the elements of the bends
            # could shrink no more than REFINEMENT times at one solve (its start then puts the
            # touchdown a node or two off: nodal contact moves a few nodes per Newton iteration)
            # or while the discrete line is in compression, a sign that its bends are not resolved
            for _ in range(GRADE_PASSES):
                graded, capped = _graded_nodes(solution, n)
                problem = build(n, fitted + ([s0] if s0 > 0 else []), s0, mu_now, graded)
                solution = rerun(problem, solution)
                compressed = np.min(solution._fields()[2]) < -1e3 * rtol * problem.load_scale
                if not (capped or compressed):
                    break
        elif start is not None:
            problem = build(n, [s0] if s0 > 0 else [], s0)
            solution = rerun(problem, solution)
        if start is None and friction > 0:
            # Jonkman's slack stretch [0, s0] of a grounded line whose friction takes the whole
            # pull: estimated from the frictionless line, or where friction fully mobilised
            # everywhere leaves the line near the anchor in compression
            if problem.anchor_on_seabed:
                s0 = solution._slack_estimate(friction)
            frictionless = solution
            problem = build(n, [s0] if s0 > 0 else [], s0, friction, graded)
            try:
                solution = rerun(problem, frictionless)
            except ConvergenceError as failed:
                # μ = 5 on a nearly L-shaped line: friction takes the whole pull H/(μw) (0.1 mm to
                # 2 mm) before the touchdown; with a node at the touchdown too the solve converges
                fitted = edges_of(frictionless)
                problem = build(n, fitted + ([s0] if s0 > 0 else []), s0, friction, graded)
                try:
                    solution = rerun(problem, frictionless)
                except ConvergenceError:
                    raise failed from None
            if s0 == 0 and problem.anchor_on_seabed:
                s0 = solution._tension_zero(1e3 * rtol * problem.load_scale)
        slack_tol = rtol * problem.load_scale
        edge_passes = 0
        for _ in range(int(fit_touchdown) + SLACK_PASSES):
            move, settled = False, True
            if edge_passes < int(fit_touchdown) or s0 > 0:
                edges = edges_of(solution)
                moved = np.inf
                if len(edges) == len(fitted):
                    moved = max((abs(a - b) for a, b in zip(edges, fitted, strict=True)), default=0.0)
                if moved > 1e-9 * L:
                    fitted, move, edge_passes = edges, True, edge_passes + 1
                    settled = moved <= 1e-6 * L  # the tension past s0 is worth a bracket only then
            if s0 > 0 or solution._problem.slack_end > 0:
                if solution._problem.slack_end == s0:
                    g, slope = solution._slack_tension()
                    if abs(g) > slack_tol:
                        s0 = _next_slack_end([*tried, (s0, g)], slope, solution.s_touchdown)
                        if settled:
                            tried.append((solution._problem.slack_end, g))
                        move = True
                else:
                    move = True
            if not move:
                break
            problem = build(n, fitted + ([s0] if s0 > 0 else []), s0, friction, graded)
            solution = rerun(problem, solution)
        if s0 > 0:
            g, _ = solution._slack_tension()
            if not abs(g) <= slack_tol:
                raise ConvergenceError(
                    f"{name}: the end of the slack stretch near the anchor was not found "
                    f"(tension {g:.3g} N there after {len(tried)} updates)",
                    solution.history,
                )
        return solution

    n = int(n_elements)
    probe = build(n, mu=0.0)
    if n > 2 * COARSE and bed is not None and np.any(probe.gaps(_guess(probe)) <= 0):
        # nested meshes: the active set moves by a few nodes per Newton iteration, so the line is
        # solved on COARSE-odd elements first and each finished solution starts the doubled mesh
        sizes = [n]
        while sizes[-1] // 2 >= COARSE:
            sizes.append(sizes[-1] // 2)
        solution = None
        for size in reversed(sizes):
            try:
                solution = solve_level(size, solution)
            except ConvergenceError:
                # a coarse mesh that cannot resolve a tight bend (a nearly L-shaped line, the
                # bend's radius H/w a thousandth of the length) stalls, or its solution starts
                # the finer mesh too far off: this level from scratch, else the next one
                if size == n:
                    if solution is None:
                        raise
                    solution = solve_level(size)
                else:
                    try:
                        solution = solve_level(size)
                    except ConvergenceError:
                        solution = None
    else:
        solution = solve_level(n)
    problem = solution._problem
    slack_tol = rtol * problem.load_scale
    s0 = problem.slack_end
    if s0 > 0:
        # the friction that holds the slack stretch (its tangential force) is at most μN
        on = solution.contact_s < s0
        slope = solution._problem.seabed.slope(solution.contact_xy[on, 0])
        force = solution.contact_force[on]
        tangential = np.abs(force[:, 0] + slope * force[:, 1]) / np.sqrt(1.0 + slope * slope)
        if np.any(tangential > friction * solution.normal_force[on] + slack_tol):
            raise InputError(
                "friction",
                "too weak to hold the slack stretch near the anchor on the sloping seabed "
                "(the line would slide down it)",
            )
    values = (solution.H, solution.V_B, solution.H_A, solution.V_A)
    if not all(np.isfinite(values)) or not np.all(np.isfinite(solution.dofs)):
        raise ConvergenceError(f"{name}: non-finite result", solution.history)
    T = solution._fields()[2]
    if np.min(T) < -1e3 * rtol * problem.load_scale:
        raise ConvergenceError(
            f"{name}: the discrete line is in compression "
            f"(min T = {np.min(T):.3g} N, H = {solution.H:.3g} N): "
            + (
                "fully mobilised friction with the anchor above the seabed"
                if friction > 0 and not problem.anchor_on_seabed
                else f"{problem.mesh.t.shape[1]} elements do not resolve its bends; give more"
            ),
            solution.history,
        )
    return solution
