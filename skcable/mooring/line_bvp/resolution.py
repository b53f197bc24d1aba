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
left. A refined solve that fails raises its `ConvergenceError`, whose ``last`` is then the coarser
line that converged and passed its checks (not resolved): the message says on how many elements.
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
        The solve's; with ``"auto"``, the last solve's, or the ``time_limit`` spent before the line
        was resolved: where a coarser line converged, its ``last`` is that line (checked, not
        resolved; its history where the time was spent), and the message says so.
    """
    if n_elements != AUTO:
        solution = solve(int(n_elements), time_limit)
        solution.n_elements = int(n_elements)
        return solution
    clock, n, coarser = time.perf_counter(), FIRST, None
    while True:
        left = time_limit - (time.perf_counter() - clock) if n > FIRST else time_limit
        try:
            if not left > 0:
                raise ConvergenceError("no time left for more elements", getattr(coarser, "history", []))
            solution = solve(n, left)
        except ConvergenceError as failed:
            if isinstance(failed, ResolutionError) and n < MOST:
                n = min(GROWTH * n, MOST)
                continue
            raise _refined(failed, n, coarser, time_limit, left) from None
        solution.n_elements = n
        if n >= MOST or not solution.unresolved():
            return solution
        coarser, n = solution, min(GROWTH * n, MOST)


def _refined(failed: ConvergenceError, failed_at: int, coarser, time_limit: float, left: float):
    """``failed``, the solve on ``failed_at`` elements, its message saying where ``"auto"`` stood,
    its ``last`` the ``coarser`` line where one converged."""
    fewer = "" if failed_at == FIRST else ", after fewer did not resolve the line"
    kept = ""
    if coarser is not None:
        failed.last = coarser
        kept = f"; error.last: the line on {coarser.n_elements} elements, converged and checked, not resolved"
    failed.args = (
        f"{str(failed).split('; error.last')[0]} (n_elements='auto': on {failed_at} elements, with "
        f"{max(left, 0.0):.3g} s left of time_limit = {time_limit:g} s{fewer}){kept}",
    )
    return failed
