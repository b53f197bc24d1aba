"""Multi-material strands (a material per layer: ACSR's steel core under aluminium layers).

Values come from closed forms written here from the wire dimensions (Σ E_i A_i cos³α_i, the
stick inertia of evenly spaced wires Σ n E A cos³α R²/2 + Σ E I_w cos α), from the single-material
strand (a strand of two identical materials must give the same numbers), and from statics (the
FE axial force of an intact strand is EA ε).
"""

from dataclasses import replace
from math import atan, cos, pi

import numpy as np
import pytest

from skcable import strand
from skcable.errors import InputError

STEEL, ALUMINIUM = strand.material("steel"), strand.material("aluminium")
# ASTM B232 Drake 26/7: steel 3.454 mm, aluminium 4.442 mm; the preset's lay ratios 19, 13, 11
DS, DA = 3.454e-3, 4.442e-3


def _drake_by_hand():
    """(E, A, I_w, n, R, lay angle) per layer, core first, from the dimensions alone."""
    rows, outside, radius, previous = [(STEEL.E_e, DS, 1, 0.0, 0.0)], 3 * DS, 0.0, DS
    for k, (n, d, E, ratio) in enumerate([(6, DS, STEEL.E_e, 19.0), (10, DA, ALUMINIUM.E_e, 13.0),
                                          (16, DA, ALUMINIUM.E_e, 11.0)]):  # fmt: skip
        outside = 3 * DS if k == 0 else outside + 2 * d
        radius += (previous + d) / 2
        previous = d
        rows.append((E, d, n, radius, atan(2 * pi * radius / (ratio * outside))))
    return [(E, pi * d**2 / 4, pi * d**4 / 64, n, R, a) for E, d, n, R, a in rows]


def _twin_of_one_material(s):
    """The same strand whose core and every layer have their own copy of the material
    (identical law, another name: a separate group in every per-material evaluation)."""
    layers = tuple(replace(layer, material=replace(s.material, name=f"copy {k}")) for k, layer in
                   enumerate(s.layers, 1))  # fmt: skip
    return replace(s, layers=layers, core_material=replace(s.material, name="core copy"))


@pytest.mark.parametrize("damage", [0, 2])
def test_a_strand_of_identical_materials_equals_the_single_material_strand(damage):
    one = strand.preset("steel-9.5").damaged(damage)
    many = _twin_of_one_material(one)
    assert len(many.materials) == 2 and len(one.materials) == 1
    a, b = one.section(), many.section()
    for name in ("EA", "EI_stick", "EI_slip", "centroid", "torsional_stiffness", "axial_torsion_coupling"):
        np.testing.assert_allclose(getattr(b, name), getattr(a, name), rtol=1e-12, atol=0, err_msg=name)
    strains = np.array([0.001, 0.004, 0.03])
    np.testing.assert_allclose(
        strand.critical_curvature(b, 0.5, strains), strand.critical_curvature(a, 0.5, strains), rtol=1e-12
    )
    fa = strand.StrandModel(one, 0.2, n_elements=8).solve(0.006)
    fb = strand.StrandModel(many, 0.2, n_elements=8).solve(0.006)
    assert fb.force == pytest.approx(fa.force, rel=1e-12)
    np.testing.assert_allclose(fb.wire_stress, fa.wire_stress, rtol=1e-12, atol=1e-3)
    np.testing.assert_allclose(
        strand.axial_force(many, strains), strand.axial_force(one, strains), rtol=1e-12
    )


def test_acsr_section_EA_and_stick_EI_equal_the_closed_forms():
    drake = strand.preset("acsr-drake")
    rows = _drake_by_hand()
    EA = sum(E * n * A * cos(a) ** 3 for E, A, _, n, _, a in rows)
    # n >= 3 wires evenly spaced on radius R: Σ y² = n R²/2 about any diameter
    EI_stick = sum(E * n * (A * cos(a) ** 3 * R**2 / 2 + I * cos(a)) for E, A, I, n, R, a in rows)
    EI_slip = sum(E * n * I * cos(a) for E, A, I, n, R, a in rows)
    section = drake.section()
    assert section.EA == pytest.approx(EA, rel=1e-12)
    np.testing.assert_allclose(section.EI_stick, EI_stick, rtol=1e-12)
    np.testing.assert_allclose(section.EI_slip, EI_slip, rtol=1e-12)
    # the bending law's secant stiffnesses in the linear range are the section's
    law = drake.bending_law(mu=0.5, axial_strain=0.001)
    np.testing.assert_allclose(law.EI_stick, EI_stick, rtol=1e-12)
    assert section.area == pytest.approx(sum(n * A for _, A, _, n, _, _ in rows), rel=1e-12)


def test_a_damaged_acsr_centroid_is_modulus_weighted():
    """Two outer aluminium wires broken: the centroid of E_i A_i (not of the plain areas)."""
    d = strand.preset("acsr-drake").damaged(2)
    w = d.wires()
    E = np.where(w.layer <= 1, STEEL.E_e, ALUMINIUM.E_e)
    weight = np.where(w.intact, E * w.area, 0.0)
    y_c, z_c = d.section().centroid
    assert z_c == pytest.approx(weight @ w.z / weight.sum(), rel=1e-12)
    assert abs(y_c) < 1e-15
    plain = np.where(w.intact, w.area, 0.0)
    assert abs(z_c - plain @ w.z / plain.sum()) > 1e-3 * abs(z_c)  # a different point indeed


def test_fe_intact_axial_stiffness_of_acsr_is_the_section_EA():
    drake = strand.preset("acsr-drake")
    step = strand.StrandModel(drake, 0.5, n_elements=8).solve(0.002)
    assert step.force == pytest.approx(drake.section().EA * 0.002, rel=1e-10)
    # and each wire's stress is its own material's: E_i cos²α_i ε
    w = drake.wires()
    E = np.where(w.layer <= 1, STEEL.E_e, ALUMINIUM.E_e)
    expected = E * np.cos(w.lay_angle) ** 2 * 0.002
    np.testing.assert_allclose(step.wire_stress[:, 0, 0], expected, rtol=1e-10)


def test_acsr_capacity_curve_ruptures_at_its_aluminium_wires():
    """Aluminium (ε_rupture 0.0745) breaks before steel (0.082) even at cos²α < 1: the first
    wires to break are the inner aluminium layer's, at strand strain 0.0745 / cos²α_2."""
    drake = strand.preset("acsr-drake")
    model = strand.StrandModel(drake, 0.3, n_elements=6)
    curve = model.capacity_curve(n_steps=24)
    assert curve.ruptured and curve.failure is None
    layer = drake.wires().layer[curve.rupture_wires]
    assert set(layer.tolist()) == {2}
    alpha_2 = drake.lay_angles[1]
    assert curve.strain[-1] == pytest.approx(ALUMINIUM.eps_rupture / np.cos(alpha_2) ** 2, rel=1e-6)
    assert curve.columns()["max_wire_strain"][-1] == ALUMINIUM.eps_rupture
    # the closed form of an undamaged strand ends at the same strain
    closed = strand.analyse(drake)
    assert closed.curve.strain[-1] == pytest.approx(curve.strain[-1], rel=1e-12)
    # the elastic limit: the inner aluminium layer leaves its linear branch (eps_y1 = 0.003) first
    assert curve.elastic_limit == pytest.approx(ALUMINIUM.eps_y1 / np.cos(alpha_2) ** 2, rel=1e-9)


def test_material_density_and_alpha_are_checked():
    base = dict(E_e=2e11, E_p=1e9, eps_y=0.004, eps_y1=0.003, eps_y2=0.005, eps_rupture=0.05)
    for argument, value in (("density", -1.0), ("density", 0.0), ("density", "7800"), ("alpha", "1e-6"),
                            ("alpha", float("nan"))):  # fmt: skip
        with pytest.raises(InputError) as err:
            strand.Material(**base, **{argument: value})
        assert err.value.argument == argument
    assert strand.Material(**base).density is None  # unknown by default
    assert strand.Material(**base, alpha=-0.5e-6).alpha == -0.5e-6  # a carbon-fibre core's


def test_layer_and_core_materials_are_checked():
    with pytest.raises(InputError) as err:
        strand.Layer(6, 3e-3, lay_angle=0.1, material="steel")
    assert err.value.argument == "material"
    with pytest.raises(InputError) as err:
        strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=0.1),), STEEL, core_material="steel")
    assert err.value.argument == "core_material"
    with pytest.raises(InputError) as err:
        strand.preset("acsr-nonesuch")
    assert err.value.argument == "name"


def test_annex_e_refuses_several_materials():
    with pytest.raises(InputError) as err:
        strand.fe.annex_e.annex_e_section(strand.preset("acsr-drake").damaged(1), slip=False, x=0.0)
    assert err.value.argument == "strand"


#: a 1x7 of a steel core under six aluminium wires (the slip laws need one helical layer)
STEEL_CORE_1X7 = strand.Strand(
    3.1e-3, (strand.Layer(6, 3.1e-3, lay_angle=0.13, material=ALUMINIUM),), STEEL, name="steel/aluminium 1x7"
)


@pytest.mark.parametrize(
    "name, slip, damage_load",
    [
        ("acsr-hawk", "none", "eccentricity"),
        ("acsr-hawk", "none", "sinusoidal"),
        ("1x7", "axis", "eccentricity"),
    ],
)
def test_damaged_multi_material_tangent_agrees_with_central_differences(name, slip, damage_load):
    """Per-material stresses and tangents, the modulus-weighted centroid, the slip law's κ_m of
    mixed wires and the sinusoidal loads of broken aluminium wires: K = ∂R/∂U by central
    differences, at a strain where the aluminium has left its linear branch (its blend starts
    at 0.003) and the steel has not."""
    d = (STEEL_CORE_1X7 if name == "1x7" else strand.preset(name)).damaged(2)
    model = strand.StrandModel(d, 0.4, n_elements=8, slip=slip, damage_load=damage_load)
    rng = np.random.default_rng(1)
    U = model.uniform(0.0036) + 1e-5 * rng.standard_normal(model.offsets[-1])
    R, K, _ = model.assemble(U)
    direction = np.zeros(U.size)
    direction[model.free] = rng.standard_normal(model.free.size) * 1e-3
    eps = 1e-6
    fd = (model.assemble(U + eps * direction)[0] - model.assemble(U - eps * direction)[0]) / (2 * eps)
    assert K @ direction == pytest.approx(fd, rel=1e-4, abs=1e-6 * np.abs(fd).max())
