r"""The static equilibrium of a moored body: Newton's method, a start from slack lines, stability.

At body position :math:`\mathbf q` the net generalised force :math:`\mathbf G(\mathbf q)` on the
body (`skcable.mooring.system`) vanishes at equilibrium. Newton's method runs with the
analytic Jacobian :math:`\partial\mathbf G/\partial\mathbf q = -K\,T` (``K`` the stiffness of the
mooring system and the body, ``T`` the map of Euler-angle increments to rotation vectors),
each step capped at a quarter of the shortest anchor radius and 0.2 rad, backtracking on
the net load over a scale that holds for the solve (the body's loads and the largest line
tension of the iterates so far), converged where the net load over the state's own scale (its
line tension, at least the body's loads) is below ``tol`` (`skcable.fe.newton`).

**Slack lines.** Where the lines lie slack on the seabed (their slack in a heap, ``H = 0``)
the stiffness has no horizontal term: :math:`K` is singular and Newton has no step. The
free directions are the null space of the scaled Jacobian (singular values below
:math:`10^{-11}` of the largest); the net force's component in it, :math:`\mathbf d`, pushes
the body. Along the ray :math:`\mathbf q + t\,\mathbf d` the force along it,
:math:`g(t) = \mathbf G(\mathbf q + t\mathbf d)\cdot\mathbf d`, stays positive while the
lines are slack and falls once they take the load: ``t`` is doubled until :math:`g < 0`,
the root bracketed (Brent's method) and Newton resumes from there. With no net force
in the free directions the step is the least-squares one (a neutral direction).

**Stability.** A static equilibrium is stable where the stiffness is positive definite:
the eigenvalues of the symmetric part of :math:`K` in consistent units (rotations times
the largest fairlead arm, N/m) are all positive (a potential at a minimum; K.-J. Bathe,
"Finite Element Procedures", 1996, §6.5.2, on stability from the tangent stiffness).
An equilibrium with a negative eigenvalue (a capsized body, say) is passed over: Newton is
run again from the start with the body upright and from the equilibrium pushed both ways
along the unstable mode, and the first stable equilibrium is returned. When none is
found the unstable one is returned with ``stable=False`` and a `PlausibilityWarning`.

**Admissible.** ``stable`` also asks that the equilibrium be a physical state
(`skcable.mooring._answers`): no segment strained beyond what its material survives, no anchor on
the seabed pulled up beyond what a drag anchor takes, no body clear of the water with its
buoyancy, nothing below the seabed. ``positive_definite`` is the stiffness's verdict alone, and
``implausible`` lists the findings (``(quantity, reason)``), each warned by
`MooringSystem.equilibrium` (`skcable.errors.PlausibilityWarning`).
"""

from __future__ import annotations

import copy
import functools
import math
import warnings
from typing import NamedTuple

import numpy as np
from scipy.linalg import lapack

from skcable import _plausible
from skcable._budget import Budget
from skcable._show import Shown, counted, quantity
from skcable.errors import ConvergenceError, InputError, PlausibilityWarning
from skcable.fe import first_converged, newton
from skcable.mooring import checks
from skcable.mooring._answers import equilibrium_findings
from skcable.mooring.axial import StrainTable
from skcable.mooring.line_bvp.check import warn_unresolved
from skcable.mooring.line_bvp.fields import LineFields
from skcable.mooring.network import end_forces, largest_end_tension
from skcable.mooring.segments import Line, Segment

__all__ = ["MooringEquilibrium", "solve_equilibrium", "stiffness_eigenvalues"]

#: Singular values of the scaled Jacobian below this fraction of the largest: a free direction.
_SINGULAR = 1e-11
#: Eigenvalues below ``-_UNSTABLE`` times the largest magnitude: an unstable equilibrium.
_UNSTABLE = 1e-8
#: `_first_run`'s last attempt: the free directions' share of the net load below which the
#: restrained directions are balanced first (`_Newton.slack_step`).
_RESTRAINED = 1e-3


def _units(system) -> tuple[np.ndarray, float]:
    """Consistent units of the dofs (1 for translations, a body's largest arm for its rotations,
    `MooringSystem.dof_units`) and the largest of them."""
    units = system.dof_units()
    return units, float(units.max(initial=1.0))


def stiffness_eigenvalues(system, K, held=()) -> np.ndarray:
    """Eigenvalues (ascending, N/m) of the symmetric part of the stiffness ``K`` of ``system`` in
    consistent units: rotations times their body's largest arm (`_units`); the dofs it holds
    (``held_dofs``: a pinned body's translations) and the ``held`` ones (a point the seabed
    holds) left out."""
    units, _ = _units(system)
    scaled = K / units[:, None] / units[None, :]
    held = np.union1d(system.held_dofs, np.asarray(held, dtype=int))
    if len(held):
        free = np.setdiff1d(np.arange(len(units)), held)
        scaled = scaled[np.ix_(free, free)]
    return np.linalg.eigvalsh(0.5 * (scaled + scaled.T))


def is_stable(eigenvalues) -> bool:
    """Whether no eigenvalue is negative beyond round-off (``-1e-8`` of the largest magnitude); a
    system of no dofs is."""
    if not len(eigenvalues):
        return True
    scale = float(np.abs(eigenvalues).max())
    return bool(eigenvalues[0] >= -_UNSTABLE * scale)


class _State(NamedTuple):
    """The system at an iterate: net load ``G`` (N, N m), stiffness ``K``, the solved lines, the
    dofs, the norm of ``G`` in consistent units and the largest line tension (N)."""

    G: np.ndarray
    K: np.ndarray
    lines: list
    position: np.ndarray
    size: float
    tension: float
    held: np.ndarray = np.zeros(0, dtype=int)  # free points' heights the seabed holds there


class _Newton:
    """One Newton solve of a system's equilibrium (module docstring): the problem's callables.

    Every state it assembles counts against the time budget (`skcable._budget.Budget`: its scaled
    residual and dofs recorded, the best kept), for the error of a search that runs out of time;
    the solves of one search (its softened systems' too) share one budget."""

    def __init__(self, system, external, tol, max_iter, without=frozenset(), neutral="raise", budget=None):
        self.system, self.external, self.tol, self.max_iter = system, external, tol, max_iter
        self.without, self.neutral = without, neutral
        self.budget = Budget() if budget is None else budget
        self.units, self.arm = _units(system)
        self.held = system.held_dofs  # a pinned body's translations: no unknowns
        # the free points' heights and the seabed under them: a point rests on it (`seabed_contact`)
        layout = system.layout
        self.floor_dofs = (
            np.array([s + 2 for s in layout.point_start.values()], dtype=int)
            if system.depth is not None
            else np.zeros(0, dtype=int)
        )
        self.floor = -float(system.depth) if system.depth is not None else 0.0
        self.unit_pairs = self.units[:, None] * self.units[None, :]  # a matrix in consistent units
        self.body_scale = system.force_scale(external)
        self.lines = None  # the lines of the last accepted state: warm starts of the trials
        self.cap = None  # the step cap, from the start (`MooringSystem.step_cap`)
        self.seen = 0.0  # the largest line tension of the run's iterates Newton stepped from (N)
        self.restrained_first = False  # `slack_step`: the restrained directions before the free ones
        self.corrected = False  # `update`: trials corrected by a step with the step's Jacobian
        self.jac = None  # the Jacobian of the last Newton step

    def merit(self, state) -> float:
        """The line search's merit: the net load's norm over a scale that holds during the line
        search and never falls in a run, the largest of the loads other than the lines' and the
        line tensions of the iterates Newton stepped from (`seen`).

        The convergence test (`norm`) judges each state by its own tension, the round-off of its
        net load; as a merit that ratio stood at 0.48 while the tensions of a body sinking 160 m
        fell a hundredfold (the net load fell with them), and the line search crawled until
        ``max_iter``."""
        return state.size / max(self.body_scale, self.seen, 1e-300)

    def update(self, x, dx, t) -> np.ndarray:
        """The trial ``x + t dx``, its free points no lower than the seabed; with ``corrected``, the
        trial then corrected by one step of Newton's method with the step's own Jacobian (a second
        order correction: the trial path bends with a taut line as a point swings on it, instead
        of stretching it)."""
        trial = self._floored(x + t * dx)
        if self.corrected and self.jac is not None:
            try:
                G = self.assemble(trial).G
            except (InputError, ConvergenceError):
                return trial
            trial = self._floored(trial + self.least_squares(self.jac, G / self.units))
        return trial

    def _floored(self, trial) -> np.ndarray:
        if len(self.floor_dofs):
            trial[self.floor_dofs] = np.maximum(trial[self.floor_dofs], self.floor)
        return trial

    def assemble(self, position) -> _State:
        """The `_State` at ``position`` (its free points no lower than the seabed); the lines start
        from the last accepted ones. A pinned body's translations and a free point on the seabed
        that the loads press into it are held: their load is the pin's or the seabed's reaction, no
        residual."""
        self.budget.spend()
        position = self._floored(position.copy())
        G, K, lines = self.system.evaluate(position, self.external, start=self.lines, without=self.without)
        contact = np.zeros(0, dtype=int)
        if len(self.floor_dofs):
            k = self.floor_dofs
            on = position[k] <= self.floor + 1e-12 * max(1.0, abs(self.floor))
            contact = k[on & (G[k] <= 0.0)]  # pressed into the seabed, or resting on it
        if len(self.held) or len(contact):  # the reactions: no unknowns, no residual
            G = G.copy()
            G[self.held] = 0.0
            G[contact] = 0.0
        size = float(np.linalg.norm(G / self.units))
        state = _State(G, K, lines, position, size, self.system.tension_scale(lines), contact)
        self.budget.record(self.norm(state), np.array(position, dtype=float))
        return state

    def norm(self, state) -> float:
        """The scaled residual's norm: the net load over the state's force scale (its largest line
        tension, at least the other loads), moments also over their body's arm."""
        return state.size / max(self.body_scale, state.tension, 1e-300)

    def jacobian(self, state) -> np.ndarray:
        """``-∂G/∂q`` at ``state``; the held dofs' rows and columns those of no unknown (a unit
        diagonal in consistent units, at the matrix's scale)."""
        jac = self.system.layout.times_rate_map(state.K, state.position)
        held = np.concatenate([self.held, state.held]).astype(int)
        if len(held):
            size = max(float(np.abs(jac / self.unit_pairs).max()), 1e-300)
            jac[held, :] = 0.0
            jac[:, held] = 0.0
            jac[held, held] = size * self.unit_pairs[held, held]
        return jac

    def increment(self, state) -> np.ndarray:
        jac = self.jacobian(state)
        self.jac = jac
        self.lines = state.lines  # Newton steps from this state: the trials start from its lines
        self.seen = max(self.seen, state.tension)
        scaled = jac / self.unit_pairs
        solved = _well_conditioned_solve(scaled, state.G / self.units)
        if solved is not None:  # no free direction: Newton's step
            return self.capped(solved / self.units)
        pair = _null_space(scaled, left=True)
        if pair is not None:
            return self.slack_step(state, pair, jac)
        return self.capped(np.linalg.solve(jac, state.G))

    def least_squares(self, jac, r) -> np.ndarray:
        """The least-squares step of the Jacobian ``jac`` for the scaled net load ``r``, capped."""
        return self.capped(np.linalg.lstsq(jac / self.unit_pairs, r, rcond=_SINGULAR)[0] / self.units)

    def capped(self, dq) -> np.ndarray:
        """``dq`` scaled down to the step cap, where a dof exceeds it."""
        excess = float(np.max(np.abs(dq) / self.cap))
        return dq / excess if excess > 1.0 else dq

    def slack_step(self, state, pair, jac) -> np.ndarray:
        """The step along the free directions (``pair``: rows, the right and left null vectors of
        the scaled Jacobian) to where the lines take the net load no Newton step reaches (its
        component along the left ones; module docstring); with no such load, the least-squares
        Newton step in the other directions (the free ones stay as they are: the equilibrium is
        checked for them at the end, `check_unique`)."""
        G, lines, position = state.G, state.lines, state.position
        null, left = pair
        r = G / self.units
        push = null.T @ (left @ r)  # along the free directions, by the load out of reach
        restrained = self.restrained_first and np.linalg.norm(push) < _RESTRAINED * np.linalg.norm(
            r - left.T @ (left @ r)
        )
        if restrained and any(_slack(line) for line in lines):
            return self.least_squares(jac, r)  # the restrained directions first
        if not np.linalg.norm(push) > 1e-12 * np.linalg.norm(r):  # no force along the free directions
            if not any(_slack(line) for line in lines) and self.neutral != "hold":
                if any(_probe(self, state, d) != "restrained" for d in null):  # nothing takes them
                    raise ConvergenceError(
                        _SINGULAR_MESSAGE.format(_named(self.system, null)), [self.norm(state)]
                    )
            # the others balanced first, the free ones stay (slack lines, lines whose stiffness
            # vanishes there but that hold them, neutral directions held): `check_unique` at the end
            return self.least_squares(jac, r)
        direction = push / np.linalg.norm(push)  # scaled dofs, |direction| = 1
        out_of_reach = left.T @ (left @ r)  # the load measured along its left partner
        measure = out_of_reach / np.linalg.norm(out_of_reach)
        ray = direction / self.units
        cap = self.system.step_cap(position, self.without) if self.cap is None else self.cap
        t = _ray_root(self, position, ray, measure, float(cap[0]), self.norm(state))
        return t * ray

    def along(self, t, position, ray, direction) -> float:
        """``g(t)``: the scaled net load at ``position + t ray`` along ``direction`` (a trial that no
        line can reach counts as pulling back, -inf)."""
        try:
            G = self.assemble(position + t * ray)[0]
        except (InputError, ConvergenceError):
            return -math.inf
        return float((G / self.units) @ direction) / max(self.body_scale, 1e-300)

    def run(self, position, lines=None):
        """`skcable.fe.newton` from ``position`` (the ``lines`` as warm starts of the first solves)."""
        self.lines, self.seen = lines, 0.0
        self.cap = self.system.step_cap(position, self.without)
        return newton(
            self.assemble,
            position,
            norm=self.norm,
            merit=self.merit,
            increment=self.increment,
            tol=self.tol,
            max_iter=self.max_iter,
            max_halvings=20,
            stagnation_window=self.max_iter,  # no stagnation rule: a capped step may gain slowly
            name="mooring equilibrium",
            rejects=(InputError, ConvergenceError),  # a line that cannot reach a trial position
            watchdog=1,  # the first full step from rest overshoots onto the stiff side: take it
            update=self.update,
            floor=self.round_off,
        )

    def round_off(self, state) -> float:
        """The round-off floor of `norm` at ``state``: the net load the stiffness gives to the dofs'
        own round-off (8 ulps of each dof, a dof of 1 m or 1 rad at least), over the force scale:
        a stiff taut line resolves its force no finer than ``EA ε``."""
        dq = 8.0 * np.finfo(float).eps * (np.abs(state.position) + self.units)
        noise = np.abs(state.K) @ dq
        return float(np.linalg.norm(noise / self.units)) / max(self.body_scale, state.tension, 1e-300)


def _ray_root(solve, position, ray, direction, reach, norm) -> float:
    """The distance ``t`` along ``ray`` where ``g(t)`` (`_Newton.along`) changes sign: doubled from
    ``1e-3 reach`` until ``g < 0`` (at most ``2**20`` times that), then Brent's method; ``norm``
    is the scaled residual at ``position`` (the history of the error, if there is no sign change)."""
    from scipy.optimize import brentq

    args = (position, ray, direction)
    lo, t = 0.0, 1e-3 * reach
    for _ in range(21):
        g = solve.along(t, *args)
        if g <= 0:
            break
        lo, t = t, 2.0 * t
    else:
        raise ConvergenceError(
            "mooring equilibrium: the lines are slack and stay slack along the net force (nothing "
            f"restrains {_named(solve.system, direction[None, :])}: add lines, waterplane_area or a "
            "metacentre)",
            [norm],
        )
    return brentq(_along_capped, lo, t, args=(solve, *args), xtol=1e-9 * t, rtol=1e-12)


def _along_capped(t, solve, position, ray, direction) -> float:
    """`_Newton.along`, at least -1 (finite for Brent's method)."""
    return max(solve.along(t, position, ray, direction), -1.0)


def _named(system, null) -> str:
    """The dofs that lead the free directions ``null`` (rows, scaled dofs), in words."""
    weight = np.abs(np.asarray(null)).max(axis=0)
    lead = np.flatnonzero(weight > 0.3 * weight.max())
    return ", ".join(system.layout.describe(int(k)) for k in lead[:6])


_SINGULAR_MESSAGE = (
    "mooring equilibrium: the stiffness is singular (a direction neither the lines nor the hydrostatics "
    "restrain: {}; add waterplane_area, a metacentre or lines)"
)


def _slack(line) -> bool:
    """Whether a solved line is slack: no horizontal tension (its slack in a heap, or lying slack),
    or its own ``is_slack`` where it says."""
    said = getattr(line, "is_slack", None)
    if said is not None:
        return bool(said)
    plane = getattr(line, "plane", None)
    return (plane.H_A == 0.0 and plane.H_B == 0.0) if plane is not None else line.H == 0.0


def check_unique(solve, state, history) -> list:
    """The directions the stiffness at the equilibrium ``state`` leaves free, judged by the net
    load a small move along each gives (`_probe`): one the loads push back along both ways is
    restrained at a higher order (a line whose tension vanishes at a free end: no stiffness, yet a
    restoring force); one along which nothing changes is neutral: raise `ConvergenceError` (the
    equilibrium is not unique), or, with ``neutral="hold"``, keep it where it started and return
    it. One the loads push further is no equilibrium: `ConvergenceError`. Returns the neutral
    directions held (rows, scaled dofs)."""
    scaled = solve.jacobian(state) / solve.unit_pairs
    if _well_conditioned_solve(scaled, np.zeros(len(scaled))) is not None:
        return []  # no singular value near zero (`_CONDITIONED`)
    free = _null_space(scaled)
    if free is None:
        return []
    held, bad = [], []
    for direction in free:
        verdict = _probe(solve, state, direction)
        if verdict == "restrained":
            continue
        if verdict == "neutral" and solve.neutral == "hold":
            held.append(direction)
        else:
            bad.append(direction)
    if bad:
        raise ConvergenceError(_SINGULAR_MESSAGE.format(_named(solve.system, np.array(bad))), history)
    return held


def _probe(solve, state, direction) -> str:
    """``"restrained"``, ``"neutral"`` or ``"pushed"``: the change of the net load along
    ``direction`` (scaled dofs) that a move of 1e-4 of the step cap each way along it gives, over
    the force scale: below 1e-12 both ways, neutral; opposing the move both ways, restrained."""
    ray = direction / solve.units
    cap = solve.cap if solve.cap is not None else solve.system.step_cap(state.position, solve.without)
    lead = int(np.argmax(np.abs(ray)))
    t = 1e-4 * float(cap[lead]) / float(abs(ray[lead]))
    scale = max(solve.body_scale, state.tension, 1e-300)
    g = []
    for sign in (1.0, -1.0):
        try:
            G = solve.assemble(state.position + sign * t * ray).G
        except (InputError, ConvergenceError):
            return "pushed"
        g.append(float(((G - state.G) / solve.units) @ direction) / scale)
    small = 1e-12
    if abs(g[0]) <= small and abs(g[1]) <= small:
        return "neutral"
    if g[0] < -small and g[1] > small:
        return "restrained"
    return "pushed"


#: `_well_conditioned_solve` solves where LAPACK's estimate of the reciprocal condition number
#: (1-norm) is above this: five orders above `_SINGULAR`, so that no singular value is below
#: `_SINGULAR` of the largest (the 2-norm condition number is at most n times the 1-norm one,
#: and the estimate is within a small factor of it; N.J. Higham, "Accuracy and Stability of
#: Numerical Algorithms", 2002, §15.3).
_CONDITIONED = 1e-6


def _well_conditioned_solve(scaled, rhs):
    """``scaled⁻¹ rhs`` by an LU factorisation where its estimated reciprocal condition number is
    above `_CONDITIONED`, else None (`_null_space` then looks for free directions): the singular
    values cost several LU factorisations, and a Newton step needs them only near a singular
    Jacobian."""
    lu, piv, info = lapack.dgetrf(scaled)
    if info != 0:
        return None
    rcond, info = lapack.dgecon(lu, float(np.abs(scaled).sum(axis=0).max()))
    if info != 0 or not rcond > _CONDITIONED:
        return None
    x, info = lapack.dgetrs(lu, piv, rhs)
    return x if info == 0 and np.isfinite(x).all() else None


def _null_space(scaled, left: bool = False):
    """The free directions of the scaled Jacobian (rows: its right singular vectors whose singular
    values are below `_SINGULAR` of the largest), or None where there is none: the singular values
    alone first (a third of a full SVD's work), the vectors only where some are that small. With
    ``left``, ``(right, left)``: the left singular vectors too, the loads no step can change (the
    Jacobian is not symmetric where a body's rotation dofs are Euler angles and its moments are
    about global axes: a rod turning about its own axis is its pitch, the moment about the axis
    its left partner)."""
    singular = np.linalg.svd(scaled, compute_uv=False)
    if singular[-1] > _SINGULAR * singular[0]:
        return None
    u, singular, vh = np.linalg.svd(scaled)
    small = singular <= _SINGULAR * singular[0]
    free = vh[small]
    if not len(free):  # (the two at a tie of round-off: the full one decides)
        return None
    return (free, u[:, small].T) if left else free


@functools.lru_cache(maxsize=1)
def _threads():
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


def solve_equilibrium(
    system,
    position,
    external,
    lines,
    tol,
    max_iter,
    without=frozenset(),
    neutral="raise",
    time_limit=math.inf,
):
    """`skcable.mooring.MooringSystem.equilibrium` on checked arguments: Newton from ``position``
    (the ``lines`` of an earlier equilibrium as warm starts, or None), the stable branch
    preferred (module docstring), ``without`` the lines of those indices, within ``time_limit``
    seconds (then `ConvergenceError` with every scaled residual evaluated as its history and the
    best point reached as its ``last``). Returns a `MooringEquilibrium`.

    The dense solves of a few dozen dofs run on one BLAS thread (threadpoolctl): more threads
    only add their start-up and, on a shared machine, their contention (an SVD of order 96 took
    80 ms on two contending threads against 1 ms on one). Below `_ONE_THREAD` dofs BLAS runs on
    one thread anyway (OpenBLAS threads only larger products), and setting the limit would cost
    more than a Newton step."""
    solve = _Newton(system, external, tol, max_iter, without, neutral, Budget(time_limit=time_limit))
    what = "mooring equilibrium (the measure: the scaled residual)"
    if system.n_dof < _ONE_THREAD:
        return solve.budget.run(what, "states", _solve_equilibrium, solve, position, lines)
    with _threads().limit(limits=1, user_api="blas"):
        return solve.budget.run(what, "states", _solve_equilibrium, solve, position, lines)


#: Systems of this many dofs and more solve under a limit of one BLAS thread (`solve_equilibrium`).
_ONE_THREAD = 24


def _first_run(solve, position, lines):
    """Newton from ``position``; where its line search finds no descent (the net load is not
    smooth where lines lie slack in heaps: Newton's step from there need not descend), the first
    of `_retries` that converges (`skcable.fe.first_converged`)."""
    try:
        return solve.run(position, lines)
    except ConvergenceError as err:
        if "no descent" not in str(err):
            raise
        history = err.history
    try:
        return first_converged(_retries(solve, position, lines), catch=(ConvergenceError, InputError))
    except (ConvergenceError, InputError):
        raise ConvergenceError(
            "mooring equilibrium: the line search found no descent, from the start nor from it pushed "
            "along the net load (the residual stalls: the loads may exceed what the mooring can hold, "
            "or the start is too far)",
            history,
        ) from None


def _retries(solve, position, lines):
    """`_first_run`'s retries, each made as it is reached: from the start pushed along the net load
    (`_pushed_starts`, `_carried_starts`); from ``position`` with the restrained directions
    balanced before the free ones are pushed (`_Newton.slack_step`: lines hanging vertically leave
    x, y and yaw free while roll and pitch are unbalanced, and the push along the free directions
    found no descent); from the start and from it carried, each trial corrected (`_Newton.update`:
    taut lines that must swing)."""
    for start in [*_pushed_starts(solve, position), *_carried_starts(solve, position)]:
        yield functools.partial(solve.run, start)
    yield functools.partial(_flagged, solve, "restrained_first", position, lines)
    for start in [position, *_carried_starts(solve, position)]:
        yield functools.partial(_flagged, solve, "corrected", start)


def _flagged(solve, flag, position, lines=None):
    """``solve.run(position, lines)`` with ``solve``'s switch ``flag`` set for it."""
    setattr(solve, flag, True)
    try:
        return solve.run(position, lines)
    finally:
        setattr(solve, flag, False)


def _carried_starts(solve, position) -> list:
    """The start carried along the net load (every dof, in consistent units) to where the load
    along it vanishes (`_ray_root`): slack lines that take no load until they are taut, and then a
    stiff one (a weight on a weightless line), where Newton's step overshoots; none where the load
    does not turn along the ray."""
    try:
        state = solve.assemble(position)
    except (ConvergenceError, InputError):
        return []
    r = state.G / solve.units
    if not np.linalg.norm(r) > 0:
        return []
    direction = r / np.linalg.norm(r)
    ray = direction / solve.units
    cap = solve.system.step_cap(position, solve.without)
    try:
        t = _ray_root(solve, position, ray, direction, float(cap.min()), solve.norm(state))
    except ConvergenceError:
        return []
    return [position + t * ray]


#: How far `_pushed_starts` pushes the start along the net load: multiples of the step cap (a
#: quarter of the shortest horizontal span of the lines, 0.2 rad).
_PUSHES = (0.04, 0.2, 0.6, 1.2)


def _pushed_starts(solve, position) -> list:
    """The start moved horizontally along the net horizontal load on each body and point by
    `_PUSHES` step caps: the lines slack in heaps at the start take up the load farther along
    it (rotations and heave stay: the hydrostatics hold them)."""
    try:
        G = solve.assemble(position)[0]
    except (ConvergenceError, InputError):
        return []
    layout = solve.system.layout
    firsts = [*layout.body_start, *layout.point_start.values()]
    horizontal = np.array([s + k for s in firsts for k in (0, 1)], dtype=int)
    ray = np.zeros_like(position)
    ray[horizontal] = G[horizontal]
    if not np.linalg.norm(ray) > 0:
        return []
    cap = solve.system.step_cap(position, solve.without)[horizontal]
    size = float(np.min(cap / np.maximum(np.abs(ray[horizontal]), 1e-300)))
    return [position + push * size * ray for push in _PUSHES]


def _solve_equilibrium(solve, position, lines):
    system, external, without = solve.system, solve.external, solve.without
    settings = (solve.tol, solve.max_iter, without, solve.neutral, solve.budget)
    result = None
    if lines is None and any(getattr(h.model, "stiffness", None) is not None for h in system.mooring_lines):
        # a pin held by a stiff spring (a tie): Newton from the start where it is near (a few steps),
        # else reached through its softer ties
        try:
            near = _Newton(system, external, solve.tol, _NEAR, without, solve.neutral, solve.budget)
            result = near.run(position)
        except (ConvergenceError, InputError):
            softer = _stiffened_start(system, position, external, settings)
            position = position if softer is None else softer
    try:
        result = result if result is not None else _first_run(solve, position, lines)
    except ConvergenceError as err:
        if "singular" in str(err) or "nothing restrains" in str(err):  # not a matter of stiffness
            raise
        start = _stiffened_start(system, position, external, settings)
        if start is None:
            raise err from None
        result = _first_run(solve, start, None)
    held = check_unique(solve, result.state, result.history)
    eigenvalues = stiffness_eigenvalues(system, result.state.K, result.state.held)
    passed = []
    if not is_stable(eigenvalues):
        passed.append(result.x.copy())
        for start in _restarts(system, position, result, solve):
            try:
                other = solve.run(start)
            except (ConvergenceError, InputError):
                continue
            other_eig = stiffness_eigenvalues(system, other.state.K, other.state.held)
            if is_stable(other_eig):
                result, eigenvalues = other, other_eig
                break
            passed.append(other.x.copy())
    G, K, lines = result.state.G, result.state.K, result.state.lines
    eq = MooringEquilibrium(
        system, result.x, external, G, K, lines, result.history, eigenvalues, passed, without=without
    )
    eq.neutral = [_named(system, d[None, :]) for d in held]
    if not eq.positive_definite:
        reason = (
            f"the mooring equilibrium found is unstable (stiffness eigenvalue {eigenvalues[0]:.3g} N/m < 0, "
            f"heel {max(b.heel for b in eq.bodies) if eq.bodies else 0.0:.3g} rad) and no stable one was "
            "found from the restarts: check the bodies' metacentres, centres of gravity and the start"
        )
        warnings.warn(PlausibilityWarning("start", reason), stacklevel=4)
    return eq


def warn_implausible(eq) -> None:
    """Warn each finding of ``eq`` (`MooringEquilibrium.implausible`), and each line a line BVP
    model of the caller's (its mesh theirs: `skcable.mooring.LineBVP`) solved on a mesh that does
    not resolve it (`skcable.mooring.line_bvp.check.warn_unresolved`): the answer's check."""
    _plausible.warn_all(eq.implausible)
    for line in eq.lines:
        solution = getattr(line, "solution", None)
        if isinstance(solution, LineFields):
            warn_unresolved(solution, stacklevel=4)  # the caller of the equilibrium named


#: The Newton steps a system with ties takes from its start before its ties are softened.
_NEAR = 6

#: The stiffness factors of `_stiffened_start`'s softened systems, softest first: of the lines
#: (and rods and ties), then of the ties alone (a pin held by a stiff spring: `skcable.mooring.rod.Tie`).
_SOFTENED = (1e-6, 1e-4, 1e-2)
_SOFTENED_TIES = tuple(10.0**k for k in range(-8, 0))


def _softened(system, factor, ties_only=False):
    """A copy of ``system`` whose lines and rods are ``factor`` times as stiff axially (their weights
    and geometry the same), or only its ties (a model with a ``stiffness``) with ``ties_only``; None
    where it has nothing to soften."""
    models = {}
    for handle in system.mooring_lines:
        model = handle.model
        if isinstance(model, Line) and not ties_only:
            segments = []
            for seg in model.segments:
                law = seg.law
                if law.kind == "constant":
                    EA = float(seg.EA) * factor
                elif isinstance(law, StrainTable):
                    EA = StrainTable(law.table[0], law.table[1] * factor, interpolation=law.interpolation)
                else:
                    return None
                segments.append(Segment(seg.length, seg.w, EA, diameter=seg.diameter))
            models[handle] = Line(segments, model.attachments, friction=model.friction)
            continue
        name = "stiffness" if ties_only else "axial_stiffness"
        if getattr(model, name, None) is not None or (not ties_only and getattr(model, "stiffness", None)):
            name = name if getattr(model, name, None) is not None else "stiffness"
            other = copy.copy(model)
            setattr(other, name, getattr(model, name) * factor)
            models[handle] = other
    return system.replaced(models=models) if models else None


def _stiffened_start(system, position, external, settings):
    """A start for a system whose stiff taut lines must turn far (a weight swinging on a line a
    million times stiffer than the weight's pendulum) or whose ties are stiff (a rod pinned to a
    body): the equilibria of the system with its ties alone softened (`_SOFTENED_TIES`), where it
    has ties, else with its lines softened (`_SOFTENED`), each from the last; None where that
    fails or there is nothing to soften. A start only: the equilibrium is the system's own, solved
    from it."""
    tol, max_iter, without, neutral, budget = settings
    with warnings.catch_warnings():  # a softened line is implausible by design
        warnings.simplefilter("ignore", PlausibilityWarning)
        ties = any(getattr(h.model, "stiffness", None) is not None for h in system.mooring_lines)
        plans = ((_SOFTENED_TIES, True), (_SOFTENED, False)) if ties else ((_SOFTENED, False),)
        for factors, ties_only in plans:
            start = position
            for factor in factors:
                soft = _softened(system, factor, ties_only)
                if soft is None:
                    start = None
                    break
                try:
                    solve = _Newton(soft, external, tol, max_iter, without, neutral, budget)
                    start = _first_run(solve, start, None).x
                except (ConvergenceError, InputError):
                    start = None
                    break
            if start is not None:
                return start
    return None


def _restarts(system, position, result, solve):
    """Starts of the search for a stable branch: the start upright (rotations zeroed), then the
    unstable equilibrium pushed both ways along its most unstable mode."""
    starts = []
    rotations = system.layout.rotation_dofs()
    if rotations.size and np.any(position[rotations] != 0):
        upright = position.copy()
        upright[rotations] = 0.0
        starts.append(upright)
    units, _ = _units(system)
    scaled = result.state.K / units[:, None] / units[None, :]
    mode = np.linalg.eigh(0.5 * (scaled + scaled.T))[1][:, 0] / units
    mode[solve.held] = 0.0  # a pin holds these
    cap = solve.system.step_cap(result.x, solve.without)
    size = float(np.min(cap / np.maximum(np.abs(mode), 1e-300)))
    starts += [result.x + size * mode, result.x - size * mode]
    return starts


class BodyState(Shown):
    """A body at equilibrium: ``body``, ``index``, ``position`` (its dofs: m, rad), ``offset`` (its
    reference point, m), ``angles`` (roll, pitch, yaw; zeros for a point body), ``rotation`` (body
    to global axes), ``heel`` (the angle of its z axis to the vertical, rad) and ``local_points``
    (its points in body axes, m, (n, 3))."""

    def __init__(self, index, body, q, local_points):
        self.index, self.body, self.position = index, body, q.copy()
        self.local_points = np.asarray(local_points, dtype=float).reshape(-1, 3)
        self.offset = q[:3].copy()
        self.angles = q[3:].copy() if len(q) == 6 else np.zeros(3)
        self.rotation = R = body.rotation(q)
        self.heel = float(np.arccos(np.clip(R[2, 2], -1.0, 1.0)))

    def _pose_shown(self) -> list:
        """The shown ``offset``, ``angles`` and ``heel`` (`skcable._show.quantity`)."""
        return [
            quantity("offset", self.offset, "m"),
            quantity("angles", self.angles, "rad"),
            quantity("heel", self.heel, "rad"),
        ]

    def __repr__(self):
        return f"BodyState(body {self.index}: {', '.join(self._pose_shown())})"


class PointState(Shown):
    """A point at equilibrium: ``point``, ``index``, ``kind`` and ``position`` (m, global axes)."""

    def __init__(self, point, position):
        self.point, self.index, self.kind, self.position = point, point.index, point.kind, position.copy()

    def __repr__(self):
        return f"PointState({self.kind} point {self.index}: {quantity('position', self.position, 'm')})"


class MooringEquilibrium(Shown):
    """A mooring system in static equilibrium (`MooringSystem.equilibrium`).

    Attributes
    ----------
    system : MooringSystem
    position : ndarray
        The dofs: each body's ``(x, y, z, roll, pitch, yaw)`` (m, rad; ``(x, y, z)`` of a point
        body), then each free point's ``(x, y, z)``.
    bodies : list of BodyState
        Each body at equilibrium (``position``, ``offset``, ``angles``, ``heel``, ``rotation``).
    points : list of PointState
        Each point of the system (``position``, m).
    lines : list of LineBetween or Line3D
        Each line at equilibrium (``end_forces``: its forces on its ends a and b, N), in the
        order of the system's lines, those left out (``without``) skipped.
    line_indices : list of int
        The system's number of each line of ``lines``.
    without : frozenset of int
        The lines left out.
    offset, angles, heel, rotation
        Those of the body of a one-body system.
    fairlead_forces, anchor_forces, fairleads, anchors : ndarray, shape (n, 3)
        The one-body constructor's: each line's force on its fairlead and on its anchor (N), the
        fairleads and the anchors (m).
    residual : ndarray
        Net load left on the dofs (N, N m).
    history : list of float
        Scaled residual at each Newton iteration.
    eigenvalues : ndarray
        Eigenvalues of the symmetric part of the stiffness in consistent units (rotations
        times their body's largest arm), N/m, ascending (`stiffness_eigenvalues`).
    positive_definite : bool
        Whether none of them is negative beyond round-off.
    implausible : list of (str, str)
        What makes the answer no physical state, ``(quantity, reason)`` (module docstring,
        "Admissible"); each is warned.
    stable : bool
        ``positive_definite`` and nothing ``implausible``: a stable, physically admissible
        equilibrium.
    unstable_found : list of ndarray
        Positions of the unstable equilibria passed over on the way to this one.
    """

    def __init__(
        self,
        system,
        q,
        external,
        G,
        K,
        lines,
        history,
        eigenvalues=None,
        unstable_found=(),
        without=frozenset(),
    ):
        self.system, self.position, self.external, self.residual = system, q, external, G
        self._K, self.lines, self.history, self.without = K, lines, history, without
        self.line_indices = [h.index for h in system.mooring_lines if h.index not in without]
        layout = system.layout
        self.bodies = [
            BodyState(i, b, layout.body_q(q, i), layout.local[i]) for i, b in enumerate(system.bodies)
        ]
        P = system.frame(q)[0]
        self.points = [PointState(p, P[p.index]) for p in system.points]
        self.depth = system.depth
        if len(self.bodies) == 1:
            one = self.bodies[0]
            self.offset, self.angles, self.heel, self.rotation = (
                one.offset,
                one.angles,
                one.heel,
                one.rotation,
            )
        if system.shortcut:
            self.fairlead_forces = np.array([line.force_on_fairlead for line in lines])
            self.anchor_forces = np.array([line.force_on_anchor for line in lines])
            self.fairleads = np.array([line.fairlead for line in lines])
            self.anchors = system.anchors
        self.eigenvalues = stiffness_eigenvalues(system, K) if eigenvalues is None else eigenvalues
        self.positive_definite = is_stable(self.eigenvalues)
        self.unstable_found = list(unstable_found)
        self.neutral: list = []  # the neutral directions held where they started (`check_unique`)
        for name in ("position", "residual", "eigenvalues"):
            if not np.isfinite(getattr(self, name)).all():
                raise ConvergenceError(f"mooring equilibrium: non-finite {name}", history)
        if not all(np.isfinite(end_forces(line)).all() for line in lines):
            raise ConvergenceError("mooring equilibrium: non-finite line forces", history)
        self.implausible = equilibrium_findings(self)
        self.stable = self.positive_definite and not self.implausible

    @property
    def handles(self) -> list:
        """The system's line handles (`MooringLine`) of ``lines``, in order."""
        return [self.system.mooring_lines[k] for k in self.line_indices]

    def stiffness(self, *, lines_only: bool = False, condensed: bool = False) -> np.ndarray:
        """Stiffness of the system at equilibrium, ``-∂G/∂(x, rotation vector)`` (N/m, N/rad,
        N m/rad), shape (n_dof, n_dof) over every body's and free point's dofs.

        ``lines_only`` leaves out the bodies' hydrostatics (from the lines at equilibrium, no new
        line solve; see `MooringSystem.stiffness`). ``condensed``: the bodies' stiffness alone,
        the free points condensed out (each in equilibrium as the bodies move),
        ``K_bb - K_bp K_pp^{-1} K_pb``, shape ``(6 n, 6 n)`` for ``n`` rigid bodies."""
        if lines_only:
            system = self.system
            _, R, arms = system.frame(self.position)
            K = system.assemble(self.position, (R, arms), self.handles, self.lines, 0.0, lines_only=True)[1]
        else:
            K = self._K.copy()
        if not condensed:
            return K
        n_body = sum(b.n_dof for b in self.system.bodies)
        Kbb, Kbp, Kpb, Kpp = (
            K[:n_body, :n_body],
            K[:n_body, n_body:],
            K[n_body:, :n_body],
            K[n_body:, n_body:],
        )
        if Kpp.size == 0:
            return Kbb
        try:
            return Kbb - Kbp @ np.linalg.solve(Kpp, Kpb)
        except np.linalg.LinAlgError:
            raise ConvergenceError(
                "mooring equilibrium: the free points' stiffness is singular: they cannot be condensed out",
                self.history,
            ) from None

    def tensions(self):
        """Tension table: each line's per-segment table with the line's number in front, plus its
        end forces (N): ``H, V_B, H_A, V_A, T_fairlead`` for the one-body constructor's lines,
        ``H_a, V_a, H_b, V_b, T_a, T_b`` (by end, a then b) and ``model`` otherwise."""
        import pandas as pd

        frames = []
        for k, line in zip(self.line_indices, self.lines, strict=True):
            table = line.tensions().copy()
            table.insert(0, "line", k)
            if self.system.shortcut:
                table["H"], table["V_B"], table["H_A"], table["V_A"] = line.H, line.V_B, line.H_A, line.V_A
                table["T_fairlead"] = line.tension_at_fairlead
            else:
                F = end_forces(line)
                table["H_a"], table["V_a"] = float(np.hypot(*F[0, :2])), float(-F[0, 2])
                table["H_b"], table["V_b"] = float(np.hypot(*F[1, :2])), float(-F[1, 2])
                table["T_a"], table["T_b"] = np.linalg.norm(F, axis=1)
                table["model"] = getattr(line, "model", "as given")
                if not isinstance(table["model"].iloc[0], str):
                    table["model"] = "as given"
            frames.append(table)
        return pd.concat(frames, ignore_index=True)

    def anchor_loads(self):
        """Each anchor's horizontal and vertical load and uplift angle (`skcable.mooring.checks`)."""
        return checks.anchor_loads(self)

    def line_checks(self):
        """Each line's end tensions, grounded length, touchdown and angle at its lower end
        (`skcable.mooring.checks`)."""
        return checks.line_checks(self)

    def segment_checks(self, safety_factor):
        """Each segment's largest tension against its MBL with ``safety_factor``
        (`skcable.mooring.checks`)."""
        return checks.segment_checks(self, safety_factor)

    def to_vtk(self, path, n: int = 101):
        """Write the lines (tension as point data), the seabed patch and the bodies to a
        ``.vtu``/``.vtk`` file, atomically (see `skcable.io.mooring_mesh`); returns the path."""
        from skcable.io import write_mooring

        return write_mooring(self, path, n)

    def __repr__(self):
        note = "" if self.positive_definite else ", UNSTABLE"
        note += "" if not self.implausible else f", IMPLAUSIBLE: {', '.join(q for q, _ in self.implausible)}"
        if self.system.shortcut:
            shown = ", ".join(
                (
                    *self.bodies[0]._pose_shown(),
                    quantity("T_fairlead", [line.tension_at_fairlead for line in self.lines], "N"),
                    quantity("min_eigenvalue", self.eigenvalues[0], "N/m"),
                    quantity("iterations", len(self.history) - 1),
                )
            )
            return f"MooringEquilibrium({counted([len(self.lines)], 'line')}: {shown}{note})"
        ends = [largest_end_tension(line) for line in self.lines]
        shown = ", ".join(
            (
                quantity("T_max", ends, "N"),
                quantity("min_eigenvalue", self.eigenvalues[0], "N/m"),
                quantity("iterations", len(self.history) - 1),
            )
        )
        bodies = "1 body" if len(self.bodies) == 1 else f"{len(self.bodies)} bodies"
        counts = f"{bodies}, {counted([len(self.points)], 'point')}, {counted([len(self.lines)], 'line')}"
        return f"MooringEquilibrium({counts}: {shown}{note})"
