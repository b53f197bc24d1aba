"""Any line geometry a mooring system produces: either end higher, buoyant segments, a touchdown
between two suspended ends, both ends on the seabed, an end on a sloped seabed, and the line BVP
where no closed form holds, each chosen with its reason.

References: the closures solved at 30 digits with mpmath (`tests.mooring.mooring_reference`),
MoorPy's published test values (``tests/test_catenary.py`` of MoorPy: its buoyant line, its
symmetric U, its sloped mirror), the lying line's tension from its stretch written here, central
differences of the end forces for the stiffness.
"""

import math

import numpy as np
import pytest

from skcable import cable, mooring
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.bathymetry import Plane
from tests.mooring.mooring_reference import (
    free_line,
    grounded_multi,
    slope_touchdown_line,
    sloped_line,
    taut_length_on_slope,
    touchdown_line,
)

W, EA = 2456.82, 1.2326e9


def test_buoyant_line_of_moorpy_test_catenary():
    # MoorPy tests/test_catenary.py, case 5: x, z, L, EA, w = 37.97, 20.49, 100, 7.51e8, -881.05
    x, z, L, EA_, w = 37.96888656874307, 20.49078283711694, 100.0, 751000000.0, -881.0549577007893
    line = mooring.Line([mooring.Segment(L, w, EA_)])
    r = mooring.line_in_plane(line, x, z, seabed=-1245.2679469540894)
    assert r.model == "free"
    H, V_A, V_B = free_line(x, z, [(L, w, EA_)], (r.H_B, r.V_B))
    np.testing.assert_allclose([r.H_A, r.V_A, r.H_B, r.V_B], [H, V_A, H, V_B], rtol=1e-12)
    # MoorPy's desired fAH, fAV, fBH, fBV (the forces on the ends; its rtol 1e-5)
    desired = [6428.437434537766, 53178.729367882406, -6428.437434537766, 34926.76640219652]
    np.testing.assert_allclose([r.H_A, -r.V_A, -r.H_B, -r.V_B], desired, rtol=1e-5)
    # the line floats: it pulls both ends up, by its buoyancy in all
    assert r.V_A < 0 and r.V_B < 0
    assert r.V_A + r.V_B == pytest.approx(w * L, rel=1e-12)


def test_buoyant_line_given_from_its_upper_end():
    line = mooring.Line([mooring.Segment(100.0, -881.0549577007893, 7.51e8)])
    up = mooring.line_in_plane(line, 37.96888656874307, 20.49078283711694)
    down = mooring.line_in_plane(line, 37.96888656874307, -20.49078283711694)
    np.testing.assert_allclose(
        [down.H_A, down.V_A, down.H_B, down.V_B], [up.H_B, up.V_B, up.H_A, up.V_A], rtol=1e-13
    )


def test_symmetric_u_of_moorpy_test_catenary():
    # MoorPy's test_catenary_symmetricU: catenary(100, 0, 130, 1e12, 100, CB=-20), against its half line
    line = mooring.Line([mooring.Segment(130.0, 100.0, 1e12)])
    u = mooring.line_in_plane(line, 100.0, 0.0, seabed=-20.0)
    assert u.model == "touchdown between the ends"
    s = u.solution
    H, V_A, V_B = touchdown_line(100.0, 0.0, 100.0, 1e12, 130.0, 20.0, (s.H, s.V_A, s.V_B))
    np.testing.assert_allclose([u.H_A, u.V_A, u.H_B, u.V_B], [H, V_A, H, V_B], rtol=1e-10)
    half = mooring.line_in_plane(mooring.Line([mooring.Segment(65.0, 100.0, 1e12)]), 50.0, 20.0, seabed=0.0)
    np.testing.assert_allclose(
        [u.H_A, u.V_A, u.H_B, u.V_B], [half.H_B, half.V_B, half.H_B, half.V_B], rtol=1e-9
    )


def test_sloped_mirror_of_moorpy():
    # MoorPy's test_sloped_mirror: a 10 degree slope, the line seen from either end
    t = math.tan(math.radians(10.0))
    line = mooring.Line([mooring.Segment(80.0, 100.0, 1e12)])
    up = mooring.line_in_plane(line, 60.0, 40.0, seabed=0.0, seabed_slope=t)
    down = mooring.line_in_plane(line, 60.0, -40.0, seabed=-(40.0 - 60.0 * t), seabed_slope=-t)
    assert up.model == down.model == "grounded (slope)"
    ref = sloped_line(60.0, 40.0, 100.0, 1e12, 80.0, t, 0.0, (up.H_B, up.length_on_seabed))
    np.testing.assert_allclose([up.H_A, up.V_A, up.H_B, up.V_B], ref, rtol=1e-10)
    np.testing.assert_allclose(
        [down.H_A, down.V_A, down.H_B, down.V_B], [ref[2], ref[3], ref[0], ref[1]], rtol=1e-10
    )
    moorpy = pytest.importorskip("moorpy.Catenary")
    fAH, fAV, fBH, fBV, _ = moorpy.catenary(60, 40, 80, 1e12, 100.0, CB=0, alpha=10, Tol=1e-5, MaxIter=50)
    np.testing.assert_allclose([up.H_A, -up.V_A, -up.H_B, -up.V_B], [fAH, fAV, fBH, fBV], rtol=1e-5)


def test_neither_end_on_a_slope_hangs_free_where_it_clears_it():
    """Both ends above a 6° slope, the line clear of it: the free elastic catenary (the 30-digit
    closure), from either end."""
    t = math.tan(math.radians(6.0))
    line = mooring.Line([mooring.Segment(400.0, W, EA)])
    for dh, seabed in ((60.0, -60.0), (-60.0, -140.0)):  # the lower end 60 m, then 40 m above it
        r = mooring.line_in_plane(line, 380.0, dh, seabed=seabed, seabed_slope=t)
        assert r.model == "free" and "clear of it" in r.reason
        H, V_A, V_B = free_line(380.0, dh, [(400.0, W, EA)], (r.H_B, r.V_B))
        np.testing.assert_allclose([r.H_A, r.V_A, r.H_B, r.V_B], [H, V_A, H, V_B], rtol=1e-10)


#: a chain between ends 40 m and 60.06 m above a 6° slope, 380 m apart: the longest it holds taut
SLOPE_SCENE = dict(span=380.0, dh=60.0, seabed=-40.0, slope=math.tan(math.radians(6.0)))


def _slope_ends(L, span, dh, b, t, start):
    """``(H_A, V_A, H_B, V_B)`` of the 30-digit closure of the line touching down on the slope
    (`tests.mooring.mooring_reference.slope_touchdown_line`, A on the slope's lower side) and its
    unknowns, from ``start = (H_2, ℓ, s_1)``."""
    H1, s1, ell, H2 = slope_touchdown_line(span, dh, W, EA, L, b, t, start)
    return np.array([H1, W * s1 - H1 * t, H2, H2 * t + W * (L - s1 - ell)]), (H2, ell, s1)


def test_a_line_touching_down_on_a_slope_between_its_ends_is_its_closed_form():
    """A frictionless line that sags onto a slope between its ends hangs, lies on it (its tension
    growing uphill by the weight's component) and rises: the 30-digit closure
    (`tests.mooring.mooring_reference.slope_touchdown_line`) gives its state. `line_in_plane`
    takes it in closed form (`touchdown_on_slope`), from either end, within 1e-9; the line BVPs
    (`solve_line_bvp`, either way up), started from it, converge to it within their
    discretisation (before, both stagnated from the flat line lifted onto the slope); the slope's
    reaction is normal to it (no friction): the ends' forces and the weight leave no net force
    along the slope; the Jacobian is the closure's, by its central differences."""
    span, dh, b, t = SLOPE_SCENE.values()
    mirrored = dict(seabed=b - dh + span * t, seabed_slope=-t)  # seen from B: the slope falls
    for L in (420.0, 440.0, 450.0):
        closed = cable.seabed.slope_touchdown(span, dh, W, EA, L, seabed=b, seabed_slope=t)
        H2 = closed.H_low + W * closed.lying * t / (1.0 + t * t)  # T grows by w ℓ sin α: H by w ℓ sin α cos α
        ends, unknowns = _slope_ends(L, span, dh, b, t, (H2, closed.lying, closed.s_low))
        np.testing.assert_allclose([closed.s_low, closed.lying], [unknowns[2], unknowns[1]], rtol=1e-9)
        line = mooring.Line([mooring.Segment(L, W, EA)])
        r = mooring.line_in_plane(line, span, dh, seabed=b, seabed_slope=t)
        down = mooring.line_in_plane(line, span, -dh, **mirrored)
        assert r.model == down.model == "touchdown on the slope"
        np.testing.assert_allclose([r.H_A, r.V_A, r.H_B, r.V_B], ends, rtol=1e-9)
        np.testing.assert_allclose([down.H_A, down.V_A, down.H_B, down.V_B], ends[[2, 3, 0, 1]], rtol=1e-9)
        for bvp, want in (
            (
                mooring.solve_line_bvp(span, dh, [mooring.BVPSegment(L, W, EA)], seabed=b, seabed_slope=t),
                ends,
            ),
            (
                mooring.solve_line_bvp(span, -dh, [mooring.BVPSegment(L, W, EA)], **mirrored),
                ends[[2, 3, 0, 1]],
            ),
        ):
            got = [bvp.H_A, bvp.V_A, bvp.H_B, bvp.V_B]
            np.testing.assert_allclose(got, want, rtol=0, atol=2e-6 * np.abs(want).max())
        x, y = r.xy(np.linspace(0.0, L, 4001)).T
        assert (y - b - t * x).min() > -1e-9 * L and (y - b - t * x).min() < 1e-9 * L  # on the slope
        net = np.array([r.H_B - r.H_A, r.V_A + r.V_B - W * L])
        assert abs(net @ np.array([1.0, t])) < 1e-9 * W * L and net[1] < 0.0
    h = 1e-3  # m: the closure's central differences in the span and the ends' heights
    moves = [(h, 0.0, 0.0), (0.0, -h, -h), (0.0, h, 0.0)]  # span; A up (dh and the seabed down); B up
    columns = [
        (
            _slope_ends(L, span + a, dh + c, b + d, t, unknowns)[0]
            - _slope_ends(L, span - a, dh - c, b - d, t, unknowns)[0]
        )
        / (2 * h)
        for a, c, d in moves
    ]
    J = np.array(columns).T
    np.testing.assert_allclose(r.jacobian(), J, rtol=0, atol=1e-5 * np.abs(J).max())


def test_the_closed_form_reaches_a_touchdown_where_the_slope_rises_above_the_lower_end():
    """A line whose free shape dips deepest below the slope where the slope lies above its lower
    end (a flat seabed there would be above that end): the continuation about the foot under the
    lower end reaches it, within 1e-9 of the 30-digit closure (before, `touchdown_on_slope`
    refused it as not touching the slope). Its arguments are refused by name."""
    span, dh, b, m, L, w, ea = (
        100.0,
        32.76473582111275,
        -10.721255518454745,
        0.2350370961240092,
        120.1349501436221,
        20.0,
        2e6,
    )
    r = cable.seabed.touchdown_on_slope(span, dh, w, ea, length=L, seabed=b, seabed_slope=m)
    start = (r.H_B, r.length_on_seabed, r.touchdown.s_low)
    H1, s1, ell, H2 = slope_touchdown_line(span, dh, w, ea, L, b, m, start)
    want = [H1, w * s1 - H1 * m, H2, H2 * m + w * (L - s1 - ell)]
    np.testing.assert_allclose([r.H_A, r.V_A, r.H_B, r.V_B], want, rtol=1e-9)
    assert r.length_on_seabed == pytest.approx(ell, rel=1e-9)
    for name, bad in (("length", dict(length=-1.0)), ("length", dict(length="x")), ("EA", dict(EA=math.inf))):
        scene = dict(span=span, dh=dh, w=w, EA=ea, length=L, seabed=b, seabed_slope=m) | bad
        with pytest.raises(InputError, match=f"^{name}: "):
            cable.seabed.touchdown_on_slope(
                scene.pop("span"), scene.pop("dh"), scene.pop("w"), scene.pop("EA"), **scene
            )


def test_a_line_longer_than_a_frictionless_slope_holds_taut_is_refused():
    """The longest line the slope holds taut between its ends (`taut_length_on_slope`) is the
    30-digit closure's, where its tension at the lower touchdown is zero; just beyond it the slack
    has no taut state (it heaps at the slope's foot): `line_in_plane`, `solve_line_bvp` and
    `solve_line_bvp_3d` refuse it as ``InputError("length")``, naming the end it heaps under,
    where before they stagnated; 2 % shorter, the line is solved."""
    span, dh, b, t = SLOPE_SCENE.values()
    longest = cable.seabed.taut_length_on_slope(span, dh, W, EA, seabed=b, seabed_slope=t)
    assert longest == pytest.approx(taut_length_on_slope(span, dh, W, EA, b, t, (320.0, 90.0)), rel=1e-10)
    L = longest * (1.0 + 1e-6)
    line = mooring.Line([mooring.Segment(L, W, EA)])
    heaps = r"length: .* longer than the 456\.675 m a frictionless slope holds taut.* below {}"
    with pytest.raises(InputError, match=heaps.format("A")):
        mooring.line_in_plane(line, span, dh, seabed=b, seabed_slope=t)
    with pytest.raises(InputError, match=heaps.format("B")):
        mooring.line_in_plane(line, span, -dh, seabed=b - dh + span * t, seabed_slope=-t)
    with pytest.raises(InputError, match=heaps.format("A")):
        mooring.solve_line_bvp(span, dh, [mooring.BVPSegment(L, W, EA)], seabed=b, seabed_slope=t)
    with pytest.raises(InputError, match=heaps.format("A")):
        mooring.solve_line_bvp_3d(
            (0.0, 0.0, 0.0), (span, 0.0, dh), [mooring.BVPSegment(L, W, EA)], seabed=Plane(b, (t, 0.0))
        )
    with pytest.raises(InputError, match=heaps.format("A")):
        cable.seabed.touchdown_on_slope(span, dh, W, EA, length=L, seabed=b, seabed_slope=t)
    with pytest.raises(InputError, match="seabed: the free line does not dip below the slope"):
        cable.seabed.touchdown_on_slope(span, dh, W, EA, length=390.0, seabed=b, seabed_slope=t)
    shorter = mooring.Line([mooring.Segment(0.98 * longest, W, EA)])
    assert mooring.line_in_plane(shorter, span, dh, seabed=b, seabed_slope=t).H_A > 0
    # 1e-3 short of it the line is nearly slack where it lands: solved so, or a failure saying so
    try:
        r = mooring.solve_line_bvp(
            span, dh, [mooring.BVPSegment(0.999 * longest, W, EA)], seabed=b, seabed_slope=t
        )
    except ConvergenceError as failed:
        assert "nearly slack where it lands on the slope's lower side" in str(failed)
    else:
        assert 0 < r.H_A < 0.02 * r.H_B


def test_a_failure_over_a_slope_says_where_the_line_may_be_longer_than_it_holds_taut():
    """Two segments (a chain, then a rope of 0.6 its weight) over that slope: no closed form, so
    no refusal; 440 m (shorter than the slope holds taut as a uniform line of their mean weight)
    solves, lying on the slope without piercing it; 480 m does not, and the failure says the
    uniform line of its mean weight would be longer than the slope holds taut (a diagnosis)."""
    span, dh, b, t = SLOPE_SCENE.values()
    # the uniform line of their mean weight 0.8 W and their compliance in series, 1.5 L/EA
    longest = cable.seabed.taut_length_on_slope(span, dh, 0.8 * W, EA / 1.5, seabed=b, seabed_slope=t)

    def segments(L):
        return [mooring.BVPSegment(0.5 * L, W, EA), mooring.BVPSegment(0.5 * L, 0.6 * W, 0.5 * EA)]

    r = mooring.solve_line_bvp(span, dh, segments(440.0), seabed=b, seabed_slope=t)
    x, y = r.xy(np.linspace(0.0, 440.0, 4001)).T
    assert r.H_A > 0 and (y - b - t * x).min() > -1e-6 * 440.0
    with pytest.raises(ConvergenceError, match=f"longer than the {longest:.6g} m this frictionless slope"):
        mooring.solve_line_bvp(span, dh, segments(480.0), seabed=b, seabed_slope=t)


def test_both_ends_on_a_slope_is_refused():
    t = math.tan(math.radians(6.0))
    line = mooring.Line([mooring.Segment(400.0, W, EA)])
    with pytest.raises(InputError, match="seabed_slope.*both ends on the sloped seabed"):
        mooring.line_in_plane(line, 380.0, 380.0 * t, seabed=0.0, seabed_slope=t)


def test_sloped_friction_and_stiffness():
    t = math.tan(math.radians(6.0))
    line = mooring.Line([mooring.Segment(420.0, W, EA)], seabed=0.0, friction=0.6)
    r = mooring.line_in_plane(line, 380.0, 150.0, seabed=0.0, seabed_slope=t)
    ref = sloped_line(380.0, 150.0, W, EA, 420.0, t, 0.6, (r.H_B, r.length_on_seabed))
    np.testing.assert_allclose([r.H_A, r.V_A, r.H_B, r.V_B], ref, rtol=1e-10)
    J = r.jacobian()
    h = 1e-4
    for col, (dspan, ddh) in ((0, (h, 0.0)), (2, (0.0, h))):
        up = mooring.line_in_plane(line, 380.0 + dspan, 150.0 + ddh, seabed=0.0, seabed_slope=t)
        down = mooring.line_in_plane(line, 380.0 - dspan, 150.0 - ddh, seabed=0.0, seabed_slope=t)
        numeric = (np.array([up.H_A, up.V_A, up.H_B, up.V_B]) - [down.H_A, down.V_A, down.H_B, down.V_B]) / (
            2 * h
        )
        np.testing.assert_allclose(J[:, col], numeric, rtol=1e-6, atol=1e-6 * np.abs(numeric).max())


def test_lazy_wave_with_a_buoyant_section():
    segments = [(300.0, W, EA), (200.0, W, EA), (150.0, -1500.0, 3e8), (250.0, W, EA)]
    line = mooring.Line([mooring.Segment(*s) for s in segments])
    r = mooring.line_in_plane(line, 600.0, 200.0, seabed=0.0)
    assert r.model == "grounded"
    H, V_B, grounded = grounded_multi(600.0, 200.0, segments, (r.H_B, r.V_B))
    np.testing.assert_allclose([r.H_B, r.V_B, r.length_on_seabed], [H, V_B, grounded], rtol=1e-10)
    # a hump: the buoyant section's top above both its ends
    y = r.xy(np.linspace(500.0, 650.0, 301))[:, 1]
    assert y.max() > max(y[0], y[-1]) + 1.0


def test_both_ends_on_the_seabed():
    line = mooring.Line(
        [mooring.Segment(200.0, W, EA), mooring.Segment(100.0, 500.0, 4e8)], [mooring.ClumpWeight(1, 1e4)]
    )
    taut = mooring.line_in_plane(line, 300.5, 0.0, seabed=0.0)
    assert taut.model == "on the seabed"
    T = 0.5 / (200.0 / EA + 100.0 / 4e8)  # the stretch of the two segments takes the extra half metre
    assert taut.H_A == pytest.approx(T, rel=1e-12) and taut.H_B == pytest.approx(T, rel=1e-12)
    assert taut.V_A == taut.V_B == 0.0
    slack = mooring.line_in_plane(line, 250.0, 0.0, seabed=0.0)
    assert slack.H_A == slack.H_B == 0.0 and slack.solution.heap
    with pytest.raises(InputError) as err:
        slack.stiffness()
    assert err.value.argument == "dh"


def test_anchor_above_the_seabed_several_segments_takes_the_bvp():
    # two equal segments touching down between suspended ends: no closed form for several segments;
    # the BVP agrees with the one-segment three-part closure at the mesh's accuracy
    half = (65.0, 100.0, 1e9)
    line = mooring.Line([mooring.Segment(*half), mooring.Segment(*half)])
    r = mooring.line_in_plane(line, 100.0, 5.0, seabed=-20.0)
    assert r.model == "bvp" and "not one uniform segment" in r.reason
    one = mooring.line_in_plane(mooring.Line([mooring.Segment(130.0, 100.0, 1e9)]), 100.0, 5.0, seabed=-20.0)
    s = one.solution
    H, V_A, V_B = touchdown_line(100.0, 5.0, 100.0, 1e9, 130.0, 20.0, (s.H, s.V_A, s.V_B))
    np.testing.assert_allclose([r.H_A, r.V_A, r.H_B, r.V_B], [H, V_A, H, V_B], rtol=1e-5)


def test_a_buoy_on_the_grounded_part_takes_the_bvp():
    line = mooring.Line(
        [mooring.Segment(400.0, W, EA), mooring.Segment(400.0, W, EA)], [mooring.Buoy(1, 2e5)]
    )
    r = mooring.line_in_plane(line, 720.0, 150.0, seabed=0.0)
    assert r.model == "bvp" and "buoy" in r.reason
    assert r.V_A + r.V_B + r.solution.bvp.normal_force.sum() == pytest.approx(800.0 * W - 2e5, rel=1e-6)


def test_touchdown_between_ends_refuses_friction():
    line = mooring.Line([mooring.Segment(130.0, 100.0, 1e12)], seabed=0.0, friction=0.3)
    with pytest.raises(InputError) as err:
        mooring.line_in_plane(line, 100.0, 0.0, seabed=-20.0)
    assert err.value.argument == "friction"


def test_end_below_the_seabed_is_refused():
    line = mooring.Line([mooring.Segment(130.0, 100.0, 1e12)])
    with pytest.raises(InputError) as err:
        mooring.line_in_plane(line, 100.0, -30.0, seabed=-20.0)
    assert err.value.argument == "seabed"
    with pytest.raises(InputError) as err:  # weightless: straight between two points, no catenary
        mooring.line_in_plane(mooring.Line([mooring.Segment(10.0, 0.0, 1e8)]), 5.0, 1.0)
    assert err.value.argument == "w"


@pytest.mark.parametrize(
    "a, b",
    [([0.0, 0.0, -80.0], [90.0, 30.0, -75.0]), ([90.0, 30.0, -75.0], [0.0, 0.0, -80.0])],
    ids=["a lower", "b lower"],
)
def test_touchdown_between_ends_stiffness_in_space(a, b):
    line = mooring.Line([mooring.Segment(130.0, 100.0, 1e9)])
    r = mooring.line_between(line, a, b, depth=100.0)
    assert r.model == "touchdown between the ends"
    K = r.stiffness()
    p0, h = np.r_[a, b], 1e-4
    numeric = np.empty((6, 6))
    for j in range(6):
        up, down = p0.copy(), p0.copy()
        up[j] += h
        down[j] -= h
        fu = mooring.line_between(line, up[:3], up[3:], depth=100.0).end_forces.ravel()
        fd = mooring.line_between(line, down[:3], down[3:], depth=100.0).end_forces.ravel()
        numeric[:, j] = -(fu - fd) / (2 * h)
    np.testing.assert_allclose(K, numeric, rtol=1e-6, atol=1e-6 * np.abs(K).max())


def test_lazy_wave_in_a_moored_system():
    system = mooring.MooringSystem(depth=200.0)
    hull = system.add_body(
        mooring.RigidBody(mass=3e6, volume=3.3e3, metacentre=(0, 0, 8.0), waterplane_area=400.0)
    )
    riser = [
        mooring.Segment(350.0, W, EA),
        mooring.Segment(120.0, -1200.0, 3e8),
        mooring.Segment(230.0, W, EA),
    ]
    for heading in np.radians([0.0, 120.0, 240.0]):
        c, s = np.cos(heading), np.sin(heading)
        a = system.add_point([650 * c, 650 * s, -200.0], fixed=True)
        system.add_line(mooring.Line(riser), a, system.add_point([15 * c, 15 * s, -10.0], body=hull))
    eq = system.equilibrium(force=(3e5, 0.0, 0.0))
    assert all(line.model == "grounded" for line in eq.lines)
    for line in eq.lines:  # each line's fairlead forces against its mpmath closure
        low, high = line.a, line.b
        span, dh = float(np.hypot(*(high - low)[:2])), float(high[2] - low[2])
        segments = [(s.length, s.w, s.EA) for s in riser]
        H, V_B, _ = grounded_multi(span, dh, segments, (line.plane.H_B, line.plane.V_B))
        np.testing.assert_allclose([line.plane.H_B, line.plane.V_B], [H, V_B], rtol=1e-10)
    net = system.net_force(eq.position, force=(3e5, 0.0, 0.0))
    assert np.abs(net[:3]).max() < 1e-9 * max(line.tension_b for line in eq.lines)
