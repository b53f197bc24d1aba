"""Where peers fail (REFERENCE.md §1): every scene converges right or raises."""

import itertools

import mpmath as mp
import numpy as np
import pytest

from skcable import cable
from skcable.errors import InputError

SPAN_OVER_DH = [1e-3, 1e-1, 1.0, 10.0, 1e3]  # nearly vertical ... nearly level
EXCESS = [1e-9, 1e-6, 1e-2, 1.0, 99.0]  # length/chord - 1: very taut ... 100x chord
SIGN = [1.0, -1.0]  # B above A, B below A

SCENES = list(itertools.product(SPAN_OVER_DH, EXCESS, SIGN))


def reference_a(span, dh, length):
    mp.mp.dps = 50
    span, dh, length = mp.mpf(span), mp.mpf(dh), mp.mpf(length)
    r = mp.sqrt(length**2 - dh**2) / span
    z = mp.findroot(lambda z: mp.log(mp.sinh(z) / z / r), (mp.mpf("1e-15"), mp.mpf(60)), solver="anderson")
    return float(span / (2 * z))


@pytest.mark.parametrize("ratio, excess, sign", SCENES)
def test_catenary_given_length_right_everywhere(ratio, excess, sign):
    dh = sign * 100.0
    span = ratio * 100.0
    # build the length from the chord in exact arithmetic, then round once
    length = float(mp.sqrt(mp.mpf(span) ** 2 + mp.mpf(dh) ** 2) * (1 + mp.mpf(excess)))
    c = cable.catenary(span, dh, 1.0, length=length)
    assert c.residual() <= 1e-10
    # condition number of a w.r.t. the length: (1/2)·S/(S - chord); the
    # answer must be as accurate as a few ulps of the input allow
    condition = 0.5 / excess
    assert c.a == pytest.approx(reference_a(span, dh, length), rel=1e-10 + 8 * 2.2e-16 * condition)
    values = [c.H, c.V_A, c.V_B, c.T_A, c.T_B, c.length, c.sag, c.x_low, c.y_low]
    assert np.all(np.isfinite(values))


@pytest.mark.parametrize("ratio, excess, sign", SCENES)
def test_other_constraints_reproduce_the_same_cable(ratio, excess, sign):
    dh, span = sign * 100.0, ratio * 100.0
    length = float(mp.sqrt(mp.mpf(span) ** 2 + mp.mpf(dh) ** 2) * (1 + mp.mpf(excess)))
    c = cable.catenary(span, dh, 1.0, length=length)
    candidates = [cable.catenary(span, dh, 1.0, sag=c.sag), cable.catenary(span, dh, 1.0, H=c.H)]
    # two cables share a maximum tension; c is one of them
    candidates.append(
        min(
            (cable.catenary(span, dh, 1.0, T_max=c.T_max, branch=b) for b in ("taut", "slack")),
            key=lambda other: abs(other.length - c.length),
        )
    )
    for other in candidates:
        assert other.residual() <= 1e-10
        # sag and T_max are flat in H for taut cables: compare the geometry
        assert other.y(0.5 * span) == pytest.approx(c.y(0.5 * span), rel=1e-6, abs=1e-9 * length)


def test_lowest_point_outside_the_span():
    # steep chord, taut cable: the vertex lies left of A, the cable rises all
    # along the span and its lowest point is A (issue #14: x_low used to be the vertex)
    c = cable.catenary(10.0, 100.0, 1.0, length=100.6)
    assert c.x_vertex < 0
    assert c.y_vertex < 0 and c.residual() < 1e-12
    assert np.all(np.diff(c.y(np.linspace(0, 10, 50))) > 0)  # monotone rise
    assert (c.x_low, c.y_low) == (0.0, 0.0)
    e = cable.elastic_catenary(10.0, 100.0, 1.0, 1e6, length=100.6)
    assert e.x_vertex < 0 and (e.x_low, e.y_low) == (0.0, 0.0)
    # V_A < 0: no material point of the cable has zero slope
    assert e.V_A < 0 and e.slope(0.0) > 0


def test_elastic_catenary_in_the_hard_corners():
    for ratio, excess, sign in [(1e-3, 1e-9, 1), (1e-3, 99.0, -1), (1e3, 1e-9, -1), (1.0, -1e-3, 1)]:
        dh, span = sign * 100.0, ratio * 100.0
        length = np.hypot(span, dh) * (1 + excess)
        e = cable.elastic_catenary(span, dh, 1.0, 1e7, length=length)
        assert e.residual() <= 1e-10


def test_inextensible_length_at_or_below_chord_names_length():
    with pytest.raises(InputError) as info:
        cable.catenary(3.0, -4.0, 1.0, length=5.0)
    assert info.value.argument == "length"
