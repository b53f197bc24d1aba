"""The watchdog of `skcable.fe.newton`: a relaxed full step, kept where the next step descends
below the point before it, undone where it does not."""

import math

import numpy as np
from scipy.optimize import brentq

from skcable.fe import newton
from tests.fe.scalar_problems import scalar_problem


def test_a_relaxed_step_over_a_hardening_spring_saves_the_halving():
    # x + c x^5 = F from rest: the first full step x = F overshoots the root onto the stiff side,
    # its residual larger than at rest (no Armijo decrease); the halved step lands on the soft
    # side again, and its full step overshoots once more
    c, F = 0.2, 1.5
    assemble, norm, increment = scalar_problem(lambda x: x + c * x**5 - F, lambda x: 1 + 5 * c * x**4)
    root = brentq(lambda x: x + c * x**5 - F, 0.0, F, xtol=1e-15)
    assert norm(assemble(np.array([F]))) > norm(assemble(np.array([0.0])))  # the overshoot
    plain = newton(assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-13)
    watched = newton(assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-13, watchdog=1)
    assert abs(watched.x[0] - root) < 1e-13 and abs(plain.x[0] - root) < 1e-13
    assert watched.steps[0] == 1.0 and plain.steps[0] < 1.0
    assert watched.assemblies < plain.assemblies


def test_a_relaxed_step_that_runs_off_is_undone_and_the_step_halved():
    # arctan from x0 = 3: the full Newton step overshoots to -9.5, where |atan| is larger, and the
    # full step from there runs off to +124 (Newton diverges from |x0| > 1.39); the watchdog
    # returns to 3 and halves
    assemble, norm, increment = scalar_problem(math.atan, lambda x: 1.0 / (1.0 + x * x))
    x0 = np.array([3.0])
    first = x0 + increment(assemble(x0))
    assert norm(assemble(first)) > norm(assemble(x0))
    assert norm(assemble(first + increment(assemble(first)))) > norm(assemble(x0))  # it runs off
    seen = []
    result = newton(
        assemble, x0, norm=norm, increment=increment, tol=1e-14, watchdog=1,
        callback=lambda i, r, s: seen.append(r),
    )  # fmt: skip
    assert abs(result.x[0]) < 1e-14
    # the relaxed iteration is dropped: the history kept descends from the start
    assert all(b < a for a, b in zip(result.history, result.history[1:], strict=False))
    assert result.steps[0] == 0.25
    assert seen[0] == norm(assemble(first))  # the callback saw the undone step
    assert len(seen) == len(result.history)
    plain = newton(assemble, x0, norm=norm, increment=increment, tol=1e-14)
    assert plain.history == result.history
    assert result.assemblies == plain.assemblies + 1  # the price: the relaxed trial and its full step,
    # less the full step from x0 the halving no longer repeats
