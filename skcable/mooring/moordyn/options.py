r"""The OPTIONS of a MoorDyn file: those the statics use, those they leave aside (and why).

Each row is ``value name`` (MoorDyn reads the name case-blind). The statics use:

- ``WtrDpth`` (or MoorPy's and MoorDyn-F's ``depth``): the water depth (m); ``DEFAULT`` (an
  OpenFAST file taking it from SeaState) counts as none. MoorDyn-C starts from 0 and makes the
  depth at least as deep as the lowest point (`water_depth`);
- ``g`` (or ``gravity``): gravity (m/s²), 9.80665 by default;
- ``rho`` (or ``WtrDnsty``, ``rhoW``): the water density (kg/m³), 1025 by default.

Every other option MoorDyn-C or MoorDyn-F knows concerns the dynamics, the initial-condition
generator, water kinematics or the outputs: each is kept (for writing back) and reported in the
model's ``ignored`` with the reason the statics leave it aside. An option MoorDyn does not know
warns (MoorDyn warns and goes on) and is reported the same way.
"""

from __future__ import annotations

import warnings

__all__ = ["MoorDynOptions", "read_options", "water_depth"]

_DYNAMICS = "a setting of MoorDyn's time integration"
_IC = "a setting of MoorDyn's initial-condition generator (the statics solve the equilibrium directly)"
_OUTPUT = "an output setting"
_WATER = (
    "water kinematics (waves, currents) read from files MoorDyn finds beside its driver; the "
    "statics solve the system in still water"
)

#: Options that MoorDyn-C (MoorDyn2.cpp, ``readOptionsLine``) or MoorDyn-F know and the statics
#: leave aside, lower case, with the reason.
IGNORED = {
    **dict.fromkeys(("dtm", "dt", "cfl", "tscheme"), _DYNAMICS),
    **dict.fromkeys(
        ("kbot", "kb"), "the seabed's contact stiffness of the dynamics (the statics' seabed is rigid)"
    ),
    **dict.fromkeys(("cbot", "cb"), "the seabed's damping (dynamics)"),
    **dict.fromkeys(
        (
            "dtic",
            "icdt",
            "tmaxic",
            "ictmax",
            "cdscaleic",
            "icdfac",
            "threshic",
            "icthresh",
            "icgendynamic",
            "gendynamicic",
        ),
        _IC,
    ),
    **dict.fromkeys(
        ("fileic", "icfile"),
        "an initial-conditions file of the dynamics (the statics start from the file's positions)",
    ),
    **dict.fromkeys(
        ("wavekin", "dtwave", "wavekin_rampt", "currents", "unifycurrentgrid", "waterkin"), _WATER
    ),
    "seafloorfile": "a 3-D seafloor file: the statics take the flat seabed at the water depth",
    "frictioncoefficient": (
        "seabed friction, whose static configuration depends on the history the dynamics follow: "
        "the statics lie without friction (as MoorPy's System)"
    ),
    **dict.fromkeys(
        ("writelog", "writeunits", "dtout", "disableoutput", "disableouttime", "outswitch", "echo"), _OUTPUT
    ),
    **dict.fromkeys(
        ("inertialf", "inertialf_rampt"), "inertial forces of a moving reference frame (dynamics)"
    ),
    **dict.fromkeys(
        ("fricdamp", "statdynfricscale", "mu_kt", "mu_ka", "mc", "cv"), "seabed friction (dynamics)"
    ),
}
#: The options the statics use, lower case: ``{name: what}``.
USED = {
    "wtrdpth": "depth",
    "depth": "depth",
    "g": "g",
    "gravity": "g",
    "rho": "rho",
    "wtrdnsty": "rho",
    "rhow": "rho",
}


class MoorDynOptions(dict):
    """``{name as written: value text}`` of the OPTIONS section, with ``depth``, ``g`` and
    ``rho`` (the statics' values, None where the file gives none) and ``ignored``
    (``{name: reason}``)."""

    depth: float | None = None
    g: float = 9.80665
    rho: float = 1025.0

    def __init__(self):
        super().__init__()
        self.ignored: dict = {}


def read_options(source, section) -> MoorDynOptions:
    """The options of the OPTIONS ``section`` of the `InputFile` ``source`` (module docstring);
    a value the statics use that is no number is refused naming the option, as is a negative
    ``g`` or ``rho``."""
    options = MoorDynOptions()
    rows = () if section is None else section.rows
    for row in rows:
        if len(row.tokens) < 2:
            raise source.error(
                row.line, "OPTIONS", f"an option is 'value name', got {' '.join(row.tokens)!r}"
            )
        name = source.word(row, 1, "OPTIONS")
        value = source.word(row, 0, name)
        options[name] = value
        low = name.lower()
        if low in USED:
            what = USED[low]
            if what == "depth" and value.lower() == "default":
                options.ignored[name] = "DEFAULT: the depth is taken from the points, as MoorDyn-C takes it"
                continue
            number = source.number(row, 0, name)
            if what in ("g", "rho") and number < 0:
                raise source.error(row.line, name, f"{value!r} is negative")
            setattr(options, what, number)
        elif low in IGNORED:
            options.ignored[name] = IGNORED[low]
        else:
            reason = f"line {row.line}: an option MoorDyn does not know (it warns and goes on): not used"
            options.ignored[name] = reason
            warnings.warn(f"{source.path.name}, {reason}: {name!r}", UserWarning, stacklevel=4)
    return options


def water_depth(given, lowest) -> float | None:
    """MoorDyn-C's water depth (m): the option's (0 when absent), made at least as deep as the
    lowest point (``lowest``, the smallest z of the points, m); None where that leaves no water
    below z = 0."""
    depth = 0.0 if given is None else float(given)
    depth = max(depth, -float(lowest))
    return depth if depth > 0 else None
