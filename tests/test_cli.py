"""The command line: readable output, JSON equal to the API, files written atomically, one-line
errors naming the flag (never a traceback), and exit statuses that say what happened."""

import argparse
import dataclasses
import json
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import skcable
from skcable import cable, cli, conductors, strand
from skcable.cli import _args
from skcable.errors import ConvergenceError

ROOT = Path(skcable.__file__).resolve().parents[1]
ENV = os.environ | {"PYTHONPATH": str(ROOT)}  # subprocesses import this checkout, whatever their cwd


def run(*args, cwd=None):
    return subprocess.run(
        [sys.executable, "-m", "skcable", *args], capture_output=True, text=True, cwd=cwd, env=ENV
    )


def as_json(*args):
    out = run(*args, "--json")
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def main(capsys, *args):
    """The command line in this process: (status, stdout, stderr)."""
    status = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


def test_examples_table_cites_its_sources(capsys):
    status, out, err = main(capsys, "examples")
    assert status == 0 and err == ""
    assert 'The lecture notes "Cables":' in out and 'J.M. Goicolea, "Cálculo de cables", UPM, 2012:' in out
    assert "seed" not in out.lower()
    ours = f"{float(cable.parabola(800, -20, 20, low=-30).H):16.10g}"
    assert "85743.7" in out and ours in out
    for alias in ("seeds", "worked-examples"):  # the old name keeps working
        assert main(capsys, alias) == (0, out, "")


def test_closed_forms_as_json(tmp_path):
    values = as_json("catenary", "--span", "800", "--dh", "-20", "--w", "20", "--low", "-30")
    assert values["H"] == pytest.approx(85819.2, abs=0.05)  # lecture notes "Cables", ex. 4, full precision
    values = as_json("parabola", "--span", "800", "--dh", "-20", "--w", "20", "--low", "-30")
    assert values["H"] == pytest.approx(85743.7, abs=0.05)  # lecture notes "Cables", ex. 3
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
    assert [p.name for p in tmp_path.iterdir()] == ["e.vtu"]  # no temporary file left


def test_funicular_worked_example(capsys):
    args = [
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
    ]
    status, out, _ = main(capsys, "funicular", *args, "--json")
    sol = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    assert status == 0 and json.loads(out)["T"] == sol.T.tolist()
    np.testing.assert_allclose(json.loads(out)["T"], [233.04, 205.38, 205.66, 237.85], atol=0.005)  # ex. 1


def test_readable_table(capsys):
    status, out, _ = main(capsys, "catenary", "--span", "200", "--w", "1", "--sag", "20")
    assert status == 0
    rows = dict(map(str.strip, line.split(" = ")) for line in out.strip().splitlines())
    values = {name: shown.split(" ", 1) for name, shown in rows.items()}
    assert float(values["H"][0]) == float(f"{cable.catenary(200, 0, 1, sag=20).H:.10g}")
    assert round(float(values["H"][0]), 4) == 253.2649  # Goicolea 2012, ex. 5
    units = {name: value[1] for name, value in values.items() if len(value) == 2}
    assert units["H"] == units["T_A"] == units["V_B"] == "N" and units["length"] == units["sag"] == "m"


def test_strand_section_json_is_the_api(capsys):
    status, out, _ = main(capsys, "strand", "section", "--preset", "steel-9.5", "--damage", "1", "--json")
    values = json.loads(out)
    section = strand.preset("steel-9.5").damaged(1).section()
    assert status == 0 and values["EA_N"] == section.EA and values["EI_stick_1_Nm2"] == section.EI_stick[0]
    # one of six outer wires (helix radius d) missing: z_c = -d/6 (Pino Vidal 2021, Table 3.2: -r/3, r = d/2)
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
    assert all(Path(p).is_file() for p in values["written"])
    assert {p.name for p in tmp_path.iterdir() if p.suffix != ".vtu"} == names  # nothing else (no stage)
    table = np.genfromtxt(tmp_path / f"{stem}.csv", delimiter=",", names=True)
    assert values["rupture_force_N"] == pytest.approx(table["force_N"][-1])
    assert "%" in out.stderr  # the progress bar


def test_strand_capacity_thesis_reading_equals_the_api(capsys):
    args = ("--damage", "2", "--slip", "none", "--length", "0.3", "--n-elements", "16", "--n-steps", "8")
    status, out, err = main(
        capsys, "strand", "capacity", *args, "--damage-load", "sinusoidal", "--no-progress", "--json"
    )
    assert status == 0, err
    model = strand.StrandModel(
        strand.preset("steel-9.5").damaged(2), 0.3, n_elements=16, damage_load="sinusoidal"
    )
    curve = model.capacity_curve(n_steps=8)
    assert json.loads(out)["K_Leq_N"] == pytest.approx(curve.K_Leq, rel=1e-12)


@pytest.mark.parametrize("converged", [3, 0])
def test_no_convergence_writes_what_converged_and_exits_3(tmp_path, capsys, monkeypatch, converged):
    # a curve that stops after `converged` steps: the library's own curve, cut short as a solver that
    # gives up there would return it (a real stop takes minutes; the CLI's handling is tested here)
    real, stopped = strand.StrandModel.capacity_curve, []

    def stopping(self, max_strain=None, n_steps=None, **kwargs):
        curve = real(self, max_strain, n_steps, **kwargs)
        assert kwargs["on_failure"] == "stop"  # the CLI asks for the converged part
        k = converged
        stopped.append(
            dataclasses.replace(
                curve,
                strain=curve.strain[: k + 1],
                force=curve.force[: k + 1],
                slip_fraction=curve.slip_fraction[: k + 1],
                steps=curve.steps[:k],
                ruptured=False,
                failure=f"no convergence beyond strain {curve.strain[k]:.6g} after 6 cutbacks",
            )
        )
        return stopped[-1]

    monkeypatch.setattr(strand.StrandModel, "capacity_curve", stopping)
    flags = ["--length", "0.3", "--n-elements", "8", "--n-steps", "8", "--no-progress", "--json"]
    status, out, err = main(capsys, "strand", "capacity", "--damage", "1", *flags, "--out", tmp_path / "r")
    curve = stopped[0]
    assert status == cli.EXIT_NO_CONVERGENCE
    assert err.count("\n") == 1 and err.startswith("skcable: error: no convergence") and curve.failure in err
    if not converged:  # nothing to write
        assert out == "" and not (tmp_path / "r").exists()
        return
    assert str(tmp_path / "r") in err
    values = json.loads(out)
    assert values["ruptured"] is False and values["last_strain"] == float(curve.strain[-1])
    assert values["K_Leq_N"] == curve.K_Leq and "D_r" not in values
    table = np.genfromtxt(tmp_path / "r" / "steel-9.5_damage1_axis.csv", delimiter=",", names=True)
    np.testing.assert_array_equal(table["strain"], curve.strain)  # the curve up to the last converged step
    np.testing.assert_array_equal(table["force_N"], curve.force)


def test_demo_writes_results(tmp_path):
    out = run("demo", "--no-progress", "--n-elements", "16", "--n-steps", "8", cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert "stick-slip" in out.stdout and out.stderr == ""
    for name in ("stick.csv", "stick-slip.pvd", "stick-slip_wires.pvd", "capacity.png", "slip_fraction.png"):
        assert (tmp_path / "results" / name).exists(), name
    assert not [p for p in (tmp_path / "results").iterdir() if p.name.startswith(".")]  # no stage left
    # one last state everywhere: the time series ends where the CSV ends (the rupture strain)
    import xml.etree.ElementTree as ET

    for name in ("stick", "stick-slip"):
        times = [
            float(d.get("timestep")) for d in ET.parse(tmp_path / "results" / f"{name}.pvd").iter("DataSet")
        ]
        csv = np.loadtxt(tmp_path / "results" / f"{name}.csv", delimiter=",", skiprows=1)
        assert times[-1] == pytest.approx(csv[-1, 0], rel=1e-12)


def test_bare_skcable_prints_help_and_runs_nothing(tmp_path):
    out = run(cwd=tmp_path)
    assert out.returncode == cli.EXIT_USAGE and out.stderr == ""
    assert out.stdout.startswith("usage: skcable") and "exit status" in out.stdout
    assert list(tmp_path.iterdir()) == []  # no demo over results/


def test_version():
    out = run("--version")
    assert out.returncode == 0 and out.stdout == f"skcable {skcable.__version__}\n"


def _options(parser):
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from ((f"{name} {where}", a) for where, a in _options(sub))
        elif action.option_strings and action.dest not in ("help", "version"):
            yield "", action


def test_every_flag_has_help_with_its_default_and_units():
    options = list(_options(cli.parser()))
    assert len(options) > 40
    for where, action in options:
        flag = f"{where}{action.option_strings[-1]}"
        assert action.help and ("(default:" in action.help or "(required)" in action.help), flag
        if action.type is _args.finite:  # a quantity: its unit in brackets
            assert "[" in action.help and "]" in action.help, flag


def test_numpy_warnings_do_not_reach_stderr(monkeypatch, capsys):
    """A solver that makes numpy warn and then gives up: the CLI prints one line."""

    def warns_then_fails(*args, **kwargs):
        np.log(np.zeros(1))  # RuntimeWarning: divide by zero
        raise ConvergenceError("catenary: no convergence", [1.0, 0.5])

    monkeypatch.setattr(cable, "catenary", warns_then_fails)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(ConvergenceError):
            cable.catenary(100.0, 0.0, 1.0, sag=2.0)
    assert any(issubclass(w.category, RuntimeWarning) for w in caught)  # the patched API does warn
    status = cli.main(["catenary", "--span", "100", "--w", "1", "--sag", "2"])
    err = capsys.readouterr().err
    assert status == cli.EXIT_NO_CONVERGENCE
    assert err.count("\n") == 1 and err.startswith("skcable: error: no convergence"), err


def test_usage_error_from_a_real_process_is_one_line():
    out = run("parabola", "--span", "1e300", "--w", "1", "--sag", "2")
    assert out.returncode == cli.EXIT_USAGE and out.stdout == ""
    # the library names the constraint that the extreme span makes overflow
    assert out.stderr.count("\n") == 1 and "--sag" in out.stderr and "Traceback" not in out.stderr


@pytest.mark.parametrize(
    "args, flag",
    [
        (("catenary", "--span", "800", "--w", "20", "--length", "10"), "--length"),
        (("catenary", "--span", "100", "--w", "1"), "--T-max"),  # no constraint: the flags are listed
        (("catenary", "--span", "nan", "--w", "1", "--sag", "2"), "--span"),
        (("catenary", "--span", "1e300", "--w", "1", "--H", "1"), "--H"),  # overflow, named
        (("parabola", "--span", "1e300", "--w", "1", "--sag", "2"), "--sag"),
        (("strand", "section", "--damage", "9"), "--damage"),
        (("strand", "section", "--preset", "copper"), "--preset"),
        (("strand", "capacity", "--slip", "sometimes"), "--slip"),
        (("strand", "capacity", "--damage-load", "both"), "--damage-load"),
        (("strand", "capacity", "--n-steps", "0"), "--n-steps"),  # it ran with 60 steps
        (("strand", "capacity", "--n-steps", "3"), "--n-steps"),
        (("strand", "capacity", "--n-elements", "1", "--no-progress"), "--n-elements"),
        (("strand", "capacity", "--mu", "-1", "--no-progress"), "--mu"),
        (("funicular", "--B", "1", "0", "--lengths", "1", "1", "--loads", "1"), "--loads"),
        (("elastic-catenary", "--span", "100", "--w", "1"), "--EA"),
        (("strand",), "strand"),
        (("study",), "study"),
        (("frobnicate",), "frobnicate"),
    ],
)
def test_bad_argument_is_one_line_exit_2(capsys, args, flag):
    status, out, err = main(capsys, *args)
    assert status == cli.EXIT_USAGE and out == ""
    assert err.count("\n") == 1 and flag in err and "Traceback" not in err


@pytest.fixture
def no_computing(monkeypatch):
    """Fail the test if a strand model or a study case is computed."""
    from skcable import study

    def computed(*args, **kwargs):
        raise AssertionError("computed before refusing")

    monkeypatch.setattr(strand, "StrandModel", computed)
    monkeypatch.setattr(study, "_evaluate", computed)


@pytest.fixture
def study_file(tmp_path):
    path = tmp_path / "study.toml"
    path.write_text(
        f'model = "cable_solve"\noutput = "{tmp_path / "t.csv"}"\n[grid]\nspan = [100.0]\nsag = [5.0]\n'
        "[fixed]\nw = 1.0\n"
    )
    return path


@pytest.mark.parametrize(
    "args, flag, reason",
    [
        (("strand", "capacity", "--out", "{file}"), "--out", "is a file, not a folder"),
        (("strand", "capacity", "--out", "{file}/sub"), "--out", "is not a folder"),
        (("demo", "--out", "{file}"), "--out", "is a file, not a folder"),
        (("catenary", "--span", "9", "--w", "1", "--sag", "1", "--vtk", "{dir}"), "--vtk", "is a folder"),
        (("catenary", "--span", "9", "--w", "1", "--sag", "1", "--vtk", "{dir}/c.foo"), "--vtk", "extension"),
        (
            ("catenary", "--span", "9", "--w", "1", "--sag", "1", "--vtk", "{file}/c.vtu"),
            "--vtk",
            "not a folder",
        ),
        (("study", "run", "{study}", "--serial", "--out", "{dir}"), "--out", "is a folder"),
        (
            ("study", "run", "{study}", "--serial", "--out", "{dir}/t.txt"),
            "--out",
            "unknown extension '.txt'",
        ),
        (("study", "run", "{study}", "--serial", "--out", "{file}/t.csv"), "--out", "not a folder"),
        (("study", "run", "{study}", "--serial", "--cache", "{file}"), "--cache", "is a file"),
        (("study", "run", "{study}", "--workers", "0"), "--workers", "at least 1"),  # it used to hang
        (("study", "run", "{study}", "--scheduler", "nonsense"), "--scheduler", "not a scheduler address"),
        (("study", "run", "{study}", "--scheduler", "foo://h:1"), "--scheduler", "unknown address scheme"),
        (("study", "run", "{study}", "--serial", "--scheduler", "tcp://h:1"), "--scheduler", "--serial"),
        (("study", "run", "{study}", "--serial", "--workers", "2"), "--workers", "--serial"),
    ],
)
def test_unusable_paths_and_options_are_refused_before_computing(
    tmp_path, capsys, no_computing, study_file, args, flag, reason
):
    regular = tmp_path / "regular_file"
    regular.write_text("")
    args = [a.format(file=regular, dir=tmp_path, study=study_file) for a in args]
    status, out, err = main(capsys, *args)
    assert status == cli.EXIT_USAGE and out == "", err
    assert err.count("\n") == 1 and flag in err and reason in err


# --- change of state and natural frequencies -------------------------------------
_STATE = ("--span", "300", "--dh", "-10", "--EA", "3e7", "--alpha", "2.3e-5", "--w0", "15", "--t0", "15")


@pytest.mark.parametrize(
    ("model", "rtol", "chosen"),
    [("catenary", None, "catenary"), ("parabola", None, "parabola"), ("auto", None, "catenary"),
     ("auto", 1e-2, "parabola")],
)  # fmt: skip
def test_change_of_state_json_is_the_api(capsys, model, rtol, chosen):
    status, out, err = main(
        capsys, "change-of-state", *_STATE, "--H0", "2e4", "--w", "15", "25", "--t", "-20", "60",
        "--wind", "0", "8", "--model", model, *(() if rtol is None else ("--rtol", str(rtol))), "--json",
    )  # fmt: skip
    assert status == cli.EXIT_OK, err
    got = json.loads(out)
    api = conductors.change_of_state(
        300.0, -10.0, EA=3e7, alpha=2.3e-5, w0=15.0, t0=15.0, H0=2e4,
        w=np.array([15.0, 25.0]), t=np.array([-20.0, 60.0]), wind=np.array([0.0, 8.0]), model=chosen,
    )  # fmt: skip
    for key in ("H", "H_plane", "sag", "T_max", "length", "blowout"):
        assert got[key] == getattr(api, key).tolist(), key
    assert (got["L0"], got["H0"], got["sag0"]) == (api.L0, api.H0, api.sag0)
    # auto says which model it took and why: the parabola's estimate against rtol
    assert got["model"] == chosen
    if model == "auto":
        assert f"rtol {rtol or 1e-3:g}" in got["reason"]


def test_conductor_table_auto_names_its_model(capsys):
    args = ("conductor", "table", *_STATE, "--H0", "2e4", "--temperatures", "-20", "60")
    status, out, err = main(capsys, *args, "--model", "auto", "--rtol", "1e-2", "--json")
    assert status == cli.EXIT_OK, err
    got = json.loads(out)
    parabola = conductors.sag_tension_table(
        300.0, -10.0, EA=3e7, alpha=2.3e-5, w0=15.0, t0=15.0, H0=2e4, temperatures=[-20.0, 60.0],
        load_cases={"bare": (15.0, 0.0)}, model="parabola",
    )  # fmt: skip
    assert got["H"] == parabola["H"].tolist() and got["model"] == "parabola"
    status, out, err = main(capsys, *args, "--model", "auto")
    assert status == cli.EXIT_OK, err
    assert out.rstrip().splitlines()[-1].startswith("model: the exact catenary")


def test_change_of_state_single_state_by_sag(capsys):
    status, out, _ = main(capsys, "change-of-state", *_STATE, "--sag0", "8", "--w", "15", "--t", "60")
    assert status == cli.EXIT_OK
    api = conductors.change_of_state(
        300.0, -10.0, EA=3e7, alpha=2.3e-5, w0=15.0, t0=15.0, sag0=8.0, w=15.0, t=60.0
    )
    assert f"{api.H:.10g}" in out and f"{api.sag:.10g}" in out


_FREQUENCIES = (
    "frequencies",
    "--span",
    "250",
    "--dh",
    "12",
    "--EA",
    "2e7",
    "--w",
    "12",
    "--sag",
    "6",
    "--n-modes",
    "3",
)


def test_frequencies_json_and_vtk_are_the_api(tmp_path, capsys):
    import meshio

    path = tmp_path / "modes.vtu"
    args = _FREQUENCIES
    status, out, err = main(capsys, *args, "--g", "9.8", "--vtk", path, "--json")
    assert status == cli.EXIT_OK, err
    got = json.loads(out)
    api = conductors.natural_frequencies(250.0, 12.0, 12.0, 2e7, sag=6.0, n_modes=3, g=9.8)
    assert got["f_in_plane"] == api.f_in_plane.tolist()
    assert got["f_out_of_plane"] == api.f_out_of_plane.tolist()
    assert got["in_plane_symmetric"] == api.in_plane_symmetric.tolist()
    assert (got["H"], got["lambda2"], got["L_e"]) == (api.H, api.lambda2, api.L_e)
    assert got["irvine_in_plane"] == api.irvine["in_plane"].tolist()
    assert got["vtk"] == str(path)
    shape = meshio.read(path).point_data["in_plane_2_m_per_sqrt_kg"]
    np.testing.assert_array_equal(shape[:, 1], api.modes_in_plane[1])


@pytest.mark.parametrize(
    "args, flag",
    [
        (("change-of-state", *_STATE, "--w", "15", "--t", "20"), "--H0"),  # neither H0 nor sag0
        (("change-of-state", *_STATE, "--H0", "2e4", "--sag0", "8", "--w", "15", "--t", "20"), "--H0"),
        (("change-of-state", *_STATE, "--H0", "2e4", "--w", "15", "16", "--t", "1", "2", "3"), "--t"),
        (("change-of-state", *_STATE, "--H0", "-2e4", "--w", "15", "--t", "20"), "--H0"),
        (("change-of-state", *_STATE, "--H0", "2e4", "--w", "15", "--t", "20", "--model", "x"), "--model"),
        (("change-of-state", *_STATE, "--H0", "2e4", "--w", "nan", "--t", "20"), "--w"),
        (("change-of-state", *_STATE, "--H0", "2e4", "--w", "15", "--t", "-1e5"), "--t"),
        (("change-of-state", *_STATE, "--H0", "2e4", "--w", "15", "--t", "20", "--rtol", "1e-3"), "--rtol"),
        (
            (
                "change-of-state",
                *_STATE,
                "--H0",
                "2e4",
                "--w",
                "15",
                "--t",
                "20",
                "--model",
                "auto",
                "--rtol",
                "-1",
            ),
            "--rtol",
        ),
        (("conductor", "table", *_STATE, "--H0", "2e4", "--temperatures", "20", "--rtol", "1e-3"), "--rtol"),
        (("frequencies", "--span", "250", "--EA", "2e7", "--w", "12"), "--sag"),
        (
            ("frequencies", "--span", "250", "--EA", "2e7", "--w", "12", "--H", "1", "--n-modes", "0"),
            "--n-modes",
        ),
        (("frequencies", "--span", "250", "--EA", "2e7", "--w", "12", "--H", "1e4", "--g", "0"), "--g"),
        (
            ("frequencies", "--span", "250", "--EA", "2e7", "--w", "12", "--H", "1e4", "--vtk", "m.csv"),
            "--vtk",
        ),
        (("frequencies", "--span", "250", "--w", "12", "--H", "1e4"), "--EA"),
    ],
)
def test_state_and_frequency_bad_flags_exit_2(capsys, args, flag):
    status, out, err = main(capsys, *args)
    assert status == cli.EXIT_USAGE and out == ""
    assert err.count("\n") == 1 and flag in err and "Traceback" not in err


# --- output paths: no parent created, unwritable named as given, no overwrite without --force ---
_CATENARY = ("catenary", "--span", "9", "--w", "1", "--sag", "1")
_CAPACITY = ("strand", "capacity", "--length", "0.3", "--n-elements", "8", "--n-steps", "4", "--no-progress")


@pytest.mark.parametrize(
    "args, flag",
    [
        ((*_CATENARY, "--vtk", "{missing}/c.vtu"), "--vtk"),
        (
            (
                "frequencies",
                "--span",
                "250",
                "--EA",
                "2e7",
                "--w",
                "12",
                "--sag",
                "6",
                "--vtk",
                "{missing}/m.vtu",
            ),
            "--vtk",
        ),
        ((*_CAPACITY, "--out", "{missing}/out"), "--out"),
        (("demo", "--out", "{missing}/results"), "--out"),
        (("study", "run", "{study}", "--serial", "--out", "{missing}/t.csv"), "--out"),
    ],
)
def test_a_missing_parent_folder_is_refused_and_never_created(
    tmp_path, capsys, no_computing, study_file, args, flag
):
    missing = tmp_path / "no" / "such"
    args = [a.format(missing=missing, study=study_file) for a in args]
    status, out, err = main(capsys, *args)
    assert status == cli.EXIT_USAGE and out == "", err
    given = next(a for a in args if str(missing) in a)
    assert err.count("\n") == 1 and err.startswith(f"skcable: error: {flag}: ") and repr(given) in err
    assert not (tmp_path / "no").exists()


def test_an_unwritable_folder_exits_2_naming_the_path_given(tmp_path, capsys):
    target = "/proc/c.vtu"  # a folder no one, root included, can create a file in
    status, out, err = main(capsys, *_CATENARY, "--vtk", target)
    assert status == cli.EXIT_USAGE and out == ""
    assert err.count("\n") == 1 and repr(target) in err and ".tmp" not in err and "probe" not in err
    if os.geteuid() != 0:  # a read-only folder stops everyone else
        folder = tmp_path / "ro"
        folder.mkdir(mode=0o555)
        status, _, err = main(capsys, *_CATENARY, "--vtk", folder / "c.vtu")
        assert status == cli.EXIT_USAGE and repr(str(folder / "c.vtu")) in err


def test_vtk_is_not_overwritten_without_force(tmp_path, capsys):
    path = tmp_path / "c.vtu"
    path.write_text("earlier")
    status, out, err = main(capsys, *_CATENARY, "--vtk", path)
    assert status == cli.EXIT_USAGE and out == "" and "--force" in err and repr(str(path)) in err
    assert path.read_text() == "earlier"
    status, out, err = main(capsys, *_CATENARY, "--vtk", path, "--force", "--json")
    assert status == cli.EXIT_OK and json.loads(out)["vtk"] == str(path)
    assert path.stat().st_size > 1000 and [p.name for p in tmp_path.iterdir()] == ["c.vtu"]


def test_strand_capacity_out_is_not_overwritten_without_force(tmp_path, capsys):
    out_dir = tmp_path / "r"
    status, out, err = main(capsys, *_CAPACITY, "--out", out_dir, "--json")
    assert status == cli.EXIT_OK, err
    before = {p.name: p.stat().st_mtime_ns for p in out_dir.iterdir()}
    assert "capacity.png" in before
    status, out, err = main(capsys, *_CAPACITY, "--out", out_dir, "--json")
    assert status == cli.EXIT_USAGE and out == "" and "--force" in err and "would overwrite" in err
    assert {p.name: p.stat().st_mtime_ns for p in out_dir.iterdir()} == before  # refused before computing
    status, out, err = main(capsys, *_CAPACITY, "--out", out_dir, "--force", "--json")
    assert status == cli.EXIT_OK, err
    assert set(before) <= {p.name for p in out_dir.iterdir()}
    assert all(out_dir.joinpath(n).stat().st_mtime_ns >= t for n, t in before.items())


# --- flags: the one the user typed, unknown ones named with the nearest --------------------------
@pytest.mark.parametrize(
    "args, message",
    [
        (
            ("catenary", "--spam", "800", "--w", "1", "--sag", "2"),
            "catenary: unknown flag --spam; did you mean --span?",
        ),
        (
            ("catenary", "--span", "800", "--w", "1", "--len", "900"),
            "unknown flag --len; did you mean --length?",
        ),
        (("frequencies", "--span", "9", "--EA", "1", "--w", "1", "--sgg", "1"), "did you mean --sag?"),
        (
            ("strand", "capacity", "--dmage", "1"),
            "strand capacity: unknown flag --dmage; did you mean --damage?",
        ),
        (("--verison",), "unknown flag --verison; did you mean --version?"),
        (("catenary", "--span=800", "--zzz=1"), "unknown flag --zzz (see skcable catenary --help)"),
    ],
)
def test_unknown_flag_is_named_with_the_nearest(capsys, args, message):
    status, out, err = main(capsys, *args)
    assert status == cli.EXIT_USAGE and out == ""
    assert err.count("\n") == 1 and message in err and "required" not in err


def test_negative_numbers_are_values_not_flags(capsys):
    status, out, _ = main(
        capsys, "catenary", "--span", "800", "--dh", "-20", "--w", "20", "--low", "-30", "--json"
    )
    assert status == cli.EXIT_OK and json.loads(out)["H"] == pytest.approx(85819.2, abs=0.05)


# --- results with units and labelled columns -------------------------------------------------
def test_change_of_state_prints_a_table_per_state_with_units(capsys):
    status, out, _ = main(
        capsys,
        "change-of-state",
        *_STATE,
        "--H0",
        "2e4",
        "--w",
        "15",
        "25",
        "--t",
        "-20",
        "60",
        "--wind",
        "0",
        "8",
    )
    assert status == cli.EXIT_OK
    api = conductors.change_of_state(
        300.0, -10.0, EA=3e7, alpha=2.3e-5, w0=15.0, t0=15.0, H0=2e4,
        w=np.array([15.0, 25.0]), t=np.array([-20.0, 60.0]), wind=np.array([0.0, 8.0]),
    )  # fmt: skip
    blocks = out.split("\n\n")
    assert (
        len(blocks) == 3 and blocks[0].startswith("reference state") and f"L0 = {api.L0:.10g} m" in blocks[0]
    )
    for i, block in enumerate(blocks[1:]):
        assert block.startswith(f"state {i + 1} of 2: w = {[15, 25][i]} N/m, t = {[-20, 60][i]} °C")
        rows = {line.split(" = ")[0].strip(): line.split(" = ")[1].split() for line in block.splitlines()[1:]}
        assert float(rows["H"][0]) == float(f"{api.H[i]:.10g}") and rows["H"][1] == "N"
        assert float(rows["sag"][0]) == float(f"{api.sag[i]:.10g}") and rows["sag"][1] == "m"
        assert rows["blowout"][1] == "rad" and float(rows["blowout"][0]) == pytest.approx(
            np.arctan2([0, 8][i], [15, 25][i])
        )


def test_frequencies_print_labelled_by_mode_and_plane(capsys):
    args = _FREQUENCIES
    status, out, _ = main(capsys, *args)
    assert status == cli.EXIT_OK
    api = conductors.natural_frequencies(250.0, 12.0, 12.0, 2e7, sag=6.0, n_modes=3)
    lines = out.splitlines()
    header = lines[0].split("  ")
    assert [h.strip() for h in header if h.strip()] == [
        "mode", "in-plane f [Hz]", "in-plane shape", "Irvine in-plane [Hz]", "out-of-plane f [Hz]",
        "Irvine out-of-plane [Hz]",
    ]  # fmt: skip
    for k in range(3):
        cells = lines[1 + k].split()
        assert int(cells[0]) == k + 1
        assert float(cells[1]) == float(f"{api.f_in_plane[k]:.10g}")
        assert cells[2] == ("symmetric" if api.in_plane_symmetric[k] else "antisymmetric")
        assert float(cells[4]) == float(f"{api.f_out_of_plane[k]:.10g}")
    assert f"L_e = {api.L_e:.10g} m" in out and "H = " in out


def test_help_imports_no_model():
    heavy = ("numpy", "scipy", "pandas", "skfem", "meshio", "matplotlib")
    code = (
        "import sys; from skcable.cli import parser; parser().format_help(); "
        f"print(sorted(m for m in {heavy!r} if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=ENV, check=True)
    assert out.stdout.strip() == "[]"
