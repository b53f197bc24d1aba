"""Tangent diagnostics: a term's tangent against central differences of its own residual.

A tangent that is not the derivative of its residual still converges, slowly (linearly) or not at
all, and a check of the whole model hides one wrong term among right ones. `check_tangent`
checks one term alone: along random directions ``d`` over the dofs a solve moves,

.. math:: e = \\max_d \\frac{\\lVert K d - (R(U + h d) - R(U - h d)) / 2h \\rVert}
                       {\\max(\\lVert K d \\rVert, \\lVert (R(U + h d) - R(U - h d)) / 2h\\rVert)},

taking for each direction the smallest error over the steps ``h = 10⁻⁴ … 10⁻¹⁰`` times the size
of ``U``: a central difference errs by ``h²`` times the residual's curvature (large in a
strongly nonlinear law) plus ``ε/h`` of round-off, and one of the steps balances the two, while
a wrong tangent errs alike at every step. A right tangent gives ``e`` of order 1e-8 to 1e-11; a
tangent off by a factor gives that factor's distance from 1.

The model supplies ``term_contribution(term, U, state=None) -> (R, K)`` (the term alone),
``free_dofs()`` and, for ``U=None``, ``tangent_check_state()`` (a generic, non-trivial state).

`directional_check` is the cheap form a model runs on its first solve (two steps along one
direction, `skcable.errors.TangentWarning`): besides the error it gives the ratio of the
tangent to the difference along the direction, ``(K d)·f / f·f`` (1 when right; ⅓, −1 or 0 for
a tangent a third of the true one, of the wrong sign, or missing), and whether the difference
is resolved at all (a term whose residual is flat or kinked there says nothing yet).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from skcable.errors import InputError

__all__ = ["STEPS", "DirectionalCheck", "check_tangent", "directional_check", "sparse_of"]

#: the finite-difference steps tried, relative to the size of the state
STEPS = 10.0 ** -np.arange(4, 11)


class DirectionalCheck(NamedTuple):
    """`directional_check`'s answer: the smallest relative error of ``K d`` against the central
    differences over the steps, the ratio ``(K d)·f / f·f`` at that step, and whether the
    differences agree between the steps (``resolved``) to 1e-3 of their size."""

    error: float
    ratio: float
    resolved: bool


def directional_check(contribution, U, d, K, steps) -> DirectionalCheck:
    """``K d`` against central differences ``(R(U + h d) − R(U − h d)) / 2h`` of
    ``contribution(x) -> R`` at the steps ``h`` (absolute), module docstring. A term whose residual
    and tangent both vanish along ``d`` gives an error 0, ratio 1 and ``resolved`` False."""
    Kd = K @ d
    best, ratio, differences = np.inf, 1.0, []
    for h in steps:
        fd = (contribution(U + h * d) - contribution(U - h * d)) / (2 * h)
        differences.append(fd)
        size = max(float(np.linalg.norm(Kd)), float(np.linalg.norm(fd)))
        error = float(np.linalg.norm(Kd - fd)) / size if size > 0 else 0.0
        if error < best:
            ff = float(fd @ fd)
            best, ratio = error, (float(Kd @ fd) / ff if ff > 0 else (1.0 if size == 0 else 0.0))
    spread = max(float(np.linalg.norm(f - differences[0])) for f in differences)
    scale = max(float(np.linalg.norm(f)) for f in differences)
    return DirectionalCheck(best, ratio, scale > 0 and spread <= 1e-3 * scale)


def sparse_of(K, n: int):
    """The sparse matrix ``K`` padded with zero rows and columns to ``n × n`` (a model whose Newton
    vector carries global unknowns after its dofs)."""
    import scipy.sparse as sp

    K = sp.coo_matrix(K)
    return sp.csr_matrix((K.data, (K.row, K.col)), shape=(n, n))


def check_tangent(term, model, U=None, *, state=None, directions: int = 6, seed: int = 0) -> float:
    """The largest relative error of ``term``'s tangent against central differences (module
    docstring) at ``U`` (default: the model's ``tangent_check_state()``), along ``directions``
    random directions over the model's free dofs.

    Parameters
    ----------
    term : Term
        A term of ``model`` (its bound copy is used) or one to bind to it.
    model : StrandModel, or a cable problem with the same three methods
    U : ndarray, optional
        The state to check at.
    state : object, optional
        The term's state (default its initial one).

    Returns
    -------
    float
        The largest relative error (0 for a term whose residual and tangent vanish there).

    Raises
    ------
    InputError
        ``U`` of the wrong size; a tangent of the wrong shape.
    """
    for name in ("term_contribution", "free_dofs"):
        if not callable(getattr(model, name, None)):
            raise InputError("model", f"must give {name}() (a StrandModel or a cable problem), got {model!r}")
    if U is None:
        U = model.tangent_check_state()
    U = np.asarray(U, dtype=float)
    R, K = model.term_contribution(term, U, state)
    if np.shape(R) != U.shape or getattr(K, "shape", None) != (U.size, U.size):
        raise InputError(
            "term",
            f"residual {np.shape(R)} and tangent {getattr(K, 'shape', None)} must be "
            f"({U.size},) and ({U.size}, {U.size})",
        )
    free = np.asarray(model.free_dofs())
    rng = np.random.default_rng(seed)
    size = max(float(np.max(np.abs(U), initial=0.0)), 1e-3)
    worst = 0.0

    def contribution(x):
        return model.term_contribution(term, x, state)[0]

    for _ in range(directions):
        d = np.zeros(U.size)
        d[free] = rng.standard_normal(free.size)
        d /= np.max(np.abs(d))
        worst = max(worst, directional_check(contribution, U, d, K, size * STEPS).error)
    return worst
