"""``skcable conductor`` (issue 31): the sag-tension table, the ruling span and the rating on the
command line, each against its own reference (the library's table, the ruling span's closed
form, linerate's heat balance called here); and the flag suggestions that ignore case."""

import json
import math

import numpy as np
import pytest

from skcable import cli, conductors

TABLE = [
    "conductor",
    "table",
    "--span",
    "400",
    "--EA",
    "3e7",
    "--alpha",
    "1.9e-5",
    "--w0",
    "16",
    "--t0",
    "15",
]
TABLE += [
    "--H0",
    "28e3",
    "--temperatures",
    "-20",
    "15",
    "75",
    "--case",
    "bare",
    "16",
    "0",
    "--case",
    "ice",
    "25",
    "4",
]


def test_the_sag_tension_table(capsys):
    assert cli.main([*TABLE, "--json"]) == cli.EXIT_OK
    got = json.loads(capsys.readouterr().out)
    want = conductors.sag_tension_table(
        400.0, 0.0, EA=3e7, alpha=1.9e-5, w0=16.0, t0=15.0, H0=28e3, temperatures=[-20.0, 15.0, 75.0],
        load_cases={"bare": (16.0, 0.0), "ice": (25.0, 4.0)},
    )  # fmt: skip
    assert got["case"] == ["bare"] * 3 + ["ice"] * 3 and got["t"] == [-20.0, 15.0, 75.0] * 2
    for name in ("H", "sag", "T_max", "length"):
        assert got[name] == [float(v) for v in want[name]]
    assert got["H"][1] == pytest.approx(28e3, rel=1e-12)  # the reference state: bare at t0
    assert cli.main(TABLE) == cli.EXIT_OK
    assert "H [N]" in capsys.readouterr().out


def test_the_ruling_span(capsys):
    spans = [250.0, 450.0, 300.0]
    assert cli.main(["conductor", "ruling-span", "--spans", *map(str, spans), "--json"]) == cli.EXIT_OK
    got = json.loads(capsys.readouterr().out)["ruling_span"]
    assert got == pytest.approx(math.sqrt(sum(s**3 for s in spans) / sum(spans)), rel=1e-15)


def test_the_rating_against_linerate(capsys):
    linerate = pytest.importorskip("linerate")
    args = ["conductor", "rating", "--diameter", "28.1e-3", "--core-diameter", "10.4e-3"]
    args += ["--strand-diameter", "4.44e-3", "--resistance", "25", "7.283e-5", "75", "8.688e-5"]
    args += [
        "--air-temperature",
        "20",
        "--wind-speed",
        "1.66",
        "--current",
        "1000",
        "--max-temperature",
        "75",
    ]
    assert cli.main([*args, "--json"]) == cli.EXIT_OK
    got = json.loads(capsys.readouterr().out)
    wire = linerate.Conductor(
        core_diameter=10.4e-3, conductor_diameter=28.1e-3, outer_layer_strand_diameter=4.44e-3,
        emissivity=0.8, solar_absorptivity=0.8, temperature1=25.0, temperature2=75.0,
        resistance_at_temperature1=7.283e-5, resistance_at_temperature2=8.688e-5,
        aluminium_cross_section_area=float("nan"), constant_magnetic_effect=1.0,
        current_density_proportional_magnetic_effect=0.0, max_magnetic_core_relative_resistance_increase=1.0,
    )  # fmt: skip
    half = 200.0 / 111_320.0
    towers = [linerate.Tower(latitude=50.0 + d, longitude=0.0, altitude=0.0) for d in (-half, half)]
    span = linerate.Span(conductor=wire, start_tower=towers[0], end_tower=towers[1], num_conductors=1)
    weather = linerate.Weather(air_temperature=20.0, wind_direction=np.radians(90.0), wind_speed=1.66,
                               ground_albedo=0.1, clearness_ratio=0.5)  # fmt: skip
    model = linerate.IEEE738(span, weather, np.datetime64("2016-06-21T12:00"))
    T = float(model.compute_conductor_temperature(1000.0, 20.0, 300.0, 1e-4))  # air to 300 °C
    assert got["temperature"] == pytest.approx(T, abs=1e-12)
    balance = model.compute_heat_balance(75.0, got["ampacity"])  # heating less cooling (W/m)
    joule = model.compute_joule_heating(75.0, got["ampacity"])
    assert abs(float(balance)) <= 1e-4 * float(joule)  # the heat balance at 75 °C holds


@pytest.mark.parametrize("typed, meant", [("--ea", "--EA"), ("--Span", "--span"), ("--h0", "--H0")])
def test_a_flag_in_the_wrong_case_suggests_the_flag(capsys, typed, meant):
    args = ["change-of-state", "--span", "300", typed, "3e7"]
    assert cli.main(args) == cli.EXIT_USAGE
    assert capsys.readouterr().err.strip().endswith(f"unknown flag {typed}; did you mean {meant}?")


def test_strict_makes_a_plausibility_warning_an_error(capsys):
    args = ["conductor", "table", *TABLE[2:12], "--H0", "28e3", "--temperatures", "323"]
    assert cli.main(args) == cli.EXIT_WARNINGS
    assert "kelvin" in capsys.readouterr().err
    assert cli.main([*args, "--strict"]) == cli.EXIT_USAGE
    out, err = capsys.readouterr()
    assert out == "" and err.startswith("skcable: error: ") and "(--strict)" in err
