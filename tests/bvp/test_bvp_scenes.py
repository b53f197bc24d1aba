"""`solve_line_bvp` on the scenes `mooring.Line` solves: the defects D4 and D5 of the fuzzing review,
two points of the suspended-cable stability grid, and a seeded sample from taut to slack.

References, independent of the BVP: 40-digit mpmath solutions of the closures written here
(Irvine's elastic catenary, the inextensible catenary, free pieces of several segments), and the
closed-form `mooring.Line` (segment closures, Jonkman's grounded pieces). Tolerances are sized to
what each number can carry: the BVP's discretisation at 64 elements, or the round-off of the data
times the condition number of H (`line_scenes.tolerance`; a taut line's H is set by its strain).
"""

import math

import mpmath as mp
import pytest

from skcable import mooring
from skcable.errors import InputError
from tests.mooring.line_scenes import DISCRETE, EPS, Scene, exact_one_segment, scenes, tolerance

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, taut lines): the
#: answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings("ignore:(strain|uplift_angle)\\b:skcable.errors.PlausibilityWarning")

mp.mp.dps = 40


def _free_pieces(span, dh, segments):
    """(H, V_B) at 40 digits of a line hanging free through ``segments`` (length, w, EA) from A:
    the closure summed over elastic-catenary pieces (Irvine, "Cable Structures", 1981)."""
    span, dh = mp.mpf(repr(span)), mp.mpf(repr(dh))
    segs = [tuple(mp.mpf(repr(float(v))) for v in seg) for seg in segments]
    total = sum(length * w for length, w, _ in segs)

    def closure(H, V_B):
        x = y = mp.mpf(0)
        V = V_B - total  # the vertical force at A's end of the first piece
        for length, w, ea in segs:
            top = V + w * length
            x += H * length / ea + H / w * (mp.asinh(top / H) - mp.asinh(V / H))
            y += (top**2 - V**2) / (2 * w * ea) + (mp.hypot(H, top) - mp.hypot(H, V)) / w
            V = top
        return [x - span, y - dh]

    return closure


def _force_error(b, H, V_B, scale):
    return math.hypot(b.H - H, b.V_B - V_B) / scale


def test_d4_a_taut_line_solves_to_its_round_off():
    # H/wL = 2.2e4: the merit (forces over the total load) stalled at 2e-10 above rtol = 1e-10; its
    # round-off floor eps |J| |z| is sized to the tension (LineProblem.merit_floor)
    sc = Scene(
        603.4299455268164,
        106.88218088197465,
        ((599.6939346579245, 56.07670748136184, 34001765662.077473),),
        seabed=0.0,
    )
    line = sc.line().solve(sc.span, sc.dh)
    H, V_B = exact_one_segment(sc, (line.H, line.V_B))
    b = sc.solve_bvp()
    assert not b.in_contact.any() and b.V_A < 0  # it lifts off the anchor
    # the condition number |d ln H / d ln L| is 47: 64 eps cond = 7e-13 of the fairlead force
    tol = tolerance(sc, line)
    assert _force_error(b, H, V_B, math.hypot(H, V_B)) <= tol  # measured 8e-14
    assert _force_error(line, H, V_B, math.hypot(H, V_B)) <= tol  # the closed form: 7e-13
    assert b.residual() > 1e-10 and b.residual() <= b.problem.merit_floor(b.state)  # at the floor


def test_d5_a_free_line_is_not_judged_a_heap_by_its_uniform_start():
    # a light rope under a heavy chain hangs free; the uniform line of their mean weight lies in a
    # heap on the seabed 192 m below the anchor, and that start once refused the line
    segments = [
        (640.4312524203101, 14.848127473657213, 2536167.6286310744),
        (849.2500712712057, 2703.66249904272, 6494901.897882393),
    ]
    span, dh, bed = 74.48396618457579, 1334.9483700936419, -192.00556567930178
    b = mooring.solve_line_bvp(span, dh, segments, seabed=bed)
    closure = _free_pieces(span, dh, segments)
    H, V_B = (float(v) for v in mp.findroot(closure, (mp.mpf(b.H), mp.mpf(b.V_B))))
    assert H == pytest.approx(134.1838, rel=1e-5)  # mooring.Line's H
    assert not b.in_contact.any()
    assert _force_error(b, H, V_B, max(b.T_A, b.T_B)) < DISCRETE  # measured 5e-10 at 64 elements
    fine = mooring.solve_line_bvp(span, dh, segments, seabed=bed, n_elements=256)
    assert _force_error(fine, H, V_B, max(b.T_A, b.T_B)) < 1e-11  # measured 1.5e-12
    assert abs(fine.H / H - 1) < abs(b.H / H - 1) / 100  # h^4: 8.3e-6 -> 2.6e-8 of H


def _catenary_H(span, dh, w, length):
    """The inextensible catenary's H at 40 digits: sinh(z)/z = sqrt(L² - dh²)/span, H = w span/(2z)."""
    span, dh, w, length = (mp.mpf(repr(float(v))) for v in (span, dh, w, length))
    r = mp.sqrt(length**2 - dh**2) / span
    z = mp.findroot(lambda z: mp.sinh(z) / z - r, mp.acosh(r) + mp.log(2 * mp.acosh(r) + 1))
    return float(w * span / (2 * z))


def _irvine_H(span, dh, w, EA, length, start):
    sc = Scene(span, dh, ((length, w, EA),))
    return exact_one_segment(sc, start)[0]


def test_grid_nearly_taut_and_vertical_inextensible_line_carries_its_round_off():
    # L/c = 1 + 1e-9, dh/span = -100: it stalled at 1.6e-8 from a stiff elastic start (EA = 1e6 wL
    # stretches it by more than its excess); it starts from the inextensible catenary now
    span, dh, w = 100.0, -10000.0, 1.0
    chord = math.hypot(span, dh)
    length = chord * (1 + 1e-9)
    exact = _catenary_H(span, dh, w, length)
    # H moves by cond = L/(2(L - c)) = 5e8 times a relative error of the length; the positions
    # carry eps L each, so the n elements' length carries n eps of it: H carries n eps cond
    cond = length / (2 * (length - chord))
    for n in (64, 256):
        b = mooring.solve_line_bvp(span, dh, [(length, w, None)], n_elements=n)
        assert abs(b.H / exact - 1) <= n * EPS * cond, n  # measured 9.8e-7 and 2.3e-6 (7e-6 and 3e-5 allowed)
        assert abs(b.H / exact - 1) <= b.round_off() <= 20 * abs(b.H / exact - 1)  # its own estimate
    # its elastic counterpart (EA = 1e3 wL) is well conditioned: h^4 to 1e-11
    ea = 1e3 * w * length
    errors = []
    for n in (128, 256):
        b = mooring.solve_line_bvp(span, dh, [(length, w, ea)], n_elements=n)
        errors.append(abs(b.H / _irvine_H(span, dh, w, ea, length, (b.H, b.V_B)) - 1))
    assert errors[1] < 1e-9 and errors[0] / errors[1] > 12  # measured 7.3e-9, 4.3e-10


@pytest.mark.parametrize("ea_over_weight", [None, 1e3])
def test_grid_very_slack_line_converges_at_h4(ea_over_weight):
    # L/c = 100 at dh/span = -3: 31.6 km of line on a 100 m span, the bend at its bottom of radius
    # H/w = 5.8 m
    span, dh, w = 100.0, -300.0, 1.0
    length = math.hypot(span, dh) * 100
    ea = None if ea_over_weight is None else ea_over_weight * w * length
    errors = []
    for n in (128, 256):
        b = mooring.solve_line_bvp(span, dh, [(length, w, ea)], n_elements=n)
        exact = (
            _catenary_H(span, dh, w, length)
            if ea is None
            else _irvine_H(span, dh, w, ea, length, (b.H, b.V_B))
        )
        errors.append(abs(b.H / exact - 1))
    assert errors[1] < 1e-7 and errors[0] / errors[1] > 12  # measured 1.3e-6 and 8.4e-8: h^4


def test_a_heap_of_several_segments_is_refused_by_the_closed_form_verdict():
    sc = Scene(
        330.2148263279923,
        7.127264349326726,
        (
            (333.12029353843093, 77.10696474128885, 57727248.32619054),
            (165.75882016232882, 138.77498082745183, 14244689562112.666),
        ),
        seabed=0.0,
        friction=0.3,
    )
    assert sc.line().solve(sc.span, sc.dh).heap
    with pytest.raises(InputError) as info:
        sc.solve_bvp()
    assert info.value.argument == "length" and "heap" in str(info.value)


def test_a_clump_ending_the_slack_stretch_is_refused_with_its_reason():
    # the clump at joint 2 rests on the seabed with friction 1: the tension is 0 up to it and
    # 2.67 N past it (mooring.Line): its friction is partly mobilised, which the BVP does not model
    sc = Scene(
        13.163859930352952,
        2.5965391453761906,
        (
            (1.9974219031117957, 46.94784029388238, 378438730.62370574),
            (7.108026283035767, 491.6503018941465, 398084566.60430115),
            (5.106888248176905, 1.1699115590581632, 8223714.8662702115),
        ),
        clump=(2, 1091.7996850936095),
        seabed=0.0,
        friction=1.0,
    )
    line = sc.line().solve(sc.span, sc.dh)
    s_clump = sc.segments[0][0] + sc.segments[1][0]
    assert line.T_of_s(s_clump - 1e-6) == 0.0 and line.T_of_s(s_clump + 1e-6) > 2.0
    with pytest.raises(InputError) as info:
        sc.solve_bvp()
    assert info.value.argument == "point_loads" and "partly mobilised" in str(info.value)


def test_rtol_must_be_one_number():
    with pytest.raises(InputError) as info:
        mooring.solve_line_bvp(100.0, 10.0, [(105.0, 10.0, 1e8)], rtol=[1e-10, 1e-9])
    assert info.value.argument == "rtol"


def _check(sc):
    """One generated scene against `mooring.Line` (and mpmath for one segment): the outcome."""
    try:
        line = sc.line().solve(sc.span, sc.dh)
    except InputError:
        return "line refuses"
    if line.heap:
        with pytest.raises(InputError) as info:
            sc.solve_bvp()
        assert info.value.argument == "length", sc
        return "heap"
    try:
        b = sc.solve_bvp()
    except InputError as refused:  # the one documented refusal of a scene Line solves
        assert refused.argument == "point_loads" and "partly mobilised" in str(refused), sc
        return "clump refused"
    scale, tol = max(line.T_A, line.T_B), tolerance(sc, line)
    error = _force_error(b, line.H, line.V_B, scale)
    if error > tol:  # the discretisation at 64 elements: it must converge on a finer mesh
        b = sc.solve_bvp(n_elements=256)
        error = _force_error(b, line.H, line.V_B, scale)
        assert error <= tol, (sc, error, tol)
    if len(sc.segments) == 1 and sc.clump is None and not line.length_on_seabed:
        exact = exact_one_segment(sc, (line.H, line.V_B))
        assert exact is not None and _force_error(b, *exact, scale) <= tol, sc
    return "solved"


def test_a_seeded_sample_of_lines_from_taut_to_slack():
    # the full survey (benchmarks/line_bvp_survey.py) runs thousands of these
    outcomes = [_check(sc) for sc in scenes(seed=26, count=300)]
    assert outcomes.count("solved") >= 180  # the sample is mostly scenes Line solves
    assert "heap" in outcomes
