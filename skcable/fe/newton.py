r"""One Newton–Raphson iteration for every nonlinear problem of skcable.

The problem gives callables, the solver is generic (as in FElupe's
``newtonrhapson`` and DOLFINx's ``NonlinearProblem``):

- ``assemble(x) -> state``: residual, tangent and whatever else the problem
  wants to keep, at the iterate ``x``;
- ``norm(state) -> float``: the convergence measure (dimensionless, e.g. the
  largest residual entry over a force scale); converged when ``< tol``, or when
  ``absolute(state) < atol`` (an absolute measure, e.g. in N) if both are given;
- ``increment(state) -> dx``: the Newton increment (the problem solves its own
  linear system, bordered or banded as it needs).

Each increment is damped by backtracking on ``merit`` (``norm`` unless given):
a trial ``x + t·dx`` is accepted when ``merit`` falls by the Armijo factor
``1 − 10⁻⁴ t`` (or the trial has converged), halving ``t`` up to
``max_halvings`` times; ``line_search=False`` takes every full step (a plain, or
semismooth, Newton). The iteration stops at once, with a `ConvergenceError`
carrying the history, when no step length gives descent or when the residual
*stagnates*: ``norm`` has not fallen below ``stagnation_factor`` times its value
``stagnation_window`` iterations earlier, or two iterations earlier once it is below
1e-12, the round-off floor of a residual relative to its force scale (a converging
Newton gains far more than that per iteration; one that crawls is either at the
round-off floor of a near-singular tangent or off the path, and more iterations only
cost assemblies).

``callback(iteration, residual_norm, step_norm)`` is called after every accepted
step (``step_norm`` the largest entry of the step taken); an exception it raises
stops the solve as an `InputError` naming ``callback`` and the iteration.

Two options serve problems whose residual is itself the output of an inner
solve (a catenary's closure inside a tension section, say): ``rejects`` lists
the exceptions a trial's ``assemble`` may raise, such a trial being rejected
like an inadmissible one (the step is halved); ``floor(state)`` is the
round-off floor of ``norm`` that the inner solves put on it, and a Newton that
stops (no descent, stagnation) with ``norm <= floor`` returns its iterate with
``NewtonResult.at_floor`` set instead of raising.

**Fallbacks.** A semismooth system (a contact's complementarity rows) can refuse every damped
step from a start where full steps identify the active set and converge: its max-norm merit
rises while the active set changes. ``full_steps="after"`` then tries full Newton steps from
the same start (its assembly reused) when the damped Newton fails; ``full_steps="first"`` tries
them first (a start near the solution, a warm start, whose active set full steps identify in a
few iterations where damped ones crawl; full semismooth steps converge superlinearly near a
solution: L. Qi, J. Sun, "A nonsmooth version of Newton's method", Math. Programming 58, 1993)
and the damped Newton where they fail. A full step is halved only where its trial is
inadmissible, one of ``rejects`` or not finite; the full steps stop where ``norm`` grows a
thousandfold past the start, or after ``max_iter`` steps (``full_max_iter`` if given). Without a
line search the Newton takes full steps already: no second attempt. ``rescue(failed)``, tried
before the full steps "after", is the problem's own way on from where the damped Newton
stopped (``failed.last``; a line on the seabed holds its contact nodes' active set): a
`NewtonResult` whose history starts there, or None. When every attempt fails, the damped
Newton's `ConvergenceError` is raised, its ``attempts`` holding every attempt's history in the
order tried. With ``active(state)``, a fingerprint of the non-smooth terms' active sets, the
full-step attempt is the active-set iteration `semismooth` instead (a step that changes the
active set is progress whatever the residual does; stopped at a cycle), tried also without a
line search, ``full_max_iter`` steps at most (a strand's contact and slip laws). Past ``tol``,
``polish`` full steps at most go on while ``norm`` falls below
``polish_factor`` times the last: quadratic convergence takes the solution to its round-off
floor for one or two more assemblies. ``callback`` sees every step of every attempt, numbered
from 1 in each.

`first_converged(attempts)` is the other retry: the same problem from other starts, or other
problems (finer meshes, a node at a touchdown), in turn, the first one's error raised when all
fail.

`NewtonOptions` gathers the user's settings (tolerances, iterations, line search,
callback, the shift limit of `minimize`) for the models that run these solvers.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, fields, replace
from typing import Any

import numpy as np

from skcable._checks import nonnegative, one_of, positive, whole
from skcable.errors import ConvergenceError, InputError

__all__ = [
    "FULL_STEPS", "LINE_SEARCHES", "NewtonOptions", "NewtonResult", "first_converged", "linear_tail",
    "minimize", "newton", "semismooth",
]  # fmt: skip

#: ``line_search`` values: on (Armijo on the residual's merit), off (full steps), or on the energy
LINE_SEARCHES = ("residual", "none", "energy", "auto")

#: ``newton``'s ``full_steps`` values: no full-step attempt, one after a failed damped Newton, one first
FULL_STEPS = ("never", "after", "first")


@dataclass(frozen=True)
class NewtonOptions:
    """A user's settings of a model's Newton solves.

    Parameters
    ----------
    tol : float
        Relative tolerance: converged when every residual entry is below ``tol`` times the
        force scale of its equations (the model's loads and reactions there).
    atol : float
        Absolute tolerance (in the residual's units, N for forces), 0 for none: converged
        also when every residual entry is below ``atol``.
    max_iter : int
        Newton iterations at most per solve.
    line_search : {"auto", "residual", "energy", "none"} or bool
        ``"residual"`` (or True): backtracking on the residual norm; ``"energy"``: Armijo on
        the model's energy (it must have one); ``"none"`` (or False): full Newton steps;
        ``"auto"``: the energy where every term has a potential, the residual otherwise.
    callback : callable, optional
        ``callback(iteration, residual_norm, step_norm)`` after every accepted step.
    max_halvings : int
        Halvings of a step in the line search at most.
    stagnation_window : int
        Iterations over which the residual must at least halve (else the solve stops).
    mu_max : float
        Largest shift of a tangent that is not positive definite (energy minimisation).
    """

    tol: float = 1e-9
    atol: float = 0.0
    max_iter: int = 25
    line_search: str | bool = "auto"
    callback: Callable | None = None
    max_halvings: int = 12
    stagnation_window: int = 4
    mu_max: float = 1.0

    def __post_init__(self):
        positive("tol", self.tol)
        nonnegative("atol", self.atol)
        whole("max_iter", self.max_iter, 1)
        whole("max_halvings", self.max_halvings, 0, 60)
        whole("stagnation_window", self.stagnation_window, 1)
        positive("mu_max", self.mu_max)
        search = self.line_search
        if isinstance(search, bool):
            object.__setattr__(self, "line_search", "residual" if search else "none")
        elif search not in LINE_SEARCHES:
            raise InputError("line_search", f"must be one of {LINE_SEARCHES} or a bool, got {search!r}")
        if self.callback is not None and not callable(self.callback):
            raise InputError(
                "callback", f"must be callable(iteration, residual_norm, step_norm), got {self.callback!r}"
            )

    @classmethod
    def of(cls, options=None, **given) -> NewtonOptions:
        """Options from a `NewtonOptions` (or None) updated by the keywords given (None skipped);
        an unknown keyword is an `InputError` naming it."""
        base = cls() if options is None else options
        if not isinstance(base, cls):
            raise InputError("options", f"must be a NewtonOptions, got {options!r}")
        if not given:
            return base
        names = {f.name for f in fields(cls)}
        for key in given:
            if key not in names:
                raise InputError(key, f"is not a Newton option (options are {sorted(names)})")
        changes = {k: v for k, v in given.items() if v is not None}
        return replace(base, **changes) if changes else base


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
    steps : list of float
        Step length ``t`` of every accepted iteration (1 is a full Newton step).
    """

    x: np.ndarray
    state: Any
    history: list = field(default_factory=list)
    assemblies: int = 0
    shifted: bool = False
    at_floor: bool = False
    steps: list = field(default_factory=list)

    @property
    def iterations(self) -> int:
        return len(self.history) - 1

    def linear_rate(self, tol: float, full_steps: bool = True) -> list[float] | None:
        """The contraction ratios of the last steps if this converged *linearly*, else None.

        Newton with a consistent tangent converges quadratically once the residual is small:
        ``r_{k+1} ≤ C r_k²``, so successive ratios ``r_{k+1}/r_k`` fall fast. A wrong tangent
        gives a constant ratio instead (`linear_tail`), here over the steps taken below a
        residual of 1e-2, none of them limited by the round-off floor (1e3·tol below): the full
        steps only, or (``full_steps=False``) every step, whatever the line search cut (a wrong
        tangent whose every step the line search halves converges linearly too).
        """
        r, t = self.history, self.steps
        ratios = [
            r[k + 1] / r[k]
            for k in range(len(r) - 1)
            if (t[k] == 1.0 or not full_steps) and 0 < r[k] < 1e-2 and r[k + 1] > 1e-3 * tol
        ]
        return linear_tail(ratios)


def linear_tail(ratios) -> list[float] | None:
    """The last three contraction ratios ``r_{k+1}/r_k`` if they show linear convergence (each in
    [0.02, 0.95], within a factor 4 of one another), else None."""
    tail = list(ratios)[-3:]
    if len(tail) < 3 or not all(0.02 <= q <= 0.95 for q in tail) or max(tail) > 4 * min(tail):
        return None
    return tail


def _convergence(tol, atol, absolute):
    """The test ``converged(state, norm)``: ``norm < tol``, or ``absolute(state) < atol`` where given."""

    def converged(s, value):
        return value < tol or (atol > 0 and absolute is not None and absolute(s) < atol)

    return converged


def _callback(callback, iteration, current, step):
    if callback is None:
        return
    try:
        callback(iteration, current, step)
    except Exception as exc:  # a user's callback: stop, and say where
        raise InputError("callback", f"raised {type(exc).__name__} at iteration {iteration}: {exc}") from exc


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
    atol: float = 0.0,
    absolute: Callable[[Any], float] | None = None,
    line_search: bool = True,
    callback: Callable | None = None,
    nonmonotone: int = 0,
    watchdog: int = 0,
    full_steps: str = "never",
    rescue: Callable[[ConvergenceError], NewtonResult | None] | None = None,
    polish: int = 0,
    polish_factor: float = 0.1,
    active: Callable[[Any], Any] | None = None,
    full_max_iter: int | None = None,
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
    atol, absolute : float, callable, optional
        Converged also when ``absolute(state) < atol``.
    line_search : bool
        Backtrack on ``merit`` (True) or take every full step (False; only a step to an
        inadmissible or rejected trial is halved).
    callback : callable, optional
        ``callback(iteration, residual_norm, step_norm)`` after every accepted step.
    nonmonotone : int
        0: a trial must lower ``merit`` below the current one. ``m > 0``: below the largest of
        the last ``m`` (the non-monotone rule of L. Grippo, F. Lampariello, S. Lucidi, "A
        nonmonotone line search technique for Newton's method", SIAM J. Numer. Anal., 1986),
        which lets a semismooth Newton step through the transients of an active set that is
        still being identified (its residual rises and falls) while keeping it from running off.
    watchdog : int
        Relaxed steps a solve may take (the watchdog technique of R.M. Chamberlain, M.J.D. Powell,
        C. Lemarechal, H.C. Pedersen, "The watchdog technique for forcing convergence in
        algorithms for constrained optimization", Math. Programming Study 16, 1982; J. Nocedal,
        S.J. Wright, "Numerical Optimization", 2006, §15.6): a full step whose merit does not
        fall is taken anyway, and the full step from there is judged against the point before
        it. If its merit is below that point's by the Armijo factor, the iteration goes on from
        it; otherwise it returns to that point and backtracks along its step from ``t = 1/2``
        (the relaxed iteration is dropped from the history; ``callback`` has seen it). A Newton
        whose full step overshoots a hardening problem's solution (a mooring pulled from rest)
        lands on the stiff side instead of halving back to the soft one, and a solve where the
        relaxed step leads nowhere pays one assembly more than without it.

    full_steps : {"never", "after", "first"}
        The full-step attempt from ``x0`` (module docstring, *Fallbacks*); none where
        ``line_search`` is False.
    rescue : callable, optional
        ``rescue(failed)`` (*Fallbacks*): a `NewtonResult` whose history starts at
        ``failed.last`` (joined to ``failed.history``), or None.
    polish, polish_factor : int, float
        Full Newton steps past ``tol`` at most, while ``norm`` falls below ``polish_factor``
        times the last (a trial one of ``rejects`` stops them).
    active : callable, optional
        ``active(state)`` (*Fallbacks*): the full-step attempt is `semismooth`, tried also where
        ``line_search`` is False; its steps are ``x + dx`` (no ``update``, no ``admissible``).
    full_max_iter : int, optional
        Iterations at most of the full-step attempt (default ``max_iter``).

    Raises
    ------
    ConvergenceError
        No descent, stagnation, or ``max_iter`` reached (above ``floor``, when given);
        ``history`` holds ``norm`` per iteration. With fallbacks, the damped Newton's error
        when every attempt fails, ``attempts`` holding the history of each in the order tried.
    InputError
        ``callback`` raised (the iteration is named), ``full_steps`` is none of
        `FULL_STEPS`, or ``active`` is given with ``update`` or ``admissible``.
    """
    one_of("full_steps", full_steps, FULL_STEPS)
    if active is not None and (update is not None or admissible is not None):
        raise InputError("active", "takes the steps x + dx: it cannot be given with update or admissible")
    update = _plain_update if update is None else update
    damped = functools.partial(
        _damped, norm=norm, increment=increment, tol=tol, max_iter=max_iter,
        merit=norm if merit is None else merit, update=update, admissible=admissible,
        max_halvings=max_halvings, stagnation_window=stagnation_window,
        stagnation_factor=stagnation_factor, name=name, rejects=rejects, floor=floor, atol=atol,
        absolute=absolute, line_search=line_search, callback=callback, nonmonotone=nonmonotone,
        watchdog=watchdog,
    )  # fmt: skip
    if not line_search and active is None:  # a Newton without line search takes full steps already
        full_steps = "never"
    if full_steps == "never" and rescue is None and not polish:
        return damped(assemble, x0, state=state)
    count = [0 if state is None else 1]  # the start counted, as the damped Newton counts it

    def counted(x):
        count[0] += 1
        return assemble(x)

    converged = _convergence(tol, atol, absolute)

    x = np.array(x0, dtype=float)
    start = counted(x) if state is None else state
    problem = _Problem(counted, norm, increment, update, admissible, rejects, converged, callback, name)
    full_iter = max_iter if full_max_iter is None else full_max_iter
    if active is None:
        full = functools.partial(problem.full_steps, x, start, full_iter, max_halvings)
    else:
        full = functools.partial(
            semismooth, counted, x, norm=norm, increment=increment, active=active, tol=tol,
            max_iter=full_iter, name=name, state=start, atol=atol, absolute=absolute,
            callback=callback, rejects=rejects,
        )  # fmt: skip
    result = _attempts(lambda: damped(counted, x, state=start), full, rescue, full_steps)
    result = problem.polished(result, polish, polish_factor)
    result.assemblies = count[0]
    return result


def _plain_update(x, dx, t):
    """The trial ``x + t·dx`` (`newton`'s default ``update``)."""
    return x + t * dx


def _attempts(damped, full, rescue, order: str) -> NewtonResult:
    """`newton`'s attempts (module docstring, *Fallbacks*): full steps first (``order`` "first"),
    the damped Newton, the ``rescue`` from where it stopped, full steps (``order`` "after");
    the first that converges, else the damped Newton's error with ``attempts`` set."""
    tried = []
    if order == "first":
        try:
            return full()
        except ConvergenceError as exc:
            tried.append(exc.history)
    try:
        return damped()
    except ConvergenceError as exc:
        failed = exc
    tried.append(failed.history)
    if rescue is not None:
        rescued = rescue(failed)
        if rescued is not None:
            rescued.history = list(failed.history) + list(rescued.history[1:])
            return rescued
    if order == "after":
        try:
            return full()
        except ConvergenceError as exc:
            tried.append(exc.history)
    failed.attempts = [list(h) for h in tried]
    raise failed from None


class _Problem:
    """A problem's callables as `newton`'s fallbacks and polish use them."""

    def __init__(self, assemble, norm, increment, update, admissible, rejects, converged, callback, name):
        self.assemble, self.norm, self.increment, self.update = assemble, norm, increment, update
        self.admissible, self.rejects, self.converged = admissible, rejects, converged
        self.callback, self.name = callback, name

    def trial(self, x, dx, t):
        """``(trial x, its state)``, the state None where the trial is inadmissible or rejected."""
        trial_x = self.update(x, dx, t)
        if self.admissible is not None and not self.admissible(trial_x):
            return trial_x, None
        try:
            return trial_x, self.assemble(trial_x)
        except self.rejects:
            return trial_x, None

    def full_steps(self, x, state, max_iter: int, max_halvings: int) -> NewtonResult:
        """Full Newton steps from ``x`` (``state`` its assembly), each halved (``max_halvings``
        times at most) only where its trial is inadmissible, rejected or not finite; stopped where
        ``norm`` grows a thousandfold past its start or no trial is found. The `NewtonResult`
        once converged within ``max_iter`` steps, else a `ConvergenceError` with the history."""
        history, steps = [self.norm(state)], []
        for _ in range(max_iter):
            if self.converged(state, history[-1]) or not history[-1] < 1e3 * history[0]:
                break
            dx, t = self.increment(state), 1.0
            for _ in range(max_halvings):
                trial_x, trial = self.trial(x, dx, t)
                if trial is not None and np.isfinite(self.norm(trial)):
                    break
                t *= 0.5
            else:
                break
            x, state = trial_x, trial
            history.append(self.norm(state))
            steps.append(t)
            if self.callback is not None:
                step = float(np.max(np.abs(t * dx), initial=0.0))
                _callback(self.callback, len(history) - 1, history[-1], step)
        if self.converged(state, history[-1]):
            return NewtonResult(x, state, history, steps=steps)
        raise ConvergenceError(f"{self.name}: full Newton steps did not converge", history, last=x)

    def polished(self, result: NewtonResult, steps: int, factor: float) -> NewtonResult:
        """``result`` taken on by full Newton steps past the tolerance, ``steps`` at most, while
        ``norm`` falls below ``factor`` times the last; a trial one of ``rejects`` stops them."""
        for _ in range(steps):
            dx = self.increment(result.state)
            trial_x = self.update(result.x, dx, 1.0)
            try:
                trial = self.assemble(trial_x)
            except self.rejects:
                break
            value = self.norm(trial)
            if not value < factor * self.norm(result.state):
                break
            result.x, result.state = trial_x, trial
            result.history.append(value)
            result.steps.append(1.0)
            _callback(self.callback, len(result.history) - 1, value, float(np.max(np.abs(dx), initial=0.0)))
        return result


def first_converged(
    attempts: Iterable[Callable[[], Any]], *, catch: tuple[type[Exception], ...] = (ConvergenceError,)
):
    """The result of the first of ``attempts`` (callables of no argument, called in turn: a
    generator's are made only as they are reached) that raises none of ``catch``; where every one
    does, the first one's error (the later ones only try to rescue it). Other exceptions pass at
    once.

    The retries of a solve from other starts or on other meshes: a line from the previous
    solution interpolated, else from its closed form; a mooring from its start pushed along the
    net load. A Newton's own fallbacks from the same start are `newton`'s options
    (``full_steps``, ``rescue``).

    Raises
    ------
    InputError
        ``attempts`` is empty.
    """
    first = None
    for attempt in attempts:
        try:
            return attempt()
        except catch as exc:
            first = exc if first is None else first
    if first is None:
        raise InputError("attempts", "must hold at least one attempt")
    raise first from None


def _damped(
    assemble, x0, *, norm, increment, tol, max_iter, merit, update, admissible, max_halvings,
    stagnation_window, stagnation_factor, name, state, rejects, floor, atol, absolute, line_search,
    callback, nonmonotone, watchdog,
) -> NewtonResult:  # fmt: skip
    """`newton`'s damped iteration from ``x0`` (its docstring; the fallbacks aside)."""
    converged = _convergence(tol, atol, absolute)

    def stop(message):
        if floor is not None and history[-1] <= floor(state):
            return NewtonResult(x, state, history, 1 + search.assemblies, at_floor=True, steps=steps)
        raise ConvergenceError(f"{name}: {message}", history, last=x)

    search = _LineSearch(assemble, update, admissible, rejects, merit, lambda s: converged(s, norm(s)),
                         line_search, max_halvings)  # fmt: skip
    x = np.array(x0, dtype=float)
    state = assemble(x) if state is None else state
    history, merits = [norm(state)], []
    steps: list[float] = []
    relaxed, saved = 0, None  # the watchdog's relaxed steps taken, and the point it returns to
    for _ in range(max_iter + 1):
        current = history[-1]
        if not np.isfinite(current):
            raise ConvergenceError(f"{name}: the residual is not finite", history, last=x)
        if converged(state, current):
            return NewtonResult(x, state, history, 1 + search.assemblies, steps=steps)
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
        merits.append(merit(state))
        base = max(merits[-nonmonotone:]) if nonmonotone else merits[-1]
        if saved is None:
            found = search(x, dx, base, 1.0, relaxed < watchdog)
        else:  # a full step from a relaxed one: below the point before it, or back there
            found = search.past(saved[1], search(x, dx, base, 1.0, True, halvings=0))
            if found is None:
                x, state, dx, base, kept = saved
                del history[kept:], steps[kept - 1 :], merits[kept:]
                increment(state)  # the problem's own record of the iterate it steps from
                found = search(x, dx, base, 0.5)
            saved = None
        if found is None:
            return stop("line search found no descent along the Newton step")
        if found[3]:  # a relaxed step: the point before it is where the watchdog returns
            relaxed += 1
            saved = (x, state, dx, base, len(history))
        x, state, t = found[0], found[1], found[2]
        history.append(norm(state))
        steps.append(t)
        if callback is not None:  # the step's norm is for the callback alone
            _callback(callback, len(history) - 1, history[-1], float(np.max(np.abs(t * dx), initial=0.0)))
    return stop(f"no convergence to {tol:g} in {max_iter} iterations")


def semismooth(
    assemble: Callable[[np.ndarray], Any],
    x0: np.ndarray,
    *,
    norm: Callable[[Any], float],
    increment: Callable[[Any], np.ndarray],
    active: Callable[[Any], Any],
    tol: float,
    max_iter: int = 100,
    name: str = "semismooth",
    state=None,
    atol: float = 0.0,
    absolute: Callable[[Any], float] | None = None,
    callback: Callable | None = None,
    rejects: tuple[type[Exception], ...] = (),
    growth: float = 1e6,
) -> NewtonResult:
    """A semismooth Newton with active sets (the primal–dual active-set method as a semismooth
    Newton: M. Hintermüller, K. Ito, K. Kunisch, SIAM J. Optim. 13, 2002): full steps on the
    generalized derivative, while ``active(state)`` (a hashable fingerprint of the non-smooth
    terms' active sets: where a contact presses, a law slips) tells the iterations apart.

    A step that changes the active set is progress whatever the residual does (the residual of a
    stiff penalty jumps by orders of magnitude as a contact zone grows node by node); the
    iteration stops, with a `ConvergenceError` carrying the history, when an active set comes
    back after others (a cycle), when a step within one active set raises the residual (its
    smooth part needs damping: a line-search Newton's job), when the residual grows ``growth``
    times beyond its start, or after ``max_iter`` iterations. ``norm``, ``increment``, ``tol``,
    ``atol``/``absolute``, ``callback``, ``rejects`` (a rejected step stops the iteration) as in
    `newton`.
    """
    converged = _convergence(tol, atol, absolute)

    x = np.array(x0, dtype=float)
    state = assemble(x) if state is None else state
    history, assemblies = [norm(state)], 1
    steps: list[float] = []
    previous = active(state)
    seen = {previous: 0}
    for k in range(max_iter + 1):
        current = history[-1]
        if not np.isfinite(current):
            raise ConvergenceError(f"{name}: the residual is not finite", history, last=x)
        if converged(state, current):
            return NewtonResult(x, state, history, assemblies, steps=steps)
        if k == max_iter:
            break
        if current > growth * history[0]:
            raise ConvergenceError(f"{name}: the residual grows (full steps diverge)", history, last=x)
        dx = increment(state)
        try:
            trial = assemble(x + dx)
        except rejects:
            raise ConvergenceError(
                f"{name}: a full step leaves the admissible states", history, last=x
            ) from None
        assemblies += 1
        key = active(trial)
        value = norm(trial)
        if key == previous and value >= current and not converged(trial, value):
            raise ConvergenceError(
                f"{name}: a step within one active set raises the residual", history + [value], last=x
            )
        if key in seen and seen[key] < k and key != previous:
            raise ConvergenceError(f"{name}: the active set cycles", history + [value], last=x)
        seen.setdefault(key, k + 1)
        previous = key
        x, state = x + dx, trial
        history.append(value)
        steps.append(1.0)
        _callback(callback, len(history) - 1, value, float(np.max(np.abs(dx), initial=0.0)))
    raise ConvergenceError(f"{name}: no convergence to {tol:g} in {max_iter} iterations", history, last=x)


class _LineSearch:
    """The backtracking of `newton` along a step: the problem's callables, and the assemblies."""

    def __init__(self, assemble, update, admissible, rejects, merit, done, line_search, max_halvings):
        self.assemble, self.update, self.admissible, self.rejects = assemble, update, admissible, rejects
        self.merit, self.done, self.line_search, self.max_halvings = merit, done, line_search, max_halvings
        self.assemblies = 0

    def __call__(self, x, dx, base, t=1.0, relax=False, halvings=None):
        """``(trial x, trial state, t, relaxed)`` of the step accepted from ``x`` along ``dx`` (from
        length ``t``, ``halvings`` at most), None where none is: a trial's merit below ``base`` by
        the Armijo factor, or converged; ``relax``: a full step that assembles and does not descend
        is taken as a relaxed one (the watchdog's)."""
        for _ in range((self.max_halvings if halvings is None else halvings) + 1):
            trial_x = self.update(x, dx, t)
            if self.admissible is None or self.admissible(trial_x):
                try:
                    trial = self.assemble(trial_x)
                except self.rejects:
                    trial = None
                self.assemblies += 1
                if trial is not None and (
                    not self.line_search or self.merit(trial) < (1.0 - 1e-4 * t) * base or self.done(trial)
                ):
                    return trial_x, trial, t, False
                if trial is not None and relax and t == 1.0 and np.isfinite(self.merit(trial)):
                    return trial_x, trial, t, True
            t *= 0.5
        return None

    def past(self, before, found):
        """``found`` (a step from a relaxed one) as a step taken where its merit is below the merit
        of ``before`` (the state before the relaxed step) by the Armijo factor, or converged; else
        None (the watchdog returns)."""
        if found is not None and (
            self.merit(found[1]) < (1.0 - 1e-4) * self.merit(before) or self.done(found[1])
        ):
            return (*found[:3], False)
        return None


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
    atol: float = 0.0,
    absolute: Callable[[Any], float] | None = None,
    callback: Callable | None = None,
    rejects: tuple[type[Exception], ...] = (),
) -> NewtonResult:
    r"""Newton for a problem with a potential Π (residual R = ∇Π, tangent K = ∇²Π), shifted where
    K is not positive definite: a Newton that passes the folds of a softening law.

    Per iteration: converged when ``norm < tol`` (or ``absolute < atol``); the increment
    ``d = −(K + μ K₀)⁻¹ R`` by a Cholesky factorisation (``solve(state, μ)``, which raises
    ``numpy.linalg.LinAlgError`` when the shifted tangent is not positive definite), with μ = 0
    (plain Newton) unless the factorisation fails or the residual stagnates (less than
    ``factor`` in ``window`` iterations): then μ starts at ``mu0`` and doubles until the
    factorisation succeeds, K₀ being the problem's own positive-definite metric (for a strand:
    its elastic tangent). d is then a descent direction of Π, and a step t = 1, ½, … is accepted
    by Armijo's rule on the energy, ``Π(x + t d) ≤ Π(x) + 10⁻⁴ t R·d``, or, where the energy
    change is at its round-off (``noise``·|Π|), by the residual falling; a full, unshifted step
    (the tangent positive definite) whose residual falls tenfold is Newton converging and is
    accepted as it is. After an accepted step
    μ shrinks fourfold (to 0 below ``mu0``); after a failed line search it grows tenfold. Gives
    up (ConvergenceError with the history) when μ exceeds ``mu_max``, when neither the residual
    nor the energy moves over ``window`` iterations, or after ``max_iter`` iterations.
    ``NewtonResult.shifted`` tells whether the shift was needed: the path passed a point where
    the tangent was not positive definite (a fold of the equilibrium path under the imposed
    data). ``callback`` and ``rejects`` (exceptions of a trial's ``assemble`` that reject it: the
    step is halved) as in `newton`. The energy of a state is asked for only where a test needs
    it (a Newton step that converges at once needs none): a model may compute it on demand.
    """
    converged = _convergence(tol, atol, absolute)

    def finite(value):
        if not np.isfinite(value):
            raise ConvergenceError(f"{name}: the energy is not finite", history, last=x)
        return value

    x = np.array(x0, dtype=float)
    state = assemble(x) if state is None else state
    assemblies = 1
    history, energies = [norm(state)], [_Once(energy, state)]
    steps: list[float] = []
    mu, shifted = 0.0, False
    for _ in range(max_iter + 1):
        current, Pi = history[-1], energies[-1]
        if not np.isfinite(current):
            raise ConvergenceError(f"{name}: the residual or the energy is not finite", history, last=x)
        if converged(state, current):
            return NewtonResult(x, state, history, assemblies, shifted, steps=steps)
        if len(history) > max_iter:
            break
        if len(history) > window and current > factor * history[-1 - window]:
            if abs(finite(Pi()) - finite(energies[-1 - window]())) <= noise * abs(Pi()):
                raise ConvergenceError(f"{name}: neither the residual nor the energy moves", history, last=x)
            if mu == 0.0:
                mu, shifted = mu0, True
        try:
            d, mu, more = _shifted_increment(solve, state, mu, mu0, mu_max)
        except np.linalg.LinAlgError:
            raise ConvergenceError(
                f"{name}: the tangent needs a shift above {mu_max:g} to be positive definite",
                history,
                last=x,
            ) from None
        shifted = shifted or more
        slope = float(gradient(state) @ d)
        step, tried = _energy_step(
            assemble, energy, norm, converged, x, d, lambda here=Pi: finite(here()), current, slope, halvings,
            noise, rejects, mu == 0.0,
        )  # fmt: skip
        assemblies += tried
        if step is not None:
            t, x, state, n_t = step
            history.append(n_t)
            energies.append(_Once(energy, state))
            steps.append(t if mu == 0.0 else 0.0)  # a shifted step is no Newton step
            mu = 0.0 if mu <= mu0 else mu / 4.0
            if callback is not None:
                _callback(callback, len(history) - 1, history[-1], float(np.max(np.abs(t * d), initial=0.0)))
        else:
            mu, shifted = (mu0 if mu == 0.0 else 10.0 * mu), True
            history.append(current)
            energies.append(Pi)
            steps.append(0.0)
    raise ConvergenceError(f"{name}: no convergence to {tol:g} in {max_iter} iterations", history, last=x)


def _shifted_increment(solve, state, mu: float, mu0: float, mu_max: float) -> tuple[np.ndarray, float, bool]:
    """``(d, mu, shifted)``: `minimize`'s increment ``solve(state, mu)``, the shift μ doubled
    (from ``mu0``) while the shifted tangent does not factorise; ``shifted`` if it had to grow.
    Raises ``numpy.linalg.LinAlgError`` once μ would exceed ``mu_max``."""
    shifted = False
    while True:
        try:
            return solve(state, mu), mu, shifted
        except np.linalg.LinAlgError:
            mu, shifted = (mu0 if mu == 0.0 else 2.0 * mu), True
            if mu > mu_max:
                raise


class _Once:
    """The energy of a state, computed on first use (`minimize` asks only where a test needs it)."""

    def __init__(self, energy, state):
        self.energy, self.state = energy, state
        self.value: float | None = None

    def __call__(self) -> float:
        if self.value is None:
            self.value = float(self.energy(self.state))
            self.state = None
        return self.value


def _energy_step(
    assemble, energy, norm, converged, x, d, Pi, current, slope, halvings, noise, rejects=(), newton=False
):
    """`minimize`'s line search along ``d``, t = 1, ½, … (its docstring): ``((t, x, state,
    norm), assemblies)`` of the accepted trial, or ``(None, halvings)`` when none is; ``Pi()``
    the energy at ``x``, asked for only when a trial has not converged; ``newton``: ``d`` is an
    unshifted Newton step, accepted in full where the residual falls tenfold."""
    t = 1.0
    for k in range(halvings):
        trial_x = x + t * d
        try:
            trial = assemble(trial_x)
        except rejects:
            t *= 0.5
            continue
        n_t = norm(trial)
        if converged(trial, n_t) or (newton and k == 0 and n_t <= 0.1 * current):
            return (t, trial_x, trial, n_t), k + 1  # accepted whatever its energy: tested first
        here = Pi()
        drop = energy(trial) - here
        if drop <= 1e-4 * t * slope or (abs(drop) <= noise * abs(here) and n_t < (1 - 1e-4 * t) * current):
            return (t, trial_x, trial, n_t), k + 1
        t *= 0.5
    return None, halvings
