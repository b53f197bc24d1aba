"""Geometric stiffness (seed 001 ex. 7), end conditions (§3.4), surfaces (§4)."""

import functools

import mpmath as mp
import numpy as np
import pytest

from skcable import bvp, cable
from skcable.errors import InputError

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings("ignore:(mu)\\b:skcable.errors.PlausibilityWarning")


def test_seed001_ex7_catenary():
    # H = 10 Q: sinh(x/a) = 1/20 (seed eq. 26)
    c = cable.catenary(2.0, 0.0, 1.0, H=1 / np.arcsinh(0.05))
    Q = c.w * c.length
    assert round(c.a / 1.0, 8) == 20.00832744
    k = cable.geometric_stiffness(c) * 2.0 / Q  # in units Q/L
    assert round(k, 2) == 12021.99  # published
    xi = mp.asinh(mp.mpf("0.05"))
    assert k == pytest.approx(float(10 * xi / (xi - mp.tanh(xi))), rel=1e-13)  # 40 digits


def test_seed001_ex7_parabolic_approximation():
    # seed eq. (27): 1/20 = xi (1 + xi²/6), a/x = 1/xi
    roots = np.roots([1 / 6, 0, 1, -1 / 20])
    xi = roots[np.abs(roots.imag) < 1e-12].real[0]
    assert round(1 / xi, 8) == 20.00832640
    k = cable.geometric_stiffness_series(2.0, 10 * xi, 10.0) * 2.0 / 1.0
    assert round(k, 2) == 12024.99


@pytest.mark.parametrize("model", [cable.catenary, cable.parabola])
@pytest.mark.parametrize("dh", [0.0, 35.0, -80.0])
def test_geometric_stiffness_by_finite_differences(model, dh):
    sol = model(200.0, dh, 1.5, sag=15.0)
    d = 1e-4
    plus = model(200.0 + d, dh, 1.5, length=sol.length).H
    minus = model(200.0 - d, dh, 1.5, length=sol.length).H
    assert cable.geometric_stiffness(sol) == pytest.approx((plus - minus) / (2 * d), rel=1e-6)


def test_stiffness_in_series_with_elastic():
    c = cable.catenary(200.0, 0.0, 1.0, sag=10.0)
    kg = cable.geometric_stiffness(c)
    k = cable.geometric_stiffness(c, EA=1e5)
    assert 1 / k == pytest.approx(1 / kg + c.length / 1e5, rel=1e-14)


def test_ring_on_rough_rod_is_at_the_friction_limit():
    c = cable.ring_on_rod(5.0, 2.0, 100.0, 0.4)
    assert c.H == pytest.approx(0.4 * c.V_B, rel=1e-12)  # H = mu·Tz (seed §3.4.3)
    assert c.length == pytest.approx(100.0, rel=1e-12)
    assert c.y(c.span) == pytest.approx(5.0, rel=1e-10)
    with pytest.raises(InputError, match="mu"):
        cable.ring_on_rod(99.0, 1.0, 100.0, 1.0)


def test_anchor_block_weight():
    c = cable.catenary(100.0, 0.0, 1.0, sag=10.0)
    W = cable.anchor_block_weight(c, 0.5)
    # at the limit, friction mu (W - V) equals H
    assert 0.5 * (W - c.V_A) == pytest.approx(c.H, rel=1e-14)


def test_sliding_load_two_symmetric_arcs():
    s = cable.sliding_load(100.0, 1.0, 110.0, 20.0)
    assert s.residual() < 1e-12
    assert s.V_A == pytest.approx((110.0 + 20.0) / 2, rel=1e-12)
    # seed §3.4.5: T_Az = P/2 = q a sinh(x_A/a) at the load point
    assert -s.arc.V_B == pytest.approx(10.0, rel=1e-12)
    # no load: a plain catenary
    free = cable.sliding_load(100.0, 1.0, 110.0, 0.0)
    assert free.H == pytest.approx(cable.catenary(100.0, 0.0, 1.0, length=110.0).H, rel=1e-10)


def test_capstan_and_membrane():
    assert cable.capstan(100.0, 0.3, np.pi) == pytest.approx(100.0 * np.exp(0.3 * np.pi))
    # two half turns compose: T(phi1 + phi2) = T(T(phi1), phi2)
    assert cable.capstan(cable.capstan(5.0, 0.2, 1.0), 0.2, 2.0) == pytest.approx(
        cable.capstan(5.0, 0.2, 3.0)
    )
    assert cable.membrane_tension(2e5, 1.5) == 3e5
    with pytest.raises(InputError, match="mu"):
        cable.capstan(1.0, -0.1, 1.0)


def test_sphere_parallel_by_force_balance():
    # independent: on a parallel of radius rho = R cos(alpha), the thread pulls
    # inward T/rho; the sphere pushes along its normal: vertical Q sin = q,
    # horizontal Q cos = T / rho
    q, R, alpha = 3.0, 2.0, 0.6
    T, Q = cable.sphere_parallel(q, R, alpha)
    assert Q * np.sin(alpha) == pytest.approx(q)
    assert Q * np.cos(alpha) == pytest.approx(T / (R * np.cos(alpha)))


def test_smooth_surface_reaction():
    # geodesic on a cylinder of radius 2 around its section: Q = -T/R
    assert cable.smooth_surface_reaction(10.0, 2.0) == -5.0
    with pytest.raises(InputError, match="R_n"):
        cable.smooth_surface_reaction(10.0, 0.0)


# --- issue #14: finite, right numbers at extreme magnitudes ---------------------------
def test_geometric_stiffness_series_at_extreme_magnitudes():
    # k = 3H/(2 span) + 12 H³/(w² span³), in 40 digits
    mp.mp.dps = 40
    for span, w, H in [(1e-300, 1.0, 1e-300), (1e300, 1e300, 1.0), (1.0, 1e-300, 1e-100), (2.0, 0.5, 10.0)]:
        exact = 1.5 * mp.mpf(H) / span + 12 * mp.mpf(H) ** 3 / (mp.mpf(w) ** 2 * mp.mpf(span) ** 3)
        assert cable.geometric_stiffness_series(span, w, H) == pytest.approx(float(exact), rel=1e-14)
    with pytest.raises(InputError, match="span, w, H"):
        cable.geometric_stiffness_series(1e-300, 1.0, 1.0)  # 12/1e-900: beyond the float range


def test_parabola_stiffness_for_taut_cables_against_mpmath():
    # dH/dspan at constant length and dh, from the exact length by 40-digit differentiation;
    # the textbook form S/a - delta (r_A + r_B) loses every digit for taut cables
    mp.mp.dps = 40

    def length(a, span, dh):
        p_a, p_b = dh / span - span / (2 * a), dh / span + span / (2 * a)

        def F(q):
            return q * mp.sqrt(1 + q * q) + mp.asinh(q)

        return a / 2 * (F(p_b) - F(p_a))

    def length_at_span(span, a, dh):
        return length(a, span, dh)

    for dh, H in [(30.0, 1e4), (30.0, 1e10), (0.0, 1e8), (-3000.0, 1e6), (30.0, 20.0)]:
        p = cable.parabola(100.0, dh, 1.0, H=H)
        a, span, h = mp.mpf(H), mp.mpf(100), mp.mpf(dh)
        d_span = mp.diff(functools.partial(length_at_span, a=a, dh=h), span)
        d_a = mp.diff(functools.partial(length, span=span, dh=h), a)
        exact = -d_span / d_a
        assert cable.geometric_stiffness(p) == pytest.approx(float(exact), rel=1e-13), (dh, H)


def test_catenary_stiffness_when_z_cubed_underflows():
    # k_G = w/(2(z - tanh z)) ~ 3w/(2 z³): here z = span w/(2H) = 1e-150, z³ underflows,
    # but w = 1e-200 brings k_G back to 1.5e250
    c = cable.catenary(100.0, 0.0, 1e-200, H=5e-49)
    with mp.workdps(340):  # z - tanh z = z³/3 + ... cancels 300 digits
        z = mp.mpf(100) * mp.mpf("1e-200") / (2 * mp.mpf("5e-49"))
        exact = mp.mpf("1e-200") / (2 * (z - mp.tanh(z)))
    assert cable.geometric_stiffness(c) == pytest.approx(float(exact), rel=1e-13)
    with pytest.raises(InputError, match="solution"):
        cable.geometric_stiffness(cable.catenary(100.0, 0.0, 1.0, H=1e151))  # 3/(2 z³) = 1.2e448


def test_capstan_and_sphere_at_extreme_magnitudes():
    mp.mp.dps = 40
    # e^1000 is beyond the float range, 1e-300·e^1000 is not
    assert cable.capstan(1e-300, 10.0, 100.0) == pytest.approx(
        float(mp.mpf("1e-300") * mp.exp(1000)), rel=1e-13
    )
    assert cable.capstan(np.array([1e-300, 1.0]), 10.0, np.array([100.0, 1.0])) == pytest.approx(
        [float(mp.mpf("1e-300") * mp.exp(1000)), float(mp.exp(10))], rel=1e-13
    )
    with pytest.raises(InputError, match="T0, mu, angle"):
        cable.capstan(1.0, 1e300, 1e300)  # mu·angle overflows: so does the tension
    # T = q R cos²/sin, Q = q/sin: q R = 1e-300·1e300 = 1; latitude 1e-300: Q = q/sin = 1e300·q
    T, Q = cable.sphere_parallel(1e-300, 1e300, 0.6)
    assert T == pytest.approx(float(mp.cos(mp.mpf(0.6)) ** 2 / mp.sin(mp.mpf(0.6))), rel=1e-14)
    T, Q = cable.sphere_parallel(1e-10, 1e-10, 1e-300)
    assert (T, Q) == pytest.approx((float(mp.mpf("1e-20") / mp.sin(mp.mpf("1e-300"))), 1e290), rel=1e-14)
    with pytest.raises(InputError, match="q, R, latitude"):
        cable.sphere_parallel(1.0, 1.0, 1e-320)  # T = 1e320
    assert cable.smooth_surface_reaction(1e300, -1e-7) == pytest.approx(1e307, rel=1e-15)
    with pytest.raises(InputError, match="T, R_n"):
        cable.smooth_surface_reaction(1e300, 1e-300)


def test_sliding_load_and_ring_at_extreme_ratios():
    # a slack cable 1e6 spans long: each arc a catenary of half the length, the load carried by V = P/2
    s = cable.sliding_load(1.0, 1.0, 1e6, 1e8)
    assert s.residual() < 1e-12
    assert s.V_A == pytest.approx((1e6 + 1e8) / 2, rel=1e-12)  # vertical equilibrium of the whole
    # the unloaded limit is the catenary of the same length
    assert cable.sliding_load(1.0, 1.0, 1e6, 0.0).H == pytest.approx(
        cable.catenary(1.0, 0.0, 1.0, length=1e6).H, rel=1e-10
    )
    # ring on a nearly smooth rod (mu = 1e-6): H = mu V_B still holds at the limit
    c = cable.ring_on_rod(5.0, 2.0, 100.0, 1e-6)
    assert c.H == pytest.approx(1e-6 * c.V_B, rel=1e-9) and c.length == pytest.approx(100.0, rel=1e-12)


# --- fairlead stiffness d(H, V_B)/d(span, dh) of every closed form ------------------------


def _mp_catenary_forces(span, dh, w, S):
    """(H, V_B) of the inextensible catenary at 40 digits: S² - dh² = (2a sinh(span/2a))²."""
    mp.mp.dps = 40
    span, dh = mp.mpf(span), mp.mpf(dh)
    z = mp.findroot(
        lambda z: mp.sinh(z) / z - mp.sqrt(S**2 - dh**2) / span, mp.mpf(0.5), tol=mp.mpf(10) ** -38
    )
    a = span / (2 * z)
    return w * a, w * (S + dh / mp.tanh(z)) / 2  # V_B = (wS + w dh coth z)/2


@pytest.mark.parametrize(
    ("span", "dh", "excess"), [(100, 20, 0.1), (100, -30, 0.05), (100, 0, 1e-6), (80, 50, 1.5)]
)
def test_fairlead_stiffness_catenary_against_mpmath_derivatives(span, dh, excess):
    w = 10.0
    S = float(np.hypot(span, dh)) * (1 + excess)
    c = cable.catenary(float(span), float(dh), w, length=S)
    K = c.stiffness()
    np.testing.assert_array_equal(cable.fairlead_stiffness(c), K)
    mp.mp.dps = 40
    S_mp, h = mp.mpf(S), mp.mpf(10) ** -12  # central differences at 40 digits: error ~ h² ~ 1e-24
    ref = np.empty((2, 2))
    for j, (ds, dd) in enumerate(((h, 0), (0, h))):
        plus = _mp_catenary_forces(span + ds, dh + dd, w, S_mp)
        minus = _mp_catenary_forces(span - ds, dh - dd, w, S_mp)
        ref[:, j] = [float((p - m) / (2 * h)) for p, m in zip(plus, minus, strict=True)]
    np.testing.assert_allclose(K, ref, rtol=1e-11)
    assert cable.geometric_stiffness(c) == K[0, 0] == c.k_G


def _central(make, span, dh, h):
    out = np.empty((2, 2))
    for j, (ds, dd) in enumerate(((h, 0.0), (0.0, h))):
        p, m = make(span + ds, dh + dd), make(span - ds, dh - dd)
        out[:, j] = [(p.H - m.H) / (2 * h), (p.V_B - m.V_B) / (2 * h)]
    return out


@pytest.mark.parametrize(
    ("span", "dh", "L"), [(100.0, 20.0, 110.0), (100.0, -30.0, 105.0), (100.0, 0.0, 100.5)]
)
def test_fairlead_stiffness_parabola_against_central_differences(span, dh, L):
    # w per horizontal length: V_B = H dh/span + w span/2, K is not symmetric
    p = cable.parabola(span, dh, 10.0, length=L)
    K = p.stiffness()
    np.testing.assert_array_equal(cable.fairlead_stiffness(p), K)
    assert p.k_G == K[0, 0] == cable.geometric_stiffness(p)
    K_fd = _central(lambda s, d: cable.parabola(s, d, 10.0, length=L), span, dh, 1e-4)
    np.testing.assert_allclose(K, K_fd, rtol=1e-7, atol=1e-7 * np.abs(K).max())


def test_fairlead_stiffness_elastic_tends_to_catenary_and_matches_moorpy():
    moorpy_catenary = pytest.importorskip("moorpy.Catenary").catenary
    c = cable.fairlead_stiffness(cable.catenary(100.0, 20.0, 10.0, length=110.0))
    e = cable.elastic_catenary(100.0, 20.0, 10.0, 1e15, length=110.0)
    np.testing.assert_allclose(e.stiffness(), c, rtol=1e-9)
    assert cable.geometric_stiffness(e) == e.stiffness()[0, 0]
    with pytest.raises(InputError, match="EA"):
        cable.geometric_stiffness(e, EA=1e9)
    # a free line: MoorPy's stiffness without seabed contact (CB < 0)
    e = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0)
    info = moorpy_catenary(800.0, 150.0, 850.0, 5e8, 1000.0, CB=-1e3, Tol=1e-12)[4]
    np.testing.assert_allclose(e.stiffness(), info["stiffnessB"], rtol=1e-8)


def test_fairlead_stiffness_broadcasts_and_refuses_other_solutions():
    span, dh = np.array([100.0, 100.0, 80.0]), np.array([20.0, -30.0, 50.0])
    for solution in (
        cable.catenary(span, dh, 10.0, length=120.0),
        cable.parabola(span, dh, 10.0, length=120.0),
        cable.elastic_catenary(span, dh, 10.0, 1e6, length=120.0),
    ):
        K = cable.fairlead_stiffness(solution)
        assert K.shape == (3, 2, 2)
        for i in range(3):
            one = type(solution).__name__.lower()
            kwargs = {"EA": 1e6} if one == "elasticcatenary" else {}
            make = {"catenary": cable.catenary, "parabola": cable.parabola}.get(one, cable.elastic_catenary)
            single = make(span[i], dh[i], 10.0, length=120.0, **kwargs)
            np.testing.assert_allclose(K[i], cable.fairlead_stiffness(single), rtol=1e-12)
    with pytest.raises(InputError, match="solution"):
        cable.fairlead_stiffness(bvp.solve_bvp)  # not a closed-form solution
