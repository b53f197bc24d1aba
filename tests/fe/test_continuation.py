"""The continuation's step control: cut, hold, grow and lift, on a solver written here that fails
on steps longer than a limit."""

import pytest

from skcable.errors import InputError
from skcable.fe.continuation import StepControl


def run(schedule, longest, fail_above=None):
    """Follow ``schedule`` with a 'solver' that fails on steps longer than ``longest`` (and at any
    value above ``fail_above``); the targets it reached and whether it failed."""
    control, at, reached = StepControl(schedule), 0.0, []
    for goal, smallest in control.goals():
        while at < goal - 1e-15:
            target, cut = control.target(at, goal), False
            while target is not None and (
                target - at > longest + 1e-12 or (fail_above and target > fail_above)
            ):
                target, cut = control.cut(at, target, smallest), True
            if target is None:
                return reached, True, control
            control.accept(at, target, cut)
            at = target
            reached.append(round(at, 12))
    return reached, False, control


def test_a_cut_increment_is_held_then_grows_back():
    # steps of 1.0 where 0.25 is the most the solver takes: cut twice, held at 0.25, doubled to 0.5
    # after two successes (which fails, cut back to 0.25 and held again)
    reached, failed, control = run([1.0, 2.0], 0.25)
    assert not failed and reached[-1] == 2.0
    assert reached[:4] == [0.25, 0.5, 0.75, 1.0]
    assert all(b - a <= 0.25 + 1e-12 for a, b in zip([0.0, *reached], reached, strict=False))


def test_the_limit_is_lifted_once_larger_than_the_schedule_steps():
    reached, failed, control = run([0.5, 1.0, 4.0], 10.0)
    assert reached == [0.5, 1.0, 4.0] and control.cutbacks == 0 and control.limit == float("inf")


def test_a_continuation_that_cannot_pass_fails_after_its_halvings():
    reached, failed, control = run([1.0, 2.0], 10.0, fail_above=1.001)
    # from 1.0 towards 2.0 the step halves six times: 1/64 of the increment is the last tried
    assert failed and reached == [1.0] and control.cutbacks == 7


def test_bad_schedules_are_refused():
    with pytest.raises(InputError, match="schedule"):
        StepControl([1.0, 0.5])
    with pytest.raises(InputError, match="halvings"):
        StepControl([1.0], halvings=-1)
