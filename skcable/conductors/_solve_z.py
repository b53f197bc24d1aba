r"""Irvine's elastic catenary of a given unstressed length, as one equation in one unknown.

A span of unstressed length :math:`L`, weight :math:`w` per unstressed length and axial
stiffness :math:`EA` hangs from A = (0, 0) to B = (a, h) (H.M. Irvine, "Cable Structures", MIT
Press, 1981, §2.2). With the catenary parameter :math:`p = H/w`, the hyperbolic angles
:math:`u_A = \mu - z`, :math:`u_B = \mu + z` of the ends (:math:`\sinh u = T_v/H`) and
:math:`\varepsilon = wL/EA`, the closure reads

.. math::
    a = p\,(\varepsilon + 2z), \qquad
    h = p \sinh\mu\,(\varepsilon\cosh z + 2\sinh z), \qquad
    L = 2p\cosh\mu\,\sinh z.

Eliminating :math:`p` and :math:`\mu` leaves one equation in :math:`z` alone: with
:math:`q = (\varepsilon\cosh z + 2\sinh z)/(\varepsilon + 2z)` (so that
:math:`\sinh\mu = h/(aq)`) and :math:`L' = L + (L\varepsilon/2)\coth z`,

.. math:: g(z) = (q^2 - 1)\,a^2 - (L'^2 - C^2) = 0, \qquad C = \sqrt{a^2 + h^2},

increasing in :math:`z` (one root). Then :math:`H = wa/(\varepsilon + 2z)` and the mean
vertical tension :math:`m = (T_{v,A} + T_{v,B})/2 = H\sinh\mu\cosh z`.

`solve_z` starts from the parabolic change of state (the cubic of CIGRE TB 324, "Sag-tension
calculation methods for overhead lines", 2007, written in :math:`\zeta = z + \varepsilon/2`:
:math:`\zeta^3 - 6\frac{L - C}{C\cos^2\psi}\zeta - \frac{3\varepsilon}{\cos^2\psi} = 0`,
guessed within a few per cent and refined by one Newton step), takes two Newton steps on :math:`g`
formed directly (enough to bring the parabola's 1e-3 to about 1e-12), then Newton steps on
:math:`g` formed without cancellation — :math:`q - 1 = (\varepsilon(\cosh z - 1) +
2(\sinh z - z))/(\varepsilon + 2z)` with :math:`\sinh z - z` by its Maclaurin series below
:math:`z = 1`, :math:`L' - C = (L - C) + (L\varepsilon/2)\coth z` — until the relative step
is below 1e-8 (the error of the next iterate is then about the square of it: round-off).
Everything works in place in the rows of one scratch block: on arrays of 1e4 elements a new
array costs more than the arithmetic on it.

This is the conductors' own solver (for speed at 10⁴ spans × states: one unknown, in place),
not another closure: the caller checks every element by the one closure of an elastic segment
evaluated by other formulas (`skcable.cable.closure.check_into`, in :math:`(H, m)`); nothing
here computes an end tension, an inverse hyperbolic sine or a logarithm, so that the check
does not share this solve's round-off.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._special import SINHC_SERIES

__all__ = ["solve_z", "series_terms"]

#: Relative Newton step below which the next iterate is at round-off (quadratic rate).
STEP_TOL = 1e-8
_MAX_PRECISE = 30
#: ``(z_max, n)``: below z_max, n terms of the series of sinh z - z reach 1e-17 relative
#: (the first term left out, 6 z^(2n) / (2n + 3)!, is below 2e-17 there).
_TERMS = ((0.01, 2), (0.06, 3), (0.15, 4), (0.27, 5), (0.42, 6), (0.6, 7), (0.8, 8), (1.0, 9))
#: Scratch rows a solve takes (`solve_z`'s ``block``).
ROWS = 15


def series_terms(z_max):
    """How many terms of the Maclaurin series of ``sinh z - z`` reach 1e-17 relative on
    ``(0, z_max]``, or None at ``z_max >= 1`` (the direct form is used there)."""
    for top, n in _TERMS:
        if z_max < top:
            return n
    return None


def _sinh_minus_z(z, t, out):
    """``sinh z - z`` into ``out`` (``t`` holds ``z²``): the series below 1, else direct."""
    n = series_terms(float(z.max()))
    if n is None:
        np.sinh(z, out=out)
        out -= z
        if float(z.min()) < 1.0:  # mixed: the series where z < 1 (all nine terms)
            small = z < 1.0
            series = np.full(z.shape, SINHC_SERIES[0])
            for coefficient in SINHC_SERIES[1:]:
                series *= t
                series += coefficient
            series *= t
            series *= z
            np.copyto(out, series, where=small)
        return out
    coefficients = SINHC_SERIES[-n:]
    out.fill(coefficients[0])
    for coefficient in coefficients[1:]:
        out *= t
        out += coefficient
    out *= t
    out *= z
    return out


class _Rows:
    """The per-element constants and the scratch rows of one solve (views of one block)."""

    def __init__(self, a, h, w, EA, L, block=None, chord=None):
        block = np.empty((ROWS, a.size)) if block is None else block
        (self.C, self.LmC, self.eps, self.E, self.a2, self.h2, self.s, self.c, self.D, self.q,
         self.x, self.g, self.dq, self.t, self.smz) = block  # fmt: skip
        self.a, self.h, self.w, self.EA, self.L = a, h, w, EA, L
        np.multiply(a, a, out=self.a2)
        np.multiply(h, h, out=self.h2)
        if chord is None:
            np.add(self.a2, self.h2, out=self.C)
            np.sqrt(self.C, out=self.C)
        else:
            np.copyto(self.C, chord)
        np.subtract(L, self.C, out=self.LmC)
        np.multiply(w, L, out=self.eps)
        self.eps /= EA
        np.multiply(self.eps, L, out=self.E)
        self.E *= 0.5


def _start(r):
    """``z`` of the parabolic cubic (module text), within about 1e-3 of the root of g.

    With ``c = (-Q)^(1/3)`` and ``x = -P/c²`` the root is ``zeta = c f(x)``, ``f³ - x f - 1 = 0``,
    guessed as ``sqrt(x + 1/sqrt(1 + x))`` for ``x >= 0`` (within 1.6 %) and
    ``1/(y + (1 + y/3)^-2)``, ``y = -x``, below (within 7.1 %), then one Newton step.
    """
    P, Qn, zeta, t, x, u, v = r.s, r.c, r.q, r.t, r.x, r.g, r.dq
    np.divide(r.C, r.a2, out=t)  # 1 / (C cos²psi), cos psi = a / C
    np.multiply(r.LmC, t, out=P)
    P *= -6.0
    np.multiply(t, r.C, out=Qn)
    Qn *= r.eps
    Qn *= 3.0  # -Q
    np.cbrt(Qn, out=zeta)
    np.multiply(zeta, zeta, out=t)
    np.divide(P, t, out=x)
    np.negative(x, out=x)
    np.maximum(x, 0.0, out=u)
    np.add(u, 1.0, out=v)
    np.sqrt(v, out=v)
    np.divide(1.0, v, out=v)
    v += u
    np.sqrt(v, out=v)  # f where x >= 0 (1 elsewhere)
    if P.max() > 0.0:  # taut: x < 0 somewhere
        np.negative(x, out=u)
        np.maximum(u, 0.0, out=u)
        np.multiply(u, 1.0 / 3.0, out=t)
        t += 1.0
        t *= t
        np.divide(1.0, t, out=t)
        t += u
        np.divide(1.0, t, out=t)  # f where x < 0 (1 elsewhere)
        v *= t
    zeta *= v
    np.multiply(zeta, zeta, out=t)  # one Newton step on zeta³ + P zeta + Q
    np.add(t, P, out=u)
    u *= zeta
    u -= Qn
    t *= 3.0
    t += P
    u /= t
    zeta -= u
    z = np.multiply(r.eps, -0.5)
    z += zeta
    zeta *= 0.5
    np.maximum(z, zeta, out=z)  # a very taut elastic span: keep z > 0
    return z


def _direct_step(r, z):
    """One Newton step on g formed directly (about 3 eps / z² relative in z: a start only)."""
    s, c, D, q, x, g, dq, t = r.s, r.c, r.D, r.q, r.x, r.g, r.dq, r.t
    np.sinh(z, out=s)
    np.cosh(z, out=c)
    np.multiply(z, 2.0, out=D)
    D += r.eps
    np.multiply(r.eps, c, out=q)
    q += s
    q += s
    q /= D  # q
    np.divide(c, s, out=x)
    x *= r.E
    x += r.L  # L'
    np.multiply(q, q, out=g)
    g *= r.a2
    g += r.h2
    np.multiply(x, x, out=t)
    g -= t  # g (halved below, with its derivative)
    np.subtract(c, q, out=dq)
    dq += dq
    np.multiply(r.eps, s, out=t)
    dq += t
    dq /= D  # q' = (eps sinh z + 2 cosh z - 2 q) / D
    dq *= q
    dq *= r.a2
    np.multiply(s, s, out=t)
    np.divide(r.E, t, out=t)
    t *= x
    dq += t  # g'/2 = q q' a² - L' dL'/dz, dL'/dz = -E / sinh²z
    g *= 0.5
    g /= dq
    z -= g
    return z


def _precise_step(r, z):
    """One Newton step on g formed without cancellation; returns the step (in ``r.g``), and
    leaves ``q - 1``, ``q'``, ``cosh z - 1`` and ``sinh z`` at the old ``z`` in ``r.q``,
    ``r.dq``, ``r.c``, ``r.s``."""
    s, cm1, D, qm1, x, g, dq, t = r.s, r.c, r.D, r.q, r.x, r.g, r.dq, r.t
    smz = r.smz
    np.multiply(z, z, out=t)
    _sinh_minus_z(z, t, out=smz)
    np.add(smz, z, out=s)
    np.multiply(s, s, out=t)  # sinh²z
    np.add(t, 1.0, out=cm1)
    np.sqrt(cm1, out=cm1)
    cm1 += 1.0
    np.divide(t, cm1, out=cm1)  # cosh z - 1 = sinh²z / (cosh z + 1)
    np.multiply(z, 2.0, out=D)
    D += r.eps
    np.multiply(r.eps, cm1, out=qm1)
    qm1 += smz
    qm1 += smz
    qm1 /= D  # q - 1
    np.add(cm1, 1.0, out=x)
    x /= s
    x *= r.E  # (L eps / 2) coth z
    np.add(qm1, 2.0, out=g)
    g *= qm1
    g *= r.a2  # (q² - 1) a²
    np.add(x, r.L, out=dq)  # L'
    np.divide(r.E, t, out=t)
    t *= dq  # L' E / sinh²z = -L' dL'/dz
    dq += r.C
    x += r.LmC  # L' - C
    x *= dq
    g -= x  # g
    np.multiply(z, cm1, out=dq)
    dq -= smz
    dq *= 4.0
    np.multiply(r.eps, s, out=x)
    x *= D
    dq += x
    dq /= D
    dq /= D  # q' = (eps sinh z D + 4 (z cosh z - sinh z)) / D²
    np.add(qm1, 1.0, out=x)
    x *= dq
    x *= r.a2
    x += t  # g'/2
    g *= 0.5
    g /= x
    z -= g
    return g


def _precise(r, z):
    """Newton steps formed without cancellation until every relative step is below
    `STEP_TOL` (later steps on the elements left); ``(step, converged)``, the rows of ``r``
    holding the last step's pieces of every element."""
    step = _precise_step(r, z)
    ok = np.abs(step) <= STEP_TOL * z
    if ok.all():
        return step, ok
    rest = np.flatnonzero(~ok)  # a start far from the root: rare, and few elements
    sub = _Rows(r.a[rest], r.h[rest], r.w[rest], r.EA[rest], r.L[rest])
    zs = z[rest]
    for _ in range(_MAX_PRECISE):
        step_s = _precise_step(sub, zs)
        done = np.abs(step_s) <= STEP_TOL * zs
        if done.all():
            break
    z[rest], step[rest], ok[rest] = zs, step_s, done
    for name in ("q", "dq", "c", "s"):
        getattr(r, name)[rest] = getattr(sub, name)
    return step, ok


def solve_z(a, h, w, EA, L, H, m, block=None, chord=None):
    """The horizontal tension ``H`` and the mean vertical tension ``m`` of the spans, written
    into the given arrays (all flat float arrays of one size, ``a > 0``, ``L > 0``): the root
    of g (module text). Returns ``converged``, False where the Newton steps did not settle
    (``H`` is NaN there). ``block``: `ROWS` rows of scratch of that size, or None;
    ``chord``: ``sqrt(a² + h²)`` if the caller has it (broadcast to the elements).

    Unchecked: the caller checks every element by an independent closure residual.
    """
    r = _Rows(a, h, w, np.broadcast_to(EA, a.shape), L, block, chord)
    with np.errstate(all="ignore"):
        z = _start(r)
        z = _direct_step(r, z)
        z = _direct_step(r, z)
        step, ok = _precise(r, z)
        # the pieces at the last iterate, carried to the new z (errors step²: round-off)
        np.multiply(step, r.dq, out=r.t)
        r.q -= r.t  # q - 1
        np.multiply(step, r.s, out=r.t)
        r.c -= r.t
        r.c += 1.0  # cosh z
        np.multiply(z, 2.0, out=r.D)
        r.D += r.eps
        np.multiply(w, a, out=H)
        H /= r.D
        r.q += 1.0
        r.q *= a
        np.divide(h, r.q, out=m)  # sinh mu = h / (a q)
        m *= r.c
        m *= H
    if not ok.all():
        H[~ok] = np.nan
    return ok


def _length_pieces(zi, hw, w_EA, L):
    """``(eps, sinh z, cosh z, sinh mu)`` at the unstressed length ``L``: ``eps = wL/EA``,
    ``z = a/(2p) - eps/2`` (``zi = a/(2p)``), ``sinh mu = h/(p N)`` (``hw = h/p``),
    ``N = eps cosh z + 2 sinh z``."""
    eps = w_EA * L
    z = eps * -0.5
    z += zi
    s, c = np.sinh(z), np.cosh(z)
    N = eps * c
    N += s
    N += s
    return eps, s, c, np.divide(hw, N, out=N)


def length_z(a, h, w, EA, H):
    r"""``(L, m, converged)`` of spans of horizontal tension ``H`` (float arrays of one shape;
    ``w``, ``EA`` floats or arrays that broadcast): the closure (module text) solved for the
    unstressed length.

    Given :math:`p = H/w`, :math:`z = a/(2p) - \varepsilon/2` and :math:`\sinh\mu =
    h/(p(\varepsilon\cosh z + 2\sinh z))` follow from :math:`L`; the third equation
    :math:`G(L) = 2p\sinh z\cosh\mu - L = 0` is solved by Newton's method from the
    inextensible catenary of that H shortened by its mean strain (about 1e-5 from the root),
    with :math:`G' \approx -1 - (H/EA)\cosh z\cosh\mu` (the term left out is
    :math:`\varepsilon\sinh^2 z\tanh^2\mu/N` times that, below 1e-9 of it for a cable
    material: the convergence stays quadratic to round-off). Unchecked (the caller checks by
    `closure_residual`).
    """
    with np.errstate(all="ignore"):
        zi = a * (0.5 * w)
        zi /= H  # a / (2p)
        two_p = np.multiply(H, 2.0 / w)
        hw = h * w
        hw /= H  # h / p
        H_EA = H / EA
        w_EA = w / EA
        S = np.sinh(zi)
        S *= two_p
        S *= S
        r = h * h
        S += r
        np.sqrt(S, out=S)  # the inextensible length
        np.divide(h, a, out=r)
        r *= r
        r += 1.0
        r *= H * H
        T = S * (0.5 * w)
        T *= T
        T += r
        np.sqrt(T, out=T)  # its mean tension, about
        T /= EA
        T += 1.0
        L = np.divide(S, T, out=S)
        for _ in range(_MAX_PRECISE):
            eps, s, c, sm = _length_pieces(zi, hw, w_EA, L)
            sm *= sm
            sm += 1.0
            np.sqrt(sm, out=sm)  # cosh mu
            G = two_p * s
            G *= sm
            G -= L
            sm *= c
            sm *= H_EA
            sm += 1.0
            G /= sm  # -step
            L += G
            G /= L
            if -STEP_TOL <= G.min() and G.max() <= STEP_TOL:
                break
        ok = np.abs(G) <= STEP_TOL
        _, _, c, sm = _length_pieces(zi, hw, w_EA, L)
        sm *= c
        sm *= H
    return L, sm, ok
