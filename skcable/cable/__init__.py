"""Suspended cables in closed form: funicular polygons, parabola, catenary, elastic catenary
(Irvine's, on a flat or sloped seabed with friction: Jonkman's), geometric stiffness, end
conditions, cables on surfaces.

Conventions: x to the right, y up, support A at (0, 0),
support B at (span, dh); distributed loads w > 0 act downward; H > 0 is the
horizontal tension; V_A, V_B are the upward support reactions. SI units by
default (m, N, N/m); any consistent system works.

The other domains build on these: cables as BVPs (`skcable.bvp`), mooring lines and systems
(`skcable.mooring`), overhead conductors (`skcable.conductors`). Their names, which 0.2.0 served
from here, are served from here for one more release with a `DeprecationWarning` naming the new
home (`skcable._moved`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach
from skcable._moved import names_moved_from

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.cable._catenary import Catenary, catenary
    from skcable.cable._elastic import ElasticCatenary
    from skcable.cable._funicular import Funicular, FunicularVertical, funicular, funicular_vertical
    from skcable.cable._parabola import Parabola, parabola
    from skcable.cable._stiffness import fairlead_stiffness, geometric_stiffness, geometric_stiffness_series
    from skcable.cable._supports import SlidingLoad, anchor_block_weight, ring_on_rod, sliding_load
    from skcable.cable._surfaces import capstan, membrane_tension, smooth_surface_reaction, sphere_parallel
    from skcable.cable.seabed import (
        SeabedCatenary,
        SlopedSeabedCatenary,
        elastic_catenary,
        sloped_seabed_catenary,
    )
    from skcable.cable.solution import CableSolution

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    "._catenary": ("Catenary", "catenary"),
    "._elastic": ("ElasticCatenary",),
    "._funicular": ("Funicular", "FunicularVertical", "funicular", "funicular_vertical"),
    "._parabola": ("Parabola", "parabola"),
    "._stiffness": ("fairlead_stiffness", "geometric_stiffness", "geometric_stiffness_series"),
    "._supports": ("SlidingLoad", "anchor_block_weight", "ring_on_rod", "sliding_load"),
    "._surfaces": ("capstan", "membrane_tension", "smooth_surface_reaction", "sphere_parallel"),
    ".seabed": ("SeabedCatenary", "SlopedSeabedCatenary", "elastic_catenary", "sloped_seabed_catenary"),
    ".solution": ("CableSolution",),
}

__getattr__, __dir__ = attach(
    __name__,
    submodules=("arc_samples", "seabed", "solution"),
    names=_NAMES,
    moved=names_moved_from(__name__),
)

__all__ = [
    "CableSolution",
    "Catenary",
    "ElasticCatenary",
    "Funicular",
    "FunicularVertical",
    "Parabola",
    "SeabedCatenary",
    "SlidingLoad",
    "SlopedSeabedCatenary",
    "anchor_block_weight",
    "capstan",
    "catenary",
    "elastic_catenary",
    "fairlead_stiffness",
    "funicular",
    "funicular_vertical",
    "geometric_stiffness",
    "geometric_stiffness_series",
    "membrane_tension",
    "parabola",
    "ring_on_rod",
    "sliding_load",
    "sloped_seabed_catenary",
    "smooth_surface_reaction",
    "sphere_parallel",
]
