r"""Unilateral contact of a line in space with a seabed ``z = b(x, y)``, with Coulomb friction.

The 2-D line's contact (`skcable.mooring.line_bvp.contact`) in three dimensions. At every
position node ``i`` but the ends the line stays above the seabed, ``g_i = z_i − b(x_i, y_i) ≥ 0``;
the seabed pushes with ``λ_i n_i``, ``n_i = (−b_x, −b_y, 1)`` (``|n_i| = sqrt(1 + |∇b|²)``, the
normal force ``N_i = λ_i |n_i|``), and Coulomb friction, fully mobilised against the line's
sliding towards the fairlead (J.M. Jonkman, "Dynamics modeling and loads analysis of an
offshore floating wind turbine", NREL, 2007), adds ``−μ N_i ŝ_i`` along the line's direction on
the seabed: ``ŝ_i`` the unit projection on the seabed's tangent plane of the chord
``c_i = r_{i+1} − r_{i−1}`` between the node's neighbours along the line (the line's tangent
there to O(h²); exact on a straight grounded stretch). Across the line there is no friction:
the seabed's slope and a cross current move a grounded line sideways until its tension holds
it.

With ``R⁰`` the residual without contact, the node's balance ``R⁰_i − λ_i n_i + μ N_i ŝ_i = 0``
splits into the multiplier ``λ_i = n_i·R⁰_i/|n_i|²`` (``ŝ_i ⊥ n_i``), two tangential rows along
``t₁ = (1, 0, b_x)`` and ``t₂ = (0, 1, b_y)``, and the complementarity row:

.. math::
    \mathbf t_k\cdot\mathbf R^0_i + \mu\,\frac{\mathbf n_i\cdot\mathbf R^0_i}{|\mathbf n_i|}\,
        (\mathbf t_k\cdot\hat{\mathbf s}_i) = 0 \quad (k = 1, 2), \qquad
    \min(\lambda_i,\ c_i\,g_i) = 0,

solved by a semismooth (primal–dual active set) Newton method (M. Hintermüller, K. Ito,
K. Kunisch, SIAM J. Optim., 2002): its generalized Jacobian takes ``c_i ∇g_i`` on the active
nodes (``λ_i > c_i g_i``) and ``∇λ_i`` elsewhere. In 2-D (``b_y = 0``, no lateral motion) the
rows are the plane line's. The rows are linear in ``R⁰_i`` (row mixing of the element
matrices); their dependence on the geometry (``∇b`` at the node through ``∇∇b``, and ``ŝ_i`` on
the neighbours) is the sparse part of the Jacobian.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import scipy.sparse as sp

from skcable.mooring.bathymetry import Bathymetry

__all__ = ["ContactRows3D", "ContactTerms3D", "anchor_split_3d", "sliding_direction"]


class ContactTerms3D(NamedTuple):
    """Per contact node at one iterate (arrays over the nodes, vectors (3, n)).

    Attributes
    ----------
    grad : ndarray (2, n)
        ``∇b`` at the node.
    hess : ndarray (2, 2, n)
        ``∇∇b`` there (1/m).
    gap : ndarray
        ``z − b`` (m).
    lam : ndarray
        ``λ`` (N per unit ``|n|``).
    active : ndarray of bool
        ``λ > c g``.
    R : ndarray (3, n)
        ``R⁰`` at the node (N).
    chord : ndarray (3, n)
        ``c = r_next − r_prev`` (m).
    """

    grad: np.ndarray
    hess: np.ndarray
    gap: np.ndarray
    lam: np.ndarray
    active: np.ndarray
    R: np.ndarray
    chord: np.ndarray


def sliding_direction(chord, normal):
    """``ŝ`` (3, n): the unit projection of ``chord`` on the plane normal to ``normal`` (both
    (3, n), ``normal`` of any length), and ``|P c|`` (the projection's length)."""
    nu = np.sum(normal * normal, axis=0)
    p = chord - np.sum(chord * normal, axis=0) / nu * normal
    size = np.sqrt(np.sum(p * p, axis=0))
    return p / np.where(size > 0, size, 1.0), size


@dataclass(frozen=True)
class ContactRows3D:
    """The contact rows of the position nodes ``nodes`` (x at ``nodes``, y at ``N + nodes``, z at
    ``2N + nodes``), their neighbours along the line ``prev``, ``next`` (position dofs in the x
    field), the seabed, ``c_i`` (N/m) per node and the friction coefficient μ; ``frozen``: the
    active set held fixed (`skcable.mooring.line_bvp.iterate.frozen_steps`), each node's row
    ``c g = 0`` where True and ``λ = 0`` where False, whatever ``λ`` and ``g`` are."""

    nodes: np.ndarray
    prev: np.ndarray
    next: np.ndarray
    N: int
    seabed: Bathymetry
    stiffness: np.ndarray
    mu: float
    frozen: np.ndarray | None = None

    def terms(self, z, R0) -> ContactTerms3D:
        """Per contact node: gradient, Hessian, gap, multiplier, active flag, ``R⁰``, chord."""
        i, N = self.nodes, self.N
        x, y, h = z[i], z[N + i], z[2 * N + i]
        grad = self.seabed.gradient(x, y)
        hess = self.seabed.hessian(x, y)
        gap = h - self.seabed.height(x, y)
        R = np.array([R0[i], R0[N + i], R0[2 * N + i]])
        nu = 1.0 + grad[0] * grad[0] + grad[1] * grad[1]
        lam = (R[2] - grad[0] * R[0] - grad[1] * R[1]) / nu
        active = lam > self.stiffness * gap if self.frozen is None else self.frozen
        chord = np.array([z[k * N + self.next] - z[k * N + self.prev] for k in range(3)])
        return ContactTerms3D(grad, hess, gap, lam, active, R, chord)

    def _friction(self, terms: ContactTerms3D):
        """``(n, ν, ŝ, |P c|, τ)``: the normal, ``|n|²``, the sliding direction, the chord's
        projected length and ``τ_k = t_k·ŝ`` (2, n)."""
        g = terms.grad
        n = np.array([-g[0], -g[1], np.ones_like(g[0])])
        nu = 1.0 + g[0] * g[0] + g[1] * g[1]
        s_hat, size = sliding_direction(terms.chord, n)
        tau = np.array([s_hat[0] + g[0] * s_hat[2], s_hat[1] + g[1] * s_hat[2]])
        return n, nu, s_hat, size, tau

    def rows(self, F, terms: ContactTerms3D) -> None:
        """Put the tangential and complementarity rows into the residual ``F`` (in place)."""
        i, N = self.nodes, self.N
        g, R = terms.grad, terms.R
        F[i] = R[0] + g[0] * R[2]
        F[N + i] = R[1] + g[1] * R[2]
        if self.mu > 0:
            _, nu, _, _, tau = self._friction(terms)
            A = terms.lam * nu  # n·R⁰
            F[i] += self.mu * A * tau[0] / np.sqrt(nu)
            F[N + i] += self.mu * A * tau[1] / np.sqrt(nu)
        F[2 * N + i] = np.where(terms.active, self.stiffness * terms.gap, terms.lam)

    def mixed(self, Ke, terms: ContactTerms3D, element_dofs, size):
        """The generalized Jacobian's contact part: ``Ke`` with the contact rows mixed in (rows of
        a node's x, y, z combined), and the geometric terms they cannot carry (sparse)."""
        i, N, mu = self.nodes, self.N, self.mu
        g, active = terms.grad, terms.active
        nu = 1.0 + g[0] * g[0] + g[1] * g[1]
        # row k of a contact node = Σ_j M[k, j] (row j of R⁰), per position dof
        M = np.zeros((3, 3, N))
        M[0, 0] = M[1, 1] = M[2, 2] = 1.0
        M[0, 2, i], M[1, 2, i] = g[0], g[1]
        if mu > 0:
            n, _, _, _, tau = self._friction(terms)
            for k in range(2):
                M[k][:, i] += mu * tau[k] / np.sqrt(nu) * n
        M[2][:, i] = np.where(active, 0.0, np.array([-g[0], -g[1], np.ones_like(nu)]) / nu)
        nb = element_dofs.shape[0]
        blocks = [Ke[k * nb : (k + 1) * nb] for k in range(3)]
        mixed = Ke.copy()
        for k in range(3):
            mixed[k * nb : (k + 1) * nb] = sum(
                M[k, j][element_dofs][:, None, :] * blocks[j] for j in range(3)
            )
        return mixed, self._geometric(terms, size)

    def _geometric(self, terms: ContactTerms3D, size):
        """The rows' derivatives through the geometry, ``R⁰`` held: through ``∇b(x_i, y_i)``
        (chain rule with ``∇∇b``), ``ŝ`` through the neighbours' positions, and the active rows
        ``c (δz − ∇b·δr_h)``."""
        i, N, mu, c = self.nodes, self.N, self.mu, self.stiffness
        g, Hs, R, lam, active = terms.grad, terms.hess, terms.R, terms.lam, terms.active
        nu = 1.0 + g[0] * g[0] + g[1] * g[1]
        # ∂F/∂g_j (3 rows, 2 columns, per node) with R⁰ held
        dF_dg = np.zeros((3, 2, i.size))
        dF_dg[0, 0], dF_dg[1, 1] = R[2], R[2]  # ∂(t_k·R)/∂g_k
        dF_dg[2] = np.where(active, 0.0, -R[:2] / nu - lam * 2.0 * g / nu)  # ∂λ/∂g_j
        rows, cols, vals = [], [], []
        if mu > 0:
            dF_dg[:2] += self._friction_by_grad(terms)
            for k in range(2):  # ŝ through the chord: ∂F_k/∂c, c = r_next − r_prev
                dc = self._friction_by_chord(terms, k)
                for j in range(3):
                    rows += [k * N + i, k * N + i]
                    cols += [j * N + self.next, j * N + self.prev]
                    vals += [dc[j], -dc[j]]
        dF_dxy = np.einsum("kjn,jmn->kmn", dF_dg, Hs)  # through g(x_i, y_i)
        for k in range(3):
            for m in range(2):
                rows.append(k * N + i)
                cols.append(m * N + i)
                vals.append(dF_dxy[k, m])
        # the active complementarity rows c (z − b): ∂/∂x = −c b_x, ∂/∂y = −c b_y, ∂/∂z = c
        for m, v in enumerate((-c * g[0], -c * g[1], c)):
            rows.append(2 * N + i)
            cols.append(m * N + i)
            vals.append(np.where(active, v, 0.0))
        return sp.coo_matrix(
            (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(size, size)
        )

    def _friction_by_grad(self, terms: ContactTerms3D):
        """``∂/∂g_j`` of the friction part ``μ A τ_k/σ`` of the tangential rows (2, 2, n):
        ``A = n·R⁰``, ``σ = |n|``, ``τ_k = t_k·ŝ``, with ``∂n/∂g_j = −e_j``, ``∂ν/∂g_j = 2 g_j``,
        ``∂t_k/∂g_j = δ_kj e_z`` and ``∂p/∂g_j = c_j n/ν + (c·n) e_j/ν + 2 g_j (c·n) n/ν²``."""
        n, nu, s_hat, size, tau = self._friction(terms)
        g, R, c = terms.grad, terms.R, terms.chord
        A, sigma = terms.lam * nu, np.sqrt(nu)
        cn = np.sum(c * n, axis=0)
        out = np.zeros((2, 2, g.shape[1]))
        for j in range(2):
            e_j = np.zeros_like(n)
            e_j[j] = 1.0
            dp = c[j] * n / nu + cn * e_j / nu + 2.0 * g[j] * cn * n / nu**2
            ds = (dp - np.sum(s_hat * dp, axis=0) * s_hat) / np.where(size > 0, size, 1.0)
            for k in range(2):
                t_k = np.zeros_like(n)
                t_k[k], t_k[2] = 1.0, g[k]
                dtau = (s_hat[2] if j == k else 0.0) + np.sum(t_k * ds, axis=0)
                out[k, j] = self.mu * (
                    -R[j] * tau[k] / sigma + A * dtau / sigma - A * tau[k] * g[j] / sigma**3
                )
        return out

    def _friction_by_chord(self, terms: ContactTerms3D, k: int):
        """``∂F_k/∂c`` (3, n): ``μ (A/σ) t_kᵀ (I − ŝŝᵀ) P_n / |P c|``."""
        n, nu, s_hat, size, tau = self._friction(terms)
        g = terms.grad
        A, sigma = terms.lam * nu, np.sqrt(nu)
        t_k = np.zeros_like(n)
        t_k[k], t_k[2] = 1.0, g[k]
        q = t_k - tau[k] * s_hat  # (I − ŝŝᵀ) t_k
        q = q - np.sum(q * n, axis=0) / nu * n  # P_n (symmetric)
        return self.mu * A / sigma * q / np.where(size > 0, size, 1.0)


def anchor_split_3d(S, grad, chord, mu):
    """The anchor's reaction on the line ``S`` (3,) (N) with the seabed under it taking its push:
    ``λ_A = max(n·S/|n|², 0)``, friction ``μ N_A`` against ``ŝ`` (the chord from the anchor to
    its neighbour projected on the seabed); returns ``(S − λ_A (n − μ|n| ŝ), λ_A (n − μ|n| ŝ))``:
    what the anchor and the seabed under it carry."""
    n = np.array([-grad[0], -grad[1], 1.0])
    nu = float(n @ n)
    lam = max(float(n @ S) / nu, 0.0)
    s_hat = sliding_direction(np.asarray(chord, dtype=float)[:, None], n[:, None])[0][:, 0]
    seabed = lam * (n - mu * np.sqrt(nu) * s_hat)
    return S - seabed, seabed
