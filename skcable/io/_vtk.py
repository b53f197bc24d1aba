"""Results as VTK meshes (meshio) for ParaView.

Points are always 3-component (VTK and ParaView need them): a suspended cable lies in
the plane z = 0 with y up; a strand's axis is x, its transverse
displacements are along y and z. Load-stepped results are written as a
ParaView collection (``.pvd``) of ``.vtu`` files, one per step, that
ParaView opens as one time series.

Every array carries its unit in its name (``tension_N``, ``angle_rad``,
``load_N_per_m``); a unit vector has none (``tangent``). Every file is written
atomically (`skcable.io._atomic`): it appears whole or not at all, a missing
parent folder is refused (never created), and a path that cannot be written is
refused with ``InputError("path", ...)`` naming the path as given.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError
from skcable.io._atomic import atomic_path, writable_file

if TYPE_CHECKING:
    import meshio

__all__ = ["cable_mesh", "funicular_mesh", "write", "write_series"]

#: The formats of the writers of one mesh for ParaView.
VTK_SUFFIXES = (".vtu", ".vtk")
#: The most points of a profile (an integer ``n``): beyond, the arrays would not fit in memory.
MAX_POINTS = 10**8


def polyline(points_2d) -> tuple[np.ndarray, list]:
    """3-component points (z = 0) and the line cells joining them in order."""
    points = np.column_stack([points_2d, np.zeros(len(points_2d))])
    segments = np.column_stack([np.arange(len(points) - 1), np.arange(1, len(points))])
    return points, [("line", segments)]


def _vector3(values) -> np.ndarray:
    """Point data as VTK wants it: scalars as they are, 2-D vectors padded with z = 0."""
    values = np.asarray(values, dtype=float)
    if values.ndim == 2 and values.shape[1] == 2:
        return np.column_stack([values, np.zeros(len(values))])
    return values


def cable_mesh(solution, n: int = 201, *, point_data=None) -> meshio.Mesh:
    """Profile of a suspended-cable solution as a polyline of ``n`` points.

    Point data: ``tension_N``, ``tangent`` (unit vector toward B),
    ``angle_rad`` (above the horizontal), ``load_N_per_m`` (per metre of
    unstretched cable, y up: a weight has a negative y component), the cable terms'
    outputs (``samples["outputs"]``: their forces, ``<Term>_force_N_per_m``, and what else
    they name), and the user's ``point_data``: name -> values at the ``n`` points, or a
    callable of the samples dict returning them. Reads only ``solution.samples(n)`` (and
    ``T_A``, to refuse an array of scenes). ``n`` is an integer in ``[2, 10**8]``; anything
    else, and a ``solution`` without ``samples``, raise `InputError` naming it.
    """
    import meshio

    if not (callable(getattr(solution, "samples", None)) and hasattr(solution, "T_A")):
        raise InputError(
            "solution",
            f"must be a cable solution with samples(n) (cable.catenary(...), ...), got {solution!r:.80}",
        )
    if np.ndim(solution.T_A) != 0:
        raise InputError("solution", "write one scene at a time: this solution holds an array of scenes")
    n = whole("n", n, 2, MAX_POINTS)
    samples = solution.samples(n)
    points, cells = polyline(samples["xy"])
    angle = samples["angle"]
    zero = np.zeros_like(angle)
    data = {
        "tension_N": samples["tension"],
        "tangent": np.column_stack([np.cos(angle), np.sin(angle), zero]),
        "angle_rad": angle,
        "load_N_per_m": np.column_stack([samples["load"], zero]),
    }
    extra = dict(samples.get("outputs", {}))
    for name, values in (point_data or {}).items():
        extra[name] = values(samples) if callable(values) else values
    for name, values in extra.items():
        values = _vector3(values)
        if values.shape[:1] != (len(points),):
            raise InputError(
                name, f"point data of shape {values.shape}: give one value per point ({len(points)})"
            )
        data[name] = values
    return meshio.Mesh(points, cells, point_data=data)


def funicular_mesh(solution) -> meshio.Mesh:
    """Funicular polygon: the joints as points, the segments as cells.

    Cell data ``tension_N``; point data ``load_N`` (the joint loads; zero at
    the supports). Reads ``nodes``, ``T`` and ``loads``: load vectors when
    the solution also has segment ``forces`` (`funicular`),
    ``(x, P downward)`` pairs otherwise (`funicular_vertical`).
    """
    import meshio

    points, cells = polyline(solution.nodes)
    loads = np.zeros((len(points), 3))
    joint = np.asarray(solution.loads, dtype=float)
    if hasattr(solution, "forces"):  # funicular(): load vectors (Px, Py), y up
        loads[1:-1, :2] = joint
    else:  # funicular_vertical(): (x, P downward) pairs
        loads[1:-1, 1] = -joint[:, 1]
    return meshio.Mesh(
        points, cells, point_data={"load_N": loads}, cell_data={"tension_N": [np.asarray(solution.T)]}
    )


def _suffixes() -> tuple[str, ...]:
    import meshio

    return tuple(meshio.extension_to_filetypes)


def write_mesh(build, path, suffixes=VTK_SUFFIXES) -> Path:
    """Check ``path`` (a file with one of ``suffixes``), then write the mesh ``build()`` returns
    there, atomically; returns the path.

    Raises
    ------
    InputError
        ``path``: not a path, a folder, an unknown suffix, a missing parent folder (never
        created) or one that takes no new file, named as given.
    """
    import meshio

    path = writable_file("path", path, suffixes, create_parents=False)
    mesh = build()
    with atomic_path(path, create_parents=False) as temp:
        meshio.write(temp, mesh)
    return path


def write(mesh: meshio.Mesh, path) -> Path:
    """Write one mesh (format from the suffix: ``.vtu``, ``.vtk``, ...), atomically; returns
    the path, checked as by `write_mesh`."""
    return write_mesh(lambda: mesh, path, _suffixes())


def write_series(meshes, times, path) -> Path:
    """Write ``meshes`` as ``<stem>_NNNN.vtu`` beside a ParaView collection ``path`` (``.pvd``).

    Each file is written atomically and the collection last, so that it never lists a step
    that is not on disk; the path is checked as by `write`.
    """
    import meshio

    path = writable_file("path", path, (".pvd",), create_parents=False)
    root = ET.Element("VTKFile", type="Collection", version="0.1")
    collection = ET.SubElement(root, "Collection")
    for i, (mesh, time) in enumerate(zip(meshes, times, strict=True)):
        name = f"{path.stem}_{i:04d}.vtu"
        with atomic_path(path.parent / name, create_parents=False) as temp:
            meshio.write(temp, mesh)
        ET.SubElement(collection, "DataSet", timestep=repr(float(time)), part="0", file=name)
    with atomic_path(path, create_parents=False) as temp:
        ET.ElementTree(root).write(temp, xml_declaration=True, encoding="utf-8")
    return path
