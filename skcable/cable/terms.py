r"""Cable terms: loads that see the whole state of the cable, with their tangents.

A cable term is a `skcable.fe.terms.Term` of a cable BVP (`solve_bvp`'s graph and arc forms).
At the quadrature points it receives the cable's state (`CableState`): the position
``r = (x, y)``, the unstretched arc length ``s`` from A, the tangent vector ``a = dr/ds`` (its
length is the stretch ``1 + ε``, its direction the unit tangent ``t``) and the tension ``T``;
it returns (`CableForce`) the force ``f`` it puts on the cable per unit *unstretched* length
(N/m, y up: a weight has ``f_y < 0``) and its derivatives ``∂f/∂r``, ``∂f/∂a``, ``∂f/∂s`` and
``∂f/∂T`` (None where they vanish). The solvers turn that into their own load and tangent:

- the arc form (position and tension along ``σ = s/L0``) takes ``Q = L0 f`` per unit σ, with
  ``∂Q/∂r = L0 ∂f/∂r``, ``∂Q/∂r' = ∂f/∂a``, ``∂Q/∂T = L0 ∂f/∂T`` and
  ``∂Q/∂L0 = f − (∂f/∂a) a + σ L0 ∂f/∂s``;
- the graph form (``y(x)`` with H global) takes the downward load per horizontal length
  ``q = −f_y m``, ``m = ds/dx`` the unstretched length per horizontal length, with ``a = (1,
  y')/m`` and ``T = H sqrt(1 + y'^2)``; it takes vertical forces only (a term with a horizontal
  component needs ``formulation="arc"``) and no dependence on ``s`` (which in the graph form
  is an integral over the span, not a local quantity).

Ready terms:

- `Buoyancy`: the weight of displaced water, ``ρ(d) g A`` upward, with a density that grows
  with the depth ``d`` below the surface (a stratified sea) and none above it;
- `WindDrag`: ``½ ρ C_d d U²`` times the length projected on the plane normal to the wind,
  along the wind;
- `CurrentDrag`: Morison's drag on the relative velocity split into its normal and tangential
  parts, ``½ ρ d |a| (C_n |v_n| v_n + C_t |v_t| v_t)`` (per unstretched length: the stretched
  length ``|a| ds`` meets the flow), with a current ``U(d)`` that may vary with depth.

Sources: J.R. Morison, M.P. O'Brien, J.W. Johnson, S.A. Schaaf, "The force exerted by surface
waves on piles", Petroleum Transactions AIME, 1950 (the drag term); J.M. Jonkman, "Dynamics
modeling and loads analysis of an offshore floating wind turbine", NREL, 2007 (normal and
tangential drag of mooring lines).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import nonnegative, positive, real
from skcable.errors import InputError
from skcable.fe.terms import Term

__all__ = ["Buoyancy", "CableForce", "CableState", "CableTerm", "CurrentDrag", "WindDrag", "term_outputs"]


@dataclass(frozen=True)
class CableState:
    """The cable at the quadrature points, as a term sees it (arrays of one shape ``P``).

    Attributes
    ----------
    x, y : ndarray P
        Position (m), A at (0, 0), y up.
    s : ndarray P or None
        Unstretched arc length from A (m); None in the graph form.
    a : ndarray (2, *P)
        ``dr/ds``: the tangent, of length the stretch ``1 + T/EA``.
    T : ndarray P
        Tension (N).
    """

    x: np.ndarray
    y: np.ndarray
    s: np.ndarray | None
    a: np.ndarray
    T: np.ndarray

    @property
    def stretch(self) -> np.ndarray:
        """``|a|``, the stretched length per unstretched length."""
        return np.hypot(self.a[0], self.a[1])

    @property
    def tangent(self) -> np.ndarray:
        """The unit tangent ``t = a/|a|`` (2, *P), towards B."""
        return self.a / self.stretch


@dataclass(frozen=True)
class CableForce:
    """A term's force per unit unstretched length (N/m, y up) and its derivatives.

    Attributes
    ----------
    f : ndarray (2, *P)
    df_dr, df_da : ndarray (2, 2, *P) or None
        ``∂f_i/∂r_j`` (N/m²) and ``∂f_i/∂a_j`` (N/m); None: zero.
    df_ds, df_dT : ndarray (2, *P) or None
        ``∂f_i/∂s`` (N/m²) and ``∂f_i/∂T`` (1/m); None: zero.
    """

    f: np.ndarray
    df_dr: np.ndarray | None = None
    df_da: np.ndarray | None = None
    df_ds: np.ndarray | None = None
    df_dT: np.ndarray | None = None


class CableTerm(Term):
    """Base of the cable terms: implement `forces`. ``uses_s``: the term reads ``state.s``
    (the graph form then refuses it); ``vertical``: its force is vertical (the graph form takes
    it; `solve_bvp` picks the arc form for a term that is not)."""

    uses_s: bool = False
    vertical: bool = False

    def forces(self, state: CableState) -> CableForce:
        """The force per unit unstretched length at ``state`` and its derivatives."""
        raise NotImplementedError

    def outputs(self, state: CableState, force: CableForce) -> dict:
        """Named point data for the results and the VTK files, at the points of ``state``:
        by default the force itself, ``<Term>_force_N_per_m`` (2, *P)."""
        return {f"{type(self).__name__}_force_N_per_m": np.asarray(force.f, dtype=float)}


def term_outputs(terms, state: CableState) -> dict:
    """Every term's `CableTerm.outputs` at ``state``, names made unique."""
    out: dict[str, np.ndarray] = {}
    for term in terms:
        for name, values in term.outputs(state, term.forces(state)).items():
            out[name if name not in out else f"{name}_{len(out)}"] = values
    return out


def _profile(name: str, value):
    """A speed or density given as a number or a callable of depth: ``(f(d), f'(d))`` callables;
    the derivative of a callable by central differences (step 1e-6 m). Both pickle (with the
    user's callable, when it does)."""
    if callable(value):
        at = _Checked(name, value)
        return at, _Slope(at)
    constant = float(real(name, value))
    return _Constant(constant), _Constant(0.0)


class _Constant:
    """``f(d) = value`` at every depth."""

    def __init__(self, value: float):
        self.value = value

    def __call__(self, d):
        return np.full(np.shape(d), self.value)


class _Checked:
    """The user's ``f(d)``, refused (naming the argument) where it is not finite."""

    def __init__(self, name: str, f):
        self.name, self.f = name, f

    def __call__(self, d):
        out = np.asarray(self.f(d), dtype=float)
        if not np.all(np.isfinite(out)):
            raise InputError(self.name, "returned non-finite values")
        return np.broadcast_to(out, np.shape(d))


class _Slope:
    """``f'(d)`` by central differences, step 1e-6 m."""

    def __init__(self, f):
        self.f = f

    def __call__(self, d):
        return (self.f(d + 1e-6) - self.f(d - 1e-6)) / 2e-6


def _direction(value) -> np.ndarray:
    e = np.asarray(real("direction", value), dtype=float)
    if e.shape != (2,) or not np.hypot(*e) > 0:
        raise InputError("direction", f"must be a non-zero (x, y) vector, got {value!r}")
    return e / np.hypot(*e)


class Buoyancy(CableTerm):
    r"""The upthrust of the water a cable displaces, with a density that varies with depth.

    Per unit unstretched length ``f_y = ρ(d) g A`` below the surface ``y = surface`` (the depth
    ``d = surface − y``) and none above it, ``ρ(d) = rho + gradient·d`` (kg/m³; a stratified
    sea: ``gradient`` in kg/m⁴). ``A`` (m²) is the displaced section per unstretched length.
    """

    vertical = True

    def __init__(
        self, area: float, *, rho: float = 1025.0, gradient: float = 0.0, g: float = 9.81, surface=0.0
    ):
        self.area, self.rho = float(positive("area", area)), float(positive("rho", rho))
        self.gradient, self.g = float(real("gradient", gradient)), float(positive("g", g))
        self.surface = float(real("surface", surface))

    def __repr__(self):
        return (
            f"Buoyancy(area={self.area:g}, rho={self.rho:g}, gradient={self.gradient:g}, "
            f"surface={self.surface:g})"
        )

    def forces(self, state):
        d = self.surface - state.y
        wet = d > 0
        rho = self.rho + self.gradient * d
        zero = np.zeros_like(d)
        f = np.array([zero, np.where(wet, rho * self.g * self.area, 0.0)])
        df_dr = np.zeros((2, 2, *d.shape))
        df_dr[1, 1] = np.where(wet, -self.gradient * self.g * self.area, 0.0)  # ∂ρ/∂y = −gradient
        return CableForce(f, df_dr=df_dr)


class WindDrag(CableTerm):
    r"""Wind on the projected length: along the wind direction ``e``, per unit unstretched length,

    .. math:: \mathbf f = \tfrac12\rho\,C_d\,d\,U^2\,|a \times e|\ \mathbf e,

    ``|a × e| ds`` the cable's length projected on the line normal to the wind (overhead-line
    practice: the wind pressure times the projected area). ``speed`` U (m/s) is a number or a
    callable of the height y (a wind profile). The projection has a kink where the cable lies
    along the wind (``smooth = False``).
    """

    smooth = False

    def __init__(
        self, speed, diameter: float, *, cd: float = 1.0, rho_air: float = 1.225, direction=(1.0, 0.0)
    ):
        self.diameter, self.cd = float(positive("diameter", diameter)), float(nonnegative("cd", cd))
        self.rho = float(positive("rho_air", rho_air))
        self.e = _direction(direction)
        self._U, self._dU = _profile("speed", speed)

    def __repr__(self):
        return f"WindDrag(diameter={self.diameter:g}, cd={self.cd:g}, direction={tuple(self.e)})"

    def forces(self, state):
        e, a = self.e, state.a
        cross = a[0] * e[1] - a[1] * e[0]
        U, dU = self._U(state.y), self._dU(state.y)
        k = 0.5 * self.rho * self.cd * self.diameter
        size = k * U * U * np.abs(cross)
        f = np.array([size * e[0], size * e[1]])
        sign = np.sign(cross)
        ones = (1,) * np.ndim(cross)
        grad_a = np.array([sign * e[1], -sign * e[0]]) * k * U * U  # ∂size/∂a
        df_da = e.reshape(2, 1, *ones) * grad_a[None]
        df_dr = np.zeros((2, 2, *np.shape(cross)))
        df_dr[:, 1] = e.reshape(2, *ones) * (2 * k * U * dU * np.abs(cross))  # U(y): ∂size/∂y
        return CableForce(f, df_dr=df_dr, df_da=df_da)


class CurrentDrag(CableTerm):
    r"""Morison's drag of a current on a cable, normal and tangential, per unit unstretched length:

    .. math:: \mathbf f = \tfrac12\rho\,d\,|a|\left(C_n|\mathbf v_n|\mathbf v_n
              + C_t|\mathbf v_t|\mathbf v_t\right),\qquad
              \mathbf v_t = (\mathbf v\cdot\mathbf t)\,\mathbf t,\quad \mathbf v_n = \mathbf v - \mathbf v_t,

    with ``v = U(d) e`` the current (the cable at rest), ``U`` (m/s) a number or a callable of the
    depth ``d = surface − y`` (a sheared current) and ``e`` its direction in the plane of the
    cable. ``|a|`` counts the stretched length that meets the flow. ``|w| w`` is continuously
    differentiable: the tangent is exact and the term smooth.
    """

    def __init__(
        self,
        speed,
        diameter: float,
        *,
        cd_normal: float = 1.2,
        cd_tangential: float = 0.0,
        rho: float = 1025.0,
        direction=(1.0, 0.0),
        surface: float = 0.0,
    ):
        self.diameter = float(positive("diameter", diameter))
        self.cn, self.ct = (
            float(nonnegative("cd_normal", cd_normal)),
            float(nonnegative("cd_tangential", cd_tangential)),
        )
        self.rho, self.surface = float(positive("rho", rho)), float(real("surface", surface))
        self.e = _direction(direction)
        self._U, self._dU = _profile("speed", speed)

    def __repr__(self):
        return (
            f"CurrentDrag(diameter={self.diameter:g}, cd_normal={self.cn:g}, cd_tangential={self.ct:g}, "
            f"direction={tuple(self.e)})"
        )

    def forces(self, state):
        a = state.a
        n = state.stretch
        t = a / n
        d = self.surface - state.y
        U, dU_dd = self._U(d), self._dU(d)
        v = self.e.reshape(2, *([1] * np.ndim(U))) * U
        c = np.sum(v * t, axis=0)
        vt = c * t
        vn = v - vt
        I = np.eye(2).reshape(2, 2, *([1] * np.ndim(U)))
        P = I - np.einsum("i...,j...->ij...", t, t)
        # ∂v_t/∂a = (t vᵀP + c P)/|a|, ∂v_n/∂a = −∂v_t/∂a
        dvt_da = (np.einsum("i...,k...,kj...->ij...", t, v, P) + c * P) / n
        k = 0.5 * self.rho * self.diameter

        def g(w):  # |w| w and its derivative |w| I + w wᵀ/|w|
            size = np.hypot(w[0], w[1])
            safe = np.where(size > 0, size, 1.0)
            return size * w, size * I + np.einsum("i...,j...->ij...", w, w) / safe

        gn, Gn = g(vn)
        gt, Gt = g(vt)
        force = self.cn * gn + self.ct * gt
        f = k * n * force
        df_da = k * (
            np.einsum("i...,j...->ij...", force, t)
            + n * np.einsum("ik...,kj...->ij...", self.ct * Gt - self.cn * Gn, dvt_da)
        )
        # through the current: ∂v/∂y = −U'(d) e; ∂v_t/∂v = t tᵀ, ∂v_n/∂v = P
        dv_dy = -dU_dd * self.e.reshape(2, *([1] * np.ndim(U)))
        tt = np.einsum("i...,j...->ij...", t, t)
        df_dv = (
            k
            * n
            * (
                self.cn * np.einsum("ik...,kj...->ij...", Gn, P)
                + self.ct * np.einsum("ik...,kj...->ij...", Gt, tt)
            )
        )
        df_dr = np.zeros((2, 2, *np.shape(U)))
        df_dr[:, 1] = np.einsum("ij...,j...->i...", df_dv, dv_dy)
        return CableForce(f, df_dr=df_dr, df_da=df_da)
