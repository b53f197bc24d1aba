"""A search's budget: at most ``max_calls`` evaluations and ``time_limit`` seconds, the best point
remembered, and the `ConvergenceError` of a search that runs out (every iteration has a bound;
what it reached is kept).

An iteration calls `Budget.spend` before each evaluation (raising `Budget.Spent`, which no
``except ConvergenceError`` of a strategy's alternatives takes) and `Budget.record` after it (its
measure, and a rank where a finer point beats a smaller measure); the
entry point runs the search by `Budget.run`, which turns `Budget.Spent` into `Budget.error` (a
`ConvergenceError` whose ``history`` is every recorded measure and whose ``last`` is the best
point reached) and gives any other `ConvergenceError` of the search the best point reached as
its ``last`` where it has none (and the recorded measures where it has no history).
"""

from __future__ import annotations

import math
import time

from skcable._checks import positive, scalar
from skcable.errors import ConvergenceError, InputError

__all__ = ["Budget", "checked_budget"]


def checked_budget(max_iter, time_limit) -> tuple[float, float]:
    """``(max_iter, time_limit)`` checked: an integer >= 1 (or None: no count) and seconds > 0."""
    if max_iter is not None and (
        isinstance(max_iter, bool)
        or not isinstance(max_iter, int | float)
        or max_iter != int(max_iter)
        or max_iter < 1
    ):
        raise InputError("max_iter", f"must be an integer >= 1, got {max_iter!r}")
    limit = scalar("time_limit", positive("time_limit", time_limit))
    return (math.inf if max_iter is None else int(max_iter)), limit


class Budget:
    """``max_calls`` evaluations and ``time_limit`` seconds from now (module docstring)."""

    class Spent(Exception):
        """The budget is spent (caught by the search's entry point only)."""

    def __init__(self, max_calls: float = math.inf, time_limit: float = math.inf):
        self.max_calls, self.time_limit = max_calls, time_limit
        self.deadline = time.monotonic() + time_limit
        self.calls = 0
        self.history: list[float] = []
        self.best: tuple[float, object] = (math.inf, None)
        self.best_rank: object = None

    def left(self) -> float:
        """Seconds left before the deadline (s), at least 0."""
        return max(0.0, self.deadline - time.monotonic())

    def spend(self) -> None:
        """Count one evaluation; `Spent` past the count or the deadline."""
        if self.calls >= self.max_calls or time.monotonic() > self.deadline:
            raise Budget.Spent
        self.calls += 1

    def record(self, measure: float, point, rank=0) -> None:
        """Remember an evaluation's ``measure`` (smaller is better) and its ``point``: the best
        point is the one of the highest ``rank`` (any ordered value: a line BVP's solve free of
        compression, then on a finer mesh, then later), of the smallest measure among equal
        ranks."""
        self.history.append(float(measure))
        better = measure < self.best[0]
        if self.best_rank is not None and rank != self.best_rank:
            better = rank > self.best_rank
        if better:
            self.best, self.best_rank = (float(measure), point), rank

    def run(self, what: str, unit: str, search, *args):
        """``search(*args)`` within the budget (module docstring)."""
        try:
            return search(*args)
        except Budget.Spent:
            raise self.error(what, unit) from None
        except ConvergenceError as failed:
            if failed.last is None:
                failed.last = self.best[1]
            if not failed.history:
                failed.history = list(self.history)
            raise

    def error(self, what: str, unit: str = "evaluations") -> ConvergenceError:
        """The `ConvergenceError` of a search out of budget: ``what`` found nothing within it."""
        count = "" if self.max_calls == math.inf else f"max_iter = {self.max_calls} {unit} or "
        return ConvergenceError(
            f"{what}: nothing within {count}time_limit = {self.time_limit:g} s ({self.calls} {unit}; the "
            f"best point reached, error.last, measures {self.best[0]:.3g})",
            self.history,
            last=self.best[1],
        )
