"""What a strand model says when a solve goes wrong, in words an analyst can act on.

- `FirstSolveCheck`: on a model's first solve, the tangent of every term an analyst wrote (a term
  class of their own, a nonlinear `FieldTerm`, a slip law of their own inside `HelicalWires`)
  against a directional difference of its own residual (`skcable.fe.check.directional_check`:
  one direction, two steps, once per term, at the first iterate where the term's residual moves
  at all); ``StrandModel(..., check_tangents=False)`` skips it.
- `non_finite`: the terms whose residual or tangent is not finite.
- `tangent_modes`: a tangent that is singular or not positive definite.
"""

from __future__ import annotations

import warnings

import numpy as np

from skcable.errors import NonFiniteError, TangentWarning
from skcable.fe.check import directional_check
from skcable.strand.fe.terms import FIELDS, FieldTerm

__all__ = ["FirstSolveCheck", "non_finite", "tangent_modes"]

#: a tangent whose directional error exceeds this is named (`FirstSolveCheck`)
TANGENT_TOLERANCE = 1e-3
#: the finite-difference steps of the first-solve check, relative to the size of the state
FIRST_STEPS = (1e-5, 1e-7)
#: assemblies of the first solves over which a term whose residual does not move yet stays pending
PATIENCE = 40
#: eigenvalues below this fraction of the largest count as zero (`tangent_modes`)
SINGULAR = 1e-10
#: the largest free block whose eigenvalues `tangent_modes` computes (a dense decomposition)
LARGEST = 3000


def _analysts(term) -> bool:
    """Whether a term's tangent is an analyst's code (module docstring)."""
    if not type(term).__module__.startswith("skcable."):
        return True
    if isinstance(term, FieldTerm):
        return not term.linear
    law = getattr(term, "slip", None)
    return law is not None and not type(law).__module__.startswith("skcable.")


class FirstSolveCheck:
    """The first-solve tangent check of a model (module docstring).

    Attributes
    ----------
    pending : list of int
        Positions (in the model's term list) of the terms not checked yet.
    notes : dict of int to str
        The terms found off, ``"Cubic() (tangent/difference 0.333)"``, for the error messages.
    """

    def __init__(self, model, enabled: bool = True):
        self.model = model
        self.pending = [i for i, t in enumerate(model._bound) if _analysts(t)] if enabled else []
        self.notes: dict[int, str] = {}
        self.calls = 0
        self._direction: np.ndarray | None = None

    def direction(self) -> np.ndarray:
        """The direction of the check: a seeded random draw over the free dofs, largest entry 1."""
        if self._direction is None:
            m = self.model
            d = np.zeros(m.assembly.N)
            d[m.free] = np.random.default_rng(0).standard_normal(m.free.size)
            self._direction = d / np.max(np.abs(d), initial=1.0)
        return self._direction

    def __call__(self, U: np.ndarray, state) -> None:
        """Check the pending terms at ``U`` (the terms' states ``state``)."""
        self.calls += 1
        if self.calls > PATIENCE:
            self.pending = []
            return
        m = self.model
        d = self.direction()
        size = max(float(np.max(np.abs(U), initial=0.0)), 1e-3 * m.length)
        for i in list(self.pending):
            term = m.terms[i]

            def contribution(x, term=term, i=i):
                return m.term_contribution(term, x, state[i])[0]

            K = m.term_contribution(term, U, state[i])[1]
            found = directional_check(contribution, U, d, K, [size * h for h in FIRST_STEPS])
            if not np.isfinite(found.error):
                continue  # a non-finite residual is `non_finite`'s to name
            if not found.resolved:
                continue  # its residual does not move (yet) along the direction: no evidence
            self.pending.remove(i)
            if found.error > TANGENT_TOLERANCE:
                self.notes[i] = f"{m._bound[i]!r} (tangent/difference {found.ratio:.3g})"
                warnings.warn(
                    f"StrandModel: the tangent of {m._bound[i]!r} disagrees with the directional "
                    f"difference of its own residual at the first solve's iterate: tangent/difference "
                    f"= {found.ratio:.3g} (relative error {found.error:.1e}); Newton will converge "
                    "slowly or not at all. skcable.fe.check_tangent(term, model, U) checks it in more "
                    "directions; StrandModel(..., check_tangents=False) skips this check.",
                    TangentWarning,
                    stacklevel=6,
                )

    def note(self) -> str:
        """The terms found off, for an error message ("" when none)."""
        if not self.notes:
            return ""
        return "; tangents off at the first solve: " + ", ".join(self.notes.values())


def non_finite(model, pieces, where: str) -> NonFiniteError:
    """The error naming the terms among ``pieces`` (``(term, arrays...)``) that gave a value
    that is not finite (``where``: the load of the solve, for the message)."""
    names = []
    for term, *arrays in pieces:
        for a in arrays:
            values = a.data if hasattr(a, "data") and not isinstance(a, np.ndarray) else a
            if a is not None and not np.all(np.isfinite(values)):
                names.append(repr(term))
                break
    culprits = ", ".join(names) or "the assembly"
    return NonFiniteError(
        f"StrandModel {where}: {culprits} gave a residual or tangent that is not finite (NaN or inf)",
        culprits,
    )


def _describe(model, vectors: np.ndarray) -> str:
    """The dofs a set of modes over the free dofs moves (columns of ``vectors``): each field (and
    the slopes of v and w) that carries a share of them, with the nodes where it moves."""
    full = np.zeros((model.assembly.N, vectors.shape[1]))
    full[model.free] = vectors
    energy = np.sum(full**2, axis=1)  # each dof's share of the modes, summed over them
    total = float(energy.sum())
    parts = []
    for k, name in enumerate(FIELDS):
        basis, offset = model.bases[name], int(model.offsets[k])
        kinds = [(name, basis.nodal_dofs[0])]
        if basis.nodal_dofs.shape[0] > 1:
            kinds.append((name + "'", basis.nodal_dofs[1]))
        for label, nodal in kinds:
            share = energy[offset + nodal]
            if float(share.sum()) < 0.02 * total:
                continue
            moving = share > 0.01 * np.max(share)
            x = model.mesh.p[0][moving]
            count = int(moving.sum())
            where = (
                f"all {count} nodes"
                if count == len(moving)
                else f"{count} nodes, x = {x.min():.4g} to {x.max():.4g} m"
            )
            parts.append(f"{label} at {where}")
    return ", ".join(parts) or "nothing"


def tangent_modes(model, a) -> str:
    """Why the tangent of an assembly ``a`` (`skcable.strand.fe.model.Assembled`) stops Newton,
    if it is singular or not positive definite: the dofs of its null vectors (a missing support)
    or its negative modes (a load beyond buckling, under compression). "" when its free block is
    regular and positive definite, or too large to decompose here."""
    n = model.free.size
    if n == 0 or n > LARGEST:
        return ""
    K = model._global_tangent(a)
    block = K[model.free][:, model.free].toarray()
    if not np.all(np.isfinite(block)):
        return ""
    # Jacobi scaling: each dof against its own stiffness (a penalty of 1e12 beside a twist of a few
    # N·m² must not make the twist look singular)
    diagonal = np.abs(np.diag(block))
    d = 1.0 / np.sqrt(np.where(diagonal > 0, diagonal, np.max(diagonal, initial=1.0) or 1.0))
    # the modes in the scaled dofs: each dof's share measured against its own stiffness
    values, vectors = np.linalg.eigh(0.5 * (block + block.T) * np.outer(d, d))
    scale = float(np.max(np.abs(values), initial=0.0))
    if scale == 0.0:
        return "the tangent is zero: no term gives the free dofs any stiffness"
    zero = np.abs(values) <= SINGULAR * scale
    negative = values < -SINGULAR * scale
    out = []
    if zero.any():
        modes = _describe(model, vectors[:, zero])
        fields = [f for f in FIELDS if f"{f} at" in modes or f"{f}' at" in modes]
        out.append(
            f"the tangent is singular: {int(zero.sum())} motion(s) of the free dofs cost no force, "
            f"moving {modes}: the supports (or the terms) leave the strand free to move that way "
            f"(hold {', '.join(fields)} at an end)"
        )
    if negative.any():
        modes = _describe(model, vectors[:, negative])
        S = a.S
        compression = -float(np.min(S[0])) if S is not None else 0.0
        if compression > 0.0:
            out.append(
                f"the tangent has {int(negative.sum())} negative mode(s), moving {modes}, under an axial "
                f"compression of up to {compression:.4g} N: the load exceeds the strand's buckling "
                "load under these supports"
            )
        else:
            out.append(
                f"the tangent has {int(negative.sum())} negative mode(s), moving {modes}: the path passed "
                "a limit point (a softening law) or the load exceeds what the strand carries"
            )
    return "; ".join(out)
