"""executor="auto": a small study never starts a cluster (never slower than serial); a long one
moves to worker processes once they pay, with the same table."""

import os

import pandas as pd
import pytest

from skcable import study
from skcable.study import executors

CASES = study.grid(span=[100.0 + 10 * i for i in range(16)], sag=[5.0], w=[2.0])


def pid_model(span, w, sag):
    return study.cable_solve(span, w, sag=sag) | {"pid": os.getpid()}


@pytest.fixture
def no_cluster(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("a cluster was started")

    monkeypatch.setattr(executors, "Dask", refuse)


def test_a_small_study_never_starts_a_cluster(no_cluster, calls):
    table = study.run(study.cable_solve, CASES, progress=False)  # executor="auto"
    assert len(calls) == 16 and (table.status == "ok").all() and table.attrs["executor"] == "serial"


def test_auto_stays_serial_without_two_cores_or_without_dask(no_cluster, monkeypatch):
    monkeypatch.setattr(executors, "CLUSTER_COST", 0.0)  # a cluster would pay...
    monkeypatch.setattr(executors, "free_cores", lambda: 1)  # ...but one free core cannot run two workers
    study.run(study.cable_solve, CASES, progress=False)
    monkeypatch.setattr(executors, "free_cores", lambda: 2)
    monkeypatch.setattr(executors, "dask_available", lambda: False)
    study.run(study.cable_solve, CASES, progress=False)
    study.run(study.cable_solve, CASES, n_workers=1, progress=False)


def test_dask_pays_only_when_the_cluster_would_finish_first():
    cost, efficiency = executors.CLUSTER_COST, executors.EFFICIENCY
    # 1 s a case on 2 workers: serially n s, on the cluster cost + ceil(n/2)/efficiency s
    for n in (2, 5, 10, 20, 40, 80, 160, 320):
        cluster = cost + -(-n // 2) / efficiency
        assert executors.dask_pays(1.0, n, 2) is (cluster < n)
    assert not executors.dask_pays(1e6, 1, 2)  # one case left: nothing to share
    assert not executors.dask_pays(1e6, 100, 1)  # one worker: nothing gained
    assert executors.dask_pays(0.2, 1000, 2) and not executors.dask_pays(0.2, 16, 2)


@pytest.mark.parametrize("load, free", [(0.0, 2), (1.0, 2), (1.4, 2), (1.6, 1), (2.0, 1), (9.0, 1)])
def test_free_cores_leave_out_the_other_work(monkeypatch, load, free):
    monkeypatch.setattr(executors, "usable_cores", lambda: 2)
    monkeypatch.setattr(executors.os, "getloadavg", lambda: (load, load, load))
    assert executors.free_cores() == free


def test_auto_on_a_busy_machine_stays_serial(no_cluster, monkeypatch):
    monkeypatch.setattr(executors, "CLUSTER_COST", 0.0)
    monkeypatch.setattr(executors, "usable_cores", lambda: 2)
    monkeypatch.setattr(executors.os, "getloadavg", lambda: (6.0, 6.0, 6.0))  # others hold both cores
    assert study.run(study.cable_solve, CASES, progress=False).attrs["executor"] == "serial"


def test_a_long_study_moves_to_worker_processes_with_the_same_table(monkeypatch):
    monkeypatch.setattr(executors, "CLUSTER_COST", 0.0)  # as if every case were long
    monkeypatch.setattr(executors, "free_cores", lambda: 2)
    cases = CASES[:6]
    auto = study.run(pid_model, cases, n_workers=2, progress=False)
    serial = study.run(pid_model, cases, executor="serial", progress=False)
    assert auto.pid[:2].tolist() == [os.getpid()] * 2  # two cases timed here...
    assert os.getpid() not in auto.pid[2:].tolist()  # ...the rest on the workers
    assert auto.attrs["executor"] == "serial, then dask, a local cluster of 2 worker processes"
    columns = ["time_s", "pid"]
    pd.testing.assert_frame_equal(auto.drop(columns=columns), serial.drop(columns=columns))


def test_a_cluster_that_does_not_start_leaves_the_study_serial(monkeypatch, calls):
    def broken(self):
        raise OSError("no free port")

    monkeypatch.setattr(executors, "CLUSTER_COST", 0.0)
    monkeypatch.setattr(executors, "free_cores", lambda: 2)
    monkeypatch.setattr(executors.Dask, "connect", broken)
    with pytest.warns(
        study.WorkerWarning, match=r"runs serially: a local Dask cluster did not start \(no free"
    ):
        table = study.run(study.cable_solve, CASES, progress=False)
    assert len(calls) == 16 and table.attrs["executor"] == "serial"
    assert (
        table.H.tolist() == study.run(study.cable_solve, CASES, executor="serial", progress=False).H.tolist()
    )


def test_a_small_study_imports_no_dask():
    import subprocess
    import sys

    code = (
        "import sys; from skcable import study; "
        "study.run(study.cable_solve, [dict(span=100.0, w=1.0, sag=5.0)], progress=False); "
        "print(sorted(m for m in ('dask', 'distributed') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True)
    assert out.stdout.strip() == "[]"
