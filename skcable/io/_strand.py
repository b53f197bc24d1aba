"""Strand step results as VTK meshes (meshio): the axis and the wires.

The writers consume a [`StepResult`][skcable.strand.StepResult] only (what it
carries and its shared layout); they never call back into the model.
"""

from __future__ import annotations

from functools import lru_cache

import meshio
import numpy as np
from skfem import Basis, ElementLineP1, MeshLine

from skcable._checks import nonnegative, positive
from skcable.errors import InputError

__all__ = ["strand_mesh", "wire_mesh"]


@lru_cache(maxsize=8)
def _p1(layout):
    """The P1 basis of a layout's mesh on its quadrature (once per model, not per step)."""
    p1 = Basis(MeshLine(layout.nodes), ElementLineP1(), intorder=6)
    if p1.dx.shape != layout.dx.shape or not np.allclose(p1.dx, layout.dx, rtol=1e-12, atol=0):
        raise InputError("step", "its quadrature does not match its mesh (order 6 on the layout's nodes)")
    return p1


def _to_nodes(layout, values):
    """L² projection of quadrature-point values (..., ne, nq) onto P1 at the mesh nodes."""
    p1 = _p1(layout)
    flat = np.reshape(values, (-1, *values.shape[-2:]))
    nodal = np.array([p1.project(v)[p1.nodal_dofs[0]] for v in flat])
    return nodal.reshape(*values.shape[:-2], -1)


def _element_mean(layout, values):
    """Mean over each element (quadrature-weighted) of values (..., ne, nq): (..., ne)."""
    dx = layout.dx
    return np.sum(values * dx, axis=-1) / np.sum(dx, axis=-1)


def _outputs(step, point_data, cell_data):
    """The step's term outputs and the user's extra fields, sorted into point and cell data."""
    layout = step.layout
    n_nodes, (ne, nq) = len(layout.nodes), layout.x.shape
    given = [(name, kind, np.asarray(values, dtype=float)) for name, (kind, values) in step.outputs.items()]
    given += [(name, "point_data", np.asarray(v, dtype=float)) for name, v in (point_data or {}).items()]
    given += [(name, "cell_data", np.asarray(v, dtype=float)) for name, v in (cell_data or {}).items()]
    points, cells = {}, {}
    for name, kind, values in given:
        if kind == "point_data" and values.shape == (ne, nq):
            points[name] = _to_nodes(layout, values)  # quadrature values, projected onto P1
        elif kind == "point_data" and values.shape[:1] == (n_nodes,):
            points[name] = values
        elif kind == "cell_data" and values.shape[:1] == (ne,):
            cells[name] = [values]
        else:
            raise InputError(
                name,
                f"{kind} of shape {values.shape}: give (n_elements, n_quad) = ({ne}, {nq}) or ({n_nodes},) "
                f"point data, ({ne},) cell data",
            )
    return points, cells


def strand_mesh(step, *, point_data=None, cell_data=None) -> meshio.Mesh:
    """The strand axis at one load step: nodes of the mesh, undeformed.

    Point data (at the nodes; quadrature values by L² projection onto P1), each array named
    with its unit: ``axial_displacement_m`` (u), ``transverse_displacement_m`` ((0, v, w): apply
    *Warp By Vector* to see the bending, which is a hundredth of the stretch),
    ``displacement_m`` ((u, v, w), to warp both), ``twist_rad``, ``axial_strain`` (ε_a),
    ``axial_force_N``, ``curvature_1_per_m``, ``curvature_2_per_m`` (about the principal axes),
    ``curvature_per_m`` ((0, v″, w″)), ``moment_N_m`` (conjugate to v″ and w″). Cell data (per
    element): ``slip_1``, ``slip_2`` (fraction of the element in slip about each principal axis),
    ``slipping`` (1 if any), ``EI_in_use_N_m2`` (tangent bending stiffness about y and z),
    ``element_size_m``.

    The terms' outputs (``step.outputs``: a contact pressure, a gap, a foundation's reaction)
    are added under their names, and so are the user's ``point_data`` (arrays at the nodes, or
    at the quadrature points (n_elements, n_quad)) and ``cell_data`` (one value per element).
    """
    layout, at = step.layout, step.nodal
    nodes = layout.nodes
    displacement = np.column_stack([at["u"], at["v"], at["w"]])
    projected = _to_nodes(
        layout, np.array([step.axial_strain, step.axial_force, *step.curvature, *step.bending, *step.moment])
    )
    points = np.column_stack([nodes, np.zeros_like(nodes), np.zeros_like(nodes)])
    slipping = np.asarray(step.slipping, dtype=float).mean(axis=2)  # (2, ne)
    zero = np.zeros_like(nodes)
    extra_points, extra_cells = _outputs(step, point_data, cell_data)
    point_data = {
        "axial_displacement_m": at["u"],
        "transverse_displacement_m": np.column_stack([zero, at["v"], at["w"]]),
        "displacement_m": displacement,
        "twist_rad": at["phi"],
        "axial_strain": projected[0],
        "axial_force_N": projected[1],
        "curvature_1_per_m": projected[2],
        "curvature_2_per_m": projected[3],
        "curvature_per_m": np.column_stack([zero, projected[4], projected[5]]),
        "moment_N_m": np.column_stack([zero, projected[6], projected[7]]),
    }
    cell_data = {
        "slip_1": [slipping[0]],
        "slip_2": [slipping[1]],
        "slipping": [np.any(step.slipping, axis=(0, 2)).astype(np.int32)],
        "EI_in_use_N_m2": [np.column_stack([_element_mean(layout, e) for e in step.EI_in_use])],
        "element_size_m": [np.diff(nodes[layout.elements], axis=0)[0]],
    }
    return meshio.Mesh(
        points,
        [("line", layout.elements.T)],
        point_data=point_data | extra_points,
        cell_data=cell_data | extra_cells,
    )


def wire_mesh(step, *, scale: float = 1.0, radial_scale: float = 1.0) -> meshio.Mesh:
    """Every wire as a polyline along its helix on the deformed axis.

    The axis displacement (times ``scale``) and the twist carry each wire; points
    at the mesh nodes. ``radial_scale`` multiplies the helix radii and the wires'
    own radii, so that a strand much longer than thick is more than a line in a
    view (the axial coordinate is never scaled). Point data: ``radius_m``, the
    wire's own radius (times ``radial_scale``): ParaView's *Tube* filter with
    "Vary Radius: By Absolute Scalar" draws the wires at their size. Cell data
    per segment: ``wire`` (index), ``layer``, ``broken`` (1 for a broken wire),
    ``wire_strain`` and ``wire_stress_MPa``, the element means.
    """
    scale = nonnegative("scale", scale)
    radial_scale = positive("radial_scale", radial_scale)
    layout, at = step.layout, step.nodal
    nodes = layout.nodes
    if np.any(np.diff(nodes) <= 0):
        raise InputError("step", "mesh nodes must be numbered along the axis for wire output")
    psi = layout.wire_psi[:, None] + layout.wire_rate[:, None] * nodes[None] - at["phi"][None]
    n_wires, n_nodes = psi.shape
    radius = radial_scale * layout.wire_radius[:, None]
    x = np.broadcast_to(nodes + scale * at["u"], psi.shape)
    y = scale * at["v"][None] + radius * np.sin(psi)
    z = scale * at["w"][None] + radius * np.cos(psi)
    points = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    start = (np.arange(n_wires)[:, None] * n_nodes + np.arange(n_nodes - 1)[None]).ravel()
    segments = np.column_stack([start, start + 1])
    repeat = lambda a: np.repeat(a, n_nodes - 1)  # noqa: E731
    cell_data = {
        "wire": [repeat(np.arange(n_wires))],
        "layer": [repeat(layout.wire_layer)],
        "broken": [repeat(layout.wire_broken.astype(np.int32))],
        "wire_strain": [_element_mean(layout, step.wire_strain).ravel()],
        "wire_stress_MPa": [1e-6 * _element_mean(layout, step.wire_stress).ravel()],
    }
    point_data = {"radius_m": np.repeat(radial_scale * layout.wire_size, n_nodes)}
    return meshio.Mesh(points, [("line", segments)], point_data=point_data, cell_data=cell_data)
