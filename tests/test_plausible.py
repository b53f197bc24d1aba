"""Plausibility warnings (issue 25, item 5): data that solve but that a unit slip explains
warn once, naming the argument and the likely unit mistake; ordinary scenes stay quiet; the
command line prints each warning as one line and still exits 0."""

import re
import warnings

import numpy as np
import pytest

from skcable import _plausible, cable, cli, conductors, mooring, strand
from skcable.errors import InputError, PlausibilityWarning

STATE = dict(alpha=2.3e-5, w0=15.0, t0=15.0, H0=2e4, w=[15.0, 25.0], t=[-20.0, 60.0])


def _ratio(warning) -> float:
    """The first number of a warning's message."""
    return float(re.search(r"[-+]?\d[\d.]*(?:e[-+]?\d+)?", str(warning.message)).group())


def test_ea_typed_in_mn_for_a_conductor():
    # issue 25: EA = 30 (MN) gave a 0.45 m unstressed length for a 300 m span
    with pytest.warns(PlausibilityWarning, match=r"^EA: .*MN") as caught:
        res = conductors.change_of_state(300.0, 0.0, EA=30.0, **STATE)
    assert res.L0 < 1.0  # solved: it is a warning, not a refusal
    assert {w.message.argument for w in caught} == {"EA"}
    assert {str(w.message) for w in caught} == {str(caught[0].message)}  # one line, however many solves
    assert 30.0 < 0.01 * 25.0 * 300.0 and _ratio(caught[0]) == 30.0


def test_ea_below_the_weight_of_a_line():
    with pytest.warns(PlausibilityWarning, match=r"^EA: ") as caught:
        cable.elastic_catenary(800.0, -20.0, 20.0, 100.0, length=810.0)  # 100 N under 16 kN
    assert 100.0 < 0.01 * 20.0 * 810.0 and _ratio(caught[0]) == 100.0
    with pytest.warns(PlausibilityWarning, match=r"^EA: "):
        mooring.Segment(850.0, 1000.0, 500.0)  # 5e8 N typed in MN
    with pytest.warns(PlausibilityWarning, match=r"^EA: "):
        cable.elastic_catenary(800.0, 150.0, 1000.0, 500.0, length=850.0, seabed=0.0)


def test_sag_typed_in_mm():
    # issue 25: --sag 6000 for a 250 m span gave an effective length of 3.8e8 m
    with pytest.warns(PlausibilityWarning, match=r"^sag: .*mm") as caught:
        conductors.natural_frequencies(250.0, 0.0, 1.2, 2e7, sag=6000.0)
    assert _ratio(caught[0]) == pytest.approx(6000.0 / 250.0, rel=1e-2)
    with pytest.warns(PlausibilityWarning, match=r"^sag: "):
        conductors.change_of_state(
            250.0, 0.0, EA=2e7, alpha=2.3e-5, w0=12.0, t0=15.0, sag0=300.0, w=12.0, t=15.0
        )


def test_alpha_typed_in_micro_per_kelvin():
    # alpha 23 (1e-6/K meant): a thermal strain of 23 per kelvin is refused, naming alpha (not t)
    with pytest.raises(InputError) as info:
        conductors.change_of_state(300.0, 0.0, EA=3e7, **dict(STATE, alpha=23.0, t=[15.0, 16.0]))
    assert info.value.argument == "alpha"
    with pytest.raises(InputError) as info:  # colder than t0 as well
        conductors.change_of_state(300.0, 0.0, EA=3e7, **dict(STATE, alpha=23.0))
    assert info.value.argument == "alpha"
    # alpha in 1e-4/K, a strain of 0.1 over 40 K: it solves, and warns naming alpha
    warm = dict(STATE, alpha=2.5e-3, t=[15.0, 55.0])
    with pytest.warns(PlausibilityWarning, match=r"^alpha: .*23e-6") as caught:
        conductors.change_of_state(300.0, 0.0, EA=3e7, **warm)
    strain = float(re.search(r"up to ([-+.\de]+),", str(caught[0].message)).group(1))
    assert strain == pytest.approx(2.5e-3 * (55.0 - 15.0), rel=1e-2)


@pytest.mark.parametrize(
    "alpha, t, t0, blamed",
    [
        (23.0, -20.0, 15.0, "alpha"),
        (2.3e-5, -1e5, 15.0, "t"),
        (-1e-5, 15.0, -1e6, "t0"),
        (-1e-5, 2e5, 0, "t"),
    ],
)
def test_the_argument_blamed_for_a_negative_thermal_factor(alpha, t, t0, blamed):
    assert 1 + alpha * (t - t0) <= 0
    assert _plausible.thermal_argument(alpha, np.asarray(t), t0) == blamed


def test_strand_strain_typed_in_per_cent():
    model = strand.StrandModel(strand.preset("steel-9.5"), 0.3, n_elements=8)
    limit = 1.5 * max(m.eps_rupture for m in model.strand.materials)  # 0.123 for this steel
    with pytest.warns(PlausibilityWarning, match=r"^max_strain: .*per cent"):
        model.capacity_curve(max_strain=1.0, n_steps=4)  # 1 %, typed as 1
    with pytest.warns(PlausibilityWarning, match=r"^strain: "):
        model.solve(0.2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        model.solve(0.06)  # between 5 % and the rupture: a wire's plastic range, no warning
        model.capacity_curve(max_strain=limit, n_steps=4)


def test_ordinary_scenes_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cable.catenary(800.0, -20.0, 20.0, low=-30.0)
        cable.catenary(1.0, 0.0, 1.0, sag=5.0)  # a slack rope hangs deeper than its span: exact
        cable.parabola(200.0, 0.0, 1.0, sag=20.0)
        cable.elastic_catenary(800.0, -20.0, 20.0, 1e12, length=801.409)
        cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.5)
        cable.elastic_catenary(800.0, 150.0, 1000.0, 5e5, length=850.0)  # rubber-like: EA ~ 0.6 w L
        line = mooring.Line(
            [mooring.Segment(300.0, 1000.0, 5e8), mooring.Segment(250.0, 400.0, 2e8)], seabed=0.0
        )
        line.solve(500.0, 150.0)
        conductors.change_of_state(300.0, 0.0, EA=3e7, **STATE)
        conductors.sag_tension_table(
            400.0, 0.0, EA=3e7, alpha=1.9e-5, w0=16.0, t0=15.0, H0=28e3,
            temperatures=[-20.0, 15.0, 75.0], load_cases={"ice": (25.0, 0.0)},
        )  # fmt: skip
        conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0)
        strand.preset("steel-9.5").damaged(1).bending_law(mu=0.5, axial_strain=0.004)


def test_cli_prints_the_warning_naming_the_flag_and_exits_0(capsys):
    args = ["change-of-state", "--span", "300", "--EA", "30", "--alpha", "2.3e-5", "--w0", "15"]
    status = cli.main([*args, "--t0", "15", "--H0", "2e4", "--w", "15", "25", "--t", "-20", "60"])
    out, err = capsys.readouterr()
    assert status == cli.EXIT_OK and "L0" in out
    assert err.startswith("skcable: warning: --EA: ") and err.count("\n") == 1 and "MN" in err
    status = cli.main(
        ["frequencies", "--span", "250", "--EA", "2e7", "--w", "1.2", "--sag", "6000", "--json"]
    )
    out, err = capsys.readouterr()
    assert status == cli.EXIT_OK and "f_in_plane" in out
    assert err.startswith("skcable: warning: --sag: ") and err.count("\n") == 1


def test_cli_alpha_is_blamed_not_t(capsys):
    args = ["change-of-state", "--span", "300", "--EA", "3e7", "--alpha", "23", "--w0", "15", "--t0", "15"]
    status = cli.main([*args, "--H0", "2e4", "--w", "15", "25", "--t", "-20", "60"])
    err = capsys.readouterr().err
    assert status == cli.EXIT_USAGE and err.startswith("skcable: error: --alpha: ") and err.count("\n") == 1
