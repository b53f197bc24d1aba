"""conductors.Conductor: data from a strand (closed forms, catalogue masses), ice and wind loads, and the
sag–tension of an intact and a damaged conductor against an independent solution of the
thermal elastic catenary (scipy root finding on Irvine's level-span equations written here)."""

from math import asinh, cos, pi, sqrt

import numpy as np
import pytest
from scipy.optimize import brentq

from skcable import conductors, strand
from skcable.errors import InputError

G = 9.80665
STEEL, ALUMINIUM = strand.material("steel"), strand.material("aluminium")


def _sigma_beyond_blend(material, strain):
    """The hardening line of the wire law (strain beyond eps_y2): E_e ε_y + E_p (ε − ε_y)."""
    assert strain > material.eps_y2
    return material.E_e * material.eps_y + material.E_p * (strain - material.eps_y)


def test_from_a_one_material_strand_the_closed_forms():
    s = strand.preset("steel-9.5")
    d, alpha = 3.1e-3, np.radians(7.5)
    A = pi * d**2 / 4
    c = conductors.Conductor.from_strand(s)
    assert c.EA == pytest.approx(STEEL.E_e * A * (1 + 6 * cos(alpha) ** 3), rel=1e-12)
    assert c.w == pytest.approx(G * 7780.0 * A * (1 + 6 / cos(alpha)), rel=1e-12)
    assert c.alpha == pytest.approx(STEEL.alpha, rel=1e-12)
    assert c.diameter == pytest.approx(3 * d, rel=1e-12)
    # the core (straight) reaches eps_rupture first; the helical wires are then at cos²α of it
    eps = STEEL.eps_rupture
    rts = A * _sigma_beyond_blend(STEEL, eps) + 6 * A * cos(alpha) * _sigma_beyond_blend(
        STEEL, cos(alpha) ** 2 * eps
    )
    assert c.rupture_force == pytest.approx(rts, rel=1e-12)
    assert c.rts is None  # a rated strength is never derived from the wire laws


@pytest.mark.parametrize(
    "name, mass",
    # ASTM B232 / B232M ACSR tables: Drake 1094 lb/kft, Hawk 656 lb/kft (1 lb/kft = 1.48816 kg/km)
    [("acsr-drake", 1094 * 1.488164e-3), ("acsr-hawk", 656 * 1.488164e-3)],
)
def test_acsr_weight_is_the_catalogue_mass(name, mass):
    c = conductors.Conductor.from_strand(strand.preset(name))
    assert c.w / G == pytest.approx(mass, rel=1e-3)


def test_acsr_alpha_is_the_stiffness_weighted_mean_and_damage_removes_outer_aluminium():
    drake = strand.preset("acsr-drake")
    R, cos_a = drake.helix_radii, np.cos(drake.lay_angles)
    As, Aa = pi * 3.454e-3**2 / 4, pi * 4.442e-3**2 / 4
    ks = STEEL.E_e * As * (1 + 6 * cos_a[0] ** 3)
    ka = ALUMINIUM.E_e * Aa * (10 * cos_a[1] ** 3 + 16 * cos_a[2] ** 3)
    intact = conductors.Conductor.from_strand(drake)
    assert len(R) == 3
    assert intact.EA == pytest.approx(ks + ka, rel=1e-12)
    assert intact.alpha == pytest.approx((ks * 11.5e-6 + ka * 23e-6) / (ks + ka), rel=1e-12)
    broken = conductors.Conductor.from_strand(drake, damage=2)
    lost = 2 * ALUMINIUM.E_e * Aa * cos_a[2] ** 3
    assert broken.EA == pytest.approx(ks + ka - lost, rel=1e-12)
    assert broken.alpha == pytest.approx((ks * 11.5e-6 + (ka - lost) * 23e-6) / (ks + ka - lost), rel=1e-12)
    assert broken.w == intact.w  # the broken wires still hang in the span
    assert broken.rupture_force < intact.rupture_force
    # damage as a list of wires: the same two outer wires in the preset's numbering (no rotation)
    listed = conductors.Conductor.from_strand(drake, damage=[(3, 0), (3, 1)])
    assert listed.EA == pytest.approx(broken.EA, rel=1e-12)
    # a stiffness from elsewhere (e.g. a capacity curve's K_Leq) replaces EA only
    given = conductors.Conductor.from_strand(drake, damage=2, EA=0.9 * broken.EA)
    assert (given.EA, given.w, given.alpha, given.rupture_force) == (
        0.9 * broken.EA,
        broken.w,
        broken.alpha,
        broken.rupture_force,
    )
    # ASTM B232: Drake's rated strength 31 200 lbf = 138.8 kN, given, not derived
    rated = conductors.Conductor.from_strand(drake, rts=138.8e3)
    assert rated.rts == 138.8e3 and rated.rupture_force == intact.rupture_force


def test_ice_and_wind_loads():
    c = conductors.Conductor(EA=3e7, w=16.0, alpha=19e-6, diameter=0.028)
    b = np.array([0.0, 0.01, 0.025])
    annulus = pi * ((0.014 + b) ** 2 - 0.014**2)  # the area between two circles
    np.testing.assert_allclose(c.ice_load(b), 917.0 * G * annulus, rtol=1e-12)
    np.testing.assert_allclose(c.ice_load(b, density=900.0, g=9.81), 900.0 * 9.81 * annulus, rtol=1e-12)
    np.testing.assert_allclose(c.wind_load(400.0, ice=b), 400.0 * (0.028 + 2 * b), rtol=1e-15)


# --- sag–tension against an independent solution -------------------------------------------
def _span_of(H, w, EA, L0, k):
    """Horizontal projection of a level thermal elastic catenary: x = ∫ (H/T)(k + T/EA) ds0 over
    the unstressed length L0 (weight w per unstressed length, T² = H² + (V_A − w s0)², V_A = w L0/2)."""
    return 2 * k * H / w * asinh(w * L0 / (2 * H)) + H * L0 / EA


def _sag_of(H, w, EA, L0, k):
    """Mid-span sag: ∫ (V/T)(k + T/EA) ds0 over the first half."""
    return k * H / w * (sqrt(1 + (w * L0 / (2 * H)) ** 2) - 1) + w * L0**2 / (8 * EA)


def _independent(span, w, EA, alpha, L0, t, t0):
    k = 1 + alpha * (t - t0)
    H = brentq(lambda H: _span_of(H, w, EA, L0, k) - span, 1.0, 1e9, xtol=1e-12, rtol=1e-15)
    return H, _sag_of(H, w, EA, L0, k)


SPAN, T0, H0 = 400.0, 15.0, 28e3
TEMPERATURES = np.array([-20.0, 0.0, 15.0, 50.0, 75.0, 100.0])


def test_damaged_conductor_sags_more_and_both_match_the_independent_solution():
    """The example of docs/conductors.md: ACSR Drake strung at 28 kN (15 °C) on a level 400 m
    span; two outer aluminium wires then break (the same unstressed length L0)."""
    drake = strand.preset("acsr-drake")
    intact = conductors.Conductor.from_strand(drake)
    broken = conductors.Conductor.from_strand(drake, damage=2)
    a = intact.change_of_state(SPAN, 0.0, t0=T0, H0=H0, t=TEMPERATURES)
    L0 = brentq(lambda L: _span_of(H0, intact.w, intact.EA, L, 1.0) - SPAN, SPAN, 1.01 * SPAN, xtol=1e-13)
    assert a.L0 == pytest.approx(L0, rel=1e-11)
    b = broken.change_of_state(SPAN, 0.0, t0=T0, length=L0, t=TEMPERATURES)
    assert b.L0 == pytest.approx(L0, rel=1e-10)
    for conductor, result in ((intact, a), (broken, b)):
        expected = np.array(
            [_independent(SPAN, conductor.w, conductor.EA, conductor.alpha, L0, t, T0) for t in TEMPERATURES]
        )
        np.testing.assert_allclose(result.H, expected[:, 0], rtol=1e-9)
        np.testing.assert_allclose(result.sag, expected[:, 1], rtol=1e-9)
    extra = b.sag - a.sag
    assert np.all(extra > 0.02)  # 2.5 to 13 cm more
    assert np.all(np.diff(extra) < 0)  # less at high temperature: lower tension, less stretch


def test_iced_and_windy_state_is_the_resultant_load_in_the_cable_plane():
    c = conductors.Conductor.from_strand(strand.preset("acsr-hawk"))
    b, p = 0.0125, 380.0
    r = c.change_of_state(SPAN, 0.0, t0=T0, H0=18e3, t=-5.0, ice=b, wind_pressure=p)
    q = np.hypot(c.w + 917.0 * G * pi * b * (c.diameter + b), p * (c.diameter + 2 * b))
    L0 = brentq(lambda L: _span_of(18e3, c.w, c.EA, L, 1.0) - SPAN, SPAN, 1.01 * SPAN, xtol=1e-13)
    k = 1 + c.alpha * (-5.0 - T0)
    # weight q per unstressed length in the plane of the resultant (a level span: the same span)
    H = brentq(lambda H: _span_of(H, q, c.EA, L0, k) - SPAN, 1.0, 1e9, xtol=1e-12, rtol=1e-15)
    assert r.H == pytest.approx(H, rel=1e-9)
    assert r.sag == pytest.approx(_sag_of(H, q, c.EA, L0, k), rel=1e-9)


def test_sag_tension_table_rows_are_the_change_of_state_results():
    c = conductors.Conductor.from_strand(strand.preset("acsr-drake"), rts=138.8e3)
    assert "T_max_per_rts" not in conductors.Conductor.from_strand(
        strand.preset("acsr-drake")
    ).sag_tension_table(SPAN, t0=T0, H0=H0, temperatures=[15.0])
    cases = {"bare": (0.0, 0.0), "ice": (0.0125, 0.0), "wind": (0.0, 380.0)}
    df = c.sag_tension_table(SPAN, t0=T0, H0=H0, temperatures=[-5.0, 15.0, 75.0], load_cases=cases)
    for name, (ice, p) in cases.items():
        r = c.change_of_state(SPAN, t0=T0, H0=H0, t=np.array([-5.0, 15.0, 75.0]), ice=ice, wind_pressure=p)
        np.testing.assert_allclose(df.loc[name, "H"], r.H, rtol=1e-12)
        np.testing.assert_allclose(df.loc[name, "T_max_per_rts"], r.T_max / c.rts, rtol=1e-12)


def test_bad_input_raises_naming_the_argument():
    def raises(argument, call):
        with pytest.raises(InputError) as err:
            call()
        assert err.value.argument == argument

    good = dict(EA=3e7, w=16.0, alpha=19e-6, diameter=0.028)
    raises("EA", lambda: conductors.Conductor(**(good | {"EA": -1.0})))
    raises("w", lambda: conductors.Conductor(**(good | {"w": float("nan")})))
    raises("diameter", lambda: conductors.Conductor(**(good | {"diameter": 0.0})))
    raises("rts", lambda: conductors.Conductor(**good, rts=-5.0))
    raises("alpha", lambda: conductors.Conductor(**(good | {"alpha": "19e-6"})))
    c = conductors.Conductor(**good)
    raises("thickness", lambda: c.ice_load(-0.01))
    raises("density", lambda: c.ice_load(0.01, density=0.0))
    raises("pressure", lambda: c.wind_load(-1.0))
    raises("ice", lambda: c.change_of_state(400.0, t0=15.0, H0=2e4, t=15.0, ice=-0.01))
    raises(
        "ice_density", lambda: c.change_of_state(400.0, t0=15.0, H0=2e4, t=15.0, ice=0.01, ice_density=0.0)
    )
    raises("wind_pressure", lambda: c.change_of_state(400.0, t0=15.0, H0=2e4, t=15.0, wind_pressure=-1.0))
    raises("length", lambda: c.change_of_state(SPAN, t0=T0, H0=H0, length=SPAN, t=0.0))
    raises("length", lambda: c.change_of_state(SPAN, t0=T0, length=SPAN, t=0.0, model="parabola"))
    raises("H0", lambda: c.change_of_state(SPAN, t0=T0, t=0.0))
    raises(
        "load_cases", lambda: c.sag_tension_table(SPAN, t0=T0, H0=H0, temperatures=[0], load_cases={"x": 1})
    )
    raises(
        "load_cases",
        lambda: c.sag_tension_table(SPAN, t0=T0, H0=H0, temperatures=[0], load_cases={"x": (-0.01, 0)}),
    )
    raises("strand", lambda: conductors.Conductor.from_strand("steel-9.5"))
    raises("damage", lambda: conductors.Conductor.from_strand(strand.preset("steel-9.5"), damage="two"))
    raises("n", lambda: conductors.Conductor.from_strand(strand.preset("steel-9.5"), damage=6))
    raises("EA", lambda: conductors.Conductor.from_strand(strand.preset("steel-9.5"), EA=0.0))
    raises("g", lambda: conductors.Conductor.from_strand(strand.preset("steel-9.5"), g=-9.8))
    # a material without density cannot give a weight
    bare = strand.Material(2e11, 1e9, eps_y=0.004, eps_y1=0.003, eps_y2=0.005, eps_rupture=0.05, alpha=12e-6)
    s = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=0.1),), bare)
    with pytest.raises(InputError, match="density") as err:
        conductors.Conductor.from_strand(s)
    assert err.value.argument == "strand"
