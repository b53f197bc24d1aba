"""Input and output shared by cables and strands: VTK meshes for ParaView (meshio).

Writers consume results only: this package imports no model.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skcable._lazy import attach

if TYPE_CHECKING:  # what static tools see; at run time, `attach` below serves them
    from skcable.io._modes import mode_shape_mesh, write_mode_shapes
    from skcable.io._mooring import lines_mesh, mooring_mesh, write_lines, write_mooring
    from skcable.io._strand import strand_mesh, wire_mesh
    from skcable.io._vtk import cable_mesh, funicular_mesh, write, write_series

#: Where each public name lives (imported on first use, PEP 562).
_NAMES = {
    "._modes": ("mode_shape_mesh", "write_mode_shapes"),
    "._mooring": ("lines_mesh", "mooring_mesh", "write_lines", "write_mooring"),
    "._strand": ("strand_mesh", "wire_mesh"),
    "._vtk": ("cable_mesh", "funicular_mesh", "write", "write_series"),
}

__getattr__, __dir__ = attach(__name__, submodules=(), names=_NAMES)

__all__ = [
    "cable_mesh",
    "funicular_mesh",
    "lines_mesh",
    "mode_shape_mesh",
    "mooring_mesh",
    "strand_mesh",
    "wire_mesh",
    "write",
    "write_lines",
    "write_mode_shapes",
    "write_mooring",
    "write_series",
]
