"""The change of state of a whole line: every span × every state in one vectorised solve.

`skcable.conductors.change_of_state` comes here when ``span`` (or ``dh``) is an array. The
reference state fixes each span's unstressed length :math:`L_0` (`_solve_z.length_z` at the
given :math:`H_0`, or the bracketed search of the one-span path at a given sag); each state is
the elastic catenary of length :math:`kL_0`, weight :math:`q/k`, stiffness :math:`EA\\,k` in the
plane of the resultant load (`skcable.conductors.thermal_catenary`), solved by
`_solve_z.solve_z` (one equation in the hyperbolic half-angle, from the parabolic change of
state, cancellation-free and in place: the conductors' own solver, for speed at 10⁴ spans).
Every element is checked by the one closure of an elastic segment, `skcable.cable.closure`
(`check_into`: the closure in H and the mean vertical tension by other formulas than the
solve's, in place); an element that fails the check is
solved again by `skcable.cable.elastic_catenary` (its own Newton and checks), which raises if
it cannot: no element is returned unchecked, none with H <= 0. The sag, the largest tension
and the loaded length come from the check's end tensions and arc.

The states are taken in passes of at most `CHUNK` elements, each in the rows of one block of
scratch (`skcable.cable._scratch.scratch`), which stays mapped from call to call.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._elastic import elastic_catenary_unchecked as elastic_catenary
from skcable.cable._scratch import scratch
from skcable.cable.closure import CHECK_ROWS, check_into, ratio_of_ends, stretched_length_into, tension_into
from skcable.conductors import _solve_z
from skcable.conductors._choice import choose
from skcable.conductors._inputs import renamed
from skcable.conductors._parabola import parabola_states
from skcable.conductors._reference import reference_length
from skcable.errors import ConvergenceError, InputError

__all__ = ["line_change_of_state", "reference_state", "sag_into", "check_finite", "CHUNK"]

#: Elements (spans × states) solved in one pass: its rows of scratch stay in the cache.
CHUNK = 1 << 14
_INPUTS = 6  # rows of a pass's data: a, h, w, EA, L and the mean vertical tension m
_RESULTS = ("H", "H_plane", "sag", "T_max", "length")


def sag_into(H, w, EA, a, h, rows, out):
    r"""The sag (largest distance chord–cable along the load) into ``out``, from the end
    tensions at A in ``rows`` (`skcable.cable.closure.check_into`'s rows 0 and 2; rows 4 to 9
    are overwritten).

    At the material point whose slope is the chord's, :math:`T_{v,s} = H h/a`, reached after
    the unstressed length :math:`s = (T_{v,s} - T_{v,A})/w`:
    :math:`x_s = Hs/EA + (H/w)\ln(p_s/p_A)`,
    :math:`y_s = s(T_{v,s} + T_{v,A})(1/(2EA) + 1/(T_s + T_A))`, the sag
    :math:`(h/a)x_s - y_s`.
    """
    tv_a, T_A = rows[0], rows[2]
    tv_s, s, T_s, P_a, u, v = rows[4:]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        np.divide(h, a, out=tv_s)
        tv_s *= H
        np.subtract(tv_s, tv_a, out=s)
        s /= w
        np.multiply(H, H, out=u)
        tension_into(tv_s, u, T_s, v)
        np.abs(tv_a, out=P_a)
        P_a += T_A
        ratio_of_ends(tv_a, tv_s, P_a, v, u, out=out)  # p_s / p_A
        out += 1.0
        out *= s
        out *= w
        np.add(T_s, T_A, out=v)
        out /= v
        np.log1p(out, out=out)  # ln(p_s / p_A)
        out *= H
        out /= w
        np.multiply(H, s, out=u)
        u /= EA
        out += u  # x_s
        np.divide(h, a, out=u)
        out *= u
        np.reciprocal(v, out=v)
        np.divide(0.5, EA, out=u)
        v += u
        tv_s += tv_a
        tv_s *= s
        tv_s *= v  # y_s
        out -= tv_s
    return out


def _robust(span, dh, w, EA, L, bad, names):
    """``(H, m)`` of the elements ``bad`` by `elastic_catenary` (refusals renamed)."""
    with renamed(names):
        sol = elastic_catenary(span[bad], dh[bad], w[bad], EA[bad], length=L[bad])
    return sol.H, 0.5 * w[bad] * L[bad] - sol.V_A


def _checked(a, h, w, EA, L, H, m, rows, ok, names):
    """Solve again the elements that are not ``ok`` (robust path), then evaluate the check
    anew: its rows feed the sag, the largest tension and the length."""
    bad = ~ok
    H[bad], m[bad] = _robust(a, h, w, EA, L, bad, names)
    with np.errstate(all="ignore"):
        ok = check_into(H, m, w, EA, L, a, h, rows)
    if not ok.all():  # elastic_catenary checks its own result: a failure here is a defect
        raise ConvergenceError("change_of_state: a state fails its closure check after the robust solve")


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
    L0, m0, ok = _solve_z.length_z(span, dh, w0, EA, H0)
    rows = np.empty((CHECK_ROWS, span.size))
    with np.errstate(all="ignore"):
        ok &= check_into(H0, m0, w0, EA, L0, span, dh, rows)
        ok &= (L0 > 0) & np.isfinite(L0)
    if not ok.all():  # the bracketed search of the one-span path, elementwise
        bad = ~ok
        with renamed({"H": "H0", "w": "w0", "length": "H0"}):
            L0[bad] = reference_length(span[bad], dh[bad], w0, EA, H0[bad], None)
            ref = elastic_catenary(span[bad], dh[bad], w0, EA, length=L0[bad])
        m0[bad] = 0.5 * w0 * L0[bad] - ref.V_A
        check_into(H0, m0, w0, EA, L0, span, dh, rows)
    sag0 = sag_into(H0, w0, EA, span, dh, rows, np.empty(span.size))
    if not np.isfinite(sag0).all():
        raise ConvergenceError("change_of_state: non-finite sag0 for these data")
    return L0, m0, H0, sag0


def _pass(spans, dhs, L0, states, out, names):
    """The states of the spans ``spans`` (a pass of ``m × spans.size`` elements, laid out
    state by state) into ``out``, rows ``H, H_plane, sag, T_max, length`` of shape
    ``(m, spans.size)``."""
    q, w_k, EA_k, k, dh_scale, wind_scale = states
    n, m = spans.size, k.size
    with scratch(_INPUTS + len(_RESULTS) + max(_solve_z.ROWS, CHECK_ROWS), m * n) as block:
        a, h, w, EA, L, mm = block[:_INPUTS]
        H, H_plane, sag, T_max, length = block[_INPUTS : _INPUTS + len(_RESULTS)]
        work = block[_INPUTS + len(_RESULTS) :]
        grid = (m, n)
        np.multiply(dh_scale[:, None], dhs[None, :], out=h.reshape(grid))  # dh in the load's plane
        if wind_scale is None:
            np.copyto(a.reshape(grid), spans[None, :])
        else:  # span_p² = span² + (dh wind/q)², without squaring the span
            np.multiply(wind_scale[:, None], dhs[None, :], out=a.reshape(grid))
            np.hypot(a.reshape(grid), spans[None, :], out=a.reshape(grid))
        np.copyto(w.reshape(grid), w_k[:, None])
        np.copyto(EA.reshape(grid), EA_k[:, None])
        np.multiply(k[:, None], L0[None, :], out=L.reshape(grid))
        chord = np.sqrt(spans * spans + dhs * dhs)  # the plane turns about the chord
        ok = _solve_z.solve_z(
            a, h, w, EA, L, H_plane, mm, work, chord=np.broadcast_to(chord, grid).reshape(-1)
        )
        rows = work[:CHECK_ROWS]
        with np.errstate(all="ignore"):
            ok &= check_into(H_plane, mm, w, EA, L, a, h, rows)
        if not ok.all():
            _checked(a, h, w, EA, L, H_plane, mm, rows, ok, names)
        np.maximum(rows[2], rows[3], out=T_max)
        stretched_length_into(H_plane, w, EA, L, rows, out=length)
        sag_into(H_plane, w, EA, a, h, rows, out=sag)
        if wind_scale is None:
            np.copyto(H, H_plane)
        else:  # H along the span from H in the plane
            np.multiply(H_plane.reshape(grid), spans[None, :], out=H.reshape(grid))
            H /= a
        for row, result in zip(out, (H, H_plane, sag, T_max, length), strict=True):
            np.copyto(row, result.reshape(grid))


def catenary_states(spans, dhs, L0, EA, w, wind, k, names):
    """The exact states of a line (flat arrays: ``n`` spans, ``m`` states): a dict of the
    results `_RESULTS`, each an ``(n, m)`` view (state-major in memory, as solved)."""
    q = np.hypot(w, wind)
    windy = bool(np.any(wind))
    states = (q, q / k, EA * k, k, w / q, wind / q if windy else None)
    out = np.empty((len(_RESULTS), k.size, spans.size))
    step = max(1, CHUNK // k.size)
    for lo in range(0, spans.size, step):
        part = slice(lo, lo + step)
        _pass(spans[part], dhs[part], L0[part], states, out[:, :, part], names)
    results = dict(zip(_RESULTS, out.transpose(0, 2, 1), strict=True))
    if not np.isfinite(out).all():  # one pass over the block; the name only on failure
        check_finite(results)
    return results


def check_finite(results):
    """Raise `ConvergenceError` naming the first result that is not finite everywhere."""
    for key, result in results.items():
        if not np.isfinite(result).all():
            raise ConvergenceError(f"change_of_state: non-finite {key} for these data")


def line_change_of_state(span, dh, EA, alpha, w0, t0, ref, w, t, wind, k, model, rtol=None):
    """`change_of_state` of spans of shape ``lead`` (arrays) over states of shape ``shape``:
    a dict of its results, each of shape ``lead + shape`` (``L0, H0, sag0`` and the choice's
    ``error_estimate`` and ``models`` of ``lead``), and the `Choice` (`skcable.conductors._choice`)."""
    lead = np.broadcast_shapes(np.shape(span), np.shape(dh))
    shape = np.shape(w)
    spans, dhs = (np.broadcast_to(v, lead).ravel().astype(float) for v in (span, dh))
    value, name = ref
    value = np.broadcast_to(value, lead).ravel().astype(float)
    wf, tf, windf = (np.ravel(v) for v in (w, t, wind))
    kf = np.broadcast_to(k, shape).ravel()
    par = None
    if model != "catenary":
        H0, sag0 = (value, None) if name == "H0" else (None, value)
        par = parabola_states(spans, dhs, EA, alpha, w0, t0, H0, sag0, wf, tf, windf)
    choice = choose(model, rtol, None if par is None else par.error, spans.size)
    if par is not None:
        out = {key: getattr(par, key) for key in _RESULTS}
        check_finite(out if choice.parabola.all() else {k: v[choice.parabola] for k, v in out.items()})
        L0, H0_out, sag0_out = par.L0, par.H0, par.sag0
    exact = np.flatnonzero(~choice.parabola)
    if exact.size:
        names = {"H": "w", "length": name}
        L0_e, _, H0_e, sag0_e = reference_state(spans[exact], dhs[exact], w0, EA, value[exact], name)
        solved = catenary_states(spans[exact], dhs[exact], L0_e, EA, wf, windf, kf, names)
        if par is None:
            out, L0, H0_out, sag0_out = solved, L0_e, H0_e, sag0_e
        else:
            for key, result in solved.items():
                out[key][exact] = result
            L0[exact], H0_out[exact], sag0_out[exact] = L0_e, H0_e, sag0_e
    blowout = np.arctan2(windf, wf)  # finite: w >= the smallest normal float, wind finite
    out["blowout"] = np.broadcast_to(blowout, (spans.size, kf.size)).copy()
    out = {key: result.reshape(*lead, *shape) for key, result in out.items()}
    for key, result in (("L0", L0), ("H0", H0_out), ("sag0", sag0_out)):
        out[key] = np.asarray(result, dtype=float).reshape(lead)
    out["error_estimate"] = choice.error_estimate.reshape(lead)
    out["models"] = choice.models().reshape(lead)
    return out, choice
