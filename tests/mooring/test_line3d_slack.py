"""Friction's slack stretch near the anchor in the line in space (`LineProblem3D.lay_slack`).

References, each independent of the line in space's solve:

- J.M. Jonkman's grounded line in closed form ("Dynamics modeling and loads analysis of an
  offshore floating wind turbine", NREL, 2007; `skcable.mooring.Line`): ``H_A = 0``, tension
  ``max(H - μ w (s_td - s), 0)`` on the seabed, and its fairlead stiffness;
- the plane line BVP (`skcable.mooring.solve_line_bvp`), whose slack stretch is its own model
  (friction holding each node's weight, `skcable.mooring.line_bvp.slack`) on its own meshes;
- central differences of the solves themselves for the stiffness;
- Coulomb's bound for the stretch: Morison's drag along it by hand against ``μ w``.
"""

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError
from skcable.mooring.bathymetry import Grid
from skcable.mooring.line_bvp.space import LineBVP3D, LineSegment, solve_line_bvp_3d

#: the pinned `line_bvp_friction` scene's line: 850 m, 1 kN/m, EA 5e8 N, friction 0.5
CHAIN = [(850.0, 1000.0, 5e8)]
ANGLE = 0.3  # the chord's heading (rad): the stretch is laid along it, not along x
ALONG = np.array([np.cos(ANGLE), np.sin(ANGLE), 0.0])
ACROSS = np.array([-np.sin(ANGLE), np.cos(ANGLE), 0.0])
FAIRLEAD = 800.0 * ALONG + np.array([0.0, 0.0, 150.0])


@pytest.fixture(scope="module")
def turned():
    """The chain on a flat seabed, its chord turned by `ANGLE`, on 96 elements."""
    return solve_line_bvp_3d((0.0, 0.0, 0.0), FAIRLEAD, CHAIN, seabed=0.0, friction=0.5, n_elements=96)


@pytest.fixture(scope="module")
def jonkman():
    """The same line in closed form (Jonkman's grounded line, `mooring.Line`)."""
    return mooring.Line([mooring.Segment(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.5).solve(800.0, 150.0)


def test_a_slack_stretch_in_space_is_jonkmans_closed_form(turned, jonkman):
    """End forces, the stretch's end and the tension field against the closed form: the fairlead's
    force in the vertical plane of the chord (H, V_B) within the discretisation (measured 2.8e-10
    of T_B), none across it; the stretch ends where Jonkman's tension ``H - μ w (s_td - s)``
    reaches zero (measured 3.3e-7 m); the P1 tension field past it the closed form's within its
    O(h²) (measured 1.2e-5 of T_B, near the fairlead; 4e-10 on the seabed); the forces on the
    line balance: the fairlead's, the seabed's (on the stretch, the anchor's node and the contact
    nodes past it) and the weight (measured 7e-16 of it)."""
    F = turned.force_on_fairlead
    assert abs(-F @ ALONG - jonkman.H) <= 1e-8 * turned.T_B
    assert abs(-F[2] - jonkman.V_B) <= 1e-8 * turned.T_B
    assert abs(F @ ACROSS) <= 1e-12 * turned.T_B
    s0 = jonkman.length_on_seabed - jonkman.H / (0.5 * 1000.0)
    assert turned.slack_end > 0 and abs(turned.slack_end - s0) <= 1e-8 * turned.length
    s = np.linspace(0.0, turned.length, 401)
    past = s > turned.slack_end + 1e-6
    T = np.asarray(turned.T_of_s(s))
    np.testing.assert_array_equal(T[s < turned.slack_end], 0.0)
    assert np.abs(T[past] - np.asarray(jonkman.T_of_s(s[past]))).max() <= 5e-5 * turned.T_B
    np.testing.assert_array_equal(turned.force_on_anchor, 0.0)
    seabed = turned.anchor_seabed_force + turned.slack_seabed_force + turned.contact_force.sum(axis=0)
    balance = (
        -turned.force_on_fairlead - turned.force_on_anchor + seabed - np.array([0.0, 0.0, turned.weight])
    )
    assert np.abs(balance).max() <= 1e-9 * turned.weight
    assert turned.slack_seabed_force[2] > 0.9 * 1000.0 * turned.slack_end  # the stretch's weight, held


def test_the_stiffness_with_a_slack_stretch_is_the_derivative_of_the_solves(turned, jonkman):
    """``∂S_B/∂r_B`` (the stretch's end and heading moving with the fairlead) against central
    differences of solves 1 mm apart (measured 5e-9 of its largest entry); in the chord's
    vertical plane, the closed form's stiffness (measured 3.2e-9); across it, ``H/800`` (measured
    4.6e-10 off): the line and its stretch
    turn about the anchor, as Jonkman's line in the vertical plane of its ends does."""
    K = turned.stiffness()
    step, numeric = 1e-3, np.zeros((3, 3))
    for k in range(3):
        move = np.zeros(3)
        move[k] = step
        plus, minus = (
            solve_line_bvp_3d((0.0, 0.0, 0.0), FAIRLEAD + d, CHAIN, seabed=0.0, friction=0.5, n_elements=96)
            for d in (move, -move)
        )
        numeric[:, k] = -(plus.force_on_fairlead - minus.force_on_fairlead) / (2.0 * step)
    scale = np.abs(K.matrix).max()
    assert np.abs(K.matrix - numeric).max() <= 1e-7 * scale
    frame = np.array([ALONG, [0.0, 0.0, 1.0]])
    np.testing.assert_allclose(frame @ K.matrix @ frame.T, jonkman.stiffness(), rtol=0, atol=1e-7 * scale)
    assert abs(ACROSS @ K.matrix @ ACROSS - jonkman.H / 800.0) <= 1e-8 * jonkman.H / 800.0
    np.testing.assert_array_equal(K.anchor, 0.0)


def test_on_a_grid_sloping_along_the_line_the_line_in_space_is_the_plane_lines():
    """A chain on a bathymetry grid sloping 1 % along the line, friction 1 (the scene the line in
    space refused before, friction holding 573 m of it): solved in space (graded meshes), it is
    the plane line on that slope within their discretisations (measured 4.2e-11 of T_B); as a
    line in the sea (`mooring.line_3d`, uniform mesh) its error against the plane line is within
    the error its model claims (`ModelChoice.error`: measured 3.2e-7, claimed 4.5e-6)."""
    x, y = np.linspace(-100.0, 1000.0, 12), np.linspace(-300.0, 300.0, 7)
    grid = Grid(x, y, -150.0 - 0.01 * x[:, None] + 0.0 * y[None, :])
    plane = mooring.solve_line_bvp(
        780.0, 130.0, [(850.0, 1200.0, 1e9)], seabed=0.0, seabed_slope=-0.01, friction=1.0, n_elements=96
    )
    want = np.array([-plane.H_B, 0.0, -plane.V_B])
    ends = (0.0, 0.0, -150.0), (780.0, 0.0, -20.0)
    space = solve_line_bvp_3d(*ends, [(850.0, 1200.0, 1e9)], seabed=grid, friction=1.0, n_elements=96)
    assert space.slack_end > 500.0
    assert np.abs(space.force_on_fairlead - want).max() <= 1e-9 * space.T_B
    line = mooring.Line([mooring.Segment(850.0, 1200.0, 1e9)], seabed=grid, friction=1.0)
    sea = mooring.line_3d(line, [0.0, 0.0, -150.0], [780.0, 0.0, -20.0])
    assert sea.model.name == "3-D line BVP"
    force = sea.end_forces[1]
    assert np.abs(force - want).max() <= sea.model.error * np.abs(want).max()


def test_a_load_across_the_end_of_the_slack_stretch_is_refused():
    """The line in space's friction acts along the line: past the stretch's end its tension, zero
    there, cannot hold a load across it (`LineBVP3DSolver.refuse_across`): a current across the
    line is refused naming ``current``, a grid sloping across it naming ``seabed``; a current
    along the line is solved, and its end forces converge with the mesh as a line's without
    current do (measured 5.7e-9 apart on 64 and 256 elements; a current of 0.2 m/s across the
    line, solved on a build without this refusal, moved them 3e-5 and its force across the
    chord 0.3 %, between 64 and 512)."""
    seg = [LineSegment(850.0, 1000.0, 5e8, diameter=0.3, cd_normal=2.4, cd_tangential=0.4)]
    with pytest.raises(InputError, match="^current:"):
        solve_line_bvp_3d((0, 0, 0), (780, 0, 150), seg, seabed=0.0, friction=1.0, current=(0.0, 0.2))
    x, y = np.linspace(-100.0, 1000.0, 12), np.linspace(-300.0, 300.0, 7)
    across = Grid(x, y, 0.0 * x[:, None] + 0.01 * y[None, :])
    with pytest.raises(InputError, match="^seabed:"):
        solve_line_bvp_3d((0, 0, 0), (780, 0, 150), seg, seabed=across, friction=1.0)
    forces = [
        solve_line_bvp_3d(
            (0, 0, 0), (780, 0, 150), seg, seabed=0.0, friction=1.0, current=(0.3, 0.0), n_elements=n
        ).force_on_fairlead
        for n in (64, 256)
    ]
    assert np.abs(forces[1] - forces[0]).max() <= 1e-7 * np.abs(forces[0]).max()


@pytest.mark.parametrize(("mu", "held"), [(0.150, False), (0.157, True)])
def test_friction_holds_the_stretch_against_a_current_along_it_up_to_coulombs_bound(mu, held):
    """A current of 1 m/s along the line towards the anchor drags the stretch by Morison's
    tangential drag, ``½ ρ d C_t v²`` = 153.75 N/m (ρ 1025 kg/m³, d 0.3 m, C_t 1); friction
    holds it up to ``μ w``, w = 1000 N/m: μ = 0.157 holds it, μ = 0.150 does not, and the line
    is refused naming ``friction``."""
    seg = [LineSegment(850.0, 1000.0, 5e8, diameter=0.3, cd_normal=2.4, cd_tangential=1.0)]

    def solve():
        return solve_line_bvp_3d((0, 0, 0), (780, 0, 150), seg, seabed=0.0, friction=mu, current=(-1.0, 0.0))

    if held:
        assert solve().slack_end > 0
    else:
        with pytest.raises(InputError, match="^friction: too weak to hold the slack stretch"):
            solve()


def test_a_warm_start_of_a_line_with_a_slack_stretch_is_its_solve_from_scratch():
    """`LineBVP3D` from a solution at a fairlead 1 m away (its stretch's end moved with it): the
    solve from scratch within the stretch's tolerance (its end solved to the Newton tolerance of
    the tension past it; measured 2.5e-14 of T_B, and 2.9e-14 m)."""
    model = LineBVP3D(CHAIN, seabed=0.0, friction=0.5, n_elements=96)
    start = model.solve((0.0, 0.0, 0.0), FAIRLEAD)
    moved = FAIRLEAD + np.array([1.0, 0.5, 0.0])
    warm, cold = model.solve((0.0, 0.0, 0.0), moved, start=start), model.solve((0.0, 0.0, 0.0), moved)
    assert warm.slack_end != start.slack_end
    assert np.abs(warm.force_on_fairlead - cold.force_on_fairlead).max() <= 1e-10 * cold.T_B
    assert abs(warm.slack_end - cold.slack_end) <= 1e-10 * cold.length


def test_a_system_of_lines_with_slack_stretches_on_a_grid_balances_its_body():
    """A body held by two chains on a bathymetry grid sloping 1 % along them, friction 1, pushed
    by 100 kN along them (a system's lines in the sea, warm starts and stiffness through the
    line in space): at its equilibrium both lines rest on slack stretches, and the lines recounted
    cold by `mooring.line_3d` at the solved positions balance the push (measured 5.9e-13 of the
    largest line force), their anchors unloaded."""
    x = np.linspace(-1200.0, 1200.0, 25)
    grid = Grid(x, x, -150.0 - 0.01 * x[:, None] + 0.0 * x[None, :])
    system = mooring.MooringSystem(depth=170.0)
    hull = system.add_body(
        mooring.PointBody(volume=60.0, mass=40e3, waterplane_area=80.0), position=(0.0, 0.0, -20.0)
    )
    top = system.add_point((0.0, 0.0, 0.0), body=hull)
    chain = mooring.Segment(850.0, 1200.0, 1e9, diameter=0.1, cd_normal=1.2, cd_tangential=0.1)
    line = mooring.Line([chain], seabed=grid, friction=1.0)
    anchors = [np.array([X, 0.0, float(grid.height(X, 0.0))]) for X in (780.0, -780.0)]
    for anchor in anchors:
        system.add_line(line, system.add_point(anchor, fixed=True), top)
    push = np.array([1e5, 0.0, 0.0])
    equilibrium = system.equilibrium(force={hull: push})
    assert all(solved.solution.slack_end > 0 for solved in equilibrium.lines)
    fairlead = np.asarray(equilibrium.points[0].position, dtype=float)  # the body's point
    recounted = [mooring.line_3d(line, anchor, fairlead) for anchor in anchors]
    forces = np.array([sea.force_on_fairlead for sea in recounted])
    scale = np.abs(forces).max()
    assert np.abs(forces[:, :2].sum(axis=0) + push[:2]).max() <= 1e-9 * scale
    for sea in recounted:
        np.testing.assert_array_equal(sea.force_on_anchor, 0.0)


@pytest.mark.parametrize("n_elements", [64, 256])
@pytest.mark.parametrize("space", [True, False], ids=["in space", "in the plane"])
def test_a_buoy_on_the_slack_stretch_is_refused_on_every_mesh(space, n_elements):
    """A 2 kN buoy 10 m from the anchor of a 1 kN/m chain, on the stretch friction holds: no
    tension holds it down, so it lifts a bight of the line, which neither line BVP models; both
    laid it flat on 64 and 128 elements (the stretch ending at 32.8 m) and lifted it on 256 and
    512 (ending at 8.3 m, H 3.6 % higher), without a warning. Both now refuse it by name, on every
    mesh: a buoy on the stretch or within the length of chain it lifts past its end, ``|P|/w``
    (`skcable.mooring.line_bvp.slack.buoy_on_stretch`). In space on 256 elements the line with
    friction fully mobilised fails before its stretch is laid, and its fallback on the plane line
    refuses: the `ConvergenceError` ends with the plane line's reason. A clump and a buoy at one
    point that pull down together are no buoy."""
    from skcable.errors import ConvergenceError

    segments = [(10.0, 1000.0, 5e8), (840.0, 1000.0, 5e8)]
    kw = dict(seabed=0.0, friction=0.5, n_elements=n_elements)
    with pytest.raises((InputError, ConvergenceError), match="no tension holds it down") as refused:
        if space:
            solve_line_bvp_3d((0, 0, 0), (800, 0, 150), segments, attachments=[(1, -2e3)], **kw)
        else:
            mooring.solve_line_bvp(800.0, 150.0, segments, point_loads=[(10.0, -2e3)], **kw)
    if isinstance(refused.value, InputError):
        assert refused.value.argument == ("attachments" if space else "point_loads")
    else:
        assert space and n_elements == 256
    if not space:
        both = mooring.solve_line_bvp(800.0, 150.0, segments, point_loads=[(10.0, 5e3), (10.0, -2e3)], **kw)
        assert both.problem.slack_end > 10.0


def test_the_plane_lines_fallback_on_the_line_in_space_keeps_the_stretch():
    """The plane line's fallback on the line in space's strategy
    (`skcable.mooring.line_bvp.fallback.space_for_plane`) takes the stretch back into the plane:
    the pinned `line_bvp_friction` scene through it is the plane line's own solve within their
    meshes' discretisation (the line in space's mesh: measured 1e-10 of H, the stretch's ends
    1.4e-9 m apart; it failed, "give more elements", with the stretch dropped)."""
    from skcable.mooring.line_bvp.driver import LineBVPSolver
    from skcable.mooring.line_bvp.fallback import space_for_plane
    from skcable.mooring.line_bvp.model import scene

    sc = scene(
        800.0,
        150.0,
        CHAIN,
        seabed=0.0,
        seabed_slope=None,
        friction=0.5,
        point_loads=[],
        fit_touchdown=3,
        n_elements=64,
    )
    through, direct = space_for_plane(LineBVPSolver(sc)), LineBVPSolver(sc).solve()
    assert abs(through.H_B - direct.H_B) <= 1e-9 * direct.H_B
    assert abs(through.problem.slack_end - direct.problem.slack_end) <= 1e-9 * direct.length


def test_the_stiffness_of_a_plane_line_with_a_slack_stretch_outlives_its_time_limit():
    """The plane line's stiffness re-solves its line with the stretch's end moved (its
    `slack_solver`) after the solve: on a budget of its own, not the solve's, spent by then (it
    raised the budget's internal exception)."""
    import time

    line = mooring.solve_line_bvp(800.0, 150.0, CHAIN, seabed=0.0, friction=0.5, time_limit=0.5)
    time.sleep(0.6)
    K = line.stiffness()
    assert np.all(np.isfinite(K)) and K[0, 0] > 0


def test_a_line_rising_vertically_from_its_anchor_with_friction_is_refused_for_its_friction():
    """300 m of chain from an anchor on the seabed to a point 100 m above it, friction 0.5: its
    slack lies on the seabed with no direction to lay a stretch along; the solve ends in
    compression and says that friction is why, not that more elements would help (a
    `skcable.errors.ResolutionError` would send ``n_elements="auto"`` to 1024 elements)."""
    from skcable.errors import ConvergenceError, ResolutionError

    with pytest.raises(ConvergenceError, match="no slack stretch lies on the seabed") as failed:
        solve_line_bvp_3d((0, 0, 0), (0, 0, 100.0), [(300.0, 1000.0, 5e8)], seabed=0.0, friction=0.5)
    assert not isinstance(failed.value, ResolutionError)
