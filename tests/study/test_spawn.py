"""Studies never hang: from an unguarded script, from standard input or from a notebook-like
``python -c`` a study either runs or says in one line what to add. Each program runs in a
subprocess with a timeout, so that a hang fails the test instead of stalling the suite."""

import json
import os
import pickle
import subprocess
import sys
from pathlib import Path

import pytest

import skcable
from skcable import cable, study
from skcable.study import spawn

ROOT = Path(skcable.__file__).resolve().parents[1]
ENV = os.environ | {"PYTHONPATH": str(ROOT), "PYTHONWARNINGS": "default"}
GUARD = 'if __name__ == "__main__":'

# The docs/studies.md snippet as people save it: no guard. It prints the pids that computed
# the cases, the lock files left and the table's H.
SNIPPET = """
import json, os, sys
from pathlib import Path
from skcable import study

def pid_model(span, w, sag):
    return study.cable_solve(span, w, sag=sag) | {{"pid": os.getpid()}}

{setup}
cases = study.grid(span=[100.0, 200.0, 300.0, 400.0], sag=[5.0], w=[10.0])
table = study.run(pid_model, cases, cache=sys.argv[1], progress=False{options})
locks = sorted(p.name for p in Path(sys.argv[1]).glob("*.lock"))
print(json.dumps({{"pids": sorted(set(table.pid.tolist())), "me": os.getpid(), "locks": locks,
                  "H": table.H.tolist(), "status": table.status.tolist()}}))
"""
PAYS = "study.executors.CLUSTER_COST = 0.0; study.executors.free_cores = lambda: 2  # a cluster would pay"
EXPECTED_H = [cable.catenary(s, 0.0, 10.0, sag=5.0).H for s in (100.0, 200.0, 300.0, 400.0)]


def program(options="", setup=""):
    return SNIPPET.format(options=options, setup=setup)


def run_program(args, tmp_path, stdin=None):
    out = subprocess.run(
        [sys.executable, *args, str(tmp_path / "cache")],
        input=stdin,
        capture_output=True,
        text=True,
        env=ENV,
        cwd=tmp_path,
        timeout=180,  # a hang fails here
    )
    assert out.returncode == 0, out.stderr
    report = json.loads(out.stdout)
    assert report["status"] == ["ok"] * 4 and report["H"] == EXPECTED_H and report["locks"] == []
    warned = [line for line in out.stderr.splitlines() if "WorkerWarning" in line]
    assert "Traceback" not in out.stderr
    return report, warned


def test_unguarded_script_on_dask_runs_on_threads_and_says_what_to_add(tmp_path):
    script = tmp_path / "snippet.py"
    script.write_text(program(', executor="dask"'))
    report, warned = run_program([str(script)], tmp_path)
    assert report["pids"] == [report["me"]]  # worker threads of this process
    assert len(warned) == 1 and f"`{GUARD}`" in warned[0] and "threads" in warned[0]
    assert f"{script} runs the study at line 11" in warned[0]


def test_unguarded_script_stays_serial_where_auto_would_start_processes(tmp_path):
    script = tmp_path / "snippet.py"
    script.write_text(program(setup=PAYS))
    report, warned = run_program([str(script)], tmp_path)
    assert report["pids"] == [report["me"]]
    assert len(warned) == 1 and "runs serially" in warned[0] and f"`{GUARD}`" in warned[0]


def test_a_small_study_from_an_unguarded_script_warns_of_nothing(tmp_path):
    script = tmp_path / "snippet.py"
    script.write_text(program())  # executor="auto": 4 quick cases stay serial, nothing to warn of
    report, warned = run_program([str(script)], tmp_path)
    assert report["pids"] == [report["me"]] and warned == []


def test_standard_input_on_dask_runs_on_threads_and_says_what_to_add(tmp_path):
    report, warned = run_program(["-"], tmp_path, stdin=program(', executor="dask"'))
    assert report["pids"] == [report["me"]]
    assert len(warned) == 1 and "<stdin>, which worker processes cannot re-import" in warned[0]


def test_standard_input_on_auto_runs(tmp_path):
    report, warned = run_program(["-"], tmp_path, stdin=program(setup=PAYS))
    assert report["pids"] == [report["me"]] and len(warned) == 1 and "runs serially" in warned[0]


def test_a_program_without_a_main_file_uses_worker_processes(tmp_path):
    """As a notebook: ``__main__`` has no file, so workers re-import nothing; the model,
    defined in ``__main__``, travels by value."""
    report, warned = run_program(["-c", program(', executor="dask"')], tmp_path)
    assert report["me"] not in report["pids"] and warned == []


BACKSTOP = """
import multiprocessing, sys
from skcable import study

def nothing():
    pass

table = study.run(study.cable_solve, [dict(span=100.0, w=1.0, sag=5.0)], executor="serial",
                  cache=sys.argv[1], progress=False)
if multiprocessing.parent_process() is None:
    child = multiprocessing.get_context("spawn").Process(target=nothing)
    child.start()
    child.join(60)
    print(child.exitcode)
"""


def test_a_study_started_by_a_workers_reimport_stops_at_once(tmp_path):
    """The backstop: a process the program spawns re-imports the script, whose study must not run there."""
    script = tmp_path / "backstop.py"
    script.write_text(BACKSTOP)
    out = subprocess.run(
        [sys.executable, str(script), str(tmp_path / "cache")],
        capture_output=True,
        text=True,
        env=ENV,
        timeout=120,
    )
    assert out.returncode == 0 and out.stdout.strip() == "1"  # the child stopped, with an error
    last = out.stderr.strip().splitlines()[-1]
    assert last.startswith("RuntimeError: skcable.study.run: a worker process is re-importing the program")
    assert f"`{GUARD}`" in last
    assert not list((tmp_path / "cache").glob("*.lock"))


@pytest.mark.parametrize(
    "source, line, inside",
    [
        (f"run()\n{GUARD}\n    run()\n", 1, False),
        (f"run()\n{GUARD}\n    run()\n", 3, True),
        ("if '__main__' == __name__:\n    x = 1\n    run()\n", 3, True),
        ("if __name__ != '__main__':\n    pass\nelse:\n    run()\n", 4, True),
        ("if __name__ != '__main__':\n    run()\n", 2, False),
        ("if other == '__main__':\n    run()\n", 2, False),
        (f"def main():\n    run()\n\n{GUARD}\n    main()\n", 5, True),
        ("def main():\n    run()\n\nmain()\n", 4, False),
        ("this is not python", 1, False),
    ],
)
def test_guarded(source, line, inside):
    assert spawn.guarded(source, line) is inside


def test_main_problem_of_this_test_run_is_none():
    assert spawn.main_problem() is None  # pytest's main module is guarded: workers may start


def test_the_package_pickles_as_a_module():
    assert pickle.loads(pickle.dumps(study)) is study


EDITED = """\"\"\"A script that edits its own docstring while it runs.\"\"\"
from pathlib import Path
from skcable.study import spawn

if __name__ == "__main__":
    print(spawn.main_problem())
    path = Path(__file__)
    path.write_text(path.read_text().replace("A script", {new!r}, 1))
print(spawn.main_problem())
"""


def test_a_script_edited_while_it_runs_is_not_misjudged(tmp_path):
    """Once its lines on disk have moved, they are no longer those running and the guard cannot
    be judged from them (a guarded benchmark edited during its run was once told it was
    unguarded); an edit that moves no line leaves the judgement as it was."""
    moved, control = tmp_path / "moved.py", tmp_path / "control.py"
    moved.write_text(EDITED.format(new="A\nscript"))  # one more line: every line moves down
    control.write_text(EDITED.format(new="A Script"))  # the same lines
    out = subprocess.run([sys.executable, str(moved)], capture_output=True, text=True, env=ENV, timeout=60)
    assert out.stdout.splitlines() == ["None", "None"], out.stderr
    out = subprocess.run([sys.executable, str(control)], capture_output=True, text=True, env=ENV, timeout=60)
    first, last = out.stdout.splitlines()
    assert first == "None" and last.startswith(f"{control} runs the study at line 9 outside"), out.stderr


def test_a_dask_shutdown_prints_no_comm_closed_at_info(monkeypatch):
    """The flake this guards against: a local cluster's ``silence_logs`` ends inside its own close,
    before its loop stops, and a batched comm cut by the closing scheduler then logged its
    ``CommClosedError`` at INFO with a traceback. Here the cluster's close restores its handlers'
    levels and logs that record; nothing may reach a handler, and the level is restored after."""
    import logging

    pytest.importorskip("distributed")
    distributed_log = logging.getLogger("distributed")
    records: list[logging.LogRecord] = []
    catcher = logging.Handler(logging.NOTSET)
    catcher.emit = records.append  # type: ignore[method-assign]
    distributed_log.addHandler(catcher)
    monkeypatch.setattr(distributed_log, "level", logging.INFO)

    class Closing:
        def close(self):
            for handler in distributed_log.handlers:
                handler.setLevel(logging.NOTSET)  # what the cluster's exit stack restores
            try:
                raise ConnectionError("in: Stream is closed")
            except ConnectionError:
                logging.getLogger("distributed.batched").info("Batched Comm Closed", exc_info=True)

    executor = study.executors.Dask()
    executor.client, executor.cluster = Closing(), Closing()
    try:
        executor.close()
    finally:
        distributed_log.removeHandler(catcher)
    assert records == [] and distributed_log.level == logging.INFO
