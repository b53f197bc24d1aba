"""Thermal elastic catenary and change of state: an independent mpmath
solution of the original equations (in 3-D with wind), the textbook cubic,
limits, tables and error cases."""

import warnings

import mpmath as mp
import numpy as np
import pytest

from skcable import cable, conductors
from skcable.errors import InputError, PlausibilityWarning

mp.mp.dps = 30


def _ends(L0, H, V_A, Z_A, w, p, EA, k):
    """Integrate ds = ds0 (k + T/EA) along the tension direction, 3-D.

    Tension (H, w s - V_A, p s - Z_A): vertical load w (down), wind p along -z.
    """

    def tension(s):
        return mp.sqrt(H**2 + (w * s - V_A) ** 2 + (p * s - Z_A) ** 2)

    def comp(f):
        return mp.quad(lambda s: f(s) / tension(s) * (k + tension(s) / EA), [0, L0])

    x = comp(lambda s: H)
    y = comp(lambda s: w * s - V_A)
    z = comp(lambda s: p * s - Z_A)
    return x, y, z


def _mp_state(span, dh, w, p, EA, k, L0, guess):
    """(H, V_A, Z_A) closing the cable at B = (span, dh, 0)."""
    L0, w, p, EA, k = (mp.mpf(v) for v in (L0, w, p, EA, k))

    def res(H, V_A, Z_A):
        x, y, z = _ends(L0, H, V_A, Z_A, w, p, EA, k)
        return [x - span, y - dh, z]

    return mp.findroot(res, [mp.mpf(g) for g in guess])


def _mp_reference(span, dh, w0, EA, H0, guess):
    """(V_A, L0) of the reference state (no wind, k = 1) with horizontal tension H0."""
    w0, EA, H0 = mp.mpf(w0), mp.mpf(EA), mp.mpf(H0)

    def res(V_A, L0):
        x, y, _ = _ends(L0, H0, V_A, 0, w0, 0, EA, 1)
        return [x - span, y - dh]

    return mp.findroot(res, [mp.mpf(g) for g in guess])


def test_thermal_mapping_against_mpmath():
    span, dh, w, EA, L0, alpha, t, t0 = 250.0, 30.0, 12.0, 4e6, 262.0, 2.3e-5, 75.0, 15.0
    c = conductors.thermal_catenary(span, dh, w, EA, length=L0, alpha=alpha, t=t, t0=t0)
    k = 1 + alpha * (t - t0)
    H, V_A, _ = _mp_state(span, dh, w, 0.0, EA, k, L0, (c.H * 1.01, c.V_A * 0.99, 0.0))
    assert c.H == pytest.approx(float(H), rel=1e-10)
    assert c.V_A == pytest.approx(float(V_A), rel=1e-10)
    # stretched length: ∫ (k + T/EA) ds0
    Hm, Va = mp.mpf(float(H)), mp.mpf(float(V_A))
    stretched = mp.quad(lambda s: k + mp.sqrt(Hm**2 + (w * s - Va) ** 2) / EA, [0, L0])
    assert c.stretched_length == pytest.approx(float(stretched), rel=1e-10)
    assert c.residual() < 1e-12


def test_thermal_catenary_broadcasts():
    t = np.array([-20.0, 15.0, 60.0])
    c = conductors.thermal_catenary(250.0, 30.0, 12.0, 4e6, length=262.0, alpha=2.3e-5, t=t, t0=15.0)
    for i in range(3):
        one = conductors.thermal_catenary(250.0, 30.0, 12.0, 4e6, length=262.0, alpha=2.3e-5, t=t[i], t0=15.0)
        assert c.H[i] == pytest.approx(one.H, rel=1e-12)
    assert np.all(np.diff(c.H) < 0)  # warmer: longer, slacker


def test_thermal_catenary_at_reference_temperature_is_elastic_catenary():
    e = cable.elastic_catenary(300.0, -10.0, 9.0, 2e7, length=302.0)
    c = conductors.thermal_catenary(300.0, -10.0, 9.0, 2e7, length=302.0, alpha=1.9e-5, t=40.0, t0=40.0)
    assert c.H == pytest.approx(e.H, rel=1e-13) and c.sag == pytest.approx(e.sag, rel=1e-12)


@pytest.mark.parametrize(
    "dh, wind, t",
    [(0.0, 0.0, 60.0), (40.0, 0.0, -10.0), (0.0, 9.0, 5.0), (40.0, 9.0, 50.0)],
)
def test_change_of_state_against_mpmath(dh, wind, t):
    span, EA, alpha, w0, t0, H0, w = 300.0, 2.5e7, 1.9e-5, 15.0, 15.0, 21000.0, 20.0
    r = conductors.change_of_state(span, dh, EA=EA, alpha=alpha, w0=w0, t0=t0, H0=H0, w=w, t=t, wind=wind)
    ref = cable.elastic_catenary(span, dh, w0, EA, length=r.L0)
    V_A0, L0 = _mp_reference(span, dh, w0, EA, H0, (ref.V_A * 1.001, r.L0 * (1 + 1e-5)))
    assert r.L0 == pytest.approx(float(L0), rel=1e-12)
    k = 1 + alpha * (t - t0)
    q = np.hypot(w, wind)
    guess = (r.H * 1.001, w * L0 / 2 * 1.001, wind * L0 / 2 * 1.001)
    H, V_A, Z_A = _mp_state(span, dh, w, wind, EA, k, L0, guess)
    assert r.H == pytest.approx(float(H), rel=1e-8)
    # T_max: the larger end tension of the 3-D solution
    T_A = mp.sqrt(H**2 + V_A**2 + Z_A**2)
    T_B = mp.sqrt(H**2 + (w * L0 - V_A) ** 2 + (wind * L0 - Z_A) ** 2)
    assert r.T_max == pytest.approx(float(max(T_A, T_B)), rel=1e-8)
    assert r.blowout == pytest.approx(np.arctan2(wind, w), rel=1e-15, abs=0)
    if dh == 0.0:  # the plane of a level span contains x: H is the in-plane H
        assert r.H_plane == pytest.approx(r.H, rel=1e-14)
    assert q > 0


def test_reference_state_from_sag_reproduces_it():
    r = conductors.change_of_state(
        400.0, 25.0, EA=3e7, alpha=2e-5, w0=16.0, t0=10.0, sag0=12.0, w=16.0, t=10.0
    )
    assert r.sag == pytest.approx(12.0, rel=1e-10) and r.sag0 == pytest.approx(12.0, rel=1e-10)
    # and with H0 equal to that state's H, the same unstressed length
    r2 = conductors.change_of_state(400.0, 25.0, EA=3e7, alpha=2e-5, w0=16.0, t0=10.0, H0=r.H, w=16.0, t=10.0)
    assert r2.L0 == pytest.approx(r.L0, rel=1e-12)


def _textbook(a, EA, alpha, w0, H0, w, dt, cos=1.0):
    """H^2 [H - H0 + EA cos a dt + EA cos^3 a^2 w0^2/(24 H0^2)] = EA cos^3 a^2 w^2 / 24, numpy.roots."""
    b = -H0 + EA * cos * alpha * dt + EA * cos**3 * a**2 * w0**2 / (24 * H0**2)
    d = EA * cos**3 * a**2 * w**2 / 24
    roots = np.roots([1.0, b, 0.0, -d])
    real = roots[np.abs(roots.imag) < 1e-9 * np.abs(roots)].real
    return real[real > 0].max()


@pytest.mark.parametrize("dh", [0.0, 60.0])
def test_parabola_against_textbook_cubic(dh):
    span, EA, alpha, w0, t0, H0 = 350.0, 2.8e7, 1.9e-5, 14.0, 15.0, 24000.0
    w, t = np.array([14.0, 22.0, 30.0]), np.array([[-20.0], [15.0], [85.0]])
    r = conductors.change_of_state(
        span, dh, EA=EA, alpha=alpha, w0=w0, t0=t0, H0=H0, w=w, t=t, model="parabola"
    )
    cos = span / np.hypot(span, dh)
    for i in range(3):
        for j in range(3):
            expected = _textbook(span, EA, alpha, w0, H0, w[j], t[i, 0] - t0, cos)
            assert r.H[i, j] == pytest.approx(expected, rel=1e-12)
    # parabolic sag w a^2 / (8 H cos psi)
    assert r.sag == pytest.approx(w * span**2 / (8 * r.H * cos), rel=1e-14)


def test_parabola_sag0_gives_textbook_H0():
    r = conductors.change_of_state(300.0, 0.0, EA=3e7, alpha=2e-5, w0=15.0, t0=0.0, sag0=6.0, w=15.0, t=0.0,
                              model="parabola")  # fmt: skip
    assert r.H == pytest.approx(15.0 * 300.0**2 / (8 * 6.0), rel=1e-14)


@pytest.mark.parametrize("dh", [0.0, 60.0])
def test_exact_and_parabola_agree_for_small_sag(dh):
    # nearly inextensible, no temperature change: the parabola is the first
    # term in sag/span, the sags differ by O((sag/span)^2), level or inclined, with wind
    rel = []
    for H0 in (1e4, 4e4, 1.6e5):  # sag/span ~ 5.6, 1.4, 0.35 %
        kw = dict(EA=1e12, alpha=2e-5, w0=15.0, t0=15.0, H0=H0, w=18.0, t=15.0, wind=5.0)
        e = conductors.change_of_state(300.0, dh, **kw)
        p = conductors.change_of_state(300.0, dh, **kw, model="parabola")
        rel.append(abs(p.sag / e.sag - 1) / (e.sag / 300.0) ** 2)
        assert p.T_max == pytest.approx(e.T_max, rel=e.sag / 300.0 / 10)
    # the ratio to (sag/span)^2 tends to a constant
    assert rel[2] == pytest.approx(rel[1], rel=0.05) and rel[1] == pytest.approx(rel[0], rel=0.1)


def test_rigid_cold_limit_and_monotonicity():
    kw = dict(EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4)
    r = conductors.change_of_state(300.0, 0.0, **kw, w=15.0, t=np.linspace(-30, 90, 7))
    assert np.all(np.diff(r.H) < 0) and np.all(np.diff(r.sag) > 0)
    r = conductors.change_of_state(300.0, 0.0, **kw, w=np.linspace(10, 40, 5), t=15.0)
    assert np.all(np.diff(r.H) > 0)


def test_sag_tension_table():
    df = conductors.sag_tension_table(
        300.0, 0.0, EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4,
        temperatures=[-20, 15, 80], load_cases={"bare": (15.0, 0.0), "ice": (25.0, 0.0), "wind": (15.0, 8.0)},
    )  # fmt: skip
    assert df.shape == (9, 7) and list(df.index.names) == ["case", "t"]
    one = conductors.change_of_state(300.0, 0.0, EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4, w=15.0, t=80.0,
                                wind=8.0)  # fmt: skip
    assert df.loc[("wind", 80.0), "H"] == pytest.approx(one.H, rel=1e-12)
    assert df.loc[("bare", 15.0), "H"] == pytest.approx(2e4, rel=1e-10)
    assert df.loc[("wind", 80.0), "blowout_deg"] == pytest.approx(np.degrees(np.arctan2(8, 15)), rel=1e-14)


KW = dict(EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, w=15.0, t=20.0)


@pytest.mark.parametrize(
    "change, argument",
    [
        (dict(H0=2e4, sag0=5.0), "H0"),
        (dict(), "H0"),
        (dict(H0=2e4, model="exact"), "model"),
        (dict(H0=2e4, model=None), "model"),
        (dict(H0=2e4, EA=-1.0), "EA"),
        (dict(H0=2e4, alpha=np.nan), "alpha"),
        (dict(H0=2e4, alpha=float("inf")), "alpha"),
        (dict(H0=-2e4), "H0"),
        (dict(sag0=0.0), "sag0"),
        (dict(H0=2e4, w=[15.0, -1.0]), "w"),
        (dict(H0=2e4, wind=-1.0), "wind"),
        (dict(H0=2e4, t=[1.0, 2.0], w=[1.0, 2.0, 3.0]), "t"),
        (dict(H0=2e4, alpha=0.1, t=-100.0), "alpha"),  # beyond any material's alpha, not t (issue 25)
        (dict(H0=2e4, alpha=2.3e-5, t=-1e5), "t"),  # below absolute zero
        (dict(H0=2e4, w0=0.0), "w0"),
        (dict(H0=2e4, t0="15"), "t0"),
        (dict(H0=2e8, model="parabola"), "H0"),  # strain 6.7: beyond a small-strain equation
    ],
)
def test_bad_input_raises_naming_the_argument(change, argument):
    kw = {**KW, **change}
    with pytest.raises(InputError) as info:
        conductors.change_of_state(300.0, 0.0, **kw)
    assert info.value.argument == argument


def test_bad_span_and_tables():
    with pytest.raises(InputError, match="span"):
        conductors.change_of_state(-1.0, 0.0, H0=2e4, **KW)
    with pytest.raises(InputError, match="load_cases"):
        conductors.sag_tension_table(300.0, 0.0, EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4,
                                     temperatures=[0.0], load_cases={"x": (1.0,)})  # fmt: skip
    with pytest.raises(InputError, match="thermal"):
        conductors.thermal_catenary(300.0, 0.0, 10.0, 1e7, length=301.0, alpha=0.1, t=-20.0, t0=0.0)


# --- issue 26, D7 and D8: untyped escapes and refusals naming the wrong argument ---------------


@pytest.mark.parametrize(
    "span, dh, change, names",
    [
        (1e308, 0.0, dict(H0=2e4), ("span", "H0")),  # once an OverflowError (span**2)
        (1e308, 0.0, dict(sag0=2e4), ("span", "sag0")),
        (300.0, 1e308, dict(H0=2e4), ("dh",)),  # once an OverflowError (dh**2)
        (1e-310, 0.0, dict(H0=2e4), ("span",)),  # subnormal: once blamed H
        (300.0, 0.0, dict(H0=2e4, EA=1e-310), ("EA",)),  # once blamed length
        (300.0, 0.0, dict(H0=2e4, w=1e-310), ("w",)),  # once a ConvergenceError with a NaN history
        (300.0, 0.0, dict(H0=2e4, w0=1e-310), ("w0",)),  # once blamed H
        (300.0, 0.0, dict(H0=1e-300), ("H0",)),  # once named H, not an argument of change_of_state
        (300.0, 0.0, dict(sag0=1e-300), ("sag0",)),  # once named sag
        (300.0, 0.0, dict(sag0=1e300), ("sag0",)),
        (300.0, 0.0, dict(H0=2e4, alpha=1e308), ("alpha",)),  # once blamed w
        (300.0, 0.0, dict(H0=2e4, t=1e308), ("t",)),  # once blamed EA
    ],
)
def test_extreme_inputs_are_refused_by_their_public_name(span, dh, change, names):
    kw = {**KW, **change}
    with pytest.raises(InputError) as info:
        conductors.change_of_state(span, dh, **kw)
    assert info.value.argument in names, info.value


def test_sag_tension_table_names_its_temperatures_and_load_cases():
    kw = dict(EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4)
    with pytest.raises(InputError) as info:  # once blamed EA
        conductors.sag_tension_table(
            300.0, 0.0, **kw, temperatures=[1e308, 15], load_cases={"b": (15.0, 0.0)}
        )
    assert info.value.argument == "temperatures"
    with pytest.raises(InputError) as info:
        conductors.sag_tension_table(300.0, 0.0, **kw, temperatures=[15], load_cases={"b": (-1.0, 0.0)})
    assert info.value.argument == "load_cases"


def test_a_thermal_strain_within_range_still_solves():
    # |alpha (t - t0)| just below 1 is refused by no check: an independent mpmath-free oracle is
    # the elastic catenary of length k L0, weight w/k and stiffness EA k
    with warnings.catch_warnings(record=True) as caught:  # a strain of 0.8: it solves, and says so
        warnings.simplefilter("always")
        r = conductors.change_of_state(
            300.0, 0.0, EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4, w=15.0, t=15.0 + 4e4
        )
    # alpha's thermal strain, and t beyond any conductor's temperature
    assert {w.message.argument for w in caught if issubclass(w.category, PlausibilityWarning)} == {
        "alpha",
        "t",
    }
    k = 1 + 2e-5 * 4e4
    e = cable.elastic_catenary(300.0, 0.0, 15.0 / k, 3e7 * k, length=r.L0 * k)
    assert r.H == pytest.approx(e.H, rel=1e-13)
