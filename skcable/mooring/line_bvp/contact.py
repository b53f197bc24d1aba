r"""Unilateral seabed contact with Coulomb friction: the seabed, and the semismooth contact rows.

**Seabed.** The line stays above the seabed, ``g_i = y_i - b(x_i) >= 0``, at every position
node ``i`` (vertices and mid-side nodes of the P2 elements, the ends excepted: they are
supports). ``λ_i >= 0`` is the multiplier of ``g_i``: the seabed pushes with ``λ_i n_i``,
``n_i = (-b'(x_i), 1)`` (normal to the seabed, of length ``sqrt(1 + b'^2)``, so the normal
force is ``N_i = λ_i |n_i|``). With Coulomb friction fully mobilised (Jonkman's model: the line
is being dragged towards the fairlead, so friction pulls it back towards the anchor) the force
is ``-μ N_i`` along the unit tangent ``t_i/|t_i|``, ``t_i = (1, b'(x_i))``, i.e. ``-μ λ_i t_i``.
The contact conditions are exact at the nodes: ``λ_i >= 0, g_i >= 0, λ_i g_i = 0``, solved by a
semismooth (primal–dual active set) Newton method (M. Hintermüller, K. Ito, K. Kunisch, "The
primal-dual active set strategy as a semismooth Newton method", SIAM J. Optim., 2002) on the
system where ``λ_i`` is eliminated: with ``R⁰`` the residual without contact,
``λ_i = n_i·R⁰_i / |n_i|²``, each node's two rows become

.. math::
    \mathbf t_i\cdot\mathbf R^0_i + \mu\,\mathbf n_i\cdot\mathbf R^0_i = 0
    \quad\text{(tangential equilibrium)}, \qquad
    \min(\lambda_i,\ c\,g_i) = 0 \quad\text{(complementarity)},

``c`` any positive constant (here the total load over the length, times the node's element
length over the mean one). Its generalized Jacobian takes ``c ∇g_i`` on the nodes where
``λ_i > c g_i`` (active) and ``∇λ_i`` elsewhere: near the solution Newton's method identifies
the active set in finitely many steps and converges quadratically. The seabed is ``y = b(x)``:
a float (flat) or a callable; its slope ``b'`` is the callable ``seabed_slope`` if given,
central differences of ``b`` otherwise, and ``b''`` (Jacobian only) central differences of
``b'``.

On a slack stretch ``[0, s0]`` near the anchor (`skcable.mooring.line_bvp.slack`) friction is
only partly mobilised: it holds the line's own tangential weight, and the tangential row
becomes ``t_i·(R⁰_i - R_ext,i) = 0`` (no friction on a flat seabed).

**The anchor on the seabed.** With the anchor on the seabed, A is a contact node as well: the
seabed takes its push ``λ_A = max(n_A·R⁰_A/|n_A|², 0)`` (friction included) and the anchor the
rest, so that a line grounded at A has ``V_A = 0`` and ``H_A = H - μ·(normal forces)`` as in
Jonkman's closed form (J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore
floating wind turbine", NREL, 2007).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import scipy.sparse as sp

from skcable._checks import real
from skcable.errors import InputError

__all__ = ["ContactRows", "ContactTerms", "Seabed", "anchor_split", "seabed_of"]


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
    """The `Seabed` of ``seabed=`` (a height or a callable ``b(x)``) and ``seabed_slope=``."""
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
    flat = float(np.asarray(real("seabed", seabed)))
    return Seabed(_Level(flat), None, flat, step)


class _Level:
    """The height ``b(x) = level`` of a flat seabed (m): a callable that pickles."""

    def __init__(self, level: float):
        self.level = level

    def __call__(self, x):
        return np.full_like(x, self.level)

    def __repr__(self):
        return f"flat seabed at {self.level:g} m"


class ContactTerms(NamedTuple):
    """Per contact node at one iterate: seabed slope ``b'`` and curvature ``b''``, gap (m),
    multiplier ``λ`` (N), active flag (``λ > c g``), and ``R⁰``'s x and y rows there (N)."""

    slope: np.ndarray
    curvature: np.ndarray
    gap: np.ndarray
    lam: np.ndarray
    active: np.ndarray
    Rx: np.ndarray
    Ry: np.ndarray


@dataclass(frozen=True)
class ContactRows:
    """The contact rows of the nodes ``nodes`` (position dofs: x at ``nodes``, y at ``N + nodes``).

    Attributes
    ----------
    nodes : ndarray of int
        The contact nodes' dofs in the x field.
    N : int
        Dofs per position field.
    seabed : Seabed
    stiffness : ndarray
        ``c_i`` of the complementarity function per node (N/m).
    mu : ndarray
        Friction coefficient per node: μ where the line slides, 0 on the slack stretch.
    sliding_share : ndarray
        The share of each node's weight beyond the slack stretch (1 where it slides).
    external_y : ndarray
        The external vertical load at each node's y row (N).
    switch : ndarray or None
        ``c_i`` of the active-set test ``λ > c g`` where it differs from ``stiffness`` (the rows
        themselves, ``c g = 0`` or ``λ = 0``, have the same Newton step for any ``c > 0``).
    frozen : ndarray of bool or None
        The active set held fixed (`skcable.mooring.line_bvp.iterate.frozen_steps`): each node's
        row is ``c g = 0`` where True and ``λ = 0`` where False, whatever ``λ`` and ``g`` are.
    """

    nodes: np.ndarray
    N: int
    seabed: Seabed
    stiffness: np.ndarray
    mu: np.ndarray
    sliding_share: np.ndarray
    external_y: np.ndarray
    switch: np.ndarray | None = None
    frozen: np.ndarray | None = None

    def terms(self, z, R0) -> ContactTerms:
        """Per contact node: slope, curvature, gap, multiplier λ, active flag."""
        i, N = self.nodes, self.N
        x, y = z[i], z[N + i]
        bp, bpp = self.seabed.slope(x), self.seabed.curvature(x)
        gap = y - self.seabed(x)
        Rx, Ry = R0[i], R0[N + i]
        norm2 = 1.0 + bp * bp
        lam = (Ry - bp * Rx) / norm2
        if self.frozen is not None:
            return ContactTerms(bp, bpp, gap, lam, self.frozen, Rx, Ry)
        active = lam > (self.stiffness if self.switch is None else self.switch) * gap
        return ContactTerms(bp, bpp, gap, lam, active, Rx, Ry)

    def rows(self, F, terms: ContactTerms) -> None:
        """Put the tangential and complementarity rows into the residual ``F`` (in place)."""
        bp, _, gap, lam, active, Rx, Ry = terms
        mu, stuck = self.mu, 1.0 - self.sliding_share
        i, N = self.nodes, self.N
        # on the slack stretch friction holds the line's own tangential weight (stuck)
        F[i] = (1.0 - mu * bp) * Rx + (bp + mu) * Ry - stuck * bp * self.external_y
        F[N + i] = np.where(active, self.stiffness * gap, lam)

    def mixed(self, Ke, terms: ContactTerms, element_dofs, size):
        """The generalized Jacobian's contact part: the element matrices ``Ke`` with the contact
        rows mixed in, and the terms they cannot carry (sparse, ``size`` square)."""
        mixed = Ke.copy()
        bp, bpp, _, lam, active, Rx, Ry = terms
        mu, i, N = self.mu, self.nodes, self.N
        norm2 = 1.0 + bp * bp
        # row mixing per position dof: x row -> a Kx + b Ky, y row -> c Kx + d Ky
        a, b = np.ones(N), np.zeros(N)
        c, d = np.zeros(N), np.ones(N)
        a[i], b[i] = 1.0 - mu * bp, bp + mu
        c[i] = np.where(active, 0.0, -bp / norm2)
        d[i] = np.where(active, 0.0, 1.0 / norm2)
        ed = element_dofs  # (3, ne): local position dofs 0..2 (x) and 3..5 (y)
        nb = ed.shape[0]
        Kx, Ky = Ke[:nb], Ke[nb : 2 * nb]
        mixed[:nb] = a[ed][:, None, :] * Kx + b[ed][:, None, :] * Ky
        mixed[nb : 2 * nb] = c[ed][:, None, :] * Kx + d[ed][:, None, :] * Ky
        # what the element matrices cannot carry: derivatives of b'(x_i) and the active rows
        stuck_y = (1.0 - self.sliding_share) * self.external_y
        dtx = bpp * (Ry - mu * Rx - stuck_y)  # d(tangential row)/dx_i through b'
        dlx = bpp * (-Rx / norm2 - lam * 2.0 * bp / norm2)  # dλ/dx_i through b'
        k = self.stiffness
        rows = np.concatenate([i, N + i, N + i])
        cols = np.concatenate([i, i, N + i])
        vals = np.concatenate([dtx, np.where(active, -k * bp, dlx), np.where(active, k, 0.0)])
        return mixed, sp.coo_matrix((vals, (rows, cols)), shape=(size, size))

    def forces(self, terms: ContactTerms, order):
        """Per node in ``order``: (slope, gap, λ, active, μ, held), ``held`` the friction (N) that
        holds a slack stretch, its own tangential weight ``t·R_ext / |t|²``."""
        bp, _, gap, lam, active, _, _ = terms
        bp, gap, lam, active = bp[order], gap[order], lam[order], active[order]
        held = (1.0 - self.sliding_share[order]) * bp * self.external_y[order] / (1.0 + bp * bp)
        return bp, gap, lam, active, self.mu[order], held


def anchor_split(H_A, V_A, slope, mu_a):
    """The anchor's reaction ``(H_A, V_A)`` (N) with the seabed under it taking its push,
    friction ``mu_a`` included: ``λ_A = max(n·R⁰_A / |n|², 0)``, ``R⁰_x(A) = -H_A``; returns
    ``(H_A, V_A, λ_A)``."""
    lam_a = max((V_A + slope * H_A) / (1.0 + slope * slope), 0.0)
    return H_A + lam_a * (-slope - mu_a), V_A - lam_a * (1.0 - mu_a * slope), lam_a
