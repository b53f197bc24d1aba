"""The term protocol: what every piece of physics of a model declares and gives.

A model (a strand, a cable BVP) is a mesh, its scikit-fem bases and a list of *terms*, each
contributing to the residual ``R(U)`` and to the tangent ``K = ∂R/∂U`` (FElupe's items, whose
``assemble.vector()`` and ``assemble.matrix()`` a generic Newton sums). What a term computes is
model-specific (section forces for a strand's section term, forces per length for a cable's
load); what it *declares* is common, and the model's solver follows the declarations:

- ``symmetric``: its tangent is symmetric (never assumed for a term that says otherwise);
- ``potential``: its residual is the gradient of an energy the term gives (then, when every term
  of a model has one, the model minimises the total energy; a term whose tangent is not
  symmetric has none);
- ``smooth``: its residual is continuously differentiable; a term with kinks (contact, a
  tensionless foundation) declares ``smooth = False`` and the model takes semismooth Newton
  steps (full steps on the generalized derivative, backtracking on the residual norm);
- ``outputs``: named results the term adds to the model's results and to every VTK file
  written from them (a reaction, a contact pressure, a gap): ``point_data`` at the quadrature
  points or the nodes, ``cell_data`` per element.

`Term.bind` copies a term and sets it up for one model (per-model work done once); the model
keeps the bound copies, the user's list stays unbound. A term may keep a *state* between Newton
solves (frozen within one, updated from the converged solution by `Term.next_state`).
"""

from __future__ import annotations

import copy
from typing import TypeVar

__all__ = ["Term"]

_T = TypeVar("_T", bound="Term")


class Term:
    """Base of every term of every model: the declarations ``symmetric``, ``smooth`` and
    ``potential`` (None: the term says so by giving an energy, a number, not None, when asked)
    mean what the module docstring says.
    """

    symmetric: bool = True
    potential: bool | None = None
    smooth: bool = True

    def bind(self: _T, model) -> _T:
        """A copy of this term set up for ``model`` (the term itself stays unbound)."""
        bound = copy.copy(self)
        bound.setup(model)
        return bound

    def setup(self, model) -> None:
        """Per-model work done once: tables at the quadrature points, constant matrices."""

    def initial_state(self, model):
        """State at the start of a load path; None for a stateless term."""
        return None

    def next_state(self, output: dict, state):
        """State implied by a converged solve (``output`` is what the term returned)."""
        return state

    def __repr__(self) -> str:
        return f"{type(self).__name__}()"
