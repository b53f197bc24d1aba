"""bvp.solve: the estimate bounds the true error, and the cheaper model is taken when good enough."""

import numpy as np
import pytest

from skcable import bvp, cable
from skcable.errors import InputError

RTOL = 1e-3
CONSTRAINTS = ("length", "sag", "H", "low", "T_max")


def true_error(sol, exact):
    pairs = [(sol.H, exact.H), (sol.T_A, exact.T_A), (sol.T_B, exact.T_B), (sol.length, exact.length)]
    return max(abs(float(a) / float(b) - 1) for a, b in pairs)


def test_single_uniform_loads_take_their_exact_closed_form():
    sol = bvp.solve(200.0, 0.0, bvp.SelfWeight(1.0), sag=20.0)
    assert (
        sol.model == "catenary" and sol.error_estimate == 0 and round(sol.H, 4) == 253.2649
    )  # seed 001 ex. 5
    sol = bvp.solve(200.0, 0.0, bvp.DeckLoad(1.0), sag=20.0)
    assert (
        sol.model == "parabola" and sol.error_estimate == 0 and round(sol.T_max, 2) == 269.26
    )  # seed 001 ex. 4


def test_stretch_decides_between_catenary_and_irvine():
    rng = np.random.default_rng(5)
    models = set()
    for _ in range(200):
        dh = 100 * rng.uniform(-2, 2)
        length = np.hypot(100, dh) * (1 + 10 ** rng.uniform(-4, -0.5))
        EA = 10 ** rng.uniform(3, 9)
        sol = bvp.solve(100.0, dh, bvp.SelfWeight(1.0), length=length, EA=EA, rtol=RTOL)
        exact = cable.elastic_catenary(100.0, dh, 1.0, EA, length=length)
        error = true_error(sol, exact)
        assert error <= max(sol.error_estimate, 1e-12) <= RTOL, (sol.model, error, sol.error_estimate)
        models.add(sol.model)
    assert {"catenary", "elastic catenary"} <= models


def deck_and_weight_scenes(n, seed):
    """Deck load plus self weight (a suspension bridge's main cable), no closed form."""
    rng = np.random.default_rng(seed)
    for _ in range(n):
        dh = 100 * rng.uniform(-1, 1)
        sag = 100 * 10 ** rng.uniform(-2.5, -0.7)
        loads = [bvp.DeckLoad(1.0), bvp.SelfWeight(10 ** rng.uniform(-3, 0))]
        yield dh, loads, CONSTRAINTS[rng.integers(len(CONSTRAINTS))], sag


def test_smeared_parabola_estimate_bounds_the_error_and_is_taken_when_good_enough():
    good, taken = 0, 0
    for dh, loads, name, sag in deck_and_weight_scenes(40, seed=2):
        reference = bvp.solve_bvp(100.0, dh, loads, sag=sag, n_elements=64, degree=4)
        values = dict(
            length=reference.length, sag=sag, H=reference.H, low=reference.y_low, T_max=reference.T_max
        )
        if name == "low" and not 1e-6 < reference.x_low < 100.0 - 1e-6:
            name = "sag"  # the lowest point is a support: no "low" constraint there
        value = float(values[name])
        if name != "sag":
            reference = bvp.solve_bvp(100.0, dh, loads, n_elements=64, degree=4, **{name: value})
        sol = bvp.solve(100.0, dh, loads, rtol=RTOL, **{name: value})
        error = true_error(sol, reference)
        assert error <= sol.error_estimate <= RTOL, (sol.model, name, error, sol.error_estimate)
        parabola = bvp.solve(100.0, dh, loads, rtol=1e9, **{name: value})  # always the parabola
        assert parabola.model == "parabola"
        if true_error(parabola, reference) <= RTOL / 20:
            good += 1
            taken += sol.model == "parabola"
    assert good >= 10 and taken / good >= 0.9, (taken, good)


def test_other_loads_take_the_bvp_with_a_bounding_estimate():
    ice = bvp.DistributedLoad(qy=lambda x: -12.0 * (x < 150.0))
    loads = [bvp.SelfWeight(16.0), ice]
    for rtol in (1e-3, 1e-6):
        sol = bvp.solve(400.0, 10.0, loads, length=401.2, EA=2.9e7, rtol=rtol)
        mesh = np.union1d(np.linspace(0, 400, 513), [150.0])
        reference = bvp.solve_bvp(400.0, 10.0, loads, length=401.2, EA=2.9e7, mesh=mesh, degree=3)
        assert sol.model == "BVP" and "P2" in sol.reason
        assert true_error(sol, reference) <= sol.error_estimate <= rtol


def test_bad_input():
    with pytest.raises(InputError, match="rtol"):
        bvp.solve(100.0, 0.0, bvp.SelfWeight(1.0), sag=1.0, rtol=0)
    with pytest.raises(InputError, match="constraint"):
        bvp.solve(100.0, 0.0, bvp.SelfWeight(1.0))
    with pytest.raises(InputError, match="loads"):
        bvp.solve(100.0, 0.0, [], sag=1.0)
