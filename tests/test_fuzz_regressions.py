"""Regression tests of the defects the fuzz of issue 26 found in the conductor, frequency, io and
command-line modules, each against a value from elsewhere (a 50-digit root written in
`tests.fuzz`, the library call the command stands for, the argument the call made invalid)."""

from __future__ import annotations

import json

import numpy as np
import pytest
from mpmath import mpf

from skcable import cable, cli, conductors, io
from skcable.errors import InputError
from tests.fuzz import state


def test_line_path_reference_length_to_round_off():
    """A taut short span: the line path's reference length stopped ~250 ulps short of its root
    (its Newton's floor sized by the check's terms, (T_A + T_B)/w, not the solve's), and the
    state's H came out 4e-11 off. Both now within a few ulps of the 50-digit root."""
    span, dh, EA, w0, H0 = (
        37.57674145332485,
        7.951481255647463,
        26120472.172644686,
        27.35360043284933,
        37256.256645053174,
    )
    alpha, t0, w, t, wind = (
        2.4894477250185215e-05,
        22.342802688728646,
        27.35360043284933,
        30.32663457446332,
        10.034135389183621,
    )
    res = conductors.change_of_state(
        np.array([span, 29.65046559678961]),
        np.array([dh, 4.331467771090164]),
        EA=EA,
        alpha=alpha,
        w0=w0,
        t0=t0,
        H0=np.array([H0, H0]),
        w=[w],
        t=[t],
        wind=[wind],
    )
    L0 = state.reference_length(span, dh, w0, EA, H0=H0)[0]
    assert abs(mpf(float(res.L0[0])) - L0) <= 4 * 2.0**-52 * L0
    want = state.state(span, dh, w, t, wind, EA, alpha, t0, L0)["H"]
    assert abs(mpf(float(res.H[0, 0])) - want) <= 1e-12 * want


@pytest.mark.parametrize("dh", ["-1.5e-05", "-2.5e-300", "-5e-324", "-1.25E+2"])
def test_cli_takes_negative_numbers_in_scientific_notation(dh, capsys):
    """``--dh -1.5e-05`` (how Python prints small floats) was refused as an unknown flag
    ("expected one argument"): it is the number, and the JSON is the library's."""
    args = ["elastic-catenary", "--span", "100", "--w", "10", "--EA", "1e7", "--length", "110"]
    assert cli.main([*args, "--dh", dh, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["H"] == cable.elastic_catenary(100.0, float(dh), 10.0, 1e7, length=110.0).H


def test_cli_names_the_flag_of_an_overflowing_negative_number(capsys):
    args = [
        "elastic-catenary",
        "--span",
        "100",
        "--w",
        "10",
        "--EA",
        "1e7",
        "--length",
        "110",
        "--dh",
        "-1e400",
    ]
    assert cli.main(args) == cli.EXIT_USAGE
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--dh" in err[0] and "-1e400" in err[0]


@pytest.mark.parametrize(
    "n", [[], np.array([1.0, 2.0]), 2.5, True, None, float("inf"), float("nan"), 10**20, 1]
)
def test_cable_mesh_refuses_a_bad_n_by_name(n):
    """Once a TypeError, OverflowError or numpy's 'Maximum allowed size exceeded'."""
    solution = cable.elastic_catenary(800.0, 200.0, 1000.0, 5e8, length=850.0)
    with pytest.raises(InputError) as info:
        io.cable_mesh(solution, n)
    assert info.value.argument == "n"


@pytest.mark.parametrize("solution", [0.0, None, "catenary", [1.0, 2.0]])
def test_cable_mesh_refuses_what_is_no_solution(solution):
    """Once an AttributeError ('float' object has no attribute 'T_A')."""
    with pytest.raises(InputError) as info:
        io.cable_mesh(solution, 51)
    assert info.value.argument == "solution"


_STATE = dict(EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, H0=2e4, w=20.0, t=80.0, wind=5.0)
_TABLE = dict(
    EA=3e7,
    alpha=2e-5,
    w0=15.0,
    t0=15.0,
    H0=2e4,
    temperatures=[-5.0, 15.0, 80.0],
    load_cases={"bare": (15.0, 0.0), "ice": (25.0, 8.0)},
)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: conductors.change_of_state(1e-300, 10.0, **_STATE), "span"),  # named dh
        (lambda: conductors.change_of_state(1e308, 10.0, **_STATE), "span"),  # named H0
        (lambda: conductors.change_of_state(300.0, 10.0, **(_STATE | {"w0": 1e308})), "w0"),  # named H0
        (lambda: conductors.change_of_state(300.0, 10.0, **(_STATE | {"t0": 1e308})), "t0"),  # named t
        (lambda: conductors.sag_tension_table(1e308, 0.0, **_TABLE), "span"),  # named H0
        (lambda: conductors.sag_tension_table(300.0, 0.0, **(_TABLE | {"EA": 2.5e-308})), "EA"),  # named H0
        (lambda: conductors.sag_tension_table(300.0, 0.0, **(_TABLE | {"t0": 1e308})), "t0"),  # temperatures
        (lambda: conductors.natural_frequencies(1e308, 10.0, 15.0, 3e7, H=2e4), "span"),  # named H
        (lambda: conductors.natural_frequencies(1e-300, 10.0, 15.0, 3e7, H=2e4), "span"),  # named dh
        (lambda: conductors.natural_frequencies(300.0, 10.0, 1e308, 3e7, H=2e4), "w"),  # named H
    ],
)
def test_refusals_name_the_outsized_argument(call, name):
    """A call valid but for one outsized argument (beyond 1e±100) names that argument (D8)."""
    with pytest.raises(InputError) as info:
        call()
    assert info.value.argument == name, info.value


@pytest.mark.parametrize("span, name", [(1e-300, "span"), (2.5e-308, "span"), (1e200, "span")])
def test_parabolic_reference_out_of_range_is_named(span, name):
    """The parabola's reference tension w0 span²/(8 sag0 cos ψ) underflowed to 0 ("stretches the
    cable by more than its length ... = 0", naming sag0) or overflowed as an OverflowError."""
    with pytest.raises(InputError) as info:
        conductors.change_of_state(
            span, 10.0, EA=3e7, alpha=2e-5, w0=15.0, t0=15.0, sag0=8.0, w=20.0, t=80.0, model="parabola"
        )
    assert info.value.argument == name, info.value
