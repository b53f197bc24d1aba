"""Input and output shared by cables and strands: VTK meshes for ParaView (meshio)."""

from skcable.io._vtk import cable_mesh, funicular_mesh, strand_mesh, wire_mesh, write, write_series

__all__ = ["cable_mesh", "funicular_mesh", "strand_mesh", "wire_mesh", "write", "write_series"]
