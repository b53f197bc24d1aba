"""Cable terms and Newton options in the line BVP (`solve_line_bvp`, `LineBVP`).

References written here: scipy ``solve_ivp`` shooting solutions of the same ODEs (a line in a
current, lifted off the seabed; a grounded line in a stratified sea, its grounded part in closed
form with Coulomb friction, Jonkman's slack stretch included), central differences of re-solved
lines (the stiffness), central differences of the term's own residual (`skcable.fe.check_tangent`),
the balance of the whole line (the terms' outputs against the end forces) and the drag formula
evaluated by hand.
"""

import pickle

import meshio
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from skcable import bvp, cable, fe, mooring
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.line_bvp.space import LineBVP3D, solve_line_bvp_3d

RHO, G = 1025.0, 9.81

# --- a line in a current, lifted off the seabed ------------------------------------------------

SPAN, DH, LENGTH, W, EA = 300.0, 20.0, 330.0, 400.0, 5e7
BED = -50.3  # the still line sags 0.23 m into it; the current lifts it 0.56 m clear
D, CN, CT, U, SURFACE = 0.1, 1.2, 0.008, 2.5, 100.0
CURRENT = bvp.CurrentDrag(U, D, cd_normal=CN, cd_tangential=CT, surface=SURFACE)


def drag(a):
    """Morison's drag per unstretched length of a current ``(U, 0)`` on a line of tangent ``a``:
    ``½ ρ d |a| (C_n |v_n| v_n + C_t |v_t| v_t)``, by hand."""
    n = np.hypot(*a)
    t = a / n
    v = np.array([U, 0.0])
    vt = (v @ t) * t
    vn = v - vt
    return 0.5 * RHO * D * n * (CN * np.hypot(*vn) * vn + CT * np.hypot(*vt) * vt)


def shoot_in_current(start):
    """``F(0)``, ``F(L)`` (the tension vectors at A and B, towards B) of the line in the current:
    ``dF/ds = −f``, ``dr/ds = (1 + T/EA) F/T`` from A = (0, 0), ``F(0)`` by fsolve on
    ``r(L) = (span, dh)``."""

    def rhs(s, z):
        F = z[2:]
        T = np.hypot(*F)
        a = (1.0 + T / EA) * F / T
        f = drag(a) - [0.0, W]
        return [a[0], a[1], -f[0], -f[1]]

    def end(F0):
        return solve_ivp(rhs, (0.0, LENGTH), [0.0, 0.0, *F0], rtol=1e-12, atol=1e-10, method="DOP853").y[
            :, -1
        ]

    F0 = fsolve(lambda F: end(F)[:2] - [SPAN, DH], start, xtol=1e-12, full_output=True)[0]
    z = end(F0)
    assert np.hypot(z[0] - SPAN, z[1] - DH) < 1e-9 * LENGTH
    return F0, z[2:]


def test_a_current_lifts_the_line_off_the_seabed_as_shooting_says():
    still = mooring.solve_line_bvp(SPAN, DH, [(LENGTH, W, EA)], seabed=BED)
    assert still.in_contact.any()  # without the current the line rests on the seabed
    line = mooring.solve_line_bvp(SPAN, DH, [(LENGTH, W, EA)], seabed=BED, terms=[CURRENT], rtol=1e-12)
    assert not line.in_contact.any() and line.gap.min() > 0.5  # lifted 0.56 m clear
    F0, FL = shoot_in_current([line.H_A, -line.V_A])
    scale = np.hypot(*F0)
    # measured 2.5e-9 of T_A on 64 elements
    assert np.max(np.abs([line.H_A, -line.V_A] - F0)) < 1e-6 * scale
    assert np.max(np.abs([line.H_B, line.V_B] - FL)) < 1e-6 * scale
    assert line.H_A - line.H_B > 0.1 * line.H_B  # the drag loads the anchor more than the fairlead
    # the exact tangent: a full step squares the residual (1e-4 → 7e-9 → 3e-14 measured, the last
    # at the round-off floor, which a polish step may halve): the last step that lands above the
    # floor (1e-12) squares its merit
    h = line.history
    k = max(i for i in range(len(h) - 1) if h[i + 1] > 1e-12)
    assert h[-1] < 1e-12 and h[k + 1] < 10 * h[k] ** 2


# --- a grounded line in a stratified sea ---------------------------------------------------------

GSPAN, GDH, GLENGTH, GW, GEA = 400.0, 100.0, 440.0, 1000.0, 5e8
AREA, GRADIENT, GSURFACE = 0.04, 0.05, 120.0
BUOYANCY = bvp.Buoyancy(AREA, rho=RHO, gradient=GRADIENT, surface=GSURFACE)


def upthrust(y):
    """``ρ(d) g A`` at height ``y`` (N/m), ``ρ = 1025 + 0.05 d``, ``d = 120 − y``."""
    return (RHO + GRADIENT * (GSURFACE - y)) * G * AREA


def shoot_grounded(H, s_td, mu):
    """The line grounded on the flat seabed y = 0 up to ``s_td`` with the horizontal tension ``H``
    at the touchdown: the grounded part in closed form (Jonkman's: ``T = max(H − μ w_n (s_td − s),
    0)``, ``w_n`` the net weight on the seabed, ``x = ∫ (1 + T/EA) ds``), the suspended part
    shot from there. Returns ``(x, y, F_x, F_y)`` at B."""
    wn = GW - upthrust(0.0)
    grip = mu * wn * s_td
    if grip <= H:
        stretch = H * s_td - 0.5 * mu * wn * s_td**2
    else:  # slack near the anchor: T falls to zero at s_td − H/(μ w_n)
        stretch = H * H / (2.0 * mu * wn)

    def rhs(s, z):
        F = z[2:]
        T = np.hypot(*F)
        a = (1.0 + T / GEA) * F / T
        return [a[0], a[1], 0.0, GW - upthrust(z[1])]

    x_td = s_td + stretch / GEA
    return solve_ivp(rhs, (s_td, GLENGTH), [x_td, 0.0, H, 0.0], rtol=1e-12, atol=1e-10, method="DOP853").y[
        :, -1
    ]


@pytest.mark.parametrize("mu", [0.0, 0.2, 0.5], ids=["frictionless", "friction", "slack stretch"])
def test_a_grounded_line_in_a_stratified_sea_matches_shooting(mu):
    line = mooring.solve_line_bvp(GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=0.0, friction=mu, terms=[BUOYANCY])
    assert (line.problem.slack_end > 0) == (mu == 0.5)
    H, s_td = fsolve(
        lambda p: shoot_grounded(*p, mu)[:2] - [GSPAN, GDH],
        [line.H_B, line.s_touchdown],
        xtol=1e-12,
        full_output=True,
    )[0]
    x, y, Fx, V_B = shoot_grounded(H, s_td, mu)
    assert np.hypot(x - GSPAN, y - GDH) < 1e-9 * GLENGTH
    H_A = max(H - mu * (GW - upthrust(0.0)) * s_td, 0.0)
    T_B = np.hypot(H, V_B)
    # measured 6e-10 of T_B on 64 elements; the touchdown 3e-8 m off
    for ours, theirs in ((line.H_B, H), (line.V_B, V_B), (line.H_A, H_A), (line.V_A, 0.0)):
        assert abs(ours - theirs) < 1e-6 * T_B
    assert abs(line.s_touchdown - s_td) < 1e-6 * GLENGTH
    # the stratification matters: a uniform sea moves the end forces by far more than 1e-6
    uniform = bvp.Buoyancy(AREA, rho=RHO + GRADIENT * GSURFACE / 2, surface=GSURFACE)
    other = mooring.solve_line_bvp(GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=0.0, friction=mu, terms=[uniform])
    assert abs(other.V_B - line.V_B) > 1e-4 * T_B


SLOPE = -0.02  # the seabed falls 2 % towards the fairlead
T_BED = np.array([1.0, SLOPE]) / np.hypot(1.0, SLOPE)
SLOPE_CURRENT = bvp.CurrentDrag(1.5, D, cd_normal=CN, cd_tangential=0.05, surface=GSURFACE)


def shoot_on_slope(T_A, s_td):
    """The line on the frictionless seabed ``y = −0.02 x`` up to ``s_td`` and suspended beyond, in a
    current of 1.5 m/s: on the seabed the tension changes by the tangential load,
    ``dT/ds = −(f − (0, w))·t``, the seabed taking the normal one; the suspended part leaves it
    tangentially. Returns ``(x, y, F_x, F_y)`` at B."""
    k = 0.5 * RHO * D * 1.5**2

    def force(a):  # the drag of a current (1.5, 0) by hand, C_n = 1.2, C_t = 0.05, and the weight
        n = np.hypot(*a)
        t = a / n
        vt = t[0] * t
        vn = np.array([1.0, 0.0]) - vt
        return k * n * (CN * np.hypot(*vn) * vn + 0.05 * np.hypot(*vt) * vt) - [0.0, GW]

    def ground(s, z):
        a = (1.0 + z[1] / GEA) * T_BED
        return [a[0], -force(a) @ T_BED]

    x_td, T_td = solve_ivp(ground, (0.0, s_td), [0.0, T_A], rtol=1e-12, atol=1e-10, method="DOP853").y[:, -1]

    def air(s, z):
        F = z[2:]
        T = np.hypot(*F)
        a = (1.0 + T / GEA) * F / T
        return [a[0], a[1], *(-force(a))]

    start = [x_td, SLOPE * x_td, *(T_td * T_BED)]
    return solve_ivp(air, (s_td, GLENGTH), start, rtol=1e-12, atol=1e-10, method="DOP853").y[:, -1]


def test_a_grounded_line_on_a_slope_in_a_current_matches_shooting():
    """The touchdown's balance takes the horizontal force there, not B's: the drag on the
    suspended part changes it by 5.5 % here."""
    line = mooring.solve_line_bvp(
        GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=lambda x: SLOPE * x, terms=[SLOPE_CURRENT]
    )
    T_A, s_td = fsolve(
        lambda p: shoot_on_slope(*p)[:2] - [GSPAN, GDH], [line.T_A, line.s_touchdown], xtol=1e-12,
        full_output=True,
    )[0]  # fmt: skip
    x, y, H_B, V_B = shoot_on_slope(T_A, s_td)
    assert np.hypot(x - GSPAN, y - GDH) < 1e-9 * GLENGTH
    T_B = np.hypot(H_B, V_B)
    # measured 1.4e-9 of T_B and 2e-8 m (B's horizontal force in the balance instead: 0.14 m, 1.3e-6)
    for ours, theirs in ((line.H_B, H_B), (line.V_B, V_B), (line.T_A, T_A)):
        assert abs(ours - theirs) < 1e-7 * T_B
    assert abs(line.s_touchdown - s_td) < 1e-6 * GLENGTH


def test_a_line_its_buoyancy_floats_is_the_mirrored_elastic_catenary():
    """A rope of 300 N/m whose upthrust (0.1 m², a uniform sea) is 1006 N/m: it floats up from the
    anchor on the seabed, the catenary of 706 N/m hung from (0, 0) to (300, −50) turned over."""
    upthrust = bvp.Buoyancy(0.1, rho=RHO, g=G, surface=200.0)
    line = mooring.solve_line_bvp(300.0, 50.0, [(340.0, 300.0, 1e8)], seabed=0.0, terms=[upthrust])
    mirror = cable.elastic_catenary(300.0, -50.0, RHO * G * 0.1 - 300.0, 1e8, length=340.0)
    assert not line.in_contact.any()
    # measured 1.4e-9 of H
    for ours, theirs in (
        (line.H_B, mirror.H),
        (line.H_A, mirror.H),
        (line.V_B, -mirror.V_B),
        (line.V_A, -mirror.V_A),
    ):
        assert abs(ours - theirs) < 1e-7 * mirror.H


class TaperedLoad(bvp.CableTerm):
    """A downward load ``100 + 0.5 s`` N/m along the unstretched arc length ``s`` from A."""

    uses_s = True
    vertical = True

    def forces(self, state):
        return bvp.CableForce(np.array([np.zeros_like(state.s), -(100.0 + 0.5 * state.s)]))


def test_a_term_reading_s_gets_the_arc_length_from_the_anchor():
    """The same load as a weight that varies along the segment (a callable of s): the same
    discrete line, to the last bit here."""
    kw = dict(fit_touchdown=0, rtol=1e-13)
    line = mooring.solve_line_bvp(300.0, 50.0, [(340.0, 300.0, 1e8)], terms=[TaperedLoad()], **kw)
    weight = mooring.solve_line_bvp(300.0, 50.0, [(340.0, lambda s: 400.0 + 0.5 * s, 1e8)], **kw)
    for name in ("H_B", "V_B", "H_A", "V_A"):
        assert abs(getattr(line, name) - getattr(weight, name)) < 1e-12 * line.T_B


# --- the tangent and the stiffness ---------------------------------------------------------------

TERMS = {
    "sheared current": bvp.CurrentDrag(lambda d: 2.5 * (1 - d / 300), 0.1, cd_tangential=0.01, surface=100.0),
    "stratified buoyancy": bvp.Buoyancy(0.004, gradient=0.05, surface=100.0),
    "wind profile": bvp.WindDrag(lambda y: 20 + 0.01 * y, 0.03),
}


class TripledBuoyancy(bvp.Buoyancy):
    """A buoyancy whose tangent is three times its derivative: what `check_tangent` must catch."""

    def forces(self, state):
        out = super().forces(state)
        return bvp.CableForce(out.f, df_dr=3.0 * out.df_dr)


@pytest.mark.parametrize("name", list(TERMS))
def test_check_tangent_passes_each_term_on_the_line(name):
    line = mooring.solve_line_bvp(SPAN, DH, [(LENGTH, W, EA)], seabed=BED, terms=list(TERMS.values()))
    term = TERMS[name]
    # at the closed-form start and at the solution; measured 8e-13 to 2.5e-9
    assert fe.check_tangent(term, line.problem) < 1e-6
    assert fe.check_tangent(term, line.problem, line.dofs) < 1e-6


def test_check_tangent_catches_a_wrong_tangent_on_the_line():
    wrong = TripledBuoyancy(0.004, gradient=50.0, surface=100.0)
    line = mooring.solve_line_bvp(SPAN, DH, [(LENGTH, W, EA)], terms=[wrong])
    assert fe.check_tangent(wrong, line.problem, line.dofs) > 0.5  # (3 − 1)/3


STIFFNESS_SCENES = {
    # suspended: a uniform mesh, the same discrete line in every re-solve (graded meshes follow
    # the solution, and their differences put 3e-6 of noise into the central differences)
    "current, suspended": (
        SPAN,
        DH,
        [(LENGTH, W, EA)],
        {"seabed": BED, "fit_touchdown": 0},
        list(TERMS.values()),
    ),
    "current, grounded": (GSPAN, GDH, [(GLENGTH, GW, GEA)], {"seabed": 0.0}, [TERMS["sheared current"]]),
    "buoyancy, slack stretch": (
        GSPAN,
        GDH,
        [(GLENGTH, GW, GEA)],
        {"seabed": 0.0, "friction": 0.5},
        [BUOYANCY],
    ),
}


@pytest.mark.parametrize("name", list(STIFFNESS_SCENES))
def test_stiffness_with_terms_is_the_derivative_of_resolved_lines(name):
    span, dh, segments, kw, terms = STIFFNESS_SCENES[name]
    line = mooring.solve_line_bvp(span, dh, segments, terms=terms, **kw)
    K = line.stiffness()
    h = 1e-5 * span
    fd = np.empty((2, 2))
    for column, (d_span, d_dh) in enumerate([(h, 0.0), (0.0, h)]):
        plus = mooring.solve_line_bvp(span + d_span, dh + d_dh, segments, terms=terms, **kw)
        minus = mooring.solve_line_bvp(span - d_span, dh - d_dh, segments, terms=terms, **kw)
        fd[:, column] = [(plus.H_B - minus.H_B) / (2 * h), (plus.V_B - minus.V_B) / (2 * h)]
    # measured 5e-9 (suspended) to 4e-8
    np.testing.assert_allclose(K, fd, rtol=0, atol=1e-6 * np.abs(fd).max())


# --- what the terms report -----------------------------------------------------------------------


def test_term_outputs_are_the_force_that_balances_the_end_forces(tmp_path):
    line = mooring.solve_line_bvp(SPAN, DH, [(LENGTH, W, EA)], seabed=BED, terms=[CURRENT])
    n = 2001
    samples = line.samples(n)
    force = samples["outputs"]["CurrentDrag_force_N_per_m"]
    assert force.shape == (n, 2)
    np.testing.assert_allclose(samples["load"], force - [0.0, W], rtol=1e-15, atol=0.0)
    # the drag by hand, from the sampled angle and the stretch 1 + T/EA: measured 4e-5 off, the
    # O(h²) between the stretch of the P2 positions and the P1-DG tension's
    angle, T = samples["angle"], samples["tension"]
    a = (1.0 + T / EA) * np.array([np.cos(angle), np.sin(angle)])
    by_hand = np.array([drag(a[:, k]) for k in range(n)])
    assert np.max(np.abs(force - by_hand)) < 1e-4 * np.max(np.abs(by_hand))
    # the whole line's balance: ∫ f ds = F(0) − F(L), the tension vectors at A and B
    s = np.linspace(0.0, LENGTH, n)
    total = np.trapezoid(force, s, axis=0)
    assert abs(total[0] - (line.H_A - line.H_B)) < 1e-6 * line.T_B
    assert abs(total[1] - W * LENGTH - (-line.V_A - line.V_B)) < 1e-6 * line.T_B
    frame = line.to_frame(n)
    np.testing.assert_array_equal(frame["CurrentDrag_force_N_per_m_x"], force[:, 0])
    np.testing.assert_array_equal(frame["CurrentDrag_force_N_per_m_y"], force[:, 1])
    read = meshio.read(line.to_vtk(tmp_path / "line.vtu", n=n))
    np.testing.assert_array_equal(read.point_data["CurrentDrag_force_N_per_m"][:, :2], force)


def test_line_model_with_terms_is_solve_line_bvp_and_pickles():
    model = mooring.LineBVP([(GLENGTH, GW, GEA)], seabed=0.0, friction=0.2, terms=[BUOYANCY])
    line = model.solve(GSPAN, GDH)
    direct = mooring.solve_line_bvp(
        GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=0.0, friction=0.2, terms=[BUOYANCY]
    )
    assert (line.H_B, line.V_B, line.H_A) == (direct.H_B, direct.V_B, direct.H_A)
    copy = pickle.loads(pickle.dumps(line))
    assert (copy.H_B, copy.V_B) == (line.H_B, line.V_B) and copy.model.terms[0].area == AREA
    np.testing.assert_array_equal(copy.stiffness(), line.stiffness())
    moved = model.solve(GSPAN + 1.0, GDH, start=line)
    assert moved.H_B > line.H_B and "Buoyancy" in repr(model)


# --- refusals ------------------------------------------------------------------------------------


class WrongShape(bvp.CableTerm):
    def forces(self, state):
        return bvp.CableForce(np.zeros(3))


class NotFinite(bvp.CableTerm):
    def forces(self, state):
        f = np.zeros((2, *np.shape(state.x)))
        return bvp.CableForce(f, df_dr=np.full((2, 2, *np.shape(state.x)), np.nan))


@pytest.mark.parametrize(
    ("terms", "match"),
    [
        ([bvp.SelfWeight(10.0)], "CableTerm"),
        (3.0, "CableTerm"),
        ([WrongShape()], "shape"),
        ([NotFinite()], "non-finite"),
        ([CURRENT], "slack stretch"),  # friction holds the whole pull near the anchor: not with drag
    ],
    ids=["a load", "a number", "wrong shape", "NaN tangent", "drag on a slack stretch"],
)
def test_bad_terms_are_refused_naming_terms(terms, match):
    with pytest.raises(InputError, match=match) as info:
        mooring.solve_line_bvp(GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=0.0, friction=0.5, terms=terms)
    assert info.value.argument == "terms"


# --- Newton options ------------------------------------------------------------------------------

SCENE = (GSPAN, GDH, [(GLENGTH, GW, GEA)])


def test_max_iter_one_raises_with_the_history():
    with pytest.raises(ConvergenceError, match="in 1 iterations") as info:
        mooring.solve_line_bvp(*SCENE, seabed=0.0, terms=[BUOYANCY], max_iter=1)
    assert len(info.value.history) == 2 and info.value.history[1] > 1e-10


def test_the_callback_sees_every_iteration():
    calls = []
    line = mooring.solve_line_bvp(*SCENE, seabed=0.0, terms=[BUOYANCY], callback=lambda *a: calls.append(a))
    last = calls[-line.iterations :]  # the final solve's steps: its history after the start
    assert [k for k, _, _ in last] == list(range(1, line.iterations + 1))
    assert [r for _, r, _ in last] == line.history[1:]
    assert all(np.isfinite(step) and step > 0 for _, _, step in calls)
    assert len(calls) > line.iterations  # the continuation's earlier solves are seen too


def test_the_line_bvp_on_a_seabed_hands_its_newton_options_on():
    calls = []
    line = mooring.solve_line_bvp(
        GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=0.0, callback=lambda *a: calls.append(a)
    )
    assert [r for _, r, _ in calls[-line.iterations :]] == line.history[1:]
    with pytest.raises(InputError) as info:
        mooring.solve_line_bvp(GSPAN, GDH, [(GLENGTH, GW, GEA)], seabed=0.0, atol=-1.0)
    assert info.value.argument == "atol"


def test_the_line_in_space_takes_the_plane_lines_newton_options():
    """`solve_line_bvp_3d` and `LineBVP3D` take the plane line's Newton options (one set of
    options for the line BVP): the callback sees every step, the last solve's merits being the
    solution's history; a tighter tolerance is met; a loose ``atol`` (N) stops the solves early."""
    ends = ((0.0, 0.0, 0.0), (GSPAN, 0.0, GDH))
    calls = []
    line = solve_line_bvp_3d(*ends, SCENE[2], seabed=0.0, callback=lambda *a: calls.append(a))
    last = calls[-line.iterations :]
    assert [k for k, _, _ in last] == list(range(1, line.iterations + 1))
    assert [r for _, r, _ in last] == line.history[1:]
    assert len(calls) > line.iterations  # the strategy's earlier solves are seen too
    tight = solve_line_bvp_3d(*ends, SCENE[2], seabed=0.0, options=fe.NewtonOptions(tol=1e-13))
    assert tight.history[-1] < 1e-13
    loose = LineBVP3D(SCENE[2], seabed=0.0, atol=1e6, fit_touchdown=0).solve(*ends)
    assert loose.iterations <= 1 + 2  # the solve, and the polish's full steps
    # the in-plane line in space and the plane line on the seabed agree, with their own options
    plane = mooring.solve_line_bvp(*SCENE, seabed=0.0, options=fe.NewtonOptions(tol=1e-13))
    assert abs(tight.force_on_fairlead[2] + plane.V_B) < 1e-6 * plane.T_B


def test_a_raising_callback_is_reraised_naming_the_iteration():
    def stop(k, r, step):
        if k == 2:
            raise RuntimeError("enough")

    with pytest.raises(InputError, match="RuntimeError at iteration 2: enough") as info:
        mooring.solve_line_bvp(*SCENE, seabed=0.0, callback=stop)
    assert info.value.argument == "callback" and isinstance(info.value.__cause__, RuntimeError)


def test_options_are_honoured():
    tight = mooring.solve_line_bvp(*SCENE, seabed=0.0, terms=[BUOYANCY], options=fe.NewtonOptions(tol=1e-13))
    assert tight.residual() < 1e-13
    plain = mooring.solve_line_bvp(*SCENE, seabed=0.0, terms=[BUOYANCY], line_search="none")
    assert abs(plain.H_B - tight.H_B) < 1e-9 * tight.T_B
    model = mooring.LineBVP(SCENE[2], seabed=0.0, options=fe.NewtonOptions(tol=1e-11, max_iter=7), atol=1.0)
    assert (model.rtol, model.max_iter, model.options.atol, model.options.line_search) == (
        1e-11,
        7,
        1.0,
        "auto",
    )
    # a force residual below atol (N) converges: one step from the closed-form start is enough here
    loose = mooring.solve_line_bvp(*SCENE, seabed=0.0, terms=[BUOYANCY], atol=1e6, fit_touchdown=0)
    assert loose.iterations <= 1 + 2  # the solve, and the polish's full steps


@pytest.mark.parametrize(
    ("given", "argument"),
    [
        ({"tolerance": 1e-9}, "tolerance"),
        ({"line_search": "energy"}, "line_search"),
        ({"line_search": "sometimes"}, "line_search"),
        ({"callback": 3}, "callback"),
        ({"rtol": 1e-9, "tol": 1e-9}, "rtol"),
        ({"rtol": -1.0}, "rtol"),
        ({"tol": np.ones(2)}, "tol"),
        ({"atol": -1.0}, "atol"),
        ({"max_iter": 0}, "max_iter"),
        ({"options": {"tol": 1e-9}}, "options"),
    ],
)
def test_bad_options_are_refused_naming_them(given, argument):
    ends = ((0.0, 0.0, 0.0), (GSPAN, 0.0, GDH))
    for make in (
        lambda: mooring.solve_line_bvp(*SCENE, seabed=0.0, **given),
        lambda: mooring.LineBVP(SCENE[2], **given),
        lambda: solve_line_bvp_3d(*ends, SCENE[2], seabed=0.0, **given),
        lambda: LineBVP3D(SCENE[2], **given),
    ):
        with pytest.raises(InputError) as info:
            make()
        assert info.value.argument == argument
