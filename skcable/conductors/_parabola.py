r"""The parabolic change-of-state equation over spans × states, and its error against the exact
catenary, estimated.

The equation (`skcable.conductors.change_of_state`: CIGRE TB 324, "Sag-tension calculation
methods for overhead lines", 2007; F. Kiessling et al., "Overhead Power Lines", Springer, 2003),
in the plane of the resultant load ``q``, span ``a`` in that plane, chord ``c``, ``C = cos psi =
a/c``:

.. math:: \varepsilon - \varepsilon_0 + \theta + e_0 - e = 0, \qquad
          e = \frac{(q a C)^2}{24 H^2}, \quad \varepsilon = \frac{H}{EA\,C}, \quad
          \theta = \alpha (t - t_0),

``e`` the parabola's excess of the length over the chord and ``epsilon`` its strain (index 0:
the reference state), i.e. ``H³ + b H² - d = 0``. It keeps the first term of each expansion
the exact model (the thermal elastic catenary, `skcable.conductors.thermal_catenary`) makes in
powers of ``z = q a/(2H)``, and drops the products of the small strains.

Error estimate
--------------
With the exact excess :math:`E = \sqrt{1 + C^2(2\varphi + \varphi^2)} - 1`,
:math:`\varphi = \sinh z/z - 1` (H.M. Irvine, "Cable Structures", 1981, §2.1), the exact mean
tension over the arc :math:`\bar T = H[z/(2\cosh m\sinh z) + \cosh 2m\cosh z/(2\cosh m)]` and the
load per stretched length :math:`q/(1 + \theta + \bar T/EA)`, the exact model's state satisfies,
to the second order in the small quantities,

.. math::
    \Phi(H_e) - \Phi(H_p) = \Delta = \delta\tau - \delta\tau_0 + X(e_0 - \varepsilon_0)
    + 2e(\theta + \varepsilon) - 2e_0\varepsilon_0 + \delta e_0 - \delta e - \eta(2e_0 + \varepsilon_0),

with :math:`\Phi = e - \varepsilon` (so that :math:`H_e/H_p - 1 = -\Delta/(2e + \varepsilon)`),
:math:`X = \theta + \varepsilon - \varepsilon_0`, the excess the parabola leaves out
:math:`\delta e = e z^2 (1/20 + S^2/12)` (``S = sin psi``), the mean strain it leaves out
:math:`\delta\tau = \varepsilon z^2 G`, :math:`G = -C^4/12 + (1 + S^2)/4 + (1 + S^2)S^2/12 -
S^2/3`, and, when the reference is a sag, the error of its tension
:math:`\eta = -\varepsilon_0 + s_0 z_0^2` (the catenary's sag exceeds the parabola's
:math:`qa^2/(8HC)` by :math:`s z^2`, :math:`s = (5C^2 - 2)/36`). Of the other results: the
sag by :math:`-e_H - (\theta + \varepsilon) + s z^2`, the largest tension by
:math:`e_H + v\,\delta v/(1 + v^2)` (``v = |tan psi| + z/C`` the parabola's V/H,
:math:`\delta v = -z(\theta + \varepsilon)/C + |\tan\psi| z^2/3 + C z^3/6`), the length by
:math:`\delta e_0 - 2e_0(\varepsilon_0 + \eta) + \delta\tau - \delta\tau_0 + X(e_0 -
\varepsilon_0) + \varepsilon e_H`, the reference's sag (or tension) by :math:`-\varepsilon_0 +
s_0 z_0^2`. The estimate of a span is `SAFETY` times the largest of these over its states and
results (the leading terms; on random lines the true error stays below 1.25 times them,
``tests/conductors/test_choice.py``), plus `FLOOR`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import TINY
from skcable.cable._scratch import scratch
from skcable.errors import ConvergenceError, InputError

__all__ = ["FLOOR", "SAFETY", "ParabolaStates", "parabola_states", "parabolic_cubic"]

#: The estimate's margin over its leading terms (the true error stays below 1.25 times them on
#: random lines: the next terms are smaller by another z² or strain).
SAFETY = 1.5
#: Added to every estimate: the round-off of the two models' solves (about 1e-15).
FLOOR = 1e-13
_ROWS = 18  # rows of scratch of a line's states


@dataclass
class ParabolaStates:
    """The parabolic change of state of ``n`` spans in ``m`` states: ``L0, H0, sag0`` and
    ``error`` (the estimate of each span, module text) of shape ``(n,)``; ``H, H_plane, sag,
    T_max, length`` of shape ``(n, m)``."""

    L0: np.ndarray
    H0: np.ndarray
    sag0: np.ndarray
    H: np.ndarray
    H_plane: np.ndarray
    sag: np.ndarray
    T_max: np.ndarray
    length: np.ndarray
    error: np.ndarray


def parabolic_cubic(b, d, rtol=1e-8, out=None, rows=None):
    """The positive root of ``H³ + b H² - d = 0`` (``d > 0``), elementwise, into ``out``.

    With ``c = d^(1/3)``, ``H = c/f`` and ``f³ - x f - 1 = 0``, ``x = b/c``; ``f`` is guessed
    as ``sqrt(x + 1/sqrt(1 + x))`` for ``x >= 0`` (within 1.6 %) and ``1/(y + (1 + y/3)^-2)``,
    ``y = -x``, below (within 7.1 %; the guess of `skcable.conductors._solve_z`). The root
    exceeds ``max(0, -b)``, where the cubic is convex: from the guess, refined by two steps of
    Newton's method on ``f`` (within 3.2e-6), Newton's method on ``H`` steps above the root and
    then decreases to it, until every relative step is below ``rtol`` (quadratic convergence:
    the error is then about its square, round-off). ``rows``: four arrays of scratch of ``b``'s
    shape, or None.
    """
    b, d = np.broadcast_arrays(np.asarray(b, dtype=float), np.asarray(d, dtype=float))
    H = np.empty(b.shape) if out is None else out
    c, f, u, y = np.empty((4, *b.shape)) if rows is None else rows
    np.cbrt(d, out=c)
    np.divide(b, c, out=y)  # x
    np.maximum(y, 0.0, out=u)
    np.add(u, 1.0, out=f)
    np.sqrt(f, out=f)
    np.divide(1.0, f, out=f)
    f += u
    np.sqrt(f, out=f)  # the guess where x >= 0 (1 elsewhere)
    np.negative(y, out=y)
    np.maximum(y, 0.0, out=y)  # y = max(-x, 0)
    np.multiply(y, 1.0 / 3.0, out=u)
    u += 1.0
    u *= u  # (1 + y/3)²
    f *= u
    u *= y
    u += 1.0
    f /= u  # times 1/(y + (1 + y/3)^-2): the guess where x < 0 (1 where x >= 0)
    np.negative(y, out=y)
    np.minimum(y, 0.0, out=y)  # min(x, 0) ...
    y += np.maximum(b / c, 0.0, out=u)  # ... + max(x, 0): x again
    for _ in range(2):  # f³ - x f - 1 is convex and increasing about its positive root
        np.multiply(f, f, out=u)
        np.multiply(u, 3.0, out=H)
        H -= y
        u -= y
        u *= f
        u -= 1.0
        u /= H
        f -= u
    np.divide(c, f, out=H)
    history = []
    two_b = np.multiply(b, 2.0, out=c)
    for _ in range(60):
        np.add(H, b, out=f)
        np.multiply(H, H, out=u)
        f *= u
        f -= d  # the cubic
        np.multiply(H, 3.0, out=u)
        u += two_b
        u *= H  # its derivative
        f /= u
        H -= f
        f /= H
        np.abs(f, out=f)
        history.append(float(np.max(f)))
        if history[-1] <= rtol:
            return H
    raise ConvergenceError("parabolic change of state: Newton on the cubic did not converge", history)


def _square(x):
    """``x * x``: a Python float's ``x**2`` raises OverflowError where the product is inf (refused
    by the checks that follow, naming an argument)."""
    return x * x


def _reference(spans, dhs, EA, w0, H0, sag0):
    """``chord, cos0, H0, sag0, excess0, L0`` of the spans' reference (flat arrays), refused
    naming ``H0`` or ``sag0`` where it leaves the float range or strains the cable beyond its
    length."""
    chord = np.hypot(spans, dhs)
    cos0 = spans / chord
    name = "H0" if sag0 is None else "sag0"
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
        if H0 is None:  # products, not powers: a float's ** raises on overflow
            H0 = w0 * spans * spans / (8.0 * sag0 * cos0)
        sag0_out = w0 * spans * spans / (8.0 * H0 * cos0)
    if not np.all(np.isfinite(H0) & (H0 >= TINY) & np.isfinite(sag0_out) & (sag0_out >= TINY)):
        raise InputError(
            name,
            "gives a parabolic reference state (H0 = w0 span^2/(8 sag0 cos psi)) outside the range "
            "of a float",
        )
    with np.errstate(over="ignore", invalid="ignore"):
        excess0 = _square(w0 * spans * cos0) / (24.0 * _square(H0))  # (S0 - c) / c
        L0 = chord * (1.0 + excess0) - H0 * chord / (EA * cos0)
    if not np.all(L0 > 0):
        strain = np.max(H0 / (EA * cos0))
        raise InputError(
            name,
            "the reference state stretches the cable by more than its length (H0/(EA cos psi) "
            f"= {strain:.3g}): the parabolic equation, a small-strain form, does not apply",
        )
    return chord, cos0, H0, sag0_out, excess0, L0


def parabola_states(spans, dhs, EA, alpha, w0, t0, H0, sag0, w, t, wind) -> ParabolaStates:
    """The parabolic change of state (module text) of ``n`` spans (``spans``, ``dhs`` and the
    reference ``H0`` or ``sag0``, flat arrays; the other None) in ``m`` states (``w``, ``t``,
    ``wind``, flat arrays), with the estimate of its error against the exact model, every
    state worked in place in rows of scratch laid out state by state (a span's value is the
    same along a row: NumPy's loops run over the spans), the results copied at the end into
    ``(n, m)`` arrays."""
    chord, cos0, H0, sag0_out, excess0, L0 = _reference(spans, dhs, EA, w0, H0, sag0)
    n, m = spans.size, w.size
    q = np.hypot(w, wind)[:, None]
    windy = bool(np.any(wind))
    span_r, chord_r, cos0_r = spans[None, :], chord[None, :], cos0[None, :]
    with scratch(_ROWS, n * m) as block, np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        rows = block.reshape(_ROWS, m, n)
        span_p, cos, b, d, qa = rows[:5]
        H, H_plane, sag, T_max, length = solved = rows[13:18]
        if windy:  # span_p² = span² + (dh wind/q)²: the span in the load's plane
            np.multiply((wind[:, None] / q), dhs[None, :], out=span_p)
            np.hypot(span_p, span_r, out=span_p)
            np.divide(span_p, chord_r, out=cos)
        else:
            span_p, cos = span_r, cos0_r
        np.add(excess0[None, :], alpha * (t[:, None] - t0), out=b)
        b *= EA
        b *= cos
        if windy:
            np.divide(cos, cos0_r, out=d)
            d *= H0[None, :]
            b -= d
        else:
            b -= H0[None, :]
        np.multiply(q, span_p, out=qa)
        qa *= cos  # q a C
        np.multiply(qa, qa, out=d)
        d *= cos
        d *= EA / 24.0
        parabolic_cubic(b, d, out=H_plane, rows=rows[5:9])
        if windy:  # dh in the load's plane
            dh_p = np.multiply((w[:, None] / q), dhs[None, :], out=b)
        else:
            dh_p = dhs[None, :]
        plane = (q, span_p, cos, qa, dh_p)
        _results(H_plane, plane, chord_r, (H, sag, T_max, length), rows[5:9], span_r if windy else None)
        reference = (spans, dhs, chord, cos0, H0, excess0, w0, sag0 is not None)
        error = _error(H_plane, plane, reference, EA, alpha * (t - t0), rows[5:13])
        out = np.empty((5, n, m))
        np.copyto(out.transpose(0, 2, 1), solved)
    return ParabolaStates(L0, H0, sag0_out, out[0], out[1], out[2], out[3], out[4], error)


def _results(H_plane, plane, chord, out, rows, spans):
    """``H`` (along the span: ``spans`` given, when the plane turned), the sag ``q a²/(8 H C)``,
    the largest tension ``hypot(H, H |tan psi| + q a/(2C))`` and the loaded length
    ``c (1 + e)`` into ``out``; ``plane``: ``q`` and the rows ``a, C, q a C, dh`` in the load's
    plane (states by spans)."""
    H, sag, T_max, length = out
    q, span_p, cos, qa, dh_p = plane
    u, v = rows[:2]
    if spans is None:
        np.copyto(H, H_plane)
    else:
        np.multiply(H_plane, spans, out=H)
        H /= span_p
    np.multiply(H_plane, cos, out=u)
    u *= 8.0
    np.multiply(span_p, span_p, out=sag)
    sag *= q
    sag /= u
    np.divide(dh_p, span_p, out=u)
    np.abs(u, out=u)
    u *= H_plane
    np.multiply(q, span_p, out=v)
    v /= cos
    v *= 0.5
    u += v  # V
    if float(np.max(u)) < 1e150 and float(np.max(H_plane)) < 1e150:  # the squares are finite
        np.multiply(u, u, out=T_max)
        np.multiply(H_plane, H_plane, out=v)
        T_max += v
        np.sqrt(T_max, out=T_max)
    else:
        np.hypot(H_plane, u, out=T_max)
    np.divide(qa, H_plane, out=u)
    u *= u
    u *= 1.0 / 24.0  # e
    u += 1.0
    np.multiply(u, chord, out=length)


def _shape_terms(cos, sin2):
    """``G`` and ``s`` (module text) of the chords of cosine ``cos`` and squared sine ``sin2``."""
    cos2 = cos * cos
    G = (1.0 + sin2) * (0.25 + sin2 / 12.0) - sin2 / 3.0 - cos2 * cos2 / 12.0
    return G, (5.0 * cos2 - 2.0) / 36.0


def _reference_terms(reference, EA):
    """The reference's terms of the estimate (module text), per span: ``eps0``, ``e0 - eps0``,
    the constant parts of Delta and of the length's error, and the reference's own error."""
    spans, dhs, chord, cos0, H0, e0, w0, sag_given = reference
    z0 = w0 * spans / (2.0 * H0)
    z02, eps0 = z0 * z0, H0 / (EA * cos0)
    sin02 = (dhs / chord) ** 2
    G0, s0 = _shape_terms(cos0, sin02)
    de0, dt0 = e0 * z02 * (1.0 / 20.0 + sin02 / 12.0), eps0 * z02 * G0
    ref = s0 * z02 - eps0  # the reference's sag (H0 given) or tension (sag0 given)
    eta = ref if sag_given else 0.0
    constant = de0 - dt0 - 2.0 * e0 * eps0 - eta * (2.0 * e0 + eps0)
    length = de0 - dt0 - 2.0 * e0 * (eps0 + eta)
    return eps0, e0 - eps0, constant, length, np.abs(ref)


def _error(H, plane, reference, EA, theta, rows):
    """The estimate (module text) of each span: the largest leading error term over its states
    and results, times `SAFETY`, plus `FLOOR`; ``rows``: eight rows of scratch of the states."""
    q, span_p, cos, qa, dh_p = plane
    eps0, m0, K0, L0s, ref = (v[None, :] for v in _reference_terms(reference, EA))
    sin2 = dh_p / reference[2][None, :]
    sin2 = sin2 * sin2
    G, s = _shape_terms(cos, sin2)
    inv_cos = 1.0 / cos
    tan3 = np.abs(dh_p) / span_p / 3.0
    z, a, eps, te, D, X, b, c = rows[:8]
    np.multiply(q, span_p, out=z)
    z /= H
    z *= 0.5  # z = q a/(2H)
    np.multiply(z, z, out=a)  # z²
    np.multiply(a, cos * cos / 6.0, out=b)  # e = C² z²/6
    np.multiply(H, inv_cos / EA, out=eps)  # epsilon
    np.add(theta[:, None], eps, out=te)  # theta + epsilon
    np.subtract(te, eps0, out=X)
    X *= m0  # X (e0 - eps0)
    np.multiply(eps, G, out=D)
    D *= a  # delta tau
    np.multiply(b, 1.0 / 20.0 + sin2 / 12.0, out=c)
    c *= a  # delta e
    np.subtract(X, c, out=c)
    c += D
    c += K0
    np.multiply(b, te, out=eps)  # e (theta + eps) ...
    eps += eps
    c += eps  # Delta
    np.multiply(H, inv_cos / EA, out=eps)  # epsilon again
    b += b
    b += eps
    c /= b  # -e_H
    D += X
    D += L0s
    np.multiply(eps, c, out=b)
    D -= b  # the length's error
    np.abs(D, out=D)
    np.abs(c, out=b)
    np.maximum(D, b, out=D)
    np.multiply(a, s, out=b)
    b -= te
    b += c  # the sag's
    np.abs(b, out=b)
    np.maximum(D, b, out=D)
    np.multiply(z, inv_cos, out=eps)  # z/C
    np.multiply(eps, te, out=X)
    np.multiply(a, tan3, out=b)
    b -= X
    np.multiply(z, a, out=X)
    X *= cos / 6.0
    b += X  # delta v
    eps += 3.0 * tan3  # v
    b *= eps
    eps *= eps
    eps += 1.0
    b /= eps
    b -= c  # the largest tension's
    np.abs(b, out=b)
    np.maximum(D, b, out=D)
    error = np.maximum(np.maximum.reduce(D, axis=0), ref[0])
    error *= SAFETY
    error += FLOOR
    return error
