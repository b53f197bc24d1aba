"""Step control of a continuation: how far the next load step goes, after a failure and after
successes.

A continuation (a capacity curve under imposed strain, a load ramp) follows a *schedule* of
goals. `StepControl` decides each step's target from the value reached so far:

- **cut**: a step that fails is halved, down to ``1/2**halvings`` of the schedule's own increment
  to that goal, below which the continuation has failed;
- **hold**: a cut increment becomes the limit of the following steps, so that a hard stretch is
  crossed at the size that worked;
- **grow**: the limit doubles after ``grow_after`` steps in a row converge at it;
- **lift**: the limit is dropped once it exceeds the schedule's largest increment.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError

__all__ = ["StepControl"]


class StepControl:
    """The step lengths of a continuation along ``schedule`` (module docstring).

    Parameters
    ----------
    schedule : sequence of float
        The goals, increasing, after the start value.
    start : float
        The value the continuation starts from.
    halvings : int
        Halvings of a step allowed below the schedule's increment.
    grow_after : int
        Successes in a row at a held increment before it doubles.

    Attributes
    ----------
    limit : float
        The largest increment allowed now (inf: none).
    cutbacks : int
        Failed steps so far (each one halved).
    """

    def __init__(self, schedule, start: float = 0.0, *, halvings: int = 6, grow_after: int = 2):
        self.schedule = np.asarray(schedule, dtype=float)
        if self.schedule.ndim != 1 or self.schedule.size == 0 or np.any(np.diff(self.schedule) <= 0):
            raise InputError("schedule", "must be an increasing sequence of goals")
        self.start = float(start)
        self.halvings, self.grow_after = whole("halvings", halvings, 0), whole("grow_after", grow_after, 1)
        self.limit, self.cutbacks = np.inf, 0
        self._streak = 0
        self._largest = float(np.max(np.diff(np.concatenate([[start], self.schedule]))))

    def goals(self) -> Iterator[tuple[float, float]]:
        """``(goal, smallest)``: each goal and the smallest increment allowed on the way to it."""
        previous = self.start
        for goal in self.schedule:
            yield float(goal), (float(goal) - previous) / 2**self.halvings
            previous = float(goal)

    def target(self, at: float, goal: float) -> float:
        """The next step's target from ``at`` towards ``goal``."""
        return min(goal, at + self.limit)

    def cut(self, at: float, target: float, smallest: float) -> float | None:
        """The halved target after a failed step to ``target``, or None when that would be below
        the ``smallest`` increment (the continuation has failed)."""
        self.cutbacks += 1
        if 0.5 * (target - at) < smallest * (1 - 1e-9):
            return None
        return at + 0.5 * (target - at)

    def accept(self, at: float, target: float, was_cut: bool) -> None:
        """A step from ``at`` to ``target`` converged (``was_cut``: after at least one cut)."""
        self._streak = 0 if was_cut else self._streak + 1
        if was_cut:
            self.limit = target - at
        elif np.isfinite(self.limit) and self._streak >= self.grow_after:
            self.limit, self._streak = 2.0 * self.limit, 0
        if self.limit >= self._largest:
            self.limit = np.inf
