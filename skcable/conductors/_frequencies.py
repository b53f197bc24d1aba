r"""Natural frequencies of a sagging cable: finite elements and Irvine's closed forms.

Model (H.M. Irvine, "Cable Structures", MIT Press, 1981, ch. 3; H.M. Irvine
and T.K. Caughey, "The linear theory of free vibrations of a suspended
cable", Proc. R. Soc. Lond. A 341, 1974): small vibrations about the static
profile :math:`y(x)`, in the coordinate :math:`x` along the span, horizontal
tension :math:`H` and mass :math:`m_x = (w/g)\,ds/dx` per unit of :math:`x`.

* Out of plane: :math:`m_x \ddot u = H u''`.
* In plane (vertical motion :math:`v`, horizontal inertia neglected):
  :math:`m_x \ddot v = H v'' + h\,y''` with the additional horizontal tension
  :math:`h = (EA/L_e)\int_0^L y' v'\,dx`, :math:`L_e = \int_0^L (ds/dx)^3 dx`.

The weak forms on scikit-fem quadratic (P2) Lagrange elements give the
generalized eigenproblem :math:`K\phi = \omega^2 M \phi` with the consistent
mass :math:`M = \int m_x \phi_i\phi_j`, the tangent
:math:`K = H\int\phi_i'\phi_j' + (EA/L_e)\, b b^T`, :math:`b_i = \int y'\phi_i'`
(in plane; without the rank-one term out of plane), fixed ends. It is solved in the
dimensionless variables :math:`\xi = x/L` (stiffness over :math:`H/L`, mass over
:math:`(w/g)L`), so that any magnitudes whose frequencies a float holds give them:
:math:`\omega^2 = (H g/w L^2)\,\mu` with :math:`\mu` an eigenvalue of
:math:`\int\phi_i'\phi_j'\,d\xi + (EA/H\ell_e)\,b b^T` over
:math:`\int (ds/dx)\phi_i\phi_j\,d\xi`, :math:`\ell_e = L_e/L`, by shift-invert
Lanczos on the band, checked by residual, mass orthonormality and a Sturm count
(`skcable._eigen`).

Assumptions: linear theory about the static state; the static profile is the
inextensible catenary with the given ``H`` (or ``sag``), its elastic stretch
(of order T/EA) neglected; ``w`` is the weight per cable length; supports
fixed; no damping, no bending stiffness, no aerodynamic coupling. The theory
is Irvine's, validated for sag/span up to about 1/8.

Irvine's closed forms (level span ``L``, small sag, :math:`c = \sqrt{H/m}`,
:math:`d = wL^2/8H`, :math:`L_e = L(1 + 8(d/L)^2)`,
:math:`\lambda^2 = (wL/H)^2 L\,EA/(H L_e)`): out of plane :math:`f_n = n c/2L`;
in plane antisymmetric :math:`f_n = n c/L`; symmetric :math:`f = \beta c/\pi L`
with :math:`\tan\beta = \beta - (4/\lambda^2)\beta^3`. The first symmetric
mode crosses the first antisymmetric one at :math:`\lambda^2 = 4\pi^2`.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq
from skfem import Basis, BilinearForm, ElementLineP2, LinearForm, MeshLine

from skcable import _plausible
from skcable._checks import TINY, exactly_one, positive_scalar, real, scalar, whole
from skcable._eigen import BandPattern, dense, farthest_from_one, first_lobe_positive, lowest_modes
from skcable._show import Shown, attributes, counted
from skcable.cable._catenary import catenary
from skcable.cable._extreme import blame_extreme
from skcable.errors import ConvergenceError, InputError

__all__ = ["NaturalFrequencies", "natural_frequencies", "irvine_frequencies"]


def irvine_frequencies(span, w, EA, H, *, n_modes=6, g=9.81):
    """Irvine's closed-form frequencies of a level, small-sag cable (Hz).

    Returns a dict: ``lambda2``, ``out_of_plane`` (n_modes), ``in_plane``
    (n_modes, ascending) and ``in_plane_symmetric`` (bool, the kind of each
    in-plane mode). See the module docstring for the formulas (Irvine, "Cable
    Structures", 1981, §3.2).
    """
    span = positive_scalar("span", span)
    w = positive_scalar("w", w)
    EA = positive_scalar("EA", EA)
    H = positive_scalar("H", H)
    g = positive_scalar("g", g)
    n_modes = whole("n_modes", n_modes, 1)
    return _irvine(span, w, EA, H, n_modes, g, {"H": H})


def _irvine(span, w, EA, H, n_modes, g, given):
    """`irvine_frequencies` on checked arguments; ``given`` names the static state's
    argument (H, or the sag it came from) where a refusal blames it."""
    c = math.sqrt(H) * math.sqrt(g) / math.sqrt(w)  # sqrt(H g / w) without overflowing H g / w
    d_over_span = (w / H) * span / 8
    L_e = span * (1 + 8 * d_over_span * d_over_span)
    ratio = (w / H) * span  # wL/H, squared by a product: a float's ** raises on overflow
    lambda2 = ratio * ratio * (EA / H) * (span / L_e)
    if not (np.isfinite(c / span) and c / span >= TINY):
        raise InputError(
            farthest_from_one(**given, g=g, w=w, span=span),
            "gives a wave speed c/span outside the range of a float",
        )
    if not (np.isfinite(lambda2) and lambda2 >= TINY):
        raise InputError(
            farthest_from_one(**given, w=w, span=span, EA=EA),
            "gives Irvine's λ² outside the range of a float",
        )
    n = np.arange(1, n_modes + 1)
    out = n * (c / span) / 2
    anti = n * (c / span)
    sym = np.array([_symmetric_root(j, lambda2) for j in n]) * (c / span) / np.pi
    freqs = np.concatenate([sym, anti])
    kinds = np.concatenate([np.ones(n_modes, bool), np.zeros(n_modes, bool)])
    order = np.argsort(freqs, kind="stable")[:n_modes]
    return {
        "lambda2": float(lambda2),
        "out_of_plane": out,
        "in_plane": freqs[order],
        "in_plane_symmetric": kinds[order],
    }


def _symmetric_root(j, lambda2):
    """The root of tan b = b - (4/lambda2) b^3 in ((j - 1/2) pi, (j + 1/2) pi).

    In ``t = b - (j - 1/2) pi`` in (0, pi), where tan b = -cot t, the equation is
    ``cos t - sin t (4 b^3/lambda2 - b) = 0``: positive at t = 0 (1), negative at t = pi
    (-1), without the poles of tan. Multiplied by lambda2/4 where lambda2 < 4, so that
    neither form overflows (both have the sign of the same bracket).
    """
    lo = (j - 0.5) * np.pi

    if lambda2 >= 4.0:

        def f(t):
            b = lo + t
            return np.cos(t) - np.sin(t) * (4.0 / lambda2 * b**3 - b)
    else:
        q = lambda2 / 4.0

        def f(t):
            b = lo + t
            return q * np.cos(t) - np.sin(t) * (b**3 - q * b)

    t = brentq(f, 0.0, np.pi, xtol=1e-15 * lo, rtol=1e-15, maxiter=200)
    return lo + t


class NaturalFrequencies(Shown):
    """Result of `natural_frequencies`.

    Attributes
    ----------
    f_in_plane, f_out_of_plane : (n_modes,) arrays
        Frequencies (Hz), ascending.
    in_plane_symmetric : (n_modes,) bool array
        True where the in-plane mode is symmetric about midspan (the larger
        part of its mass-weighted norm; exact for a level span).
    x : (n_points,) array
        Abscissae of the mode shapes (element ends and midpoints, ends included).
    y : (n_points,) array
        Height of the static profile above A at ``x`` (m).
    span, dh : float
        The supports: A = (0, 0), B = (span, dh).
    modes_in_plane, modes_out_of_plane : (n_modes, n_points) arrays
        Mode shapes, vertical and transverse, mass-normalised (``φᵀMφ = 1``),
        each signed so that its first lobe from A is positive.
    H, sag, L_e, lambda2 : float
        Static state: horizontal tension, sag, Irvine's L_e = ∫(ds/dx)³dx,
        and λ² = (wL/H)² L EA/(H L_e) with that L_e.
    irvine : dict
        `irvine_frequencies` for the same data (level, small-sag closed form).
    mass, stiffness_in_plane, stiffness_out_of_plane : 2-D arrays
        The matrices of the eigenproblems in SI units (free DOFs, in the order
        of ``x[1:-1]``), made dense on first access.
    """

    f_in_plane: np.ndarray
    f_out_of_plane: np.ndarray
    in_plane_symmetric: np.ndarray
    x: np.ndarray
    y: np.ndarray
    span: float
    dh: float
    modes_in_plane: np.ndarray
    modes_out_of_plane: np.ndarray
    H: float
    sag: float
    L_e: float
    lambda2: float
    irvine: dict

    def __init__(self, *, matrices=None, **values):
        self._matrices = matrices
        self.__dict__.update(values)

    @functools.cached_property
    def mass(self) -> np.ndarray:
        return self._matrices.mass()

    @functools.cached_property
    def stiffness_out_of_plane(self) -> np.ndarray:
        return self._matrices.stiffness_out_of_plane()

    @functools.cached_property
    def stiffness_in_plane(self) -> np.ndarray:
        return self.stiffness_out_of_plane + self._matrices.coupling()

    def __repr__(self):
        shown = attributes(
            self, {"f_in_plane": "Hz", "f_out_of_plane": "Hz", "H": "N", "sag": "m", "lambda2": ""}
        )
        return f"NaturalFrequencies({counted([len(self.f_in_plane)], 'mode')}: {shown})"


@BilinearForm
def _stiff(u, v, p):
    return u.grad[0] * v.grad[0]


@BilinearForm
def _mass(u, v, p):
    return p["m"] * u * v


@LinearForm
def _coupling(v, p):
    return p["slope"] * v.grad[0]


class _UnitMesh(NamedTuple):
    """P2 elements on [0, 1]: the basis, the free DOFs in the order of ξ, the band of
    ∫φ'φ'dξ on them and where a mass matrix's entries go in its band."""

    basis: Basis
    order: np.ndarray
    stiffness: np.ndarray  # upper band
    mass_pattern: BandPattern
    xi: np.ndarray  # the DOFs' ξ, ends included
    xi_quadrature: np.ndarray


@functools.lru_cache(maxsize=8)
def _unit_mesh(n_elements: int) -> _UnitMesh:
    basis = Basis(MeshLine(np.linspace(0.0, 1.0, n_elements + 1)), ElementLineP2(), intorder=8)
    free = basis.complement_dofs(basis.get_dofs())
    order = free[np.argsort(basis.doflocs[0][free])]
    stiffness = _stiff.coo_data(basis)
    rows, cols = stiffness.indices
    mass_rows, mass_cols = _mass.coo_data(basis, m=np.ones_like(basis.dx)).indices
    mesh = _UnitMesh(
        basis,
        order,
        BandPattern(rows, cols, order, basis.N).band(stiffness.data),
        BandPattern(mass_rows, mass_cols, order, basis.N),
        np.concatenate([[0.0], basis.doflocs[0][order], [1.0]]),
        basis.mapping.F(basis.X)[0],
    )
    for array in (mesh.order, mesh.stiffness, mesh.xi, mesh.xi_quadrature):
        array.flags.writeable = False
    return mesh


def natural_frequencies(span, dh, w, EA, *, H=None, sag=None, n_modes=6, g=9.81):
    """In-plane and out-of-plane natural frequencies of a sagging cable.

    Finite elements (scikit-fem, P2, consistent mass) on Irvine's linear
    theory about the static catenary; see the module docstring for the model
    and its assumptions (H.M. Irvine, "Cable Structures", MIT Press, 1981).

    Parameters
    ----------
    span, dh : float
        Horizontal distance (> 0) and height of B above A (m).
    w : float
        Weight per unit cable length (N/m), > 0; the mass per length is w/g.
    EA : float
        Axial stiffness (N), > 0.
    H, sag : float
        Exactly one: horizontal tension (N) or sag (largest vertical distance
        chord–cable, m) of the static state.
    n_modes : int
        Number of modes of each family, >= 1 (at most 60).
    g : float
        Gravity (m/s²), > 0.

    Returns
    -------
    NaturalFrequencies
        Frequencies and mass-normalised mode shapes, Irvine's λ² and his
        closed-form frequencies beside them.

    Raises
    ------
    InputError
        A non-physical or non-scalar argument, not exactly one of H, sag; or
        magnitudes whose frequencies, matrices or λ² a float cannot hold (the
        argument farthest from 1 is named).
    ConvergenceError
        The static catenary did not converge, or the eigenpairs failed their
        checks (`skcable._eigen`).
    """
    span = positive_scalar("span", span)
    dh = scalar("dh", dh)
    w = positive_scalar("w", w)
    if w < TINY:  # a subnormal weight: its static catenary has no digits left
        raise InputError("w", f"must be at least the smallest normal float ({TINY:.3g} N/m), got {w!r}")
    EA = positive_scalar("EA", EA)
    g = positive_scalar("g", g)
    n_modes = whole("n_modes", n_modes, 1)
    if n_modes > 60:
        raise InputError("n_modes", f"must be <= 60, got {n_modes}")
    name, value = exactly_one(H=H, sag=sag)
    given = {name: positive_scalar(name, value)}
    with blame_extreme(span=span, dh=dh, w=w, EA=EA, g=g, **given):  # the outsized argument, if one is
        static = catenary(span, dh, w, **given)
    H, sag = float(static.H), float(static.sag)
    irvine = _irvine(span, w, EA, H, n_modes, g, given)
    mesh = _unit_mesh(max(120, 24 * n_modes))
    slope = real("slope", static.slope(np.clip(span * mesh.xi_quadrature, 0.0, span)))
    ds_dx = np.hypot(1.0, slope)
    mass = mesh.mass_pattern.band(_mass.coo_data(mesh.basis, m=ds_dx).data)  # ∫ (ds/dx) φφ dξ
    b = _coupling.assemble(mesh.basis, slope=slope)[mesh.order]  # ∫ y' φ' dξ = ∫ y' φ' dx
    l_e = float(np.sum(ds_dx**3 * mesh.basis.dx))  # L_e / span
    scale = _Scales.of(span, w, EA, H, g, l_e, given)
    matrices = _Matrices(scale, mesh.stiffness, mass, b)
    results = {}
    for plane, rank_one in (("in", (scale.extension, b)), ("out", None)):
        mu, phi = lowest_modes(
            mesh.stiffness, mass, n_modes, rank_one=rank_one, what=f"natural_frequencies ({plane}-plane)"
        )
        unit = np.zeros((n_modes, mesh.xi.size))  # mass-normalised on the unit span
        unit[:, 1:-1] = phi.T
        results[plane] = (scale.frequencies(mu), first_lobe_positive(unit))

    # symmetric about midspan: compare the symmetric and antisymmetric parts (x is symmetric),
    # on the unit shapes (the SI ones may be too large for their squares)
    unit = results["in"][1]
    symmetric = np.linalg.norm(unit + unit[:, ::-1], axis=1) > np.linalg.norm(unit - unit[:, ::-1], axis=1)
    x = span * mesh.xi
    _plausible.conductor(span, dh, EA=EA, w=w, sag=sag if name == "sag" else None)
    _plausible.gravity(g)
    return NaturalFrequencies(
        f_in_plane=results["in"][0],
        f_out_of_plane=results["out"][0],
        in_plane_symmetric=symmetric,
        x=x,
        y=_static_profile(static, x, dh),
        span=span,
        dh=dh,
        modes_in_plane=results["in"][1] * scale.mode,
        modes_out_of_plane=results["out"][1] * scale.mode,
        H=H,
        sag=sag,
        L_e=span * l_e,
        lambda2=scale.lambda2,
        irvine=irvine,
        matrices=matrices,
    )


class _Scales(NamedTuple):
    """The dimensionless problem's scales, each checked to lie in the range of a float."""

    extension: float  # EA/(H ℓ_e): the in-plane rank-one term over H/span
    mass: float  # (w/g) span
    stiffness: float  # H/span
    coupling: float  # EA/L_e
    frequency: float  # sqrt(H g/w)/(2 pi span): f = sqrt(mu) times it
    mode: float  # 1/sqrt(mass)
    lambda2: float  # (w span/H)^2 EA/(H ℓ_e)
    blame: dict  # the arguments, to name the one farthest from 1 where a scale leaves the float range
    given: str  # "H" or "sag", the argument of the static state

    @classmethod
    def of(cls, span, w, EA, H, g, l_e, given):
        blame = {"span": span, "w": w, "EA": EA, "g": g, **given}
        extension = EA / H / l_e
        ratio = (w / H) * span
        lambda2 = ratio * ratio * extension
        frequency = math.sqrt(H) * math.sqrt(g) / math.sqrt(w) / span / (2 * math.pi)
        scales = cls(
            extension,
            w / g * span,
            H / span,
            EA / (span * l_e),
            frequency,
            math.sqrt(g) / (math.sqrt(w) * math.sqrt(span)),
            lambda2,
            blame,
            next(iter(given)),
        )
        for field, names in (
            ("extension", ("EA", *given)),
            ("lambda2", ("EA", "w", "span", *given)),
            ("frequency", ("w", "g", "span", *given)),
            ("mode", ("w", "g", "span")),
        ):
            value = getattr(scales, field)
            if not (np.isfinite(value) and value >= TINY):
                raise InputError(scales.culprit(names), f"gives a {field} scale outside the range of a float")
        return scales

    def culprit(self, names):
        return farthest_from_one(**{name: self.blame[name] for name in names})

    def frequencies(self, mu):
        f = np.sqrt(mu) * self.frequency
        if not (np.all(np.isfinite(f)) and np.all(f >= TINY)):
            raise InputError(self.culprit(self.blame), "gives frequencies outside the range of a float")
        return f


class _Matrices:
    """The eigenproblems' matrices in SI units, from the bands of the dimensionless ones;
    every entry checked finite and normal at once, made dense on demand."""

    def __init__(self, scale, stiffness, mass, b):
        self.scale, self.stiffness_band, self.mass_band, self.b = scale, stiffness, mass, b
        for field, band, names in (
            ("mass", mass, ("w", "g", "span")),
            ("stiffness", stiffness, ("span", scale.given)),
        ):
            entries = np.abs(band[band != 0])
            factor = getattr(scale, field)
            if not (math.isfinite(factor * float(entries.max())) and factor * float(entries.min()) >= TINY):
                raise InputError(scale.culprit(names), f"gives a {field} matrix outside the range of a float")
        b_max = float(np.abs(b).max())
        largest = scale.stiffness * float(np.abs(stiffness).max()) + scale.coupling * b_max * b_max
        if not math.isfinite(largest):
            raise InputError(
                scale.culprit(("EA", "span")), "gives an in-plane stiffness outside the range of a float"
            )

    def mass(self):
        return self.scale.mass * dense(self.mass_band)

    def stiffness_out_of_plane(self):
        return self.scale.stiffness * dense(self.stiffness_band)

    def coupling(self):
        return self.scale.coupling * np.outer(self.b, self.b)


def _static_profile(static, x, dh):
    """Heights of the static catenary at ``x``, the ends exactly 0 and ``dh``."""
    y = np.asarray(static.y(x), dtype=float)
    y[0], y[-1] = 0.0, dh
    if not np.all(np.isfinite(y)):
        raise ConvergenceError("natural_frequencies: the static profile came out non-finite")
    return y
