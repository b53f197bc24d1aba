r"""Where a line leaves the seabed: the touchdown and the landing from the balance of forces.

Nodal contact puts the touchdown at a node, up to half an element from where the line leaves
the seabed, an error in the end forces of order (that distance)² that jumps with the mesh. The
drivers put a node at the touchdown instead (`skcable.mooring.line_bvp.driver`,
`skcable.mooring.line_bvp.space.driver`), found from the equilibrium of the suspended part, in the
plane or in space: the tension vector at ``s``,

.. math:: \mathbf F(s) = \mathbf S_B + \int_s^L \mathbf f\,ds - \sum_{s_k > s} P_k\,\mathbf e_z,

(``S_B`` the fairlead's reaction on the line, ``f`` the distributed force, ``P_k`` the point
loads, ``e_z`` up) is tangent to the seabed where the line leaves it, ``n(r(s))·F(s) = 0`` with
``n = (−∇b, 1)``: in the plane the vertical balance ``V_B − W(s, L) = H b'``. The landing of a
line hanging from an anchor above the seabed is the same balance of the part ``[0, s]``,
``F(s) = −S_A − ∫_0^s f ds + Σ_{s_k < s} P_k e_z``. The integrals are the element integrals of
the solution's forces and, in the element of ``s``, a Gauss–Legendre rule of `ORDER` points; the
root is bracketed between the mesh nodes around the last (first) node on the seabed and found as
the root of the balance's Chebyshev interpolant over the element, kept where the balance changes
sign within 1e-13 of the length of it (else by Brent's method to that tolerance).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

__all__ = ["ORDER", "LineBalance", "landing", "touchdown"]

#: Gauss–Legendre points of the integral over the part of an element
ORDER = 8
#: Chebyshev points of the interpolant whose root starts the touchdown's search
SAMPLES = 12
_X, _W = np.polynomial.legendre.leggauss(ORDER)


class LineBalance:
    """The balance of a solved line from its fairlead (``side = "b"``) or anchor (``"a"``): the
    tension vector `forces` ``F(s)`` (module docstring) and ``n(r(s))·F(s)`` (`values`; a scalar
    call for Brent's method), vectorised over the arc lengths. Without the residual without
    contact ``R0`` the end's reaction is left out: from the anchor, ``F(s)`` is then the load on
    ``[0, s]``, ``Σ_{s_k < s} P_k e_z − ∫_0^s f ds`` (the weight and the point loads up, the
    cable terms' force against)."""

    def __init__(self, problem, z, R0, side):
        self.problem, self.z, self.side = problem, z, side
        g = problem.assembly.interpolate(z)
        f = -problem.distributed_load(g)[0]
        dim = problem.dim
        left, right = np.sort(problem.mesh.p[0, problem.mesh.t], axis=0)
        order = np.argsort(left)  # the elements along the line
        self.left, self.right = left[order], right[order]
        element_force = np.sum(f * problem.assembly.dx, axis=1)[:, order]  # (dim, ne)
        zero = np.zeros((dim, 1))
        # the elements' forces beyond element k (side b: k+1…) or before it (side a: …k−1)
        self.beyond = np.concatenate([np.cumsum(element_force[:, ::-1], axis=1)[:, ::-1], zero], axis=1)[
            :, 1:
        ]
        self.before = np.concatenate([zero, np.cumsum(element_force, axis=1)], axis=1)[:, :-1]
        if R0 is None:
            self.end = np.zeros(dim)
        else:
            self.end = R0[problem.end_dofs("b")] if side == "b" else -R0[problem.end_dofs("a")]
        self.loads_s = np.array([s_p for s_p, _ in problem.point_loads], dtype=float)
        self.loads_P = np.array([P for _, P in problem.point_loads], dtype=float)

    def forces(self, s) -> np.ndarray:
        """``F(s)`` (dim, n) (N), the tension vector at the arc lengths ``s`` (1-D) towards the
        fairlead."""
        k = np.clip(np.searchsorted(self.right, s), 0, self.right.size - 1)
        lo, hi = (s, self.right[k]) if self.side == "b" else (self.left[k], s)
        half = 0.5 * np.maximum(hi - lo, 0.0)
        points = (0.5 * (lo + hi))[:, None] + half[:, None] * _X  # (n, ORDER)
        f = self.problem.forces_at(self.z, points.ravel()).reshape(-1, *points.shape)
        partial = np.einsum("knq,nq->kn", f, half[:, None] * _W)
        if self.side == "b":
            F = self.end[:, None] + self.beyond[:, k] + partial
            F[-1] -= np.sum(np.where(self.loads_s[:, None] > s, self.loads_P[:, None], 0.0), axis=0)
        else:
            F = self.end[:, None] - self.before[:, k] - partial
            F[-1] += np.sum(np.where(self.loads_s[:, None] < s, self.loads_P[:, None], 0.0), axis=0)
        return F

    def values(self, s) -> np.ndarray:
        """``n(r(s))·F(s)`` (N) at the arc lengths ``s`` (1-D)."""
        r = self.problem.state_at(self.z, s).position
        grad = self.problem.seabed.gradient(*r[:-1])
        F = self.forces(s)
        return F[-1] - np.sum(grad * F[:-1], axis=0)

    def __call__(self, s) -> float:
        return float(self.values(np.array([float(s)]))[0])


def _root(balance, near, nodes, length):
    """The root of ``balance`` between the mesh ``nodes`` around ``near``, nearest it; None
    where it changes sign nowhere there."""
    h = float(np.max(np.diff(nodes)))
    grid = nodes[(nodes >= near - 2 * h) & (nodes <= near + 2 * h)]
    values = balance.values(grid)
    zero = np.flatnonzero(values == 0.0)
    if zero.size:
        return float(grid[zero[np.argmin(np.abs(grid[zero] - near))]])
    change = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
    if not change.size:
        return None
    k = int(change[np.argmin(np.abs(grid[change] - near))])
    found = _interpolated_root(balance, grid[k], grid[k + 1], 1e-13 * length)
    return float(brentq(balance, grid[k], grid[k + 1], xtol=1e-13 * length)) if found is None else found


def _interpolated_root(balance, a, b, xtol):
    """The root in ``[a, b]`` of the Chebyshev interpolant of ``balance`` at `SAMPLES` points
    (one evaluation), kept where ``balance`` changes sign within ``xtol`` of it (a second one)
    and refined there by a secant step; None where it does not (a kink in the element: the
    seabed's grid, a tabulated current), for Brent's method."""
    x = a + (b - a) * 0.5 * (1.0 - np.cos(np.pi * (np.arange(SAMPLES) + 0.5) / SAMPLES))
    roots = np.polynomial.Chebyshev.fit(x, balance.values(x), SAMPLES - 1, domain=[a, b]).roots()
    real = roots.real[(np.abs(roots.imag) <= 1e-9 * (b - a)) & (roots.real >= a) & (roots.real <= b)]
    if real.size != 1:
        return None
    lo, hi = max(a, real[0] - xtol), min(b, real[0] + xtol)
    v_lo, v_hi = balance.values(np.array([lo, hi]))
    if v_lo == 0.0 or v_hi == 0.0:
        return float(lo if v_lo == 0.0 else hi)
    if np.sign(v_lo) == np.sign(v_hi):
        return None
    return float(np.clip(lo - v_lo * (hi - lo) / (v_hi - v_lo), lo, hi))


def touchdown(problem, z, state, from_anchor=False):
    """The arc length (m) where the line leaves the seabed for the last time towards the
    fairlead (module docstring), sought near its last node on the seabed, or near the anchor
    where ``from_anchor`` (the anchor's node alone presses on the seabed); None without contact
    or without a sign change near it."""
    active = state.terms is not None and np.any(state.terms.active)
    if not (active or from_anchor):
        return None
    near = 0.0
    if active:
        near = float(problem.basis.doflocs[0][problem.contact_rows.nodes[state.terms.active]].max())
    return _root(LineBalance(problem, z, state.R0, "b"), near, np.sort(problem.mesh.p[0]), problem.L)


def landing(problem, z, state):
    """The arc length (m) where a line hanging from an anchor above the seabed first lands on it;
    None where the anchor lies on the seabed or nothing touches."""
    if state.terms is None or not np.any(state.terms.active):
        return None
    a = problem.anchor
    if abs(a[-1] - float(problem.seabed.height(*a[:-1]))) <= 1e-12 * problem.L:  # as the solutions
        return None
    near = float(problem.basis.doflocs[0][problem.contact_rows.nodes[state.terms.active]].min())
    return _root(LineBalance(problem, z, state.R0, "a"), near, np.sort(problem.mesh.p[0]), problem.L)
