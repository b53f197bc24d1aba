r"""Model no more than a scene needs: the cheapest cable model within a tolerance.

`solve` takes the cheapest model whose *estimated* relative error is
below ``rtol``:

1. **parabola** for a deck load (load per horizontal length, exact), with
   any self weight smeared over the span (approximate);
2. **catenary** for self weight alone (exact; the parabola standing for it
   would cost more: it needs a fixed point on the weight per horizontal metre);
3. **elastic catenary** (Irvine) for self weight with ``EA`` and a given
   unstretched length, when the stretch matters at ``rtol``;
4. **BVP** (scikit-fem) for every other case, the mesh doubled until the
   estimate is below ``rtol``.

Error estimates (relative, on H, the end tensions and the length):

- *Shape*: a parabola standing for a catenary errs by the
  first neglected term of Goicolea (2012) §3.2.1's series
  :math:`z = a[1 + \tfrac12 (x/a)^2 + \tfrac1{24}(x/a)^4 + \dots]` relative to
  the kept one, :math:`t^2/12` for a level span with support slopes ±t
  (Goicolea 2012, ex. 4/5: 1.33 % against the true 1.3 % in H). For any chord,
  with :math:`u_A, u_B` the support values of x/a (Δ = |u_B − u_A|,
  c = |u_A + u_B|/2), the estimate is :math:`K\,\tfrac{\Delta^2}{48}(1 + c)`
  (Δ = 2t gives t²/12 when c = 0); the factor 1 + c and K = 2 (5 for the
  ``low`` constraint, whose vertex may sit near a support) were chosen on
  random scenes so that the estimate bounds the largest relative error in
  H, the end tensions, the length and the sag (``tests/bvp/test_choice.py``
  checks the bound on random scenes of every constraint). With a deck load, only the
  self weight's share of the load (per horizontal metre) is misplaced: the
  estimate is multiplied by that share.
- *Stretch*: an inextensible model of an elastic cable (``EA`` given) errs by
  the wire strain :math:`\varepsilon = T_{\max}/EA` in the length and, when the
  unstretched length is the constraint, by
  :math:`\varepsilon\,S/(2(S - c))` in H (a parabola's :math:`H \propto (S-c)^{-1/2}`;
  c the chord), which grows without bound as the cable tightens; both times
  1.5, a margin over the first-order value (the test checks the bound
  against Irvine's closed form on 200 random scenes).
- *Discretisation*: the BVP's H on n and 2n P2 elements (error
  :math:`\propto h^4`): the difference of the two bounds the error of the
  coarser one; the finer is returned.

``tests/bvp/test_choice.py`` checks on random scenes that the estimates
bound the true error and that the cheaper model is taken when it is good
enough.
"""

from __future__ import annotations

import math

from skcable._checks import exactly_one, positive_scalar, scalar
from skcable.bvp import solve_bvp
from skcable.bvp.loads import DeckLoad, PointLoad, SelfWeight
from skcable.cable._catenary import catenary
from skcable.cable._elastic import elastic_catenary
from skcable.cable._parabola import parabola
from skcable.errors import ConvergenceError, InputError

__all__ = ["solve"]

#: Models in the order they are tried (cheapest first).
MODELS = ("parabola", "catenary", "elastic catenary", "BVP")


def _shape_error(solution, constraint) -> float:
    """K·Δ²/48·(1 + |c|): Δ, c the difference and mean of the support slopes from the vertex."""
    a, b = float(solution.slope(0.0)), float(solution.slope(float(solution.span)))
    spread, centre = abs(b - a), 0.5 * abs(a + b)
    safety = 5.0 if constraint[0] == "low" else 2.0  # the vertex near a support amplifies "low"
    return safety * spread * spread / 48.0 * (1.0 + centre)


def _stretch_error(solution, EA, constraint) -> float:
    if EA is None:
        return 0.0
    strain = 1.5 * float(solution.T_max) / EA  # 1.5: a margin over the first-order estimate
    if constraint[0] != "length":
        return strain
    chord = math.hypot(float(solution.span), float(solution.dh))
    excess = float(solution.length) - chord
    return strain * max(1.0, float(solution.length) / (2.0 * excess)) if excess > 0 else math.inf


def _smeared_parabola(span, dh, deck, weight, constraint):
    """Parabola under the deck load plus the self weight smeared per horizontal metre
    (``weight·S/span``, S its own length: a fixed point, 2–3 digits per pass)."""
    name, value = constraint
    w = deck + weight
    for _ in range(4 if weight else 1):
        sol = parabola(span, dh, w, **{name: value})
        w = deck + weight * float(sol.length) / span
    return parabola(span, dh, w, **{name: value}) if weight else sol


def _annotate(solution, model, estimate, reason, tried):
    solution.model, solution.error_estimate, solution.reason = model, estimate, reason
    solution.tried = tried
    return solution


def solve(
    span, dh, loads, *, length=None, sag=None, H=None, low=None, T_max=None, EA=None, rtol: float = 1e-3
):
    """Solve with the cheapest model whose estimated relative error is below ``rtol``.

    Parameters
    ----------
    span, dh : float
        B = (span, dh) relative to A (m).
    loads : load or list of loads
        As for `solve_bvp`.
    length, sag, H, low, T_max : float
        Exactly one constraint (``length`` unstretched when ``EA`` is given).
    EA : float, optional
        Axial stiffness (N); inextensible when omitted.
    rtol : float
        Largest acceptable estimated relative error.

    Returns
    -------
    CableSolution
        The chosen model's solution with four more attributes: ``model``
        (one of `MODELS`), ``error_estimate``, ``reason`` (why this
        model) and ``tried`` (the cheaper models rejected, with their estimates).

    Examples
    --------
    >>> solve(200.0, 0.0, SelfWeight(1.0), sag=20.0).model  # Goicolea (2012) ex. 5
    'catenary'
    >>> s = solve(1000.0, 0.0, [DeckLoad(100e3), SelfWeight(15e3)], sag=100.0, rtol=1e-2)
    >>> s.model, s.error_estimate < 1e-2  # a suspension bridge's main cable
    ('parabola', True)
    """
    span = positive_scalar("span", span)
    dh = scalar("dh", dh)
    rtol = positive_scalar("rtol", rtol)
    if EA is not None:
        EA = positive_scalar("EA", EA)
    name, value = exactly_one(length=length, sag=sag, H=H, low=low, T_max=T_max)
    constraint = (name, scalar(name, value))
    loads = list(loads) if isinstance(loads, (list, tuple)) else [loads]
    if not loads:
        raise InputError("loads", "give at least one load")
    for load in loads:
        if not (isinstance(load, PointLoad) or callable(getattr(load, "graph_terms", None))):
            raise InputError(
                "loads",
                f"must be load objects (SelfWeight, DeckLoad, PointLoad, ...), got {type(load).__name__}",
            )
    tried: list[tuple[str, float]] = []  # the cheaper models rejected, with their estimates
    if all(type(ld) in (SelfWeight, DeckLoad) for ld in loads):
        deck = sum(float(ld.w) for ld in loads if isinstance(ld, DeckLoad))
        weight = sum(float(ld.w) for ld in loads if isinstance(ld, SelfWeight))
        if deck > 0:  # the parabola: exact for a deck load, the self weight smeared
            sol = _smeared_parabola(span, dh, deck, weight, constraint)
            share = 1.0 - deck / float(sol.w)  # the self weight's part of the load
            shape = share * _shape_error(sol, constraint)
            estimate = shape + _stretch_error(sol, EA, constraint)
            what = "deck load" + (" and self weight smeared" if weight else "")
            if estimate <= rtol:
                reason = f"{what}: estimated error {estimate:.1e} (shape {shape:.1e}) <= rtol {rtol:g}"
                return _annotate(sol, "parabola", estimate, reason, tried)
            tried.append(("parabola", estimate))
        else:  # the catenary: exact for self weight
            sol = catenary(span, dh, weight, **{constraint[0]: constraint[1]})
            estimate = _stretch_error(sol, EA, constraint)
            if estimate <= rtol:
                reason = "self weight: the catenary is exact" + (
                    f"; stretch neglected, estimated error {estimate:.1e} <= rtol {rtol:g}" if EA else ""
                )
                return _annotate(sol, "catenary", estimate, reason, tried)
            tried.append(("catenary", estimate))
            if constraint[0] == "length":
                sol = elastic_catenary(span, dh, weight, EA, length=constraint[1])
                reason = "self weight, elastic, given unstretched length: Irvine's closed form is exact"
                return _annotate(sol, "elastic catenary", sol.residual(), reason, tried)
    return _bvp(span, dh, loads, constraint, EA, rtol, tried)


def _bvp(span, dh, loads, constraint, EA, rtol, tried, n_elements: int = 16, largest: int = 4096):
    """BVP on n and 2n elements until the two H agree within rtol."""
    name, value = constraint
    coarse = solve_bvp(span, dh, loads, EA=EA, n_elements=n_elements, **{name: value})
    history = []
    while True:
        fine = solve_bvp(span, dh, loads, EA=EA, n_elements=2 * n_elements, **{name: value})
        pairs = ((fine.H, coarse.H), (fine.T_max, coarse.T_max), (fine.length, coarse.length))
        estimate = max(abs(a / b - 1) for a, b in pairs)
        history.append(estimate)
        if estimate <= rtol:
            reason = (
                f"no closed form takes these loads at rtol {rtol:g}; {2 * n_elements} P2 elements, "
                f"estimated error {estimate:.1e} (difference from {n_elements} elements)"
            )
            return _annotate(fine, "BVP", estimate, reason, tried)
        n_elements *= 2
        if 2 * n_elements > largest:
            raise ConvergenceError(f"solve: BVP not within rtol {rtol:g} on {largest} elements", history)
        coarse = fine
