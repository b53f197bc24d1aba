"""The change of state of a whole line (spans × states in one call) against the one-span path,
an mpmath solution of the closure, and its refusals."""

import mpmath as mp
import numpy as np
import pytest

from skcable import cable, conductors
from skcable.cable.closure import check_residual
from skcable.conductors import _solve_z
from skcable.errors import InputError

KW = dict(EA=3.4e7, alpha=2.3e-5, w0=15.97, t0=15.0)


@pytest.fixture(scope="module")
def grid():
    rng = np.random.default_rng(20240924)
    n = 1000
    spans = rng.uniform(50.0, 1200.0, n)
    dh = rng.uniform(-0.3, 0.3, n) * spans
    H0 = rng.uniform(5e3, 6e4, n)
    w = np.array([15.97, 15.97, 25.0, 40.0, 15.97])
    t = np.array([-20.0, 90.0, 0.0, -5.0, 15.0])
    wind = np.array([0.0, 5.0, 0.0, 12.0, 0.0])
    return spans, dh, H0, w, t, wind


def test_a_random_line_equals_the_one_span_path(grid):
    spans, dh, H0, w, t, wind = grid
    line = conductors.change_of_state(spans, dh, **KW, H0=H0, w=w, t=t, wind=wind)
    assert line.H.shape == (spans.size, w.size) and line.L0.shape == (spans.size,)
    assert np.all(line.H > 0)
    for i in range(spans.size):
        one = conductors.change_of_state(
            float(spans[i]), float(dh[i]), **KW, H0=float(H0[i]), w=w, t=t, wind=wind
        )
        np.testing.assert_allclose(line.H[i], one.H, rtol=1e-10, atol=0)
        np.testing.assert_allclose(line.sag[i], one.sag, rtol=1e-10, atol=0)
        np.testing.assert_allclose(line.T_max[i], one.T_max, rtol=1e-10, atol=0)
        np.testing.assert_allclose(line.length[i], one.length, rtol=1e-12, atol=0)
        assert line.L0[i] == pytest.approx(one.L0, rel=1e-12)
    # the reference state is reproduced: the state (w0, t0, no wind) has H0
    np.testing.assert_allclose(line.H[:, 4], H0, rtol=1e-11)


def _mp_state(span, dh, w, EA, L, guess):
    """(H, V_A) closing Irvine's elastic catenary at 40 digits (the integrals in closed form)."""
    mp.mp.dps = 40
    span, dh, w, EA = (mp.mpf(float(v)) for v in (span, dh, w, EA))
    L = mp.mpf(L)

    def closure(H, V):
        tb, ta = w * L - V, -V
        x = H * L / EA + H / w * (mp.asinh(tb / H) - mp.asinh(ta / H))
        y = L * (w * L / 2 - V) / EA + (mp.sqrt(H**2 + tb**2) - mp.sqrt(H**2 + ta**2)) / w
        return [x - span, y - dh]

    return mp.findroot(closure, [mp.mpf(float(g)) for g in guess])


@pytest.mark.parametrize("i", [0, 17, 423, 999])
def test_line_states_against_a_40_digit_solution(grid, i):
    spans, dh, H0, w, t, wind = grid
    line = conductors.change_of_state(spans, dh, **KW, H0=H0, w=w, t=t, wind=wind)
    # the reference length: the closure at H0 solved for (V_A, L0) at 40 digits
    mp.mp.dps = 40
    a, h, w0, EA, H = (mp.mpf(float(v)) for v in (spans[i], dh[i], KW["w0"], KW["EA"], H0[i]))

    def reference(V, L):
        tb, ta = w0 * L - V, -V
        x = H * L / EA + H / w0 * (mp.asinh(tb / H) - mp.asinh(ta / H))
        y = L * (w0 * L / 2 - V) / EA + (mp.sqrt(H**2 + tb**2) - mp.sqrt(H**2 + ta**2)) / w0
        return [x - a, y - h]

    start = cable.elastic_catenary(spans[i], dh[i], KW["w0"], KW["EA"], length=line.L0[i])  # a start only
    V0, L0 = mp.findroot(reference, [mp.mpf(float(start.V_A)), mp.mpf(float(line.L0[i]))])
    assert line.L0[i] == pytest.approx(float(L0), rel=4e-16)
    k = 1 + KW["alpha"] * (t[2] - KW["t0"])  # a windless state: its vertical plane
    start = conductors.thermal_catenary(
        spans[i], dh[i], w[2], KW["EA"], length=float(L0), alpha=KW["alpha"], t=t[2], t0=15.0
    )
    H_mp, _ = _mp_state(spans[i], dh[i], w[2] / k, KW["EA"] * k, L0 * k, (start.H, start.V_A))
    assert line.H[i, 2] == pytest.approx(float(H_mp), rel=2e-12)


def test_spans_broadcast_with_dh_and_per_span_reference(grid):
    spans, dh, H0, w, t, wind = grid
    line = conductors.change_of_state(spans[:5], 0.0, **KW, H0=2e4, w=w, t=t)
    one = conductors.change_of_state(float(spans[3]), 0.0, **KW, H0=2e4, w=w, t=t)
    np.testing.assert_allclose(line.H[3], one.H, rtol=1e-10)
    sag = conductors.change_of_state(spans[:5], dh[:5], **KW, sag0=0.03 * spans[:5], w=w, t=t)
    one = conductors.change_of_state(float(spans[2]), float(dh[2]), **KW, sag0=0.03 * spans[2], w=w, t=t)
    np.testing.assert_allclose(sag.H[2], one.H, rtol=1e-10)
    np.testing.assert_allclose(sag.sag0, 0.03 * spans[:5], rtol=1e-10)
    par = conductors.change_of_state(spans[:5], dh[:5], **KW, H0=H0[:5], w=w, t=t, model="parabola")
    one = conductors.change_of_state(
        float(spans[1]), float(dh[1]), **KW, H0=float(H0[1]), w=w, t=t, model="parabola"
    )
    np.testing.assert_allclose(par.H[1], one.H, rtol=1e-13)


def test_the_independent_check_catches_a_wrong_tension():
    span, dh, w, EA = 400.0, 30.0, 16.0, 3e7
    L, m, ok = _solve_z.length_z(np.array([span]), np.array([dh]), w, EA, np.array([2.5e4]))
    assert ok.all()
    res, bound = check_residual(np.array([2.5e4]), m, w, EA, L, span, dh)
    assert res[0] <= bound[0]
    res, bound = check_residual(np.array([2.5e4 * (1 + 1e-9)]), m, w, EA, L, span, dh)
    assert res[0] > bound[0]


@pytest.mark.parametrize(
    "change, name",
    [
        (dict(H0=[2e4, 2e4, 2e4]), "H0"),  # two spans, three tensions
        (dict(H0=[2e4, -1.0]), "H0"),
        (dict(H0=2e4, span=[300.0, -1.0]), "span"),
        (dict(H0=2e4, dh=[0.0, 1.0, 2.0]), "dh"),
        (dict(H0=1.0), "H0"),  # span·w0/(2 H0) beyond cosh's range
        (dict(H0=2e4, w=[15.0, 1e-310]), "w"),
    ],
)
def test_line_refusals_name_their_argument(change, name):
    args = dict(span=[300.0, 450.0], dh=0.0, **KW, w=[15.97, 20.0], t=[15.0, 40.0]) | change
    span, dh = args.pop("span"), args.pop("dh")
    with pytest.raises(InputError) as info:
        conductors.change_of_state(span, dh, **args)
    assert info.value.argument == name, info.value


def test_a_line_table_holds_each_span_table():
    spans, dh = np.array([250.0, 420.0, 310.0]), np.array([0.0, 25.0, -12.0])
    cases = {"bare": (15.97, 0.0), "ice": (30.0, 0.0), "wind": (15.97, 9.0)}
    kw = dict(**KW, H0=2.5e4, temperatures=[-10.0, 15.0, 75.0], load_cases=cases)
    line = conductors.sag_tension_table(spans, dh, **kw)
    assert list(line.index.names) == ["span_no", "case", "t"] and line.shape == (27, 9)
    for i in range(3):
        one = conductors.sag_tension_table(float(spans[i]), float(dh[i]), **kw)
        part = line.xs(i, level="span_no")
        np.testing.assert_allclose(part[one.columns].to_numpy(), one.to_numpy(), rtol=1e-10)
        assert np.all(part["span"] == spans[i]) and np.all(part["dh"] == dh[i])


def test_conductor_methods_take_a_line():
    from skcable import strand

    drake = conductors.Conductor.from_strand(strand.preset("acsr-drake"))
    spans = np.array([300.0, 380.0, 455.0])
    line = drake.change_of_state(spans, 0.0, t0=15.0, H0=28e3, t=[-20.0, 75.0], ice=[0.0, 0.0])
    for i in range(3):
        one = drake.change_of_state(float(spans[i]), t0=15.0, H0=28e3, t=[-20.0, 75.0], ice=[0.0, 0.0])
        np.testing.assert_allclose(line.H[i], one.H, rtol=1e-10)
    # a given unstressed length per span (e.g. of the intact conductor)
    again = drake.change_of_state(spans, 0.0, t0=15.0, length=line.L0, t=[-20.0, 75.0])
    np.testing.assert_allclose(again.H, line.H, rtol=1e-9)
    table = drake.sag_tension_table(spans, t0=15.0, H0=28e3, temperatures=[15.0], load_cases={"bare": (0, 0)})
    np.testing.assert_allclose(table["H"], 28e3, rtol=1e-11)
