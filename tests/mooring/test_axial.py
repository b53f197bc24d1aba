"""Axial strain laws and their integrals along a catenary, against closures written here in
mpmath (quadrature and findroot) with the same ε(T)."""

import pickle

import mpmath as mp
import numpy as np
import pytest
from scipy.interpolate import PchipInterpolator

from skcable import cable
from skcable.errors import InputError
from skcable.mooring.axial import (
    ConstantEA,
    StaticDynamicRope,
    StrainFunction,
    StrainTable,
    catenary_ends,
    catenary_quadrature,
    elongation,
    law_catenary,
    strain_law,
)

EA, TREF = 5e8, 2e6


def log_strain(T):  # a rope that stiffens with the load: ε = (T*/EA) ln(1 + T/T*)
    return TREF / EA * np.log1p(T / TREF)


def log_slope(T):
    return 1.0 / (EA * (1.0 + T / TREF))


LOG = StrainFunction(log_strain, log_slope)
# a polyester-like working curve (strain, tension) as a table
TABLE_EPS = np.array([0.0, 0.004, 0.009, 0.015, 0.022, 0.03])
TABLE_T = np.array([0.0, 1.2e5, 3.4e5, 6.6e5, 1.1e6, 1.7e6])
TABLE = StrainTable(TABLE_EPS, TABLE_T)


def mp_closure(span, dh, w, L, eps, cuts=lambda H, V0: [], dps=30):
    """(H, V_A) of the hanging segment by mpmath: x = ∫(1 + ε)H/T ds, z = ∫(1 + ε)V/T ds,
    T = sqrt(H² + (V0 + w s)²), with the interval split at ``cuts(H, V0)`` (the arc lengths of
    the law's kinks)."""
    mp.mp.dps = 30

    def ends(H, V0):
        pts = [mp.mpf(0), *sorted(c for c in cuts(H, V0) if 0 < c < L), mp.mpf(L)]

        def f(s, which):
            V = V0 + w * s
            T = mp.sqrt(H * H + V * V)
            return (1 + eps(T)) * (H if which == 0 else V) / T

        return [mp.quad(lambda s: f(s, 0), pts) - span, mp.quad(lambda s: f(s, 1), pts) - dh]

    start = cable.elastic_catenary(span, dh, w, EA, length=L)
    H, V0 = mp.findroot(lambda H, V0: ends(H, V0), (mp.mpf(start.H), mp.mpf(-start.V_A)), tol=1e-20)
    return float(H), float(-V0)


def mp_log(T):
    return mp.mpf(TREF) / EA * mp.log(1 + T / TREF)


def test_a_nonlinear_law_catenary_matches_an_mpmath_closure():
    span, dh, w, L = 780.0, 186.0, 1000.0, 850.0
    line = law_catenary(span, dh, w, LOG, length=L)
    H, V_A = mp_closure(span, dh, w, L, mp_log)
    assert line.H == pytest.approx(H, rel=1e-9) and line.V_A == pytest.approx(V_A, rel=1e-9)
    # the law matters: the constant EA at zero load gives a line 1e-3 softer
    plain = cable.elastic_catenary(span, dh, w, EA, length=L)
    assert abs(plain.H / H - 1) > 1e-4


def test_a_tabulated_law_catenary_matches_an_mpmath_closure_split_at_its_points():
    span, dh, w, L = 600.0, 300.0, 300.0, 690.0
    curve = PchipInterpolator(TABLE_T, TABLE_EPS)

    def eps(T):
        return mp.mpf(float(curve(float(T))))

    def cuts(H, V0):  # where T(s) passes a point of the table: V = ±sqrt(T_k² - H²)
        out = []
        for Tk in TABLE_T[1:]:
            if Tk > H:
                for V in (mp.sqrt(Tk * Tk - H * H), -mp.sqrt(Tk * Tk - H * H)):
                    out.append((V - V0) / w)
        return out

    line = law_catenary(span, dh, w, TABLE, length=L)
    assert np.max(line.T_of_s(np.array([0.0, L]))) < TABLE_T[-1]  # the line stays inside the table
    H, V_A = mp_closure(span, dh, w, L, eps, cuts, dps=17)  # ε in floats: 17 digits are all there is
    assert line.H == pytest.approx(H, rel=1e-9) and line.V_A == pytest.approx(V_A, rel=1e-9)


def test_constant_ea_is_irvines_elastic_catenary():
    for span, dh, L in ((780.0, 186.0, 850.0), (300.0, -40.0, 420.0), (100.0, 300.0, 330.0)):
        line = law_catenary(span, dh, 400.0, 3e8, length=L)
        ref = cable.elastic_catenary(span, dh, 400.0, 3e8, length=L)
        assert line.H == pytest.approx(ref.H, rel=1e-12) and line.V_A == pytest.approx(ref.V_A, rel=1e-12)


@pytest.mark.parametrize(
    ("H", "V0", "w"),
    [(2e3, -5e4, 300.0), (1e-3, -3e4, 300.0), (5e5, 1e5, -200.0), (4e4, 1e3, 1e-9), (0.0, -2e4, 150.0)],
    ids=["slack", "nearly vertical", "buoyant", "nearly weightless", "vertical"],
)
def test_the_elastic_integrals_match_mpmath_quadrature(H, V0, w):
    L = 200.0
    e = elongation(LOG, H, V0, w, L)
    mp.mp.dps = 30
    zero = [] if (V0 > 0) == (V0 + w * L > 0) else [mp.mpf(-V0) / w]  # V = 0 inside: |V|'s kink

    def quad(g):
        return float(mp.quad(lambda s: g(mp.mpf(H), mp.mpf(V0) + w * s), [0, *zero, L]))

    def T_of(H, V):
        return mp.sqrt(H * H + V * V)

    ref = [
        quad(lambda H, V: mp_log(T_of(H, V))),
        quad(lambda H, V: mp_log(T_of(H, V)) * H / T_of(H, V)),
        quad(lambda H, V: mp_log(T_of(H, V)) * V / T_of(H, V)),
    ]
    got = [e.stretch, e.x, e.z]
    scale = max(abs(r) for r in ref)
    np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-13 * scale)


def test_the_jacobians_match_central_differences():
    for law in (LOG, TABLE, ConstantEA(2e7)):
        H, V0, w, L = 3e5, -2e5, 800.0, 700.0
        e = elongation(law, H, V0, w, L)
        x, z, J = catenary_ends(law, H, V0, w, L)
        for j, step in enumerate(([1.0, 0.0], [0.0, 1.0])):
            h = 1e-3 * H
            dH, dV = h * step[0], h * step[1]
            plus, minus = elongation(law, H + dH, V0 + dV, w, L), elongation(law, H - dH, V0 - dV, w, L)
            fd = [(getattr(plus, k) - getattr(minus, k)) / (2 * h) for k in ("stretch", "x", "z")]
            np.testing.assert_allclose(e.jacobian[:, j], fd, rtol=1e-6, atol=1e-9 * np.abs(e.jacobian).max())
            ends_p, ends_m = (
                catenary_ends(law, H + dH, V0 + dV, w, L),
                catenary_ends(law, H - dH, V0 - dV, w, L),
            )
            fd = [(ends_p[k] - ends_m[k]) / (2 * h) for k in range(2)]
            np.testing.assert_allclose(J[:, j], fd, rtol=1e-6, atol=1e-9 * np.abs(J).max())


def test_the_quadrature_splits_at_the_tables_points():
    H, V0, w, L = 1e5, -5e5, 2e3, 600.0  # T from 5.1e5 to 7.1e5 passes the point at 6.6e5
    T, V, c = catenary_quadrature(H, V0, w, L, TABLE.breakpoints)
    assert c.sum() == pytest.approx(L, rel=1e-13)
    kink = 6.6e5
    assert T.min() < kink < T.max()  # the split at the kink: nodes on both sides, none on it
    below, above = T[T < kink], T[T > kink]
    assert below.size % 12 == 0 and above.size % 12 == 0


def test_tables_and_functions_give_strain_and_compliance_vectorised_and_continue_linearly():
    T = np.array([[-1e4, 0.0, 5e4], [1.2e5, 1.0e6, 2.5e6]])
    eps, k = TABLE.strain(T), TABLE.compliance(T)
    assert eps.shape == k.shape == T.shape
    curve = PchipInterpolator(TABLE_T, TABLE_EPS)
    np.testing.assert_allclose(eps[0, 1:], curve(T[0, 1:]), rtol=1e-15)
    slope_end = curve.derivative()(TABLE_T[-1])
    assert eps[1, 2] == pytest.approx(TABLE_EPS[-1] + slope_end * (2.5e6 - TABLE_T[-1]), rel=1e-14)
    assert k[0, 0] == pytest.approx(curve.derivative()(0.0), rel=1e-14)
    np.testing.assert_allclose(LOG.compliance(T[1]), log_slope(T[1]), rtol=1e-15)


def test_the_rope_has_a_static_and_a_dynamic_stiffness():
    rope = StaticDynamicRope(1.1e8, alpha=2.0e8, beta=20.0)
    T = np.array([0.0, 5e5, 2e6])
    np.testing.assert_allclose(rope.strain(T), T / 1.1e8, rtol=1e-15)
    np.testing.assert_allclose(rope.dynamic_compliance(T), 1.0 / (2.0e8 + 20.0 * T), rtol=1e-15)
    assert rope.kind == "constant" and ConstantEA(1.0).dynamic_compliance(np.ones(2)).tolist() == [1.0, 1.0]


def test_bad_laws_are_refused_by_name():
    with pytest.raises(InputError, match="strain.*increase"):
        StrainTable([0.0, 0.01, 0.008], [0.0, 1e5, 2e5])
    with pytest.raises(InputError, match="tension.*increase"):
        StrainTable([0.0, 0.01, 0.02], [0.0, 2e5, 1e5])
    with pytest.raises(InputError, match="strain.*starts at"):
        StrainTable([0.001, 0.01], [0.0, 2e5])
    with pytest.raises(InputError, match="tension"):
        StrainTable([0.0, 0.01], [0.0, 2e5, 3e5])
    with pytest.raises(InputError, match="derivative.*increasing"):
        StrainFunction(lambda T: -T / EA, lambda T: -1 / EA + 0 * T).compliance(np.array([1e3]))
    with pytest.raises(InputError, match="strain.*vanish"):
        StrainFunction(lambda T: 1e-3 + T / EA, lambda T: 1 / EA + 0 * T)
    with pytest.raises(InputError, match="beta"):
        StaticDynamicRope(1e8, 1e8, -1.0)
    with pytest.raises(InputError, match="EA.*derivative"):
        strain_law(log_strain)
    with pytest.raises(InputError, match="EA"):
        strain_law(-3.0)
    with pytest.raises(InputError, match="derivative"):
        law_catenary(300.0, 10.0, 100.0, StrainFunction(log_strain, lambda T: 0 * T), length=320.0)


def test_laws_pickle():
    for law in (LOG, TABLE, ConstantEA(3e8), StaticDynamicRope(1e8, 2e8, 15.0)):
        copy = pickle.loads(pickle.dumps(law))
        T = np.linspace(-1e4, 2e6, 7)
        np.testing.assert_array_equal(copy.strain(T), law.strain(T))
        np.testing.assert_array_equal(copy.dynamic_compliance(T), law.dynamic_compliance(T))
        assert repr(copy) == repr(law)
