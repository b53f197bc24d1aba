"""skcable._eigen, the lowest modes of banded pencils: against the dense scipy eigh (bisection
over the whole spectrum) and a dense count of negative eigenvalues, on pencils with exactly
double eigenvalues, where Lanczos from one start vector can miss a copy."""

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse as sp

from skcable import _eigen
from skcable.errors import ConvergenceError


def _string(n):
    """P1 string on [0, 1] with fixed ends: K = tridiag(-1, 2, -1)/h, M = h tridiag(1, 4, 1)/6."""
    h = 1.0 / (n + 1)
    one = np.ones(n - 1)
    K = sp.diags([-one, 2 * np.ones(n), -one], [-1, 0, 1]) / h
    M = sp.diags([one, 4 * np.ones(n), one], [-1, 0, 1]) * h / 6
    return K, M


def _double(n):
    """Two uncoupled copies of the string, DOFs interleaved: every eigenvalue exactly double."""
    K, M = _string(n)
    return sp.kron(K, sp.eye(2)).tocsr(), sp.kron(M, sp.eye(2)).tocsr()


def test_band_storage_round_trip_and_assembly_pattern():
    K, _ = _double(40)
    band = _eigen.upper_band(K)
    np.testing.assert_array_equal(_eigen.dense(band), K.toarray())
    coo = K.tocoo()
    order = np.arange(80)[::-1]  # reversed: the band of the reversed matrix
    pattern = _eigen.BandPattern(coo.row, coo.col, order, 80)
    np.testing.assert_array_equal(_eigen.dense(pattern.band(coo.data)), K.toarray()[np.ix_(order, order)])


def test_double_eigenvalues_come_in_pairs():
    K, M = _double(150)
    lam, phi = _eigen.lowest_modes(_eigen.upper_band(K), _eigen.upper_band(M), 6)
    dense = scipy.linalg.eigh(K.toarray(), M.toarray(), subset_by_index=[0, 5], eigvals_only=True)
    np.testing.assert_allclose(lam, dense, rtol=1e-11)
    np.testing.assert_allclose(lam[::2], lam[1::2], rtol=1e-11)
    np.testing.assert_allclose(phi.T @ M @ phi, np.eye(6), atol=1e-12)


def test_a_copy_missed_by_lanczos_is_seen_by_the_count(monkeypatch):
    # Lanczos made to return one copy of each pair (what it can do in exact arithmetic): the
    # Sturm count at the shift between its 6th and 7th values finds 12 eigenvalues below, not 6,
    # and the dense solver answers instead
    K, M = _double(150)
    Kb, Mb = _eigen.upper_band(K), _eigen.upper_band(M)
    whole = _eigen._lanczos(Kb, Mb, 14, 0.0, None)
    monkeypatch.setattr(_eigen, "_lanczos", lambda *args: (whole[0][::2], whole[1][:, ::2]))
    lam, _ = _eigen.lowest_modes(Kb, Mb, 6)
    dense = scipy.linalg.eigh(K.toarray(), M.toarray(), subset_by_index=[0, 5], eigvals_only=True)
    np.testing.assert_allclose(lam, dense, rtol=1e-11)


def test_count_with_the_rank_one_term_is_the_dense_inertia():
    K, M = _string(200)
    rng = np.random.default_rng(3)
    b = rng.standard_normal(200) * np.sin(np.linspace(0, 3, 200))
    dense = scipy.linalg.eigh(K.toarray() + 50.0 * np.outer(b, b), M.toarray(), eigvals_only=True)
    plain = scipy.linalg.eigh(K.toarray(), M.toarray(), eigvals_only=True)
    Kb, Mb = _eigen.upper_band(K), _eigen.upper_band(M)
    for j in (0, 3, 9, 30):
        sigma = 0.5 * (dense[j] + dense[j + 1])
        assert [_eigen._count_is(Kb, Mb, sigma, 50.0, b, k) for k in (j, j + 1, j + 2)] == [
            False,
            True,
            False,
        ]
        below = int(np.count_nonzero(plain < sigma))
        assert [_eigen._count_is(Kb, Mb, sigma, 0.0, None, k) for k in (below - 1, below, below + 1)] == [
            False,
            True,
            False,
        ]


def test_the_checks_refuse_a_wrong_pair():
    K, M = _string(100)
    Kb, Mb = _eigen.upper_band(K), _eigen.upper_band(M)
    lam, phi = _eigen.lowest_modes(Kb, Mb, 3)
    assert _eigen._check(Kb, Mb, 0.0, None, lam, phi)
    assert not _eigen._check(Kb, Mb, 0.0, None, lam * (1 + 1e-9), phi)  # off by 1e-9: beyond round-off
    assert not _eigen._check(Kb, Mb, 0.0, None, lam, 1.001 * phi)  # not mass-normalised


def test_an_indefinite_mass_raises_convergence_error():
    K, M = _string(100)
    with pytest.raises(ConvergenceError):
        _eigen.lowest_modes(_eigen.upper_band(K), _eigen.upper_band(-M), 3)
