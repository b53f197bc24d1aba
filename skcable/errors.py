"""Exceptions raised by skcable.

Bad input raises `InputError` (a `ValueError`) naming the
argument and the reason; a solver that does not converge raises
`ConvergenceError` carrying its iteration history, `NonFiniteError` (a `ConvergenceError`)
names the term or law that produced a value that is not finite, and `ResolutionError` (a
`ConvergenceError`) is a line BVP whose discrete line ends in compression on a mesh too coarse
for its bends.

Warnings say what is suspicious but not wrong: `PlausibilityWarning` for data
that a unit slip would explain (an EA in MN, a strain beyond any wire's),
`SlowConvergenceWarning` for a Newton that converges at a linear rate where its
tangent promises a quadratic one (a term's tangent is likely wrong), its subclass
`TangentWarning` for a term whose tangent disagrees with a directional difference of its own
residual (checked on a model's first solve), `ResolutionWarning` for an answer whose mesh does not
resolve it (a line BVP's element that turns through a bend within itself, or whose weight varies
within it), and `CacheWarning` for a cached study result computed by other code.
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = [
    "InputError",
    "ConvergenceError",
    "PlausibilityWarning",
    "SlowConvergenceWarning",
    "TangentWarning",
    "NonFiniteError",
    "ResolutionError",
    "ResolutionWarning",
    "CacheWarning",
]


class InputError(ValueError):
    """An argument is outside the domain where the problem has a solution; ``argument`` is its name
    as spelled in the public API.
    """

    def __init__(self, argument: str, reason: str):
        self.argument = argument
        super().__init__(f"{argument}: {reason}")


class ConvergenceError(RuntimeError):
    """An iterative solver stopped before meeting its tolerance.

    Attributes
    ----------
    history : list of float
        The residual (or step) norm after every iteration, first to last.
    last : object or None
        The solver's last iterate, where it has one (what the failed solve reached); for a
        search that keeps what converged, its best point (a line BVP: its solution on the
        finest mesh reached, not checked; with ``n_elements="auto"``, where a refined solve
        fails, the coarser line, checked but not resolved).
    attempts : list of list of float
        The history of every attempt of a solve that tried more than one from its start (a
        damped Newton, then full steps: `skcable.fe.newton`'s ``full_steps``), in the order
        tried; empty otherwise.
    """

    def __init__(self, message: str, history: Sequence[float] = (), last=None, attempts=()):
        self.history = [float(h) for h in history]
        self.last = last
        self.attempts = [[float(h) for h in tried] for tried in attempts]
        tail = ", ".join(f"{h:.3e}" for h in self.history[-8:])
        more = f" (last {min(8, len(self.history))} of {len(self.history)}: {tail})" if self.history else ""
        super().__init__(message + more)


class NonFiniteError(ConvergenceError):
    """A term (or a law inside it) produced a value that is not finite; the message names it, and
    ``source`` says what produced it (the term's or the law's repr).
    """

    def __init__(self, message: str, source: str = ""):
        self.source = source
        super().__init__(message)


class ResolutionError(ConvergenceError):
    """A line BVP whose solve converged to a discrete line in compression: its elements do not
    resolve the line's bends (`skcable.mooring.line_bvp.solver.LineSolver.refuse_compressed`), and
    more may solve it; ``n_elements="auto"`` gives them (`skcable.mooring.line_bvp.resolution`).
    """


class PlausibilityWarning(UserWarning):
    """Data that solve but are unlikely to be meant (a unit slip, say); ``argument`` is the
    suspicious argument's name as spelled in the public API.
    """

    def __init__(self, argument: str, reason: str):
        self.argument = argument
        super().__init__(f"{argument}: {reason}")


class SlowConvergenceWarning(RuntimeWarning):
    """A Newton iteration converged at a linear rate where its tangent should give a quadratic
    one: a term's tangent is probably not the derivative of its residual."""


class TangentWarning(SlowConvergenceWarning):
    """A term's tangent disagrees with a directional difference of its own residual: Newton will
    converge slowly or not at all. The message names the term and the ratio of its tangent to the
    difference along the direction checked (1 when right; ⅓, −1 or 0 for a tangent a third of the
    true one, of the wrong sign, or missing)."""


class ResolutionWarning(UserWarning):
    """An answer that converged and passed its checks on a mesh too coarse for it: its numbers
    carry a discretisation error beyond what its checks see (a line BVP whose element turns
    through a bend within itself, or whose weight varies within an element:
    `skcable.mooring.line_bvp.check.unresolved`). ``argument`` names what resolves it
    (``n_elements``)."""

    def __init__(self, argument: str, reason: str):
        self.argument = argument
        super().__init__(f"{argument}: {reason}")


class CacheWarning(UserWarning):
    """A cached result was computed by other code (another source fingerprint) and is recomputed."""
