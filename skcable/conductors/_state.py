r"""Thermal strain in the elastic catenary and the change-of-state equation.

Thermal strain
--------------
A material element of unstressed length :math:`ds_0` at the reference
temperature :math:`t_0` has, at temperature :math:`t` and tension :math:`T`,
the length :math:`ds = ds_0\,(1 + \alpha(t - t_0) + T/EA)`; the weight
``w`` is per unstressed *reference* length. With :math:`k = 1 + \alpha(t-t_0)`
this is exactly

.. math:: ds = (k\,ds_0)\left(1 + \frac{T}{EA\,k}\right),

Irvine's elastic catenary (H.M. Irvine, "Cable Structures", MIT Press,
1981, §2.2) of unstressed length :math:`k L_0`, weight :math:`w/k` per unit of
that length and axial stiffness :math:`EA\,k`. `thermal_catenary` solves it
that way with `elastic_catenary`.

Change of state
---------------
The unstressed reference length :math:`L_0` is found from a reference state
(load ``w0``, temperature ``t0``, horizontal tension ``H0`` or sag ``sag0``)
and kept for every other state (vertical load ``w`` including ice,
temperature ``t``, transverse wind ``wind``). A uniform load of fixed
direction keeps the cable in the plane through the chord and the load
direction; the exact model solves the thermal elastic catenary in that plane
under the resultant :math:`q = \sqrt{w^2 + \text{wind}^2}`. The
``"parabola"`` model is the classical cubic change-of-state equation (e.g.
CIGRE TB 324, "Sag-tension calculation methods for overhead lines", 2007;
F. Kiessling et al., "Overhead Power Lines", Springer, 2003), written in the
same plane for a chord inclined at :math:`\psi` (span :math:`a` in the plane):

.. math::
    H^2\left[H - H_0\frac{\cos\psi}{\cos\psi_0} + EA\cos\psi\,\alpha(t - t_0)
    + \frac{EA\cos\psi\,q_0^2 a_0^2\cos^2\psi_0}{24 H_0^2}\right]
    = \frac{EA\cos\psi\, q^2 a^2 \cos^2\psi}{24},

which for a level span is the textbook
:math:`H^2[H - H_0 + EA\,\alpha\Delta t + EA\,w_0^2a^2/(24H_0^2)] = EA\,w^2a^2/24`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, nonnegative, positive, real, scalar
from skcable._show import Shown, attributes, counted, quantity
from skcable.cable._elastic import elastic_catenary_unchecked as elastic_catenary
from skcable.cable._extreme import blame_extreme
from skcable.conductors._choice import check_model, choose
from skcable.conductors._inputs import load_plane, normal, renamed, thermal_factor
from skcable.conductors._lines import check_finite, line_change_of_state
from skcable.conductors._parabola import parabola_states
from skcable.conductors._reference import reference_length
from skcable.errors import InputError

__all__ = ["ThermalCatenary", "thermal_catenary", "ChangeOfState", "change_of_state", "sag_tension_table"]


class ThermalCatenary(Shown):
    """Solution of `thermal_catenary`.

    ``H, V_A, V_B, T_A, T_B, sag`` and ``y(x), T(x), slope(x)`` of the loaded
    cable; ``length`` the unstressed length at the reference temperature,
    ``stretched_length`` the length under load at temperature ``t``;
    ``k = 1 + alpha (t - t0)``; ``curve`` the equivalent `ElasticCatenary`
    (unstressed length ``k length``, weight ``w/k``, stiffness ``EA k``).
    """

    def __init__(self, curve, w, EA, length, k):
        self.curve, self.w, self.EA, self.length, self.k = curve, w, EA, length, k
        self.span, self.dh = curve.span, curve.dh
        self.H, self.V_A, self.V_B = curve.H, curve.V_A, curve.V_B
        self.T_A, self.T_B = curve.T_A, curve.T_B
        self.sag, self.stretched_length = curve.sag, curve.stretched_length

    def y(self, x):
        """Height above A at abscissa ``x``."""
        return self.curve.y(x)

    def T(self, x):
        """Tension at abscissa ``x``."""
        return self.curve.T(x)

    def slope(self, x):
        """dy/dx at ``x``."""
        return self.curve.slope(x)

    def residual(self):
        """Largest relative residual of the equivalent elastic catenary."""
        return self.curve.residual()

    def __repr__(self):
        forces = dict.fromkeys(("H", "V_A", "V_B", "T_A", "T_B"), "N")
        shown = attributes(
            self, {"k": "", **forces, **dict.fromkeys(("sag", "length", "stretched_length"), "m")}
        )
        where = f"{counted(np.shape(self.H), 'scene')}: " if np.ndim(self.H) else ""
        return f"ThermalCatenary({where}{shown})"


def thermal_catenary(span, dh, w, EA, *, length, alpha, t, t0=0.0):
    """Elastic catenary with thermal strain, A = (0, 0) to B = (span, dh) (module text).

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance (> 0) and height of B above A.
    w : float or array_like
        Weight per unit unstressed length at ``t0`` (> 0).
    EA : float or array_like
        Axial stiffness (> 0).
    length : float or array_like
        Unstressed length at ``t0`` (> 0).
    alpha : float or array_like
        Coefficient of thermal expansion (1/K), finite.
    t, t0 : float or array_like
        Temperature and reference temperature; ``1 + alpha (t - t0)`` must be > 0.

    Raises
    ------
    InputError, ConvergenceError
        As `elastic_catenary`; ``t`` when the thermal factor is not positive.
    """
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    EA = positive("EA", EA)
    length = positive("length", length)
    alpha, t, t0 = real("alpha", alpha), real("t", t), real("t0", t0)
    broadcast(span=span, dh=dh, w=w, EA=EA, length=length, alpha=alpha, t=t, t0=t0)
    k = thermal_factor(alpha, t, t0)
    curve = elastic_catenary(span, dh, w / k, EA * k, length=length * k)
    return ThermalCatenary(curve, w, EA, length, k)


class ChangeOfState(Shown):
    """Result of `change_of_state`; arrays over the broadcast states.

    Attributes
    ----------
    H : tension component along the span (horizontal, in the span's vertical
        plane direction x), constant along the cable.
    H_plane : tension component perpendicular to the resultant load in the
        plane of the cable (equal to ``H`` without wind or for a level span).
    sag : largest distance chord–cable in the plane of the resultant load,
        measured along the load (the vertical sag without wind).
    T_max : largest tension (at the higher end of the plane).
    length : loaded length at temperature ``t``.
    blowout : angle of the resultant load (and, for a level span, of the
        cable's plane) from the vertical, ``atan(wind / w)`` (rad).
    L0 : unstressed length at the reference temperature.
    H0, sag0 : the reference state's horizontal tension and sag (model's).
    w, t, wind : the states, as given.
    model : the model of the results: ``"catenary"``, ``"parabola"``, or ``"mixed"`` when
        ``model="auto"`` took the parabola for some spans and the exact catenary for others.
    models : the model of each span (a string for one span, else an array of them).
    error_estimate : the estimated relative error of each span's results (the largest over its
        states of H, sag, T_max, length and the reference's H0 or sag0): the parabola's estimate
        where it was taken (`skcable.conductors._parabola`), 0 for the exact model.
    reason : why this model, in words (``model="auto"``: the estimates against ``rtol``).
    rtol : the tolerance of ``model="auto"`` (None for the other models).
    """

    # set by ``__init__`` from its keywords: floats for one span and one state, else arrays
    H: Any
    H_plane: Any
    sag: Any
    T_max: Any
    length: Any
    blowout: Any
    L0: Any
    H0: Any
    sag0: Any
    w: Any
    t: Any
    wind: Any
    model: str
    models: Any
    error_estimate: Any
    reason: str
    rtol: Any
    T_max_pct_rts: Any  # set by `skcable.conductors.Conductor.change_of_state` when the RTS is known

    def __init__(self, **values):
        self.__dict__.update(values)

    def __repr__(self):
        spans = np.shape(self.L0)
        where = (counted(spans, "span") + " × " if spans else "") + counted(
            np.shape(self.H)[len(spans) :], "state"
        )
        shown = [quantity("t", self.t, "°C"), quantity("w", self.w, "N/m")]
        if np.any(self.wind):
            shown += [quantity("wind", self.wind, "N/m"), quantity("blowout", self.blowout, "rad")]
        shown += [
            quantity("H", self.H, "N"),
            quantity("sag", self.sag, "m"),
            quantity("T_max", self.T_max, "N"),
            quantity("L0", self.L0, "m"),
        ]
        return f"ChangeOfState({self.model}, {where}: {', '.join(shown)})"


def change_of_state(
    span, dh, *, EA, alpha, w0, t0, H0=None, sag0=None, w, t, wind=0.0, model="catenary", rtol=None
) -> ChangeOfState:
    """Sag and tension of a cable in other states at its unstressed length.

    One span, or a whole line of spans at once: with ``span``, ``dh`` arrays (of one shape,
    e.g. ``(n,)``) and states of shape ``(m,)``, every result has shape ``(n, m)`` (the spans'
    shape followed by the states'), computed by one vectorised solve and residual-checked
    element by element (`skcable.conductors`, the line path).

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance between the supports (> 0) and height of B above A, of one span
        or broadcast together over the spans of a line.
    EA : float
        Axial stiffness (> 0).
    alpha : float
        Coefficient of thermal expansion (1/K), finite.
    w0, t0 : float
        Reference state: weight per length (> 0, no wind) and temperature.
    H0, sag0 : float or array_like
        Exactly one: the horizontal tension or the sag (vertical distance
        chord–cable, largest) of the reference state; one number, or one per span.
    w, t, wind : float or array_like
        The states: vertical load per unstressed reference length including
        ice (> 0), temperature, transverse (horizontal, perpendicular to the
        span) wind load per the same length (>= 0); broadcast together.
    model : {"catenary", "parabola", "auto"}
        ``"catenary"``: the elastic catenary with thermal strain (exact, see
        `thermal_catenary`), in the plane of the resultant load.
        ``"parabola"``: the classical cubic change-of-state equation (CIGRE TB
        324, 2007; Kiessling et al., "Overhead Power Lines", 2003), valid for
        small sag/span, with the same plane.
        ``"auto"``: for each span, the parabola where its estimated relative error (in H, the
        sag, T_max, the length and the reference's H0 or sag0, over the span's states) is at
        most ``rtol``, else the exact catenary (`skcable.conductors._choice`).
    rtol : float, optional
        The tolerance of ``model="auto"`` (default 1e-3); refused with the other models.

    Returns
    -------
    ChangeOfState
        ``H, H_plane, sag, T_max, length, blowout`` over the spans × states; ``L0``,
        ``H0``, ``sag0``, ``models`` and ``error_estimate`` per span (floats for one span);
        ``model`` and ``reason``: the model taken and why.

    Raises
    ------
    InputError
        A non-physical argument, both or neither of ``H0``, ``sag0``, an
        unknown model, a thermal strain ``alpha (t - t0)`` outside (-1, 1). Where an
        argument lies beyond any physical magnitude (beyond 1e±100), a refusal it causes in
        the solvers names it (`skcable.conductors` checks, `blame_extreme`).
    ConvergenceError
        A solver stopped (with its history).
    """
    model, rtol = check_model(model, rtol)
    span, dh = normal("span", span), real("dh", dh)
    lead = broadcast(span=span, dh=dh)
    EA = normal("EA", scalar("EA", EA))
    alpha, t0 = scalar("alpha", alpha), scalar("t0", t0)
    w0 = normal("w0", scalar("w0", w0))
    H0, sag0 = _reference_input(H0, sag0, lead)
    w, t, wind = normal("w", w), real("t", t), nonnegative("wind", wind)
    shape = broadcast(w=w, t=t, wind=wind)
    w, t, wind = (np.array(np.broadcast_to(v, shape), dtype=float) for v in (w, t, wind))
    given = dict(span=span, dh=dh, EA=EA, alpha=alpha, w0=w0, t0=t0, H0=H0, sag0=sag0, w=w, t=t, wind=wind)
    with blame_extreme(**given):  # a refusal deep inside names an outsized argument, if one is
        return _states(span, dh, EA, alpha, w0, t0, H0, sag0, w, t, wind, shape, lead, (model, rtol))


def _states(span, dh, EA, alpha, w0, t0, H0, sag0, w, t, wind, shape, lead, model) -> ChangeOfState:
    """`change_of_state` on checked arguments (the states' arrays of ``shape``, the spans' ``lead``;
    ``model``: the model and its ``rtol``)."""
    k = thermal_factor(alpha, t, t0)
    model, rtol = model
    if lead:
        ref = (H0 if H0 is not None else sag0, "H0" if H0 is not None else "sag0")
        out, choice = line_change_of_state(span, dh, EA, alpha, w0, t0, ref, w, t, wind, k, model, rtol)
        out.update(w=w, t=t, wind=wind, model=choice.model, reason=choice.reason, rtol=rtol)
        return ChangeOfState(**out)
    par = choice = None
    if model != "catenary":
        one = np.array([float(span)]), np.array([float(dh)])
        H0_, sag0_ = (None if v is None else np.array([float(v)]) for v in (H0, sag0))
        par = parabola_states(*one, EA, alpha, w0, t0, H0_, sag0_, w.ravel(), t.ravel(), wind.ravel())
    choice = choose(model, rtol, None if par is None else par.error, 1)
    q, span_p, dh_p = load_plane(span, dh, w, wind)
    if par is not None and choice.parabola[0]:
        L0, H0_out, sag0_out = par.L0[0], par.H0[0], par.sag0[0]
        H_plane, sag, T_max, length = (
            getattr(par, key).reshape(shape) for key in ("H_plane", "sag", "T_max", "length")
        )
    else:
        ref_name = "H0" if sag0 is None else "sag0"
        with renamed({"H": "H0", "sag": "sag0", "w": "w0", "length": ref_name}):
            L0 = reference_length(span, dh, w0, EA, H0, sag0)
            ref = elastic_catenary(span, dh, w0, EA, length=L0)
        H0_out, sag0_out = ref.H, ref.sag
        with renamed({"H": "w", "length": ref_name}):
            sol = elastic_catenary(span_p, dh_p, q / k, EA * k, length=L0 * k)
        H_plane, sag = sol.H, sol.sag
        T_max, length = np.maximum(sol.T_A, sol.T_B), sol.stretched_length
    H = H_plane * span / span_p
    blowout = np.arctan2(wind, w)
    out = dict(H=H, H_plane=H_plane, sag=sag, T_max=T_max, length=length, blowout=blowout)
    check_finite(out)
    out.update(w=w, t=t, wind=wind)
    if shape == ():
        out = {key: float(value) for key, value in out.items()}
    _plausible.conductor(
        span, dh, EA=EA, w=max(w0, float(np.max(w))), sag=sag0, alpha=alpha, t=t, t0=t0, T_max=out["T_max"]
    )
    return ChangeOfState(
        **out, L0=float(L0), H0=float(H0_out), sag0=float(sag0_out), model=choice.model,
        models=str(choice.models()[0]), error_estimate=float(choice.error_estimate[0]),
        reason=choice.reason, rtol=rtol,
    )  # fmt: skip


def _reference_input(H0, sag0, lead):
    """Exactly one of ``H0``, ``sag0``: a normal positive number, or one per span."""
    if (H0 is None) == (sag0 is None):
        got = "both" if H0 is not None else "neither"
        raise InputError("H0", f"give exactly one of H0, sag0 for the reference state; got {got}")
    name, value = ("H0", H0) if H0 is not None else ("sag0", sag0)
    value = normal(name, value if lead else scalar(name, value))
    if lead and np.ndim(value):
        try:
            fits = np.broadcast_shapes(np.shape(value), lead) == lead
        except ValueError:
            fits = False
        if not fits:
            raise InputError(name, f"must be one number or one per span ({lead}), got {np.shape(value)}")
    return (value, None) if name == "H0" else (None, value)


def sag_tension_table(
    span, dh, *, EA, alpha, w0, t0, H0=None, sag0=None, temperatures, load_cases, model="catenary", rtol=None
):
    """Sag-tension table: a pandas DataFrame over load case × temperature.

    ``load_cases`` maps a case name to ``(w, wind)`` (vertical load per length
    including ice, transverse wind per length); ``temperatures`` is a
    sequence. The other arguments (``model``, ``rtol`` too) are those of `change_of_state`. The index
    is ``(case, t)``; the columns ``w, wind, H, sag, T_max, length,
    blowout_deg``. For a line (``span`` a 1-D array, ``dh`` and ``H0`` or ``sag0``
    one number or one per span) the index is ``(span_no, case, t)`` and the columns
    start with the span's ``span, dh``: one vectorised solve for the whole table. The
    frame's ``attrs`` carry ``model``, ``reason`` and ``rtol`` (which model, and why).
    """
    import pandas as pd

    if not isinstance(load_cases, dict) or not load_cases:
        raise InputError("load_cases", "must be a non-empty dict name -> (w, wind)")
    temps = np.atleast_1d(real("temperatures", temperatures))
    if temps.ndim != 1:
        raise InputError("temperatures", f"must be a 1-D sequence, got shape {temps.shape}")
    names = list(load_cases)
    try:
        loads = np.array([[float(v) for v in load_cases[n]] for n in names], dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError("load_cases", f"each value must be a pair (w, wind) of numbers ({exc})") from None
    if loads.shape != (len(names), 2):
        raise InputError("load_cases", "each value must be a pair (w, wind)")
    with renamed({"t": "temperatures", "w": "load_cases", "wind": "load_cases"}):
        res = change_of_state(
            span, dh, EA=EA, alpha=alpha, w0=w0, t0=t0, H0=H0, sag0=sag0,
            w=loads[:, :1], t=temps[None, :], wind=loads[:, 1:], model=model, rtol=rtol,
        )  # fmt: skip
    n_states = len(names) * temps.size
    data = {
        "w": np.repeat(loads[:, 0], temps.size),
        "wind": np.repeat(loads[:, 1], temps.size),
        "H": np.reshape(res.H, (-1, n_states)),
        "sag": np.reshape(res.sag, (-1, n_states)),
        "T_max": np.reshape(res.T_max, (-1, n_states)),
        "length": np.reshape(res.length, (-1, n_states)),
        "blowout_deg": np.degrees(np.reshape(res.blowout, (-1, n_states))),
    }
    if np.ndim(res.L0) == 0:
        index = pd.MultiIndex.from_product([names, temps], names=["case", "t"])
        data = {key: np.ravel(value) for key, value in data.items()}
    else:
        if np.ndim(res.L0) != 1:
            shape = np.shape(res.L0)
            raise InputError("span", f"a table takes one span or a 1-D line of spans, got shape {shape}")
        n = res.L0.size
        index = pd.MultiIndex.from_product([range(n), names, temps], names=["span_no", "case", "t"])
        spans, dhs = np.broadcast_arrays(np.asarray(span, dtype=float), np.asarray(dh, dtype=float))
        line = {"span": np.repeat(np.ravel(spans), n_states), "dh": np.repeat(np.ravel(dhs), n_states)}
        data = line | {key: np.ravel(np.broadcast_to(value, (n, n_states))) for key, value in data.items()}
    frame = pd.DataFrame(data, index=index)
    frame.attrs.update(model=res.model, reason=res.reason, rtol=res.rtol)  # which model, and why
    return frame
