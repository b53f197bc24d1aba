r"""Axial strain laws ε(T) of line segments, and their exact integrals along a catenary.

A segment's axial law gives its strain ``ε(T)`` (stretched length per unstretched length, less
one) and its compliance ``dε/dT`` (1/N) at tensions ``T`` (N), vectorised:

- `ConstantEA`: ``ε = T/EA`` (a chain, a wire rope: Irvine's elastic catenary);
- `StrainTable`: a table of (strain, tension) points from (0, 0), both strictly increasing,
  interpolated by a monotone piecewise cubic with a continuous derivative (F.N. Fritsch,
  R.E. Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal., 1980: scipy's
  ``PchipInterpolator``) and continued linearly with its end slopes beyond the table (and below
  zero tension, where a Newton iterate may pass);
- `StrainFunction`: the user's ``ε(T)`` with its derivative;
- `StaticDynamicRope`: a synthetic (polyester, nylon) rope with a static stiffness ``EA_s`` for
  the quasi-static offset and a dynamic one ``EA_d = α + β T_mean`` about a mean position
  (MoorPy's ``EAd`` and ``EAd_Lm``; the Syrope model's working curves: S. Falkenberg, T. Åhjem,
  "Syrope: a method for the calculation of stiffness of fibre ropes", OMAE 2017).

Each law says which compliance applies to a linearisation: ``compliance`` (quasi-static) and
``dynamic_compliance`` (about a mean state; the static one for every law but the rope's).

**The integrals along a catenary.** On a segment of constant weight ``w`` per unstretched
length (N/m, any sign), horizontal force ``H`` and vertical force ``V(s) = V0 + w s`` along
its unstretched length ``s ∈ [0, L]``, the tension ``T(s) = sqrt(H² + V²)`` is known in closed
form, and the segment's end offsets are the rigid catenary's plus the elastic parts

.. math:: \Delta x = \int_0^L \varepsilon(T)\,\frac{H}{T}\,ds, \qquad
          \Delta z = \int_0^L \varepsilon(T)\,\frac{V}{T}\,ds, \qquad
          \Delta L = \int_0^L \varepsilon(T)\,ds

(Irvine's elastic catenary when ``ε = T/EA``: H.M. Irvine, "Cable Structures", MIT Press,
1981, ch. 2). `catenary_quadrature` evaluates them by Gauss–Legendre quadrature in the
variable ``u = asinh(V/H)`` (``T = H cosh u``, ``ds = (H/w) cosh u du``), in which the
integrand is smooth however slack or steep the segment is, on pieces of at most `PIECE` in
``u`` split where the law's derivative has a kink (a table's points): `ORDER` points per piece
integrate a smooth law to round-off. `elongation` gives the three integrals and their
derivatives by ``(H, V0)``, `catenary_ends` the whole end offsets and their Jacobian, and
`law_catenary` solves a hanging segment between two points.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable import _plausible
from skcable._checks import one_of, positive, real
from skcable.cable._special import asinh_step
from skcable.errors import InputError

__all__ = [
    "ORDER",
    "PIECE",
    "ConstantEA",
    "Elongation",
    "LawCatenary",
    "StaticDynamicRope",
    "StrainFunction",
    "StrainLaw",
    "StrainTable",
    "catenary_ends",
    "catenary_quadrature",
    "elongation",
    "law_catenary",
    "strain_law",
]

#: Gauss–Legendre points per piece of a catenary's quadrature
ORDER = 12
#: the largest piece in u = asinh(V/H)
PIECE = 0.5


def _checked(name: str, values, shape) -> np.ndarray:
    out = np.asarray(values, dtype=float)
    try:
        out = np.broadcast_to(out, shape)
    except ValueError as exc:
        raise InputError(name, f"returned shape {out.shape} for tensions of shape {shape}") from exc
    if not np.all(np.isfinite(out)):
        raise InputError(name, "returned non-finite values")
    return out


class StrainLaw:
    """Base of the axial laws: ``strain(T)`` and ``compliance(T) = dε/dT`` (1/N), vectorised.

    Attributes
    ----------
    breakpoints : ndarray
        Tensions (N) where the law is only once differentiable (a quadrature splits there).
    kind : str
        ``"constant"`` where ``ε = T/EA``, ``"nonlinear"`` otherwise.
    """

    breakpoints: np.ndarray = np.zeros(0)
    kind = "nonlinear"

    def strain(self, T) -> np.ndarray:
        """``ε(T)`` at tensions ``T`` (N)."""
        raise NotImplementedError

    def compliance(self, T) -> np.ndarray:
        """``dε/dT`` (1/N) at tensions ``T`` (N): the quasi-static one."""
        raise NotImplementedError

    def dynamic_compliance(self, T) -> np.ndarray:
        """``dε/dT`` (1/N) for a linearisation about a mean state of tension ``T``: the static
        one, but for a rope with a dynamic stiffness (`StaticDynamicRope`)."""
        return self.compliance(T)

    def secant_EA(self, T) -> np.ndarray:
        """``T/ε(T)`` (N), the secant stiffness (the tangent one, ``1/compliance``, at ``T = 0``)."""
        T = np.asarray(T, dtype=float)
        eps = self.strain(T)
        safe = np.where(eps != 0, eps, 1.0)
        return np.where(eps != 0, T / safe, 1.0 / self.compliance(T))


class ConstantEA(StrainLaw):
    """``ε = T/EA``, ``EA`` (N) > 0."""

    kind = "constant"

    def __init__(self, EA: float):
        self.EA = float(positive("EA", EA))

    def strain(self, T):
        return np.asarray(T, dtype=float) / self.EA

    def compliance(self, T):
        return np.full(np.shape(T), 1.0 / self.EA)

    def __repr__(self):
        return f"ConstantEA(EA={self.EA:g} N)"


class StrainTable(StrainLaw):
    """``ε(T)`` from a table of points (strain, tension) starting at (0, 0), both strictly
    increasing: the monotone cubic through them (scipy's ``PchipInterpolator``, a continuous
    derivative), or the straight segments between them (``interpolation="linear"``: MoorDyn's
    strain–tension curves, ``moordyn::interp``), linear with its end slopes below zero and beyond
    the last point.

    Parameters
    ----------
    strain : array_like
        Strains (-), from 0, strictly increasing.
    tension : array_like
        Tensions (N) at those strains, from 0, strictly increasing.
    interpolation : {"pchip", "linear"}, optional
        The curve between the points.
    """

    def __init__(self, strain, tension, *, interpolation: str = "pchip"):
        from scipy.interpolate import BSpline, PchipInterpolator, make_interp_spline

        one_of("interpolation", interpolation, ("pchip", "linear"))

        eps, T = real("strain", strain), real("tension", tension)
        for name, values in (("strain", eps), ("tension", T)):
            if np.ndim(values) != 1 or np.size(values) < 2:
                raise InputError(name, f"must be a table of at least two points, got {values!r}")
        if np.size(eps) != np.size(T):
            raise InputError("tension", f"one tension per strain: {np.size(T)} for {np.size(eps)}")
        for name, values in (("strain", eps), ("tension", T)):
            if values[0] != 0.0:
                raise InputError(name, f"the table starts at (0, 0), got {values[0]!r}")
            if not np.all(np.diff(values) > 0):
                k = int(np.argmin(np.diff(values) > 0))
                raise InputError(
                    name,
                    f"must increase strictly (ε(T) increasing), got {values[k]:g} then {values[k + 1]:g}",
                )
        self.table = (np.array(eps, dtype=float), np.array(T, dtype=float))
        self.interpolation = interpolation
        self.breakpoints = self.table[1][1:]
        if interpolation == "linear":
            spline = make_interp_spline(self.table[1], self.table[0], k=1)
            self.curve = BSpline(spline.t, spline.c, 1, extrapolate=False)
            slopes = np.diff(self.table[0]) / np.diff(self.table[1])  # a knot's derivative is one side's
            self.ends = (float(slopes[0]), float(slopes[-1]))
        else:
            self.curve = PchipInterpolator(self.table[1], self.table[0], extrapolate=False)
            self.ends = (float(self.curve.derivative()(T[0])), float(self.curve.derivative()(T[-1])))
        self.slope = self.curve.derivative()

    def strain(self, T):
        T = np.asarray(T, dtype=float)
        eps, tension = self.table
        below, above = T < 0.0, T > tension[-1]
        inside = np.clip(T, 0.0, tension[-1])
        out = self.curve(inside)
        return np.where(
            below, self.ends[0] * T, np.where(above, eps[-1] + self.ends[1] * (T - tension[-1]), out)
        )

    def compliance(self, T):
        T = np.asarray(T, dtype=float)
        tension = self.table[1]
        out = self.slope(np.clip(T, 0.0, tension[-1]))
        return np.where(T < 0.0, self.ends[0], np.where(T > tension[-1], self.ends[1], out))

    def __repr__(self):
        eps, T = self.table
        linear = ", linear" if self.interpolation == "linear" else ""
        return f"StrainTable({eps.size} points to ε={eps[-1]:g} at T={T[-1]:g} N{linear})"


class StrainFunction(StrainLaw):
    """The user's law: ``strain(T)`` and its ``derivative(T)`` (1/N), vectorised, ``ε(0) = 0``;
    every value finite and the derivative > 0 at every tension >= 0 it is asked for (an
    ``ε(T)`` that is not increasing is refused, naming ``derivative``).

    Parameters
    ----------
    strain, derivative : callable
        ``ε(T)`` and ``dε/dT``, arrays in, arrays out.
    """

    def __init__(self, strain, derivative):
        for name, fn in (("strain", strain), ("derivative", derivative)):
            if not callable(fn):
                raise InputError(name, f"must be a callable of the tension, got {fn!r}")
        self.function, self.derivative = strain, derivative
        at_zero = float(_checked("strain", strain(np.zeros(1)), (1,))[0])
        if abs(at_zero) > 1e-12:
            raise InputError("strain", f"must vanish at zero tension, got ε(0) = {at_zero:g}")

    def strain(self, T):
        T = np.asarray(T, dtype=float)
        return _checked("strain", self.function(T), T.shape)

    def compliance(self, T):
        T = np.asarray(T, dtype=float)
        out = _checked("derivative", self.derivative(T), T.shape)
        bad = (T >= 0) & ~(out > 0)
        if np.any(bad):
            raise InputError(
                "derivative",
                f"must be > 0 (ε(T) increasing), got {out[bad].flat[0]:g} at T = {T[bad].flat[0]:g} N",
            )
        return out

    def __repr__(self):
        return f"StrainFunction({getattr(self.function, '__name__', 'callable')})"


class StaticDynamicRope(ConstantEA):
    """A synthetic rope: ``ε = T/EA_s`` for the quasi-static offset, and a dynamic stiffness
    ``EA_d = α + β T_mean`` (N; β dimensionless) for a linearisation about a mean position, at
    the local mean tension (MoorPy's ``EAd`` and ``EAd_Lm``, which it applies at the mean of a
    line's end tensions).

    Parameters
    ----------
    EA_static : float
        ``EA_s`` (N), > 0.
    alpha : float
        ``α`` (N), > 0.
    beta : float
        ``β`` (-), >= 0.
    """

    def __init__(self, EA_static: float, alpha: float, beta: float = 0.0):
        super().__init__(EA_static)
        self.alpha = float(positive("alpha", alpha))
        self.beta = float(real("beta", beta))
        if self.beta < 0:
            raise InputError(
                "beta", f"must be >= 0 (the dynamic stiffness grows with the mean load), got {beta!r}"
            )

    def dynamic_EA(self, T) -> np.ndarray:
        """``α + β T`` (N) at the mean tensions ``T``, the negative ones taken as zero."""
        return self.alpha + self.beta * np.maximum(np.asarray(T, dtype=float), 0.0)

    def dynamic_compliance(self, T):
        return 1.0 / self.dynamic_EA(T)

    def __repr__(self):
        return f"StaticDynamicRope(EA_static={self.EA:g} N, alpha={self.alpha:g} N, beta={self.beta:g})"


def strain_law(EA, name: str = "EA") -> StrainLaw | None:
    """The law a user means by ``EA``: None (inextensible), a number (`ConstantEA`) or a
    `StrainLaw`; anything else refused, naming ``name``."""
    if EA is None or isinstance(EA, StrainLaw):
        return EA
    if callable(EA):
        raise InputError(
            name, "a callable strain needs its derivative: give StrainFunction(strain, derivative)"
        )
    try:
        return ConstantEA(EA)
    except InputError as exc:
        raise InputError(name, str(exc).split(": ", 1)[1]) from None


# --- the integrals along a catenary ------------------------------------------------------------
_GAUSS = np.polynomial.legendre.leggauss(ORDER)


def _pieces(lo: float, hi: float, cuts) -> np.ndarray:
    """The ends of the pieces of ``[lo, hi]``: split at ``cuts`` inside it, then each piece in
    equal parts of at most `PIECE`."""
    inner = np.sort([c for c in cuts if lo < c < hi])
    ends = np.concatenate([[lo], inner, [hi]])
    parts = [
        np.linspace(a, b, max(1, int(np.ceil((b - a) / PIECE))) + 1)[:-1]
        for a, b in zip(ends[:-1], ends[1:], strict=True)
    ]
    return np.concatenate([*parts, [hi]])


def _gauss(ends: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights on the pieces ``ends``."""
    x, wts = _GAUSS
    half, middle = 0.5 * np.diff(ends), 0.5 * (ends[1:] + ends[:-1])
    return (middle[:, None] + half[:, None] * x).ravel(), (half[:, None] * wts).ravel()


def catenary_quadrature(H: float, V0: float, w: float, length: float, breakpoints=()):
    """Nodes and weights of ``∫_0^L g(T(s), V(s)) ds`` on a catenary segment (module docstring).

    Parameters
    ----------
    H : float
        Horizontal force (N), >= 0.
    V0 : float
        Vertical force at ``s = 0`` (N), along the line towards its other end.
    w : float
        Weight per unstretched length (N/m), any sign: ``V(s) = V0 + w s``.
    length : float
        Unstretched length (m), > 0.
    breakpoints : sequence of float
        Tensions (N) where the integrand's law has a kink (`StrainLaw.breakpoints`).

    Returns
    -------
    T, V, weights : ndarray
        Tension and vertical force (N) at the nodes, and the weights (m): ``Σ weights g``.
    """
    if w == 0.0:  # no weight: the tension is constant along the segment
        T0 = float(np.hypot(H, V0))
        return np.array([T0]), np.array([float(V0)]), np.array([float(length)])
    if H == 0.0:  # vertical: T = |V|, integrated in V (ds = dV / |w|), offsets from V0
        dV = w * length
        cuts = [c - V0 for c in (0.0, *(c for b in breakpoints for c in (b, -b)))]
        t, weights = _gauss(_pieces(min(0.0, dV), max(0.0, dV), cuts))
        V = V0 + t
        return np.abs(V), V, weights / abs(w)
    q = V0 / H
    d = w * length / H
    u0 = float(np.arcsinh(q))
    # the pieces as offsets from u0 (a short, taut segment's du is far below u0's rounding)
    du = float(asinh_step(q, d)) if d >= 0 else -float(asinh_step(q + d, -d))
    cuts = [c - u0 for b in breakpoints if b > H for c in (np.arccosh(b / H), -np.arccosh(b / H))]
    t, weights = _gauss(_pieces(min(0.0, du), max(0.0, du), cuts))
    u = u0 + t
    T, V = H * np.cosh(u), H * np.sinh(u)
    return T, V, weights * T / abs(w)


@dataclass(frozen=True)
class Elongation:
    """The elastic integrals of a catenary segment (module docstring) and their derivatives.

    Attributes
    ----------
    stretch : float
        ``∫ ε ds`` (m): the segment's elongation.
    x, z : float
        ``∫ ε H/T ds`` and ``∫ ε V/T ds`` (m): the elastic parts of its end offsets.
    jacobian : ndarray (3, 2)
        ``∂(stretch, x, z)/∂(H, V0)`` (m/N).
    """

    stretch: float
    x: float
    z: float
    jacobian: np.ndarray


def elongation(law: StrainLaw, H: float, V0: float, w: float, length: float) -> Elongation:
    """``∫ ε ds``, ``∫ ε H/T ds``, ``∫ ε V/T ds`` along the catenary segment ``(H, V0, w, L)``
    with the strain law ``law``, and their derivatives by ``H`` and ``V0`` (the integrals of
    the integrands' derivatives: ``∂T/∂H = H/T``, ``∂T/∂V0 = V/T``, ``∂V/∂V0 = 1``)."""
    T, V, c = catenary_quadrature(H, V0, w, length, law.breakpoints)
    eps, k = law.strain(T), law.compliance(T)
    h, v = H / T, V / T  # cos and sin of the line's angle
    e_T = eps / T
    jac = np.array(
        [
            [np.sum(c * k * h), np.sum(c * k * v)],
            [np.sum(c * (k * h * h + e_T * v * v)), np.sum(c * (k - e_T) * h * v)],
            [np.sum(c * (k - e_T) * h * v), np.sum(c * (k * v * v + e_T * h * h))],
        ]
    )
    return Elongation(float(np.sum(c * eps)), float(np.sum(c * eps * h)), float(np.sum(c * eps * v)), jac)


def catenary_ends(law: StrainLaw | None, H: float, V0: float, w: float, length: float):
    """The end offsets ``(Δx, Δz)`` (m) of a catenary segment from its start (rigid catenary plus
    `elongation`'s elastic parts; ``law`` None: inextensible) and their Jacobian by ``(H, V0)``
    (2, 2) (m/N). ``H`` > 0."""
    V1 = V0 + w * length
    T0, T1 = float(np.hypot(H, V0)), float(np.hypot(H, V1))
    if w == 0.0:
        x, z = length * H / T0, length * V0 / T0
        jac = length * np.array([[V0 * V0, -H * V0], [-H * V0, H * H]]) / T0**3
    else:
        q, d = V0 / H, w * length / H
        A = float(asinh_step(q, d)) if d >= 0 else -float(asinh_step(q + d, -d))
        x = H / w * A
        z = length * (V0 + V1) / (T0 + T1)  # (T1 - T0)/w without its cancellation
        jac = np.array(
            [
                [(A - (V1 / T1 - V0 / T0)) / w, H / w * (1.0 / T1 - 1.0 / T0)],
                [H / w * (1.0 / T1 - 1.0 / T0), (V1 / T1 - V0 / T0) / w],
            ]
        )
    if law is not None:
        e = elongation(law, H, V0, w, length)
        x, z, jac = x + e.x, z + e.z, jac + e.jacobian[1:]
    return float(x), float(z), jac


@dataclass(frozen=True)
class LawCatenary:
    """A segment hanging between two points with an axial law (`law_catenary`).

    Attributes
    ----------
    H : float
        Horizontal force (N).
    V_A, V_B : float
        Upward reactions at A and B (N): the vertical force along the line is ``-V_A`` at A and
        ``V_B = -V_A + w L`` at B.
    span, dh, w, length : float
        The scene (m, m, N/m, m).
    law : StrainLaw or None
    history : list of float
        The largest end-offset error over the chord, per Newton iteration.
    """

    H: float
    V_A: float
    V_B: float
    span: float
    dh: float
    w: float
    length: float
    law: StrainLaw | None
    history: list = field(default_factory=list)

    def x_z_of_s(self, s) -> np.ndarray:
        """Position ``(x, z)`` (m) relative to A at unstretched arc lengths ``s`` (m): (n, 2)."""
        s = np.atleast_1d(np.asarray(real("s", s), dtype=float))
        out = [
            catenary_ends(self.law, self.H, -self.V_A, self.w, si)[:2] if si > 0 else (0.0, 0.0) for si in s
        ]
        return np.array(out, dtype=float)

    def T_of_s(self, s) -> np.ndarray:
        """Tension (N) at unstretched arc lengths ``s`` (m)."""
        s = np.asarray(real("s", s), dtype=float)
        return np.hypot(self.H, -self.V_A + self.w * s)

    @property
    def elongation(self) -> float:
        """``∫ ε ds`` (m)."""
        return (
            0.0 if self.law is None else elongation(self.law, self.H, -self.V_A, self.w, self.length).stretch
        )


def law_catenary(
    span, dh, w, law, *, length, start=None, tol: float = 1e-13, max_iter: int = 50
) -> LawCatenary:
    """A segment of weight ``w`` (N/m, > 0), unstretched ``length`` (m) and axial ``law`` (a
    `StrainLaw`, a number EA or None) from A = (0, 0) to B = (span, dh): its ``(H, V_A)`` by
    Newton's method on `catenary_ends` (from ``start = (H, V_A)``, else from the elastic
    catenary of the law's secant stiffness at the weight of the line), converged when the end
    offsets meet B to ``tol`` of the chord.

    Raises
    ------
    InputError
        Bad data, named (a chord longer than the stretched line has no hanging solution).
    ConvergenceError
        Newton did not converge (with its history).
    """
    from skcable.cable._elastic import elastic_catenary
    from skcable.fe.newton import newton

    span, dh, w = positive("span", span), real("dh", dh), positive("w", w)
    L = positive("length", length)
    law = strain_law(law)
    chord = float(np.hypot(span, dh))
    if start is None:
        EA = 1e9 * w * L if law is None else float(law.secant_EA(np.array(w * L)))
        with _plausible.quiet():  # a guess, not an answer
            guess = elastic_catenary(span, dh, w, EA, length=L)
        start = (float(guess.H), float(guess.V_A))
    H0, VA0 = (float(v) for v in start)
    scale = np.array([H0, max(abs(VA0), H0)])

    def assemble(u):
        H, V0 = u * scale
        if not H > 0:
            return None
        x, z, jac = catenary_ends(law, H, V0, w, L)
        return np.array([x - span, z - dh]), jac * scale

    def norm(state):
        return np.inf if state is None else float(np.max(np.abs(state[0]))) / chord

    def increment(state):
        return np.linalg.solve(state[1], -state[0])

    result = newton(
        assemble, np.array([H0, -VA0]) / scale, norm=norm, increment=increment, tol=tol,
        max_iter=max_iter, admissible=lambda u: u[0] > 0, name="law_catenary",
    )  # fmt: skip
    H, V0 = result.x * scale
    return LawCatenary(float(H), float(-V0), float(V0 + w * L), span, dh, w, L, law, list(result.history))
