r"""The cable terms of a line BVP: their forces and derivatives at any points of the line.

A cable term (`skcable.bvp.terms.CableTerm`: `Buoyancy`, `WindDrag`, `CurrentDrag`, the
current's drag on a line's segments or an analyst's own) sees the line's state
(`skcable.bvp.terms.CableState`: the position ``r = (x, y[, z])``, the unstretched arc length
``s`` from A, ``a = dr/ds`` and the tension ``T``) and returns the force ``f`` it puts on the line
per unit unstretched length (N/m, the last coordinate up) with ``∂f/∂r``, ``∂f/∂a`` and
``∂f/∂T``. The line BVP is posed on the unstretched arc length itself, so ``f`` is its load per
unit length as it is (the arc form of `skcable.bvp.arc` scales it by ``L0``): in the residual
the line's load per unit unstretched length is, ``v`` the vertical coordinate (y in the plane, z
in space),

.. math::
    \mathbf p = -\mathbf f + w\,\mathbf e_v, \qquad
    \frac{\partial \mathbf p}{\partial \mathbf r} = -\frac{\partial \mathbf f}{\partial \mathbf r},\quad
    \frac{\partial \mathbf p}{\partial \mathbf a} = -\frac{\partial \mathbf f}{\partial \mathbf a},\quad
    \frac{\partial \mathbf p}{\partial T} = -\frac{\partial \mathbf f}{\partial T},

``w`` the segments' self weight (downward). ``∂f/∂s`` does not enter: the arc length is no
unknown of the line. `term_load` sums the terms and checks what each returns (shapes, finite
values): a refusal is an `skcable.InputError` naming ``terms``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable.bvp.terms import CableState
from skcable.errors import InputError

__all__ = ["TermLoad", "term_load"]


@dataclass(frozen=True)
class TermLoad:
    """The terms' force per unit unstretched length (N/m, the last coordinate up) at points of
    shape ``P`` and its derivatives, summed over the terms (None where every term's vanishes).

    Attributes
    ----------
    f : ndarray (dim, *P)
    df_dr, df_da : ndarray (dim, dim, *P) or None
        ``∂f_i/∂r_j`` (N/m²) and ``∂f_i/∂a_j`` (N/m).
    df_dT : ndarray (dim, *P) or None
        ``∂f_i/∂T`` (1/m).
    """

    f: np.ndarray
    df_dr: np.ndarray | None
    df_da: np.ndarray | None
    df_dT: np.ndarray | None


def _checked(term, name: str, value, shape) -> np.ndarray:
    """``value`` as a float array of ``shape``, finite; else an `InputError` naming ``terms``."""
    out = np.asarray(value, dtype=float)
    if out.shape != shape:
        raise InputError("terms", f"{term!r} returned {name} of shape {out.shape}, not {shape}")
    if not np.all(np.isfinite(out)):
        raise InputError("terms", f"{term!r} returned non-finite values of {name}")
    return out


def _add(total, term, name, value, shape):
    """``total + value`` (``value`` checked; None stays out)."""
    if value is None:
        return total
    value = _checked(term, name, value, shape)
    return value if total is None else total + value


def term_load(terms, r, s, a, T) -> TermLoad:
    """The terms' force and its derivatives at the state ``(r, s, a, T)`` (``r`` and ``a``: one
    array of shape ``P`` per coordinate, 2 or 3; ``s``, ``T`` of shape ``P``), summed (module
    docstring)."""
    state = CableState.at(r, s, a, T)
    dim, shape = len(r), np.shape(T)
    vector, matrix = (dim, *shape), (dim, dim, *shape)
    f = np.zeros(vector)
    df_dr = df_da = df_dT = None
    for term in terms:
        out = term.forces(state)
        f = f + _checked(term, "the force f", out.f, vector)
        df_dr = _add(df_dr, term, "df_dr", out.df_dr, matrix)
        df_da = _add(df_da, term, "df_da", out.df_da, matrix)
        df_dT = _add(df_dT, term, "df_dT", out.df_dT, vector)
    return TermLoad(f, df_dr, df_da, df_dT)
