r"""The layer-by-layer stick/slip law in the strand finite element: a slip law with history.

`StageSlip` makes a [`StageLaw`][skcable.strand.StageLaw] (a
[`LayerSlipLaw`][skcable.strand.LayerSlipLaw]: one stage per helical layer) the slip law of
[`HelicalWires`][skcable.strand.HelicalWires]. At every quadrature point and principal axis the
state holds the slip curvature :math:`\kappa_{p,k}` of every stage as the last converged step
left it, and at every Newton iterate the law maps the point's principal curvature κ from that
state (the return mapping of `StageLaw.update`):

$$
m_k = \operatorname{clip}\big(B_k(\kappa - \kappa_{p,k}),\ -M_k,\ M_k\big), \qquad
M_c = \sum_k m_k, \qquad \frac{\partial M_c}{\partial\kappa} = \sum_{k\ \text{sticking}} B_k .
$$

The model keeps the new slip curvatures of a converged step (`next_state`), so the state is
committed step by step and the law traces Masing's loops under any path of the structure.

**What the model adds.** M_c is the *composite* moment; the section moment is
:math:`EI_w\kappa + M_c` with the wires' own bending :math:`EI_w` of `WireBending`, so the
law's :math:`EI_{\min}` must be the section's ``EI_slip`` and its stick share :math:`\sum_k B_k`
the section's ``EI_stick − EI_slip`` (the elastic ones: a `LayerSlipLaw` of the model's
strand at an axial strain in its wires' linear range; checked when a model takes the law, to
1e-6). The wires' strains follow the composite curvature :math:`M_c/(EI_{stick} - EI_{slip})`
as for any section law (one per point and axis: each layer's own stuck curvature is not
resolved in the wires' strains).

**Frozen parameters.** :math:`B_k` and :math:`M_k` are those of the law's own axial strain (its
tension): the model's axial strain does not move them (:math:`\partial M_c/\partial\varepsilon_a
= 0`). Load the model with the law's tension (``axial="force"``, ``solve(force=law.tension)``).
"""

from __future__ import annotations

import numpy as np

from skcable.errors import InputError
from skcable.strand._stages import StageLaw
from skcable.strand.fe.slip import SlipLaw

__all__ = ["StageSlip", "MATCH"]

#: how closely a `StageSlip` law's EI_min and stick share must match the model's section
MATCH = 1e-6


class StageSlip(SlipLaw):
    """A `StageLaw` (a `LayerSlipLaw`) as the strand element's slip law, with its history (the
    module's text).

    Parameters
    ----------
    law : StageLaw
        The section's stages (``strand.LayerSlipLaw(section, mu=, tension=)``), or any
        `StageLaw` whose EI_min and stick share are the model's section's.
    mu : float, optional
        The friction coefficient of the Cardou law the results report beside (``kappa_m`` of a
        `StepResult`: not used by this law); default the law's largest ``mu``, else 0.5.

    """

    name = "stages"
    smooth = False
    layered = True

    def __init__(self, law, mu=None):
        if not isinstance(law, StageLaw):
            raise InputError(
                "law", f"must be a StageLaw (strand.LayerSlipLaw, strand.StageLaw), got {law!r:.80}"
            )
        if mu is None:
            mu = float(np.max(law.mu)) if hasattr(law, "mu") else 0.5
        super().__init__(mu)
        self.law = law
        carries = law.slip_moment > 0
        self._first = np.where(carries, law.kappa_slip, np.inf).min(axis=1)  # (2,)

    def __repr__(self) -> str:
        return f"StageSlip({self.law!r})"

    def check(self, model) -> None:
        """Refuse a model whose section is not the law's (module text): EI_min and the stick
        share ``sum B_k`` against the section's elastic EI_slip and EI_stick − EI_slip."""
        section = model.strand_section
        for what, law_value, own in (
            ("EI_min", self.law.EI_min, section.EI_slip),
            ("stick share sum(B_k)", self.law.stiffness.sum(axis=1), section.EI_stick - section.EI_slip),
        ):
            off = np.abs(law_value - own) > MATCH * np.maximum(section.EI_stick, 1e-300)
            if off.any():
                raise InputError(
                    "slip",
                    f"the law's {what} {np.round(law_value, 6).tolist()} N·m² is not the model's section's "
                    f"{np.round(own, 6).tolist()} N·m² (to {MATCH:g} of EI_stick): a law of another strand, "
                    "or of an axial strain beyond its wires' linear range",
                )

    def initial_state(self, shape):
        """Zero slip curvatures ``(2, n_stages, n_elements, n_quad)``: the straight, unslipped strand."""
        return self.law.initial_slip(shape[1:])

    def _checked(self, kappa, state) -> np.ndarray:
        state = np.asarray(state, dtype=float)
        if state.shape != (2, self.law.n_stages, *kappa.shape[1:]):
            raise InputError(
                "state",
                f"the slip curvatures of {self!r:.60} must have shape (2, n_stages={self.law.n_stages}, "
                f"n_elements, n_quad) = {(2, self.law.n_stages, *kappa.shape[1:])}, got {state.shape}: "
                "a state of another law or mesh",
            )
        if not np.all(np.isfinite(state)):
            raise InputError(
                "state", f"holds {int(np.sum(~np.isfinite(state)))} slip curvatures that are not finite"
            )
        return state

    def moment(self, kappa, points, state):
        """The stages' moment ``M_c`` (N·m), its tangent (N·m²) and 0 for ∂/∂ε_a (frozen law)."""
        response = self.law.update(kappa, self._checked(kappa, state))
        EI_min = self.law.EI_min.reshape((2,) + (1,) * (kappa.ndim - 1))
        return response.moment - EI_min * kappa, response.tangent - EI_min, np.zeros_like(kappa)

    def _stages(self, kappa, state):
        """The checked ``state`` and the stages' B_k and M_k over the points of ``kappa``."""
        extra = (slice(None), slice(None)) + (None,) * (kappa.ndim - 1)
        return self._checked(kappa, state), self.law.stiffness[extra], self.law.slip_moment[extra]

    def energy(self, kappa, points, state):
        """The potential of `moment` at a fixed state (J/m): per stage ``½ B d²`` while it
        sticks, ``M (|d| − M/(2B))`` once it slips, ``d = κ − κ_p``."""
        state, B, M = self._stages(kappa, state)
        d = np.abs(kappa[:, None] - state)
        safe = np.where(B > 0, B, 1.0)
        inside = B * d <= M
        psi = np.where(inside, 0.5 * B * d**2, M * (d - 0.5 * M / safe))
        return np.sum(np.where(B > 0, psi, 0.0), axis=1)

    def next_state(self, kappa, points, state):
        """The slip curvatures the converged curvatures ``kappa`` leave: the committed state."""
        return self.law.update(kappa, self._checked(kappa, state)).slip

    def slipping(self, kappa, points, state):
        """Points where a stage is on its slip limit about each axis (``|m_k| >= M_k`` to 1e-9)."""
        state, B, M = self._stages(kappa, state)
        trial = np.abs(B * (kappa[:, None] - state))
        return np.any((M > 0) & (trial >= M * (1.0 - 1e-9)), axis=1)

    def onset(self, points):
        """The law's first knee about each axis (1/m), at every point: where the strand first
        slips; about an axis without friction, Cardou's κ_m there (finite: `BendingLaw`)."""
        first = self._first.reshape(2, *(1,) * points.axial.ndim)
        return np.where(np.isfinite(first), first, points.kappa_m)

    def work(self, previous, state) -> np.ndarray:
        """The friction work of a step per unit length (J/m) at every point and axis,
        ``sum_k M_k |κ_p,k − κ_p,k(previous)|``, from the states before and after it:
        ``(2, n_elements, n_quad)``."""
        previous, state = np.asarray(previous, dtype=float), np.asarray(state, dtype=float)
        if previous.shape != state.shape or state.ndim < 2 or state.shape[:2] != (2, self.law.n_stages):
            raise InputError(
                "state", f"two states of this law's shape, got {previous.shape} and {state.shape}"
            )
        extra = (slice(None), slice(None)) + (None,) * (state.ndim - 2)
        return np.sum(self.law.slip_moment[extra] * np.abs(state - previous), axis=1)
