"""Line elements of any degree, and a scikit-fem workaround.

Degrees 1 and 2 are scikit-fem's ``ElementLineP1`` / ``ElementLineP2``; degrees 3 to 6 its
hierarchical ``ElementLinePp``, through `ElementLinePpExact`, which evaluates at the points it is
given.
"""

from __future__ import annotations

import numpy as np
from skfem import ElementLineP1, ElementLineP2, ElementLinePp

from skcable.errors import InputError

__all__ = ["ElementLinePpExact", "line_element"]

_ELEMENTS = {1: ElementLineP1, 2: ElementLineP2}


class ElementLinePpExact(ElementLinePp):
    """``ElementLinePp`` whose Legendre cache is keyed on the points themselves.

    scikit-fem 12's ``ElementLinePp.lbasis`` re-evaluates its cached values only when the
    *number* of points changes, so evaluating at one point and then at another
    (``Basis.probes``, ``interpolator``) returns the first point's values. Assembly, always at
    the same quadrature points, is not affected.
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


def line_element(degree, name: str = "degree"):
    """The line element of polynomial degree 1 to 6 (``InputError(name)`` otherwise)."""
    if isinstance(degree, (int, np.integer)) and not isinstance(degree, bool):
        if int(degree) in _ELEMENTS:
            return _ELEMENTS[int(degree)]()
        if 3 <= degree <= 6:
            return ElementLinePpExact(int(degree))
    raise InputError(name, f"must be an integer from 1 to 6, got {degree!r}")
