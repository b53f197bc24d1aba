"""Line failure: the damaged system's equilibrium and the tension redistribution beside the intact one.

References: each line's closure at 30 digits with mpmath and the force balance on the damaged
system's body (`tests.mooring.mooring_reference`), and MoorPy's ``System`` built without the line.
"""

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError
from tests.mooring.mooring_reference import balance, reference_forces

W, EA, LENGTH, DEPTH = 2456.82, 1.2326e9, 850.0, 200.0
HEADINGS = np.radians([0.0, 120.0, 240.0])
FORCE, MOMENT = (1.0e6, 3.0e5, 0.0), (0.0, 0.0, 2.0e6)
OWN = dict(mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5), metacentre=(0, 0, 10), waterplane_area=600.0)


def spread():
    system = mooring.MooringSystem(depth=DEPTH)
    hull = system.add_body(mooring.RigidBody(**OWN))
    line = mooring.Line([mooring.Segment(LENGTH, W, EA)])
    handles = []
    for h in HEADINGS:
        c, s = np.cos(h), np.sin(h)
        a = system.add_point([800 * c, 800 * s, -DEPTH], fixed=True)
        handles.append(system.add_line(line, a, system.add_point([20 * c, 20 * s, -14.0], body=hull)))
    return system, hull, handles


def test_failure_balances_the_damaged_system():
    system, hull, handles = spread()
    case = system.failure([handles[2]], force=FORCE, moment=MOMENT)
    damaged = case.damaged
    assert damaged.line_indices == [0, 1] and damaged.stable
    forces = [reference_forces(line, (W, EA, LENGTH), DEPTH) for line in damaged.lines]
    for line, F in zip(damaged.lines, forces, strict=True):
        np.testing.assert_allclose(line.end_forces, F, rtol=1e-10, atol=1e-6)
    net = balance(damaged, forces, {("body", 0): np.r_[FORCE, MOMENT]})[("body", 0)]
    scale = max(max(np.abs(F).max() for F in forces), OWN["mass"] * 9.81)  # the solver's force scale
    assert np.abs(net[:3]).max() < 1e-9 * scale and np.abs(net[3:]).max() < 1e-9 * scale * 20.0
    table = case.redistribution()
    assert table["failed"].tolist() == [False, False, True] and table["T_damaged"].iloc[2] == 0.0
    for k in (0, 1):
        T = np.linalg.norm(damaged.lines[k].end_forces, axis=1).max()
        assert table["T_damaged"].iloc[k] == pytest.approx(T, rel=1e-14)
    assert (table["change"].iloc[:2] > 0).any()  # the others take the load
    offsets = case.offsets()
    assert offsets["distance"].iloc[0] > 1.0


def test_failure_matches_moorpy_without_the_line():
    moorpy = pytest.importorskip("moorpy")
    system, hull, handles = spread()
    damaged = system.failure([handles[0]], force=FORCE, moment=MOMENT).damaged
    ms = moorpy.System(depth=DEPTH)
    ms.setLineType(dnommm=120, material="chain", name="chain")
    ms.lineTypes["chain"].update(w=W, EA=EA)
    own = dict(m=OWN["mass"], v=OWN["volume"], rCG=OWN["center_of_gravity"], AWP=OWN["waterplane_area"])
    body = ms.addBody(0, np.zeros(6), **own, rM=OWN["metacentre"], f6Ext=np.r_[FORCE, MOMENT])
    for h in HEADINGS[1:]:  # built without the failed line
        c, s = np.cos(h), np.sin(h)
        ms.addPoint(1, [800 * c, 800 * s, -DEPTH])
        anchor = len(ms.pointList)
        ms.addPoint(1, [20 * c, 20 * s, -14.0])
        fair = len(ms.pointList)
        body.attachPoint(fair, [20 * c, 20 * s, -14.0])
        ms.addLine(LENGTH, "chain", pointA=anchor, pointB=fair)
    ms.initialize()
    ms.solveEquilibrium(tol=1e-8, maxIter=500)
    np.testing.assert_allclose(damaged.bodies[0].position[:3], body.r6[:3], atol=1e-4)
    np.testing.assert_allclose(damaged.bodies[0].position[3:], body.r6[3:], atol=1e-7)


def test_each_line_failing_alone_and_refusals():
    system, hull, handles = spread()
    cases = system.failure_cases(force=FORCE, moment=MOMENT)
    assert len(cases) == 3 and all(c.intact is cases[0].intact for c in cases)
    assert [c.failed[0].index for c in cases] == [0, 1, 2]
    with pytest.raises(InputError) as err:
        system.failure([], force=FORCE)
    assert err.value.argument == "failed"
    with pytest.raises(InputError) as err:
        system.equilibrium(without=handles)  # nothing holds the body
    assert err.value.argument == "bodies"
    other = spread()[2][0]
    with pytest.raises(InputError) as err:
        system.equilibrium(without=[other])
    assert err.value.argument == "without"
