"""Lines of one model solved together on arrays (`skcable.mooring.segments.batch`,
`solve_many_between`), against mpmath closures and the line-by-line solve."""

import numpy as np
import pytest

from skcable import mooring
from skcable.mooring import choice
from skcable.mooring.segments.batch import batchable, solve_batch
from tests.mooring.mooring_reference import balance, free_line, grounded_line, reference_forces

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings("ignore:(strain|uplift_angle)\\b:skcable.errors.PlausibilityWarning")

W, EA, L = 2456.82, 1.2326e9, 850.0  # studless chain of 120 mm


def _line(friction):
    return mooring.Line([mooring.Segment(L, W, EA)], seabed=0.0, friction=friction)


@pytest.mark.parametrize("friction", [0.0, 0.5, 3.0])
def test_the_batch_meets_the_mpmath_closure_of_each_scene(friction):
    # grounded lines from a touchdown (friction partly or fully holding the grounded part: 3.0
    # leaves H_A = 0) and lines lifted off the anchor (the vertical force at A upward)
    line = _line(friction)
    spans = np.array([700.0, 760.0, 790.0, 815.0, 600.0, 640.0])
    dhs = np.array([180.0, 186.0, 190.0, 195.0, 560.0, 600.0])
    starts = [line.solve(s + 3.0, d - 1.0) for s, d in zip(spans, dhs, strict=True)]
    solved = solve_batch(line, spans, dhs, starts)
    for sol, span, dh in zip(solved, spans, dhs, strict=True):
        assert sol is not None
        if sol.state.contact:
            H, V_B, H_A, _ = grounded_line(span, dh, W, EA, L, friction, (sol.H, sol.V_B))
            assert abs(sol.H_A - H_A) <= 1e-11 * H
        else:
            H, _, V_B = free_line(span, dh, [(L, W, EA)], (sol.H, sol.V_B))
        assert abs(sol.H - H) <= 1e-11 * H and abs(sol.V_B - V_B) <= 1e-11 * V_B
    assert any(s.state.contact for s in solved) and not all(s.state.contact for s in solved)


def test_a_scene_the_batch_cannot_close_is_left_to_the_line():
    # the middle fairlead moved so close that the slack lies in a heap (H = 0): no root with
    # H > 0, so the array Newton does not converge there and returns None for it alone
    line = _line(0.0)
    spans, dhs = np.array([780.0, 300.0, 790.0]), np.array([186.0, 186.0, 186.0])
    starts = [line.solve(781.0, 186.0)] * 3
    solved = solve_batch(line, spans, dhs, starts)
    assert solved[1] is None and line.solve(300.0, 186.0).heap
    for k in (0, 2):
        alone = line.solve(spans[k], dhs[k])
        assert abs(solved[k].H - alone.H) <= 1e-12 * alone.H


def test_which_lines_are_batched():
    assert batchable(_line(0.5))
    two = [mooring.Segment(400.0, W, EA), mooring.Segment(450.0, 800.0, 5e8)]
    assert not batchable(mooring.Line(two, seabed=0.0))
    assert not batchable(mooring.Line([mooring.Segment(L, W, EA)], [mooring.ClumpWeight(1, 1e4)], seabed=0.0))
    assert not batchable(mooring.Line([mooring.Segment(L, -100.0, EA)]))


def _spread(n_lines, friction):
    system = mooring.MooringSystem(depth=200.0)
    own = dict(mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5.0), metacentre=(0, 0, 10.0))
    body = system.add_body(mooring.RigidBody(**own, waterplane_area=600.0))
    line = mooring.Line([mooring.Segment(L, W, EA)], seabed=0.0, friction=friction)
    for h in np.radians(np.arange(n_lines) * 360.0 / n_lines):
        anchor = system.add_point([800 * np.cos(h), 800 * np.sin(h), -200.0], fixed=True)
        system.add_line(line, anchor, system.add_point([20 * np.cos(h), 20 * np.sin(h), -14.0], body=body))
    return system, body


def test_a_spread_mooring_solved_together_balances_and_matches_line_by_line(monkeypatch):
    n = choice.BATCH + 4
    system, body = _spread(n, 0.5)
    force = {body: (6.0e6, 1.5e6, 0.0)}
    eq = system.equilibrium(force=force)
    solved = []
    original = choice.solve_many_between
    monkeypatch.setattr(
        "skcable.mooring.system.solve_many_between",
        lambda *a: solved.append(sum(x is not None for x in original(*a))) or original(*a),
    )
    eq = system.equilibrium(force=force)
    assert solved and max(solved) == n  # every line solved together at every evaluation
    forces = [reference_forces(line, (W, EA, L), 200.0, 0.5) for line in eq.lines]
    for line, F in zip(eq.lines, forces, strict=True):
        np.testing.assert_allclose(line.end_forces, F, rtol=1e-10, atol=1e-10 * np.abs(F).max())
    # the equilibrium's force scale (the body's weight), moments over its fairleads' arm (20 m)
    scale = max(max(np.abs(F).max() for F in forces), abs(body.weight[2]) + body.buoyancy[2])
    net = balance(eq, forces, {("body", 0): np.r_[force[body], 0, 0, 0]})[("body", 0)]
    assert np.abs(net[:3]).max() < 1e-9 * scale and np.abs(net[3:]).max() < 1e-9 * scale * 20.0
    # the body's own loads (`RigidBody.own_force`) at its tilted equilibrium are the reference's
    own = balance(eq, [np.zeros((2, 3))] * len(forces))[("body", 0)]
    assert np.abs(eq.bodies[0].angles).max() > 1e-4  # tilted: the moments of weight and buoyancy
    np.testing.assert_allclose(body.own_force(eq.bodies[0].position), own, rtol=1e-12, atol=1e-12 * scale)
    monkeypatch.setattr("skcable.mooring.system.BATCH", 10**9)  # line by line
    alone = system.equilibrium(force=force)
    np.testing.assert_allclose(eq.position, alone.position, rtol=0, atol=1e-9 * np.abs(alone.position).max())


def test_a_fairlead_on_the_vertical_of_its_anchor_hangs_straight():
    from scipy.optimize import brentq

    line = _line(0.0)
    hung = mooring.line_between(line, [0.0, 0.0, -200.0], [0.0, 0.0, -14.0], depth=200.0)
    # the line hangs straight down from the fairlead to the seabed, the rest in a heap there: the
    # hanging length ℓ stretches to the height, ℓ + W ℓ²/(2 EA) = 186 m, its top tension W ℓ
    hanging = brentq(lambda ell: ell + W * ell**2 / (2.0 * EA) - 186.0, 0.0, 400.0, xtol=1e-14)
    assert hung.model == "vertical" and hung.state == "on the seabed"
    np.testing.assert_allclose(
        hung.end_forces, [[0.0, 0.0, 0.0], [0.0, 0.0, -W * hanging]], rtol=1e-13, atol=0.0
    )
    assert hung.length_on_seabed == pytest.approx(L - hanging, rel=1e-13)
    # among lines solved together it is left out, for `solve_between` to solve on its own
    ends = [(np.array([800.0, 0.0, -200.0]), np.array([20.0, 0.0, -14.0]))] * (choice.BATCH + 1)
    ends[3] = (np.array([0.0, 0.0, -200.0]), np.array([0.0, 0.0, -14.0]))
    start = mooring.line_between(line, *ends[0], depth=200.0)
    solved = choice.solve_many_between(line, ends, 200.0, [start] * len(ends))
    assert solved[3] is None and all(s is not None for k, s in enumerate(solved) if k != 3)
