"""Self-damping: the model's power against the string-loop integral written here (quadrature
along the loop), its exponents against log-derivatives of that integral and against the power
law of a loop energy W ∝ κ_a^p, Foti & Martinelli (2018)'s eqs. 23–30 as printed, and refusals."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from skcable import conductors, strand
from skcable.errors import InputError

T, MASS = 28e3, 1.628  # N, kg/m: ACSR Drake at 20 % RTS
EI1, EI2, KS = 1400.0, 40.0, 0.02  # a bilinear law: N·m², N·m², 1/m


def bilinear_W(kappa_a):
    """Masing's loop energy of the bilinear law, 4 (EI1 - EI2) κs (κa - κs)+ (J/m)."""
    return 4 * (EI1 - EI2) * KS * max(kappa_a - KS, 0.0)


def loop_power(W, y, f, tension=T, mass=MASS, knees=()):
    """P = f (2/λ) ∫_0^{λ/2} W(κ(x)) dx, κ(x) = (4π² y/λ²) sin(2πx/λ), by adaptive quadrature along
    the loop (split where κ(x) crosses a knee)."""
    lam = math.sqrt(tension / mass) / f
    k0 = 4 * math.pi**2 * y / lam**2
    split = sorted(
        lam / (2 * math.pi) * s
        for k in knees
        if k < k0
        for s in (math.asin(k / k0), math.pi - math.asin(k / k0))
    )
    integral = quad(lambda x: W(k0 * math.sin(2 * math.pi * x / lam)), 0.0, lam / 2, points=split or None,
                    epsabs=0, epsrel=1e-13, limit=400)[0]  # fmt: skip
    return f * 2 / lam * integral


@pytest.fixture(scope="module")
def bilinear():
    return strand.StageLaw(EI2, [EI1 - EI2], [(EI1 - EI2) * KS])


@pytest.fixture(scope="module")
def cardinal():
    return strand.LayerSlipLaw(strand.preset("acsr-cardinal").section(), mu=0.7, tension=40e3)


@pytest.mark.parametrize(("y", "f"), [(2e-3, 40.0), (5e-3, 30.0), (2e-2, 25.0), (1e-2, 60.0)])
def test_self_damping_is_the_string_loop_integral_of_the_bilinear_loop(bilinear, y, f):
    P = conductors.self_damping(bilinear, y, f, T, MASS)
    assert P == pytest.approx(loop_power(bilinear_W, y, f, knees=[KS]), rel=1e-10, abs=1e-300)


def test_self_damping_of_a_layered_law_is_the_string_loop_integral(cardinal):
    m = 1.829  # kg/m, ACSR Cardinal
    for y, f in [(3e-3, 40.0), (1e-2, 30.0), (3e-2, 20.0)]:
        expected = loop_power(
            lambda k: float(cardinal.energy_per_cycle(k, 0)), y, f, 40e3, m, cardinal.kappa_slip[0]
        )
        assert conductors.self_damping(cardinal, y, f, 40e3, m) == pytest.approx(expected, rel=1e-9)
    grid = conductors.self_damping(
        cardinal, np.array([[3e-3], [1e-2]]), np.array([20.0, 30.0, 40.0]), 40e3, m
    )
    assert grid.shape == (2, 3)
    assert grid[1, 2] == conductors.self_damping(cardinal, 1e-2, 40.0, 40e3, m)


def test_below_the_first_knee_nothing_is_dissipated(bilinear):
    lam = math.sqrt(T / MASS) / 20.0
    y = 0.9 * KS * lam**2 / (4 * math.pi**2)
    assert conductors.self_damping(bilinear, y, 20.0, T, MASS) == 0.0
    with pytest.raises(InputError) as err:
        conductors.damping_exponents(bilinear, y, 20.0, T, MASS)
    assert err.value.argument == "y"


@pytest.mark.parametrize(("y", "f"), [(3e-2, 30.0), (2e-2, 25.0), (1e-2, 60.0)])
def test_exponents_of_the_bilinear_law_over_a_string_loop(bilinear, y, f):
    """l = p, m = 2p + 1, n = p with p = d ln W̄ / d ln κ_0, W̄ the loop-averaged energy: the
    log-derivatives of the quadrature in y, f and T here (Richardson-extrapolated central
    differences), and p from W̄ itself."""

    def slope(g, x, h=2e-3):
        d = lambda h: (math.log(g(x * math.exp(h))) - math.log(g(x * math.exp(-h)))) / (2 * h)  # noqa: E731
        return (4 * d(h / 2) - d(h)) / 3

    l_fd = slope(lambda v: loop_power(bilinear_W, v, f, knees=[KS]), y)
    m_fd = slope(lambda v: loop_power(bilinear_W, y, v, knees=[KS]), f)
    n_fd = -slope(lambda v: loop_power(bilinear_W, y, f, tension=v, knees=[KS]), T)
    k0 = 4 * math.pi**2 * y * f * f * MASS / T
    p = slope(lambda k: quad(lambda u: bilinear_W(k * math.sin(u)), 0, math.pi / 2, epsrel=1e-13, limit=200,
                             points=[math.asin(KS / k)])[0], k0)  # fmt: skip
    l, m, n = conductors.damping_exponents(bilinear, y, f, T, MASS)
    for ours, written in [(l, l_fd), (m, m_fd), (n, n_fd), (l, p), (m, 2 * p + 1), (n, p)]:
        assert ours == pytest.approx(written, abs=1e-8)


class PowerLawLoop:
    """A law whose loop energy is W = c κ_a^p exactly (no closed form: quadrature path)."""

    def __init__(self, c, p):
        self.c, self.p = c, p

    def energy_per_cycle(self, kappa_a, axis=0):
        return self.c * np.asarray(kappa_a) ** self.p


@pytest.mark.parametrize("p", [1.0, 2.3, 3.0])
def test_a_power_law_loop_gives_l_p_m_2p_plus_1_n_p(p):
    law = PowerLawLoop(50.0, p)
    y, f = 1e-2, 30.0
    P = conductors.self_damping(law, y, f, T, MASS)
    ratio = lambda P2: math.log(P2 / P) / math.log(2.0)  # noqa: E731
    assert ratio(conductors.self_damping(law, 2 * y, f, T, MASS)) == pytest.approx(p, abs=1e-10)
    assert ratio(conductors.self_damping(law, y, 2 * f, T, MASS)) == pytest.approx(2 * p + 1, abs=1e-10)
    assert ratio(conductors.self_damping(law, y, f, 2 * T, MASS)) == pytest.approx(-p, abs=1e-10)
    assert ratio(conductors.self_damping(law, y, f, T, 2 * MASS)) == pytest.approx(p, abs=1e-10)
    # the quadrature itself: (2/π) ∫_0^{π/2} sin^p u du = Γ((p+1)/2) / (√π Γ(p/2 + 1))
    k0 = 4 * math.pi**2 * y * f * f * MASS / T
    mean_sin_p = math.gamma((p + 1) / 2) / (math.sqrt(math.pi) * math.gamma(p / 2 + 1))
    assert P == pytest.approx(f * 50.0 * k0**p * mean_sin_p, rel=1e-9)


def foti_as_printed(y, f, T, m, EI, k0):
    """Foti & Martinelli (2018), eqs. 23–30: P = G1(kn) P_ms + G2(kn) P_gs."""
    G1 = lambda kn: 1 / 3 - 3 / 8 * math.cos(2 * math.pi * kn) + math.cos(6 * math.pi * kn) / 24  # noqa: E731
    G2 = lambda kn: math.pi - 4 * math.pi * kn + math.sin(4 * math.pi * kn)  # noqa: E731
    P_ms = 128 * math.pi**5 * m**3 * EI / k0 * y**3 * f**7 / T**3
    P_gs = 4 * math.pi**3 * m**2 * EI * y**2 * f**5 / T**2
    lam = math.sqrt(T / m) / f
    kn = math.asin(min(1.0, lam**2 * k0 / (4 * math.pi**2 * y))) / (2 * math.pi)
    return G1(kn) * P_ms + G2(kn) * P_gs


@pytest.mark.parametrize("y", [1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1])
@pytest.mark.parametrize("f", [5.0, 20.0, 60.0])
def test_foti_damping_is_the_paper(y, f):
    EI, k0 = 1397.0, 0.028
    ours = conductors.foti_damping(y, f, T, MASS, EI, k0)
    assert ours == pytest.approx(foti_as_printed(y, f, T, MASS, EI, k0), rel=1e-12)
    # and it is the string-loop integral of its loop energy: EI κ³/(2 κ0) below κ0, EI κ²/2 above
    W = lambda k: EI * k**3 / (2 * k0) if k <= k0 else EI * k**2 / 2  # noqa: E731
    assert ours == pytest.approx(loop_power(W, y, f, knees=[k0]), rel=1e-10)


def test_foti_limits_are_micro_slip_and_gross_slip_power_laws():
    EI, k0 = 1397.0, 0.028
    P = lambda y, f: conductors.foti_damping(y, f, T, MASS, EI, k0)  # noqa: E731
    y, f = 1e-4, 10.0  # micro-slip: P ∝ y³ f⁷ / T³
    assert math.log(P(2 * y, f) / P(y, f), 2) == pytest.approx(3.0, abs=1e-12)
    assert math.log(P(y, 2 * f) / P(y, f), 2) == pytest.approx(7.0, abs=1e-12)


def test_power_laws():
    y, f = np.array([1e-3, 2e-3]), 20.0
    for name, (l, m, n) in conductors.DAMPING_EXPONENTS.items():
        P = conductors.power_law_damping(y, f, T, 1.0, name)
        np.testing.assert_allclose(P, y**l * f**m / T**n, rtol=1e-14)
        assert 2.0 <= l <= 2.6 and 4.0 <= m <= 6.0 and 1.5 <= n <= 3.0  # the published ranges
    assert conductors.power_law_damping(1e-3, 20.0, T, 2.0, (2.0, 5.0, 1.0)) == pytest.approx(
        2e-6 * 20.0**5 / T
    )
    assert conductors.DAMPING_EXPONENTS["noiseux-1991"] == (2.44, 5.63, 2.76)
    assert conductors.DAMPING_EXPONENTS["kraus-hagedorn-1991"] == (2.47, 5.38, 2.80)


@pytest.mark.parametrize(
    ("call", "argument"),
    [
        (lambda: conductors.foti_damping(0.0, 20.0, T, MASS, 1e3, 0.02), "y"),
        (lambda: conductors.foti_damping(1e-3, -20.0, T, MASS, 1e3, 0.02), "f"),
        (lambda: conductors.foti_damping(1e-3, 20.0, 0.0, MASS, 1e3, 0.02), "tension"),
        (lambda: conductors.foti_damping(1e-3, 20.0, T, float("nan"), 1e3, 0.02), "mass"),
        (lambda: conductors.foti_damping(1e-3, 20.0, T, MASS, -1.0, 0.02), "EI_max"),
        (lambda: conductors.foti_damping(1e-3, 20.0, T, MASS, 1e3, 0.0), "kappa_0"),
        (lambda: conductors.foti_damping([1e-3, 2e-3], [1.0, 2.0, 3.0], T, MASS, 1e3, 0.02), "f"),
        (lambda: conductors.self_damping(object(), 1e-3, 20.0, T, MASS), "law"),
        (lambda: conductors.self_damping(PowerLawLoop(1.0, 2.0), -1e-3, 20.0, T, MASS), "y"),
        (lambda: conductors.self_damping(PowerLawLoop(-1.0, 2.0), 1e-3, 20.0, T, MASS), "law"),
        (lambda: conductors.damping_exponents(PowerLawLoop(1.0, 2.0), 1e-3, 20.0, T, MASS), "law"),
        (lambda: conductors.power_law_damping(1e-3, 20.0, T, 1.0, "unknown"), "exponents"),
        (lambda: conductors.power_law_damping(1e-3, 20.0, T, 1.0, (1.0, 2.0)), "exponents"),
        (lambda: conductors.power_law_damping(1e-3, 20.0, T, 0.0), "k"),
    ],
)
def test_bad_input_is_named(call, argument):
    with pytest.raises(InputError) as err:
        call()
    assert err.value.argument == argument
