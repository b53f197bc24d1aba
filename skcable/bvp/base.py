"""What the graph and arc-length solutions share."""

from __future__ import annotations

from functools import cached_property

import numpy as np

from skcable.bvp.terms import term_outputs
from skcable.cable.solution import CableSolution

__all__ = ["FiniteElementSolution", "sampled_outputs"]


def sampled_outputs(terms, state) -> dict:
    """The cable terms' outputs at the samples of a profile (`skcable.bvp.terms.term_outputs`),
    a vector as ``(n, 2)``."""
    return {
        name: np.moveaxis(v, 0, -1) if np.ndim(v) > 1 else v for name, v in term_outputs(terms, state).items()
    }


class FiniteElementSolution(CableSolution):
    """A finite-element cable solution: sag and lowest point by a search of
    the discrete profile (``problem.extremum``), Newton's history, and the result protocol's
    ``profile``, ``to_frame`` and ``tensions`` (`skcable.results`, through `CableSolution`)."""

    def __init__(self, problem, dofs, history, state):
        self._problem = problem
        self.span, self.dh, self.EA = problem.span, problem.dh, problem.EA
        self.mesh, self.basis = problem.mesh, problem.basis
        self.dofs = dofs
        self.history = [float(h) for h in history]
        self.iterations = len(self.history) - 1
        self.constraint = problem.constraint
        self._state = state

    @property
    def problem(self):
        """The discrete problem this solution solved (mesh, bases, loads, assembly): what
        `skcable.fe.check_tangent` checks a cable term on, ``check_tangent(term, sol.problem)``."""
        return self._problem

    @cached_property
    def _sag(self):
        return self._problem.extremum(self.dofs, "sag")

    @cached_property
    def _low(self):
        return self._problem.extremum(self.dofs, "low")

    @property
    def sag(self):
        return self._sag[1]

    @property
    def y_low(self):
        return self._low[1]
