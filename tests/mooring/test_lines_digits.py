"""D1 of issue 26 in the mooring lines: taut, light, stiff lines keep their digits.

Where ``wL/H`` is small against ``|V|/H`` the difference ``asinh(V_top/H) - asinh(V_bot/H)`` of
rounded ratios loses ``|V|/(wL)`` ulps; the closures now take the step ``wL/H`` formed
directly, and Newton runs to the closure's own round-off. References: the closures at 50
digits (mpmath), from the equations written here. Scenes are kept where the answer is
well conditioned in its data (``EA/H <= 1e3``: a relative change of one ulp in the span moves
``H`` by at most ``EA/H`` ulps), so that 1e-12 is a fair bound for any double computation.
"""

import mpmath as mp
import numpy as np
import pytest

from skcable import cable, mooring

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings("ignore:(uplift_angle)\\b:skcable.errors.PlausibilityWarning")

mp.mp.dps = 50


def _mp_free_line(segments, span, dh, H0, V0):
    """``(H, V_B)`` of a free multi-segment line (Irvine's pieces, statics from B down), with
    90 working digits: the differences of asinh of nearly equal ratios lose up to 15 of them."""
    with mp.workdps(90):
        segs = [tuple(mp.mpf(v) for v in s) for s in segments]
        span, dh = mp.mpf(span), mp.mpf(dh)

        def closure(H, V):
            X = Z = mp.mpf(0)
            Vt = V
            for L, w, EA in reversed(segs):
                Vb = Vt - w * L
                X += H * L / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
                Z += L * (Vt + Vb) / (2 * EA) + (mp.sqrt(H * H + Vt * Vt) - mp.sqrt(H * H + Vb * Vb)) / w
                Vt = Vb
            return [X - span, Z - dh]

        root = _mp_newton(closure, H0, V0)
        assert max(abs(f) for f in closure(*root)) < mp.mpf(10) ** -50 * (abs(span) + abs(dh))
        return root


def _mp_newton(closure, x0, y0, steps=8):
    """Newton's method at the working precision, the Jacobian by `mpmath.diff`."""
    x, y = mp.mpf(x0), mp.mpf(y0)
    scale = max(abs(v) for v in closure(mp.mpf(0) * x + 1, y)) + 1  # lengths: a residual scale
    for _ in range(steps):
        f = closure(x, y)
        if max(abs(v) for v in f) < mp.mpf(10) ** (12 - mp.mp.dps) * scale:
            break  # converged: further steps only stir the round-off of the derivatives
        rows = [_mp_gradient(closure, x, y, i) for i in (0, 1)]
        step = mp.lu_solve(mp.matrix(rows), mp.matrix(f))
        x, y = x - step[0], y - step[1]
    return x, y


def _mp_gradient(closure, x, y, i):
    """``∂f_i/∂(x, y)`` by `mpmath.diff`."""
    return [mp.diff(lambda h: closure(h, y)[i], x), mp.diff(lambda v: closure(x, v)[i], y)]


def _taut_light_scenes(seed, count):
    """Lines of 1-3 segments, w 0.01-1 N/m, EA 1e9-1e10 N, strained 1e-3-1e-2, any slope."""
    rng = np.random.default_rng(seed)
    for _ in range(count):
        n = int(rng.integers(1, 4))
        segments = [
            (float(rng.uniform(50, 500)), float(10 ** rng.uniform(-2, 0)), float(10 ** rng.uniform(9, 10)))
            for _ in range(n)
        ]
        chord = sum(s[0] for s in segments) * (1 + float(10 ** rng.uniform(-3, -2)))
        angle = rng.uniform(-1.2, 1.2)
        yield segments, chord * np.cos(angle), chord * np.sin(angle)


def _close(solution, H, V):
    assert solution.H == pytest.approx(float(H), rel=1e-12)
    assert solution.V_B == pytest.approx(float(V), rel=1e-12, abs=1e-12 * float(H))


@pytest.mark.parametrize("seed", range(4))
def test_taut_light_multi_segment_lines_against_50_digits(seed):
    for segments, span, dh in _taut_light_scenes(seed, 6):
        line = mooring.Line([mooring.Segment(*s) for s in segments])
        sol = line.solve(span, dh)
        assert sol.H / sum(L * w for L, w, _ in segments) > 1e3  # light: wL/H below 1e-3
        H, V = _mp_free_line(segments, span, dh, sol.H, sol.V_B)
        _close(sol, H, V)
        # warm-started from a solution 1 m away, and in 3-D: the same root to 1e-12
        near = line.solve(span - 1.0, dh + 0.5)
        _close(line.solve(span, dh, start=near), H, V)
        l3 = mooring.line_3d(line, (10.0, -20.0, -5.0), (10.0 + span * 0.6, -20.0 + span * 0.8, -5.0 + dh))
        h3, v3 = _mp_free_line(segments, l3.span, l3.dh, l3.H, l3.V_B)
        _close(l3.solution, h3, v3)


def test_issue_d1_scene_as_a_line():
    """Issue 26's D1 scene (H = 5.66673e10, 50-digit root) as a one-segment `Line`."""
    span, dh, w, EA, L = (
        0.2332264670872486,
        -0.26928872264561327,
        0.2670976622234697,
        1037758168845.9086,
        0.3288194802156623,
    )
    sol = mooring.Line([mooring.Segment(L, w, EA)]).solve(span, dh)
    H, V = _mp_free_line([(L, w, EA)], span, dh, 5.66673e10, -(w * L) / 2 - 5.66673e10 * 1.15)
    assert abs(float(H) / 5.66673e10 - 1) < 1e-5  # the root the issue names
    _close(sol, H, V)


def test_profile_of_a_taut_light_line_against_50_digits():
    segments, span, dh = next(_taut_light_scenes(7, 1))
    segments = [*segments, (120.0, 0.05, 5e9)]
    span, dh = span + 120.0 * 1.001 * np.cos(0.3), dh + 120.0 * 1.001 * np.sin(0.3)
    line = mooring.Line([mooring.Segment(*s) for s in segments])
    sol = line.solve(span, dh)
    H, V = _mp_free_line(segments, span, dh, sol.H, sol.V_B)
    # the point s on the line from A, at 50 digits: walk the pieces from A upwards
    V_A = sum(mp.mpf(w) * mp.mpf(L_) for L_, w, _ in segments) - V
    s_values = np.linspace(0.0, line.length, 17)
    x_ref, y_ref = [], []
    for s in s_values:
        x = y = mp.mpf(0)
        Vb, left = -V_A, mp.mpf(s)
        for L_, w, EA in ((mp.mpf(a), mp.mpf(b), mp.mpf(c)) for a, b, c in segments):
            ds = min(left, L_)
            Vt = Vb + w * ds
            x += H * ds / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
            y += ds * (Vt + Vb) / (2 * EA) + (mp.sqrt(H * H + Vt * Vt) - mp.sqrt(H * H + Vb * Vb)) / w
            left -= ds
            Vb = Vb + w * L_
            if left <= 0:
                break
        x_ref.append(float(x))
        y_ref.append(float(y))
    chord = np.hypot(span, dh)
    xy = sol.xy(s_values)
    np.testing.assert_allclose(xy[:, 0], x_ref, rtol=0, atol=1e-12 * chord)
    np.testing.assert_allclose(xy[:, 1], y_ref, rtol=0, atol=1e-12 * chord)


def _mp_sloped_closure(span, dh, w, EA, L, m):
    """Jonkman's closure on the slope ``y = m x``, frictionless, the grounded part fully
    tensioned (a falling slope: the tension grows towards A), at 50 digits: ``(H, L_B) ->
    (X - span, Z - dh)``."""
    span, dh, w, EA, L, m = (mp.mpf(v) for v in (span, dh, w, EA, L, m))
    cos = 1 / mp.sqrt(1 + m * m)
    sin = m * cos

    def closure(H, L_B):
        T_t = H / cos
        grounded = L_B + (T_t * L_B - w * sin * L_B * L_B / 2) / EA
        L_s = L - L_B
        V_t, V_B = H * m, H * m + w * L_s
        X = H * L_s / EA + H / w * (mp.asinh(V_B / H) - mp.asinh(V_t / H))
        Z = (mp.sqrt(H * H + V_B**2) - mp.sqrt(H * H + V_t**2)) / w + (V_B**2 - V_t**2) / (2 * EA * w)
        return [grounded * cos + X - span, grounded * sin + Z - dh]

    return closure


@pytest.mark.parametrize(
    ("w", "light", "EA_over_H"), [(0.05, 1e4, 300.0), (0.5, 2e3, 1e3), (0.01, 1e5, 100.0)]
)
def test_taut_light_line_on_a_falling_slope_against_50_digits(w, light, EA_over_H):
    m, L, L_B = -0.2, 900.0, 300.0
    H = light * w * L
    EA = EA_over_H * H
    # B where the line with these (H, L_B) ends (the closure at 50 digits), rounded to floats
    X, Z = _mp_sloped_closure(0.0, 0.0, w, EA, L, m)(mp.mpf(H), mp.mpf(L_B))
    span, dh = float(X), float(Z)
    sol = cable.sloped_seabed_catenary(span, dh, w, EA, length=L, seabed_slope=m)
    closure = _mp_sloped_closure(span, dh, w, EA, L, m)
    root = _mp_newton(closure, H, L_B)
    assert sol.H == pytest.approx(float(root[0]), rel=1e-12)
    # the touchdown of a taut, light line nearly along the slope is ill conditioned in the data
    # (it moves by the run's rounding over the line's angle to the slope): L_B is checked by its
    # backward error, the exact closure at the computed (H, L_B) within the data's round-off
    residual = closure(mp.mpf(sol.H), mp.mpf(sol.length_on_seabed))
    assert max(abs(float(f)) for f in residual) < 8 * np.finfo(float).eps * np.hypot(span, dh)


@pytest.mark.parametrize("seed", range(3))
def test_lifted_seabed_line_and_free_sloped_line_against_50_digits(seed):
    """A taut, light line lifted off its anchor on a flat seabed (and one that leaves A above a
    falling slope): the free elastic catenary path of `elastic_catenary(..., seabed=0)` and of
    `sloped_seabed_catenary`."""
    segments, span, dh = next(_taut_light_scenes(100 + seed, 1))
    L = sum(s[0] for s in segments)
    w, EA = segments[0][1], segments[0][2]
    dh = abs(dh) + 0.05 * L  # B above A: the line rises from the anchor, lifted
    span = float(np.sqrt((L * 1.004) ** 2 - dh * dh))
    flat = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0)
    sloped = cable.sloped_seabed_catenary(span, dh, w, EA, length=L, seabed_slope=-0.5)
    assert flat.length_on_seabed == 0.0 and sloped.length_on_seabed == 0.0
    H, V = _mp_free_line([(L, w, EA)], span, dh, flat.H, flat.V_B)
    _close(flat, H, V)
    _close(sloped, H, V)
