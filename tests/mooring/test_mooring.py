"""Lines in 3-D and moored bodies.

References: the 2-D solution rotated into the line's plane by hand, central
differences of the forces for every stiffness (3x3 of a line, 6x6 and 3x3 of the
moored body, perturbing rotations with scipy's `Rotation`), equilibrium of the
forces recomputed from the lines, the symmetry of a three-line spread mooring,
and MoorPy's ``System`` on the same layout (an independent implementation).
"""

import importlib.util
import json
import runpy
import warnings
from pathlib import Path

import meshio
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from skcable import cable, cli, mooring
from skcable.errors import ConvergenceError, InputError, PlausibilityWarning

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(uplift_angle|position|strain)\\b:skcable.errors.PlausibilityWarning"
)

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = runpy.run_path(str(ROOT / "examples" / "spread_mooring.py"))

CHAIN = mooring.Line([mooring.Segment(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.4)
FREE = mooring.Line([mooring.Segment(400.0, 200.0, 1e8)])  # no seabed: hangs free


def test_single_line_force_is_the_2d_solution_rotated():
    anchor, heading = np.array([10.0, -20.0, -200.0]), np.radians(37.0)
    fairlead = anchor + [780.0 * np.cos(heading), 780.0 * np.sin(heading), 186.0]
    line = mooring.line_3d(CHAIN, anchor, fairlead)
    flat = cable.elastic_catenary(780.0, 186.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.4)
    turn = Rotation.from_euler("z", heading).as_matrix()
    np.testing.assert_allclose(line.force_on_fairlead, turn @ [-flat.H, 0.0, -flat.V_B], rtol=1e-12)
    np.testing.assert_allclose(line.force_on_anchor, turn @ [flat.H_A, 0.0, -flat.V_A], rtol=1e-12, atol=1e-9)
    # the seabed takes the friction: the line's forces and weight balance with it
    friction = (flat.H - flat.H_A) * line.direction
    weight_left = flat.w * (flat.length - flat.length_on_seabed)
    total = line.force_on_fairlead + line.force_on_anchor + friction + [0.0, 0.0, weight_left]
    assert np.abs(total).max() < 1e-9 * flat.H
    points, tension = line.profile_with_tension(51)
    np.testing.assert_allclose(points[[0, -1]], [anchor, fairlead], atol=1e-6)
    assert tension[-1] == pytest.approx(line.tension_at_fairlead, rel=1e-12)


@pytest.mark.parametrize("model", [CHAIN, FREE], ids=["grounded, friction", "free"])
def test_line_stiffness_matches_central_differences(model):
    anchor = np.array([5.0, 3.0, -2.0])
    reach = (780.0, 186.0) if model is CHAIN else (380.0, 60.0)
    heading = np.radians(-113.0)
    fairlead = anchor + [reach[0] * np.cos(heading), reach[0] * np.sin(heading), reach[1]]
    K = mooring.line_3d(model, anchor, fairlead).stiffness()
    h = 1e-3
    numeric = np.empty((3, 3))
    for j in range(3):
        step = np.eye(3)[j] * h
        up = mooring.line_3d(model, anchor, fairlead + step).force_on_fairlead
        down = mooring.line_3d(model, anchor, fairlead - step).force_on_fairlead
        numeric[:, j] = -(up - down) / (2 * h)
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-6 * np.abs(K).max())


def test_vertical_line_and_bad_points_are_refused():
    with pytest.raises(InputError) as err:
        mooring.line_3d(CHAIN, [0.0, 0.0, -200.0], [0.0, 0.0, -10.0])
    assert err.value.argument == "fairlead"
    with pytest.raises(InputError) as err:
        mooring.line_3d(CHAIN, [0.0, 0.0], [1.0, 0.0, 0.0])
    assert err.value.argument == "anchor"
    with pytest.raises(InputError) as err:
        mooring.line_3d(CHAIN, [0.0, 0.0, 0.0], [1.0, np.nan, 0.0])
    assert err.value.argument == "fairlead"


def _euler_after(q, rotation_vector):
    """Position q with the body turned further by a small rotation about global axes."""
    turned = Rotation.from_rotvec(rotation_vector) * Rotation.from_euler("ZYX", q[[5, 4, 3]])
    yaw, pitch, roll = turned.as_euler("ZYX")
    return np.concatenate([q[:3], [roll, pitch, yaw]])


def _numeric_stiffness(system, q, lines_only, h=(1e-3, 1e-6)):
    numeric = np.empty((6, 6))
    for j in range(6):
        step = np.eye(6)[j]
        if j < 3:
            up, down = q + h[0] * step, q - h[0] * step
            size = h[0]
        else:
            up, down = _euler_after(q, h[1] * step[3:]), _euler_after(q, -h[1] * step[3:])
            size = h[1]
        if lines_only:
            f_up, f_down = system.lines_force(up), system.lines_force(down)
        else:
            f_up, f_down = system.net_force(up), system.net_force(down)
        numeric[:, j] = -(f_up - f_down) / (2 * size)
    return numeric


class _LinesOnly:
    """The net force of the lines alone, from the public pieces (line_3d and the arms)."""

    def __init__(self, system):
        self.system = system

    def lines_force(self, q):
        lines = self.system.solve_lines(q)
        arms = np.array([line.fairlead for line in lines]) - q[:3]
        forces = np.array([line.force_on_fairlead for line in lines])
        return np.concatenate([forces.sum(axis=0), np.cross(arms, forces).sum(axis=0)])


def test_rigid_body_stiffness_matches_central_differences():
    system = EXAMPLE["system"]()
    q = np.array([30.0, -12.0, 0.5, 0.03, -0.05, 0.4])  # turned and off equilibrium: f x r terms count
    K = system.stiffness(q, lines_only=True)
    numeric = _numeric_stiffness(_LinesOnly(system), q, lines_only=True)
    np.testing.assert_allclose(K, numeric, rtol=1e-5, atol=2e-6 * np.abs(K).max())
    K_total = system.stiffness(q)
    numeric = _numeric_stiffness(system, q, lines_only=False)
    np.testing.assert_allclose(K_total, numeric, rtol=1e-5, atol=2e-6 * np.abs(K_total).max())
    assert np.abs(K_total - K_total.T).max() > 1e-3 * np.abs(K_total).max()  # unsymmetric off equilibrium


def test_equilibrium_balances_the_forces_recomputed_from_the_lines():
    rest, pushed = EXAMPLE["solve"]()
    system = pushed.system
    q = pushed.position
    body = system.body
    R = mooring.rotation_matrix(*q[3:])
    lines = [
        mooring.line_3d(m, a, q[:3] + R @ p)
        for m, a, p in zip(system.lines, system.anchors, body.fairleads, strict=True)
    ]
    arms = np.array([line.fairlead for line in lines]) - q[:3]
    forces = np.array([line.force_on_fairlead for line in lines])
    g, rho = 9.81, 1025.0
    weight, buoyancy = np.array([0, 0, -body.mass * g]), np.array([0, 0, rho * g * body.volume])
    total_force = forces.sum(axis=0) + weight + buoyancy + EXAMPLE["FORCE"]
    total_force[2] -= rho * g * body.waterplane_area * q[2]
    total_moment = (
        np.cross(arms, forces).sum(axis=0)
        + np.cross(R @ body.center_of_gravity, weight)
        + np.cross(R @ body.metacentre, buoyancy)
        + EXAMPLE["MOMENT"]
    )
    scale = max(line.tension_at_fairlead for line in lines)
    assert np.abs(total_force).max() < 1e-9 * scale
    assert np.abs(total_moment).max() < 1e-9 * scale * 20.0
    assert pushed.heel == pytest.approx(np.arccos(R[2, 2]), abs=1e-15)
    assert pushed.offset[0] > 0 and pushed.offset[1] > 0  # pushed along +x, +y
    table = pushed.tensions()
    np.testing.assert_allclose(table["T_upper"], [line.tension_at_fairlead for line in lines], rtol=1e-10)
    np.testing.assert_allclose(table["T_fairlead"], np.linalg.norm(forces, axis=1), rtol=1e-12)


def test_spread_mooring_at_rest_is_symmetric():
    rest, _ = EXAMPLE["solve"]()
    scale = rest.lines[0].tension_at_fairlead
    assert np.abs(rest.position[[0, 1, 3, 4, 5]]).max() < 1e-9
    tensions = [line.tension_at_fairlead for line in rest.lines]
    np.testing.assert_allclose(tensions, tensions[0], rtol=1e-10)
    K = rest.stiffness(lines_only=True)
    # from the lines kept at equilibrium = the lines solved again at that position
    np.testing.assert_allclose(
        K, rest.system.stiffness(rest.position, lines_only=True), rtol=1e-12, atol=1e-12 * np.abs(K).max()
    )
    # three-fold symmetry: isotropic in the horizontal plane, equal roll and pitch, no surge-yaw coupling
    assert K[0, 0] == pytest.approx(K[1, 1], rel=1e-9) and abs(K[0, 1]) < 1e-9 * K[0, 0]
    assert K[3, 3] == pytest.approx(K[4, 4], rel=1e-9)
    assert abs(K[0, 5]) < 1e-9 * K[0, 0] * 20 and abs(K[1, 5]) < 1e-9 * K[0, 0] * 20
    np.testing.assert_allclose(K, K.T, atol=1e-9 * np.abs(K).max())  # no net force of the lines: symmetric
    assert np.all(np.linalg.eigvalsh(0.5 * (K + K.T)) > 0) and scale > 0


def test_spread_mooring_matches_moorpy():
    pytest.importorskip("moorpy")
    _, pushed = EXAMPLE["solve"]()
    r6, tensions, K_moorpy, ms = EXAMPLE["moorpy_solve"]()
    # MoorPy: solveEquilibrium(tol=1e-8 m on positions), each line solved to 1e-4 m on its end point:
    # positions agree to 1e-6 m and 1e-9 rad, forces and stiffness to ~1e-7
    np.testing.assert_allclose(pushed.position[:3], r6[:3], atol=1e-5)
    np.testing.assert_allclose(pushed.position[3:], r6[3:], atol=1e-8)
    np.testing.assert_allclose([line.tension_at_fairlead for line in pushed.lines], tensions, rtol=1e-7)
    K = pushed.system.stiffness(r6, lines_only=True)  # at MoorPy's own position
    np.testing.assert_allclose(K, K_moorpy, rtol=1e-6, atol=1e-7 * np.abs(K).max())
    K_all = pushed.system.stiffness(r6)
    K_all_moorpy = ms.bodyList[0].getStiffnessA(lines_only=False, all_DOFs=True)
    np.testing.assert_allclose(K_all, K_all_moorpy, rtol=1e-6, atol=1e-7 * np.abs(K_all).max())


def test_large_yaw_matches_moorpy():
    """A yaw moment that turns the platform by 46 degrees: large rotations, same parametrisation."""
    pytest.importorskip("moorpy")
    force, moment = np.array([2e6, 5e5, 0.0]), np.array([1e6, 1e7, 6e7])
    eq = EXAMPLE["system"]().equilibrium(force=force, moment=moment)
    r6, tensions, _, _ = EXAMPLE["moorpy_solve"](force, moment)
    assert r6[5] > 0.7  # radians
    np.testing.assert_allclose(eq.position[:3], r6[:3], atol=1e-5)
    np.testing.assert_allclose(eq.position[3:], r6[3:], atol=1e-8)
    np.testing.assert_allclose([line.tension_at_fairlead for line in eq.lines], tensions, rtol=1e-7)


def test_point_body_equilibrium_and_stiffness():
    anchors = EXAMPLE["layout"]()[0]
    buoy = mooring.PointBody(mass=2e4, volume=60.0, waterplane_area=30.0)
    chain = mooring.Line([mooring.Segment(850.0, 600.0, 3e8)], seabed=0.0)
    system = mooring.MooringSystem(buoy, [chain] * 3, anchors, depth=200.0)
    eq = system.equilibrium(force=(5e4, -2e4, 0.0))
    forces = eq.fairlead_forces.sum(axis=0) + [5e4, -2e4, 0.0]
    forces[2] += 9.81 * (1025.0 * 60.0 - 2e4) - 1025.0 * 9.81 * 30.0 * eq.offset[2]
    assert np.abs(forces).max() < 1e-9 * eq.lines[0].tension_at_fairlead
    K, h = eq.stiffness(), 1e-3
    numeric = np.column_stack(
        [
            -(system.net_force(eq.position + h * e) - system.net_force(eq.position - h * e)) / (2 * h)
            for e in np.eye(3)
        ]
    )
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-7 * np.abs(K).max())
    with pytest.raises(InputError) as err:
        system.equilibrium(moment=(0.0, 0.0, 1.0))
    assert err.value.argument == "moment"


def test_failures_are_loud():
    system = EXAMPLE["system"]()
    with pytest.raises(ConvergenceError) as err:
        system.equilibrium(force=EXAMPLE["FORCE"], max_iter=1)
    assert len(err.value.history) >= 2 and err.value.history[-1] > 1e-10
    # one line and no hydrostatics: nothing holds the body's yaw about the line
    body = mooring.RigidBody([[20.0, 0.0, -14.0]])
    single = mooring.MooringSystem(
        body, [mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0)], [[800.0, 0.0, -200.0]]
    )
    with pytest.raises(ConvergenceError, match="singular"):
        single.equilibrium()
    with pytest.raises(InputError) as err:
        mooring.MooringSystem(system.body, system.lines[:2], system.anchors[:2])
    assert err.value.argument == "body"
    with pytest.raises(InputError) as err:
        mooring.MooringSystem(system.body, system.lines, system.anchors[:, :2])
    assert err.value.argument == "anchors"
    with pytest.raises(InputError) as err:
        system.equilibrium(start=[0.0, 0.0, 0.0, 0.0, np.pi / 2, 0.0])
    assert err.value.argument == "start"


def test_vtk_of_lines_seabed_and_body(tmp_path):
    _, pushed = EXAMPLE["solve"]()
    path = pushed.to_vtk(tmp_path / "moored.vtu", n=41)
    assert [p.name for p in tmp_path.iterdir()] == ["moored.vtu"]  # written atomically, nothing else left
    mesh = meshio.read(path)
    kinds = {block.type: len(block.data) for block in mesh.cells}
    assert kinds == {"line": 3 * 40, "quad": 1, "hexahedron": 1}
    tension = mesh.point_data["tension_N"]
    for i, line in enumerate(pushed.lines):  # the last point of each line is its fairlead
        assert mesh.points[41 * i + 40] == pytest.approx(line.fairlead, abs=1e-6)
        assert tension[41 * i + 40] == pytest.approx(line.tension_at_fairlead, rel=1e-12)
    assert np.all(mesh.points[3 * 41 : 3 * 41 + 4, 2] == -200.0)  # the seabed patch
    with pytest.raises(InputError) as err:
        pushed.to_vtk(tmp_path / "moored.txt")
    assert err.value.argument == "path"


def test_plot_of_line_profiles():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from skcable import plot

    _, pushed = EXAMPLE["solve"]()
    ax = plot.mooring_profiles(pushed, n=31)
    drawn = ax.get_lines()
    assert len(drawn) == 4  # three lines and the seabed
    for line, curve in zip(pushed.lines, drawn, strict=False):
        assert curve.get_ydata()[-1] == pytest.approx(line.fairlead[2], abs=1e-6)
    plt.close(ax.figure)


def test_cli_line_as_json_equals_the_api(capsys):
    args = [
        "line",
        "--span",
        "800",
        "--dh",
        "150",
        "--length",
        "300",
        "250",
        "300",
        "--w",
        "1000",
        "400",
        "1000",
    ]
    status = cli.main(
        [*args, "--EA", "5e8", "--clump", "1", "2e4", "--seabed", "0", "--friction", "0.5", "--json"]
    )
    out, err = capsys.readouterr()
    assert status == 0 and err == ""
    values = json.loads(out)
    segments = [
        mooring.Segment(300.0, 1000.0, 5e8),
        mooring.Segment(250.0, 400.0, 5e8),
        mooring.Segment(300.0, 1000.0, 5e8),
    ]
    line = mooring.Line(segments, [mooring.ClumpWeight(1, 2e4)], seabed=0.0, friction=0.5)
    ref = line.solve(800.0, 150.0)
    assert values["H"] == ref.H and values["H_A"] == ref.H_A and values["V_B"] == ref.V_B
    assert values["length_on_seabed"] == ref.length_on_seabed
    assert values["segment_T_upper"] == ref.tensions()["T_upper"].tolist()
    assert [
        values[k] for k in ("k_H_span", "k_H_dh", "k_VB_span", "k_VB_dh")
    ] == ref.stiffness().ravel().tolist()
    # one segment: Jonkman's closed form (elastic_catenary), to round-off
    one = ["line", "--span", "800", "--dh", "150", "--length", "850", "--w", "1000", "--EA", "5e8", "--json"]
    assert cli.main([*one, "--seabed", "0", "--friction", "0.5"]) == 0
    values = json.loads(capsys.readouterr().out)
    closed = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.5)
    for name in ("H", "H_A", "V_B", "length_on_seabed"):
        assert values[name] == pytest.approx(getattr(closed, name), rel=1e-12)
    for flags, flag in (
        (["--w", "0", "--seabed", "0"], "--w"),  # weightless (a buoyant w < 0 is a line)
        (["--w", "1000", "1000"], "--w"),
        (["--clump", "0.5", "10"], "--clump"),
    ):
        status = cli.main([*args, "--EA", "5e8", *flags])
        out, err = capsys.readouterr()
        assert status == cli.EXIT_USAGE and out == "" and err.startswith(f"skcable: error: {flag}:"), err
        assert len(err.strip().splitlines()) == 1


def test_cli_line_free_and_vtk(capsys, tmp_path):
    args = ["line", "--span", "380", "--dh", "60", "--length", "400", "--w", "200", "--EA", "1e8"]
    status = cli.main([*args, "--json", "--vtk", str(tmp_path / "line.vtu")])
    out, err = capsys.readouterr()
    assert status == 0 and err == ""
    values = json.loads(out)
    ref = cable.elastic_catenary(380.0, 60.0, 200.0, 1e8, length=400.0)  # Irvine's, no seabed
    # two solvers, each to its own round-off (the Line's closure to ~1e-15, Irvine's to ~1e-12)
    assert values["H"] == pytest.approx(ref.H, rel=1e-11) and values["H_A"] == values["H"]
    assert values["V_A"] == pytest.approx(ref.V_A, rel=1e-11)
    assert values["length_on_seabed"] == 0.0
    mesh = meshio.read(tmp_path / "line.vtu")
    assert mesh.point_data["tension_N"][-1] == pytest.approx(ref.T_B, rel=1e-12)
    assert [p.name for p in tmp_path.iterdir()] == ["line.vtu"]
    # one plane for every 2-D line (issue 31): the command's file is the API's, x-y with y up
    api = meshio.read(
        mooring.Line([mooring.Segment(400.0, 200.0, 1e8)]).solve(380.0, 60.0).to_vtk(tmp_path / "api.vtu")
    )
    np.testing.assert_array_equal(mesh.points, api.points)
    assert np.all(mesh.points[:, 2] == 0.0) and mesh.points[-1, :2] == pytest.approx([380.0, 60.0], abs=1e-9)


# -- warm starts in the equilibrium loop -------------------------------------------------------
class _ColdLine:
    """A third-party line model: ``solve(span, dh)`` only, no warm start."""

    def __init__(self, line):
        self.line = line
        self.calls = 0

    def solve(self, span, dh):
        self.calls += 1
        return self.line.solve(span, dh)


def test_equilibrium_with_warm_starts_equals_cold_solves_and_moorpy(monkeypatch):
    """The lines warm-started from their previous solutions give the iterates of cold solves
    (a model without ``start=``), to round-off; both agree with MoorPy."""
    force, moment = np.array(EXAMPLE["FORCE"]), np.array(EXAMPLE["MOMENT"])
    warm_system = EXAMPLE["system"]()
    chain = warm_system.lines[0]
    cold_models = [_ColdLine(chain) for _ in range(3)]
    cold_system = mooring.MooringSystem(warm_system.body, cold_models, warm_system.anchors)
    cold = cold_system.equilibrium(force=force, moment=moment)
    cold_starts = []
    guess = chain._guess
    monkeypatch.setattr(chain, "_guess", lambda *args: cold_starts.append(args) or guess(*args))
    warm = warm_system.equilibrium(force=force, moment=moment)
    # only the first line at rest is solved cold; the two others of the same model start from it
    assert len(cold_starts) == 1
    assert sum(model.calls for model in cold_models) >= 3 * len(cold.history)
    assert len(warm.history) == len(cold.history)
    np.testing.assert_allclose(warm.position[:3], cold.position[:3], rtol=0, atol=1e-9)
    np.testing.assert_allclose(warm.position[3:], cold.position[3:], rtol=0, atol=1e-12)
    np.testing.assert_allclose(warm.fairlead_forces, cold.fairlead_forces, rtol=1e-10, atol=1e-4)
    K = cold.stiffness()
    np.testing.assert_allclose(warm.stiffness(), K, rtol=1e-9, atol=1e-9 * np.abs(K).max())
    if importlib.util.find_spec("moorpy") is None:
        return
    r6, tensions, _, _ = EXAMPLE["moorpy_solve"]()
    for eq in (warm, cold):
        np.testing.assert_allclose(eq.position[:3], r6[:3], atol=1e-5)
        np.testing.assert_allclose(eq.position[3:], r6[3:], atol=1e-8)
        np.testing.assert_allclose([line.tension_at_fairlead for line in eq.lines], tensions, rtol=1e-7)


def test_equilibrium_restarted_from_an_equilibrium():
    system = EXAMPLE["system"]()
    force, moment = np.array(EXAMPLE["FORCE"]), np.array(EXAMPLE["MOMENT"])
    first = system.equilibrium(force=force, moment=moment)
    again = system.equilibrium(force=force, moment=moment, start=first)
    assert len(again.history) == 1  # already in equilibrium: no Newton step
    np.testing.assert_allclose(again.position, first.position, rtol=0, atol=1e-12)
    # a nearby load from the previous equilibrium: the same as from rest
    pushed = system.equilibrium(force=1.1 * force, moment=moment, start=first)
    from_rest = system.equilibrium(force=1.1 * force, moment=moment)
    np.testing.assert_allclose(pushed.position[:3], from_rest.position[:3], rtol=0, atol=1e-8)
    np.testing.assert_allclose(pushed.position[3:], from_rest.position[3:], rtol=0, atol=1e-10)
    other = EXAMPLE["system"]()
    with pytest.raises(InputError) as err:
        other.equilibrium(force=force, start=first)
    assert err.value.argument == "start"
    with pytest.raises(InputError) as err:
        system.solve_lines(first.position, start=first.lines[:2])
    assert err.value.argument == "start"


def test_line_models_with_and_without_start():
    from skcable.mooring.line3d import takes_start

    class Keyword:
        def solve(self, span, dh, *, start=None): ...

    class Anything:
        def solve(self, span, dh, **options): ...

    assert takes_start(CHAIN) and takes_start(Keyword()) and takes_start(Anything())
    cold = _ColdLine(CHAIN)
    assert not takes_start(cold)
    anchor, fairlead = [0.0, 0.0, -200.0], [780.0, 0.0, -14.0]
    previous = mooring.line_3d(CHAIN, anchor, [785.0, 1.0, -14.5])
    with pytest.raises(InputError) as err:
        mooring.line_3d(cold, anchor, fairlead, start=previous)
    assert err.value.argument == "start"
    warm = mooring.line_3d(CHAIN, anchor, fairlead, start=previous)
    reference = mooring.line_3d(cold, anchor, fairlead)
    np.testing.assert_allclose(warm.force_on_fairlead, reference.force_on_fairlead, rtol=1e-12)
    np.testing.assert_allclose(warm.stiffness(), reference.stiffness(), rtol=1e-9)


# -- a line whose slack lies in a heap on the seabed (H = 0) ------------------------------------
HEAP_FORCE = np.array([4.0e7, 0.0, 0.0])  # N: the body pushed 133 m towards line 0's anchor


def test_equilibrium_with_a_line_in_a_heap_matches_moorpy():
    """Under 4e7 N of surge line 0 goes slack into a heap (MoorPy's profile 4): it gives only its
    vertical force, the two others carry the load. The forces recomputed from the lines balance
    to round-off; MoorPy's System agrees."""
    system = EXAMPLE["system"]()
    eq = system.equilibrium(force=HEAP_FORCE, moment=np.zeros(3))
    assert [line.solution.heap for line in eq.lines] == [True, False, False]
    heap = eq.lines[0]
    assert heap.H == 0.0 and heap.V_B > 0 and heap.solution.x_touchdown == heap.span
    points, tension = heap.profile_with_tension(51)  # vertical under the fairlead, the slack on the seabed
    np.testing.assert_allclose(points[-1], heap.fairlead, rtol=0, atol=1e-9 * heap.span)
    assert np.all(points[:, 2] >= -200.0 - 1e-9) and tension[-1] == pytest.approx(heap.V_B, rel=1e-12)
    q = eq.position
    body = system.body
    R = mooring.rotation_matrix(*q[3:])
    lines = [
        mooring.line_3d(m, a, q[:3] + R @ p)
        for m, a, p in zip(system.lines, system.anchors, body.fairleads, strict=True)
    ]
    forces = np.array([line.force_on_fairlead for line in lines])
    arms = np.array([line.fairlead for line in lines]) - q[:3]
    g, rho = 9.81, 1025.0
    weight, buoyancy = np.array([0, 0, -body.mass * g]), np.array([0, 0, rho * g * body.volume])
    total_force = forces.sum(axis=0) + weight + buoyancy + HEAP_FORCE
    total_force[2] -= rho * g * body.waterplane_area * q[2]
    total_moment = (
        np.cross(arms, forces).sum(axis=0)
        + np.cross(R @ body.center_of_gravity, weight)
        + np.cross(R @ body.metacentre, buoyancy)
    )
    scale = max(line.tension_at_fairlead for line in lines)
    assert np.abs(total_force).max() < 1e-9 * scale
    assert np.abs(total_moment).max() < 1e-9 * scale * 20.0
    # the stiffness at the heap equilibrium: central differences (line 0 stays in its heap)
    K = system.stiffness(q, lines_only=True)
    numeric = _numeric_stiffness(_LinesOnly(system), q, lines_only=True)
    np.testing.assert_allclose(K, numeric, rtol=1e-5, atol=2e-6 * np.abs(K).max())
    if importlib.util.find_spec("moorpy") is None:
        return
    r6, tensions, K_moorpy, ms = EXAMPLE["moorpy_solve"](HEAP_FORCE, np.zeros(3))
    assert ms.lineList[0].info["ProfileType"] == 4
    np.testing.assert_allclose(eq.position[:3], r6[:3], atol=1e-5)
    np.testing.assert_allclose(eq.position[3:], r6[3:], atol=1e-8)
    np.testing.assert_allclose([line.tension_at_fairlead for line in eq.lines], tensions, rtol=1e-7)


# -- D3: lines that start slack on the seabed ----------------------------------------------
def slack_scene(seed):
    """A point buoy held by 3-4 chains from anchors around it, each chain longer than its
    L-shape at the buoy's start (its slack in a heap, H = 0: no horizontal stiffness
    there), pushed by a horizontal force that some of them can hold."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 5))
    depth = float(rng.uniform(50.0, 300.0))
    radius = float(rng.uniform(1.0, 4.0)) * depth
    angles = np.radians(rng.uniform(0, 360) + np.arange(n) * 360 / n + rng.uniform(-15, 15, n))
    anchors = np.column_stack([radius * np.cos(angles), radius * np.sin(angles), np.full(n, -depth)])
    w, EA = float(rng.uniform(200.0, 2000.0)), float(rng.uniform(1e8, 1e9))
    length = (radius + depth) * float(rng.uniform(1.02, 1.3))
    chain = mooring.Line([mooring.Segment(length, w, EA)], seabed=0.0)
    volume = 2.0 * w * depth * n / (1025.0 * 9.81)
    buoy = mooring.PointBody(volume=volume, waterplane_area=float(rng.uniform(20.0, 500.0)))
    push, phi = float(rng.uniform(0.15, 1.5)) * w * depth, rng.uniform(0.0, 2.0 * np.pi)
    force = np.array([push * np.cos(phi), push * np.sin(phi), 0.0])
    return mooring.MooringSystem(buoy, [chain] * n, anchors, depth=depth), force, (length, w, EA)


def _recount(system, eq, force, chain):
    """Net force on the buoy from the equilibrium's position, each chain re-solved by the
    seabed closed form (`elastic_catenary`, not `Line`), the buoy's own loads written here."""
    length, w, EA = chain
    p = eq.position
    total = np.array(force, dtype=float)
    for anchor in system.anchors:
        d = p - anchor
        span = float(np.hypot(d[0], d[1]))
        sol = cable.elastic_catenary(span, float(d[2]), w, EA, length=length, seabed=0.0)
        total += [-sol.H * d[0] / span, -sol.H * d[1] / span, -sol.V_B]
    body = system.body
    total[2] += 1025.0 * 9.81 * (body.volume - body.waterplane_area * p[2])
    return total


@pytest.mark.parametrize("seed", range(12))
def test_equilibrium_from_slack_lines(seed):
    system, force, chain = slack_scene(seed)
    start = system.solve_lines(np.zeros(3))
    assert all(line.solution.heap for line in start)  # every chain slack at the start
    assert np.abs(system.stiffness(np.zeros(3))[:2, :2]).max() == 0.0  # no horizontal stiffness there
    eq = system.equilibrium(force=force)
    assert eq.stable and any(line.H > 0 for line in eq.lines)
    scale = max(np.abs(eq.fairlead_forces).max(), np.linalg.norm(force))
    assert np.abs(_recount(system, eq, force, chain)).max() < 1e-8 * scale
    # a start beyond the slack region converges to the same equilibrium
    far = system.equilibrium(force=force, start=eq.position + [20.0, -10.0, 0.0])
    np.testing.assert_allclose(far.position, eq.position, atol=1e-7 * system.depth)


def test_slack_start_matches_moorpy():
    moorpy = pytest.importorskip("moorpy")
    for seed in range(4):
        system, force, (length, w, EA) = slack_scene(seed)
        eq = system.equilibrium(force=force)
        ms = moorpy.System(depth=system.depth)
        ms.setLineType(dnommm=100, material="chain", name="chain")
        ms.lineTypes["chain"].update(w=w, EA=EA, m=w / 9.81, d_vol=0.0)
        body = system.body
        ms.addBody(0, np.zeros(6), v=body.volume, AWP=body.waterplane_area, f6Ext=np.r_[force, 0, 0, 0],
                   DOFs=[0, 1, 2])  # fmt: skip
        for i, anchor in enumerate(system.anchors):
            ms.addPoint(1, anchor)
            ms.addPoint(1, np.zeros(3))
            ms.bodyList[0].attachPoint(2 * i + 2, np.zeros(3))
            ms.addLine(length, "chain", pointA=2 * i + 1, pointB=2 * i + 2)
        ms.initialize()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # MoorPy divides by the zero arm of its points
            assert ms.solveEquilibrium(tol=1e-8, maxIter=500)
        # MoorPy solves each line to 1e-4 m on its end point
        np.testing.assert_allclose(eq.position, ms.bodyList[0].r6[:3], atol=1e-4)


# -- D6: unstable (capsized) equilibria ------------------------------------------------------
def _turned(angle):
    """The example's platform and lines turned by ``angle`` about z (anchors, fairleads, loads)."""
    c, s = np.cos(angle), np.sin(angle)
    Rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    system = EXAMPLE["system"]()
    body = system.body
    turned = mooring.RigidBody(
        body.fairleads @ Rz.T,
        mass=body.mass,
        volume=body.volume,
        center_of_gravity=body.center_of_gravity,
        metacentre=body.metacentre,
        waterplane_area=body.waterplane_area,
    )
    moored = mooring.MooringSystem(turned, system.lines, system.anchors @ Rz.T, depth=system.depth)
    return moored, Rz @ np.array(EXAMPLE["FORCE"]), Rz @ np.array(EXAMPLE["MOMENT"])


def _upside_down_root(system, force, moment):
    """The capsized root Newton reaches from a start heeled by 2.8 rad (no stability check)."""
    from skcable.mooring.equilibrium import _Newton

    solve = _Newton(system, np.concatenate([force, moment]), 1e-10, 60)
    return solve.run(np.array([0.0, 0.0, 0.0, 2.8, 0.1, 0.0]))


@pytest.mark.parametrize("angle", [0.0, 0.7, 2.0])
def test_capsized_root_is_passed_over_for_the_stable_one(angle):
    system, force, moment = _turned(angle)
    root = _upside_down_root(system, force, moment)
    R = system.body.rotation(root.x)
    assert np.arccos(R[2, 2]) > 2.5  # capsized
    K = root.state[1]
    arm = np.abs(system.body.fairleads).max()
    units = np.r_[np.ones(3), np.full(3, arm)]
    Ks = K / units[:, None] / units[None, :]
    assert np.linalg.eigvalsh(0.5 * (Ks + Ks.T))[0] < 0  # unstable, by the eigenvalues written here
    eq = system.equilibrium(force=force, moment=moment, start=[0.0, 0.0, 0.0, 2.8, 0.1, 0.0])
    assert eq.stable and eq.eigenvalues[0] > 0 and len(eq.unstable_found) >= 1
    # the stable equilibrium of the scene as the default start finds it, turned
    upright = EXAMPLE["system"]().equilibrium(force=EXAMPLE["FORCE"], moment=EXAMPLE["MOMENT"])
    c, s = np.cos(angle), np.sin(angle)
    Rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    np.testing.assert_allclose(eq.offset, Rz @ upright.offset, atol=1e-6)
    assert eq.heel == pytest.approx(upright.heel, abs=1e-9)
    np.testing.assert_allclose(
        sorted(line.tension_at_fairlead for line in eq.lines),
        sorted(line.tension_at_fairlead for line in upright.lines),
        rtol=1e-8,
    )


def test_unstable_equilibrium_is_flagged_and_warned():
    system, force, moment = _turned(0.0)
    root = _upside_down_root(system, force, moment)
    # from the capsized root itself, with no iteration left for a restart to leave it
    with pytest.warns(PlausibilityWarning, match="unstable"):
        eq = system.equilibrium(force=force, moment=moment, start=root.x, max_iter=1)
    assert not eq.stable and eq.eigenvalues[0] < 0 and "UNSTABLE" in repr(eq)


# -- D7: untyped escapes -------------------------------------------------------------------
def test_a_missing_line_model_is_named():
    for model in (None, 3.0, "chain"):
        with pytest.raises(InputError) as err:
            mooring.line_3d(model, (0.0, 0.0, -200.0), (500.0, 0.0, -10.0))
        assert err.value.argument == "model"


def test_lines_must_be_a_list_of_models():
    chain = mooring.Line([mooring.Segment(850.0, 1000.0, 5e8)], seabed=0.0)
    anchors = [[800.0, 0.0, -200.0]]
    for lines in (5, None, chain, "chain", {0: chain}, 2.5):
        with pytest.raises(InputError) as err:
            mooring.MooringSystem(mooring.PointBody(volume=100.0), lines, anchors)
        assert err.value.argument == "lines"
    assert len(mooring.MooringSystem(mooring.PointBody(volume=100.0), (chain,), anchors).lines) == 1
