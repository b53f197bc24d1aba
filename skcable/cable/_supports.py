"""End conditions of seed 001 §3.4 that are not a plain constraint.

Given maximum tension (a counterweight over a pulley, §3.4.1) and given
horizontal tension (§3.4.2, and §3.4.6 for supports at different heights)
are the ``T_max`` and ``H`` constraints of :func:`~skcable.cable.catenary`.
This module adds the ring sliding on a rough rod (§3.4.3), the anchor block
on a rough floor (§3.4.4) and the sliding point load (§3.4.5).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import nonnegative, positive, real, require
from skcable._xp import namespace
from skcable.cable._catenary import Catenary, catenary
from skcable.cable._roots import find_root
from skcable.errors import InputError

__all__ = ["SlidingLoad", "anchor_block_weight", "ring_on_rod", "sliding_load"]


def ring_on_rod(dh, w, length, mu) -> Catenary:
    r"""Catenary whose end B is a ring on a rough horizontal rod, at the limit of slip.

    A is fixed at (0, 0); the ring at height ``dh`` holds while
    ``H <= mu·V_B`` (seed 001 §3.4.3), i.e. while the cable meets the rod at
    ``sinh u_B >= 1/mu``. At the limit ``sinh u_B = 1/mu`` the length and
    height give ``a`` in closed form,

    .. math:: a = \frac{S^2 - dh^2}{2(S\sinh u_B - dh\cosh u_B)},

    and the span follows; the ring slides if pulled any farther.

    Returns
    -------
    Catenary
        The limiting catenary (its ``span`` is the largest that holds).
    """
    dh = real("dh", dh)
    w, length, mu = positive("w", w), positive("length", length), positive("mu", mu)
    xp = namespace(dh, w, length, mu)
    require("length", length > xp.abs(dh), "must exceed |dh| to reach the rod", length)
    sinh_b = 1.0 / mu
    cosh_b = xp.sqrt(1.0 + sinh_b * sinh_b)
    denominator = length * sinh_b - dh * cosh_b
    require(
        "mu",
        denominator > 0,
        "is so large that the ring holds at every span the cable can reach (no slip limit)",
        mu,
    )
    a = (length - dh) * (length + dh) / (2.0 * denominator)
    u_b = xp.arcsinh(sinh_b)
    span = a * (u_b - xp.arcsinh(sinh_b - length / a))
    return catenary(span, dh, w, H=w * a)


def anchor_block_weight(solution, mu, *, end: str = "A"):
    """Least weight of a block on a rough floor anchoring one end (seed 001 §3.4.4).

    The cable lifts the block by ``V`` and drags it by ``H``; with normal
    force ``N = W - V`` the block holds while ``H <= mu·N``, so
    ``W >= V + H/mu``.

    Parameters
    ----------
    solution : CableSolution
        The cable (any closed form or BVP result).
    mu : float
        Friction coefficient block–floor, > 0.
    end : {"A", "B"}
    """
    mu = positive("mu", mu)
    if end not in ("A", "B"):
        raise InputError("end", f"must be 'A' or 'B', got {end!r}")
    return (solution.V_A if end == "A" else solution.V_B) + solution.H / mu


@dataclass(frozen=True)
class SlidingLoad:
    """Solution of :func:`sliding_load`: two symmetric catenary arcs.

    Attributes
    ----------
    arc : Catenary
        The left arc, from A to the load point at mid-span.
    H, V_A, V_B, T_A, T_B : float
        Horizontal tension, reactions and support tensions (N).
    y_load : float
        Height of the load point relative to the supports (m, negative).
    P, length : float
        The data.
    """

    arc: Catenary
    P: float
    length: float

    @property
    def H(self):
        return self.arc.H

    @property
    def V_A(self):
        return self.arc.V_A

    V_B = V_A

    @property
    def T_A(self):
        return self.arc.T_A

    T_B = T_A

    @property
    def y_load(self):
        return self.arc.dh

    def residual(self) -> float:
        """Arc residual, load-point equilibrium and total length, relative."""
        arc = self.arc
        scale = arc.w * self.length + self.P
        return max(
            arc.residual(),
            abs(float(2.0 * -arc.V_B - self.P)) / scale,  # the two arcs hold P
            abs(float(2.0 * arc.length - self.length)) / self.length,
        )


def sliding_load(span, w, length, P) -> SlidingLoad:
    r"""Point load ``P`` free to slide on a cable with supports at equal height.

    The load settles at mid-span; each half is a catenary arc whose end
    tension at the load carries ``P/2`` vertically (seed 001 §3.4.5). With
    the load point at hyperbolic angle :math:`u_C = -\operatorname{asinh}(P/2wa)`,
    the parameter ``a`` solves
    :math:`\sinh u_C - \sinh(u_C - \mathrm{span}/2a) = S/2a`.
    """
    span, w, length = positive("span", span), positive("w", w), positive("length", length)
    P = nonnegative("P", P)
    require("length", length > span, "must exceed the span", length)
    half, half_length = 0.5 * span, 0.5 * length

    def f(t, half, half_length, load):
        a = half * np.exp(t)
        u_c = -np.arcsinh(load / (2.0 * a))
        return (np.sinh(u_c) - np.sinh(u_c - half / a)) * a / half_length - 1.0

    t, _ = find_root(f, -5.0, 60.0, (half, half_length, P / w), what="sliding_load")
    a = half * np.exp(t)
    u_c = -np.arcsinh(P / (2.0 * w * a))
    y_c = 2.0 * a * np.sinh(u_c - half / (2.0 * a)) * np.sinh(half / (2.0 * a))
    return SlidingLoad(catenary(half, float(y_c), w, H=float(w * a)), float(P), float(length))
