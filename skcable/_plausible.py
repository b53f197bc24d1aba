"""Plausibility: data that solve but that a unit slip would explain, and answers no cable survives.

One place decides what is absurd, per domain, each limit with its reason and its source (the
table `LIMITS`, shown in docs/howto.md). Each check warns (`skcable.errors.PlausibilityWarning`,
naming the quantity as the public API spells it, its value and the limit) and never changes a
result, or refuses (`skcable.errors.InputError`) where no answer can be right. The library's
functions call them in one line, after their own refusals (a refused input gets one message:
the refusal).

**Arguments** (checked where they are taken):

- an axial stiffness below a hundredth of the line's own weight, ``EA < 0.01 w L``: its
  weight alone would stretch it a hundredfold (EA typed in MN, say);
- a conductor's sag larger than its span (change of state and natural frequencies, theories
  of a shallow cable; the catenary and the parabola are exact at any sag);
- a thermal strain beyond 5 %, a temperature outside a conductor's range (or one that looks
  like kelvin), an acceleration of gravity off the Earth's, a friction coefficient beyond any
  pair of engineering materials;
- a strand's imposed strain beyond 1.5 times its wires' rupture strain.

**Answers** (checked by the outermost public call only, `answer`: the trial states of an
iteration inside it are not answers):

- a strain no material of its kind survives (`STRAIN_LIMITS`: chain, wire rope, synthetic rope,
  conductor; a line of unknown material is held to the loosest);
- a tension beyond the last point of a line's strain–tension table (`beyond_table`: the law
  there extrapolates the data);
- an anchor on the seabed pulled up beyond what a drag anchor takes (`ANCHOR_UPLIFT`);
- a body above the water that keeps its buoyancy, or below the seabed.

Floats (NumPy scalars too) take a fast path, a comparison of floats; arrays one ``np.any``.
"""

from __future__ import annotations

import contextvars
import functools
import math
import warnings

import numpy as np

from skcable.errors import PlausibilityWarning

__all__ = [
    "ANCHOR_UPLIFT",
    "LIMITS",
    "MAX_STRAIN",
    "STRAIN_LIMITS",
    "anchor_uplift",
    "answer",
    "beyond_table",
    "quiet",
    "body_height",
    "conductor",
    "conductor_temperature",
    "friction",
    "gravity",
    "line_strain",
    "stiffness",
    "strand_strain",
    "thermal_argument",
]

#: The largest strain a steel or aluminium cable survives.
MAX_STRAIN = 0.05
#: The smallest plausible EA / (w·length): below it the line's weight stretches it a hundredfold.
MIN_STIFFNESS = 0.01
#: Absolute zero in °C: a temperature below it is a mistake, not a state.
ABSOLUTE_ZERO = -273.15
#: No cable material expands by more than this per kelvin (steel 1.2e-5, aluminium 2.3e-5 1/K).
MAX_ALPHA = 1e-4


def _largest(value) -> float:
    """The largest element (a float as it is); NaN is refused by the callers' own checks."""
    if isinstance(value, float):
        return value
    return float(np.max(value))


def _warn(argument: str, reason: str) -> None:
    warnings.warn(PlausibilityWarning(argument, reason), stacklevel=3)


def stiffness(EA, w, length, argument: str = "EA") -> None:
    """Warn if ``EA < MIN_STIFFNESS·w·length`` anywhere: the line's weight alone would
    stretch it a hundredfold, which no material does (rubber-like test lines, stretched by
    their length, stay quiet). The message names ``EA`` alone, so that the solves inside a
    change of state, say, repeat the same line (shown once)."""
    if isinstance(EA, float) and isinstance(w, float) and isinstance(length, float):
        if EA >= MIN_STIFFNESS * w * length:
            return
        least = EA
    else:
        EA, weight = np.asarray(EA, dtype=float), np.asarray(w) * np.asarray(length)
        low = EA < MIN_STIFFNESS * weight
        if not np.any(low):
            return
        least = float(np.min(np.broadcast_to(EA, low.shape)[low]))
    _warn(
        argument,
        f"{least:.3g} N is below a hundredth of the line's own weight w·length: its weight alone "
        "would stretch it more than a hundredfold (a steel line's EA is thousands of times "
        "w·length); is EA in N (not kN or MN)?",
    )


def conductor(span, dh, *, EA, w, sag=None, alpha=None, t=None, t0=None, T_max=None) -> None:
    """A conductor's span (change of state, natural frequencies: theories of a shallow
    cable): ``sag`` against the span, ``EA`` against the weight of the chord's length, the
    temperatures ``t``, ``t0`` against a conductor's range (`conductor_temperature`), the
    thermal strain ``alpha·(t - t0)`` and the elastic strain of the answer, ``T_max/EA``,
    against what a conductor survives (`STRAIN_LIMITS`)."""
    stiffness(EA, _largest(w), float(np.hypot(span, dh)))
    if not outermost():  # a trial state of a search (`quiet`): the states below are no answer
        return
    if t is not None:
        conductor_temperature(t, "t")
    if t0 is not None:
        conductor_temperature(t0, "t0")
    if T_max is not None:
        found = line_strain(float(np.max(np.asarray(T_max) / np.asarray(EA))), "conductor", "T_max")
        if found is not None:
            _warn(*found)
    if sag is not None and _largest(sag) > span:
        _warn(
            "sag",
            f"is {_largest(sag) / span:.3g} times the span, where a conductor sags a few per cent "
            "of it; is the sag in m (not cm or mm)?",
        )
    if alpha is not None:
        strain = abs(alpha) * float(np.max(np.abs(np.asarray(t, dtype=float) - t0)))
        if strain > MAX_STRAIN:
            _warn(
                "alpha",
                f"gives a thermal strain |alpha·(t - t0)| up to {strain:.3g}, beyond 5 % (no steel or "
                "aluminium cable survives it); is alpha in 1/K (not 1e-6/K: 23e-6, not 23)?",
            )


def thermal_argument(alpha, t, t0) -> str:
    """The argument to blame for a thermal factor ``1 + alpha (t - t0) <= 0``: a temperature
    below absolute zero, else an ``alpha`` beyond any cable material's, else ``t``."""
    if _largest(-np.asarray(t0, dtype=float)) > -ABSOLUTE_ZERO:
        return "t0"
    if _largest(-np.asarray(t, dtype=float)) > -ABSOLUTE_ZERO:
        return "t"
    return "alpha" if _largest(np.abs(alpha)) > MAX_ALPHA else "t"


def strand_strain(argument: str, strain, rupture) -> None:
    """Warn if an imposed strain exceeds 5 % and 1.5 times the largest rupture strain of the
    strand's wires (``rupture``: one value or several): no wire survives it."""
    limit = max(MAX_STRAIN, 1.5 * _largest(np.asarray(rupture, dtype=float)))
    largest = _largest(np.abs(strain)) if not isinstance(strain, float) else abs(strain)
    if largest > limit:
        _warn(
            argument,
            f"is a strain of {largest:.3g}, beyond 5 % and beyond 1.5 times the wires' rupture strain "
            f"(no wire survives it); is it a strain (0.01), not a per cent (1)?",
        )


# -- the limits, with their reasons and sources (one table: the docs show it) -----------------

#: The largest strain a material of each kind survives (-): beyond it the answer is no state of a
#: real line. A synthetic rope's is that of its linear fits (nylon's reaches 118 % at its MBL,
#: `skcable.mooring.library`); ``None``: a line of unknown material, held to the ropes'.
STRAIN_LIMITS: dict[str | None, float] = {
    "chain": 0.25,
    "wire rope": MAX_STRAIN,
    "synthetic rope": 1.5,
    "conductor": MAX_STRAIN,
    None: 0.5,
}
#: The materials a `skcable.mooring.Segment` may name (its ``material``).
MATERIALS = ("chain", "wire rope", "synthetic rope", "conductor")
#: The largest uplift angle (rad) at an anchor on the seabed: what a drag anchor takes.
ANCHOR_UPLIFT = math.radians(5.0)
#: A conductor's temperatures (°C): the coldest design ambient to the hottest rated operation.
CONDUCTOR_TEMPERATURE = (-60.0, 250.0)
#: The acceleration of gravity on the Earth's surface (m/s²), with a margin for altitude.
GRAVITY = (9.7, 9.9)
#: A friction coefficient (-) beyond any measured: over three times the largest of a dry pair of
#: engineering surfaces (about 1.5, clean metals in a vacuum aside) and five times a chain's on
#: sand or clay (0.6 to 1). Test scenes of the friction-limited regimes use up to 3.
MAX_FRICTION = 5.0

#: Each limit: (quantity, limit, reason, source). docs/howto.md prints this table.
LIMITS = (
    ("strain of a chain", "25 %",
     "offshore chain steels' minimum elongation at fracture is 17 % (R3) to 12 % (R5)",
     "Det Norske Veritas, DNV-OS-E302 Offshore Mooring Chain, 2008 (grades R3 to R5)"),
    ("strain of a wire rope or a conductor", "5 %",
     "steel and aluminium wires rupture at a few per cent (the strands' materials, docs/strand_sections.md)",
     "the wire materials of the strand seeds (Goicolea; Pino Vidal)"),
    ("strain of a line of unknown material", "50 %",
     "polyester, the common mooring rope, breaks at 10 to 20 %, nylon at 20 to 40 %",
     "S.D. Weller, L. Johanning, P. Davies, S.J. Banfield, Synthetic mooring ropes for marine renewable "
     "energy applications, Renewable Energy 83, 2015"),
    ("strain of a synthetic rope (material='synthetic rope')", "150 %",
     "a linear EA fitted to nylon's load-extension curve reaches 118 % at its MBL",
     "Orcina Ltd., OrcaFlex Manual (line type wizard, 'Rope'), skcable.mooring.library"),
    ("uplift angle at an anchor on the seabed", "5°",
     "a drag anchor is designed for a horizontal pull: no uplift in the intact condition, a few "
     "degrees in soft clay (a pile, suction or plate anchor that takes uplift: filter the warning)",
     "API RP 2SK, Design and Analysis of Stationkeeping Systems for Floating Structures, 3rd ed., 2005"),
    ("a body clear of the water", "lowest point above z = 0, or heave above V / A_WP",
     "the hydrostatics keep the buoyancy ρ g V whatever the heave: a body out of the water has none",
     "J.N. Newman, Marine Hydrodynamics, MIT Press, 1977, ch. 6 (linear hydrostatics about the waterline)"),
    ("a body or a point below the seabed", "z < -depth", "no line or body sits inside the seabed", "-"),
    ("tension beyond a strain–tension table", "its last point",
     "past it the law continues the table's end slope, which no point of the data backs (MoorDyn "
     "holds the last tension there: a rope that yields)",
     "MoorDyn-C, moordyn::interp (M. Hall et al., MoorDyn v2, NREL)"),
    ("conductor temperature", "-60 to 250 °C",
     "the coldest design ambient to the hottest rated operation (high-temperature conductors); "
     "a value near 273 + t is in kelvin",
     "CIGRE Technical Brochure 426, Guide for qualifying high temperature conductors, 2010"),
    ("acceleration of gravity g", "9.7 to 9.9 m/s²", "9.78 at the equator to 9.83 at the poles",
     "the normal gravity of the World Geodetic System 1984 (WGS 84)"),
    ("friction coefficient", "at most 5", "no dry pair of engineering surfaces exceeds about 1.5, a chain "
     "on sand or clay 1",
     "E. Rabinowicz, Friction and Wear of Materials, 2nd ed., Wiley, 1995"),
)  # fmt: skip


# -- answers: checked by the outermost public call -----------------------------------------------

_NESTED: contextvars.ContextVar[bool] = contextvars.ContextVar("skcable_plausible_nested", default=False)


def answer(check):
    """Decorator of a public function or method whose answer is checked by ``check(answer)``
    (it warns), but only where the call is the outermost such call: the solves an equilibrium,
    a design or a continuation runs inside are trial states, not answers. A context variable
    says so (threads and asyncio tasks each have their own)."""

    def wrap(function):
        @functools.wraps(function)
        def checked(*args, **kwargs):
            if _NESTED.get():
                return function(*args, **kwargs)
            token = _NESTED.set(True)
            try:
                result = function(*args, **kwargs)
            finally:
                _NESTED.reset(token)
            check(result)
            return result

        return checked

    return wrap


class quiet:
    """``with quiet():`` the `answer` checks inside are off: a library's own trial solve (a start,
    a guess, a candidate model) is no answer. Re-entrant, per thread and task."""

    __slots__ = ("_token",)

    def __enter__(self):
        self._token = _NESTED.set(True)
        return self

    def __exit__(self, *exc):
        _NESTED.reset(self._token)
        return False


def outermost() -> bool:
    """Whether no `answer`-checked call is running (a result found here is an answer)."""
    return not _NESTED.get()


def warn_all(findings) -> None:
    """Warn each ``(argument, reason)`` of ``findings`` (a `PlausibilityWarning` each)."""
    for argument, reason in findings:
        warnings.warn(PlausibilityWarning(argument, reason), stacklevel=4)


def _percent(value: float) -> str:
    return f"{100.0 * value:.3g} %"


def line_strain(strain, material=None, quantity: str = "strain", where: str = ""):
    """``(quantity, reason)`` where a line's largest ``strain`` (-; one value or an array) exceeds
    what a material of its kind survives (`STRAIN_LIMITS`; ``material`` None: unknown, the
    loosest), else None. ``where`` says which line or segment, in words."""
    limit = STRAIN_LIMITS[material]
    if not isinstance(strain, float) and np.size(strain) == 0:
        return None
    largest = _largest(strain)
    if not largest > limit:
        return None
    kind = f"{material}" if material is not None else "line of unknown material (give Segment(material=))"
    return (
        quantity,
        f"is a strain of {_percent(largest)}{where}, beyond the {_percent(limit)} a {kind} survives: no "
        "real line is in this state (too short a line, too large a load, or EA too small or in other "
        "units?)",
    )


def beyond_table(tension: float, last: float, where: str = ""):
    """``("tension", reason)`` where a line's largest ``tension`` (N) exceeds the ``last`` (N)
    point of its strain–tension table (`skcable.mooring.axial.StrainTable`), else None."""
    if not tension > last:
        return None
    return (
        "tension",
        f"is {tension:.6g} N{where}, beyond the last point of its strain–tension table ({last:.6g} "
        "N): there the law continues the table's end slope, which no point of the data backs "
        "(MoorDyn holds the last tension there); extend the table",
    )


def anchor_uplift(angle: float, where: str = ""):
    """``("uplift_angle", reason)`` where a line pulls an anchor on the seabed up at ``angle``
    (rad, above the horizontal) beyond `ANCHOR_UPLIFT`, else None."""
    if not angle > ANCHOR_UPLIFT:
        return None
    return (
        "uplift_angle",
        f"is {math.degrees(angle):.3g}°{where}: an anchor on the seabed pulled up beyond the "
        f"{math.degrees(ANCHOR_UPLIFT):.3g}° a drag anchor takes (too short a line, or a pile or suction "
        "anchor: then filter this warning)",
    )


def body_height(lowest: float, heave: float, volume: float, waterplane_area: float, where: str = ""):
    """``("position", reason)`` where a body of ``volume`` > 0 is clear of the water: a floating
    body (``waterplane_area`` > 0, its reference point on the waterline) heaved up by more than
    ``V / A_WP`` (its waterplane's restoring has lifted out more than its whole displaced volume);
    a submerged one (no waterplane) with its lowest known point above the surface (``lowest`` >
    0, m: its reference point, centre of gravity and fairleads). Else None."""
    if not volume > 0:
        return None
    clear = heave > volume / waterplane_area if waterplane_area > 0 else lowest > 0.0
    if not clear:
        return None
    return (
        "position",
        f"puts {where or 'a body'} clear of the water (lowest point z = {lowest:.4g} m, heave "
        f"{heave:.4g} m) while its buoyancy ρ g V stays: the answer keeps a buoyancy the body "
        "cannot have (a start, a load or a line that lifts it out?)",
    )


def below_seabed(z: float, depth: float | None, where: str):
    """``("position", reason)`` where ``z`` (m) lies below the seabed at ``-depth``, else None."""
    if depth is None or not z < -depth * (1.0 + 1e-9):
        return None
    return ("position", f"puts {where} at z = {z:.6g} m, below the seabed (depth {depth:g} m)")


def conductor_temperature(t, argument: str = "t") -> None:
    """Warn where a conductor's temperature ``t`` (°C; one or several) lies outside
    `CONDUCTOR_TEMPERATURE`, saying so if it looks like kelvin."""
    low, high = CONDUCTOR_TEMPERATURE
    values = np.atleast_1d(np.asarray(t, dtype=float))
    out = values[(values < low) | (values > high)]
    if not out.size:
        return
    worst = float(out[np.argmax(np.abs(out))])
    hint = ""
    if low <= worst - 273.15 <= high:
        hint = f"; is it in kelvin ({worst:g} K = {worst - 273.15:.4g} °C)?"
    _warn(
        argument,
        f"is {worst:g} °C, outside a conductor's range ({low:g} to {high:g} °C: the coldest design "
        f"ambient to the hottest rated operation){hint}",
    )


def gravity(g, argument: str = "g") -> None:
    """Warn where the acceleration of gravity ``g`` (m/s²) is not the Earth's (`GRAVITY`)."""
    low, high = GRAVITY
    if low <= float(g) <= high or float(g) == 0.0:  # 0: a weightless scene (MoorDyn's tests), not a slip
        return
    _warn(
        argument,
        f"is {float(g):g} m/s², not the Earth's ({low:g} to {high:g} m/s²); is it in mm/s² (9810) or "
        "ft/s² (32.2)? Give every input in one set of units",
    )


def friction(mu, argument: str = "friction") -> None:
    """Warn where a friction coefficient ``mu`` exceeds `MAX_FRICTION`."""
    if not isinstance(mu, float) and np.size(mu) == 0:
        return
    largest = _largest(mu)
    if not largest > MAX_FRICTION:
        return
    _warn(
        argument,
        f"is a friction coefficient of {largest:g}, beyond {MAX_FRICTION:g} (no dry pair of engineering "
        "surfaces exceeds about 1.5; a chain on clay or sand: 0.6 to 1); is it a coefficient, not an "
        "angle in degrees or a per cent?",
    )
