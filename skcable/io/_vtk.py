"""Results as VTK meshes (meshio) for ParaView.

Points are always 3-component (VTK and ParaView need them): a suspended cable lies in
the plane z = 0 with y up; a strand's axis is x, its transverse
displacements are along y and z. Load-stepped results are written as a
ParaView collection (``.pvd``) of ``.vtu`` files, one per step, that
ParaView opens as one time series.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import meshio
import numpy as np

from skcable.errors import InputError

__all__ = ["cable_mesh", "funicular_mesh", "write", "write_series"]


def _polyline(points_2d) -> tuple[np.ndarray, list]:
    """3-component points (z = 0) and the line cells joining them in order."""
    points = np.column_stack([points_2d, np.zeros(len(points_2d))])
    segments = np.column_stack([np.arange(len(points) - 1), np.arange(1, len(points))])
    return points, [("line", segments)]


def cable_mesh(solution, n: int = 201) -> meshio.Mesh:
    """Profile of a suspended-cable solution as a polyline of ``n`` points.

    Point data: ``tension`` (N), ``tangent`` (unit vector toward B),
    ``angle`` (rad above the horizontal), ``load`` (N per metre of
    unstretched cable, y up: a weight has a negative y component). Reads
    only ``solution.samples(n)`` (and ``H``, to refuse an array of scenes).
    """
    if np.ndim(solution.H) != 0:
        raise InputError("solution", "write one scene at a time: this solution holds an array of scenes")
    if int(n) < 2:
        raise InputError("n", f"must be at least 2, got {n!r}")
    samples = solution.samples(int(n))
    points, cells = _polyline(samples["xy"])
    angle = samples["angle"]
    zero = np.zeros_like(angle)
    point_data = {
        "tension": samples["tension"],
        "tangent": np.column_stack([np.cos(angle), np.sin(angle), zero]),
        "angle": angle,
        "load": np.column_stack([samples["load"], zero]),
    }
    return meshio.Mesh(points, cells, point_data=point_data)


def funicular_mesh(solution) -> meshio.Mesh:
    """Funicular polygon: the joints as points, the segments as cells.

    Cell data ``tension`` (N); point data ``load`` (N, the joint loads; zero
    at the supports). Reads ``nodes``, ``T`` and ``loads``: load vectors when
    the solution also has segment ``forces`` (`funicular`),
    ``(x, P downward)`` pairs otherwise (`funicular_vertical`).
    """
    points, cells = _polyline(solution.nodes)
    loads = np.zeros((len(points), 3))
    joint = np.asarray(solution.loads, dtype=float)
    if hasattr(solution, "forces"):  # funicular(): load vectors (Px, Py), y up
        loads[1:-1, :2] = joint
    else:  # funicular_vertical(): (x, P downward) pairs
        loads[1:-1, 1] = -joint[:, 1]
    return meshio.Mesh(
        points, cells, point_data={"load": loads}, cell_data={"tension": [np.asarray(solution.T)]}
    )


def write(mesh: meshio.Mesh, path) -> Path:
    """Write one mesh (format from the suffix: ``.vtu``, ``.vtk``, ...); returns the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    meshio.write(path, mesh)
    return path


def write_series(meshes, times, path) -> Path:
    """Write ``meshes`` as ``<stem>_NNNN.vtu`` beside a ParaView collection ``path`` (``.pvd``)."""
    path = Path(path)
    if path.suffix != ".pvd":
        raise InputError("path", f"a time series is written as a .pvd collection, got {path.name!r}")
    path.parent.mkdir(parents=True, exist_ok=True)
    root = ET.Element("VTKFile", type="Collection", version="0.1")
    collection = ET.SubElement(root, "Collection")
    for i, (mesh, time) in enumerate(zip(meshes, times, strict=True)):
        name = f"{path.stem}_{i:04d}.vtu"
        meshio.write(path.parent / name, mesh)
        ET.SubElement(collection, "DataSet", timestep=repr(float(time)), part="0", file=name)
    ET.ElementTree(root).write(path, xml_declaration=True, encoding="utf-8")
    return path
