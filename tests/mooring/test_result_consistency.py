"""Every line result agrees with itself (issue 32, item 3): its tension field at the line's ends is
the tension its own end forces give (less an attachment carried by the support there), and its
profile starts and ends at its ends, within the error the result claims.

The claim is the result's own: a closed form's closure residual (`residual()`, round-off); a
line in the sea its `ModelChoice.field_error` (for the 3-D line BVP the difference of its tension
field from the same line's on half the elements, measured: the P1 tension converges at h² while
the end forces, the supports' reactions, are good to `ModelChoice.error`). The floor below which
no comparison is asked is the round-off of the closed forms' evaluation (a few hundred ulps of the
largest tension, and of the chord for the positions).
"""

from __future__ import annotations

import numpy as np
import pytest

from skcable import mooring
from skcable.mooring import axial
from skcable.mooring.bathymetry import Plane
from skcable.mooring.sea_line import LineInSeaBetween

#: the round-off floor of a comparison (relative): a closed form's T(s) and its end forces are
#: evaluated by different operations (sqrt of sums against hypot)
FLOOR = 256 * np.finfo(float).eps

CHAIN = mooring.Segment(300.0, 1000.0, 5e8)
WIRE = mooring.Segment(250.0, 400.0, 2e8)
DRAGGED = mooring.Segment(600.0, 1000.0, 5e8, diameter=0.1, cd_normal=1.2)
LAW = axial.StrainFunction(lambda T: T / 2e8 + 4e-3 * (T / 1e6) ** 2, lambda T: 1.0 / 2e8 + 8e-3 * T / 1e12)


def _ends_of(result):
    """``(a, b, F_a, F_b, P_a, P_b)``: the ends, the line's forces on them (N) and the attachments
    the supports carry there (N, down), whatever the result's type."""
    if hasattr(result, "end_forces") and hasattr(result, "a"):
        F_a, F_b = result.end_forces
        a, b = result.a, result.b
    else:
        F_a, F_b = result.force_on_anchor, result.force_on_fairlead
        a, b = result.anchor, result.fairlead
    P_a, P_b = result.line.arrays.P_end  # the line from a to b
    return np.asarray(a), np.asarray(b), np.asarray(F_a), np.asarray(F_b), P_a, P_b


def _claimed(result) -> float:
    """The relative error the result claims for its fields."""
    model = getattr(result, "model_choice", None) or getattr(result, "model", None)
    if hasattr(model, "field_error"):
        return model.field_error
    solution = result.solution
    return float(solution.residual()) if hasattr(solution, "residual") else 0.0


def _assert_consistent(result, length):
    a, b, F_a, F_b, P_a, P_b = _ends_of(result)
    own_a = np.linalg.norm(F_a + [0.0, 0.0, P_a])  # the line's tension there, the attachment aside
    own_b = np.linalg.norm(F_b + [0.0, 0.0, P_b])
    scale = max(np.linalg.norm(F_a), np.linalg.norm(F_b))
    tol = (_claimed(result) + FLOOR) * scale
    T = np.asarray(result.T_of_s(np.array([0.0, length])), dtype=float)
    assert abs(T[0] - own_a) <= tol, (T[0], own_a, tol)
    assert abs(T[1] - own_b) <= tol, (T[1], own_b, tol)
    points, tension = result.profile_with_tension(5)
    np.testing.assert_allclose(tension[[0, -1]], T, rtol=0, atol=tol)
    chord = float(np.linalg.norm(b - a))
    np.testing.assert_allclose(points[[0, -1]], [a, b], rtol=0, atol=(_claimed(result) + FLOOR) * chord)


def _sea(line, a, b):
    return mooring.line_3d(line, a, b)


A, B = (0.0, 0.0, -200.0), (420.0, 160.0, -20.0)
C30, S30 = np.cos(np.radians(30.0)), np.sin(np.radians(30.0))
ALONG = Plane(-200.0, (0.04 * C30, 0.04 * S30))  # a slope along the line at 30°, none across

SEA = {
    "closed form": lambda: _sea(mooring.Line([CHAIN, WIRE], seabed=0.0, friction=0.3), A, B),
    "closed form (slope)": lambda: _sea(
        mooring.Line([mooring.Segment(480.0, 600.0, 4e8)], seabed=ALONG, friction=0.3),
        A,
        (430.0 * C30, 430.0 * S30, -20.0),
    ),
    "closed form (axial laws)": lambda: _sea(
        mooring.Line([mooring.Segment(150.0, 1200.0, 5e9), mooring.Segment(600.0, 40.0, LAW)]),
        (0.0, 0.0, -300.0),
        (390.0, 520.0, -50.0),
    ),
    "3-D line BVP, a current": lambda: _sea(mooring.Line([DRAGGED], current=(0.0, 0.5)), A, (450, 0, -14.0)),
    "3-D line BVP, a current, grounded, attachments at its ends": lambda: _sea(
        mooring.Line(
            [DRAGGED, mooring.Segment(200.0, 300.0, 2e8, diameter=0.08, cd_normal=1.2)],
            [mooring.ClumpWeight(0, 2e4), mooring.ClumpWeight(1, 1e4), mooring.Buoy(2, 1e4)],
            seabed=0.0,
            current=(0.3, 0.4),
        ),
        A,
        (640.0, 60.0, -20.0),
    ),
    "3-D line BVP, a shaped seabed": lambda: _sea(
        mooring.Line([mooring.Segment(500.0, 600.0, 4e8)], seabed=Plane(-200.0, (0.05, 0.02)), friction=0.2),
        A,
        (450.0, 0.0, -20.0),
    ),
}


@pytest.mark.parametrize("scene", sorted(SEA))
def test_a_line_in_the_sea_agrees_with_its_end_forces(scene):
    solved = SEA[scene]()
    assert scene.startswith(solved.model.name)
    assert solved.model.field_error >= solved.model.error
    _assert_consistent(solved, solved.line.length)


def test_a_line_in_the_sea_seen_from_its_other_end_agrees_with_its_end_forces():
    line = mooring.Line(
        [DRAGGED, mooring.Segment(200.0, 300.0, 2e8, diameter=0.08, cd_normal=1.2)],
        [mooring.ClumpWeight(0, 2e4), mooring.ClumpWeight(2, 1e4)],
        current=(0.2, 0.5),
    )
    sea = mooring.line_3d(line, A, (560.0, 120.0, -20.0))
    # the system's view of a line whose fixed end is b: its ends, forces and fields turned round
    flipped = LineInSeaBetween(line, sea, reverse=True)
    turned = [type(p)(2 - p.joint, abs(p.force)) for p in line.attachments]
    flipped.line = type(line)(line.segments[::-1], turned)
    _assert_consistent(flipped, line.length)


PLANE = {
    "free, B lower": lambda: mooring.line_in_plane(
        mooring.Line([CHAIN, WIRE, CHAIN], [mooring.Buoy(2, 5e4)]), 780.0, -350.0
    ),
    "grounded, attachments at both ends": lambda: mooring.line_in_plane(
        mooring.Line(
            [CHAIN, WIRE], [mooring.ClumpWeight(0, 1e4), mooring.ClumpWeight(2, 2e4)], seabed=0, friction=0.5
        ),
        500.0,
        150.0,
        seabed=0.0,
    ),
    "grounded (slope)": lambda: mooring.line_in_plane(
        mooring.Line([mooring.Segment(80.0, 100.0, 1e9)]), 60.0, 40.0, seabed=0.0, seabed_slope=0.17
    ),
    "touchdown between the ends": lambda: mooring.line_in_plane(
        mooring.Line([mooring.Segment(130.0, 100.0, 1e9)]), 100.0, 5.0, seabed=-20.0
    ),
    "touchdown on the slope": lambda: mooring.line_in_plane(
        mooring.Line([mooring.Segment(440.0, 2456.82, 1.2326e9)]),
        380.0,
        60.0,
        seabed=-40.0,
        seabed_slope=0.105,
    ),
    "on the seabed": lambda: mooring.line_in_plane(
        mooring.Line([mooring.Segment(300.0, 100.0, 1e8)]), 300.5, 0.0, seabed=0.0
    ),
}


class _InSpace:
    """A `PlaneLine` seen as a result with ends in space (y the height), for `_assert_consistent`."""

    def __init__(self, plane, line):
        self.plane, self.line, self.solution, self.reversed = plane, line, plane.solution, False
        self.a, self.b = np.zeros(3), np.array([plane.span, 0.0, plane.dh])
        self.end_forces = np.array([[plane.H_A, 0.0, -plane.V_A], [-plane.H_B, 0.0, -plane.V_B]])
        self.T_of_s = plane.T_of_s

    def profile_with_tension(self, n):
        s = np.linspace(0.0, self.plane.length, n)
        xy = self.plane.xy(s)
        return np.column_stack([xy[:, 0], 0.0 * s, xy[:, 1]]), np.asarray(self.plane.T_of_s(s), dtype=float)


@pytest.mark.parametrize("scene", sorted(PLANE))
def test_a_line_in_its_plane_agrees_with_its_end_forces(scene):
    plane = PLANE[scene]()
    assert plane.model == scene.split(",")[0]
    line = plane.solution_line.variant(reverse=True) if plane.reversed else plane.solution_line
    _assert_consistent(_InSpace(plane, line), plane.length)


def test_a_line_between_two_points_and_its_closed_form_agree_with_their_end_forces():
    line = mooring.Line([CHAIN, WIRE, CHAIN], [mooring.ClumpWeight(1, 2e4)], seabed=0.0, friction=0.5)
    between = mooring.line_between(line, [0.0, 0.0, -50.0], [800.0, 30.0, -200.0], depth=200.0)
    assert between.model == "grounded" and between.plane.reversed
    _assert_consistent(between, line.length)
    solution = line.solve(800.0, 150.0)
    in_space = mooring.Line3D(line, np.zeros(3), np.array([800.0, 0.0, 150.0]), solution)
    in_space.line = line
    _assert_consistent(in_space, line.length)


def test_the_check_sees_a_field_off_its_end_forces():  # the assertion above can fail
    solved = SEA["3-D line BVP, a current"]()
    off = LineInSeaBetween(solved.line, solved, reverse=False)
    off.end_forces = off.end_forces * (1.0 + 10.0 * solved.model.field_error)
    with pytest.raises(AssertionError):
        _assert_consistent(off, solved.line.length)


@pytest.mark.parametrize("fit_touchdown", [0, 3])
def test_the_grounded_lengths_by_segment_sum_to_the_length_on_the_seabed(fit_touchdown):
    """Both line BVPs' ``tensions()`` share `length_on_seabed` (from `s_landing` to `s_touchdown`,
    where the balance of forces puts them) out among the segments. The line in space's table took
    the span of its contact nodes instead: without fitting (the touchdown between nodes) its sum
    was half an element off its own `length_on_seabed`."""
    from skcable.mooring.line_bvp.space import solve_line_bvp_3d

    segments = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    plane = mooring.solve_line_bvp(780.0, 160.0, segments, seabed=-20.0, fit_touchdown=fit_touchdown)
    space = solve_line_bvp_3d(
        (0.0, 0.0, 0.0), (780.0, 0.0, 160.0), segments, seabed=-20.0, fit_touchdown=fit_touchdown
    )
    for line in (plane, space):
        assert line.length_on_seabed > 10.0  # lands and lies on it between its ends
        grounded = line.tensions()["grounded_length"].to_numpy()
        assert grounded.sum() == pytest.approx(line.length_on_seabed, rel=1e-12)
