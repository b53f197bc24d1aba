"""strand.analyse: closed form for intact strands (checked against the FE model), stick or slip."""

import numpy as np
import pytest

from skcable import strand
from skcable.errors import InputError


def test_closed_form_is_the_fe_model_of_an_intact_strand():
    s = strand.preset("aluminium-10.1")
    analysis = strand.analyse(s)
    assert analysis.model == "closed form" and "no FE" in analysis.reason
    fe = strand.StrandModel(s, 0.3, n_elements=8).capacity_curve(n_steps=10)
    np.testing.assert_allclose(fe.force[1:], strand.axial_force(s, fe.strain[1:]), rtol=1e-12)
    assert analysis.curve.strain[-1] == pytest.approx(fe.strain[-1], rel=1e-9)  # the core ruptures first
    assert analysis.curve.K_Leq == pytest.approx(s.section().EA, rel=1e-12)  # Papailiou eq. 2.20
    assert analysis.curve.D_r == 0 and analysis.curve.toughness > 0


def test_damaged_strand_switches_slip_on_where_stick_reaches_kappa_m():
    analysis = strand.analyse(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=16, n_steps=8)
    assert analysis.model == "stick-slip" and analysis.curve.model.slip.name == "axis"
    reached = [np.max(np.abs(s.curvature) / s.kappa_m) >= 1 for s in analysis.stick.steps]
    strain = analysis.stick.steps[int(np.argmax(reached))].strain
    assert any(reached) and f"{strain:.3g}" in analysis.reason


def test_stick_is_kept_when_the_wires_never_slip():
    # a steep lay (17°) and the largest friction taken (mu = 2): kappa_m (its capstan gain grows
    # with mu sin α) stays above the stick curvature
    steep = strand.Strand(3.1e-3, (strand.Layer(6, 3.1e-3, lay_angle=0.3),), strand.material("steel"))
    analysis = strand.analyse(steep.damaged(1), 0.3, mu=2.0, n_elements=16, n_steps=8)
    assert analysis.model == "stick" and analysis.curve is analysis.stick
    assert all(np.max(np.abs(s.curvature) / s.kappa_m) < 1 for s in analysis.stick.steps)


def test_bad_input():
    with pytest.raises(InputError, match="n_points"):
        strand.analyse(strand.preset("steel-9.5"), n_points=1)
    with pytest.raises(InputError, match="length"):
        strand.analyse(strand.preset("steel-9.5"), -1.0)
    with pytest.raises(InputError, match="mu"):  # exp(mu θ sin α) beyond the floating-point range
        _ = strand.preset("steel-9.5").damaged(1).bending_law(mu=1e4).kappa_m
