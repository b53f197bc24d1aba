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


# -- issue 26: mirror and unit-scale invariance of the closed forms, against 50-digit oracles ---
EPS = 2.0**-52
#: (span, dh, w, strain w·L/EA, excess length/chord - 1), drawn once from a seeded generator
_rng = np.random.default_rng(26)
INVARIANCE_SCENES = [
    (
        float(10 ** _rng.uniform(-2, 3)),
        float(np.tan(_rng.uniform(-1.4, 1.4))),
        float(10 ** _rng.uniform(-2, 4)),
        float(10 ** _rng.uniform(-7, -1)),
        float(10 ** _rng.uniform(-8, 1)),
    )
    for _ in range(16)
]
TRANSFORMS = {  # (mirror, length factor, force factor)
    "mirror": (True, 1.0, 1.0),
    "metres x10": (False, 10.0, 1.0),
    "metres x1000": (False, 1000.0, 1.0),
    "newtons x10": (False, 1.0, 10.0),
    "newtons x1000": (False, 1.0, 1000.0),
}


def _transformed(span, slope, w, L_over_chord, transform):
    """The scene's (span, dh, w, length) after ``transform``: B mirrored (dh -> -dh), or lengths
    and forces in other units (w in force per length)."""
    mirror, k_length, k_force = transform
    dh = span * slope * (-1.0 if mirror else 1.0)
    length = float(mp.sqrt(mp.mpf(span) ** 2 + mp.mpf(span * slope) ** 2) * (1 + mp.mpf(L_over_chord)))
    return span * k_length, dh * k_length, w * k_force / k_length, length * k_length


def _parabola_a(span, dh, length):
    mp.mp.dps = 50
    span, dh, length = mp.mpf(span), mp.mpf(dh), mp.mpf(length)
    slope = dh / span

    def excess(log_a):
        a = mp.exp(log_a)
        p_a, p_b = slope - span / (2 * a), slope + span / (2 * a)
        primitive = lambda p: p * mp.sqrt(1 + p * p) + mp.asinh(p)  # noqa: E731
        return mp.log(a / 2 * (primitive(p_b) - primitive(p_a)) / length)

    chord = mp.sqrt(span**2 + dh**2)
    guess = mp.sqrt(span / (24 * (length - chord))) * span / (1 + slope**2) ** mp.mpf(0.75)
    return float(mp.exp(mp.findroot(excess, mp.log(guess))))


@pytest.mark.parametrize("scene", INVARIANCE_SCENES, ids=[f"scene{i}" for i in range(16)])
def test_closed_forms_are_mirror_and_unit_invariant(scene):
    """Each transformed scene against its own 50-digit root: to 1e-12, or to a few ulps of the
    data times the condition number where the scene allows no better; the mirror (exact data)
    against the scene itself."""
    from tests.cable.test_elastic import assert_root

    span, slope, w, strain, excess = scene
    base = _transformed(span, slope, w, excess, (False, 1.0, 1.0))
    c0 = cable.catenary(*base[:3], length=base[3])
    e0 = cable.elastic_catenary(*base[:3], base[2] * base[3] / strain, length=base[3])
    condition = 1.0 + 0.5 / excess  # of a = H/w with respect to the length
    tol = max(1e-12, 8 * EPS * condition)
    for name, transform in TRANSFORMS.items():
        span_t, dh_t, w_t, L_t = _transformed(span, slope, w, excess, transform)
        k_force = transform[2]
        c = cable.catenary(span_t, dh_t, w_t, length=L_t)
        assert c.a == pytest.approx(reference_a(span_t, dh_t, L_t), rel=tol), name
        p = cable.parabola(span_t, dh_t, w_t, length=L_t)
        assert p.a == pytest.approx(_parabola_a(span_t, dh_t, L_t), rel=tol), name
        EA_t = w_t * L_t / strain
        e = cable.elastic_catenary(span_t, dh_t, w_t, EA_t, length=L_t)
        assert_root(e, (span_t, dh_t, w_t, EA_t, L_t))
        if transform[0]:  # the mirror: the same data, A and B swapped
            assert (c.H, c.V_A, c.V_B) == (c0.H, c0.V_B, c0.V_A)
            assert e.H / k_force == pytest.approx(e0.H, rel=max(1e-12, 64 * EPS * condition))
            assert e.V_A == pytest.approx(e0.V_B, rel=1e-12, abs=1e-12 * e0.T_max)
