r"""Arc-length (Lagrangian) formulation of the suspended cable.

Goicolea (2012) eq. (3), ``d/ds (T dr/ds / |dr/ds|) + q = 0``, in the unstretched
arc length ``s = L0 σ``, σ ∈ [0, 1], with position r(σ) = (x, y) and
tension T(σ) as fields and the unstretched length L0 as a global unknown
(fixed when the constraint is the length). With ``a = dr/dσ``, ``n = |a|``,
``e = a/n`` and ``Q = L0 q`` the load per unit σ:

.. math::
    \int_0^1 T\,\mathbf e\cdot\delta\mathbf r'\,d\sigma - \int_0^1 \mathbf Q\cdot\delta\mathbf r\,d\sigma = 0,
    \qquad \int_0^1 \left(n - L_0 (1 + T/EA)\right)\delta T\,d\sigma = 0,

(the second is the stretch law; ``EA = ∞`` makes it inextensibility). It
describes any shape, including cables that are not graphs y(x), and takes
horizontal loads. Positions are P2 and the tension discontinuous P1, on
bases that share one quadrature. The pairing matters: with a *continuous*
P1 tension the system counts more tangential position modes than stretch
constraints, and the tangential re-parametrisation modes inside elements,
which no stiffness holds (the geometric term ``T (I - e e^T)/n`` has none
along the cable), make the tangent nearly singular as soon as the cable
curves (condition number above 1e8 and stalled Newton for a cable six times
its chord); P2/P1-DG is square element by element and stays well
conditioned (below 1e5 in the same case; both tested). Newton's method with
the consistent tangent (the only non-analytic piece: the x-derivative of a
user's load callable, by central differences).

The forms (`skcable.bvp.forms`) are a *section law* in the
generalized strains ``(x', y', x, y, T)``: `ArcProblem` assembles them
with `skcable.fe.Assembly` (basis values and patterns once) and
solves the bordered banded system of `skcable.fe.linear.BorderedSolver`.

Support reactions come from the residual rows at the supports:
``H_A = -R_x(A)``, ``V_A = R_y(A)``, ``H_B = R_x(B)``, ``V_B = R_y(B)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.optimize import elementwise
from skfem import Basis, ElementLineP1DG, ElementLineP2, MeshLine

from skcable._checks import positive, real, require
from skcable.bvp.base import FiniteElementSolution, sampled_outputs
from skcable.bvp.elements import end_dofs
from skcable.bvp.loads import DeckLoad, DistributedLoad, PointLoad, SelfWeight
from skcable.bvp.section import tension_section
from skcable.bvp.terms import CableState, CableTerm
from skcable.cable._catenary import catenary
from skcable.errors import ConvergenceError, InputError
from skcable.fe.assembly import Assembly
from skcable.fe.linear import BorderedSolver
from skcable.fe.probes import element_values, gradient_probes, minimum_near
from skcable.results import ProfileMixin

__all__ = ["ArcProblem", "ArcSolution", "ArcState", "arc_guess", "arc_loads", "term_loads"]

#: generalized strains of the section law: x', y', x, y, T
_STRAINS = (("x", 1), ("y", 1), ("x", 0), ("y", 0), ("T", 0))
_AX, _AY, _X, _Y, _T = range(5)


def arc_loads(loads, x, dx, L0, span):
    """Load per unit σ, ``Q = (Qx, Qy)``, and its derivatives.

    Returns ``Qx, Qy, dQx/dx, dQy/dx, dQx/dx', dQy/dx', dQx/dL0, dQy/dL0``
    at the quadrature points (x' = dx/dσ).
    """
    zero = np.zeros_like(x)
    out = [zero.copy() for _ in range(8)]
    h = 1e-7 * span
    for load in loads:
        if isinstance(load, CableTerm):
            continue  # `term_loads`
        if isinstance(load, SelfWeight):
            out[1] -= load.w * L0
            out[7] -= load.w
        elif isinstance(load, DeckLoad):
            out[1] -= load.w * dx
            out[5] -= load.w
        elif isinstance(load, DistributedLoad):
            for k, fn in ((0, load.qx), (1, load.qy)):
                if fn is None:
                    continue
                value = np.broadcast_to(np.asarray(fn(x), dtype=float), x.shape)
                slope = (np.asarray(fn(x + h), dtype=float) - np.asarray(fn(x - h), dtype=float)) / (2 * h)
                if load.per == "cable":
                    out[k] += L0 * value
                    out[2 + k] += L0 * slope
                    out[6 + k] += value
                else:
                    out[k] += value * dx
                    out[2 + k] += slope * dx
                    out[4 + k] += value
        else:
            raise InputError("load", f"{type(load).__name__} is not supported by formulation='arc'")
    return out


def term_loads(terms, X, Y, ax, ay, T, L0, sigma):
    """The cable terms' load per unit σ, ``Q = L0 f`` (2, *P), and its derivatives by the
    position ``r`` (2, 2, *P), by ``r' = dr/dσ`` (2, 2, *P), by the tension (2, *P) and by L0
    (2, *P) (`skcable.bvp.terms`): ``a = r'/L0``, ``s = σ L0``."""
    a = np.array([ax, ay]) / L0
    state = CableState(X, Y, sigma * L0, a, T)
    Q, dQ_dr, dQ_da = np.zeros((2, *X.shape)), np.zeros((2, 2, *X.shape)), np.zeros((2, 2, *X.shape))
    dQ_dT, dQ_dL = np.zeros((2, *X.shape)), np.zeros((2, *X.shape))
    for term in terms:
        out = term.forces(state)
        f = np.asarray(out.f, dtype=float)
        if f.shape != Q.shape or not np.all(np.isfinite(f)):
            raise InputError(
                "load", f"{term!r} returned forces of shape {f.shape} (not {Q.shape}) or non-finite ones"
            )
        Q += L0 * f
        dQ_dL += f
        if out.df_dr is not None:
            dQ_dr += L0 * out.df_dr
        if out.df_da is not None:
            dQ_da += out.df_da
            dQ_dL -= np.einsum("ij...,j...->i...", out.df_da, a)
        if out.df_ds is not None:
            dQ_dL += sigma * L0 * out.df_ds
        if out.df_dT is not None:
            dQ_dT += L0 * out.df_dT
    return Q, dQ_dr, dQ_da, dQ_dT, dQ_dL


@dataclass
class ArcState:
    """Everything assembled at one iterate; vectors over all dofs ``[x, y, T]``."""

    R: np.ndarray | None
    Ke: np.ndarray | None  # element tangents (n_local, n_local, ne)
    dR_dL0: np.ndarray | None
    g: float
    dg: np.ndarray | None  # wrt [x, y, T]
    dg_dL0: float
    merit: float  # max-norm of the scaled residual: the convergence test and line-search merit
    descent: float  # 2-norm of the scaled residual
    assembly: Assembly | None = None

    @cached_property
    def J(self):
        """The global Jacobian wrt ``[x, y, T]`` (CSR), for inspection; Newton uses the band."""
        assert self.assembly is not None, "a rejected state has no Jacobian"
        return self.assembly.matrix(element_matrices=self.Ke)


_REJECTED = ArcState(None, None, None, np.inf, None, np.inf, np.inf, np.inf)


class ArcProblem:
    """Mesh, bases, loads, constraint and the assembly of one arc-length solve.

    ``tension`` is the tension's element (P1-DG; a continuous P1 is there to
    show why not, see the module docstring).
    """

    def __init__(self, span, dh, loads, EA, constraint, n_elements, degree, tension=None, end_force=None):
        if any(isinstance(ld, PointLoad) for ld in loads):
            raise InputError("load", "point loads at fixed x need formulation='graph'")
        if degree != 2:
            raise InputError(
                "degree", f"formulation='arc' uses degree 2 (P2 positions, P1 tension), got {degree!r}"
            )
        self.span, self.dh, self.EA, self.constraint, self.loads = span, dh, EA, constraint, loads
        self.terms = [ld for ld in loads if isinstance(ld, CableTerm)]
        #: a load has a horizontal component: H_A and H_B differ
        self.horizontal = any(getattr(ld, "qx", None) is not None for ld in loads) or any(
            not t.vertical for t in self.terms
        )
        self.compliance = 0.0 if EA is None else 1.0 / EA
        n = positive("n_elements", n_elements)
        require("n_elements", n == int(n), "must be a whole number", n)
        self.mesh = MeshLine(np.linspace(0.0, 1.0, int(n) + 1))
        self.basis = Basis(self.mesh, ElementLineP2(), intorder=6)
        self.tbasis = self.basis.with_element(ElementLineP1DG() if tension is None else tension)
        N, M = self.basis.N, self.tbasis.N
        self.N, self.M = N, M
        self.end_a, self.end_b, inner = end_dofs(self.basis)
        #: a force (N, y up) on a free end B, or None (B fixed at (span, dh))
        self.end_force = None if end_force is None else np.asarray(end_force, dtype=float)
        if self.end_force is not None:
            inner = np.sort(np.append(inner, self.end_b))
        self.free = np.concatenate([inner, N + inner, 2 * N + np.arange(M)])
        self.fixed_length = constraint[0] == "length"
        self.assembly = Assembly({"x": self.basis, "y": self.basis, "T": self.tbasis}, _STRAINS)
        self.solver = BorderedSolver(self.assembly.banded(self.free))
        self._force_rows = self.free[self.free < 2 * N]
        self._stretch_rows = self.free[self.free >= 2 * N]

    def fields(self, z):
        N = self.N
        return z[:N], z[N : 2 * N], z[2 * N :]

    def assemble(self, z, L0) -> ArcState:
        asmb = self.assembly
        g = asmb.interpolate(z)
        ax, ay, X, T = g[_AX], g[_AY], g[_X], g[_T]
        section = tension_section((ax, ay), T)
        if section is None:  # a collapsed tangent: reject this iterate
            return _REJECTED
        n, (ex, ey), D = section  # T e, the stretch and their tangent (skcable.bvp.section)
        Qx, Qy, dQx_dx, dQy_dx, dQx_dxp, dQy_dxp, dQx_dL, dQy_dL = arc_loads(self.loads, X, ax, L0, self.span)
        c = self.compliance
        S = np.stack([T * ex, T * ey, -Qx, -Qy, n - L0 * (1.0 + T * c)])
        D[_X, _X], D[_X, _AX] = -dQx_dx, -dQx_dxp
        D[_Y, _X], D[_Y, _AX] = -dQy_dx, -dQy_dxp
        D[_T, _T] = -L0 * c
        zero = np.zeros_like(n)
        dS_dL0 = np.stack([zero, zero, -dQx_dL, -dQy_dL, -(1.0 + T * c)])
        if self.terms:  # the cable terms (skcable.bvp.terms): their loads and full tangent
            Q, dQ_dr, dQ_da, dQ_dT, dQ_dL = term_loads(self.terms, X, g[_Y], ax, ay, T, L0, asmb.x)
            S[_X : _Y + 1] -= Q
            D[_X : _Y + 1, _X : _Y + 1] -= dQ_dr
            D[_X : _Y + 1, _AX : _AY + 1] -= dQ_da
            D[_X : _Y + 1, _T] -= dQ_dT
            dS_dL0[_X : _Y + 1] -= dQ_dL
        R = asmb.vector(S)
        if self.end_force is not None:  # the force on the free end B: external, a dead load
            R[self.end_b] -= self.end_force[0]
            R[self.N + self.end_b] -= self.end_force[1]
        Ke = asmb.element_matrices(D)
        dR_dL0 = asmb.vector(dS_dL0)
        gap, dg, dg_dL0 = self.constraint_terms(z, R, Ke, dR_dL0, g)
        force = np.abs(R[self._force_rows]) / self.load_scale
        stretch = np.abs(R[self._stretch_rows]) / self.length_scale
        constraint = float(abs(gap) / self.constraint_scale)
        merit = max(float(np.max(force, initial=0.0)), float(np.max(stretch, initial=0.0)), constraint)
        descent = float(np.sqrt(np.sum(force * force) + np.sum(stretch * stretch) + constraint * constraint))
        return ArcState(R, Ke, dR_dL0, float(gap), dg, float(dg_dL0), merit, descent, asmb)

    # --- one term alone (skcable.fe.check_tangent) ---------------------------------------------
    def term_contribution(self, term, U, state=None):
        """``(R, K)`` of the cable term ``term`` alone at ``U = [z, L0]`` (the Newton vector):
        its residual (its load, negated) over the dofs and its tangent by them, L0 held."""
        from skcable.fe.check import sparse_of

        z, L0 = U[:-1], float(U[-1])
        g = self.assembly.interpolate(z)
        Q, dQ_dr, dQ_da, dQ_dT, _ = term_loads(
            [term], g[_X], g[_Y], g[_AX], g[_AY], g[_T], L0, self.assembly.x
        )
        S = np.zeros((5, *g.shape[1:]))
        S[_X : _Y + 1] = -Q
        D = np.zeros((5, 5, *g.shape[1:]))
        D[_X : _Y + 1, _X : _Y + 1] = -dQ_dr
        D[_X : _Y + 1, _AX : _AY + 1] = -dQ_da
        D[_X : _Y + 1, _T] = -dQ_dT
        K = self.assembly.matrix(self.assembly.element_matrices(D))
        return np.append(self.assembly.vector(S), 0.0), sparse_of(K, len(U))

    def free_dofs(self):
        """The dofs a solve moves, L0 left out (for `skcable.fe.check_tangent`)."""
        return self.free

    def tangent_check_state(self):
        """The start of a solve, ``[z, L0]`` (for `skcable.fe.check_tangent`)."""
        z, L0 = arc_guess(self)
        return np.append(z, L0)

    def absolute(self, state, rtol) -> float:
        """The largest force residual (N) where the stretch and constraint rows meet ``rtol``
        (``atol``'s measure), else inf."""
        if state.R is None:
            return np.inf
        stretch = np.max(np.abs(state.R[self._stretch_rows]), initial=0.0) / self.length_scale
        if not (stretch < rtol and abs(state.g) / self.constraint_scale < rtol):
            return np.inf
        return float(np.max(np.abs(state.R[self._force_rows]), initial=0.0))

    def scaled(self, R, g):
        """Residual in consistent units: forces over the total load, stretch
        rows over the length, the constraint over its own scale."""
        return np.concatenate(
            [
                R[self._force_rows] / self.load_scale,
                R[self._stretch_rows] / self.length_scale,
                [g / self.constraint_scale],
            ]
        )

    def increment(self, state: ArcState) -> np.ndarray:
        """Newton increment of (z, L0): the bordered banded solve."""
        system, free = self.solver.system, self.free
        R, Ke, dR_dL0, dg = state.R, state.Ke, state.dR_dL0, state.dg
        assert R is not None and Ke is not None, "a rejected state has no increment"
        ab = system.add_elements(system.band(), Ke)
        if self.fixed_length:
            d_z, d_L = self.solver.solve(ab, R[free], gap=0.0)
        else:
            assert dR_dL0 is not None and dg is not None, "an assembly of free length has its borders"
            d_z, d_L = self.solver.solve(ab, R[free], dR_dL0[free], dg[free], state.dg_dL0, state.g)
        step = np.zeros(2 * self.N + self.M + 1)
        step[free] = d_z
        step[-1] = d_L
        return step

    # --- constraint -------------------------------------------------------------
    def reactions(self, R):
        N = self.N
        if self.end_force is not None:  # B is free: what acts there is the given force
            return -R[self.end_a], R[N + self.end_a], self.end_force[0], self.end_force[1]
        return -R[self.end_a], R[N + self.end_a], R[self.end_b], R[N + self.end_b]  # H_A, V_A, H_B, V_B

    def constraint_terms(self, z, R, Ke, dR_dL0, strains):
        name, value = self.constraint
        size = self.assembly.N
        if name == "length":
            return 0.0, np.zeros(size), 0.0
        N = self.N
        if name == "H":
            row = self.end_a
            return -R[row] - value, -self.assembly.row(Ke, row), -dR_dL0[row]
        if name == "T_max":
            rows = [(self.end_a, N + self.end_a), (self.end_b, N + self.end_b)]
            tensions = [np.hypot(R[i], R[j]) for i, j in rows]
            i, j = rows[int(np.argmax(tensions))]
            T = max(tensions)
            dg = (R[i] * self.assembly.row(Ke, i) + R[j] * self.assembly.row(Ke, j)) / T
            return T - value, dg, (R[i] * dR_dL0[i] + R[j] * dR_dL0[j]) / T
        sigma, achieved, row = self.extremum(z, name, strains)
        dg = np.zeros(size)
        if name == "low":
            dg[N : 2 * N] = row
        else:
            dg[:N], dg[N : 2 * N] = self.dh / self.span * row, -row
        return achieved - value, dg, 0.0

    def extremum(self, z, kind, strains=None):
        """(σ*, value, d value/d dofs of the field) for sag (max tilt·x - y) or lowest point (min y)."""
        xd, yd, _ = self.fields(z)
        g = self.assembly.interpolate(z) if strains is None else strains
        tilt = 0.0 if kind == "low" else self.dh / self.span
        element_dofs = self.basis.element_dofs
        value, s_star, k = minimum_near(
            self.basis, g[_Y] - tilt * g[_X], lambda k: yd[element_dofs[:, k]] - tilt * xd[element_dofs[:, k]]
        )
        row = np.zeros(self.N)
        row[element_dofs[:, k]] = element_values(self.basis, k, s_star)
        return s_star, (value if kind == "low" else -value), row

    #: set by `arc_guess` from the initial catenary
    length_scale = 1.0
    load_scale = 1.0

    def straight_loads(self, L0):
        """``(Qx, Qy)`` per unit σ on the straight chord of unstretched length L0, every load."""
        sigma = self.assembly.x
        x, y = sigma * self.span, sigma * self.dh
        out = arc_loads(self.loads, x, np.full_like(x, self.span), L0, self.span)
        Qx, Qy = out[0], out[1]
        if self.terms:
            zero = np.zeros_like(x)
            Q = term_loads(self.terms, x, y, zero + self.span, zero + self.dh, zero, L0, sigma)[0]
            Qx, Qy = Qx + Q[0], Qy + Q[1]
        return Qx, Qy

    def total_load(self, L0):
        """Magnitude of the distributed load on a straight cable of length L0 (N)."""
        Qx, Qy = self.straight_loads(L0)
        return float(np.sum(np.hypot(Qx, Qy) * self.assembly.dx)) or 1.0

    @property
    def constraint_scale(self):
        name, value = self.constraint
        return float(np.hypot(self.span, self.dh)) if name in ("low", "length") else abs(float(value))


def arc_guess(problem: ArcProblem):
    """Catenary under the mean load, in the frame where that load is gravity: (z, L0).

    A uniform load per unit length in any direction hangs the cable in a
    catenary whose "vertical" is the load's direction; the mean load of the
    actual loads gives that frame. For vertical loads this is the ordinary
    catenary of the same total weight, with the same constraint.
    """
    span, dh = problem.span, problem.dh
    name, value = problem.constraint
    chord = float(np.hypot(span, dh))
    length = (value if value > chord else chord * (1 + 1e-6)) if name == "length" else chord
    dx = problem.assembly.dx
    Q = problem.straight_loads(length)
    mean = np.array([np.sum(Q[0] * dx), np.sum(Q[1] * dx)]) / length
    q = float(np.hypot(*mean))
    up = -mean / q
    across = np.array([up[1], -up[0]])
    B = np.array([span, dh])
    if B @ across < 0:  # mirror the frame so that B lies to the right
        across = -across
    span_r, dh_r = max(float(B @ across), 1e-9 * chord), float(B @ up)
    if name == "length":
        guess = catenary(span_r, dh_r, q, length=length)
        if problem.EA is not None:  # stretch the start by the mean strain it predicts
            strain = 0.5 * (guess.T_A + guess.T_B) / problem.EA
            guess = catenary(span_r, dh_r, q, length=max(length * (1 + strain), chord * (1 + 1e-6)))
    elif name in ("H", "low", "sag", "T_max") and abs(up[0]) < 1e-12:  # vertical loads: same constraint
        guess = catenary(span_r, dh_r, q, **{name: value})
    else:  # the constraint refers to global axes: start from a moderately slack cable
        guess = catenary(span_r, dh_r, q, length=1.05 * chord)
    u_a = guess.m - guess.z

    def local(sigma):  # catenary coordinates in the rotated frame at arc fraction sigma
        xr = guess.a * (np.arcsinh(sigma * guess.length / guess.a + np.sinh(u_a)) - u_a)
        return xr, guess.y(np.clip(xr, 0.0, span_r))

    xr, yr = local(problem.basis.doflocs[0])
    xs, ys = xr * across[0] + yr * up[0], xr * across[1] + yr * up[1]
    T = guess.T(np.clip(local(problem.tbasis.doflocs[0])[0], 0.0, span_r))
    xs[problem.end_a], xs[problem.end_b] = 0.0, span
    ys[problem.end_a], ys[problem.end_b] = 0.0, dh
    L_guess = (
        value if name == "length" else guess.length / (1 + 0.5 * (guess.T_A + guess.T_B) * problem.compliance)
    )
    problem.length_scale = float(L_guess)
    problem.load_scale = problem.total_load(L_guess) + (
        0.0 if problem.end_force is None else float(np.hypot(*problem.end_force))
    )
    return np.concatenate([xs, ys, T]), float(L_guess)


class ArcSolution(FiniteElementSolution):
    """Solution of `solve_bvp` with ``formulation="arc"`` (the result protocol of
    `skcable.results`).

    ``H_A``, ``H_B`` are the horizontal tensions at A and B (N): equal unless horizontal loads
    act. ``H`` is kept where they are equal (vertical loads); under horizontal loads it is A's,
    with a `DeprecationWarning` (use ``H_A`` or ``H_B``). ``xy(s)`` and ``T_of_s(s)`` take the
    unstretched arc length ``s`` (m) from A, ``s ∈ [0, length]``.
    """

    formulation = "arc"

    def __init__(self, problem: ArcProblem, z, L0, history, state: ArcState | None = None):
        super().__init__(problem, z, history, problem.assemble(z, L0) if state is None else state)
        self.L0 = float(L0)
        self.H_A, self.V_A, self.H_B, self.V_B = (float(v) for v in problem.reactions(self._state.R))
        if problem.end_force is not None:  # B went where the force took it
            xd, yd, _ = problem.fields(z)
            self.span, self.dh = float(xd[problem.end_b]), float(yd[problem.end_b])

    @property
    def H(self):
        """The horizontal tension (N) where it is the same at both ends (no horizontal load);
        under horizontal loads it differs between the ends: ``H_A`` and ``H_B``."""
        if self._problem.horizontal:
            raise AttributeError(
                "ArcSolution.H: under horizontal loads the horizontal tension differs between the "
                "ends: use H_A or H_B"
            )
        return self.H_A

    @property
    def T_A(self):
        return float(np.hypot(self.H_A, self.V_A))

    @property
    def T_B(self):
        return float(np.hypot(self.H_B, self.V_B))

    @property
    def length(self):
        return self.L0

    @cached_property
    def stretched_length(self):
        g = self._problem.assembly.interpolate(self.dofs)
        return float(np.sum(np.hypot(g[_AX], g[_AY]) * self._problem.assembly.dx))

    @property
    def x_low(self):
        return float(self._at_sigma(self._low[0])[0])

    def _sigma(self, s):
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.L0 * (1 + 1e-15)), f"must lie in [0, length = {self.L0:g}] m", s)
        return np.minimum(s / self.L0, 1.0)

    def _at_sigma(self, sigma):
        probes = self.basis.probes(np.reshape(sigma, (1, -1)))
        xd, yd, _ = self._problem.fields(self.dofs)
        return np.stack([probes @ xd, probes @ yd], axis=-1).reshape(*np.shape(sigma), 2)

    def xy(self, s):
        """Position (x, y) (m) at the unstretched arc length ``s`` (m) from A: array ``(..., 2)``."""
        return self._at_sigma(self._sigma(s))

    def T_of_s(self, s):
        """Tension (N) at the unstretched arc length ``s`` (m) from A."""
        sigma = self._sigma(s)
        T = self._problem.fields(self.dofs)[2]
        return (self._problem.tbasis.probes(np.reshape(sigma, (1, -1))) @ T).reshape(np.shape(sigma))[()]

    def stiffness(self):
        """Fairlead stiffness ``∂(H_B, V_B)/∂(span, dh)`` (N/m), A fixed and the unstretched length
        kept: the discrete solution's own derivative (implicit function theorem on the converged
        tangent: ``dz = −K_ff⁻¹ K_fB dB``, ``dR_B = K_Bf dz + K_BB dB``), rows (H_B, V_B)."""
        problem = self._problem
        if problem.end_force is not None:
            raise InputError("end_force", "B is free (loaded by a force): its position has no stiffness here")
        import scipy.sparse.linalg as spla

        J = self._state.J.tocsc()
        free, B = problem.free, np.array([problem.end_b, problem.N + problem.end_b])
        K_fB = J[free][:, B].toarray()
        dz = -spla.splu(J[free][:, free].tocsc()).solve(K_fB)
        K = J[B][:, free] @ dz + J[B][:, B].toarray()
        if not np.all(np.isfinite(K)):
            raise ConvergenceError("ArcSolution.stiffness: the tangent is singular here", self.history)
        return np.asarray(K, dtype=float)

    def _sigma_of_x(self, x):
        x = np.asarray(real("x", x), dtype=float)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        xd = self._problem.fields(self.dofs)[0]
        nodal = xd[self.basis.nodal_dofs[0]]
        if np.any(np.diff(nodal) <= 0):
            raise InputError("x", "the cable is not a graph y(x) here (x(s) is not increasing): use xy(s)")
        probe = self.basis.probes

        def f(s, target):  # find_root passes the targets of the elements it still works on
            return (probe(np.atleast_2d(s.ravel())) @ xd).reshape(s.shape) - target

        res = elementwise.find_root(f, (np.zeros_like(x), np.ones_like(x)), args=(x,))
        if not np.all(res.success):
            raise ConvergenceError(f"ArcSolution: no σ found where x(σ) = x ({res.status})", [])
        return np.asarray(res.x)

    def y(self, x):
        s = self._sigma_of_x(x)
        return self._at_sigma(s)[..., 1][()]

    def slope(self, x):
        s = np.atleast_1d(self._sigma_of_x(x))
        xd, yd, _ = self._problem.fields(self.dofs)
        G = gradient_probes(self.basis, s.reshape(1, -1))
        return ((G @ yd) / (G @ xd)).reshape(np.shape(x))[()]

    def T(self, x):
        s = np.atleast_1d(self._sigma_of_x(x))
        T = self._problem.fields(self.dofs)[2]
        return (self._problem.tbasis.probes(s.reshape(1, -1)) @ T).reshape(np.shape(x))[()]

    def to_frame(self, n: int = 201):
        """``n`` profile samples evenly spaced in unstretched arc length (pandas DataFrame):
        columns ``s`` (m), ``x``, ``y`` (m) and ``T`` (N), then the cable terms' outputs
        (``samples()["outputs"]``), a vector as ``<name>_x`` and ``<name>_y``."""
        outputs = self.samples(n)["outputs"] if self._problem.terms else {}
        return ProfileMixin.frame_with_outputs(self, n, outputs)

    def samples(self, n: int = 201) -> dict:
        """The profile at ``n`` equally spaced σ (unstretched arc length): see
        `CableSolution.samples`; non-graph shapes included."""
        sigma = np.linspace(0.0, 1.0, n)
        xd, yd, T = self._problem.fields(self.dofs)
        G = gradient_probes(self.basis, sigma.reshape(1, -1))
        dx, dy = G @ xd, G @ yd
        xy = self._at_sigma(sigma)
        loads = arc_loads(self._problem.loads, xy[:, 0], dx, self.L0, self.span)
        outputs = {}
        if self._problem.terms:
            tension = self._problem.tbasis.probes(sigma.reshape(1, -1)) @ T
            terms = self._problem.terms
            Q = term_loads(terms, xy[:, 0], xy[:, 1], dx, dy, tension, self.L0, sigma)[0]
            loads = [loads[0] + Q[0], loads[1] + Q[1]]
            state = CableState(xy[:, 0], xy[:, 1], sigma * self.L0, np.array([dx, dy]) / self.L0, tension)
            outputs = sampled_outputs(terms, state)
        return {
            "xy": xy,
            "tension": self._problem.tbasis.probes(sigma.reshape(1, -1)) @ T,
            "angle": np.arctan2(dy, dx),
            "load": np.column_stack([loads[0], loads[1]]) / self.L0,
            "outputs": outputs,
        }

    def _residuals(self):
        problem, state = self._problem, self._state
        yield from problem.scaled(state.R, state.g)
        yield from self._common_residuals(np)

    def __repr__(self):
        return (
            f"ArcSolution(span={self.span:g}, dh={self.dh:g}, {self.mesh.t.shape[1]} elements: "
            f"H_A={self.H_A:.9g}, V_A={self.V_A:.9g}, H_B={self.H_B:.9g}, V_B={self.V_B:.9g}, "
            f"T_A={self.T_A:.9g}, T_B={self.T_B:.9g}, length={self.length:.9g} (N, m), "
            f"iterations={self.iterations})"
        )
