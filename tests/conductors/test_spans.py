"""Ruling span and the exact tension section with suspension strings."""

import numpy as np
import pytest
from scipy.optimize import brentq, fsolve

from skcable import cable, conductors
from skcable.conductors._spans import _Section
from skcable.errors import ConvergenceError, InputError

CONDUCTOR = dict(EA=3.0e7, alpha=2.3e-5, w0=15.0, t0=15.0, H0=2.0e4)
SPANS = [300.0, 450.0, 250.0, 400.0]
STRINGS = dict(insulator_length=2.5, insulator_weight=600.0)


def test_ruling_span_is_the_common_tension_of_the_parabolic_section():
    """Independent derivation: at a common H the parabolic length excess w²L³/24H² plus
    the elastic and thermal strains, summed over the level spans, is conserved; the H
    solving that (brentq) is the parabolic change of state of the span sqrt(ΣL³/ΣL)."""
    spans = np.array(SPANS)
    EA, alpha, w0, t0, H0 = (CONDUCTOR[k] for k in ("EA", "alpha", "w0", "t0", "H0"))
    w, t = 22.0, -5.0

    def excess(H, w, t):  # (stretched length - span) summed over the spans, at L0 fixed
        return np.sum(w**2 * spans**3 / (24 * H**2) - H * spans / EA - alpha * (t - t0) * spans)

    H = brentq(lambda H: excess(H, w, t) - excess(H0, w0, t0), 1e3, 1e6, xtol=1e-12, rtol=1e-15)
    L_r = conductors.ruling_span(spans)
    ruling = conductors.change_of_state(L_r, 0.0, **CONDUCTOR, w=w, t=t, model="parabola")
    assert ruling.H == pytest.approx(H, rel=1e-12)
    assert conductors.ruling_span([123.0]) == 123.0
    assert conductors.ruling_span([1e200, 1e200]) == pytest.approx(1e200, rel=1e-15)


def test_equal_level_spans_are_each_a_single_span():
    section = conductors.tension_section(
        [350.0] * 4, 0.0, **CONDUCTOR, w=[15.0, 25.0], t=[[-20.0], [60.0]], **STRINGS
    )
    single = conductors.change_of_state(350.0, 0.0, **CONDUCTOR, w=[15.0, 25.0], t=[[-20.0], [60.0]])
    assert section.H.shape == (2, 2, 4)
    np.testing.assert_allclose(section.H, np.repeat(single.H[..., None], 4, -1), rtol=1e-12)
    np.testing.assert_allclose(section.sag, np.repeat(single.sag[..., None], 4, -1), rtol=1e-12)
    np.testing.assert_array_equal(section.swing, 0.0)
    # equal spans: the ruling span is the span and its approximation is exact
    np.testing.assert_allclose(section.H_gap, 0.0, atol=1e-12)


def test_zero_length_strings_leave_the_spans_independent():
    dh = [10.0, -25.0, 5.0, 30.0]
    section = conductors.tension_section(
        SPANS, dh, **CONDUCTOR, w=25.0, t=[-20.0, 60.0], insulator_length=0.0, insulator_weight=600.0
    )
    for i, (span, h) in enumerate(zip(SPANS, dh, strict=True)):
        alone = conductors.change_of_state(span, h, **CONDUCTOR, w=25.0, t=[-20.0, 60.0])
        np.testing.assert_allclose(section.H[:, i], alone.H, rtol=1e-10)  # solver tolerance
        np.testing.assert_allclose(section.sag[:, i], alone.sag, rtol=1e-10)
    np.testing.assert_array_equal(section.swing, 0.0)


def test_moment_balance_of_every_string():
    section = conductors.tension_section(
        SPANS, [0.0, 20.0, -10.0, 0.0], **CONDUCTOR, w=18.0, t=70.0, **STRINGS
    )
    dH = np.diff(section.H)
    load = section.V_B[:-1] + section.V_A[1:] + 0.5 * STRINGS["insulator_weight"]
    np.testing.assert_allclose(np.tan(section.swing_angle), dH / load, rtol=1e-9, atol=1e-13)
    np.testing.assert_allclose(section.swing, 2.5 * np.sin(section.swing_angle), rtol=1e-14)
    np.testing.assert_allclose(section.clamp_rise, 2.5 * (1 - np.cos(section.swing_angle)), rtol=1e-9)
    # the clamps moved, the dead-ends did not: the spans add up to the section's length
    assert np.sum(section.span) == pytest.approx(np.sum(SPANS), rel=1e-15)
    assert np.sum(section.dh) == pytest.approx(10.0, rel=1e-13)
    assert section.moment_residual < 1e-11
    # the hot, long-span side loses tension less than the short spans: strings swing
    # toward the longer span
    assert np.all(np.sign(section.swing) == np.sign(np.diff(section.H)))


def test_jacobian_equals_central_differences():
    spans = np.array(SPANS)
    dh = [0.0, 20.0, -10.0, 0.0]
    L0 = np.array(
        [
            conductors.change_of_state(a, h, **CONDUCTOR, w=15.0, t=15.0).L0
            for a, h in zip(spans, dh, strict=True)
        ]
    )
    eqs = _Section(spans, np.array([0.0, 20, -10, 0]), L0, 3e7, 21.0, 2.3e-5, 55.0, 15.0,
                   np.array([2.5, 1.5, 3.0]), np.array([600.0, 300.0, 900.0]))  # fmt: skip
    delta = np.array([0.3, -0.2, 0.5])
    _, _, (sub, diag, sup), _ = eqs.residual(delta)
    J = np.diag(diag) + np.diag(sub[1:], -1) + np.diag(sup[:-1], 1)
    step = 1e-6
    numeric = np.column_stack(
        [
            (eqs.residual(delta + step * e)[0] - eqs.residual(delta - step * e)[0]) / (2 * step)
            for e in np.eye(3)
        ]
    )
    numeric *= np.minimum(eqs.lam, 1.0)  # the Jacobian is in delta / min(lam, 1)
    np.testing.assert_allclose(J, numeric, rtol=2e-6, atol=1e-6 * np.abs(J).max())


def _reference_lengths(spans, dh, w0, EA, H0):
    """Each span's unstressed length at H0: brentq on the elastic catenary's H, span by span."""

    def one(a, h):
        chord = np.hypot(a, h)
        return brentq(
            lambda L: cable.elastic_catenary(a, h, w0, EA, length=L).H - H0,
            chord * 0.999,
            chord * 1.05,
            xtol=1e-14,
            rtol=1e-15,
        )

    return np.array([one(a, h) for a, h in zip(spans, dh, strict=True)])


def _independent(spans, dh, EA, alpha, w0, t0, H0, w, t, lam, W):
    """The same section written afresh: unknowns the swing angles, each span Irvine's
    elastic catenary of length k L0, weight w/k, stiffness EA k (k = 1 + alpha (t - t0)),
    L0 from the reference tension by brentq, the balance by fsolve."""
    spans, dh = np.asarray(spans), np.asarray(dh)
    L0 = _reference_lengths(spans, dh, w0, EA, H0)
    k = 1 + alpha * (t - t0)

    def spans_of(phi):
        x = np.concatenate([[0.0], lam * np.sin(phi), [0.0]])
        z = np.concatenate([[0.0], lam * (1 - np.cos(phi)), [0.0]])
        return [
            cable.elastic_catenary(a + x[i + 1] - x[i], h + z[i + 1] - z[i], w / k, EA * k, length=k * L)
            for i, (a, h, L) in enumerate(zip(spans, dh, L0, strict=True))
        ]

    def balance(phi):
        c = spans_of(phi)
        return [
            ((c[j + 1].H - c[j].H) - np.tan(phi[j]) * (c[j].V_B + c[j + 1].V_A + W / 2)) / H0
            for j in range(len(phi))
        ]

    phi = fsolve(balance, np.zeros(len(spans) - 1), xtol=1e-14)
    return phi, spans_of(phi)


def test_against_an_independent_solution():
    dh = [0.0, 20.0, -10.0, 0.0]
    section = conductors.tension_section(SPANS, dh, **CONDUCTOR, w=30.0, t=-10.0, **STRINGS)
    phi, spans = _independent(SPANS, dh, **CONDUCTOR, w=30.0, t=-10.0, lam=2.5, W=600.0)
    np.testing.assert_allclose(section.swing_angle, phi, rtol=1e-8)
    np.testing.assert_allclose(section.H, [s.H for s in spans], rtol=1e-10)
    np.testing.assert_allclose(section.sag, [s.sag for s in spans], rtol=1e-10)
    assert np.abs(section.swing_angle).max() > 1e-3  # a real swing, not a trivial case


def test_long_strings_equalise_the_tension_as_the_ruling_span_assumes():
    section = conductors.tension_section(
        SPANS, 0.0, **CONDUCTOR, w=15.0, t=[-20.0, 80.0], insulator_length=1e4, insulator_weight=1.0
    )
    spread = section.H.max(axis=-1) / section.H.min(axis=-1) - 1
    assert np.all(spread < 2e-4)
    # a free section at one H: the ruling span's tension up to its parabolic terms
    np.testing.assert_allclose(section.H_gap, 0.0, atol=2e-3)
    short = conductors.tension_section(SPANS, 0.0, **CONDUCTOR, w=15.0, t=[-20.0, 80.0], **STRINGS)
    assert np.all(np.abs(short.H_gap).max(axis=-1) > 10 * np.abs(section.H_gap).max(axis=-1))


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(spans=[100.0, -1.0]), "spans"),
        (dict(dh=[0.0, 1.0, 2.0]), "dh"),
        (dict(EA=0.0), "EA"),
        (dict(H0=float("nan")), "H0"),
        (dict(w=-1.0), "w"),
        (dict(insulator_length=-1.0), "insulator_length"),
        (dict(insulator_weight=[1.0, 2.0, 3.0]), "insulator_weight"),
        (dict(t=-1e5), "t"),
        (dict(alpha="x"), "alpha"),
    ],
)
def test_bad_input_is_named(kwargs, name):
    args = dict(spans=[100.0, 200.0], dh=0.0, **CONDUCTOR, w=15.0, t=20.0, **STRINGS) | kwargs
    spans = args.pop("spans")
    with pytest.raises(InputError) as info:
        conductors.tension_section(spans, **args)
    assert info.value.argument == name
    with pytest.raises(InputError, match="spans"):
        conductors.ruling_span([[1.0, 2.0]])


def test_one_span_is_the_change_of_state():
    section = conductors.tension_section([300.0], 5.0, **CONDUCTOR, w=15.0, t=60.0, **STRINGS)
    alone = conductors.change_of_state(300.0, 5.0, **CONDUCTOR, w=15.0, t=60.0)
    assert section.H.shape == (1,) and section.swing.shape == (0,)
    # both paths sit within a few 1e-12 of the 40-digit H (16659.056581833374 N): the closure
    # fixes L0 to ~1e-14, and H/EA = 7e-4 amplifies that by EA/H in H
    assert section.H[0] == pytest.approx(alone.H, rel=1e-11)
    assert section.H[0] == pytest.approx(16659.056581833374, rel=4e-12)


def test_non_convergence_raises_with_its_history(monkeypatch):
    import skcable.conductors._spans as spans

    monkeypatch.setattr(spans, "_MAX_ITER", 1)
    with pytest.raises(ConvergenceError) as info:
        conductors.tension_section(SPANS, 0.0, **CONDUCTOR, w=15.0, t=60.0, **STRINGS)
    assert len(info.value.history) == 2 and info.value.history[1] < info.value.history[0]


def test_a_very_stiff_taut_conductor_converges_to_its_round_off():
    """EA = 1e11 N at H0 = 200 kN: the spans' closure tolerance (1e-13 of the chord) moves H by
    ~1e-10 of H; Newton stops there and reports it, the balance still holds to that."""
    section = conductors.tension_section(
        [100.0, 500.0, 250.0, 800.0, 50.0], [0, 50, -80, 20, 5], EA=1e11, alpha=2e-5, w0=15.0, t0=15.0,
        H0=2e5, w=40.0, t=90.0, insulator_length=4.0, insulator_weight=300.0,
    )  # fmt: skip
    assert 0 < section.moment_residual < 1e-8
    load = section.V_B[:-1] + section.V_A[1:] + 150.0
    np.testing.assert_allclose(np.tan(section.swing_angle), np.diff(section.H) / load, rtol=1e-6)


# --- issue 26, D7 and D8 -----------------------------------------------------------------------


@pytest.mark.parametrize("length", [1e-300, 5e-324])
def test_a_vanishing_string_is_a_fixed_clamp(length):
    """Once a LinAlgError (the Jacobian divided by the string's length): a string of 1e-300 m or
    a subnormal one holds its clamp as a string of length 0 does (independent spans)."""
    kw = dict(**CONDUCTOR, w=15.0, t=80.0, insulator_weight=600.0)
    short = conductors.tension_section([100.0, 200.0, 300.0], **kw, insulator_length=length)
    fixed = conductors.tension_section([100.0, 200.0, 300.0], **kw, insulator_length=0.0)
    alone = [conductors.change_of_state(a, 0.0, **CONDUCTOR, w=15.0, t=80.0).H for a in (100.0, 200.0, 300.0)]
    np.testing.assert_allclose(short.H, fixed.H, rtol=1e-12)
    np.testing.assert_allclose(fixed.H, alone, rtol=1e-11)  # the one-span path: to its ~4e-12


def test_a_huge_string_equalises_the_tensions():
    section = conductors.tension_section(
        [100.0, 200.0], **CONDUCTOR, w=15.0, t=20.0, insulator_length=1e308, insulator_weight=600.0
    )
    assert section.H[1] == pytest.approx(section.H[0], rel=1e-9)


def test_string_weights_one_per_string():
    kw = dict(**CONDUCTOR, w=15.0, t=60.0, insulator_length=2.5)
    spans = [250.0, 450.0, 300.0]
    same = conductors.tension_section(spans, **kw, insulator_weight=[600.0, 600.0])
    scalar = conductors.tension_section(spans, **kw, insulator_weight=600.0)
    np.testing.assert_array_equal(same.H, scalar.H)
    heavy = conductors.tension_section(spans, **kw, insulator_weight=[600.0, 5000.0])
    load = heavy.V_B[:-1] + heavy.V_A[1:] + 0.5 * np.array([600.0, 5000.0])  # the weights as given
    np.testing.assert_allclose(np.tan(heavy.swing_angle), np.diff(heavy.H) / load, rtol=1e-8)
    for bad in ([600.0], [600.0, 600.0, 600.0], [[600.0, 600.0]], [600.0, -1.0], [600.0, "x"]):
        with pytest.raises(InputError) as info:
            conductors.tension_section(spans, **kw, insulator_weight=bad)
        assert info.value.argument == "insulator_weight"


@pytest.mark.parametrize(
    "change, name",
    [
        (dict(alpha=1e308), "alpha"),  # once blamed w
        (dict(t=1e308), "t"),
        (dict(w0=1e-310), "w0"),
        (dict(EA=1e-310), "EA"),
        (dict(H0=1e-300), "H0"),  # once named H
        (dict(spans=[1e-310, 100.0]), "spans"),
    ],
)
def test_extreme_inputs_name_their_argument(change, name):
    args = dict(spans=[100.0, 200.0], **CONDUCTOR, w=15.0, t=20.0, **STRINGS) | change
    spans = args.pop("spans")
    with pytest.raises(InputError) as info:
        conductors.tension_section(spans, **args)
    assert info.value.argument == name, info.value


def _independent_line(spans, dh, EA, alpha, w0, t0, H0, w, t, lam, W):
    """`_independent` for long sections: the spans as one vectorised elastic catenary, and
    fsolve told that the balance's Jacobian is banded (its finite differences then cost three
    evaluations)."""
    L0 = _reference_lengths(spans, dh, w0, EA, H0)
    k = 1 + alpha * (t - t0)

    def spans_of(phi):
        x = np.concatenate([[0.0], lam * np.sin(phi), [0.0]])
        z = np.concatenate([[0.0], lam * (1 - np.cos(phi)), [0.0]])
        return cable.elastic_catenary(spans + np.diff(x), dh + np.diff(z), w / k, EA * k, length=k * L0)

    def balance(phi):
        c = spans_of(phi)
        return (np.diff(c.H) - np.tan(phi) * (c.V_B[:-1] + c.V_A[1:] + W / 2)) / H0

    # xtol near the angles' round-off: fsolve may stop short of it and say so; the reference is
    # taken where its own balance holds to 1e-12 of H0 (measured 2e-14 to 9e-14), whatever its message
    phi, _, _, message = fsolve(balance, np.zeros(len(spans) - 1), xtol=1e-14, band=(1, 1), full_output=True)
    assert np.abs(balance(phi)).max() <= 1e-12, message
    return phi, spans_of(phi)


@pytest.mark.parametrize("n", [5, 50, 500])
def test_long_sections_against_an_independent_solution(n):
    """The banded Newton on 5, 50 and 500 spans against fsolve on the swing angles."""
    rng = np.random.default_rng(n)
    spans, dh = rng.uniform(200.0, 500.0, n), rng.uniform(-20.0, 20.0, n)
    kw = dict(EA=3.4e7, alpha=2.3e-5, w0=15.97, t0=15.0, H0=2.8e4, w=15.97, t=75.0)
    section = conductors.tension_section(spans, dh, **kw, insulator_length=3.0, insulator_weight=700.0)
    phi, curves = _independent_line(spans, dh, **kw, lam=3.0, W=700.0)
    np.testing.assert_allclose(section.swing_angle, phi, rtol=1e-7, atol=1e-12)
    np.testing.assert_allclose(section.H, curves.H, rtol=1e-10)
    np.testing.assert_allclose(section.sag, curves.sag, rtol=1e-10)
    assert np.abs(section.swing_angle).max() > 1e-3
