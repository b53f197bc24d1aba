r"""Cable terms: loads that see the whole state of the cable, with their tangents.

A cable term is a `skcable.fe.terms.Term` of a cable BVP (`solve_bvp`'s graph and arc forms,
the 3-D line BVP `skcable.mooring.line_bvp.space`). At the quadrature points it receives the cable's
state (`CableState`): the position ``r`` (``(x, y)``, y up, for a plane cable; ``(x, y, z)``, z
up, for a cable in space: the last coordinate is the vertical one), the unstretched arc length
``s`` from A, the tangent vector ``a = dr/ds`` (its length is the stretch ``1 + ε``, its
direction the unit tangent ``t``) and the tension ``T``; it returns (`CableForce`) the force
``f`` it puts on the cable per unit *unstretched* length (N/m: a weight has a negative vertical
component) and its derivatives ``∂f/∂r``, ``∂f/∂a``, ``∂f/∂s`` and ``∂f/∂T`` (None where they
vanish). The plane solvers turn that into their own load and tangent:

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
  length ``|a| ds`` meets the flow), with a current that may vary with depth: a speed along a
  direction, or a horizontal vector field ``U(z)`` in any direction (`skcable.bvp.current`).

Every term works in 2-D and in 3-D (`CableState.dim`); a plane cable's numbers are those of the
plane terms before they were generalised, bit for bit.

Sources: J.R. Morison, M.P. O'Brien, J.W. Johnson, S.A. Schaaf, "The force exerted by surface
waves on piles", Petroleum Transactions AIME, 1950 (the drag term); J.M. Jonkman, "Dynamics
modeling and loads analysis of an offshore floating wind turbine", NREL, 2007 (normal and
tangential drag of mooring lines).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable import _plausible
from skcable._checks import nonnegative, positive, real
from skcable.bvp.current import Current, current_of
from skcable.errors import InputError
from skcable.fe.terms import Term

__all__ = [
    "Buoyancy",
    "CableForce",
    "CableState",
    "CableTerm",
    "CurrentDrag",
    "WindDrag",
    "morison",
    "norm",
    "term_outputs",
]


@dataclass(frozen=True)
class CableState:
    """The cable at the quadrature points, as a term sees it (arrays of one shape ``P``).

    A plane cable (the 2-D BVPs) has ``r = (x, y)``, y up; a cable in space (the 3-D line BVP,
    `skcable.mooring.line_bvp.space`) has ``r = (x, y, z)``, z up: the last coordinate is always the
    vertical one (`height`), and ``a`` has one row per coordinate (`dim`).

    Attributes
    ----------
    x, y : ndarray P
        Position (m); in 2-D A at (0, 0) and y up, in 3-D y horizontal.
    s : ndarray P or None
        Unstretched arc length from A (m); None in the graph form.
    a : ndarray (dim, *P)
        ``dr/ds``: the tangent, of length the stretch ``1 + ε``.
    T : ndarray P
        Tension (N).
    z : ndarray P or None
        Height (m, up) of a cable in space; None for a plane cable.
    """

    x: np.ndarray
    y: np.ndarray
    s: np.ndarray | None
    a: np.ndarray
    T: np.ndarray
    z: np.ndarray | None = None

    def __post_init__(self):
        if np.shape(self.a)[:1] != ((2,) if self.z is None else (3,)):
            raise InputError(
                "a",
                f"must have {2 if self.z is None else 3} rows, one per coordinate, got {np.shape(self.a)}",
            )

    @classmethod
    def at(cls, r, s, a, T) -> CableState:
        """The state from the position ``r`` (dim, *P) (2 or 3 rows, the last one vertical)."""
        return cls(r[0], r[1], s, a, T) if len(r) == 2 else cls(r[0], r[1], s, a, T, z=r[2])

    @property
    def dim(self) -> int:
        """2 for a plane cable, 3 for a cable in space."""
        return 2 if self.z is None else 3

    @property
    def height(self) -> np.ndarray:
        """The vertical coordinate (m, up): ``y`` in 2-D, ``z`` in 3-D."""
        return self.y if self.z is None else self.z

    @property
    def position(self) -> np.ndarray:
        """``r`` (dim, *P)."""
        return np.array([self.x, self.y] if self.z is None else [self.x, self.y, self.z])

    @property
    def stretch(self) -> np.ndarray:
        """``|a|``, the stretched length per unstretched length."""
        return norm(self.a)

    @property
    def tangent(self) -> np.ndarray:
        """The unit tangent ``t = a/|a|`` (dim, *P), towards B."""
        return self.a / self.stretch


def norm(v) -> np.ndarray:
    """The length of vectors ``v`` (dim, *P): ``hypot`` in 2-D, the root of the sum of squares in
    3-D."""
    if len(v) == 2:
        return np.hypot(v[0], v[1])
    return np.sqrt(np.einsum("i...,i...->...", v, v))


@dataclass(frozen=True)
class CableForce:
    """A term's force per unit unstretched length (N/m, the last component vertical, up) and its
    derivatives (``dim`` the state's: 2 or 3).

    Attributes
    ----------
    f : ndarray (dim, *P)
    df_dr, df_da : ndarray (dim, dim, *P) or None
        ``∂f_i/∂r_j`` (N/m²) and ``∂f_i/∂a_j`` (N/m); None: zero.
    df_ds, df_dT : ndarray (dim, *P) or None
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
        by default the force itself, ``<Term>_force_N_per_m`` (dim, *P)."""
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


def _direction(value) -> np.ndarray | None:
    """A unit direction of 2 (plane) or 3 (space) components; None stays None (along x)."""
    if value is None:
        return None
    e = np.asarray(real("direction", value), dtype=float)
    if e.shape not in ((2,), (3,)) or not float(np.sqrt(np.sum(e * e))) > 0:
        raise InputError("direction", f"must be a non-zero (x, y) or (x, y, z) vector, got {value!r}")
    return e / (np.hypot(*e) if e.size == 2 else np.sqrt(np.sum(e * e)))


def _along(e: np.ndarray | None, dim: int) -> np.ndarray:
    """The term's direction for a state of ``dim`` coordinates: ``e``, or x where it is None;
    a direction of the other dimension refused (never reinterpreted)."""
    if e is None:
        return np.eye(dim)[0]
    if e.size != dim:
        raise InputError(
            "direction",
            f"has {e.size} components for a {dim}-D cable: give (x, y{', z' if dim == 3 else ''})",
        )
    return e


def _ones(shape) -> tuple[int, ...]:
    return (1,) * len(shape)


class Buoyancy(CableTerm):
    r"""The upthrust of the water a cable displaces, with a density that varies with depth.

    Per unit unstretched length ``f_v = ρ(d) g A`` along the vertical (``y`` in 2-D, ``z`` in
    3-D) below the surface ``surface`` (the depth ``d = surface − height``) and none above it,
    ``ρ(d) = rho + gradient·d`` (kg/m³; a stratified sea: ``gradient`` in kg/m⁴). ``A`` (m²) is
    the displaced section per unstretched length.
    """

    vertical = True

    def __init__(
        self, area: float, *, rho: float = 1025.0, gradient: float = 0.0, g: float = 9.81, surface=0.0
    ):
        self.area, self.rho = float(positive("area", area)), float(positive("rho", rho))
        self.gradient, self.g = float(real("gradient", gradient)), float(positive("g", g))
        _plausible.gravity(self.g)
        self.surface = float(real("surface", surface))

    def __repr__(self):
        return (
            f"Buoyancy(area={self.area:g}, rho={self.rho:g}, gradient={self.gradient:g}, "
            f"surface={self.surface:g})"
        )

    def forces(self, state):
        d = self.surface - state.height
        dim = state.dim
        wet = d > 0
        rho = self.rho + self.gradient * d
        f = np.zeros((dim, *d.shape))
        f[-1] = np.where(wet, rho * self.g * self.area, 0.0)
        df_dr = np.zeros((dim, dim, *d.shape))
        df_dr[-1, -1] = np.where(wet, -self.gradient * self.g * self.area, 0.0)  # ∂ρ/∂height = −gradient
        return CableForce(f, df_dr=df_dr)


class WindDrag(CableTerm):
    r"""Wind on the projected length: along the wind direction ``e``, per unit unstretched length,

    .. math:: \mathbf f = \tfrac12\rho\,C_d\,d\,U^2\,|a \times e|\ \mathbf e,

    ``|a × e| ds`` the cable's length projected on the plane normal to the wind (overhead-line
    practice: the wind pressure times the projected area). ``speed`` U (m/s) is a number or a
    callable of the height (``y`` in 2-D, ``z`` in 3-D: a wind profile). ``direction``: (x, y)
    for a plane cable, (x, y, z) for one in space; None (default) along x. The projection has a
    kink where the cable lies along the wind (``smooth = False``).
    """

    smooth = False

    def __init__(self, speed, diameter: float, *, cd: float = 1.0, rho_air: float = 1.225, direction=None):
        self.diameter, self.cd = float(positive("diameter", diameter)), float(nonnegative("cd", cd))
        self.rho = float(positive("rho_air", rho_air))
        self.direction = _direction(direction)
        self._U, self._dU = _profile("speed", speed)

    @property
    def e(self) -> np.ndarray:
        """The wind's unit direction (along x in the plane where none was given)."""
        return _along(self.direction, 2 if self.direction is None else self.direction.size)

    def __repr__(self):
        return f"WindDrag(diameter={self.diameter:g}, cd={self.cd:g}, direction={tuple(self.e)})"

    def forces(self, state):
        if state.dim == 3:
            return self._forces_3d(state)
        e, a = _along(self.direction, 2), state.a
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

    def _forces_3d(self, state):
        """In space: ``|a × e| = |a − (a·e) e|`` (e of unit length), whose gradient in a is
        ``(a − (a·e) e)/|a × e|`` (zero where the cable lies along the wind)."""
        e, a = _along(self.direction, 3), state.a
        shape = np.shape(state.T)
        along = a - np.einsum("i...,i->...", a, e)[None] * e.reshape(3, *_ones(shape))
        cross = norm(along)
        U, dU = self._U(state.z), self._dU(state.z)
        k = 0.5 * self.rho * self.cd * self.diameter
        E = e.reshape(3, *_ones(shape))
        f = E * (k * U * U * cross)
        grad_a = k * U * U * along / np.where(cross > 0, cross, 1.0)
        df_da = E[:, None] * grad_a[None]
        df_dr = np.zeros((3, 3, *shape))
        df_dr[:, 2] = E * (2 * k * U * dU * cross)
        return CableForce(f, df_dr=df_dr, df_da=df_da)


class CurrentDrag(CableTerm):
    r"""Morison's drag of a current on a cable, normal and tangential, per unit unstretched length:

    .. math:: \mathbf f = \tfrac12\rho\,d\,|a|\left(C_n|\mathbf v_n|\mathbf v_n
              + C_t|\mathbf v_t|\mathbf v_t\right),\qquad
              \mathbf v_t = (\mathbf v\cdot\mathbf t)\,\mathbf t,\quad \mathbf v_n = \mathbf v - \mathbf v_t,

    with ``v`` the current's velocity (the cable at rest) and ``|a|`` the stretched length per
    unstretched length that meets the flow (Morison et al. 1950; Jonkman 2007 for the normal and
    tangential coefficients of mooring lines). The current ``speed`` is one of

    - a number or a callable of the depth ``d = surface − height`` (a sheared current), along
      ``direction``: (x, y) in the plane of a 2-D cable, (x, y, z) for a cable in space, None
      (default) along x;
    - a horizontal vector ``(Ux, Uy)`` (m/s) or a `skcable.bvp.current.Current` (a callable
      ``z -> (Ux, Uy)`` of the height, or a table over depth): any horizontal direction in 3-D
      (``direction`` must then be None); on a 2-D cable (x horizontal, y up) its ``Uy`` is out of
      the plane and must be zero.

    ``|w| w`` is continuously differentiable: the tangent is exact and the term smooth (a
    tabulated current's kinks aside).
    """

    def __init__(
        self,
        speed,
        diameter: float,
        *,
        cd_normal: float = 1.2,
        cd_tangential: float = 0.0,
        rho: float = 1025.0,
        direction=None,
        surface: float = 0.0,
    ):
        self.diameter = float(positive("diameter", diameter))
        self.cn, self.ct = (
            float(nonnegative("cd_normal", cd_normal)),
            float(nonnegative("cd_tangential", cd_tangential)),
        )
        self.rho, self.surface = float(positive("rho", rho)), float(real("surface", surface))
        self.direction = _direction(direction)
        self.current = None
        if isinstance(speed, Current) or (not callable(speed) and np.shape(speed) == (2,)):
            if direction is not None:
                raise InputError(
                    "direction", "a current given as a vector or a Current has its own direction"
                )
            self.current = current_of(speed)
        else:
            self._U, self._dU = _profile("speed", speed)

    @property
    def e(self) -> np.ndarray:
        """The direction of a scalar current (along x in the plane where none was given)."""
        return _along(self.direction, 2 if self.direction is None else self.direction.size)

    def __repr__(self):
        if self.current is not None:
            return (
                f"CurrentDrag(diameter={self.diameter:g}, cd_normal={self.cn:g}, cd_tangential={self.ct:g}, "
                f"current={self.current!r})"
            )
        return (
            f"CurrentDrag(diameter={self.diameter:g}, cd_normal={self.cn:g}, cd_tangential={self.ct:g}, "
            f"direction={tuple(self.e)})"
        )

    def velocity(self, state):
        """The current ``v`` (dim, *P) (m/s) at ``state`` and its derivative by the height
        ``dv/dh`` (dim, *P) (1/s)."""
        dim, shape = state.dim, np.shape(state.T)
        if self.current is None:
            e = _along(self.direction, dim).reshape(dim, *_ones(shape))
            d = self.surface - state.height
            U, dU_dd = self._U(d), self._dU(d)
            return e * U, -dU_dd * e
        U, dU = self.current.velocity(state.height), self.current.gradient(state.height)
        if dim == 3:
            zero = np.zeros((1, *shape))
            return np.concatenate([U, zero]), np.concatenate([dU, zero])
        if np.any(U[1] != 0) or np.any(dU[1] != 0):
            raise InputError(
                "speed", "a 2-D cable lies in the (x, y-up) plane: its current's Uy must be zero"
            )
        zero = np.zeros_like(U[0])
        return np.array([U[0], zero]), np.array([dU[0], zero])

    def forces(self, state):
        v, dv_dh = self.velocity(state)
        return morison(v, dv_dh, state.a, 0.5 * self.rho * self.diameter, self.cn, self.ct)


def morison(v, dv_dh, a, k, cn, ct) -> CableForce:
    """Morison's drag ``k |a| (C_n |v_n| v_n + C_t |v_t| v_t)`` (`CurrentDrag`) and its
    derivatives by ``a`` and by the height (through ``dv/dh``), for ``v``, ``a`` (dim, *P).

    ``∂v_t/∂a = (t vᵀP + c P)/|a|`` (``P = I − t tᵀ``, ``c = v·t``) and ``∂v_n/∂a = −∂v_t/∂a``;
    ``d(|w| w)/dw = |w| I + w wᵀ/|w|``; through the current ``∂v_t/∂v = t tᵀ``, ``∂v_n/∂v = P``.
    """
    dim = len(a)
    n = norm(a)
    t = a / n
    c = np.sum(v * t, axis=0)
    vt = c * t
    vn = v - vt
    I = np.eye(dim).reshape(dim, dim, *([1] * np.ndim(c)))
    P = I - np.einsum("i...,j...->ij...", t, t)
    dvt_da = (np.einsum("i...,k...,kj...->ij...", t, v, P) + c * P) / n

    def g(w):  # |w| w and its derivative |w| I + w wᵀ/|w|
        size = norm(w)
        safe = np.where(size > 0, size, 1.0)
        return size * w, size * I + np.einsum("i...,j...->ij...", w, w) / safe

    gn, Gn = g(vn)
    gt, Gt = g(vt)
    force = cn * gn + ct * gt
    f = k * n * force
    df_da = k * (
        np.einsum("i...,j...->ij...", force, t)
        + n * np.einsum("ik...,kj...->ij...", ct * Gt - cn * Gn, dvt_da)
    )
    tt = np.einsum("i...,j...->ij...", t, t)
    df_dv = (
        k * n * (cn * np.einsum("ik...,kj...->ij...", Gn, P) + ct * np.einsum("ik...,kj...->ij...", Gt, tt))
    )
    df_dr = np.zeros((dim, dim, *np.shape(c)))
    df_dr[:, -1] = np.einsum("ij...,j...->i...", df_dv, dv_dh)
    return CableForce(f, df_dr=df_dr, df_da=df_da)
