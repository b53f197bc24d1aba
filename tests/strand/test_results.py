"""Results: a capacity curve takes the increments asked for, one step writes its own VTK file."""

import meshio
import numpy as np
import pytest

from skcable import strand
from skcable.errors import InputError

STEEL = strand.preset("steel-9.5")


@pytest.mark.parametrize("max_strain, n_steps", [(0.002, 4), (0.002, 7), (0.02, 10)])
def test_n_steps_is_the_number_of_increments_whatever_max_strain_is(max_strain, n_steps):
    model = strand.StrandModel(STEEL.damaged(1), 0.5, n_elements=16)
    curve = model.capacity_curve(max_strain=max_strain, n_steps=n_steps)
    assert not curve.ruptured and len(curve.steps) == n_steps == len(curve.strain) - 1
    assert curve.strain[-1] == pytest.approx(max_strain, rel=1e-12)
    knee = 2 * STEEL.material.eps_y
    if max_strain <= knee:  # below twice the yield strain: equal increments
        np.testing.assert_allclose(np.diff(curve.strain), max_strain / n_steps, rtol=1e-12)


def test_one_step_writes_its_vtk_file_atomically(tmp_path):
    model = strand.StrandModel(
        STEEL.damaged(1), 0.3, n_elements=12, slip="axis", terms=[strand.ElasticFoundation(1e3)]
    )
    step = model.solve(0.003)
    paths = step.to_vtk(tmp_path / "step.vtu", wires=True)
    assert [p.name for p in paths] == ["step.vtu", "step_wires.vtu"]
    mesh = meshio.read(paths[0])
    # the axis at the nodes with the step's own displacements, the terms' outputs beside them
    np.testing.assert_array_equal(mesh.points[:, 0], step.layout.nodes)
    np.testing.assert_allclose(mesh.point_data["axial_displacement_m"], step.nodal["u"], rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        mesh.point_data["transverse_displacement_m"][:, 1], step.nodal["v"], atol=1e-15
    )
    assert "moment_N_m" in mesh.point_data and "slipping" in mesh.cell_data
    wires = meshio.read(paths[1])
    assert len(wires.points) > len(mesh.points)
    # the user's arrays join; a missing folder is refused by name and nothing is left behind
    extra = step.to_vtk(tmp_path / "extra.vtk", fields=lambda s: ({"lift_mm": 1e3 * s.nodal["v"]}, None))
    np.testing.assert_allclose(meshio.read(extra[0]).point_data["lift_mm"], 1e3 * step.nodal["v"])
    with pytest.raises(InputError, match="path"):
        step.to_vtk(tmp_path / "missing" / "step.vtu")
    assert not (tmp_path / "missing").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["extra.vtk", "step.vtu", "step_wires.vtu"]
