"""What moved in 0.3.0, one package per domain: the one table of moves, served for one release.

0.2.0 held three domains inside `skcable.cable`; 0.3.0 gives each its package
(`skcable.bvp`, `skcable.mooring`, `skcable.conductors`), and names its mooring modules by what
they hold (the 0.3.0 development paths ``skcable.mooring.<old>`` are served as well). Two tables
say where things went:

- `MODULES`: an old module path and its new one. Importing the old path (or any module below
  it) gives a stand-in that serves the new module's names, with a `DeprecationWarning` naming the
  new path. The stand-in is not the new module, so nothing imported through it lands in the new
  module's namespace.
- `NAMES`: public names of a 0.2.0 package that now live in another package, served from the
  old package with a `DeprecationWarning` naming the new path.

CHANGELOG.md carries the same moves as a migration table; `tests/test_moved.py` checks each.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import types
import warnings
from collections.abc import Sequence

__all__ = ["MODULES", "NAMES", "install", "names_moved_from", "serve"]

#: old module path -> new module path (a longer old path wins over its prefix)
MODULES = {
    "skcable.cable.bvp.line3d": "skcable.mooring.line_bvp.space",
    "skcable.cable.bvp.line": "skcable.mooring.line_bvp",
    "skcable.cable.bvp.solve": "skcable.bvp.formulation",
    "skcable.cable.bvp": "skcable.bvp",
    "skcable.cable._choice": "skcable.bvp.choice",
    "skcable.cable._loads": "skcable.bvp.loads",
    "skcable.cable.terms": "skcable.bvp.terms",
    "skcable.cable.current": "skcable.bvp.current",
    "skcable.cable.lines.seabed.closure": "skcable.cable.closure",
    "skcable.cable.lines.seabed": "skcable.cable.seabed",
    "skcable.cable.lines.segments.closure": "skcable.mooring.segments.state",
    "skcable.cable.lines.arc_samples": "skcable.cable.arc_samples",
    "skcable.cable.lines.in_sea": "skcable.mooring.sea_line",
    "skcable.mooring.in_sea": "skcable.mooring.sea_line",
    "skcable.cable.lines.between": "skcable.mooring.between_points",
    "skcable.mooring.between": "skcable.mooring.between_points",
    "skcable.cable.lines.plane": "skcable.mooring.plane_line",
    "skcable.mooring.plane": "skcable.mooring.plane_line",
    "skcable.cable.lines.lying": "skcable.mooring.line_on_seabed",
    "skcable.mooring.lying": "skcable.mooring.line_on_seabed",
    "skcable.cable.lines.assembly": "skcable.mooring.net_loads",
    "skcable.mooring.assembly": "skcable.mooring.net_loads",
    "skcable.cable.lines.geometry": "skcable.mooring.choice",
    "skcable.mooring.geometry": "skcable.mooring.choice",
    "skcable.cable.lines": "skcable.mooring",
    "skcable.cable.axial": "skcable.mooring.axial",
    "skcable.cable.bathymetry": "skcable.mooring.bathymetry",
    "skcable.cable.conductors": "skcable.conductors",
    "skcable.cable._conductor": "skcable.conductors._conductor",
    "skcable.cable._spans": "skcable.conductors._spans",
    "skcable.cable._state": "skcable.conductors._state",
    "skcable.cable._frequencies": "skcable.conductors._frequencies",
}

_LINE_BVP = ("BVPSegment", "LineBVP", "LineBVPSolution", "solve_line_bvp")
_LINE_BVP_3D = ("LineBVP3D", "LineBVP3DSolution", "LineSegment", "solve_line_bvp_3d")
_BETWEEN = ("BATCH", "line_between", "solve_between", "solve_many_between")
_LINES = ("skcable.cable.lines", "skcable.mooring")
_IN_SEA: dict[str, Sequence[str]] = {
    "skcable.mooring.choice": ("solve_line_in_sea",),
    "skcable.mooring.slope": ("SlopeModel", "SlopeSolution"),
}
_SEABED = ("SeabedCatenary", "SlopedSeabedCatenary", "elastic_catenary", "sloped_seabed_catenary")

#: old package -> {new package: the names of the old package that live there now}
NAMES: dict[str, dict[str, Sequence[str]]] = {
    "skcable.cable": {
        "skcable.bvp": (
            "ArcSolution",
            "BVPSolution",
            "Buoyancy",
            "CableForce",
            "CableState",
            "CableTerm",
            "CurrentDrag",
            "DeckLoad",
            "DistributedLoad",
            "PointLoad",
            "SelfWeight",
            "WindDrag",
            "solve",
            "solve_bvp",
        ),
        "skcable.mooring": (
            *_LINE_BVP,
            "Buoy",
            "ClumpWeight",
            "Component",
            "LawLineSolution",
            "Line",
            "Line3D",
            "LineBetween",
            "LineInSea",
            "LineSolution",
            "ModelChoice",
            "MoorDynModel",
            "MooringEquilibrium",
            "MooringLine",
            "MooringPoint",
            "MooringSystem",
            "PlaneLine",
            "PointBody",
            "RigidBody",
            "Segment",
            "component",
            "components",
            "design_line",
            "design_pattern",
            "line_3d",
            "line_between",
            "line_in_plane",
            "read_moordyn",
            "register_component",
            "rotation_matrix",
            "write_moordyn",
        ),
        "skcable.conductors": (
            "ChangeOfState",
            "ClampStress",
            "ComponentCurve",
            "Conductor",
            "CreepLaw",
            "NaturalFrequencies",
            "ResidualStrength",
            "StressStrainModel",
            "TensionSection",
            "ThermalCatenary",
            "ThermalRating",
            "WohlerCurve",
            "change_of_state",
            "clamp_stress",
            "clearance_ampacity",
            "fatigue_life",
            "irvine_frequencies",
            "level_span_states",
            "miner_damage",
            "natural_frequencies",
            "poffenberger_swart",
            "residual_strength",
            "ruling_span",
            "sag_at_current",
            "sag_tension_table",
            "tension_section",
            "thermal_catenary",
        ),
    },
    "skcable.cable.bvp": {"skcable.mooring": (*_LINE_BVP, *_LINE_BVP_3D)},
    # the functions that choose a line's model left the modules of its results for `choice`
    **{f"{package}.between": {"skcable.mooring.choice": _BETWEEN} for package in _LINES},
    **{f"{package}.in_sea": _IN_SEA for package in _LINES},
    "skcable.cable.lines": {"skcable.cable": _SEABED},
}


def names_moved_from(package: str) -> dict[str, str]:
    """``{old name: new dotted path}`` for the names that left ``package``."""
    return {name: f"{new}.{name}" for new, names in NAMES.get(package, {}).items() for name in names}


def _deprecated(old: str, new: str, stacklevel: int = 3) -> None:
    warnings.warn(
        f"{old} is deprecated: use {new} (the old name goes in the next release)",
        DeprecationWarning,
        stacklevel=stacklevel,
    )


def serve(old: str, new: str) -> object:
    """The object at the dotted path ``new``, served under its old name ``old`` with a
    `DeprecationWarning` pointed at the caller of the module ``__getattr__`` that asks."""
    _deprecated(old, new, stacklevel=4)
    path, _, attribute = new.rpartition(".")
    return getattr(importlib.import_module(path), attribute)


def new_module_of(old: str) -> str | None:
    """The new path of the old module ``old`` (or of the module below a moved one), or None."""
    for prefix in sorted(MODULES, key=len, reverse=True):
        if old == prefix or old.startswith(prefix + "."):
            return MODULES[prefix] + old[len(prefix) :]
    return None


def _stand_in(old: str, new: types.ModuleType) -> types.ModuleType:
    """A module named ``old`` that serves ``new``'s names (and the names that left ``old``)."""
    stand_in = types.ModuleType(old, new.__doc__)
    moved = names_moved_from(old)

    def __getattr__(name: str) -> object:
        if name in moved:
            return serve(f"{old}.{name}", moved[name])
        return getattr(new, name)

    stand_in.__getattr__ = __getattr__  # type: ignore[method-assign]  # PEP 562 on a module object
    stand_in.__dir__ = lambda: sorted(set(dir(new)) | set(moved))  # type: ignore[method-assign]
    if hasattr(new, "__path__"):  # a package: its submodules are found below the old name too
        stand_in.__path__ = list(new.__path__)
    return stand_in


class _OldPaths(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds the old module paths of `MODULES` and loads their stand-ins."""

    def find_spec(self, fullname, path=None, target=None):
        new = new_module_of(fullname)
        if new is None:
            return None
        return importlib.machinery.ModuleSpec(fullname, self, is_package=True)

    def create_module(self, spec):
        new = new_module_of(spec.name)
        assert new is not None  # find_spec returned this spec for a moved name only
        _deprecated(spec.name, new)
        return _stand_in(spec.name, importlib.import_module(new))

    def exec_module(self, module) -> None:
        """Nothing to run: the stand-in serves a module that is already loaded."""


def install() -> None:
    """Put the finder of the old paths first on ``sys.meta_path`` (once)."""
    if not any(isinstance(finder, _OldPaths) for finder in sys.meta_path):
        sys.meta_path.insert(0, _OldPaths())
