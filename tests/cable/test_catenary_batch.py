"""Vectorised ``catenary(length=...)`` and ``catenary(H=...)`` solved and checked pass by pass
(`skcable.cable._catenary_batch`): against a 40-digit mpmath solution of the closed form, against
the scalar path, against the general path's refusals; the start against mpmath's root; the
peak memory against the results' own."""

import math
import tracemalloc

import mpmath
import numpy as np
import pytest

from skcable import ConvergenceError, InputError, cable
from skcable.cable import _catenary_batch
from skcable.cable._hanging import start

NAMES = ("H", "V_A", "V_B", "T_A", "T_B", "length")


def _mp_of_length(span, dh, w, length):
    """H, V_A, V_B, T_A, T_B and length in 40 digits: sinh(z)/z = sqrt(S² - dh²)/span solved by
    mpmath.findroot (in logarithms), then the closed form (Irvine, Cable Structures, 1981, §2.1)."""
    with mpmath.workdps(40):
        span, dh, w, S = (mpmath.mpf(float(v)) for v in (span, dh, w, length))
        r = mpmath.sqrt(S * S - dh * dh) / span
        z0 = mpmath.sqrt(6 * (r - 1)) if r < 2 else mpmath.log(2 * r * mpmath.log(2 * r))
        z = mpmath.findroot(lambda z: mpmath.log(mpmath.sinh(z) / z / r), z0, tol=mpmath.mpf(10) ** -35)
        a = span / (2 * z)
        m = mpmath.asinh(dh / span * z / mpmath.sinh(z))
        H = w * a
        values = (
            H,
            H * mpmath.sinh(z - m),
            H * mpmath.sinh(z + m),
            H * mpmath.cosh(m - z),
            H * mpmath.cosh(m + z),
            2 * a * mpmath.sinh(z) * mpmath.cosh(m),
        )
        return [float(v) for v in values]


def _scenes(n, seed):
    """Spans 1 m to 2 km, |dh| up to 3 spans, lengths 1e-9 to 20 chords over the chord (taut,
    slack, beyond twice the chord)."""
    rng = np.random.default_rng(seed)
    spans = 10.0 ** rng.uniform(0.0, 3.3, n)
    dh = spans * rng.uniform(-3.0, 3.0, n)
    over = 10.0 ** rng.uniform(-9.0, 1.3, n)
    return spans, dh, np.hypot(spans, dh) * (1.0 + over), rng.uniform(1.0, 300.0, n)


def _assert_matches_mpmath(c, spans, dh, w, lengths):
    """Each result within 2e-13 of the 40-digit one, or within the data's own conditioning: an
    ulp of the length, the span or dh moves S² - dh² - span² by (S² + dh² + span²)·eps, and z
    (so H) by half that relative to it."""
    for i in range(spans.size):
        ref = _mp_of_length(spans[i], dh[i], w[i], lengths[i])
        scale = max(abs(v) for v in ref[:5])
        with mpmath.workdps(40):
            L2, d2, s2 = (mpmath.mpf(float(v)) ** 2 for v in (lengths[i], dh[i], spans[i]))
            cond = float((L2 + d2 + s2) / (L2 - d2 - s2))
        rel = max(2e-13, 4 * np.finfo(float).eps * cond)
        for name, value in zip(NAMES, ref, strict=True):
            got = float(getattr(c, name)[i])
            assert got == pytest.approx(value, rel=rel, abs=rel * scale), (name, i)


def test_length_arrays_match_mpmath_across_taut_and_slack():
    spans, dh, lengths, w = _scenes(120, 3)
    c = cable.catenary(spans, dh, w, length=lengths)
    assert type(c.H) is np.ndarray and c.constraint[0] == "length"
    _assert_matches_mpmath(c, spans, dh, w, lengths)
    assert c.residual() < 1e-13


def test_length_arrays_of_a_float_dh_and_w_match_mpmath_and_the_scalar_path():
    rng = np.random.default_rng(11)
    spans = rng.uniform(100.0, 1000.0, 60)
    lengths = np.hypot(spans, 20.0) * (1.0 + 10.0 ** rng.uniform(-8.0, -0.3, 60))
    c = cable.catenary(spans, -20.0, 20.0, length=lengths)
    _assert_matches_mpmath(c, spans, np.full(60, -20.0), np.full(60, 20.0), lengths)
    for i in range(0, 60, 7):
        one = cable.catenary(float(spans[i]), -20.0, 20.0, length=float(lengths[i]))
        for name in NAMES:
            assert float(getattr(c, name)[i]) == pytest.approx(float(getattr(one, name)), rel=1e-14)


def test_passes_of_any_size_give_the_same_bits(monkeypatch):
    """The passes are an order of the work only: one pass, or passes of 7 elements, give the same
    results to the bit (the same formulas element by element), for ``length=`` and ``H=``."""
    spans, dh, lengths, w = _scenes(100, 5)
    whole = cable.catenary(spans, dh, w, length=lengths)
    given_H = cable.catenary(spans, dh, w, H=whole.H)
    monkeypatch.setattr(_catenary_batch, "CHUNK", 7)
    monkeypatch.setattr(_catenary_batch.of_length, "__defaults__", (7,))
    monkeypatch.setattr(_catenary_batch.of_H, "__defaults__", (7,))
    parts = cable.catenary(spans, dh, w, length=lengths)
    parts_H = cable.catenary(spans, dh, w, H=whole.H)
    for name in (*NAMES, "z", "m", "a"):
        np.testing.assert_array_equal(getattr(parts, name), getattr(whole, name), err_msg=name)
        np.testing.assert_array_equal(getattr(parts_H, name), getattr(given_H, name), err_msg=name)


def test_two_dimensional_arrays_keep_their_shape():
    spans, dh, lengths, w = (v.reshape(4, 5) for v in _scenes(20, 9))
    c = cable.catenary(spans, dh, w, length=lengths)
    assert c.H.shape == c.T_B.shape == c.length.shape == (4, 5)
    flat = cable.catenary(spans.ravel(), dh.ravel(), w.ravel(), length=lengths.ravel())
    np.testing.assert_array_equal(c.V_A.ravel(), flat.V_A)
    assert c.y(spans / 2).shape == (4, 5)
    # shapes that only broadcast take the general path (a 2-D excess, started elementwise)
    lengths = np.hypot(spans[0], 1.0) * np.array([[1.001], [1.3], [2.5]])
    b = cable.catenary(spans[0], np.array([[1.0], [1.0], [1.0]]), 1.0, length=lengths)
    assert b.H.shape == (3, 5)
    for i in range(3):
        one = cable.catenary(spans[0], 1.0, 1.0, length=lengths[i])
        np.testing.assert_allclose(b.H[i], one.H, rtol=1e-14)


@pytest.mark.parametrize(
    ("span", "dh", "w", "length", "argument"),
    [
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([120.0, 150.0]), "length"),  # below the chord
        (np.array([100.0, 200.0]), 0.0, 2.0, np.array([120.0, 200.0]), "length"),  # the chord itself
        (np.array([100.0, math.nan]), -1.0, 2.0, np.array([120.0, 250.0]), "span"),
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([120.0, math.inf]), "length"),
        (np.array([100.0, 200.0]), math.nan, 2.0, np.array([120.0, 250.0]), "dh"),
        (np.array([100.0, 200.0]), -1.0, np.array([2.0, 0.0]), np.array([120.0, 250.0]), "w"),
        (np.array([100.0, 0.01]), -1.0, 2.0, np.array([120.0, 1e306]), "length"),  # z beyond 709
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([120.0, 250.0, 300.0]), "length"),  # shapes
    ],
)
def test_refusals_name_the_argument(span, dh, w, length, argument):
    with pytest.raises(InputError) as info:
        cable.catenary(span, dh, w, length=length)
    assert info.value.argument == argument


def test_data_beyond_the_normal_range_take_the_general_path_and_agree():
    """Spans of 1e-120 m and 1e120 m: outside the fused path's range (where the general path
    scales by a power of two), solved there, equal to the same scene scaled to metres."""
    spans, lengths = np.array([1e-120, 1e120]), np.array([1.5e-120, 1.5e120])
    c = cable.catenary(spans, 0.0, 1.0, length=lengths)
    unit = cable.catenary(1.0, 0.0, 1.0, length=1.5)
    np.testing.assert_allclose(c.z, unit.z, rtol=1e-15)


def test_the_start_is_within_its_bound_and_one_step_settles():
    """The start against mpmath's root of sinh(z)/z = 1 + rho on (0, 1): the Padé approximant
    (arrays; floats from rho = 0.01) within 2.5e-8, the inverted series' first terms (floats
    below 0.01) within 4e-8; Halley's method stops after one step there."""
    rhos = np.geomspace(1e-12, 0.999999, 400)

    def root(r):
        r = mpmath.mpf(float(r))
        return float(mpmath.findroot(lambda z: mpmath.sinh(z) / z - 1 - r, mpmath.sqrt(6 * r)))

    with mpmath.workdps(30):
        roots = np.array([root(r) for r in rhos])
    z = _catenary_batch.start(rhos)
    assert np.max(np.abs(z / roots - 1)) < 2.6e-8
    starts = np.array([start(float(r)) for r in rhos])
    padé = rhos >= 0.01
    np.testing.assert_allclose(starts[padé], z[padé], rtol=4e-16)
    assert np.max(np.abs(starts[~padé] / roots[~padé] - 1)) < 4e-8
    history = _catenary_batch.iterate(z, rhos)
    assert len(history) == 1
    # an ulp or two below z = 1 (the series of sinh(z)/z - 1); above, sinh(z)/z - 1 itself
    # loses up to 6 eps (`skcable.cable._special`)
    small = roots < 1.0
    np.testing.assert_allclose(z[small], roots[small], rtol=3e-16)
    np.testing.assert_allclose(z[~small], roots[~small], rtol=1.5e-15)


def test_a_solve_that_does_not_settle_raises_with_its_history():
    z = np.array([0.5, math.nan])
    with pytest.raises(ConvergenceError) as info:
        _catenary_batch.iterate(z, np.array([0.04, 0.04]))
    assert len(info.value.history) == 100


def test_peak_memory_is_the_results_own_plus_one_block():
    """The results are ten rows of the spans' size (z, a, sinh z, m, H, length, V and T of
    both ends); the passes add one block of scratch of `CHUNK` elements and the excess of a
    pass: the call's peak traced memory stays within the results' plus 2 MiB."""
    n = 200_000
    rng = np.random.default_rng(2)
    spans = rng.uniform(100.0, 1000.0, n)
    lengths = np.hypot(spans, 20.0) * (1.0 + rng.uniform(1e-6, 0.5, n))
    cable.catenary(spans, -20.0, 20.0, length=lengths)  # the scratch pool filled
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        c = cable.catenary(spans, -20.0, 20.0, length=lengths)
        peak = tracemalloc.get_traced_memory()[1] - base
    finally:
        tracemalloc.stop()
    assert c.H.size == n
    assert peak <= 10 * 8 * n + 2 * 2**20


def test_very_slack_and_very_taut_roots_match_mpmath():
    """Far from the usual range: z up to about 210 (lengths up to 1e90 spans, through the
    vectorised path) and z below 1e-150, where z² underflows (`_catenary_batch.iterate` on the
    excess itself)."""
    lengths = np.geomspace(3.0, 1e90, 25)
    spans = np.ones(25)
    c = cable.catenary(spans, 0.5, 1.0, length=lengths)
    _assert_matches_mpmath(c, spans, np.full(25, 0.5), np.ones(25), lengths)
    rho = np.array([1e-310, 1e-305, 0.3, 1e200])
    z = _catenary_batch.start(rho)
    _catenary_batch.iterate(z, rho)
    with mpmath.workdps(400):  # sinh(z)/z = 1 + 1e-310 needs 340 digits to be told from one
        for zi, r in zip(z, rho, strict=True):  # in y = z/sqrt(6 rho), of order one
            scale = mpmath.sqrt(6 * mpmath.mpf(float(r)))
            y = mpmath.findroot(lambda y, r=r, s=scale: mpmath.log(mpmath.sinh(y * s) / (y * s) / (1 + r)), 1)
            assert zi == pytest.approx(float(y * scale), rel=1e-15)
