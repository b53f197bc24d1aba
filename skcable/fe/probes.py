"""Evaluation of a scikit-fem field at arbitrary points of a line mesh.

scikit-fem's ``Basis.probes`` gives values; `gradient_probes` gives
derivatives, `element_values` the basis values inside one element and
`element_minimum` the exact minimum of the field over one element
(used for the sag and the lowest point).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from numpy.polynomial import Polynomial

__all__ = ["element_minimum", "element_values", "gradient_probes", "minimum_near"]


def gradient_probes(basis, x):
    """Matrix giving d/dx of a field at the points ``x`` (skfem's ``probes`` gives values)."""
    x = np.atleast_2d(np.asarray(x, dtype=float))
    cells = basis.mesh.element_finder(mapping=basis.mapping)(*x)
    pts = basis.mapping.invF(x[:, :, np.newaxis], tind=cells)
    grads = np.array(
        [basis.elem.gbasis(basis.mapping, pts, k, tind=cells)[0].grad[0] for k in range(basis.Nbfun)]
    ).reshape(basis.Nbfun, -1)
    rows = np.tile(np.arange(x.shape[1]), basis.Nbfun)
    cols = basis.element_dofs[:, cells].flatten()
    return sp.coo_matrix((grads.flatten(), (rows, cols)), shape=(x.shape[1], basis.N)).tocsr()


def element_values(basis, element, x):
    """Values at ``x`` (scalar or 1-D) of every basis function of ``element`` (as skfem's
    ``probes``, through ``gbasis``, which orients hierarchical modes): (Nbfun,) or (Nbfun, n)."""
    points = np.atleast_1d(np.asarray(x, dtype=float))
    cells = np.array([element])
    X = basis.mapping.invF(points[None, None, :], tind=cells)
    values = np.array(
        [np.asarray(basis.elem.gbasis(basis.mapping, X, j, tind=cells)[0]) for j in range(basis.Nbfun)]
    ).reshape(basis.Nbfun, points.size)
    return values[:, 0] if np.ndim(x) == 0 else values


def element_minimum(basis, element, local, lean=0.0):
    """Minimum over ``element`` of ``local·φ(x) + lean·x``: (value, x).

    The field is a polynomial of the element's degree in x: it is sampled at
    degree + 1 Chebyshev points, fitted exactly, and minimised over the
    roots of its derivative and the element's ends.
    """
    left, right = np.sort(basis.mesh.p[0, basis.mesh.t[:, element]])
    degree = max(int(basis.elem.maxdeg), 1)
    theta = np.pi * (np.arange(degree + 1) + 0.5) / (degree + 1)
    x = left + (right - left) * 0.5 * (1.0 - np.cos(theta))
    poly = Polynomial.fit(
        x, local @ element_values(basis, element, x) + lean * x, degree, domain=[left, right]
    )
    roots = poly.deriv().roots()
    roots = roots[np.isreal(roots)].real
    candidates = np.concatenate([[left, right], roots[(roots > left) & (roots < right)]])
    values = poly(candidates)
    best = int(np.argmin(values))
    return float(values[best]), float(candidates[best])


def minimum_near(basis, values, local_of, lean=0.0):
    """Minimum of a field near its smallest quadrature value: (value, x, element).

    ``values`` (nq, ne) are the field (plus ``lean·x``) at the quadrature
    points; the best point picks the element, and the exact minimum of
    ``local_of(k)·φ + lean·x`` is taken there and in the two neighbours.
    """
    element = int(np.unravel_index(np.argmin(values), values.shape)[1])
    n_elements = basis.mesh.t.shape[1]
    candidates = [
        (*element_minimum(basis, k, local_of(k), lean), k)
        for k in range(max(element - 1, 0), min(element + 2, n_elements))
    ]
    return min(candidates)
