"""Results as VTK meshes (meshio) for ParaView.

Points are always 3-component (REFERENCE.md §3): a suspended cable lies in
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
from skfem import ElementLineP1

from skcable.errors import InputError

__all__ = ["cable_mesh", "funicular_mesh", "strand_mesh", "wire_mesh", "write", "write_series"]


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
    the solution also has segment ``forces`` (:func:`~skcable.cable.funicular`),
    ``(x, P downward)`` pairs otherwise (:func:`~skcable.cable.funicular_vertical`).
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


def _to_nodes(model, values):
    """L² projection of quadrature-point values (..., ne, nq) onto P1 at the mesh nodes."""
    p1 = model.ub.with_element(ElementLineP1())
    flat = np.reshape(values, (-1, *values.shape[-2:]))
    nodal = np.array([p1.project(v)[p1.nodal_dofs[0]] for v in flat])
    return nodal.reshape(*values.shape[:-2], -1)


def _element_mean(model, values):
    """Mean over each element (quadrature-weighted) of values (..., ne, nq): (..., ne)."""
    dx = model.ub.dx
    return np.sum(values * dx, axis=-1) / np.sum(dx, axis=-1)


def _step_state(model, step):
    mask = step.slipping[0, :, 0] if model.slip == "element" else step.slipping
    return model.section_state(step.dofs, mask if model.slip != "none" else None)


def strand_mesh(model, step) -> meshio.Mesh:
    """The strand axis at one load step: nodes of the mesh, undeformed.

    Point data (at the nodes; quadrature values by L² projection onto P1):
    ``displacement`` (u, v, w in m: apply *Warp By Vector*), ``twist`` (rad),
    ``axial_strain`` (ε_a), ``axial_force`` (N), ``curvature_1``,
    ``curvature_2`` (about the principal axes, 1/m), ``curvature`` (v″, w″),
    ``moment`` (N·m, conjugate to v″ and w″). Cell data (per element):
    ``slip_1``, ``slip_2`` (fraction of the element in slip about each
    principal axis), ``slipping`` (1 if any), ``EI_in_use`` (tangent bending
    stiffness about y and z, N·m²), ``element_size`` (m).
    """
    at = model.nodal_values(step.dofs)
    nodes = model.mesh.p[0]
    displacement = np.column_stack([at["u"], at["v"], at["w"]])
    state = _step_state(model, step)
    S, D = state["S"], state["D"]
    g = model.generalized_strains(step.dofs)
    projected = _to_nodes(
        model, np.array([state["axial"], state["N"], *state["curvature"], g[2], g[4], S[2], S[4]])
    )
    points = np.column_stack([nodes, np.zeros_like(nodes), np.zeros_like(nodes)])
    slipping = np.asarray(step.slipping, dtype=float).mean(axis=2)  # (2, ne)
    point_data = {
        "displacement": displacement,
        "twist": at["phi"],
        "axial_strain": projected[0],
        "axial_force": projected[1],
        "curvature_1": projected[2],
        "curvature_2": projected[3],
        "curvature": np.column_stack([np.zeros_like(nodes), projected[4], projected[5]]),
        "moment": np.column_stack([np.zeros_like(nodes), projected[6], projected[7]]),
    }
    cell_data = {
        "slip_1": [slipping[0]],
        "slip_2": [slipping[1]],
        "slipping": [np.any(step.slipping, axis=(0, 2)).astype(np.int32)],
        "EI_in_use": [np.column_stack([_element_mean(model, D[2, 2]), _element_mean(model, D[4, 4])])],
        "element_size": [np.diff(nodes[model.mesh.t], axis=0)[0]],
    }
    return meshio.Mesh(points, [("line", model.mesh.t.T)], point_data=point_data, cell_data=cell_data)


def wire_mesh(model, step, *, scale: float = 1.0) -> meshio.Mesh:
    """Every wire as a polyline along its helix on the deformed axis.

    The axis displacement (times ``scale``) and the twist carry each wire;
    points at the mesh nodes. Cell data per segment: ``wire`` (index),
    ``layer``, ``broken`` (1 for a broken wire), ``wire_strain`` and
    ``wire_stress`` (Pa), the element means.
    """
    nodes = model.mesh.p[0]
    if np.any(np.diff(nodes) <= 0):
        raise InputError("model", "mesh nodes must be numbered along the axis for wire output")
    at = model.nodal_values(step.dofs)
    wires = model.wire_data
    psi = wires.psi[:, None] + model.wire_rate[:, None] * nodes[None] - at["phi"][None]  # (n_wires, n_nodes)
    n_wires, n_nodes = psi.shape
    x = np.broadcast_to(nodes + scale * at["u"], psi.shape)
    y = scale * at["v"][None] + wires.radius[:, None] * np.sin(psi)
    z = scale * at["w"][None] + wires.radius[:, None] * np.cos(psi)
    points = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    start = (np.arange(n_wires)[:, None] * n_nodes + np.arange(n_nodes - 1)[None]).ravel()
    segments = np.column_stack([start, start + 1])
    repeat = lambda a: np.repeat(a, n_nodes - 1)  # noqa: E731
    cell_data = {
        "wire": [repeat(np.arange(n_wires))],
        "layer": [repeat(wires.layer)],
        "broken": [repeat((~model.alive).astype(np.int32))],
        "wire_strain": [_element_mean(model, step.wire_strain).ravel()],
        "wire_stress": [_element_mean(model, step.wire_stress).ravel()],
    }
    return meshio.Mesh(points, [("line", segments)], cell_data=cell_data)


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
