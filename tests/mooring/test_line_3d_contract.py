"""Issue 23, phase 2: the user contract of lines in the sea.

``mooring.Segment(..., cd_normal, cd_tangential)`` with a strain law, ``mooring.Line(..., current,
rho_water, seabed=Bathymetry)`` and ``mooring.line_3d(line, anchor, fairlead)`` choosing the model
per line. Every reference is computed here: an mpmath closure of the same ε(T), MoorPy's
current model on a taut line, a ``solve_ivp`` integration of a subsurface buoy's line.
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from skcable import ConvergenceError, InputError, mooring
from skcable.mooring import axial
from skcable.mooring.bathymetry import DepthFunction, Plane

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(uplift_angle|position)\\b:skcable.errors.PlausibilityWarning"
)

RHO = 1025.0


# -- bad input, named --------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["cd_normal", "cd_tangential"])
def test_a_negative_drag_coefficient_is_refused_by_name(name):
    with pytest.raises(InputError) as err:
        mooring.Segment(100.0, 50.0, 1e8, diameter=0.1, **{name: -0.1})
    assert err.value.argument == name


def test_drag_without_a_diameter_is_refused():
    with pytest.raises(InputError) as err:
        mooring.Segment(100.0, 50.0, 1e8, cd_normal=1.2)
    assert err.value.argument == "diameter"


def test_a_non_increasing_strain_law_is_refused():
    with pytest.raises(InputError) as err:
        axial.StrainTable([0.0, 0.01, 0.01], [0.0, 1e5, 2e5])
    assert err.value.argument == "strain"
    # a callable law whose derivative is not positive: refused by the segment that takes it
    law = axial.StrainFunction(lambda T: -T / 1e8, lambda T: np.full(np.shape(T), -1e-8))
    with pytest.raises(InputError) as err:
        mooring.Segment(300.0, 100.0, law)
    assert err.value.argument == "derivative"


def test_a_current_that_drags_nothing_is_refused():
    with pytest.raises(InputError) as err:
        mooring.Line([mooring.Segment(100.0, 50.0, 1e8)], current=(0.5, 0.0))
    assert err.value.argument == "current"


def test_the_plane_paths_refuse_a_line_in_the_sea_by_name():
    """A line in a current, on a bathymetry or with a nonlinear law is never solved in a plane
    without what makes it so (add_line and line_between solve a Line in the plane of its ends)."""
    law = axial.StrainTable([0.0, 0.01, 0.03], [0.0, 1e6, 2.5e6])
    drag = dict(diameter=0.1, cd_normal=1.2)
    for line, name in (
        (mooring.Line([mooring.Segment(100.0, 50.0, 1e8, **drag)], current=(0.5, 0.0)), "current"),
        (mooring.Line([mooring.Segment(100.0, 50.0, 1e8)], seabed=Plane(-50.0, (0.1, 0.0))), "seabed"),
        (mooring.Line([mooring.Segment(100.0, 50.0, law)]), "EA"),
    ):
        with pytest.raises(InputError) as err:
            mooring.line_between(line, (0.0, 0.0, -50.0), (80.0, 0.0, -10.0))
        assert err.value.argument == name


def test_the_plane_solve_of_a_line_in_a_current_points_to_line_3d():
    line = mooring.Line([mooring.Segment(100.0, 50.0, 1e8, diameter=0.1, cd_normal=1.2)], current=(0.5, 0.0))
    with pytest.raises(InputError, match="line_3d") as err:
        line.solve(80.0, 30.0)
    assert err.value.argument == "current"


# -- the closed form with a nonlinear ε(T) against an mpmath closure ---------------------------
def _mp_closure(segments, span, dh, start):
    """(H, V_B) of the hanging line of ``segments`` (length, w, ε, in mpmath) by mp.findroot on the
    run and rise ``∫ (1 + ε(T)) (H, V)/T ds``."""
    mpmath = pytest.importorskip("mpmath")
    mpmath.mp.dps = 30

    def ends(H, V):
        X = Z = mpmath.mpf(0)
        W_above = sum(mpmath.mpf(w) * L for L, w, _ in segments)
        V0 = V - W_above  # vertical force at the anchor, along the line towards B
        for L, w, eps in segments:

            def T(s, V0=V0, w=w):
                return mpmath.sqrt(H * H + (V0 + w * s) ** 2)

            X += mpmath.quad(lambda s, T=T, eps=eps: (1 + eps(T(s))) * H / T(s), [0, L])
            Z += mpmath.quad(
                lambda s, T=T, eps=eps, V0=V0, w=w: (1 + eps(T(s))) * (V0 + w * s) / T(s), [0, L]
            )
            V0 += w * L
        return X - span, Z - dh

    H, V = mpmath.findroot(ends, (mpmath.mpf(start[0]), mpmath.mpf(start[1])))
    return float(H), float(V)


def test_a_nonlinear_ea_line_matches_an_mpmath_closure():
    # a polyester-like law: ε = T/EA0 + c (T/T0)², stiffening... softening with load (any increasing ε)
    EA0, c, T0 = 2e8, 4e-3, 1e6

    def eps(T):
        return T / EA0 + c * (T / T0) ** 2

    law = axial.StrainFunction(eps, lambda T: 1.0 / EA0 + 2.0 * c * T / T0**2)
    chain = (150.0, 1200.0)
    rope = (600.0, 40.0)
    line = mooring.Line([mooring.Segment(*chain, 5e9), mooring.Segment(*rope, law)])
    span, dh = 650.0, 250.0
    sol = line.solve(span, dh)
    segs = [(chain[0], chain[1], lambda T: T / 5e9), (rope[0], rope[1], eps)]
    H, V_B = _mp_closure(segs, span, dh, (sol.H, sol.V_B))
    assert sol.H == pytest.approx(H, rel=1e-9)
    assert sol.V_B == pytest.approx(V_B, rel=1e-9)
    # line_3d reports the closed form with the laws, and the same forces in space
    l3 = mooring.line_3d(line, (0.0, 0.0, -300.0), (span * 0.6, span * 0.8, dh - 300.0))
    assert l3.model.name == "closed form (axial laws)"
    assert np.linalg.norm(l3.force_on_fairlead) == pytest.approx(np.hypot(H, V_B), rel=1e-9)
    # the laws' elongation is exact: the stretched length along the profile is ∫(1 + ε) ds
    s = np.linspace(0.0, line.length, 4001)
    pts = l3.profile(4001)
    arc = np.sum(np.linalg.norm(np.diff(pts, axis=0), axis=1))
    stretched = line.length + float(l3.tensions()["stretch"].sum())
    assert arc == pytest.approx(stretched, rel=1e-6)  # the chords of 4000 pieces
    assert l3.T_of_s(s[[0, -1]]) == pytest.approx([l3.tension_at_anchor, l3.tension_at_fairlead], rel=1e-12)


def test_a_constant_law_given_as_a_law_is_the_constant_ea_line():
    a = mooring.Line([mooring.Segment(500.0, 600.0, 4e8)]).solve(420.0, 180.0)
    b = mooring.Line([mooring.Segment(500.0, 600.0, axial.ConstantEA(4e8))]).solve(420.0, 180.0)
    assert (a.H, a.V_B) == (b.H, b.V_B)


# -- the model chosen per line, reported -------------------------------------------------------
def test_line_3d_of_a_plain_line_is_the_closed_form_as_before():
    from skcable.mooring.line3d import solve_in_space

    line = mooring.Line([mooring.Segment(500.0, 600.0, 4e8)], seabed=0.0, friction=0.3)
    a, b = np.array([0.0, 0.0, -200.0]), np.array([300.0, 320.0, -20.0])
    l3 = mooring.line_3d(line, a, b)
    old = solve_in_space(line, a, b, float(np.hypot(300.0, 320.0)))
    assert l3.model.name == "closed form" and l3.model.error < 1e-12
    np.testing.assert_array_equal(l3.force_on_fairlead, old.force_on_fairlead)
    np.testing.assert_array_equal(l3.stiffness(), old.stiffness())
    assert l3.H == old.H  # the closed form's attributes, as line_3d gave them
    assert l3.equilibrium_residual <= 1e-9 * line.weight / line.length


def test_a_current_or_a_shaped_seabed_takes_the_bvp_and_says_why():
    seg = mooring.Segment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2)
    in_current = mooring.line_3d(mooring.Line([seg], current=(0.0, 0.8)), (0, 0, -200.0), (400.0, 0, -20.0))
    assert in_current.model.name == "3-D line BVP" and "current" in in_current.model.reason
    assert in_current.model.error < 1e-6
    assert in_current.force_on_fairlead[1] > 0  # the cross current pulls the fairlead along +y
    assert in_current.equilibrium_residual <= in_current.solution.residual_bound
    assert in_current.profile(7).shape == (7, 3)
    bed = Plane(-200.0, (0.05, 0.02))  # a slope across the line too: no closed form
    on_slope = mooring.line_3d(
        mooring.Line([seg], seabed=bed, friction=0.2), (0, 0, -200.0), (450.0, 0, -20.0)
    )
    assert on_slope.model.name == "3-D line BVP" and "seabed" in on_slope.model.reason
    # a flat Bathymetry is the flat closed form, placed at the anchor
    flat = mooring.line_3d(
        mooring.Line([seg], seabed=Plane(-200.0), friction=0.2), (0, 0, -200.0), (450.0, 0, -20.0)
    )
    ref = mooring.line_3d(mooring.Line([seg], seabed=0.0, friction=0.2), (0, 0, -200.0), (450.0, 0, -20.0))
    assert flat.model.name == "closed form"
    np.testing.assert_allclose(flat.force_on_fairlead, ref.force_on_fairlead, rtol=1e-14)


def test_a_line_on_a_plane_sloping_along_it_is_the_sloped_closed_form():
    """Jonkman's line on a slope (the closed form line_3d takes) against the 3-D BVP of the same
    line on the same plane, turned to an azimuth of 30°."""
    from skcable.mooring.line_bvp.space import LineSegment, solve_line_bvp_3d

    c, s = np.cos(np.radians(30.0)), np.sin(np.radians(30.0))
    bed = Plane(-200.0, (0.04 * c, 0.04 * s))
    line = mooring.Line([mooring.Segment(480.0, 600.0, 4e8)], seabed=bed, friction=0.3)
    a, b = np.array([0.0, 0.0, -200.0]), np.array([430.0 * c, 430.0 * s, -20.0])
    closed = mooring.line_3d(line, a, b)
    assert closed.model.name == "closed form (slope)" and closed.model.error < 1e-12
    bvp = solve_line_bvp_3d(a, b, [LineSegment(480.0, 600.0, 4e8)], seabed=bed, friction=0.3, n_elements=256)
    scale = bvp.T_B
    assert closed.solution.length_on_seabed > 50.0  # the line rests on the slope
    np.testing.assert_allclose(closed.force_on_fairlead, bvp.force_on_fairlead, atol=1e-9 * scale)
    np.testing.assert_allclose(closed.force_on_anchor, bvp.force_on_anchor, atol=1e-9 * scale)
    assert closed.profile(11).shape == (11, 3)


def test_the_bvp_of_a_line_in_still_water_is_its_closed_form():
    """A zero current (it drags nothing) keeps the BVP: its forces are the closed form's to its
    discretisation error, which the reported estimate bounds."""
    seg = mooring.Segment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2)
    a, b = (0.0, 0.0, -200.0), (400.0, 100.0, -20.0)
    still = mooring.line_3d(mooring.Line([seg], current=lambda z: (0.0 * z, 0.0 * z)), a, b)
    closed = mooring.line_3d(mooring.Line([seg]), a, b)
    assert still.model.name == "3-D line BVP"
    gap = np.abs(still.end_forces - closed.end_forces).max() / still.tension_at_fairlead
    assert gap < 1e-7
    assert gap <= max(still.model.error, 1e-12) * 10


# -- MoorPy's current model, where its smeared load is exact ----------------------------------
def test_a_taut_line_in_a_uniform_current_matches_moorpy():
    moorpy = pytest.importorskip("moorpy")
    w, EA, d, cd, L = 20.0, 5e9, 0.1, 1.2, 140.0
    A, B = np.array([0.0, 0.0, -200.0]), np.array([100.0, 0.0, -100.0])
    U = np.array([0.0, 1.0, 0.0])
    ms = moorpy.System(depth=500.0, current=list(U))
    ms.setLineType(dnommm=100, material="chain", name="rope")
    ms.lineTypes["rope"].update(w=w, EA=EA, m=w / 9.81 + RHO * np.pi / 4 * d * d, d_vol=d, Cd=cd, CdAx=0.0)
    ms.rho = RHO
    ms.addPoint(1, A)
    ms.addPoint(1, B)
    ms.addLine(L, "rope", pointA=1, pointB=2)
    ms.initialize()
    mp_line = ms.lineList[0]
    for _ in range(20):  # MoorPy lags the drag by one solve: iterate it to its fixed point
        mp_line.staticSolve(tol=1e-10)
    line = mooring.Line(
        [mooring.Segment(L, w, EA, diameter=d, cd_normal=cd)], current=(0.0, 1.0), rho_water=RHO
    )
    ours = mooring.line_3d(line, A, B)
    T = np.linalg.norm(ours.force_on_fairlead)
    # a taut line (chord 141.4 m, 140 m long, T ≈ 5e7 N): the smeared load is exact to ~1e-7
    np.testing.assert_allclose(ours.force_on_anchor, mp_line.fA, atol=1e-7 * T)
    np.testing.assert_allclose(ours.force_on_fairlead, mp_line.fB, atol=1e-7 * T)
    # the cross force, 4e3 N of it, to MoorPy's tolerance
    assert ours.force_on_fairlead[1] == pytest.approx(mp_line.fB[1], rel=1e-5)


# -- the knock-down of a subsurface buoy in a current -------------------------------------------
def _buoy_line_ivp(L, w, EA, d, cd, U, buoy, drag_buoy):
    """The buoy's position relative to the anchor: the line integrated from the buoy down, where
    the force in the line is known (the buoy's net buoyancy and drag), by solve_ivp."""

    def rhs(s, y):  # s from the buoy down; y = (r, F) with F the force in the line (T t, up)
        F = y[3:]
        T = np.linalg.norm(F)
        t = F / T
        v = np.array([U, 0.0, 0.0])
        vn = v - (v @ t) * t
        stretch = 1.0 + T / EA
        drag = 0.5 * RHO * d * cd * stretch * np.linalg.norm(vn) * vn
        q = drag + np.array([0.0, 0.0, -w])
        return np.concatenate([-stretch * t, q])  # d/ds of r and of F going down: dF/ds = +q

    F_top = np.array([drag_buoy, 0.0, buoy])
    sol = solve_ivp(
        rhs, (0.0, L), np.concatenate([np.zeros(3), F_top]), rtol=1e-12, atol=1e-10, method="DOP853"
    )
    anchor_rel = sol.y[:3, -1]
    return -anchor_rel  # the buoy relative to the anchor


def test_the_knock_down_of_a_subsurface_buoy_in_a_current():
    L, w, EA, d, cd, U = 180.0, 150.0, 2e8, 0.08, 1.2, 1.0
    buoy, drag_buoy = 6e4, 0.5 * RHO * 1.0 * (np.pi * 1.0**2) * U * U  # a 2 m sphere-ish buoy
    top = _buoy_line_ivp(L, w, EA, d, cd, U, buoy, drag_buoy)
    knock_down = L - top[2]
    assert knock_down > 1.0  # the current knocks it down
    anchor = np.array([0.0, 0.0, -300.0])
    line = mooring.Line(
        [mooring.Segment(L, w, EA, diameter=d, cd_normal=cd)], current=(U, 0.0), rho_water=RHO
    )
    solved = mooring.line_3d(line, anchor, anchor + top)
    # the line holds the buoy against its buoyancy and drag
    np.testing.assert_allclose(solved.force_on_fairlead, [-drag_buoy, 0.0, -buoy], atol=1e-7 * buoy)


# -- a seabed the line cannot follow -----------------------------------------------------------
def test_a_seabed_the_line_cannot_reach_raises_with_its_history():
    def height(x, y):
        return -200.0 + 150.0 * np.exp(-(((x - 200.0) / 5.0) ** 2))

    def gradient(x, y):
        x = np.asarray(x, dtype=float)
        return np.array([(height(x, y) + 200.0) * (-2.0 * (x - 200.0) / 25.0), 0.0 * x])

    ridge = DepthFunction(height, gradient)  # a wall 150 m high and 10 m wide across the line
    line = mooring.Line([mooring.Segment(420.0, 600.0, 4e8)], seabed=ridge)
    with pytest.raises(ConvergenceError) as err:
        mooring.line_3d(line, (0.0, 0.0, -200.0), (400.0, 0.0, -20.0))
    assert len(err.value.history) > 1


# -- pickling ------------------------------------------------------------------------------------
def test_lines_in_the_sea_pickle():
    seg = mooring.Segment(300.0, 500.0, axial.StrainTable([0.0, 0.01, 0.03], [0.0, 1e6, 2.5e6]))
    line = mooring.Line(
        [seg, mooring.Segment(200.0, 50.0, 1e8, diameter=0.1, cd_normal=1.2)], current=(0.3, 0.1)
    )
    back = pickle.loads(pickle.dumps(line))
    assert back.current is not None and back.segments[1].cd_normal == 1.2
    solved = mooring.line_3d(line, (0.0, 0.0, -300.0), (420.0, 0.0, -20.0))
    again = pickle.loads(pickle.dumps(solved))
    np.testing.assert_array_equal(again.force_on_fairlead, solved.force_on_fairlead)
    assert again.model == solved.model


# -- a mooring system of lines in a current -----------------------------------------------------
def test_a_mooring_system_takes_lines_in_a_current():
    """A subsurface buoy on three lines in a current: at the system's equilibrium the lines, each
    solved again here by line_3d at the buoy's position, balance its net buoyancy; the current
    moves it from where it rests in still water."""
    seg = mooring.Segment(230.0, 150.0, 2e8, diameter=0.08, cd_normal=1.2, cd_tangential=0.01)
    line = mooring.Line([seg], current=(0.8, 0.2))
    angles = np.radians([0.0, 120.0, 240.0])
    anchors = np.column_stack([150.0 * np.cos(angles), 150.0 * np.sin(angles), np.full(3, -300.0)])
    buoy = mooring.PointBody(mass=2e4, volume=80.0)
    system = mooring.MooringSystem(buoy, [line] * 3, anchors, depth=300.0)
    eq = system.equilibrium(start=(0.0, 0.0, -120.0))
    position = np.asarray(eq.position, dtype=float)
    lines = [mooring.line_3d(line, a, position) for a in anchors]
    assert all(solved.model.name == "3-D line BVP" for solved in lines)
    net = sum(solved.force_on_fairlead for solved in lines) + buoy.own_force(position)
    lift = float(buoy.buoyancy[2] + buoy.weight[2])
    np.testing.assert_allclose(net, 0.0, atol=1e-6 * lift)
    still = mooring.MooringSystem(buoy, [mooring.Line([seg])] * 3, anchors, depth=300.0).equilibrium(
        start=(0.0, 0.0, -120.0)
    )
    assert np.linalg.norm(position - np.asarray(still.position, dtype=float)) > 1e-3


def test_the_segment_checks_of_a_system_read_the_lines_in_the_sea():
    """The MBL checks of a system see the segments of its lines in a current (none skipped)."""
    seg = mooring.Segment(230.0, 150.0, 2e8, mbl=4e6, diameter=0.08, cd_normal=1.2)
    angles = np.radians([0.0, 120.0, 240.0])
    anchors = np.column_stack([150.0 * np.cos(angles), 150.0 * np.sin(angles), np.full(3, -300.0)])
    buoy = mooring.PointBody(mass=2e4, volume=80.0)
    line = mooring.Line([seg], current=(0.8, 0.2))
    eq = mooring.MooringSystem(buoy, [line] * 3, anchors, depth=300.0).equilibrium(start=(0.0, 0.0, -120.0))
    table = eq.segment_checks(1.67)
    assert len(table) == 3
    T_max = [max(solved.tension_at_anchor, solved.tension_at_fairlead) for solved in eq.lines]
    np.testing.assert_allclose(table["T_max"], T_max, rtol=1e-9)


def test_the_stiffness_of_a_line_in_a_current_is_its_central_differences():
    seg = mooring.Segment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2, cd_tangential=0.008)
    line = mooring.Line([seg], current=(0.3, 0.7))
    a, b = np.array([0.0, 0.0, -200.0]), np.array([400.0, 50.0, -20.0])
    K = mooring.line_3d(line, a, b).stiffness()
    h = 1e-3
    columns = []
    for k in range(3):
        step = np.zeros(3)
        step[k] = h
        up = mooring.line_3d(line, a, b + step).force_on_fairlead
        down = mooring.line_3d(line, a, b - step).force_on_fairlead
        columns.append(-(up - down) / (2 * h))
    np.testing.assert_allclose(K, np.array(columns).T, atol=1e-6 * np.abs(K).max())
