"""Samples of a line's profile along its unstretched arc length, for the VTK writer.

`skcable.io.cable_mesh` reads a solution's ``samples(n)``: ``xy`` (n, 2) m, ``tension`` (N),
``angle`` (rad above the horizontal) and ``load`` (n, 2) N/m, y up. The mooring lines sample
them at ``n`` points evenly spaced in unstretched arc length (the result protocol's
``profile(n)``), where a line on the seabed or in a heap has no single-valued ``y(x)``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["arc_samples", "write_profile"]


def arc_samples(x, y, T, angle, w) -> dict:
    """The ``samples`` dict of `skcable.io.cable_mesh` from the positions ``x, y`` (m), tensions
    ``T`` (N), tangent angles (rad) and weights per unstretched length ``w`` (N/m, downward)."""
    load = np.column_stack([np.zeros_like(np.asarray(x, dtype=float)), -np.broadcast_to(w, np.shape(x))])
    return {
        "xy": np.column_stack([x, y]),
        "tension": np.asarray(T, dtype=float),
        "angle": angle,
        "load": load,
    }


def write_profile(solution, path, n: int):
    """Write ``solution.samples(n)`` as a VTK polyline, atomically (`skcable.io.write`); returns the path."""
    from skcable.io import cable_mesh, write

    return write(cable_mesh(solution, n), path)
