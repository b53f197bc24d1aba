"""The command line: readable output, JSON equal to the API, files written, one-line errors."""

import json
import subprocess
import sys

import numpy as np
import pytest

from skcable import cable, strand


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "skcable", *args], capture_output=True, text=True, cwd=cwd)


def as_json(*args):
    out = run(*args, "--json")
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def test_seeds_table():
    out = run("seeds")
    assert out.returncode == 0 and "85743.7" in out.stdout


def test_closed_forms_as_json(tmp_path):
    values = as_json("catenary", "--span", "800", "--dh", "-20", "--w", "20", "--low", "-30")
    assert values["H"] == pytest.approx(85819.2, abs=0.05)  # seed 000 ex. 4 to full precision
    values = as_json("parabola", "--span", "800", "--dh", "-20", "--w", "20", "--low", "-30")
    assert values["H"] == pytest.approx(85743.7, abs=0.05)  # seed 000 ex. 3
    values = as_json(
        "elastic-catenary",
        "--span",
        "400",
        "--dh",
        "10",
        "--w",
        "16",
        "--EA",
        "3e7",
        "--length",
        "401.2",
        "--vtk",
        str(tmp_path / "e.vtu"),
    )
    assert values["H"] == pytest.approx(cable.elastic_catenary(400, 10, 16, 3e7, length=401.2).H, rel=1e-12)
    assert (tmp_path / "e.vtu").stat().st_size > 1000


def test_funicular_seed_example():
    values = as_json(
        "funicular",
        "--B",
        "20",
        "2",
        "--lengths",
        "5",
        "6",
        "6",
        "5",
        "--loads",
        "5",
        "-75",
        "10",
        "-100",
        "5",
        "-75",
    )
    np.testing.assert_allclose(values["T"], [233.04, 205.38, 205.66, 237.85], atol=0.005)  # seed 000 ex. 1


def test_readable_table():
    out = run("catenary", "--span", "200", "--w", "1", "--sag", "20")
    assert out.returncode == 0
    rows = dict(map(str.strip, line.split(" = ")) for line in out.stdout.strip().splitlines())
    assert round(float(rows["H"]), 4) == 253.2649  # seed 001 ex. 5


def test_strand_section_json_is_the_api():
    values = as_json("strand", "section", "--preset", "steel-9.5", "--damage", "1")
    section = strand.preset("steel-9.5").damaged(1).section()
    assert values["EA_N"] == section.EA and values["EI_stick_1_Nm2"] == section.EI_max[0]
    # one of six outer wires (helix radius d) missing: z_c = -d/6 (seed 003 Table 3.2: -r/3, r = d/2)
    assert values["centroid_z_m"] == pytest.approx(-3.1e-3 / 6)


def test_strand_capacity_writes_csv_vtk_png(tmp_path):
    out = run(
        "strand",
        "capacity",
        "--damage",
        "1",
        "--slip",
        "axis",
        "--length",
        "0.3",
        "--n-elements",
        "16",
        "--n-steps",
        "8",
        "--out",
        str(tmp_path),
        "--json",
    )
    assert out.returncode == 0, out.stderr
    values = json.loads(out.stdout)
    names = {p.split("/")[-1] for p in values["written"]}
    stem = "steel-9.5_damage1_axis"
    assert {
        f"{stem}.csv",
        f"{stem}.pvd",
        f"{stem}_wires.pvd",
        "capacity.png",
        f"{stem}_curvature.png",
    } <= names
    table = np.genfromtxt(tmp_path / f"{stem}.csv", delimiter=",", names=True)
    assert values["rupture_force_N"] == pytest.approx(table["force_N"][-1])
    assert "%" in out.stderr  # the progress bar


def test_strand_capacity_thesis_reading_equals_the_api():
    from skcable import strand

    args = ("--damage", "2", "--slip", "none", "--length", "0.3", "--n-elements", "16", "--n-steps", "8")
    out = run("strand", "capacity", *args, "--damage-load", "sinusoidal", "--no-progress", "--json")
    assert out.returncode == 0, out.stderr
    model = strand.StrandModel(
        strand.preset("steel-9.5").damaged(2), 0.3, n_elements=16, damage_load="sinusoidal"
    )
    curve = model.capacity_curve(n_steps=8)
    assert json.loads(out.stdout)["K_Leq_N"] == pytest.approx(curve.K_Leq, rel=1e-12)


def test_demo_writes_results(tmp_path):
    out = run("demo", "--no-progress", cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert "stick-slip" in out.stdout
    for name in ("stick.csv", "stick-slip.pvd", "stick-slip_wires.pvd", "capacity.png", "slip_fraction.png"):
        assert (tmp_path / "results" / name).exists(), name


@pytest.mark.parametrize(
    "args, flag",
    [
        (("catenary", "--span", "800", "--w", "20", "--length", "10"), "length"),
        (("strand", "section", "--damage", "9"), "--damage"),
        (("strand", "section", "--preset", "copper"), "--preset"),
        (("strand", "capacity", "--slip", "sometimes"), "--slip"),
        (("strand", "capacity", "--damage-load", "both"), "--damage-load"),
        (("funicular", "--B", "1", "0", "--lengths", "1", "1", "--loads", "1"), "loads"),
        (("elastic-catenary", "--span", "100", "--w", "1"), "--EA"),
        (("strand",), "strand"),
    ],
)
def test_bad_argument_is_one_line_exit_2(args, flag):
    out = run(*args)
    assert out.returncode == 2
    assert out.stderr.strip().count("\n") == 0 and flag in out.stderr and "Traceback" not in out.stderr
