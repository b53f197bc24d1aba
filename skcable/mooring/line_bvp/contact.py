r"""Unilateral seabed contact with Coulomb friction, in the plane and in space: one set of rows.

**Seabed.** At every position node ``i`` but the ends (they are supports) the line stays above
the seabed ``r_v = b(r_h)`` (``r_h`` the horizontal coordinates: x in the plane, (x, y) in space;
``r_v`` the vertical one): ``g_i = r_v - b(r_{h,i}) >= 0``. ``λ_i >= 0`` is its multiplier: the
seabed pushes with ``λ_i n_i``, ``n_i = (-∇b, 1)`` (of length ``sqrt(1 + |∇b|²)``, so the normal
force is ``N_i = λ_i |n_i|``). Coulomb friction, fully mobilised against the line's sliding
towards the fairlead (J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore
floating wind turbine", NREL, 2007), adds ``-μ N_i ŝ_i`` along the line on the seabed: ``ŝ_i``
the unit projection on the seabed's tangent plane of the chord ``c_i = r_{i+1} - r_{i-1}``
between the node's neighbours along the line (the line's tangent there to O(h²); in the plane
``±t/|t|``, ``t = (1, b')``, exactly). In space there is no friction across the line: the seabed's
slope and a cross current move a grounded line sideways until its tension holds it.

With ``R⁰`` the residual without contact, the node's balance ``R⁰_i - λ_i n_i + μ N_i ŝ_i = 0``
splits into the multiplier ``λ_i = n_i·R⁰_i/|n_i|²`` (``ŝ_i ⊥ n_i``), one tangential row per
horizontal coordinate along ``t_k = e_k + (∂_k b) e_v``, and the complementarity row:

.. math::
    \mathbf t_k\cdot\mathbf R^0_i + \mu_i\,\frac{\mathbf n_i\cdot\mathbf R^0_i}{|\mathbf n_i|}\,
        (\mathbf t_k\cdot\hat{\mathbf s}_i) - h_i\,\partial_k b = 0, \qquad
    \min(\lambda_i,\ c_i\,g_i) = 0,

solved by a semismooth (primal–dual active set) Newton method (M. Hintermüller, K. Ito,
K. Kunisch, "The primal-dual active set strategy as a semismooth Newton method", SIAM J. Optim.,
2002): its generalized Jacobian takes ``c_i ∇g_i`` on the active nodes (``λ_i > c_i g_i``) and
``∇λ_i`` elsewhere, and near the solution Newton's method identifies the active set in finitely
many steps and converges quadratically. ``c_i`` is the force scale per length times the node's
element length over the mean one. The rows are linear in ``R⁰_i`` (row mixing of the element
matrices); their dependence on the geometry (``∇b`` at the node through ``∇∇b``, and ``ŝ_i`` on
the neighbours) is the sparse part of the Jacobian. In the plane, with ``|t| = |n|``, the
tangential row is ``(1 - μ b') R⁰_x + (b' + μ) R⁰_y - h b'``.

**The slack stretch.** On a slack stretch ``[0, s0]`` near the anchor
(`skcable.mooring.line_bvp.slack`) friction is only partly mobilised: it holds the line's own
tangential weight, ``μ_i = 0`` and ``h_i`` the node's own external vertical load (the term
``-h_i ∂_k b``, i.e. ``t_k·(R⁰_i - R_ext,i) = 0``; none on a flat seabed).

**The plane seabed.** ``y = b(x)``: a float (flat) or a callable; its slope ``b'`` is the
callable ``seabed_slope`` if given, central differences of ``b`` otherwise, and ``b''``
(Jacobian only) central differences of ``b'`` (`Seabed`). In space the seabed is a
`skcable.mooring.bathymetry.Bathymetry`.

**The anchor on the seabed.** With the anchor on the seabed, A is a contact node as well: the
seabed takes its push ``λ_A = max(n_A·R⁰_A/|n_A|², 0)`` (friction included) and the anchor the
rest, so that a line grounded at A has ``V_A = 0`` and ``H_A = H - μ·(normal forces)`` as in
Jonkman's closed form (`anchor_split`, in the plane and in space).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np
import scipy.sparse as sp

from skcable._checks import real
from skcable.errors import InputError

__all__ = [
    "ContactRows",
    "ContactTerms",
    "Seabed",
    "anchor_split",
    "seabed_of",
    "sliding_direction",
]


@dataclass(frozen=True)
class Seabed:
    """The seabed ``y = b(x)`` (m), with its slope and curvature at any x; as a seabed of the
    contact rows, ``height``, ``gradient`` (1, n) and ``hessian`` (1, 1, n) of x. ``straight``:
    ``(b(0), b')`` (m, -) of a seabed known to be a straight line (a flat one's ``(flat, 0)``),
    None for a callable's."""

    function: Callable
    slope_fn: Callable | None
    flat: float | None
    step: float
    straight: tuple[float, float] | None = None

    def __call__(self, x):
        if self.flat is not None:
            return np.full_like(x, self.flat)
        return self._checked(self.function, x, "seabed")

    def height(self, x):
        """``b(x)`` (m)."""
        return self(x)

    def gradient(self, x):
        """``b'(x)`` as a (1, n) gradient."""
        return self.slope(x)[None]

    def hessian(self, x):
        """``b''(x)`` as a (1, 1, n) Hessian (1/m)."""
        return self.curvature(x)[None, None]

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
        """``b'(x)``: the given slope, else central differences of ``b``."""
        if self.flat is not None:
            return np.zeros_like(x)
        if self.slope_fn is not None:
            return self._checked(self.slope_fn, x, "seabed_slope")
        h = self.step
        return (self(x + h) - self(x - h)) / (2.0 * h)

    def curvature(self, x):
        """``b''(x)`` by central differences of ``b'``."""
        if self.flat is not None:
            return np.zeros_like(x)
        h = self.step
        return (self.slope(x + h) - self.slope(x - h)) / (2.0 * h)


def seabed_of(seabed, seabed_slope, span) -> Seabed | None:
    """The `Seabed` of ``seabed=`` (a height or a callable ``b(x)``) and ``seabed_slope=`` (with
    a height: a number, the straight seabed ``b(x) = seabed + seabed_slope x``; with a callable:
    a callable of x returning db/dx)."""
    if seabed is None:
        if seabed_slope is not None:
            raise InputError("seabed_slope", "applies to a seabed: give seabed= as well")
        return None
    step = 1e-5 * span
    if callable(seabed):
        if seabed_slope is not None and not callable(seabed_slope):
            raise InputError("seabed_slope", "must be a callable of x returning db/dx with a callable seabed")
        return Seabed(seabed, seabed_slope, None, step)
    if isinstance(seabed, (np.ndarray, list, tuple)) and np.size(seabed) != 1:
        raise InputError("seabed", "a height (m) or a callable b(x); one scene at a time")
    level = float(np.asarray(real("seabed", seabed)).reshape(-1)[0])
    slope = 0.0 if seabed_slope is None else seabed_slope
    if callable(slope) or np.size(slope) != 1:
        raise InputError("seabed_slope", "with a seabed height (a number), a slope dy/dx (a number)")
    slope = float(np.asarray(real("seabed_slope", slope)).reshape(-1)[0])
    if slope == 0.0:
        return Seabed(_Level(level), None, level, step, (level, 0.0))
    return Seabed(_Straight(level, slope), _Straight(slope, 0.0), None, step, (level, slope))


class _Straight:
    """The height ``b(x) = level + slope x`` of a straight seabed (m), or its slope (``level`` the
    slope, ``slope`` 0): a callable that pickles."""

    def __init__(self, level: float, slope: float):
        self.level, self.slope = level, slope

    def __call__(self, x):
        return self.level + self.slope * np.asarray(x, dtype=float)

    def __repr__(self):
        return f"{self.level:g} + {self.slope:g} x"


class _Level:
    """The height ``b(x) = level`` of a flat seabed (m): a callable that pickles."""

    def __init__(self, level: float):
        self.level = level

    def __call__(self, x):
        return np.full_like(x, self.level)

    def __repr__(self):
        return f"flat seabed at {self.level:g} m"


class ContactTerms(NamedTuple):
    """Per contact node at one iterate (arrays over the nodes; ``d`` the horizontal dimensions).

    Attributes
    ----------
    grad : ndarray (d, n)
        ``∇b`` at the node.
    hess : ndarray (d, d, n)
        ``∇∇b`` there (1/m).
    gap : ndarray
        ``r_v − b`` (m).
    lam : ndarray
        ``λ`` (N per unit ``|n|``).
    active : ndarray of bool
        ``λ > c g`` (or the set held).
    R : ndarray (dim, n)
        ``R⁰`` at the node (N).
    chord : ndarray (dim, n)
        ``c = r_next − r_prev`` (m).
    friction : tuple
        ``(n, ν, ŝ, |P c|, τ)``: the normal ``(−∇b, 1)``, ``ν = |n|²``, the sliding direction,
        the chord's projected length and ``τ_k = t_k·ŝ`` (d, n), computed once per iterate (the
        last three None without friction).
    """

    grad: np.ndarray
    hess: np.ndarray
    gap: np.ndarray
    lam: np.ndarray
    active: np.ndarray
    R: np.ndarray
    chord: np.ndarray
    friction: tuple

    @property
    def slope(self) -> np.ndarray:
        """``b'`` of a plane line's nodes."""
        return self.grad[0]


def sliding_direction(chord, normal):
    """``ŝ`` (dim, n): the unit projection of ``chord`` on the plane normal to ``normal`` (both
    (dim, n), ``normal`` of any length), and ``|P c|`` (the projection's length)."""
    nu = np.sum(normal * normal, axis=0)
    p = chord - np.sum(chord * normal, axis=0) / nu * normal
    size = np.sqrt(np.sum(p * p, axis=0))
    return p / np.where(size > 0, size, 1.0), size


@dataclass(frozen=True)
class ContactRows:
    """The contact rows of the position nodes ``nodes`` (coordinate ``k`` at ``k N + nodes``).

    Attributes
    ----------
    nodes : ndarray of int
        The contact nodes' dofs in the first field, along the line.
    prev, next : ndarray of int
        Their neighbours along the line (dofs in the first field).
    N : int
        Dofs per position field.
    dim : int
        2 (the plane) or 3 (space).
    seabed : Seabed or Bathymetry
        ``height``, ``gradient`` and ``hessian`` of the horizontal coordinates.
    stiffness : ndarray
        ``c_i`` of the complementarity function per node (N/m).
    mu : ndarray
        Friction coefficient per node: μ where the line slides, 0 on a slack stretch.
    held : ndarray or None
        ``h_i``: the external vertical load (N) whose tangential part friction holds on a slack
        stretch, per node (None: no slack stretch).
    switch : ndarray or None
        ``c_i`` of the active-set test ``λ > c g`` where it differs from ``stiffness`` (the rows
        themselves, ``c g = 0`` or ``λ = 0``, have the same Newton step for any ``c > 0``).
    frozen : ndarray of bool or None
        The active set held fixed (`skcable.mooring.line_bvp.iterate.frozen_steps`): each node's
        row is ``c g = 0`` where True and ``λ = 0`` where False, whatever ``λ`` and ``g`` are.
    """

    nodes: np.ndarray
    prev: np.ndarray
    next: np.ndarray
    N: int
    dim: int
    seabed: Any
    stiffness: np.ndarray
    mu: np.ndarray
    held: np.ndarray | None = None
    switch: np.ndarray | None = None
    frozen: np.ndarray | None = None

    #: some node slides with friction (the friction rows are written)
    sliding: bool = field(init=False, default=False)
    #: the nodes' dofs (dim, n), and their neighbours' (the chord)
    at: np.ndarray = field(init=False, repr=False)
    at_next: np.ndarray = field(init=False, repr=False)
    at_prev: np.ndarray = field(init=False, repr=False)

    def __post_init__(self):
        first = np.arange(self.dim)[:, None] * self.N  # the first dof of each coordinate
        object.__setattr__(self, "sliding", bool(np.any(self.mu > 0)))
        object.__setattr__(self, "at", first + self.nodes)
        object.__setattr__(self, "at_next", first + self.next)
        object.__setattr__(self, "at_prev", first + self.prev)

    def terms(self, z, R0) -> ContactTerms:
        """Per contact node: gradient, Hessian, gap, multiplier, active flag, ``R⁰``, chord."""
        d = self.dim - 1
        r = z[self.at]
        grad, hess = self.seabed.gradient(*r[:d]), self.seabed.hessian(*r[:d])
        gap = r[d] - self.seabed.height(*r[:d])
        R = R0[self.at]
        nu = 1.0 + (grad * grad).sum(axis=0)
        lam = (R[d] - (grad * R[:d]).sum(axis=0)) / nu
        if self.frozen is not None:
            active = self.frozen
        else:
            active = lam > (self.stiffness if self.switch is None else self.switch) * gap
        chord = z[self.at_next] - z[self.at_prev]
        n = np.empty_like(R)
        n[:d], n[d] = -grad, 1.0
        friction: tuple = (n, nu, None, None, None)
        if self.sliding:
            s_hat, size = sliding_direction(chord, n)
            friction = (n, nu, s_hat, size, s_hat[:d] + grad * s_hat[d])
        return ContactTerms(grad, hess, gap, lam, active, R, chord, friction)

    @staticmethod
    def _friction(terms: ContactTerms):
        """``(n, ν, ŝ, |P c|, τ)`` of ``terms`` (`ContactTerms.friction`)."""
        return terms.friction

    def rows(self, F, terms: ContactTerms) -> None:
        """Put the tangential and complementarity rows into the residual ``F`` (in place)."""
        i, N, d = self.nodes, self.N, self.dim - 1
        g, R = terms.grad, terms.R
        for k in range(d):
            F[k * N + i] = R[k] + g[k] * R[d]
        if self.sliding:
            _, nu, _, _, tau = self._friction(terms)
            A = terms.lam * nu  # n·R⁰
            for k in range(d):
                F[k * N + i] += self.mu * A * tau[k] / np.sqrt(nu)
        if self.held is not None:
            for k in range(d):
                F[k * N + i] -= self.held * g[k]
        F[d * N + i] = np.where(terms.active, self.stiffness * terms.gap, terms.lam)

    def mixed(self, Ke, terms: ContactTerms, element_dofs, size):
        """The generalized Jacobian's contact part: ``Ke`` with the contact rows mixed in (rows of
        a node's coordinates combined), and the geometric terms they cannot carry (sparse)."""
        i, N, d, dim = self.nodes, self.N, self.dim - 1, self.dim
        g, active = terms.grad, terms.active
        n, nu = terms.friction[:2]
        # row k of a contact node = Σ_j M[k, j] (row j of R⁰), per position dof
        M = np.zeros((dim, dim, N))
        for k in range(dim):
            M[k, k] = 1.0
        for k in range(d):
            M[k, d, i] = g[k]
        if self.sliding:
            tau = self._friction(terms)[4]
            for k in range(d):
                M[k][:, i] += self.mu * tau[k] / np.sqrt(nu) * n
        M[d][:, i] = np.where(active, 0.0, n / nu)
        nb = element_dofs.shape[0]
        blocks = [Ke[k * nb : (k + 1) * nb] for k in range(dim)]
        mixed = Ke.copy()
        for k in range(dim):
            mixed[k * nb : (k + 1) * nb] = sum(
                M[k, j][element_dofs][:, None, :] * blocks[j] for j in range(dim)
            )
        return mixed, self._geometric(terms, size)

    def _geometric(self, terms: ContactTerms, size):
        """The rows' derivatives through the geometry, ``R⁰`` held: through ``∇b(r_h)`` (chain
        rule with ``∇∇b``), ``ŝ`` through the neighbours' positions, and the active rows
        ``c (δr_v − ∇b·δr_h)``."""
        i, N, c, d, dim = self.nodes, self.N, self.stiffness, self.dim - 1, self.dim
        g, Hs, R, lam, active = terms.grad, terms.hess, terms.R, terms.lam, terms.active
        nu = 1.0 + np.sum(g * g, axis=0)
        # ∂F/∂g_j (dim rows, d columns, per node) with R⁰ held
        dF_dg = np.zeros((dim, d, i.size))
        for k in range(d):
            dF_dg[k, k] = R[d] if self.held is None else R[d] - self.held  # ∂(t_k·R − h g_k)/∂g_k
        dF_dg[d] = np.where(active, 0.0, -R[:d] / nu - lam * 2.0 * g / nu)  # ∂λ/∂g_j
        rows, cols, vals = [], [], []
        if self.sliding:
            dF_dg[:d] += self._friction_by_grad(terms)
        if self.sliding and dim == 3:  # in the plane ŝ = ±t/|t| holds whatever the chord
            for k in range(d):  # ŝ through the chord: ∂F_k/∂c, c = r_next − r_prev
                dc = self._friction_by_chord(terms, k)
                for j in range(dim):
                    rows += [k * N + i, k * N + i]
                    cols += [j * N + self.next, j * N + self.prev]
                    vals += [dc[j], -dc[j]]
        dF_dh = np.sum(dF_dg[:, :, None, :] * Hs[None], axis=1)  # (dim, d, n): through g(r_h)
        at = self.at
        rows.append(np.repeat(at, d, axis=0).ravel())
        cols.append(np.tile(at[:d], (dim, 1)).ravel())
        vals.append(dF_dh.ravel())
        # the active complementarity rows c (r_v − b): ∂/∂r_h = −c ∇b, ∂/∂r_v = c
        rows.append(np.tile(at[d], dim))
        cols.append(at.ravel())
        vals.append(np.where(active, np.concatenate([-c * g, c[None]]), 0.0).ravel())
        return sp.coo_matrix(
            (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(size, size)
        )

    def _friction_by_grad(self, terms: ContactTerms):
        """``∂/∂g_j`` of the friction part ``μ A τ_k/σ`` of the tangential rows (d, d, n):
        ``A = n·R⁰``, ``σ = |n|``, ``τ_k = t_k·ŝ``, with ``∂n/∂g_j = −e_j``, ``∂ν/∂g_j = 2 g_j``,
        ``∂t_k/∂g_j = δ_kj e_v`` and ``∂p/∂g_j = c_j n/ν + (c·n) e_j/ν + 2 g_j (c·n) n/ν²``."""
        n, nu, s_hat, size, tau = self._friction(terms)
        g, R, c, d = terms.grad, terms.R, terms.chord, self.dim - 1
        A, sigma = terms.lam * nu, np.sqrt(nu)
        cn = np.sum(c * n, axis=0)
        out = np.zeros((d, d, g.shape[1]))
        for j in range(d):
            e_j = np.zeros_like(n)
            e_j[j] = 1.0
            dp = c[j] * n / nu + cn * e_j / nu + 2.0 * g[j] * cn * n / nu**2
            ds = (dp - np.sum(s_hat * dp, axis=0) * s_hat) / np.where(size > 0, size, 1.0)
            for k in range(d):
                t_k = np.zeros_like(n)
                t_k[k], t_k[d] = 1.0, g[k]
                dtau = (s_hat[d] if j == k else 0.0) + np.sum(t_k * ds, axis=0)
                out[k, j] = self.mu * (
                    -R[j] * tau[k] / sigma + A * dtau / sigma - A * tau[k] * g[j] / sigma**3
                )
        return out

    def _friction_by_chord(self, terms: ContactTerms, k: int):
        """``∂F_k/∂c`` (dim, n): ``μ (A/σ) t_kᵀ (I − ŝŝᵀ) P_n / |P c|``."""
        n, nu, s_hat, size, tau = self._friction(terms)
        g, d = terms.grad, self.dim - 1
        A, sigma = terms.lam * nu, np.sqrt(nu)
        t_k = np.zeros_like(n)
        t_k[k], t_k[d] = 1.0, g[k]
        q = t_k - tau[k] * s_hat  # (I − ŝŝᵀ) t_k
        q = q - np.sum(q * n, axis=0) / nu * n  # P_n (symmetric)
        return self.mu * A / sigma * q / np.where(size > 0, size, 1.0)

    def forces(self, terms: ContactTerms):
        """Per node: ``(normal, friction)``, the seabed's normal force ``λ n`` and its friction
        (dim, n) (N): ``−μ N ŝ`` where the line slides, and on a slack stretch the force that
        holds the node's own tangential weight, ``−h (∇b·t)/|t|²``-wise along the seabed."""
        g, d = terms.grad, self.dim - 1
        n, nu, s_hat, _, _ = self._friction(terms)
        normal = terms.lam * n
        friction = np.zeros_like(n) if s_hat is None else -self.mu * terms.lam * np.sqrt(nu) * s_hat
        if self.held is not None and d == 1:
            t = np.concatenate([np.ones_like(g), g])
            friction = friction + self.held * g[0] / nu * t
        return normal, friction


def anchor_split(S, grad, chord, mu):
    """The anchor's reaction on the line ``S`` (dim,) (N) with the seabed under it taking its
    push, in the plane (``dim = 2``) or in space (3): ``λ_A = max(n·S/|n|², 0)`` with
    ``n = (−∇b, 1)``, friction ``μ N_A`` against ``ŝ`` (``chord`` projected on the seabed: the
    chord from the anchor to its neighbour; in the plane ``(1, b')``, towards the fairlead).

    Returns ``(S − C, C, λ_A)``, ``C = λ_A (n − μ|n| ŝ)``: what the anchor carries, what the
    seabed under it carries (N), and the multiplier."""
    n = np.array([*(-np.asarray(grad, dtype=float)), 1.0])
    nu = float(n @ n)
    lam = max(float(n @ S) / nu, 0.0)
    s_hat = sliding_direction(np.asarray(chord, dtype=float)[:, None], n[:, None])[0][:, 0]
    seabed = lam * (n - mu * np.sqrt(nu) * s_hat)
    return S - seabed, seabed, lam
