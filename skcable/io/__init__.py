"""Input and output shared by cables and strands: VTK meshes for ParaView (meshio).

Writers consume results only: this package imports no model.
"""

from skcable.io._modes import mode_shape_mesh, write_mode_shapes
from skcable.io._strand import strand_mesh, wire_mesh
from skcable.io._vtk import cable_mesh, funicular_mesh, write, write_series

__all__ = ["cable_mesh", "funicular_mesh", "strand_mesh", "wire_mesh", "write", "write_series"]
__all__ += ["mode_shape_mesh", "write_mode_shapes"]

# moored bodies: lines, seabed patch and body
from skcable.io._mooring import mooring_mesh, write_mooring  # noqa: E402

__all__ += ["mooring_mesh", "write_mooring"]
