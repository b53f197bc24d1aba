"""The elements a line needs: the ``n_elements="auto"`` of both line BVPs.

A solve on a mesh too coarse for its line converges all the same: its discrete equations hold to
round-off, and its end forces are off by the discretisation's error, which no residual sees.
`skcable.mooring.line_bvp.check.unresolved` says where a converged line's mesh misses a bend or a
weight varying along it (calibrated on the differential survey's scenes against 1024 elements:
`benchmarks/line_bvp_resolution.py`, its table in docs/bvp.md). With ``n_elements="auto"``
(`skcable.mooring.solve_line_bvp`, `skcable.mooring.LineBVP`, `solve_line_bvp_3d`, `LineBVP3D`)
the line is solved on `FIRST` elements, then, while the check flags it, on `GROWTH` times as
many, up to `MOST`, each solve as the first (from scratch, or from a warm start's line: a warm
start starts from `FIRST` too, so that the elements are the ends' to choose, not the path's).
A solve that ends in compression for want of elements (a `skcable.errors.ResolutionError`: the
discrete line's bends not resolved) is a line not resolved too, and more elements follow.
Where `MOST` do not resolve the line either, the public solve warns
(`skcable.errors.ResolutionWarning`), as it does on a number of elements the caller gave. The
solution's ``n_elements`` is the number the solve took.

The whole search counts against the ``time_limit`` of one solve: each refined solve gets what is
left. A failure raises the last solve's `ConvergenceError` (a `skcable.errors.ResolutionError`
where 1024 elements end in compression too), the first solve's unchanged, a later one's saying
on how many elements it failed and what the coarser solve did: ended in compression, or
converged to a line not resolved, which is then its ``last`` (converged and checked).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Literal, TypeVar

from skcable._checks import whole
from skcable.errors import ConvergenceError, InputError, ResolutionError
from skcable.mooring.line_bvp.fields import LineFields

__all__ = ["AUTO", "FIRST", "GROWTH", "MOST", "elements_option", "solve_resolved"]

#: the ``n_elements`` that asks for the elements the line needs
AUTO: Literal["auto"] = "auto"
#: the elements of the first solve, the growth of the next ones and the most ``"auto"`` takes
FIRST, GROWTH, MOST = 64, 4, 1024

Solution = TypeVar("Solution", bound=LineFields)


def elements_option(n_elements) -> int | Literal["auto"]:
    """``n_elements`` checked: a whole number of elements (at least 1), or ``"auto"``."""
    if isinstance(n_elements, str):
        if n_elements != AUTO:
            raise InputError("n_elements", f"must be a whole number or 'auto', got {n_elements!r}")
        return AUTO
    return int(whole("n_elements", n_elements, 1))


def solve_resolved(
    solve: Callable[[int, float], Solution], n_elements: int | Literal["auto"], time_limit: float
) -> Solution:
    """The line ``solve(n, seconds)`` gives on ``n`` elements within ``seconds``: on ``n_elements``
    (a number), or on the elements it needs (``"auto"``, module docstring: from `FIRST` whatever
    the start, so that a warm start gives the solve from scratch; a solve that ends in compression
    for want of elements, a `skcable.errors.ResolutionError`, is a line not resolved too). The
    solution's ``n_elements`` says how many it took.

    Raises
    ------
    ConvergenceError
        The solve's; with ``"auto"``, the last solve's (a `skcable.errors.ResolutionError` where the
        most elements end in compression too), or the ``time_limit`` spent before the line was
        resolved; after the first solve, saying what the coarser one did, and where it converged,
        its ``last`` is that line (checked, not resolved).
    """
    if n_elements != AUTO:
        solution = solve(int(n_elements), time_limit)
        solution.n_elements = int(n_elements)
        return solution
    clock, n = time.perf_counter(), FIRST
    coarser: Solution | None = None  # the last line that converged, not resolved
    compressed: ResolutionError | None = None  # the last solve's failure, in compression
    while True:
        left = time_limit - (time.perf_counter() - clock) if n > FIRST else time_limit
        try:
            if not left > 0:
                before = compressed if compressed is not None else coarser
                raise ConvergenceError(
                    f"no time left of time_limit = {time_limit:g} s for {n} elements",
                    getattr(before, "history", []),
                    last=getattr(compressed, "last", None),
                )
            solution = solve(n, left)
        except ResolutionError as failed:
            if n < MOST:
                compressed, n = failed, min(GROWTH * n, MOST)
                continue
            raise _noted(failed, n, coarser, compressed) from None
        except ConvergenceError as failed:
            raise _noted(failed, n, coarser, compressed) from None
        solution.n_elements = n
        if n >= MOST or not solution.unresolved():
            return solution
        coarser, compressed, n = solution, None, min(GROWTH * n, MOST)


def _noted(failed: ConvergenceError, n: int, coarser, compressed) -> ConvergenceError:
    """``failed`` (the solve on ``n`` elements, or no time left for it) saying what ``"auto"`` did
    before it: the first solve's unchanged; else whether the solve on fewer elements ended in
    compression (``compressed``, a `skcable.errors.ResolutionError`) or converged to a line not
    resolved (``coarser``, which becomes its ``last``)."""
    if n == FIRST:
        return failed
    fewer = n // GROWTH  # FIRST, GROWTH and MOST make the counts 64, 256, 1024
    message, notes = str(failed), [f"n_elements='auto': on {n} elements"]
    if compressed is not None:
        notes.append(f"on {fewer} the discrete line ended in compression, its bends not resolved")
    if coarser is not None:
        failed.last = coarser
        message = message.split("; error.last")[0]
        notes.append(f"on {coarser.n_elements} it converged, not resolved: error.last, checked")
    failed.args = (f"{message} ({'; '.join(notes)})",)
    return failed
