"""The vectorised catenary: many spans solved, evaluated and checked in passes that stay in cache.

`skcable.cable.catenary` on float64 arrays of one shape comes here (``length=`` and ``H=``). The
formulas are those of `skcable.cable._catenary` (H.M. Irvine, *Cable Structures*, 1981, §2.1;
Goicolea 2012, eq. 17) and the root of ``sinh(z)/z = 1 + rho`` is found as in
`skcable.cable._hanging` (the Padé start, then Halley's method), and every element is checked by
the residual of `skcable.cable._catenary.Catenary`. What changes is the order of the work: the
spans are taken in passes of at most `CHUNK` elements, and each pass runs the whole pipeline
(the excess, the start, Halley's step, the forces, the residual) in the rows of one block of
scratch. A new array of 10⁶ floats costs more than the arithmetic on it, and a row of `CHUNK`
floats stays in the processor's cache from one operation to the next; the peak memory is the
results' own plus one block.
"""

from __future__ import annotations

import math

import numpy as np

from skcable.cable._hanging import PADE_DEN, PADE_NUM, RHO_LIMIT, STEP_TOL, Z_LIMIT, Z_MIN
from skcable.cable._scratch import scratch
from skcable.cable._special import SINHC_SERIES, largest_abs
from skcable.errors import ConvergenceError

__all__ = ["CHUNK", "halley_step", "start", "iterate", "forces_into", "residual_rows", "of_length", "of_H"]

#: Elements in one pass: a row of them (128 kB) and the block's dozen rows stay in cache.
CHUNK = 1 << 14
_MAX, _MIN = np.maximum.reduce, np.minimum.reduce
_SQRT_HALF = math.sqrt(0.5)
_MAX_FLOAT = float(np.finfo(float).max)
#: Terms of the series of sinh(z)/z - 1 enough below each z² (`skcable.cable._special.sinhc_pair`).
_TERMS = ((0.01, 5), (0.1, 7), (1.0, 9))
#: Largest iterations of Halley's method before `iterate` gives up.
_MAX_STEPS = 100
#: The Padé approximant's coefficients of each power, highest first, as columns (numerator,
#: denominator) for Horner's rule on the two at once.
_PADE = np.array([PADE_NUM, PADE_DEN]).T[:, :, None].copy()


def start(rho, out=None, scratch=None, top=None):
    """A start for the root of ``sinh(z)/z = 1 + rho`` (``rho > 0``, an array), elementwise:
    `skcable.cable._hanging.start` on arrays (the Padé approximant below ``rho = 1``, three
    fixed-point steps of the asymptote above); ``scratch``: two rows of ``rho``'s size, or None;
    ``top``: the largest ``rho``, if the caller has it."""
    z = np.empty(rho.shape) if out is None else out
    both = np.empty((2, rho.size)) if scratch is None else scratch.reshape(2, -1)  # num., den.
    top = float(_MAX(rho, axis=None)) if top is None else top
    small = (rho if top < 1.0 else np.minimum(rho, 1.0)).reshape(-1)
    np.multiply(small, _PADE[0], out=both)  # Horner's rule on the two at once
    both += _PADE[1]
    for c in _PADE[2:]:
        both *= small
        both += c
    num, den = both
    num *= small
    np.divide(num, den, out=z.reshape(-1))
    np.sqrt(z, out=z)
    if top >= 1.0:
        big = np.flatnonzero(rho >= 1.0)
        y = np.log1p(rho.reshape(-1)[big])
        zb = y + np.log(2.0 * (y + 1.0))
        zb = y + np.log(2.0 * zb)
        z.reshape(-1)[big] = y + np.log(2.0 * zb)
    return z


def _phi_into(z, t, phi, scratch, z_min, z_max):
    """``sinh(z)/z - 1`` into ``phi`` (``t`` holds ``z²``, and ``z`` lies in ``[z_min, z_max]``):
    its Maclaurin series where ``z < 1`` (as many terms as the largest ``z²`` there needs,
    `_TERMS`), ``sinh(z)/z - 1`` elsewhere (`skcable.cable._special.sinhc_m1`)."""
    if z_min >= 1.0:
        np.sinh(z, out=phi)
        phi /= z
        phi -= 1.0
        return phi
    top = min(z_max * z_max, 0.99)
    coefficients = SINHC_SERIES[-next(n for bound, n in _TERMS if top < bound) :]
    np.multiply(t, coefficients[0], out=phi)
    phi += coefficients[1]
    for c in coefficients[2:]:
        phi *= t
        phi += c
    phi *= t
    if z_max >= 1.0:  # mixed: the direct form where z >= 1
        np.sinh(z, out=scratch)
        scratch /= z
        scratch -= 1.0
        np.copyto(phi, scratch, where=z >= 1.0)
    return phi


def halley_step(z, rho, rows, near=False):
    r"""The step of Halley's method for :math:`g(z) = \log(\sinh z/z) - \operatorname{log1p}
    \rho` into ``rows[0]`` (returned), elementwise, ``rows`` six rows of scratch of ``z``'s
    size: the step of `skcable.cable._hanging.step` (Newton's where Halley's correction exceeds
    one half), with :math:`g = \operatorname{log1p}((\varphi - \rho)/(1 + \rho))`.

    :math:`g' = \varphi'/(1 + \varphi)` with :math:`\varphi' = (2\sinh^2(z/2) - \varphi)/z`
    (the derivative of :math:`\sinh z/z`, :math:`(\cosh z - 1 - \varphi)/z`; it loses at
    most two bits, which move the step by 1e-16 of itself: the root is set by :math:`g`,
    whose :math:`\varphi` is accurate to an ulp). Above ``z = 20`` or below ``1e-150`` (where
    ``z²`` underflows) `_far_step`. ``near``: the caller vouches that ``z`` lies within 1e-7 of
    the root (the Padé start), where Halley's correction is about that small: Newton's step is
    not looked for.
    """
    z_min, z_max = float(_MIN(z, axis=None)), float(_MAX(z, axis=None))
    if not (1e-150 <= z_min and z_max <= 20.0):
        rows[0] = _far_step(z, rho)
        return rows[0]
    step, phi, slope, A, t, c = rows[:6]
    np.multiply(z, z, out=t)
    _phi_into(z, t, phi, slope, z_min, z_max)
    np.multiply(z, 0.5, out=slope)
    np.sinh(slope, out=slope)
    np.multiply(slope, slope, out=slope)
    slope *= 2.0
    slope -= phi
    slope /= z  # phi'
    np.subtract(phi, rho, out=A)
    np.add(rho, 1.0, out=c)
    A /= c
    np.log1p(A, out=A)  # g
    np.add(phi, 1.0, out=step)
    step *= A
    step /= slope  # Newton's step, g/g' = g (1 + phi)/phi'
    # Halley's correction g g''/(2 g'²) = g phi (2 + phi)/(2 z² phi'²), as g'' = phi (2 + phi)
    # /(z² (1 + phi)²) (`skcable.cable._hanging.step`)
    np.add(phi, 2.0, out=c)
    c *= phi
    c *= A
    t *= slope
    t *= slope
    t += t
    c /= t
    if not near:
        np.abs(c, out=t)
        far = t > 0.5  # Newton's step there (a NaN stays, and fails the stop test)
        if far.any():
            c[far] = 0.0
    np.subtract(1.0, c, out=c)
    step /= c
    return step


def _far_step(z, rho):
    """`skcable.cable._hanging.step` on arrays holding ``z`` above 20 or below 1e-150."""
    big, tiny = z > 20.0, z < 1e-150
    target = np.log1p(rho)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        zb = np.where(big, z, 21.0)
        first = 1.0 / np.tanh(zb) - 1.0 / zb
        newton = (zb - np.log(2.0 * zb) + np.log1p(-np.exp(-2.0 * zb)) - target) / first
        correction = 0.5 * newton / (zb * zb) / first
        far = np.where(np.abs(correction) <= 0.5, newton / (1.0 - correction), newton)
        zs = np.where((z >= 1e-150) & (z <= 20.0), z, 1.0)  # a NaN stays in z, and fails
        near = halley_step(zs, rho, np.empty((6, *z.shape)))
        tiny_step = _tiny_newton(np.where(tiny, z, 1e-150), rho)
    return np.where(big, far, np.where(tiny, tiny_step, near))


def _tiny_newton(z, rho):
    """Newton's step below ``z = 1e-150`` (``z²`` underflows; Halley's correction is ~1e-300
    there): ``phi = z²/6``, ``phi' = z/3`` to the first order, from the series."""
    phi = z * (z * SINHC_SERIES[-1])
    return np.log1p((phi - rho) / (1.0 + rho)) * (1.0 + phi) / (z * (2.0 * SINHC_SERIES[-1]))


def iterate(z, rho, rows=None, history=None, near=False):
    """Halley's method on ``g(z) = log(sinh z / z) - log1p(rho)`` from ``z`` (arrays of one size,
    ``z`` overwritten with the root), each element stopping on its own when its relative
    change falls below `STEP_TOL` (cubic convergence: its error is then below 1e-20); later
    steps run on the few elements left. Returns ``history`` (the largest relative change of
    each step, appended to) or raises `ConvergenceError`. ``near``: `halley_step`'s, for the
    first step."""
    history = [] if history is None else history
    flat = z.reshape(-1)
    targets = (rho if np.shape(rho) == z.shape else np.broadcast_to(rho, z.shape)).reshape(-1)
    rows = np.empty((6, flat.size)) if rows is None else rows
    change = halley_step(flat, targets, rows, near)
    flat -= change
    change /= flat
    np.abs(change, out=change)
    history.append(float(_MAX(change)))  # NaN if any is
    if history[-1] < STEP_TOL:
        return history
    active = np.flatnonzero(~(change < STEP_TOL))  # NaN keeps iterating (and fails)
    for _ in range(_MAX_STEPS - 1):
        zs, ts = flat[active], targets[active]
        change = halley_step(zs, ts, np.empty((6, active.size)))
        zs -= change
        change /= zs
        np.abs(change, out=change)
        history.append(float(_MAX(change)))
        flat[active] = zs
        active = active[~(change < STEP_TOL)]
        if active.size == 0:
            return history
    raise ConvergenceError("catenary(length=...): Halley's method did not converge", history)


def forces_into(span, dh, w, a, z, out, u):
    """The results of these elements from ``a`` and ``z`` into ``out`` (rows ``sinh_z``, ``m``,
    ``H``, ``length`` and the ``(2, size)`` blocks ``V``, ``T`` of the two ends): the formulas
    of `Catenary._arrays`, in place; ``u`` is a ``(2, size)`` block of scratch."""
    sinh_z, m, H, V, T, length = (out[k] for k in ("sinh_z", "m", "H", "V", "T", "length"))
    np.sinh(z, out=sinh_z)
    np.divide(sinh_z, z, out=m)  # the steps of `_m_in_place`
    np.divide(np.divide(dh, span, out=u[0]), m, out=m)
    np.arcsinh(m, out=m)
    np.multiply(w, a, out=H)
    np.subtract(z, m, out=u[0])  # -u_A
    np.add(z, m, out=u[1])  # u_B
    np.sinh(u, out=V)
    np.cosh(u, out=T)  # cosh is even: cosh(m - z)
    V *= H
    T *= H
    np.multiply(a, sinh_z, out=length)
    length *= 2.0
    length *= np.cosh(m, out=u[0])


def residual_rows(block, V, T, H, w, dh, length, met):
    """`Catenary.residual` of these elements written into the first five rows of ``block``
    (the last two are scratch), with the ends' forces in the blocks ``V`` and ``T``: closure
    through the end tensions, vertical balance, each end's tension along its components; the
    fifth row, the constraint met, is ``met(row)``'s to fill. Returns the largest magnitude
    (NaN if any is)."""
    rows, two, pair = block[:5], block[5], block[5:7]
    closure, balance, ends = rows[0], rows[1], rows[2:4]
    np.subtract(T[1], T[0], out=closure)
    closure -= w * dh
    closure /= np.add(T[0], T[1], out=two)
    np.multiply(w, length, out=two)  # the weight
    np.add(V[0], V[1], out=balance)
    balance -= two
    np.abs(V, out=ends)  # the rows of the ends, not yet written, as scratch
    two += ends[0]
    two += ends[1]
    balance /= two
    # each end: (1 - t² - v²)/2, t = H/T, v = V/T through one reciprocal scaled by √½ (its
    # rounding, 1e-16 relative, moves the term by 1e-16: the round-off the term measures)
    np.divide(_SQRT_HALF, T, out=pair)
    np.multiply(V, pair, out=ends)
    ends *= ends  # v²/2
    pair *= H
    np.square(pair, out=pair)  # t²/2
    np.subtract(0.5, pair, out=pair)
    np.subtract(pair, ends, out=ends)
    met(rows[4])
    return largest_abs(rows)


#: Rows of the results, in one block: ``z, a, sinh_z, m, H, length`` and the ends' ``V``, ``T``.
_RESULTS = ("z", "a", "sinh_z", "m", "H", "length")
_SCRATCH = 9  # rows of a pass's block: the residual's seven, ``u``'s two (the solve's six among them)


def _results(n, names):
    """The rows ``names`` and the ends' blocks ``V``, ``T`` of ``n`` elements, views of one new
    block."""
    block = np.empty((len(names) + 4, n))
    out = dict(zip(names, block, strict=False))
    out["V"], out["T"] = block[len(names) : len(names) + 2], block[len(names) + 2 :]
    return out


def _part(value, part):
    """``value[part]`` for an array, ``value`` for a float."""
    return value if isinstance(value, float) else value[part]


def _passes(n, size, fill):
    """Run ``fill(part, rows)`` over the passes of ``n`` elements, ``rows`` a block of
    `_SCRATCH` rows of the pass's size; the largest of their returns (the residuals), or None
    as soon as one returns None (a check failed)."""
    largest = 0.0
    with scratch(_SCRATCH, min(n, size)) as block:
        for lo in range(0, n, size):
            part = slice(lo, min(n, lo + size))
            got = fill(part, block[:, : part.stop - lo])
            if got is None:
                return None
            largest = got if not got <= largest else largest  # a NaN is kept
    return largest


def _excess_into(span, dh, length, rows, span_lo):
    r"""``rho = sqrt(S² - dh²)/span - 1`` into ``rows[0]`` free of cancellation (the formulas
    of `skcable.cable._catenary._z_from_length`: for a taut cable :math:`((S - M)(S + M) -
    m^2)/\mathrm{span}/(\sqrt{(S - |dh|)(S + |dh|)} + \mathrm{span})`, ``M``, ``m`` the longer
    and the shorter leg; beyond twice the chord the product of two square roots), or None where
    a length does not exceed its chord. ``rows``: three rows of scratch; ``span_lo``: the
    least span (of all the passes)."""
    rho, x, y = rows[:3]
    legs = abs(dh) if isinstance(dh, float) else np.abs(dh, out=y)
    np.multiply(span, span, out=x)
    x += dh * dh if isinstance(dh, float) else np.multiply(dh, dh, out=rho)
    np.sqrt(x, out=x)  # the chord
    if not (length > x).all():  # a NaN fails too
        return None
    x *= 2.0
    short = length < x
    if isinstance(dh, float) and legs <= span_lo:
        longer, shorter_sq = span, legs * legs
    else:
        longer, shorter_sq = np.maximum(span, legs), np.minimum(span, legs)
        shorter_sq *= shorter_sq
    np.subtract(length, longer, out=rho)
    np.add(length, longer, out=x)
    rho *= x
    rho -= shorter_sq
    rho /= span
    np.subtract(length, legs, out=x)
    legs = np.add(length, legs, out=y) if not isinstance(legs, float) else length + legs
    x *= legs
    np.sqrt(x, out=x)
    x += span
    rho /= x
    if not short.all():  # slack: sqrt((S - |dh|)/span) sqrt((S + |dh|)/span) - 1
        slack = np.flatnonzero(~short)
        lg = abs(dh) if isinstance(dh, float) else np.abs(dh[slack])
        ls, sp = length[slack], span[slack]
        rho[slack] = np.sqrt((ls - lg) / sp) * np.sqrt((ls + lg) / sp) - 1.0
    return rho


def of_length(span, dh, w, length, span_range, size=CHUNK):
    """``(largest residual, results)`` of the catenaries of ``length`` (flat float64 arrays of
    one size; ``dh``, ``w`` floats or such arrays; every value checked finite and in range by
    the caller, lengths in (1e-100, 1e100)), or None where a check of the general path
    would fail (a length not beyond its chord, data beyond the closed form's range, a solve
    that does not settle): that path then raises, naming the argument. ``span_range``: the
    least and the largest span. ``results``: the rows of `_RESULTS` and the ends' blocks ``V``,
    ``T``."""
    out = _results(span.size, _RESULTS)
    span_lo, span_hi = span_range

    def fill(part, rows):
        s, L, d, wp = span[part], length[part], _part(dh, part), _part(w, part)
        rho = _excess_into(s, d, L, rows, span_lo)
        top = None if rho is None else float(_MAX(rho))
        if top is None or not top < RHO_LIMIT:
            return None
        z, a = out["z"][part], out["a"][part]
        start(rho, z, rows[1:3], top)
        try:
            iterate(z, rho, rows[1:7], near=top < 1.0)  # the Padé start: within 2.5e-8
        except ConvergenceError:
            return None
        z_lo = float(_MIN(z))
        # a = fl(fl(span/z)/2) is largest at the longest span and the least z (rounding is monotone)
        if not (Z_MIN <= z_lo and float(_MAX(z)) <= Z_LIMIT and span_hi / z_lo * 0.5 <= _MAX_FLOAT):
            return None
        np.divide(s, z, out=a)
        a *= 0.5  # = span / (2 z): halving is exact
        return _forces_and_residual(s, d, wp, a, z, out, part, rows, L)

    largest = _passes(span.size, size, fill)
    return None if largest is None else (largest, out)


def of_H(span, dh, w, a, z, H, size=CHUNK):
    """``(largest residual, results)`` of the catenaries of horizontal tension ``H`` (flat
    float64 arrays of one size, ``a = H/w`` and ``z = span/(2a)`` already formed and checked in
    range by the caller; ``dh``, ``w`` floats or such arrays): the rows ``sinh_z``, ``m``,
    ``H``, ``length`` and the ends' blocks ``V``, ``T``, filled and checked pass by pass."""
    out = _results(span.size, _RESULTS[2:])

    def fill(part, rows):
        s, d, wp = span[part], _part(dh, part), _part(w, part)
        return _forces_and_residual(s, d, wp, a[part], z[part], out, part, rows, H[part])

    largest = _passes(span.size, size, fill)
    return None if largest is None else (largest, out)


def _forces_and_residual(span, dh, w, a, z, out, part, rows, given):
    """`forces_into` and `residual_rows` of the pass ``part`` (``given``: the constraint's value
    there, held against the result it fixes: ``length`` when ``out`` has the row ``a``, else
    ``H``)."""
    mine = {k: out[k][..., part] for k in ("sinh_z", "m", "H", "V", "T", "length")}
    forces_into(span, dh, w, a, z, mine, rows[7:9])
    achieved = mine["length"] if "a" in out else mine["H"]

    def met(row):
        np.subtract(achieved, given, out=row)
        row /= given

    return residual_rows(rows, mine["V"], mine["T"], mine["H"], w, dh, mine["length"], met)
