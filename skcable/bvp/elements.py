"""The finite elements of the graph form, and a scikit-fem workaround.

The elements themselves are `skcable.fe.elements` (degree 1 to 6, with a scikit-fem
workaround), re-exported here.
"""

from __future__ import annotations

import numpy as np

from skcable.fe.elements import ElementLinePpExact, line_element

__all__ = ["ElementLinePpExact", "end_dofs", "line_element"]


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
