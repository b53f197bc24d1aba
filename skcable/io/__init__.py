"""Input and output shared by cables and strands: VTK meshes for ParaView (meshio).

Writers consume results only: this package imports no model.
"""

from skcable.io._modes import mode_shape_mesh, write_mode_shapes
from skcable.io._mooring import lines_mesh, mooring_mesh, write_lines, write_mooring
from skcable.io._strand import strand_mesh, wire_mesh
from skcable.io._vtk import cable_mesh, funicular_mesh, write, write_series

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
