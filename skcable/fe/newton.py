r"""One Newton–Raphson iteration for every nonlinear problem of skcable.

The problem gives callables, the solver is generic (as in FElupe's
``newtonrhapson`` and DOLFINx's ``NonlinearProblem``):

- ``assemble(x) -> state``: residual, tangent and whatever else the problem
  wants to keep, at the iterate ``x``;
- ``norm(state) -> float``: the convergence measure (dimensionless, e.g. the
  largest residual entry over a force scale); converged when ``< tol``;
- ``increment(state) -> dx``: the Newton increment (the problem solves its own
  linear system, bordered or banded as it needs).

Each increment is damped by backtracking on ``merit`` (``norm`` unless given):
a trial ``x + t·dx`` is accepted when ``merit`` falls by the Armijo factor
``1 − 10⁻⁴ t`` (or the trial has converged), halving ``t`` up to
``max_halvings`` times. The iteration stops at once, with a
`ConvergenceError` carrying the history, when no step
length gives descent or when the residual *stagnates*: ``norm`` has not fallen
below ``stagnation_factor`` times its value ``stagnation_window`` iterations
earlier, or two iterations earlier once it is below 1e-12, the round-off floor of a
residual relative to its force scale (a converging Newton gains far more than that per iteration; one
that crawls is either at the round-off floor of a near-singular tangent or
off the path, and more iterations only cost assemblies).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from skcable.errors import ConvergenceError

__all__ = ["NewtonResult", "newton"]


@dataclass
class NewtonResult:
    """A converged Newton solve.

    Attributes
    ----------
    x : ndarray
        The solution.
    state : object
        What ``assemble`` returned at ``x``.
    history : list of float
        ``norm`` at the start and after every iteration.
    assemblies : int
        Calls of ``assemble`` (line-search trials included).
    """

    x: np.ndarray
    state: Any
    history: list = field(default_factory=list)
    assemblies: int = 0

    @property
    def iterations(self) -> int:
        return len(self.history) - 1


def newton(
    assemble: Callable[[np.ndarray], Any],
    x0: np.ndarray,
    *,
    norm: Callable[[Any], float],
    increment: Callable[[Any], np.ndarray],
    tol: float,
    max_iter: int = 25,
    merit: Callable[[Any], float] | None = None,
    update: Callable[[np.ndarray, np.ndarray, float], np.ndarray] | None = None,
    admissible: Callable[[np.ndarray], bool] | None = None,
    max_halvings: int = 12,
    stagnation_window: int = 4,
    stagnation_factor: float = 0.5,
    name: str = "newton",
    state=None,
) -> NewtonResult:
    """Solve ``R(x) = 0`` from ``x0``; see the module docstring.

    Parameters
    ----------
    assemble, norm, increment : callable
        The problem (module docstring).
    tol : float
        Converged when ``norm(state) < tol``.
    max_iter : int
        Newton iterations at most.
    merit : callable, optional
        Line-search merit of a state (default ``norm``).
    update : callable, optional
        ``update(x, dx, t)`` → the trial iterate (default ``x + t·dx``).
    admissible : callable, optional
        Trials for which it is False are not assembled; the step is halved.
    max_halvings, stagnation_window, stagnation_factor
        Line search and stagnation rule (module docstring).
    name : str
        Prefix of error messages.
    state : object, optional
        ``assemble(x0)`` if the caller has it already.

    Raises
    ------
    ConvergenceError
        No descent, stagnation, or ``max_iter`` reached; ``history`` holds ``norm`` per iteration.
    """
    merit = norm if merit is None else merit
    update = (lambda x, dx, t: x + t * dx) if update is None else update
    x = np.array(x0, dtype=float)
    state = assemble(x) if state is None else state
    assemblies = 1
    history = [norm(state)]
    for _ in range(max_iter + 1):
        current = history[-1]
        if not np.isfinite(current):
            raise ConvergenceError(f"{name}: the residual is not finite", history)
        if current < tol:
            return NewtonResult(x, state, history, assemblies)
        if len(history) > max_iter:
            break
        back = len(history) - 1 - stagnation_window
        # at the round-off floor of a relative residual (below 1e-12) two iterations are enough to tell
        floor = current < 1e-12 and len(history) > 2 and current > stagnation_factor * history[-3]
        if floor or (back >= 0 and current > stagnation_factor * history[back]):
            raise ConvergenceError(
                f"{name}: the residual stagnates (less than a factor {1 / stagnation_factor:g} "
                f"in {stagnation_window} iterations)",
                history,
            )
        dx = increment(state)
        base, t = merit(state), 1.0
        for _ in range(max_halvings + 1):
            trial_x = update(x, dx, t)
            if admissible is None or admissible(trial_x):
                trial = assemble(trial_x)
                assemblies += 1
                if merit(trial) < (1.0 - 1e-4 * t) * base or norm(trial) < tol:
                    break
            t *= 0.5
        else:
            raise ConvergenceError(f"{name}: line search found no descent along the Newton step", history)
        x, state = trial_x, trial
        history.append(norm(state))
    raise ConvergenceError(f"{name}: no convergence to {tol:g} in {max_iter} iterations", history)
