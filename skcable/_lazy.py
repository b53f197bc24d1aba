"""Lazy public names of a package (PEP 562, "Module __getattr__ and __dir__", 2017).

A package's ``__init__`` lists its submodules and where each public name lives;
`attach` returns the module-level ``__getattr__`` and ``__dir__`` that import the
defining module on first access and keep the name in the package's namespace (the
second access is a plain lookup). ``import skcable`` therefore loads none of pandas,
scipy.optimize, scikit-fem, meshio, pyvista or matplotlib until a name that needs them
is used. Names that moved are still served, with a `DeprecationWarning` naming their
new home. The same design as ``lazy_loader.attach`` (Scientific Python SPEC 1), plus the
deprecations.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Iterable, Mapping

from skcable._moved import serve

__all__ = ["attach"]


def attach(
    package: str,
    submodules: Iterable[str] = (),
    names: Mapping[str, Iterable[str]] | None = None,
    moved: Mapping[str, str] | None = None,
) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for ``package``.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    submodules : iterable of str
        Submodules served as attributes (``skcable.cable``).
    names : mapping of str to iterable of str
        Module (relative to ``package`` when it starts with a dot) -> the public names
        it defines, as the import statements they replace would list them.
    moved : mapping of str to str, optional
        Old public name -> its new dotted path ``module.name``; served with a
        `DeprecationWarning` that names the new path, and not listed by ``__dir__``.
    """
    where = {name: f".{name}" for name in submodules}
    for module, listed in (names or {}).items():
        where |= dict.fromkeys(listed, module)
    moved = dict(moved or {})
    modules = set(submodules)

    def __getattr__(name: str) -> object:
        if name in where:
            module = importlib.import_module(where[name], package)
            value = module if name in modules else getattr(module, name)
            setattr(sys.modules[package], name, value)
            return value
        if name in moved:
            return serve(f"{package}.{name}", moved[name])
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(where))

    return __getattr__, __dir__
