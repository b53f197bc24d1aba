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


# --- issue #14: residuals sized to their round-off ---------------------------------
def mp_catenary_state(span, dh, w, a):
    """40-digit H, V_A, V_B, T_A, T_B, length of the catenary with parameter ``a``."""
    span, dh, w, a = (mp.mpf(v) for v in (span, dh, w, a))
    z = span / (2 * a)
    m = mp.asinh(dh / span * z / mp.sinh(z))
    H = w * a
    return {
        "H": H,
        "V_A": H * mp.sinh(z - m),
        "V_B": H * mp.sinh(z + m),
        "T_A": H * mp.cosh(m - z),
        "T_B": H * mp.cosh(m + z),
        "length": 2 * a * mp.sinh(z) * mp.cosh(m),
    }


def test_taut_inclined_cable_passes_its_own_check():
    # V_A ≈ -3e9 and V_B ≈ 3e9 balance a weight of 104: the old vertical
    # equilibrium residual (relative to the weight) was 5.7e-9 from round-off alone
    c = cable.catenary(100.0, 30.0, 1.0, H=1e10)
    assert c.residual() < 1e-15
    for name, exact in mp_catenary_state(100.0, 30.0, 1.0, 1e10).items():
        assert getattr(c, name) == pytest.approx(float(exact), rel=1e-14), name
    p = cable.parabola(100.0, 30.0, 1.0, H=1e10)
    assert p.residual() < 1e-15
    # parabola, seed 000 §2: V_A = w span/2 - H dh/span
    assert p.V_A == pytest.approx(50.0 - 1e10 * 0.3, rel=1e-15)


def random_low_scenes(n=1000, seed=141):
    """Vertex from 1e-10 to 1e8 spans below the lower support, any chord slope in ±2."""
    rng = np.random.default_rng(seed)
    span = 10 ** rng.uniform(0, 3, n)
    dh = span * rng.uniform(-2, 2, n)
    w = 10 ** rng.uniform(-2, 4, n)
    depth = span * 10 ** rng.uniform(-10, 8, n)
    return span, dh, w, np.minimum(0.0, dh) - depth


def random_T_max_scenes(n=1000, seed=142):
    """Counterweights from 2 to 1e10 times the weight of a span's cable."""
    rng = np.random.default_rng(seed)
    span = 10 ** rng.uniform(0, 3, n)
    dh = span * rng.uniform(-2, 2, n)
    w = 10 ** rng.uniform(-2, 4, n)
    return span, dh, w, w * span * 10 ** rng.uniform(0.3, 10, n)


def test_1000_random_low_scenes_in_one_array_call():
    # before the fix 163 of these failed their own check (deep vertices: the
    # constraint residual was relative to the chord, not to the depth)
    span, dh, w, low = random_low_scenes()
    c = cable.catenary(span, dh, w, low=low)
    assert c.residual() < 1e-12
    # the vertex is the lowest point; its depth is right to the round-off of the scene
    assert np.all((c.x_low > 0) & (c.x_low < span))
    assert np.all(np.abs(c.y_low - low) <= 1e-13 * (np.hypot(span, dh) + np.abs(low)))
    # 40-digit references: 2a[asinh sqrt(d_A/2a) + asinh sqrt(d_B/2a)] = span (vertex inside)
    mp.mp.dps = 40
    for i in range(0, 1000, 40):
        a = mp_root_in(mp_low_equation(span[i], dh[i], low[i]), c.a[i])
        exact = mp_catenary_state(span[i], dh[i], w[i], a)
        for name in ("H", "T_A", "T_B", "length"):
            assert getattr(c, name)[i] == pytest.approx(float(exact[name]), rel=1e-11), (i, name)


def mp_low_equation(span, dh, low):
    """f(a) = 2a[asinh sqrt(d_A/2a) + asinh sqrt(d_B/2a)] - span: the vertex d_A below A, d_B below B."""
    d_a, d_b, span = -mp.mpf(low), mp.mpf(dh) - mp.mpf(low), mp.mpf(span)
    return lambda a: 2 * a * (mp.asinh(mp.sqrt(d_a / (2 * a))) + mp.asinh(mp.sqrt(d_b / (2 * a)))) - span


def mp_T_max_equation(span, dh, w, T_max):
    """g(a) = w a cosh(|m| + z) - T_max, z = span/2a, sinh m = (dh/span) z / sinh z."""
    span, dh, w, T_max = (mp.mpf(v) for v in (span, dh, w, T_max))

    def g(a):
        z = span / (2 * a)
        return w * a * mp.cosh(abs(mp.asinh(dh / span * z / mp.sinh(z))) + z) - T_max

    return g


def mp_root_in(f, near):
    """The 40-digit root of f within 1e-6 (relative) of ``near``: it must be bracketed there."""
    near = mp.mpf(near)
    return mp.findroot(f, (near * (1 - mp.mpf("1e-6")), near * (1 + mp.mpf("1e-6"))), solver="anderson")


def test_1000_random_T_max_scenes_in_one_array_call():
    # before the fix 262 of these failed their own check (taut cables: V_A and
    # V_B cancel in the vertical equilibrium)
    span, dh, w, T_max = random_T_max_scenes()
    for branch in ("taut", "slack"):
        c = cable.catenary(span, dh, w, T_max=T_max, branch=branch)
        assert c.residual() < 1e-10
        assert c.T_max == pytest.approx(T_max, rel=1e-10)
    taut = cable.catenary(span, dh, w, T_max=T_max)
    mp.mp.dps = 40
    for i in range(0, 1000, 40):
        a = mp_root_in(mp_T_max_equation(span[i], dh[i], w[i], T_max[i]), taut.a[i])
        exact = mp_catenary_state(span[i], dh[i], w[i], a)
        for name in ("H", "V_A", "V_B", "length"):
            assert getattr(taut, name)[i] == pytest.approx(float(exact[name]), rel=1e-10), (i, name)


# --- issue #14: the lowest point of the cable, and the vertex -------------------------
def test_lowest_point_is_a_support_when_the_vertex_lies_beyond_it():
    # B 150 m below A on a 646 m span, taut: the vertex is thousands of metres
    # past B, and the lowest point of the cable is B itself
    c = cable.catenary(646.0, -150.0, 10.0, H=2e5)
    assert c.x_vertex > 5 * 646.0
    assert (c.x_low, c.y_low) == (646.0, -150.0)
    x = np.linspace(0.0, 646.0, 200_001)
    assert np.min(c.y(x)) == pytest.approx(c.y_low, abs=1e-9)  # brute force: B is lowest
    # the vertex: zero slope there, and y(x_vertex) on the continued catenary
    assert abs(c.slope(c.x_vertex)) < 1e-12
    assert c.y(c.x_vertex) == pytest.approx(c.y_vertex, rel=1e-12)
    # seed 000 §3: the vertex lies a·asinh(V_A/H) right of A (V_A < 0 here: the cable falls from A)
    assert c.x_vertex == pytest.approx(c.a * np.arcsinh(c.V_A / c.H), rel=1e-12)
    # mirrored: the vertex lies left of A and the lowest point is A
    m = cable.catenary(646.0, 150.0, 10.0, H=2e5)
    assert (m.x_low, m.y_low) == (0.0, 0.0)
    assert m.x_vertex == pytest.approx(646.0 - c.x_vertex, rel=1e-12)


def test_lowest_point_and_vertex_agree_inside_the_span_and_broadcast():
    c = cable.catenary(800.0, -20.0, 20.0, low=-30.0)  # seed 000 ex. 4
    assert (c.x_low, c.y_low) == (c.x_vertex, c.y_vertex)
    assert c.y_low == pytest.approx(-30.0, rel=1e-13)
    spans = np.array([800.0, 646.0, 646.0])
    v = cable.catenary(
        spans, np.array([-20.0, -150.0, 150.0]), np.array([20.0, 10.0, 10.0]), H=np.array([85819.2, 2e5, 2e5])
    )
    assert v.x_low[1:].tolist() == [646.0, 0.0] and v.y_low[1:].tolist() == [-150.0, 0.0]
    assert v.x_low[0] == v.x_vertex[0] and v.y_low[0] == v.y_vertex[0]
    for i in range(3):
        s = cable.catenary(spans[i], v.dh[i], v.w[i], H=v.H[i])
        assert (s.x_low, s.y_low, s.x_vertex, s.y_vertex) == pytest.approx(
            (v.x_low[i], v.y_low[i], v.x_vertex[i], v.y_vertex[i]), rel=1e-13
        )
    assert "x_vertex=" in repr(c)
