"""The open FE core from an analyst's side: supports as data, Newton options, contact, tangent
checks, loads anywhere, term declarations and outputs — each against a closed form or an
independent computation written here."""

import numpy as np
import pytest
import scipy.sparse as sp

from skcable import strand
from skcable.errors import ConvergenceError, InputError, SlowConvergenceWarning, TangentWarning
from skcable.fe import NewtonOptions, check_tangent

#: a strand whose wires run parallel to its axis: a prismatic Euler–Bernoulli beam of known EI
STRAIGHT = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=1e-9),), strand.material("steel"))
SEC = STRAIGHT.section()
EA, EI = SEC.EA, SEC.EI_stick[0]


def tensioned_beam(N, q, L, conditions, x, derivative=0):
    """v(x) of ``EI v'''' − N v'' = q`` under four boundary conditions, solved here by its general
    solution ``v = a + b x + c e^{k (x − L)} + d e^{−k x} − q x²/(2N)``, k = sqrt(N/EI) (each
    exponential bounded by 1 on [0, L]).

    ``conditions``: four ``(x0, kind, value)`` with kind ``"v"``, ``"v'"``, ``"M"`` (EI v'') or
    ``"V"`` (the transverse force EI v''' − N v'); ``derivative`` 0 to 3: v or a derivative."""
    k = np.sqrt(N / EI)
    orders = np.arange(4)

    def rows(x0):  # derivatives 0..3 (rows) of the four homogeneous solutions (columns) at x0
        grow, decay = np.exp(k * (x0 - L)), np.exp(-k * x0)
        polynomial = np.array([[1.0, x0], [0.0, 1.0], [0.0, 0.0], [0.0, 0.0]])
        return np.column_stack([polynomial, k**orders * grow, (-k) ** orders * decay])

    def particular(x0):
        return np.array([-q * x0**2 / (2 * N), -q * x0 / N, -q / N, 0.0])

    A, b = [], []
    for x0, kind, value in conditions:
        combine = np.array(
            {"v": [1, 0, 0, 0], "v'": [0, 1, 0, 0], "M": [0, 0, EI, 0], "V": [0, -N, 0, EI]}[kind]
        )
        A.append(combine @ rows(x0))
        b.append(value - combine @ particular(x0))
    c = np.linalg.solve(np.array(A), np.array(b))
    x = np.asarray(x, dtype=float)
    values = [rows(xi)[derivative] @ c + particular(xi)[derivative] for xi in np.atleast_1d(x)]
    return np.array(values).reshape(x.shape)


def deflection(model, step, x):
    return model.bases["v"].probes(np.atleast_2d(x)) @ model.split(step.dofs)["v"]


X = np.array([0.1, 0.3, 0.5, 0.8, 1.0])


@pytest.mark.parametrize(
    "supports, axial, conditions",
    [
        (("pinned", "pinned"), "strain", [(0.0, "v", 0), (0.0, "M", 0), (1.0, "v", 0), (1.0, "M", 0)]),
        (("clamped", "free"), "force", [(0.0, "v", 0), (0.0, "v'", 0), (1.0, "M", 0), (1.0, "V", 0)]),
        (("clamped", "sliding"), "force", [(0.0, "v", 0), (0.0, "v'", 0), (1.0, "v'", 0), (1.0, "V", 0)]),
    ],
    ids=["pinned-pinned", "cantilever", "clamped-sliding"],
)
def test_tensioned_strand_under_a_transverse_load_matches_the_beam_equation(supports, axial, conditions):
    # a small load: the stretch of the bent axis, ½ v′², stays 1e-9 of the strain (the beam equation
    # is linear, the model is not); a free or sliding end is pulled by the axial force EA ε
    L, q, strain = 1.0, 0.01, 0.001
    model = strand.StrandModel(
        STRAIGHT, L, n_elements=128, grading=0.0, supports=supports, axial=axial,
        terms=[strand.TransverseLoad(qy=q)],
    )  # fmt: skip
    step = model.solve(strain) if axial == "strain" else model.solve(force=EA * strain)
    exact = tensioned_beam(EA * strain, q, L, conditions, X)
    assert deflection(model, step, X) == pytest.approx(exact, rel=1e-6, abs=1e-9 * np.abs(exact).max())
    assert model.supports.describe() == supports


def test_a_prescribed_end_rotation_bends_the_strand_as_the_beam_equation_says():
    L, strain, theta = 1.0, 0.001, 2e-5  # ½ θ² = 2e-10: the linear beam equation holds to 1e-7
    right = {"v": 0.0, "v'": theta, "w": 0.0, "w'": 0.0, "phi": 0.0}
    model = strand.StrandModel(STRAIGHT, L, n_elements=128, grading=0.0, supports=("clamped", right))
    step = model.solve(strain)
    exact = tensioned_beam(EA * strain, 0.0, L, [(0, "v", 0), (0, "v'", 0), (L, "v", 0), (L, "v'", theta)], X)
    assert deflection(model, step, X) == pytest.approx(exact, rel=1e-6, abs=1e-9 * np.abs(exact).max())
    # the moment the right support applies is the reaction on v' there: EI v''(L) of the beam
    conditions = [(0, "v", 0), (0, "v'", 0), (L, "v", 0), (L, "v'", theta)]
    curvature = tensioned_beam(EA * strain, 0.0, L, conditions, L, derivative=2)
    assert step.reactions["right"]["v'"] == pytest.approx(EI * curvature, rel=1e-5)


def test_twin_and_pickle_keep_the_supports():
    d = strand.preset("steel-9.5").damaged(1)
    model = strand.StrandModel(d, 0.4, n_elements=12, supports=("pinned", "pinned"))
    assert model.twin().supports == model.supports
    import pickle

    again = pickle.loads(pickle.dumps(model))
    assert again.supports == model.supports and again.mesh.p.tolist() == model.mesh.p.tolist()
    np.testing.assert_array_equal(again.solve(0.002).dofs, model.solve(0.002).dofs)


def test_small_transverse_load_converges_as_tightly_as_the_axial_pull():
    """−0.01 N/m beside a 25 kN pull: the default tolerance measures each group of equations
    against its own forces, so v is within 1e-8 of the solve to round-off, and the transverse
    equations' residual is a billionth of the load they carry (the old rule, 1e-9 of EA·ε for
    every equation, allowed 2.5e-5 N there: a thousandth of the load on a node)."""
    s = strand.preset("steel-9.5")
    q, strain = -0.01, 0.003
    model = strand.StrandModel(s, 1.0, n_elements=32, terms=[strand.TransverseLoad(qy=q)])
    default = model.solve(strain)
    tight = model.solve(strain, tol=1e-14)
    v, v0 = default.nodal["v"], tight.nodal["v"]
    assert np.max(np.abs(v - v0)) <= 1e-8 * np.max(np.abs(v0))
    R, _, _ = model.assemble(default.dofs)
    transverse = np.intersect1d(model.free, np.arange(model.offsets[1], model.offsets[2]))
    assert np.max(np.abs(R[transverse])) <= 1e-9 * abs(q) * model.length


# --- Newton options --------------------------------------------------------------------------------
def test_newton_options_reach_every_solve_and_the_callback_sees_each_iteration():
    d = strand.preset("steel-9.5").damaged(1)
    model = strand.StrandModel(d, 0.3, n_elements=12)
    seen = []
    step = model.solve(0.002, callback=lambda k, r, dx: seen.append((k, r, dx)), tol=1e-12)
    assert [k for k, _, _ in seen] == list(range(1, step.iterations + 1))
    assert [r for _, r, _ in seen] == step.history[1:]
    assert step.history[-1] < 1e-12
    curve = model.capacity_curve(n_steps=8, tol=1e-11, max_iter=30, line_search="residual")
    assert curve.ruptured and all(s.history[-1] < 1e-11 for s in curve.steps)
    assert curve.options == NewtonOptions(tol=1e-11, max_iter=30, line_search="residual")


def test_bad_options_and_a_raising_callback_are_named():
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=8)
    with pytest.raises(InputError, match="tol"):
        model.solve(0.001, tol=-1.0)
    with pytest.raises(InputError, match="line_search"):
        model.solve(0.001, line_search="sometimes")
    with pytest.raises(InputError, match="spam"):
        model.solve(0.001, spam=1)

    def boom(k, r, dx):
        raise RuntimeError("stop here")

    with pytest.raises(InputError, match="callback.*iteration 1.*stop here"):
        model.solve(0.001, callback=boom, tol=1e-14)


# --- supports and terms refused by name ----------------------------------------------------------
def test_bad_supports_and_terms_are_refused_by_name():
    s = strand.preset("steel-9.5")
    with pytest.raises(InputError, match="unknown dof 'theta'"):
        strand.StrandModel(s, 0.3, n_elements=4, supports=("clamped", {"theta": 0.0}))
    with pytest.raises(InputError, match="names no dof"):
        strand.StrandModel(s, 0.3, n_elements=4, supports=({}, "clamped"))
    with pytest.raises(InputError, match="axial load's dof"):
        strand.StrandModel(s, 0.3, n_elements=4, supports=("clamped", {"u": 0.0}))
    with pytest.raises(InputError, match="supports"):
        strand.StrandModel(s, 0.3, n_elements=4, supports="clamped")
    with pytest.raises(InputError, match="x"):  # a spring on a clamped node would do nothing
        strand.StrandModel(s, 0.3, n_elements=4, grading=0.0, terms=[strand.NodalSpring(0.0, 1e3)])

    class WrongShape(strand.Term):
        def contribute(self, U, step):
            return np.zeros(3), None, {}

    with pytest.raises(InputError, match="shape"):
        strand.StrandModel(s, 0.3, n_elements=4, terms=[WrongShape()]).solve(0.001)


# --- tangent diagnostics -----------------------------------------------------------------------------
class Cubic(strand.Term):
    """A cubic spring bed on v, ``q = −c v³``, with its tangent times ``factor`` (1: right)."""

    def __init__(self, c, factor=1.0):
        self.c, self.factor = c, factor

    def setup(self, model):
        self.fa = strand.FieldAssembly(model, [("v", 0)])

    def contribute(self, U, step):
        v = self.fa.interpolate(U)[0]
        return (
            self.fa.vector((self.c * v**3)[None]),
            self.fa.matrix((self.factor * 3 * self.c * v**2)[None, None]),
            {},
        )


def test_check_tangent_catches_a_wrong_tangent_and_passes_a_right_one():
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[Cubic(1e9), Cubic(1e9, 3.0)])
    U = model.uniform(0.001)
    U[model.free] += 1e-3 * np.random.default_rng(0).standard_normal(model.free.size)
    right, wrong = model.terms[-2:]
    assert check_tangent(right, model, U) < 1e-6
    assert check_tangent(wrong, model, U) == pytest.approx(2.0 / 3.0, rel=1e-3)  # |3K − K| / |3K|
    for term in model.terms[:-2]:  # the built-in physics
        assert check_tangent(term, model, U) < 1e-6


def test_a_wrong_tangent_converges_linearly_and_newton_names_it():
    load = strand.TransverseLoad(qy=2e3)
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[load, Cubic(1e12, 3.0)])
    with (
        pytest.warns(SlowConvergenceWarning, match=r"Cubic\(\) \(6\.7e-01\)"),
        pytest.warns(TangentWarning, match=r"Cubic\(\).*tangent/difference = 3\b"),  # the first solve's check
    ):
        model.solve(0.001, max_iter=200)
    with pytest.raises(ConvergenceError, match=r"tangents off by check_tangent: Cubic\(\) \(6\.7e-01\)"):
        model.solve(0.001, max_iter=20)
    right = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[load, Cubic(1e12)])
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error", SlowConvergenceWarning)
        step = right.solve(0.001, tol=1e-12)
    assert step.iterations < 15


# --- declarations: an unsymmetric linear term, a follower load ---------------------------------------
@pytest.mark.parametrize("coupling", [1e2, 1e4, 1e6])
def test_an_unsymmetric_linear_term_is_no_potential_and_converges(coupling):
    """A one-way coupling, the w-equation loaded by c·v: the tangent is not symmetric, so the term
    has no energy (taken for one, its ½ Uᵀ K U made energy minimisation fail from c = 1e4) and the
    model solves with Newton. The solution is checked on the equations assembled here: the plain
    model's residual plus the coupling matrix of scikit-fem's ``asm``."""
    from skfem import BilinearForm, asm

    @BilinearForm
    def one_way(u, v, w):
        return w.c * u * v

    term = strand.FieldTerm(tangent={("w", "v"): one_way}, c=coupling)
    load = strand.TransverseLoad(qy=1.0)
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[load, term])
    assert not model.bound(term).symmetric and not model.bound(term).potential
    step = model.solve(0.001, tol=1e-12)
    plain = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[load])
    R, _, _ = plain.assemble(step.dofs)
    C = asm(one_way, model.bases["v"], model.bases["w"], c=coupling)
    R[model.offsets[2] : model.offsets[3]] += C @ model.split(step.dofs)["v"]
    assert np.max(np.abs(R[model.free])) <= 1e-9 * 1.0  # the load is 1 N/m on a 1 m strand
    # w answers c v alone: pushed against v by the coupling
    assert np.max(np.abs(step.nodal["w"])) > 0 and np.all(step.nodal["w"] * step.nodal["v"] <= 0)


def test_a_follower_force_has_an_unsymmetric_tangent_that_checks():
    term = strand.FollowerForce(0.6, 50.0, direction=(0.0, 1.0, 0.0))
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[term])
    step = model.solve(0.001, tol=1e-12)
    bound = model.bound(term)
    assert not bound.symmetric
    assert check_tangent(term, model, step.dofs) < 1e-6
    R, K = model.term_contribution(term, step.dofs)
    assert abs(K - K.T).max() > 1e-6 * abs(K).max()
    # the force turned with the axis: perpendicular to the deformed tangent at x = 0.6
    F, _ = bound.force(step.dofs)
    a = bound._slope @ step.dofs + np.array([1.0, 0.0, 0.0])
    assert abs(F @ a) <= 1e-12 * np.linalg.norm(F) * np.linalg.norm(a) and np.linalg.norm(F) == pytest.approx(
        50.0
    )


# --- loads anywhere ------------------------------------------------------------------------------------
def test_a_point_force_between_nodes_matches_the_beam_with_a_point_load():
    L, P, a, strain = 1.0, 0.05, 0.37, 0.001  # 0.37 m: no node of the 128-element mesh
    model = strand.StrandModel(STRAIGHT, L, n_elements=128, grading=0.0, terms=[strand.PointForce(a, fy=P)])
    assert not np.any(np.isclose(model.mesh.p[0], a))
    step = model.solve(strain, tol=1e-12)
    # the clamped tensioned beam with a point load: the Green's function, from two pieces joined at
    # a by continuity of v, v', v'' and a jump P of the transverse force
    N = EA * strain
    k = np.sqrt(N / EI)
    basis = lambda x: np.array([np.ones_like(x), x, np.cosh(k * x), np.sinh(k * x)])  # noqa: E731
    d1 = lambda x: np.array([0 * x, 1 + 0 * x, k * np.sinh(k * x), k * np.cosh(k * x)])  # noqa: E731
    d2 = lambda x: np.array([0 * x, 0 * x, k**2 * np.cosh(k * x), k**2 * np.sinh(k * x)])  # noqa: E731
    d3 = lambda x: np.array([0 * x, 0 * x, k**3 * np.sinh(k * x), k**3 * np.cosh(k * x)])  # noqa: E731
    z = np.zeros(4)
    M = np.array(
        [
            [*basis(0.0), *z],
            [*d1(0.0), *z],
            [*z, *basis(L)],
            [*z, *d1(L)],
            [*basis(a), *-basis(a)],
            [*d1(a), *-d1(a)],
            [*d2(a), *-d2(a)],
            [*(EI * d3(a) - N * d1(a)), *-(EI * d3(a) - N * d1(a))],
        ]
    )
    c = np.linalg.solve(M, np.array([0, 0, 0, 0, 0, 0, 0, -P]))  # V(a-) - V(a+) = -P
    x = np.array([0.2, 0.37, 0.6, 0.9])
    exact = np.where(x < a, c[:4] @ basis(x), c[4:] @ basis(x))
    # the FE error is that of the clamps' boundary layers (width sqrt(EI/N) = 0.07 m): 3.6e-6 at x = 0.9
    assert deflection(model, step, x) == pytest.approx(exact, rel=1e-5)


def test_a_point_moment_anywhere_equals_the_work_of_its_rotation():
    L = 1.0
    terms = [strand.PointMoment(0.43, mz=2.0), strand.PointMoment(0.43, my=-1.0, mx=0.5)]
    model = strand.StrandModel(STRAIGHT, L, n_elements=16, grading=0.0, terms=terms)
    f = sum(model.bound(t)._f for t in terms)
    # the virtual work of the moments along a field that rotates rigidly: δv' = 1, δw' = 1, δφ = 1
    U = np.zeros(model.assembly.N)
    parts = model.split(U)
    x = {n: model.bases[n].doflocs[0] for n in ("v", "w", "phi")}
    for name in ("v", "w"):
        nodal = model.bases[name].nodal_dofs
        parts[name][nodal[0]] = model.mesh.p[0]  # value = x, slope = 1
        parts[name][nodal[1]] = 1.0
    parts["phi"][:] = 1.0
    assert f @ U == pytest.approx(2.0 * 1.0 - (-1.0) * 1.0 + 0.5 * 1.0, rel=1e-12) and x


# --- contact and non-smooth terms --------------------------------------------------------------------
@pytest.mark.parametrize("k", [1e8, 1e10, 1e12])
def test_a_rigid_cylinder_converges_from_the_straight_start_quadratically(k):
    """A sheave of radius 0.5 m whose top lies 1 mm above the straight strand at mid-span lifts it:
    the model's own Newton converges from the straight start (semismooth steps), quadratically at
    the end; the lift balances the clamps' reactions, and the solution is that of a plain
    semismooth Newton written here on ``model.assemble``."""
    L, strain, r = 1.0, 0.001, 0.5
    cylinder = strand.RigidCylinder((0.5 * L, -r + 1e-3), r, k)
    model = strand.StrandModel(STRAIGHT, L, n_elements=64, grading=0.0, terms=[cylinder])
    step = model.solve(strain)
    h = step.history
    assert h[-1] < 1e-9 and step.iterations <= 30
    # quadratic at the end: once the active set is found, r_{k+1} <= C r_k² (above round-off)
    tail = [(a, b) for a, b in zip(h, h[1:], strict=False) if a < 0.1 and b > 1e-11]
    assert tail and all(b <= 100 * a * a for a, b in tail[-2:])
    pressure = step.outputs["contact_pressure"][1]  # (ne, nq), along the cylinder's normal
    parts = model.split(step.dofs)
    u, v = model.bases["u"].interpolate(parts["u"]), model.bases["v"].interpolate(parts["v"])
    x = np.asarray(model.bases["u"].global_coordinates())[0]
    normal_y = (v - cylinder.center[1]) / np.hypot(x + u - cylinder.center[0], v - cylinder.center[1])
    lift = float(np.sum(pressure * normal_y * model.bases["v"].dx))
    assert lift > 0
    assert step.reactions["left"]["v"] + step.reactions["right"]["v"] == pytest.approx(-lift, rel=1e-6)
    # an independent semismooth Newton: full steps on model.assemble from the same start
    U = model.uniform(strain)
    for _ in range(80):
        R, K, _ = model.assemble(U)
        if np.max(np.abs(R[model.free])) < 1e-10 * max(1.0, lift):
            break
        U[model.free] += sp.linalg.spsolve(K[model.free][:, model.free].tocsc(), -R[model.free])
    np.testing.assert_allclose(step.nodal["v"], model.nodal_values(U)["v"], rtol=1e-6, atol=1e-9 * 1e-3)


@pytest.mark.parametrize("k", [1e8, 1e10, 1e12])
def test_a_tensionless_foundation_holds_only_where_the_strand_presses(k):
    """A bed 0.2 mm below the straight strand, a downward load on its middle third: the strand
    sinks onto the bed there and stays clear of it towards the clamps, which the bed never pulls."""
    L, strain, q = 1.0, 0.0005, 2e3

    def middle(x):
        return -q * ((x > L / 3) & (x < 2 * L / 3))

    load = strand.TransverseLoad(qy=middle)
    bed = strand.TensionlessFoundation(k, surface=-2e-4)
    model = strand.StrandModel(STRAIGHT, L, n_elements=64, grading=0.0, terms=[load, bed])
    step = model.solve(strain)
    assert step.history[-1] < 1e-9
    gap, reaction = step.outputs["gap"][1], step.outputs["reaction"][1]
    assert np.all(reaction >= 0) and np.all(reaction[gap >= 0] == 0)
    assert np.any(gap < 0) and np.any(gap > 0)  # on the bed under the load, clear of it elsewhere
    np.testing.assert_allclose(reaction[gap < 0], -k * gap[gap < 0], rtol=1e-12)  # a bed of modulus k
    held = float(np.sum(reaction * model.bases["v"].dx))
    # vertical balance: the bed and the clamps hold the load (the reactions are the supports' forces;
    # the load is its function integrated by the model's quadrature, a step function between nodes)
    dx = model.bases["v"].dx
    applied = -float(np.sum(middle(model.x) * dx))
    assert held + step.reactions["left"]["v"] + step.reactions["right"]["v"] == pytest.approx(
        applied, rel=1e-9
    )


def test_term_outputs_and_user_fields_reach_the_vtk_file(tmp_path):
    import meshio

    cylinder = strand.RigidCylinder((0.5, -0.5 + 1e-3), 0.5, 1e10)
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=32, grading=0.0, terms=[cylinder])
    curve = model.capacity_curve(max_strain=0.002, n_steps=4)

    def fields(step):  # the user's own arrays: at the nodes, and per element
        return {"lift_mm": 1e3 * step.nodal["v"]}, {"element_index": np.arange(32.0)}

    curve.to_vtk(tmp_path / "strand.pvd", fields=fields)
    last = meshio.read(sorted(tmp_path.glob("strand_*.vtu"))[-1])
    step = curve.steps[-1]
    assert {"contact_pressure", "gap", "lift_mm"} <= set(last.point_data)
    # the quadrature outputs, projected onto the nodes: the largest pressure where the cylinder is
    pressure = last.point_data["contact_pressure"]
    assert np.max(pressure) > 0 and abs(last.points[np.argmax(pressure), 0] - 0.5) < 0.1
    np.testing.assert_array_equal(last.point_data["lift_mm"], 1e3 * step.nodal["v"])
    np.testing.assert_array_equal(last.cell_data["element_index"][0], np.arange(32.0))
    with pytest.raises(InputError, match="bad"):
        curve.step_mesh(-1, fields=lambda s: ({"bad": np.zeros(5)}, None))


def test_p3_axial_element_solves_and_agrees_with_p2():
    d = strand.preset("steel-9.5").damaged(1)
    p2 = strand.StrandModel(d, 0.4, n_elements=24).solve(0.003, tol=1e-12)
    p3 = strand.StrandModel(d, 0.4, n_elements=24, element="P3").solve(0.003, tol=1e-12)
    assert np.all(np.isfinite(p3.dofs)) and p3.force == pytest.approx(p2.force, rel=1e-5)
    with pytest.raises(InputError, match="element"):
        strand.StrandModel(d, 0.4, n_elements=8, element="P7")


def test_a_tie_between_distant_nodes_moves_the_solve_to_sparse():
    """A spring tying v at x = 0.25 m to v at 0.75 m (a multi-point constraint) breaks the band:
    the solve still converges, to the same answer as a dense solve of the model's own system."""

    class Tie(strand.Term):
        def setup(self, model):
            nodes = model.mesh.p[0]
            i = [
                model.offsets[1] + model.bases["v"].nodal_dofs[0][np.argmin(abs(nodes - x))]
                for x in (0.25, 0.75)
            ]
            N = model.assembly.N
            self.K = sp.csr_matrix(
                ([1e4, -1e4, -1e4, 1e4], ([i[0], i[0], i[1], i[1]], [i[0], i[1], i[0], i[1]])), shape=(N, N)
            )

        potential = True

        def contribute(self, U, step):
            return self.K @ U, self.K, {}

        def energy(self, U, step):
            return 0.5 * float(U @ (self.K @ U))

    load = strand.TransverseLoad(qy=lambda x: 100.0 * (x < 0.5))
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[load, Tie()])
    step = model.solve(0.001, tol=1e-12)
    assert not model._system.is_banded
    R, K, _ = model.assemble(step.dofs)
    assert np.max(np.abs(R[model.free])) < 1e-9 * 100.0
    v = step.nodal["v"]
    nodes = model.mesh.p[0]
    assert np.interp(0.25, nodes, v) != pytest.approx(np.interp(0.75, nodes, v))
