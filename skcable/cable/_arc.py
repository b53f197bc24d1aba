r"""Arc-length (Lagrangian) formulation of the suspended cable on scikit-fem.

Seed 001 eq. (3), ``d/ds (T dr/ds / |dr/ds|) + q = 0``, in the unstretched
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
bases that share one quadrature, assembled block by block. The pairing
matters: with a *continuous* P1 tension the system counts more tangential
position modes than stretch constraints, and the tangential re-
parametrisation modes inside elements, which no stiffness holds (the
geometric term ``T (I - e e^T)/n`` has none along the cable), make the
tangent nearly singular as soon as the cable curves (condition number above
1e8 and stalled Newton for a cable six times its chord); P2/P1-DG is square
element by element and stays well conditioned (below 1e5 in the same case;
both tested). Newton's method with the consistent tangent (the only
non-analytic piece: the x-derivative of a user's load callable, by central
differences).

Support reactions come from the residual rows at the supports:
``H_A = -R_x(A)``, ``V_A = R_y(A)``, ``H_B = R_x(B)``, ``V_B = R_y(B)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from scipy.optimize import elementwise
from skfem import Basis, BilinearForm, ElementLineP1DG, ElementLineP2, LinearForm, MeshLine, asm, solve

from skcable._checks import real, require
from skcable.cable._bvp import FiniteElementSolution, _gradient_probes, element_minimum, element_values
from skcable.cable._catenary import catenary
from skcable.cable._loads import DeckLoad, DistributedLoad, PointLoad, SelfWeight
from skcable.errors import ConvergenceError, InputError

__all__ = ["ArcSolution", "arc_constitutive", "arc_equilibrium_x", "arc_equilibrium_y", "arc_loads"]


# --- forms -------------------------------------------------------------------
@LinearForm
def arc_equilibrium_x(v, w):
    """``∫ (T e_x v' - Q_x v) dσ``."""
    return w.T * w.ex * v.grad[0] - w.Qx * v


@LinearForm
def arc_equilibrium_y(v, w):
    """``∫ (T e_y v' - Q_y v) dσ``."""
    return w.T * w.ey * v.grad[0] - w.Qy * v


@LinearForm
def arc_constitutive(v, w):
    """``∫ (n - L0 (1 + T/EA)) v dσ``."""
    return (w.n - w.L0 * (1.0 + w.T * w.compliance)) * v


@BilinearForm
def _geometric(u, v, w):
    """``∫ T (δ_ij - e_i e_j) / n u' v'`` for the (i, j) block given as w.P."""
    return w.T * w.P / w.n * u.grad[0] * v.grad[0]


@BilinearForm
def _load_position(u, v, w):
    """``-∫ (dQ_i/dx u + dQ_i/dx' u') v``."""
    return -(w.dQ_dx * u + w.dQ_dxp * u.grad[0]) * v


@BilinearForm
def _tension_coupling(u, v, w):
    """``∫ u e_i v'``: tension trial u, position test v."""
    return u * w.e * v.grad[0]


@BilinearForm
def _tension_mass(u, v, w):
    """``-∫ L0/EA u v``."""
    return -w.L0 * w.compliance * u * v


def arc_loads(loads, x, dx, L0, span):
    """Load per unit σ, ``Q = (Qx, Qy)``, and its derivatives.

    Returns ``Qx, Qy, dQx/dx, dQy/dx, dQx/dx', dQy/dx', dQx/dL0, dQy/dL0``
    at the quadrature points (x' = dx/dσ).
    """
    zero = np.zeros_like(x)
    out = [zero.copy() for _ in range(8)]
    h = 1e-7 * span
    for load in loads:
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


@dataclass
class _ArcState:
    R: np.ndarray  # [Rx, Ry, Rc] full
    J: sp.csr_matrix  # full Jacobian wrt [x, y, T]
    dR_dL0: np.ndarray
    g: float
    dg: np.ndarray  # wrt [x, y, T]
    dg_dL0: float
    merit: float  # max-norm of the scaled residual: the convergence test
    descent: float  # 2-norm of the scaled residual: the line-search merit


class _ArcProblem:
    def __init__(self, span, dh, loads, EA, constraint, n_elements, degree):
        if any(isinstance(ld, PointLoad) for ld in loads):
            raise InputError("load", "point loads at fixed x need formulation='graph'")
        if degree < 2 or degree > 2:
            raise InputError(
                "degree", f"formulation='arc' uses degree 2 (P2 positions, P1 tension), got {degree!r}"
            )
        self.span, self.dh, self.EA, self.constraint, self.loads = span, dh, EA, constraint, loads
        self.compliance = 0.0 if EA is None else 1.0 / EA
        self.mesh = MeshLine(np.linspace(0.0, 1.0, int(n_elements) + 1))
        self.basis = Basis(self.mesh, ElementLineP2(), intorder=6)
        self.tbasis = self.basis.with_element(ElementLineP1DG())
        N, M = self.basis.N, self.tbasis.N
        self.N, self.M = N, M
        ends = self.basis.get_dofs().all()
        self.end_a, self.end_b = (ends[0], ends[1]) if self.basis.doflocs[0, ends[0]] == 0 else ends[::-1]
        inner = self.basis.complement_dofs(ends)
        self.free = np.concatenate([inner, N + inner, 2 * N + np.arange(M)])
        self.fixed_length = constraint[0] == "length"

    def fields(self, z):
        N = self.N
        return z[:N], z[N : 2 * N], z[2 * N :]

    def assemble(self, z, L0) -> _ArcState:
        b, tb = self.basis, self.tbasis
        xd, yd, Td = self.fields(z)
        X, Y, T = b.interpolate(xd), b.interpolate(yd), tb.interpolate(Td)
        ax, ay = X.grad[0], Y.grad[0]
        n = np.sqrt(ax * ax + ay * ay)
        if not np.all(n > 0):  # a collapsed tangent: reject this iterate
            return _ArcState(None, None, None, np.inf, None, np.inf, np.inf, np.inf)
        ex, ey = ax / n, ay / n
        Qx, Qy, dQx_dx, dQy_dx, dQx_dxp, dQy_dxp, dQx_dL, dQy_dL = arc_loads(
            self.loads, np.asarray(X), ax, L0, self.span
        )
        common = dict(T=np.asarray(T), n=n, ex=ex, ey=ey)
        Rx = asm(arc_equilibrium_x, b, Qx=Qx, **common)
        Ry = asm(arc_equilibrium_y, b, Qy=Qy, **common)
        Rc = asm(arc_constitutive, tb, n=n, L0=L0, T=np.asarray(T), compliance=self.compliance)
        Kxx = asm(_geometric, b, T=np.asarray(T), n=n, P=1 - ex * ex) + asm(
            _load_position, b, dQ_dx=dQx_dx, dQ_dxp=dQx_dxp
        )
        Kxy = asm(_geometric, b, T=np.asarray(T), n=n, P=-ex * ey)
        Kyx = Kxy + asm(_load_position, b, dQ_dx=dQy_dx, dQ_dxp=dQy_dxp)
        Kyy = asm(_geometric, b, T=np.asarray(T), n=n, P=1 - ey * ey)
        KxT = asm(_tension_coupling, tb, b, e=ex)  # rows: x tests, cols: T trials
        KyT = asm(_tension_coupling, tb, b, e=ey)
        KTT = asm(_tension_mass, tb, L0=L0, compliance=self.compliance)
        J = sp.bmat([[Kxx, Kxy, KxT], [Kyx, Kyy, KyT], [KxT.T, KyT.T, KTT]], format="csr")
        dRx_dL = -asm(LinearForm(lambda v, w: w.d * v), b, d=dQx_dL)
        dRy_dL = -asm(LinearForm(lambda v, w: w.d * v), b, d=dQy_dL)
        dRc_dL = -asm(LinearForm(lambda v, w: (1.0 + w.T * w.c) * v), tb, T=np.asarray(T), c=self.compliance)
        R = np.concatenate([Rx, Ry, Rc])
        dR_dL0 = np.concatenate([dRx_dL, dRy_dL, dRc_dL])
        g, dg, dg_dL0 = self.constraint_terms(z, L0, R, J, dR_dL0)
        scaled = self.scaled(R, g)
        return _ArcState(
            R, J, dR_dL0, g, dg, dg_dL0, float(np.max(np.abs(scaled))), float(np.linalg.norm(scaled))
        )

    def scaled(self, R, g):
        """Residual in consistent units: forces over the total load, stretch
        rows over the length, the constraint over its own scale."""
        N = self.N
        force_rows, stretch_rows = self.free[self.free < 2 * N], self.free[self.free >= 2 * N]
        return np.concatenate(
            [
                R[force_rows] / self.load_scale,
                R[stretch_rows] / self.length_scale,
                [g / self.constraint_scale],
            ]
        )

    # --- constraint -------------------------------------------------------------
    def reactions(self, R):
        N = self.N
        return -R[self.end_a], R[N + self.end_a], R[self.end_b], R[N + self.end_b]  # H_A, V_A, H_B, V_B

    def constraint_terms(self, z, L0, R, J, dR_dL0):
        name, value = self.constraint
        size = 2 * self.N + self.M
        if name == "length":
            return 0.0, np.zeros(size), 0.0
        N = self.N
        if name == "H":
            row = self.end_a
            return -R[row] - value, -J.getrow(row).toarray()[0], -dR_dL0[row]
        if name == "T_max":
            rows = [(self.end_a, N + self.end_a), (self.end_b, N + self.end_b)]
            tensions = [np.hypot(R[i], R[j]) for i, j in rows]
            i, j = rows[int(np.argmax(tensions))]
            T = max(tensions)
            dg = (R[i] * J.getrow(i).toarray()[0] + R[j] * J.getrow(j).toarray()[0]) / T
            return T - value, dg, (R[i] * dR_dL0[i] + R[j] * dR_dL0[j]) / T
        sigma, achieved, row = self.extremum(z, name)
        dg = np.zeros(size)
        if name == "low":
            dg[N : 2 * N] = row
        else:
            dg[:N], dg[N : 2 * N] = self.dh / self.span * row, -row
        return achieved - value, dg, 0.0

    def extremum(self, z, kind):
        """(σ*, value, d value/d dofs of the field) for sag (max tilt·x - y) or lowest point (min y)."""
        xd, yd, _ = self.fields(z)
        tilt = 0.0 if kind == "low" else self.dh / self.span
        at_quad = np.asarray(self.basis.interpolate(yd)) - tilt * np.asarray(self.basis.interpolate(xd))
        element = int(np.unravel_index(np.argmin(at_quad), at_quad.shape)[0])
        best = None
        for k in range(max(element - 1, 0), min(element + 2, self.mesh.t.shape[1])):
            dofs = self.basis.element_dofs[:, k]
            candidate = (*element_minimum(self.basis, k, yd[dofs] - tilt * xd[dofs]), k)
            best = candidate if best is None or candidate < best else best
        value, s_star, k = best
        row = np.zeros(self.N)
        row[self.basis.element_dofs[:, k]] = element_values(self.basis, k, s_star)
        return s_star, (value if kind == "low" else -value), row

    #: set by :func:`_arc_guess` from the initial catenary
    length_scale = 1.0
    load_scale = 1.0

    def total_load(self, L0):
        """Magnitude of the distributed load on a straight cable of length L0 (N)."""
        x = np.asarray(self.basis.global_coordinates())[0] * self.span
        out = arc_loads(self.loads, x, np.full_like(x, self.span), L0, self.span)
        return float(np.sum(np.hypot(out[0], out[1]) * self.basis.dx)) or 1.0

    @property
    def constraint_scale(self):
        name, value = self.constraint
        return float(np.hypot(self.span, self.dh)) if name in ("low", "length") else abs(float(value))

    def step(self, state):
        free = self.free
        J = state.J[free][:, free]
        rhs = -state.R[free]
        if self.fixed_length:
            return solve(J, rhs), 0.0
        border = sp.bmat(
            [
                [J, sp.csr_matrix(state.dR_dL0[free][:, None])],
                [sp.csr_matrix(state.dg[free][None, :]), sp.csr_matrix([[state.dg_dL0]])],
            ],
            format="csr",
        )
        out = solve(border, np.concatenate([rhs, [-state.g]]))
        return out[:-1], out[-1]


def _arc_guess(problem):
    """Catenary under the mean load, in the frame where that load is gravity.

    A uniform load per unit length in any direction hangs the cable in a
    catenary whose "vertical" is the load's direction; the mean load of the
    actual loads gives that frame. For vertical loads this is the ordinary
    catenary of the same total weight, with the same constraint.
    """
    span, dh = problem.span, problem.dh
    name, value = problem.constraint
    chord = float(np.hypot(span, dh))
    length = (value if value > chord else chord * (1 + 1e-6)) if name == "length" else chord
    x = np.asarray(problem.basis.global_coordinates())[0] * span
    Q = arc_loads(problem.loads, x, np.full_like(x, span), length, span)
    mean = np.array([np.sum(Q[0] * problem.basis.dx), np.sum(Q[1] * problem.basis.dx)]) / length
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
    problem.load_scale = problem.total_load(L_guess)
    return np.concatenate([xs, ys, T]), float(L_guess)


class ArcSolution(FiniteElementSolution):
    """Solution of :func:`~skcable.cable.solve_bvp` with ``formulation="arc"``.

    Attributes as :class:`~skcable.cable.BVPSolution`; ``H`` is the
    horizontal reaction at A (constant along the cable unless horizontal
    loads act), ``H_B`` the one at B; ``xy(sigma)`` gives the position at
    the normalised unstretched arc length σ ∈ [0, 1].
    """

    formulation = "arc"

    def __init__(self, problem, z, L0, history):
        self._problem = problem
        self.span, self.dh, self.EA = problem.span, problem.dh, problem.EA
        self.mesh, self.basis = problem.mesh, problem.basis
        self.dofs, self.L0 = z, L0
        self.history = list(history)
        self.iterations = len(self.history) - 1
        self.constraint = problem.constraint
        self._state = problem.assemble(z, L0)
        self.H, self.V_A, self.H_B, self.V_B = (float(v) for v in problem.reactions(self._state.R))

    @property
    def T_A(self):
        return float(np.hypot(self.H, self.V_A))

    @property
    def T_B(self):
        return float(np.hypot(self.H_B, self.V_B))

    @property
    def length(self):
        return self.L0

    @cached_property
    def stretched_length(self):
        xd, yd, _ = self._problem.fields(self.dofs)
        ax, ay = self.basis.interpolate(xd).grad[0], self.basis.interpolate(yd).grad[0]
        return float(np.sum(np.sqrt(ax * ax + ay * ay) * self.basis.dx))

    @property
    def x_low(self):
        return float(self.xy(self._low[0])[0])

    def xy(self, sigma):
        """Position (x, y) at σ ∈ [0, 1], array ``(..., 2)``."""
        sigma = np.asarray(real("sigma", sigma), dtype=float)
        require("sigma", (sigma >= 0) & (sigma <= 1), "must lie in [0, 1]", sigma)
        probes = self.basis.probes(sigma.reshape(1, -1))
        xd, yd, _ = self._problem.fields(self.dofs)
        return np.stack([probes @ xd, probes @ yd], axis=-1).reshape(*sigma.shape, 2)

    def _sigma_of_x(self, x):
        x = np.asarray(real("x", x), dtype=float)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        xd = self._problem.fields(self.dofs)[0]
        nodal = xd[self.basis.nodal_dofs[0]]
        if np.any(np.diff(nodal) <= 0):
            raise InputError(
                "x", "the cable is not a graph y(x) here (x(σ) is not increasing): use xy(sigma)"
            )
        probe = self.basis.probes

        def f(s):
            return (probe(np.atleast_2d(s.ravel())) @ xd).reshape(s.shape) - x

        res = elementwise.find_root(f, (np.zeros_like(x), np.ones_like(x)))
        return np.asarray(res.x)

    def y(self, x):
        s = self._sigma_of_x(x)
        return self.xy(s)[..., 1][()]

    def slope(self, x):
        s = np.atleast_1d(self._sigma_of_x(x))
        xd, yd, _ = self._problem.fields(self.dofs)

        G = _gradient_probes(self.basis, s.reshape(1, -1))
        return ((G @ yd) / (G @ xd)).reshape(np.shape(x))[()]

    def T(self, x):
        s = np.atleast_1d(self._sigma_of_x(x))
        T = self._problem.fields(self.dofs)[2]
        return (self._problem.tbasis.probes(s.reshape(1, -1)) @ T).reshape(np.shape(x))[()]

    def samples(self, n: int = 201) -> dict:
        """The profile at ``n`` equally spaced σ (unstretched arc length): see
        :meth:`CableSolution.samples`; non-graph shapes included."""
        sigma = np.linspace(0.0, 1.0, n)
        xd, yd, T = self._problem.fields(self.dofs)
        G = _gradient_probes(self.basis, sigma.reshape(1, -1))
        dx, dy = G @ xd, G @ yd
        xy = self.xy(sigma)
        loads = arc_loads(self._problem.loads, xy[:, 0], dx, self.L0, self.span)
        return {
            "xy": xy,
            "tension": self._problem.tbasis.probes(sigma.reshape(1, -1)) @ T,
            "angle": np.arctan2(dy, dx),
            "load": np.column_stack([loads[0], loads[1]]) / self.L0,
        }

    def _residuals(self):
        problem, state = self._problem, self._state
        yield from problem.scaled(state.R, state.g)
        yield from self._common_residuals(np)

    def __repr__(self):
        return (
            f"ArcSolution(span={self.span:g}, dh={self.dh:g}, {self.mesh.t.shape[1]} elements: "
            f"H={self.H:.9g}, V_A={self.V_A:.9g}, V_B={self.V_B:.9g}, length={self.length:.9g}, "
            f"iterations={self.iterations})"
        )


def solve_arc(span, dh, loads, EA, constraint, n_elements, degree, rtol, max_iter):
    """Newton on the arc-length formulation; see :func:`~skcable.cable.solve_bvp`."""
    problem = _ArcProblem(span, dh, loads, EA, constraint, n_elements, degree)
    z, L0 = _arc_guess(problem)
    if problem.fixed_length:
        L0 = float(constraint[1])
    state = problem.assemble(z, L0)
    history = [state.merit]
    for _ in range(max_iter):
        if state.merit < rtol:
            break
        dz, dL = problem.step(state)
        step = 1.0
        for _ in range(40):
            trial_z = z.copy()
            trial_z[problem.free] += step * dz
            trial_L = L0 + step * dL
            if trial_L > 0:
                trial = problem.assemble(trial_z, trial_L)
                if np.isfinite(trial.merit) and (
                    trial.merit < (1 - 1e-4 * step) * state.merit or trial.merit < rtol
                ):
                    break
            step *= 0.5
        else:
            raise ConvergenceError("solve_bvp(formulation='arc'): line search failed", history)
        z, L0, state = trial_z, trial_L, trial
        history.append(state.merit)
    if state.merit >= rtol:
        raise ConvergenceError(f"solve_bvp(formulation='arc'): no convergence to {rtol:g}", history)
    return ArcSolution(problem, z, L0, history)
