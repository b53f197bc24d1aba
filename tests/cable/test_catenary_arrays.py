"""Vectorised ``catenary(H=...)``: its fused checks on arrays of one shape, and the ends' forces
held as two-row blocks, against mpmath, against the scalar path and against the refusals of the
general checks."""

import math

import mpmath
import numpy as np
import pytest

from skcable import InputError, cable


def _mp_catenary(span, dh, w, H):
    """H, V_A, V_B, T_A, T_B and length by the closed form in 40 digits (z = span w/(2H),
    sinh m = (dh/span) z/sinh z; Irvine, Cable Structures, 1981, §2.2)."""
    with mpmath.workdps(40):
        span, dh, w, H = (mpmath.mpf(float(v)) for v in (span, dh, w, H))
        a = H / w
        z = span / (2 * a)
        m = mpmath.asinh(dh / span * z / mpmath.sinh(z))
        return [
            float(v)
            for v in (
                H,
                H * mpmath.sinh(z - m),
                H * mpmath.sinh(z + m),
                H * mpmath.cosh(m - z),
                H * mpmath.cosh(m + z),
                2 * a * mpmath.sinh(z) * mpmath.cosh(m),
            )
        ]


NAMES = ("H", "V_A", "V_B", "T_A", "T_B", "length")


def test_arrays_match_mpmath_and_the_scalar_path():
    rng = np.random.default_rng(7)
    spans = rng.uniform(50.0, 1200.0, 40)
    H = rng.uniform(300.0, 2e5, 40)
    c = cable.catenary(spans, -20.0, 20.0, H=H)
    for i in range(spans.size):
        ref = _mp_catenary(spans[i], -20.0, 20.0, H[i])
        one = cable.catenary(float(spans[i]), -20.0, 20.0, H=float(H[i]))
        for name, value in zip(NAMES, ref, strict=True):
            got = float(getattr(c, name)[i])
            assert got == pytest.approx(value, rel=1e-13, abs=1e-13 * ref[0]), name
            assert got == pytest.approx(float(getattr(one, name)), rel=1e-13, abs=1e-13 * ref[0])
    assert c.residual() < 1e-14


def test_array_dh_and_w_of_the_same_shape():
    spans = np.array([300.0, 500.0, 800.0])
    dh, w, H = np.array([-40.0, 0.0, 60.0]), np.array([10.0, 15.0, 20.0]), np.array([5e3, 2e4, 9e4])
    c = cable.catenary(spans, dh, w, H=H)
    for i in range(3):
        ref = _mp_catenary(spans[i], dh[i], w[i], H[i])
        assert [float(getattr(c, n)[i]) for n in NAMES] == pytest.approx(ref, rel=1e-13, abs=1e-9)


def test_broadcast_shapes_take_the_general_path_and_agree():
    """``dh`` of shape (2, 1) against spans of shape (3,): the ends' blocks are built from the
    attributes for the residual."""
    spans, dh, H = np.array([300.0, 500.0, 800.0]), np.array([[-40.0], [25.0]]), np.array([5e3, 2e4, 9e4])
    c = cable.catenary(spans, dh, 15.0, H=H)
    assert c.T_B.shape == (2, 3)
    for j in range(2):
        for i in range(3):
            ref = _mp_catenary(spans[i], dh[j, 0], 15.0, H[i])
            assert float(c.T_B[j, i]) == pytest.approx(ref[4], rel=1e-13)
            assert float(c.V_A[j, i]) == pytest.approx(ref[1], rel=1e-12, abs=1e-9)
    assert c.residual() < 1e-14


@pytest.mark.parametrize(
    ("span", "dh", "w", "H", "argument"),
    [
        (np.array([100.0, 0.0]), -1.0, 2.0, np.array([1e3, 1e3]), "span"),
        (np.array([100.0, math.nan]), -1.0, 2.0, np.array([1e3, 1e3]), "span"),
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([1e3, math.inf]), "H"),
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([1e3, -5.0]), "H"),
        (np.array([100.0, 200.0]), math.nan, 2.0, np.array([1e3, 1e3]), "dh"),
        (np.array([100.0, 200.0]), 1e300, 2.0, np.array([1e3, 1e3]), "dh"),
        (np.array([100.0, 200.0]), np.array([1.0, 1e300]), 2.0, np.array([1e3, 1e3]), "dh"),
        (np.array([100.0, 200.0]), -1.0, 0.0, np.array([1e3, 1e3]), "w"),
        (np.array([100.0, 200.0]), -1.0, np.array([2.0, -2.0]), np.array([1e3, 1e3]), "w"),
        (np.array([100.0, 200.0]), -1.0, 1e300, np.array([1e3, 1e-30]), "H"),  # H/w underflows
        (np.array([100.0, 200.0]), -1.0, 1e-300, np.array([1e3, 1e300]), "H"),  # H/w overflows
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([1e3, 1e-2]), "H"),  # z beyond 709
        (np.array([100.0, 200.0]), -1.0, 2.0, np.array([1e3, 1e3, 1e3]), "H"),  # shapes
    ],
)
def test_refusals_name_the_argument(span, dh, w, H, argument):
    with pytest.raises(InputError) as info:
        cable.catenary(span, dh, w, H=H)
    assert info.value.argument == argument


def test_data_whose_fused_bounds_are_too_wide_still_solve():
    """z = 0.5 and 500 in one call: the bound of z from the extremes of span and H/w exceeds
    709, so every element is tested (the general path), and each is solved."""
    spans, w, H = np.array([1000.0, 1.0]), 2.0, np.array([2000.0, 0.002])
    c = cable.catenary(spans, -0.5, w, H=H)
    assert c.z == pytest.approx([0.5, 500.0], rel=1e-15)
    for i in range(2):
        ref = _mp_catenary(spans[i], -0.5, w, H[i])
        assert [float(getattr(c, n)[i]) for n in NAMES] == pytest.approx(ref, rel=1e-13, abs=1e-12)
