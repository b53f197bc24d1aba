"""Files written whole or not at all, and output paths checked before any computing.

`atomic_path` hands a writer a temporary path in the target's directory
(same file system, same suffix, so writers that pick a format from the suffix
still work) and moves the finished file onto the target with `os.replace`:
a reader, a concurrent writer or a kill never leaves a torn or empty target, and
the last writer wins with a complete file. `writable_file` and
`writable_dir` refuse, with `skcable.InputError`, a path that cannot
be written (a directory where a file is meant, a file where a folder is meant,
an unknown extension, a parent that is not a writable folder).
"""

from __future__ import annotations

import contextlib
import os
import secrets
from pathlib import Path

from skcable.errors import InputError

__all__ = ["TEMP_GLOB", "atomic_path", "writable_dir", "writable_file", "write_text"]

#: Glob of the temporary files `atomic_path` creates (left behind only by a kill).
TEMP_GLOB = ".*.tmp*"


@contextlib.contextmanager
def atomic_path(path):
    """Context manager: yields a temporary path beside ``path``; on a clean exit the file
    written there is flushed to disk and moved onto ``path``; on an exception it is removed
    and ``path`` is left as it was."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temp = path.with_name(f".{path.stem}.{secrets.token_hex(6)}.tmp{path.suffix}")
    try:
        yield temp
        with open(temp, "rb+") as handle:  # a writer may close without syncing
            os.fsync(handle.fileno())
        os.replace(temp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            temp.unlink()
        raise
    _sync_dir(path.parent)


def write_text(path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically; returns the path."""
    path = Path(path)
    with atomic_path(path) as temp:
        # O_EXCL: the random name is ours alone; the umask sets the permissions as for open()
        fd = os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
    return path


def _sync_dir(folder: Path) -> None:
    """Make the rename durable (POSIX); a no-op where folders cannot be opened."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _existing_ancestor(path: Path) -> Path:
    path = Path(os.path.abspath(path))
    while not path.exists() and path != path.parent:
        path = path.parent
    return path


def _check_parent(name: str, path: Path, start: Path, what: str) -> None:
    """``path`` can be created if the nearest existing folder above ``start`` is writable."""
    ancestor = _existing_ancestor(start)
    if not ancestor.is_dir():
        raise InputError(name, f"cannot write {what} {str(path)!r}: {str(ancestor)!r} is not a folder")
    if not os.access(ancestor, os.W_OK | os.X_OK):
        raise InputError(name, f"cannot write {what} {str(path)!r}: no write permission in {str(ancestor)!r}")


def writable_file(name: str, path, suffixes) -> Path:
    """Return ``path`` as a Path if a file with one of ``suffixes`` can be written there
    (missing parent folders are created later); raise ``InputError(name, ...)`` otherwise."""
    path = Path(path)
    if path.is_dir():
        raise InputError(name, f"{str(path)!r} is a folder; give a file name, e.g. {str(path / 'out')!r}")
    if path.suffix.lower() not in suffixes:
        known = " or ".join(suffixes)
        raise InputError(name, f"unknown extension {path.suffix or '(none)'!r} in {str(path)!r}; use {known}")
    _check_parent(name, path, path.parent, "file")
    if path.exists() and not os.access(path, os.W_OK):
        raise InputError(name, f"cannot write file {str(path)!r}: no write permission")
    return path


def writable_dir(name: str, path) -> Path:
    """Return ``path`` as a Path if it is (or can be created as) a writable folder; raise
    ``InputError(name, ...)`` otherwise."""
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise InputError(name, f"{str(path)!r} is a file, not a folder")
    _check_parent(name, path, path, "into folder")
    return path
