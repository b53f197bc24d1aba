"""Elastic catenary: limits, an independent ODE integration, stretch."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from skcable import cable
from skcable.cable import ElasticCatenary
from skcable.errors import InputError, PlausibilityWarning


def test_tends_to_inextensible_catenary():
    ref = cable.catenary(800.0, -20.0, 20.0, length=801.409)
    errors = []
    for EA in (1e9, 1e11, 1e13, 1e15):
        e = cable.elastic_catenary(800.0, -20.0, 20.0, EA, length=801.409)
        errors.append(abs(e.H / ref.H - 1))
        assert e.residual() < 1e-12
    # the stretch, hence the error, falls as 1/EA
    assert errors[-1] < 1e-5 and all(b < a / 50 for a, b in zip(errors, errors[1:], strict=False))


def test_against_ode_integration_of_equilibrium():
    # integrate dx/ds = H/EA + H/T, dy/ds = Tv/EA + Tv/T independently
    e = cable.elastic_catenary(150.0, 30.0, 9.0, 2e5, length=160.0)

    def rhs(s, state):
        tv = 9.0 * s - e.V_A
        T = np.hypot(e.H, tv)
        return [e.H / 2e5 + e.H / T, tv / 2e5 + tv / T, T / 2e5 + 1.0]

    sol = solve_ivp(rhs, (0, 160.0), [0.0, 0.0, 0.0], rtol=1e-12, atol=1e-12)
    x_end, y_end, stretched = sol.y[:, -1]
    assert x_end == pytest.approx(150.0, rel=1e-9)
    assert y_end == pytest.approx(30.0, rel=1e-8)
    assert e.stretched_length == pytest.approx(stretched + 0.0, rel=1e-9)
    mid = solve_ivp(rhs, (0, 80.0), [0.0, 0.0, 0.0], rtol=1e-12, atol=1e-12).y[:, -1]
    assert e.y(mid[0]) == pytest.approx(mid[1], rel=1e-8)


def test_cable_shorter_than_chord_stretches_like_a_bar():
    # nearly weightless: H ≈ EA (chord/L0 - 1)
    e = cable.elastic_catenary(100.0, 0.0, 1e-6, 1e6, length=99.0)
    assert e.H == pytest.approx(1e6 * (100.0 / 99.0 - 1), rel=1e-6)
    assert e.stretched_length == pytest.approx(100.0, rel=1e-9)


def test_vectorised_matches_scalar():
    spans, dhs, L0 = (
        np.array([800.0, 10.0, 1.0]),
        np.array([-20.0, 50.0, -1000.0]),
        np.array([801.409, 100.0, 1000.01]),
    )
    v = cable.elastic_catenary(spans, dhs, 20.0, 1e9, length=L0)
    for i in range(3):
        s = cable.elastic_catenary(spans[i], dhs[i], 20.0, 1e9, length=L0[i])
        # both closed to 1e-13·chord; H moves ~40 kN per m of closure here
        assert v.H[i] == pytest.approx(s.H, rel=1e-10)
        assert v.V_A[i] == pytest.approx(s.V_A, rel=1e-10, abs=1e-9)


def test_bad_input():
    with pytest.raises(InputError, match="EA"):
        cable.elastic_catenary(100.0, 0.0, 1.0, 0.0, length=110.0)
    with pytest.raises(InputError, match="length"):
        cable.elastic_catenary(100.0, 0.0, 1.0, 1e6, length=-1.0)


def test_lowest_point_and_vertex_tend_to_the_inextensible_ones():
    # issue #14: x_low, y_low is a point of the cable; the vertex may lie beyond a support
    for dh, length in [(-20.0, 801.409), (-300.0, 870.0), (300.0, 870.0)]:
        ref = cable.catenary(800.0, dh, 20.0, length=length)
        e = cable.elastic_catenary(800.0, dh, 20.0, 1e15, length=length)
        assert e.x_vertex == pytest.approx(ref.x_vertex, rel=1e-7)
        assert e.y_vertex == pytest.approx(ref.y_vertex, rel=1e-7)
        assert (e.x_low, e.y_low) == pytest.approx((ref.x_low, ref.y_low), rel=1e-7, abs=1e-9)
    assert (e.x_low, e.y_low) == (0.0, 0.0) and e.x_vertex < 0  # B far above A: the cable rises from A
    with pytest.raises(InputError, match="s"):
        e.x_of_s(1e300)


def test_strongly_stretched_line_stops_at_the_round_off_of_its_terms():
    # strain w L/EA ~ 1.7e4: the closure's terms are 1e4 times the span, and its
    # residual cannot fall below their round-off; against Irvine's equations at 40 digits
    import mpmath as mp

    span, dh, w, EA, L = 1800.988193505437, 16.54946719505425, 932.2190796045037, 100.4200470840098, 1809.31
    with pytest.warns(PlausibilityWarning, match="EA"):  # no material stretches so
        e = cable.elastic_catenary(span, dh, w, EA, length=L)
    mp.mp.dps = 40
    span_, dh_, w_, EA_, L_ = (mp.mpf(v) for v in (span, dh, w, EA, L))

    def closure(H, VA):
        VB = w_ * L_ - VA
        X = H * L_ / EA_ + H / w_ * (mp.asinh(VB / H) - mp.asinh(-VA / H))
        Z = L_ * (w_ * L_ / 2 - VA) / EA_ + (mp.sqrt(H**2 + VB**2) - mp.sqrt(H**2 + VA**2)) / w_
        return [X - span_, Z - dh_]

    H, VA = mp.findroot(closure, (mp.mpf(e.H), mp.mpf(e.V_A)), tol=mp.mpf(10) ** -30)
    assert e.H == pytest.approx(float(H), rel=1e-10)
    assert e.V_A == pytest.approx(float(VA), rel=1e-10, abs=1e-10 * float(H))


# -- issue 26, D1 and D2: an independent 50-digit oracle ---------------------------------------
def irvine_root(span, dh, w, EA, L, dps=50):
    """``(H, V_A)`` of Irvine's closure at ``dps`` digits, independently of skcable: a damped
    Newton in mpmath from the inextensible catenary (or the stretched bar)."""
    import mpmath as mp

    with mp.workdps(dps):
        span, dh, w, EA, L = (mp.mpf(v) for v in (span, dh, w, EA, L))
        chord = mp.sqrt(span**2 + dh**2)

        def closure(H, V):
            VB = w * L - V
            X = H * L / EA + H / w * (mp.asinh(VB / H) - mp.asinh(-V / H))
            Y = L * (w * L / 2 - V) / EA + (mp.sqrt(H**2 + VB**2) - mp.sqrt(H**2 + V**2)) / w
            return X - span, Y - dh

        def jacobian(H, V):
            VB = w * L - V
            TA, TB = mp.sqrt(H**2 + V**2), mp.sqrt(H**2 + VB**2)
            arc = mp.asinh(VB / H) - mp.asinh(-V / H)
            j_xv = H / w * (1 / TA - 1 / TB)
            return L / EA + (arc - VB / TB - V / TA) / w, j_xv, -j_xv, -L / EA - (V / TA + VB / TB) / w

        longer = max(L, chord * (1 + mp.mpf("1e-3")))
        r = mp.sqrt(longer**2 - dh**2) / span
        z = mp.findroot(
            lambda z: mp.log(mp.sinh(z) / z / r), (mp.mpf("1e-20"), mp.mpf(800)), solver="anderson"
        )
        H_cat = w * span / (2 * z)
        H = max(H_cat, EA * (chord / L - 1) * span / chord)
        V = (w * longer - w * dh / mp.tanh(z)) / 2 * H / H_cat
        for _ in range(500):
            f = closure(H, V)
            merit = max(abs(f[0]), abs(f[1])) / chord
            if merit < mp.mpf(10) ** (8 - dps):
                return H, V
            a, b, c, d = jacobian(H, V)
            det = a * d - b * c
            dH, dV = -(f[0] * d - f[1] * b) / det, -(a * f[1] - c * f[0]) / det
            t = mp.mpf(1)
            while not (H + t * dH > 0 and max(map(abs, closure(H + t * dH, V + t * dV))) / chord < merit):
                t /= 2
            H, V = H + t * dH, V + t * dV
        raise AssertionError("the oracle did not converge")


def irvine_bound(span, dh, w, EA, L, H, V):
    """Relative error in H that one ulp of each term of the two closure equations allows at the
    root (J⁻¹ applied to the terms' round-off), in mpmath: the floor of any float solver."""
    import mpmath as mp

    with mp.workdps(30):
        span, dh, w, EA, L, H, V = (mp.mpf(v) for v in (span, dh, w, EA, L, H, V))
        VB = w * L - V
        TA, TB = mp.sqrt(H**2 + V**2), mp.sqrt(H**2 + VB**2)
        arc = mp.asinh(VB / H) - mp.asinh(-V / H)
        a, b = L / EA + (arc - VB / TB - V / TA) / w, H / w * (1 / TA - 1 / TB)
        c, d = -b, -L / EA - (V / TA + VB / TB) / w
        terms_x = H * L / EA + H / w * arc + span
        terms_y = L * (w * L / 2 + abs(V)) / EA + abs(TB - TA) / w + abs(dh) + L
        return float((abs(d) * terms_x + abs(b) * terms_y) * mp.mpf(2) ** -52 / abs(a * d - b * c) / H)


def assert_root(solution, args, factor=32.0):
    """H within 1e-12 of the 50-digit root, or within ``factor`` times the floor where the
    scene allows no better (its H is that ill-conditioned)."""
    H, V = irvine_root(*args)
    tol = max(1e-12, factor * irvine_bound(*args, H, V))
    assert abs(solution.H / float(H) - 1) <= tol, (solution.H, float(H), tol)
    T = max(solution.T_A, solution.T_B)
    assert abs(solution.V_A - float(V)) <= tol * T, (solution.V_A, float(V))


def test_taut_steep_line_keeps_its_digits():
    # D1: wL/H ~ 1.6e-12 against V_A/H ~ 1.15: the arc asinh(V_B/H) - asinh(-V_A/H) of the
    # rounded ratios cancelled, H came out 5.66173e10 against 5.66673e10, and residual() agreed
    args = (
        0.2332264670872486,
        -0.26928872264561327,
        0.2670976622234697,
        1037758168845.9086,
        0.3288194802156623,
    )
    e = cable.elastic_catenary(*args[:4], length=args[4])
    H, V = irvine_root(*args)
    assert abs(e.H / float(H) - 1) <= 1e-12 and abs(e.V_A / float(V) - 1) <= 1e-12
    # the residual, evaluated by another formula, sees the old answer
    wrong = ElasticCatenary(*args, 5.66173e10, e.V_A * 5.66173e10 / e.H, ("length", args[4]))
    assert wrong.residual() > 1e-6
    assert e.residual() < 1e-14


def test_steel_wire_converges_in_any_unit_system():
    # D2: a 2.34 m steel wire at 0.68 % strain stalled at 1.33e-13 against a tighter bound
    span, dh, w, EA, L = (
        2.1958015558525883,
        -0.8647353183964065,
        8.075179402033653,
        18565645.32965864,
        2.344012229866921,
    )
    e = cable.elastic_catenary(span, dh, w, EA, length=L)
    assert_root(e, (span, dh, w, EA, L))
    for k_length, k_force in [(10.0, 1.0), (1000.0, 1.0), (1.0, 10.0), (1.0, 1000.0), (1000.0, 1e-3)]:
        args = (span * k_length, dh * k_length, w * k_force / k_length, EA * k_force, L * k_length)
        scaled = cable.elastic_catenary(*args[:4], length=args[4])
        assert_root(scaled, args)
        assert scaled.H / k_force == pytest.approx(e.H, rel=1e-12)


def test_nearly_vertical_line_closes_its_horizontal_equation_at_its_own_round_off():
    # span 1e-20 m under dh = 30 m: X is 1e21 times smaller than Y, and a test of both against
    # the chord left H wrong by 9e-11
    e = cable.elastic_catenary(1e-20, 30.0, 2.0, 1e6, length=120.0)
    assert_root(e, (1e-20, 30.0, 2.0, 1e6, 120.0))
    assert abs(e.H / float(irvine_root(1e-20, 30.0, 2.0, 1e6, 120.0)[0]) - 1) < 1e-14
