"""The fallbacks of `skcable.fe.newton` (``full_steps``, ``rescue``, ``polish``) and the retries of
`skcable.fe.first_converged`, on scalar equations whose roots are known in closed form or by
Brent's method."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from skcable.errors import ConvergenceError, InputError
from skcable.fe import NewtonResult, first_converged, newton
from tests.fe.scalar_problems import scalar_problem


def _kinked(x):
    """A semismooth residual: R = x - 1 left of 0, -1 - x on (0, 1/2], 7x - 5 past 1/2 (its root
    5/7). Its generalized derivative at 0 is the left piece's, 1: the Newton step from 0 goes
    right, where |R| grows, so no step length descends; the full step lands at 1 (|R| = 2, no
    descent either), and the full step from there lands on the root."""
    return x - 1.0 if x <= 0.0 else -1.0 - x + 8.0 * max(0.0, x - 0.5)


def _kinked_slope(x):
    return 1.0 if x <= 0.0 else (7.0 if x > 0.5 else -1.0)


KINKED = scalar_problem(_kinked, _kinked_slope)


def test_the_damped_newton_stalls_where_full_steps_reach_the_root():
    assemble, norm, increment = KINKED
    root = brentq(_kinked, 0.5, 1.0, xtol=1e-15)
    assert math.isclose(root, 5.0 / 7.0, rel_tol=1e-14)
    with pytest.raises(ConvergenceError, match="no descent") as damped:
        newton(assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12)
    assert damped.value.history == [1.0]
    seen = []
    result = newton(
        assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="after",
        callback=lambda k, r, s: seen.append((k, r, s)),
    )  # fmt: skip
    assert abs(result.x[0] - root) < 1e-15
    # the full steps' own history, from the same start: |R(0)| = 1, |R(1)| = 2, then the root
    assert result.history[:2] == [1.0, 2.0] and result.history[2] < 1e-12
    assert result.steps == [1.0, 1.0]
    # the callback saw both steps of the full-step attempt, numbered from 1, with their lengths 1 and 2/7
    assert [k for k, _, _ in seen] == [1, 2]
    assert seen[0][2] == 1.0 and math.isclose(seen[1][2], 2.0 / 7.0, rel_tol=1e-14)
    # the start's assembly is reused: start, the damped trials (1 + 12 halvings), two full steps
    assert result.assemblies == 1 + 13 + 2


def test_when_both_fail_the_damped_error_is_raised_with_both_histories():
    assemble, norm, increment = KINKED
    with pytest.raises(ConvergenceError, match="no descent") as failed:
        newton(
            assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, max_iter=1,
            full_steps="after",
        )  # fmt: skip
    # the damped Newton's history, and the full steps' one step to x = 1, where |R| = 2
    assert failed.value.history == [1.0]
    assert failed.value.attempts == [[1.0], [1.0, 2.0]]
    assert failed.value.last is not None and failed.value.last[0] == 0.0


def test_full_steps_first_fall_back_on_the_damped_newton():
    # arctan from x0 = 3: full Newton steps diverge (|x| grows once |x| > 1.3917: 3, -9.5, 124,
    # -2.4e4, ..., 1e146 at the eighth), the damped ones reach the root, 0
    assemble, norm, increment = scalar_problem(math.atan, lambda x: 1.0 / (1.0 + x * x))
    with pytest.raises(ConvergenceError):
        newton(
            assemble,
            np.array([3.0]),
            norm=norm,
            increment=increment,
            tol=1e-12,
            max_iter=8,
            line_search=False,
        )
    result = newton(
        assemble, np.array([3.0]), norm=norm, increment=increment, tol=1e-12, max_iter=8, full_steps="first"
    )
    assert abs(result.x[0]) < 1e-12
    assert min(result.steps) < 1.0  # the damped Newton's
    # and from the kinked start, full steps first converge without the damped attempt
    assemble, norm, increment = KINKED
    first = newton(assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="first")
    assert abs(first.x[0] - 5.0 / 7.0) < 1e-15 and first.assemblies == 3


def test_a_failed_full_steps_first_raises_the_damped_error():
    assemble, norm, increment = KINKED
    with pytest.raises(ConvergenceError, match="no descent") as failed:
        newton(
            assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, max_iter=1,
            full_steps="first",
        )  # fmt: skip
    assert failed.value.attempts == [[1.0, 2.0], [1.0]]


def test_without_line_search_there_is_no_second_attempt():
    assemble, norm, increment = scalar_problem(math.atan, lambda x: 1.0 / (1.0 + x * x))
    calls = []

    def counted(x):
        calls.append(x[0])
        return assemble(x)

    with pytest.raises(ConvergenceError) as failed:
        newton(
            counted, np.array([3.0]), norm=norm, increment=increment, tol=1e-12, max_iter=8,
            line_search=False, full_steps="after",
        )  # fmt: skip
    assert failed.value.attempts == []
    assert calls.count(3.0) == 1  # the start assembled once: no attempt from it again


def test_the_rescue_goes_on_from_where_the_damped_newton_stopped():
    assemble, norm, increment = KINKED
    root = 5.0 / 7.0
    stops = []

    def rescue(failed):
        stops.append((str(failed), failed.last[0]))
        state = assemble(np.array([root]))
        return NewtonResult(np.array([root]), state, [norm(assemble(failed.last)), norm(state)])

    result = newton(
        assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="after",
        rescue=rescue,
    )  # fmt: skip
    assert len(stops) == 1 and "no descent" in stops[0][0] and stops[0][1] == 0.0
    assert result.x[0] == root and result.history == [1.0, abs(_kinked(root))]
    # a rescue that has no way on: the full steps after it
    after = newton(
        assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="after",
        rescue=lambda failed: None,
    )  # fmt: skip
    assert abs(after.x[0] - root) < 1e-15 and after.history[:2] == [1.0, 2.0]


def test_the_polish_takes_the_root_to_its_round_off():
    # x² = 2 from 1.5 to 1e-5: Newton stops 2.1e-6 from √2; two more full steps take it to the
    # double nearest √2 (math.sqrt is correctly rounded), each residual below a tenth of the last
    assemble, norm, increment = scalar_problem(lambda x: x * x - 2.0, lambda x: 2.0 * x)
    plain = newton(assemble, np.array([1.5]), norm=norm, increment=increment, tol=1e-5)
    assert abs(plain.x[0] - math.sqrt(2.0)) > 1e-6
    polished = newton(assemble, np.array([1.5]), norm=norm, increment=increment, tol=1e-5, polish=2)
    assert abs(polished.x[0] - math.sqrt(2.0)) <= math.ulp(math.sqrt(2.0))
    assert polished.history[: len(plain.history)] == plain.history
    extra = polished.history[len(plain.history) - 1 :]
    assert len(extra) == 3 and all(b < 0.1 * a for a, b in zip(extra, extra[1:], strict=False))
    assert polished.steps[-2:] == [1.0, 1.0]


def test_full_steps_is_checked():
    assemble, norm, increment = KINKED
    with pytest.raises(InputError, match="full_steps"):
        newton(assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="always")


def test_first_converged_makes_the_attempts_in_turn_and_raises_the_first_error():
    made = []

    def attempts():
        for k in range(4):
            made.append(k)
            yield lambda k=k: _fails(f"attempt {k}") if k < 2 else k

    assert first_converged(attempts()) == 2
    assert made == [0, 1, 2]  # the fourth never made
    with pytest.raises(ConvergenceError, match="attempt 0") as first:
        first_converged([lambda: _fails("attempt 0"), lambda: _fails("attempt 1")])
    assert first.value.history == [0.0]
    with pytest.raises(KeyError):  # not caught: passes at once
        first_converged([lambda: {}["x"], lambda: 1])
    assert first_converged([lambda: {}["x"], lambda: 1], catch=(KeyError,)) == 1
    with pytest.raises(InputError, match="attempts"):
        first_converged([])


def _fails(message):
    raise ConvergenceError(message, [0.0])


def _piece(state_x):
    return 0 if state_x <= 0.0 else (1 if state_x <= 0.5 else 2)


def _kinked_active(assemble):
    """``assemble`` that keeps ``x`` in its state, and the active piece of `_kinked` as ``active``."""

    def with_x(x):
        return (*assemble(x), float(x[0]))

    return with_x, lambda state: _piece(state[2])


@pytest.mark.parametrize("line_search", [True, False])
def test_active_makes_the_first_attempt_the_active_set_iteration(line_search):
    assemble, norm, increment = KINKED
    assemble, active = _kinked_active(assemble)
    root = brentq(_kinked, 0.5, 1.0, xtol=1e-15)
    result = newton(
        assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="first",
        active=active, line_search=line_search,
    )  # fmt: skip
    assert abs(result.x[0] - root) < 1e-15 and math.isclose(root, 5.0 / 7.0, rel_tol=1e-14)
    # the residual doubles on the step from 0 to 1 (the active piece changes: progress), then the
    # step within the last piece lands on the root; the start reused, two steps assembled
    assert result.history[:2] == [1.0, 2.0] and result.history[2] < 1e-12
    assert result.assemblies == 1 + 2


def test_full_max_iter_limits_the_active_set_iteration_and_the_damped_error_is_raised():
    assemble, norm, increment = KINKED
    assemble, active = _kinked_active(assemble)
    with pytest.raises(ConvergenceError, match="no descent") as failed:
        newton(
            assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="first",
            active=active, full_max_iter=1,
        )  # fmt: skip
    # one step of the active-set iteration (|R| from 1 to 2), then the damped Newton's no descent
    assert failed.value.attempts == [[1.0, 2.0], [1.0]]
    # without a line search the active-set iteration is still tried first: its one step assembled,
    # then the plain Newton's two from the start
    plain = newton(
        assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="first",
        active=active, full_max_iter=1, line_search=False,
    )  # fmt: skip
    assert abs(plain.x[0] - 5.0 / 7.0) < 1e-15 and plain.assemblies == 1 + 1 + 2
    # without a line search the active-set iteration is still tried first: its one step assembled,
    # then the plain Newton's two from the start
    plain = newton(
        assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="first",
        active=active, full_max_iter=1, line_search=False,
    )  # fmt: skip
    assert abs(plain.x[0] - 5.0 / 7.0) < 1e-15 and plain.assemblies == 1 + 1 + 2
    with pytest.raises(InputError, match="active"):
        newton(
            assemble, np.array([0.0]), norm=norm, increment=increment, tol=1e-12, full_steps="first",
            active=active, update=lambda x, dx, t: x + t * dx,
        )  # fmt: skip
