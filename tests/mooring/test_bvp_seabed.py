"""The arc-length line BVP on a seabed (`solve_line_bvp`) and the sloped-seabed closed form.

References: Jonkman's closed form (`elastic_catenary(..., seabed=0, friction=)`), the
sloped closed form (`sloped_seabed_catenary`) and MoorPy's ``catenary(alpha=)``, shooting on
the segments' elastic-catenary closed forms (scipy ``root``), shooting on the ODE for a
continuously varying weight (``solve_ivp``), statics (forces on the line sum to zero).
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

from skcable import bvp, cable
from skcable.cable.seabed import sloped_seabed_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.mooring import BVPSegment, solve_line_bvp

SPAN, DH, W, EA, L = 400.0, 100.0, 1000.0, 5e8, 440.0
RTOL = 1e-10


def _contact_is_exact(b):
    """Complementarity at the nodes: no penetration beyond round-off, λ >= 0, λ·gap = 0."""
    scale = b.problem.load_scale
    assert b.gap.min() >= -1e-12 * b.length
    assert b.normal_force.min() >= -10 * RTOL * scale
    assert np.all(np.abs(b.gap[b.in_contact]) <= 1e-12 * b.length)
    assert np.all(np.abs(b.normal_force[~b.in_contact]) <= 10 * RTOL * scale)


def _statics(b):
    """Anchor, fairlead and seabed forces on the line against its weight: (vertical, horizontal)."""
    vertical = (b.V_A + b.V_B + b.contact_force[:, 1].sum() - b.weight) / b.weight
    horizontal = (b.H - b.H_A + b.contact_force[:, 0].sum()) / b.weight
    return vertical, horizontal


def test_flat_seabed_converges_to_jonkman_at_h4_with_the_touchdown_fitted():
    ref = cable.elastic_catenary(SPAN, DH, W, EA, length=L, seabed=0.0)
    errors = {}
    for n in (40, 80, 160):
        b = solve_line_bvp(SPAN, DH, [(L, W, EA)], seabed=0.0, n_elements=n)
        errors[n] = [b.H / ref.H - 1, b.V_B / ref.V_B - 1, (b.length_on_seabed - ref.length_on_seabed) / L]
        _contact_is_exact(b)
        assert b.V_A == 0.0 and b.H_A == pytest.approx(b.H, rel=1e-12)  # Jonkman: V_A = 0, H_A = H
        assert max(abs(v) for v in _statics(b)) < 1e-12
    e40, e160 = (np.abs(errors[n]) for n in (40, 160))
    # on the mesh graded by curvature the error still falls at h⁴, unevenly from one doubling to
    # the next: the rate over two doublings
    rate = np.log2(e40 / e160) / 2
    assert np.all(rate > 3.5)  # measured 4.1 (H), 4.6 (V_B, grounded length)
    assert np.all(e160 < 1e-10)  # measured 3.5e-11 (H), 5.6e-13 (V_B), 2.3e-13 (grounded length / L)


def test_nodal_contact_without_fitting_misplaces_the_touchdown_by_less_than_an_element():
    ref = cable.elastic_catenary(SPAN, DH, W, EA, length=L, seabed=0.0)
    for n in (40, 80):
        b = solve_line_bvp(SPAN, DH, [(L, W, EA)], seabed=0.0, n_elements=n, fit_touchdown=0)
        _contact_is_exact(b)
        spacing = L / n / 2  # between P2 nodes
        last = b.contact_s[b.in_contact][-1]
        assert 0.0 <= ref.length_on_seabed - last < spacing  # the true touchdown lies before the next node
        # the vertical balance places it much closer than the nodes do
        assert abs(b.s_touchdown - ref.length_on_seabed) < 0.1 * (ref.length_on_seabed - last)
        assert abs(b.H / ref.H - 1) < 3e-4  # measured 1.1e-4 and 2.0e-4: the error jumps with the mesh


def test_friction_matches_jonkman():
    mu = 0.2
    ref = cable.elastic_catenary(SPAN, DH, W, EA, length=L, seabed=0.0, friction=mu)
    assert ref.H_A > 0  # the whole grounded line is in tension: friction fully mobilised
    b = solve_line_bvp(SPAN, DH, [(L, W, EA)], seabed=0.0, friction=mu, n_elements=80)
    assert b.H == pytest.approx(ref.H, rel=5e-9)  # measured 6.0e-10 on the graded mesh
    assert b.V_B == pytest.approx(ref.V_B, rel=5e-9)
    assert b.H_A == pytest.approx(ref.H_A, rel=1e-8)  # measured 1.1e-9
    assert b.length_on_seabed == pytest.approx(ref.length_on_seabed, rel=1e-9)
    _contact_is_exact(b)
    # friction μN towards the anchor at every contact node
    on = b.in_contact
    assert np.allclose(b.contact_force[on, 0], -mu * b.normal_force[on], rtol=1e-12, atol=0)
    assert max(abs(v) for v in _statics(b)) < 1e-12


def test_friction_that_takes_the_whole_pull_leaves_a_slack_stretch_as_jonkman():
    # Jonkman's H_A = 0 case: the grounded line near the anchor is slack (T = 0), friction is
    # fully mobilised only over the last H/(μw) of the grounded line
    mu = 0.5
    ref = cable.elastic_catenary(SPAN, DH, W, EA, length=L, seabed=0.0, friction=mu)
    assert ref.H_A == 0.0
    s0 = ref.length_on_seabed - ref.H / (mu * W)  # end of the slack stretch
    errors = {}
    for n in (40, 80, 160):
        b = solve_line_bvp(SPAN, DH, [(L, W, EA)], seabed=0.0, friction=mu, n_elements=n)
        errors[n] = [b.H / ref.H - 1, b.V_B / ref.V_B - 1, (b.length_on_seabed - ref.length_on_seabed) / L]
        # H_A = 0 to the tolerance of the slack-stretch search (rtol of the total weight)
        assert abs(b.H_A) <= RTOL * W * L and b.V_A == 0.0
        assert b.tension(np.linspace(0.0, L, 1001)).min() >= -RTOL * W * L  # no compression
        _contact_is_exact(b)
        assert max(abs(v) for v in _statics(b)) < 1e-12
        slack = b.in_contact & (b.contact_s < s0 - L / n)
        sliding = b.in_contact & (b.contact_s > s0 + L / n)
        assert np.all(np.abs(b.contact_force[slack, 0]) <= 1e-12 * W * L)  # no friction where T = 0
        assert np.allclose(b.contact_force[sliding, 0], -mu * b.normal_force[sliding], rtol=1e-12, atol=0)
    e40, e160 = (np.abs(errors[n]) for n in (40, 160))
    assert np.all(np.log2(e40 / e160) / 2 > 3.5)  # measured 4.1 (H), 4.9 (V_B, grounded length)
    assert np.all(e160 < 1e-10)  # measured 3.5e-11 (H), 4.4e-13 (V_B), 1.8e-13 (grounded length / L)
    # s0 is found to a tension RTOL·W·L past it, which friction μW builds in RTOL·L/μ (measured 7e-9 m)
    assert b.problem.slack_end == pytest.approx(s0, abs=RTOL * L / mu)


def test_sloped_closed_form_matches_moorpy():
    catenary = pytest.importorskip("moorpy.Catenary").catenary
    for slope in (0.05, -0.05):
        r = sloped_seabed_catenary(SPAN, DH, W, EA, length=L, seabed_slope=slope)
        fAH, fAV, fBH, fBV, info = catenary(
            SPAN, DH, L, EA, W, CB=0.0, alpha=np.degrees(np.arctan(slope)), Tol=1e-12, MaxIter=500
        )
        assert r.length_on_seabed > 0
        assert r.H == pytest.approx(abs(fBH), rel=1e-10)
        assert r.V_B == pytest.approx(abs(fBV), rel=1e-10)
        assert r.H_A == pytest.approx(abs(fAH), rel=1e-10)
        assert r.length_on_seabed == pytest.approx(info["LBot"], rel=1e-10)
        assert r.residual() < 1e-12


def test_sloped_closed_form_on_a_steep_downslope_and_its_heap():
    # a 45° downslope, slack lines: the flat start of the rotated frame is a heap, the slope
    # still pulls the line taut (found by the review's fuzzing); MoorPy's catenary(alpha=) agrees
    catenary = pytest.importorskip("moorpy.Catenary").catenary
    for length in (145.0, 150.0, 170.0):
        r = sloped_seabed_catenary(100.0, -50.0, 10.0, 1e8, length=length, seabed_slope=-1.0)
        fAH, fAV, fBH, fBV, info = catenary(100.0, -50.0, length, 1e8, 10.0, CB=0.0, alpha=-45.0, Tol=1e-12)
        assert r.H == pytest.approx(abs(fBH), rel=1e-10) and r.V_B == pytest.approx(abs(fBV), rel=1e-10)
        assert r.length_on_seabed == pytest.approx(info["LBot"], rel=1e-10)
    # more line than the L-shape along a level "slope": the heap elastic_catenary returns, refused here
    assert cable.elastic_catenary(500.0, 100.0, 1000.0, 1e9, length=700.0, seabed=0.0).heap
    with pytest.raises(InputError, match="length.*heap"):
        sloped_seabed_catenary(500.0, 100.0, 1000.0, 1e9, length=700.0, seabed_slope=0.0)


@pytest.mark.parametrize("slope, mu", [(0.05, 0.0), (-0.05, 0.1)])
def test_bvp_on_a_slope_matches_the_sloped_closed_form(slope, mu):
    r = sloped_seabed_catenary(SPAN, DH, W, EA, length=L, seabed_slope=slope, friction=mu)
    b = solve_line_bvp(
        SPAN,
        DH,
        [(L, W, EA)],
        seabed=lambda x: slope * x,
        seabed_slope=lambda x: slope + 0 * x,
        friction=mu,
        n_elements=80,
    )
    for name in ("H", "V_B", "H_A"):  # measured 7.9e-9 and 7.6e-10 on the graded mesh
        assert getattr(b, name) == pytest.approx(getattr(r, name), rel=5e-8), name
    assert b.V_A == pytest.approx(r.V_A, abs=1e-6 * r.T_A)
    assert b.length_on_seabed == pytest.approx(r.length_on_seabed, rel=5e-8)  # measured 8.7e-10
    assert b.x_touchdown == pytest.approx(r.x_touchdown, rel=5e-8)
    _contact_is_exact(b)
    assert max(abs(v) for v in _statics(b)) < 1e-12


def test_a_bump_on_the_seabed_statics_and_contact():
    def bed(x):
        return -5.0 + 4.0 * np.exp(-(((x - 120.0) / 25.0) ** 2))

    b = solve_line_bvp(300.0, 60.0, [(340.0, 500.0, 2e8)], seabed=bed, n_elements=80)
    assert max(abs(v) for v in _statics(b)) < 1e-12
    _contact_is_exact(b)
    xy = b.contact_xy[b.in_contact]
    assert xy[0, 0] > 0 and np.any(np.abs(xy[:, 0] - 120.0) < 5.0)  # hangs from A, lies over the bump
    assert b.V_A > 0  # the anchor, above the seabed, holds the part hanging from it
    assert b.s_landing > 0 and b.length_on_seabed == b.s_touchdown - b.s_landing
    # between contact nodes the line may dip below a curved seabed by the P2 chord error only:
    # (node spacing)² / 8 times the largest curvature 2·4/25² of the bump (7e-3 m; measured 6e-4)
    s = np.linspace(0.0, b.length, 2001)
    p = b.xy(s)
    spacing = np.max(np.diff(b.mesh.p[0])) / 2
    assert np.min(p[:, 1] - bed(p[:, 0])) > -(spacing**2) / 8 * (2 * 4.0 / 25.0**2)


def test_no_touchdown_equals_the_line_without_seabed_exactly():
    span, dh, length = 300.0, 50.0, 310.0
    free = solve_line_bvp(span, dh, [(length, W, EA)], n_elements=32)
    high = solve_line_bvp(span, dh, [(length, W, EA)], seabed=-1000.0, n_elements=32)
    assert not high.in_contact.any() and high.s_touchdown == 0.0 and high.length_on_seabed == 0.0
    np.testing.assert_array_equal(free.dofs, high.dofs)
    assert (free.H, free.V_A, free.V_B, free.H_A) == (high.H, high.V_A, high.V_B, high.H_A)
    # and the line without seabed is the arc form of solve_bvp (and Irvine's catenary)
    irvine = cable.elastic_catenary(span, dh, W, EA, length=length)
    assert free.H == pytest.approx(irvine.H, rel=1e-7)  # measured 2e-8 at 32 elements
    assert free.V_A == pytest.approx(irvine.V_A, rel=1e-7)


def _segment_shot(H, V0, segments, points):
    """(Δx, Δy) of free elastic-catenary pieces from a start where the tension is (H, V0)."""
    x = y = 0.0
    V = V0
    for k, (length, w, ea) in enumerate(segments):
        Vb = V + w * length
        x += H * length / ea + H / w * (np.arcsinh(Vb / H) - np.arcsinh(V / H))
        y += (np.hypot(H, Vb) - np.hypot(H, V)) / w + (Vb * Vb - V * V) / (2 * ea * w)
        V = Vb + points.get(k, 0.0)
    return x, y


def test_chain_wire_chain_with_a_clump_weight_matches_shooting():
    segments = [(100.0, 1500.0, 8e8), (250.0, 300.0, 4e8), (60.0, 1500.0, 8e8)]
    clump = 2e4  # N, at the wire–chain joint
    span, dh = 360.0, 120.0
    b = solve_line_bvp(span, dh, segments, point_loads=[(350.0, clump)], n_elements=80)

    def f(u):
        x, y = _segment_shot(u[0], u[1], segments, {1: clump})
        return [x - span, y - dh]

    sol = root(f, [b.H, -b.V_A], tol=1e-14)
    H, V0 = sol.x
    assert np.max(np.abs(f(sol.x))) < 1e-9
    V_B = V0 + sum(seg[0] * seg[1] for seg in segments) + clump
    assert b.H == pytest.approx(H, rel=1e-7)  # measured 1.5e-8 at 80 elements
    assert b.V_A == pytest.approx(-V0, rel=1e-7)
    assert b.V_B == pytest.approx(V_B, rel=1e-7)
    assert max(abs(v) for v in _statics(b)) < 1e-12


def test_chain_wire_chain_grounded_in_the_chain_matches_shooting():
    segments = [(300.0, 1500.0, 8e8), (500.0, 600.0, 4e8), (50.0, 1500.0, 8e8)]
    span, dh = 780.0, 250.0  # about 270 m of the bottom chain on the seabed
    b = solve_line_bvp(span, dh, segments, seabed=0.0, n_elements=120)

    def f(u):
        H, L_B = u
        rest = [(segments[0][0] - L_B, *segments[0][1:]), *segments[1:]]
        x, y = _segment_shot(H, 0.0, rest, {})
        return [L_B * (1 + H / segments[0][2]) + x - span, y - dh]

    sol = root(f, [b.H, b.length_on_seabed], tol=1e-14)
    H, L_B = sol.x
    assert np.max(np.abs(f(sol.x))) < 1e-9 and 0 < L_B < segments[0][0]
    assert b.H == pytest.approx(H, rel=1e-7)  # measured 3.3e-9
    assert b.length_on_seabed == pytest.approx(L_B, rel=1e-7)
    _contact_is_exact(b)


def test_continuously_varying_weight_matches_ode_shooting():
    length, ea, span, dh = 300.0, 3e8, 260.0, 40.0

    def w(s):
        return 800.0 * (1.0 + 0.5 * np.sin(np.pi * s / length))

    b = solve_line_bvp(span, dh, [BVPSegment(length, w, ea)], n_elements=64)

    def shoot(u):
        H, V0 = u

        def rhs(s, state):
            V = V0 + state[2]
            T = np.hypot(H, V)
            stretch = 1.0 + T / ea
            return [H / T * stretch, V / T * stretch, w(s)]

        out = solve_ivp(rhs, (0.0, length), [0.0, 0.0, 0.0], rtol=1e-12, atol=1e-10, method="DOP853")
        return [out.y[0, -1] - span, out.y[1, -1] - dh]

    sol = root(shoot, [b.H, -b.V_A], tol=1e-13)
    H, V0 = sol.x
    assert np.max(np.abs(shoot(sol.x))) < 1e-8
    assert b.H == pytest.approx(H, rel=1e-8)
    assert b.V_A == pytest.approx(-V0, rel=1e-8)


def test_non_convergence_raises_with_history():
    with pytest.raises(ConvergenceError) as info:
        solve_line_bvp(SPAN, DH, [(L, W, EA)], seabed=0.0, n_elements=40, max_iter=1, rtol=1e-14)
    assert len(info.value.history) >= 1


@pytest.mark.parametrize(
    "kwargs, argument",
    [
        ({"seabed": "flat"}, "seabed"),
        ({"seabed": 1.0}, "seabed"),  # above the anchor
        ({"seabed": lambda x: np.nan * x}, "seabed"),
        ({"seabed": lambda x: x[:1]}, "seabed"),
        ({"seabed": 0.0, "seabed_slope": lambda x: 0 * x}, "seabed_slope"),
        ({"seabed_slope": lambda x: 0 * x}, "seabed_slope"),
        ({"friction": 0.1}, "friction"),
        ({"seabed": 0.0, "friction": -0.1}, "friction"),
        ({"seabed": lambda x: 0.5 * x}, "dh"),  # B below the seabed
        ({"point_loads": [(0.0, 1.0)]}, "point_loads"),
        ({"fit_touchdown": 1.5}, "fit_touchdown"),
    ],
)
def test_bad_input_is_named(kwargs, argument):
    with pytest.raises(InputError) as info:
        solve_line_bvp(SPAN, DH, [(L, W, EA)], n_elements=8, **kwargs)
    assert info.value.argument == argument


def test_bad_segments_are_named():
    with pytest.raises(InputError, match="segments"):
        solve_line_bvp(SPAN, DH, [], n_elements=8)
    with pytest.raises(InputError, match="length"):
        solve_line_bvp(SPAN, DH, [(-1.0, W, EA)], n_elements=8)
    with pytest.raises(InputError, match="slope"):
        sloped_seabed_catenary(SPAN, DH, W, EA, length=L, seabed_slope=np.nan)
    with pytest.raises(InputError, match="dh"):
        sloped_seabed_catenary(SPAN, DH, W, EA, length=L, seabed_slope=0.5)


@pytest.mark.parametrize("slack_end", [0.0, 60.0])
def test_generalized_jacobian_agrees_with_central_differences(slack_end):
    # a curved seabed (b'' != 0), friction (with a slack stretch: there friction holds the
    # nodes' own tangential weight), some nodes active and some not; the perturbation keeps
    # every node on its side of the switch λ = c·g, where F is smooth
    from skcable.mooring.line_bvp.contact import seabed_of
    from skcable.mooring.line_bvp.inputs import segments_of
    from skcable.mooring.line_bvp.problem import LineProblem
    from skcable.mooring.line_bvp.start import closed_form_start

    def bed(x):
        return -2.0 + 1.5 * np.sin(x / 40.0)

    problem = LineProblem(
        300.0, 60.0, segments_of([(340.0, 500.0, 2e8)]), [], seabed_of(bed, None, 300.0), 0.15, 12,
        slack_end=slack_end,
    )  # fmt: skip
    assert (problem.contact_rows.held is not None) == (slack_end > 0)
    z = closed_form_start(problem)
    rng = np.random.default_rng(5)
    z = z + 0.01 * rng.standard_normal(z.size)
    z[problem.N + problem.end_a], z[problem.N + problem.end_b] = 0.0, 60.0
    state = problem.assemble(z)
    active = state.terms[4]
    assert active.any() and not active.all()
    d = np.zeros(z.size)
    d[problem.free] = rng.standard_normal(problem.free.size)
    eps = 1e-6
    plus, minus = problem.assemble(z + eps * d), problem.assemble(z - eps * d)
    assert np.array_equal(plus.terms[4], active) and np.array_equal(minus.terms[4], active)
    J = problem.jacobian(state)
    fd = (plus.F - minus.F) / (2 * eps)
    rows = problem.free
    scale = np.max(np.abs(fd[rows]))
    assert np.max(np.abs((J @ d)[rows] - fd[rows])) < 1e-6 * scale


def test_the_seabed_scene_is_the_mooring_lines_and_solve_bvp_says_so():
    """Jonkman's scene solved by the line BVP agrees with the closed form; `solve_bvp`, which
    handed it on in 0.2.0, refuses it naming the mooring line BVP (bvp imports no mooring)."""
    ref = cable.elastic_catenary(SPAN, DH, W, EA, length=L, seabed=0.0, friction=0.2)
    direct = solve_line_bvp(SPAN, DH, [(L, W, EA)], seabed=0.0, friction=0.2, n_elements=80)
    assert direct.H == pytest.approx(ref.H, rel=2e-7)
    for given in ({"seabed": 0.0, "friction": 0.2}, {"friction": 0.2}):
        with pytest.raises(InputError, match=r"skcable\.mooring\.solve_line_bvp") as info:
            bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), length=L, EA=EA, n_elements=80, **given)
        assert info.value.argument == next(iter(given))


def test_inextensible_line_with_a_buoy_on_the_seabed():
    # inextensible: Jonkman's closed form in the limit EA -> inf
    b = solve_line_bvp(SPAN, DH, [(L, W, None)], seabed=0.0, n_elements=80)
    ref = cable.elastic_catenary(SPAN, DH, W, 1e15, length=L, seabed=0.0)
    assert b.H == pytest.approx(ref.H, rel=3e-8)  # measured 3.0e-9 (6e-10 with EA = 5e8)
    # a buoy (upward point force) on the suspended part: statics and contact still exact
    buoyed = solve_line_bvp(
        SPAN, DH, [(200.0, W, EA), (240.0, W, EA)], seabed=0.0, point_loads=[(300.0, -5e4)], n_elements=80
    )
    assert buoyed.weight == pytest.approx(W * L - 5e4, rel=1e-12)
    assert max(abs(v) for v in _statics(buoyed)) < 1e-12
    _contact_is_exact(buoyed)
    assert buoyed.s_touchdown < 300.0


# Scenes of benchmarks/seabed_stability.py (span 100 m, w = 1 N/m, A on a flat seabed) that
# failed before the slack stretch, the graded meshes and the nested solves: (dh/span, slack
# (L - chord)/(span + dh - chord), μ, EA/(wL)).
STABILITY_SCENES = [
    (10.0, 0.5, 5.0, 1e3),  # nearly vertical, friction takes the whole pull: slack stretch
    (0.3, 0.9, 0.5, 1e7),  # slack, a slack stretch of 90 % of the grounded line
    (0.05, 0.5, 0.0, 1e3),  # nearly horizontal: 7 % of the line hangs, a uniform mesh wastes it
    (0.05, 1e-6, 5.0, 1e3),  # taut: the frictionless estimate sees a slack stretch, there is none
]


def _stability_scene(ratio, slack, mu, ea_over_weight):
    span = 100.0
    dh = ratio * span
    chord = float(np.hypot(span, dh))
    length = chord + slack * (span + dh - chord)
    return span, dh, length, ea_over_weight * length


@pytest.mark.parametrize("ratio, slack, mu, ea_over_weight", STABILITY_SCENES)
def test_stability_map_scenes_converge_to_jonkman_at_h4(ratio, slack, mu, ea_over_weight):
    span, dh, length, ea = _stability_scene(ratio, slack, mu, ea_over_weight)
    ref = cable.elastic_catenary(span, dh, 1.0, ea, length=length, seabed=0.0, friction=mu)
    values, errors = {}, {}
    for n in (40, 80):
        b = solve_line_bvp(span, dh, [(length, 1.0, ea)], seabed=0.0, friction=mu, n_elements=n)
        values[n] = np.array([b.H, b.V_B, b.length_on_seabed])
        errors[n] = np.abs(
            values[n] / np.array([ref.H, ref.V_B, length]) - [1, 1, ref.length_on_seabed / length]
        )
        if ref.H_A == 0.0:  # Jonkman's slack stretch: H_A = 0 to rtol of the weight
            assert (
                abs(b.H_A) <= RTOL * length and b.tension(np.linspace(0, length, 501)).min() >= -RTOL * length
            )
        else:
            assert b.H_A == pytest.approx(ref.H_A, rel=1e-6)
        _contact_is_exact(b)
        assert max(abs(v) for v in _statics(b)) < 1e-12
    rate = np.log2(errors[40] / errors[80])
    assert np.all(rate > 3.3)  # measured 3.7-4.3 (H, V_B, grounded length)
    # so the error at 80 elements is within the Richardson bound of the change from 40 to 80
    scale = np.array([ref.H, ref.V_B, length])
    assert np.all(errors[80] <= np.abs(values[80] - values[40]) / scale / (2**3.3 - 1))


def test_a_fine_mesh_finds_its_contact_set_by_nested_solves():
    # 1280 elements from the start's 32-element active set stalled (the contact set crawls a few
    # nodes per Newton iteration); nested solves 40 -> 1280 reach the round-off floor
    span, dh, length, ea = _stability_scene(1.0, 0.5, 0.0, 1e7)
    ref = cable.elastic_catenary(span, dh, 1.0, ea, length=length, seabed=0.0)
    b = solve_line_bvp(span, dh, [(length, 1.0, ea)], seabed=0.0, n_elements=1280)
    assert b.H == pytest.approx(ref.H, rel=1e-10)  # measured 1e-12
    assert b.V_B == pytest.approx(ref.V_B, rel=1e-10)
    _contact_is_exact(b)


# Scenes of benchmarks/seabed_stability.py that raised ConvergenceError before the monitor's tail
# term and the fallback starts: nearly L-shaped lines (slack 0.999, the bend at the touchdown of
# radius H/w = 0.5 mm and 6 mm on 100 m and 200 m of line), and μ = 5 on a nearly level slack line
# (friction takes the whole pull 3 cm from the touchdown).
NEAR_L_SCENES = [
    (0.05, 0.999, 0.0, 1e3),  # H/w = 0.54 mm: x = (H/w) asinh(σ w/H) past the touchdown
    (1.0, 0.999, 0.5, 1e7),  # H/w = 6.2 mm, friction takes the whole pull: slack stretch
    (0.05, 0.9, 5.0, 1e3),  # H/w = 0.15 m, a 3 cm friction zone
]


@pytest.mark.parametrize("ratio, slack, mu, ea_over_weight", NEAR_L_SCENES)
def test_nearly_L_shaped_lines_converge_to_jonkman_at_h4(ratio, slack, mu, ea_over_weight):
    span, dh, length, ea = _stability_scene(ratio, slack, mu, ea_over_weight)
    ref = cable.elastic_catenary(span, dh, 1.0, ea, length=length, seabed=0.0, friction=mu)
    values, errors = {}, {}
    for n in (80, 160):
        b = solve_line_bvp(span, dh, [(length, 1.0, ea)], seabed=0.0, friction=mu, n_elements=n)
        values[n] = np.array([b.H, b.V_B, b.length_on_seabed])
        errors[n] = np.abs(
            values[n] / np.array([ref.H, ref.V_B, length]) - [1, 1, ref.length_on_seabed / length]
        )
        if ref.H_A == 0.0:
            assert abs(b.H_A) <= RTOL * length
        # complementarity to the solver's tolerance: the switch min(λ, c g) of a node on a tiny
        # element (c ∝ its length) can leave the first node past the touchdown flagged in
        # contact 4 µm above the seabed with λ = 1.7e-9 N (1.7e-11 of the weight) at 80 elements
        scale = b.problem.load_scale
        assert b.gap.min() >= -1e-12 * b.length
        assert b.normal_force.min() >= -10 * RTOL * scale
        on_bed = np.abs(b.gap) <= 1e-12 * b.length
        assert np.all(on_bed[b.in_contact] | (b.normal_force[b.in_contact] <= 10 * RTOL * scale))
        assert np.all(np.abs(b.normal_force[~b.in_contact]) <= 10 * RTOL * scale)
        assert max(abs(v) for v in _statics(b)) < 1e-12
    # measured 4.5-4.9 (H), 3.8-7.2 (V_B, grounded length); H converged like h (3e-4 of H at
    # 80 elements on the first scene) with the turning-only monitor
    rate = np.log2(errors[80] / errors[160])
    assert np.all(rate > 3.5)
    scale = np.array([ref.H, ref.V_B, length])
    assert np.all(errors[160] <= np.abs(values[160] - values[80]) / scale / (2**3.5 - 1))
    # the fairlead force to the benchmark's tolerance: measured 1e-11 to 1.1e-10 of |T_B|
    force_error = np.hypot(values[160][0] - ref.H, values[160][1] - ref.V_B) / np.hypot(ref.H, ref.V_B)
    assert force_error < 1e-9
