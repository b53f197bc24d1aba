"""The change of state of a whole line: every span × every state in one vectorised solve.

`skcable.cable.change_of_state` comes here when ``span`` (or ``dh``) is an array. The
reference state fixes each span's unstressed length :math:`L_0` (`_grid.reference_lengths` at
the given :math:`H_0`, or the bracketed search of the one-span path at a given sag); each
state is the elastic catenary of length :math:`kL_0`, weight :math:`q/k`, stiffness
:math:`EA\\,k` in the plane of the resultant load (`skcable.cable.thermal_catenary`),
started from the parabolic change of state and solved by `_grid.solve_spans`. Every element
is checked by `_grid.closure_residual` (formulas other than the solve's); an element that
fails the check is solved again by `skcable.cable.elastic_catenary` (its own Newton and
checks), which raises if it cannot: no element is returned unchecked, none with H <= 0.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._elastic import elastic_catenary
from skcable.cable.conductors._grid import (
    closure_residual,
    reference_lengths,
    sag_of,
    solve_spans,
    start_tension,
    stretched_length_of,
)
from skcable.cable.conductors._inputs import load_plane, renamed
from skcable.cable.conductors._parabola import parabola_states
from skcable.cable.conductors._reference import reference_length
from skcable.errors import ConvergenceError, InputError

__all__ = ["line_change_of_state", "reference_state"]


def _robust(span, dh, w, EA, L, bad, names):
    """``(H, m)`` of the elements ``bad`` by `elastic_catenary` (refusals renamed)."""
    with renamed(names):
        sol = elastic_catenary(span[bad], dh[bad], w[bad], EA[bad], length=L[bad])
    return sol.H, 0.5 * w[bad] * L[bad] - sol.V_A


def _checked(span, dh, w, EA, L, H, m, names):
    """Replace the elements that fail the independent closure check by a robust solve."""
    with np.errstate(all="ignore"):
        residual, bound = closure_residual(H, m, w, EA, L, span, dh)
        bad = ~((residual <= bound) & (H > 0) & np.isfinite(H) & np.isfinite(m))
    if bad.any():
        H, m = H.copy(), m.copy()
        H[bad], m[bad] = _robust(span, dh, w, EA, L, bad, names)
    return H, m


def _solve(span, dh, w, EA, L, start, names):
    """Spans of unstressed length ``L`` (flat arrays), checked; a failed vectorised Newton
    leaves every element to the robust path."""
    try:
        with np.errstate(all="ignore"):
            H, m = solve_spans(span, dh, w, EA, L, H=start)
    except ConvergenceError:
        H, m = np.full(span.shape, np.nan), np.zeros(span.shape)
    return _checked(span, dh, w, EA, L, H, m, names)


def reference_state(span, dh, w0, EA, value, name):
    """``L0, m0, H0, sag0`` of the reference state per span (flat arrays): ``value`` is the
    horizontal tension (``name="H0"``) or the sag (``"sag0"``) of each span."""
    if name == "sag0":
        with renamed({"H": "sag0", "sag": "sag0", "w": "w0", "length": "sag0"}):
            L0 = np.asarray(reference_length(span, dh, w0, EA, None, value), dtype=float)
            ref = elastic_catenary(span, dh, w0, EA, length=L0)
        return L0, 0.5 * w0 * L0 - ref.V_A, ref.H, ref.sag
    H0 = value
    with np.errstate(over="ignore"):
        reach = 0.5 * w0 * span / H0
    if not np.all(reach < 700.0):
        raise InputError("H0", "makes a span so slack that span·w0/(2 H0) exceeds 700 (cosh overflows)")
    try:
        with np.errstate(all="ignore"):
            L0, m0 = reference_lengths(span, dh, w0, EA, H0)
            residual, bound = closure_residual(H0, m0, w0, EA, L0, span, dh)
        bad = ~((residual <= bound) & (L0 > 0) & np.isfinite(L0))
    except ConvergenceError:
        L0, m0, bad = np.full(span.shape, np.nan), np.zeros(span.shape), np.ones(span.shape, bool)
    if bad.any():  # the bracketed search of the one-span path, elementwise
        with renamed({"H": "H0", "w": "w0", "length": "H0"}):
            L0[bad] = reference_length(span[bad], dh[bad], w0, EA, H0[bad], None)
            ref = elastic_catenary(span[bad], dh[bad], w0, EA, length=L0[bad])
        m0[bad] = 0.5 * w0 * L0[bad] - ref.V_A
    return L0, m0, H0, sag_of(H0, m0, w0, EA, L0, span, dh)


def line_change_of_state(span, dh, EA, alpha, w0, t0, ref, w, t, wind, k, model):
    """`change_of_state` of spans of shape ``lead`` (arrays) over states of shape ``shape``:
    a dict of its results, each of shape ``lead + shape`` (``L0, H0, sag0`` of ``lead``)."""
    lead = np.broadcast_shapes(np.shape(span), np.shape(dh))
    shape = np.shape(w)
    spans, dhs = (np.broadcast_to(v, lead).ravel().astype(float) for v in (span, dh))
    value, name = ref
    value = np.broadcast_to(value, lead).ravel().astype(float)
    wf, tf, windf = (np.ravel(v) for v in (w, t, wind))
    kf = np.broadcast_to(k, shape).ravel()
    q, span_p, dh_p = load_plane(spans[:, None], dhs[:, None], wf[None, :], windf[None, :])
    if model == "parabola":
        H0, sag0 = (value, None) if name == "H0" else (None, value)
        L0, H0_out, sag0_out, H_plane, sag, T_max, length = parabola_states(
            spans[:, None], dhs[:, None], EA, alpha, w0, t0, None if H0 is None else H0[:, None],
            None if sag0 is None else sag0[:, None], tf[None, :], q, span_p, dh_p,
        )  # fmt: skip
        L0, H0_out, sag0_out = (np.broadcast_to(v, (spans.size, 1))[:, 0] for v in (L0, H0_out, sag0_out))
    else:
        L0, _, H0_out, sag0_out = reference_state(spans, dhs, w0, EA, value, name)
        shape2 = span_p.shape
        L = (L0[:, None] * kf[None, :]).ravel()
        wk = np.broadcast_to(q / kf[None, :], shape2).ravel()
        EAk = np.broadcast_to(EA * kf[None, :], shape2).ravel()
        sp, dp = span_p.ravel(), dh_p.ravel()
        with np.errstate(all="ignore"):
            start = start_tension(sp, dp, wk, EAk, L)
        H_p, m = _solve(sp, dp, wk, EAk, L, start, {"H": "w", "length": name})
        sag = sag_of(H_p, m, wk, EAk, L, sp, dp)
        T_max = np.sqrt(H_p * H_p + (np.abs(m) + 0.5 * wk * L) ** 2)
        length = stretched_length_of(H_p, m, wk, EAk, L)
        H_plane, sag, T_max, length = (v.reshape(shape2) for v in (H_p, sag, T_max, length))
    H = H_plane * spans[:, None] / span_p
    blowout = np.broadcast_to(np.arctan2(windf, wf), H.shape)
    out = dict(H=H, H_plane=H_plane, sag=sag, T_max=T_max, length=length, blowout=blowout)
    for key, value in out.items():
        if not np.all(np.isfinite(value)):
            raise ConvergenceError(f"change_of_state: non-finite {key} for these data")
    out = {key: np.ascontiguousarray(value).reshape(*lead, *shape) for key, value in out.items()}
    for key, value in (("L0", L0), ("H0", H0_out), ("sag0", sag0_out)):
        out[key] = np.asarray(value, dtype=float).reshape(lead)
    return out
