"""The fingerprint of the code that computes a case, so that a cache never returns another code's numbers.

A study cache entry records the fingerprint of the code that made it; an entry whose
fingerprint is not this process's is recomputed (with a `skcable.errors.CacheWarning`).
The fingerprint is the SHA-256 of

- every file of the installed ``skcable`` package (its relative path and its bytes;
  ``__pycache__`` and hidden files left out), so that any edit of the numerics, however
  small, changes it while the version number stays;
- the versions of Python, NumPy, SciPy and scikit-fem, whose numerics skcable rests on;
- for a model function defined outside skcable (a user's), the source text of that
  function, when Python can read it (`inspect.getsource`). A change in a helper it
  calls from another module is not seen: bump such a model's name, or clear the cache.

The package's part is computed once per process (about 2 ms for its files and 20 ms for the
versions) and reused.

Examples
--------
>>> fingerprint = package_fingerprint()
>>> len(fingerprint), fingerprint == package_fingerprint()
(64, True)
"""

from __future__ import annotations

import functools
import hashlib
import inspect
import platform
from collections.abc import Callable
from pathlib import Path

__all__ = ["code_fingerprint", "package_fingerprint", "tree_fingerprint"]

#: The libraries whose versions enter the fingerprint (distribution names).
DEPENDENCIES = ("numpy", "scipy", "scikit-fem")


def tree_fingerprint(root) -> str:
    """SHA-256 (64 hexadecimal digits) of the files under the folder ``root``: relative paths and
    contents, in sorted order (``__pycache__`` folders, ``.pyc`` files and hidden files and
    folders are left out: they are made from the sources or are not part of them).
    """
    root = Path(root)
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*")):
        relative = path.relative_to(root)
        hidden = any(part.startswith(".") or part == "__pycache__" for part in relative.parts)
        if hidden or path.suffix in (".pyc", ".pyo") or not path.is_file():
            continue
        data = path.read_bytes()
        digest.update(f"{relative.as_posix()}\0{len(data)}\0".encode())
        digest.update(data)
    return digest.hexdigest()


def _versions() -> str:
    from importlib.metadata import PackageNotFoundError, version

    found = [f"python {platform.python_implementation()} {platform.python_version()}"]
    for name in DEPENDENCIES:
        try:
            found.append(f"{name} {version(name)}")
        except PackageNotFoundError:
            found.append(f"{name} absent")
    return "; ".join(found)


@functools.cache
def package_fingerprint() -> str:
    """The fingerprint of skcable's own code and of the libraries under its numerics (64
    hexadecimal digits, computed on the first call and reused by the process).
    """
    import skcable

    text = f"{tree_fingerprint(Path(skcable.__file__).parent)}\0{_versions()}"
    return hashlib.sha256(text.encode()).hexdigest()


def code_fingerprint(model: Callable) -> str:
    """The fingerprint of the code that computes a case of ``model``: `package_fingerprint`,
    combined with the source of ``model`` when it is defined outside skcable and its source can
    be read (64 hexadecimal digits).
    """
    fingerprint = package_fingerprint()
    module = str(getattr(model, "__module__", "") or "")
    if module == "skcable" or module.startswith("skcable."):
        return fingerprint
    try:
        source = inspect.getsource(model)
    except (OSError, TypeError):  # built-in, partial, defined at a prompt: the package's part only
        return fingerprint
    return hashlib.sha256(f"{fingerprint}\0{source}".encode()).hexdigest()
