"""What one case computes: the model functions a study may name, and one case evaluated.

A *model function* takes a case's parameters as keyword arguments and returns a dict of
scalar outputs. `evaluate` runs one case and never raises: a case that fails (bad
parameters, no convergence, any exception) becomes a record with ``status = "failed"`` and
the first line of its error, so that one case cannot stop a study.

Examples
--------
>>> record = evaluate(cable_solve, {"span": 100.0, "w": 10.0, "sag": 5.0})
>>> record["status"], round(record["outputs"]["H"], 1)
('ok', 2508.3)
>>> evaluate(cable_solve, {"span": 100.0, "w": 10.0, "sag": -1.0})["error"]
'InputError: sag: must be > 0, got -1.0'
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from skcable._checks import whole
from skcable.errors import InputError

__all__ = ["MODELS", "cable_solve", "evaluate", "failure", "first_line", "strand_capacity"]


def strand_capacity(
    preset: str = "steel-9.5",
    damage: int = 0,
    slip: str = "none",
    mu: float = 0.5,
    length: float = 1.0,
    n_elements: int | None = None,
    n_steps: int | None = None,
    damage_load: str = "eccentricity",
) -> dict:
    """Capacity curve of a preset strand, as the scalars a study tabulates.

    Builds ``strand.StrandModel(strand.preset(preset).damaged(damage), length, ...)`` and
    loads it to rupture (`skcable.strand.StrandModel.capacity_curve`), after S. Pino Vidal,
    "Rigidez a flexión en cables: análisis numérico", Universidad de Chile, 2021.

    Parameters
    ----------
    preset : str
        Name of a strand preset (`skcable.strand.preset`).
    damage : int
        Broken wires (>= 0; 0 is the intact strand).
    slip : str
        Slip model of the strand element (``"none"`` for stick, ``"element"``, ``"axis"``).
    mu : float
        Friction coefficient between wires (-).
    length : float
        Strand length between the clamps (m).
    n_elements : int, optional
        Beam elements along the strand (default: the model's).
    n_steps : int, optional
        Load steps to rupture, >= 4 (default: the model's).
    damage_load : str
        How the damage loads the section (``"eccentricity"`` or ``"sinusoidal"``).

    Returns
    -------
    dict
        ``K_Leq`` (N), ``D_r`` (-), ``toughness`` (N), ``rupture_strain`` (-),
        ``rupture_force`` (N), ``peak_curvature`` (1/m), ``slip_onset_strain`` (-, the
        strain of the first step with slip; None when the strand never slips) and
        ``max_slip_fraction`` (-).

    Raises
    ------
    InputError
        A bad argument (``damage``, ``n_elements`` or ``n_steps`` not an integer in range,
        an unknown preset, ...).
    ConvergenceError
        The load stepping did not converge.
    """
    from skcable import strand

    damage = whole("damage", damage, 0)
    n_elements = None if n_elements is None else whole("n_elements", n_elements)
    n_steps = None if n_steps is None else whole("n_steps", n_steps, 4)  # 0 would mean "the default"
    s = strand.preset(preset)
    s = s.damaged(damage) if damage else s
    model = strand.StrandModel(s, length, slip=slip, mu=mu, n_elements=n_elements, damage_load=damage_load)
    curve = model.capacity_curve(n_steps=n_steps)
    slipping = np.flatnonzero(curve.slip_fraction > 0)
    return {
        "K_Leq": curve.K_Leq,
        "D_r": curve.D_r,
        "toughness": curve.toughness,
        "rupture_strain": float(curve.strain[-1]),
        "rupture_force": float(curve.force[-1]),
        "peak_curvature": float(max(np.max(np.abs(st.curvature)) for st in curve.steps)),
        "slip_onset_strain": float(curve.strain[slipping[0]]) if slipping.size else None,
        "max_slip_fraction": float(np.max(curve.slip_fraction)),
    }


def cable_solve(
    span: float,
    w: float,
    dh: float = 0.0,
    EA: float | None = None,
    length: float | None = None,
    sag: float | None = None,
    H: float | None = None,
    low: float | None = None,
    T_max: float | None = None,
) -> dict:
    """A suspended cable in closed form, as the scalars a study tabulates.

    The inextensible catenary (`skcable.cable.catenary`) given one of ``length, sag, H,
    low, T_max``; with ``EA``, H. M. Irvine's elastic catenary (`skcable.cable.elastic_catenary`,
    "Cable Structures", 1981) given ``length``.

    Parameters
    ----------
    span : float
        Horizontal distance between the supports (m).
    w : float
        Weight per unit length (N/m).
    dh : float
        Height of the right support above the left one (m).
    EA : float, optional
        Axial stiffness (N); needs ``length`` and nothing else.
    length, sag, H, low, T_max : float, optional
        The one constraint: unstretched length (m), sag (m), horizontal tension (N), height
        of the lowest point (m) or largest tension (N).

    Returns
    -------
    dict
        ``H`` (N), ``T_max`` (N), ``length`` (m), ``sag`` (m) and ``residual`` (the
        equilibrium residual of the solution, -).

    Raises
    ------
    InputError
        A bad argument, or ``EA`` with a constraint other than ``length``.
    """
    from skcable import cable

    given = {"length": length, "sag": sag, "H": H, "low": low, "T_max": T_max}
    constraint = {k: v for k, v in given.items() if v is not None}
    if EA is None:
        sol = cable.catenary(span, dh, w, **constraint)
    else:
        if set(constraint) != {"length"}:
            raise InputError(
                "EA", f"the elastic catenary is solved for a given length only, got {constraint}"
            )
        sol = cable.elastic_catenary(span, dh, w, EA, length=length)
    return {
        "H": float(sol.H),
        "T_max": float(sol.T_max),
        "length": float(sol.length),
        "sag": float(sol.sag),
        "residual": sol.residual(),
    }


# The models are published as skcable.study.<name>: their qualified name keys the cache.
strand_capacity.__module__ = cable_solve.__module__ = "skcable.study"

#: Model functions a study file may name (``model = "strand_capacity"``).
MODELS: dict[str, Callable[..., dict]] = {"strand_capacity": strand_capacity, "cable_solve": cable_solve}


def _plain(name: str, value):
    """An output as a JSON scalar (numpy scalars unwrapped), raising for anything else."""
    if isinstance(value, np.generic):
        value = value.item()
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    raise TypeError(f"output {name!r} must be a number, a string, a bool or None, got {type(value).__name__}")


def first_line(exc: BaseException) -> str:
    """``"<ExceptionType>: <message>"``, cut at the first line break (how a table records an error)."""
    return (f"{type(exc).__name__}: {exc}".splitlines() or [type(exc).__name__])[0]


def failure(error: str, time_s: float = 0.0) -> dict:
    """The record of a case that failed with ``error`` after ``time_s`` s (the shape `evaluate` returns)."""
    return {"outputs": {}, "status": "failed", "error": error, "time_s": time_s}


def evaluate(model: Callable[..., dict], case: dict) -> dict:
    """Run ``model(**case)`` once; never raises.

    Returns
    -------
    dict
        ``outputs`` (the model's dict, numpy scalars unwrapped), ``status`` (``"ok"``, or
        ``"failed"`` when the model raised or returned something else than scalars: number,
        string, bool or None), ``error`` (the error's first line, ``""`` when ok) and
        ``time_s`` (wall seconds).
    """
    start = time.perf_counter()
    try:
        outputs = {str(k): _plain(str(k), v) for k, v in dict(model(**case)).items()}
    except Exception as exc:  # noqa: BLE001 - one case's failure must not stop the study
        return failure(first_line(exc), time.perf_counter() - start)
    return {"outputs": outputs, "status": "ok", "error": "", "time_s": time.perf_counter() - start}
