"""skcable: structural cables and metallic strands on scikit-fem.

Subpackages
-----------
cable
    Suspended cables: closed forms (funicular polygon, parabola, catenary,
    elastic catenary), geometric stiffness, end conditions, cables on
    surfaces, cable BVPs, mooring lines and overhead conductors.
strand
    Metallic strands: geometry, damage, sections, materials, the bending law
    and the strand finite element.
io
    Results to VTK files for ParaView.

The subpackages are imported on first use (PEP 562): ``import skcable`` is light.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach
from skcable.errors import ConvergenceError, InputError

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable import cable, io, plot, strand, study  # noqa: F401

__all__ = ["cable", "strand", "ConvergenceError", "InputError"]

_getattr, __dir__ = attach(__name__, submodules=("cable", "strand", "io", "plot", "study"))


def __getattr__(name: str) -> object:
    if name == "__version__":  # the installed package's metadata (pyproject's version)
        from importlib.metadata import version

        globals()["__version__"] = version("skcable")
        return globals()["__version__"]
    return _getattr(name)
