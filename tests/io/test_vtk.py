"""VTK output read back with meshio and pyvista, compared with the results and closed forms."""

import ast
from pathlib import Path

import meshio
import numpy as np
import pytest
import pyvista as pv

from skcable import bvp, cable, conductors, mooring, strand
from skcable.errors import InputError
from skcable.io import funicular_mesh, write, write_series


@pytest.fixture(scope="module")
def curves():
    """Short, coarse curves: one damaged with slip, one intact stick."""
    damaged = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=24, slip="axis")
    intact = strand.StrandModel(strand.preset("steel-9.5"), 0.3, n_elements=8)
    return damaged.capacity_curve(max_strain=0.006, n_steps=6), intact.capacity_curve(
        max_strain=0.004, n_steps=4
    )


@pytest.mark.parametrize(
    "solve",
    [
        lambda: cable.catenary(800, -20, 20, low=-30),
        lambda: cable.parabola(800, -20, 20, low=-30),
        lambda: cable.elastic_catenary(800, -20, 20, 1e8, length=810),
        lambda: bvp.solve_bvp(800, -20, [bvp.SelfWeight(20)], low=-30, n_elements=32),
        lambda: bvp.solve_bvp(800, -20, [bvp.SelfWeight(20)], length=810, n_elements=32, formulation="arc"),
    ],
)
def test_cable_profile_round_trip(tmp_path, solve):
    sol = solve()
    path = sol.to_vtk(tmp_path / "cable.vtu", n=51)
    mesh, grid = meshio.read(path), pv.read(path)
    assert mesh.points.shape == (51, 3) and np.all(mesh.points[:, 2] == 0)
    np.testing.assert_allclose(grid.points, mesh.points)
    x, y = mesh.points[:, 0], mesh.points[:, 1]
    np.testing.assert_allclose([x[0], y[0], x[-1], y[-1]], [0, 0, 800, -20], atol=1e-9)
    T, angle, load = (mesh.point_data[k] for k in ("tension_N", "angle_rad", "load_N_per_m"))
    np.testing.assert_allclose(grid.point_data["tension_N"], T)
    # statics: the horizontal component of the tension is H everywhere (no horizontal load);
    # the arc form's P1 tension and P2 slope meet it to the discretisation error (h^2)
    rtol = 1e-4 if isinstance(sol, bvp.ArcSolution) else 1e-6
    np.testing.assert_allclose(T * np.cos(angle), sol.H, rtol=rtol)
    np.testing.assert_allclose(T[[0, -1]], [sol.T_A, sol.T_B], rtol=rtol)
    np.testing.assert_allclose(np.linalg.norm(mesh.point_data["tangent"], axis=1), 1.0)
    # the weight per unstretched metre: w, or w dx/ds for the parabola's load per horizontal metre
    expected = 20 * np.cos(angle) if isinstance(sol, cable.Parabola) else np.full_like(T, 20.0)
    np.testing.assert_allclose(-load[:, 1], expected, rtol=1e-9)


def test_funicular_round_trip(tmp_path):
    sol = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    mesh = meshio.read(sol.to_vtk(tmp_path / "f.vtu"))
    np.testing.assert_allclose(mesh.points[:, :2], sol.nodes)
    np.testing.assert_allclose(mesh.cell_data["tension_N"][0], sol.T)
    np.testing.assert_allclose(mesh.cell_data["tension_N"][0][0], 233.04, atol=0.005)  # notes "Cables", ex. 1
    vertical = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    loads = meshio.read(write(funicular_mesh(vertical), tmp_path / "v.vtu")).point_data["load_N"]
    np.testing.assert_allclose(loads[:, 1], [0, -50, -30, -40, 0])


def test_array_solution_is_refused(tmp_path):
    with pytest.raises(InputError, match="solution"):
        cable.catenary([800, 900], 0, 20, sag=30).to_vtk(tmp_path / "x.vtu")
    with pytest.raises(InputError, match="n"):
        cable.catenary(800, 0, 20, sag=30).to_vtk(tmp_path / "x.vtu", n=1)


def test_strand_series_round_trip(tmp_path, curves):
    curve = curves[0]
    pvd, wires = curve.to_vtk(tmp_path / "s.pvd", wires=True)
    reader = pv.PVDReader(pvd)
    np.testing.assert_allclose(reader.time_values, [s.strain for s in curve.steps])
    model, step = curve.model, curve.steps[-1]
    reader.set_active_time_point(len(curve.steps) - 1)
    grid = reader.read()[0]
    mesh = meshio.read(tmp_path / f"s_{len(curve.steps) - 1:04d}.vtu")
    parts = model.split(step.dofs)
    np.testing.assert_allclose(mesh.points[:, 0], model.mesh.p[0])
    np.testing.assert_allclose(
        mesh.point_data["displacement_m"][:, 0], parts["u"][model.bases["u"].nodal_dofs[0]]
    )
    np.testing.assert_allclose(
        mesh.point_data["displacement_m"][:, 1], parts["v"][model.bases["v"].nodal_dofs[0]]
    )
    np.testing.assert_allclose(grid.point_data["displacement_m"], mesh.point_data["displacement_m"])
    # the pulled end moves by strain * length
    assert mesh.point_data["displacement_m"][np.argmax(model.mesh.p[0]), 0] == pytest.approx(
        step.strain * 0.3
    )
    # the axial force along the strand equals the reaction (equilibrium of any cut), to the projection
    np.testing.assert_allclose(mesh.point_data["axial_force_N"], step.force, rtol=2e-2)
    np.testing.assert_allclose(mesh.cell_data["element_size_m"][0].sum(), 0.3)
    # axial and transverse displacement apart: u alone, and (0, v, w)
    np.testing.assert_array_equal(
        mesh.point_data["axial_displacement_m"], mesh.point_data["displacement_m"][:, 0]
    )
    transverse = mesh.point_data["transverse_displacement_m"]
    assert np.all(transverse[:, 0] == 0) and np.array_equal(
        transverse[:, 1:], mesh.point_data["displacement_m"][:, 1:]
    )
    np.testing.assert_allclose(grid.cell_data["slip_1"], mesh.cell_data["slip_1"][0])
    assert np.all((mesh.cell_data["slip_1"][0] >= 0) & (mesh.cell_data["slip_1"][0] <= 1))
    EI = mesh.cell_data["EI_in_use_N_m2"][0]
    section = model.strand.section()
    assert np.all(EI > 0.9 * section.EI_slip.min()) and np.all(EI < 1.1 * section.EI_stick.max())
    w = meshio.read(tmp_path / f"s_wires_{len(curve.steps) - 1:04d}.vtu")
    n_nodes = model.mesh.p.shape[1]
    assert w.points.shape == (7 * n_nodes, 3)
    assert w.cell_data["broken"][0].sum() == n_nodes - 1  # one broken wire, every segment flagged
    assert pv.PVDReader(wires).time_values == reader.time_values


def test_intact_strand_fields_match_closed_form(tmp_path, curves):
    curve = curves[1]
    step = curve.steps[-1]
    mesh = curve.step_mesh(-1)
    EA = curve.model.strand.section().EA
    np.testing.assert_allclose(mesh.point_data["axial_force_N"], EA * step.strain, rtol=1e-6)
    assert np.max(np.abs(mesh.point_data["curvature_per_m"])) < 1e-9
    # undeformed wires (scale 0) lie on their helix: radius = core + wire radius = d for equal wires
    wires = curve.step_mesh(0, wires=True, scale=0.0)
    radius = np.hypot(wires.points[:, 1], wires.points[:, 2]).reshape(7, -1)
    np.testing.assert_allclose(radius[1:], 3.1e-3, rtol=1e-12)
    np.testing.assert_allclose(radius[0], 0.0)
    with pytest.raises(InputError, match="step"):
        curve.step_mesh(99)


def test_series_needs_pvd(tmp_path):
    with pytest.raises(InputError, match="path"):
        write_series([], [], tmp_path / "x.vtu")


def test_csv_matches_curve(tmp_path, curves):
    curve = curves[0]
    table = np.genfromtxt(curve.to_csv(tmp_path / "c.csv"), delimiter=",", names=True)
    # written to 17 significant digits: every double reads back as itself
    np.testing.assert_array_equal(table["strain"], curve.strain)
    np.testing.assert_array_equal(table["force_N"], curve.force)
    np.testing.assert_array_equal(table["slip_fraction"], curve.slip_fraction)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.csv"]


def test_a_csv_write_that_fails_leaves_the_previous_file(tmp_path, curves, monkeypatch):
    """Atomic: a write that fails half-way (here numpy's writer, after a partial line) leaves the
    file as it was and no temporary file beside it."""
    path = curves[0].to_csv(tmp_path / "c.csv")
    before = path.read_bytes()

    def broken(fname, *args, **kwargs):
        Path(fname).write_text("strain,force_N\n0.1,")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(np, "savetxt", broken)
    with pytest.raises(OSError, match="c.csv"):
        curves[1].to_csv(path)
    assert path.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.csv"]


# --- writers consume results: no import of the models, no import circle ------------------
ROOT = Path(__file__).resolve().parents[2] / "skcable"


def _import_graph():
    """Every skcable module and the skcable modules it imports (function-level imports included,
    ``if TYPE_CHECKING:`` blocks and lazy names served by `skcable._lazy` not)."""
    modules = {}
    for path in ROOT.rglob("*.py"):
        parts = path.relative_to(ROOT.parent).with_suffix("").parts
        modules[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    graph = {}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        found = set()
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):  # what static tools alone see is not imported
            if isinstance(node, ast.If) and getattr(node.test, "id", "") == "TYPE_CHECKING":
                node.body = []
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                found.update(alias.name for alias in node.names)
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    head = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join(head + ([base] if base else []))
                found.update(
                    f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names
                )
        graph[name] = {m for m in found if m in modules and m != name}
    return graph


def test_writers_import_no_model():
    graph = _import_graph()
    writers = [name for name in graph if name.startswith("skcable.io")]
    assert "skcable.io._vtk" in writers
    for name in writers:
        models = sorted(m for m in graph[name] if m.startswith(("skcable.cable", "skcable.strand")))
        assert not models, f"{name} imports {models}"


def test_no_import_circle_in_the_package():
    graph = _import_graph()

    def reaches(start, goal):
        seen, todo = set(), [start]
        while todo:
            for nxt in graph[todo.pop()] - seen:
                if nxt == goal:
                    return True
                seen.add(nxt)
                todo.append(nxt)
        return False

    circles = [name for name in graph if reaches(name, name)]  # the whole package
    assert not circles, f"modules on an import circle: {circles}"


# --- writers: atomic, no parent created, the user's path in every refusal ---------------------
def _polygon():
    return funicular_mesh(cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)]))


def _line():
    return mooring.line_3d(mooring.Line([mooring.Segment(400.0, 200.0, 1e8)]), (0, 0, 0), (380.0, 0, 60.0))


def _moored():
    line = mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0)
    angles = np.radians([0.0, 120.0, 240.0])
    anchors = np.column_stack([800 * np.cos(angles), 800 * np.sin(angles), np.full(3, -200.0)])
    fairleads = np.column_stack([20 * np.cos(angles), 20 * np.sin(angles), np.full(3, -14.0)])
    body = mooring.RigidBody(fairleads, waterplane_area=600.0)
    return mooring.MooringSystem(body, [line] * 3, anchors).equilibrium()


def _writers():
    """Each writer of skcable.io with a valid result, and a suffix of its format."""
    from skcable.io import write_lines, write_mode_shapes, write_mooring

    sol = cable.catenary(800, -20, 20, low=-30)
    modes = conductors.natural_frequencies(100.0, 0.0, 10.0, 5e7, sag=3.0, n_modes=2)
    return {
        "write": (lambda p: write(_polygon(), p), ".vtu"),
        "to_vtk": (lambda p: sol.to_vtk(p), ".vtk"),
        "write_series": (lambda p: write_series([_polygon(), _polygon()], [0.0, 1.0], p), ".pvd"),
        "write_mode_shapes": (lambda p: write_mode_shapes(modes, p), ".vtu"),
        "write_lines": (lambda p: write_lines([_line()], p), ".vtu"),
        "write_mooring": (lambda p: write_mooring(_moored(), p), ".vtu"),
    }


@pytest.mark.parametrize(
    "writer", ["write", "to_vtk", "write_series", "write_mode_shapes", "write_lines", "write_mooring"]
)
def test_writer_refuses_a_missing_parent_and_never_creates_it(tmp_path, writer):
    call, suffix = _writers()[writer]
    path = tmp_path / "no" / "such" / f"out{suffix}"
    with pytest.raises(InputError) as info:
        call(path)
    assert info.value.argument == "path" and repr(str(path)) in str(info.value)
    assert not (tmp_path / "no").exists()
    with pytest.raises(InputError) as info:  # a folder that takes no new file, root included
        call(f"/proc/out{suffix}")
    assert info.value.argument == "path" and f"'/proc/out{suffix}'" in str(info.value)
    assert ".tmp" not in str(info.value)
    written = call(tmp_path / f"out{suffix}")  # and where it can write, it does, leaving no temporary
    assert Path(written).is_file() and not list(tmp_path.glob(".*"))


def test_write_mode_shapes_none_is_a_path_error():  # issue 26, D7: a TypeError escaped
    from skcable.io import write_mode_shapes

    res = conductors.natural_frequencies(100.0, 0.0, 10.0, 5e7, sag=3.0, n_modes=2)
    for path in (None, 3.0, ["m.vtu"]):
        with pytest.raises(InputError) as info:
            write_mode_shapes(res, path)
        assert info.value.argument == "path"


def test_a_failed_write_leaves_the_earlier_file(tmp_path, monkeypatch):
    path = tmp_path / "c.vtu"
    path.write_text("earlier")

    def breaks(target, mesh, *args, **kwargs):
        Path(target).write_text("half")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(meshio, "write", breaks)
    with pytest.raises(OSError) as info:
        cable.catenary(800, -20, 20, low=-30).to_vtk(path)
    assert repr(str(path)) in str(info.value) and ".tmp" not in str(info.value)  # the user's path
    assert path.read_text() == "earlier" and [p.name for p in tmp_path.iterdir()] == ["c.vtu"]


def test_array_names_carry_their_units(tmp_path):
    from skcable.io import cable_mesh, lines_mesh, mode_shape_mesh, mooring_mesh

    unit = ("_N", "_rad", "_N_per_m", "_m_per_sqrt_kg")
    meshes = [
        cable_mesh(cable.catenary(800, -20, 20, low=-30)),
        _polygon(),
        mode_shape_mesh(conductors.natural_frequencies(100.0, 0.0, 10.0, 5e7, sag=3.0, n_modes=2)),
        lines_mesh([_line()]),
        mooring_mesh(_moored()),
    ]
    unitless = {"tangent", "part", "line"}  # a unit vector, a part number, a line number
    for mesh in meshes:
        for name in [*mesh.point_data, *mesh.cell_data]:
            assert name in unitless or name.endswith(unit), name


def test_the_array_names_of_getting_started_are_the_files():
    """docs/getting_started.md names the arrays of the demo's step files (issue 31: it named
    `displacement`, `curvature_1`, `axial_force` where the files say `displacement_m`, ...)."""
    import re
    from pathlib import Path

    from skcable import strand

    page = (Path(__file__).resolve().parents[2] / "docs" / "getting_started.md").read_text()
    paraview = page[page.index("In ParaView") :].split("\n\n")[0]
    named = set(re.findall(r"`([A-Za-z_0-9]+)`", paraview))
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=8, slip="axis")
    mesh = model.capacity_curve(max_strain=0.004, n_steps=4).step_mesh(1)
    assert len(named) >= 4 and named <= set(mesh.point_data) | set(mesh.cell_data), named
