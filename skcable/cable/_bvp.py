r"""Suspended cables as 1D nonlinear boundary-value problems on scikit-fem.

Graph formulation (seed 000 §3, seed 001 §3.1): with no horizontal load
the horizontal tension H is constant and the profile y(x) satisfies

.. math:: H\,y'' = q(x, y', H), \qquad y(0) = 0,\quad y(\mathrm{span}) = dh,

``q`` the downward load per unit horizontal length (self weight per cable
length becomes ``w sqrt(1 + y'^2)``, or ``w f`` with the unstretched
measure ``f`` of :mod:`skcable.cable._loads` when ``EA`` is given), plus
point loads ``P`` that kink the cable. Weak form, for every test function
v vanishing at the supports:

.. math:: R(y, H; v) = \int_0^{\mathrm{span}} \left(H y' v' + q\,v\right)dx
          + \sum_k P_k v(x_k) = 0,

closed by one constraint ``g(y, H) = 0`` (length, sag, H, lowest point or
maximum tension), H being a global unknown: Newton's method on the
bordered system

.. math:: \begin{bmatrix} K & \partial R/\partial H \\
                          \partial g/\partial y & \partial g/\partial H \end{bmatrix}
          \begin{bmatrix}\delta y \\ \delta H\end{bmatrix}
          = -\begin{bmatrix} R \\ g \end{bmatrix},

with the analytic Jacobian ``K = ∫ (H u' v' + dq/dy' u' v) dx``, backtracking
on the residual, and the catenary of the same total load as the initial
guess (the parabola where no catenary meets the constraint). The support
reactions come out of the residual at the boundary dofs
(``V_A = R_A = -H y'(0)``, ``V_B = R_B = H y'(span)``), which is exact for
the discrete solution.

The forms below are public: :data:`graph_residual`, :data:`graph_tangent`,
:data:`graph_dH`; a load is any object with ``graph_terms`` (see
:mod:`skcable.cable._loads`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from numpy.polynomial import Polynomial
from skfem import (
    Basis,
    BilinearForm,
    ElementLineP1,
    ElementLineP2,
    ElementLinePp,
    LinearForm,
    MeshLine,
    asm,
    solve,
)

from skcable._checks import exactly_one, positive, real, require
from skcable.cable._catenary import catenary
from skcable.cable._loads import PointLoad, unstretched_measure
from skcable.cable._parabola import parabola
from skcable.cable.solution import CableSolution, checked
from skcable.errors import ConvergenceError, InputError

__all__ = ["BVPSolution", "graph_dH", "graph_residual", "graph_tangent", "solve_bvp"]


@LinearForm
def graph_residual(v, w):
    """``∫ (H y' v' + q v) dx``, ``y' = s + u'``: the weak equilibrium of the graph form."""
    return w.H * (w.s + w.u.grad[0]) * v.grad[0] + w.q * v


@BilinearForm
def graph_tangent(u, v, w):
    """``∂R/∂y``: ``∫ (H u' v' + dq/dy' u' v) dx``."""
    return w.H * u.grad[0] * v.grad[0] + w.dq_dslope * u.grad[0] * v


@LinearForm
def graph_dH(v, w):
    """``∂R/∂H``: ``∫ (y' v' + dq/dH v) dx``."""
    return (w.s + w.u.grad[0]) * v.grad[0] + w.dq_dH * v


_ELEMENTS = {1: ElementLineP1, 2: ElementLineP2}


class ElementLinePpExact(ElementLinePp):
    """``ElementLinePp`` whose Legendre cache is keyed on the points themselves.

    scikit-fem 12's ``ElementLinePp.lbasis`` re-evaluates its cached values
    only when the *number* of points changes, so evaluating at one point and
    then at another (``Basis.probes``, ``interpolator``) returns the first
    point's values. Assembly, always at the same quadrature points, is not
    affected.
    """

    _cached_at = None

    def lbasis(self, X, i):
        if (
            self._cached_at is None
            or self._cached_at.shape != X[0].shape
            or not np.array_equal(self._cached_at, X[0])
        ):
            self.P, self.dP = self._reval_legendre(X[0, :], self.p)
            self._cached_at = np.array(X[0], copy=True)
        return self.P[i], self.dP[i]


def _element(degree):
    if degree in _ELEMENTS:
        return _ELEMENTS[degree]()
    if isinstance(degree, (int, np.integer)) and 3 <= degree <= 6:
        return ElementLinePpExact(int(degree))
    raise InputError("degree", f"must be an integer from 1 to 6, got {degree!r}")


def _gradient_probes(basis, x):
    """Matrix giving dy/dx at the points ``x`` (skfem's ``probes`` gives values)."""
    x = np.atleast_2d(np.asarray(x, dtype=float))
    cells = basis.mesh.element_finder(mapping=basis.mapping)(*x)
    pts = basis.mapping.invF(x[:, :, np.newaxis], tind=cells)
    grads = np.array(
        [basis.elem.gbasis(basis.mapping, pts, k, tind=cells)[0].grad[0] for k in range(basis.Nbfun)]
    ).reshape(basis.Nbfun, -1)
    rows = np.tile(np.arange(x.shape[1]), basis.Nbfun)
    cols = basis.element_dofs[:, cells].flatten()
    return sp.coo_matrix((grads.flatten(), (rows, cols)), shape=(x.shape[1], basis.N)).tocsr()


def element_values(basis, element, x):
    """Values at ``x`` (scalar or 1-D) of every basis function of ``element`` (as skfem's
    ``probes``, through ``gbasis``, which orients hierarchical modes): (Nbfun,) or (Nbfun, n)."""
    points = np.atleast_1d(np.asarray(x, dtype=float))
    cells = np.array([element])
    X = basis.mapping.invF(points[None, None, :], tind=cells)
    values = np.array(
        [np.asarray(basis.elem.gbasis(basis.mapping, X, j, tind=cells)[0]) for j in range(basis.Nbfun)]
    ).reshape(basis.Nbfun, points.size)
    return values[:, 0] if np.ndim(x) == 0 else values


def element_minimum(basis, element, local, lean=0.0):
    """Minimum over ``element`` of ``local·φ(x) + lean·x``: (value, x).

    The field is a polynomial of the element's degree in x: it is sampled at
    degree + 1 Chebyshev points, fitted exactly, and minimised over the
    roots of its derivative and the element's ends.
    """
    left, right = np.sort(basis.mesh.p[0, basis.mesh.t[:, element]])
    degree = max(int(basis.elem.maxdeg), 1)
    theta = np.pi * (np.arange(degree + 1) + 0.5) / (degree + 1)
    x = left + (right - left) * 0.5 * (1.0 - np.cos(theta))
    poly = Polynomial.fit(
        x, local @ element_values(basis, element, x) + lean * x, degree, domain=[left, right]
    )
    roots = poly.deriv().roots()
    roots = roots[np.isreal(roots)].real
    candidates = np.concatenate([[left, right], roots[(roots > left) & (roots < right)]])
    values = poly(candidates)
    best = int(np.argmin(values))
    return float(values[best]), float(candidates[best])


@dataclass
class _State:
    """Everything assembled at one iterate."""

    R: np.ndarray  # full residual vector
    K: sp.csr_matrix
    dR_dH: np.ndarray
    g: float
    dg_dy: np.ndarray
    dg_dH: float
    merit: float  # max-norm of the scaled residual: the convergence test
    descent: float  # 2-norm of the scaled residual: the line-search merit


class FiniteElementSolution(CableSolution):
    """What the graph and arc-length solutions share: sag and lowest point by
    a search of the discrete profile (``problem.extremum``)."""

    @cached_property
    def _sag(self):
        return self._problem.extremum(self.dofs, "sag")

    @cached_property
    def _low(self):
        return self._problem.extremum(self.dofs, "low")

    @property
    def sag(self):
        return self._sag[1]

    @property
    def y_low(self):
        return self._low[1]


class BVPSolution(FiniteElementSolution):
    formulation = "graph"

    """Solution of :func:`solve_bvp`.

    Attributes are those of :class:`~skcable.cable.Catenary` (``H, V_A, V_B,
    T_A, T_B, length, sag, x_low, y_low``, methods ``y, T, slope,
    residual``) plus ``mesh``, ``basis``, ``dofs`` (the FE vector of y),
    ``iterations``, ``history`` (merit per Newton iteration), ``dofs`` (the FE
    vector of ``u = y - (dh/span) x``, the depth below the chord, so that
    rounding scales with the sag rather than with dh),
    ``stretched_length`` and ``EA``. With ``EA``, ``length`` is the
    unstretched length, as for :func:`~skcable.cable.elastic_catenary`.
    """

    def __init__(self, problem, dofs, H, history):
        self._problem = problem
        self.span, self.dh, self.EA = problem.span, problem.dh, problem.EA
        self.mesh, self.basis = problem.mesh, problem.basis
        self.dofs, self.H = dofs, H
        self.history = list(history)
        self.iterations = len(self.history) - 1
        self.constraint = problem.constraint
        self._state = problem.assemble(dofs, H)

    @cached_property
    def V_A(self):
        return float(self._state.R[self._problem.end_a])

    @cached_property
    def V_B(self):
        return float(self._state.R[self._problem.end_b])

    @cached_property
    def T_A(self):
        return float(np.hypot(self.H, self.V_A))

    @cached_property
    def T_B(self):
        return float(np.hypot(self.H, self.V_B))

    @cached_property
    def stretched_length(self):
        return self._problem.lengths(self.dofs, self.H)[0]

    @cached_property
    def length(self):
        lengths = self._problem.lengths(self.dofs, self.H)
        return lengths[1] if self.EA is not None else lengths[0]

    @property
    def x_low(self):
        return self._low[0]

    def y(self, x):
        """Height of the cable above A at ``x`` (m)."""
        x = np.asarray(real("x", x), dtype=float)
        out = self.basis.probes(x.reshape(1, -1)) @ self.dofs
        return (self._problem.chord_slope * x + out.reshape(x.shape))[()]

    def slope(self, x):
        """dy/dx at ``x`` (inside an element; the one to the left at nodes)."""
        x = np.asarray(real("x", x), dtype=float)
        du = (_gradient_probes(self.basis, x.reshape(1, -1)) @ self.dofs).reshape(x.shape)
        return (self._problem.chord_slope + du)[()]

    def T(self, x):
        """Tension at ``x`` (N): ``H sqrt(1 + y'^2)``."""
        return self.H * np.sqrt(1.0 + self.slope(x) ** 2)

    def weight_per_length(self, x, slope):
        problem = self._problem
        q = sum(ld.graph_terms(x, slope, self.H, self.EA)[0] for ld in problem.distributed)
        return q / unstretched_measure(slope, self.H, self.EA)[0]

    def _residuals(self):
        problem, state = self._problem, self._state
        scale = problem.load_scale
        yield np.max(np.abs(state.R[problem.interior]), initial=0.0) / scale  # weak equilibrium
        yield state.g / problem.constraint_scale
        yield from self._common_residuals(np)

    def __repr__(self):
        return (
            f"BVPSolution(span={self.span:g}, dh={self.dh:g}, {self.mesh.t.shape[1]} elements: "
            f"H={self.H:.9g}, V_A={self.V_A:.9g}, V_B={self.V_B:.9g}, length={self.length:.9g}, "
            f"iterations={self.iterations})"
        )


class _GraphProblem:
    """Mesh, basis, loads and constraint of one graph-form solve."""

    def __init__(self, span, dh, loads, EA, constraint, mesh, n_elements, degree):
        self.span, self.dh, self.EA, self.constraint = span, dh, EA, constraint
        self.chord_slope = dh / span  # the unknown is u = y - chord_slope * x, zero at both supports
        self.point_loads = [ld for ld in loads if isinstance(ld, PointLoad)]
        self.distributed = [ld for ld in loads if not isinstance(ld, PointLoad)]
        for ld in self.distributed:
            if not hasattr(ld, "graph_terms"):
                raise InputError("load", f"{ld!r} has no graph_terms(x, slope, H, EA) method")
        xs = [ld.x for ld in self.point_loads]
        at = np.array(xs if xs else [0.5 * span])
        require("load", (at > 0) & (at < span), "point loads need 0 < x < span", at)
        if mesh is None:
            n = int(positive("n_elements", n_elements))
            nodes = np.union1d(np.linspace(0.0, span, n + 1), xs)
        else:
            nodes = np.union1d(np.asarray(mesh.p[0] if isinstance(mesh, MeshLine) else mesh, dtype=float), xs)
            if not (np.isclose(nodes[0], 0.0) and np.isclose(nodes[-1], span)):
                raise InputError("mesh", f"must run from 0 to span = {span}, got [{nodes[0]}, {nodes[-1]}]")
            nodes[0], nodes[-1] = 0.0, span
        self.mesh = MeshLine(nodes)
        element = _element(degree)
        self.basis = Basis(self.mesh, element, intorder=2 * element.maxdeg + 2)
        self.x_quad = np.asarray(self.basis.global_coordinates())[0]
        boundary = self.basis.get_dofs().all()
        self.end_a, self.end_b = (
            (boundary[0], boundary[1]) if self.basis.doflocs[0, boundary[0]] == 0 else boundary[::-1]
        )
        self.interior = self.basis.complement_dofs(boundary)
        node_of = {float(x): i for i, x in enumerate(nodes)}
        self.point_dofs = np.array(
            [self.basis.nodal_dofs[0, node_of[float(ld.x)]] for ld in self.point_loads], dtype=int
        )
        self.point_values = np.array([ld.P for ld in self.point_loads], dtype=float)

    # --- pieces ----------------------------------------------------------
    def load_terms(self, slope, H):
        q = np.zeros_like(slope)
        dq_ds, dq_dh = np.zeros_like(slope), np.zeros_like(slope)
        for load in self.distributed:
            a, b, c = load.graph_terms(self.x_quad, slope, H, self.EA)
            q, dq_ds, dq_dh = q + a, dq_ds + b, dq_dh + c
        return q, dq_ds, dq_dh

    def lengths(self, dofs, H):
        """(stretched, unstretched) length by the basis' quadrature."""
        slope = self.chord_slope + self.basis.interpolate(dofs).grad[0]
        f = unstretched_measure(slope, H, self.EA)[0]
        dx = self.basis.dx
        return float(np.sum(np.sqrt(1.0 + slope**2) * dx)), float(np.sum(f * dx))

    def extremum(self, dofs, kind):
        """(x*, value, d value/d dofs) of the sag (max of tilt·x - y) or the lowest point (min y).

        The best quadrature point picks the element; the exact minimum of the
        element's polynomial is taken there and in its two neighbours.
        """
        tilt = 0.0 if kind == "low" else self.chord_slope  # minimise y - tilt x = u + (s - tilt) x
        lean = self.chord_slope - tilt
        at_quad = np.asarray(self.basis.interpolate(dofs)) + lean * self.x_quad
        element = int(np.unravel_index(np.argmin(at_quad), at_quad.shape)[0])
        candidates = []
        for k in range(max(element - 1, 0), min(element + 2, self.mesh.t.shape[1])):
            local = dofs[self.basis.element_dofs[:, k]]
            candidates.append((*element_minimum(self.basis, k, local, lean), k))
        _, x_star, k = min(candidates)
        row = np.zeros(self.basis.N)
        row[self.basis.element_dofs[:, k]] = element_values(self.basis, k, x_star)
        y_star = self.chord_slope * x_star + float(row @ dofs)
        value = y_star if kind == "low" else tilt * x_star - y_star
        return x_star, value, row

    def assemble(self, dofs, H) -> _State:
        u = self.basis.interpolate(dofs)
        slope_u = u.grad[0]
        slope = self.chord_slope + slope_u
        q, dq_ds, dq_dh = self.load_terms(slope, H)
        R = asm(graph_residual, self.basis, u=u, s=self.chord_slope, H=H, q=q)
        R[self.point_dofs] += self.point_values
        K = asm(graph_tangent, self.basis, H=H, dq_dslope=dq_ds)
        dR_dH = asm(graph_dH, self.basis, u=u, s=self.chord_slope, dq_dH=dq_dh)
        name, value = self.constraint
        zero = np.zeros(self.basis.N)
        if name == "H":
            g, dg_dy, dg_dH = H - value, zero, 1.0
        elif name == "length":
            f, df_ds, df_dh = unstretched_measure(slope, H, self.EA)
            if self.EA is None:  # excess over the chord, free of cancellation (taut cables)
                s, du = self.chord_slope, slope_u
                excess = du * (2.0 * s + du) / (f + np.hypot(1.0, s))
                g = float(np.sum(excess * self.basis.dx)) - self.excess_length
            else:
                g = float(np.sum(f * self.basis.dx)) - value
            dg_dy = asm(LinearForm(lambda v, w: w.df_ds * v.grad[0]), self.basis, df_ds=df_ds)
            dg_dH = float(np.sum(df_dh * self.basis.dx))
        elif name in ("sag", "low"):
            _, achieved, row = self.extremum(dofs, name)
            g, dg_dy, dg_dH = achieved - value, (row if name == "low" else -row), 0.0
        else:  # T_max: the larger end tension, reactions from the residual rows
            end = self.end_a if abs(R[self.end_a]) >= abs(R[self.end_b]) else self.end_b
            v = R[end]  # V_A = R_A, V_B = R_B
            T = np.hypot(H, v)
            g = T - value
            dg_dy = (v / T) * K.getrow(end).toarray()[0]
            dg_dH = (H + v * dR_dH[end]) / T
        scaled = np.concatenate([R[self.interior] / self.load_scale, [g / self.constraint_scale]])
        return _State(
            R,
            K,
            dR_dH,
            float(g),
            dg_dy,
            float(dg_dH),
            float(np.max(np.abs(scaled))),
            float(np.linalg.norm(scaled)),
        )

    @cached_property
    def load_scale(self):
        """Total vertical load on the straight chord (N): scale of the residual."""
        slope = np.full_like(self.x_quad, self.dh / self.span)
        q, _, _ = self.load_terms(slope, 0.0)
        return float(np.sum(np.abs(q) * self.basis.dx) + np.sum(np.abs(self.point_values))) or 1.0

    @cached_property
    def excess_length(self):
        """Given length minus chord, with the chord's rounding kept out (as in catenary())."""
        length = self.constraint[1]
        legs = abs(self.dh)
        longer, shorter = max(self.span, legs), min(self.span, legs)
        return ((length - longer) * (length + longer) - shorter * shorter) / (
            length + np.hypot(self.span, self.dh)
        )

    @property
    def constraint_scale(self):
        name, value = self.constraint
        if name == "low":
            return float(np.hypot(self.span, self.dh))
        if name == "length":  # relative to the excess over the chord: taut cables keep their digits
            return float(self.excess_length) if self.EA is None else self.stretched_excess
        return abs(float(value))

    #: stretched length minus chord at the initial guess (set by :func:`_initial_guess`)
    stretched_excess = 1.0

    def newton_step(self, state, H):
        name = self.constraint[0]
        interior = self.interior
        K_ii = state.K[interior][:, interior]
        if name == "H":
            return solve(K_ii, -state.R[interior]), -state.g / state.dg_dH
        border = sp.bmat(
            [
                [K_ii, sp.csr_matrix(state.dR_dH[interior][:, None])],
                [sp.csr_matrix(state.dg_dy[interior][None, :]), sp.csr_matrix([[state.dg_dH]])],
            ],
            format="csr",
        )
        step = solve(border, -np.concatenate([state.R[interior], [state.g]]))
        return step[:-1], step[-1]


def _initial_guess(problem):
    """Catenary (or, where none fits the constraint, parabola) of the same total load."""
    name, value = problem.constraint
    chord = np.hypot(problem.span, problem.dh)
    if name == "length" and value <= chord:
        if problem.EA is None:
            raise InputError("length", "must exceed the chord sqrt(span**2 + dh**2)")
        value = chord * (1 + 1e-6)  # an elastic cable shorter than its chord: start just slack
    length = value if name == "length" else chord
    try:
        guess = catenary(problem.span, problem.dh, problem.load_scale / length, **{name: value})
    except InputError:
        guess = parabola(problem.span, problem.dh, problem.load_scale / problem.span, **{name: value})
    s = problem.chord_slope
    basis = problem.basis
    locations = basis.doflocs[0]
    if np.all(np.isfinite(locations)):  # Lagrange element: interpolate at the dofs
        dofs = guess.y(locations) - s * locations
    else:  # hierarchical (ElementLinePp): vertex values, modal dofs zero
        dofs = np.zeros(basis.N)
        dofs[basis.nodal_dofs[0]] = guess.y(problem.mesh.p[0]) - s * problem.mesh.p[0]
    dofs[problem.end_a], dofs[problem.end_b] = 0.0, 0.0
    if problem.EA is not None:
        problem.stretched_excess = max(problem.lengths(dofs, guess.H)[0] - chord, 1e-12 * chord)
    return dofs, float(guess.H)


def _choose_formulation(formulation, span, dh, loads, name, value):
    if formulation not in ("auto", "graph", "arc"):
        raise InputError("formulation", f"must be 'auto', 'graph' or 'arc', got {formulation!r}")
    if formulation != "auto":
        return formulation
    horizontal = any(getattr(ld, "qx", None) is not None for ld in loads)
    return "arc" if horizontal else "graph"


def solve_bvp(
    span,
    dh,
    load,
    *,
    length=None,
    sag=None,
    H=None,
    low=None,
    T_max=None,
    EA=None,
    n_elements: int = 64,
    degree: int = 2,
    mesh=None,
    rtol: float = 1e-10,
    max_iter: int = 50,
    formulation: str = "auto",
):
    """Suspended cable under any vertical loads, solved by finite elements.

    Parameters
    ----------
    span, dh : float
        B = (span, dh) relative to A = (0, 0) (m).
    load : load or list of loads
        :class:`SelfWeight`, :class:`DeckLoad`, :class:`DistributedLoad`,
        :class:`PointLoad`, or any object with ``graph_terms``.
    length, sag, H, low, T_max : float
        Exactly one constraint, as in :func:`~skcable.cable.catenary`; with
        ``EA``, ``length`` is the unstretched length. ``T_max`` is the larger
        end tension.
    EA : float, optional
        Axial stiffness (N); inextensible when omitted.
    n_elements, degree : int
        Uniform mesh size and polynomial degree (1 to 6) of y.
    mesh : MeshLine or array, optional
        Node abscissae from 0 to span, instead of ``n_elements``.
    rtol : float
        Newton stops when the interior residual (relative to the total load)
        and the constraint residual are both below ``rtol``.
    formulation : {"auto", "graph", "arc"}
        ``"graph"``: y(x) with H a global unknown (any degree, point loads);
        ``"arc"``: position and tension along the unstretched arc length
        (:mod:`skcable.cable._arc`: any shape, horizontal loads, P2/P1).
        ``"auto"`` takes the arc form when a load has a horizontal
        component, the graph form otherwise: started from the catenary of
        the same weight it converges from 1e-9 to 99 times the chord and
        for spans down to 1e-3 of the height difference, and it is the more
        accurate per element (docs/bvp.md maps both).

    Returns
    -------
    BVPSolution or ArcSolution
        ``formulation`` tells which was used.

    Raises
    ------
    InputError
        Bad data (named argument).
    ConvergenceError
        Newton stalled; ``history`` holds the merit per iteration.
    """
    span, dh = positive("span", span), real("dh", dh)
    loads = list(load) if isinstance(load, (list, tuple)) else [load]
    if not loads:
        raise InputError("load", "give at least one load")
    EA = None if EA is None else positive("EA", EA)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    value = real(name, value) if name == "low" else positive(name, value)
    if name == "low":
        require("low", value < min(0.0, dh), "must lie below both supports, low < min(0, dh)", value)
    positive("rtol", rtol)
    formulation = _choose_formulation(formulation, span, dh, loads, name, value)
    if formulation == "arc":
        from skcable.cable._arc import solve_arc

        solution = solve_arc(span, dh, loads, EA, (name, value), n_elements, degree, rtol, max_iter)
        return checked(solution, solution.history)
    problem = _GraphProblem(span, dh, loads, EA, (name, value), mesh, n_elements, degree)
    dofs, H_k = _initial_guess(problem)
    if name == "H":
        H_k = value
    interior = problem.interior
    state = problem.assemble(dofs, H_k)
    history = [state.merit]
    for _ in range(max_iter):
        if state.merit < rtol:
            return checked(BVPSolution(problem, dofs, H_k, history), history)
        d_y, d_H = problem.newton_step(state, H_k)
        step = 1.0
        for _ in range(40):  # backtracking: H stays positive, the merit falls
            trial_dofs = dofs.copy()
            trial_dofs[interior] += step * d_y
            trial_H = H_k + step * d_H
            if trial_H > 0:
                trial = problem.assemble(trial_dofs, trial_H)
                if trial.descent < (1.0 - 1e-4 * step) * state.descent or trial.merit < rtol:
                    break
            step *= 0.5
        else:
            raise ConvergenceError(
                "solve_bvp: line search failed (no descent along the Newton step)", history
            )
        dofs, H_k, state = trial_dofs, trial_H, trial
        history.append(state.merit)
    if state.merit < rtol:
        return checked(BVPSolution(problem, dofs, H_k, history), history)
    raise ConvergenceError(f"solve_bvp: no convergence to {rtol:g} in {max_iter} Newton iterations", history)
