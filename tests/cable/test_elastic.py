"""Elastic catenary: limits, an independent ODE integration, stretch."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from skcable import cable
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
