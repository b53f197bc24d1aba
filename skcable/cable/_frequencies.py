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
(in plane; without the rank-one term out of plane), fixed ends, solved by
`scipy.linalg.eigh`.

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

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import brentq
from skfem import Basis, BilinearForm, ElementLineP2, LinearForm, MeshLine

from skcable import _plausible
from skcable._checks import exactly_one, positive, real, scalar, whole
from skcable.cable._catenary import catenary
from skcable.errors import ConvergenceError, InputError

__all__ = ["NaturalFrequencies", "natural_frequencies", "irvine_frequencies"]


def irvine_frequencies(span, w, EA, H, *, n_modes=6, g=9.81):
    """Irvine's closed-form frequencies of a level, small-sag cable (Hz).

    Returns a dict: ``lambda2``, ``out_of_plane`` (n_modes), ``in_plane``
    (n_modes, ascending) and ``in_plane_symmetric`` (bool, the kind of each
    in-plane mode). See the module docstring for the formulas (Irvine, "Cable
    Structures", 1981, §3.2).
    """
    span = _scalar_positive("span", span)
    w = _scalar_positive("w", w)
    EA = _scalar_positive("EA", EA)
    H = _scalar_positive("H", H)
    g = _scalar_positive("g", g)
    n_modes = whole("n_modes", n_modes, 1)
    c = np.sqrt(H * g / w)
    d = w * span**2 / (8 * H)
    L_e = span * (1 + 8 * (d / span) ** 2)
    lambda2 = (w * span / H) ** 2 * span * EA / (H * L_e)
    if not (np.isfinite(c) and c > 0 and np.isfinite(lambda2) and lambda2 > 0):
        raise InputError("H", "gives the wave speed or Irvine's λ² outside the range of a float")
    n = np.arange(1, n_modes + 1)
    out = n * c / (2 * span)
    anti = n * c / span
    sym = np.array([_symmetric_root(j, lambda2) for j in n]) * c / (np.pi * span)
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
    """The root of tan b = b - (4/lambda2) b^3 in ((j - 1/2) pi, (j + 1/2) pi)."""

    def f(b):  # increasing on the branch: f' = tan^2 b + 12 b^2/lambda2 >= 0
        return np.sin(b) - np.cos(b) * (b - 4.0 / lambda2 * b**3)

    # f = cos(b) (tan b - b + ...): cos changes sign at the ends of the branch,
    # the product form has no poles; bracket the branch's open interval
    lo, hi = (j - 0.5) * np.pi, (j + 0.5) * np.pi
    f_lo, f_hi = f(lo), f(hi)
    if f_lo * f_hi > 0:  # the root is at an end (lambda2 -> 0 or infinity limits)
        return lo if abs(f_lo) < abs(f_hi) else hi
    return brentq(f, lo, hi, xtol=1e-15 * hi, rtol=1e-15, maxiter=200)


class NaturalFrequencies:
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
        Mode shapes, vertical and transverse, mass-normalised (``φᵀMφ = 1``).
    H, sag, L_e, lambda2 : float
        Static state: horizontal tension, sag, Irvine's L_e = ∫(ds/dx)³dx,
        and λ² = (wL/H)² L EA/(H L_e) with that L_e.
    irvine : dict
        `irvine_frequencies` for the same data (level, small-sag closed form).
    mass, stiffness_in_plane, stiffness_out_of_plane : 2-D arrays
        The matrices of the eigenproblems (free DOFs, in the order of
        ``x[1:-1]``).
    """

    def __init__(self, **values):
        self.__dict__.update(values)

    def __repr__(self):
        return (
            f"NaturalFrequencies(n_modes={len(self.f_in_plane)}, lambda2={self.lambda2:.4g}, "
            f"f_in_plane={np.round(self.f_in_plane, 6).tolist()})"
        )


def _scalar_positive(name, value):
    value = scalar(name, value)
    return positive(name, value)


@BilinearForm
def _stiff(u, v, p):
    return u.grad[0] * v.grad[0]


@BilinearForm
def _mass(u, v, p):
    return p["m"] * u * v


@LinearForm
def _coupling(v, p):
    return p["slope"] * v.grad[0]


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
        A non-physical or non-scalar argument, not exactly one of H, sag.
    ConvergenceError
        The static catenary did not converge, or a non-finite or
        non-positive eigenvalue came out.
    """
    span = _scalar_positive("span", span)
    dh = scalar("dh", dh)
    w = _scalar_positive("w", w)
    EA = _scalar_positive("EA", EA)
    g = _scalar_positive("g", g)
    n_modes = whole("n_modes", n_modes, 1)
    if n_modes > 60:
        raise InputError("n_modes", f"must be <= 60, got {n_modes}")
    name, value = exactly_one(H=H, sag=sag)
    value = _scalar_positive(name, value)
    static = catenary(span, dh, w, **{name: value})
    H, sag = float(static.H), float(static.sag)

    n_el = max(120, 24 * n_modes)
    mesh = MeshLine(np.linspace(0.0, span, n_el + 1))
    basis = Basis(mesh, ElementLineP2(), intorder=8)
    xq = basis.mapping.F(basis.X)[0]  # quadrature points (elements, points)
    slope = real("slope", static.slope(np.clip(xq, 0.0, span)))
    ds_dx = np.sqrt(1.0 + slope**2)
    m_x = w / g * ds_dx
    L_e = float(np.sum(ds_dx**3 * basis.dx))
    K_s = _stiff.assemble(basis).toarray()
    M = _mass.assemble(basis, m=m_x).toarray()
    b = _coupling.assemble(basis, slope=slope)

    free = basis.complement_dofs(basis.get_dofs())
    x_all = basis.doflocs[0]
    order = free[np.argsort(x_all[free])]
    M = M[np.ix_(order, order)]
    K_out = H * K_s[np.ix_(order, order)]
    K_in = K_out + EA / L_e * np.outer(b[order], b[order])
    x = np.concatenate([[0.0], x_all[order], [span]])

    results = {}
    for plane, K in (("in", K_in), ("out", K_out)):  # in-plane, out-of-plane
        if not (np.all(np.isfinite(K)) and np.all(np.isfinite(M))):
            raise InputError("H", f"gives the {plane}-plane stiffness or mass outside the range of a float")
        omega2, phi = eigh(K, M, subset_by_index=[0, n_modes - 1])
        if omega2.shape != (n_modes,) or not (np.all(np.isfinite(omega2)) and np.all(omega2 > 0)):
            raise ConvergenceError(f"natural_frequencies: {plane}-plane eigenvalues not finite and > 0")
        shapes = np.zeros((n_modes, x.size))
        shapes[:, 1:-1] = phi.T
        results[plane] = (np.sqrt(omega2) / (2 * np.pi), shapes)

    # symmetric about midspan: compare the symmetric and antisymmetric parts
    mirror = np.argsort(span - x)  # x is symmetric on the uniform mesh
    shapes = results["in"][1]
    sym_part = np.linalg.norm(shapes + shapes[:, mirror], axis=1)
    anti_part = np.linalg.norm(shapes - shapes[:, mirror], axis=1)
    lambda2 = (w * span / H) ** 2 * span * EA / (H * L_e)
    _plausible.conductor(span, dh, EA=EA, w=w, sag=sag if name == "sag" else None)
    return NaturalFrequencies(
        f_in_plane=results["in"][0],
        f_out_of_plane=results["out"][0],
        in_plane_symmetric=sym_part > anti_part,
        x=x,
        y=_static_profile(static, x, dh),
        span=span,
        dh=dh,
        modes_in_plane=results["in"][1],
        modes_out_of_plane=results["out"][1],
        H=H,
        sag=sag,
        L_e=L_e,
        lambda2=float(lambda2),
        irvine=irvine_frequencies(span, w, EA, H, n_modes=n_modes, g=g),
        mass=M,
        stiffness_in_plane=K_in,
        stiffness_out_of_plane=K_out,
    )


def _static_profile(static, x, dh):
    """Heights of the static catenary at ``x``, the ends exactly 0 and ``dh``."""
    y = np.asarray(static.y(x), dtype=float)
    y[0], y[-1] = 0.0, dh
    if not np.all(np.isfinite(y)):
        raise ConvergenceError("natural_frequencies: the static profile came out non-finite")
    return y
