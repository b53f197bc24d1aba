"""change_of_state(model="auto"): the parabola's error estimate bounds its true error against the
exact model (the thermal elastic catenary) on random lines, and the parabola is taken where the
estimate is within rtol (as tests/bvp/test_choice.py holds bvp.solve)."""

import numpy as np
import pytest

from skcable import InputError, conductors

RESULTS = ("H", "H_plane", "sag", "T_max", "length")


def random_line(seed, n=150, sag_given=False, steep=False):
    """Spans 30 m to 2 km, level or inclined up to 60 %, reference sag/span 0.5 % to 25 %,
    conductors of EA 1e7 to 3e9 N, eight states: -40 to 120 °C, ice up to 4 w0, wind to 25 N/m
    (``steep``: inclined up to 200 %, wind to 60 N/m)."""
    rng = np.random.default_rng(seed)
    spans = 10 ** rng.uniform(np.log10(30.0), np.log10(2000.0), n)
    dh = spans * rng.uniform(-0.6, 0.6, n) * (rng.uniform(size=n) < 0.7) * (10.0 / 3.0 if steep else 1.0)
    w0 = rng.uniform(3.0, 30.0)
    sag0 = 10 ** rng.uniform(np.log10(0.005), np.log10(0.25), n) * spans
    m = 8
    states = dict(
        w=w0 * np.where(rng.uniform(size=m) < 0.4, rng.uniform(1.0, 4.0, m), 1.0),
        t=rng.uniform(-40.0, 120.0, m),
        wind=np.where(rng.uniform(size=m) < 0.4, rng.uniform(0.0, 60.0 if steep else 25.0, m), 0.0),
    )
    ref = dict(sag0=sag0) if sag_given else dict(H0=w0 * spans * np.hypot(spans, dh) / (8.0 * sag0))
    kw = dict(EA=10 ** rng.uniform(7.0, 9.5), alpha=rng.uniform(1e-5, 2.5e-5), w0=w0, t0=rng.uniform(-5, 25))
    return spans, dh, {**kw, **ref, **states}


def true_error(approx, exact, sag_given):
    """The largest relative difference of each span's results (over its states), and of the
    reference's tension (a sag given) or sag (a tension given)."""
    error = np.max([np.abs(getattr(approx, k) / getattr(exact, k) - 1).max(axis=1) for k in RESULTS], axis=0)
    ref = "H0" if sag_given else "sag0"
    return np.maximum(error, np.abs(getattr(approx, ref) / getattr(exact, ref) - 1))


@pytest.mark.parametrize("sag_given", [False, True])
@pytest.mark.parametrize(
    ("seed", "steep"), [(0, False), (1, False), (2, False), (3, False), (4, True), (5, True)]
)
def test_the_estimate_bounds_the_parabola_error(seed, steep, sag_given):
    spans, dh, kw = random_line(seed, sag_given=sag_given, steep=steep)
    exact = conductors.change_of_state(spans, dh, **kw)
    parabola = conductors.change_of_state(spans, dh, **kw, model="parabola")
    error = true_error(parabola, exact, sag_given)
    assert np.all(error <= parabola.error_estimate), np.max(error / parabola.error_estimate)
    # not a loose bound: the true error reaches more than half the estimate somewhere
    assert np.max(error / parabola.error_estimate) > 0.5


@pytest.mark.parametrize("rtol", [1e-3, 3e-3, 1e-2])
def test_auto_takes_the_parabola_where_its_estimate_is_within_rtol(rtol):
    spans, dh, kw = random_line(11, n=200)
    exact = conductors.change_of_state(spans, dh, **kw)
    parabola = conductors.change_of_state(spans, dh, **kw, model="parabola")
    auto = conductors.change_of_state(spans, dh, **kw, model="auto", rtol=rtol)
    taken = parabola.error_estimate <= rtol
    assert 0 < taken.sum() < spans.size  # both models on this line at these tolerances
    assert auto.model == "mixed" and list(auto.models) == ["parabola" if p else "catenary" for p in taken]
    for key in (*RESULTS, "L0", "H0", "sag0"):
        np.testing.assert_array_equal(getattr(auto, key)[taken], getattr(parabola, key)[taken], err_msg=key)
        np.testing.assert_array_equal(getattr(auto, key)[~taken], getattr(exact, key)[~taken], err_msg=key)
    assert np.all(true_error(auto, exact, False) <= rtol)
    np.testing.assert_array_equal(auto.error_estimate, np.where(taken, parabola.error_estimate, 0.0))
    assert f"rtol {rtol:g}" in auto.reason and f"{taken.sum()} of {spans.size} spans" in auto.reason


def test_one_span_says_which_model_and_why():
    kw = dict(EA=3.4e7, alpha=1.9e-5, w0=15.97, t0=15.0, w=15.97, t=np.array([5.0, 15.0, 30.0]))
    taut = conductors.change_of_state(300.0, 10.0, **kw, H0=30e3, model="auto")  # sag/span 2 %
    assert taut.model == taut.models == "parabola" and taut.error_estimate <= 1e-3
    assert "within rtol 0.001" in taut.reason and taut.rtol == 1e-3
    exact = conductors.change_of_state(300.0, 10.0, **kw, H0=30e3)
    assert taut.H == pytest.approx(exact.H, rel=taut.error_estimate)
    slack = conductors.change_of_state(300.0, 10.0, **kw, H0=3e3, model="auto")  # sag/span 20 %
    assert slack.model == "catenary" and slack.error_estimate == 0.0 and "exceeds rtol" in slack.reason
    np.testing.assert_array_equal(slack.H, conductors.change_of_state(300.0, 10.0, **kw, H0=3e3).H)
    assert exact.model == exact.models == "catenary" and exact.error_estimate == 0.0 and exact.rtol is None


def test_the_bench_line_at_mechaphlowers_accuracy_takes_the_parabola():
    """The line of benchmarks/bench_lines.py (1000 spans, ACSR Drake, -20 to 90 °C) at rtol 4e-3
    (mechaphlowers' parabolic model is 4.0e-3 from the exact H there): the parabola everywhere,
    within that of the exact model."""
    rng = np.random.default_rng(24)
    spans = rng.uniform(150.0, 600.0, 1000)
    dh = rng.uniform(-0.1, 0.1, 1000) * spans
    kw = dict(EA=3.4e7, alpha=1.9e-5, w0=15.97, t0=15.0, H0=28e3, w=15.97, t=np.linspace(-20.0, 90.0, 10))
    auto = conductors.change_of_state(spans, dh, **kw, model="auto", rtol=4e-3)
    assert auto.model == "parabola" and np.all(auto.models == "parabola")
    exact = conductors.change_of_state(spans, dh, **kw)
    assert np.max(true_error(auto, exact, False)) <= 4e-3


@pytest.mark.parametrize(
    ("change", "argument"),
    [(dict(rtol=1e-3), "rtol"), (dict(model="parabola", rtol=1e-3), "rtol"),
     (dict(model="auto", rtol=0.0), "rtol"), (dict(model="auto", rtol="1e-3"), "rtol"),
     (dict(model="choose"), "model")],
)  # fmt: skip
def test_rtol_belongs_to_auto(change, argument):
    with pytest.raises(InputError) as info:
        conductors.change_of_state(
            300.0, 0.0, EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4, w=15.0, t=20.0, **change
        )
    assert info.value.argument == argument


def test_a_conductor_takes_auto_and_rtol_from_a_reference_length():
    """`Conductor.change_of_state` passes ``model="auto"`` and ``rtol`` through, a reference
    length included (its exact H0, then each span's model): within rtol of the exact model on
    every span, the parabola on the short ones, and its table says which model it took."""
    drake = conductors.Conductor.from_catalogue("acsr-drake")
    spans = np.array([60.0, 150.0, 400.0, 1200.0])
    L0 = drake.change_of_state(spans, t0=15.0, H0=28e3, t=15.0).L0  # an intact line's lengths
    states = dict(t0=15.0, length=L0, t=np.array([-20.0, 15.0, 75.0]), ice=0.01, wind_pressure=300.0)
    exact = drake.change_of_state(spans, **states)
    auto = drake.change_of_state(spans, **states, model="auto", rtol=2e-3)
    parabola = conductors.change_of_state(
        spans, 0.0, EA=drake.EA, alpha=drake.alpha, w0=drake.w, t0=15.0, H0=exact.H0, w=exact.w,
        t=exact.t, wind=exact.wind, model="parabola",
    )  # fmt: skip
    took = np.asarray(auto.models) == "parabola"
    assert auto.model == "mixed"
    assert took.any() and not took.all(), auto.reason
    assert np.all(np.abs(auto.H / exact.H - 1) <= 2e-3)
    np.testing.assert_array_equal(auto.H[took], parabola.H[took])
    np.testing.assert_array_equal(auto.H[~took], exact.H[~took])
    table = drake.sag_tension_table(
        400.0, t0=15.0, H0=28e3, temperatures=[0.0, 50.0], model="auto", rtol=1e-1
    )
    assert table.attrs["model"] == "parabola" and "rtol 0.1" in table.attrs["reason"]
    with pytest.raises(InputError) as info:
        drake.change_of_state(400.0, t0=15.0, H0=28e3, t=15.0, rtol=1e-3)
    assert info.value.argument == "rtol"
