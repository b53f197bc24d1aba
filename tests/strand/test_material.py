"""Wire material law: Table B.1, Table 3.4, C1 continuity, oddness."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from skcable import strand
from skcable.errors import InputError

MPA = 1e6
# Table B.1, printed (MPa-based units)
TABLE_B1 = {
    "steel": (76550244800, -210513173.2, 196603.774, 983.01887),
    "aluminium": (632198627.3, -11110305.51, 64509.80, 193.529),
}


@pytest.mark.parametrize("name", TABLE_B1)
def test_cubic_coefficients_match_table_B1(name):
    m = strand.material(name)
    a, b, c, d = TABLE_B1[name]
    assert m.a / MPA == pytest.approx(a, rel=1e-7)
    assert m.b / MPA == pytest.approx(b, rel=1e-7)
    assert m.c / MPA == pytest.approx(c, rel=1e-9)
    assert m.d / MPA == pytest.approx(d, abs=5e-4)  # printed to 3 decimals


@pytest.mark.parametrize("name", TABLE_B1)
def test_cubic_coefficients_match_closed_forms_B6_B7(name):
    m = strand.material(name)
    e1, e2, ey = m.eps_y1, m.eps_y2, m.eps_y
    square = e1**2 - 2 * e1 * e2 + e2**2
    assert m.a == pytest.approx((m.E_e - m.E_p) * (2 * ey - e1 - e2) / ((e1 - e2) * square), rel=1e-12)
    assert m.b == pytest.approx((m.E_e - m.E_p) * (3 * ey - e1 - 2 * e2) / square, rel=1e-12)


def test_softening_range_from_the_printed_coefficients():
    """The roots of dσ/dε = 3a t² + 2b t + c with Table B.1's printed a, b, c (t = ε − ε'_y):
    aluminium's blend softens between them; steel's tangent stays positive."""
    a, b, c, _ = TABLE_B1["aluminium"]
    m = strand.material("aluminium")
    expected = np.sort(np.roots([3 * a, 2 * b, c]).real) + m.eps_y1
    assert m.softening_range == pytest.approx(expected, rel=1e-6)
    assert float(m.tangent(expected.mean())) < 0
    assert strand.material("steel").softening_range is None


def test_rupture_stress_table_3_4():
    assert strand.material("steel").stress_rupture / MPA == pytest.approx(1443.0, abs=0.05)


@pytest.mark.parametrize("name", TABLE_B1)
def test_c1_at_both_blend_ends(name):
    m = strand.material(name)
    for eps in (m.eps_y1, m.eps_y2):
        h = 1e-9
        left, right = m.stress(eps - h), m.stress(eps + h)
        assert right - left == pytest.approx(2 * h * m.tangent(eps), rel=1e-4)  # continuous value
        assert m.tangent(eps - h) == pytest.approx(m.tangent(eps + h), rel=1e-4)  # continuous slope
    # tangent is the derivative of stress everywhere (central differences)
    eps = np.linspace(1e-4, m.eps_rupture, 997)
    h = 1e-8
    assert np.allclose((m.stress(eps + h) - m.stress(eps - h)) / (2 * h), m.tangent(eps), rtol=1e-5)


@given(st.floats(-0.1, 0.1))
def test_stress_is_odd_and_tangent_even(eps):
    m = strand.material("steel")
    assert m.stress(-eps) == -m.stress(eps)
    assert m.tangent(-eps) == m.tangent(eps)
    assert m.secant(eps) == pytest.approx(m.stress(eps) / eps if eps else m.E_e)


def test_vectorised_and_bad_input():
    m = strand.material("aluminium")
    assert m.stress(np.array([0.001, 0.002])).shape == (2,)
    with pytest.raises(InputError, match="name"):
        strand.material("copper")
    with pytest.raises(InputError, match="eps_y"):
        strand.Material(2e11, 1e9, eps_y=0.004, eps_y1=0.005, eps_y2=0.006, eps_rupture=0.08)


def test_repr_is_one_short_line_with_units():
    text = repr(strand.material("steel"))
    assert "\n" not in text and len(text) < 200
    assert "'steel'" in text and "Pa" in text and "eps_rupture=0.082" in text
