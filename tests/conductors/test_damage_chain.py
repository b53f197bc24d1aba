"""The damaged-conductor chain: Poffenberger–Swart against its closed form, the Safe Border Line
against its published constants, Miner's sum, and the residual strength (the layer rule against
mechaphlowers, the capacity curves)."""

import mpmath as mp
import numpy as np
import pytest

from skcable import strand
from skcable.conductors import (
    WohlerCurve,
    clamp_stress,
    fatigue_life,
    layer_rrts,
    miner_damage,
    poffenberger_swart,
    residual_strength,
    wire_strengths,
)
from skcable.errors import InputError


def _ps_closed_form(Y_b, H, EI, E_a, d_a, x_b):
    """sigma_a = E_a d_a p² Y_b / (4 (exp(-p x_b) - 1 + p x_b)), p = sqrt(H/EI), at 40 digits."""
    mp.mp.dps = 40
    Y_b, H, EI, E_a, d_a, x_b = (mp.mpf(v) for v in (Y_b, H, EI, E_a, d_a, x_b))
    p = mp.sqrt(H / EI)
    return float(E_a * d_a * p**2 * Y_b / (4 * (mp.exp(-p * x_b) - 1 + p * x_b)))


@pytest.mark.parametrize(
    "Y_b, H, EI",
    [
        (0.5e-3, 28e3, 28.0),  # Drake at 20 % RTS, slip stiffness: p x_b ~ 2.8
        (0.5e-3, 28e3, 1700.0),  # stick stiffness: p x_b ~ 0.36
        (0.2e-3, 5e3, 2000.0),  # p x_b ~ 0.14
        (1e-3, 10.0, 3000.0),  # p x_b ~ 5e-3: the series branch
        (1e-3, 1e-6, 3000.0),  # p x_b ~ 1.6e-6
        (2e-3, 1e5, 1.0),  # p x_b ~ 28
    ],
)
def test_poffenberger_swart_against_its_closed_form(Y_b, H, EI):
    E_a, d_a = 68.9e9, 4.44e-3
    got = poffenberger_swart(Y_b, H, EI, E_a, d_a)
    assert got == pytest.approx(_ps_closed_form(Y_b, H, EI, E_a, d_a, 0.089), rel=1e-14)
    # for p x_b -> 0 the stiff-beam limit: exp(-z) - 1 + z -> z²/2, K -> E_a d_a / (2 x_b²)
    if np.sqrt(H / EI) * 0.089 < 1e-5:
        assert got / Y_b == pytest.approx(E_a * d_a / (2 * 0.089**2), rel=1e-4)


def test_poffenberger_swart_broadcasts_and_refuses():
    Y = np.array([0.25e-3, 0.5e-3, 1e-3])
    s = poffenberger_swart(Y, 28e3, 30.0, 68.9e9, 4.44e-3)
    np.testing.assert_allclose(s / Y, s[0] / Y[0], rtol=1e-15)
    for kw, name in (
        (dict(Y_b=-1e-3), "Y_b"),
        (dict(H=0.0), "H"),
        (dict(EI=-1.0), "EI"),
        (dict(x_b=0.0), "x_b"),
    ):
        args = dict(Y_b=1e-3, H=28e3, EI=30.0, E_a=68.9e9, d_a=4.44e-3) | kw
        with pytest.raises(InputError) as info:
            poffenberger_swart(**args)
        assert info.value.argument == name


def test_clamp_stress_of_a_damaged_drake_is_bounded_by_stick_and_slip():
    drake = strand.preset("acsr-drake")
    intact = clamp_stress(drake, 0.5e-3, 28e3)
    section = drake.section()
    E_a, d_a = drake.layer_materials[-1].E_e, drake.layers[-1].wire_diameter
    assert intact.slip[0] == pytest.approx(
        _ps_closed_form(0.5e-3, 28e3, section.EI_slip[0], E_a, d_a, 0.089), rel=1e-13
    )
    assert intact.stick[0] == pytest.approx(
        _ps_closed_form(0.5e-3, 28e3, section.EI_stick[0], E_a, d_a, 0.089), rel=1e-13
    )
    assert intact.low < intact.high  # the slip stiffness, smaller, gives the larger stress
    assert intact.high == pytest.approx(float(np.max(intact.slip)), rel=1e-15)
    broken = clamp_stress(drake.damaged(2), 0.5e-3, 28e3)
    assert broken.EI_stick.min() < intact.EI_stick.min()


# CIGRE SC22 WG04 (1979), "Recommendations for the evaluation of the lifetime of transmission line
# conductors", Electra 63, as tabulated in EPRI, "Transmission Line Reference Book: Wind-Induced
# Conductor Motion" (2006), the Safe Border Line: sigma_a = A N^b MPa.
SBL = {1: ((730.0, -0.2), (430.0, -0.168)), 2: ((450.0, -0.2), (263.0, -0.168))}


@pytest.mark.parametrize("layers", [1, 2, 3])
def test_safe_border_line_against_its_published_constants(layers):
    line = WohlerCurve.safe_border_line(layers)
    (A1, b1), (A2, b2) = SBL[min(layers, 2)]
    for N in (1e5, 1e6, 1.9e7):
        assert line.amplitude(N) == pytest.approx(A1 * 1e6 * N**b1, rel=1e-14)
    for N in (2e7, 1e8, 5e8):
        assert line.amplitude(N) == pytest.approx(A2 * 1e6 * N**b2, rel=1e-14)
    N = np.array([1e5, 3e6, 1.9e7, 2.5e7, 1e8, 5e8])  # (not within the 0.1 % overlap at the joint)
    np.testing.assert_allclose(line.cycles(line.amplitude(N)), N, rtol=1e-12)
    # the two pieces meet at 2e7 cycles within 1.5 % (the published constants are rounded)
    assert A1 * 2e7**b1 == pytest.approx(A2 * 2e7**b2, rel=1.5e-2)


def test_miner_sum_over_a_histogram():
    curve = WohlerCurve(((0.0, 400e6, -0.25),))
    amplitudes = np.array([5e6, 10e6, 20e6])
    counts = np.array([1e9, 1e8, 1e6])
    expected = sum(n / (s / 400e6) ** (1 / -0.25) for s, n in zip(amplitudes, counts, strict=True))
    assert miner_damage(amplitudes, counts, curve) == pytest.approx(expected, rel=1e-14)
    assert fatigue_life(amplitudes, counts, curve) == pytest.approx(1 / expected, rel=1e-14)
    assert fatigue_life(amplitudes, 0 * counts, curve) == float("inf")
    # a constant amplitude at the curve's own life is D = 1
    sbl = WohlerCurve.safe_border_line(2)
    assert miner_damage([sbl.amplitude(3e7)], [3e7], sbl) == pytest.approx(1.0, rel=1e-12)
    with pytest.raises(InputError) as info:
        miner_damage([5e6, 1e7], [1.0], curve)
    assert info.value.argument == "counts"
    with pytest.raises(InputError) as info:
        WohlerCurve(((0.0, 400e6, 0.25),))
    assert info.value.argument == "pieces"


def test_layer_rule_against_mechaphlowers():
    """The same conductor (Drake, ASTM B232 rated strength 140.1 kN, the wire shares of
    `wire_strengths`) with 2 outer wires broken: mechaphlowers' AdditiveLayerRts."""
    pd = pytest.importorskip("pandas")
    cable_strength = pytest.importorskip("mechaphlowers.core.models.cable.cable_strength")
    drake = strand.preset("acsr-drake")
    rts = 140.1e3
    share = wire_strengths(drake, rts)  # core, steel layer, inner, outer aluminium
    counts = [1, 6, 10, 16]
    data = {"rts_cable": [rts]}  # mechaphlowers: layer 1 is the outer one
    for i, k in enumerate(reversed(range(4))):
        data[f"rts_layer_{i + 1}"] = [share[k]]
        data[f"nb_strand_layer_{i + 1}"] = [counts[k]]
    model = cable_strength.AdditiveLayerRts(pd.DataFrame(data))
    model.cut_strands = [2, 0, 0, 0]
    ours = residual_strength(drake, 2, rts=rts)
    assert ours.rrts == pytest.approx(model.rrts, rel=1e-15)
    assert model.rts_coverage() == pytest.approx(1.0, rel=1e-13)  # the shares add up to rts
    assert list(ours.broken) == [0, 0, 0, 2]


def test_layer_rule_and_capacity_curve():
    drake = strand.preset("acsr-drake")
    rts = 140.1e3
    share = wire_strengths(drake, rts)
    assert layer_rrts(rts, [0, 0, 1, 2], share) == pytest.approx(rts - share[2] - 2 * share[3], rel=1e-15)
    by_fe = residual_strength(drake, 2, rts=rts, method="capacity")
    assert by_fe.force_damaged < by_fe.force_intact
    assert by_fe.rrts == pytest.approx(rts * by_fe.force_damaged / by_fe.force_intact, rel=1e-15)
    # the eccentric net section bends: it loses more than the broken wires' share
    assert by_fe.rrts < residual_strength(drake, 2, rts=rts).rrts * 1.001
    with pytest.raises(InputError) as info:
        layer_rrts(rts, [0, 0, 0, 1000], share)
    assert info.value.argument == "broken"
    with pytest.raises(InputError) as info:
        residual_strength(drake, 2, rts=rts, method="guess")
    assert info.value.argument == "method"
