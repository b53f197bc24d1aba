"""A mooring system at equilibrium as one VTK mesh (meshio) for ParaView.

Global axes, z up, metres. Cells: each line as a polyline (``line`` cells), the seabed patch (one
``quad`` at z = -depth under every point, when the result has a ``depth``), each rigid body as a
``hexahedron`` (the box of its points in body axes, turned and moved with it), each point body and
each free point as a ``vertex``. Point data: ``tension_N`` (zero off the lines). Cell data:
``part`` (0 line, 1 seabed, 2 body, 3 free point) and ``line`` (the line's number in the system,
-1 off the lines); the bodies follow the seabed in the order of the system's bodies. Files are
written atomically; a missing parent folder is refused, never created. Reads only the result's ``lines``
(``profile_with_tension(n)``), ``line_indices``, ``bodies`` (``offset``, ``rotation``,
``local_points``, ``position``), ``points`` (``position``, ``kind``) and ``depth``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError
from skcable.io._vtk import write_mesh

if TYPE_CHECKING:
    import meshio

__all__ = ["lines_mesh", "mooring_mesh", "write_lines", "write_mooring"]

# VTK's hexahedron: the bottom face counter-clockwise, then the top face
_BOX = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])


def _body_box(state) -> np.ndarray:
    """The 8 corners (global axes) of the box of a body's points in body axes, each side at least a
    tenth of the largest (and 1 m)."""
    R, x0 = np.asarray(state.rotation), np.asarray(state.offset)
    local = np.asarray(state.local_points, dtype=float).reshape(-1, 3)
    if not len(local):
        local = np.zeros((1, 3))
    low, high = local.min(axis=0), local.max(axis=0)
    side = max(1.0, 0.1 * float((high - low).max()))
    centre, half = 0.5 * (low + high), np.maximum(0.5 * (high - low), 0.5 * side)
    corners = centre - half + _BOX * (2.0 * half)
    return x0 + corners @ R.T


def _polylines(lines, n):
    """Points, tension, segment cells and line numbers of lines with ``profile(n)``."""
    n = whole("n", n, 2)
    profiles = [line.profile_with_tension(n) for line in lines]
    if not profiles:
        raise InputError("lines", "holds no line")
    sizes = [len(xyz) for xyz, _ in profiles]
    start = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    segments = np.concatenate(
        [
            np.column_stack([k + np.arange(m - 1), k + np.arange(1, m)])
            for k, m in zip(start, sizes, strict=True)
        ]
    )
    line_id = np.concatenate([np.full(m - 1, i) for i, m in enumerate(sizes)])
    points = np.vstack([xyz for xyz, _ in profiles])
    tension = np.concatenate([np.asarray(T, dtype=float) for _, T in profiles])
    return [points], [tension], segments, line_id


def lines_mesh(lines, n: int = 101) -> meshio.Mesh:
    """Lines in 3-D (e.g. `skcable.mooring.Line3D`, anything with ``profile(n)`` giving
    ``(points (m, 3), tension (m,))``) as polylines: point data ``tension_N``, cell data
    ``line`` (the line's number)."""
    import meshio

    points, tension, segments, line_id = _polylines(lines, n)
    if not (np.isfinite(points[0]).all() and np.isfinite(tension[0]).all()):
        raise InputError("lines", "hold non-finite coordinates or tensions")
    return meshio.Mesh(
        points[0], [("line", segments)], point_data={"tension_N": tension[0]}, cell_data={"line": [line_id]}
    )


def write_lines(lines, path, n: int = 101) -> Path:
    """Write `lines_mesh` of ``lines`` to ``path`` as `write_mooring` writes its mesh."""
    return write_mesh(lambda: lines_mesh(lines, n), path)


class _Cells:
    """The mesh being gathered: point blocks, their tensions, cell blocks and their data."""

    def __init__(self, points, tension, segments, line_id):
        self.points, self.tension, self.count = list(points), list(tension), len(points[0])
        self.cells, self.part, self.line, self.body = (
            [("line", segments)],
            [np.zeros(len(segments), int)],
            [line_id],
            [np.full(len(segments), -1)],
        )

    def add(self, kind, xyz, part):
        xyz = np.asarray(xyz, dtype=float).reshape(-1, 3)
        cells = self.count + np.arange(len(xyz))
        self.cells.append((kind, cells[None, :] if kind != "vertex" else cells[:, None]))
        self.points.append(xyz)
        self.tension.append(np.zeros(len(xyz)))
        ncell = len(self.cells[-1][1])
        self.part.append(np.full(ncell, part))
        self.line.append(np.full(ncell, -1))
        self.count += len(xyz)


def mooring_mesh(result, n: int = 101) -> meshio.Mesh:
    """Lines (``n`` points each, >= 2), seabed patch, bodies and free points of a solved
    `MooringEquilibrium` (module docstring)."""
    import meshio

    points, tension, segments, line_id = _polylines(result.lines, n)
    indices = np.asarray(getattr(result, "line_indices", range(len(result.lines))))
    mesh = _Cells(points, tension, segments, indices[line_id])
    everything = np.array([p.position for p in result.points]).reshape(-1, 3)
    if getattr(result, "depth", None) is not None and len(everything):
        low, high = everything[:, :2].min(axis=0), everything[:, :2].max(axis=0)
        margin = 0.1 * max(float((high - low).max()), 1.0)
        low, high = low - margin, high + margin
        z = -float(result.depth)
        mesh.add(
            "quad",
            [[low[0], low[1], z], [high[0], low[1], z], [high[0], high[1], z], [low[0], high[1], z]],
            1,
        )
    for state in result.bodies:
        if len(state.position) == 6:
            mesh.add("hexahedron", _body_box(state), 2)
        else:
            mesh.add("vertex", state.offset, 2)
    free = [p.position for p in result.points if p.kind == "free"]
    if free:
        mesh.add("vertex", free, 3)
    xyz = np.vstack(mesh.points)
    if not np.isfinite(xyz).all():
        raise InputError("result", "holds non-finite coordinates")
    cell_data = {"part": mesh.part, "line": mesh.line}
    return meshio.Mesh(
        xyz, mesh.cells, point_data={"tension_N": np.concatenate(mesh.tension)}, cell_data=cell_data
    )


def write_mooring(result, path, n: int = 101) -> Path:
    """Write `mooring_mesh` of ``result`` to ``path`` (``.vtu`` or ``.vtk``), atomically, the path
    checked before the mesh is built (`skcable.io._vtk.write_mesh`); returns the path."""
    return write_mesh(lambda: mooring_mesh(result, n), path)
