"""The conductors' model choice: of a change of state, the parabola where its estimated error is
within the tolerance the user gives, the exact catenary elsewhere, and why.

The exact model (the thermal elastic catenary in the plane of the load,
`skcable.conductors.thermal_catenary`) is right to the round-off its closure check allows; the
parabolic change-of-state equation (`skcable.conductors._parabola`) is several times cheaper and
errs by terms of order ``(sag/span)²`` and of the strains' products, which
`skcable.conductors._parabola` estimates span by span (a bound: ``tests/conductors/test_choice.py``
holds it against the exact model on random lines). ``model="auto"`` takes, for each span, the
parabola for all its states where that estimate is at most ``rtol``, else the exact model for
all of them (one unstressed length a span).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import one_of, positive_scalar
from skcable.errors import InputError

__all__ = ["MODELS", "RTOL", "Choice", "choose", "check_model"]

#: The models `skcable.conductors.change_of_state` takes.
MODELS = ("catenary", "parabola", "auto")
#: The tolerance of ``model="auto"`` when none is given (that of `skcable.bvp.solve`).
RTOL = 1e-3


@dataclass
class Choice:
    """The model of each span and why.

    ``parabola``: a span takes the parabola (bool, per span); ``error_estimate``: the chosen
    model's estimated relative error (0 for the exact model), per span; ``model``: ``"catenary"``,
    ``"parabola"`` or ``"mixed"`` (the spans differ); ``reason``: why, in words."""

    parabola: np.ndarray
    error_estimate: np.ndarray
    model: str
    reason: str

    def models(self):
        """The model of each span, an array of strings of the spans' shape."""
        return np.where(self.parabola, "parabola", "catenary")


def check_model(model, rtol):
    """``(model, rtol)`` checked: a model of `MODELS`, and ``rtol`` a positive number for
    ``"auto"`` (`RTOL` when None), refused for the others (it would be ignored)."""
    one_of("model", model, MODELS)
    if model != "auto":
        if rtol is not None:
            raise InputError("rtol", f"applies to model='auto' only (the model is {model!r})")
        return model, None
    return model, RTOL if rtol is None else positive_scalar("rtol", rtol)


def choose(model, rtol, parabola_error, n) -> Choice:
    """The choice for ``n`` spans: ``parabola_error`` the parabola's estimate of each (None for
    ``model="catenary"``, which does not form it)."""
    if model == "catenary":
        zero = np.zeros(n)
        return Choice(zero > 0, zero, "catenary", "model='catenary': the exact thermal elastic catenary")
    if model == "parabola":
        worst = f"{np.max(parabola_error):.1e}"
        reason = f"model='parabola': the parabolic change of state, estimated error up to {worst}"
        return Choice(np.ones(n, dtype=bool), parabola_error, "parabola", reason)
    chosen = parabola_error <= rtol  # NaN: the exact model
    k = int(np.count_nonzero(chosen))
    error = np.where(chosen, parabola_error, 0.0)
    if k == n:
        worst = f"{np.max(parabola_error):.1e}"
        reason = f"the parabola: its estimated error, at most {worst}, is within rtol {rtol:g}"
        return Choice(chosen, error, "parabola", reason + (f" on all {n} spans" if n > 1 else ""))
    over = parabola_error[~chosen]
    over = over[np.isfinite(over)]
    exceeds = f"{over.min():.1e}" if over.size else "not finite"
    if k == 0:
        reason = (
            f"the exact catenary: the parabola's estimated error ({exceeds} and above) exceeds rtol {rtol:g}"
        )
        return Choice(chosen, error, "catenary", reason + (f" on all {n} spans" if n > 1 else ""))
    reason = (
        f"the parabola on {k} of {n} spans (estimated error at most {np.max(parabola_error[chosen]):.1e}, "
        f"within rtol {rtol:g}); the exact catenary on the {n - k} others, where the parabola's "
        f"estimate ({exceeds} and above) exceeds it"
    )
    return Choice(chosen, error, "mixed", reason)
