r"""Damped Newton's method for two unknowns, elementwise over scenes.

Every closed form of the package that closes a cable on two unknowns (Irvine's elastic
catenary, lines on a seabed, multi-segment lines, funicular polygons) solves
:math:`f(x, y) = 0`, :math:`f = (f_1, f_2)`, with the analytic Jacobian, the 2 × 2 step by
Cramer's rule and a backtracking line search (Dennis and Schnabel, *Numerical Methods for
Unconstrained Optimization and Nonlinear Equations*, 1983, §6.3). `solve2` is that
iteration, once, with two back ends:

- **scalar**: Python floats throughout (NumPy ufuncs cost 0.2–1 µs each on a scalar), for
  the hot one-scene paths;
- **array**: NumPy, one Newton per element of the broadcast shape of ``x``, ``y`` and
  ``args``; elements stop independently and the closure is evaluated only on the elements
  still iterating (``args`` are passed compressed to them, as in
  `scipy.optimize.elementwise`).

The back end is the array one when ``x`` or ``y`` is an ndarray (``args`` are then broadcast
to their shape), else the scalar one (``args`` are passed as they are: arrays a closure
reduces, such as a polygon's segments, are welcome).

The closure
-----------
``closure(x, y, *args)`` returns a tuple whose first eight items are::

    f1, f2, j11, j12, j21, j22, size1, size2

the two residuals in one unit (both in metres, say: the miss of the end point), their
Jacobian ``j_ik = ∂f_i/∂(x, y)_k`` and the size of each residual's terms (``size_i > 0``:
the sum of the magnitudes of what is added or subtracted to form ``f_i``, the operands of
any difference inside included), so that a few ulps of ``size_i`` are the round-off of
``f_i``. The line search asks a sufficient decrease of the merit :math:`\max(|f_1|, |f_2|)`;
convergence is judged on each residual against its own size,
:math:`\max_i |f_i|/\mathrm{size}_i` (the history records it). More items may follow
(the scalar back end hands the whole tuple back as `Newton2.last`; the array back end keeps
the eight). A point outside the closure's domain (``H <= 0``, a segment gone slack) is
signalled by a non-finite residual, or on the scalar back end by an ``OverflowError``,
``ZeroDivisionError`` or ``ValueError``: the line search then halves the step.

Convergence is sized to that round-off, so that a scene converges alike in any unit
system: an element has converged when each residual is at most ``floor`` (by default
`FLOOR`, 8 ulps) times its size, or, within `STALL` times that, when a step no longer halves
the relative residual (the quadratic rate has ended in the round-off) or no step along
Newton's direction reduces the merit. An element that stops otherwise (no decrease above
the round-off, a singular or non-finite step, ``max_iter`` iterations) has not converged:
`solve2` raises `skcable.errors.ConvergenceError` with that history, or with ``strict=False``
returns the iterate and ``converged`` False there (for callers with a fallback). A caller
with a coarser tolerance of its own passes it as ``floor`` (and sizes in its scale: a chord).

Examples
--------
The unit circle meets the line ``x = y`` at ``(1/√2, 1/√2)``:

>>> def closure(x, y):
...     return x * x + y * y - 1.0, x - y, 2.0 * x, 2.0 * y, 1.0, -1.0, x * x + y * y + 1.0, abs(x) + abs(y)
>>> result = solve2(closure, 1.0, 0.0)
>>> round(result.x, 15), result.converged
(0.707106781186548, True)
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from skcable.errors import ConvergenceError

__all__ = ["FLOOR", "Newton2", "STALL", "solve2"]

#: Default convergence floor: residuals within 8 ulps of the size of their terms.
FLOOR = 8.0 * 2.220446049250313e-16
#: An element whose merit no step can reduce is converged while within this many floors.
STALL = 8.0
#: Sufficient decrease of the line search (Armijo's constant on the merit).
_DECREASE = 1e-4
_DOMAIN = (OverflowError, ZeroDivisionError, ValueError)


class Newton2(NamedTuple):
    """Result of `solve2`.

    Attributes
    ----------
    x, y : float or ndarray
        The last iterate (the solution where ``converged``).
    history : list of float
        The largest relative residual ``max(|f1|/size1, |f2|/size2)`` over the elements
        still iterating, at the start and after every iteration.
    converged : bool or ndarray of bool
        Per element.
    last : tuple
        The closure's value at ``(x, y)``: the whole tuple (scalar back end) or its eight
        leading arrays (array back end), of the shape of ``x``.
    """

    x: Any
    y: Any
    history: list
    converged: Any
    last: tuple


def solve2(
    closure,
    x,
    y,
    args=(),
    *,
    max_iter: int = 60,
    halvings: int = 30,
    floor: float = FLOOR,
    slack: float = 4.0,
    what: str = "Newton",
    strict: bool = True,
) -> Newton2:
    """Solve ``closure(x, y, *args)[:2] = 0`` elementwise from ``(x, y)`` (module docstring).

    Parameters
    ----------
    closure : callable
        ``closure(x, y, *args) -> (f1, f2, j11, j12, j21, j22, size1, size2, ...)``.
    x, y : float or ndarray
        The start.
    args : tuple
        Further arguments of ``closure``; on the array back end broadcast against ``x``
        and ``y`` and compressed to the elements still iterating.
    max_iter : int
        Largest number of Newton steps.
    halvings : int
        Largest number of step halvings of the line search.
    floor : float
        Converged where each residual is at most this times its size.
    slack : float
        The line search takes a step whose merit is below
        ``merit·(1 - 1e-4·t) + slack·floor·max(size1, size2)``: a sufficient decrease, or a
        change within the round-off (0 asks for a strict decrease).
    what : str
        Names the iteration in the error message.
    strict : bool
        Raise `ConvergenceError` unless every element converged (default); else return.

    Returns
    -------
    Newton2
    """
    if not (isinstance(x, np.ndarray) or isinstance(y, np.ndarray)):
        return _scalar(closure, float(x), float(y), args, max_iter, halvings, floor, slack, what, strict)
    return _array(closure, x, y, args, max_iter, halvings, floor, slack, what, strict)


def _relative(f1, f2, s1, s2):
    a, b = abs(f1) / s1, abs(f2) / s2
    return a if a > b else b


def _scalar(closure, x, y, args, max_iter, halvings, floor, slack, what, strict):
    last = closure(x, y, *args)
    f1, f2, j11, j12, j21, j22, s1, s2 = last[:8]
    relative = _relative(f1, f2, s1, s2)
    history = [relative]
    for _ in range(max_iter):
        if relative <= floor:
            return Newton2(x, y, history, True, last)
        det = j11 * j22 - j12 * j21
        if not (det != 0.0 and math.isfinite(det)):
            break  # singular or non-finite Jacobian
        dx, dy = (f2 * j12 - f1 * j22) / det, (f1 * j21 - f2 * j11) / det
        if not (math.isfinite(dx) and math.isfinite(dy)):
            break
        merit, accept, t = max(abs(f1), abs(f2)), slack * floor * max(s1, s2), 1.0
        for _ in range(halvings + 1):
            xn, yn = x + t * dx, y + t * dy
            try:
                trial = closure(xn, yn, *args)
                if max(abs(trial[0]), abs(trial[1])) < merit * (1.0 - _DECREASE * t) + accept:  # not NaN
                    break
            except _DOMAIN:
                pass
            t *= 0.5
        else:  # no decrease along Newton's direction
            if relative <= STALL * floor:
                return Newton2(x, y, history, True, last)
            break
        x, y, last = xn, yn, trial
        f1, f2, j11, j12, j21, j22, s1, s2 = last[:8]
        new = _relative(f1, f2, s1, s2)
        stalled, relative = new > 0.5 * relative, new
        history.append(relative)
        if stalled and relative <= STALL * floor:
            return Newton2(x, y, history, True, last)
    else:
        if relative <= floor:
            return Newton2(x, y, history, True, last)
    if strict:
        raise ConvergenceError(f"{what}: Newton did not converge", history)
    return Newton2(x, y, history, False, last)


def _evaluate(closure, x, y, args):
    with np.errstate(all="ignore"):
        out = closure(x, y, *args)
    shape = x.shape
    return [
        v
        if type(v) is np.ndarray and v.shape == shape and v.dtype == np.float64
        else np.broadcast_to(np.asarray(v, dtype=float), shape)
        for v in out[:8]
    ]


def _array(closure, x, y, args, max_iter, halvings, floor, slack, what, strict):
    shape = np.broadcast_shapes(np.shape(x), np.shape(y), *(np.shape(a) for a in args))
    x = np.array(np.broadcast_to(x, shape), dtype=float).ravel()
    y = np.array(np.broadcast_to(y, shape), dtype=float).ravel()
    args = [np.broadcast_to(a, shape).ravel() if np.ndim(a) else a for a in args]
    last = [v.copy() for v in _evaluate(closure, x, y, args)]
    converged = np.zeros(x.size, dtype=bool)
    active = np.arange(x.size)

    def relative(at):
        return np.maximum(np.abs(last[0][at]) / last[6][at], np.abs(last[1][at]) / last[7][at])

    history = [float(np.max(relative(active)))]
    for iteration in range(max_iter + 1):
        before = relative(active)
        done = before <= floor
        converged[active[done]] = True
        active, before = active[~done], before[~done]
        if active.size == 0 or iteration == max_iter:
            break
        f1, f2, j11, j12, j21, j22, s1, s2 = (v[active] for v in last)
        det = j11 * j22 - j12 * j21
        with np.errstate(all="ignore"):
            dx, dy = (f2 * j12 - f1 * j22) / det, (f1 * j21 - f2 * j11) / det
        stuck = ~(np.isfinite(dx) & np.isfinite(dy))
        accept = slack * floor * np.maximum(s1, s2)
        moved = _line_search(closure, (x, y, args, active, dx, dy, last), halvings, accept, stuck)
        after = relative(active)
        # stalled (no longer halving) or no step: converged at the round-off, or stopped
        at_floor = (~moved | (after > 0.5 * before)) & (after <= STALL * floor)
        converged[active[at_floor]] = True
        active = active[moved & ~at_floor]
        history.append(float(np.max(relative(active), initial=0.0)))
    if strict and not converged.all():
        bad = int(np.flatnonzero(~converged)[0])
        raise ConvergenceError(f"{what}: Newton did not converge at element {bad}", history)
    out = [v.reshape(shape) for v in last]
    return Newton2(x.reshape(shape), y.reshape(shape), history, converged.reshape(shape), tuple(out))


def _line_search(closure, state, halvings, accept, stuck):
    """Backtracking from ``x, y`` at ``active`` (``state``, updated in place) on the merit
    ``max(|f1|, |f2|)``; True where a step was taken."""
    x, y, args, active, dx, dy, last = state
    merit = np.maximum(np.abs(last[0][active]), np.abs(last[1][active]))
    moved = np.zeros(active.size, dtype=bool)
    pending = np.flatnonzero(~stuck)
    t = np.ones(active.size)
    for _ in range(halvings + 1):
        if pending.size == 0:
            break
        at = active[pending]
        xn, yn = x[at] + t[pending] * dx[pending], y[at] + t[pending] * dy[pending]
        trial = _evaluate(closure, xn, yn, [a[at] if np.ndim(a) else a for a in args])
        new = np.maximum(np.abs(trial[0]), np.abs(trial[1]))
        ok = new < merit[pending] * (1.0 - _DECREASE * t[pending]) + accept[pending]  # False for NaN
        good = at[ok]
        x[good], y[good] = xn[ok], yn[ok]
        for full, value in zip(last, trial, strict=True):
            full[good] = value[ok]
        moved[pending[ok]] = True
        pending = pending[~ok]
        t[pending] *= 0.5
    return moved
