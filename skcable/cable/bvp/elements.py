"""The finite elements of the graph form, and a scikit-fem workaround.

Degrees 1 and 2 are scikit-fem's ``ElementLineP1`` / ``ElementLineP2``;
degrees 3 to 6 its hierarchical ``ElementLinePp``, through
`ElementLinePpExact`, which evaluates at the points it is given.
"""

from __future__ import annotations

import numpy as np
from skfem import ElementLineP1, ElementLineP2, ElementLinePp

from skcable.errors import InputError

__all__ = ["ElementLinePpExact", "end_dofs", "line_element"]

_ELEMENTS = {1: ElementLineP1, 2: ElementLineP2}


class ElementLinePpExact(ElementLinePp):
    """``ElementLinePp`` whose Legendre cache is keyed on the points themselves.

    scikit-fem 12's ``ElementLinePp.lbasis`` re-evaluates its cached values
    only when the *number* of points changes, so evaluating at one point and
    then at another (``Basis.probes``, ``interpolator``) returns the first
    point's values. Assembly, always at the same quadrature points, is not
    affected.
    """

    _cached_at = None

    def lbasis(self, X, i):
        if (
            self._cached_at is None
            or self._cached_at.shape != X[0].shape
            or not np.array_equal(self._cached_at, X[0])
        ):
            self.P, self.dP = self._reval_legendre(X[0, :], self.p)
            self._cached_at = np.array(X[0], copy=True)
        return self.P[i], self.dP[i]


def line_element(degree):
    """The line element of polynomial degree 1 to 6 (``InputError("degree")`` otherwise)."""
    if isinstance(degree, (int, np.integer)) and not isinstance(degree, bool):
        if int(degree) in _ELEMENTS:
            return _ELEMENTS[int(degree)]()
        if 3 <= degree <= 6:
            return ElementLinePpExact(int(degree))
    raise InputError("degree", f"must be an integer from 1 to 6, got {degree!r}")


def end_dofs(basis):
    """The dofs of the values at the first and last node of a line mesh, and the others.

    Returns ``(a, b, interior)``: ``a`` at the smallest coordinate, ``b`` at the
    largest (scikit-fem's ``get_dofs().all()`` without building the facets).
    """
    x = basis.mesh.p[0]
    a = int(basis.nodal_dofs[0, int(np.argmin(x))])
    b = int(basis.nodal_dofs[0, int(np.argmax(x))])
    keep = np.ones(basis.N, dtype=bool)
    keep[[a, b]] = False
    return a, b, np.flatnonzero(keep)
