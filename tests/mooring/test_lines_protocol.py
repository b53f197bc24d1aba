"""The mooring lines' solutions satisfy the result protocol (`skcable.results`).

`SeabedCatenary` (taut, with friction, a heap, the anchor above the seabed),
`SlopedSeabedCatenary` (grounded and free) and `LineSolution` (a chain-wire-chain line with a
clump, a heap) against checks computed here: the end tensions from the end forces, the
profile's ends at A and B, the tension at the ends, the stiffness against central
differences of the solver, the writers read back. ``LINE_FACTORIES`` is the registry of
this module (the shared ``tests/test_result_protocol.py`` takes the same form).
"""

import meshio
import numpy as np
import pytest

from skcable import cable, mooring
from skcable.results import CableResult

W, EA = 1000.0, 5e8
CHAIN, WIRE = mooring.Segment(200.0, 1500.0, 8e8), mooring.Segment(500.0, 300.0, 4e8)


def _multi(span, dh, clump=2e4, seabed=0.0):
    friction = 0.0 if seabed is None else 0.3
    line = mooring.Line(
        [CHAIN, WIRE, CHAIN], [mooring.ClumpWeight(1, clump)], seabed=seabed, friction=friction
    )
    return line.solve(span, dh)


def _heap(span, dh):
    return mooring.Line([mooring.Segment(400.0, W, EA)], seabed=0.0).solve(span, dh)


#: name -> (solve(span, dh), span, dh): every mooring-line solution type in its regimes
LINE_FACTORIES = {
    "seabed": (lambda a, b: cable.elastic_catenary(a, b, W, EA, length=850.0, seabed=0.0), 800.0, 150.0),
    "seabed friction": (
        lambda a, b: cable.elastic_catenary(a, b, W, EA, length=850.0, seabed=0.0, friction=0.5),
        800.0,
        150.0,
    ),
    "seabed heap": (lambda a, b: cable.elastic_catenary(a, b, W, EA, length=400.0, seabed=0.0), 100.0, 150.0),
    "anchor above seabed": (
        lambda a, b: cable.elastic_catenary(a, b, W, EA, length=900.0, seabed=-40.0),
        800.0,
        150.0,
    ),
    "sloped grounded": (
        lambda a, b: cable.sloped_seabed_catenary(a, b, W, EA, length=850.0, seabed_slope=0.05, friction=0.3),
        800.0,
        150.0,
    ),
    "sloped downhill": (
        lambda a, b: cable.sloped_seabed_catenary(a, b, W, EA, length=850.0, seabed_slope=-0.1),
        800.0,
        150.0,
    ),
    "sloped free": (
        lambda a, b: cable.sloped_seabed_catenary(a, b, W, EA, length=820.0, seabed_slope=-0.3),
        780.0,
        150.0,
    ),
    "line": (_multi, 780.0, 200.0),
    "line free": (lambda a, b: _multi(a, b, seabed=None), 800.0, 300.0),
    "line heap": (
        lambda a, b: mooring.Line([mooring.Segment(400.0, W, EA)], seabed=0.0).solve(a, b),
        100.0,
        150.0,
    ),
}


@pytest.fixture(params=sorted(LINE_FACTORIES))
def case(request):
    solve, span, dh = LINE_FACTORIES[request.param]
    return request.param, solve, span, dh, solve(span, dh)


def test_end_forces_and_profile(case):
    name, _, span, dh, r = case
    assert isinstance(r, CableResult)
    assert r.T_A == pytest.approx(np.hypot(r.H_A, r.V_A), rel=1e-12, abs=1e-9 * r.T_B)
    assert r.T_B == pytest.approx(np.hypot(r.H_B, r.V_B), rel=1e-12)
    n = 41
    xy = r.profile(n)
    assert xy.shape == (n, 2)
    np.testing.assert_allclose(xy[0], [0.0, 0.0], atol=1e-9 * span)
    np.testing.assert_allclose(xy[-1], [span, dh], atol=1e-9 * span)
    np.testing.assert_allclose(r.xy(np.linspace(0.0, r.length, n)), xy, rtol=0, atol=0)
    assert r.T_of_s(0.0) == pytest.approx(r.T_A, rel=1e-9, abs=1e-9 * r.T_B)
    assert r.T_of_s(r.length) == pytest.approx(r.T_B, rel=1e-9)
    # the stretched length of the profile is at least its chord from A to B
    assert np.hypot(*np.diff(xy, axis=0).T).sum() >= np.hypot(span, dh) * (1 - 1e-9)
    assert "H=" in repr(r) and "T_B=" in repr(r)


def test_stiffness_against_central_differences(case):
    name, solve, span, dh, r = case
    K = r.stiffness()
    assert K.shape == (2, 2)
    np.testing.assert_array_equal(cable.fairlead_stiffness(r), K)
    if "heap" in name:  # one-sided: only dV_B/d(dh) (see SeabedCatenary.stiffness)
        h = 1e-3
        numeric = (solve(span, dh + h).V_B - solve(span, dh - h).V_B) / (2 * h)
        assert K[1, 1] == pytest.approx(numeric, rel=1e-6)
        return
    h = 1e-4 * np.hypot(span, dh)
    columns = []
    for ds, dz in ((h, 0.0), (0.0, h)):
        plus, minus = solve(span + ds, dh + dz), solve(span - ds, dh - dz)
        columns.append([(plus.H_B - minus.H_B) / (2 * h), (plus.V_B - minus.V_B) / (2 * h)])
    np.testing.assert_allclose(K, np.array(columns).T, rtol=1e-5, atol=1e-6 * np.abs(K).max())


def test_tables_and_files(case, tmp_path):
    name, _, span, dh, r = case
    table = r.tensions()
    assert table["T_lower"].iloc[0] == pytest.approx(r.T_A, rel=1e-9, abs=1e-9 * r.T_B)
    assert table["T_upper"].iloc[-1] == pytest.approx(r.T_B, rel=1e-12)
    frame = r.to_frame(11)
    assert list(frame.columns) == ["s", "x", "y", "T"] and len(frame) == 11
    assert frame["s"].iloc[-1] == pytest.approx(r.length)
    path = r.to_vtk(tmp_path / "line.vtu", n=21)
    mesh = meshio.read(path)
    assert mesh.points.shape == (21, 3)
    np.testing.assert_allclose(mesh.points[-1, :2], [span, dh], atol=1e-9 * span)
    np.testing.assert_allclose(mesh.point_data["tension_N"][[0, -1]], [r.T_of_s(0.0), r.T_B], rtol=1e-12)


def test_outline_keeps_the_joints_and_the_touchdown():
    r = _multi(780.0, 200.0)
    outline = r.outline(20)
    # the joints (x_joints, y_joints) are points of the outline, not of the 20 evenly spaced
    for x, y in zip(r.x_joints, r.y_joints, strict=True):
        assert np.min(np.hypot(outline[:, 0] - x, outline[:, 1] - y)) < 1e-9
    assert np.min(np.abs(outline[:, 0] - r.x_touchdown)) < 1e-9
    assert len(outline) > 20 and r.profile(20).shape == (20, 2)


def test_line_3d_profile_over_unstretched_arc_length():
    line = mooring.Line([mooring.Segment(850.0, W, EA)], seabed=0.0)
    anchor, fairlead = np.array([0.0, 0.0, -200.0]), np.array([500.0, 300.0, -14.0])
    l3 = mooring.line_3d(line, anchor, fairlead)
    points = l3.profile(31)
    assert points.shape == (31, 3)
    np.testing.assert_allclose(points[[0, -1]], [anchor, fairlead], atol=1e-9 * 600)
    # the points are the 2-D solution's at the same unstretched arc lengths, turned into space
    s = np.linspace(0.0, line.length, 31)
    xy = l3.solution.xy(s)
    np.testing.assert_allclose(points[:, 2] - anchor[2], xy[:, 1], atol=1e-9)
    np.testing.assert_allclose(np.hypot(*(points[:, :2] - anchor[:2]).T), xy[:, 0], atol=1e-9)
    assert l3.T_of_s(line.length) == pytest.approx(l3.tension_at_fairlead, rel=1e-12)
    tension = l3.profile_with_tension(31)[1]
    np.testing.assert_allclose(tension, l3.solution.T_of_s(s), rtol=0, atol=0)
