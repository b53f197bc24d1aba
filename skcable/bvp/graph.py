r"""Graph form of the suspended cable: y(x) with the horizontal tension H a global unknown.

The lecture notes "Cables" §3, Goicolea (2012) §3.1: with no horizontal load H is constant and

.. math:: H\,y'' = q(x, y', H), \qquad y(0) = 0,\quad y(\mathrm{span}) = dh,

``q`` the downward load per unit horizontal length (self weight per cable
length becomes ``w sqrt(1 + y'^2)``, or ``w f`` with the unstretched measure
``f`` of `skcable.bvp.loads` when ``EA`` is given), plus point loads
``P`` that kink the cable. Weak form, for every test function v vanishing at
the supports (`graph_residual`):

.. math:: R(y, H; v) = \int_0^{\mathrm{span}} \left(H y' v' + q\,v\right)dx
          + \sum_k P_k v(x_k) = 0,

closed by one constraint ``g(y, H) = 0`` (length, sag, H, lowest point or
maximum tension). The unknown is the depth below the chord ``u = y - (dh/span)
x`` (zero at both supports, so that rounding scales with the sag), any degree
1–6. `GraphProblem.assemble` evaluates the residual, the tangent (per
element), ``∂R/∂H`` and the constraint row with basis values, element
products and a band layout computed once per problem; the increment is the
bordered banded solve of `skcable.fe.linear.BorderedSolver`. Support
reactions are the residual rows at the supports (``V_A = R_A``, ``V_B =
R_B``), exact for the discrete solution.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from skfem import Basis, MeshLine

from skcable._checks import positive, real, require
from skcable.bvp.base import FiniteElementSolution, sampled_outputs
from skcable.bvp.elements import end_dofs, line_element
from skcable.bvp.loads import PointLoad, unstretched_measure
from skcable.bvp.terms import CableState, CableTerm
from skcable.cable._catenary import catenary
from skcable.cable._parabola import parabola
from skcable.errors import InputError
from skcable.fe.assembly import Assembly
from skcable.fe.linear import BorderedSolver
from skcable.fe.probes import element_values, gradient_probes, minimum_near

__all__ = ["BVPSolution", "GraphProblem", "GraphState", "initial_guess"]


@dataclass
class GraphState:
    """Everything assembled at one iterate (vectors over all dofs, supports included)."""

    R: np.ndarray  # residual
    Ke: np.ndarray  # element tangents (n_local, n_local, ne)
    dR_dH: np.ndarray
    g: float
    dg_dy: np.ndarray
    dg_dH: float
    merit: float  # max-norm of the scaled residual: the convergence test
    descent: float  # 2-norm of the scaled residual: the line-search merit
    assembly: Assembly

    @cached_property
    def K(self):
        """The global tangent ``∂R/∂y`` (CSR), for inspection; Newton uses the band of ``Ke``."""
        return self.assembly.matrix(element_matrices=self.Ke)


def graph_term_loads(terms, x, y, slope, H, EA):
    """The cable terms' downward load per horizontal length ``q = −f_y m`` and its derivatives
    by y', H and y (`skcable.bvp.terms`): ``m = ds/dx`` the unstretched length per horizontal
    length, ``a = (1, y')/m``, ``T = H sqrt(1 + y'^2)``; a horizontal force is refused."""
    m, dm_ds, dm_dH = unstretched_measure(slope, H, EA)
    c = np.sqrt(1.0 + slope * slope)
    a = np.array([np.ones_like(slope), slope]) / m
    state = CableState(x, y, None, a, H * c)
    da_ds = np.array([np.zeros_like(slope), np.ones_like(slope)]) / m - a * (dm_ds / m)
    da_dH = -a * (dm_dH / m)
    q, dq_ds, dq_dH, dq_dy = (np.zeros_like(slope) for _ in range(4))
    for term in terms:
        out = term.forces(state)
        f = np.asarray(out.f, dtype=float)
        if f.shape != (2, *slope.shape) or not np.all(np.isfinite(f)):
            raise InputError("load", f"{term!r} returned forces of shape {f.shape} or non-finite ones")
        if np.any(f[0] != 0.0):
            raise InputError("load", f"{term!r} has a horizontal component: give formulation='arc'")
        fy = f[1]
        dfy_ds = np.zeros_like(slope) if out.df_da is None else np.sum(out.df_da[1] * da_ds, axis=0)
        dfy_dH = np.zeros_like(slope) if out.df_da is None else np.sum(out.df_da[1] * da_dH, axis=0)
        if out.df_dT is not None:  # T = H c: ∂T/∂y' = H y'/c, ∂T/∂H = c
            dfy_ds = dfy_ds + out.df_dT[1] * H * slope / c
            dfy_dH = dfy_dH + out.df_dT[1] * c
        q = q - fy * m
        dq_ds = dq_ds - (dfy_ds * m + fy * dm_ds)
        dq_dH = dq_dH - (dfy_dH * m + fy * dm_dH)
        if out.df_dr is not None:
            dq_dy = dq_dy - out.df_dr[1, 1] * m
    return q, dq_ds, dq_dH, dq_dy


def _mesh_nodes(mesh, n_elements, span, at):
    """Node abscissae from 0 to span (point-load abscissae ``at`` added)."""
    if mesh is None:
        n = positive("n_elements", n_elements)
        require("n_elements", n == int(n) and n < 2**31, "must be a whole number", n)
        nodes = np.linspace(0.0, span, int(n) + 1)
        return np.union1d(nodes, at) if len(at) else nodes
    given = np.asarray(real("mesh", mesh.p[0] if isinstance(mesh, MeshLine) else mesh), dtype=float)
    if given.ndim != 1 or given.size < 2:
        raise InputError("mesh", f"must be a 1-D array of at least 2 node abscissae, got shape {given.shape}")
    nodes = np.sort(given)
    gaps = np.diff(nodes)
    if np.any(gaps <= 1e-12 * span):
        k = int(np.argmin(gaps))
        raise InputError("mesh", f"repeated node at x = {nodes[k]!r} (elements must have positive length)")
    if not (np.isclose(nodes[0], 0.0) and np.isclose(nodes[-1], span)):
        raise InputError("mesh", f"must run from 0 to span = {span}, got [{nodes[0]}, {nodes[-1]}]")
    nodes[0], nodes[-1] = 0.0, span
    return np.union1d(nodes, at) if len(at) else nodes


class GraphProblem:
    """Mesh, basis, loads, constraint and the assembly of one graph-form solve."""

    def __init__(self, span, dh, loads, EA, constraint, mesh, n_elements, degree):
        self.span, self.dh, self.EA, self.constraint = span, dh, EA, constraint
        self.loads, self.degree = list(loads), degree
        self.chord_slope = dh / span  # the unknown is u = y - chord_slope * x, zero at both supports
        self.point_loads = [ld for ld in loads if isinstance(ld, PointLoad)]
        self.terms = [ld for ld in loads if isinstance(ld, CableTerm)]
        for term in self.terms:
            if term.uses_s:
                raise InputError("load", f"{term!r} reads the arc length s: give formulation='arc'")
        self.distributed = [ld for ld in loads if not isinstance(ld, (PointLoad, CableTerm))]
        for ld in self.distributed:
            if not hasattr(ld, "graph_terms"):
                raise InputError("load", f"{ld!r} has no graph_terms(x, slope, H, EA) method")
        xs = np.array([float(ld.x) for ld in self.point_loads])
        at = xs if xs.size else np.array([0.5 * span])
        require("load", (at > 0) & (at < span), "point loads need 0 < x < span", at)
        element = line_element(degree)
        nodes = _mesh_nodes(mesh, n_elements, span, xs)
        self.mesh = MeshLine(nodes)
        basis = self.basis = Basis(self.mesh, element, intorder=2 * element.maxdeg + 2)
        N = basis.N
        # strains: y' (order 1) and y (order 0); basis values and element products once
        self.assembly = Assembly({"u": basis}, [("u", 1), ("u", 0)])
        self.x_quad = self.assembly.x  # (nq, ne), as every quadrature array here
        self._stiffness = self.assembly.block(0, 0)  # ∫ φ_i' φ_j' dx
        self.end_a, self.end_b, self.interior = end_dofs(basis)
        self.solver = BorderedSolver(self.assembly.banded(self.interior))
        # point loads: the nodal dof at each abscissa, repeated abscissae summed
        self.point_values = np.array([float(ld.P) for ld in self.point_loads])
        self.point_dofs = basis.nodal_dofs[0, np.searchsorted(nodes, xs)].astype(int)
        self.point_vector = np.bincount(self.point_dofs, weights=self.point_values, minlength=N)

    # --- pieces ----------------------------------------------------------
    def load_terms(self, slope, H, y=None):
        """``q, dq/dy', dq/dH, dq/dy`` summed over the loads at the quadrature points (``dq/dy``
        None without cable terms; ``y`` the height there, needed by them)."""
        q = np.zeros_like(slope)
        dq_ds, dq_dh = np.zeros_like(slope), np.zeros_like(slope)
        for load in self.distributed:
            a, b, c = load.graph_terms(self.x_quad, slope, H, self.EA)
            q, dq_ds, dq_dh = q + a, dq_ds + b, dq_dh + c
        if not self.terms:
            return q, dq_ds, dq_dh, None
        y = self.chord_slope * self.x_quad if y is None else y
        a, b, c, d = graph_term_loads(self.terms, self.x_quad, y, slope, H, self.EA)
        return q + a, dq_ds + b, dq_dh + c, d

    def strains(self, dofs):
        """``(u', u)`` at the quadrature points: (2, nq, ne)."""
        return self.assembly.interpolate(dofs)

    def lengths(self, dofs, H):
        """(stretched, unstretched) length by the basis' quadrature."""
        slope = self.chord_slope + self.strains(dofs)[0]
        f = unstretched_measure(slope, H, self.EA)[0]
        dx = self.assembly.dx
        return float(np.sum(np.sqrt(1.0 + slope**2) * dx)), float(np.sum(f * dx))

    def extremum(self, dofs, kind, values=None):
        """(x*, value, d value/d dofs) of the sag (max of tilt·x - y) or the lowest point (min y).

        The best quadrature point picks the element; the exact minimum of the
        element's polynomial is taken there and in its two neighbours.
        ``values``: u at the quadrature points, if already known.
        """
        tilt = 0.0 if kind == "low" else self.chord_slope  # minimise y - tilt x = u + (s - tilt) x
        lean = self.chord_slope - tilt
        u = self.strains(dofs)[1] if values is None else values
        element_dofs = self.basis.element_dofs
        _, x_star, k = minimum_near(
            self.basis, u + lean * self.x_quad, lambda k: dofs[element_dofs[:, k]], lean
        )
        row = np.zeros(self.basis.N)
        row[element_dofs[:, k]] = element_values(self.basis, k, x_star)
        y_star = self.chord_slope * x_star + float(np.sum(row * dofs))
        value = y_star if kind == "low" else tilt * x_star - y_star
        return x_star, value, row

    def assemble(self, dofs, H) -> GraphState:
        asmb = self.assembly
        du, u = asmb.interpolate(dofs)
        slope = self.chord_slope + du
        q, dq_ds, dq_dh, dq_dy = self.load_terms(slope, H, self.chord_slope * self.x_quad + u)
        R = asmb.gather(asmb.local(0, H * slope) + asmb.local(1, q)) + self.point_vector
        Ke = H * self._stiffness + asmb.block(1, 0, dq_ds)
        if dq_dy is not None:  # cable terms that depend on the height
            Ke = Ke + asmb.block(1, 1, dq_dy)
        dR_dH = asmb.gather(asmb.local(0, slope) + asmb.local(1, dq_dh))
        name, value = self.constraint
        if name == "H":
            g, dg_dy, dg_dH = H - value, np.zeros(self.basis.N), 1.0
        elif name == "length":
            f, df_ds, df_dh = unstretched_measure(slope, H, self.EA)
            dx = asmb.dx
            if self.EA is None:  # excess over the chord, free of cancellation (taut cables)
                s = self.chord_slope
                excess = du * (2.0 * s + du) / (f + np.hypot(1.0, s))
                g = float(np.sum(excess * dx)) - self.excess_length
            else:
                g = float(np.sum(f * dx)) - value
            dg_dy = asmb.gather(asmb.local(0, df_ds))
            dg_dH = float(np.sum(df_dh * dx))
        elif name in ("sag", "low"):
            _, achieved, row = self.extremum(dofs, name, u)
            g, dg_dy, dg_dH = achieved - value, (row if name == "low" else -row), 0.0
        else:  # T_max: the larger end tension, reactions from the residual rows
            end = self.end_a if abs(R[self.end_a]) >= abs(R[self.end_b]) else self.end_b
            v = R[end]  # V_A = R_A, V_B = R_B
            T = np.hypot(H, v)
            g = T - value
            dg_dy = (v / T) * asmb.row(Ke, end)
            dg_dH = (H + v * dR_dH[end]) / T
        force = np.abs(R[self.interior]) / self.load_scale
        constraint = float(abs(g) / self.constraint_scale)
        merit = max(float(np.max(force, initial=0.0)), constraint)
        descent = float(np.sqrt(np.sum(force * force) + constraint * constraint))
        return GraphState(R, Ke, dR_dH, float(g), dg_dy, float(dg_dH), merit, descent, asmb)

    # --- one term alone (skcable.fe.check_tangent) ---------------------------------------------
    def term_contribution(self, term, U, state=None):
        """``(R, K)`` of the cable term ``term`` alone at ``U = [dofs, H]`` (the Newton vector):
        its residual ``∫ q v`` over the dofs and its tangent by them, H held."""
        from skcable.fe.check import sparse_of

        dofs, H = U[:-1], float(U[-1])
        asmb = self.assembly
        du, u = asmb.interpolate(dofs)
        slope = self.chord_slope + du
        q, dq_ds, _, dq_dy = graph_term_loads(
            [term], self.x_quad, self.chord_slope * self.x_quad + u, slope, H, self.EA
        )
        K = asmb.matrix(asmb.block(1, 0, dq_ds) + asmb.block(1, 1, dq_dy))
        return np.append(asmb.gather(asmb.local(1, q)), 0.0), sparse_of(K, len(U))

    def free_dofs(self):
        """The dofs a solve moves, H left out (for `skcable.fe.check_tangent`)."""
        return self.interior

    def tangent_check_state(self):
        """The start of a solve, ``[dofs, H]`` (for `skcable.fe.check_tangent`)."""
        dofs, H = initial_guess(self)
        return np.append(dofs, H)

    def absolute(self, state, rtol) -> float:
        """The largest interior force residual (N) where the constraint meets ``rtol`` (``atol``'s
        measure), else inf."""
        if not abs(state.g) / self.constraint_scale < rtol:
            return np.inf
        return float(np.max(np.abs(state.R[self.interior]), initial=0.0))

    def increment(self, state: GraphState) -> np.ndarray:
        """Newton increment of (dofs, H): the bordered banded solve."""
        system, interior = self.solver.system, self.interior
        ab = system.add_elements(system.band(), state.Ke)
        if self.constraint[0] == "H":
            d_u, d_H = self.solver.solve(ab, state.R[interior], corner=state.dg_dH, gap=state.g)
        else:
            d_u, d_H = self.solver.solve(
                ab,
                state.R[interior],
                state.dR_dH[interior],
                state.dg_dy[interior],
                state.dg_dH,
                state.g,
            )
        step = np.zeros(self.basis.N + 1)
        step[interior] = d_u
        step[-1] = d_H
        return step

    @cached_property
    def load_scale(self):
        """Total vertical load on the straight chord (N): scale of the residual."""
        slope = np.full_like(self.x_quad, self.dh / self.span)
        q = self.load_terms(slope, 0.0)[0]
        return float(np.sum(np.abs(q) * self.assembly.dx) + np.sum(np.abs(self.point_values))) or 1.0

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

    #: stretched length minus chord at the initial guess (set by `initial_guess`)
    stretched_excess = 1.0


def initial_guess(problem: GraphProblem):
    """Catenary (or, where none fits the constraint, parabola) of the same total load: (dofs, H)."""
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
    H = float(value) if name == "H" else float(guess.H)
    return dofs, H


class BVPSolution(FiniteElementSolution):
    """Solution of `solve_bvp` (graph form).

    Attributes are those of `Catenary` (``H, V_A, V_B,
    T_A, T_B, length, sag, x_low, y_low``, methods ``y, T, slope,
    residual``) plus ``mesh``, ``basis``, ``iterations``, ``history`` (merit
    per Newton iteration), ``dofs`` (the FE vector of ``u = y - (dh/span)
    x``, the depth below the chord, so that rounding scales with the sag
    rather than with dh), ``stretched_length`` and ``EA``. With ``EA``,
    ``length`` is the unstretched length, as for
    `elastic_catenary`.
    """

    formulation = "graph"

    def __init__(
        self, problem: GraphProblem, dofs, H, history, state: GraphState | None = None, resolver=None
    ):
        super().__init__(problem, dofs, history, problem.assemble(dofs, H) if state is None else state)
        self.H = float(H)
        #: ``resolver(solution, span, dh)``: the problem solved again with B moved (for `stiffness`)
        self.resolver = resolver

    @property
    def H_A(self):
        """The horizontal tension (N), the same at both ends (the graph form takes vertical loads)."""
        return self.H

    @property
    def H_B(self):
        return self.H

    @cached_property
    def _arc_length(self):
        """Unstretched arc length at the mesh nodes (m), and the quadrature of each element."""
        problem = self._problem
        slope = problem.chord_slope + problem.strains(self.dofs)[0]
        f = unstretched_measure(slope, self.H, self.EA)[0]
        per_element = np.sum(f * problem.assembly.dx, axis=0)
        nodes = self.mesh.p[0]
        order = np.argsort(nodes)
        s = np.zeros(len(nodes))
        s[order[1:]] = np.cumsum(per_element[np.argsort(self.mesh.p[0, self.mesh.t].mean(axis=0))])
        return nodes[order], s[order]

    def _x_of_s(self, s):
        """The abscissa (m) at unstretched arc length ``s`` (m): a root of ``s(x) − s`` in the
        element that holds it (scipy's bracketed elementwise root finder on the element's own
        quadrature of the measure)."""
        from scipy.optimize import elementwise

        s = np.asarray(real("s", s), dtype=float)
        x_nodes, s_nodes = self._arc_length
        require(
            "s",
            (s >= 0) & (s <= s_nodes[-1] * (1 + 1e-15)),
            f"must lie in [0, length = {s_nodes[-1]:g}] m",
            s,
        )
        s = np.minimum(s, s_nodes[-1])
        k = np.clip(np.searchsorted(s_nodes, s) - 1, 0, len(x_nodes) - 2)
        a, b, s_a = x_nodes[k], x_nodes[k + 1], s_nodes[k]
        points, weights = np.polynomial.legendre.leggauss(8)

        def gap(x, a, s_a, s):  # s(x) − s, s(x) inside the element [a, x] by Gauss–Legendre
            half = 0.5 * (x - a)
            xq = a[..., None] + half[..., None] * (points + 1.0)
            f = unstretched_measure(self.slope(xq), self.H, self.EA)[0]
            return s_a + half * np.sum(f * weights, axis=-1) - s

        root = elementwise.find_root(gap, (a, b), args=(a, s_a, s))
        return np.where(s >= s_nodes[-1], x_nodes[-1], np.asarray(root.x))

    def xy(self, s):
        """Position (x, y) (m) at unstretched arc length ``s`` (m) from A: array ``(..., 2)``."""
        x = self._x_of_s(s)
        return np.stack([x, np.asarray(self.y(x))], axis=-1)

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` (m) from A."""
        return self.T(self._x_of_s(s))

    def stiffness(self, step: float = 1e-5):
        """Fairlead stiffness ``∂(H_B, V_B)/∂(span, dh)`` (N/m), A fixed and the unstretched length
        kept, by central differences of the same discrete problem re-solved from this solution at
        ``span ± step·span`` and ``dh ± step·span`` (to rtol 1e-13), rows (H_B, V_B)."""
        columns = []
        for d_span, d_dh in ((1.0, 0.0), (0.0, 1.0)):
            h = step * self.span
            plus, minus = (
                self._resolved(self.span + sign * h * d_span, self.dh + sign * h * d_dh) for sign in (1, -1)
            )
            columns.append([(plus.H - minus.H) / (2 * h), (plus.V_B - minus.V_B) / (2 * h)])
        return np.array(columns).T

    def _resolved(self, span, dh):
        """This problem at B = (span, dh) with the unstretched length kept (`solve_bvp`'s resolver)."""
        if self.resolver is None:
            raise InputError(
                "solution", "was not made by solve_bvp: it cannot be solved again for its stiffness"
            )
        return self.resolver(self, span, dh)

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
    def _lengths(self):
        return self._problem.lengths(self.dofs, self.H)

    @property
    def stretched_length(self):
        return self._lengths[0]

    @property
    def length(self):
        return self._lengths[1] if self.EA is not None else self._lengths[0]

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
        du = (gradient_probes(self.basis, x.reshape(1, -1)) @ self.dofs).reshape(x.shape)
        return (self._problem.chord_slope + du)[()]

    def T(self, x):
        """Tension at ``x`` (N): ``H sqrt(1 + y'^2)``."""
        return self.H * np.sqrt(1.0 + self.slope(x) ** 2)

    def samples(self, n: int = 201) -> dict:
        """The profile at ``n`` equally spaced x (`CableSolution.samples`), with the cable terms'
        outputs there (``"outputs"``: name -> (n,) or (n, 2))."""
        out = super().samples(n)
        problem = self._problem
        out["outputs"] = {}
        if problem.terms:
            x, y = out["xy"][:, 0], out["xy"][:, 1]
            slope = np.tan(out["angle"])
            m = unstretched_measure(slope, self.H, self.EA)[0]
            state = CableState(x, y, None, np.array([np.ones_like(x), slope]) / m, out["tension"])
            out["outputs"] = sampled_outputs(problem.terms, state)
        return out

    def weight_per_length(self, x, slope):
        problem = self._problem
        q = sum(ld.graph_terms(x, slope, self.H, self.EA)[0] for ld in problem.distributed)
        if problem.terms:
            q = q + graph_term_loads(problem.terms, x, self.y(x), slope, self.H, self.EA)[0]
        return q / unstretched_measure(slope, self.H, self.EA)[0]

    def _residuals(self):
        problem, state = self._problem, self._state
        yield np.max(np.abs(state.R[problem.interior]), initial=0.0) / problem.load_scale  # equilibrium
        yield state.g / problem.constraint_scale
        yield from self._common_residuals(np)

    def __repr__(self):
        return (
            f"BVPSolution(span={self.span:g}, dh={self.dh:g}, {self.mesh.t.shape[1]} elements: "
            f"H={self.H:.9g} (both ends), V_A={self.V_A:.9g}, V_B={self.V_B:.9g}, "
            f"T_A={self.T_A:.9g}, T_B={self.T_B:.9g}, length={self.length:.9g} (N, m), "
            f"iterations={self.iterations})"
        )
