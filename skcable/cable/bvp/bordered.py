"""Deprecated: the bordered banded solve is `skcable.fe.linear.BorderedSolver`, served here for
one release with a `DeprecationWarning`."""

from skcable._lazy import attach

__all__: list[str] = []
__getattr__, __dir__ = attach(__name__, moved={"BorderedSolver": "skcable.fe.linear.BorderedSolver"})
