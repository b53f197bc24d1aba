"""The study cache: one verified JSON entry per finished case, so that an interrupted study resumes.

``<cache>/<key>.json`` holds the result of the case whose `skcable.study.cases.case_key` is
``key``, with what it was computed from: the schema (`SCHEMA`, `SCHEMA_VERSION`), the
skcable version, the fingerprint of the code (`skcable.study.fingerprint.code_fingerprint`),
the model's name, the parameters, the result and a SHA-256 checksum of all of it. Entries
are written atomically (a temporary file moved onto the name), so that a kill leaves the old
entry or the new one, never a torn one.

An entry that cannot be used is recomputed, with one `skcable.errors.CacheWarning` naming
the file and the reason: empty, truncated or not JSON, of another schema, edited by hand
(checksum), for other parameters or another model, or made by other code (another skcable
version or code fingerprint: the numbers may have changed).

Examples
--------
>>> import tempfile
>>> from skcable.study import tasks
>>> case = {"span": 100.0, "w": 10.0, "sag": 5.0}
>>> with tempfile.TemporaryDirectory() as folder:
...     cache = Cache(folder, tasks.cable_solve)
...     cache.write("k", case, tasks.evaluate(tasks.cable_solve, case))
...     cache.read("k", case)["status"]
'ok'
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import time
from collections.abc import Callable
from pathlib import Path

from skcable.errors import CacheWarning
from skcable.io._atomic import TEMP_GLOB, write_text
from skcable.study._warn import warn
from skcable.study.cases import describe, model_name
from skcable.study.fingerprint import code_fingerprint
from skcable.study.locks import CaseLocks

__all__ = ["SCHEMA", "SCHEMA_VERSION", "WARN_EACH", "Cache", "canonical", "checksum"]

SCHEMA = "skcable.study cache entry"
#: Version 2 records the code fingerprint; entries of version 1 are recomputed.
SCHEMA_VERSION = 2
#: Unusable entries named one warning each; the others are counted in one last warning.
WARN_EACH = 3
_TEMP_AGE = 600.0  # s after which a temporary file is a killed writer's (writes take milliseconds)


def canonical(value):
    """``value`` as it reads back from JSON, other objects as their ``str`` (how cases are compared)."""
    return json.loads(json.dumps(value, sort_keys=True, default=str))


def checksum(entry: dict) -> str:
    """SHA-256 (64 hexadecimal digits) of an entry's fields but ``checksum`` (sorted keys, compact JSON)."""
    body = {k: v for k, v in entry.items() if k != "checksum"}
    text = json.dumps(body, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def _malformed(result) -> bool:
    return (
        not isinstance(result, dict)
        or result.get("status") not in ("ok", "failed")
        or not isinstance(result.get("outputs"), dict)
        or not isinstance(result.get("error"), str)
        or not isinstance(result.get("time_s"), (int, float))
    )


class Cache:
    """A folder of verified entries, one per case key, and the locks of the cases in progress.

    ``folder`` is created if missing; ``model`` is the study's model function, whose name and
    code ``fingerprint`` (the attribute) entries are written with and checked against; ``locks``
    (a `CaseLocks`) are the locks this run holds. Opening a cache removes what killed runs
    left: temporary files older than 10 minutes and stale locks (`skcable.study.locks`).
    """

    def __init__(self, folder, model: Callable):
        from skcable import __version__

        self.folder = Path(folder)
        self.model = model_name(model)
        self.version = __version__
        self.fingerprint = code_fingerprint(model)
        self.warned: set[str] = set()
        self.folder.mkdir(parents=True, exist_ok=True)
        for temp in self.folder.glob(TEMP_GLOB):
            with contextlib.suppress(OSError):
                if time.time() - temp.stat().st_mtime > _TEMP_AGE:
                    temp.unlink()
        self.locks = CaseLocks(self.folder)
        self.locks.reclaim_all()

    def entry_path(self, key: str) -> Path:
        """The entry file of ``key``: ``<folder>/<key>.json``."""
        return self.folder / f"{key}.json"

    def read(self, key: str, case: dict) -> dict | None:
        """The verified result record of ``case`` (as `skcable.study.tasks.evaluate` returns it), or None.

        None when there is no entry or it cannot be used (then a `CacheWarning` names the file and
        the reason, once per file and run, for the first `WARN_EACH` files; `close` counts the
        others in one more warning).
        """
        path = self.entry_path(key)
        problem: str | None
        try:
            raw = path.read_bytes()
        except FileNotFoundError:
            return None
        except OSError as exc:
            result, problem = None, f"cannot be read ({exc.strerror})"
        else:
            result, problem = self._verify(raw, case)
        if problem is None:
            return result
        if str(path) not in self.warned:
            self.warned.add(str(path))
            if len(self.warned) <= WARN_EACH:
                warn(f"study cache: {path} {problem}; recomputing that case ({describe(case)})", CacheWarning)
        return None

    def _verify(self, raw: bytes, case: dict) -> tuple[dict | None, str | None]:
        if not raw.strip():
            return None, f"is empty ({len(raw)} bytes)"
        try:
            entry = json.loads(raw.decode("utf-8"))
        except UnicodeDecodeError:
            return None, "is not UTF-8 text"
        except json.JSONDecodeError as exc:
            return None, f"is not valid JSON, truncated or damaged ({exc.msg}, line {exc.lineno})"
        if not isinstance(entry, dict) or entry.get("schema") != SCHEMA:
            return None, f"is not a {SCHEMA}"
        if entry.get("schema_version") != SCHEMA_VERSION:
            found = entry.get("schema_version")
            return None, f"has schema version {found!r}; this skcable reads {SCHEMA_VERSION}"
        if entry.get("checksum") != checksum(entry):
            return None, "does not match its checksum (edited or damaged)"
        return self._check_origin(entry, case)

    def _check_origin(self, entry: dict, case: dict) -> tuple[dict | None, str | None]:
        if entry.get("skcable_version") != self.version:
            return None, f"was computed by skcable {entry.get('skcable_version')}, this is {self.version}"
        if entry.get("code") != self.fingerprint:
            found = str(entry.get("code"))[:12]
            return (
                None,
                f"was computed by other code (fingerprint {found}, this code's {self.fingerprint[:12]})",
            )
        if entry.get("model") != self.model:
            return None, f"belongs to model {entry.get('model')}, not {self.model}"
        if entry.get("parameters") != canonical(case):
            return None, f"holds the parameters {entry.get('parameters')}, not this case's"
        if _malformed(entry.get("result")):
            return None, "holds a malformed result"
        return entry["result"], None

    def write(self, key: str, case: dict, result: dict) -> None:
        """Write the entry of ``case`` and its ``result`` record atomically (replacing any older one)."""
        entry = {
            "schema": SCHEMA,
            "schema_version": SCHEMA_VERSION,
            "skcable_version": self.version,
            "code": self.fingerprint,
            "model": self.model,
            "key": key,
            "parameters": canonical(case),
            "result": result,
        }
        entry["checksum"] = checksum(entry)
        write_text(self.entry_path(key), json.dumps(entry, indent=1, sort_keys=True) + "\n")

    def close(self) -> None:
        """Release the locks this run holds; warn of the unusable entries not named yet."""
        self.locks.close()
        more = len(self.warned) - WARN_EACH
        if more > 0:
            warn(
                f"study cache: {more} more entries of {self.folder} cannot be used either; recomputing them",
                CacheWarning,
            )
