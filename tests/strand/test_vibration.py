"""Bending frequencies of a tensioned strand: FE (Hermite beam + geometric stiffness)
against the pinned closed form, the clamped-clamped Euler-Bernoulli roots, the exact
clamped-clamped frequency determinant (mpmath) and the taut-string limit."""

import mpmath as mp
import numpy as np
import pytest

from skcable import strand
from skcable.errors import InputError
from skcable.strand import beam_frequencies, pinned_beam_frequencies, strand_bending_frequencies


def _clamped_root(EI, N, L, m, guess, dps=40):
    """Root near ``guess`` of the 4x4 determinant of w = A cosh ax + B sinh ax + C cos bx
    + D sin bx with w = w' = 0 at both ends, a² - b² = N/EI, a²b² = m ω²/EI (mpmath)."""
    with mp.workdps(dps):
        EI, N, L, m = map(mp.mpf, (EI, N, L, m))

        def det(f):
            s = mp.sqrt(N**2 + 4 * EI * m * (2 * mp.pi * f) ** 2)
            a, b = mp.sqrt((N + s) / (2 * EI)), mp.sqrt((s - N) / (2 * EI))
            rows = [
                [1, 0, 1, 0],
                [0, a, 0, b],
                [mp.cosh(a * L), mp.sinh(a * L), mp.cos(b * L), mp.sin(b * L)],
                [a * mp.sinh(a * L), a * mp.cosh(a * L), -b * mp.sin(b * L), b * mp.cos(b * L)],
            ]
            return mp.det(mp.matrix(rows)) / (mp.cosh(a * L) * a * b)

        g = mp.mpf(guess)
        return float(mp.findroot(det, (0.97 * g, 1.03 * g), solver="anderson", tol=mp.mpf(10) ** (-dps + 5)))


@pytest.mark.parametrize("N", [0.0, 30.0, 3.0e4])
def test_pinned_fe_equals_closed_form(N):
    fe = beam_frequencies(2.0, N, 1.3, 0.4, ends="pinned", n_modes=4)
    closed = pinned_beam_frequencies(2.0, N, 1.3, 0.4, n_modes=4)
    np.testing.assert_allclose(fe.f, closed, rtol=1e-6)
    np.testing.assert_array_equal(fe.pinned_closed_form, closed)


def test_pinned_closed_form_limits():
    n = np.arange(1, 4)
    # N -> 0: the Euler-Bernoulli beam (n pi / l)^2 sqrt(EI/m)
    beam = (n * np.pi / 2.0) ** 2 * np.sqrt(3.0 / 0.5) / (2 * np.pi)
    np.testing.assert_allclose(pinned_beam_frequencies(3.0, 0.0, 2.0, 0.5, n_modes=3), beam, rtol=1e-15)
    # EI -> 0: the taut string n/(2l) sqrt(N/m)
    string = n / 4.0 * np.sqrt(1e4 / 0.5)
    f = pinned_beam_frequencies(1e-9, 1e4, 2.0, 0.5, n_modes=3)
    np.testing.assert_allclose(f, string, rtol=1e-9)


def test_clamped_beam_roots_without_tension():
    beta_l = np.array([4.730040744862704, 7.853204624095838, 10.99560783800167])  # cos bl cosh bl = 1
    EI, m, L = 2.0, 1.5, 0.8
    fe = beam_frequencies(EI, 0.0, L, m, n_modes=3)
    np.testing.assert_allclose(fe.f, beta_l**2 / L**2 * np.sqrt(EI / m) / (2 * np.pi), rtol=1e-6)


@pytest.mark.parametrize("N", [0.5, 50.0, 5000.0])  # k l = l sqrt(N/EI) from 0.5 to 50
def test_clamped_fe_equals_exact_determinant(N):
    fe = beam_frequencies(2.0, N, 1.0, 1.5, n_modes=3, n_elements=120)
    exact = [_clamped_root(2.0, N, 1.0, 1.5, f) for f in fe.f]
    np.testing.assert_allclose(fe.f, exact, rtol=1e-6)
    assert np.all(fe.f > fe.pinned_closed_form)  # clamping stiffens


def test_clamped_taut_string_limit():
    # EI -> 0 at fixed N (k l = l sqrt(N/EI) = 200): the exact clamped roots, and the FE
    # once its mesh resolves the boundary layer of width 1/k, tend to the string
    # n/(2l) sqrt(N/m) from above, the clamped boundary layer adding about 2/(k l)
    kl = 200.0
    fe = beam_frequencies(1.0, kl**2, 1.0, 1.0, n_modes=3, n_elements=400)
    exact = np.array([_clamped_root(1.0, kl**2, 1.0, 1.0, f, dps=150) for f in fe.f])
    np.testing.assert_allclose(fe.f, exact, rtol=1e-6)
    excess = exact / (np.arange(1, 4) / 2.0 * kl) - 1.0
    assert np.all((excess > 2.0 / kl) & (excess < 2.5 / kl)), excess * kl


def test_modes_are_mass_normalised_and_vanish_at_the_ends():
    fe = beam_frequencies(2.0, 100.0, 1.0, 1.5, n_modes=3)
    assert fe.modes.shape == (3, fe.x.size)
    np.testing.assert_array_equal(fe.modes[:, [0, -1]], 0.0)
    # the first clamped mode is symmetric about midspan, the second antisymmetric, to the accuracy
    # of a computed eigenvector, eps |lambda_max| / gap: on 96 Hermite elements the largest
    # eigenvalue is 4.3e7 times the gap between the first two, so about 1e-16 * 4e7 = 4e-9 (a bound
    # of 1e-9 was broken by 1.9e-9 on another LAPACK build); 1e-7 leaves a margin of 25
    for k, sign in ((0, 1.0), (1, -1.0)):
        peak = np.abs(fe.modes[k]).max()
        np.testing.assert_allclose(fe.modes[k], sign * fe.modes[k, ::-1], atol=1e-7 * peak)


def test_strand_stick_and_slip_and_damage():
    intact = strand.preset("steel-9.5")
    m = 7850.0 * intact.section().area
    N, L = 5e3, 0.5
    ok = strand_bending_frequencies(intact.section(), N, L, m, n_modes=2)
    sec = intact.section()
    np.testing.assert_allclose(ok.f_stick, beam_frequencies(sec.EI_stick[0], N, L, m, n_modes=2).f, rtol=0)
    np.testing.assert_allclose(ok.f_slip, beam_frequencies(sec.EI_slip[0], N, L, m, n_modes=2).f, rtol=0)
    assert np.all(ok.drop > 0) and np.all(ok.drop < 1)
    np.testing.assert_allclose(ok.drop, 1 - ok.f_slip / ok.f_stick, rtol=1e-15)
    damaged = strand_bending_frequencies(intact.damaged(1).section(), N, L, m, axis=1, n_modes=2)
    assert np.all(damaged.f_stick < ok.f_stick) and np.all(damaged.f_slip < ok.f_slip)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(EI=-1.0), "EI"),
        (dict(N=-1.0), "N"),
        (dict(length=0.0), "length"),
        (dict(mass_per_length=float("nan")), "mass_per_length"),
        (dict(ends="free"), "ends"),
        (dict(n_modes=0), "n_modes"),
        (dict(n_elements=3), "n_elements"),
    ],
)
def test_bad_input_is_named(kwargs, name):
    args = dict(EI=1.0, N=1.0, length=1.0, mass_per_length=1.0) | kwargs
    with pytest.raises(InputError) as info:
        beam_frequencies(**args)
    assert info.value.argument == name


def test_strand_bad_section_and_axis():
    with pytest.raises(InputError, match="section"):
        strand_bending_frequencies(1.0, 1.0, 1.0, 1.0)
    with pytest.raises(InputError, match="axis"):
        strand_bending_frequencies(strand.preset("steel-9.5").section(), 1.0, 1.0, 1.0, axis=2)


def test_modes_are_signed_first_lobe_up():
    # pinned: the modes are sin(n pi x / l) exactly, and come signed as they are
    fe = beam_frequencies(2.0, 30.0, 1.3, 0.4, ends="pinned", n_modes=4)
    for n in range(1, 5):
        exact = np.sin(n * np.pi * fe.x / 1.3)
        cos = fe.modes[n - 1] @ exact / (np.linalg.norm(fe.modes[n - 1]) * np.linalg.norm(exact))
        assert cos == pytest.approx(1.0, abs=1e-8)


# --- magnitudes at the edges of the float range (issue 26, D7) ---------------------------
def test_tension_1e308_is_the_taut_string():
    # N = 1e308 once escaped as ValueError; N l^2/EI ~ 2e306: the taut string n/(2l) sqrt(N/m)
    section = strand.preset("steel-9.5").section()
    r = strand_bending_frequencies(section, N=1e308, length=1.0, mass_per_length=0.45)
    string = np.arange(1, 7) / 2.0 * np.sqrt(1e308) / np.sqrt(0.45)  # N/m itself overflows
    for f in (r.f_stick, r.f_slip, r.drop):
        assert np.all(np.isfinite(f))
    # clamping stiffens; on 96 elements the boundary layer (width sqrt(EI/N)) is not resolved
    # and adds 0.25 % (the exact clamped excess, 2 sqrt(EI/N)/l, is 1e-153)
    assert np.all(r.f_stick > string) and np.all(r.f_stick < 1.003 * string)
    pinned = beam_frequencies(float(section.EI_stick[0]), 1e308, 1.0, 0.45, ends="pinned")
    np.testing.assert_allclose(pinned.f, string, rtol=1e-6)


@pytest.mark.parametrize("m", [1e-310, 1e-300, 1e300])
def test_frequencies_scale_as_one_over_root_mass(m):
    # f = sqrt(mu) sqrt(N/m) / (2 pi l) with mu independent of m: a denormal mass included
    section = strand.preset("steel-9.5").section()
    ref = strand_bending_frequencies(section, 1e3, 1.0, 0.45, n_modes=3)
    r = strand_bending_frequencies(section, 1e3, 1.0, m, n_modes=3)
    np.testing.assert_allclose(r.f_stick * np.sqrt(m / 0.45), ref.f_stick, rtol=1e-12)
    np.testing.assert_allclose(r.f_slip * np.sqrt(m / 0.45), ref.f_slip, rtol=1e-12)


@pytest.mark.parametrize("EI", [1e-310, 1e-300, 1e300])
def test_beam_frequencies_scale_as_root_stiffness(EI):
    # N = 0: f = sqrt(mu) sqrt(EI/m) / (2 pi l^2), the clamped roots of cos bl cosh bl = 1
    beta_l = np.array([4.730040744862704, 7.853204624095838, 10.99560783800167])
    fe = beam_frequencies(EI, 0.0, 1.0, 1.0, n_modes=3)
    np.testing.assert_allclose(fe.f, beta_l**2 * np.sqrt(EI) / (2 * np.pi), rtol=1e-6)
    assert np.all(np.isfinite(fe.modes))


def test_pinned_closed_form_at_the_float_limits():
    n = np.arange(1, 4)
    # N/(k^2 EI) = 1e318 / k^2 beyond a float: the string n/(2l) sqrt(N/m)
    np.testing.assert_allclose(
        pinned_beam_frequencies(1e-10, 1e308, 1.0, 1.0, n_modes=3), n / 2 * 1e154, rtol=1e-12
    )
    # k^2 = (n pi / 1e300)^2 underflows: the string again
    f = pinned_beam_frequencies(1.0, 1e4, 1e300, 1.0, n_modes=3)
    np.testing.assert_allclose(f, n / 2e300 * 100.0, rtol=1e-12)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(length=1e-300), "length"),  # frequencies ~ 1e301 / l beyond a float
        (dict(mass_per_length=1e-300, length=1e-150), "mass_per_length"),  # the farther from 1
    ],
)
def test_frequencies_beyond_a_float_are_refused_by_name(kwargs, name):
    args = dict(N=1e3, length=1.0, mass_per_length=0.45) | kwargs
    with pytest.raises(InputError) as info:
        strand_bending_frequencies(strand.preset("steel-9.5").section(), **args)
    assert info.value.argument == name
