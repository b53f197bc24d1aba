"""A moored body at equilibrium as one VTK mesh (meshio) for ParaView.

Global axes, z up, metres. Cells: each line as a polyline (``line`` cells), the
seabed patch (one ``quad`` at z = -depth, under the anchors and the body, when the
result has a ``depth``) and the body (a ``hexahedron``: the box of its fairleads in
body axes, turned and moved with it; a ``vertex`` for a point body). Point data:
``tension_N`` (zero off the lines); cell data: ``part`` (0 line, 1 seabed, 2 body)
and ``line`` (the line's number, -1 off the lines). Files are written atomically; a
missing parent folder is refused, never created. Reads only the result's
``lines`` (``profile(n)``), ``anchors``, ``fairleads``, ``offset``, ``rotation``,
``depth`` and ``position``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError
from skcable.io._atomic import atomic_path, writable_file

if TYPE_CHECKING:
    import meshio

__all__ = ["lines_mesh", "mooring_mesh", "write_lines", "write_mooring"]

_SUFFIXES = (".vtu", ".vtk")
# VTK's hexahedron: the bottom face counter-clockwise, then the top face
_BOX = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])


def _body_box(result) -> np.ndarray:
    """The 8 corners (global axes) of the box of the fairleads in body axes, each side at
    least a tenth of the largest (and 1 m)."""
    R, x0 = np.asarray(result.rotation), np.asarray(result.offset)
    local = (np.asarray(result.fairleads) - x0) @ R  # R^T (b - x0), row-wise
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
    """Lines in 3-D (e.g. `skcable.cable.Line3D`, anything with ``profile(n)`` giving
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
    """Write `lines_mesh` of ``lines`` to ``path`` (``.vtu`` or ``.vtk``), atomically (see
    `write_mooring`)."""
    import meshio

    path = writable_file("path", path, _SUFFIXES, create_parents=False)
    mesh = lines_mesh(lines, n)
    with atomic_path(path, create_parents=False) as temp:
        meshio.write(temp, mesh)
    return path


def mooring_mesh(result, n: int = 101) -> meshio.Mesh:
    """Lines, seabed patch and body of a `MooringEquilibrium` (see the module docstring).

    Parameters
    ----------
    result : MooringEquilibrium
        A solved moored body.
    n : int
        Points per line, >= 2.
    """
    import meshio

    points, tension, segments, line_id = _polylines(result.lines, n)
    count = len(points[0])
    points, tension = list(points), list(tension)
    cells = [("line", segments)]
    part = [np.zeros(len(segments), dtype=int)]
    line_id = [line_id]
    if getattr(result, "depth", None) is not None:
        corners = np.vstack([np.asarray(result.anchors)[:, :2], np.asarray(result.fairleads)[:, :2]])
        low, high = corners.min(axis=0), corners.max(axis=0)
        margin = 0.1 * float((high - low).max())
        low, high = low - margin, high + margin
        z = -float(result.depth)
        quad = np.array(
            [[low[0], low[1], z], [high[0], low[1], z], [high[0], high[1], z], [low[0], high[1], z]]
        )
        points.append(quad)
        tension.append(np.zeros(4))
        cells.append(("quad", count + np.arange(4)[None, :]))
        part.append(np.ones(1, dtype=int))
        line_id.append(np.full(1, -1))
        count += 4
    rigid = len(result.position) == 6
    body = _body_box(result) if rigid else np.asarray(result.offset, dtype=float)[None, :]
    points.append(body)
    tension.append(np.zeros(len(body)))
    cells.append(("hexahedron" if rigid else "vertex", count + np.arange(len(body))[None, :]))
    part.append(np.full(1, 2))
    line_id.append(np.full(1, -1))
    points = np.vstack(points)
    if not np.isfinite(points).all():
        raise InputError("result", "holds non-finite coordinates")
    return meshio.Mesh(
        points,
        cells,
        point_data={"tension_N": np.concatenate(tension)},
        cell_data={"part": part, "line": line_id},
    )


def write_mooring(result, path, n: int = 101) -> Path:
    """Write `mooring_mesh` of ``result`` to ``path`` (``.vtu`` or ``.vtk``), atomically: the
    file appears whole or not at all. The path is checked before the mesh is built: a
    missing parent folder is refused (never created), as is one that takes no new file, with
    ``InputError("path", ...)`` naming the path as given."""
    import meshio

    path = writable_file("path", path, _SUFFIXES, create_parents=False)
    mesh = mooring_mesh(result, n)
    with atomic_path(path, create_parents=False) as temp:
        meshio.write(temp, mesh)
    return path
