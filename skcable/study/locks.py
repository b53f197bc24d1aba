"""Locks on the cases in progress, so that runs sharing a cache split the work and a dead run blocks nobody.

A run computing a case holds ``<cache>/<key>.lock``, a small JSON file naming its owner
(``host``, ``pid``, a random ``token``). The file appears whole or not at all: it is
written under a temporary name and hard-linked onto the lock's name, which fails when a
lock is there already (on a file system without hard links it is created exclusively and
then filled). A live run refreshes its locks' modification time every `HEARTBEAT` s.

A lock is *stale*, and taken over at once, when

- it names no owner (empty or not JSON: a kill between creating and filling it, or
  damage; with the hard link a live lock is never empty),
- its owner is on this host and its process is gone, or
- it has not been refreshed for `STALE_AFTER` s (a run on another host that died, or a
  process id reused by another program).

Taking a lock over moves it aside under a temporary name and checks that the file moved
is the one judged stale (same bytes: every owner's token is its own); a lock that a live run
created meanwhile is put back.
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
import socket
import threading
import time
from pathlib import Path

from skcable.io._atomic import create_text

__all__ = ["HEARTBEAT", "STALE_AFTER", "CaseLocks", "pid_alive"]

#: A lock not refreshed for this long (s) belongs to a run that died.
STALE_AFTER = 60.0
#: Seconds between the refreshes of the locks a run holds.
HEARTBEAT = 10.0
_HOST = socket.gethostname()


def pid_alive(pid) -> bool:
    """Whether a process of this id (as read from a lock; anything else is "not alive") runs on
    this host, ours to signal or not. Always True on Windows, where ``os.kill(pid, 0)`` would
    end it (a lock's age decides there).
    """
    if os.name == "nt":
        return True
    if isinstance(pid, bool) or not isinstance(pid, int) or pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # exists, not ours to signal
        return True
    return True


def _temp_name(path: Path) -> Path:
    return path.with_name(f".{path.name}.{secrets.token_hex(6)}.tmp")  # matches io's TEMP_GLOB


def _create(path: Path, text: str) -> bool:
    """Create ``path`` holding ``text``, whole; False if it exists."""
    temp = _temp_name(path)
    create_text(temp, text)
    try:
        os.link(temp, path)
        return True
    except FileExistsError:
        return False
    except (OSError, NotImplementedError):  # no hard links here: create, then fill
        pass
    finally:
        with contextlib.suppress(OSError):
            temp.unlink()
    try:
        create_text(path, text)
    except FileExistsError:
        return False
    return True


def _owner(raw: bytes) -> dict | None:
    try:
        owner = json.loads(raw)
    except ValueError:
        return None
    return owner if isinstance(owner, dict) else None


class CaseLocks:
    """The locks one run holds in an existing cache folder; ``held`` maps key -> token of each."""

    def __init__(self, folder):
        self.folder = Path(folder)
        self.held: dict[str, str] = {}
        self._stop = threading.Event()
        self._heart: threading.Thread | None = None

    def path(self, key: str) -> Path:
        """The lock file of ``key``: ``<folder>/<key>.lock``."""
        return self.folder / f"{key}.lock"

    def acquire(self, key: str) -> bool:
        """Lock ``key`` for this run: True if this run holds the lock now, False if a live run holds it."""
        path = self.path(key)
        token = secrets.token_hex(8)
        text = json.dumps({"host": _HOST, "pid": os.getpid(), "token": token})
        for _ in range(3):
            if _create(path, text):
                self.held[key] = token
                self._beat()
                return True
            if not self.reclaim(path):
                return False
        return False

    def reclaim(self, path: Path) -> bool:
        """Remove the lock at ``path`` if it is stale (see the module's notes): True if no lock is
        left there (it was stale, or it is gone), False if a live run holds it.
        """
        try:
            seen = path.stat()
            raw = path.read_bytes()
        except FileNotFoundError:
            return True
        if not self._stale(seen, raw):
            return False
        tomb = _temp_name(path)
        try:
            os.rename(path, tomb)
        except FileNotFoundError:
            return True
        if tomb.read_bytes() != raw:  # a live run's new lock (its token is its own): give it back
            with contextlib.suppress(OSError):
                os.link(tomb, path)
        with contextlib.suppress(OSError):
            tomb.unlink()
        return True

    @staticmethod
    def _stale(stat: os.stat_result, raw: bytes) -> bool:
        owner = _owner(raw)
        if owner is None or time.time() - stat.st_mtime > STALE_AFTER:
            return True
        return owner.get("host") == _HOST and not pid_alive(owner.get("pid"))

    def release(self, key: str) -> None:
        """Remove this run's lock on ``key`` (a lock another run took over is left alone)."""
        token = self.held.pop(key, None)
        if token is None:
            return
        path = self.path(key)
        with contextlib.suppress(OSError):
            owner = _owner(path.read_bytes())
            if owner is not None and owner.get("token") == token:
                path.unlink()

    def reclaim_all(self) -> None:
        """Take over every stale lock of the folder (a killed run's)."""
        for path in self.folder.glob("*.lock"):
            with contextlib.suppress(OSError):
                self.reclaim(path)

    def _beat(self) -> None:
        if self._heart is None:
            self._heart = threading.Thread(target=self._refresh, name="skcable-study-locks", daemon=True)
            self._heart.start()

    def _refresh(self) -> None:
        while not self._stop.wait(HEARTBEAT):
            for key in list(self.held):
                with contextlib.suppress(OSError):
                    os.utime(self.path(key))

    def close(self) -> None:
        """Release every lock this run holds and stop refreshing them."""
        for key in list(self.held):
            self.release(key)
        self._stop.set()
