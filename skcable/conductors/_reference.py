"""The unstressed length of one span (or of spans, elementwise) in a reference state of given
horizontal tension or sag: a bracketed root search on Irvine's elastic catenary (H.M. Irvine,
"Cable Structures", MIT Press, 1981, §2.2), the one-span path of `change_of_state`."""

from __future__ import annotations

import numpy as np

from skcable.cable._catenary import catenary
from skcable.cable._elastic import elastic_catenary_unchecked as elastic_catenary
from skcable.cable._roots import find_root
from skcable.errors import InputError

__all__ = ["reference_length"]


def reference_length(span, dh, w0, EA, H0, sag0):
    """Unstressed length at t0 of the elastic catenary with H0 (or sag0)."""
    if H0 is not None:
        guess = catenary(span, dh, w0, H=H0)

        def f(L0, *a):
            return elastic_catenary(*a[:4], length=L0).H / a[4] - 1.0  # decreasing in L0

        target = H0
    else:
        guess = catenary(span, dh, w0, sag=sag0)

        def f(L0, *a):
            return 1.0 - elastic_catenary(*a[:4], length=L0).sag / a[4]  # sag increases with L0

        target = sag0
    # the inextensible length: the elastic cable of that unstressed length
    # sags more; one of 4 T_max/EA less sags less (widened if not)
    hi = guess.length
    with np.errstate(over="ignore"):
        stretch = 4.0 * np.maximum(guess.T_A, guess.T_B) / EA
    if not np.all(np.isfinite(stretch) & (stretch < 1e300)):
        name = "H0" if H0 is not None else "sag0"
        raise InputError(
            name, f"strains the reference state by T/EA = {np.max(stretch) / 4:.3g}: beyond any float"
        )
    args = np.broadcast_arrays(span, dh, w0, EA, target)
    lo = hi / (1.0 + stretch)
    for _ in range(8):
        bad = np.asarray(f(lo, *args) < 0)
        if not bad.any():
            break
        lo = np.where(bad, lo / (1.0 + stretch), lo)
    L0, _ = find_root(f, lo, hi, tuple(args), what="change_of_state: reference length")
    return L0
