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

Two options serve problems whose residual is itself the output of an inner
solve (a catenary's closure inside a tension section, say): ``rejects`` lists
the exceptions a trial's ``assemble`` may raise, such a trial being rejected
like an inadmissible one (the step is halved); ``floor(state)`` is the
round-off floor of ``norm`` that the inner solves put on it, and a Newton that
stops (no descent, stagnation) with ``norm <= floor`` returns its iterate with
``NewtonResult.at_floor`` set instead of raising.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from skcable.errors import ConvergenceError

__all__ = ["NewtonResult", "minimize", "newton"]


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
    shifted : bool
        [`minimize`][skcable.fe.newton.minimize] only: the tangent needed a shift somewhere.
    at_floor : bool
        [`newton`][skcable.fe.newton.newton] with ``floor`` only: it stopped above ``tol``
        at the round-off floor ``floor(state)`` of the residual.
    """

    x: np.ndarray
    state: Any
    history: list = field(default_factory=list)
    assemblies: int = 0
    shifted: bool = False
    at_floor: bool = False

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
    rejects: tuple[type[Exception], ...] = (),
    floor: Callable[[Any], float] | None = None,
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
    rejects : tuple of exception types
        Raised by ``assemble`` at a trial iterate: the trial is rejected (the step halved).
    floor : callable, optional
        ``floor(state)``: the round-off floor of ``norm``; a stop at or below it returns.

    Raises
    ------
    ConvergenceError
        No descent, stagnation, or ``max_iter`` reached (above ``floor``, when given);
        ``history`` holds ``norm`` per iteration.
    """
    merit = norm if merit is None else merit

    def stop(message):
        if floor is not None and history[-1] <= floor(state):
            return NewtonResult(x, state, history, assemblies, at_floor=True)
        raise ConvergenceError(f"{name}: {message}", history)

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
        at_round_off = current < 1e-12 and len(history) > 2 and current > stagnation_factor * history[-3]
        if at_round_off or (back >= 0 and current > stagnation_factor * history[back]):
            return stop(
                f"the residual stagnates (less than a factor {1 / stagnation_factor:g} "
                f"in {stagnation_window} iterations)"
            )
        dx = increment(state)
        base, t = merit(state), 1.0
        for _ in range(max_halvings + 1):
            trial_x = update(x, dx, t)
            if admissible is None or admissible(trial_x):
                try:
                    trial = assemble(trial_x)
                except rejects:
                    trial = None
                assemblies += 1
                if trial is not None and (merit(trial) < (1.0 - 1e-4 * t) * base or norm(trial) < tol):
                    break
            t *= 0.5
        else:
            return stop("line search found no descent along the Newton step")
        x, state = trial_x, trial
        history.append(norm(state))
    return stop(f"no convergence to {tol:g} in {max_iter} iterations")


def minimize(
    assemble: Callable[[np.ndarray], Any],
    x0: np.ndarray,
    *,
    norm: Callable[[Any], float],
    energy: Callable[[Any], float],
    gradient: Callable[[Any], np.ndarray],
    solve: Callable[[Any, float], np.ndarray],
    tol: float,
    max_iter: int = 40,
    mu0: float = 1e-6,
    mu_max: float = 1.0,
    halvings: int = 8,
    window: int = 3,
    factor: float = 0.5,
    noise: float = 1e-12,
    name: str = "minimize",
    state=None,
) -> NewtonResult:
    r"""Newton for a problem with a potential Π (residual R = ∇Π, tangent K = ∇²Π), shifted where
    K is not positive definite: a Newton that passes the folds of a softening law.

    Per iteration: converged when ``norm < tol``; the increment ``d = −(K + μ K₀)⁻¹ R`` by a
    Cholesky factorisation (``solve(state, μ)``, which raises ``numpy.linalg.LinAlgError`` when
    the shifted tangent is not positive definite), with μ = 0 (plain Newton) unless the
    factorisation fails or the residual stagnates (less than ``factor`` in ``window``
    iterations): then μ starts at ``mu0`` and doubles until the factorisation succeeds, K₀ being
    the problem's own positive-definite metric (for a strand: its elastic tangent). d is then a
    descent direction of Π, and a step t = 1, ½, … is accepted by Armijo's rule on the energy,
    ``Π(x + t d) ≤ Π(x) + 10⁻⁴ t R·d``, or, where the energy change is at its round-off
    (``noise``·|Π|), by the residual falling. After an accepted step μ shrinks fourfold (to 0
    below ``mu0``); after a failed line search it grows tenfold. Gives up (ConvergenceError with
    the history) when μ exceeds ``mu_max``, when neither the residual nor the energy moves over
    ``window`` iterations, or after ``max_iter`` iterations. ``NewtonResult.shifted`` tells
    whether the shift was needed: the path passed a point where the tangent was not positive
    definite (a fold of the equilibrium path under the imposed data).
    """
    x = np.array(x0, dtype=float)
    state = assemble(x) if state is None else state
    assemblies = 1
    history, energies = [norm(state)], [energy(state)]
    mu, shifted = 0.0, False
    for _ in range(max_iter + 1):
        current, Pi = history[-1], energies[-1]
        if not (np.isfinite(current) and np.isfinite(Pi)):
            raise ConvergenceError(f"{name}: the residual or the energy is not finite", history)
        if current < tol:
            return NewtonResult(x, state, history, assemblies, shifted)
        if len(history) > max_iter:
            break
        if len(history) > window and current > factor * history[-1 - window]:
            if abs(Pi - energies[-1 - window]) <= noise * abs(Pi):
                raise ConvergenceError(f"{name}: neither the residual nor the energy moves", history)
            if mu == 0.0:
                mu, shifted = mu0, True
        while True:
            try:
                d = solve(state, mu)
                break
            except np.linalg.LinAlgError:
                mu, shifted = (mu0 if mu == 0.0 else 2.0 * mu), True
                if mu > mu_max:
                    raise ConvergenceError(
                        f"{name}: the tangent needs a shift above {mu_max:g} to be positive definite", history
                    ) from None
        R = gradient(state)
        slope = float(R @ d)
        t, accepted = 1.0, False
        for _ in range(halvings):
            trial_x = x + t * d
            trial = assemble(trial_x)
            assemblies += 1
            drop = energy(trial) - Pi
            n_t = norm(trial)
            if (
                n_t < tol
                or drop <= 1e-4 * t * slope
                or (abs(drop) <= noise * abs(Pi) and n_t < (1 - 1e-4 * t) * current)
            ):
                accepted = True
                break
            t *= 0.5
        if accepted:
            x, state = trial_x, trial
            history.append(n_t)
            energies.append(energy(state))
            mu = 0.0 if mu <= mu0 else mu / 4.0
        else:
            mu, shifted = (mu0 if mu == 0.0 else 10.0 * mu), True
            history.append(current)
            energies.append(Pi)
    raise ConvergenceError(f"{name}: no convergence to {tol:g} in {max_iter} iterations", history)
