"""The axial load as data: an imposed strain, an axial force, or nothing; "free" means free.

Closed forms: a cantilever under a uniform load q, ``v(L) = q L⁴ / 8 EI``; the same cantilever
pulled by an axial force P, the solution of ``EI v'''' − P v'' = q`` with ``v = v' = 0`` at
the clamp, ``EI v'' = 0`` and ``EI v''' − P v' = 0`` at the tip (a dead axial load: no transverse
component), written here in its exponential basis.
"""

import numpy as np
import pytest

from skcable import strand
from skcable.errors import InputError

# a strand whose wires run parallel to its axis: a prismatic beam of known EI
STRAIGHT = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=1e-9),), strand.material("steel"))
EA, EI = STRAIGHT.section().EA, STRAIGHT.section().EI_stick[0]
L = 1.0


def _tip(model, step):
    return float((model.bases["v"].probes(np.atleast_2d([L])) @ model.split(step.dofs)["v"])[0])


def tensioned_cantilever(P, q, x):
    """v(x) of EI v'''' − P v'' = q, v(0) = v'(0) = 0, v''(L) = 0, EI v'''(L) − P v'(L) = 0."""
    k = np.sqrt(P / EI)
    # v = a + b x + c e^{k(x−L)} + d e^{−kx} − q x² / 2P
    rows = [
        [1.0, 0.0, np.exp(-k * L), 1.0],  # v(0)
        [0.0, 1.0, k * np.exp(-k * L), -k],  # v'(0)
        [0.0, 0.0, k**2, k**2 * np.exp(-k * L)],  # v''(L)
        [0.0, -P, 0.0, 0.0],  # EI v'''(L) − P v'(L): the exponentials cancel
    ]
    rhs = [0.0, 0.0, q / P, -P * q * L / P]
    a, b, c, d = np.linalg.solve(np.array(rows), np.array(rhs))
    return a + b * x + c * np.exp(k * (x - L)) + d * np.exp(-k * x) - q * x**2 / (2 * P)


def test_a_clamped_free_strand_without_axial_load_is_a_cantilever():
    q = 0.01
    model = strand.StrandModel(
        STRAIGHT, L, n_elements=64, grading=0.0, supports=("clamped", "free"), axial="none",
        terms=[strand.TransverseLoad(qy=q)],
    )  # fmt: skip
    step = model.solve(tol=1e-12)
    assert _tip(model, step) == pytest.approx(q * L**4 / (8 * EI), rel=1e-6)
    # nothing holds it axially: no membrane force (a held tip would see EA ½ v'(L)², 7e-3 N here;
    # the P2 axial field leaves a thousandth of it pointwise, orthogonal to the constants)
    held = EA * 0.5 * (q * L**3 / (6 * EI)) ** 2
    assert np.max(np.abs(step.axial_force)) < 1e-3 * held
    assert abs(np.sum(step.axial_force * step.layout.dx)) < 1e-9 * held * L
    assert step.force == 0.0 and "u" not in step.reactions["right"]
    # the clamp carries the load: shear q L, moment q L² / 2, and its axial reaction is listed
    left = step.reactions["left"]
    assert -left["v"] == pytest.approx(q * L, rel=1e-9)
    assert abs(left["v'"]) == pytest.approx(q * L**2 / 2, rel=1e-9)
    assert abs(left["u"]) < 1e-9 * q * L


@pytest.mark.parametrize("P", [10.0, 1e3])
def test_a_clamped_free_strand_pulled_by_a_force_is_the_tensioned_cantilever(P):
    q = 0.01
    model = strand.StrandModel(
        STRAIGHT, L, n_elements=128, grading=0.0, supports=("clamped", "free"), axial="force",
        terms=[strand.TransverseLoad(qy=q)],
    )  # fmt: skip
    step = model.solve(force=P, tol=1e-10)
    x = np.array([0.25, 0.5, 0.75, 1.0])
    v = model.bases["v"].probes(np.atleast_2d(x)) @ model.split(step.dofs)["v"]
    exact = tensioned_cantilever(P, q, x)
    assert v == pytest.approx(exact, rel=1e-6)
    # the force is the load: the axial force is P along the strand, the clamp reacts −P
    assert step.force == P
    np.testing.assert_allclose(step.axial_force, P, rtol=1e-6)
    assert step.reactions["left"]["u"] == pytest.approx(-P, rel=1e-9)
    assert step.strain == pytest.approx(P / EA, rel=1e-3)  # the bent axis shortens a little


def test_the_imposed_strains_reaction_is_listed_with_the_others():
    s = strand.preset("steel-9.5").damaged(1)
    step = strand.StrandModel(s, 0.5, n_elements=16).solve(0.003)
    assert step.reactions["right"]["u"] == step.force
    assert step.reactions["left"]["u"] == pytest.approx(-step.force, rel=1e-9)


def test_a_capacity_curve_driven_by_force_follows_the_strain_driven_one():
    """The same damaged strand pulled by strain and by force: at each force the mean strain of
    the force-driven curve is the strain-driven curve's (interpolated between its steps, which the
    fine strain schedule below makes accurate to 1e-4); in the elastic range both are F = K ε."""
    s = strand.preset("steel-9.5").damaged(1)
    by_strain = strand.StrandModel(s, 0.5, n_elements=16).capacity_curve(max_strain=0.004, n_steps=160)
    top = 0.95 * float(by_strain.force[-1])
    model = strand.StrandModel(s, 0.5, n_elements=16, axial="force")
    by_force = model.capacity_curve(n_steps=8, max_force=top)
    assert len(by_force.steps) == 8 and by_force.force[-1] == pytest.approx(top, rel=1e-12)
    expected = np.interp(by_force.force, by_strain.force, by_strain.strain)
    np.testing.assert_allclose(by_force.strain, expected, rtol=1e-4, atol=0)
    for step in by_force.steps:  # each step is the equilibrium at its force
        R = model.assemble(step.dofs, step.state, force=step.force)[0]
        assert np.max(np.abs(R[model.free])) < 1e-8 * step.force


def test_loads_that_do_not_fit_the_model_are_refused_by_name():
    s = strand.preset("steel-9.5")
    with pytest.raises(InputError, match="supports.*leaves u\\(L\\) free.*axial='force'"):
        strand.StrandModel(s, 0.3, n_elements=4, supports=("clamped", "free"))
    with pytest.raises(InputError, match="supports.*must hold u"):
        strand.StrandModel(s, 0.3, n_elements=4, supports=("free", "clamped"), axial="force")
    with pytest.raises(InputError, match="axial"):
        strand.StrandModel(s, 0.3, n_elements=4, axial="pressure")
    force = strand.StrandModel(s, 0.3, n_elements=4, axial="force")
    with pytest.raises(InputError, match="strain.*solve\\(force="):
        force.solve(0.001)
    with pytest.raises(InputError, match="force"):
        force.solve()
    with pytest.raises(InputError, match="max_force"):
        force.capacity_curve()
    with pytest.raises(InputError, match="max_strain"):
        force.capacity_curve(0.01, max_force=1e3)
    none = strand.StrandModel(s, 0.3, n_elements=4, supports=("clamped", "free"), axial="none")
    with pytest.raises(InputError, match="strain"):
        none.solve(0.001)
    with pytest.raises(InputError, match="model"):
        none.capacity_curve()
    with pytest.raises(InputError, match="max_force"):
        strand.StrandModel(s, 0.3, n_elements=4).capacity_curve(max_force=1e3)
    with pytest.raises(InputError, match="axial"):
        strand.StrandModel(s.damaged(1), 0.3, n_elements=4, damage_load="sinusoidal", axial="force")


def test_the_load_survives_the_twin_and_pickle():
    import pickle

    d = strand.preset("steel-9.5").damaged(1)
    model = strand.StrandModel(d, 0.4, n_elements=12, axial="force")
    assert model.twin().axial == "force" and model.twin().supports == model.supports
    again = pickle.loads(pickle.dumps(model))
    assert again.axial == "force"
    np.testing.assert_array_equal(again.solve(force=2e4).dofs, model.solve(force=2e4).dofs)
    assert model.supports.describe() == ("clamped", "clamped")
