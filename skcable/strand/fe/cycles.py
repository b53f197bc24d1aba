r"""A strand bent back and forth: its loop over load steps, the energy it dissipates per cycle
and the friction work its layers do.

`bending_cycles` drives one held dof of a [`StrandModel`][skcable.strand.StrandModel] whose slip
law keeps a history ([`StageSlip`][skcable.strand.StageSlip]) from the unbent strand to ``+a``
(the *backbone*), then ``cycles`` times down to ``−a`` and back. Every step commits the slip
state, so the reaction traces the hysteresis loop: per cycle, the energy the support puts in,
:math:`W = \oint R\,dq` (J), equals by the balance of energy the friction work the stages did,
:math:`\sum \int \sum_k M_k|\Delta\kappa_{p,k}|\,dx` (J), once the loop closes.

**Exact loops** (``exact=True``, the default). The stick/slip law is piecewise linear, so the
strand's response is linear between *events*, the loads at which a stage starts to slip at some
point. Each step is cut at its events: from the converged state, the tangent (with the stages
that slip as the load goes on) gives the rate of every point's curvature, the first stage to
reach its slip moment gives the next event, and the model is solved there. The reaction is then
linear between the vertices (the moderate-rotation kinematics aside: ε_a = u′ + ½v′² stiffens
the strand by a relative amount of the order of the end slope squared), and the trapezoidal
rule gives the loop's area, the energy per cycle, exactly: it equals the summed friction work to
about 1e-9 (tests/strand/test_cycles.py, benchmarks/strand_loops.py). Without ``exact``, the
steps are the schedule's alone and the loop's area carries the trapezoidal rule's error at the
kinks it steps over (6 % with two steps a quarter cycle in the benchmark).

**Masing's rules for a structure.** A structure whose only nonlinearity is its Coulomb stages,
loaded from the virgin state by one displacement q so that every point that slips is loaded
monotonically, obeys Masing's rules as a whole: after a reversal at :math:`(q_r, R_r)` the
increment problem is the virgin one with every slip limit doubled, whose solution is twice the
virgin solution at half the displacement, so :math:`R = R_r - 2(R_b((q_r - q)/2) - R_b(0))`
with the structure's backbone :math:`R_b`, and a cycle :math:`\pm q_a` dissipates

$$
W = 8\int_0^{q_a}\big(R_b - R_b(0)\big)\,dq - 4q_a\big(R_b(q_a) - R_b(0)\big)
  = 4\,D_b(q_a),
$$

:math:`D_b(q_a)` the friction work done along the backbone up to :math:`q_a` (every slip of a
half cycle is twice the backbone's at half the displacement). `BendingCycles.masing_energy` is
the first form from the traced backbone. A point that stops slipping while the drive goes on
(`BendingCycles.unloaded`) breaks the premise: the first cycle then need not close.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
import scipy.sparse.linalg as spla

from skcable._checks import one_of, whole
from skcable._show import Shown, counted, quantity
from skcable.errors import ConvergenceError, InputError, PlausibilityWarning
from skcable.strand._arguments import real_number
from skcable.strand.fe.stages import StageSlip
from skcable.strand.fe.supports import StrandSupports
from skcable.strand.fe.terms import FIELDS

__all__ = [
    "ACTIVE_SET_ROUNDS", "BendingCycles", "ON_LIMIT", "PROBE", "SIMULTANEOUS", "TENSION_MATCH",
    "bending_cycles",
]  # fmt: skip

#: how far into a step (relative to it) the tangent of its start is taken: the stages on their
#: slip limit go on slipping as the load goes on, and unload (stick) after a reversal
PROBE = 1e-7
#: events closer than this (relative to the step) to the first are taken at once
SIMULTANEOUS = 1e-9
#: a stage whose moment is within this of its slip moment (relative) is on its limit
ON_LIMIT = 1e-6
#: tangents tried at a vertex until the stages' status agrees with the rate it gives
ACTIVE_SET_ROUNDS = 4
#: the largest relative difference between the strand's axial force and its law's tension
#: before `bending_cycles` warns
TENSION_MATCH = 0.01


@dataclass(repr=False, eq=False)
class BendingCycles(Shown):
    """A strand bent back and forth (`bending_cycles`): the vertices of its path and its energies.

    Attributes
    ----------
    drive : ndarray (n,)
        The driven dof at every vertex, from the value the supports give it (rad for a slope, m
        for a displacement): 0 (the unbent strand), the backbone to ``+amplitude``, then each
        cycle's branches.
    reaction : ndarray (n,)
        The support's reaction on the driven dof there (N·m for a slope, N for a displacement):
        what the support applies to the strand.
    work : ndarray (n,)
        The friction work of the stages in the step ending at each vertex (J; 0 at the first).
    branch : ndarray (n,) of int
        0 for the start and the backbone; ``2c + 1`` and ``2c + 2`` for the down and up branches
        of cycle c (from 0).
    steps : list of StepResult
        The model's steps at the schedule's points (the start, ``n_steps`` per quarter cycle).
    step_vertex : ndarray of int
        The vertex of each step.
    amplitude : float
        ``a``: the drive swings between ``±a`` about the support's own value.
    dof, end : str
        The driven dof and its end.
    exact : bool
        Whether the steps were cut at every event (module text).
    inexact : int
        Pieces of the path where the stages did not slip as the tangent at their start had them
        slip: there the loop's area is not exact.
    unloaded : ndarray of int
        Per branch (0 the backbone), how many stage–point pairs stopped slipping while the drive
        went on (a point whose curvature turned back: the slip elsewhere unloading it). Masing's
        rules hold for the structure when the backbone has none (module text); a first cycle
        after a backbone with some need not close (it shakes down to a steady loop).
    failure : str or None
        Why the path stopped before its end (``on_failure="stop"``), else None.
    """

    drive: np.ndarray
    reaction: np.ndarray
    work: np.ndarray
    branch: np.ndarray
    steps: list
    step_vertex: np.ndarray
    amplitude: float
    dof: str
    end: str
    exact: bool
    inexact: int = 0
    unloaded: np.ndarray | None = None
    failure: str | None = None

    @property
    def cycles(self) -> int:
        """The complete cycles traced (back at ``+a``)."""
        done = 0
        while (
            np.any(self.branch == 2 * done + 2)
            and self.drive[self.branch == 2 * done + 2][-1] == self.amplitude
        ):
            done += 1
        return done

    @property
    def backbone(self) -> tuple[np.ndarray, np.ndarray]:
        """``(drive, reaction)`` of the first loading, from the unbent strand to ``+a``."""
        keep = self.branch == 0
        return self.drive[keep], self.reaction[keep]

    def _cycle(self, c: int) -> np.ndarray:
        if not 0 <= c < self.cycles:
            raise InputError("cycle", f"must lie in [0, {self.cycles}) (complete cycles traced), got {c!r}")
        (inside,) = np.nonzero((self.branch == 2 * c + 1) | (self.branch == 2 * c + 2))
        return np.concatenate([[inside[0] - 1], inside])  # from the vertex at +a where it starts

    def loop(self, cycle: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """``(drive, reaction)`` of cycle ``cycle``: from ``+a`` down to ``−a`` and back, every
        vertex (the first and last at ``+a``)."""
        index = self._cycle(cycle)
        return self.drive[index], self.reaction[index]

    @property
    def energy_per_cycle(self) -> np.ndarray:
        """``∮ R dq`` of each cycle (J): the energy the support puts in, which the strand
        dissipates (the trapezoidal rule over the vertices: exact with ``exact``)."""
        return np.array([_area(*self.loop(c)) for c in range(self.cycles)])

    @property
    def friction_per_cycle(self) -> np.ndarray:
        """The friction work the stages did over each cycle (J), summed over its steps."""
        return np.array([float(np.sum(self.work[self._cycle(c)[1:]])) for c in range(self.cycles)])

    @property
    def backbone_friction(self) -> float:
        """The friction work done along the backbone (J)."""
        return float(np.sum(self.work[self.branch == 0]))

    @property
    def masing_energy(self) -> float:
        """Masing's energy per cycle of the traced backbone (J):
        ``8 ∫ (R_b − R_b(0)) dq − 4 a (R_b(a) − R_b(0))`` (module text), the trapezoidal rule
        over its vertices."""
        q, R = self.backbone
        if q[-1] != self.amplitude:
            raise ConvergenceError(
                f"bending_cycles stopped before the backbone reached the amplitude: {self.failure}"
            )
        R = R - R[0]
        q = q - q[0]
        return 8.0 * _area(q, R) - float(4.0 * q[-1] * R[-1])

    def to_frame(self):
        """A pandas DataFrame of the vertices: drive, reaction, work, branch."""
        import pandas as pd

        return pd.DataFrame(
            dict(drive=self.drive, reaction=self.reaction, work=self.work, branch=self.branch)
        )

    def __repr__(self) -> str:
        unit = "rad" if self.dof in ("v'", "w'", "phi") else "m"
        shown = [
            quantity("amplitude", self.amplitude, unit),
            quantity("energy_per_cycle", self.energy_per_cycle, "J"),
            quantity("friction_per_cycle", self.friction_per_cycle, "J"),
            quantity("inexact", self.inexact),
            quantity("unloaded", self.unloaded),
        ]
        end = f"stopped: {self.failure}" if self.failure else "done"
        counts = f"{counted([self.cycles], 'cycle')}, {counted([self.drive.size], 'point')}"
        return f"BendingCycles({self.end} {self.dof}, {counts}, {end}: {', '.join(shown)})"


def _area(q, R) -> float:
    """``∫ R dq`` by the trapezoidal rule over the vertices (J)."""
    return float(np.sum(0.5 * (R[1:] + R[:-1]) * np.diff(q)))


class _Tracer:
    """The path of `bending_cycles`: the model, where its history lives, the driven dof, the last
    converged vertex (dofs, state, the rate of the piece that reached it) and the vertices so far."""

    def __init__(self, model, dof, end, load, options):
        self.model, self.dof, self.end, self.load, self.options = model, dof, end, load, options
        found = [
            (i, bound)
            for i, bound in enumerate(model.bound(t) for t in model.terms)
            if isinstance(getattr(bound, "slip", None), StageSlip)
        ]
        if not found:
            raise InputError(
                "model",
                f"its slip law {getattr(model, 'slip', None)!r:.80} keeps no history of slip: bending it "
                "back and forth traces no loop (give slip=StageSlip(LayerSlipLaw(...)))",
            )
        self.index, self.wires = found[0]
        self.law = self.wires.slip
        offsets = {name: int(model.offsets[i]) for i, name in enumerate(FIELDS)}
        self.driven = StrandSupports.index(end, dof, model.bases, offsets)
        self.base = float(getattr(model.supports, end)[dof])
        self.dx = model.layout.dx
        shape = (slice(None), slice(None), None, None)
        self.B, self.M = self.law.law.stiffness[shape], self.law.law.slip_moment[shape]
        self.rate = None  # dU/dq of the piece that reached the last vertex
        self.moved, self.direction = np.zeros(self.B.shape, dtype=bool), 0.0  # of that piece
        self.unloaded: dict[int, int] = {}  # per branch: stages that stopped slipping within it
        self.rows: list[tuple[float, float, float, int]] = []  # (drive, reaction, work, branch)
        self.inexact = 0
        start = self.solve(0.0, None, None)
        self._check_tension(start.force)
        self.U, self.state = start.dofs, start.state
        self.rows.append((0.0, float(start.reactions[end][dof]), 0.0, 0))
        self.start = start

    def _check_tension(self, force: float) -> None:
        """Warn when the strand's axial force is not the tension the law's knees are for."""
        tension = getattr(self.law.law, "tension", None)
        if tension is None or abs(force - tension) <= TENSION_MATCH * abs(tension):
            return
        argument = "force" if "force" in self.load else "strain" if "strain" in self.load else "model"
        warnings.warn(
            PlausibilityWarning(
                argument,
                f"the strand's axial force {force:.6g} N is not the tension {tension:.6g} N of its layer "
                "law, whose knees are that tension's (the law's parameters do not follow the model's)",
            ),
            stacklevel=4,
        )

    def solve(self, q, guess, state):
        prescribed = {self.end: {self.dof: self.base + q}}
        return self.model.solve(
            self.load.get("strain"), guess, state, force=self.load.get("force"), options=self.options,
            diagnose=False, prescribed=prescribed,
        )  # fmt: skip

    def friction(self, before, after) -> float:
        """The friction work between two states (J)."""
        per_point = self.law.work(before[self.index], after[self.index])
        return float(np.sum(per_point.sum(axis=0) * self.dx))

    def curvature(self, U) -> np.ndarray:
        return self.wires.principal(self.model.generalized_strains(U))

    def _rate(self, guide, direction: float, span: float):
        """``(dU/dq, sticking)`` with the tangent at the last vertex moved a little way (`PROBE`
        of ``span``) along ``direction`` times ``guide`` (a rate; None: at the vertex itself),
        and the stages that stick there."""
        model, U0 = self.model, self.U
        probe = U0 if guide is None else U0 + (PROBE * span * direction) * guide
        _, K, _ = model.assemble(probe, self.state, force=self.load.get("force", 0.0))
        K = K.tocsr()
        free = model.free
        rate = np.zeros(model.assembly.N)
        rate[self.driven] = 1.0
        column = np.asarray(K[free][:, [self.driven]].todense()).ravel()
        rate[free] = spla.spsolve(K[free][:, free].tocsc(), -column)
        slip = self.state[self.index]
        sticking = (np.abs(self.B * (self.curvature(probe)[:, None] - slip)) <= self.M) & (self.M > 0)
        return rate, sticking

    def tangent_rate(self, moment, direction: float, span: float):
        """``(dU/dq, sticking)`` at the last vertex as the drive moves along ``direction`` (+1 or
        −1): the stages on their slip limit slip on where their moment grows along the rate and
        stick where it falls (after a reversal, or where the slip elsewhere unloads a point).
        The status is first taken along the last piece's rate, then along the new rate until
        the two agree (`ACTIVE_SET_ROUNDS`)."""
        on_limit = (np.abs(moment) >= self.M * (1.0 - ON_LIMIT)) & (self.M > 0) & (self.B > 0)
        guide = self.rate
        for _ in range(ACTIVE_SET_ROUNDS):
            rate, sticking = self._rate(guide, direction, span)
            speed = self.B * direction * self.curvature(rate)[:, None]
            if np.array_equal(on_limit & ~sticking, on_limit & (speed * np.sign(moment) > 0)):
                break
            guide = rate
        return rate, sticking

    def next_event(self, q0: float, q1: float):
        """``(q, rate, sticking, first)``: where the first stage starts to slip between the last
        vertex at ``q0`` and ``q1`` (``q1`` if none does), the rate of the piece, the stages that
        stick along it, and those that start to slip at its end."""
        direction, span = float(np.sign(q1 - q0)), abs(q1 - q0)
        moment = self.B * (self.curvature(self.U)[:, None] - self.state[self.index])
        rate, sticking = self.tangent_rate(moment, direction, span)
        speed = self.B * direction * self.curvature(rate)[:, None]
        moving = sticking & (speed != 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):  # >= 0: a sticking stage is inside its limit
            distance = np.where(
                moving, (np.sign(speed) * self.M - moment) / np.where(moving, speed, 1.0), np.inf
            )
        first = max(float(distance.min(initial=np.inf)), 0.0)
        if first >= span:
            return q1, rate, sticking, distance <= span * (1.0 + SIMULTANEOUS)
        return q0 + direction * first, rate, sticking, distance <= first + span * SIMULTANEOUS

    def advance(self, q1: float, exact: bool, branch: int):
        """From the last vertex to ``q1``, cut at every event with ``exact``; returns the
        `StepResult` at ``q1``."""
        self.unloaded.setdefault(branch, 0)
        q = self.rows[-1][0]
        step, pieces = None, 0
        while q != q1:
            pieces += 1
            if pieces > 2 * self.state[self.index].size + 16:  # each stage starts to slip once a step
                raise ConvergenceError(
                    f"bending_cycles: the slip events between drive {self.rows[-1][0]:.6g} and {q1:.6g} do "
                    f"not advance ({pieces - 1} pieces, more than twice the stages' points)"
                )
            if exact:
                target, rate, sticking, first = self.next_event(q, q1)
                guess = self.U + (target - q) * rate
            else:
                target, rate, guess = q1, None, self.U
            step = self.solve(target, guess, self.state)
            moved = np.abs(self.B * (step.state[self.index] - self.state[self.index])) > 1e-9 * self.M
            if exact:  # a stage that slipped where the tangent had it stick, or the reverse
                slipping = ~sticking & (self.M > 0) & (self.B > 0)
                self.inexact += bool(np.any(moved & sticking & ~first) or np.any(slipping & ~moved))
            direction = np.sign(target - q)
            if direction == self.direction:  # the drive goes on: a stage that slipped and stops unloads
                self.unloaded[branch] += int(np.sum(self.moved & ~moved))
            work = self.friction(self.state, step.state)
            self.rows.append((float(target), float(step.reactions[self.end][self.dof]), work, branch))
            self.U, self.state, self.rate, q = step.dofs, step.state, rate, target
            self.moved, self.direction = moved, direction
        return step


def _schedule(amplitude: float, cycles: int, n_steps: int) -> list[tuple[int, np.ndarray]]:
    """``(branch, targets)`` of the backbone and of every branch of every cycle."""
    a = amplitude
    out = [(0, np.linspace(0.0, a, n_steps + 1)[1:])]
    for c in range(cycles):
        out.append((2 * c + 1, np.linspace(a, -a, 2 * n_steps + 1)[1:]))
        out.append((2 * c + 2, np.linspace(-a, a, 2 * n_steps + 1)[1:]))
    return out


def bending_cycles(
    model,
    amplitude: float,
    *,
    dof: str = "v'",
    end: str = "right",
    cycles: int = 2,
    n_steps: int = 8,
    strain: float | None = None,
    force: float | None = None,
    exact: bool = True,
    on_failure: str = "raise",
    options=None,
    **newton_options,
) -> BendingCycles:
    """Bend a strand back and forth by one held dof and trace its loop (the module's text).

    Parameters
    ----------
    model : StrandModel
        A model whose slip law keeps a history (``slip=StageSlip(law)``) and whose supports
        hold ``dof`` at ``end`` (its value there is the centre of the swing).
    amplitude : float
        ``a`` > 0: the drive swings between ``±a`` (rad for a slope, m for a displacement).
    dof, end : str
        The driven dof, one the supports hold at ``end`` ("left" or "right"): ``"v'"`` or
        ``"w'"`` (an end rotation; the reaction is the end moment), ``"v"`` or ``"w"`` (an end
        moved across the axis; the reaction is the transverse force), ...
    cycles : int
        Cycles ``+a → −a → +a`` after the backbone, >= 1.
    n_steps : int
        Steps from 0 to ``a`` (a branch takes twice as many), >= 1.
    strain, force : float, optional
        The axial load of every solve, as `StrandModel.solve` takes it (``axial="strain"``:
        ``strain``; ``axial="force"``: ``force``, N; ``axial="none"``: neither).
    exact : bool
        Cut the steps at every event (module text): the loop's area is then exact.
    on_failure : {"raise", "stop"}
        What a step that does not converge does: raise `ConvergenceError`, or return the path
        traced so far with ``failure`` set.
    options, **newton_options
        Newton settings of every solve, as `StrandModel.solve` takes them.

    Returns
    -------
    BendingCycles
    """
    amplitude = _checked_amplitude(model, amplitude, dof, end)
    whole("cycles", cycles, 1)
    whole("n_steps", n_steps, 1)
    one_of("on_failure", on_failure, ("raise", "stop"))
    from skcable.fe import NewtonOptions

    options = NewtonOptions.of(model.options if options is None else options, **newton_options)
    load = {k: v for k, v in (("strain", strain), ("force", force)) if v is not None}
    tracer = _Tracer(model, dof, end, load, options)
    steps, step_vertex, failure = [tracer.start], [0], None
    for branch, targets in _schedule(amplitude, cycles, n_steps):
        for target in targets.tolist():
            try:
                steps.append(tracer.advance(target, bool(exact), branch))
            except ConvergenceError as exc:
                said = str(exc.args[0]).split(" (last ")[0]
                failure = f"no convergence between drive {tracer.rows[-1][0]:.6g} and {target:.6g}: {said}"
                if on_failure == "raise":
                    raise ConvergenceError("bending_cycles: " + failure, exc.history, exc.last) from exc
                break
            step_vertex.append(len(tracer.rows) - 1)
        if failure:
            break
    q, R, work, branches = (np.array(column) for column in zip(*tracer.rows, strict=True))
    return BendingCycles(
        q, R, work, branches.astype(int), steps, np.array(step_vertex), amplitude, dof, end, bool(exact),
        tracer.inexact, np.array([tracer.unloaded[b] for b in sorted(tracer.unloaded)]), failure,
    )  # fmt: skip


def _checked_amplitude(model, amplitude, dof, end) -> float:
    one_of("end", end, ("left", "right"))
    held = getattr(model.supports, end)
    if dof not in held:
        raise InputError(
            "dof", f"{dof!r} is not held at the {end} end (it holds {sorted(held)}): hold it in supports="
        )
    amplitude = real_number("amplitude", amplitude, lower=0.0, strict=True)
    for value in (held[dof] + amplitude, held[dof] - amplitude):
        StrandSupports.value(end, dof, value, "amplitude")  # a slope within MAX_SLOPE
    return amplitude
