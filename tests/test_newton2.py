"""The two-unknown damped Newton of skcable._newton2, on problems with known roots."""

import math

import numpy as np
import pytest

from skcable._newton2 import FLOOR, STALL, solve2
from skcable.errors import ConvergenceError

EPS = 2.220446049250313e-16


def circle_and_hyperbola(x, y, r, c):
    """x² + y² = r², x·y = c: roots x, y = sqrt((r² ± sqrt(r⁴ - 4c²))/2)."""
    f1, f2 = x * x + y * y - r * r, x * y - c
    return f1, f2, 2.0 * x, 2.0 * y, y, x, x * x + y * y + r * r, abs(x * y) + abs(c)


def exact_root(r, c):
    x = math.sqrt((r**2 + math.sqrt(r**4 - 4 * c * c)) / 2)  # x² = (r² + sqrt(r⁴ - 4c²))/2
    return x, c / x


def test_scalar_back_end_finds_the_closed_form_root():
    result = solve2(circle_and_hyperbola, 2.0, 0.5, (2.0, 1.0))
    x, y = math.sqrt(2 + math.sqrt(3)), math.sqrt(2 - math.sqrt(3))  # r = 2, c = 1
    assert result.converged is True and isinstance(result.x, float)
    assert result.x == pytest.approx(x, rel=4 * EPS) and result.y == pytest.approx(y, rel=8 * EPS)
    assert result.history[-1] <= FLOOR and len(result.history) < 10


def test_array_back_end_is_elementwise_and_matches_the_scalar_one():
    rng = np.random.default_rng(3)
    r = rng.uniform(1.0, 10.0, 50)
    c = r * r * rng.uniform(0.01, 0.45, 50)
    x0, y0 = r.copy(), 0.1 * r
    calls = []

    def counted(x, y, r, c):
        calls.append(np.size(x))
        return circle_and_hyperbola(x, y, r, c)

    result = solve2(counted, x0, y0, (r, c))
    assert result.converged.all() and result.x.shape == (50,)
    for i in range(50):
        one = solve2(circle_and_hyperbola, float(x0[i]), float(y0[i]), (float(r[i]), float(c[i])))
        assert result.x[i] == pytest.approx(one.x, rel=4 * EPS)
        assert result.x[i] == pytest.approx(exact_root(r[i], c[i])[0], rel=8 * EPS)
    # elements stop independently: later evaluations cover only those still iterating
    assert calls[0] == 50 and min(calls) < 50


def test_scaled_problem_converges_alike():
    # the same problem in other units: the round-off floor scales with it, so the iteration does
    base = solve2(circle_and_hyperbola, 2.0, 0.5, (2.0, 1.0))
    for k in (1e-100, 1e-3, 1e3, 1e100):  # squares stay normal floats
        scaled = solve2(circle_and_hyperbola, 2.0 * k, 0.5 * k, (2.0 * k, k * k))
        assert scaled.x == pytest.approx(base.x * k, rel=8 * EPS)
        assert len(scaled.history) == len(base.history)


def test_no_root_raises_with_the_history():
    def no_root(x, y):  # x² + 1 = 0, y = 0
        return x * x + 1.0, y, 2.0 * x, 0.0, 0.0, 1.0, x * x + 1.0, abs(y) + 1.0

    with pytest.raises(ConvergenceError) as info:
        solve2(no_root, 1.0, 1.0, what="no root")
    assert "no root" in str(info.value) and info.value.history[0] == 1.0
    result = solve2(no_root, np.array([1.0, 2.0]), np.zeros(2), strict=False)
    assert not result.converged.any()
    with pytest.raises(ConvergenceError, match="element 0"):
        solve2(no_root, np.array([1.0, 2.0]), np.zeros(2))


def test_points_outside_the_domain_are_stepped_around():
    # sqrt(x) - 2 = 0 and y = 1 from x = 0.1: the full Newton step lands below 0 for no
    # start, but from x = 40 the tangent overshoots to x < 0, outside the domain
    def closure(x, y):
        if x <= 0:
            raise ValueError("math domain error")
        return math.sqrt(x) - 2.0, y - 1.0, 0.5 / math.sqrt(x), 0.0, 0.0, 1.0, 2.0, 1.0

    assert solve2(closure, 0.1, 0.0).x == pytest.approx(4.0, rel=4 * EPS)

    def array_closure(x, y):
        root = np.sqrt(np.where(x > 0, x, np.nan))
        one = 1.0 + 0.0 * x
        return root - 2.0, y - 1.0, 0.5 / root, 0.0 * x, 0.0 * x, one, 2.0 * one, one

    assert solve2(array_closure, np.array([0.1, 3.0]), np.zeros(2)).x == pytest.approx(4.0, rel=4 * EPS)


def test_a_residual_stalled_at_its_round_off_is_converged():
    # a residual no step can reduce (round-off noise of 2 floors): converged, as it is within
    # STALL floors; 10 floors above STALL is no convergence
    def stalled(level):
        return lambda x, y: (level * FLOOR + 0.0 * x, y, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0)

    for back_end in (1.0, np.ones(3)):
        result = solve2(stalled(2.0), back_end, 0.0 * back_end)
        assert np.all(result.converged) and len(result.history) == 2
        with pytest.raises(ConvergenceError):
            solve2(stalled(10.0 * STALL), back_end, 0.0 * back_end)
