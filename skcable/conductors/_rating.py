r"""Conductor temperature from its current and the weather, through linerate: a thin adapter.

The heat balance of a bare overhead conductor — Joule and solar heating against convective
and radiative cooling, steady or with the conductor's heat capacity — is IEEE Std 738-2012,
"Standard for Calculating the Current-Temperature Relationship of Bare Overhead Conductors",
and CIGRE Technical Brochure 601, "Guide for thermal rating calculations of overhead lines",
2014. Both are computed by linerate (Statnett, https://github.com/statnett/linerate, an
optional dependency: ``pip install "skcable[rating]"``); nothing of them is written here.
`ThermalRating` holds one linerate model (``linerate.IEEE738`` or ``linerate.Cigre601``) of a
``linerate.Span`` (its ``linerate.Conductor``: resistance, diameters, emissivity, absorptivity)
under a ``linerate.Weather`` at a time. With a `skcable.conductors.Conductor` for the mechanics,
`sag_at_current` and `clearance_ampacity` join it to the change of state (the clearance to
ground or to a crossing). linerate's bisections take a tolerance in °C or A; the defaults here
are 1e-4 of those units.
"""

from __future__ import annotations

import numpy as np

from skcable import _plausible
from skcable._checks import one_of, positive, positive_scalar, real, scalar
from skcable.errors import ConvergenceError, InputError

__all__ = ["ThermalRating", "sag_at_current", "clearance_ampacity"]

_STANDARDS = ("ieee738", "cigre601")
_ONE_SECOND = np.timedelta64(1, "s")


def _linerate():
    try:
        import linerate
    except ImportError as exc:  # the optional dependency
        raise ImportError(
            "conductor temperatures come from linerate: pip install 'skcable[rating]' (or linerate)"
        ) from exc
    return linerate


class ThermalRating:
    """The heat balance of one span's conductor under one weather (IEEE 738 or CIGRE 601).

    Parameters
    ----------
    span : linerate.Span
        The span (towers, number of conductors) and its ``linerate.Conductor``.
    weather : linerate.Weather
        Air temperature (°C), wind speed (m/s) and direction (rad), ground albedo, clearness.
        Required: a rating without weather is refused (``InputError('weather')``).
    time : numpy.datetime64
        The time (the sun's position).
    standard : {"ieee738", "cigre601"}
        The model: ``linerate.IEEE738`` or ``linerate.Cigre601``.

    Attributes
    ----------
    model : linerate.ThermalModel
        The linerate model, for anything this adapter does not expose.
    """

    def __init__(self, span, weather, time, *, standard: str = "ieee738"):
        linerate = _linerate()
        one_of("standard", standard, _STANDARDS)
        if weather is None:
            raise InputError(
                "weather",
                "a conductor's temperature and ampacity need the weather (air temperature, wind, "
                "sun): give a linerate.Weather",
            )
        if not isinstance(weather, linerate.BaseWeather):
            raise InputError("weather", f"must be a linerate.Weather, got {weather!r}")
        if not isinstance(span, linerate.Span):
            raise InputError("span", f"must be a linerate.Span, got {span!r}")
        if time is None or not np.issubdtype(np.asarray(time).dtype, np.datetime64):
            raise InputError("time", f"must be a numpy.datetime64 (the sun's position), got {time!r}")
        cls = linerate.IEEE738 if standard == "ieee738" else linerate.Cigre601
        self.span, self.weather, self.time, self.standard = span, weather, time, standard
        self.model = cls(span, weather, time)

    def __repr__(self):
        air, wind = self.weather.air_temperature, self.weather.wind_speed
        return f"ThermalRating({self.standard}, air {air} °C, wind {wind} m/s)"

    def temperature(self, current, *, bounds=None, tolerance: float = 1e-4):
        """Steady-state conductor temperature (°C) at ``current`` (A, >= 0, total over the
        span's conductors; any shape): the root of the heat balance in ``bounds`` (default:
        from the air temperature, where heating exceeds cooling, to 300 °C), to ``tolerance``
        °C (linerate's vectorised bisection)."""
        current = real("current", current)
        if np.any(np.asarray(current) < 0):
            raise InputError("current", "must be >= 0 (A)")
        lo, hi = _bounds("bounds", (float(self.weather.air_temperature), 300.0) if bounds is None else bounds)
        try:
            value = self.model.compute_conductor_temperature(
                current, min_temperature=lo, max_temperature=hi, tolerance=positive("tolerance", tolerance)
            )
        except ValueError as exc:  # no sign change of the balance in the bounds
            raise InputError("current", f"heats the conductor outside ({lo}, {hi}) °C ({exc})") from None
        return _finite("temperature", value)

    def temperature_after(self, current, duration, *, initial_temperature, time_step=_ONE_SECOND):
        """Conductor temperature (°C) after carrying ``current`` (A) for ``duration``
        (numpy.timedelta64) from ``initial_temperature`` (°C): linerate's forward-Euler
        integration of the heat balance with the conductor's heat capacity (its span needs a
        ``linerate.ConductorWithHeatCapacity``)."""
        linerate = _linerate()
        if not isinstance(self.span.conductor, linerate.ConductorWithHeatCapacity):
            raise InputError(
                "span", "a transient temperature needs a linerate.ConductorWithHeatCapacity (its masses)"
            )
        for name, value in (("duration", duration), ("time_step", time_step)):
            if not isinstance(value, np.timedelta64) or value <= np.timedelta64(0, "s"):
                raise InputError(name, f"must be a positive numpy.timedelta64, got {value!r}")
        value = self.model.compute_temperature_after_heating(
            real("initial_temperature", initial_temperature), duration, real("current", current), time_step
        )
        return _finite("temperature", value)

    def ampacity(self, max_temperature, *, bounds=(0.0, 10000.0), tolerance: float = 1e-4):
        """Steady-state ampacity (A, total over the span's conductors) at ``max_temperature``
        (°C, any shape), to ``tolerance`` A (linerate's bisection in ``bounds``)."""
        max_temperature = real("max_temperature", max_temperature)
        lo, hi = _bounds("bounds", bounds)
        try:
            value = self.model.compute_steady_state_ampacity(
                max_temperature, min_ampacity=lo, max_ampacity=hi, tolerance=positive("tolerance", tolerance)
            )
        except ValueError as exc:
            raise InputError("max_temperature", f"has no ampacity in {bounds} A ({exc})") from None
        return _finite("ampacity", value)


def _bounds(name, bounds):
    try:
        lo, hi = (scalar(name, v) for v in bounds)
    except (TypeError, ValueError):
        raise InputError(name, f"must be a pair (low, high), got {bounds!r}") from None
    if not lo < hi:
        raise InputError(name, f"must be a pair (low, high) with low < high, got {bounds!r}")
    return lo, hi


def _finite(what, value):
    value = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(value)):
        raise ConvergenceError(f"linerate returned a non-finite {what}")
    return float(value) if value.ndim == 0 else value


def _rating(rating):
    if rating is None:
        raise InputError(
            "rating", "an ampacity or a temperature from current needs a ThermalRating (weather)"
        )
    if not isinstance(rating, ThermalRating):
        raise InputError("rating", f"must be a ThermalRating, got {rating!r}")
    return rating


def sag_at_current(conductor, span, dh=0.0, *, rating, current, t0, H0=None, sag0=None, length=None):
    """Sag and tension (`Conductor.change_of_state`) at the temperature ``current`` heats the
    conductor to under ``rating``'s weather.

    Returns
    -------
    ChangeOfState
        With ``temperature`` (°C) added: the conductor temperatures of ``current``.
    """
    rating = _rating(rating)
    temperature = rating.temperature(current)
    result = conductor.change_of_state(span, dh, t0=t0, H0=H0, sag0=sag0, length=length, t=temperature)
    result.temperature = temperature
    return result


def clearance_ampacity(
    conductor, span, dh=0.0, *, rating, max_sag, t0, H0=None, sag0=None, length=None, bounds=(-50.0, 300.0)
):
    """The largest steady-state current (A) whose sag stays within ``max_sag`` (m): the
    temperature ``T`` at which the bare conductor's sag reaches ``max_sag`` (brentq on
    `Conductor.change_of_state`, the sag increasing with temperature), then
    ``rating.ampacity(T)``.

    Returns
    -------
    (float, float)
        The ampacity (A) and the temperature ``T`` (°C).

    Raises
    ------
    InputError
        ``rating`` missing (``'rating'``: an ampacity needs the weather); ``max_sag`` not
        reached within ``bounds`` °C (``'max_sag'``).
    """
    from scipy.optimize import brentq

    rating = _rating(rating)
    max_sag = positive_scalar("max_sag", max_sag)
    lo, hi = _bounds("bounds", bounds)

    def excess(t):
        with _plausible.quiet():  # a trial temperature of the search, not an answer
            state = conductor.change_of_state(span, dh, t0=t0, H0=H0, sag0=sag0, length=length, t=t)
        return float(state.sag) - max_sag

    f_lo, f_hi = excess(lo), excess(hi)
    if f_lo > 0 or f_hi < 0:
        raise InputError(
            "max_sag",
            f"is not reached between {lo} and {hi} °C (sags {f_lo + max_sag:.4g} to {f_hi + max_sag:.4g} m)",
        )
    T = brentq(excess, lo, hi, xtol=1e-10, rtol=4 * np.finfo(float).eps)
    return rating.ampacity(T), float(T)
