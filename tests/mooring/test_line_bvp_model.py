"""The line BVP as a result and as a line model: stiffness, tables, `line_3d`, a spread mooring.

References: central differences of re-solved lines (the stiffness from the implicit function
theorem), the closed-form `mooring.Line` of the same segments (tables, 3-D forces, a whole spread
mooring in equilibrium), the 2-D solution rotated by hand.
"""

import runpy
from pathlib import Path

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError, ResolutionWarning
from skcable.mooring import LineBVP, LineBVPSolution
from skcable.mooring.line_bvp.space import solve_line_bvp_3d

ROOT = Path(__file__).resolve().parents[2]
SCENES = {
    "free": (360.0, 120.0, [(100.0, 1500.0, 8e8), (250.0, 300.0, 4e8), (60.0, 1500.0, 8e8)], {}),
    "grounded": (400.0, 100.0, [(440.0, 1000.0, 5e8)], {"seabed": 0.0}),
    "friction": (400.0, 100.0, [(440.0, 1000.0, 5e8)], {"seabed": 0.0, "friction": 0.2}),
    "slack stretch": (400.0, 100.0, [(440.0, 1000.0, 5e8)], {"seabed": 0.0, "friction": 0.5}),
    "clump, grounded": (
        780.0,
        250.0,
        [(300.0, 1500.0, 8e8), (500.0, 600.0, 4e8), (50.0, 1500.0, 8e8)],
        {"seabed": 0.0, "friction": 0.3, "point_loads": [(300.0, 2e4)]},
    ),
}


@pytest.mark.parametrize("name", list(SCENES))
def test_stiffness_is_the_derivative_of_resolved_lines(name):
    span, dh, segments, kw = SCENES[name]
    b = mooring.solve_line_bvp(span, dh, segments, **kw)
    assert (b.problem.slack_end > 0) == (name == "slack stretch")
    K = b.stiffness()
    h = 1e-5 * span  # central differences' truncation below 1e-8 of K, round-off 1e-11
    fd = np.empty((2, 2))
    for column, (d_span, d_dh) in enumerate([(h, 0.0), (0.0, h)]):
        plus = mooring.solve_line_bvp(span + d_span, dh + d_dh, segments, **kw)
        minus = mooring.solve_line_bvp(span - d_span, dh - d_dh, segments, **kw)
        fd[:, column] = [(plus.H_B - minus.H_B) / (2 * h), (plus.V_B - minus.V_B) / (2 * h)]
    # measured 1e-8 to 5e-8; holding the slack stretch's end instead of solving for it was 8e-4 off
    np.testing.assert_allclose(K, fd, rtol=0, atol=1e-6 * np.abs(fd).max())
    if "friction" not in kw:  # without friction the line has a potential: K is symmetric
        assert abs(K[0, 1] - K[1, 0]) < 1e-9 * np.abs(K).max()


def test_tensions_per_segment_match_the_closed_form():
    span, dh, segments, kw = SCENES["clump, grounded"]
    b = mooring.solve_line_bvp(span, dh, segments, **kw)
    line = mooring.Line(
        [mooring.Segment(*s) for s in segments], [mooring.ClumpWeight(1, 2e4)], seabed=0.0, friction=0.3
    ).solve(span, dh)
    ours, closed = b.tensions(), line.tensions()
    assert list(ours["segment"]) == [0, 1, 2]
    np.testing.assert_allclose(ours["length"], [s[0] for s in segments], rtol=1e-15)
    # at the joints the P1-DG tension field is O(h²): 6e-5 of T_B at 64 elements, 1.4e-5 at 128
    # on the free line of this module (the field is superconvergent at the elements' Gauss
    # points, 2e-7); the ends are the support reactions
    scale = line.T_B
    for column in {"T_lower", "T_upper", "H_lower", "H_upper"} & set(closed.columns):
        np.testing.assert_allclose(ours[column], closed[column], rtol=0, atol=1e-4 * scale, err_msg=column)
    np.testing.assert_allclose(ours["grounded_length"], closed["grounded_length"], atol=1e-8 * b.length)
    assert ours["T_lower"][0] == b.T_A and ours["T_upper"].iloc[-1] == b.T_B


def test_a_line_model_in_space_is_its_2d_solution_rotated():
    chain = LineBVP([(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.4)
    anchor, heading = np.array([10.0, -20.0, -200.0]), np.radians(37.0)
    fairlead = anchor + [780.0 * np.cos(heading), 780.0 * np.sin(heading), 186.0]
    line = mooring.line_3d(chain, anchor, fairlead)
    flat = chain.solve(780.0, 186.0)
    assert isinstance(line.solution, LineBVPSolution) and line.solution.model is chain
    e = np.array([np.cos(heading), np.sin(heading), 0.0])
    np.testing.assert_allclose(line.force_on_fairlead, -flat.H_B * e + [0, 0, -flat.V_B], rtol=1e-12)
    points = line.profile(51)
    points = points[0] if isinstance(points, tuple) else points  # (points, tension) before 0.2
    np.testing.assert_allclose(points[[0, -1]], [anchor, fairlead], atol=1e-9 * 850.0)
    # the 3x3 stiffness against central differences of the fairlead force
    K, h = line.stiffness(), 1e-2
    numeric = np.column_stack(
        [
            -(
                mooring.line_3d(chain, anchor, fairlead + h * step).force_on_fairlead
                - mooring.line_3d(chain, anchor, fairlead - h * step).force_on_fairlead
            )
            / (2 * h)
            for step in np.eye(3)
        ]
    )
    np.testing.assert_allclose(K, numeric, rtol=0, atol=1e-6 * np.abs(K).max())


def test_a_warm_start_gives_the_cold_solution():
    model = LineBVP([(440.0, 1000.0, 5e8)], seabed=0.0, friction=0.5)
    cold = model.solve(400.0, 100.0)
    previous = model.solve(402.0, 99.0)
    warm = model.solve(400.0, 100.0, start=previous)
    # both converged on meshes graded from different paths: they agree to the discretisation
    assert warm.H_B == pytest.approx(cold.H_B, rel=1e-9) and warm.V_B == pytest.approx(cold.V_B, rel=1e-9)
    assert warm.problem.slack_end == pytest.approx(cold.problem.slack_end, rel=1e-6)
    other = mooring.solve_line_bvp(400.0, 100.0, [(440.0, 1000.0, 5e8)], seabed=0.0)
    for start in (other, (1e5, 2e5)):
        with pytest.raises(InputError) as info:
            model.solve(400.0, 100.0, start=start)
        assert info.value.argument == "start"


def test_the_model_checks_its_arguments_once():
    for kwargs, argument in [
        ({"friction": 0.2}, "friction"),
        ({"seabed": 0.0, "friction": -1.0}, "friction"),
        ({"seabed_slope": lambda x: 0 * x}, "seabed_slope"),
        ({"n_elements": 2.5}, "n_elements"),
        ({"rtol": [1e-10, 1e-9]}, "rtol"),
        ({"point_loads": [(500.0, 1.0)]}, "point_loads"),
    ]:
        with pytest.raises(InputError) as info:
            LineBVP([(440.0, 1000.0, 5e8)], **kwargs)
        assert info.value.argument == argument, kwargs
    with pytest.raises(InputError) as info:
        LineBVP([(440.0, 1000.0, 5e8)], seabed=0.0).solve(400.0, -1.0)  # B below the seabed
    assert info.value.argument == "dh"


def test_a_spread_mooring_of_bvp_lines_equals_the_closed_form_one():
    example = runpy.run_path(str(ROOT / "examples" / "spread_mooring.py"))
    closed = example["system"]()
    line = LineBVP([(example["LENGTH"], example["W"], example["EA"])], seabed=0.0)
    bvp = mooring.MooringSystem(closed.body, [line] * 3, closed.anchors, depth=example["DEPTH"])
    push = dict(force=example["FORCE"], moment=example["MOMENT"])
    ours, theirs = bvp.equilibrium(**push), closed.equilibrium(**push)
    # the lines' forces agree to 2e-8 (the BVP's discretisation at 64 elements): the offset of
    # 56 m to 1e-7 m, the heel to 1e-9 rad
    np.testing.assert_allclose(ours.position[:3], theirs.position[:3], rtol=0, atol=1e-7)
    np.testing.assert_allclose(ours.position[3:], theirs.position[3:], rtol=0, atol=1e-9)
    tensions = [[line.tension_at_fairlead for line in eq.lines] for eq in (ours, theirs)]
    np.testing.assert_allclose(*tensions, rtol=1e-7)
    K, K_closed = ours.stiffness(), theirs.stiffness()
    np.testing.assert_allclose(K, K_closed, rtol=0, atol=1e-7 * np.abs(K_closed).max())


def test_a_mooring_of_bvp_lines_on_a_coarse_mesh_warns_from_its_equilibrium():
    """The spread mooring of `test_a_spread_mooring_of_bvp_lines_equals_the_closed_form_one` with
    its line BVPs on 8 elements: the bend where each chain lands is not resolved, and the
    equilibrium (an answer, where the line solves inside it are trials) warns
    (`skcable.errors.ResolutionWarning`), naming the caller's line; its fairlead tensions are off
    the closed form's by more than 1e-5 (measured 9.4e-5)."""
    example = runpy.run_path(str(ROOT / "examples" / "spread_mooring.py"))
    closed = example["system"]()
    line = LineBVP([(example["LENGTH"], example["W"], example["EA"])], seabed=0.0, n_elements=8)
    bvp = mooring.MooringSystem(closed.body, [line] * 3, closed.anchors, depth=example["DEPTH"])
    push = dict(force=example["FORCE"], moment=example["MOMENT"])
    with pytest.warns(ResolutionWarning, match="do not resolve a bend") as caught:
        ours = bvp.equilibrium(**push)
    assert all(Path(w.filename) == Path(__file__) for w in caught)
    tensions = [[line.tension_at_fairlead for line in eq.lines] for eq in (ours, closed.equilibrium(**push))]
    assert np.max(np.abs(np.subtract(*tensions)) / tensions[1]) > 1e-5


def test_a_line_the_model_choice_solves_by_its_bvp_takes_the_elements_it_needs():
    """The survey's scene 3:160 as a `mooring.Line`: a chain split at its 10.3 kN clump (joint 1),
    a light rope, over a seabed 7.1 m below the anchor; it touches down between its ends, so
    `line_in_plane` solves it by the line BVP. Its bend at the bottom has a radius of a few
    centimetres: on the model's 64 elements H was 11.02 N (8 % low) and V_A 6e-4 off, on 256 still
    1.6 % off, both flagged by the resolution check (`skcable.mooring.line_bvp.check.unresolved`).
    The model now solves it again on four times the elements until the check passes (1024 here),
    says so in its reason, and is within 1e-5 of the largest end force of the same line with the
    chain whole and the clump a point load inside it (other joints, another mesh), by the line in
    space on 1024 elements (measured 1.3e-6)."""
    chain, rope = (1151.2050522936047, 342377713.3053049), (19.835188621190447, 10534704.169814138)
    lengths = (24.145342086592702, 73.23715508631014 - 24.145342086592702, 341.53988038717597)
    segments = [(lengths[0], *chain), (lengths[1], *chain), (lengths[2], *rope)]
    line = mooring.Line(
        [mooring.Segment(*seg) for seg in segments], [mooring.ClumpWeight(1, 10272.346177262758)]
    )
    span, dh, seabed = 399.88638259698047, 2.3202982852674046, -7.0821617336914935
    solved = mooring.line_in_plane(line, span, dh, seabed=seabed)
    assert solved.model == "bvp" and solved.reason.endswith("on 1024 elements (64 did not resolve it)")
    whole = [(lengths[0] + lengths[1], *chain), (lengths[2], *rope)]
    space = solve_line_bvp_3d(
        (0.0, 0.0, 0.0), (span, 0.0, dh), whole, point_loads=[(lengths[0], 10272.346177262758)],
        seabed=seabed, n_elements=1024,
    )  # fmt: skip
    want = np.array([space.force_on_anchor[0], -space.force_on_anchor[2], -space.force_on_fairlead[2]])
    got = np.array([solved.H_A, solved.V_A, solved.V_B])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-5 * np.abs(want).max())


def test_the_nested_solves_retry_from_scratch_and_skip_a_failing_coarse_level():
    """`skcable.mooring.line_bvp.mesh.solve_nested`, the plane line's and the line in space's:
    with levels that fail where told, the calls are the documented policy's: a level that fails
    from the coarser solution is solved from scratch, a coarse one that fails even so is skipped
    (the next starts from scratch), and the finest level's failure is raised."""
    from skcable.errors import ConvergenceError
    from skcable.mooring.line_bvp.mesh import nested_sizes, solve_nested

    assert nested_sizes(256) == [32, 64, 128, 256]

    def levels(failing):
        calls = []

        def level(size, coarser):
            calls.append((size, coarser))
            if (size, coarser is None) in failing:
                raise ConvergenceError(f"level {size}", [])
            return size

        return calls, level

    calls, level = levels({(64, False), (64, True)})
    assert solve_nested(256, level) == 256
    assert calls == [(32, None), (64, 32), (64, None), (128, None), (256, 128)]
    calls, level = levels({(256, False), (256, True)})
    with pytest.raises(ConvergenceError, match="level 256"):
        solve_nested(256, level)
    assert calls[-2:] == [(256, 128), (256, None)]


def test_the_plane_line_is_checked_by_an_assembly_of_its_own():
    """The plane line's equilibrium residual (`skcable.mooring.line_bvp.check`, the line in
    space's: scikit-fem's own ``asm``, not the solve's assembly) lies within its bound on a
    grounded line with friction and on a line with a clump and a sloping seabed (measured 2.5e-9
    and 4.1e-9 N/m, the bound 1e-5), and the check fails where the line is not in equilibrium:
    one node of the suspended part moved up by 1e-6 of the length (52 and 35 N/m measured)
    raises naming ``solve_line_bvp``."""
    from skcable.errors import ConvergenceError

    segments = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    lines = [
        mooring.solve_line_bvp(800.0, 150.0, [(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.5, n_elements=80),
        mooring.solve_line_bvp(800.0, 150.0, segments, seabed=lambda x: -0.02 * x, point_loads=[(420, 2e4)]),
    ]
    for line in lines:
        assert line.equilibrium_residual <= line.residual_bound <= 1e-8 * 1000.0
        z, s = line.dofs.copy(), line.problem.basis.doflocs[0]
        k = int(np.argmin(np.abs(s - 0.9 * line.length)))  # a node of the suspended part
        z[line.problem.N + k] += 1e-6 * line.length  # moved up
        moved = LineBVPSolution(line.problem, z, line.history, line.state)
        with pytest.raises(ConvergenceError, match="solve_line_bvp: the equilibrium residual"):
            moved.check()


def test_a_spurious_frictionless_line_stops_the_slack_estimate_by_name():
    """`skcable.mooring.line_bvp.slack.slack_estimate` on a frictionless solution that pushes at
    its fairlead (H < 0: a spurious branch; seen as H = −23.9 N in the plane survey's scene 1:71
    before the sloped start) raises a `ConvergenceError` with the solve's history, not scipy's
    bare ValueError from a bracket with no sign change."""
    from types import SimpleNamespace

    from skcable.errors import ConvergenceError
    from skcable.mooring.line_bvp.slack import slack_estimate

    spurious = SimpleNamespace(
        H=-23.9,
        s_touchdown=50.0,
        history=[1e-3, 1e-12],
        touches_beyond_anchor=lambda: True,
        seabed_slope_at=lambda s: -0.008,
        load_before=lambda s: (0.0, 70.0 * s),
    )
    with pytest.raises(ConvergenceError, match="H = -23.9 N") as err:
        slack_estimate(spurious, 1.0)
    assert err.value.history == [1e-3, 1e-12]
