r"""Tension sections of several spans: the ruling span and the exact multi-span solution.

A tension section runs between two dead-end (strain) towers, where the
conductor is fixed, over suspension towers where it hangs from insulator
strings. A change of temperature or load changes the spans' tensions
differently; the strings swing along the line until the horizontal forces
balance, and the spans exchange length.

Ruling span
-----------
If the strings swing freely enough to equalise the horizontal tension in
every span, a level section behaves as one span of length (e.g. CIGRE TB 324,
"Sag-tension calculation methods for overhead lines", 2007, §3.3; F. Kiessling
et al., "Overhead Power Lines", Springer, 2003, §14)

.. math:: L_r = \sqrt{\frac{\sum_i L_i^3}{\sum_i L_i}},

obtained by summing the parabolic length excess :math:`w^2L_i^3/24H^2` and
the strains (elastic and thermal) over the spans at one common :math:`H`.
Each span's sag then follows from the ruling span's sag as
:math:`s_i = s_r (L_i/L_r)^2`. `ruling_span` implements the level form only:
for inclined spans the terms of the sum carry different powers of the chord
angles and no single equivalent span exists; `tension_section` solves them
exactly.

Exact multi-span solution
-------------------------
`tension_section` solves every span as the elastic catenary with thermal
strain (`thermal_catenary`; H.M. Irvine, "Cable Structures", MIT Press, 1981,
§2.2) between clamp points that move with the strings. A suspension string of
length :math:`\lambda` and weight :math:`W` is a rigid pendulum hinged at its
fixed attachment point; its lower end (the clamp) moves along the line by
:math:`\delta = \lambda\sin\varphi` and rises by
:math:`\lambda(1 - \cos\varphi)`. The conductor is clamped, so each span keeps
its unstressed length :math:`L_{0,i}`, set by a reference state (all spans at
the horizontal tension :math:`H_0`, load :math:`w_0`, temperature
:math:`t_0`, strings vertical). Moments about the hinge give, at every
suspension string,

.. math:: (H_{i+1} - H_i)\cos\varphi = (V_{B,i} + V_{A,i+1} + W/2)\sin\varphi,

i.e. :math:`\tan\varphi = \Delta H / (V + W/2)` with :math:`V` the weight of
conductor the clamp carries (the string's own weight acting at its middle).
The swings :math:`\delta` are found by Newton's method (`skcable.fe.newton`) with the analytic
Jacobian (each span's fairlead stiffness, `ElasticCatenary.stiffness`, by the
implicit function theorem), with backtracking that keeps
:math:`|\delta| < \lambda`, to a balance of :math:`10^{-11}` of the largest
:math:`H` (or, when Newton stalls above it, within four times the round-off
that the spans' own closure tolerance puts on :math:`H` and :math:`V`, which a
very stiff, taut conductor amplifies; ``moment_residual`` reports the balance
reached). A string of zero length holds its clamp fixed (the
spans on both sides are then independent). Loads are vertical (no wind): the
section stays in its vertical plane.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from skcable._checks import broadcast, nonnegative, real, scalar
from skcable._show import Shown, attributes, counted
from skcable.cable._extreme import blame_extreme
from skcable.conductors._inputs import normal, renamed, thermal_factor
from skcable.conductors._lines import reference_state
from skcable.conductors._state import change_of_state, thermal_catenary
from skcable.errors import ConvergenceError, InputError
from skcable.fe import newton

__all__ = ["ruling_span", "TensionSection", "tension_section"]

_TOL = 1e-11  # on the moment balance of the strings, relative to the largest H
_MAX_ITER = 60
_CLOSURE = 1e-13  # relative closure tolerance of elastic_catenary's Newton


def _spans(spans) -> np.ndarray:
    spans = np.atleast_1d(normal("spans", spans))
    if spans.size == 0:
        raise InputError("spans", "give at least one span")
    if spans.ndim != 1:
        raise InputError("spans", f"must be a 1-D sequence of span lengths, got shape {spans.shape}")
    return spans


def ruling_span(spans) -> float:
    r"""Ruling (equivalent) span of a level tension section (m),
    :math:`L_r = \sqrt{\sum L_i^3 / \sum L_i}` (module text).

    Parameters
    ----------
    spans : array_like
        Horizontal lengths of the level spans (m), each > 0.

    Returns
    -------
    float
    """
    spans = _spans(spans)
    # scaled by the longest span: no overflow of L³ for any float span
    top = spans.max()
    return float(top * np.sqrt(np.sum((spans / top) ** 3) / np.sum(spans / top)))


class TensionSection(Shown):
    """Result of `tension_section`.

    Arrays have the states' broadcast shape followed by the spans (``n``) or
    the suspension strings (``n - 1``) axis; for one state, just that axis.

    Attributes
    ----------
    H, V_A, V_B, T_max, sag : (..., n)
        Each span's horizontal tension, upward reactions at its left (A) and
        right (B) clamp, largest tension (N) and sag (largest vertical
        chord–cable distance, m).
    span, dh : (..., n)
        Each span's horizontal length and height difference between its
        clamps in the state (m).
    swing, swing_angle, clamp_rise : (..., n - 1)
        Each string's clamp displacement along the line (m, positive towards
        the last tower), angle from the vertical (rad) and rise of the clamp
        (m).
    L0 : (n,)
        Unstressed length of each span at ``t0`` (m).
    ruling_span : float
        `ruling_span` of the spans (m).
    H_ruling, sag_ruling_span : (...)
        Horizontal tension and sag of the ruling span's change of state
        (`change_of_state` on a level span ``ruling_span``, catenary).
    sag_ruling : (..., n)
        Each span's sag by the ruling-span approximation,
        ``sag_ruling_span (L_i / L_r)²`` with the reference spans ``L_i``.
    moment_residual : float
        Largest ``|ΔH cos φ - (V + W/2) sin φ| / max H`` over the swinging
        strings (length > 0) and the states (the balance solved).
    iterations : (...) int
        Newton iterations per state.
    """

    # set by ``__init__`` from its keywords (shapes above), with the states' ``w`` and ``t``
    H: Any
    V_A: Any
    V_B: Any
    T_max: Any
    sag: Any
    span: Any
    dh: Any
    swing: Any
    swing_angle: Any
    clamp_rise: Any
    L0: np.ndarray
    ruling_span: float
    H_ruling: Any
    sag_ruling_span: Any
    sag_ruling: Any
    moment_residual: float
    iterations: Any
    w: Any
    t: Any

    def __init__(self, **values):
        self.__dict__.update(values)

    @property
    def H_gap(self):
        """``H_ruling / H - 1`` per span: the ruling-span approximation's error in tension."""
        return np.asarray(self.H_ruling)[..., None] / self.H - 1.0

    @property
    def sag_gap(self):
        """``sag_ruling / sag - 1`` per span: the ruling-span approximation's error in sag."""
        return self.sag_ruling / self.sag - 1.0

    def __repr__(self):
        states = np.shape(self.H)[:-1]
        where = f"{counted(np.shape(self.L0), 'span')}, {counted(states, 'state')}"
        shown = attributes(
            self,
            {"t": "°C", "w": "N/m", "H": "N", "sag": "m", "swing": "m", "ruling_span": "m", "H_ruling": "N"},
        )
        return f"TensionSection({where}: {shown})"


class _Section:
    """The equations of one state: spans, strings, unstressed lengths.

    The unknowns are ``u = delta / scale`` with ``scale = min(lam, 1)``: a string shorter
    than 1 m swings by its sine ``s = delta / lam`` (a subnormal length, whose ``delta``
    underflows, still balances), a longer one by ``delta`` (a huge length does not overflow
    a column of the Jacobian).
    """

    def __init__(self, spans, dh, L0, EA, w, alpha, t, t0, lam, weight):
        self.spans, self.dh, self.L0, self.EA, self.w = spans, dh, L0, EA, w
        self.alpha, self.t, self.t0 = alpha, t, t0
        self.lam, self.weight = lam, weight
        self.free = lam > 0
        self.scale = np.where(self.free, np.minimum(lam, 1.0), 1.0)  # of the unknowns (m)
        # s = u * to_sine: exactly u below 1 m
        self.to_sine = 1.0 / np.where(self.free & (lam >= 1.0), lam, 1.0)

    def sines(self, u):
        """``sin phi`` and ``cos phi`` of every string (0 and 1 for a fixed one)."""
        s = np.where(self.free, u * self.to_sine, 0.0)
        return s, np.sqrt((1.0 - s) * (1.0 + s))

    def geometry(self, u):
        """Clamp rise, d(rise)/d(delta), and each span's (span, dh) for the unknowns ``u``."""
        s, c = self.sines(u)
        delta = np.where(self.free, u * self.scale, 0.0)
        rise = self.lam * s * s / (1.0 + c)  # lam (1 - cos phi)
        slope = s / np.where(c > 0, c, 1.0)
        dx = np.concatenate([[0.0], delta, [0.0]])
        dz = np.concatenate([[0.0], rise, [0.0]])
        span = self.spans + dx[1:] - dx[:-1]
        dh = self.dh + dz[1:] - dz[:-1]
        return rise, slope, span, dh

    def curves(self, u):
        _, _, span, dh = self.geometry(u)
        if np.any(span <= 0):
            raise InputError("insulator_length", "a string swings so far that a span vanishes")
        # the vectorised Newton of elastic_catenary probes backtracking steps whose closure
        # overflows (and are rejected); its result is checked by its own residual
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            return thermal_catenary(
                span, dh, self.w, self.EA, length=self.L0, alpha=self.alpha, t=self.t, t0=self.t0
            )

    def residual(self, u):
        """Moment balance of every string (N), the spans' solution and stiffness, and the
        balance's Jacobian in ``u``: its three diagonals ``(sub, diag, sup)`` (row ``j``
        holds ``dR_j/du_{j-1}, dR_j/du_j, dR_j/du_{j+1}``; rows of fixed strings unused)."""
        sol = self.curves(u)
        H, V_A, V_B = sol.H, sol.V_A, sol.V_B
        s, c = self.sines(u)
        dH = H[1:] - H[:-1]
        load = V_B[:-1] + V_A[1:] + 0.5 * self.weight
        R = dH * c - load * s
        _, slope, _, _ = self.geometry(u)
        K = sol.curve.stiffness()  # (n, 2, 2): rows (H, V_B), columns (span, dh)
        slope_all = np.concatenate([[0.0], slope, [0.0]])
        # span i moves with its right clamp (string i: span + delta) and its left one
        # (string i - 1: span - delta), dh with the clamps' rise; V_A = w L0 - V_B
        right = K[:, :, 0] + K[:, :, 1] * slope_all[1:, None]  # d(H, V_B)_i / d delta_i
        left = -(K[:, :, 0] + K[:, :, 1] * slope_all[:-1, None])  # d(H, V_B)_i / d delta_{i-1}
        diag = c * (left[1:, 0] - right[:-1, 0]) - s * (right[:-1, 1] - left[1:, 1])
        sub = -(c * left[:-1, 0] + s * left[:-1, 1])  # row j: d/d delta_{j-1} (span j)
        sup = c * right[1:, 0] + s * right[1:, 1]  # row j: d/d delta_{j+1} (span j + 1)
        # in the unknowns u: d delta / du = scale, ds / du = to_sine
        scale = self.scale
        sub = sub * np.concatenate([[0.0], scale[:-1]])
        sup = sup * np.concatenate([scale[1:], [0.0]])
        diag = diag * scale + (-dH * s / c - load) * self.to_sine
        return R, sol, (sub, diag, sup), K


def _round_off(sol, K) -> float:
    """Floor of the balance residual (relative to max H) set by the spans' own tolerance:
    each catenary closes to ``_CLOSURE`` of its chord, which moves its H and V_B by its
    stiffness times that (a stiff, taut cable amplifies it)."""
    K = np.abs(K).sum(axis=(-2, -1))
    chord = np.hypot(sol.span, sol.dh)
    return max(_TOL, _CLOSURE * float(np.max(K * chord)) / float(np.max(sol.H)))


def _free_band(diagonals, free):
    """The tridiagonal matrix of the free strings (LAPACK's ``dl, d, du``): removing a fixed
    string's row and column leaves its neighbours uncoupled."""
    sub, diag, sup = diagonals
    adjacent = np.diff(free) == 1
    return np.where(adjacent, sub[free[1:]], 0.0), diag[free], np.where(adjacent, sup[free[:-1]], 0.0)


def _banded_step(diagonals, R, free):
    """``-J⁻¹ R`` over the free strings by LU of the tridiagonal J (LAPACK ``dgttrf``,
    ``dgttrs``), O(n); its reciprocal condition number (``dgtcon``), O(n), refuses a
    numerically singular J."""
    from scipy.linalg import lapack

    dl, d, du = _free_band(diagonals, free)
    if d.size <= 2:  # LAPACK's tridiagonal wrappers want three rows: a 1x1 or 2x2 directly
        J = np.diag(d) + np.diag(dl, -1) + np.diag(du, 1)
        if not np.all(np.isfinite(J)) or np.linalg.cond(J) > 1e14:
            return None
        return np.linalg.solve(J, -R[free])
    anorm = float(
        np.max(np.abs(d) + np.abs(np.concatenate([dl, [0.0]])) + np.abs(np.concatenate([[0.0], du])))
    )
    dl_, d_, du_, du2, ipiv, info = lapack.dgttrf(dl, d, du)
    if info != 0 or not np.isfinite(anorm):
        return None
    rcond, _ = lapack.dgtcon(dl_, d_, du_, du2, ipiv, anorm)
    if not rcond > 1e-14:
        return None
    x, _ = lapack.dgttrs(dl_, d_, du_, du2, ipiv, -R[free][:, None])
    return x[:, 0]


def _solve_state(eqs: _Section, u0):
    """The swings of one state by `skcable.fe.newton`: a trial whose spans cannot be solved
    is rejected, and a stop within four times the spans' round-off (`_round_off`) is kept.
    Each step is one banded solve (`_banded_step`): O(n) per iteration."""
    free = np.flatnonzero(eqs.free)

    def norm(state):
        R, sol, _, _ = state
        return float(np.max(np.abs(R[free]), initial=0.0)) / float(np.max(sol.H))

    def increment(state):
        R, _, diagonals, _ = state
        step = np.zeros_like(R)
        if free.size:
            with np.errstate(all="ignore"):
                x = _banded_step(diagonals, R, free)
            if x is None or not np.all(np.isfinite(x)):
                raise ConvergenceError(
                    "tension_section: singular Jacobian of the strings' balance", [norm(state)]
                )
            step[free] = x
        return step

    result = newton(
        eqs.residual,
        np.where(eqs.free, u0, 0.0),
        norm=norm,
        increment=increment,
        tol=_TOL,
        max_iter=_MAX_ITER,
        admissible=lambda u: bool(np.all(np.abs(u[free] * eqs.to_sine[free]) < 1.0)),
        max_halvings=39,
        stagnation_window=_MAX_ITER,  # no stagnation rule: the floor below decides
        name="tension_section",
        rejects=(ConvergenceError, InputError),
        floor=lambda state: 4.0 * _round_off(state[1], state[3]),
    )
    return result.x, result.history[-1], result.state[1], result.iterations


def tension_section(
    spans, dh=0.0, *, EA, alpha, w0, t0, H0, w, t, insulator_length, insulator_weight
) -> TensionSection:
    r"""Exact change of state of a tension section with suspension strings.

    The section's conductor runs from the dead-end at A = (0, 0) over the
    clamps of ``n - 1`` suspension strings to the dead-end at the far end;
    span ``i`` joins clamp ``i`` to clamp ``i + 1``. See the module docstring
    for the equations (moment balance of every string, each span an elastic
    catenary with thermal strain).

    Parameters
    ----------
    spans : array_like (n,)
        Horizontal lengths of the spans between the clamps in the reference
        state (strings vertical), m, each > 0.
    dh : float or array_like (n,)
        Height of each span's right clamp above its left one in the reference
        state (m).
    EA : float
        Axial stiffness of the conductor (N), > 0.
    alpha : float
        Coefficient of thermal expansion (1/K).
    w0, t0, H0 : float
        Reference state: weight per unstressed length (N/m, > 0),
        temperature, and the horizontal tension of every span (N, > 0), the
        strings vertical.
    w, t : float or array_like
        The states: weight per unstressed reference length including ice
        (N/m, > 0) and temperature; broadcast together.
    insulator_length : float or array_like (n - 1,)
        Length of each suspension string, hinge to clamp (m), >= 0 (0: the
        clamp is fixed).
    insulator_weight : float or array_like (n - 1,)
        Weight of each string (N), >= 0, acting at its middle.

    Returns
    -------
    TensionSection
        The spans and the strings, with the ruling-span approximation beside them.

    Raises
    ------
    InputError
        A non-physical argument, named; a thermal factor ``1 + alpha (t - t0)
        <= 0``.
    ConvergenceError
        Newton on the strings' balance (or a span's catenary) did not
        converge; the error carries the residual history.
    """
    spans = _spans(spans)
    n = spans.size
    dh = real("dh", dh)
    if np.ndim(dh) not in (0, 1) or np.size(dh) not in (1, n):
        raise InputError("dh", f"must be one number or one per span ({n}), got shape {np.shape(dh)}")
    dh = np.broadcast_to(np.asarray(dh, dtype=float), (n,)).copy()
    EA = normal("EA", scalar("EA", EA))
    alpha, t0 = scalar("alpha", alpha), scalar("t0", t0)
    w0 = normal("w0", scalar("w0", w0))
    H0 = normal("H0", scalar("H0", H0))
    strings = {}
    for name, value in (("insulator_length", insulator_length), ("insulator_weight", insulator_weight)):
        value = nonnegative(name, value)
        if np.ndim(value) > 1 or (np.ndim(value) == 1 and np.size(value) != n - 1):
            raise InputError(
                name, f"must be one number or one per string ({n - 1}), got shape {np.shape(value)}"
            )
        strings[name] = np.broadcast_to(np.asarray(value, dtype=float), (n - 1,)).copy()
    lam, weight = strings["insulator_length"], strings["insulator_weight"]
    w, t = normal("w", w), real("t", t)
    shape = broadcast(w=w, t=t)
    given = dict(spans=spans, dh=dh, EA=EA, alpha=alpha, w0=w0, t0=t0, H0=H0, w=w, t=t)
    with blame_extreme(**given, insulator_length=lam, insulator_weight=weight):  # the outsized one, if any
        return _section(spans, dh, EA, alpha, w0, t0, H0, w, t, lam, weight, shape)


def _section(spans, dh, EA, alpha, w0, t0, H0, w, t, lam, weight, shape) -> TensionSection:
    """`tension_section` on checked arguments (``lam``, ``weight``: the strings, one per string)."""
    n = spans.size
    w_all, t_all = (np.broadcast_to(v, shape).ravel() for v in (w, t))
    thermal_factor(alpha, t_all, t0)  # raises naming t

    # every span's unstressed length at once (the line path of change_of_state, checked)
    with renamed({"span": "spans"}):
        L0, *_ = reference_state(spans, dh, w0, EA, np.full(n, H0), "H0")

    fields = ("H", "V_A", "V_B", "T_max", "sag", "span", "dh")
    out = {name: np.empty((w_all.size, n)) for name in fields}
    out |= {name: np.empty((w_all.size, n - 1)) for name in ("swing", "swing_angle", "clamp_rise")}
    iterations = np.empty(w_all.size, dtype=int)
    worst = 0.0
    u = np.zeros(n - 1)
    for j, (w_j, t_j) in enumerate(zip(w_all, t_all, strict=True)):
        eqs = _Section(spans, dh, L0, EA, float(w_j), alpha, float(t_j), t0, lam, weight)
        u, residual, sol, iterations[j] = _solve_state(eqs, u)  # continuation from the last state
        rise, _, span_j, dh_j = eqs.geometry(u)
        worst = max(worst, residual)
        values = dict(
            H=sol.H, V_A=sol.V_A, V_B=sol.V_B, T_max=np.maximum(sol.T_A, sol.T_B), sag=sol.sag,
            span=span_j, dh=dh_j, swing=np.where(eqs.free, u * eqs.scale, 0.0),
            swing_angle=np.arcsin(eqs.sines(u)[0]), clamp_rise=rise,
        )  # fmt: skip
        for name, value in values.items():
            if not np.all(np.isfinite(value)):
                raise ConvergenceError(f"tension_section: non-finite {name} in state {j}")
            out[name][j] = value

    L_r = ruling_span(spans)
    # the line path of change_of_state (one span): its vectorised solve, checked
    ruling = change_of_state([L_r], 0.0, EA=EA, alpha=alpha, w0=w0, t0=t0, H0=H0, w=w_all, t=t_all)
    H_r, sag_r = ruling.H[0], ruling.sag[0]
    sag_ruling = sag_r[:, None] * (spans / L_r) ** 2

    def shaped(value):
        return value.reshape(*shape, *value.shape[1:])

    return TensionSection(
        **{name: shaped(value) for name, value in out.items()},
        L0=L0,
        ruling_span=L_r,
        H_ruling=shaped(H_r) if shape else float(H_r[0]),
        sag_ruling_span=shaped(sag_r) if shape else float(sag_r[0]),
        sag_ruling=shaped(sag_ruling),
        moment_residual=worst,
        iterations=shaped(iterations) if shape else int(iterations[0]),
        w=w,
        t=t,
    )
