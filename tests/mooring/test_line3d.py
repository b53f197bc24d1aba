"""The 3-D line BVP (`skcable.mooring.line_bvp.space`) against independent references written here:
scipy ``solve_ivp`` shooting of the same ODEs (in and across the line's plane, multi-segment
with a clump and a nonlinear axial law, a tabulated current), the sloped closed form
(`sloped_seabed_catenary`) on a plane bathymetry, central differences of its own solutions for
the stiffness, a vertical tether's series compliance for the dynamic stiffness, and statics."""

import pickle
import re

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

from skcable.bvp.current import TabulatedCurrent
from skcable.cable.seabed import sloped_seabed_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.axial import StaticDynamicRope, StrainFunction, StrainTable
from skcable.mooring.bathymetry import DepthFunction, Grid, Plane
from skcable.mooring.line_bvp.space import LineBVP3D, LineSegment, solve_line_bvp_3d

RHO = 1025.0
A = np.array([20.0, -10.0, -200.0])
AZIMUTH = np.radians(30.0)
E = np.array([np.cos(AZIMUTH), np.sin(AZIMUTH)])
B = A + np.array([400.0 * E[0], 400.0 * E[1], 180.0])
CHAIN = dict(length=500.0, w=600.0, EA=4e8, diameter=0.1, cd_normal=1.2, cd_tangential=0.008)


def drag(v, a, d, cn, ct):
    """Morison's drag per unstretched length, written here."""
    n = np.linalg.norm(a)
    t = a / n
    vt = (v @ t) * t
    vn = v - vt
    return 0.5 * RHO * d * n * (cn * np.linalg.norm(vn) * vn + ct * np.linalg.norm(vt) * vt)


def shoot(anchor, fairlead, pieces, velocity, start):
    """``(F(0), F(L))``: the tension vectors at the ends by shooting ``dr/ds = (1 + ε(T)) F/T``,
    ``dF/ds = −f`` segment by segment (``pieces``: (length, w, strain(T), d, cn, ct, P at its
    upper joint)), ``F`` jumping by ``P e_z`` at a joint, from ``F(0)`` found by MINPACK's hybrd so that
    ``r(L)`` is the fairlead. ``velocity(z)`` is the current (3,)."""

    def rhs(s, y, w, strain, d, cn, ct):
        r, F = y[:3], y[3:]
        T = np.linalg.norm(F)
        a = (1.0 + strain(T)) * F / T
        f = drag(velocity(r[2]), a, d, cn, ct) if d else np.zeros(3)
        f[2] -= w
        return np.concatenate([a, -f])

    def end(F0):
        y = np.concatenate([anchor, F0])
        for length, w, strain, d, cn, ct, P in pieces:
            sol = solve_ivp(
                rhs, (0.0, length), y, args=(w, strain, d, cn, ct), rtol=1e-12, atol=1e-9, method="DOP853"
            )
            y = sol.y[:, -1].copy()
            y[5] += P
        return y

    F0 = root(lambda F: end(F)[:3] - fairlead, start, method="hybr", options={"xtol": 1e-12}).x
    y = end(F0)
    assert np.max(np.abs(y[:3] - fairlead)) < 1e-9 * np.linalg.norm(fairlead - anchor)
    return F0, y[3:]


def assert_end_forces(line, F0, FL, rtol):
    """The line's end forces against shooting's: ``force_on_anchor = F(0)``, ``force_on_fairlead
    = −F(L)``."""
    scale = np.linalg.norm(FL)
    assert np.max(np.abs(line.force_on_anchor - F0)) < rtol * scale
    assert np.max(np.abs(line.force_on_fairlead + FL)) < rtol * scale


@pytest.mark.parametrize("across", [False, True], ids=["current in the line's plane", "current across it"])
def test_a_line_in_a_uniform_current_matches_shooting(across):
    U = np.array([-0.9 * E[1], 0.9 * E[0]]) if across else 0.9 * E
    line = solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], current=tuple(U), n_elements=128)
    c = CHAIN
    F0, FL = shoot(
        A, B, [(c["length"], c["w"], lambda T: T / c["EA"], c["diameter"], 1.2, 0.008, 0.0)],
        lambda z: np.array([U[0], U[1], 0.0]), line.force_on_anchor,
    )  # fmt: skip
    assert_end_forces(line, F0, FL, 1e-7)
    middle = line.xyz(np.array(250.0)) - A
    off_plane = middle[0] * -E[1] + middle[1] * E[0]
    if across:  # the line leaves its vertical plane, downstream
        assert off_plane > 5.0
    else:
        assert abs(off_plane) < 1e-9 * 400.0
    assert line.equilibrium_residual <= line.residual_bound


def test_the_end_forces_converge_at_h_to_the_p_plus_1():
    """P2 positions (p = 2): the error ratio on mesh doubling is at most 2^-(p+1) = 1/8 (the end
    forces superconverge: measured 1/16)."""
    U = (-0.5, 0.8)
    F0, FL = shoot(
        A, B, [(500.0, 600.0, lambda T: T / 4e8, 0.1, 1.2, 0.008, 0.0)], lambda z: np.array([*U, 0.0]),
        solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], current=U).force_on_anchor,
    )  # fmt: skip
    errors = []
    for n in (16, 32, 64):
        line = solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], current=U, n_elements=n)
        errors.append(np.max(np.abs(line.force_on_fairlead + FL)) / np.linalg.norm(FL))
    ratios = np.array(errors[1:]) / np.array(errors[:-1])
    assert np.all(ratios < 1 / 8), ratios
    assert np.all(ratios > 1 / 40), ratios  # and it is the discretisation, not round-off, here


def polyester_law():
    """A polyester-like rope: ε = (T*/EA) ln(1 + T/T*), stiffening with the load."""
    EA, Tr = 1.2e8, 3e5

    def strain(T):
        return Tr / EA * np.log1p(T / Tr)

    def slope(T):
        return 1.0 / (EA * (1.0 + T / Tr))

    return StrainFunction(strain, slope), strain


def test_chain_polyester_chain_with_a_clump_in_a_sheared_current_matches_shooting():
    law, strain = polyester_law()
    table = TabulatedCurrent([0.0, 50.0, 150.0, 400.0], [[0.9, 0.3], [0.7, 0.35], [0.35, 0.2], [0.1, 0.05]])
    segments = [
        LineSegment(150.0, 1400.0, 7e8, 0.15, 2.4, 0.4),
        LineSegment(450.0, 30.0, law, 0.16, 1.2, 0.008),
        LineSegment(60.0, 1400.0, 7e8, 0.15, 2.4, 0.4),
    ]
    anchor, fairlead = np.array([0.0, 0.0, -300.0]), np.array([560.0, 60.0, -15.0])
    line = solve_line_bvp_3d(
        anchor, fairlead, segments, attachments=[(1, 2e4)], current=table, n_elements=200
    )

    def velocity(z):
        U = table.velocity(np.array(z))
        return np.array([float(U[0]), float(U[1]), 0.0])

    pieces = [
        (150.0, 1400.0, lambda T: T / 7e8, 0.15, 2.4, 0.4, 2e4),
        (450.0, 30.0, strain, 0.16, 1.2, 0.008, 0.0),
        (60.0, 1400.0, lambda T: T / 7e8, 0.15, 2.4, 0.4, 0.0),
    ]
    F0, FL = shoot(anchor, fairlead, pieces, velocity, line.force_on_anchor)
    assert_end_forces(line, F0, FL, 1e-7)


def slope_scene(slope, friction):
    span, dh, w, EA, L = 400.0, 100.0, 1000.0, 5e8, 440.0
    a = np.array([10.0, -20.0, -150.0])
    b = a + np.array([span * E[0], span * E[1], dh])
    bed = Plane(a[2], slope=(slope * E[0], slope * E[1]), origin=a[:2])
    ref = sloped_seabed_catenary(span, dh, w, EA, length=L, seabed_slope=slope, friction=friction)
    return a, b, bed, [LineSegment(L, w, EA)], ref


@pytest.mark.parametrize(("slope", "friction"), [(0.05, 0.0), (-0.05, 0.1)])
def test_a_line_on_a_plane_bathymetry_matches_the_sloped_closed_form(slope, friction):
    """The plane rises along the line's azimuth (30°): in the line's vertical plane it is the
    closed form's slope. The touchdown is fitted; the end forces converge at h⁴, and their
    Richardson extrapolation from 128 and 256 elements meets the closed form to 1e-9."""
    a, b, bed, segments, ref = slope_scene(slope, friction)

    def forces(n):
        line = solve_line_bvp_3d(a, b, segments, seabed=bed, friction=friction, n_elements=n)
        Fb, Fa = -line.force_on_fairlead, line.force_on_anchor
        return line, np.array([Fb[:2] @ E, Fb[2], Fa[:2] @ E, -Fa[2]])

    coarse, fine = forces(128)[1], forces(256)
    line, fine = fine
    exact = np.array([ref.H, ref.V_B, ref.H_A, ref.V_A])
    scale = np.array([ref.H, ref.V_B, ref.H_A, ref.T_A])
    assert np.all(np.abs(fine - exact) / scale < 1e-8)
    ratio = np.abs(fine - exact) / np.abs(coarse - exact)
    assert np.all(ratio < 1 / 8), ratio
    richardson = (16.0 * fine - coarse) / 15.0
    assert np.all(np.abs(richardson - exact) / scale < 1e-9), np.abs(richardson - exact) / scale
    assert line.s_touchdown == pytest.approx(ref.length_on_seabed, rel=1e-6)
    assert np.all(line.gap >= -1e-12 * line.length) and np.all(np.abs(line.gap[line.in_contact]) < 1e-9)
    assert line.normal_force.min() > -1e-6 * line.weight


def statics(line):
    """The forces on the line, summed, over its weight: anchor, fairlead, seabed and distributed."""
    p = line.problem
    f = -p.distributed_load(p.assembly.interpolate(line.dofs))[0]
    total = -line.force_on_anchor - line.force_on_fairlead + line.contact_force.sum(axis=0)
    total = total + line.anchor_seabed_force + np.sum(f * p.assembly.dx, axis=(1, 2))
    total[2] -= np.sum(p.point_values)
    return total / line.weight


def wavy_grid():
    xs, ys = np.linspace(-100, 900, 21), np.linspace(-300, 300, 13)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    return Grid(xs, ys, -200 + 0.03 * X + 10 * np.sin(X / 150) * np.cos(Y / 120))


def test_a_line_on_a_grid_seabed_in_a_current_balances_and_touches_exactly():
    grid = wavy_grid()
    a = np.array([0.0, 0.0, float(grid.height(0.0, 0.0))])
    line = solve_line_bvp_3d(
        a, (600.0, 50.0, -20.0), [LineSegment(660.0, 1000.0, 5e8, 0.09, 2.4, 0.4)], seabed=grid,
        friction=0.15, current=(0.2, 0.6), n_elements=96,
    )  # fmt: skip
    assert np.max(np.abs(statics(line))) < 1e-12
    assert line.in_contact.sum() > 20 and np.all(line.gap >= -1e-12 * line.length)
    # on the seabed the friction is μ N along it, and the seabed pushes along its normal
    on = line.in_contact
    normal = grid.normal(line.contact_xyz[on, 0], line.contact_xyz[on, 1]).T
    along = line.contact_force[on] - np.sum(line.contact_force[on] * normal, axis=1)[:, None] * normal
    np.testing.assert_allclose(
        np.linalg.norm(along, axis=1), 0.15 * line.normal_force[on], rtol=1e-9, atol=1e-9
    )


def test_the_stiffness_matches_central_differences():
    cases = [
        (A, B, dict(current=(0.3, 0.9)), [LineSegment(**CHAIN)]),
        (
            *slope_scene(0.05, 0.1)[:2],
            dict(seabed=slope_scene(0.05, 0.1)[2], friction=0.1),
            slope_scene(0.05, 0.1)[3],
        ),
    ]
    for anchor, fairlead, options, segments in cases:
        model = LineBVP3D(segments, n_elements=64, fit_touchdown=0, **options)
        line = model.solve(anchor, fairlead)
        K = np.asarray(line.stiffness())
        h = 1e-3
        fd = np.zeros((3, 3))
        for j in range(3):
            step = np.zeros(3)
            step[j] = h
            plus = model.solve(anchor, fairlead + step, start=line).force_on_fairlead
            minus = model.solve(anchor, fairlead - step, start=line).force_on_fairlead
            fd[:, j] = -(plus - minus) / (2 * h)  # K = ∂S_B/∂r_B, S_B = −force_on_fairlead
        assert np.max(np.abs(K - fd)) < 1e-6 * np.max(np.abs(K)), (K, fd)


def test_the_dynamic_stiffness_of_a_vertical_tether_is_its_series_compliance():
    """A vertical rope: its axial stiffness is ``1/∫ ds/EA(T(s))``, statically ``EA_s/L`` and
    dynamically ``β w / ln((α + β T_B)/(α + β T_A))`` with ``T(s) = T_A + w s``."""
    rope = StaticDynamicRope(1e8, alpha=2e8, beta=30.0)
    L, w = 200.0, 50.0
    line = solve_line_bvp_3d((0.0, 0.0, -250.0), (0.0, 0.0, -48.0), [LineSegment(L, w, rope)], n_elements=32)
    T_A, T_B = line.T_A, line.T_B
    assert T_B - T_A == pytest.approx(w * L, rel=1e-12)
    static, dynamic = line.stiffness("static"), line.stiffness("dynamic")
    assert static.kind == "static" and dynamic.kind == "dynamic"
    assert static.matrix[2, 2] == pytest.approx(1e8 / L, rel=1e-10)
    expected = 30.0 * w / np.log((2e8 + 30.0 * T_B) / (2e8 + 30.0 * T_A))
    assert dynamic.matrix[2, 2] == pytest.approx(expected, rel=1e-9)


def test_a_tabulated_law_line_matches_shooting():
    eps = np.array([0.0, 0.002, 0.005, 0.009, 0.014, 0.02])
    tension = np.array([0.0, 0.8e5, 2.2e5, 4.4e5, 7.5e5, 1.2e6])
    law = StrainTable(eps, tension)
    line = solve_line_bvp_3d(
        A, B, [LineSegment(500.0, 600.0, law, 0.1, 1.2, 0.0)], current=(0.4, -0.3), n_elements=256
    )
    F0, FL = shoot(
        A, B, [(500.0, 600.0, lambda T: float(law.strain(np.array(T))), 0.1, 1.2, 0.0, 0.0)],
        lambda z: np.array([0.4, -0.3, 0.0]), line.force_on_anchor,
    )  # fmt: skip
    assert_end_forces(line, F0, FL, 1e-7)


def test_the_drag_term_tangent_is_exact():
    from skcable.fe import check_tangent

    line = solve_line_bvp_3d(
        A, B, [LineSegment(**CHAIN)], current=TabulatedCurrent([0, 400.0], [[1, 0.5], [0.2, 0.1]])
    )
    for term in line.problem.terms:
        assert check_tangent(term, line.problem, line.dofs) < 1e-6


def test_a_line_that_cannot_lie_on_its_seabed_fails_with_its_history():
    """A ridge higher than the line can pass over: no equilibrium."""

    def height(x, y):
        return -200 + 190 * np.exp(-(((x - 300) / 40) ** 2))

    def gradient(x, y):
        return -2 * (x - 300) / 40**2 * 190 * np.exp(-(((x - 300) / 40) ** 2)), 0 * y

    with pytest.raises(ConvergenceError) as info:
        solve_line_bvp_3d(
            (0.0, 0.0, -200.0), (600.0, 0.0, -20.0), [LineSegment(640.0, 1000.0, 5e8)],
            seabed=DepthFunction(height, gradient), n_elements=64,
        )  # fmt: skip
    assert len(info.value.history) > 2


def test_bad_inputs_are_refused_by_name():
    with pytest.raises(InputError, match="cd_normal"):
        LineSegment(100.0, 10.0, 1e8, 0.1, -1.0)
    with pytest.raises(InputError, match="cd_tangential"):
        LineSegment(100.0, 10.0, 1e8, 0.1, 1.0, -0.1)
    with pytest.raises(InputError, match="diameter"):
        LineSegment(100.0, 10.0, 1e8, None, 1.0)
    with pytest.raises(InputError, match="strain"):
        LineSegment(100.0, 10.0, StrainTable([0.0, 0.01, 0.005], [0.0, 1e5, 2e5]))
    with pytest.raises(InputError, match="depths"):
        solve_line_bvp_3d(
            A, B, [LineSegment(**CHAIN)], current=TabulatedCurrent([0.0, 50.0, 20.0], np.ones((3, 2)))
        )
    xs, ys = np.linspace(0, 500, 6), np.linspace(-50, 50, 3)
    z = -200.0 + 0 * xs[:, None] + 0 * ys
    z[3, 1] = np.nan
    with pytest.raises(InputError, match="z"):
        solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], seabed=Grid(xs, ys, z))
    with pytest.raises(InputError, match="friction"):
        solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], friction=0.3)
    with pytest.raises(InputError, match="current"):
        solve_line_bvp_3d(A, B, [LineSegment(500.0, 600.0, 4e8)], current=(1.0, 0.0))
    with pytest.raises(InputError, match="seabed"):
        solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], seabed=-150.0)  # above the anchor
    with pytest.raises(InputError, match="fairlead"):  # a seabed through the anchor, above the fairlead
        solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], seabed=Plane(A[2], slope=(1.0, 0.0), origin=A[:2]))
    with pytest.raises(InputError, match="attachments"):
        solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], attachments=[(1, 1e4)])
    with pytest.raises(InputError, match="anchor"):
        solve_line_bvp_3d((0.0, 0.0), B, [LineSegment(**CHAIN)])
    with pytest.raises(InputError, match="spam"):
        LineBVP3D([LineSegment(**CHAIN)], spam=1)
    for bad in ("Graded", None, True):
        with pytest.raises(InputError, match="mesh") as refused:
            LineBVP3D([LineSegment(**CHAIN)], mesh=bad)
        assert refused.value.argument == "mesh"
    for bad, why in [
        ([(500.0, 1e4)], "inside the line"),  # at the fairlead: a support, not a point load
        ([(0.0, 1e4)], "inside the line"),
        ([(100.0, float("nan"))], "point_loads"),
        ([(100.0,)], r"\(s, P\)"),
        (3.0, "sequence"),
        ([(100.0, [1e4, 2e4])], "two numbers"),
    ]:
        with pytest.raises(InputError, match=why) as refused:
            solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], point_loads=bad)
        assert refused.value.argument == "point_loads"


def test_vtk_repr_and_pickle(tmp_path):
    import meshio

    line = solve_line_bvp_3d(A, B, [LineSegment(**CHAIN)], current=(0.3, 0.9), n_elements=32)
    mesh = meshio.read(line.to_vtk(tmp_path / "line.vtu", n=41))
    np.testing.assert_allclose(mesh.points, line.profile(41), rtol=1e-12)
    np.testing.assert_allclose(
        mesh.point_data["tension_N"], line.T_of_s(np.linspace(0, 500.0, 41)), rtol=1e-12
    )
    drag_written = mesh.point_data["CurrentDrag_force_N_per_m"]
    assert drag_written.shape == (41, 3)
    s = 250.0
    k = 20
    a = line.state_at(np.array([s])).a[:, 0]
    np.testing.assert_allclose(
        drag_written[k], drag(np.array([0.3, 0.9, 0.0]), a, 0.1, 1.2, 0.008), rtol=1e-10
    )
    assert "force_on_fairlead=[" in repr(line) and "32 elements" in repr(line)
    from skcable.io import lines_mesh

    polyline = lines_mesh([line], n=21)  # the 3-D writer of the mooring lines reads it too
    np.testing.assert_allclose(polyline.points, line.profile(21), rtol=1e-12)
    table = line.tensions()
    assert table["T_lower"].iloc[0] == line.T_A and table["T_upper"].iloc[-1] == line.T_B
    copy = pickle.loads(pickle.dumps(line))
    np.testing.assert_array_equal(copy.force_on_fairlead, line.force_on_fairlead)
    np.testing.assert_array_equal(copy.profile(11), line.profile(11))
    assert repr(copy) == repr(line)


@pytest.mark.parametrize("kind", ["grid", "depth function"])
def test_the_contact_rows_generalized_jacobian_is_exact(kind):
    """On a curved seabed with friction and a current, the contact rows' Jacobian (row mixing,
    ∇∇b, the sliding direction through the neighbours) against central differences of the
    residual, the active set held."""

    def height(x, y):
        return -200 + 0.03 * x + 10 * np.sin(x / 150) * np.cos(y / 120)

    def gradient(x, y):
        return 0.03 + 10 / 150 * np.cos(x / 150) * np.cos(y / 120), -10 / 120 * np.sin(x / 150) * np.sin(
            y / 120
        )

    bed = wavy_grid() if kind == "grid" else DepthFunction(height, gradient)
    a = np.array([0.0, 0.0, float(bed.height(0.0, 0.0))])
    segment = LineSegment(660.0, 1000.0, 5e8, 0.09, 2.4, 0.4)
    line = solve_line_bvp_3d(
        a, (600.0, 50.0, -20.0), [segment], seabed=bed, friction=0.15, current=(0.2, 0.6), n_elements=48
    )
    p, z = line.problem, line.dofs
    state = p.assemble(z)
    J = p.jacobian(state)
    rng = np.random.default_rng(0)
    for _ in range(4):
        d = np.zeros(z.size)
        d[p.free] = rng.standard_normal(p.free.size)
        d /= np.abs(d).max()
        errors = []
        for h in (1e-5, 1e-6, 1e-7):
            plus, minus = p.assemble(z + h * d), p.assemble(z - h * d)
            assert np.array_equal(plus.terms.active, state.terms.active)
            fd = ((plus.F - minus.F) / (2 * h))[p.free]
            errors.append(np.linalg.norm((J @ d)[p.free] - fd) / np.linalg.norm(fd))
        assert min(errors) < 1e-8, errors


def test_the_line_model_pickles_and_solves_alike():
    model = LineBVP3D(
        [LineSegment(**CHAIN)], current=TabulatedCurrent([0, 400.0], [[1, 0.5], [0.2, 0.1]]), n_elements=24
    )
    copy = pickle.loads(pickle.dumps(model))
    np.testing.assert_array_equal(copy.solve(A, B).force_on_fairlead, model.solve(A, B).force_on_fairlead)
    assert repr(copy) == repr(model)
    with pytest.raises(InputError, match="start"):
        model.solve(A, B, start=copy.solve(A, B))


# -- the line in space in its vertical plane is the plane line (issue 32, item 2) --------------------
SEGMENTS = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]


@pytest.mark.parametrize("scene", ["a seabed sloping along the line", "a clump at a joint, no seabed"])
def test_the_line_in_space_in_its_vertical_plane_is_the_plane_line(scene):
    """The pinned plane scenes of `tests/pinned_library.py` (`line_bvp_slope`, `line_bvp_free`)
    solved by the 3-D line BVP in the vertical plane x-z: the two discretisations (the plane's
    graded meshes, the 3-D line's uniform ones) agree to their discretisation errors, 2.7e-8 and
    2.2e-8 of the largest force at the pinned element counts (64 and 48), 1e-9 and 3e-9 at 256
    elements (measured); held at 256 to 1e-8, and closer than on a quarter of the elements."""
    from skcable import mooring

    if scene.startswith("a seabed"):
        plane = mooring.solve_line_bvp(800.0, 150.0, SEGMENTS, seabed=lambda x: -0.02 * x, n_elements=256)
        kwargs = dict(seabed=Plane(0.0, (-0.02, 0.0)))
        b = (800.0, 0.0, 150.0)
    else:
        plane = mooring.solve_line_bvp(700.0, 250.0, SEGMENTS, point_loads=[(300.0, 2e4)], n_elements=256)
        kwargs = dict(attachments=[(1, 2e4)])
        b = (700.0, 0.0, 250.0)
    want = np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])
    gaps = []
    for n in (64, 256):
        space = solve_line_bvp_3d((0.0, 0.0, 0.0), b, SEGMENTS, n_elements=n, **kwargs)
        assert abs(space.force_on_fairlead[1]) <= 1e-12 * space.T_B  # it stays in its plane
        got = np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])
        gaps.append(np.abs(got - want).max() / np.abs(want).max())
    assert gaps[1] < 1e-8 and gaps[1] < gaps[0]


def test_the_line_in_space_solves_the_slack_stretch_the_plane_line_solves():
    """Where friction holds a slack stretch near the anchor (the pinned `line_bvp_friction`), the
    plane line models it (Jonkman's H_A = 0) and so does the line in space (the stretch laid on
    the seabed, `LineProblem3D.lay_slack`; it refused such a line before): the same end forces
    and the same end of the stretch within their meshes' discretisation (measured 1.4e-10 of the
    fairlead's force and 1.3e-7 m apart), the anchor unloaded."""
    from skcable import mooring

    plane = mooring.solve_line_bvp(
        800.0, 150.0, [(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.5, n_elements=80
    )
    assert plane.problem.slack_end > 0 and abs(plane.H_A) <= 1e-9 * plane.H
    space = solve_line_bvp_3d(
        (0.0, 0.0, 0.0), (800.0, 0.0, 150.0), [(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.5, n_elements=80
    )
    want = np.array([-plane.H_B, 0.0, -plane.V_B])
    assert np.abs(space.force_on_fairlead - want).max() <= 1e-9 * space.T_B
    assert abs(space.slack_end - plane.problem.slack_end) <= 1e-9 * space.length
    np.testing.assert_array_equal(space.force_on_anchor, 0.0)


def test_on_one_mesh_the_line_in_its_vertical_plane_solves_the_plane_lines_equations():
    """One line law (`skcable.mooring.line_bvp.discrete`): on the same uniform mesh (no fitting,
    no seabed), a line of three segments with a clump at a joint and a stratified sea's buoyancy
    (a term depending on the height) solved in space in the plane x-z gives the plane line's end
    forces to round-off (both polish to the round-off floor: measured 3.4e-15 of the largest, 4.1e-15
    without the term)."""
    from skcable import mooring
    from skcable.bvp.terms import Buoyancy

    term = Buoyancy(0.01, gradient=0.05, surface=300.0)
    plane = mooring.solve_line_bvp(
        700.0, 250.0, SEGMENTS, point_loads=[(300.0, 2e4)], n_elements=48, fit_touchdown=0, terms=[term]
    )
    space = solve_line_bvp_3d(
        (0.0, 0.0, 0.0), (700.0, 0.0, 250.0), SEGMENTS, attachments=[(1, 2e4)], n_elements=48,
        fit_touchdown=0, terms=[term],
    )  # fmt: skip
    np.testing.assert_array_equal(plane.problem.mesh.p, space.problem.mesh.p)
    want = np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])
    got = np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-13 * np.abs(want).max())


@pytest.mark.parametrize("dim", [2, 3])
def test_held_at_its_active_set_a_grounded_line_returns_to_its_solution(dim):
    """The rescue of `skcable.mooring.line_bvp.iterate` (full steps with the contact nodes'
    active set held, `DiscreteLine.with_active_set`) in the plane and in space: held, each
    node's row is the one the set names; from the converged line of a grounded scene with
    friction with every free dof moved by 1e-4 of the length
    (the contact rows then far from converged), the steps held at the solution's own active set
    meet the tolerance within its steps and land on the semismooth solve's dofs to 1e-9 of the
    scale of each field."""
    from skcable import mooring
    from skcable.fe import NewtonOptions
    from skcable.mooring.line_bvp.iterate import FROZEN_STEPS, frozen_steps

    if dim == 2:
        line = mooring.solve_line_bvp(800.0, 150.0, [(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.3)
    else:
        line = solve_line_bvp_3d(
            (0.0, 0.0, 0.0), (800.0, 0.0, 150.0), [(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.3
        )
    problem, z = line.problem, line.dofs
    active = problem.assemble(z).terms.active
    held = problem.with_active_set(active)
    # held, a node's complementarity row is c g where the set says active, λ where not
    flipped = problem.with_active_set(~active).assemble(z)
    rows = problem.contact_rows.nodes + (dim - 1) * problem.N
    c = problem.contact_rows.stiffness
    want = np.where(~active, c * flipped.terms.gap, flipped.terms.lam)
    np.testing.assert_array_equal(flipped.F[rows], want)
    moved = z.copy()
    rng = np.random.default_rng(3)
    moved[problem.free] += (
        1e-4 * problem.L * rng.uniform(-1.0, 1.0, problem.free.size) * (problem.free < dim * problem.N)
    )
    assert problem.assemble(moved).merit > 1e3 * 1e-10
    out = frozen_steps(held, moved, NewtonOptions(tol=1e-10, max_iter=FROZEN_STEPS))
    assert out is not None
    got, history = out[0], out[2]
    assert len(history) - 1 <= FROZEN_STEPS
    N = problem.N
    positions, tensions = slice(0, dim * N), slice(dim * N, None)
    for part in (positions, tensions):
        np.testing.assert_allclose(got[part], z[part], rtol=0, atol=1e-9 * np.abs(z[part]).max())


def test_the_line_in_space_checks_its_terms_as_the_plane_line_does():
    """One check of the cable terms (`skcable.mooring.line_bvp.inputs.terms_of`): a number or a
    list holding one is an `InputError` naming ``terms`` (a number raised numpy's TypeError
    before), and one term alone is taken as the list of it, in the plane and in space alike."""
    from skcable import mooring
    from skcable.bvp.terms import Buoyancy

    for bad in (5.0, [5.0]):
        with pytest.raises(InputError, match="terms"):
            solve_line_bvp_3d((0.0, 0.0, 0.0), (500.0, 0.0, 100.0), [(600.0, 1000.0, 5e8)], terms=bad)
        with pytest.raises(InputError, match="terms"):
            mooring.solve_line_bvp(500.0, 100.0, [(600.0, 1000.0, 5e8)], terms=bad)
    term = Buoyancy(0.01)
    one = solve_line_bvp_3d((0.0, 0.0, 0.0), (500.0, 0.0, 100.0), [(600.0, 1000.0, 5e8)], terms=term)
    listed = solve_line_bvp_3d((0.0, 0.0, 0.0), (500.0, 0.0, 100.0), [(600.0, 1000.0, 5e8)], terms=[term])
    np.testing.assert_array_equal(one.force_on_fairlead, listed.force_on_fairlead)


def test_on_one_mesh_a_weight_along_the_line_and_a_load_inside_a_segment_are_the_plane_lines():
    """One segment type (`skcable.mooring.line_bvp.inputs.LineSegment`, the plane line's
    `BVPSegment` too): a weight that varies along the arc length (a callable) and a point load
    inside a segment (``point_loads``, by arc length) in space, in the plane x-z, on the plane
    line's uniform mesh, give the plane line's end forces to round-off (measured 2.3e-14 of the
    largest)."""
    from skcable import mooring

    assert mooring.BVPSegment is LineSegment

    def w(s):
        return 900.0 + 0.3 * s

    segments = [(300.0, w, 5e8), (250.0, 400.0, 2e8), (300.0, w, 5e8)]
    common = dict(point_loads=[(420.0, 2e4)], n_elements=48, fit_touchdown=0)
    plane = mooring.solve_line_bvp(700.0, 250.0, segments, **common)
    space = solve_line_bvp_3d((0.0, 0.0, 0.0), (700.0, 0.0, 250.0), segments, **common)
    np.testing.assert_array_equal(plane.problem.mesh.p, space.problem.mesh.p)
    want = np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])
    got = np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-13 * np.abs(want).max())
    # statics: the ends carry the whole weight, ∫ w ds over the outer segments by hand, the clump
    outer = 900.0 * 600.0 + 0.3 * (300.0**2 + 850.0**2 - 550.0**2) / 2.0
    np.testing.assert_allclose(-(got[1] + got[3]), outer + 250.0 * 400.0 + 2e4, rtol=1e-12)


def test_a_clump_resting_on_a_sloping_seabed_solves_in_the_plane_as_in_space():
    """A clump weight inside a segment, resting on a seabed that slopes along the line, on 256
    elements: the plane line's uniform start hangs above the seabed there (3 cm at its lowest)
    and its one level stagnated (a `ConvergenceError` before); it now goes by nested meshes, as
    the line in space does, and the two lines' end forces (graded meshes in the plane, uniform
    in space) agree to their discretisation errors (measured 1.4e-10 of the largest)."""
    from skcable import mooring

    segments = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    common = dict(point_loads=[(420.0, 2e4)], n_elements=256)
    plane = mooring.solve_line_bvp(800.0, 150.0, segments, seabed=lambda x: -0.02 * x, **common)
    space = solve_line_bvp_3d(
        (0.0, 0.0, 0.0), (800.0, 0.0, 150.0), segments, seabed=Plane(0.0, (-0.02, 0.0)), **common
    )
    assert 420.0 < plane.s_touchdown  # the clump rests on the seabed
    want = np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])
    got = np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-8 * np.abs(want).max())


def test_the_plane_line_refuses_what_only_the_line_in_space_models_by_name():
    """The plane line has no current and a constant EA: a segment with drag coefficients or a
    strain law is refused naming ``segments``; a `ConstantEA` is its number (the same line)."""
    from skcable import mooring
    from skcable.mooring.axial import ConstantEA

    with pytest.raises(InputError, match="segments.*current"):
        mooring.solve_line_bvp(500.0, 100.0, [LineSegment(600.0, 1000.0, 5e8, 0.1, 1.2)])
    with pytest.raises(InputError, match="segments.*strain law"):
        law = StrainFunction(lambda T: T / 5e8, lambda T: 0 * T + 2e-9)
        mooring.LineBVP([LineSegment(600.0, 1000.0, law)])
    by_law = mooring.solve_line_bvp(500.0, 100.0, [(600.0, 1000.0, ConstantEA(5e8))])
    by_number = mooring.solve_line_bvp(500.0, 100.0, [(600.0, 1000.0, 5e8)])
    assert (by_law.H, by_law.V_B) == (by_number.H, by_number.V_B)


def test_the_line_in_space_grades_its_mesh_by_its_turning_as_the_plane_line_does():
    """`skcable.mooring.line_bvp.mesh.graded_nodes`, which the line in space uses where its uniform
    mesh ends in compression: for one line solved in the plane and in space (on one uniform mesh),
    the nodes graded by the turning of the unit tangent in space are those graded by the plane's
    angle, within 1e-6 of the length (the two differ by the finite differences of an angle and of
    a unit vector, to the second order of the angle step: measured 6.1e-8); turned by 30° about
    the vertical and moved, the line in space grades its mesh alike to round-off (measured
    4.3e-14: the turning of a tangent does not depend on the frame)."""
    from skcable import mooring
    from skcable.mooring.line_bvp.mesh import fixed_nodes, graded_nodes

    mesh = dict(n_elements=48, fit_touchdown=0)
    plane = mooring.solve_line_bvp(700.0, 250.0, SEGMENTS, point_loads=[(300.0, 2e4)], **mesh)
    space = solve_line_bvp_3d((0.0, 0.0, 0.0), (700.0, 0.0, 250.0), SEGMENTS, attachments=[(1, 2e4)], **mesh)
    c, s = np.cos(np.pi / 6), np.sin(np.pi / 6)
    B_turned = (10.0 + 700.0 * c, -5.0 + 700.0 * s, 250.0)
    turned = solve_line_bvp_3d((10.0, -5.0, 0.0), B_turned, SEGMENTS, attachments=[(1, 2e4)], **mesh)
    fixed = fixed_nodes(plane.problem.joints, [(300.0, 2e4)])
    L = plane.problem.L
    want = graded_nodes(plane.problem, plane.dofs, 48, fixed)[0]
    h = np.diff(want)
    assert h.max() > 2.0 * h.min(), "the test needs a mesh the line's turning grades"
    got = graded_nodes(space.problem, space.dofs, 48, fixed)[0]
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-6 * L)
    again = graded_nodes(turned.problem, turned.dofs, 48, fixed)[0]
    np.testing.assert_allclose(again, got, rtol=0, atol=1e-12 * L)


def test_a_line_whose_slack_lies_in_a_heap_is_refused_in_space_as_in_the_plane():
    """400 m of chain between an anchor on a flat seabed 100 m down and a fairlead 200 m off: its
    L-shape is 300 m long, so the slack lies in a heap (H = 0), which the arc-length form has no
    tension to solve for. Both lines refuse it by name, from the one closed-form start
    (`skcable.mooring.line_bvp.start`; the line in space's in the vertical plane of its ends),
    as `skcable.cable.elastic_catenary(seabed=)` returns that state."""
    from skcable import cable, mooring

    assert cable.elastic_catenary(200.0, 100.0, 1000.0, 5e8, length=400.0, seabed=0.0).heap
    with pytest.raises(InputError, match="heap") as plane:
        mooring.solve_line_bvp(200.0, 100.0, [(400.0, 1000.0, 5e8)], seabed=0.0)
    with pytest.raises(InputError, match="heap") as space:
        solve_line_bvp_3d((0.0, 0.0, -100.0), (200.0, 0.0, 0.0), [(400.0, 1000.0, 5e8)], seabed=-100.0)
    assert plane.value.argument == space.value.argument == "length"


#: a chain at the anchor under a light rope, on a seabed rising from the anchor at tan α = 0.0965
#: (the survey's scene 1:43, `benchmarks/line_bvp_planes.py`, which both lines failed as
#: "in compression: give more elements")
RISING = dict(
    segments=[
        (160.79387729255396, 1166.4576289746321, 1.7786e8),
        (260.92682156281796, 75.34616514177478, 1.28e8),
    ],
    span=393.7672111241806,
    dh=92.47974466075216,
    slope=0.09654431846687947,
)


@pytest.mark.parametrize("mu", [0.0, 0.05, 0.2])
def test_a_line_the_seabed_rising_from_the_anchor_pushes_into_compression_is_refused_by_name(mu):
    """The chain lying on the seabed from the anchor slides down the slope unless friction holds
    it: along the seabed ``dT/ds = w (sin α − μ cos α)``, so with ``μ < tan α`` its weight pushes
    it against the anchor and the line has no equilibrium in tension, on any mesh. Both lines
    refuse it by naming ``friction`` (`skcable.mooring.line_bvp.check.refuse_sliding`); with
    ``μ > tan α`` friction holds a slack stretch near the anchor, which both model (the plane
    line by friction holding each node's weight, the line in space by laying the stretch): the
    same fairlead force within their discretisations (measured 2.2e-10 of T_B), both anchors
    unloaded (Jonkman's ``H_A = 0``: the plane line left its anchor node's share of the weight
    along the slope to the anchor, 249 N on 64 elements, 61 N on 256, before friction held it as
    it holds the stretch's other nodes; now 6e-7 N)."""
    from skcable import mooring

    sc = RISING
    m = sc["slope"]
    common = dict(friction=mu, n_elements=64)
    bed = dict(seabed=lambda x: m * np.asarray(x), seabed_slope=lambda x: np.full(np.shape(x), m))
    B = (sc["span"], 0.0, sc["dh"])

    def plane():
        return mooring.solve_line_bvp(sc["span"], sc["dh"], sc["segments"], **bed, **common)

    def space():
        return solve_line_bvp_3d((0.0, 0.0, 0.0), B, sc["segments"], seabed=Plane(0.0, (m, 0.0)), **common)

    if mu < m:
        for solve in (plane, space):
            with pytest.raises(InputError, match="slide down") as refused:
                solve()
            assert refused.value.argument == "friction"
    else:
        line = plane()
        assert line.problem.slack_end > 0 and line.equilibrium_residual <= line.residual_bound
        laid = space()
        want = np.array([-line.H_B, 0.0, -line.V_B])
        assert np.abs(laid.force_on_fairlead - want).max() <= 2e-9 * laid.T_B
        assert abs(laid.slack_end - line.problem.slack_end) <= 1e-9 * laid.length
        # the plane line's H_A is the tension left past its stretch, solved to 1e-10 of the force
        # scale: bounded at ten times that (measured 6e-7 N, 3e-11 of it, on 64 elements)
        assert max(abs(line.H_A), abs(line.V_A)) <= 1e-9 * line.problem.load_scale
        np.testing.assert_array_equal(laid.force_on_anchor, 0.0)


def test_a_line_whose_friction_would_take_more_than_its_pull_fails_saying_so():
    """70 m of rope hanging from an anchor 2 m above a seabed falling at 0.084, 41 m of it lying
    on the seabed (the survey's scene 1:83, `benchmarks/line_bvp_planes.py`): without friction
    the seabed carries about 1000 N of it while the pull at the touchdown is 67 N, so friction
    fully mobilised at μ = 0.6 would take the whole pull before the landing and the line rests
    with friction partly mobilised, which Jonkman's model does not describe. Both lines fail, and
    say so with their history; at μ = 0.05 (μN below the pull) both solve."""
    from skcable import mooring

    def w(s):
        return 22.46914539818281 * (
            1 + 0.19493681225993587 * np.sin(2 * np.pi * s / 68.37579951177868 + 4.7464916805)
        )

    segments = [(69.95813778856333, w, 1042166171.4004604)]
    span, dh, level, m = 55.378995773288224, 13.0605082376325, -2.139077440408955, -0.08378586867495089
    bed = dict(seabed=lambda x: level + m * np.asarray(x), seabed_slope=lambda x: np.full(np.shape(x), m))

    def plane(mu):
        return mooring.solve_line_bvp(span, dh, segments, friction=mu, n_elements=64, **bed)

    def space(mu):
        B = (span, 0.0, dh)
        return solve_line_bvp_3d(
            (0.0, 0.0, 0.0), B, segments, seabed=Plane(level, (m, 0.0)), friction=mu, n_elements=64
        )

    # the seabed's normal force on the line without friction: the weight of its grounded stretch
    # (between the landing and the touchdown, by the balance of forces) times cos α
    free = plane(0.0)
    grounded = free.load_before(free.s_touchdown)[1] - free.load_before(free.s_landing)[1]
    normal = grounded / np.hypot(1.0, m)
    assert 900.0 < normal < 1100.0 and free.tension(np.array([free.s_touchdown - 1e-6]))[0] < 70.0
    for solve in (plane, space):
        with pytest.raises(ConvergenceError, match="partly mobilised") as failed:
            solve(0.6)
        assert failed.value.history and "times the pull at its touchdown" in str(failed.value)
        said = float(re.search(r"μN = ([0-9.e+]+) N", str(failed.value)).group(1))
        # the nodal multipliers against the integral of the weight: measured 3e-5, the message has 4 digits
        assert said == pytest.approx(0.6 * normal, rel=2e-4)
        line = solve(0.05)
        assert line.equilibrium_residual <= line.residual_bound


def test_a_rope_in_a_strong_current_on_a_seabed_is_graded_by_steps_of_the_current(monkeypatch):
    """A light rope (30 N/m) in a 3 m/s cross current, anchored on a flat seabed, 128 elements:
    its closed-form starts fail, and the meshes graded by the start are reached by nested solves
    whose coarsest one takes the current in steps (`LineBVP3DSolver.continued` on a graded
    mesh). Its end forces agree with the line on 512 uniform elements (``mesh="uniform"``, an
    independent mesh) within 1e-8 of the largest (measured 5.1e-10)."""
    from skcable.mooring.line_bvp.space.driver import LineBVP3DSolver

    rope = LineSegment(700.0, 30.0, 5e7, 0.12, 2.4, 0.3)
    ends = ((0.0, 0.0, -200.0), (600.0, 0.0, -20.0))
    steps = []
    continued = LineBVP3DSolver.continued

    def spy(self, n, fitted, z0, nodes_at=None):
        steps.append(nodes_at is not None)
        return continued(self, n, fitted, z0, nodes_at=nodes_at)

    monkeypatch.setattr(LineBVP3DSolver, "continued", spy)
    graded = LineBVP3D([rope], seabed=-200.0, current=(0.0, 3.0), n_elements=128).solve(*ends)
    assert steps and steps[0] and graded.problem.nodes_at is not None
    uniform = LineBVP3D([rope], seabed=-200.0, current=(0.0, 3.0), n_elements=512, mesh="uniform").solve(
        *ends
    )
    scale = np.abs(uniform.force_on_fairlead).max()
    assert np.abs(graded.force_on_fairlead - uniform.force_on_fairlead).max() <= 1e-8 * scale
    assert np.abs(graded.force_on_anchor - uniform.force_on_anchor).max() <= 1e-8 * scale


def _scene_3d(anchor, fairlead, segments, **options):
    """The checked `Scene3D` that `solve_line_bvp_3d` solves."""
    from skcable.mooring.line_bvp.space.inputs import scene

    return scene(anchor, fairlead, LineBVP3D(segments, **options).checked)


def test_a_line_hangs_in_its_vertical_plane_only_where_nothing_pushes_it_out():
    """`plane_scene`: the chord at 30° azimuth (``E``), a seabed sloping along it by 0.05 from
    30 m below the anchor: the plane line's span is the chord's horizontal length, its height the
    chord's, its seabed ``b(x) = −30 − 0.05 x`` relative to the anchor (the plane's formula). A
    seabed sloping across the chord by 1e-3, a current, a strain law that is not a constant
    stiffness, a grid seabed, or a vertical line: None (the line in space is not the plane
    line's there)."""
    from skcable.bvp.current import UniformCurrent
    from skcable.mooring.line_bvp.space.vertical_plane import plane_scene

    along = Plane(A[2] - 30.0, -0.05 * E, origin=A[:2])
    seg = [LineSegment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2)]
    plane = plane_scene(_scene_3d(A, B, seg, seabed=along), 10.0)
    assert plane.span == pytest.approx(400.0, rel=1e-15) and plane.dh == pytest.approx(180.0, rel=1e-15)
    x = np.array([0.0, 123.0, 399.0])
    np.testing.assert_allclose(plane.seabed(x), -30.0 - 0.05 * x, rtol=0, atol=1e-12)
    np.testing.assert_allclose(plane.seabed.slope(x), -0.05, rtol=0, atol=1e-15)
    assert plane.time_limit == 10.0 and plane.segments[0].length == 500.0
    across = Plane(A[2] - 30.0, -0.05 * E + 1e-3 * np.array([-E[1], E[0]]), origin=A[:2])
    grid = Grid(np.linspace(-100, 600, 8), np.linspace(-100, 600, 8), np.full((8, 8), A[2] - 30.0))
    law = StrainTable([0.0, 0.01, 0.02], [0.0, 2e6, 6e6])
    for space in (
        _scene_3d(A, B, seg, seabed=across),
        _scene_3d(A, B, seg, current=UniformCurrent((0.5, 0.0))),
        _scene_3d(A, B, [LineSegment(500.0, 600.0, law)]),
        _scene_3d(A, B, seg, seabed=grid),
        _scene_3d(A, A + np.array([0.0, 0.0, 180.0]), seg),
    ):
        assert plane_scene(space, 10.0) is None


def test_where_its_strategy_fails_the_line_in_space_takes_the_plane_lines_solve(monkeypatch):
    """Where the line in space's own strategy fails (made to, here), a line in the vertical plane
    of its ends is solved by the plane line's strategy, then in space on that mesh from it: its end
    forces are the plane line's (`solve_line_bvp`, solved apart on the same scene) to round-off
    (the two discretise one line on one mesh), out of the plane none; a line off that plane (a
    seabed sloping across the chord) fails as before, and so does a scene whose meshes the plane
    line would grade otherwise (``mesh="uniform"`` on a seabed; no seabed, where the line in space
    keeps its uniform mesh)."""
    from skcable import mooring
    from skcable.mooring.line_bvp.space.driver import LineBVP3DSolver

    def fails(self, start=None):
        raise ConvergenceError("solve_line_bvp_3d: made to fail", [1.0])

    monkeypatch.setattr(LineBVP3DSolver, "strategy", fails)
    along = Plane(A[2] - 30.0, -0.05 * E, origin=A[:2])
    segments = [(500.0, 600.0, 4e8)]
    want = mooring.solve_line_bvp(
        400.0, 180.0, segments, seabed=lambda x: -30.0 - 0.05 * np.asarray(x),
        seabed_slope=lambda x: np.full(np.shape(x), -0.05), n_elements=48,
    )  # fmt: skip
    space = solve_line_bvp_3d(A, B, segments, seabed=along, n_elements=48)
    assert space.s_touchdown > 0  # on the seabed
    h_a, h_b = space.force_on_anchor[:2] @ E, space.force_on_fairlead[:2] @ E
    got = np.array([h_a, space.force_on_anchor[2], h_b, space.force_on_fairlead[2]])
    expected = np.array([want.H_A, -want.V_A, -want.H_B, -want.V_B])
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    side = np.array([-E[1], E[0]])
    assert abs(space.force_on_fairlead[:2] @ side) <= 1e-12 * space.T_B
    across = Plane(A[2] - 30.0, -0.05 * E + 1e-3 * side, origin=A[:2])
    for options in (dict(seabed=across), dict(seabed=along, mesh="uniform"), dict(seabed=None)):
        with pytest.raises(ConvergenceError, match="made to fail") as failed:
            solve_line_bvp_3d(A, B, segments, n_elements=48, **options)
        assert "plane line" not in str(failed.value)


def test_the_line_in_spaces_touchdown_and_landing_are_the_plane_lines():
    """`s_touchdown` and `s_landing` of the line in space are where the hanging part's force is
    tangent to the seabed (`skcable.mooring.line_bvp.fields.LineFields`), as the plane line's:
    without fitting (``fit_touchdown=0``, uniform meshes of 64 elements), a line landing on a
    slope below its anchor and a line anchored on a flat seabed give the plane line's within 1e-9
    of the length (one discrete line, measured 1e-12). The last contact node, which the line in
    space reported before, lies 1.4 m and 0.17 m past the touchdown."""
    from skcable import mooring

    for span, dh, segment, height, slope in (
        (400.0, 180.0, (500.0, 600.0, 4e8), -30.0, -0.05),
        (800.0, 150.0, (850.0, 1000.0, 5e8), 0.0, 0.0),
    ):
        plane = mooring.solve_line_bvp(
            span, dh, [segment], seabed=lambda x, h=height, b=slope: h + b * np.asarray(x),
            seabed_slope=lambda x, b=slope: np.full(np.shape(x), b), n_elements=64, fit_touchdown=0,
        )  # fmt: skip
        space = solve_line_bvp_3d(
            (0.0, 0.0, 0.0), (span, 0.0, dh), [segment], seabed=Plane(height, (slope, 0.0)),
            n_elements=64, fit_touchdown=0,
        )  # fmt: skip
        assert plane.s_touchdown > 0 and abs(space.s_touchdown - plane.s_touchdown) <= 1e-9 * plane.length
        assert abs(space.s_landing - plane.s_landing) <= 1e-9 * plane.length
        assert space.length_on_seabed == space.s_touchdown - space.s_landing
        last_node = float(space.contact_s[space.in_contact].max())  # what it reported before
        assert last_node - space.s_touchdown > 0.1  # measured 1.37 m and 0.17 m


def test_partly_mobilised_friction_is_refused_as_such_where_the_touchdown_has_no_balance():
    """Two segments landing on a gentle slope 20 m below the anchor with friction 0.2 on 24
    elements: friction fully mobilised would take more than the pull, and with the anchor above
    the seabed the line rests with friction partly mobilised, which neither line BVP models (a
    slack stretch from an anchor on the seabed the line in space lays); its solve ends in
    compression there, and the balance that places the touchdown has no root near the contact
    edge. The refusal names the friction (the fitting stops where it finds no root, and the
    checks and the diagnosis say why), not the missing root, and does not ask for elements."""
    with pytest.raises(ConvergenceError, match="fully mobilised friction with the anchor above") as failed:
        solve_line_bvp_3d(
            (0.0, 0.0, 0.0), (700.0, 0.0, 150.0), [(300.0, 1000.0, 5e8), (500.0, 800.0, 5e8)],
            seabed=Plane(-20.0, (0.02, 0.0)), friction=0.2, n_elements=24,
        )  # fmt: skip
    assert "no sign change" not in str(failed.value).split(";")[0]
    assert "give more" not in str(failed.value) and "partly mobilised" in str(failed.value)
