r"""The tension's part of the arc-length forms' section law, shared by the arc form and the line.

Both arc-length forms (`skcable.bvp.arc`, on ``σ = s/L0``, and the mooring line of
`skcable.mooring.line_bvp`, on the unstretched arc length itself, in the plane and in space)
assemble a section law in the generalized strains ``g = (a, r, T)`` (``(x', y', x, y, T)`` in the
plane) with `skcable.fe.Assembly`. Its tension part is the same in all: with ``a = r'``,
``n = |a|`` and ``e = a/n``, the section force ``T e``
on the position derivatives and ``e·δa`` (the stretch ``n``'s variation) on the tension, with the
tangent

.. math::
    \frac{\partial (T\mathbf e)}{\partial \mathbf a} = \frac{T}{n}\,(\mathbf I - \mathbf e\,\mathbf e^T),
    \qquad \frac{\partial (T\mathbf e)}{\partial T} = \mathbf e,
    \qquad \frac{\partial n}{\partial \mathbf a} = \mathbf e^T

(Goicolea 2012, the arc-length form of ``d/ds (T r'/|r'|) + q = 0``). `tension_section` returns
them; each form adds its loads and its stretch law (``n − L0 (1 + T/EA)`` or ``n − 1 − T/EA``).
"""

from __future__ import annotations

import numpy as np

__all__ = ["STRAINS", "strains_of", "tension_section"]


def strains_of(dim: int) -> tuple[tuple[str, int], ...]:
    """The generalized strains (field, derivative order) of an arc-length form in ``dim``
    dimensions: ``r'`` by coordinate, ``r``, ``T``."""
    names = "xyz"[:dim]
    return (*((c, 1) for c in names), *((c, 0) for c in names), ("T", 0))


#: the generalized strains of the plane arc-length forms: x', y', x, y, T
STRAINS = strains_of(2)


def tension_section(a, T):
    """``(n, e, D)`` at the quadrature points from ``a = dr/ds`` (``dim`` arrays of one shape
    ``P``, 2 or 3) and ``T``: the stretch ``n = |a|``, the unit tangent ``e`` (dim, *P) and the
    section tangent ``D`` (2 dim + 1, 2 dim + 1, *P) over the strains ``(a, r, T)`` with its
    tension entries filled (module docstring), the others zero; None where ``n`` has a zero (a
    collapsed tangent: the iterate is rejected)."""
    dim = len(a)
    n = np.sqrt(sum(a_i * a_i for a_i in a))
    if not np.all(n > 0):
        return None
    e = np.array([a_i / n for a_i in a])
    D = np.zeros((2 * dim + 1, 2 * dim + 1, *n.shape))
    Tn = T / n
    for i in range(dim):
        D[i, i] = Tn * (1.0 - e[i] * e[i])
        for j in range(i + 1, dim):
            D[i, j] = D[j, i] = -Tn * e[i] * e[j]
        D[i, 2 * dim] = D[2 * dim, i] = e[i]
    return n, e, D
