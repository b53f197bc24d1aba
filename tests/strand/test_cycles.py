"""FE loops: a strand whose layers slip with history (`StageSlip`), bent back and forth by an end
rotation or an end moved across its axis, traces a hysteresis loop step by step. Its loop energy
is checked against the balance of energy (the friction work its stages did) and against Masing's
rules for a structure, from its own monotonic backbone.

**Masing's rules for a structure** (the statement the checks use). Take a structure whose only
nonlinearity is its Coulomb stages (at every point, elastic elements of stiffness B_k that slip
at ±M_k, in parallel with an elastic part), loaded from the virgin state by one displacement q
such that every point's curvature grows monotonically along the first loading R_b(q). After a
reversal at (q_r, R_r) every stage has a range of 2M_k before it slips the other way (those that
slipped sit at ±M_k; those that did not slip do not reach their limit again within the branch,
|q − q_r| <= 2 q_r), so the increment problem is the virgin problem with every slip limit
doubled. That problem is homogeneous of degree one in (displacements, limits): its solution is
twice the virgin solution at half the displacement, so

    R(q) = R_r − 2 (R_b((q_r − q)/2) − R_b(0)),   every slip increment twice the backbone's,

and a cycle ±q_a closes (the branch up from −q_a ends at the state of the first arrival at +q_a)
and dissipates

    W = ∮ R dq = 8 ∫_0^{q_a} (R_b − R_b(0)) dq − 4 q_a (R_b(q_a) − R_b(0)) = 4 D_b(q_a),

with D_b(q_a) the friction work done along the backbone up to q_a. The strand element is such a
structure up to its moderate-rotation kinematics (ε_a = u' + ½v'²), which stiffen it
conservatively by a relative amount of the order of the end slope squared: that enters Masing's
integral (the integral of a nonlinear elastic backbone is not ½ q R) but neither the friction work
nor the balance of energy. At the slopes used here (6 mrad; 2 mm across 0.3 m) it is about
2e-7 of W, below the 1e-6 the checks ask for.

Measured (these models, `bending_cycles(exact=True)`): the loop energy equals the summed friction
work to about 5e-9, and Masing's value of the backbone to about 2e-7.
"""

import numpy as np
import pytest
from scipy.integrate import trapezoid

from skcable import strand
from skcable.errors import InputError, PlausibilityWarning
from skcable.fe import check_tangent

P = 20e3  # N: the axial force of the 1x7 and the tension of its law


def model_of(name="steel-9.5", tension=P, mu=0.5, length=0.3, n_elements=32):
    s = strand.preset(name)
    law = strand.LayerSlipLaw(s.section(), mu=mu, tension=tension)
    # both ends clamped, the axial force at x = L (u(L) free): its end turned or moved by `prescribed`
    model = strand.StrandModel(s, length, n_elements=n_elements, slip=strand.StageSlip(law), axial="force")
    return model, law


@pytest.fixture(scope="module")
def steel():
    return model_of()


@pytest.fixture(scope="module")
def rotated(steel):
    model, _ = steel
    return strand.bending_cycles(model, 0.006, force=P, n_steps=2, cycles=2)


@pytest.fixture(scope="module")
def moved(steel):
    model, _ = steel
    return strand.bending_cycles(model, 2e-3, dof="v", force=P, n_steps=2, cycles=1)


def masing(q, R):
    """Masing's energy per cycle of a backbone given by its vertices (the structural statement of
    the module docstring), the integral by the trapezoidal rule over them (exact: the backbone is
    linear between its vertices, which are every slip event)."""
    q, R = q - q[0], R - R[0]
    return 8.0 * trapezoid(R, q) - 4.0 * q[-1] * R[-1]


def loop_energy(q, R):
    """∮ R dq of a closed polygon by the shoelace formula, ∮ R dq = −½ ∮ (q dR − R dq): its area,
    positive for a loop run clockwise in the (q, R) plane (a dissipating one)."""
    return -0.5 * (np.dot(q[:-1], R[1:]) - np.dot(q[1:], R[:-1]))


@pytest.mark.parametrize("run", ["rotated", "moved"])
def test_loop_energy_is_masings_and_the_friction_work(request, run):
    cycles = request.getfixturevalue(run)
    assert cycles.inexact == 0 and cycles.failure is None
    q_b, R_b = cycles.backbone
    assert np.all(np.diff(q_b) > 0) and q_b[-1] == cycles.amplitude
    W_masing = masing(q_b, R_b)
    for c in range(cycles.cycles):
        q, R = cycles.loop(c)
        W = loop_energy(q, R)
        assert W > 0  # the support puts energy in: the strand dissipates it
        assert W == pytest.approx(cycles.energy_per_cycle[c], rel=1e-12)
        assert W == pytest.approx(W_masing, rel=1e-6)
        assert W == pytest.approx(cycles.friction_per_cycle[c], rel=1e-6)
    # every slip of a half cycle twice the backbone's: the cycle's friction is 4 D_b
    assert cycles.friction_per_cycle == pytest.approx(4 * np.sum(cycles.work[cycles.branch == 0]), rel=1e-9)


@pytest.mark.parametrize("run", ["rotated", "moved"])
def test_every_branch_is_masings_of_the_backbone(request, run):
    """R(q) = R_a − 2 (R_b((a − q)/2) − R_b(0)) down, and its mirror up, at every vertex (R_b
    between the backbone's vertices by linear interpolation: exact, they are every event)."""
    cycles = request.getfixturevalue(run)
    q_b, R_b = cycles.backbone
    a, R_a = q_b[-1], R_b[-1]
    q, R = cycles.loop(0)
    down = np.arange(len(q)) <= int(np.argmin(q))
    half = np.where(down, a - q, q + a) / 2
    expected = np.where(down, R_a, -R_a) - np.where(down, 2, -2) * (np.interp(half, q_b, R_b) - R_b[0])
    np.testing.assert_allclose(R, expected, rtol=0, atol=1e-6 * abs(R_a))


@pytest.mark.parametrize("run", ["rotated", "moved"])
def test_the_backbone_loads_every_slipping_point_monotonically(request, run):
    """The premise of the structural statement: where a stage slips on the backbone, the point's
    curvature grows all along it (no stage stops slipping while the drive goes on; at the
    schedule's points, the curvature of every point that slipped grows)."""
    cycles = request.getfixturevalue(run)
    assert cycles.unloaded[0] == 0
    on_backbone = [s for s, v in zip(cycles.steps, cycles.step_vertex, strict=True) if cycles.branch[v] == 0]
    slipped = np.any(on_backbone[-1].state[0] != 0.0, axis=1)  # (axis, element, point)
    assert slipped.any()
    size = np.array([np.abs(s.curvature)[slipped] for s in on_backbone])
    assert np.all(np.diff(size, axis=0) > 0)


def test_the_second_cycle_repeats_the_first(rotated):
    (q0, R0), (q1, R1) = rotated.loop(0), rotated.loop(1)
    assert len(q0) == len(q1)
    np.testing.assert_allclose(q1, q0, rtol=0, atol=1e-9 * rotated.amplitude)
    np.testing.assert_allclose(R1, R0, rtol=0, atol=1e-9 * np.max(np.abs(R0)))
    W = rotated.energy_per_cycle
    assert W[1] == pytest.approx(W[0], rel=1e-9)
    assert rotated.friction_per_cycle[1] == pytest.approx(rotated.friction_per_cycle[0], rel=1e-12)


def test_a_1x7_layer_law_bends_as_cardous_law(steel, rotated):
    """With one helical layer the layer law is Cardou's single knee: on the backbone the model with
    history gives the end moment of the stateless `AxisSlip` at the same end rotations (its knees at
    each point's own axial strain, equal here to 1e-6)."""
    model, law = steel
    axis = strand.StrandModel(model.strand, model.length, n_elements=32, slip="axis", mu=0.5, axial="force")
    for i in (1, 2):
        vertex = rotated.step_vertex[i]
        q = rotated.drive[vertex]
        step = axis.solve(force=P, prescribed={"right": {"v'": q}})
        assert step.reactions["right"]["v'"] == pytest.approx(rotated.reaction[vertex], rel=1e-5)


def test_a_multilayer_conductor_slips_layer_by_layer():
    """ACSR Drake (three helical layers, a stage each) at 28 kN, μ = 0.3, its end turned ±4 mrad:
    every layer slips at the clamp, and the loop energy is the friction work and Masing's value of
    the backbone to 1e-6."""
    model, law = model_of("acsr-drake", 28e3, mu=0.3, length=0.6, n_elements=24)
    cycles = strand.bending_cycles(model, 0.004, force=28e3, n_steps=1, cycles=1)
    assert cycles.inexact == 0 and cycles.unloaded[0] == 0
    slip = cycles.steps[1].state[0]  # the backbone's end: the slip curvatures (2, layers, ne, nq)
    assert np.all(np.any(slip != 0.0, axis=(0, 2, 3)))
    W = loop_energy(*cycles.loop(0))
    assert W == pytest.approx(cycles.friction_per_cycle[0], rel=1e-6)
    assert W == pytest.approx(masing(*cycles.backbone), rel=1e-6)


def test_steps_that_step_over_events_miss_the_loop(steel, rotated):
    """Without ``exact`` the steps are the schedule's: the trapezoidal rule steps over the kinks
    and the loop's area falls short of the friction work, which stays exact."""
    model, _ = steel
    coarse = strand.bending_cycles(model, 0.006, force=P, n_steps=2, cycles=1, exact=False)
    assert coarse.friction_per_cycle[0] == pytest.approx(rotated.friction_per_cycle[0], rel=1e-9)
    assert abs(coarse.energy_per_cycle[0] / coarse.friction_per_cycle[0] - 1) > 1e-3


def test_the_law_is_the_stages_return_mapping(steel, rotated):
    model, law = steel
    slip = strand.StageSlip(law)
    rng = np.random.default_rng(3)
    kappa = rng.normal(scale=0.1, size=(2, 5, 4))
    state = rng.normal(scale=0.05, size=(2, 1, 5, 4))
    M, dM, dM_de = slip.moment(kappa, None, state)
    response = law.update(kappa, state)
    EI_min = law.EI_min[:, None, None]
    np.testing.assert_allclose(M + EI_min * kappa, response.moment, rtol=1e-14)
    np.testing.assert_allclose(dM + EI_min, response.tangent, rtol=1e-14)
    assert not dM_de.any()
    # its potential at a frozen state: dψ/dκ = M_c by central differences
    h = 1e-7
    fd = (slip.energy(kappa + h, None, state) - slip.energy(kappa - h, None, state)) / (2 * h)
    np.testing.assert_allclose(fd, M, rtol=1e-6, atol=1e-8)
    # the friction work of a step: Σ M_k |Δκ_p|
    new = slip.next_state(kappa, None, state)
    np.testing.assert_allclose(slip.work(state, new), response.work, rtol=1e-14)
    # the term's tangent in the model, at a slipping state of the loop
    before, step = rotated.steps[3], rotated.steps[4]  # 3 mrad and 0 on the way down
    assert np.any(slip.next_state(step.curvature, None, before.state[0]) != before.state[0])  # it slips
    assert check_tangent(model.terms[0], model, step.dofs, state=before.state[0]) < 1e-6


def test_refusals(steel):
    model, law = steel
    state = model.initial_state()
    bad = (np.full_like(state[0], np.nan), *state[1:])
    with pytest.raises(InputError, match="^state: .*not finite"):
        model.solve(force=P, state=bad)
    with pytest.raises(InputError, match="^state: .*shape"):
        model.solve(force=P, state=(state[0][:, :, :3], *state[1:]))
    with pytest.raises(InputError, match="^model: .*no history"):  # a law without history traces no loop
        axis = strand.StrandModel(model.strand, 0.3, n_elements=16, slip="axis", axial="force")
        strand.bending_cycles(axis, 0.006, force=P)
    for amplitude in (0.0, -1e-3, float("nan"), 0.3, True):  # 0.3 rad: beyond the moderate rotations
        with pytest.raises(InputError, match="^amplitude: "):
            strand.bending_cycles(model, amplitude, force=P)
    with pytest.raises(InputError, match="^dof: "):
        strand.bending_cycles(model, 0.006, dof="u", force=P)
    with pytest.raises(InputError, match="^cycles: "):
        strand.bending_cycles(model, 0.006, cycles=0, force=P)
    with pytest.raises(InputError, match="^prescribed: .*not held"):
        model.solve(force=P, prescribed={"left": {"u'": 0.0}})
    with pytest.raises(InputError, match="^prescribed: "):
        model.solve(force=P, prescribed={"right": {"v'": 0.5}})
    with pytest.warns(PlausibilityWarning, match="^force: .*not the tension"):  # knees of another tension
        strand.bending_cycles(model, 0.001, force=0.8 * P, n_steps=1, cycles=1)
    with pytest.raises(InputError, match="^law: "):
        strand.StageSlip(strand.BendingLaw(model.strand.section(), mu=0.5, axial_strain=0.002))
    drake = strand.LayerSlipLaw(strand.preset("acsr-drake").section(), mu=0.5, tension=28e3)
    with pytest.raises(InputError, match="^slip: .*not the model's section"):  # a law of another strand
        strand.StrandModel(model.strand, 0.3, slip=strand.StageSlip(drake))
    with pytest.raises(InputError, match="^slip: .*single helical layer"):
        strand.StrandModel(strand.preset("acsr-drake"), 0.3, slip="axis")
