"""Oracle of a sagging cable's natural frequencies: Irvine's linear theory by Chebyshev
collocation (spectral, independent of skcable's finite elements).

Irvine ("Cable Structures", MIT Press, 1981, ch. 3): about the inextensible catenary of
horizontal tension ``H`` through A = (0, 0), B = (span, dh), in ``ξ = x/span``,

    out of plane:  -u'' = μ (ds/dx) u,
    in plane:      -v'' - (EA/(H ℓ_e)) (∫ y' v' dξ) (y')' = μ (ds/dx) v,      ℓ_e = ∫ (ds/dx)³ dξ,

with ``v(0) = v(1) = 0`` and ``ω² = μ H g/(w span²)``. The collocation runs at two resolutions;
their difference is the oracle's own error bar.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
from scipy.linalg import eig

__all__ = ["catenary_H", "frequencies"]


def _cheb(N):
    """Chebyshev-Gauss-Lobatto points on [0, 1], the differentiation matrix, Clenshaw-Curtis weights."""
    j = np.arange(N + 1)
    t = np.cos(np.pi * j / N)  # [1 .. -1]
    c = np.where((j == 0) | (j == N), 2.0, 1.0) * (-1.0) ** j
    T = np.tile(t, (N + 1, 1)).T
    dT = T - T.T
    D = np.outer(c, 1.0 / c) / (dT + np.eye(N + 1))
    D -= np.diag(D.sum(axis=1))
    x = (1.0 - t) / 2.0  # ascending in [0, 1]
    D = -2.0 * D  # d/dx = -2 d/dt
    theta = np.pi * j / N
    w = np.zeros(N + 1)
    v = np.ones(N - 1)
    if N % 2 == 0:
        w[0] = w[N] = 1.0 / (N**2 - 1)
        for k in range(1, N // 2):
            v -= 2.0 * np.cos(2 * k * theta[1:-1]) / (4 * k * k - 1)
        v -= np.cos(N * theta[1:-1]) / (N**2 - 1)
    else:
        w[0] = w[N] = 1.0 / N**2
        for k in range(1, (N - 1) // 2 + 1):
            v -= 2.0 * np.cos(2 * k * theta[1:-1]) / (4 * k * k - 1)
    w[1:-1] = 2.0 * v / N
    return x, D, w / 2.0  # weights on [0, 1]


def catenary_H(span, dh, w, sag):
    """``H`` of the inextensible catenary of that ``sag`` (largest vertical chord-cable distance)."""

    def sag_of(H):
        c = H / w
        x0 = span / 2 - c * mpmath.asinh(dh / (2 * c * mpmath.sinh(span / (2 * c))))
        xs = x0 + c * mpmath.asinh(dh / span)
        y = c * (mpmath.cosh((xs - x0) / c) - mpmath.cosh(x0 / c))
        return dh * xs / span - y

    with mpmath.workdps(30):
        lo, hi = mpmath.mpf(w * span) / 1e6, mpmath.mpf(w * span)
        while sag_of(hi) > sag:
            hi *= 4
        while sag_of(lo) < sag:
            lo /= 4
        for _ in range(200):
            mid = mpmath.sqrt(lo * hi)
            lo, hi = (mid, hi) if sag_of(mid) > sag else (lo, mid)
            if hi / lo - 1 < 1e-17:
                break
        return float(mid)


def _profile(span, dh, w, H, x):
    c = H / w
    x0 = span / 2 - c * math.asinh(dh / (2 * c * math.sinh(span / (2 * c))))
    arg = (span * x - x0) / c
    return np.sinh(arg), np.cosh(arg), (span / c) * np.cosh(arg)  # y', ds/dx, dy'/dξ


def _mu(span, dh, w, EA, H, N, n_modes):
    x, D, q = _cheb(N)
    slope, ds, curv = _profile(span, dh, w, H, x)
    D2 = (D @ D)[1:-1, 1:-1]
    B = np.diag(ds[1:-1])
    l_e = float(q @ ds**3)
    beta = EA / (H * l_e)
    coupling = (q * slope) @ D[:, 1:-1]  # ∫ y' v' dξ as a row acting on the interior values
    A_in = -D2 - beta * np.outer(curv[1:-1], coupling)
    out = []
    for A in (A_in, -D2):
        values = eig(A, B, right=False)
        values = np.sort(values[np.abs(values.imag) <= 1e-6 * np.abs(values)].real)
        out.append(values[values > 0][:n_modes])
    return out, l_e


def frequencies(span, dh, w, EA, H, g, n_modes):
    """``(f_in, f_out, error)``: the lowest in-plane and out-of-plane frequencies (Hz) and the
    oracle's relative error bar (the two resolutions' difference)."""
    scale = H * g / (w * span * span)
    (mu_a, nu_a), _ = _mu(span, dh, w, EA, H, 56, n_modes)
    (mu_b, nu_b), _ = _mu(span, dh, w, EA, H, 88, n_modes)
    if len(mu_b) < n_modes or len(nu_b) < n_modes or len(mu_a) < n_modes or len(nu_a) < n_modes:
        raise ValueError("the collocation lost modes")
    error = max(np.max(np.abs(mu_a / mu_b - 1)), np.max(np.abs(nu_a / nu_b - 1)))
    f = [np.sqrt(m * scale) / (2 * np.pi) for m in (mu_b, nu_b)]
    return f[0], f[1], float(error)
