r"""Bending stress at a suspension clamp and fatigue of the conductor's outer wires.

Poffenberger–Swart
------------------
Under aeolian vibration the conductor bends at the last point of contact with the clamp. The
idealized (fictive) stress amplitude in an outer wire follows from the bending amplitude
:math:`Y_b` measured peak to peak at :math:`x_b = 89` mm from that point (J.C. Poffenberger,
R.L. Swart, "Differential displacement and dynamic conductor strain", IEEE Trans. Power
Apparatus and Systems 84(4), 1965; IEEE, "Standardization of conductor vibration
measurements", 1966; CIGRE SC22 WG11 TF4, "Fatigue endurance capability of conductor/clamp
systems", TB 429, 2010):

.. math::
    \sigma_a = K\,Y_b, \qquad
    K = \frac{E_a d_a p^2}{4\left(e^{-p x_b} - 1 + p x_b\right)}, \qquad p = \sqrt{H/EI},

with :math:`E_a` the Young's modulus and :math:`d_a` the diameter of the outer-layer wires,
:math:`H` the conductor's tension and :math:`EI` its bending stiffness — between its slip value
(the wires bending each about its own axis, :math:`EI_{\min}`) and its stick value (the section
bending as a whole, :math:`EI_{\max}`): `clamp_stress` takes both from the (damaged) section,
`skcable.strand.Section`. The denominator cancels for small :math:`p x_b`; it is evaluated by
its Taylor series there (:math:`z^2/2 - z^3/6 + \dots`, :math:`z = p x_b < 0.1`).

Fatigue
-------
`WohlerCurve` is a piecewise power law :math:`\sigma_a = A N^b` (an S–N curve) with its
inverse, the number of cycles to failure; `WohlerCurve.safe_border_line` is the CIGRE Safe
Border Line (CIGRE SC22 WG04, "Recommendations for the evaluation of the lifetime of
transmission line conductors", Electra 63, 1979; as tabulated in EPRI, "Transmission Line
Reference Book: Wind-Induced Conductor Motion", 2nd ed., 2006): for conductors of one layer of
aluminium wires :math:`A = 730` MPa, :math:`b = -0.2` up to :math:`N = 2\times 10^7` and
:math:`A = 430` MPa, :math:`b = -0.168` beyond; for more than one layer :math:`A = 450` MPa,
:math:`b = -0.2` and :math:`A = 263` MPa, :math:`b = -0.168`. `miner_damage` is Palmgren–Miner's
sum :math:`D = \sum_i n_i / N(\sigma_i)` over a histogram of amplitudes, and `fatigue_life`
the time to :math:`D = 1` at a yearly histogram.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import nonnegative, positive
from skcable._show import Shown
from skcable.errors import InputError

__all__ = [
    "poffenberger_swart",
    "clamp_amplitude",
    "ClampStress",
    "clamp_stress",
    "WohlerCurve",
    "miner_damage",
    "fatigue_life",
]

#: The distance (m) from the last point of contact at which Y_b is measured (IEEE, 1966).
X_B = 0.089


def _denominator(z):
    """``exp(-z) - 1 + z`` without cancellation: its Taylor series below z = 0.1."""
    z = np.asarray(z, dtype=float)
    small = z < 0.1
    zs = np.where(small, z, 0.0)
    # z²/2 - z³/6 + z⁴/24 - ... to z^9 (the next term, z^10/10!, is below 3e-17 z²/2 there)
    series = zs * zs * (0.5 + zs * (-1 / 6 + zs * (1 / 24 + zs * (-1 / 120 + zs * (1 / 720 + zs * (
        -1 / 5040 + zs * (1 / 40320 - zs / 362880)))))))  # fmt: skip
    direct = np.expm1(-np.where(small, 1.0, z)) + np.where(small, 1.0, z)
    return np.where(small, series, direct)


def poffenberger_swart(Y_b, H, EI, E_a, d_a, x_b=X_B):
    r"""Idealized stress amplitude (Pa) in an outer wire at a clamp: Poffenberger–Swart.

    :math:`\sigma_a = E_a d_a p^2 Y_b / (4(e^{-p x_b} - 1 + p x_b))`, :math:`p = \sqrt{H/EI}`
    (module text: Poffenberger and Swart, 1965).

    Parameters
    ----------
    Y_b : float or array_like
        Bending amplitude, peak to peak, at ``x_b`` from the last point of contact (m), >= 0.
    H : float or array_like
        Conductor tension (N), > 0.
    EI : float or array_like
        Bending stiffness (N m²), > 0: ``EI_min`` (slip) to ``EI_max`` (stick).
    E_a, d_a : float or array_like
        Young's modulus (Pa) and diameter (m) of the outer-layer wires, > 0.
    x_b : float or array_like
        Where ``Y_b`` is measured (m), > 0; 0.089 m by the IEEE (1966) convention.

    Returns
    -------
    float or ndarray
        The stress amplitude (Pa), broadcast over the arguments.
    """
    Y_b = nonnegative("Y_b", Y_b)
    H, EI, E_a, d_a, x_b = (
        positive(n, v) for n, v in zip(("H", "EI", "E_a", "d_a", "x_b"), (H, EI, E_a, d_a, x_b), strict=True)
    )
    p2 = H / EI
    z = np.sqrt(p2) * x_b
    sigma = E_a * d_a * p2 * Y_b / (4.0 * _denominator(z))
    if not np.all(np.isfinite(sigma)):
        raise InputError("H", "gives a stress outside the float range for these data")
    return float(sigma) if np.ndim(sigma) == 0 else sigma


def clamp_amplitude(y_max, f, tension, mass, EI, x_b=X_B):
    r"""Bending amplitude :math:`Y_b` (m, **peak to peak**) at ``x_b`` from the last point of
    contact with a clamp, of a vibration loop of antinode amplitude ``y_max`` (zero to peak).

    Near a clamped end the loop of a taut string, :math:`y\sin\beta x` with
    :math:`\beta = 2\pi f\sqrt{m/T}`, becomes the boundary layer of a tensioned beam,
    :math:`w(x) = (y\beta/p)(e^{-px} - 1 + px)`, :math:`p = \sqrt{T/EI}` (zero displacement and
    slope at the clamp, the string's slope :math:`y\beta` away from it; asymptotic for
    :math:`p \gg \beta`), so that

    .. math:: Y_b = 2 w(x_b) = \frac{2 y\beta}{p}\left(e^{-p x_b} - 1 + p x_b\right).

    `poffenberger_swart` of this :math:`Y_b` (the same EI) is the outer wire's stress amplitude
    :math:`E_a (d_a/2)\,w''(0) = \pi d_a E_a f \sqrt{m/EI}\,y` (the "f·y_max" rule).

    Parameters
    ----------
    y_max : float or array_like
        Antinode amplitude, zero to peak (m), > 0.
    f : float or array_like
        Frequency (Hz), > 0.
    tension, mass, EI : float or array_like
        Tension (N), mass per unit length (kg/m), bending stiffness at the clamp (N·m²), > 0.
    x_b : float
        Where ``Y_b`` is measured (m), > 0; 0.089 m (IEEE, 1966).

    Returns
    -------
    float or ndarray
        ``Y_b`` peak to peak (m), broadcast over the arguments.
    """
    names = ("y_max", "f", "tension", "mass", "EI", "x_b")
    y, f, T, m, EI, x_b = (
        positive(n, v) for n, v in zip(names, (y_max, f, tension, mass, EI, x_b), strict=True)
    )
    p = np.sqrt(T / EI)
    beta = 2.0 * np.pi * f * np.sqrt(m / T)
    Y_b = 2.0 * y * beta / p * _denominator(p * x_b)
    if not np.all(np.isfinite(Y_b)):
        raise InputError("y_max", "gives a bending amplitude beyond floating point")
    return float(Y_b) if np.ndim(Y_b) == 0 else Y_b


@dataclass(frozen=True)
class ClampStress(Shown):
    """Poffenberger–Swart stress amplitudes (Pa) of one conductor at a clamp.

    ``stick`` and ``slip`` per bending axis of the section (its two principal axes: a damaged
    section has two), with ``EI_stick`` and ``EI_slip``; ``low`` and ``high`` the bounds over
    both (the slip stiffness, the smaller, gives the larger stress); ``E_a``, ``d_a`` the outer
    wires' modulus and diameter used.
    """

    stick: np.ndarray
    slip: np.ndarray
    EI_stick: np.ndarray
    EI_slip: np.ndarray
    E_a: float
    d_a: float

    @property
    def low(self) -> float:
        return float(np.min([self.stick, self.slip]))

    @property
    def high(self) -> float:
        return float(np.max([self.stick, self.slip]))


def clamp_stress(strand, Y_b, H, *, x_b=X_B) -> ClampStress:
    """Poffenberger–Swart stresses of a (damaged) strand, with the stick and slip bending
    stiffnesses of its section as bounds (`skcable.strand.Section.EI_stick`, ``EI_slip``) and
    the outer layer's wire modulus and diameter.

    Parameters
    ----------
    strand : skcable.strand.Strand
        The conductor's strand, intact or with broken wires (``strand.damaged(n)``).
    Y_b, H, x_b : float
        As in `poffenberger_swart` (scalars).
    """
    if not callable(getattr(strand, "section", None)) or not hasattr(strand, "layers"):
        raise InputError("strand", f"must be a skcable.strand.Strand, got {strand!r}")
    section = strand.section()
    outer = strand.layers[-1]
    material = strand.layer_materials[-1]
    E_a, d_a = float(material.E_e), float(outer.wire_diameter)
    EI_stick, EI_slip = np.atleast_1d(section.EI_stick), np.atleast_1d(section.EI_slip)
    stick = np.asarray(poffenberger_swart(Y_b, H, EI_stick, E_a, d_a, x_b))
    slip = np.asarray(poffenberger_swart(Y_b, H, EI_slip, E_a, d_a, x_b))
    return ClampStress(stick, slip, EI_stick, EI_slip, E_a, d_a)


@dataclass(frozen=True)
class WohlerCurve:
    """A piecewise power-law S–N curve: ``sigma_a = A_k N^b_k`` for ``N`` from ``N_k`` on.

    Parameters
    ----------
    pieces : sequence of (N_from, A, b)
        Increasing ``N_from`` (the first 0), ``A`` in Pa (> 0) and ``b < 0``; the amplitude must
        fall with N (continuous within 2 % at the joints, as the published curves are).
    name : str
        Label.
    """

    pieces: tuple
    name: str = ""

    def __post_init__(self):
        try:
            pieces = tuple((float(n), float(a), float(b)) for n, a, b in self.pieces)
        except (TypeError, ValueError):
            raise InputError("pieces", f"must be a sequence of (N_from, A, b), got {self.pieces!r}") from None
        if not pieces or pieces[0][0] != 0.0:
            raise InputError("pieces", "must start at N_from = 0")
        for n, a, b in pieces:
            if not (np.isfinite(n) and n >= 0 and np.isfinite(a) and a > 0 and np.isfinite(b) and b < 0):
                raise InputError("pieces", f"need N_from >= 0, A > 0 and b < 0, got {(n, a, b)}")
        for (n0, a0, b0), (n1, a1, b1) in zip(pieces, pieces[1:], strict=False):
            if not n1 > n0:
                raise InputError("pieces", "N_from must increase")
            left, right = a0 * n1**b0, a1 * n1**b1
            if abs(left / right - 1) > 0.02:
                raise InputError("pieces", f"the curve jumps at N = {n1:g} ({left:.4g} to {right:.4g} Pa)")
        object.__setattr__(self, "pieces", pieces)

    @classmethod
    def safe_border_line(cls, layers: int = 2):
        """The CIGRE Safe Border Line (module text) of a conductor with ``layers`` layers of
        aluminium wires (1, or more than 1)."""
        if isinstance(layers, bool) or not isinstance(layers, (int, np.integer)) or layers < 1:
            raise InputError("layers", f"must be an integer >= 1 (aluminium layers), got {layers!r}")
        if layers == 1:
            return cls(((0.0, 730e6, -0.2), (2e7, 430e6, -0.168)), name="CIGRE Safe Border Line, 1 layer")
        return cls(((0.0, 450e6, -0.2), (2e7, 263e6, -0.168)), name="CIGRE Safe Border Line, >1 layer")

    def amplitude(self, N):
        """Stress amplitude (Pa) at ``N`` cycles (> 0, any shape)."""
        N = positive("N", N)
        out = np.zeros(np.shape(N))
        for n0, a, b in self.pieces:
            out = np.where(np.asarray(N) >= n0, a * np.asarray(N, dtype=float) ** b, out)
        return float(out) if out.ndim == 0 else out

    def cycles(self, sigma_a):
        """Cycles to failure at the stress amplitude ``sigma_a`` (Pa, > 0, any shape): the
        inverse of `amplitude`, ``(sigma_a / A_k)^(1/b_k)`` on the first piece it falls in: where
        the rounded published pieces overlap near a joint (0.1 % for the Safe Border Line), the
        smaller N, and the joint's N for a stress within a downward jump."""
        s = np.asarray(positive("sigma_a", sigma_a), dtype=float)
        out = np.full(s.shape, np.nan)
        bounds = [n for n, _, _ in self.pieces[1:]] + [np.inf]
        for (n0, a, b), upper in zip(self.pieces, bounds, strict=True):
            N = (s / a) ** (1.0 / b)
            unset = np.isnan(out)
            out = np.where(unset & (N >= n0) & (N < upper), N, out)
            out = np.where(unset & (N < n0), n0, out)  # above this piece at its start: the joint
        return float(out) if out.ndim == 0 else out


def miner_damage(amplitudes, counts, curve: WohlerCurve):
    r"""Palmgren–Miner damage :math:`D = \sum_i n_i / N(\sigma_i)` of a histogram.

    Parameters
    ----------
    amplitudes : array_like
        The stress amplitudes of the histogram's bins (Pa, > 0).
    counts : array_like
        The cycles in each bin (>= 0), of the same shape.
    curve : WohlerCurve
        The S–N curve (e.g. `WohlerCurve.safe_border_line`).
    """
    if not isinstance(curve, WohlerCurve):
        raise InputError("curve", f"must be a WohlerCurve, got {curve!r}")
    amplitudes = np.atleast_1d(positive("amplitudes", amplitudes))
    counts = np.atleast_1d(nonnegative("counts", counts))
    if amplitudes.shape != counts.shape:
        raise InputError(
            "counts", f"must have the shape of amplitudes {amplitudes.shape}, got {counts.shape}"
        )
    return float(np.sum(counts / np.atleast_1d(curve.cycles(amplitudes))))


def fatigue_life(amplitudes, counts_per_year, curve: WohlerCurve) -> float:
    """Years to Miner's ``D = 1`` at a yearly histogram (`miner_damage` of one year's cycles);
    inf when the histogram is empty."""
    damage = miner_damage(amplitudes, counts_per_year, curve)
    return float("inf") if damage == 0 else 1.0 / damage
