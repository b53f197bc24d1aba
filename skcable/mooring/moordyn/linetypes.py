r"""LINE TYPES and ROD TYPES of a MoorDyn file, and the axial law each line type's EA column means.

A line type row is ``Name Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx`` (MoorDyn v2: 10 columns,
11 with the VIV lift coefficient ``Cl``, 13 with ``Cl dF cF``) or MoorDyn v1's
``Name Diam MassDen EA BA/-zeta Can Cat Cdn Cdt`` (9 columns). The statics take the first four:
the weight in water per length :math:`w = g\,(m - \rho\,\tfrac{\pi}{4} d^2)` (``d`` the
volume-equivalent diameter) and the axial law of the EA column, as MoorDyn-C reads it
(``readLineProps``, ``read_curve``):

- a number: ``ε = T/EA`` (`skcable.mooring.axial.ConstantEA`);
- the name of a strain–tension file beside the input file: its rows after the first three
  lines, ``strain tension``, joined by straight segments as MoorDyn interpolates them
  (`skcable.mooring.axial.StrainTable` with ``interpolation="linear"``);
- ``EA_s|EA_d`` or ``EA_s|α|β`` (MoorDyn's viscoelastic ropes): the static stiffness ``EA_s``
  (a number or a file) for the statics, the dynamic one ``EA_d`` or ``α + β T`` kept with it
  (`skcable.mooring.axial.StaticDynamicRope`);
- ``SYROPE:file|α|β`` (the Syrope rope model, S. Falkenberg et al., OMAE 2017): the working curve
  MoorDyn sets from the largest mean tension ``Tmax`` of the file's ``SYROPE IC`` section
  (``Line::setWorkingCurve``: ``nEApointsWC = 30`` points from ``ε_min`` to ``ε_max``, the
  original working curve read from the file ``OWC`` names). Its tension vanishes below
  ``ε_min`` (the rope's permanent elongation), so the statics take the rope as
  ``L (1 + ε_min)`` long with the curve in strains of that length,
  ``ε' = (ε - ε_min)/(1 + ε_min)``: the same tension at every stretched length.

A rod type row is ``Name Diam Mass/m Cd Ca CdEnd CaEnd``: the statics take ``Diam`` and
``Mass/m`` (`skcable.mooring.rod`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from skcable.errors import InputError
from skcable.mooring import axial
from skcable.mooring.moordyn.text import file_error

__all__ = ["LineType", "RodType", "read_line_types", "read_rod_types"]

#: MoorDyn-C's points of a Syrope working curve (``Line.hpp``, ``nEApointsWC``).
WORKING_CURVE_POINTS = 30


@dataclass
class LineType:
    """A line type: ``name``, ``d`` (m), ``mass`` (kg/m), the ``EA`` text and its ``law`` (None for
    a Syrope rope until its working curve is set), ``rest`` (the other columns, as written), the
    ``line`` (row) it is defined on; a Syrope rope's ``syrope`` settings. Two are equal where
    their columns are."""

    name: str
    d: float
    mass: float
    EA: str
    law: object = field(compare=False)
    rest: list
    line: int = field(compare=False)
    syrope: dict | None = field(default=None, compare=False)

    def weight(self, rho: float, g: float) -> float:
        """Weight in water per length (N/m): ``g (m - rho π d²/4)``."""
        return g * (self.mass - rho * math.pi / 4.0 * self.d * self.d)


@dataclass
class RodType:
    """A rod type: ``name``, ``d`` (m), ``mass`` (kg/m), ``rest`` (the hydrodynamic columns)."""

    name: str
    d: float
    mass: float
    rest: list = field(default_factory=list)


def _curve(source, row, text, column) -> tuple[np.ndarray, np.ndarray]:
    """The ``(strain, tension)`` rows of the curve file ``text`` beside the input file, read as
    MoorDyn-C's ``read_curve`` reads them (rows after the first three lines)."""
    path = source.path.parent / text
    try:
        lines = Path(path).read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise source.error(row.line, column, f"the curve file {text!r} cannot be read: {exc}") from None
    strain, tension = [], []
    for k, line in enumerate(lines[3:], start=4):
        tokens = line.split()
        if not tokens:
            continue
        if len(tokens) < 2:
            raise file_error(path, k, column, f"a curve row is 'strain tension', got {line.strip()!r}")
        try:
            values = [float(tokens[0]), float(tokens[1])]
        except ValueError:
            raise file_error(path, k, column, f"{line.strip()!r} is not two numbers") from None
        if not all(math.isfinite(v) for v in values):
            raise file_error(path, k, column, f"{line.strip()!r} is not finite")
        strain.append(values[0])
        tension.append(values[1])
    if len(strain) < 2:
        raise file_error(path, None, column, "fewer than two curve points after the three header lines")
    return np.array(strain), np.array(tension)


def _table(source, row, text, column) -> axial.StrainTable:
    """A strain–tension file as a `StrainTable` from (0, 0), linear between its points."""
    strain, tension = _curve(source, row, text, column)
    start = f"the curve {text!r} starts at ({strain[0]:g}, {tension[0]:g})"
    if strain[0] < 0.0 or tension[0] < 0.0:
        raise source.error(row.line, column, f"{start}, not at or above (0, 0)")
    if tension[0] > 0.0:
        raise source.error(
            row.line,
            column,
            f"{start}: below it MoorDyn holds the first tension (a rope taut when slack), which no "
            "static law means; start it at (0, 0)",
        )
    if strain[0] > 0.0:
        raise source.error(
            row.line,
            column,
            f"{start}: below it MoorDyn's tension is zero (a rope slack up to that strain), which a "
            "law of the strain by the tension cannot hold; start it at (0, 0)",
        )
    try:
        return axial.StrainTable(strain, tension, interpolation="linear")
    except InputError as exc:
        raise source.error(row.line, column, f"the curve {text!r}: {exc}") from None


def _static(source, row, text, column):
    """A number (the EA, N) or a curve file's `StrainTable`."""
    try:
        float(text)
    except ValueError:
        return _table(source, row, text, column)
    return source.number(row, 3, column, text=text)


def _law(source, row, text):
    """The axial law of an EA column (module docstring): ``(law, syrope settings or None)``."""
    parts = text.split("|")
    if parts[0].upper().startswith("SYROPE:"):
        if len(parts) != 3:
            raise source.error(row.line, "EA", f"{text!r}: a Syrope EA is 'SYROPE:file|alpha|beta'")
        alpha = source.number(row, 3, "EA", text=parts[1])
        beta = source.number(row, 3, "EA", text=parts[2])
        return None, _syrope_settings(source, row, parts[0][len("SYROPE:") :], alpha, beta)
    if len(parts) > 3:
        raise source.error(row.line, "EA", f"{text!r}: an EA has at most three '|'-separated values")
    static = _static(source, row, parts[0], "EA")
    if len(parts) == 1:
        return static, None
    dynamic = [source.number(row, 3, "EA", text=p) for p in parts[1:]]
    if not isinstance(static, float):  # a curve with a dynamic stiffness: the statics take the curve
        return static, None
    try:
        return axial.StaticDynamicRope(static, dynamic[0], dynamic[1] if len(dynamic) > 1 else 0.0), None
    except InputError as exc:
        raise source.error(row.line, "EA", f"{text!r}: {exc}") from None


def _syrope_settings(source, row, name, alpha, beta) -> dict:
    """The Syrope settings file ``name`` beside the input (``value key`` rows: ``OWC``, ``WCType``,
    ``k1``, ``k2``) and its original working curve."""
    path = source.path.parent / name
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise source.error(row.line, "EA", f"the Syrope file {name!r} cannot be read: {exc}") from None
    settings: dict = {"alpha": alpha, "beta": beta}
    for line in lines:
        tokens = line.split()
        if len(tokens) >= 2:
            settings[tokens[1].lower()] = tokens[0]
    missing = [k for k in ("owc", "wctype", "k1", "k2") if k not in settings]
    if missing:
        raise source.error(row.line, "EA", f"the Syrope file {name!r} lacks {', '.join(missing)}")
    kind = settings["wctype"].lower()
    if kind not in ("linear", "quadratic", "exp"):
        raise source.error(
            row.line,
            "EA",
            f"the Syrope file {name!r}: WCType {settings['wctype']!r} is not LINEAR, QUADRATIC or EXP",
        )
    settings["wctype"] = kind
    for key in ("k1", "k2"):
        try:
            settings[key] = float(settings[key])
        except ValueError:
            raise source.error(
                row.line, "EA", f"the Syrope file {name!r}: {key} {settings[key]!r} is not a number"
            ) from None
    strain, tension = _curve(_Beside(path), row, settings["owc"], "EA")
    settings["owc"] = (strain, tension)
    return settings


class _Beside:
    """The location of a file for `_curve` (its ``path``, its ``error``)."""

    def __init__(self, path):
        self.path = Path(path)
        self.error = lambda line, column, reason: file_error(self.path, line, column, reason)


def working_curve(settings, Tmax: float, length: float, source, row):
    """``(length, law)`` of a Syrope rope of unstretched ``length`` (m) whose largest mean tension
    was ``Tmax`` (N): MoorDyn-C's working curve (module docstring), its tension zero below
    ``ε_min``, as a rope ``length (1 + ε_min)`` long with a `StrainTable` from (0, 0)."""
    strain, tension = settings["owc"]
    if not tension[0] <= Tmax <= tension[-1]:
        raise source.error(
            row.line,
            "Tmax0",
            f"{Tmax:g} N lies outside the original working curve's [{tension[0]:g}, {tension[-1]:g}] N",
        )
    k1, k2, kind = settings["k1"], settings["k2"], settings["wctype"]
    eps_max = float(np.interp(Tmax, tension, strain))
    eps_min = strain[0] + k1 * (eps_max - strain[0])
    if kind == "linear" and k1 >= 1.0:  # k1 the working curve's slope (N)
        eps_min = eps_max - Tmax / k1
    xi = np.linspace(0.0, 1.0, WORKING_CURVE_POINTS)
    if kind == "linear":
        T = Tmax * xi
    elif kind == "quadratic":
        T = Tmax * xi * (k2 * xi + (1.0 - k2))
    else:
        T = Tmax * (1.0 - np.exp(k2 * xi)) / (1.0 - np.exp(k2))
    eps = eps_min + (eps_max - eps_min) * xi
    stretched = (eps - eps_min) / (1.0 + eps_min)
    try:
        law = axial.StrainTable(stretched, T, interpolation="linear")
    except InputError as exc:
        raise source.error(row.line, "EA", f"the Syrope working curve at Tmax = {Tmax:g} N: {exc}") from None
    return length * (1.0 + eps_min), law


def read_line_types(source, section) -> dict:
    """``{name: LineType}`` of the LINE TYPES ``section`` (module docstring)."""
    types: dict = {}
    for row in section.rows:
        source.columns(row, (9, 10, 11, 13), "LINE TYPES")
        name = source.word(row, 0, "LineType")
        if name in types:
            raise source.error(
                row.line, name, f"line type {name!r} is defined twice (also on line {types[name].line})"
            )
        d = source.number(row, 1, "Diam")
        mass = source.number(row, 2, "Mass/m")
        if d <= 0:
            raise source.error(row.line, "Diam", f"{row.tokens[1]!r}: the diameter must be > 0")
        EA = source.word(row, 3, "EA")
        law, syrope = _law(source, row, EA)
        types[name] = LineType(name, d, mass, EA, law, list(row.tokens[4:]), row.line, syrope)
    return types


def read_rod_types(source, section) -> dict:
    """``{name: RodType}`` of the ROD TYPES ``section``."""
    types: dict = {}
    rows = () if section is None else section.rows
    for row in rows:
        source.columns(row, (7,), "ROD TYPES")
        name = source.word(row, 0, "RodType")
        d, mass = source.number(row, 1, "Diam"), source.number(row, 2, "Mass/m")
        if d <= 0 or mass < 0:
            raise source.error(row.line, name, "a rod type needs Diam > 0 and Mass/m >= 0")
        types[name] = RodType(name, d, mass, list(row.tokens[3:]))
    return types
