"""Design to a target, bracketed and guaranteed: each design checked by a forward solve of the
designed line (and its mpmath closure), or of the designed system; an unreachable target refused
with its reachable range."""

import math

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError
from tests.mooring.mooring_reference import grounded_line

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(uplift_angle|position)\\b:skcable.errors.PlausibilityWarning"
)

W, EA, DEPTH = 2456.82, 1.2326e9, 200.0
ANCHOR, FAIRLEAD = np.array([800.0, 0.0, -DEPTH]), np.array([20.0, 0.0, -14.0])
CHAIN = mooring.Line([mooring.Segment(850.0, W, EA)], seabed=0.0, friction=0.5)


def test_length_for_a_pretension_checked_by_a_forward_solve():
    design = mooring.design_line(CHAIN, ANCHOR, FAIRLEAD, target="pretension", value=1.2e6, depth=DEPTH)
    L = design.x
    designed = mooring.Line([mooring.Segment(L, W, EA)], seabed=0.0, friction=0.5)
    forward = mooring.line_between(designed, ANCHOR, FAIRLEAD, depth=DEPTH)
    assert forward.tension_b == pytest.approx(1.2e6, rel=1e-10)
    span, dh = float(np.hypot(*(FAIRLEAD - ANCHOR)[:2])), float(FAIRLEAD[2] - ANCHOR[2])
    H, V_B, _, _ = grounded_line(span, dh, W, EA, L, 0.5, (forward.plane.H_B, forward.plane.V_B))
    assert math.hypot(H, V_B) == pytest.approx(1.2e6, rel=1e-10)


@pytest.mark.parametrize(
    "target, value, vary",
    [
        ("horizontal_tension", 5e5, "length"),
        ("declination", 0.9, "length"),
        ("touchdown", 200.0, "length"),
        ("layback", 400.0, "anchor_radius"),
        ("pretension", 9e5, "anchor_radius"),
    ],
)
def test_each_target(target, value, vary):
    design = mooring.design_line(CHAIN, ANCHOR, FAIRLEAD, target=target, value=value, vary=vary, depth=DEPTH)
    forward = mooring.line_between(design.line, design.anchor, FAIRLEAD, depth=DEPTH)
    plane = forward.plane
    got = {
        "horizontal_tension": plane.H_B,
        "declination": math.atan2(plane.V_B, plane.H_B),
        "touchdown": plane.solution.x_touchdown,
        "layback": forward.span - plane.solution.x_touchdown,
        "pretension": forward.tension_b,
    }[target]
    assert got == pytest.approx(value, rel=1e-10)
    assert design.bracket[0] <= design.x <= design.bracket[1]


def test_clump_weight_for_a_pretension():
    line = mooring.Line(
        [mooring.Segment(700.0, W, EA), mooring.Segment(150.0, W, EA)],
        [mooring.ClumpWeight(1, 1e4)],
        seabed=0.0,
    )
    design = mooring.design_line(
        line, ANCHOR, FAIRLEAD, target="pretension", value=1.3e6, vary="clump", depth=DEPTH
    )
    forward = mooring.line_between(
        mooring.Line(line.segments, [mooring.ClumpWeight(1, design.x)], seabed=0.0),
        ANCHOR,
        FAIRLEAD,
        depth=DEPTH,
    )
    assert forward.tension_b == pytest.approx(1.3e6, rel=1e-10)


def test_an_unreachable_target_names_the_range():
    with pytest.raises(InputError, match=r"out of reach.*takes values in \[") as err:
        mooring.design_line(CHAIN, ANCHOR, FAIRLEAD, target="pretension", value=1e3, depth=DEPTH)
    assert err.value.argument == "value"
    # the range's low end is the line in a heap: its vertical part's weight, by the closure written here
    low = float(str(err.value).split("[")[-1].split(",")[0])
    height = FAIRLEAD[2] + DEPTH
    l_B = 2 * height / (1 + math.sqrt(1 + 2 * W * height / EA))  # w l + w l^2/(2EA) = w height
    assert low == pytest.approx(W * l_B, rel=1e-9)
    with pytest.raises(InputError) as err:
        mooring.design_line(CHAIN, ANCHOR, FAIRLEAD, target="tension", value=1e6, depth=DEPTH)
    assert err.value.argument == "target"


def test_a_symmetric_pattern_checked_by_its_forward_equilibrium():
    def build(length):
        system = mooring.MooringSystem(depth=DEPTH)
        hull = system.add_body(
            mooring.RigidBody(mass=8e6, volume=8.2e3, metacentre=(0, 0, 10), waterplane_area=600.0)
        )
        handles = []
        for h in np.radians([0.0, 120.0, 240.0]):
            c, s = np.cos(h), np.sin(h)
            a = system.add_point([800 * c, 800 * s, -DEPTH], fixed=True)
            line = mooring.Line([mooring.Segment(length, W, EA)], seabed=0.0)
            handles.append(system.add_line(line, a, system.add_point([20 * c, 20 * s, -14.0], body=hull)))
        return system, handles

    system, handles = build(850.0)
    design = mooring.design_pattern(system, handles, target="pretension", value=1.1e6)
    forward_system, _ = build(design.x)
    eq = forward_system.equilibrium()
    np.testing.assert_allclose([line.tension_b for line in eq.lines], 1.1e6, rtol=1e-9)
