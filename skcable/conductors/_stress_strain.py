r"""Conductor stress–strain models: polynomial initial curves, final curves after the maximum
load, the knee point, creep, and the sag–tension of a level span by strain summation.

The model is that of the Aluminum Association / Alcoa graphical method (Aluminum Association,
"Aluminum Electrical Conductor Handbook", 3rd ed., 1989; CIGRE WG B2.12, "Sag-tension
calculation methods for overhead lines", TB 324, 2007, §2.3–2.5), written as a strain law:

- each component :math:`k` of the conductor (the aluminium layers, the steel core) has an
  **initial** loading curve, a polynomial :math:`f_k(\varepsilon) = \sum_{i=0}^{4} a_{k,i}
  \varepsilon^i` giving its load per unit area of the whole conductor (Pa) at its mechanical
  strain :math:`\varepsilon`, increasing over its range :math:`[0, \varepsilon_{k,\max}]`
  (refused otherwise), linear beyond its ends with the end slopes;
- the components share the conductor's strain; each one's mechanical strain is the conductor's
  less its own thermal strain, :math:`\varepsilon_k = \varepsilon - \alpha_k (t - t_\text{ref})`,
  and their loads add up, :math:`\sigma = T/A = \sum_k f_k(\varepsilon_k)`;
- after the **maximum load** of the design (a load history), a component unloads along its
  **final** modulus :math:`E_k`: :math:`f_k = E_k(\varepsilon_k - p_k)` below the peak strain
  :math:`\varepsilon_{k,\text{peak}}`, with the permanent set
  :math:`p_k = \varepsilon_{k,\text{peak}} - f_k(\varepsilon_{k,\text{peak}})/E_k`; above the
  peak it follows its initial curve again;
- **creep** adds a permanent strain to a component (CIGRE TB 324, §2.5: the strain after a
  given time at the everyday stress), here :math:`p_k \to p_k + \varepsilon_{k,\text{creep}}`;
  `CreepLaw` is the power law :math:`\varepsilon_c = K\,e^{\varphi\theta}\sigma^{\alpha}t^{\mu}`
  of TB 324 (§2.5.2) with the user's coefficients (none are shipped: they are the conductor
  maker's test results);
- an aluminium component takes at most ``compression_limit`` (Pa, over the whole area) in
  compression; at 0 (the default) it goes slack: the **knee point**, above which the steel
  alone carries the tension and the sag grows at the steel's thermal rate.

`level_span_states` solves a level span of length :math:`S` under weight :math:`w` by strain
summation: the catenary length :math:`L(H) = 2c\sinh(S/2c)`, :math:`c = H/w`, equals the
reference length stretched by the model's strain at the average tension
:math:`T_\text{avg} = H(S + c\sinh(S/c))/(2L)`, :math:`L(H) = L_0(1 + \varepsilon(T_\text{avg}/A,
t))`, with :math:`L_0` fixed by the stringing state on the initial curve. Newton on
:math:`(H, \varepsilon)` with the derivatives of :math:`L` and :math:`T_\text{avg}` by complex
steps (exact to round-off) and the polynomials' own derivatives. It prints, as the industry's
programs do, each load case's initial state, its final state after the maximum load, and its
final state after creep.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable._checks import nonnegative, positive, positive_scalar, real, scalar
from skcable.errors import ConvergenceError, InputError

__all__ = [
    "ComponentCurve",
    "StressStrainModel",
    "History",
    "CreepLaw",
    "PSI",
    "aa_coefficients",
    "level_span_states",
]

#: One pound-force per square inch (Pa).
PSI = 6894.757293168361


def aa_coefficients(coefficients_psi_percent):
    """Polynomial coefficients as the Aluminum Association prints them (psi, strain in %) to
    this module's (Pa, strain as a fraction): ``a_i · psi · 100^i``."""
    a = np.asarray(real("coefficients", coefficients_psi_percent), dtype=float)
    return tuple(float(v) for v in a * PSI * 100.0 ** np.arange(a.size))


@dataclass(frozen=True)
class ComponentCurve:
    """One component's curves (the aluminium layers, or the steel core).

    Parameters
    ----------
    name : str
        Label (``"aluminium"``, ``"steel"``).
    coefficients : sequence of float
        ``a_0 ... a_n`` (n <= 4) of the initial curve ``f(ε) = Σ a_i ε^i`` (Pa over the
        conductor's whole area; ε a fraction; `aa_coefficients` converts the Aluminum
        Association's psi and %).
    strain_max : float
        The polynomial's range ``[0, strain_max]`` (> 0); ``f`` must increase over it.
    final_modulus : float
        The final (unloading) modulus over the whole area (Pa), > 0.
    alpha : float
        Its coefficient of thermal expansion (1/K).
    compression_limit : float or None
        Largest compression it takes (Pa over the whole area, >= 0): 0 for aluminium that
        goes slack (the knee), None for none (the steel core, linear in compression).
    """

    name: str
    coefficients: tuple
    strain_max: float
    final_modulus: float
    alpha: float
    compression_limit: float | None = None

    def __post_init__(self):
        a = np.atleast_1d(real("coefficients", self.coefficients)).astype(float)
        if a.ndim != 1 or not 1 <= a.size <= 5:
            raise InputError("coefficients", f"must be 1 to 5 numbers a_0 ... a_4, got {a.size}")
        top = positive_scalar("strain_max", self.strain_max)
        slope = np.polynomial.Polynomial(a).deriv()
        grid = np.linspace(0.0, top, 2001)
        roots = np.asarray(slope.roots(), dtype=complex)
        stationary = [float(r.real) for r in roots if abs(r.imag) < 1e-12 and 0.0 <= float(r.real) <= top]
        if np.any(slope(grid) <= 0) or any(slope(r) <= 0 for r in stationary):
            worst = float(grid[np.argmin(slope(grid))])
            raise InputError(
                "coefficients",
                f"the initial curve of {self.name!r} must increase over [0, {top:g}]: its slope is "
                f"{slope(worst):.4g} Pa at strain {worst:.4g}",
            )
        limit = self.compression_limit
        values = dict(
            coefficients=tuple(float(v) for v in a),
            strain_max=top,
            final_modulus=positive_scalar("final_modulus", self.final_modulus),
            alpha=scalar("alpha", self.alpha),
            compression_limit=None
            if limit is None
            else nonnegative("compression_limit", scalar("compression_limit", limit)),
        )
        for key, value in values.items():
            object.__setattr__(self, key, value)

    def initial(self, strain):
        """Load (Pa) and its slope on the initial curve at mechanical ``strain`` (arrays)."""
        a = np.asarray(self.coefficients)
        p = np.polynomial.Polynomial(a)
        d = p.deriv()
        eps = np.asarray(strain, dtype=float)
        lo, hi = 0.0, self.strain_max
        inside = np.clip(eps, lo, hi)
        load = p(inside) + d(inside) * (eps - inside)  # linear beyond the range, end slopes
        return load, d(inside)

    def load(self, strain, permanent=None, peak=None):
        """Load (Pa) and slope at ``strain``: the initial curve, or with a history (``permanent``
        set and ``peak`` strain) the final line below the peak; the compression limit applied."""
        load, slope = self.initial(strain)
        if permanent is not None:
            eps = np.asarray(strain, dtype=float)
            below = eps < peak
            load = np.where(below, self.final_modulus * (eps - permanent), load)
            slope = np.where(below, self.final_modulus, slope)
        if self.compression_limit is not None:
            slack = load < -self.compression_limit
            load = np.where(slack, -self.compression_limit, load)
            slope = np.where(slack, 0.0, slope)
        return load, slope


@dataclass(frozen=True)
class History:
    """A load history: each component's permanent set and peak mechanical strain (after the
    maximum load), and its creep strain ``offset`` (its whole curve moved by it)."""

    permanent: tuple
    peak: tuple
    offset: tuple = ()
    label: str = "initial"


@dataclass(frozen=True)
class CreepLaw:
    r"""Creep strain :math:`\varepsilon_c = K e^{\varphi\theta} \sigma^{\alpha} t^{\mu}` (CIGRE TB
    324, 2007, §2.5.2): ``sigma`` the component's stress (Pa over the whole area, divided by
    ``sigma_unit``), ``t`` hours, ``theta`` °C; the coefficients are the conductor maker's."""

    K: float
    phi: float
    alpha: float
    mu: float
    sigma_unit: float = 1e6

    def strain(self, sigma, hours, temperature):
        hours = real("time", hours)
        if np.any(np.asarray(hours) < 0):
            raise InputError("time", f"a creep time must be >= 0 (hours), got {hours}")
        sigma = np.maximum(np.asarray(real("sigma", sigma), dtype=float), 0.0) / self.sigma_unit
        return (
            self.K
            * np.exp(self.phi * real("temperature", temperature))
            * sigma**self.alpha
            * np.asarray(hours) ** self.mu
        )


@dataclass(frozen=True)
class StressStrainModel:
    """The conductor's strain law ε(σ, t, history) from its components (module text).

    Parameters
    ----------
    components : sequence of ComponentCurve
    area : float
        The conductor's whole cross-section (m²): ``σ = T / area``.
    t_ref : float
        The temperature of the curves' tests (°C).
    """

    components: tuple
    area: float
    t_ref: float = 20.0
    initial_history: History = field(init=False)

    def __post_init__(self):
        comps = tuple(self.components)
        if not comps or not all(isinstance(c, ComponentCurve) for c in comps):
            raise InputError("components", "must be a non-empty sequence of ComponentCurve")
        object.__setattr__(self, "components", comps)
        object.__setattr__(self, "area", positive_scalar("area", self.area))
        object.__setattr__(self, "t_ref", scalar("t_ref", self.t_ref))
        none = (None,) * len(comps)
        object.__setattr__(self, "initial_history", History(none, none, (0.0,) * len(comps), "initial"))

    def mechanical(self, strain, t):
        """Each component's mechanical strain at conductor ``strain`` and temperature ``t``."""
        return [strain - c.alpha * (t - self.t_ref) for c in self.components]

    def _component_loads(self, strain, t, history):
        """Each component's ``(load, slope)`` (Pa over the whole area) at conductor ``strain``, ``t``."""
        history = history or self.initial_history
        offsets = history.offset or (0.0,) * len(self.components)
        parts = zip(
            self.components, self.mechanical(strain, t), history.permanent, history.peak, offsets, strict=True
        )
        return [c.load(eps - o, p, k) for c, eps, p, k, o in parts]

    def loads(self, strain, t, history=None):
        """Each component's load (Pa over the whole area) at conductor ``strain``, ``t``."""
        return [float(load) for load, _ in self._component_loads(strain, t, history)]

    def stress(self, strain, t, history=None):
        """Conductor stress (Pa) and its slope dσ/dε at ``strain``, ``t``."""
        total = slope = 0.0
        for load, d in self._component_loads(strain, t, history):
            total, slope = total + load, slope + d
        return total, slope

    def strain(self, stress, t, history=None):
        """The conductor strain at ``stress`` (Pa), ``t`` (scalars): the root of the
        non-decreasing sum of the components' loads, by `safeguarded_newton`."""
        history = history or self.initial_history
        stress = float(stress)
        modulus = sum(c.final_modulus for c in self.components)
        thermal = sum(c.alpha * c.final_modulus for c in self.components) / modulus * (t - self.t_ref)
        start = stress / modulus + thermal

        def f(eps):
            value, slope = self.stress(eps, t, history)
            return float(value) - stress, float(slope)

        step = abs(stress) / modulus + 1e-4
        lo, hi = _bracket(f, start, step, increasing=True)
        return safeguarded_newton(f, start, lo, hi, "stress-strain: the strain of a stress")

    def after_load(self, strain, t, previous=None, label="final after load"):
        """The history after the conductor reached ``strain`` at ``t`` (its maximum load):
        each component's peak (the larger of the previous one and this) and permanent set."""
        previous = previous or self.initial_history
        permanent, peak = [], []
        for c, eps, p0, k0 in zip(
            self.components, self.mechanical(strain, t), previous.permanent, previous.peak, strict=True
        ):
            top = eps if k0 is None else max(eps, k0)
            load, _ = c.initial(top)
            permanent.append(float(top - load / c.final_modulus) if p0 is None or top > k0 else p0)
            peak.append(float(top))
        return History(tuple(permanent), tuple(peak), (), label)

    def with_creep(self, history, creep, label="final after creep"):
        """``history`` with each component's creep strain (a sequence, one per component): its
        curve moved by that strain (CIGRE TB 324, §2.5: creep as a strain offset)."""
        creep = np.atleast_1d(nonnegative("creep", creep)).astype(float)
        if creep.size != len(self.components):
            raise InputError("creep", f"give one creep strain per component ({len(self.components)})")
        return History(history.permanent, history.peak, tuple(float(c) for c in creep), label)


def _length(H, w, S):
    c = H / w
    return 2.0 * c * np.sinh(S / (2.0 * c))


def _average_tension(H, w, S):
    c = H / w
    return H * (S + c * np.sinh(S / c)) / (2.0 * _length(H, w, S))


def _derivative(f, H, *args):
    """``f'(H)`` by a complex step (exact to round-off)."""
    h = 1e-20 * H
    return float(np.imag(f(H + 1j * h, *args)) / h)


def _bracket(f, x0, step, *, increasing, positive_x=False):
    """``(lo, hi)`` around the root of the monotone ``f`` (value, slope), widened from ``x0``."""
    lo, hi = (x0 / 2, x0 * 2) if positive_x else (x0 - step, x0 + step)
    for _ in range(200):
        f_lo, f_hi = f(lo)[0], f(hi)[0]
        if increasing and f_lo <= 0 <= f_hi or not increasing and f_lo >= 0 >= f_hi:
            return lo, hi
        if (f_lo > 0) == increasing:
            lo = lo / 2 if positive_x else lo - 2 * (hi - lo)
        else:
            hi = hi * 2 if positive_x else hi + 2 * (hi - lo)
    raise ConvergenceError("no sign change found to bracket the root", [f_lo, f_hi])


def safeguarded_newton(f, x, lo, hi, what, rtol=4e-16, max_iter=200):
    """The root of ``f`` (returning value and slope) in the bracket ``[lo, hi]``: Newton's step
    where it stays inside the bracket and halves it at least, bisection otherwise (W.H. Press et
    al., "Numerical Recipes", 3rd ed., 2007, §9.4, ``rtsafe``); to a few ulps of x."""
    f_lo = f(lo)[0]
    history = []
    x = min(max(x, lo), hi)
    dx_old = hi - lo
    for _ in range(max_iter):
        value, slope = f(x)
        history.append(abs(value))
        if value == 0:
            return x
        if (value < 0) == (f_lo < 0):
            lo, f_lo = x, value
        else:
            hi = x
        newton = x - value / slope if slope != 0 else np.nan
        if not lo < newton < hi or abs(2 * value) > abs(dx_old * slope):
            dx_old, x_new = (hi - lo) / 2, (lo + hi) / 2
        else:
            dx_old, x_new = abs(newton - x), newton
        if abs(x_new - x) <= rtol * max(abs(x), abs(lo), abs(hi)) or hi - lo <= rtol * max(abs(lo), abs(hi)):
            return x_new
        x = x_new
    raise ConvergenceError(f"{what} did not converge", history)


def _solve_level(model, span, w, t, L0, history, H_start):
    """(H, strain) of the level span at weight ``w``, temperature ``t`` under ``history``:
    ``g(H) = L(H)/L0 - 1 - ε(T_avg(H)/A)``, decreasing in H, by `safeguarded_newton`."""
    A = model.area

    def g(H):
        eps = model.strain(float(_average_tension(H, w, span)) / A, t, history)
        _, slope = model.stress(eps, t, history)
        dT = _derivative(_average_tension, H, w, span)
        value = float(_length(H, w, span)) / L0 - 1.0 - eps
        return value, _derivative(_length, H, w, span) / L0 - dT / (A * float(slope))

    lo, hi = _bracket(g, H_start, 0.0, increasing=False, positive_x=True)
    H = safeguarded_newton(g, H_start, lo, hi, "level span: the tension of a state")
    return H, model.strain(float(_average_tension(H, w, span)) / A, t, history)


def level_span_states(model, span, *, w0, t0, H0, cases, max_load, creep=None):
    """Sag–tension of a level span by strain summation: initial, final after load, final after creep.

    Parameters
    ----------
    model : StressStrainModel
    span : float
        The level span (m), > 0.
    w0, t0, H0 : float
        The stringing state on the initial curve: weight (N/m), temperature (°C), horizontal
        tension (N); it fixes the unstressed reference length.
    cases : dict
        Name -> ``(w, t)``: the states of the table.
    max_load : str
        The case of the maximum design load (its initial state sets the history).
    creep : sequence of float or None
        Each component's creep strain (e.g. `CreepLaw.strain` at the everyday stress and ten
        years); None: no creep rows.

    Returns
    -------
    pandas.DataFrame
        Index ``(case, condition)`` with conditions ``initial``, ``final after load`` and
        ``final after creep``; columns ``w, t, H, sag, strain, T_avg``, and ``slack`` (True
        where a component carries no load: beyond the knee).
    """
    import pandas as pd

    if not isinstance(model, StressStrainModel):
        raise InputError("model", f"must be a StressStrainModel, got {model!r}")
    span = positive_scalar("span", span)
    w0, H0, t0 = positive_scalar("w0", w0), positive_scalar("H0", H0), scalar("t0", t0)
    if not isinstance(cases, dict) or max_load not in cases:
        raise InputError(
            "max_load", f"must name one of the cases {list(cases) if isinstance(cases, dict) else cases}"
        )
    eps0 = model.strain(float(_average_tension(H0, w0, span)) / model.area, t0)
    L0 = float(_length(H0, w0, span)) / (1.0 + eps0)
    w_max, t_max = cases[max_load]
    H_max, eps_max = _solve_level(model, span, w_max, t_max, L0, None, H0)
    histories = [model.initial_history, model.after_load(eps_max, t_max)]
    if creep is not None:
        histories.append(model.with_creep(histories[1], creep))
    rows, index = [], []
    for name, (w, t) in cases.items():
        w, t = positive("cases", w), real("cases", t)
        for history in histories:
            H, eps = _solve_level(model, span, w, t, L0, history, H0)
            c = H / w
            loads = model.loads(eps, t, history)
            sag = c * (np.cosh(span / (2 * c)) - 1.0)
            T_avg = float(_average_tension(H, w, span))
            slack = bool(np.any(np.asarray(loads) <= 0))
            rows.append(dict(w=w, t=t, H=H, sag=sag, strain=eps, T_avg=T_avg, slack=slack))
            index.append((name, history.label))
    return pd.DataFrame(rows, index=pd.MultiIndex.from_tuples(index, names=["case", "condition"]))
