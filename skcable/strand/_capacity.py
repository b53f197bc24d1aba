"""Capacity curves of a strand under imposed axial strain (seed 003 §4.3).

``K_Leq`` (eq. 4.30) is the step-weighted mean slope over the linear-elastic
range, i.e. the secant ``F(ε_e)/ε_e`` at the last step whose wires all stay
below the blend start ε'_y of the material law; ``toughness`` is the area
under the curve up to rupture (the first wire reaching ``eps_rupture``);
``D_r = 1 - U_T/U_T0`` (eq. 4.31) against the undamaged strand with the same
model settings.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from skcable.errors import ConvergenceError, InputError

__all__ = ["CapacityCurve", "capacity_curve"]


@dataclass
class CapacityCurve:
    """Force–strain curve and the state at every step.

    Attributes
    ----------
    strain, force, slip_fraction : ndarray
        Per step (the origin included), N for the force.
    steps : list of StepResult
    ruptured : bool
        Whether the curve ended at a wire's rupture strain.
    chatter_steps : list of int
        Steps whose element slip states did not settle (``slip="element"``):
        the union of the states met was kept (conservative).
    """

    model: object
    strain: np.ndarray
    force: np.ndarray
    slip_fraction: np.ndarray
    steps: list
    ruptured: bool
    chatter_steps: list = field(default_factory=list)
    n_steps: int = 0

    @cached_property
    def _elastic_end(self):
        """(strain, force) where the most strained wire reaches eps_y1, interpolated between steps."""
        limit = self.model.strand.material.eps_y1
        peak = np.concatenate([[0.0], [np.max(s.wire_strain) for s in self.steps]])
        beyond = np.flatnonzero(peak >= limit)
        if beyond.size == 0:
            return float(self.strain[-1]), float(self.force[-1])
        i = int(beyond[0])
        t = (limit - peak[i - 1]) / (peak[i] - peak[i - 1])
        strain = float(self.strain[i - 1] + t * (self.strain[i] - self.strain[i - 1]))
        # the force comes from the elastic side (the last elastic segment extended),
        # not from across the kink of the material law
        j = max(i - 2, 0)
        if i > 1:
            slope = (self.force[i - 1] - self.force[j]) / (self.strain[i - 1] - self.strain[j])
        else:
            slope = self.force[i] / self.strain[i]
        return strain, float(self.force[i - 1] + slope * (strain - self.strain[i - 1]))

    @property
    def elastic_limit(self) -> float:
        """Strand strain at which the first wire leaves the linear branch (eps_y1), interpolated."""
        return self._elastic_end[0]

    @property
    def K_Leq(self) -> float:
        """Equivalent linear stiffness over [0, elastic_limit] (N), eq. 4.30: the secant there."""
        strain, force = self._elastic_end
        return force / strain

    @property
    def toughness(self) -> float:
        """Area under the force–strain curve (N), up to rupture or the last step."""
        return float(np.trapezoid(self.force, self.strain))

    @cached_property
    def reference(self):
        """The undamaged strand's curve with the same settings (for D_r)."""
        model = self.model
        intact = replace(model.strand, broken=frozenset())
        twin = type(model)(intact, model.length, mesh=model.mesh, slip=model.slip, mu=model.mu)
        return capacity_curve(twin, n_steps=self.n_steps)

    @property
    def D_r(self) -> float:
        """Damage index ``1 - U_T / U_T0`` (eq. 4.31)."""
        return 1.0 - self.toughness / self.reference.toughness


def capacity_curve(model, max_strain=None, n_steps=None, *, state_passes: int = 6) -> CapacityCurve:
    """Pull ``model`` step by step until a wire breaks (or ``max_strain``).

    ``n_steps`` (default 60) strain increments, half of them up to twice the
    yield strain and half from there to ``max_strain`` (default 1.5 eps_rupture;
    the curve stops at the first wire rupture). A step that fails is halved up
    to 8 times; with ``slip="element"`` each step iterates the element states
    to a fixed point (at most ``state_passes``).
    """
    material = model.strand.material
    n_steps = int(n_steps or 60)
    if n_steps < 4:
        raise InputError("n_steps", f"must be at least 4, got {n_steps!r}")
    top = float(max_strain) if max_strain is not None else 1.5 * material.eps_rupture
    # half the steps up to twice the yield strain (where slip and yield shape the
    # curve and K_Leq is measured), half from there to rupture
    knee = min(2.0 * material.eps_y, top)
    schedule = np.unique(
        np.concatenate(
            [
                np.linspace(0.0, knee, n_steps // 2 + 1),
                np.linspace(knee, max(top, knee), n_steps - n_steps // 2 + 1),
            ]
        )
    )[1:]
    n_elements = model.mesh.t.shape[1]
    element_slip = np.zeros(n_elements, dtype=bool) if model.slip == "element" else None
    strains, forces, fractions, steps, chatter = [0.0], [0.0], [0.0], [], []
    U, eps, previous = None, 0.0, None
    ruptured = False
    for goal in schedule:
        while eps < goal - 1e-15:
            target = goal
            for _ in range(9):
                try:
                    guess = None if U is None else _extrapolate(U, previous, eps, target)
                    result = _solve_with_states(model, guess, target, element_slip, state_passes)
                    break
                except ConvergenceError:
                    target = eps + 0.5 * (target - eps)
            else:
                raise ConvergenceError(
                    f"capacity_curve: no convergence beyond strain {eps:.6g} after 8 cutbacks"
                )
            previous, (U, step, element_slip, settled) = (U, eps), result
            if not settled:
                chatter.append(len(steps))
            eps = target
            steps.append(step)
            strains.append(step.strain)
            forces.append(step.force)
            fractions.append(step.slip_fraction)
            if np.max(step.wire_strain) >= material.eps_rupture:
                # end the curve where the most strained wire reaches its rupture strain
                before = np.max(steps[-2].wire_strain) if len(steps) > 1 else 0.0
                t = (material.eps_rupture - before) / (np.max(step.wire_strain) - before)
                strains[-1] = strains[-2] + t * (strains[-1] - strains[-2])
                forces[-1] = forces[-2] + t * (forces[-1] - forces[-2])
                ruptured = True
                break
        if ruptured:
            break
    return CapacityCurve(
        model, np.array(strains), np.array(forces), np.array(fractions), steps, ruptured, chatter, n_steps
    )


def _extrapolate(U, previous, eps, target):
    U_prev, eps_prev = previous if previous[0] is not None else (None, 0.0)
    if U_prev is None or eps == eps_prev:
        return U * (target / eps) if eps > 0 else None
    return U + (U - U_prev) * (target - eps) / (eps - eps_prev)


def _solve_with_states(model, guess, strain, element_slip, passes):
    from skcable.strand._model import StepResult

    seen = []
    settled = True
    for _ in range(passes):
        U, state, history, R = model.solve_step(guess, strain, element_slip)
        if model.slip != "element":
            break
        exceeded = np.any(np.abs(state["curvature"]) > state["kappa_m"], axis=(0, 2))
        new = exceeded | (element_slip & np.any(state["slipping"], axis=(0, 2)) & False)
        if np.array_equal(new, element_slip):
            break
        if any(np.array_equal(new, old) for old in seen):  # chattering: keep the union, stop
            element_slip = element_slip | new
            U, state, history, R = model.solve_step(U, strain, element_slip)
            settled = False
            break
        seen.append(element_slip.copy())
        element_slip, guess = new, U
    step = StepResult(
        strain=strain,
        force=float(R[model.pull]),
        x=model.x_quad,
        curvature=state["curvature"],
        kappa_m=state["kappa_m"],
        slipping=np.asarray(state["slipping"]),
        wire_strain=np.where(model.alive[:, None, None], state["strain"], 0.0),
        wire_stress=state["stress"],
        dofs=U,
        iterations=len(history) - 1,
        history=history,
    )
    return U, step, element_slip, settled
