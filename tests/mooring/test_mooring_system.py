"""Mooring systems of bodies, points and lines: MoorPy's system scenes, a shared mooring, a bridle.

References: each line's closure solved at 30 digits with mpmath and the force balance at every
free point and body from those forces (`tests.mooring.mooring_reference`); central differences of
the net loads for every stiffness (rotations perturbed with scipy's `Rotation`); the condensed
body stiffness against the free points re-solved at each perturbed body position; MoorPy's
``System`` on the same scene (M. Hall's quasi-static mooring code at NREL), to its tolerance.
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from skcable import mooring
from skcable.errors import ConvergenceError, InputError
from tests.mooring.mooring_reference import balance, reference_forces
from tests.test_repr import check_repr

W, EA = 2456.82, 1.2326e9  # studless chain of 120 mm (MoorPy's chain type): N/m in water, N


def chain(length, friction=0.0):
    return mooring.Line([mooring.Segment(length, W, EA)], friction=friction)


def _reference(eq, props, friction=0.0):
    """mpmath end forces of every line of ``eq`` (one-segment lines; ``props[k] = (w, EA, L)``)."""
    return [
        reference_forces(line, props[k], eq.system.depth, friction)
        for k, line in zip(eq.line_indices, eq.lines, strict=True)
    ]


def _check_balance(eq, props, external=None, rtol=1e-9):
    forces = _reference(eq, props)
    for line, F in zip(eq.lines, forces, strict=True):
        np.testing.assert_allclose(line.end_forces, F, rtol=1e-10, atol=1e-10 * np.abs(F).max())
    own = [abs(b.body.weight[2]) + b.body.buoyancy[2] for b in eq.bodies]
    own += [np.abs(p.own_force).max() for p in eq.system.points]
    scale = max(max(np.abs(F).max() for F in forces), *own)  # the equilibrium's force scale
    for key, net in balance(eq, forces, external).items():
        assert np.abs(net[:3]).max() < rtol * scale, (key, net)
        if key[0] == "body":
            arm = max(1.0, np.abs(eq.system.layout.local[key[1]]).max())
            assert np.abs(net[3:]).max() < rtol * scale * arm, (key, net)


# -- MoorPy's test_basicU: a U line between two anchors, two buoyant free points --------------------------
def basic_u():
    system = mooring.MooringSystem(depth=100.0)
    anchor_a = system.add_point([-200.0, 0.0, -100.0], fixed=True)
    float_a = system.add_point([-100.0, 0.0, -50.0], volume=50.0)
    float_b = system.add_point([100.0, 0.0, -40.0], volume=50.0)
    anchor_b = system.add_point([200.0, 0.0, -100.0], fixed=True)
    for L, a, b in ((120.0, anchor_a, float_a), (250.0, float_a, float_b), (120.0, float_b, anchor_b)):
        system.add_line(chain(L), a, b)
    return system, [(W, EA, 120.0), (W, EA, 250.0), (W, EA, 120.0)]


def test_basic_u_balances_at_every_point():
    system, props = basic_u()
    eq = system.equilibrium()
    assert [line.model for line in eq.lines] == ["grounded", "touchdown between the ends", "grounded"]
    _check_balance(eq, props)
    # the scene is symmetric about x = 0: so is its equilibrium
    a, b = eq.points[1].position, eq.points[2].position
    np.testing.assert_allclose(a * [-1, 1, 1], b, atol=1e-9)
    assert eq.stable


def test_basic_u_matches_moorpy():
    moorpy = pytest.importorskip("moorpy")
    ms = moorpy.System(depth=100)
    ms.setLineType(dnommm=120, material="chain", name="chain")
    ms.lineTypes["chain"].update(w=W, EA=EA)
    for kind, r, v in (
        (1, [-200, 0, -100], 0),
        (0, [-100, 0, -50], 50),
        (0, [100, 0, -40], 50),
        (1, [200, 0, -100], 0),
    ):
        ms.addPoint(kind, r, m=0, v=v)
    for L, a, b in ((120, 1, 2), (250, 2, 3), (120, 3, 4)):
        ms.addLine(L, "chain", pointA=a, pointB=b)
    ms.initialize()
    ms.solveEquilibrium3(tol=1e-6)
    eq = basic_u()[0].equilibrium()
    # MoorPy's own test compares at 1e-3 m; its equilibrium tolerance is on the positions
    np.testing.assert_allclose(eq.points[1].position, ms.pointList[1].r, atol=1e-3)
    np.testing.assert_allclose(eq.points[2].position, ms.pointList[2].r, atol=1e-3)


# -- MoorPy's test_tensions_swap and test_stiffnesses_swap ------------------------------------------------
def _swap_pair():
    system = mooring.MooringSystem(depth=60.0)
    low, high = (
        system.add_point([0.0, 0.0, -60.0], fixed=True),
        system.add_point([100.0, 10.0, -30.0], fixed=True),
    )
    system.add_line(chain(120.0), low, high)
    system.add_line(chain(120.0), high, low)
    return system


def test_tensions_swap():
    system = _swap_pair()
    one, other = system.solve_lines(np.zeros(0))
    assert one.model == other.model == "grounded"
    np.testing.assert_allclose(one.end_forces, other.end_forces[::-1], rtol=1e-13, atol=1e-9)
    for line in (one, other):
        np.testing.assert_allclose(
            line.end_forces, reference_forces(line, (W, EA, 120.0), 60.0), rtol=1e-10, atol=1e-6
        )


def test_tensions_swap_match_moorpy():
    moorpy = pytest.importorskip("moorpy")
    ms = moorpy.System(depth=60)
    ms.setLineType(dnommm=120, material="chain", name="chain")
    ms.lineTypes["chain"].update(w=W, EA=EA)
    ms.addPoint(1, [0, 0, -60])
    ms.addPoint(1, [100, 10, -30])
    ms.addLine(120, "chain", pointA=1, pointB=2)
    ms.addLine(120, "chain", pointA=2, pointB=1)
    ms.initialize()
    one, other = _swap_pair().solve_lines(np.zeros(0))
    # MoorPy's test: atol 10 N (its catenary solved to 1e-4 m on the end point)
    np.testing.assert_allclose(one.end_forces, [ms.lineList[0].fA, ms.lineList[0].fB], atol=10.0)
    np.testing.assert_allclose(other.end_forces, [ms.lineList[1].fA, ms.lineList[1].fB], atol=10.0)
    K = one.stiffness()
    np.testing.assert_allclose(K[3:, 3:], ms.lineList[0].KB, rtol=1e-5, atol=10.0)
    np.testing.assert_allclose(other.stiffness()[:3, :3], ms.lineList[1].KA, rtol=1e-5, atol=10.0)


def test_stiffnesses_swap():
    system = _swap_pair()
    one, other = system.solve_lines(np.zeros(0))
    K1, K2 = one.stiffness(), other.stiffness()
    swap = np.r_[3:6, 0:3]
    np.testing.assert_allclose(K1, K2[np.ix_(swap, swap)], rtol=1e-12, atol=1e-9 * np.abs(K1).max())
    # the free end's block against central differences (the grounded end's vertical is one-sided)
    h = 1e-4
    a, b = system.points[0].position, system.points[1].position
    numeric = np.empty((3, 3))
    for j in range(3):
        step = np.eye(3)[j] * h
        up = mooring.line_between(one.line, a, b + step, depth=60.0).end_forces
        down = mooring.line_between(one.line, a, b - step, depth=60.0).end_forces
        numeric[:, j] = -(up[1] - down[1]) / (2 * h)
    np.testing.assert_allclose(K1[3:, 3:], numeric, rtol=1e-6, atol=1e-6 * np.abs(numeric).max())


# -- a two-turbine shared mooring ----------------------------------------------------------------------
def two_turbines():
    system = mooring.MooringSystem(depth=200.0)
    turbines, props = [], []
    for i, x0 in enumerate((0.0, 1400.0)):
        hull = mooring.RigidBody(
            mass=8.0e6,
            volume=8.2e3,
            center_of_gravity=(0, 0, -5),
            metacentre=(0, 0, 10),
            waterplane_area=600.0,
        )
        turbines.append(system.add_body(hull, position=[x0, 0, 0, 0, 0, 0]))
        for heading in np.radians((120.0, 240.0) if i == 0 else (60.0, -60.0)):
            c, s = np.cos(heading), np.sin(heading)
            anchor = system.add_point([x0 + 800 * c, 800 * s, -200.0], fixed=True)
            system.add_line(chain(850.0), anchor, system.add_point([20 * c, 20 * s, -14.0], body=hull))
            props.append((W, EA, 850.0))
    shared = mooring.Line([mooring.Segment(1500.0, 1000.0, 6.0e8)])  # sags onto the seabed between them
    a = system.add_point([20.0, 0.0, -14.0], body=turbines[0])
    b = system.add_point([-20.0, 0.0, -14.0], body=turbines[1])
    system.add_line(shared, a, b)
    props.append((1000.0, 6.0e8, 1500.0))
    return system, turbines, props


LOADS = ((1.5e6, 3.0e5, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))  # force, moment: on the first turbine


def test_shared_mooring_balances_every_body():
    system, turbines, props = two_turbines()
    force, moment = {turbines[0]: LOADS[0]}, {turbines[0]: (1e6, 5e6, 2e6)}
    eq = system.equilibrium(force=force, moment=moment)
    assert eq.lines[-1].model == "touchdown between the ends"
    assert eq.stable and eq.bodies[0].offset[0] > 0 and eq.bodies[1].offset[0] > 0  # the shared line pulls
    _check_balance(eq, props, {("body", 0): np.r_[LOADS[0], 1e6, 5e6, 2e6]})


def _euler_after(qb, rotation_vector):
    turned = Rotation.from_rotvec(rotation_vector) * Rotation.from_euler("ZYX", qb[[5, 4, 3]])
    yaw, pitch, roll = turned.as_euler("ZYX")
    return np.concatenate([qb[:3], [roll, pitch, yaw]])


def _numeric(system, q, net, h=(1e-3, 1e-6)):
    """-∂net/∂(x, rotation vector) by central differences over the dofs of ``system``."""
    layout = system.layout
    n = layout.n_dof
    numeric = np.empty((n, n))
    for k in range(n):
        up, down = q.copy(), q.copy()
        for i, s in enumerate(layout.body_start):
            if s + 3 <= k < s + 6 and layout.bodies[i].n_dof == 6:
                rv = np.eye(3)[k - s - 3] * h[1]
                up[s : s + 6], down[s : s + 6] = (
                    _euler_after(q[s : s + 6], rv),
                    _euler_after(q[s : s + 6], -rv),
                )
                size = h[1]
                break
        else:
            up[k] += h[0]
            down[k] -= h[0]
            size = h[0]
        numeric[:, k] = -(net(up) - net(down)) / (2 * size)
    return numeric


def test_shared_mooring_stiffness_matches_central_differences():
    system, turbines, _ = two_turbines()
    force = {turbines[0]: LOADS[0]}
    eq = system.equilibrium(force=force)
    q = (
        eq.position + np.r_[3.0, -2.0, 0.2, 0.01, -0.02, 0.05, -1.0, 2.0, -0.1, -0.01, 0.02, -0.03]
    )  # off equilibrium
    K = system.stiffness(q)
    numeric = _numeric(system, q, lambda x: system.net_force(x, force=force))
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-6 * np.abs(K).max())


# -- a three-line bridle: two legs from the hull to a free junction, one line to the anchor --------------
def bridle():
    system = mooring.MooringSystem(depth=150.0)
    hull = system.add_body(
        mooring.RigidBody(mass=2e6, volume=2.2e3, metacentre=(0, 0, 6.0), waterplane_area=300.0)
    )
    props = []
    for heading in np.radians((120.0, 240.0)):
        c, s = np.cos(heading), np.sin(heading)
        anchor = system.add_point([700 * c, 700 * s, -150.0], fixed=True)
        system.add_line(chain(720.0), anchor, system.add_point([15 * c, 15 * s, -8.0], body=hull))
        props.append((W, EA, 720.0))
    junction = system.add_point([60.0, 0.0, -30.0], mass=2000.0)  # the bridle's plate
    wire = (120.0, 5.0e8)
    for y in (-12.0, 12.0):
        leg = mooring.Line([mooring.Segment(50.0, *wire)])
        system.add_line(leg, system.add_point([15.0, y, -8.0], body=hull), junction)
        props.append((120.0, 5.0e8, 50.0))
    anchor = system.add_point([700.0, 0.0, -150.0], fixed=True)
    system.add_line(chain(660.0), junction, anchor)
    props.append((W, EA, 660.0))
    return system, hull, junction, props


def test_bridle_balances_at_the_junction_and_the_hull():
    system, hull, junction, props = bridle()
    eq = system.equilibrium(force={hull: (-4e5, 1e5, 0.0)})
    _check_balance(eq, props, {("body", 0): np.r_[-4e5, 1e5, 0.0, 0.0, 0.0, 0.0]})
    assert [line.model for line in eq.lines][2:] == ["free", "free", "grounded"]


def test_bridle_stiffness_free_and_condensed():
    system, hull, junction, _ = bridle()
    force = {hull: (-4e5, 1e5, 0.0)}
    eq = system.equilibrium(force=force)
    K = eq.stiffness()
    numeric = _numeric(system, eq.position, lambda x: system.net_force(x, force=force))
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-6 * np.abs(K).max())
    # condensed: the junction re-solved in equilibrium at each perturbed hull position
    Kc = eq.stiffness(condensed=True)
    assert Kc.shape == (6, 6)

    def hull_load(qb):  # the hull held at qb: only the junction moves
        sub = _held(system, qb, mooring.MooringSystem(depth=150.0))
        sol = sub.equilibrium(start=eq.points[junction.index].position)
        return system.net_force(np.concatenate([qb, sol.position]), force=force)[:6]

    h = (1e-3, 1e-6)
    numeric_c = np.empty((6, 6))
    for k in range(6):
        up, down = eq.position[:6].copy(), eq.position[:6].copy()
        if k < 3:
            up[k] += h[0]
            down[k] -= h[0]
            size = h[0]
        else:
            rv = np.eye(3)[k - 3] * h[1]
            up, down, size = _euler_after(up, rv), _euler_after(down, -rv), h[1]
        numeric_c[:, k] = -(hull_load(up) - hull_load(down)) / (2 * size)
    np.testing.assert_allclose(Kc, numeric_c, rtol=1e-5, atol=1e-6 * np.abs(Kc).max())


def _held(system, qb, fixed):
    """``system`` with its body held at ``qb``: the body's points become fixed points there."""
    R = mooring.rotation_matrix(*qb[3:])
    new = {}
    for p in system.points:
        if p.kind == "body":
            new[p.index] = fixed.add_point(qb[:3] + R @ p.position, fixed=True)
        elif p.kind == "fixed":
            new[p.index] = fixed.add_point(p.position, fixed=True)
        else:
            new[p.index] = fixed.add_point(p.position, mass=p.mass, volume=p.volume, force=p.force)
    for h in system.mooring_lines:
        fixed.add_line(h.model, new[h.a.index], new[h.b.index])
    return fixed


# -- the one-body constructor is a shortcut of the same system --------------------------------------------
def test_one_body_constructor_equals_the_system_built_point_by_point():
    angles = np.radians([0.0, 120.0, 240.0])
    anchors = np.column_stack([800 * np.cos(angles), 800 * np.sin(angles), np.full(3, -200.0)])
    fairleads = np.column_stack([20 * np.cos(angles), 20 * np.sin(angles), np.full(3, -14.0)])
    own = dict(
        mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5), metacentre=(0, 0, 10), waterplane_area=600.0
    )
    line = mooring.Line([mooring.Segment(850.0, W, EA)], seabed=0.0)
    old = mooring.MooringSystem(mooring.RigidBody(fairleads, **own), [line] * 3, anchors, depth=200.0)
    new = mooring.MooringSystem(depth=200.0)
    hull = new.add_body(mooring.RigidBody(**own))
    for a, f in zip(anchors, fairleads, strict=True):
        new.add_line(line, new.add_point(a, fixed=True), new.add_point(f, body=hull))
    force, moment = (2e6, 5e5, 0.0), (1e6, 1e7, 3e6)
    eq_old, eq_new = old.equilibrium(force=force, moment=moment), new.equilibrium(force=force, moment=moment)
    np.testing.assert_allclose(eq_new.position, eq_old.position, rtol=0, atol=1e-9)
    np.testing.assert_allclose(eq_new.stiffness(), eq_old.stiffness(), rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(
        [line.end_forces for line in eq_new.lines],
        [line.end_forces for line in eq_old.lines],
        rtol=1e-9,
        atol=1e-3,
    )


# -- bad input, refused by name ---------------------------------------------------------------------------
def test_a_point_with_no_line_is_refused():
    system, _ = basic_u()
    system.add_point([0.0, 50.0, -60.0], volume=1.0)
    with pytest.raises(InputError, match="point 4") as err:
        system.equilibrium()
    assert err.value.argument == "points"


def test_a_line_from_a_point_to_itself_is_refused():
    system = mooring.MooringSystem(depth=100.0)
    p = system.add_point([0.0, 0.0, -50.0])
    with pytest.raises(InputError, match="itself") as err:
        system.add_line(chain(10.0), p, p)
    assert err.value.argument == "b"


def test_no_restoring_stiffness_is_named_not_a_hang():
    system = mooring.MooringSystem(depth=100.0)
    hull = system.add_body(mooring.RigidBody())  # no hydrostatics, one line: nothing holds its yaw
    anchor = system.add_point([300.0, 0.0, -100.0], fixed=True)
    system.add_line(chain(320.0), anchor, system.add_point([0.0, 0.0, 0.0], body=hull))
    with pytest.raises(ConvergenceError, match="body 0") as err:
        system.equilibrium()
    assert err.value.history


def test_other_bad_parts_are_named():
    system = mooring.MooringSystem(depth=100.0)
    with pytest.raises(InputError) as err:
        system.add_point([0.0, 0.0, -120.0], fixed=True)
    assert err.value.argument == "position"
    other = mooring.MooringSystem(depth=100.0)
    stranger = other.add_point([0.0, 0.0, -100.0], fixed=True)
    here = system.add_point([0.0, 0.0, -100.0], fixed=True)
    with pytest.raises(InputError) as err:
        system.add_line(chain(10.0), here, stranger)
    assert err.value.argument == "b"
    with pytest.raises(InputError) as err:
        system.add_point([0.0, 0.0, 0.0], body=mooring.RigidBody())
    assert err.value.argument == "body"
    with pytest.raises(InputError) as err:
        system.add_body(mooring.RigidBody([[1.0, 0.0, 0.0]]))
    assert err.value.argument == "body"
    turbines = two_turbines()[0]
    with pytest.raises(InputError) as err:
        turbines.equilibrium(force=(1.0, 0.0, 0.0))
    assert err.value.argument == "force"
    with pytest.raises(InputError) as err:
        system.equilibrium()
    assert err.value.argument == "points"


def test_reprs_read_back():
    """The system's equilibrium, its bodies and points print their key numbers with units, read
    back by the parser of tests/test_repr.py and compared with the attributes."""
    system, turbines, props = two_turbines()
    eq = system.equilibrium(force={turbines[0]: LOADS[0]})
    spec = {
        "T_max": ("N", lambda e: [np.linalg.norm(line.end_forces, axis=1).max() for line in e.lines]),
        "min_eigenvalue": ("N/m", lambda e: np.min(e.eigenvalues)),
        "iterations": ("", lambda e: len(e.history) - 1),
    }
    assert check_repr(eq, spec).startswith("MooringEquilibrium(2 bodies, 10 points, 5 lines: ")
    body = {"offset": ("m", lambda b: b.offset), "angles": ("rad", lambda b: b.angles)}
    body["heel"] = ("rad", lambda b: b.heel)
    assert check_repr(eq.bodies[1], body).startswith("BodyState(body 1: ")
    u = basic_u()[0].equilibrium()
    free = u.points[1]
    assert check_repr(free, {"position": ("m", lambda p: p.position)}) == (
        f"PointState(free point 1: position=[{', '.join(f'{v:.6g}' for v in free.position)}] m)"
    )
