r"""The lowest modes of a small banded symmetric pencil :math:`K\phi = \lambda M\phi`.

The vibration problems of the package (`skcable.conductors.natural_frequencies`,
`skcable.strand.beam_frequencies`) assemble a stiffness :math:`K` and a consistent mass
:math:`M`, both symmetric positive definite and banded in the order of the nodes
(half-bandwidth 2 or 3), the in-plane cable adding one rank-one term :math:`c\,bb^T`,
:math:`c \ge 0`. Their few lowest modes are the largest eigenvalues :math:`1/\lambda` of
the standard symmetric operator :math:`R K^{-1} R^T` (:math:`M = R^T R`, banded Cholesky),
found by the implicitly restarted Lanczos method (ARPACK, through
`scipy.sparse.linalg.eigsh`), with :math:`(K + c\,bb^T)^{-1}` applied by Sherman and
Morrison's formula: the spectral transformation of T. Ericsson and A. Ruhe, "The spectral
transformation Lanczos method for the numerical solution of large sparse generalized
symmetric eigenvalue problems", Math. Comp. 35, 1980. Each step costs a few banded
triangular solves, :math:`O(n)`, where the dense `scipy.linalg.eigh` costs :math:`O(n^3)`.

Every answer is checked by means that do not share its round-off:

* the residual :math:`\|K\phi - \lambda M\phi\|_\infty` of each pair, from the band
  matrices (not their factors), against
  :math:`16\,n\varepsilon(\|K\|_\infty + \lambda\|M\|_\infty)\|\phi\|_\infty`, the backward
  error of a stable eigensolver;
* the mass orthonormality :math:`\Phi^T M \Phi = I`, to :math:`16\,n\varepsilon\,\max |\Phi|^T|M||\Phi|`;
* the count of eigenvalues below a shift :math:`\sigma` between the last wanted eigenvalue
  and the next: by Sylvester's law of inertia, the number of negative eigenvalues of
  :math:`K - \sigma M` (LAPACK ``dsbevx`` on the band; the rank-one term by the inertia of
  the bordered matrix), the "Sturm sequence check" of K.J. Bathe, "Finite Element
  Procedures", Prentice Hall, 1996, §11.4.3. Lanczos from one start vector can miss one
  of two (nearly) equal eigenvalues; the count sees it.

A pencil that Lanczos does not solve to these checks, or one too small for it, is solved by
the dense `scipy.linalg.eigh` (bisection, which counts by construction). Its answer passes
the same residual and orthonormality checks, or `ConvergenceError` is raised.

All of it runs on one BLAS thread (threadpoolctl): on vectors and matrices of a few hundred
entries, more threads only add their start-up and their contention on a shared machine
(a dense solve of order 287 took 81 ms on the default two threads against 16.5 ms on one).
"""

from __future__ import annotations

import functools

import numpy as np
import scipy.sparse as sp
from scipy.linalg import eigh
from scipy.linalg.blas import dtbmv
from scipy.linalg.lapack import dgbcon, dgbtrf, dgbtrs, dpbtrf, dpbtrs, dsbevx, dtbtrs
from scipy.sparse.linalg import ArpackError, ArpackNoConvergence, LinearOperator, eigsh

from skcable.errors import ConvergenceError

__all__ = ["BandPattern", "dense", "farthest_from_one", "first_lobe_positive", "lowest_modes", "upper_band"]

_EPS = float(np.finfo(float).eps)

#: below this order (or with fewer than 4 DOFs a wanted mode) the dense solver is the faster
_DENSE_BELOW = 64


def upper_band(A) -> np.ndarray:
    """LAPACK's upper band storage of the symmetric matrix ``A`` (sparse or dense).

    ``ab[p + i - j, j] = A[i, j]`` for ``max(0, j - p) <= i <= j``, ``p`` the half-bandwidth
    (the largest ``j - i`` of a stored entry). Only the upper triangle of ``A`` is read.
    """
    coo = sp.coo_matrix(A)
    upper = coo.row <= coo.col
    i, j, v = coo.row[upper], coo.col[upper], coo.data[upper]
    p = int((j - i).max(initial=0))
    ab = np.zeros((p + 1, coo.shape[1]))
    np.add.at(ab, (p + i - j, j), v)
    return ab


class BandPattern:
    """Where each entry of an assembled matrix goes in the upper band storage of its block
    on the DOFs ``order`` (in that order): assembly straight into the band.

    Parameters
    ----------
    rows, cols : (nnz,) int arrays
        The entries' DOFs (`skfem`'s ``coo_data(...).indices``; repeated entries are summed).
    order : (n,) int array
        The DOFs kept, in the order of the band (the others are dropped).
    size : int
        The number of DOFs.
    """

    def __init__(self, rows, cols, order, size):
        position = np.full(size, -1)
        position[order] = np.arange(len(order))
        i, j = position[rows], position[cols]
        self.keep = (i >= 0) & (j >= 0) & (i <= j)
        self.p = int((j - i)[self.keep].max(initial=0))
        self.n = len(order)
        self.flat = ((self.p + i - j) * self.n + j)[self.keep]

    def band(self, data) -> np.ndarray:
        """The ``(p + 1, n)`` upper band of the matrix whose entries are ``data``."""
        summed = np.bincount(self.flat, weights=data[self.keep], minlength=(self.p + 1) * self.n)
        return summed.reshape(self.p + 1, self.n)


def lowest_modes(K, M, n_modes, *, rank_one=None, what="the eigenproblem"):
    r"""The ``n_modes`` smallest eigenvalues and their M-orthonormal vectors.

    Parameters
    ----------
    K, M : (p + 1, n) arrays
        :math:`K` and :math:`M` in upper band storage (`upper_band`), both positive definite.
    n_modes : int
        Number of modes, ``1 <= n_modes < n``.
    rank_one : (float, (n,) array), optional
        ``(c, b)``: the pencil is :math:`(K + c\,bb^T, M)`, ``c >= 0`` finite.
    what : str
        Named in the error message.

    Returns
    -------
    lam : (n_modes,) array
        Eigenvalues, ascending, > 0.
    phi : (n, n_modes) array
        Eigenvectors, :math:`\Phi^T M \Phi = I`.

    Raises
    ------
    ConvergenceError
        Neither solver gave pairs that pass the checks of the module docstring.
    """
    c, b = (0.0, None) if rank_one is None else (float(rank_one[0]), np.asarray(rank_one[1], dtype=float))
    if b is not None and c == 0.0:
        b = None
    with _threads().limit(limits=1, user_api="blas"):
        return _solve(K, M, n_modes, c, b, what)


def _solve(K, M, n_modes, c, b, what):
    n = K.shape[1]
    if n >= _DENSE_BELOW and 4 * (n_modes + 1) <= n:
        found = _lanczos(K, M, n_modes + 1, c, b)
        if found is not None:
            lam, phi = found
            sigma = 0.5 * (lam[-2] + lam[-1])  # between the last wanted mode and the next
            if _count_is(K, M, sigma, c, b, n_modes) and _check(K, M, c, b, lam, phi):
                return lam[:n_modes], phi[:, :n_modes]
    try:
        lam, phi = _dense_modes(K, M, n_modes, c, b)
    except (np.linalg.LinAlgError, ValueError) as exc:  # M not positive definite, or not finite
        raise ConvergenceError(f"{what}: the dense eigensolver failed ({exc})") from exc
    if not _check(K, M, c, b, lam, phi):
        raise ConvergenceError(f"{what}: the eigenpairs failed their residual or orthonormality check")
    return lam, phi


def _lanczos(K, M, k, c, b):
    """The ``k`` lowest pairs by shift-invert Lanczos, or None where it cannot say."""
    U, info_k = dpbtrf(K)
    R, info_m = dpbtrf(M)
    if info_k or info_m:
        return None
    q = M.shape[0] - 1
    if b is None:

        def inverse(v):
            return dpbtrs(U, v)[0]
    else:
        z = dpbtrs(U, b)[0]
        denominator = 1.0 / c + b @ z  # > 0: K positive definite, c > 0

        def inverse(v):
            y = dpbtrs(U, v)[0]
            return y - z * ((b @ y) / denominator)

    def op(psi):  # R K^-1 R^T psi
        return dtbmv(q, R, inverse(dtbmv(q, R, psi, trans=1)))

    n = K.shape[1]
    try:
        mu, psi = eigsh(_Operator(op, n), k=k, which="LA", v0=_start(n), tol=0)
    except (ArpackNoConvergence, ArpackError):
        return None
    if not (np.all(np.isfinite(mu)) and np.all(mu > 0)):
        return None
    order = np.argsort(-mu)
    phi, info = dtbtrs(R, psi[:, order])
    if info:
        return None
    return 1.0 / mu[order], phi


class _Operator(LinearOperator):
    """A symmetric operator on vectors of ``n`` floats, ``matvec`` without the generic
    checks of `LinearOperator` (ARPACK calls it with contiguous vectors of that length)."""

    def __init__(self, function, n):
        super().__init__(np.dtype(float), (n, n))
        self.function = function

    def _matvec(self, x):
        return self.function(np.ravel(x))

    def matvec(self, x):
        return self.function(x)


@functools.lru_cache(maxsize=16)
def _start(n):
    """Lanczos' start vector: random, so that every mode is in it; seeded, so that a run
    repeats the last."""
    start = np.random.default_rng(0).standard_normal(n)
    start.flags.writeable = False
    return start


def _band_matmat(ab, X):
    """``A @ X`` for ``A`` in upper band storage."""
    p = ab.shape[0] - 1
    Y = ab[p][:, None] * X
    for d in range(1, p + 1):
        a = ab[p - d, d:][:, None]
        Y[:-d] += a * X[d:]
        Y[d:] += a * X[:-d]
    return Y


def _norm(ab) -> float:
    """Largest absolute row sum (the infinity norm, a bound on the spectral radius)."""
    p = ab.shape[0] - 1
    magnitude = np.abs(ab)
    rows = magnitude[p].copy()
    for d in range(1, p + 1):
        rows[:-d] += magnitude[p - d, d:]
        rows[d:] += magnitude[p - d, d:]
    return float(rows.max())


def _minus(K, M, sigma):
    """``K - sigma M`` in the band storage of the wider of the two."""
    p = max(K.shape[0], M.shape[0])
    A = np.zeros((p, K.shape[1]))
    A[p - K.shape[0] :] += K
    A[p - M.shape[0] :] -= sigma * M
    return A


def _count_is(K, M, sigma, c, b, k) -> bool:
    """Whether exactly ``k`` eigenvalues of the pencil lie below ``sigma``, beyond round-off.

    Sylvester: as ``M`` is positive definite, that count is the number of negative eigenvalues
    of ``A = K - sigma M`` (+ ``c bb^T``). LAPACK ``dsbevx`` gives the ``k``-th to ``k+2``-th
    eigenvalues of ``A`` (bisection on its tridiagonal form, backward stable); one of them
    within ``64 n eps ||A||`` of 0 leaves the count to round-off, and the answer is no. With
    the bordered matrix ``[[A, b], [b^T, -1/c]]``, whose inertia is that of ``A`` and of
    ``-(1/c + b^T A^-1 b)``, and also that of ``-1/c`` and of ``A + c bb^T``, the rank-one term
    removes one negative eigenvalue where ``1/c + b^T A^-1 b < 0``; that sign counts where it
    exceeds its error bound (LU of the band and ``dgbcon``'s condition estimate).
    """
    A = _minus(K, M, sigma)
    n = A.shape[1]
    norm = _norm(A)
    resolution = 64 * n * _EPS * norm  # of an eigenvalue of A from dsbevx
    low, top = max(k, 1), min(n, k + 2)
    w, _, m, _, info = dsbevx(
        A, 0.0, 0.0, low, top, compute_v=0, range=2, abstol=resolution / 4, overwrite_ab=0
    )
    w = w[:m]
    if info or m != top - low + 1 or np.any(np.abs(w) <= resolution):
        return False
    negative = low - 1 + int(np.count_nonzero(w < 0))  # w[0] is the low-th: low - 1 below it
    if b is None:
        return negative == k
    if negative not in (k, k + 1):
        return False
    return negative - _rank_one_drop(A, c, b, norm) == k


def _rank_one_drop(A, c, b, norm) -> int:
    """1 where ``1/c + b^T A^-1 b < 0`` (the rank-one term removes a negative eigenvalue), 0
    where it is > 0, 2 (no count fits) where round-off could decide its sign."""
    n, p = A.shape[1], A.shape[0] - 1
    general = np.zeros((3 * p + 1, n))  # dgbtrf's storage: p rows for the fill-in, then the band
    general[p : 2 * p + 1] = A
    for d in range(1, p + 1):
        general[2 * p + d, :-d] = A[p - d, d:]  # the lower triangle, mirrored
    lu, pivots, info = dgbtrf(general, p, p)
    if info:
        return 2
    z, info = dgbtrs(lu, p, p, b, pivots)
    rcond, info_c = dgbcon(p, p, lu, pivots, norm, norm="I")
    s = 1.0 / c + b @ z
    if info or info_c or not (np.isfinite(s) and rcond > 0):
        return 2
    if abs(s) <= 16 * n * _EPS / rcond * (1.0 / c + np.abs(b) @ np.abs(z)):
        return 2
    return int(s < 0)


def _check(K, M, c, b, lam, phi) -> bool:
    """Residual and mass orthonormality of the pairs, from the band matrices."""
    if not (np.all(np.isfinite(lam)) and np.all(lam > 0) and np.all(np.isfinite(phi))):
        return False
    n = K.shape[1]
    KX = _band_matmat(K, phi)
    MX = _band_matmat(M, phi)
    norm_K = _norm(K)
    if b is not None:
        KX += (c * b)[:, None] * (b @ phi)
        norm_K += c * float(np.abs(b).sum() * np.abs(b).max())
    residual = np.abs(KX - MX * lam).max(axis=0)  # infinity norms: no squares to overflow
    size = 16 * n * _EPS * (norm_K + lam * _norm(M)) * np.abs(phi).max(axis=0)
    if not np.all(residual <= size):
        return False
    gram = float(np.abs(phi.T @ MX - np.eye(phi.shape[1])).max())
    if gram <= 16 * n * _EPS:  # |Φ|ᵀ|M||Φ| >= |ΦᵀMΦ| = 1: within the bound below
        return True
    scale = np.abs(phi).T @ _band_matmat(np.abs(M), np.abs(phi))
    return gram <= 16 * n * _EPS * float(scale.max())


def dense(ab) -> np.ndarray:
    """The symmetric matrix whose upper band storage is ``ab``."""
    p, n = ab.shape[0] - 1, ab.shape[1]
    A = np.zeros((n, n))
    for d in range(p + 1):
        i = np.arange(n - d)
        A[i, i + d] = ab[p - d, d:]
        A[i + d, i] = ab[p - d, d:]
    return A


@functools.lru_cache(maxsize=1)
def _threads():
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


def _dense_modes(K, M, k, c, b):
    """The ``k`` lowest pairs by the dense `scipy.linalg.eigh`."""
    Kd, Md = dense(K), dense(M)
    if b is not None:
        Kd += c * np.outer(b, b)
    return eigh(Kd, Md, subset_by_index=[0, k - 1])


def farthest_from_one(**values) -> str:
    """The name of the value farthest from 1 in magnitude (``|log|v||`` largest): the one to
    name where a product of several arguments leaves the range of a float."""
    return max(values, key=lambda name: abs(np.log(abs(float(values[name])))))


def first_lobe_positive(shapes: np.ndarray) -> np.ndarray:
    """Each row of ``shapes`` signed so that its first entry of at least half the row's largest
    magnitude is positive (a mode shape's first lobe from the first end points up)."""
    magnitude = np.abs(shapes)
    first = np.argmax(magnitude >= 0.5 * magnitude.max(axis=1, keepdims=True), axis=1)
    sign = np.sign(shapes[np.arange(shapes.shape[0]), first])
    return shapes * np.where(sign == 0, 1.0, sign)[:, None]
