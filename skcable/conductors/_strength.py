r"""Residual rated strength of a conductor with broken wires, two ways.

**The layer rule** (RTE's rule, as mechaphlowers' ``AdditiveLayerRts`` computes it): the rated
strength less the strength of each broken wire,

.. math:: RRTS = RTS - \sum_k n_k\,s_k,

with :math:`n_k` broken wires in layer :math:`k` and :math:`s_k` the part of the rated strength one
wire of that layer carries. Without a catalogue value, :math:`s_k` shares the rated strength out
over the wires in proportion to their own ultimate axial force
:math:`A_j \cos\alpha_j\,\sigma_{u,j}` (the wire laws of `skcable.strand`).

**The capacity curve** (`skcable.strand.StrandModel.capacity_curve`, the strand finite element):
the axial force at which the first intact wire of the damaged strand ruptures, against the intact
strand's, gives :math:`RRTS = RTS\,F_{r,\text{damaged}}/F_{r,\text{intact}}` — the broken wires'
share of the force and the bending of the eccentric net section both included.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import nonnegative, one_of, positive_scalar
from skcable._show import Shown
from skcable.errors import ConvergenceError, InputError

__all__ = ["layer_rrts", "wire_strengths", "ResidualStrength", "residual_strength"]


def layer_rrts(rts, broken, wire_strength) -> float:
    """``rts - sum(broken_k * wire_strength_k)`` (N): the layer rule.

    ``broken`` and ``wire_strength`` are per layer (any order, the same for both); the result
    must stay > 0.
    """
    rts = positive_scalar("rts", rts)
    broken = np.atleast_1d(nonnegative("broken", broken))
    strength = np.atleast_1d(nonnegative("wire_strength", wire_strength))
    if broken.shape != strength.shape or broken.ndim != 1:
        raise InputError(
            "broken", f"must be one count per layer of wire_strength {strength.shape}, got {broken.shape}"
        )
    if np.any(broken != np.round(broken)):
        raise InputError("broken", f"must be whole numbers of wires, got {broken.tolist()}")
    residual = rts - float(broken @ strength)
    if not residual > 0:
        raise InputError("broken", f"leave no strength: rts - sum(n s) = {residual:.6g} N")
    return residual


def wire_strengths(strand, rts) -> np.ndarray:
    """One wire's share of ``rts`` (N) per layer (core first): ``rts`` shared in proportion to
    each wire's ultimate axial force ``A cos(alpha) sigma_u`` (its material's
    ``stress_rupture``), over every wire of the intact strand."""
    rts = positive_scalar("rts", rts)
    wires = strand.wires()
    force = wires.area * np.cos(wires.lay_angle) * strand.wire_materials().take("stress_rupture")
    share = rts * force / np.sum(force)
    return np.array([share[wires.layer == k][0] for k in range(len(strand.layers) + 1)])


@dataclass(frozen=True)
class ResidualStrength(Shown):
    """Residual rated strength of a damaged conductor.

    ``rrts`` (N) and ``fraction = rrts / rts``; ``method``; ``broken`` per layer (core first);
    for the capacity method ``force_intact`` and ``force_damaged``, the forces at the first wire
    rupture (N), else None.
    """

    rrts: float
    rts: float
    method: str
    broken: np.ndarray
    force_intact: float | None = None
    force_damaged: float | None = None

    @property
    def fraction(self) -> float:
        return self.rrts / self.rts


def _rupture_force(strand, kwargs):
    from skcable.strand import StrandModel

    curve = StrandModel(strand, **kwargs).capacity_curve(on_failure="stop")
    if not curve.ruptured:
        raise ConvergenceError(
            f"residual_strength: the capacity curve stopped before rupture ({curve.failure})"
        )
    return float(curve.force[-1])


def residual_strength(strand, damage, *, rts, method: str = "layers", wire_strength=None, **model):
    """Residual rated strength of ``strand`` with the wires ``damage`` broken.

    Parameters
    ----------
    strand : skcable.strand.Strand
        The intact conductor.
    damage : int or list of (layer, index)
        As `Strand.damaged`: n adjacent outer wires, or those wires.
    rts : float
        The intact conductor's rated tensile strength (N), from its standard (`Conductor.rts`).
    method : {"layers", "capacity"}
        The layer rule, or the capacity curves of the strand finite element (module text).
    wire_strength : array_like, optional
        One wire's strength per layer (core first), N, for the layer rule (e.g. a catalogue's);
        by default `wire_strengths`.
    **model
        Passed to `skcable.strand.StrandModel` for the capacity method (``length``,
        ``n_elements``...).
    """
    one_of("method", method, ("layers", "capacity"))
    rts = positive_scalar("rts", rts)
    damaged = (
        strand.damaged(damage) if isinstance(damage, (int, np.integer)) else strand.damaged(wires=damage)
    )
    wires = damaged.wires()
    broken = np.array([np.sum(~wires.intact & (wires.layer == k)) for k in range(len(strand.layers) + 1)])
    if method == "layers":
        strength = wire_strengths(strand, rts) if wire_strength is None else wire_strength
        return ResidualStrength(layer_rrts(rts, broken, strength), rts, method, broken)
    intact, after = _rupture_force(strand, model), _rupture_force(damaged, model)
    return ResidualStrength(rts * after / intact, rts, method, broken, intact, after)
