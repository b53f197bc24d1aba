"""Parabola (load per horizontal length): seed examples and independent checks."""

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import quad

from skcable import cable
from skcable.errors import InputError


def test_seed000_ex3_published_values():
    p = cable.parabola(800.0, -20.0, 20.0, low=-30.0)
    assert round(p.x_low, 2) == 507.18
    assert round(p.H, 1) == 85743.7
    assert round(p.sag, 2) == 18.66
    assert round(p.T_A, 1) == 86341.7
    assert round(p.T_B, 1) == 85943.5
    assert round(p.length, 3) == 801.408


def test_seed000_ex3_equations_hold():
    # the seed's two equations: H (y_m + x_m tan a) = wL x_m/2 - w x_m²/2 and w x_m²/2 = y_m H
    p = cable.parabola(800.0, -20.0, 20.0, low=-30.0)
    x_m, tan_a = p.x_low, -20.0 / 800.0
    assert p.H * (30 + x_m * tan_a) == pytest.approx(20 * 800 * x_m / 2 - 20 * x_m**2 / 2, rel=1e-13)
    assert 20 * x_m**2 / 2 == pytest.approx(30 * p.H, rel=1e-13)


def test_seed001_ex4_published_values():
    p = cable.parabola(200.0, 0.0, 1.0, sag=20.0)
    assert round(p.H, 1) == 250.0
    assert round(p.T_max, 2) == 269.26
    assert round(p.length, 4) == 205.2121


def test_seed000_length_formula_in_end_tensions():
    # seed 000 §2: S = L²/(16 f H) [T_A sqrt((T_A/H)²-1) + T_B sqrt(...) + H ln(...)]
    p = cable.parabola(600.0, 45.0, 7.0, H=9000.0)
    H, TA, TB, L, f = p.H, p.T_A, p.T_B, 600.0, p.sag
    S = (
        L**2
        / (16 * f * H)
        * (
            TA * np.sqrt((TA / H) ** 2 - 1)
            + TB * np.sqrt((TB / H) ** 2 - 1)
            + H * np.log((TB + np.sqrt(TB**2 - H**2)) / (TA - np.sqrt(TA**2 - H**2)))
        )
    )
    assert p.length == pytest.approx(S, rel=1e-12)


@pytest.mark.parametrize("dh, sag_ratio", [(0.0, 1e-6), (-30.0, 0.1), (500.0, 0.3), (-2000.0, 2.0)])
def test_length_by_40_digit_quadrature(dh, sag_ratio):
    p = cable.parabola(100.0, dh, 3.0, sag=100.0 * sag_ratio)
    mp.mp.dps = 40
    exact = mp.quad(lambda q: mp.sqrt(1 + q * q), [p.p_A, p.p_B]) * p.a
    assert p.length - np.hypot(100.0, dh) == pytest.approx(
        float(exact - mp.sqrt(100**2 + mp.mpf(dh) ** 2)), rel=1e-9
    )


@pytest.mark.parametrize("constraint", ["length", "sag", "H", "low", "T_max"])
def test_every_constraint_round_trips(constraint):
    ref = cable.parabola(800.0, -20.0, 20.0, low=-30.0)
    attr = {"low": "y_low"}.get(constraint, constraint)
    p = cable.parabola(800.0, -20.0, 20.0, **{constraint: getattr(ref, attr)})
    assert p.H == pytest.approx(ref.H, rel=1e-10)
    assert p.residual() < 1e-12


def test_general_cable_theorem():
    # seed 000 §1.b: H · (depth below chord) = simply supported beam moment w x (L-x)/2
    p = cable.parabola(240.0, 35.0, 4.0, H=1500.0)
    x = np.linspace(0, 240, 9)
    depth = 35.0 * x / 240.0 - p.y(x)
    assert np.allclose(p.H * depth, 4.0 * x * (240 - x) / 2, rtol=1e-12, atol=1e-9)


def test_tension_profile_by_quadrature_of_the_load():
    p = cable.parabola(240.0, 35.0, 4.0, H=1500.0)
    # vertical tension at x = -V_A + w x; T = sqrt(H² + Tv²)
    assert p.T(100.0) == pytest.approx(np.hypot(p.H, -p.V_A + 4.0 * 100.0), rel=1e-13)
    arc, _ = quad(lambda x: np.sqrt(1 + p.slope(x) ** 2), 0, 240, epsrel=1e-13)
    assert p.length == pytest.approx(arc, rel=1e-12)


def test_bad_input():
    with pytest.raises(InputError, match="T_max"):
        cable.parabola(100.0, 0.0, 1.0, T_max=40.0)  # below w·span/2
    with pytest.raises(InputError, match="length"):
        cable.parabola(100.0, 0.0, 1.0, length=99.0)
    with pytest.raises(InputError, match="low"):
        cable.parabola(100.0, -10.0, 1.0, low=-5.0)


def test_lowest_point_and_vertex():
    # seed 000 ex. 3: the vertex 507.18 m from A is the lowest point
    p = cable.parabola(800.0, -20.0, 20.0, low=-30.0)
    assert (p.x_low, p.y_low) == (p.x_vertex, p.y_vertex)
    # taut and steep: the vertex lies beyond B (x_v = -a p_A, seed 001 §3.2), B is the lowest point
    q = cable.parabola(646.0, -150.0, 10.0, H=2e5)
    assert q.x_vertex == pytest.approx(2e5 / 10.0 * (150.0 / 646.0 + 646.0 / (2 * 2e4)), rel=1e-14)
    assert (q.x_low, q.y_low) == (646.0, -150.0)
    assert np.min(q.y(np.linspace(0, 646.0, 100_001))) == pytest.approx(-150.0, abs=1e-9)
    r = cable.parabola(646.0, 150.0, 10.0, H=2e5)
    assert (r.x_low, r.y_low) == (0.0, 0.0)


def test_taut_inclined_parabola_passes_its_own_check():
    # issue #14: V_A and V_B of ±3e9 balance 100 N; the residual now divides by them
    p = cable.parabola(100.0, 30.0, 1.0, H=1e10)
    assert p.residual() < 1e-15
    assert p.V_B == pytest.approx(50.0 + 1e10 * 0.3, rel=1e-15)  # w span/2 + H dh/span
    span = np.array([100.0, 646.0])
    v = cable.parabola(span, np.array([30.0, -150.0]), 1.0, H=np.array([1e10, 1e12]))
    assert v.residual() < 1e-15


def test_extreme_constraints_are_scaled_not_overflowed():
    # T_max = 1e200 N on a 1e-50 m span: the quadratic in a is formed in scaled units (tau² overflows).
    # Level span: T_max = H sqrt(1 + (span/2a)²) = H sqrt(1 + (w span/2H)²)
    p = cable.parabola(1e-50, 0.0, 1.0, T_max=1e200)
    assert p.H == pytest.approx(1e200, rel=1e-15)
    # length 1e-300 m above a chord of 1e-300 m: S = chord (1 + 8/3 (f/L)² ...) with f/L = 1/4 here
    q = cable.parabola(1e-300, 0.0, 1.0, sag=0.25e-300)
    r = cable.parabola(1e-300, 0.0, 1.0, length=q.length)
    assert r.H == pytest.approx(q.H, rel=1e-12)
