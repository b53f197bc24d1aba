"""The bordered banded solve now lives in `skcable.fe.linear` (`BorderedSolver`)."""

from skcable.fe.linear import BorderedSolver

__all__ = ["BorderedSolver"]
