r"""Loads on a strand: distributed transverse loads, point forces and moments anywhere, and a
follower force that turns with the axis.

Point loads need not sit at a node: a force ``F`` at ``x₀`` does the virtual work
``F·δu(x₀)`` with the basis values at ``x₀`` (scikit-fem's ``Basis.probes``, as its
``point_source``), a moment ``M`` the work ``M·δθ(x₀)`` with the rotations
``θ_x = φ``, ``θ_y = −w′``, ``θ_z = v′`` of the axis (basis derivatives at ``x₀``).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from skfem import LinearForm

from skcable._checks import real
from skcable.errors import InputError
from skcable.fe.probes import gradient_probes
from skcable.strand.fe.terms import FIELDS, FieldTerm, Term

__all__ = ["FollowerForce", "PointForce", "PointMoment", "TransverseLoad", "unit_load"]


@LinearForm
def unit_load(v, w):
    """``∫ q v dx``: a load per length ``w.q`` on one field."""
    return w.q * v


# the forms wrap functions of other names: a term holding them pickles (a decorated function's
# name would find the form, not the function)
def _load_y_form(v, w):
    return w.qy * v


def _load_z_form(v, w):
    return w.qz * v


_load_y, _load_z = LinearForm(_load_y_form), LinearForm(_load_z_form)


class TransverseLoad(FieldTerm):
    """A transverse load per unit length on the strand axis: ``qy`` along y (v), ``qz`` along z (w),
    in N/m; constants or callables of x (m)."""

    def __init__(self, qy=0.0, qz=0.0):
        super().__init__(load={"v": _load_y, "w": _load_z}, qy=qy, qz=qz)


def _at(model, x, name="x") -> float:
    x = float(real(name, x))
    if not 0.0 <= x <= model.length:
        raise InputError(name, f"must lie on the strand, in [0, {model.length:g}] m, got {x!r}")
    return x


def _rows(model, field: str, x: float, derivative: bool) -> np.ndarray:
    """The model-wide row of ``field`` (its value, or its x-derivative) at ``x``: (N,)."""
    basis = model.bases[field]
    at = np.array([[x]])
    local = gradient_probes(basis, at) if derivative else basis.probes(at)
    out = np.zeros(model.assembly.N)
    k = FIELDS.index(field)
    out[model.offsets[k] : model.offsets[k + 1]] = np.asarray(local.todense()).ravel()
    return out


class _PointTerm(Term):
    """A dead load vector ``f`` (N,) built once: residual ``−f``, energy ``−f·U``."""

    potential = True
    _f: np.ndarray  # the load vector (N,), set by the subclass's ``setup``

    def contribute(self, U, step):
        return -self._f, None, {}

    def energy(self, U, step):
        return -float(self._f @ U)


class PointForce(_PointTerm):
    """A force ``(fx, fy, fz)`` (N) at abscissa ``x`` (m), anywhere on the strand (not only at
    nodes): the virtual work ``F·δu(x)`` with the basis values at ``x``."""

    def __init__(self, x: float, fx: float = 0.0, fy: float = 0.0, fz: float = 0.0):
        self.x = x
        self.force = tuple(float(real(n, v)) for n, v in (("fx", fx), ("fy", fy), ("fz", fz)))

    def __repr__(self):
        return f"PointForce(x={self.x:g}, fx={self.force[0]:g}, fy={self.force[1]:g}, fz={self.force[2]:g})"

    def setup(self, model):
        x = _at(model, self.x)
        f = np.zeros(model.assembly.N)
        for value, field in zip(self.force, ("u", "v", "w"), strict=True):
            if value != 0.0:
                f += value * _rows(model, field, x, False)
        self._f = f


class PointMoment(_PointTerm):
    """A moment ``(mx, my, mz)`` (N·m) at abscissa ``x`` (m), anywhere on the strand: the torque
    ``mx`` on the twist φ, ``my`` and ``mz`` on the rotations ``θ_y = −w′`` and ``θ_z = v′``."""

    def __init__(self, x: float, mx: float = 0.0, my: float = 0.0, mz: float = 0.0):
        self.x = x
        self.moment = tuple(float(real(n, v)) for n, v in (("mx", mx), ("my", my), ("mz", mz)))

    def __repr__(self):
        return (
            f"PointMoment(x={self.x:g}, mx={self.moment[0]:g}, my={self.moment[1]:g}, mz={self.moment[2]:g})"
        )

    def setup(self, model):
        x = _at(model, self.x)
        mx, my, mz = self.moment
        f = np.zeros(model.assembly.N)
        if mx:
            f += mx * _rows(model, "phi", x, False)
        if my:
            f -= my * _rows(model, "w", x, True)
        if mz:
            f += mz * _rows(model, "v", x, True)
        self._f = f


class FollowerForce(Term):
    r"""A force of magnitude ``P`` (N) at abscissa ``x`` that turns with the strand's axis there.

    Its direction is ``R(t) d``: ``d`` the direction given in the undeformed frame and ``R`` the
    smallest rotation that takes the undeformed axis ``e_x`` to the deformed tangent
    ``t = a/|a|``, ``a = (1 + u', v', w')`` (Rodrigues: with ``v = e_x × t``, ``c = t_x``,
    ``R d = c d + v × d + v (v·d)/(1 + c)``; ``d = e_x`` gives ``t`` itself, the classic
    tangential follower of Beck's column). The load depends on the deformation and has no
    potential: its tangent is not symmetric (``symmetric = False``), and a model holding it
    solves with Newton and a residual line search.
    """

    symmetric = False
    potential = False

    def __init__(self, x: float, P: float, direction=(1.0, 0.0, 0.0)):
        self.x, self.P = x, float(real("P", P))
        d = np.asarray(real("direction", direction), dtype=float)
        if d.shape != (3,) or not np.linalg.norm(d) > 0:
            raise InputError("direction", f"must be a non-zero 3-vector, got {direction!r}")
        self.direction = d / np.linalg.norm(d)

    def __repr__(self):
        return f"FollowerForce(x={self.x:g}, P={self.P:g}, direction={tuple(self.direction)})"

    def setup(self, model):
        x = _at(model, self.x)
        # δ(u, v, w)(x) and (u', v', w')(x) as rows over the model's dofs: sparse (3, N)
        self._value = sp.csr_matrix(np.array([_rows(model, f, x, False) for f in ("u", "v", "w")]))
        self._slope = sp.csr_matrix(np.array([_rows(model, f, x, True) for f in ("u", "v", "w")]))

    def force(self, U):
        """``(F, ∂F/∂a)``: the force (3,) and its derivative by ``a = (1 + u', v', w')`` (3, 3)."""
        a = self._slope @ U + np.array([1.0, 0.0, 0.0])
        n = np.linalg.norm(a)
        t = a / n
        d = self.direction
        v = np.array([0.0, -t[2], t[1]])
        c = 1.0 + t[0]
        F = t[0] * d + np.cross(v, d) + v * (v @ d) / c
        ey, ez = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])
        dF_dt = np.column_stack(
            [
                d - v * (v @ d) / c**2,
                np.cross(ez, d) + (ez * (v @ d) + v * d[2]) / c,
                -np.cross(ey, d) - (ey * (v @ d) + v * d[1]) / c,
            ]
        )
        dt_da = (np.eye(3) - np.outer(t, t)) / n
        return self.P * F, self.P * dF_dt @ dt_da

    def contribute(self, U, step):
        F, dF_da = self.force(U)
        K = -(self._value.T @ sp.csr_matrix(dF_da) @ self._slope)
        return -(self._value.T @ F), sp.csr_matrix(K), {}
