r"""Wind power input to a conductor in aeolian vibration.

A steady cross wind locked on a vibration of frequency f (Hz) and antinode amplitude y (m, zero
to peak) feeds a conductor of diameter D (m) with the power per unit length (W/m)

$$
P_w = f^3 D^4\,\beta\,F(y/D), \qquad \beta = \left(1 + (I_v/0.09)^2\right)^{-1/2},
$$

F (W/(m⁴ Hz³)) from wind-tunnel and field studies and β the reduction by the turbulence
intensity :math:`I_v` (F. Foti, L. Martinelli, "An enhanced unified model for the self-damping of
stranded cables under aeolian vibrations", J. Wind Eng. Ind. Aerodyn. 182, 2018, eqs. 4–5; β
multiplies every model here, the studies being in smooth flow):

- ``"cigre"``: CIGRE's fit :math:`F(e) = -99.73 e^3 + 101.62 e^2 + 0.1627 e + 0.2256`, as Foti &
  Martinelli (2018, eq. 4) give it, valid for :math:`0 < y/D \le e_0`, the root where its power
  vanishes (`wind_band`; beyond, the fit turns negative: refused);
- tabulated studies, as compiled in RTE's pallas-dohl (rte-france/pallas-dohl,
  ``src/dohl/wind_power_data.yaml``, commit 45b6cb96), after EPRI's "Transmission Line Reference
  Book: Wind-Induced Conductor Motion" (2006): ``"diana-falco-1971"`` (G. Diana, M. Falco, 1971),
  ``"rawlins-1983"`` (C.B. Rawlins, 1983) and ``"brika-laneville-1995"`` (D. Brika, A. Laneville,
  1995), F at tabulated y/D, interpolated by a monotone cubic (Fritsch–Carlson, scipy's
  ``PchipInterpolator``) and refused outside the table.
"""

from __future__ import annotations

import functools

import numpy as np

from skcable._checks import broadcast, nonnegative, one_of, positive, scalar
from skcable.errors import InputError

__all__ = ["WIND_MODELS", "wind_band", "wind_power"]

#: CIGRE's fit F(e), highest power first.
_CIGRE = (-99.73, 101.62, 0.1627, 0.2256)
#: The turbulence intensity scale of β (Foti & Martinelli 2018, eq. 5).
_I_L = 0.09

#: Tabulated studies: y/D and F (W/(m⁴ Hz³)), as compiled in pallas-dohl (module text).
_TABLES = {
    "diana-falco-1971": (
        (0.03, 0.06, 0.10, 0.20, 0.30, 0.40, 0.50, 0.60, 0.70, 0.80),
        (0.23, 0.70, 1.80, 5.00, 9.00, 14.00, 18.00, 20.00, 21.00, 20.00),
    ),
    "rawlins-1983": (
        (0.03, 0.06, 0.10, 0.20, 0.30, 0.40, 0.50, 0.60, 0.70),
        (0.18, 0.60, 1.60, 4.00, 6.50, 9.00, 10.10, 10.70, 10.80),
    ),
    "brika-laneville-1995": (
        (0.01, 0.03, 0.06, 0.10, 0.20, 0.30, 0.40),
        (0.03, 0.17, 0.49, 1.10, 3.20, 5.50, 6.00),
    ),
}

#: The wind power models.
WIND_MODELS = ("cigre", *_TABLES)


@functools.cache
def _cigre_root() -> float:
    """e_0: the positive root of CIGRE's F (where its power vanishes)."""
    roots = np.roots(_CIGRE)
    real = roots[np.abs(roots.imag) < 1e-12].real
    return float(real[real > 0].min())


@functools.cache
def _table(model: str):
    from scipy.interpolate import PchipInterpolator

    e, F = (np.array(v) for v in _TABLES[model])
    return PchipInterpolator(e, F, extrapolate=False)


def _model(model) -> str:
    return one_of("model", model, WIND_MODELS)


def wind_band(model: str = "cigre") -> tuple[float, float]:
    """The range of y/D a wind model holds on: ``(0, e_0]`` for CIGRE's fit (module text), the
    table's first and last y/D for a tabulated study."""
    model = _model(model)
    if model == "cigre":
        return 0.0, _cigre_root()
    e = _TABLES[model][0]
    return float(e[0]), float(e[-1])


def _turbulence_factor(turbulence) -> float:
    intensity = nonnegative("turbulence", scalar("turbulence", turbulence))
    return 1.0 / float(np.sqrt(1.0 + (intensity / _I_L) ** 2))


def _F(model: str, e):
    """F(e) of ``model`` (W/(m⁴ Hz³)), e inside its band (checked by the caller)."""
    if model == "cigre":
        a, b, c, d = _CIGRE
        return ((a * e + b) * e + c) * e + d
    return _table(model)(e)


def wind_power(y, f, diameter, model: str = "cigre", turbulence=0.0):
    r"""Wind power input per unit length (W/m), :math:`f^3 D^4 \beta F(y/D)` (module text).

    Parameters
    ----------
    y : float or array_like
        Antinode amplitude, zero to peak (m), > 0, with y/D inside the model's band
        (`wind_band`).
    f : float or array_like
        Frequency (Hz), > 0.
    diameter : float or array_like
        Conductor diameter (m), > 0.
    model : str
        One of `WIND_MODELS`: ``"cigre"`` (default) or a tabulated study.
    turbulence : float
        Turbulence intensity :math:`I_v` (>= 0); 0: smooth flow (β = 1).

    Returns
    -------
    float or ndarray
        The power per unit length (W/m), broadcast over the arguments.
    """
    model = _model(model)
    y, f, diameter = positive("y", y), positive("f", f), positive("diameter", diameter)
    broadcast(y=y, f=f, diameter=diameter)
    beta = _turbulence_factor(turbulence)
    e = np.asarray(y / diameter, dtype=float)
    low, high = wind_band(model)
    outside = ~((e > low) & (e <= high) if model == "cigre" else (e >= low) & (e <= high))
    if outside.any():
        bad = float(e[outside].flat[0])
        raise InputError(
            "y",
            f"y/D = {bad:.6g} lies outside the range of the {model!r} wind model, [{low:.6g}, {high:.6g}]",
        )
    power = f**3 * diameter**4 * beta * _F(model, e)
    if not np.all(np.isfinite(power)):
        raise InputError("f", "gives a wind power beyond floating point")
    return float(power) if np.ndim(power) == 0 else np.asarray(power)
