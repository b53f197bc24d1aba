"""Parameter studies: serial and Dask give the same table; failures are isolated; studies resume."""

import json
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from skcable import cable, study
from skcable.errors import InputError

CASES = study.grid(span=[100.0, 300.0], sag=[5.0, 30.0, -1.0], w=[12.0])  # sag -1: a bad case


def without_time(table):
    return table.drop(columns="time_s")


def test_grid_and_sample():
    assert len(CASES) == 6 and CASES[1] == {"span": 100.0, "sag": 30.0, "w": 12.0}
    cases = study.sample(5, seed=3, fixed={"w": 1.0}, span=(100, 200))
    assert len(cases) == 5 and all(100 <= c["span"] <= 200 and c["w"] == 1.0 for c in cases)
    assert cases == study.sample(5, seed=3, fixed={"w": 1.0}, span=(100, 200))  # reproducible
    with pytest.raises(InputError, match="span"):
        study.grid(span=100.0)
    with pytest.raises(InputError, match="span"):
        study.sample(3, span=(2, 1))
    with pytest.raises(InputError, match="n"):
        study.sample(0, span=(1, 2))


def test_serial_table_is_the_api_and_isolates_failures():
    table = study.run(study.cable_solve, CASES, executor="serial", progress=False)
    assert list(table.status) == ["ok", "ok", "failed"] * 2
    assert table.error[2].startswith("InputError: sag")
    for _, row in table[table.status == "ok"].iterrows():
        direct = cable.catenary(float(row.span), 0.0, float(row.w), sag=float(row.sag))
        assert row.H == direct.H and row.residual < 1e-9
        assert row.sag_result == pytest.approx(row.sag, rel=1e-12)  # the output beside the parameter
    assert np.isnan(table.H[2])  # no output for the failed case, the error says why


def test_dask_local_cluster_gives_the_same_table():
    serial = study.run(study.cable_solve, CASES, executor="serial", progress=False)
    parallel = study.run(study.cable_solve, CASES, executor="dask", n_workers=2, progress=False)
    pd.testing.assert_frame_equal(without_time(serial), without_time(parallel))


def test_resume_reads_finished_cases(tmp_path, monkeypatch):
    calls = []
    evaluate = study._evaluate

    def counting(model, case):
        calls.append(case)
        return evaluate(model, case)

    monkeypatch.setattr(study, "_evaluate", counting)
    first = study.run(study.cable_solve, CASES[:3], executor="serial", cache=tmp_path, progress=False)
    assert len(calls) == 3 and len(list(tmp_path.glob("*.json"))) == 3
    # "interrupted" after three cases: the full study computes only the other three
    full = study.run(study.cable_solve, CASES, executor="serial", cache=tmp_path, progress=False)
    assert len(calls) == 6
    pd.testing.assert_frame_equal(without_time(first), without_time(full.iloc[:3]))
    study.run(study.cable_solve, CASES, executor="serial", cache=tmp_path, progress=False)
    assert len(calls) == 6  # nothing recomputed, failed cases included


def test_bad_run_arguments():
    with pytest.raises(InputError, match="executor"):
        study.run(study.cable_solve, CASES, executor="threads")
    with pytest.raises(InputError, match="cases"):
        study.run(study.cable_solve, [], executor="serial")


def test_strand_capacity_case():
    row = study.strand_capacity("steel-9.5", 1, slip="axis", length=0.3, n_elements=12, n_steps=8)
    from skcable import strand

    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.3, slip="axis", n_elements=12)
    curve = model.capacity_curve(n_steps=8)
    assert row["K_Leq"] == curve.K_Leq and row["D_r"] == curve.D_r
    assert 0 < row["slip_onset_strain"] <= row["rupture_strain"]


def write_study(tmp_path, body):
    path = tmp_path / "study.toml"
    path.write_text(body)
    return path


def test_study_file_and_cli(tmp_path):
    path = write_study(
        tmp_path,
        f"""
model = "cable_solve"
output = "{tmp_path / "out.parquet"}"
cache = "{tmp_path / "cache"}"
[grid]
span = [100.0, 200.0]
sag = [10.0]
[fixed]
w = 2.0
""",
    )
    spec = study.load_study(path)
    assert spec["cases"] == [{"w": 2.0, "span": 100.0, "sag": 10.0}, {"w": 2.0, "span": 200.0, "sag": 10.0}]
    out = subprocess.run(
        [sys.executable, "-m", "skcable", "study", "run", str(path), "--serial", "--no-progress"],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stderr
    table = pd.read_parquet(tmp_path / "out.parquet")
    assert table.H.tolist() == [cable.catenary(s, 0, 2.0, sag=10.0).H for s in (100.0, 200.0)]
    assert len(list((tmp_path / "cache").glob("*.json"))) == 2
    cached = json.loads(next((tmp_path / "cache").glob("*.json")).read_text())
    assert cached["status"] == "ok"


@pytest.mark.parametrize(
    "body, argument",
    [
        ('model = "beam"\n[grid]\nspan = [1.0]\n', "model"),
        ('model = "cable_solve"\n', "grid"),
        ('model = "cable_solve"\n[sample]\nspan = [1.0, 2.0]\n', "sample"),
        ("model = \n", "path"),
    ],
)
def test_bad_study_files(tmp_path, body, argument):
    with pytest.raises(InputError, match=argument):
        study.load_study(write_study(tmp_path, body))
    out = subprocess.run(
        [sys.executable, "-m", "skcable", "study", "run", str(tmp_path / "study.toml"), "--serial"],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and out.stderr.count("\n") == 1
