"""Aeolian vibration: the energy balance against a residual written here (CIGRE's fit and Foti &
Martinelli's damping as printed), the clamp amplitude against a clamped tensioned beam's mode on
finite elements, the chain to a Miner life recomputed here, and every refusal named."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from skcable import conductors, strand
from skcable.errors import ConvergenceError, InputError

T = 28e3  # N: ACSR Drake at 20 % RTS
F_BAND = np.linspace(5.0, 60.0, 100)


@pytest.fixture(scope="module")
def drake():
    d = strand.preset("acsr-drake")
    c = conductors.Conductor.from_strand(d)
    law = strand.LayerSlipLaw(d.section(), mu=0.7, tension=T)
    return dict(
        strand=d, mass=c.w / 9.80665, D=c.diameter, EI=float(law.EI_max[0]), k0=float(law.kappa_0[0]), law=law
    )


def cigre_as_printed(y, f, D, Iv=0.0):
    """P_w = f³ D⁴ β F(y/D), F = -99.73 e³ + 101.62 e² + 0.1627 e + 0.2256, β = (1 + (Iv/0.09)²)^-1/2."""
    e = y / D
    return (
        f**3 * D**4 * (-99.73 * e**3 + 101.62 * e**2 + 0.1627 * e + 0.2256) / math.sqrt(1 + (Iv / 0.09) ** 2)
    )


def foti_as_printed(y, f, T, m, EI, k0):
    """Foti & Martinelli (2018), eqs. 23–30."""
    lam = math.sqrt(T / m) / f
    kn = math.asin(min(1.0, lam**2 * k0 / (4 * math.pi**2 * y))) / (2 * math.pi)
    G1 = 1 / 3 - 3 / 8 * math.cos(2 * math.pi * kn) + math.cos(6 * math.pi * kn) / 24
    G2 = math.pi - 4 * math.pi * kn + math.sin(4 * math.pi * kn)
    return (
        G1 * 128 * math.pi**5 * m**3 * EI / k0 * y**3 * f**7 / T**3
        + G2 * 4 * math.pi**3 * m**2 * EI * y**2 * f**5 / T**2
    )


def test_drake_amplitude_is_the_root_of_wind_equals_foti_damping(drake):
    """Issue 35's acceptance: Drake at 28 kN, Foti's damping, CIGRE's wind without turbulence:
    the residual, written here, vanishes to 1e-10 of the wind power at every frequency."""
    m, D, EI, k0 = drake["mass"], drake["D"], drake["EI"], drake["k0"]
    y = conductors.aeolian_amplitude(
        F_BAND, D, m, T, lambda y, f: conductors.foti_damping(y, f, T, m, EI, k0)
    )
    assert y.shape == F_BAND.shape
    for yi, fi in zip(y, F_BAND, strict=True):
        wind = cigre_as_printed(yi, fi, D)
        assert abs(wind - foti_as_printed(yi, fi, T, m, EI, k0)) <= 1e-10 * wind
        # the first root: the wind exceeds the damping at every smaller amplitude
        below = yi * np.geomspace(1e-5, 1 - 1e-9, 200)
        assert all(cigre_as_printed(v, fi, D) > foti_as_printed(v, fi, T, m, EI, k0) for v in below)
        # and the same root by brentq on the printed formulas
        balance = lambda v, fi=fi: cigre_as_printed(v, fi, D) - foti_as_printed(v, fi, T, m, EI, k0)  # noqa: E731
        root = brentq(balance, below[-1], 1.02 * D)
        assert yi == pytest.approx(root, rel=1e-10)


def test_a_scalar_frequency_gives_a_float(drake):
    m, D, EI, k0 = drake["mass"], drake["D"], drake["EI"], drake["k0"]
    damping = lambda y, f: conductors.foti_damping(y, f, T, m, EI, k0)  # noqa: E731
    y = conductors.aeolian_amplitude(30.0, D, m, T, damping)
    assert isinstance(y, float)
    assert y == conductors.aeolian_amplitude(np.array([30.0]), D, m, T, damping)[0]


def test_turbulence_lowers_the_wind_and_the_amplitude(drake):
    m, D, EI, k0 = drake["mass"], drake["D"], drake["EI"], drake["k0"]
    damping = lambda y, f: conductors.foti_damping(y, f, T, m, EI, k0)  # noqa: E731
    calm = conductors.aeolian_amplitude(F_BAND, D, m, T, damping)
    gusty = conductors.aeolian_amplitude(F_BAND, D, m, T, damping, turbulence=0.15)
    assert np.all(gusty < calm)
    for yi, fi in zip(gusty[::17], F_BAND[::17], strict=True):
        wind = cigre_as_printed(yi, fi, D, 0.15)
        assert abs(wind - foti_as_printed(yi, fi, T, m, EI, k0)) <= 1e-10 * wind


def test_wind_models():
    D = 0.028
    assert conductors.wind_power(0.01, 20.0, D) == pytest.approx(cigre_as_printed(0.01, 20.0, D), rel=1e-14)
    assert conductors.wind_power(0.01, 20.0, D, turbulence=0.09) == pytest.approx(
        cigre_as_printed(0.01, 20.0, D) / math.sqrt(2), rel=1e-14
    )
    low, e0 = conductors.wind_band("cigre")
    assert low == 0.0
    assert e0 == pytest.approx(
        brentq(lambda e: cigre_as_printed(e, 1.0, 1.0), 0.5, 2.0, xtol=1e-15), rel=1e-13
    )
    # the tabulated studies pass through their points (F at y/D, W/(m⁴ Hz³))
    tables = {
        "diana-falco-1971": ([0.03, 0.20, 0.80], [0.23, 5.00, 20.00]),
        "rawlins-1983": ([0.03, 0.30, 0.70], [0.18, 6.50, 10.80]),
        "brika-laneville-1995": ([0.01, 0.10, 0.40], [0.03, 1.10, 6.00]),
    }
    for model, (e, F) in tables.items():
        np.testing.assert_allclose(
            conductors.wind_power(np.array(e) * D, 10.0, D, model), 1e3 * D**4 * np.array(F)
        )
        assert conductors.wind_band(model) == (e[0], e[-1])
    assert set(conductors.WIND_MODELS) == {"cigre", *tables}


def test_clamp_amplitude_is_a_clamped_tensioned_beams_mode():
    """A clamped–clamped tensioned beam on finite elements (skcable.strand.beam_frequencies,
    Hermite elements): 2 |w(x_b)| scaled to the antinode amplitude, against the boundary-layer
    formula, asymptotic in β/p (here 0.05 and 0.1)."""
    EI, m, L = 41.0, 1.628, 5.0
    beam = strand.beam_frequencies(EI, T, L, m, n_modes=4, n_elements=1000)  # 5 mm; 1/p = 38 mm
    p = math.sqrt(T / EI)
    for k in (1, 3):
        f, w = beam.f[k], beam.modes[k]
        y = float(np.abs(w).max())
        Y_b = 2 * abs(float(np.interp(0.089, beam.x, w)))
        beta = 2 * math.pi * f * math.sqrt(m / T)
        assert conductors.clamp_amplitude(y, f, T, m, EI) == pytest.approx(Y_b, rel=(beta / p) ** 2)


def test_poffenberger_swart_of_the_clamp_amplitude_is_the_f_ymax_rule():
    """σ_a = π d_a E_a f sqrt(m/EI) y_max (E_a d_a/2 times the clamp curvature y β p)."""
    m, EI, E_a, d_a = 1.628, 41.0, 69e9, 4.442e-3
    for y, f in [(1e-3, 20.0), (5e-3, 8.0), (2e-4, 60.0)]:
        Y_b = conductors.clamp_amplitude(y, f, T, m, EI)
        sigma = conductors.poffenberger_swart(Y_b, T, EI, E_a, d_a)
        assert sigma == pytest.approx(math.pi * d_a * E_a * f * math.sqrt(m / EI) * y, rel=1e-12)


def test_the_chain_to_a_life(drake):
    hours = np.full(F_BAND.size, 10.0)
    result = conductors.aeolian_vibration(drake["strand"], T, F_BAND, damping="foti", hours_per_year=hours)
    m, D, EI, k0 = drake["mass"], drake["D"], drake["EI"], drake["k0"]
    y = conductors.aeolian_amplitude(
        F_BAND, D, m, T, lambda y, f: conductors.foti_damping(y, f, T, m, EI, k0)
    )
    np.testing.assert_array_equal(result.y_max, y)
    EI_min = float(drake["law"].EI_min[0])
    assert (
        result.EI_clamp == EI_min
        and result.E_a == strand.material("aluminium").E_e
        and result.d_a == 4.442e-3
    )
    sigma = math.pi * result.d_a * result.E_a * F_BAND * math.sqrt(m / EI_min) * y
    np.testing.assert_allclose(result.sigma_a, sigma, rtol=1e-12)
    # the Safe Border Line of a conductor of more than one aluminium layer: 450 MPa N^-0.2, 263 MPa N^-0.168
    N = np.where((sigma / 450e6) ** -5.0 < 2e7, (sigma / 450e6) ** -5.0, (sigma / 263e6) ** (-1 / 0.168))
    np.testing.assert_allclose(result.cycles, N, rtol=1e-10)
    damage = np.sum(F_BAND * 3600 * hours / N)
    assert result.damage_per_year == pytest.approx(damage, rel=1e-10)
    assert result.life_years == pytest.approx(1 / damage, rel=1e-10)
    frame = result.to_frame()
    assert list(frame.columns)[:4] == ["f_Hz", "y_max_m", "wavelength_m", "Y_b_pp_m"] and len(frame) == 100
    np.testing.assert_allclose(
        result.damping_power, [cigre_as_printed(a, b, D) for a, b in zip(y, F_BAND, strict=True)], rtol=1e-9
    )


def test_broken_wires_change_the_law_the_mass_and_the_amplitude(drake):
    intact = conductors.aeolian_vibration(drake["strand"], T, F_BAND[::10], damping="foti")
    broken = conductors.aeolian_vibration(drake["strand"], T, F_BAND[::10], damping="foti", damage=3, axis=1)
    assert broken.law.section.strand.broken and not intact.law.section.strand.broken
    assert broken.mass == intact.mass  # a broken wire stays in the span
    assert broken.law.EI_max[1] < intact.law.EI_max[1]
    assert not np.allclose(broken.law.kappa_slip, intact.law.kappa_slip)
    assert not np.allclose(broken.y_max, intact.y_max)
    assert intact.life_years is None


def test_the_models_own_damping(drake):
    result = conductors.aeolian_vibration(drake["strand"], T, F_BAND[::10])
    m, D = drake["mass"], drake["D"]
    for yi, fi in zip(result.y_max, result.f, strict=True):
        e0 = conductors.wind_band()[1]
        wind = 0.0 if yi == e0 * D else cigre_as_printed(yi, fi, D)
        own = conductors.self_damping(drake["law"], yi, fi, T, m)
        assert abs(wind - own) <= 1e-10 * max(wind, own, 1e-300)


@pytest.mark.parametrize(
    ("call", "argument"),
    [
        (lambda d, damp: conductors.wind_power(0.0, 20.0, 0.028), "y"),
        (lambda d, damp: conductors.wind_power(0.03, 20.0, 0.028), "y"),  # y/D > e0
        (lambda d, damp: conductors.wind_power(1e-4, 20.0, 0.028, "rawlins-1983"), "y"),
        (lambda d, damp: conductors.wind_power(0.01, 0.0, 0.028), "f"),
        (lambda d, damp: conductors.wind_power(0.01, 20.0, -0.028), "diameter"),
        (lambda d, damp: conductors.wind_power(0.01, 20.0, 0.028, "karman"), "model"),
        (lambda d, damp: conductors.wind_power(0.01, 20.0, 0.028, turbulence=-0.1), "turbulence"),
        (lambda d, damp: conductors.aeolian_amplitude([20.0, 0.0], d["D"], d["mass"], T, damp), "f"),
        (lambda d, damp: conductors.aeolian_amplitude(20.0, 0.0, d["mass"], T, damp), "diameter"),
        (lambda d, damp: conductors.aeolian_amplitude(20.0, d["D"], -1.0, T, damp), "mass"),
        (lambda d, damp: conductors.aeolian_amplitude(20.0, d["D"], d["mass"], 0.0, damp), "tension"),
        (lambda d, damp: conductors.aeolian_amplitude(20.0, d["D"], d["mass"], T, 3.0), "damping"),
        (
            lambda d, damp: conductors.aeolian_amplitude(
                20.0, d["D"], d["mass"], T, lambda y, f: -damp(y, f)
            ),
            "damping",
        ),
        (
            lambda d, damp: conductors.aeolian_amplitude(
                20.0, d["D"], d["mass"], T, lambda y, f: damp(y, f) * np.nan
            ),
            "damping",
        ),
        (
            lambda d, damp: conductors.aeolian_amplitude(
                [20.0, 30.0], d["D"], d["mass"], T, lambda y, f: 1.0
            ),
            "damping",
        ),
        (lambda d, damp: conductors.aeolian_vibration(d["strand"], T, [20.0], damping="rayleigh"), "damping"),
        (lambda d, damp: conductors.aeolian_vibration(d["strand"], T, [20.0], clamp_EI="mean"), "clamp_EI"),
        (
            lambda d, damp: conductors.aeolian_vibration(d["strand"], T, [20.0], hours_per_year=[1.0, 2.0]),
            "hours_per_year",
        ),
        (
            lambda d, damp: conductors.aeolian_vibration(d["strand"], T, [20.0], hours_per_year=[9000.0]),
            "hours_per_year",
        ),
        (lambda d, damp: conductors.aeolian_vibration(d["strand"], T, [20.0], curve="sbl"), "curve"),
        (lambda d, damp: conductors.aeolian_vibration(d["strand"], -T, [20.0]), "tension"),
    ],
)
def test_bad_input_is_named(drake, call, argument):
    damping = lambda y, f: conductors.foti_damping(y, f, T, drake["mass"], drake["EI"], drake["k0"])  # noqa: E731
    with pytest.raises(InputError) as err:
        call(drake, damping)
    assert err.value.argument == argument


def test_no_root_in_the_band(drake):
    m, D = drake["mass"], drake["D"]
    with pytest.raises(ConvergenceError, match="no root of P_wind = P_damping.*smallest amplitude"):
        conductors.aeolian_amplitude(20.0, D, m, T, lambda y, f: 1e3 + 0 * y * f)
    with pytest.raises(ConvergenceError, match="no root of P_wind = P_damping.*'rawlins-1983'"):
        conductors.aeolian_amplitude(20.0, D, m, T, lambda y, f: 0 * y * f, model="rawlins-1983")


def test_a_tabulated_wind_balances_too(drake):
    m, D, EI, k0 = drake["mass"], drake["D"], drake["EI"], drake["k0"]
    damping = lambda y, f: conductors.foti_damping(y, f, T, m, EI, k0)  # noqa: E731
    f = np.linspace(10.0, 25.0, 6)  # outside, the root leaves the table: below 0.03 or above 0.8
    y = conductors.aeolian_amplitude(f, D, m, T, damping, model="diana-falco-1971")
    np.testing.assert_allclose(conductors.wind_power(y, f, D, "diana-falco-1971"), damping(y, f), rtol=1e-10)
    assert np.all((y / D >= 0.03) & (y / D <= 0.8))
    with pytest.raises(ConvergenceError, match="smallest amplitude"):
        conductors.aeolian_amplitude(40.0, D, m, T, damping, model="diana-falco-1971")


def test_a_loop_steeper_than_a_taut_strings_is_refused(drake):
    """At 100 N the loops are short: an undamped conductor's amplitude, y/D = e0, is no taut
    string's loop there (slope 2π y/λ above 0.3)."""
    with pytest.raises(InputError, match="taut") as err:
        conductors.aeolian_amplitude(60.0, drake["D"], drake["mass"], 100.0, lambda y, f: 0.0 * y * f)
    assert err.value.argument == "f"
