"""End conditions of Goicolea (2012) §3.4 that are not a plain constraint.

Given maximum tension (a counterweight over a pulley, §3.4.1) and given
horizontal tension (§3.4.2, and §3.4.6 for supports at different heights)
are the ``T_max`` and ``H`` constraints of `catenary`.
This module adds the ring sliding on a rough rod (§3.4.3), the anchor block
on a rough floor (§3.4.4) and the sliding point load (§3.4.5).
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, float_range, positive, real, require, scalar
from skcable._xp import namespace
from skcable.cable._catenary import Catenary, catenary
from skcable.cable._roots import LOG_XTOL, find_root
from skcable.cable._special import asinh_step, log_cosh
from skcable.cable.solution import ACCEPT
from skcable.errors import ConvergenceError, InputError

__all__ = ["SlidingLoad", "anchor_block_weight", "ring_on_rod", "sliding_load"]


@contextmanager
def _data(names: str):
    """Name the caller's arguments when the catenary built from them is refused."""
    try:
        yield
    except InputError as exc:
        raise InputError(names, f"give a catenary outside the closed form's range ({exc})") from exc


def ring_on_rod(dh, w, length, mu) -> Catenary:
    r"""Catenary whose end B is a ring on a rough horizontal rod, at the limit of slip.

    A is fixed at (0, 0); the ring at height ``dh`` holds while
    ``H <= mu·V_B`` (Goicolea 2012, §3.4.3), i.e. while the cable meets the rod at
    ``sinh u_B >= 1/mu``. At the limit ``sinh u_B = 1/mu`` the length and
    height give ``a`` in closed form,

    .. math:: a = \frac{S^2 - dh^2}{2(S\sinh u_B - dh\cosh u_B)},

    and the span follows; the ring slides if pulled any farther.

    Returns
    -------
    Catenary
        The limiting catenary (its ``span`` is the largest that holds).

    Raises
    ------
    InputError
        A bad argument, a friction so large that the ring never slips, or
        data so extreme that the catenary leaves the range of a float.
    """
    dh = real("dh", dh)
    w, length, mu = positive("w", w), positive("length", length), positive("mu", mu)
    _plausible.friction(mu, "mu")
    broadcast(dh=dh, w=w, length=length, mu=mu)
    xp = namespace(dh, w, length, mu)
    require("length", length > xp.abs(dh), "must exceed |dh| to reach the rod", length)
    with float_range("dh, w, length, mu", "the slip limit"), np.errstate(over="ignore", invalid="ignore"):
        sinh_b = 1.0 / mu
        cosh_b = xp.hypot(1.0, sinh_b)
        gap = (length - dh) * (length + dh)
        # S sinh u_B - dh cosh u_B cancels where dh > 0, mu small and S near dh:
        # rationalised, ((S² - dh²) sinh² - dh²)/(S sinh + dh cosh), divided through by sinh
        plain = length * sinh_b - dh * cosh_b
        rationalised = (gap * sinh_b - dh * (dh / sinh_b)) / (length + dh * (cosh_b / sinh_b))
        if xp is np:
            denominator = np.where(dh > 0, rationalised, plain)
        else:
            denominator = rationalised if dh > 0 else plain
    require(
        "mu",
        denominator > 0,
        "is so large that the ring holds at every span the cable can reach (no slip limit)",
        mu,
    )
    with float_range("dh, w, length, mu", "the slip limit"), np.errstate(over="ignore", invalid="ignore"):
        a = gap / (2.0 * denominator)
        step = length / a
        span = a * asinh_step(sinh_b - step, step)  # the step formed directly
    require(
        "dh, w, length, mu",
        (span > 0) & (span < math.inf),
        "give no representable span at the slip limit",
        span,
    )
    with _data("dh, w, length, mu"):
        return catenary(span, dh, w, H=w * a)


def anchor_block_weight(solution, mu, *, end: str = "A"):
    """Least weight of a block on a rough floor anchoring one end (Goicolea 2012, §3.4.4).

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
    _plausible.friction(mu, "mu")
    if end not in ("A", "B"):
        raise InputError("end", f"must be 'A' or 'B', got {end!r}")
    try:
        H, V = solution.H, (solution.V_A if end == "A" else solution.V_B)
    except AttributeError as exc:
        raise InputError(
            "solution", f"must be a solved cable (with H, V_A, V_B), got {type(solution).__name__}"
        ) from exc
    broadcast(mu=mu, H=np.asarray(H) if np.ndim(H) else 0.0)
    with float_range("mu", "H/mu"), np.errstate(over="ignore"):
        W = V + H / mu
    bad = ~np.isfinite(W)
    if np.any(bad):
        raise InputError("mu", "is so small that the block weight V + H/mu overflows a float")
    return W


@dataclass(frozen=True)
class SlidingLoad:
    """Solution of `sliding_load`: two symmetric catenary arcs.

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

    H = property(lambda self: self.arc.H)
    V_A = V_B = property(lambda self: self.arc.V_A)
    T_A = T_B = property(lambda self: self.arc.T_A)
    y_load = property(lambda self: self.arc.dh)

    def residual(self) -> float:
        """Arc residual, load-point equilibrium and total length, relative."""
        arc = self.arc
        # V_B = H sinh(u_B) carries round-off of the arc's tension; it and P cancel
        scale = float(arc.T_B) + float(arc.w * arc.length) + self.P
        return max(
            arc.residual(),
            abs(float(2.0 * -arc.V_B - self.P)) / scale,  # the two arcs hold P
            abs(float(2.0 * arc.length - self.length)) / self.length,
        )


def sliding_load(span, w, length, P) -> SlidingLoad:
    r"""Point load ``P`` free to slide on a cable with supports at equal height.

    The load settles at mid-span; each half is a catenary arc whose end
    tension at the load carries ``P/2`` vertically (Goicolea 2012, §3.4.5). With
    the load point at hyperbolic angle :math:`u_C = -\operatorname{asinh}(P/2wa)`,
    the parameter ``a`` solves
    :math:`\sinh u_C - \sinh(u_C - \mathrm{span}/2a) = S/2a`, taken in logs
    (:math:`2\cosh(u_C - h/2)\sinh(h/2)` with :math:`h = \mathrm{span}/2a`)
    so that slack cables and heavy loads do not overflow.

    Raises
    ------
    InputError
        A bad argument (named), or data whose arcs leave the range of a float.
    ConvergenceError
        The search for ``a`` stopped, or the residual exceeds 1e-9.
    """
    span, w, length = scalar("span", span), scalar("w", w), scalar("length", length)
    P = scalar("P", P)
    for name, value in (("span", span), ("w", w), ("length", length)):
        require(name, value > 0, "must be > 0", value)
    require("P", P >= 0, "must be >= 0", P)
    require("length", length > span, "must exceed the span", length)
    half, half_length = 0.5 * span, 0.5 * length
    load = P / w  # may overflow: then so would every tension
    require("P", load < math.inf, "is so large relative to w that P/w overflows a float", P)
    # logs of the data: u_C = -asinh(e^q) with q = log(P/2w) - log(a), a = half·e^t
    logs = (math.log(half), math.log(half_length), math.log(0.5 * load) if load > 0 else -math.inf)

    def f(t, log_half, log_half_length, log_half_load):
        # log[(sinh u_C - sinh(u_C - h)) a / half_length], h = half/a = e^{-t}
        h = np.exp(-t)
        u_c = -_asinh_exp(log_half_load - log_half - t)
        return np.log(2.0) + log_cosh(u_c - 0.5 * h) + _log_sinh(0.5 * h) + t + log_half - log_half_length

    # t = -50: the arcs hang almost vertically, e^50 half-spans long (f > 0);
    # at hi the load's slope P/(2wa) and the sag are negligible (f < 0)
    lo = -50.0
    hi = min(40.0 + max(0.0, logs[2] - logs[0]), 700.0)
    with float_range("span, w, length, P", "the sliding-load search"):
        if not f(hi, *logs) < 0:
            raise InputError(
                "length", "is so close to the span that the arcs cannot be found in floating point"
            )
        t, history = find_root(f, lo, hi, logs, what="sliding_load", xtol=LOG_XTOL)
        a = half * math.exp(t)
        u_c = -float(_asinh_exp(logs[2] - logs[0] - t))
        h = half / a
        y_c = 2.0 * math.sinh(u_c - 0.5 * h) * (a * math.sinh(0.5 * h))
    with _data("span, w, length, P"):
        arc = catenary(half, y_c, w, H=w * a)
    solution = SlidingLoad(arc, P, length)
    residual = solution.residual()
    if not residual <= ACCEPT:
        raise ConvergenceError(f"sliding_load: residual {residual:.3e} above {ACCEPT:.0e}", history)
    return solution


def _asinh_exp(q):
    """asinh(e^q) for any q (e^q may overflow): q + log(1 + sqrt(1 + e^{-2q})) above 0."""
    q = np.asarray(q, dtype=float)
    positive_q = np.maximum(q, 0.0)
    return np.where(
        q > 0.0,
        positive_q + np.log1p(np.sqrt(1.0 + np.exp(-2.0 * positive_q))),
        np.arcsinh(np.exp(np.minimum(q, 0.0))),
    )


def _log_sinh(x):
    """log(sinh x) for x > 0 without overflow."""
    x = np.asarray(x, dtype=float)
    big = np.maximum(x, 20.0)
    return np.where(
        x > 20.0, big - np.log(2.0) + np.log1p(-np.exp(-2.0 * big)), np.log(np.sinh(np.minimum(x, 20.0)))
    )
