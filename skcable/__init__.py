"""skcable: structural cables and metallic strands on scikit-fem.

Subpackages
-----------
cable
    Suspended cables in closed form: funicular polygon, parabola, catenary, elastic
    catenary (on a seabed too), geometric stiffness, end conditions, cables on surfaces.
bvp
    Cables as nonlinear boundary-value problems on scikit-fem, with their terms, and the
    choice of the cheapest model a scene needs.
mooring
    Mooring lines and systems: multi-segment lines, lines in the sea, bodies, MoorDyn files.
conductors
    Overhead-line conductors: change of state, ruling span, frequencies, ratings, fatigue.
strand
    Metallic strands: geometry, damage, sections, materials, the bending law
    and the strand finite element.
fe
    The finite-element core the domains share (it knows no physics).
io, plot, study
    VTK files for ParaView, figures, parameter studies.

The subpackages are imported on first use (PEP 562): ``import skcable`` is light.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable import _moved
from skcable._lazy import attach
from skcable.errors import ConvergenceError, InputError

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable import bvp, cable, conductors, io, mooring, plot, strand, study  # noqa: F401

__all__ = ["bvp", "cable", "conductors", "mooring", "strand", "ConvergenceError", "InputError"]

_getattr, __dir__ = attach(
    __name__, submodules=("bvp", "cable", "conductors", "mooring", "strand", "io", "plot", "study")
)
_moved.install()  # the module paths of 0.2.0 that moved, served for one release


def __getattr__(name: str) -> object:
    if name == "__version__":  # the installed package's metadata (pyproject's version)
        from importlib.metadata import version

        globals()["__version__"] = version("skcable")
        return globals()["__version__"]
    return _getattr(name)
