r"""The energy balance of aeolian vibration: antinode amplitude, clamp stress and fatigue life.

**Energy balance.** At each frequency f the steady antinode amplitude :math:`y_{\max}` (m, zero
to peak) is where the wind's power input equals the power the conductor dissipates,
:math:`P_w(y, f) = P_d(y, f)` (`skcable.conductors.wind_power`, and any damping: the conductor's
own, `self_damping`, Foti & Martinelli's, `foti_damping`, a power law...). `aeolian_amplitude`
scans the wind model's band of y/D (`wind_band`; for CIGRE's fit from 1e-6 to :math:`e_0`, where
its power vanishes) on 40 geometric points for the first amplitude where the damping overtakes
the wind, then bisects that interval to the last bit of y, all frequencies at once. The
amplitude is the smallest root: the one a vibration growing from rest settles at.

**To the clamp and to a life** (`aeolian_vibration`): the bending amplitude :math:`Y_b` at
89 mm from the clamp (`clamp_amplitude`, peak to peak, as Poffenberger–Swart and the IEEE
define it), the outer wires' stress amplitude (`poffenberger_swart`), the cycles to failure on
an S–N curve (the CIGRE Safe Border Line by default, `WohlerCurve.safe_border_line`), and with
the hours per year each frequency is excited, Miner's damage per year and the life
(`miner_damage`, `fatigue_life`). A damaged conductor (broken wires) has its own stiffnesses,
knees and friction (`skcable.strand.LayerSlipLaw` of the damaged section) and its own mass and
diameter (`Conductor.from_strand`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from skcable._checks import nonnegative, one_of, positive, positive_scalar
from skcable.conductors._damping import foti_damping, self_damping
from skcable.conductors._fatigue import WohlerCurve, clamp_amplitude, miner_damage, poffenberger_swart
from skcable.conductors._wind import WIND_MODELS, wind_band, wind_power
from skcable.errors import ConvergenceError, InputError

if TYPE_CHECKING:
    from skcable.strand import LayerSlipLaw

__all__ = ["AeolianVibration", "aeolian_amplitude", "aeolian_vibration"]

#: Points of the scan for the first crossing, and the lowest y/D of CIGRE's band.
_SCAN, _LOWEST = 40, 1e-6


def _damping_power(damping, y, f) -> np.ndarray:
    """``damping(y, f)`` checked: finite, >= 0, of the broadcast shape."""
    power = np.asarray(damping(y, f), dtype=float)
    shape = np.broadcast_shapes(np.shape(y), np.shape(f))
    if power.shape != shape:
        raise InputError(
            "damping", f"must return the power at every (y, f), shape {shape}; got shape {power.shape}"
        )
    bad = ~(np.isfinite(power) & (power >= 0))
    if bad.any():
        i = tuple(int(k) for k in np.argwhere(bad)[0])
        yi, fi = np.broadcast_to(y, shape)[i], np.broadcast_to(f, shape)[i]
        raise InputError(
            "damping",
            f"returned {power[i]!r} W/m at y = {yi:.6g} m, f = {fi:.6g} Hz: a power must be finite and >= 0",
        )
    return power


def _balance(y, f, diameter, damping, model, turbulence, top):
    """P_w - P_d at (y, f); CIGRE's power is exactly 0 at the top of its band (its root)."""
    wind = wind_power(y, f, diameter, model, turbulence)
    if model == "cigre":
        wind = np.where(y >= top, 0.0, wind)
    return wind - _damping_power(damping, y, f)


def _bracket(f, diameter, damping, model, turbulence):
    """(lo, hi) per frequency: the balance > 0 at lo, <= 0 at hi, the first such pair of the scan."""
    low, high = wind_band(model)
    top = high * diameter
    grid = diameter * np.geomspace(max(low, _LOWEST), high, _SCAN)
    r = _balance(grid[:, None], f[None, :], diameter, damping, model, turbulence, top)
    band = f"[{grid[0] / diameter:.3g}, {high:.6g}]"
    if np.any(r[0] <= 0):
        k = int(np.argmax(r[0] <= 0))
        raise ConvergenceError(
            f"aeolian_amplitude: no root of P_wind = P_damping in the band y/D in {band} at "
            f"f = {f[k]:.6g} Hz: the damping exceeds the wind power from the smallest amplitude on"
        )
    crossed = r <= 0
    if not np.all(crossed.any(axis=0)):
        k = int(np.argmin(crossed.any(axis=0)))
        raise ConvergenceError(
            f"aeolian_amplitude: no root of P_wind = P_damping in the band y/D in {band} of the "
            f"{model!r} wind model at f = {f[k]:.6g} Hz: the wind power exceeds the damping over all of it"
        )
    first = np.argmax(crossed, axis=0)
    return grid[first - 1], grid[first], top


def _bisect(f, diameter, damping, model, turbulence):
    lo, hi, top = _bracket(f, diameter, damping, model, turbulence)
    history = []
    for _ in range(200):
        if np.all(hi - lo <= 4.0 * np.finfo(float).eps * hi):
            return hi
        mid = 0.5 * (lo + hi)
        r = _balance(mid, f, diameter, damping, model, turbulence, top)
        history.append(float(np.max(hi - lo) / np.max(hi)))
        lo, hi = np.where(r > 0, mid, lo), np.where(r > 0, hi, mid)
    raise ConvergenceError("aeolian_amplitude: the bisection did not close its interval", history)


def aeolian_amplitude(f, diameter, mass, tension, damping: Callable, *, model: str = "cigre", turbulence=0.0):
    r"""Antinode amplitude :math:`y_{\max}` (m, zero to peak) where the wind's power equals the
    damping's, :math:`P_w(y, f) = P_d(y, f)` (module text).

    Parameters
    ----------
    f : float or array_like
        Frequencies (Hz), > 0.
    diameter : float
        Conductor diameter (m), > 0.
    mass, tension : float
        Mass per unit length (kg/m) and tension (N), > 0: the loop's wavelength
        :math:`\lambda = \sqrt{T/m}/f`, against which the amplitude is checked (a taut-string
        loop of slope :math:`2\pi y/\lambda` above 0.3 is refused, the model's picture failing).
    damping : callable
        ``damping(y, f)`` → the power dissipated per unit length (W/m, finite, >= 0) at antinode
        amplitudes ``y`` (m) and frequencies ``f`` (Hz), arrays broadcast together; e.g.
        ``lambda y, f: conductors.foti_damping(y, f, T, m, EI_max, kappa_0)``.
    model, turbulence
        The wind model and the turbulence intensity, as `wind_power`.

    Returns
    -------
    float or ndarray
        :math:`y_{\max}` (m) at every frequency, to the last bit of its bisection.

    Raises
    ------
    InputError
        A non-positive frequency, diameter, mass or tension; a ``damping`` that is not callable
        or returns a negative, non-finite or wrongly shaped power (named ``damping``).
    ConvergenceError
        No root in the wind model's band: the damping exceeds the wind from the smallest
        amplitude on, or the wind exceeds the damping over the whole band (a tabulated model).
    """
    single = np.ndim(f) == 0
    f = np.atleast_1d(positive("f", f)).astype(float)
    diameter = positive_scalar("diameter", diameter)
    mass, tension = positive_scalar("mass", mass), positive_scalar("tension", tension)
    if not callable(damping):
        raise InputError("damping", f"must be a callable damping(y, f) -> W/m, got {damping!r:.80}")
    wind_band(model)  # the model's name, checked
    shape = f.shape
    y = _bisect(f.ravel(), diameter, damping, model, turbulence).reshape(shape)
    slope = 2.0 * np.pi * y * f / np.sqrt(tension / mass)
    if np.any(slope > 0.3):
        k = int(np.argmax(slope.ravel() > 0.3))
        raise InputError(
            "f",
            f"at f = {f.ravel()[k]:.6g} Hz the loop's slope 2π y/λ = {slope.ravel()[k]:.3g} is no taut "
            "string's (above 0.3): the energy balance does not hold there",
        )
    return float(y[0]) if single else y


@dataclass(frozen=True)
class AeolianVibration:
    """Result of `aeolian_vibration`: one conductor over a frequency band. SI units.

    Attributes
    ----------
    f : ndarray
        Frequencies (Hz).
    y_max : ndarray
        Antinode amplitude, zero to peak (m).
    wavelength : ndarray
        Loop wavelength ``sqrt(T/m)/f`` (m).
    Y_b : ndarray
        Bending amplitude at ``x_b`` from the clamp, **peak to peak** (m).
    sigma_a : ndarray
        Outer-wire stress amplitude, Poffenberger–Swart (Pa).
    cycles : ndarray
        Cycles to failure at ``sigma_a`` on ``curve``.
    damping_power : ndarray
        The damping (= wind) power at the balance (W/m).
    tension, mass, diameter, EI_clamp, E_a, d_a, x_b : float
        The data of the chain (N, kg/m, m, N·m², Pa, m, m).
    law : skcable.strand.LayerSlipLaw
        The conductor's bending law (damaged section if wires are broken).
    damping, wind, turbulence, axis : str, str, float, int
        How the balance was made.
    curve : WohlerCurve
    hours_per_year : ndarray or None
        Hours per year each frequency is excited; with them ``damage_per_year`` (Miner) and
        ``life_years`` (inf with no damage), else None.
    """

    f: np.ndarray
    y_max: np.ndarray
    wavelength: np.ndarray
    Y_b: np.ndarray
    sigma_a: np.ndarray
    cycles: np.ndarray
    damping_power: np.ndarray
    tension: float
    mass: float
    diameter: float
    EI_clamp: float
    E_a: float
    d_a: float
    x_b: float
    law: LayerSlipLaw = field(repr=False)
    damping: str = "model"
    wind: str = "cigre"
    turbulence: float = 0.0
    axis: int = 0
    curve: WohlerCurve | None = None
    hours_per_year: np.ndarray | None = None
    damage_per_year: float | None = None
    life_years: float | None = None

    def to_frame(self):
        """A pandas DataFrame, one row per frequency, the units in the column names."""
        import pandas as pd

        columns = {
            "f_Hz": self.f, "y_max_m": self.y_max, "wavelength_m": self.wavelength,
            "Y_b_pp_m": self.Y_b, "sigma_a_Pa": self.sigma_a, "cycles_to_failure": self.cycles,
            "damping_W_per_m": self.damping_power,
        }  # fmt: skip
        if self.hours_per_year is not None:
            columns["hours_per_year"] = self.hours_per_year
        return pd.DataFrame(columns)

    def __repr__(self):
        from skcable._show import attributes

        shown = attributes(
            self, {"f": "Hz", "y_max": "m", "Y_b": "m", "sigma_a": "Pa", "life_years": "years"}
        )
        name = getattr(getattr(self.law, "section", None), "strand", None)
        label = getattr(name, "name", "") or "conductor"
        return f"AeolianVibration({label!r}, T={self.tension:.6g} N, damping {self.damping!r}: {shown})"


def _damping_model(damping, law, tension, mass, axis):
    """(label, callable) of ``damping``: "model", "foti" or a callable."""
    if isinstance(damping, str):
        if damping == "model":
            return damping, lambda y, f: self_damping(law, y, f, tension, mass, axis=axis)
        if damping == "foti":
            EI_max, kappa_0 = float(law.EI_max[axis]), float(law.kappa_0[axis])
            return damping, lambda y, f: foti_damping(y, f, tension, mass, EI_max, kappa_0)
    if callable(damping):
        return "custom", damping
    raise InputError(
        "damping", f"must be 'model', 'foti' or a callable damping(y, f) -> W/m, got {damping!r:.80}"
    )


def _clamp_stiffness(clamp_EI, law, axis) -> float:
    if isinstance(clamp_EI, str):
        if clamp_EI not in ("min", "max"):
            raise InputError("clamp_EI", f"must be 'min', 'max' or a stiffness in N·m², got {clamp_EI!r}")
        return float((law.EI_min if clamp_EI == "min" else law.EI_max)[axis])
    return positive_scalar("clamp_EI", clamp_EI)


def _life(f, sigma_a, hours_per_year, curve):
    """(hours, Miner's damage per year, life in years), or Nones without hours."""
    if hours_per_year is None:
        return None, None, None
    hours = np.asarray(nonnegative("hours_per_year", hours_per_year), dtype=float)
    if hours.shape != f.shape:
        raise InputError(
            "hours_per_year", f"must give one number per frequency, shape {f.shape}, got {hours.shape}"
        )
    if hours.sum() > 8766.0 * (1 + 1e-12):
        raise InputError("hours_per_year", f"add up to {hours.sum():.6g} h, more than a year (8766 h)")
    damage = miner_damage(sigma_a, f * 3600.0 * hours, curve)
    return hours, damage, (float("inf") if damage == 0 else 1.0 / damage)


def aeolian_vibration(
    strand, tension, frequencies, *, mu=0.7, damage=None, damping="model", wind: str = "cigre",
    turbulence=0.0, axis: int = 0, clamp_EI="min", x_b: float = 0.089, hours_per_year=None, curve=None,
) -> AeolianVibration:  # fmt: skip
    r"""Aeolian vibration of one conductor over a frequency band, from its strand to a fatigue
    life (module text).

    Parameters
    ----------
    strand : skcable.strand.Strand
        The conductor's strand (``strand.preset("acsr-drake")``).
    tension : float
        Conductor tension (N), > 0.
    frequencies : array_like
        Frequencies (Hz), > 0 (e.g. the Strouhal band of the wind speeds of the site).
    mu : float or array_like
        Friction between the wires (`skcable.strand.LayerSlipLaw`).
    damage : None, int or list of (layer, index)
        Broken wires (as `Conductor.from_strand`): the law, mass and stiffness are the damaged
        conductor's.
    damping : "model", "foti" or callable
        The conductor's own self-damping (`self_damping` of its layer law), Foti & Martinelli's
        closed form with the same law's EI_max and κ_0 (`foti_damping`), or ``damping(y, f)`` in W/m.
    wind, turbulence
        The wind model and the turbulence intensity (`wind_power`).
    axis : {0, 1}
        The principal axis of bending (a damaged section has two).
    clamp_EI : "min", "max" or float
        The bending stiffness at the clamp for Poffenberger–Swart: the law's EI_min (default, the
        usual choice), EI_max, or a value (N·m²).
    x_b : float
        Where Y_b is measured from the last point of contact (m), 0.089 (IEEE, 1966).
    hours_per_year : array_like, optional
        Hours per year each frequency is excited (>= 0, one per frequency, at most a year in
        all): Miner's damage per year and the life.
    curve : WohlerCurve, optional
        The S–N curve; default the CIGRE Safe Border Line for the conductor's number of layers of
        its outer material (`WohlerCurve.safe_border_line`).

    Returns
    -------
    AeolianVibration
    """
    from skcable.conductors._conductor import STANDARD_GRAVITY, Conductor
    from skcable.strand import LayerSlipLaw

    tension = positive_scalar("tension", tension)
    f = np.atleast_1d(positive("frequencies", frequencies)).astype(float)
    one_of("wind", wind, WIND_MODELS)
    conductor = Conductor.from_strand(strand, damage=damage)
    mass, diameter = conductor.w / STANDARD_GRAVITY, conductor.diameter
    law = LayerSlipLaw(conductor.strand.section(), mu=mu, tension=tension)
    label, power = _damping_model(damping, law, tension, mass, axis)
    y = np.atleast_1d(aeolian_amplitude(f, diameter, mass, tension, power, model=wind, turbulence=turbulence))
    EI = _clamp_stiffness(clamp_EI, law, axis)
    outer = conductor.strand.layers[-1]
    E_a, d_a = float(conductor.strand.layer_materials[-1].E_e), float(outer.wire_diameter)
    Y_b = np.atleast_1d(clamp_amplitude(y, f, tension, mass, EI, x_b))
    sigma = np.atleast_1d(poffenberger_swart(Y_b, tension, EI, E_a, d_a, x_b))
    if curve is None:
        materials = conductor.strand.layer_materials
        curve = WohlerCurve.safe_border_line(layers=sum(m is materials[-1] for m in materials[1:]))
    elif not isinstance(curve, WohlerCurve):
        raise InputError("curve", f"must be a WohlerCurve, got {curve!r:.80}")
    cycles = np.atleast_1d(curve.cycles(sigma))
    hours, per_year, life = _life(f, sigma, hours_per_year, curve)
    return AeolianVibration(
        f=f, y_max=y, wavelength=np.sqrt(tension / mass) / f, Y_b=Y_b, sigma_a=sigma, cycles=cycles,
        damping_power=_damping_power(power, y, f), tension=tension, mass=mass, diameter=diameter, EI_clamp=EI,
        E_a=E_a, d_a=d_a, x_b=float(x_b), law=law, damping=label, wind=wind, turbulence=float(turbulence),
        axis=int(axis), curve=curve, hours_per_year=hours, damage_per_year=per_year, life_years=life,
    )  # fmt: skip
