"""Funicular polygons: seed 000 examples 1 and 2."""

import numpy as np
import pytest

from skcable import cable
from skcable.errors import InputError


def test_seed000_ex1_published_values():
    f = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    assert np.round(f.T, 2).tolist() == [233.04, 205.38, 205.66, 237.85]
    assert np.round(np.degrees(f.angles), 1).tolist() == [-26.7, -8.3, 20.0, 37.7]
    assert np.round(f.nodes[:, 0], 2).tolist() == [0.0, 4.47, 10.41, 16.04, 20.0]
    assert np.round(f.nodes[:, 1], 2).tolist() == [0.0, -2.24, -3.11, -1.06, 2.0]
    assert f.residual() < 1e-12


def test_seed000_ex1_equations_hold():
    # the seed's matrix form: C·Tx = Px, C·Ty = Py, sum L cos = Lx, sum L sin = Ly
    f = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    C = np.eye(3, 4) - np.eye(3, 4, 1)
    assert np.allclose(C @ (f.T * np.cos(f.angles)), [5, 10, 5], atol=1e-10)
    assert np.allclose(C @ (f.T * np.sin(f.angles)), [-75, -100, -75], atol=1e-10)
    assert np.dot([5, 6, 6, 5], np.cos(f.angles)) == pytest.approx(20, rel=1e-13)


def test_single_load_on_symmetric_cable():
    # two equal segments, load P at the joint: T = P / (2 sin theta)
    f = cable.funicular((8, 0), [5, 5], [(0, -60)])
    theta = np.arccos(4 / 5)
    assert f.T == pytest.approx([60 / (2 * np.sin(theta))] * 2, rel=1e-12)


def test_seed000_ex2_published_values():
    f = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    assert round(f.H, 3) == 28.511
    assert round(f.V_A, 3) == 80.851
    assert round(f.V_B, 3) == 39.149
    assert np.round(f.T, 3).tolist() == [85.731, 42.008, 28.523, 48.430]
    assert np.round(f.nodes[:, 1], 2).tolist() == [0.0, -2.84, -5.0, -5.12, -1.0]
    assert f.residual() < 1e-12


def test_vertical_loads_agree_with_general_funicular():
    v = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    lengths = np.hypot(*np.diff(v.nodes, axis=0).T)
    g = cable.funicular((10, -1), lengths, [(0, -50), (0, -30), (0, -40)])
    assert g.T == pytest.approx(v.T, rel=1e-10)
    assert g.nodes == pytest.approx(v.nodes, abs=1e-10)


def test_bad_input():
    with pytest.raises(InputError, match="lengths"):
        cable.funicular((20, 0), [5, 5], [(0, -1)])  # cannot reach
    with pytest.raises(InputError, match="lengths"):
        cable.funicular((20, 0), [5, 5, 15], [(0, -1)])  # count mismatch
    with pytest.raises(InputError, match="through"):
        cable.funicular_vertical(10, 0, [(5, 1)], through=(5, 1))  # above chord
    with pytest.raises(InputError, match="loads"):
        cable.funicular_vertical(10, 0, [(12, 1)], H=1.0)
