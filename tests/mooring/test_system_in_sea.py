"""Lines in the sea (a current, a bathymetry, a nonlinear axial law) in a mooring system built point
by point (issues 22 and 23): ``MooringSystem(depth=).add_line`` takes a line in the sea with one
fixed end, either order of its points, and solves it by ``mooring.line_3d``'s choice of model.

The references are written here: each line recounted by ``mooring.line_3d`` (or
``mooring.line_between`` for a plain line) at the solved positions, its segments and seabed stated
from the anchor in the test, and the force balance at every body and free point; the same scene
posed through the one-body shortcut; the stiffness against central differences.
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from skcable import InputError, mooring
from skcable.mooring import axial
from skcable.mooring.bathymetry import Plane
from tests.mooring.test_mooring_system import _numeric
from tests.test_pickle import assert_same

RHO, G = 1025.0, 9.81
DEPTH = 200.0
CURRENT = (0.6, 0.25)
FRICTION = 0.0
HULL_LINE = 830.0  # semi-taut: the lines hang clear of the seabed


MBL = 6e6


def chain_segment(length=850.0):
    return mooring.Segment(length, 1000.0, 5e8, mbl=MBL, diameter=0.1, cd_normal=1.2, cd_tangential=0.1)


def anchors_at(radius, angles_deg, z=-DEPTH):
    angles = np.radians(angles_deg)
    return np.column_stack([radius * np.cos(angles), radius * np.sin(angles), np.full(len(angles), z)])


# -- a hull held by two lines in a current and a bridle: an anchor line in the current to a free --------
# -- junction (given from the junction: its fixed end is b), and a plain line up to the hull ------------
def hull_and_junction():
    system = mooring.MooringSystem(depth=DEPTH)
    hull = system.add_body(
        mooring.PointBody(volume=60.0, mass=40e3, waterplane_area=80.0), position=(0, 0, 0)
    )
    top = system.add_point((0.0, 0.0, 0.0), body=hull)
    in_current = mooring.Line([chain_segment(HULL_LINE)], seabed=0.0, friction=FRICTION, current=CURRENT)
    anchors = anchors_at(800.0, [60.0, 300.0])
    for anchor in anchors:
        system.add_line(in_current, system.add_point(anchor, fixed=True), top)
    junction = system.add_point((-300.0, 0.0, -120.0), mass=2e3, volume=8.0)
    anchor3 = system.add_point((-800.0, 0.0, -DEPTH), fixed=True)
    lower = mooring.Line(
        [chain_segment(300.0), chain_segment(215.0)], seabed=0.0, friction=FRICTION, current=CURRENT
    )
    system.add_line(lower, junction, anchor3)  # the fixed end is b: solved from it
    plain = mooring.Line([mooring.Segment(360.0, 400.0, 3e8)])
    system.add_line(plain, junction, top)  # between two moving points: the system's own model
    return system, hull, junction, (anchors, np.array([-800.0, 0.0, -DEPTH]))


LOAD = np.array([2e5, 5e4, 0.0])


@pytest.fixture(scope="module")
def solved():
    """The hull and junction scene at equilibrium under ``LOAD`` on the hull (solved once)."""
    system, hull, junction, ends = hull_and_junction()
    return system, hull, junction, ends, system.equilibrium(force={hull: LOAD})


def _recounted_line(segments, anchor, end, seabed_height):
    """The line from ``anchor`` to ``end`` in the current, its seabed a float relative to the anchor:
    its force on ``end`` (N), by ``mooring.line_3d``."""
    line = mooring.Line(segments, seabed=seabed_height - anchor[2], friction=FRICTION, current=CURRENT)
    return mooring.line_3d(line, anchor, end).force_on_fairlead


def test_equilibrium_balances_each_body_and_free_point_recounted_by_line_3d(solved):
    system, hull, junction, (anchors, anchor3), eq = solved
    external = LOAD
    x_hull, x_junction = eq.bodies[0].position, eq.points[junction.index].position
    on_hull = [_recounted_line([chain_segment(HULL_LINE)], a, x_hull, -DEPTH) for a in anchors]
    # the lower leg recounted from its anchor: its segments stated in reverse (the junction is its a)
    on_junction = _recounted_line([chain_segment(215.0), chain_segment(300.0)], anchor3, x_junction, -DEPTH)
    plain = mooring.line_between(
        mooring.Line([mooring.Segment(360.0, 400.0, 3e8)]), x_junction, x_hull, depth=DEPTH
    )
    own_hull = np.array([0.0, 0.0, RHO * G * 60.0 - 40e3 * G - RHO * G * 80.0 * x_hull[2]])
    own_junction = np.array([0.0, 0.0, RHO * G * 8.0 - 2e3 * G])
    hull_sum = sum(on_hull) + plain.end_forces[1] + own_hull + external
    junction_sum = on_junction + plain.end_forces[0] + own_junction
    scale = max(np.linalg.norm(f) for f in [*on_hull, on_junction])
    assert np.abs(hull_sum).max() < 1e-8 * scale
    assert np.abs(junction_sum).max() < 1e-8 * scale
    # the system's own line forces are the recounted ones, at each end in the order a, b
    np.testing.assert_allclose(eq.lines[2].end_forces[0], on_junction, rtol=0, atol=1e-9 * scale)
    assert eq.lines[2].reversed and not eq.lines[0].reversed


def test_checks_tables_and_vtk_show_the_model_that_ran(solved, tmp_path):
    system, hull, junction, _, eq = solved
    checks = eq.line_checks()
    assert list(checks["model"]) == ["3-D line BVP", "3-D line BVP", "3-D line BVP", "free"]
    assert list(checks["lower_end"])[:3] == ["a", "a", "b"]
    table = eq.tensions()
    assert set(table.loc[table["line"] < 3, "model"]) == {"3-D line BVP"}
    # the reversed leg's table runs from the junction (a): its first row is the 300 m segment,
    # its T at a the tension at the junction
    leg = table[table["line"] == 2]
    assert list(leg["length"]) == [300.0, 215.0]
    T_a = float(np.linalg.norm(eq.lines[2].end_forces[0]))
    assert abs(float(leg["T_a"].iloc[0]) - T_a) < 1e-9 * T_a
    # the tension field at the junction, s = 0 from a, is the field at s = L from the anchor
    sea = eq.lines[2].sea
    assert float(eq.lines[2].T_of_s(0.0)) == float(sea.T_of_s(515.0))
    assert float(eq.lines[2].T_of_s(515.0)) == float(sea.T_of_s(0.0))
    # the segment check of the leg's segment at the junction: its largest tension, that of the
    # hanging chain's upper end, the junction's (to the BVP's tension field there)
    row = eq.segment_checks(1.67).query("line == 2 and segment == 0").iloc[0]
    assert abs(row["T_max"] - T_a) < 1e-5 * T_a and row["utilisation"] == 1.67 * row["T_max"] / MBL
    points, tension = eq.lines[2].profile_with_tension(11)
    np.testing.assert_allclose(points[0], eq.points[junction.index].position, atol=1e-9)
    np.testing.assert_allclose(points[-1], (-800.0, 0.0, -DEPTH), atol=1e-9)
    path = eq.to_vtk(tmp_path / "system.vtu", n=11)
    import meshio

    mesh = meshio.read(path)
    assert mesh.point_data["tension_N"].size >= 4 * 11


# -- a buoy (a free point) held by three lines in a current: against the one-body shortcut ---------------
def test_a_free_buoy_in_a_current_matches_the_shortcut_point_body():
    anchors = anchors_at(500.0, [0.0, 120.0, 240.0])
    line = mooring.Line(
        [mooring.Segment(480.0, 300.0, 2e8, diameter=0.06, cd_normal=1.2)], seabed=0.0, current=CURRENT
    )
    law = axial.StrainTable(strain=[0.0, 0.01, 0.02, 0.04], tension=[0.0, 1.5e6, 4e6, 1.2e7])
    rope = mooring.Line([mooring.Segment(470.0, 40.0, law, diameter=0.12, cd_normal=1.0)], seabed=0.0)
    models = [line, rope, line]
    shortcut = mooring.MooringSystem(mooring.PointBody(volume=40.0, mass=5e3), models, anchors)
    ref = shortcut.equilibrium(start=(0.0, 0.0, -60.0))

    system = mooring.MooringSystem(depth=DEPTH)
    buoy = system.add_point((0.0, 0.0, -60.0), volume=40.0, mass=5e3)
    for i, (model, anchor) in enumerate(zip(models, anchors, strict=True)):
        a = system.add_point(anchor, fixed=True)
        system.add_line(model, *((buoy, a) if i == 1 else (a, buoy)))  # the rope given from the buoy
    eq = system.equilibrium()
    np.testing.assert_allclose(eq.points[buoy.index].position, ref.position, rtol=0, atol=1e-7)
    assert list(eq.line_checks()["model"]) == ["3-D line BVP", "closed form (axial laws)", "3-D line BVP"]


def test_stiffness_matches_central_differences(solved):
    system, hull, junction, _, eq = solved
    force = {hull: LOAD}
    q = eq.position + np.r_[2.0, -1.0, 0.1, 1.5, 0.5, -1.0]  # off equilibrium
    K = system.stiffness(q)
    numeric = _numeric(system, q, lambda x: system.net_force(x, force=force), h=(1e-3, 1e-6))
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-6 * np.abs(K).max())


def test_rigid_body_stiffness_matches_central_differences_on_a_shaped_seabed():
    bed = Plane(-DEPTH, (0.02, -0.01))
    seg = chain_segment()
    anchors = anchors_at(800.0, [0.0, 120.0, 240.0], 0.0)
    anchors[:, 2] = bed.height(anchors[:, 0], anchors[:, 1])
    fairleads = anchors_at(20.0, [0.0, 120.0, 240.0], -10.0)
    system = mooring.MooringSystem(depth=DEPTH + 30.0)  # below the sloped seabed: only drawn
    hull = system.add_body(mooring.RigidBody(waterplane_area=500.0))
    for i, (anchor, fairlead) in enumerate(zip(anchors, fairleads, strict=True)):
        a, b = system.add_point(anchor, fixed=True), system.add_point(fairlead, body=hull)
        line = mooring.Line([seg], seabed=bed, current=CURRENT if i else None)
        system.add_line(line, *((b, a) if i == 2 else (a, b)))
    eq = system.equilibrium(force=(1e5, 0.0, 0.0))
    assert list(eq.line_checks()["model"]) == ["3-D line BVP"] * 3
    q = eq.position + np.r_[1.0, -0.5, 0.1, 0.01, -0.01, 0.02]
    K = system.stiffness(q)
    numeric = _numeric(system, q, lambda x: system.net_force(x, force=(1e5, 0.0, 0.0)), h=(1e-3, 1e-6))
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-6 * np.abs(K).max())


def test_a_line_in_the_sea_between_two_moving_points_is_refused_by_name():
    system = mooring.MooringSystem(depth=DEPTH)
    hull = system.add_body(mooring.PointBody(waterplane_area=80.0))
    top = system.add_point((0.0, 0.0, 0.0), body=hull)
    junction = system.add_point((-300.0, 0.0, -120.0), mass=2e3)
    system.add_line(
        mooring.Line([chain_segment()], current=CURRENT), system.add_point((800, 0, -DEPTH), fixed=True), top
    )
    with pytest.raises(InputError) as caught:
        system.add_line(mooring.Line([chain_segment(300.0)], current=CURRENT), junction, top)
    assert caught.value.argument == "line"
    assert "line 1" in str(caught.value) and "both ends moving" in str(caught.value)
    assert "current" in str(caught.value)


def test_a_system_with_a_line_in_the_sea_pickles(solved):
    eq = solved[-1]
    copy = pickle.loads(pickle.dumps(eq))
    assert_same(eq.position, copy.position)
    for a, b in zip(eq.lines, copy.lines, strict=True):
        assert_same(a.end_forces, b.end_forces)
    again = copy.system.equilibrium(force={copy.system.bodies[0]: LOAD}, start=copy)
    np.testing.assert_allclose(again.position, eq.position, rtol=0, atol=1e-9)


def test_a_copy_with_replaced_parts_keeps_its_lines_in_the_sea(solved):
    system, hull, junction, _, eq = solved
    other = system.replaced()  # as failure cases and design to a target build theirs
    assert [h.sea is not None for h in other.mooring_lines] == [True, True, True, False]
    lines = other.solve_lines(eq.position)
    for a, b in zip(eq.lines, lines, strict=True):
        np.testing.assert_allclose(b.end_forces, a.end_forces, rtol=0, atol=1e-6 * np.abs(a.end_forces).max())
