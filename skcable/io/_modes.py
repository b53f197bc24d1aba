"""Mode shapes of a vibrating cable as a VTK mesh for ParaView.

The cable's static profile is a polyline in the plane z = 0 (y up, x along
the span, as the other cable meshes of `skcable.io`); every mode is a point
data *vector*: an in-plane mode moves the points along y, an out-of-plane
mode along z. In ParaView, Warp By Vector on one of them (with a scale
factor: the shapes are mass-normalised, ``φᵀMφ = 1``, in m/√kg) shows the
mode, and animating the scale factor between ±s animates it. The arrays carry
their unit in their names (``in_plane_1_m_per_sqrt_kg``).

This module reads a result (`skcable.conductors.NaturalFrequencies` or any object
with the same attributes) and imports no model.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from skcable.errors import InputError
from skcable.io._vtk import polyline, write_mesh

if TYPE_CHECKING:
    import meshio

__all__ = ["mode_shape_mesh", "write_mode_shapes"]

#: The unit of the mass-normalised shapes (φᵀMφ = 1), at the end of every array's name.
UNIT = "_m_per_sqrt_kg"


def mode_shape_mesh(result) -> meshio.Mesh:
    """Static profile and mode shapes of a natural-frequency result as a polyline (module docstring).

    Reads ``x``, ``y`` (static profile, m), ``modes_in_plane`` and ``modes_out_of_plane``
    ((n_modes, n_points) each). Points ``(x, y, 0)``, line cells joining them in order; point
    data ``in_plane_<k>_m_per_sqrt_kg`` = ``(0, φ_k, 0)`` and ``out_of_plane_<k>_m_per_sqrt_kg``
    = ``(0, 0, φ_k)`` for k = 1..n_modes, mode k of each family the k-th frequency of
    ``f_in_plane``, ``f_out_of_plane`` (not stored: meshio writes no field data to VTU/VTK files).

    Raises
    ------
    InputError
        ``result`` lacks one of those attributes, or their shapes disagree, or a value is not
        finite.
    """
    import meshio

    try:
        x, y = np.asarray(result.x, dtype=float), np.asarray(result.y, dtype=float)
        fields = {
            "in_plane": (np.asarray(result.modes_in_plane, dtype=float), 1),
            "out_of_plane": (np.asarray(result.modes_out_of_plane, dtype=float), 2),
        }
    except AttributeError as exc:
        raise InputError("result", f"must be a natural_frequencies() result ({exc})") from None
    if x.ndim != 1 or x.size < 2 or y.shape != x.shape:
        raise InputError("result", f"x and y must be 1-D of the same size >= 2, got {x.shape}, {y.shape}")
    points, cells = polyline(np.column_stack([x, y]))
    point_data = {}
    for name, (shapes, component) in fields.items():
        if shapes.ndim != 2 or shapes.shape[1] != x.size:
            raise InputError("result", f"modes_{name} has shape {shapes.shape} for {x.size} points")
        for k, shape in enumerate(shapes, start=1):
            vector = np.zeros((x.size, 3))
            vector[:, component] = shape
            point_data[f"{name}_{k}{UNIT}"] = vector
    for name, value in [("points", points), *point_data.items()]:
        if not np.all(np.isfinite(value)):
            raise InputError("result", f"{name} holds a value that is not finite")
    return meshio.Mesh(points, cells, point_data=point_data)


def write_mode_shapes(result, path) -> Path:
    """Write `mode_shape_mesh` of ``result`` to ``path`` (``.vtu`` or ``.vtk``), atomically
    (`skcable.io._vtk.write_mesh`: the path checked before the mesh is built); returns the path."""
    return write_mesh(lambda: mode_shape_mesh(result), path)
