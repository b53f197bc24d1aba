"""Exceptions raised by skcable.

Bad input raises `InputError` (a `ValueError`) naming the
argument and the reason; a solver that does not converge raises
`ConvergenceError` carrying its iteration history.
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["InputError", "ConvergenceError"]


class InputError(ValueError):
    """An argument is outside the domain where the problem has a solution.

    Attributes
    ----------
    argument : str
        Name of the offending argument, as spelled in the public API.
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
    """

    def __init__(self, message: str, history: Sequence[float] = ()):
        self.history = [float(h) for h in history]
        tail = ", ".join(f"{h:.3e}" for h in self.history[-8:])
        more = f" (last {min(8, len(self.history))} of {len(self.history)}: {tail})" if self.history else ""
        super().__init__(message + more)
