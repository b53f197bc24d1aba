"""One solve of one discrete line, in the plane or in space: semismooth Newton, its fallbacks, the polish.

`solve_on(problem, z0, options)` runs `skcable.fe.newton` (damped by backtracking on the max-norm
merit, unless ``options.line_search`` is ``"none"``) from ``z0`` with the Newton options
(`skcable.fe.NewtonOptions`: ``tol``, ``atol``, ``max_iter``, ``max_halvings``,
``stagnation_window``, ``callback``) and its fallbacks (`skcable.fe.newton`, *Fallbacks*). The
max-norm merit of a semismooth system can refuse every damped step where full steps identify the
active set and converge: full steps are tried from the same start (``full_steps="after"``)
before the first failure is raised; from a start near the solution (a warm start, a refitted
touchdown: ``near``) full steps come first, the damped ones where they fail. A trial off a
seabed's grid (`skcable.mooring.bathymetry.OffGrid`) is a step too long. Past ``tol``, full
Newton steps go on while the merit still halves (``polish``, `POLISH` at most):
quadratic convergence takes the solution to its round-off floor for one or two more
assemblies; where full steps cycle between two active sets there, the polish goes on with the
active set held (`held_polish`). Where the damped Newton stops (no descent, stagnation) with
the line on the seabed, `frozen_steps` goes on from where it stopped with the active set held (the
``rescue``): a node on the seabed with no push (``λ = g = 0``, a touchdown at a node) makes the
semismooth Newton cycle between two active sets (the max-norm merit refuses both steps), and one
of them, held, is a smooth system whose solution meets the contact conditions to ``tol``.
``callback(iteration, residual_norm, step_norm)`` sees every step of them all, numbered from 1
in each solve (the fallback starts again from the start); an exception it raises stops the solve
as an `skcable.InputError` naming ``callback`` and the iteration.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from skcable.errors import ConvergenceError, InputError
from skcable.fe import NewtonOptions, NewtonResult, newton
from skcable.mooring.bathymetry import OffGrid

__all__ = [
    "FROZEN_STEPS",
    "HELD_FROM",
    "HELD_POLISH",
    "POLISH",
    "frozen_steps",
    "held_polish",
    "report",
    "solve_on",
]

#: Newton steps past rtol at most, while the merit halves
POLISH = 3

#: full Newton steps at most per active set held (`frozen_steps`)
FROZEN_STEPS = 8

#: the merit past which a converged solve's polish goes on with its active set held
#: (`held_polish`), in round-off floors (the solution's check allows 64 times the rounding too,
#: `LineFields.check`)
HELD_POLISH = 64.0
#: the merit, in Newton's tolerances, below which `held_polish` does not look: the floor costs
#: a pass over the element matrices, not worth it after every solve (at 1e-3 of the default
#: tolerance, 1e-13, 64 floors lie above it wherever the floor exceeds 1.6e-15)
HELD_FROM = 1e-3


def report(callback, iteration: int, merit: float, step) -> None:
    """``callback(iteration, merit, max |step|)``, if given; what it raises becomes an
    `InputError` naming ``callback`` and the iteration (as `skcable.fe.newton` does)."""
    if callback is None:
        return
    try:
        callback(iteration, merit, float(np.max(np.abs(step), initial=0.0)))
    except Exception as exc:  # a user's callback: stop, and say where
        raise InputError("callback", f"raised {type(exc).__name__} at iteration {iteration}: {exc}") from exc


def converged(problem, state, options: NewtonOptions) -> bool:
    """Whether ``state`` meets ``options.tol`` (the merit) or ``options.atol`` (the force rows, N,
    with the stretch rows within ``tol``)."""
    return state.merit < options.tol or (
        options.atol > 0 and problem.absolute(state, options.tol) < options.atol
    )


def _active_sets(problem, state):
    """The active sets `frozen_steps` holds: the iterate's, its full Newton step's, their union
    and their intersection (each once)."""
    here = state.terms.active
    trial = problem.assemble(state.z + problem.increment(state))
    there = here if trial.terms is None else trial.terms.active
    masks: list[np.ndarray] = []
    for mask in (here, there, here | there, here & there):
        if not any(np.array_equal(mask, seen) for seen in masks):
            masks.append(mask)
    return masks


def frozen_steps(problem, z, options: NewtonOptions, steps: int = FROZEN_STEPS):
    """Full Newton steps from ``z`` with the contact nodes' active set held
    (`LineProblem.with_active_set`), for each of `_active_sets` in turn, ``steps`` at most:
    (z, state, history) once the line's own residual (its true contact rows, ``min(λ, c g)``)
    meets ``options.tol`` (`converged`); None if no active set gets there or the line has no
    contact rows. ``history`` holds the true merit per step."""
    state = problem.assemble(z)
    if state.terms is None or not np.isfinite(state.merit):
        return None
    for mask in _active_sets(problem, state):
        held = problem.with_active_set(mask)
        zh, sh, history = z, held.assemble(z), [state.merit]
        for _ in range(steps):
            if not np.isfinite(sh.merit):
                break
            step = held.increment(sh)
            zh = zh + step
            sh, true = held.assemble(zh), problem.assemble(zh)
            history.append(true.merit)
            report(options.callback, len(history) - 1, true.merit, step)
            if converged(problem, true, options):
                return zh, true, history
    return None


def _rescue(problem, options: NewtonOptions):
    """`newton`'s ``rescue`` of a line: `frozen_steps` from where the damped Newton stopped, within
    the steps it left of ``max_iter`` (none where it ran out of them)."""

    def rescue(failed: ConvergenceError) -> NewtonResult | None:
        steps = min(FROZEN_STEPS, options.max_iter - (len(failed.history) - 1))
        out = None
        if failed.last is not None and steps > 0:
            out = frozen_steps(problem, failed.last, options, steps)
        return None if out is None else NewtonResult(out[0], out[1], out[2])

    return rescue


def solve_on(
    problem, z0, options: NewtonOptions, near: bool = False, name: str = "solve_line_bvp"
) -> NewtonResult:
    """The line of ``problem`` from the iterate ``z0`` (module docstring): damped Newton, else its
    rescue (`frozen_steps`, a line on the seabed), else full steps (the damped one's error
    raised when all fail; none where the Newton takes them already, ``line_search="none"``), then
    the polish (`held_polish` after it); ``near``: full steps first. ``name`` names the solve in
    its errors."""
    result = newton(
        problem.assemble,
        problem.placed(z0),
        norm=lambda state: state.merit,
        increment=problem.increment,
        tol=options.tol,
        max_iter=options.max_iter,
        max_halvings=options.max_halvings,
        stagnation_window=options.stagnation_window,
        name=name,
        floor=problem.merit_floor,
        atol=options.atol,
        absolute=lambda state: problem.absolute(state, options.tol),
        line_search=options.line_search != "none",
        callback=options.callback,
        rejects=(OffGrid,),
        full_steps="first" if near else "after",
        rescue=_rescue(problem, options),
        polish=POLISH,
        polish_factor=0.5,
    )
    return held_polish(problem, result, options)


def held_polish(problem, result: NewtonResult, options: NewtonOptions) -> NewtonResult:
    """``result`` taken on to its round-off floor with the contact nodes' active set held
    (`frozen_steps`, `POLISH` steps at most), where the polish stopped above ``HELD_POLISH`` times
    that floor (`DiscreteLine.merit_floor`) and above ``HELD_FROM`` times ``options.tol``;
    ``result`` as it is where no held set gets there.

    A node on the seabed with no push (``λ = g = 0``) makes full semismooth steps cycle between
    two active sets past ``tol`` too: the polish stops where the first of them raises the merit,
    and the solve returns at ``tol``, not at round-off. On a graded mesh that residual force, over
    an element of a fraction of a millimetre, is a residual per length far above the solution's
    check (`LineFields.check`, round-off): survey scene 2:243 on 128 elements stopped at a merit
    of 2.6e-11, and the check refused its 0.036 N/m against 1.2e-4 N/m
    (`benchmarks/line_bvp_planes.py`); one step with the active set held takes it to 1.6e-15."""
    state = result.state
    if state.terms is None or not state.merit > HELD_FROM * options.tol:  # the floor not worth its cost
        return result
    target = HELD_POLISH * problem.merit_floor(state)
    if not 0.0 < target < state.merit:
        return result
    out = frozen_steps(problem, result.x, replace(options, tol=target, atol=0.0), POLISH)
    if out is None:
        return result
    z, held, history = out
    steps = [*result.steps, *[1.0] * (len(history) - 1)]
    return NewtonResult(z, held, [*result.history, *history[1:]], result.assemblies, steps=steps)
