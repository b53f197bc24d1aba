"""Arc-length formulation: closed forms, rotated gravity, non-graph shapes, tangent, rates."""

import numpy as np
import pytest

from skcable import bvp, cable
from skcable.bvp.arc import ArcProblem as _ArcProblem
from skcable.bvp.arc import arc_guess as _arc_guess
from skcable.errors import InputError

SPAN, DH, W = 800.0, -20.0, 20.0
REF = cable.catenary(SPAN, DH, W, low=-30.0)


@pytest.mark.parametrize("constraint", ["length", "sag", "H", "low", "T_max"])
def test_reproduces_catenary_for_every_constraint(constraint):
    value = {"low": REF.y_low}.get(constraint, getattr(REF, constraint, None))
    b = bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), **{constraint: value}, formulation="arc", n_elements=128)
    assert b.formulation == "arc"
    for name in ("H", "V_A", "V_B", "T_A", "T_B", "length"):
        assert getattr(b, name) == pytest.approx(getattr(REF, name), rel=1e-8), name
    assert b.residual() < 1e-10
    assert b.y(400.0) == pytest.approx(REF.y(400.0), rel=1e-7)


def test_elastic_matches_irvine():
    e = cable.elastic_catenary(150.0, 30.0, 9.0, 2e5, length=160.0)
    b = bvp.solve_bvp(
        150.0, 30.0, bvp.SelfWeight(9.0), EA=2e5, length=160.0, formulation="arc", n_elements=128
    )
    assert b.H == pytest.approx(e.H, rel=1e-8)
    assert b.stretched_length == pytest.approx(e.stretched_length, rel=1e-9)


def rotated_catenary(span, dh, qx, qy, length):
    """Uniform load per cable length in any direction = gravity along q: the
    closed-form catenary in a frame whose y' axis points against q."""
    q = np.hypot(qx, qy)
    up = -np.array([qx, qy]) / q
    across = np.array([up[1], -up[0]])
    B = np.array([span, dh])
    if B @ across < 0:  # a mirrored frame keeps B to the right
        across = -across
    c = cable.catenary(float(B @ across), float(B @ up), q, length=length)
    # tension pulling into the cable at A and at B (global axes)
    t_a = c.H * across - c.V_A * up
    t_b = c.H * across + c.V_B * up
    return c, t_a, t_b


@pytest.mark.parametrize("qx, qy", [(5.0, -10.0), (-20.0, -1.0), (3.0, 0.0)])
def test_horizontal_load_is_rotated_gravity(qx, qy):
    load = bvp.DistributedLoad(qx=lambda x: qx + 0 * x, qy=lambda x: qy + 0 * x)
    span, dh, length = 30.0, 5.0, 100.0
    b = bvp.solve_bvp(span, dh, load, length=length, n_elements=512)  # auto picks the arc form
    assert b.formulation == "arc"
    _, t_a, t_b = rotated_catenary(span, dh, qx, qy, length)
    # components to 1e-6 of the tension: in its own frame the blown-back cable
    # (-20, -1) is 3.3 times its chord, the hardest of the three (2.3e-7 at 512 elements)
    assert [b.H_A, -b.V_A] == pytest.approx(list(t_a), abs=1e-6 * np.hypot(*t_a))
    assert [b.H_B, b.V_B] == pytest.approx(list(t_b), abs=1e-6 * np.hypot(*t_b))
    # total load balances: H_A - H_B = qx L, V_A + V_B = -qy L
    assert b.H_A - b.H_B == pytest.approx(qx * length, rel=1e-9, abs=1e-9)
    # H is kept where the two ends agree; here they do not, and it says so
    with pytest.raises(AttributeError, match="H_A or H_B"):  # deprecated in 0.2.0, gone in 0.3.0
        b.H  # noqa: B018
    assert b.V_A + b.V_B == pytest.approx(-qy * length, rel=1e-9, abs=1e-9)


def test_cable_blown_back_past_its_support_is_not_a_graph():
    load = bvp.DistributedLoad(qx=lambda x: -20.0 + 0 * x, qy=lambda x: -1.0 + 0 * x)
    b = bvp.solve_bvp(30.0, 5.0, load, length=100.0, n_elements=128)
    xy = b.xy(np.linspace(0, b.length, 201))  # s in metres of unstretched arc length
    assert xy[:, 0].min() < -10.0  # the cable passes far left of A
    with pytest.raises(InputError, match="x"):
        b.y(15.0)


def test_tangent_agrees_with_finite_differences():
    load = [
        bvp.SelfWeight(2.0),
        bvp.DeckLoad(1.0),
        bvp.DistributedLoad(qx=lambda x: 0.5 * np.sin(x / 20)),
    ]
    problem = _ArcProblem(100.0, 30.0, load, 1e4, ("sag", 12.0), 10, 2)
    z, L0 = _arc_guess(problem)
    rng = np.random.default_rng(3)
    z = z + 0.01 * rng.standard_normal(z.size)
    state = problem.assemble(z, L0)
    d = rng.standard_normal(z.size)
    eps = 1e-6
    plus, minus = problem.assemble(z + eps * d, L0), problem.assemble(z - eps * d, L0)
    assert state.J @ d == pytest.approx((plus.R - minus.R) / (2 * eps), rel=1e-5, abs=1e-6)
    assert state.dg @ d == pytest.approx((plus.g - minus.g) / (2 * eps), rel=1e-5, abs=1e-9)
    up, down = problem.assemble(z, L0 + 1e-4), problem.assemble(z, L0 - 1e-4)
    assert state.dR_dL0 == pytest.approx((up.R - down.R) / 2e-4, rel=1e-5, abs=1e-8)


def test_rates_positions_h3_tension_h4():
    ref = cable.catenary(100.0, 30.0, 1.0, length=160.0)
    u_a = ref.m - ref.z
    sigma = np.linspace(0, 1, 2001)
    x = ref.a * (np.arcsinh(sigma * 160.0 / ref.a + np.sinh(u_a)) - u_a)
    exact = np.column_stack([x, ref.y(x)])
    position, tension = [], []
    for n in (16, 32, 64):
        b = bvp.solve_bvp(100.0, 30.0, bvp.SelfWeight(1.0), length=160.0, n_elements=n, formulation="arc")
        position.append(np.sqrt(np.trapezoid(np.sum((b.xy(sigma * b.length) - exact) ** 2, axis=1), sigma)))
        tension.append(abs(b.T_A / ref.T_A - 1))
    assert np.log2(position[-2] / position[-1]) == pytest.approx(3.0, abs=0.2)
    assert np.log2(tension[-2] / tension[-1]) == pytest.approx(4.0, abs=0.2)


def test_arc_rejects_what_it_cannot_do():
    with pytest.raises(InputError, match="degree"):
        bvp.solve_bvp(SPAN, DH, bvp.SelfWeight(W), H=1e5, formulation="arc", degree=3)


def test_discontinuous_tension_keeps_the_tangent_well_conditioned():
    # why P1-DG: with a continuous P1 tension, tangential modes inside the elements have
    # no stiffness and the tangent of a curved cable is nearly singular
    from skfem import ElementLineP1

    span, dh = 100.0, 30.0
    length = 6.0 * np.hypot(span, dh)
    conditions = {}
    for name in ("P1-DG", "P1"):
        tension = ElementLineP1() if name == "P1" else None
        problem = _ArcProblem(span, dh, [bvp.SelfWeight(1.0)], None, ("length", length), 64, 2, tension)
        z, _ = _arc_guess(problem)
        J = problem.assemble(z, length).J[problem.free][:, problem.free].toarray()
        conditions[name] = np.linalg.cond(J)
    assert conditions["P1-DG"] < 1e5 < 1e8 < conditions["P1"]


def _arc_reference(problem, z, L0):
    """R, J and dR/dL0 by scikit-fem's ``asm`` of the forms, block by block."""
    import scipy.sparse as sp
    from skfem import asm

    from skcable.bvp import forms
    from skcable.bvp.arc import arc_loads

    b, tb = problem.basis, problem.tbasis
    xd, yd, Td = problem.fields(z)
    X, Y, T = b.interpolate(xd), b.interpolate(yd), np.asarray(tb.interpolate(Td))
    ax, ay = X.grad[0], Y.grad[0]
    n = np.sqrt(ax * ax + ay * ay)
    ex, ey = ax / n, ay / n
    Qx, Qy, dQx_dx, dQy_dx, dQx_dxp, dQy_dxp, dQx_dL, dQy_dL = arc_loads(
        problem.loads, np.asarray(X), ax, L0, problem.span
    )
    c = problem.compliance
    common = dict(T=T, n=n, ex=ex, ey=ey)
    Rx = asm(forms.arc_equilibrium_x, b, Qx=Qx, **common)
    Ry = asm(forms.arc_equilibrium_y, b, Qy=Qy, **common)
    Rc = asm(forms.arc_constitutive, tb, n=n, L0=L0, T=T, compliance=c)
    Kxx = asm(forms.arc_geometric, b, T=T, n=n, P=1 - ex * ex) + asm(
        forms.arc_load_position, b, dQ_dx=dQx_dx, dQ_dxp=dQx_dxp
    )
    Kxy = asm(forms.arc_geometric, b, T=T, n=n, P=-ex * ey)
    Kyx = Kxy + asm(forms.arc_load_position, b, dQ_dx=dQy_dx, dQ_dxp=dQy_dxp)
    Kyy = asm(forms.arc_geometric, b, T=T, n=n, P=1 - ey * ey)
    KxT = asm(forms.arc_tension_coupling, tb, b, e=ex)
    KyT = asm(forms.arc_tension_coupling, tb, b, e=ey)
    KTT = asm(forms.arc_tension_mass, tb, L0=L0, compliance=c)
    J = sp.bmat([[Kxx, Kxy, KxT], [Kyx, Kyy, KyT], [KxT.T, KyT.T, KTT]], format="csr")
    dR = [asm(forms.arc_load_dL0, b, d=dQx_dL), asm(forms.arc_load_dL0, b, d=dQy_dL)]
    dR.append(asm(forms.arc_constitutive_dL0, tb, T=T, compliance=c))
    return np.concatenate([Rx, Ry, Rc]), J, np.concatenate(dR)


@pytest.mark.parametrize("EA", [None, 1e4])
def test_fast_assembly_equals_scikit_fem_forms(EA):
    load = [
        bvp.SelfWeight(2.0),
        bvp.DeckLoad(1.0),
        bvp.DistributedLoad(qx=lambda x: 0.5 * np.sin(x / 20), qy=lambda x: -0.1 * x / 100),
        bvp.DistributedLoad(qy=lambda x: -1.0 - np.cos(x / 30), per="horizontal"),
    ]
    problem = _ArcProblem(100.0, 30.0, load, EA, ("sag", 12.0), 10, 2)
    z, L0 = _arc_guess(problem)
    z = z + 0.01 * np.random.default_rng(5).standard_normal(z.size)
    state = problem.assemble(z, L0)
    R, J, dR_dL0 = _arc_reference(problem, z, L0)
    for fast, reference in ((state.R, R), (state.J.toarray(), J.toarray()), (state.dR_dL0, dR_dL0)):
        np.testing.assert_allclose(fast, reference, rtol=0, atol=1e-12 * np.max(np.abs(reference)))


def test_y_slope_and_T_take_arrays_and_agree_with_the_catenary():
    """The arc form's y(x), slope(x) and T(x) on an array of x (each element's σ found by its own
    root search) against the inextensible catenary of the same scene, to the discretisation."""
    sol = bvp.solve_bvp(300.0, 10.0, bvp.SelfWeight(3.0), length=320.0, formulation="arc", n_elements=128)
    exact = cable.catenary(300.0, 10.0, 3.0, length=320.0)
    x = np.array([0.0, 37.5, 150.0, 261.0, 300.0])
    np.testing.assert_allclose(sol.y(x), exact.y(x), rtol=0, atol=1e-6 * 320.0)
    np.testing.assert_allclose(sol.slope(x), exact.slope(x), rtol=0, atol=1e-5)
    np.testing.assert_allclose(sol.T(x), exact.T(x), rtol=1e-5)
    assert sol.y(x).shape == x.shape and sol.y(x[[2]]).shape == (1,)
