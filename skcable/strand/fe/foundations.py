r"""Supports along the strand: a Winkler foundation and nodal springs (linear), and the
non-smooth ones — a tensionless (unilateral) foundation and a rigid cylinder in contact — as
penalties, declared ``smooth = False`` so that the model takes semismooth Newton steps.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from skfem import BilinearForm

from skcable._checks import nonnegative, one_of, positive, real
from skcable.errors import InputError
from skcable.strand.fe.terms import FIELDS, FieldAssembly, FieldTerm, Term

__all__ = ["ElasticFoundation", "NodalSpring", "RigidCylinder", "TensionlessFoundation"]


# the forms wrap functions of other names: a term holding them pickles (a decorated function's
# name would find the form, not the function)
def _winkler_y_form(u, v, w):
    return w.ky * u * v


def _winkler_z_form(u, v, w):
    return w.kz * u * v


_winkler_y, _winkler_z = BilinearForm(_winkler_y_form), BilinearForm(_winkler_z_form)


class ElasticFoundation(FieldTerm):
    """A Winkler foundation under the strand: ``q = −k v`` and ``−k w`` (k in N/m per m of strand).

    ``ElasticFoundation(k)`` acts in both transverse directions; ``ky``/``kz`` set each
    (None: none in that direction). Constants or callables of x, >= 0.
    """

    def __init__(self, k=None, *, ky=None, kz=None):
        if k is not None and (ky is not None or kz is not None):
            raise InputError("k", "give k (both directions) or ky/kz, not both")
        ky, kz = (k, k) if k is not None else (ky, kz)
        if ky is None and kz is None:
            raise InputError("k", "give the foundation modulus k (N/m per m), or ky and/or kz")
        tangent = {
            key: form
            for key, form, value in ((("v", "v"), _winkler_y, ky), (("w", "w"), _winkler_z, kz))
            if value is not None
        }
        params = {name: value for name, value in (("ky", ky), ("kz", kz)) if value is not None}
        super().__init__(tangent=tangent, **params)

    def setup(self, model):
        super().setup(model)
        for name, value in self._w.items():
            nonnegative(name, value)


class NodalSpring(Term):
    """A linear spring of stiffness ``k`` on the value of ``field`` at the mesh node at ``x``:
    N/m for u, v, w; N·m/rad for phi."""

    def __init__(self, x: float, k: float, field: str = "v"):
        self.field = one_of("field", field, FIELDS)
        self.x, self.k = float(real("x", x)), float(positive("k", k))

    def __repr__(self):
        return f"NodalSpring(x={self.x:g}, k={self.k:g}, field={self.field!r})"

    def setup(self, model):
        nodes = model.mesh.p[0]
        node = int(np.argmin(np.abs(nodes - self.x)))
        if abs(nodes[node] - self.x) > 1e-9 * model.length:
            raise InputError("x", f"must be a mesh node; the nearest is at {nodes[node]:.6g} m")
        basis = model.bases[self.field]
        dof = model.offsets[FIELDS.index(self.field)] + basis.nodal_dofs[0][node]
        if dof in model.fixed or dof == model.pull:
            raise InputError(
                "x",
                f"the spring on {self.field} at x = {self.x:g} m acts on a dof the supports fix: "
                "it would do nothing",
            )
        N = model.assembly.N
        self._K = sp.csr_matrix(([self.k], ([dof], [dof])), shape=(N, N))

    def contribute(self, U, step):
        return self._K @ U, self._K, {}

    def energy(self, U, step):
        return 0.5 * float(U @ (self._K @ U))


class TensionlessFoundation(Term):
    r"""A foundation that pushes but never pulls: a unilateral Winkler bed as a penalty.

    The bed's surface lies at ``surface`` (m) in ``field`` (v or w); on the side ``"below"``
    it pushes the strand up with ``k (surface − v)`` where the strand has sunk into it and lets
    it lift off freely elsewhere (``"above"``: the mirror). Per unit length,

    .. math:: R = \int k\,\min(v - s, 0)\,\delta v\,dx, \qquad
              K = \int k\,H(s - v)\,\delta v\,\Delta v\,dx,

    a penalty of modulus ``k`` (N/m per m of strand, up to 1e12), with the potential
    ``½ k min(v − s, 0)²``. The residual has a kink where the strand leaves the bed:
    ``smooth = False``, so the model takes semismooth Newton steps (the generalized
    derivative ``H``, full steps, backtracking on the residual norm). Outputs: ``reaction``
    (N/m, the bed's pressure per length) and ``gap`` (m) at the quadrature points.
    """

    smooth = False
    potential = True

    def __init__(self, k: float, *, field: str = "v", surface: float = 0.0, side: str = "below"):
        if field not in ("v", "w"):
            raise InputError("field", f"must be 'v' or 'w', got {field!r}")
        if side not in ("below", "above"):
            raise InputError("side", f"must be 'below' or 'above', got {side!r}")
        self.k, self.field = float(positive("k", k)), field
        self.surface, self.sign = float(real("surface", surface)), (1.0 if side == "below" else -1.0)

    def __repr__(self):
        side = "below" if self.sign > 0 else "above"
        return (
            f"TensionlessFoundation(k={self.k:g}, field={self.field!r}, surface={self.surface:g}, "
            f"side={side!r})"
        )

    def setup(self, model):
        self._fa = FieldAssembly(model, [(self.field, 0)])

    def _gap(self, U):
        return self.sign * (self._fa.interpolate(U)[0] - self.surface)  # (ne, nq), < 0 in the bed

    def contribute(self, U, step):
        gap = self._gap(U)
        pressure = np.where(gap < 0, -self.k * gap, 0.0)
        R = self._fa.vector(-self.sign * pressure[None])
        # the generalized derivative takes the bed's branch at the kink (gap = 0): a strand that
        # starts on the bed's surface meets its stiffness at the first step
        K = self._fa.matrix((self.k * (gap <= 0))[None, None].astype(float))
        return R, K, {"point_data": {"reaction": pressure, "gap": gap}, "active": gap <= 0}

    def energy(self, U, step):
        gap = np.minimum(self._gap(U), 0.0)
        return float(0.5 * self.k * np.sum(gap * gap * self._fa.dx))


class RigidCylinder(Term):
    r"""Contact with a rigid cylinder whose axis is normal to the plane of ``field`` (v: the x–y
    plane, w: x–z), centred at ``center = (x_c, y_c)`` (m), of ``radius`` (m): a sheave, a
    saddle, a clamp's groove, as a penalty. A point of the axis ``p = (x + u, v)`` that
    penetrates the cylinder, ``g = |p − c| − r < 0``, is pushed out along ``n = (p − c)/|p − c|``
    with ``k |g|`` per length (``k`` in N/m², up to 1e12):

    .. math:: R = \int k\,\min(g, 0)\,\mathbf n\cdot\delta\mathbf p\,dx, \qquad
              K = \int k\,H(-g)\left[\mathbf n\mathbf n^T
                  + \frac{g}{|\mathbf p - \mathbf c|}(I - \mathbf n\mathbf n^T)\right] dx,

    the potential ``½ k min(g, 0)²``. ``smooth = False`` (semismooth Newton). Outputs:
    ``contact_pressure`` (N/m) and ``gap`` (m) at the quadrature points.
    """

    smooth = False
    potential = True

    def __init__(self, center, radius: float, k: float, *, field: str = "v"):
        if field not in ("v", "w"):
            raise InputError("field", f"must be 'v' or 'w', got {field!r}")
        c = np.asarray(real("center", center), dtype=float)
        if c.shape != (2,):
            raise InputError("center", f"must be (x_c, y_c), got {center!r}")
        self.center, self.radius = c, float(positive("radius", radius))
        self.k, self.field = float(positive("k", k)), field

    def __repr__(self):
        return (
            f"RigidCylinder(center={tuple(self.center)}, radius={self.radius:g}, k={self.k:g}, "
            f"field={self.field!r})"
        )

    def setup(self, model):
        self._fa = FieldAssembly(model, [("u", 0), (self.field, 0)])

    def _kinematics(self, U):
        u, v = self._fa.interpolate(U)
        d = np.array([self._fa.x + u - self.center[0], v - self.center[1]])
        dist = np.hypot(d[0], d[1])
        return d / np.where(dist > 0, dist, 1.0), dist, dist - self.radius

    def contribute(self, U, step):
        n, dist, gap = self._kinematics(U)
        inside = gap <= 0  # the generalized derivative takes the contact branch at the kink
        force = np.where(gap < 0, self.k * gap, 0.0)  # k min(g, 0)
        R = self._fa.vector(force * n)
        ratio = np.where(inside, gap / np.where(dist > 0, dist, 1.0), 0.0)
        D = np.empty((2, 2, *gap.shape))
        for i in range(2):
            for j in range(2):
                nn = n[i] * n[j]
                D[i, j] = self.k * inside * (nn + ratio * ((i == j) - nn))
        output = {"point_data": {"contact_pressure": -force, "gap": gap}, "active": inside}
        return R, self._fa.matrix(D), output

    def energy(self, U, step):
        gap = np.minimum(self._kinematics(U)[2], 0.0)
        return float(0.5 * self.k * np.sum(gap * gap * self._fa.dx))
