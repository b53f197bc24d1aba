"""Catenary: seed worked examples, independent references, properties."""

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from skcable import cable
from skcable.errors import InputError

mp.mp.dps = 40


def mp_catenary_from_length(span, dh, length):
    """40-digit reference: solve sinh(z)/z = sqrt(S²-dh²)/span with mpmath."""
    span, dh, length = mp.mpf(span), mp.mpf(dh), mp.mpf(length)
    r = mp.sqrt(length**2 - dh**2) / span
    z = mp.findroot(lambda z: mp.log(mp.sinh(z) / z / r), (mp.mpf("1e-12"), mp.mpf(50)), solver="anderson")
    return span / (2 * z)  # a = H / w


# --- seed 000, example 4 (catenary, lowest point 30 m below A) -------------
def test_seed000_ex4_published_values():
    c = cable.catenary(800.0, -20.0, 20.0, low=-30.0)
    # the seed stopped its iteration early (REFERENCE.md §1): H is ~0.5 kN off
    assert c.x_low == pytest.approx(507.107, abs=1e-3)
    assert c.H == pytest.approx(85818.7, rel=1e-5)
    assert c.T_A == pytest.approx(86418.7, rel=1e-5)
    assert c.T_B == pytest.approx(86018.7, rel=1e-5)
    assert c.length == pytest.approx(801.409, abs=1e-3)
    assert c.residual() < 1e-12


def test_seed000_ex4_full_precision_against_mpmath():
    c = cable.catenary(800.0, -20.0, 20.0, low=-30.0)
    # independent: vertex depth condition 2a[asinh(sqrt(dA/2a)) + asinh(sqrt(dB/2a))] = span
    a = mp.findroot(
        lambda a: 2 * a * (mp.asinh(mp.sqrt(30 / (2 * a))) + mp.asinh(mp.sqrt(10 / (2 * a)))) - 800, 4000
    )
    assert c.H == pytest.approx(float(20 * a), rel=1e-13)
    assert float(20 * a) == pytest.approx(85819.2, abs=0.05)  # REFERENCE.md's full-precision H


# --- seed 001, example 5 (catenary given sag, equal heights) ---------------
def test_seed001_ex5_published_values():
    c = cable.catenary(200.0, 0.0, 1.0, sag=20.0)
    assert round(c.H, 4) == 253.2649
    assert round(c.T_max, 4) == 273.2649
    assert round(c.length, 4) == 205.2374
    # seed: T_max = q (f + a)
    assert c.T_max == pytest.approx(c.w * (20.0 + c.a), rel=1e-14)


# --- independent checks -------------------------------------------------------
@pytest.mark.parametrize(
    "span, dh, length",
    [(800, -20, 801.409), (100, 30, 150), (1, 1000, 1000.5), (100, 0, 100 * (1 + 1e-9)), (10, -3, 1000)],
)
def test_length_solution_matches_40_digit_reference(span, dh, length):
    c = cable.catenary(span, dh, 1.0, length=length)
    assert c.a == pytest.approx(float(mp_catenary_from_length(span, dh, length)), rel=1e-10)
    assert c.residual() < 1e-12


def test_profile_passes_supports_and_length_by_quadrature():
    c = cable.catenary(300.0, 45.0, 12.0, H=2000.0)
    assert c.y(0.0) == 0.0
    assert c.y(300.0) == pytest.approx(45.0, rel=1e-13)
    arc, _ = quad(lambda x: np.sqrt(1 + c.slope(x) ** 2), 0, 300, epsabs=0, epsrel=1e-13)
    assert c.length == pytest.approx(arc, rel=1e-12)


def test_sag_is_largest_chord_distance_by_brute_force():
    c = cable.catenary(500.0, -120.0, 3.0, length=560.0)
    x = np.linspace(0, 500, 2_000_001)
    assert c.sag == pytest.approx(np.max(-120.0 * x / 500 - c.y(x)), rel=1e-10)


def test_tension_is_conservative_T_equals_w_times_height_plus_const():
    # seed 001 eq. (5)-(6): T = w·y + h along the whole cable
    c = cable.catenary(250.0, 40.0, 7.0, sag=30.0)
    x = np.linspace(0, 250, 11)
    assert np.allclose(c.T(x) - c.w * c.y(x), c.T_A, rtol=1e-13)


def test_reactions_balance_weight_and_moment():
    c = cable.catenary(400.0, 60.0, 5.0, low=-25.0)
    assert c.V_A + c.V_B == pytest.approx(c.w * c.length, rel=1e-13)
    # moment about A: V_B·span - H·dh = w ∫ x ds
    moment, _ = quad(lambda x: x * np.sqrt(1 + c.slope(x) ** 2), 0, 400, epsrel=1e-13)
    assert c.V_B * 400 - c.H * 60 == pytest.approx(c.w * moment, rel=1e-11)


@pytest.mark.parametrize("constraint", ["length", "sag", "H", "low", "T_max"])
def test_every_constraint_round_trips(constraint):
    ref = cable.catenary(800.0, -20.0, 20.0, low=-30.0)
    attr = {"low": "y_low"}.get(constraint, constraint)
    c = cable.catenary(800.0, -20.0, 20.0, **{constraint: getattr(ref, attr)})
    # length is ill-conditioned (H moves 37 kN per metre, REFERENCE.md §1)
    assert c.H == pytest.approx(ref.H, rel=1e-9 if constraint == "length" else 1e-12)


def test_T_max_has_taut_and_slack_branches():
    taut = cable.catenary(100.0, 10.0, 1.0, T_max=200.0)
    slack = cable.catenary(100.0, 10.0, 1.0, T_max=200.0, branch="slack")
    assert taut.T_max == pytest.approx(200.0, rel=1e-12)
    assert slack.T_max == pytest.approx(200.0, rel=1e-12)
    assert slack.length > taut.length
    # the tension at the higher support is w (a + depth of vertex below it)
    for c in (taut, slack):
        assert c.T_B == pytest.approx(c.w * (c.a + c.dh - c.y_low), rel=1e-12)


def test_T_max_below_the_least_possible_raises():
    with pytest.raises(InputError, match="T_max"):
        cable.catenary(100.0, 0.0, 1.0, T_max=50.0)  # minimum is w·span·0.755...


def test_given_H_different_heights_matches_seed_quadratic():
    # seed 001 §3.4.6: with u = cosh(xA/a), beta = cosh(L/a):
    # beta·u + sqrt(beta²-1)·sqrt(u²-1) - u = h/a (u chosen with vertex left of B)
    span, dh, w, H = 120.0, 25.0, 2.0, 300.0
    a = H / w
    c = cable.catenary(span, dh, w, H=H)
    beta = mp.cosh(mp.mpf(span) / a)
    for sign in (1, -1):
        try:
            u = mp.findroot(
                lambda u, sign=sign: beta * u + sign * mp.sqrt(beta**2 - 1) * mp.sqrt(u**2 - 1) - u - dh / a,
                1.01,
            )
        except ValueError:
            continue
        x_a = sign * float(mp.acosh(u)) * a  # abscissa of A from the vertex
        if abs(-x_a - c.x_low) < 1e-6 * span:
            break
    else:
        pytest.fail("no root of the seed's quadratic matches")
    assert -x_a == pytest.approx(c.x_low, rel=1e-9)


def test_swapping_supports_mirrors_the_solution():
    c = cable.catenary(300.0, 40.0, 4.0, length=340.0)
    m = cable.catenary(300.0, -40.0, 4.0, length=340.0)
    assert m.H == pytest.approx(c.H, rel=1e-13)
    assert (m.V_A, m.V_B) == pytest.approx((c.V_B, c.V_A), rel=1e-12)
    assert m.x_low == pytest.approx(300.0 - c.x_low, rel=1e-12)
    assert m.y(100.0) == pytest.approx(c.y(200.0) - 40.0, rel=1e-12)


def test_parabola_is_the_shallow_limit():
    # as sag/span -> 0 the catenary's H approaches the parabola's w·span²/8f
    errors = []
    for ratio in (1e-1, 1e-2, 1e-3):
        c = cable.catenary(100.0, 0.0, 1.0, sag=100.0 * ratio)
        p = cable.parabola(100.0, 0.0, 1.0, sag=100.0 * ratio)
        errors.append(abs(c.H / p.H - 1))
    # the leading correction is O((f/L)²)
    assert errors[1] < errors[0] / 50 and errors[2] < errors[1] / 50


def test_vectorised_equals_scalar_calls():
    spans = np.array([100.0, 800.0, 5.0])
    dhs = np.array([0.0, -20.0, 300.0])
    lengths = np.array([120.0, 801.409, 400.0])
    v = cable.catenary(spans, dhs, 20.0, length=lengths)
    for i in range(3):
        s = cable.catenary(spans[i], dhs[i], 20.0, length=lengths[i])
        for name in ("H", "V_A", "V_B", "T_A", "T_B", "length", "sag", "x_low", "y_low"):
            assert getattr(v, name)[i] == pytest.approx(getattr(s, name), rel=1e-13, abs=1e-12)
    assert v.points(7).shape == (3, 7, 2)


@settings(max_examples=200, deadline=None)
@given(
    span=st.floats(1e-2, 1e4),
    slope=st.floats(-50, 50),
    excess=st.floats(-9, 2),  # log10 of (length/chord - 1)
    w=st.floats(1e-3, 1e3),
)
def test_random_scenes_close_with_tiny_residual(span, slope, excess, w):
    dh = slope * span
    length = np.hypot(span, dh) * (1 + 10.0**excess)
    c = cable.catenary(span, dh, w, length=length)
    assert c.residual() < 1e-10
    assert c.y(span) == pytest.approx(dh, abs=1e-9 * np.hypot(span, dh))
    for name in ("length", "sag", "H", "low", "T_max"):
        value = {"low": c.y_low}.get(name, getattr(c, name, None))
        if name == "low" and not (c.y_low < min(0.0, dh) and 0 < c.x_low < span):
            continue
        other = cable.catenary(span, dh, w, **{name: value})
        assert other.residual() < 1e-10


# --- bad input ----------------------------------------------------------------
@pytest.mark.parametrize(
    "kwargs, argument",
    [
        (dict(span=0.0, dh=0.0, w=1.0, length=2.0), "span"),
        (dict(span=1.0, dh=0.0, w=-1.0, length=2.0), "w"),
        (dict(span=1.0, dh=float("nan"), w=1.0, length=2.0), "dh"),
        (dict(span=3.0, dh=4.0, w=1.0, length=5.0), "length"),  # = chord
        (dict(span=3.0, dh=4.0, w=1.0, length=4.9), "length"),
        (dict(span=3.0, dh=4.0, w=1.0, low=1.0), "low"),
        (dict(span=3.0, dh=4.0, w=1.0, low=0.0), "low"),
        (dict(span=3.0, dh=4.0, w=1.0, H=0.0), "H"),
        (dict(span=3.0, dh=4.0, w=1.0), "constraint"),
        (dict(span=3.0, dh=4.0, w=1.0, H=1.0, sag=1.0), "constraint"),
        (dict(span=3.0, dh=4.0, w=1.0, T_max=10.0, branch="loose"), "branch"),
    ],
)
def test_bad_input_names_the_argument(kwargs, argument):
    with pytest.raises(InputError) as info:
        cable.catenary(**kwargs)
    assert info.value.argument == argument
    assert isinstance(info.value, ValueError)


def test_bad_element_of_an_array_is_located():
    with pytest.raises(InputError, match=r"index \(1,\)"):
        cable.catenary(np.array([10.0, 10.0]), 0.0, 1.0, length=np.array([11.0, 9.0]))
