"""Parameter studies: serial and Dask give the same table; failures are isolated; studies resume
from a cache whose entries are verified, written atomically and shared safely between runs."""

import json
import os
import re
import socket
import subprocess
import sys
import threading
import time
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import skcable
from skcable import cable, cli, study
from skcable.errors import InputError

CASES = study.grid(span=[100.0, 300.0], sag=[5.0, 30.0, -1.0], w=[12.0])  # sag -1: a bad case
ROOT = Path(skcable.__file__).resolve().parents[1]
ENV = os.environ | {"PYTHONPATH": str(ROOT)}  # subprocesses import this checkout of skcable


def without_time(table):
    return table.drop(columns="time_s")


def direct_H(case):
    return cable.catenary(case["span"], 0.0, case["w"], sag=case["sag"]).H


def test_grid_and_sample():
    assert len(CASES) == 6 and CASES[1] == {"span": 100.0, "sag": 30.0, "w": 12.0}
    cases = study.sample(5, seed=3, fixed={"w": 1.0}, span=(100, 200))
    assert len(cases) == 5 and all(100 <= c["span"] <= 200 and c["w"] == 1.0 for c in cases)
    assert cases == study.sample(5, seed=3, fixed={"w": 1.0}, span=(100, 200))  # reproducible
    with pytest.raises(InputError, match="span"):
        study.grid(span=100.0)
    with pytest.raises(InputError, match="span: a grid axis needs at least one value"):
        study.grid(span=[])
    with pytest.raises(InputError, match="span"):
        study.sample(3, span=(2, 1))
    with pytest.raises(InputError, match="span"):
        study.sample(3, span=("a", "b"))
    with pytest.raises(InputError, match="n"):
        study.sample(0, span=(1, 2))
    with pytest.raises(InputError, match="n: must be an integer"):
        study.sample(2.5, span=(1, 2))  # not silently 2
    with pytest.raises(InputError, match="span: is both sampled and fixed"):
        study.sample(2, fixed={"span": 1.0}, span=(1, 2))


def test_serial_table_is_the_api_and_isolates_failures():
    table = study.run(study.cable_solve, CASES, executor="serial", progress=False)
    assert list(table.status) == ["ok", "ok", "failed"] * 2
    assert table.error[2].startswith("InputError: sag")
    for _, row in table[table.status == "ok"].iterrows():
        direct = cable.catenary(float(row.span), 0.0, float(row.w), sag=float(row.sag))
        assert row.H == direct.H and row.residual < 1e-9
        assert row.sag_result == pytest.approx(row.sag, rel=1e-12)  # the output beside the parameter
    assert np.isnan(table.H[2])  # no output for the failed case, the error says why


def test_printed_table_is_a_short_summary():
    cases = study.grid(span=[100.0 + i for i in range(150)], sag=[5.0, -1.0], w=[1.0])
    table = study.run(study.cable_solve, cases, executor="serial", progress=False)
    text = repr(table)
    failed = int((table.status != "ok").sum())
    n = len(cases)
    assert (
        text.splitlines()[0] == f"skcable study of cable_solve: {n} cases, {n - failed} ok, {failed} failed"
    )
    assert len(text.splitlines()) <= 15 and len(str(table[table.status == "ok"]).splitlines()) <= 15
    assert len(table.to_string().splitlines()) == len(cases) + 1  # the full table is still there


def test_dask_local_cluster_gives_the_same_table():
    serial = study.run(study.cable_solve, CASES, executor="serial", progress=False)
    parallel = study.run(study.cable_solve, CASES, executor="dask", n_workers=2, progress=False)
    pd.testing.assert_frame_equal(without_time(serial), without_time(parallel))


def test_resume_reads_finished_cases(tmp_path, calls):
    first = study.run(study.cable_solve, CASES[:3], executor="serial", cache=tmp_path, progress=False)
    assert len(calls) == 3 and len(list(tmp_path.glob("*.json"))) == 3
    # "interrupted" after three cases: the full study computes only the other three
    full = study.run(study.cable_solve, CASES, executor="serial", cache=tmp_path, progress=False)
    assert len(calls) == 6 and full.attrs["from_cache"] == 3
    pd.testing.assert_frame_equal(without_time(first), without_time(full.iloc[:3]))
    study.run(study.cable_solve, CASES, executor="serial", cache=tmp_path, progress=False)
    assert len(calls) == 6  # nothing recomputed, failed cases included
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        f"{study.case_key(study.cable_solve, c)}.json" for c in CASES
    )  # no lock or temporary file left


def test_cache_entry_records_what_it_was_computed_from(tmp_path):
    table = study.run(study.cable_solve, CASES[:1], executor="serial", cache=tmp_path, progress=False)
    entry = json.loads((tmp_path / f"{table.key[0]}.json").read_text())
    assert entry["model"] == "skcable.study.cable_solve"
    assert entry["parameters"] == CASES[0]
    assert entry["skcable_version"] == skcable.__version__
    assert entry["result"]["status"] == "ok"
    assert entry["result"]["outputs"]["H"] == direct_H(CASES[0]) == table.H[0]
    assert len(entry["checksum"]) == 64


def _entry(path):
    return json.loads(path.read_text())


def _with_checksum(entry):
    entry["checksum"] = study.cache.checksum(entry)
    return json.dumps(entry)


DAMAGES = {
    "empty file (a kill during a non-atomic write)": lambda p, other: b"",
    "truncated JSON": lambda p, other: p.read_bytes()[: len(p.read_bytes()) // 2],
    "not UTF-8": lambda p, other: b"\xff\xfe\x00garbage",
    "old format (no schema)": lambda p, other: json.dumps(_entry(p)["result"]).encode(),
    "future schema version": lambda p, other: json.dumps(_entry(p) | {"schema_version": 99}).encode(),
    "hand-edited value": lambda p, other: json.dumps(
        _entry(p) | {"result": _entry(p)["result"] | {"outputs": {"H": 1.0}}}
    ).encode(),
    "another case's entry": lambda p, other: other.read_bytes(),
    "another skcable version": lambda p, other: _with_checksum(
        _entry(p) | {"skcable_version": "0.0.1"}
    ).encode(),
}


@pytest.mark.parametrize("damage", list(DAMAGES))
def test_damaged_entry_is_recomputed_with_a_warning(tmp_path, calls, damage):
    first = study.run(study.cable_solve, CASES[:3], executor="serial", cache=tmp_path, progress=False)
    path = tmp_path / f"{first.key[0]}.json"
    path.write_bytes(DAMAGES[damage](path, tmp_path / f"{first.key[1]}.json"))
    calls.clear()
    with pytest.warns(study.CacheWarning, match=re.escape(str(path))):
        again = study.run(study.cable_solve, CASES[:3], executor="serial", cache=tmp_path, progress=False)
    assert calls == [CASES[0]]  # only the damaged case, recomputed
    assert again.H[0] == direct_H(CASES[0])
    pd.testing.assert_frame_equal(without_time(first), without_time(again))
    calls.clear()
    with warnings.catch_warnings():
        warnings.simplefilter("error", study.CacheWarning)  # the entry was rewritten whole
        study.run(study.cable_solve, CASES[:3], executor="serial", cache=tmp_path, progress=False)
    assert calls == []


# a slow model, so that two runs overlap
def slow_cable(span, w, sag):
    time.sleep(0.02)
    return study.cable_solve(span, w, sag=sag)


def test_two_concurrent_runs_share_the_cache(tmp_path, calls):
    cases = study.grid(span=[100.0 + 10 * i for i in range(24)], sag=[5.0], w=[2.0])
    tables, errors = {}, []

    def one(name):
        try:
            tables[name] = study.run(slow_cable, cases, executor="serial", cache=tmp_path, progress=False)
        except Exception as exc:  # noqa: BLE001 - reported below
            errors.append(exc)

    threads = [threading.Thread(target=one, args=(name,)) for name in ("a", "b")]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=60)
    assert not errors and set(tables) == {"a", "b"}
    assert sorted(c["span"] for c in calls) == [c["span"] for c in cases]  # each case computed once
    pd.testing.assert_frame_equal(without_time(tables["a"]), without_time(tables["b"]))
    assert tables["a"].H.tolist() == [direct_H(c) for c in cases]
    assert sorted(p.suffix for p in tmp_path.iterdir()) == [".json"] * len(cases)  # no lock left


KILLED_RUN = """
import json, sys, time
from skcable import study

def slow(span, w, sag):
    time.sleep(float(sys.argv[2]))
    return study.cable_solve(span, w, sag=sag)

cases = study.grid(span=[100.0 + i for i in range(40)], sag=[5.0], w=[2.0])
table = study.run(slow, cases, executor="serial", cache=sys.argv[1], progress=False)
print(json.dumps(table.H.tolist()))
"""


def test_killed_run_resumes_without_damage(tmp_path):
    cache = tmp_path / "cache"
    script = tmp_path / "study_script.py"
    script.write_text(KILLED_RUN)
    killed = subprocess.Popen([sys.executable, str(script), str(cache), "0.02"], env=ENV)
    deadline = time.monotonic() + 30
    while len(list(cache.glob("*.json"))) < 5 and time.monotonic() < deadline:
        time.sleep(0.01)
    killed.kill()  # SIGKILL: no cleanup, its lock (if any) stays behind
    killed.wait()
    done = len(list(cache.glob("*.json")))
    assert 5 <= done < 40
    resumed = subprocess.run(
        [sys.executable, str(script), str(cache), "0"], env=ENV, capture_output=True, text=True, timeout=60
    )
    assert resumed.returncode == 0 and resumed.stderr == "", resumed.stderr  # no warning, no traceback
    spans = [100.0 + i for i in range(40)]
    assert json.loads(resumed.stdout) == [cable.catenary(s, 0.0, 2.0, sag=5.0).H for s in spans]
    entries = [p for p in cache.iterdir() if re.fullmatch(r"[0-9a-f]{16}\.json", p.name)]
    assert len(entries) == 40 and not list(cache.glob("*.lock"))  # (a kill mid-write leaves a temp file)


def _dead_pid():
    process = subprocess.Popen([sys.executable, "-c", "pass"])
    process.wait()
    return process.pid


@pytest.mark.parametrize("owner", ["dead process on this host", "old lock from another host"])
def test_lock_of_a_dead_run_is_taken_over(tmp_path, calls, owner):
    key = study.case_key(study.cable_solve, CASES[0])
    lock = tmp_path / f"{key}.lock"
    if owner == "dead process on this host":
        lock.write_text(json.dumps({"host": socket.gethostname(), "pid": _dead_pid(), "token": "x"}))
    else:
        lock.write_text(json.dumps({"host": "elsewhere", "pid": 1, "token": "x"}))
        old = time.time() - study.STALE_AFTER - 1
        os.utime(lock, (old, old))
    table = study.run(study.cable_solve, CASES[:1], executor="serial", cache=tmp_path, progress=False)
    assert calls == [CASES[0]] and table.H[0] == direct_H(CASES[0])
    assert not lock.exists()


def test_a_run_waits_for_a_live_lock_and_takes_over_when_its_run_dies(tmp_path, calls):
    key = study.case_key(study.cable_solve, CASES[0])
    other = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])  # "another run"
    try:
        owner = {"host": socket.gethostname(), "pid": other.pid, "token": "x"}
        (tmp_path / f"{key}.lock").write_text(json.dumps(owner))
        tables = []
        waiting = threading.Thread(
            target=lambda: tables.append(
                study.run(study.cable_solve, CASES[:2], executor="serial", cache=tmp_path, progress=False)
            )
        )
        waiting.start()
        time.sleep(0.5)
        assert waiting.is_alive() and calls == [CASES[1]]  # the free case is done, the locked one waited
    finally:
        other.kill()
        other.wait()
    waiting.join(timeout=30)
    assert not waiting.is_alive() and calls == [CASES[1], CASES[0]]
    assert tables[0].H.tolist() == [direct_H(CASES[0]), direct_H(CASES[1])]


def test_bad_run_arguments(calls, tmp_path):
    with pytest.raises(InputError, match="executor"):
        study.run(study.cable_solve, CASES, executor="threads")
    with pytest.raises(InputError, match="cases"):
        study.run(study.cable_solve, [], executor="serial")
    with pytest.raises(InputError, match="n_workers: must be an integer >= 1"):
        study.run(study.cable_solve, CASES, executor="dask", n_workers=0)  # it used to hang
    with pytest.raises(InputError, match="n_workers: must be an integer"):
        study.run(study.cable_solve, CASES, executor="dask", n_workers=1.5)
    with pytest.raises(InputError, match="n_workers"):
        study.run(study.cable_solve, CASES, scheduler="tcp://host:8786", n_workers=3)  # not silently ignored
    with pytest.raises(InputError, match="scheduler"):
        study.run(study.cable_solve, CASES, executor="serial", scheduler="tcp://host:8786")
    for address in ("nonsense", "foo://host:1", "tcp://host"):
        with pytest.raises(InputError, match="scheduler: .* is not a scheduler address"):
            study.run(study.cable_solve, CASES, scheduler=address)
    with pytest.raises(InputError, match="cases: case 0 .* unknown parameter 'spna'"):
        study.run(study.cable_solve, [{"spna": 1.0, "w": 1.0, "sag": 1.0}], executor="serial")
    with pytest.raises(InputError, match="cases: case 0 .* missing parameter 'w'"):
        study.run(study.cable_solve, [{"span": 1.0, "sag": 1.0}], executor="serial")
    with pytest.raises(InputError, match="cache: .* is a file"):
        study.run(study.cable_solve, CASES, executor="serial", cache=__file__)
    assert calls == []  # all refused before computing


def test_unreachable_scheduler_is_an_input_error(calls):
    import dask

    with dask.config.set({"distributed.comm.timeouts.connect": "0.5s"}):
        with pytest.raises(InputError, match="scheduler: no dask scheduler answers at 'tcp://127.0.0.1:1'"):
            study.run(study.cable_solve, CASES, scheduler="tcp://127.0.0.1:1", progress=False)
    assert calls == []


def test_strand_capacity_case():
    row = study.strand_capacity("steel-9.5", 1, slip="axis", length=0.3, n_elements=12, n_steps=8)
    from skcable import strand

    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.3, slip="axis", n_elements=12)
    curve = model.capacity_curve(n_steps=8)
    assert row["K_Leq"] == curve.K_Leq and row["D_r"] == curve.D_r
    assert 0 < row["slip_onset_strain"] <= row["rupture_strain"]
    for n_steps in (0, 3, 7.5):  # 0 is not "the default", 7.5 is not 7
        with pytest.raises(InputError, match="n_steps"):
            study.strand_capacity("steel-9.5", 1, n_steps=n_steps)


def test_cable_solve_elastic_needs_length():
    row = study.cable_solve(400.0, 16.0, dh=10.0, EA=3e7, length=401.2)
    assert row["H"] == cable.elastic_catenary(400.0, 10.0, 16.0, 3e7, length=401.2).H
    with pytest.raises(InputError, match="EA"):
        study.cable_solve(400.0, 16.0, EA=3e7, sag=10.0)


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
        env=ENV,
    )
    assert out.returncode == 0, out.stderr
    table = pd.read_parquet(tmp_path / "out.parquet")
    assert table.H.tolist() == [cable.catenary(s, 0, 2.0, sag=10.0).H for s in (100.0, 200.0)]
    assert len(list((tmp_path / "cache").glob("*.json"))) == 2
    cached = json.loads(next((tmp_path / "cache").glob("*.json")).read_text())
    assert cached["result"]["status"] == "ok"
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "cache",
        "out.parquet",
        "study.toml",
    ]  # no temp file


def test_failed_cases_are_named_and_the_exit_status_says_so(tmp_path, capsys):
    path = write_study(
        tmp_path,
        f'model = "cable_solve"\noutput = "{tmp_path / "t.csv"}"\n[grid]\nspan = [100.0]\nsag = [5.0, -1.0]\n'
        "[fixed]\nw = 2.0\n",
    )
    status = cli.main(["study", "run", str(path), "--serial", "--no-progress"])
    out, err = capsys.readouterr()
    assert status == cli.EXIT_CASES_FAILED
    assert "failed w=2.0, span=100.0, sag=-1.0: InputError: sag" in out
    assert err == "skcable: 1 of 2 cases failed\n"
    table = pd.read_csv(tmp_path / "t.csv")
    assert (
        table.status.tolist() == ["ok", "failed"] and table.H[0] == cable.catenary(100.0, 0, 2.0, sag=5.0).H
    )


GOOD_GRID = "[grid]\nspan = [100.0]\nsag = [5.0]\n[fixed]\nw = 1.0\n"


@pytest.mark.parametrize(
    "body, argument",
    [
        ('model = "beam"\n[grid]\nspan = [1.0]\n', "model"),
        ('model = "cable_solve"\n', "grid"),
        ('model = "cable_solve"\n[sample]\nspan = [1.0, 2.0]\n', "sample"),
        ("model = \n", "path"),
        ('model = "cable_solve"\ncahce = "c"\n' + GOOD_GRID, "cahce"),  # a misspelt key
        ('model = "cable_solve"\n' + GOOD_GRID + "[sample]\nn = 2\nspan = [1.0, 2.0]\n", "sample"),
        (
            'model = "cable_solve"\n[grid]\nspan = [100.0]\nsag = [5.0]\n[fixed]\nw = 1.0\nspan = 3.0\n',
            "fixed",
        ),
        ('model = "cable_solve"\n[grid]\nspna = [100.0]\nsag = [5.0]\n[fixed]\nw = 1.0\n', "grid"),
        ('model = "cable_solve"\n[grid]\nspan = [100.0]\nsag = [5.0]\n', "fixed"),  # w missing
        ('model = "cable_solve"\n[grid]\nspan = []\nsag = [5.0]\n[fixed]\nw = 1.0\n', "span"),
        ('model = "cable_solve"\n[sample]\nn = 2.5\nspan = [1.0, 2.0]\n[fixed]\nw = 1.0\nsag = 0.1\n', "n"),
        ('model = "cable_solve"\noutput = "t.txt"\n' + GOOD_GRID, "output"),
        ('model = "cable_solve"\ngrid = 3\n', "grid"),
        ('model = "strand_capacity"\n[grid]\nn_stpes = [8]\n', "grid"),
    ],
)
def test_bad_study_files(tmp_path, capsys, calls, body, argument):
    path = write_study(tmp_path, body)
    with pytest.raises(InputError, match=argument):
        study.load_study(path)
    status = cli.main(["study", "run", str(path), "--serial"])
    out, err = capsys.readouterr()
    assert status == cli.EXIT_USAGE and out == ""
    assert err.count("\n") == 1 and err.startswith(f"skcable: error: {path}: {argument}")
    assert calls == []


def test_shipped_study_files_load():
    files = sorted((ROOT / "studies").glob("*.toml"))
    assert files
    for path in files:
        spec = study.load_study(path)  # no unknown key, no parameter the model does not take
        assert spec["cases"] and spec["output"].suffix in study.TABLE_SUFFIXES
    old, new = (
        study.load_study(ROOT / "studies" / name)
        for name in ("seed003_tables_4_1_4_2.toml", "pino_vidal_2021_tables_4_1_4_2.toml")
    )
    assert old["cases"] == new["cases"] and len(new["cases"]) == 16  # the former name still works


def test_cli_reports_a_damaged_entry_in_one_line_and_recomputes_it(tmp_path, capsys):
    path = write_study(
        tmp_path,
        f'model = "cable_solve"\noutput = "{tmp_path / "t.csv"}"\ncache = "{tmp_path / "c"}"\n' + GOOD_GRID,
    )
    assert cli.main(["study", "run", str(path), "--serial", "--no-progress"]) == 0
    entry = next((tmp_path / "c").glob("*.json"))
    entry.write_bytes(b"")  # what a kill during the old non-atomic write left
    capsys.readouterr()
    assert cli.main(["study", "run", str(path), "--serial", "--no-progress"]) == 0
    out, err = capsys.readouterr()
    assert err.count("\n") == 1 and err.startswith("skcable: warning: study cache:") and str(entry) in err
    assert "0 read from the cache" in out
    assert pd.read_csv(tmp_path / "t.csv").H[0] == cable.catenary(100.0, 0.0, 1.0, sag=5.0).H
