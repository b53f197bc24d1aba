"""Funicular polygons: seed 000 examples 1 and 2."""

import numpy as np
import pytest

from skcable import cable
from skcable.errors import ConvergenceError, InputError


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


# --- issue #14 ------------------------------------------------------------------------
def test_coincident_loads_act_as_their_sum():
    # two loads at x = 3 are one load of 30 + 12 = 42 there (statics: forces at a point add)
    split = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40), (3, 12)], through=(3, -5))
    summed = cable.funicular_vertical(10, -1, [(1, 50), (3, 42), (7, 40)], through=(3, -5))
    assert split.residual() < 1e-15  # was NaN: a zero-length segment between the two
    assert split.loads.tolist() == [[1.0, 50.0], [3.0, 42.0], [7.0, 40.0]]
    for name in ("H", "V_A", "V_B"):
        assert getattr(split, name) == pytest.approx(getattr(summed, name), rel=1e-15)
    assert split.T == pytest.approx(summed.T, rel=1e-15)
    assert split.nodes == pytest.approx(summed.nodes, rel=1e-15, abs=1e-15)
    # with H given: the reactions of a simply supported beam, V_A = sum P (span - x)/span - H dh/span
    f = cable.funicular_vertical(10.0, 2.0, [(4.0, 5.0), (4.0, 7.0)], H=20.0)
    assert f.V_A == pytest.approx(12.0 * 6.0 / 10.0 - 20.0 * 0.2, rel=1e-15)
    assert f.nodes[1, 1] == pytest.approx(2.0 * 0.4 - 12.0 * 4.0 * 6.0 / 10.0 / 20.0, rel=1e-15)


def test_results_are_residual_checked_before_they_are_returned(monkeypatch):
    monkeypatch.setattr(cable.FunicularVertical, "residual", lambda self: 1e-6)
    with pytest.raises(ConvergenceError, match="residual"):
        cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    monkeypatch.setattr(cable.Funicular, "residual", lambda self: float("nan"))
    with pytest.raises(ConvergenceError, match="residual"):
        cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])


def test_the_residual_sees_a_wrong_polygon():
    f = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    nodes = f.nodes.copy()
    nodes[2, 1] += 1e-6  # a joint moved by a micrometre
    moved = cable.FunicularVertical(f.H, f.V_A, f.V_B, f.T, nodes, f.loads, f.constraint)
    assert 1e-8 < moved.residual() < 1e-5
    g = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    forces = g.forces.copy()
    forces[1] *= 1 + 1e-6
    wrong = cable.Funicular(g.T, g.angles, g.nodes, forces, g.loads, g.lengths, g.history)
    assert wrong.residual() > 1e-8


def test_magnitudes_from_1e_minus_300_to_1e300_scale_exactly():
    # the problems are homogeneous: forces scale with the loads, positions with the lengths
    ref = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    for k in (2.0**-990, 2.0**990):  # powers of two: the scaled data are exact
        f = cable.funicular((20, 2), [5, 6, 6, 5], np.array([(5, -75), (10, -100), (5, -75)]) * k)
        assert f.T == pytest.approx(ref.T * k, rel=1e-13)
        g = cable.funicular((20 * k, 2 * k), np.array([5, 6, 6, 5]) * k, [(5, -75), (10, -100), (5, -75)])
        assert g.T == pytest.approx(ref.T, rel=1e-13) and g.nodes == pytest.approx(ref.nodes * k, rel=1e-12)
    v = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    w = cable.funicular_vertical(
        10e300, -1e300, [(1e300, 50e-300), (3e300, 30e-300), (7e300, 40e-300)], through=(3e300, -5e300)
    )
    assert w.H == pytest.approx(v.H * 1e-300, rel=1e-13) and w.nodes == pytest.approx(
        v.nodes * 1e300, rel=1e-13
    )


def test_unloaded_or_malformed_input_is_refused():
    with pytest.raises(InputError, match="loads"):
        cable.funicular((20, 2), [5, 6, 6, 5], np.zeros((3, 2)))  # no loads: no equilibrium shape
    with pytest.raises(InputError, match="loads"):
        cable.funicular((20, 2), [5, 6, 6, 5], [5, -75, 10, -100, 5, -75])  # flat list: not reinterpreted
    with pytest.raises(InputError, match="tol"):
        cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)], tol=0.0)
    with pytest.raises(InputError, match="through"):
        cable.funicular_vertical(10, 0, [(5, 1)], through=5.0)
