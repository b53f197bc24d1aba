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

The forms (`skcable.cable.bvp.forms`) are a *section law* in the
generalized strains ``(x', y', x, y, T)``: `ArcProblem` assembles them
with `skcable.fe.Assembly` (basis values and patterns once) and
solves the bordered banded system of `skcable.cable.bvp.bordered`.

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
from skcable.cable._catenary import catenary
from skcable.cable._loads import DeckLoad, DistributedLoad, PointLoad, SelfWeight
from skcable.cable.bvp.base import FiniteElementSolution
from skcable.cable.bvp.elements import end_dofs
from skcable.cable.bvp.probes import element_values, gradient_probes, minimum_near
from skcable.errors import InputError
from skcable.fe.assembly import Assembly
from skcable.fe.linear import BorderedSolver

__all__ = ["ArcProblem", "ArcSolution", "ArcState", "arc_guess", "arc_loads"]

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
        return self.assembly.matrix(element_matrices=self.Ke)


_REJECTED = ArcState(None, None, None, np.inf, None, np.inf, np.inf, np.inf)


class ArcProblem:
    """Mesh, bases, loads, constraint and the assembly of one arc-length solve.

    ``tension`` is the tension's element (P1-DG; a continuous P1 is there to
    show why not, see the module docstring).
    """

    def __init__(self, span, dh, loads, EA, constraint, n_elements, degree, tension=None):
        if any(isinstance(ld, PointLoad) for ld in loads):
            raise InputError("load", "point loads at fixed x need formulation='graph'")
        if degree != 2:
            raise InputError(
                "degree", f"formulation='arc' uses degree 2 (P2 positions, P1 tension), got {degree!r}"
            )
        self.span, self.dh, self.EA, self.constraint, self.loads = span, dh, EA, constraint, loads
        self.compliance = 0.0 if EA is None else 1.0 / EA
        n = positive("n_elements", n_elements)
        require("n_elements", n == int(n), "must be a whole number", n)
        self.mesh = MeshLine(np.linspace(0.0, 1.0, int(n) + 1))
        self.basis = Basis(self.mesh, ElementLineP2(), intorder=6)
        self.tbasis = self.basis.with_element(ElementLineP1DG() if tension is None else tension)
        N, M = self.basis.N, self.tbasis.N
        self.N, self.M = N, M
        self.end_a, self.end_b, inner = end_dofs(self.basis)
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
        n = np.sqrt(ax * ax + ay * ay)
        if not np.all(n > 0):  # a collapsed tangent: reject this iterate
            return _REJECTED
        ex, ey = ax / n, ay / n
        Qx, Qy, dQx_dx, dQy_dx, dQx_dxp, dQy_dxp, dQx_dL, dQy_dL = arc_loads(self.loads, X, ax, L0, self.span)
        c = self.compliance
        S = np.stack([T * ex, T * ey, -Qx, -Qy, n - L0 * (1.0 + T * c)])
        D = np.zeros((5, 5, *n.shape))
        Tn = T / n
        D[_AX, _AX] = Tn * (1.0 - ex * ex)
        D[_AX, _AY] = D[_AY, _AX] = -Tn * ex * ey
        D[_AY, _AY] = Tn * (1.0 - ey * ey)
        D[_AX, _T] = D[_T, _AX] = ex
        D[_AY, _T] = D[_T, _AY] = ey
        D[_X, _X], D[_X, _AX] = -dQx_dx, -dQx_dxp
        D[_Y, _X], D[_Y, _AX] = -dQy_dx, -dQy_dxp
        D[_T, _T] = -L0 * c
        R = asmb.vector(S)
        Ke = asmb.element_matrices(D)
        zero = np.zeros_like(n)
        dR_dL0 = asmb.vector(np.stack([zero, zero, -dQx_dL, -dQy_dL, -(1.0 + T * c)]))
        gap, dg, dg_dL0 = self.constraint_terms(z, R, Ke, dR_dL0, g)
        force = np.abs(R[self._force_rows]) / self.load_scale
        stretch = np.abs(R[self._stretch_rows]) / self.length_scale
        constraint = float(abs(gap) / self.constraint_scale)
        merit = max(float(np.max(force, initial=0.0)), float(np.max(stretch, initial=0.0)), constraint)
        descent = float(np.sqrt(np.sum(force * force) + np.sum(stretch * stretch) + constraint * constraint))
        return ArcState(R, Ke, dR_dL0, float(gap), dg, float(dg_dL0), merit, descent, asmb)

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
        ab = system.add_elements(system.band(), state.Ke)
        if self.fixed_length:
            d_z, d_L = self.solver.solve(ab, state.R[free], gap=0.0)
        else:
            d_z, d_L = self.solver.solve(
                ab, state.R[free], state.dR_dL0[free], state.dg[free], state.dg_dL0, state.g
            )
        step = np.zeros(2 * self.N + self.M + 1)
        step[free] = d_z
        step[-1] = d_L
        return step

    # --- constraint -------------------------------------------------------------
    def reactions(self, R):
        N = self.N
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

    def total_load(self, L0):
        """Magnitude of the distributed load on a straight cable of length L0 (N)."""
        x = self.assembly.x * self.span
        out = arc_loads(self.loads, x, np.full_like(x, self.span), L0, self.span)
        return float(np.sum(np.hypot(out[0], out[1]) * self.assembly.dx)) or 1.0

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
    x, dx = problem.assembly.x * span, problem.assembly.dx
    Q = arc_loads(problem.loads, x, np.full_like(x, span), length, span)
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
    problem.load_scale = problem.total_load(L_guess)
    return np.concatenate([xs, ys, T]), float(L_guess)


class ArcSolution(FiniteElementSolution):
    """Solution of `solve_bvp` with ``formulation="arc"``.

    Attributes as `BVPSolution`; ``H`` is the
    horizontal reaction at A (constant along the cable unless horizontal
    loads act), ``H_B`` the one at B; ``xy(sigma)`` gives the position at
    the normalised unstretched arc length σ ∈ [0, 1].
    """

    formulation = "arc"

    def __init__(self, problem: ArcProblem, z, L0, history, state: ArcState | None = None):
        super().__init__(problem, z, history, problem.assemble(z, L0) if state is None else state)
        self.L0 = float(L0)
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
        g = self._problem.assembly.interpolate(self.dofs)
        return float(np.sum(np.hypot(g[_AX], g[_AY]) * self._problem.assembly.dx))

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
        G = gradient_probes(self.basis, s.reshape(1, -1))
        return ((G @ yd) / (G @ xd)).reshape(np.shape(x))[()]

    def T(self, x):
        s = np.atleast_1d(self._sigma_of_x(x))
        T = self._problem.fields(self.dofs)[2]
        return (self._problem.tbasis.probes(s.reshape(1, -1)) @ T).reshape(np.shape(x))[()]

    def samples(self, n: int = 201) -> dict:
        """The profile at ``n`` equally spaced σ (unstretched arc length): see
        `CableSolution.samples`; non-graph shapes included."""
        sigma = np.linspace(0.0, 1.0, n)
        xd, yd, T = self._problem.fields(self.dofs)
        G = gradient_probes(self.basis, sigma.reshape(1, -1))
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
