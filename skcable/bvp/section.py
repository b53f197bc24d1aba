r"""The tension's part of the arc-length forms' section law, shared by the arc form and the line.

Both arc-length forms (`skcable.bvp.arc`, on ``σ = s/L0``, and the mooring line of
`skcable.mooring.line_bvp`, on the unstretched arc length itself) assemble a section law in the
generalized strains ``g = (x', y', x, y, T)`` with `skcable.fe.Assembly`. Its tension part is
the same in both: with ``a = (x', y')``, ``n = |a|`` and ``e = a/n``, the section force ``T e``
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

__all__ = ["STRAINS", "tension_section"]

#: the generalized strains (field, derivative order) of both arc-length forms: x', y', x, y, T
STRAINS = (("x", 1), ("y", 1), ("x", 0), ("y", 0), ("T", 0))
AX, AY, X, Y, T_ = range(5)


def tension_section(ax, ay, T):
    """``(n, ex, ey, D)`` at the quadrature points from ``x'``, ``y'`` and ``T`` (arrays of one
    shape ``P``): the stretch ``n = |a|``, the unit tangent ``e`` and the section tangent ``D``
    (5, 5, *P) with its tension entries filled (module docstring), the others zero; None where
    ``n`` has a zero (a collapsed tangent: the iterate is rejected)."""
    n = np.sqrt(ax * ax + ay * ay)
    if not np.all(n > 0):
        return None
    ex, ey = ax / n, ay / n
    D = np.zeros((5, 5, *n.shape))
    Tn = T / n
    D[AX, AX] = Tn * (1.0 - ex * ex)
    D[AX, AY] = D[AY, AX] = -Tn * ex * ey
    D[AY, AY] = Tn * (1.0 - ey * ey)
    D[AX, T_] = D[T_, AX] = ex
    D[AY, T_] = D[T_, AY] = ey
    return n, ex, ey, D
