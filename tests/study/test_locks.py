"""Locks on cases in progress: whole when they appear, a dead run's taken over at once (D9), a live
run's never."""

import json
import os
import socket
import threading

import pytest

from skcable import cable, study
from skcable.study import locks

CASE = {"span": 100.0, "sag": 5.0, "w": 12.0}


def run_beside(cache):
    """Run the one-case study in a thread; the thread, and the table once it ends."""
    tables = []
    thread = threading.Thread(
        target=lambda: tables.append(
            study.run(study.cable_solve, [CASE], executor="serial", cache=cache, progress=False)
        ),
        daemon=True,
    )
    thread.start()
    return thread, tables


@pytest.mark.parametrize("content", [b"", b'{"host": ', b"\xff garbage", b"[1, 2]"])
def test_a_lock_left_empty_by_a_kill_is_taken_over_at_once(tmp_path, calls, monkeypatch, content):
    """D9: a kill between creating a lock and filling it stalled the next run for 60 s."""
    monkeypatch.setattr(locks, "STALE_AFTER", 3600.0)  # the lock's age cannot be what frees it
    lock = tmp_path / f"{study.case_key(study.cable_solve, CASE)}.lock"
    lock.write_bytes(content)
    thread, tables = run_beside(tmp_path)
    thread.join(timeout=30)  # a stall fails here rather than hanging the suite
    assert not thread.is_alive(), "the run waited for a lock that names no owner"
    assert calls == [CASE] and tables[0].H[0] == cable.catenary(100.0, 0.0, 12.0, sag=5.0).H
    assert not lock.exists()


def test_a_lock_appears_whole_and_names_its_owner(tmp_path):
    held = locks.CaseLocks(tmp_path)
    try:
        assert held.acquire("k")
        owner = json.loads(held.path("k").read_text())
        assert owner["pid"] == os.getpid() and owner["host"] == socket.gethostname()
        assert owner["token"] == held.held["k"]
        assert sorted(p.name for p in tmp_path.iterdir()) == ["k.lock"]  # no temporary file left
        assert not locks.CaseLocks(tmp_path).acquire("k")  # held by a live run
    finally:
        held.close()
    assert not held.path("k").exists()


def test_a_live_runs_lock_is_not_taken_over(tmp_path):
    path = tmp_path / "k.lock"
    text = json.dumps({"host": socket.gethostname(), "pid": os.getpid(), "token": "other"})
    path.write_text(text)
    assert not locks.CaseLocks(tmp_path).reclaim(path)
    locks.CaseLocks(tmp_path).reclaim_all()
    assert path.read_text() == text


class RacedLocks(locks.CaseLocks):
    """Between judging the lock stale and moving it aside, another run replaces it by its own."""

    fresh = json.dumps({"host": socket.gethostname(), "pid": os.getpid(), "token": "fresh"})

    def _stale(self, stat, raw):
        path = self.folder / "k.lock"
        path.unlink()
        path.write_text(self.fresh)  # a new file (another inode), held by a live run
        return True


def test_taking_over_gives_back_a_lock_a_live_run_made_meanwhile(tmp_path):
    path = tmp_path / "k.lock"
    path.write_text(json.dumps({"host": socket.gethostname(), "pid": -1, "token": "dead"}))
    RacedLocks(tmp_path).reclaim(path)
    assert path.read_text() == RacedLocks.fresh
    assert sorted(p.name for p in tmp_path.iterdir()) == ["k.lock"]


def test_a_lock_of_a_run_on_another_host_waits_for_its_age(tmp_path):
    path = tmp_path / "k.lock"
    path.write_text(json.dumps({"host": "elsewhere", "pid": 1, "token": "x"}))
    assert not locks.CaseLocks(tmp_path).reclaim(path)  # fresh: that run may be alive
    old = path.stat().st_mtime - locks.STALE_AFTER - 1
    os.utime(path, (old, old))
    assert locks.CaseLocks(tmp_path).reclaim(path) and not path.exists()
