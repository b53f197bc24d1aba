"""Files written whole or not at all, and output paths checked before any computing.

`atomic_path` hands a writer a temporary path in the target's directory
(same file system, same suffix, so writers that pick a format from the suffix
still work) and moves the finished file onto the target with `os.replace`:
a reader, a concurrent writer or a kill never leaves a torn or empty target, and
the last writer wins with a complete file. `writable_file` and
`writable_dir` refuse, with `skcable.InputError` naming the path as the user
gave it, a path that cannot be written (a directory where a file is meant, a file
where a folder is meant, an unknown extension, a parent that is not a folder or
does not take new files, which they find by creating and removing a probe file:
permissions alone do not tell for root, a read-only mount or ``/proc``). With
``create_parents=False`` (the writers of `skcable.io` and the command line) a missing
parent folder is refused, and never created.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import tempfile
from pathlib import Path

from skcable.errors import InputError

__all__ = ["TEMP_GLOB", "atomic_path", "create_text", "writable_dir", "writable_file", "write_text"]

#: Glob of the temporary files `atomic_path` creates (left behind only by a kill).
TEMP_GLOB = ".*.tmp*"


@contextlib.contextmanager
def atomic_path(path, *, create_parents: bool = True):
    """Context manager: yields a temporary path beside ``path``; on a clean exit the file
    written there is flushed to disk and moved onto ``path``; on an exception it is removed
    and ``path`` is left as it was.

    Missing parent folders are created, unless ``create_parents`` is false: then they are
    refused with ``InputError("path", ...)``. An `OSError` while writing names ``path``
    (as given), never the temporary file.
    """
    path = Path(path)
    if create_parents:
        path.parent.mkdir(parents=True, exist_ok=True)
    elif not path.parent.is_dir():
        raise InputError("path", _missing(path, path.parent))
    temp = path.with_name(f".{path.stem}.{secrets.token_hex(6)}.tmp{path.suffix}")
    try:
        yield temp
        with open(temp, "rb+") as handle:  # a writer may close without syncing
            os.fsync(handle.fileno())
        os.replace(temp, path)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            temp.unlink()
        if isinstance(exc, OSError) and exc.filename != str(path):
            raise OSError(exc.errno, f"cannot write {str(path)!r}: {exc.strerror}") from exc
        raise
    _sync_dir(path.parent)


def write_text(path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically; returns the path."""
    path = Path(path)
    with atomic_path(path) as temp:
        create_text(temp, text)  # the random name is ours alone
    return path


def create_text(path, text: str) -> None:
    """Create the file ``path`` holding ``text`` (UTF-8); `FileExistsError` if it exists (O_EXCL).
    The umask sets the permissions, as for ``open()``."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    with os.fdopen(fd, "w", encoding="utf-8") as handle:
        handle.write(text)


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


def _as_path(name: str, path) -> Path:
    if not isinstance(path, (str, os.PathLike)):
        raise InputError(name, f"must be a path (str or os.PathLike), got {path!r}")
    return Path(path)


def _missing(path: Path, folder: Path) -> str:
    return f"cannot write {str(path)!r}: the folder {str(folder)!r} does not exist (create it first)"


def _probe(folder: Path) -> str | None:
    """Why ``folder`` takes no new file (None when it does): a probe file is created and removed."""
    try:
        fd, name = tempfile.mkstemp(prefix=".skcable-probe-", dir=folder)
    except OSError as exc:
        return exc.strerror or type(exc).__name__
    os.close(fd)
    with contextlib.suppress(OSError):
        os.unlink(name)
    return None


def _check_folder(name: str, path: Path, folder: Path, what: str, create_parents: bool) -> None:
    """A file or folder ``path`` can be created in ``folder``: it exists (or, with
    ``create_parents``, its nearest existing ancestor does), is a folder and takes new files."""
    where = _existing_ancestor(folder) if create_parents else Path(folder)
    if not where.exists():
        raise InputError(name, _missing(path, folder))
    if not where.is_dir():
        raise InputError(name, f"cannot write {what} {str(path)!r}: {str(where)!r} is not a folder")
    reason = _probe(where)
    if reason is not None:
        raise InputError(
            name, f"cannot write {what} {str(path)!r}: {str(where)!r} takes no new file ({reason})"
        )


def writable_file(name: str, path, suffixes, *, create_parents: bool = True) -> Path:
    """Return ``path`` as a Path if a file with one of ``suffixes`` can be written there;
    raise ``InputError(name, ...)`` naming ``path`` otherwise. Missing parent folders are
    created later, or refused here with ``create_parents=False``."""
    path = _as_path(name, path)
    if path.is_dir():
        raise InputError(name, f"{str(path)!r} is a folder; give a file name, e.g. {str(path / 'out')!r}")
    if path.suffix.lower() not in suffixes:
        known = " or ".join(suffixes)
        raise InputError(name, f"unknown extension {path.suffix or '(none)'!r} in {str(path)!r}; use {known}")
    _check_folder(name, path, path.parent, "file", create_parents)
    if path.exists() and not os.access(path, os.W_OK):
        raise InputError(name, f"cannot write file {str(path)!r}: no write permission")
    return path


def writable_dir(name: str, path, *, create_parents: bool = True) -> Path:
    """Return ``path`` as a Path if it is (or can be created as) a writable folder; raise
    ``InputError(name, ...)`` naming ``path`` otherwise. With ``create_parents=False`` the
    folder itself may be missing, its parent may not."""
    path = _as_path(name, path)
    if path.exists() and not path.is_dir():
        raise InputError(name, f"{str(path)!r} is a file, not a folder")
    folder = path if path.is_dir() else path.parent
    _check_folder(name, path, folder, "into folder", create_parents)
    return path
