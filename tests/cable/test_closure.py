"""The one closure of an elastic segment (`skcable.cable.closure`) against the world: Irvine's and
Jonkman's equations written here in their textbook form at 50 digits (mpmath; their Jacobians by
mpmath's numerical differentiation), an ODE integration of the equilibrium and quadratures; and
its two back ends (Python floats, NumPy arrays) and its in-place check against each other.

H.M. Irvine, "Cable Structures", MIT Press, 1981, §2.2; J.M. Jonkman, "Dynamics modeling and
loads analysis of an offshore floating wind turbine", NREL, 2007.
"""

import numpy as np
import pytest
from mpmath import mp, mpf
from scipy.integrate import quad, solve_ivp

from skcable._xp import scalar_math
from skcable.cable import closure

#: hanging pieces ``(H, V_b, w, EA, L)``: slack and taut, the vertex inside and beyond either end,
#: a taut steep line whose step wL/H is 1e-9 of its slope, a soft one, a buoyant one
PIECES = [
    (2.0e4, -8.0e3, 20.0, 1e7, 801.4),
    (1.5e3, -3.0e4, 1000.0, 5e8, 60.0),
    (3.0e5, 2.0e4, 15.0, 3e7, 400.0),
    (1.0e6, -1.2e6, 1e-3, 1e9, 1.0),
    (50.0, -200.0, 9.0, 2e3, 40.0),
    (8.0e3, 3.0e3, -40.0, 1e8, 120.0),
]


def _irvine(H, Vb, w, EA, L):
    """Run and rise of a hanging piece, Irvine's textbook form, at 50 digits."""
    Vt = Vb + w * L
    x = H * L / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
    y = L * (Vb + Vt) / (2 * EA) + (mp.hypot(H, Vt) - mp.hypot(H, Vb)) / w
    return x, y


@pytest.mark.parametrize("piece", PIECES)
def test_hanging_piece_and_its_jacobian_are_irvines(piece):
    with mp.workdps(50):
        p = [mpf(v) for v in piece]
        x, y = _irvine(*p)
        cols = []  # ∂/∂H, ∂/∂V_b, ∂/∂L of (x, y)
        for i in (0, 1, 4):

            def shifted(t, i=i, k=0):
                q = list(p)
                q[i] = t
                return _irvine(*q)[k]

            cols.append([mp.diff(lambda t, k=k, i=i: shifted(t, i, k), p[i]) for k in (0, 1)])
    got = closure.hanging(*piece)
    assert got[0] == pytest.approx(float(x), rel=1e-14)
    assert got[1] == pytest.approx(float(y), rel=1e-13, abs=1e-14 * piece[4])
    expected = {2: cols[0][0], 3: cols[1][0], 4: cols[1][1], 5: cols[2][0], 6: cols[2][1]}
    scale = max(abs(float(v)) for v in expected.values())
    for k, value in expected.items():
        assert got[k] == pytest.approx(float(value), rel=1e-12, abs=1e-13 * scale), k
    assert got[3] == pytest.approx(float(cols[0][1]), rel=1e-12, abs=1e-13 * scale)  # ∂y/∂H = ∂x/∂V_b
    H, Vb, w, _, L = piece
    assert got[7] == pytest.approx(np.hypot(H, Vb), rel=1e-15)
    assert got[8] == pytest.approx(np.hypot(H, Vb + w * L), rel=1e-15)


def test_positions_follow_an_ode_integration_of_the_equilibrium():
    H, Vb, w, EA, L = 1.2e4, -9.0e3, 25.0, 4e6, 700.0

    def rhs(s, state):
        tv = Vb + w * s
        T = np.hypot(H, tv)
        return [H / EA + H / T, tv / EA + tv / T, T / EA + 1.0]

    s = np.linspace(0.0, L, 7)
    sol = solve_ivp(rhs, (0.0, L), [0.0, 0.0, 0.0], t_eval=s, rtol=1e-12, atol=1e-10)
    x, y = closure.positions(H, Vb, w, EA, s, np)
    np.testing.assert_allclose(x, sol.y[0], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(y, sol.y[1], rtol=1e-9, atol=1e-9)
    assert closure.stretched_length(H, Vb, w, EA, L) == pytest.approx(sol.y[2, -1], rel=1e-10)


@pytest.mark.parametrize("piece", PIECES)
def test_stretched_length_is_the_integral_of_the_strain(piece):
    H, Vb, w, EA, L = piece
    integral, _ = quad(lambda s: np.hypot(H, Vb + w * s) / EA, 0.0, L, epsabs=0, epsrel=1e-13)
    assert closure.stretched_length(*piece) - L == pytest.approx(integral, rel=1e-11)
    assert closure.stretched_length(H, Vb, w, EA, 0.0) == 0.0


@pytest.mark.parametrize(("T", "l", "mu_w"), [(5e4, 300.0, 80.0), (5e4, 300.0, 400.0), (5e4, 300.0, 0.0)])
def test_grounded_piece_stretches_by_the_integral_of_its_tension(T, l, mu_w):
    EA = 5e8
    integral, _ = quad(lambda s: max(T - mu_w * s, 0.0) / EA, 0.0, l, points=[T / mu_w] if mu_w else None)
    e, e_T, e_l, low = closure.grounded(T, l, mu_w, EA)
    assert e == pytest.approx(integral, rel=1e-12)
    assert low == max(T - mu_w * l, 0.0)
    for got, h, f in ((e_T, 1.0, lambda d: closure.grounded(T + d, l, mu_w, EA)[0]),
                      (e_l, 1e-3, lambda d: closure.grounded(T, l + d, mu_w, EA)[0])):  # fmt: skip
        assert got == pytest.approx((f(h) - f(-h)) / (2 * h), rel=1e-6, abs=1e-18)


def _jonkman(H, V, w, EA, L, mu):
    """Run and rise from the anchor of a line resting on the seabed from it (Jonkman 2007)."""
    L_B = L - V / w
    ell = min(L_B, H / (mu * w)) if mu > 0 else L_B
    X = L_B + (H * ell - mu * w * ell * ell / 2) / EA + H * V / (w * EA) + H / w * mp.asinh(V / H)
    Z = (mp.hypot(H, V) - H) / w + V * V / (2 * w * EA)
    return X, Z


@pytest.mark.parametrize("mu", [0.0, 0.3, 2.0])
def test_a_segment_on_the_seabed_is_jonkmans_with_his_jacobian(mu):
    H, V, w, EA, L = 6.0e4, 3.0e5, 1000.0, 5e8, 850.0  # 550 m grounded: friction takes it all at mu = 2
    with mp.workdps(50):
        p = [mpf(v) for v in (H, V, w, EA, L, mu)]
        X, Z = _jonkman(*p)
        jac = [
            [mp.diff(lambda t, k=k: _jonkman(t, p[1], *p[2:])[k], p[0]) for k in (0, 1)],
            [mp.diff(lambda t, k=k: _jonkman(p[0], t, *p[2:])[k], p[1]) for k in (0, 1)],
        ]
    for xp, cast in ((scalar_math, float), (np, np.array)):
        got = closure.segment(cast(H), cast(V), w, EA, L, mu * w, True, xp)
        assert float(got[0]) == pytest.approx(float(X), rel=1e-14)
        assert float(got[1]) == pytest.approx(float(Z), rel=1e-14)
        want = (jac[0][0], jac[1][0], jac[0][1], jac[1][1])  # X_H, X_V, Z_H, Z_V
        for g, e in zip(got[2:], want, strict=True):
            assert float(g) == pytest.approx(float(e), rel=1e-10, abs=1e-14)


def test_a_segment_clear_of_the_seabed_is_the_hanging_piece():
    H, V, w, EA, L = 6.0e4, 9.0e5, 1000.0, 5e8, 850.0  # V > wL: lifted off its anchor
    got = closure.segment(H, V, w, EA, L, 300.0, True)
    piece = closure.hanging(H, V - w * L, w, EA, L)
    assert got == (piece[0], piece[1], piece[2], piece[3], piece[3], piece[4])
    assert np.isnan(closure.segment(-1.0, V, w, EA, L, 0.0, False)[0])


def test_floats_and_arrays_are_one_source():
    columns = [np.array(v) for v in zip(*PIECES, strict=True)]
    arrays = closure.hanging(*columns, np)
    ends = np.array([closure.positions(*piece) for piece in PIECES]).T
    checks = closure.check(*columns, *ends, np)
    for i, piece in enumerate(PIECES):
        floats = closure.hanging(*piece)
        # ∂x/∂H's series of sinh A - A: nine terms on arrays, as few as reach them on floats
        np.testing.assert_allclose([a[i] for a in arrays], floats, rtol=2e-15, atol=0)
        np.testing.assert_allclose(ends[:, i], floats[:2], rtol=4e-16)
        # the check on floats and on arrays, each at its own round-off (math's and NumPy's log1p)
        np.testing.assert_allclose(
            closure.check(*piece, *ends[:, i]), [c[i] for c in checks], rtol=0, atol=3e-16
        )
        assert max(abs(c[i]) for c in checks) < 1e-15  # a few ulps of the terms


@pytest.mark.parametrize("piece", [p for p in PIECES if p[2] > 0])
def test_the_in_place_check_is_the_check_and_catches_an_error(piece):
    H, Vb, w, EA, L = piece
    span, dh = closure.positions(*piece)
    m = Vb + 0.5 * w * L
    assert max(abs(r) for r in closure.check(*piece, span, dh)) < 4e-16
    rows = np.empty((closure.CHECK_ROWS, 2))
    missed = np.array([dh, dh + 1e-9 * (abs(span) + abs(dh))])  # B 1e-9 of the chord too high
    ok = closure.check_into(np.array([H, H]), np.array([m, m]), w, EA, L, span, missed, rows)
    assert ok.tolist() == [True, False]
    assert rows[2, 0] == pytest.approx(np.hypot(H, Vb), rel=1e-15)
    assert rows[3, 0] == pytest.approx(np.hypot(H, Vb + w * L), rel=1e-15)
    length = closure.stretched_length_into(np.array([H, H]), w, EA, L, rows, np.empty(2))
    assert length[0] == pytest.approx(closure.stretched_length(*piece), rel=1e-13)
    wrong = closure.check(H * (1 + 1e-9), Vb, w, EA, L, span, dh)
    assert max(abs(r) for r in wrong) > 1e-13


def _sloped(H, L_B, w, EA, L, m, mu):
    """Run and rise from A of a line grounded over ``L_B`` on the slope ``y = m x`` and hanging
    tangentially from there (Jonkman 2007 on a slope; Irvine 1981 for the hanging part)."""
    cos = 1 / mp.sqrt(1 + m * m)
    sin = m * cos
    k, T_t = w * (sin + mu * cos), H / cos
    ell = min(L_B, T_t / k) if k > 0 else L_B
    G = L_B + (T_t * ell - k * ell * ell / 2) / EA
    V_t = H * m
    x, y = _irvine(H, V_t, w, EA, L - L_B)
    return G * cos + x, G * sin + y


@pytest.mark.parametrize(
    ("m", "mu", "L_B"), [(0.1, 0.5, 300.0), (0.1, 0.5, 800.0), (-0.2, 0.3, 400.0), (0.0, 0.0, 400.0)]
)
def test_a_segment_on_a_slope_and_its_jacobian_are_the_equations(m, mu, L_B):
    H, w, EA, L = 6.0e4, 1000.0, 5e8, 1000.0  # L_B = 800: friction holds the anchor's end slack
    with mp.workdps(50):
        p = [mpf(v) for v in (H, L_B, w, EA, L, m, mu)]
        X, Z = _sloped(*p)
        jac = [
            [mp.diff(lambda t, i=i, k=k: _sloped(*p[:i], t, *p[i + 1 :])[k], p[i]) for i in (0, 1)]
            for k in (0, 1)
        ]
    got = closure.on_slope(H, L_B, w, EA, L, m, mu)
    assert got[0] == pytest.approx(float(X), rel=1e-14)
    assert got[1] == pytest.approx(float(Z), rel=1e-13, abs=1e-14 * L)
    for g, e in zip(got[2:], (jac[0][0], jac[0][1], jac[1][0], jac[1][1]), strict=True):
        assert g == pytest.approx(float(e), rel=1e-10, abs=1e-14)
