"""Cable terms (buoyancy varying with depth, current and wind drag) in the cable BVPs, against an
independent shooting solution of the same equations written here with scipy's solve_ivp."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from skcable import bvp
from skcable.errors import InputError

RHO, G = 1025.0, 9.81


def shoot(span, dh, length, EA, force, start):
    """The cable's end forces by shooting: ``d(T t)/ds = −f(r, a)``, ``dr/ds = (1 + T/EA) t`` from
    A = (0, 0) with the tension vector ``F(0)`` found (fsolve) so that ``r(L) = (span, dh)``.
    ``force(x, y, a) -> (fx, fy)`` per unstretched length. Returns ``F(0)``, ``F(L)``."""

    def rhs(s, z):
        x, y, Fx, Fy = z
        T = np.hypot(Fx, Fy)
        a = (1.0 + T / EA) * np.array([Fx, Fy]) / T
        fx, fy = force(x, y, a)
        return [a[0], a[1], -fx, -fy]

    def end(F0):
        sol = solve_ivp(rhs, (0.0, length), [0.0, 0.0, *F0], rtol=1e-12, atol=1e-12 * length, method="DOP853")
        return sol.y[:, -1]

    F0 = fsolve(lambda F: end(F)[:2] - [span, dh], start, xtol=1e-12)
    z = end(F0)
    assert np.hypot(z[0] - span, z[1] - dh) < 1e-9 * length
    return F0, z[2:]


def end_forces(sol):
    """``F(0)`` and ``F(L)`` of a BVP solution: the tension vectors at A and B, towards B."""
    return np.array([sol.H_A, -sol.V_A]), np.array([sol.H_B, sol.V_B])


SPAN, DH, LENGTH, W, EA = 300.0, 40.0, 340.0, 400.0, 5e7
AREA = 0.01  # m², displaced section per unstretched length


def test_buoyancy_varying_with_depth_matches_shooting():
    """A chain hanging under water in a sea whose density grows with depth (0.05 kg/m⁴): its
    weight less the upthrust ρ(d) g A, in the graph and the arc form."""
    gradient, surface = 0.05, 60.0
    buoyancy = bvp.Buoyancy(AREA, rho=RHO, gradient=gradient, surface=surface)

    def force(x, y, a):
        d = surface - y
        return 0.0, -W + (RHO + gradient * d) * G * AREA

    loads = [bvp.SelfWeight(W), buoyancy]
    for formulation in ("graph", "arc"):
        sol = bvp.solve_bvp(
            SPAN, DH, loads, length=LENGTH, EA=EA, n_elements=256, formulation=formulation, rtol=1e-12
        )
        F0, FL = shoot(SPAN, DH, LENGTH, EA, force, [sol.H_A, -sol.V_A])
        A, B = end_forces(sol)
        scale = np.hypot(*F0)
        assert np.max(np.abs(A - F0)) < 1e-6 * scale and np.max(np.abs(B - FL)) < 1e-6 * scale, formulation
    # the stratification matters: with a uniform sea the end forces differ by far more than 1e-6
    plain = bvp.solve_bvp(
        SPAN, DH, [bvp.SelfWeight(W), bvp.Buoyancy(AREA, surface=surface)], length=LENGTH, EA=EA
    )
    assert abs(plain.H / sol.H - 1) > 1e-4


@pytest.mark.parametrize("profile", ["uniform", "sheared"])
def test_current_drag_matches_shooting(profile):
    """A submerged cable in a current along x, uniform or sheared (U falling linearly with depth),
    with normal and tangential drag: the arc form against shooting."""
    d_cable, cn, ct, surface = 0.1, 1.2, 0.008, 50.0
    U0 = 1.5
    speed = U0 if profile == "uniform" else (lambda d: U0 * (1.0 - d / 200.0))
    drag = bvp.CurrentDrag(speed, d_cable, cd_normal=cn, cd_tangential=ct, surface=surface)

    def force(x, y, a):
        d = surface - y
        U = U0 if profile == "uniform" else U0 * (1.0 - d / 200.0)
        v = np.array([U, 0.0])
        n = np.hypot(*a)
        t = a / n
        vt = (v @ t) * t
        vn = v - vt
        f = 0.5 * RHO * d_cable * n * (cn * np.hypot(*vn) * vn + ct * np.hypot(*vt) * vt)
        return f[0], f[1] - W

    sol = bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(W), drag], length=LENGTH, EA=EA, n_elements=256, rtol=1e-12)
    assert sol.formulation == "arc"  # a horizontal force: the arc form, chosen for the user
    F0, FL = shoot(SPAN, DH, LENGTH, EA, force, [sol.H_A, -sol.V_A])
    A, B = end_forces(sol)
    scale = np.hypot(*F0)
    assert np.max(np.abs(A - F0)) < 1e-6 * scale and np.max(np.abs(B - FL)) < 1e-6 * scale
    assert abs(sol.H_B - sol.H_A) > 1e-3 * sol.H_A  # the drag changed the horizontal tension along the cable


def test_wind_drag_on_the_projected_length_matches_shooting():
    """Wind along x on a steep cable (no part of it along the wind): ½ ρ C_d d U² |a × e| e."""
    k = 0.5 * 1.225 * 1.0 * 0.03 * 25.0**2
    wind = bvp.WindDrag(25.0, 0.03, cd=1.0)

    def force(x, y, a):
        return k * abs(a[1]), -20.0

    span, dh, length = 100.0, 300.0, 330.0
    sol = bvp.solve_bvp(
        span, dh, [bvp.SelfWeight(20.0), wind], length=length, EA=1e7, n_elements=256, rtol=1e-12
    )
    F0, FL = shoot(span, dh, length, 1e7, force, [sol.H_A, -sol.V_A])
    A, B = end_forces(sol)
    scale = np.hypot(*F0)
    assert np.max(np.abs(A - F0)) < 1e-6 * scale and np.max(np.abs(B - FL)) < 1e-6 * scale


@pytest.mark.parametrize(
    "term",
    [
        bvp.Buoyancy(AREA, gradient=0.05, surface=60.0),
        bvp.CurrentDrag(lambda d: 1.5 * (1 - d / 200), 0.1, cd_tangential=0.01, surface=50.0),
        bvp.WindDrag(lambda y: 20 + 0.01 * y, 0.03),
    ],
    ids=["buoyancy", "current", "wind"],
)
def test_cable_term_derivatives_match_central_differences(term):
    rng = np.random.default_rng(2)
    x, y = rng.uniform(0, 300, 7), rng.uniform(-40, 40, 7)
    a = np.array([rng.uniform(0.3, 1.0, 7), rng.uniform(-1.0, 1.0, 7)]) * 1.001
    T = rng.uniform(1e3, 1e4, 7)
    out = term.forces(bvp.CableState(x, y, None, a, T))
    h = 1e-6
    for j, (dx, dy) in enumerate(((h, 0), (0, h))):
        fd = (
            term.forces(bvp.CableState(x + dx, y + dy, None, a, T)).f
            - term.forces(bvp.CableState(x - dx, y - dy, None, a, T)).f
        ) / (2 * h)
        assert np.allclose(out.df_dr[:, j], fd, rtol=1e-6, atol=1e-9 * np.abs(out.f).max())
    if out.df_da is not None:
        for j in range(2):
            e = np.zeros((2, 1))
            e[j] = h
            fd = (
                term.forces(bvp.CableState(x, y, None, a + e, T)).f
                - term.forces(bvp.CableState(x, y, None, a - e, T)).f
            ) / (2 * h)
            assert np.allclose(out.df_da[:, j], fd, rtol=1e-6, atol=1e-9 * np.abs(out.f).max())


def test_terms_the_graph_form_cannot_take_are_refused():
    drag = bvp.CurrentDrag(1.0, 0.1)
    with pytest.raises(InputError, match="horizontal component"):
        bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(W), drag], length=LENGTH, formulation="graph")

    class Along(bvp.CableTerm):
        uses_s = True
        vertical = True

        def forces(self, state):
            return bvp.CableForce(np.array([0 * state.s, -1.0 - 0 * state.s]))

    with pytest.raises(InputError, match="arc length"):
        bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(W), Along()], length=LENGTH, formulation="graph")
    sol = bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(W), Along()], length=LENGTH)
    assert sol.formulation == "arc"
    with pytest.raises(InputError, match="area"):
        bvp.Buoyancy(-1.0)
    with pytest.raises(InputError, match="cd_normal"):
        bvp.CurrentDrag(1.0, 0.1, cd_normal=-1.0)
    with pytest.raises(InputError, match="direction"):
        bvp.WindDrag(10.0, 0.03, direction=(0.0, 0.0))


class Scaled(bvp.CableTerm):
    """A cable term whose tangent is another's times a factor (1: right)."""

    def __init__(self, inner, factor):
        self.inner, self.factor, self.vertical = inner, factor, inner.vertical

    def forces(self, state):
        out = self.inner.forces(state)
        scale = lambda d: None if d is None else self.factor * d  # noqa: E731
        return bvp.CableForce(out.f, scale(out.df_dr), scale(out.df_da), scale(out.df_ds), scale(out.df_dT))


@pytest.mark.parametrize("formulation", ["graph", "arc"])
def test_check_tangent_checks_cable_terms_too(formulation):
    from skcable.fe import check_tangent

    buoyancy = bvp.Buoyancy(AREA, gradient=5.0, surface=60.0)
    drag = bvp.CurrentDrag(lambda d: 1.5 * (1 - d / 200), 0.1, cd_tangential=0.01, surface=50.0)
    terms = [buoyancy] if formulation == "graph" else [buoyancy, drag]
    for term in terms:
        sol = bvp.solve_bvp(
            SPAN, DH, [bvp.SelfWeight(W), term], length=LENGTH, EA=EA, formulation=formulation
        )
        U = sol.problem.tangent_check_state()
        assert check_tangent(term, sol.problem, U) < 1e-6
        wrong = check_tangent(Scaled(term, 3.0), sol.problem, U)
        if formulation == "arc":  # the term's whole tangent is its force's derivatives: off by 2/3
            assert wrong == pytest.approx(2.0 / 3.0, rel=1e-3)
        else:  # the graph form adds the measure's own derivative, right as it is: off by less
            assert wrong > 1e-2


# --- Newton options and a free end loaded by a force in solve_bvp -----------------------------------
def test_solve_bvp_takes_newton_options_and_names_bad_ones():
    seen = []
    sol = bvp.solve_bvp(
        SPAN, DH, bvp.SelfWeight(W), length=LENGTH, callback=lambda k, r, dx: seen.append((k, r))
    )
    assert [k for k, _ in seen] == list(range(1, sol.iterations + 1))
    assert [r for _, r in seen] == sol.history[1:]
    full = bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), length=LENGTH, line_search=False, formulation="arc")
    assert full.H == pytest.approx(sol.H, rel=1e-6)
    loose = bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), length=LENGTH, rtol=1e-14, atol=1e-3, max_iter=60)
    assert np.max(np.abs(loose.problem.assemble(loose.dofs, loose.H).R[loose.problem.interior])) < 1e-3
    for bad in (
        dict(line_search="energy"),
        dict(callback=3),
        dict(atol=-1.0),
        dict(n_elements=16.0),
        dict(max_iter=2.5),
    ):
        with pytest.raises(InputError, match=next(iter(bad))):
            bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), length=LENGTH, **bad)

    def boom(k, r, dx):
        raise ValueError("enough")

    with pytest.raises(InputError, match="callback.*iteration 1.*enough"):
        bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), length=LENGTH, callback=boom)


def test_a_free_end_loaded_by_a_force_lands_where_the_elastic_catenary_says():
    """A line of length L hanging from A, its free end B pulled by (Fx, Fy): H = Fx throughout,
    the vertical tension at B is Fy, and B lies at Irvine's closed-form position."""
    L, w, EA, Fx, Fy = 400.0, 50.0, 2e7, 6e3, 1.2e4
    sol = bvp.solve_bvp(300.0, 100.0, bvp.SelfWeight(w), length=L, EA=EA, end_force=(Fx, Fy), n_elements=128)
    assert sol.formulation == "arc"
    Va = Fy - w * L  # the vertical tension at A (negative: the line leaves A downwards)
    x = Fx / w * (np.arcsinh(Fy / Fx) - np.arcsinh(Va / Fx)) + Fx * L / EA
    y = (np.hypot(Fx, Fy) - np.hypot(Fx, Va)) / w + (Fy * L - 0.5 * w * L * L) / EA
    assert sol.span == pytest.approx(x, rel=1e-9) and sol.dh == pytest.approx(y, rel=1e-9)
    assert sol.H == pytest.approx(Fx, rel=1e-9) and sol.V_A == pytest.approx(-Va, rel=1e-9)
    assert (sol.H_B, sol.V_B) == (Fx, Fy)
    with pytest.raises(InputError, match="end_force"):
        bvp.solve_bvp(300.0, 100.0, bvp.SelfWeight(w), sag=20.0, end_force=(Fx, Fy))
    with pytest.raises(InputError, match="end_force"):
        bvp.solve_bvp(300.0, 100.0, bvp.SelfWeight(w), length=L, end_force=(Fx,))


def test_cable_term_outputs_and_user_fields_reach_the_vtk_file(tmp_path):
    import meshio

    drag = bvp.CurrentDrag(1.5, 0.1, cd_tangential=0.01, surface=50.0)
    sol = bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(W), drag], length=LENGTH, EA=EA, n_elements=64)
    path = sol.to_vtk(
        tmp_path / "line.vtu", n=41, point_data={"depth_m": lambda samples: 50.0 - samples["xy"][:, 1]}
    )
    mesh = meshio.read(path)
    force = mesh.point_data["CurrentDrag_force_N_per_m"]
    assert force.shape == (41, 3) and np.all(force[:, 2] == 0)
    # the drag written is the term's own force at the written points
    samples = sol.samples(41)
    np.testing.assert_allclose(
        force[:, :2],
        samples["outputs"]["CurrentDrag_force_N_per_m"],
        rtol=0,
        atol=1e-12 * np.abs(force).max(),
    )
    np.testing.assert_allclose(mesh.point_data["depth_m"], 50.0 - mesh.points[:, 1], rtol=1e-12)
    graph = bvp.solve_bvp(SPAN, DH, [bvp.SelfWeight(W), bvp.Buoyancy(AREA, surface=60.0)], length=LENGTH)
    up = meshio.read(graph.to_vtk(tmp_path / "graph.vtu", n=11)).point_data["Buoyancy_force_N_per_m"]
    np.testing.assert_allclose(up[:, 1], RHO * G * AREA, rtol=1e-12)
    with pytest.raises(InputError, match="short"):
        sol.to_vtk(tmp_path / "bad.vtu", n=41, point_data={"short": np.zeros(3)})


def test_the_arc_forms_frame_carries_the_term_outputs_at_its_points():
    """`ArcSolution.to_frame`: the buoyancy column is ρ g A where the frame's own y lies below the
    surface and 0 above it (the surface cuts the cable), the drag column as the samples give it."""
    surface = 0.5 * DH
    terms = [
        bvp.SelfWeight(W),
        bvp.Buoyancy(AREA, surface=surface),
        bvp.CurrentDrag(1.0, 0.1, surface=surface),
    ]
    sol = bvp.solve_bvp(SPAN, DH, terms, length=LENGTH, EA=EA, n_elements=64)
    assert sol.formulation == "arc"
    frame = sol.to_frame(41)
    wet = frame["y"].to_numpy() < surface
    assert 0 < wet.sum() < 41
    np.testing.assert_allclose(
        frame["Buoyancy_force_N_per_m_y"], np.where(wet, RHO * G * AREA, 0.0), rtol=1e-12
    )
    np.testing.assert_array_equal(frame["Buoyancy_force_N_per_m_x"], 0.0)
    drag = sol.samples(41)["outputs"]["CurrentDrag_force_N_per_m"]
    np.testing.assert_array_equal(frame[["CurrentDrag_force_N_per_m_x", "CurrentDrag_force_N_per_m_y"]], drag)
    np.testing.assert_allclose(frame["s"], np.linspace(0.0, LENGTH, 41), rtol=1e-15)
