"""Independent references for mooring lines and systems, written for the tests: each line's
closure solved at 30 digits with mpmath (Irvine's elastic catenary piece by piece, Jonkman's
grounded line, the three-part line touching down between two suspended ends), and the force
balance at every free point and body from those forces.

H.M. Irvine, "Cable Structures", MIT Press, 1981; J.M. Jonkman, "Dynamics modeling and loads
analysis of an offshore floating wind turbine", NREL, 2007.
"""

import mpmath as mp
import numpy as np

mp.mp.dps = 30


def _pieces(H, V, segments, loads):
    """Run and rise of suspended segments (from A; ``V`` the vertical force at B, just below
    its joint; ``loads`` the downward point loads at the inner joints)."""
    x = y = mp.mpf(0)
    Vt = V
    for i in range(len(segments) - 1, -1, -1):
        L, w, EA = (mp.mpf(v) for v in segments[i])
        Vb = Vt - w * L
        x += H * L / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
        y += (Vt * Vt - Vb * Vb) / (2 * EA * w) + (mp.hypot(H, Vt) - mp.hypot(H, Vb)) / w
        Vt = Vb - (mp.mpf(loads[i]) if i > 0 else 0)
    return x, y, Vt  # Vt: the vertical force just above A, downward load of the line on A's side


def free_line(span, dh, segments, start, loads=None):
    """A multi-segment line hanging free from A = (0, 0) to B = (span, dh): ``(H, V_A, V_B)``
    (N; ``V_A`` the upward reaction at A), from ``start = (H, V_B)``. ``loads``: downward point
    loads at the joints 0..n (those at the ends carried by the supports)."""
    n = len(segments)
    loads = [0.0] * (n + 1) if loads is None else loads

    def f(H, V):
        x, y, _ = _pieces(H, V, segments, loads)
        return x - span, y - dh

    H, V = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    V_bottom = _pieces(H, V, segments, loads)[2]
    return float(H), float(-V_bottom + loads[0]), float(V + loads[-1])


def grounded_line(span, dh, w, EA, L, friction, start):
    """One segment from A on the seabed to B: Jonkman's closure, ``(H, V_B, H_A, L_B)``."""
    span, dh, w, EA, L, mu = (mp.mpf(v) for v in (span, dh, w, EA, L, friction))

    def f(H, V):
        L_B = L - V / w
        ell = min(L_B, H / (mu * w)) if mu > 0 else L_B
        X = L_B + H / w * mp.asinh(V / H) + H * V / (w * EA) + (H * ell - mu * w * ell * ell / 2) / EA
        Z = H / w * (mp.sqrt(1 + (V / H) ** 2) - 1) + V * V / (2 * EA * w)
        return X - span, Z - dh

    H, V = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    L_B = L - V / w
    return float(H), float(V), float(max(H - mu * w * L_B, 0)), float(L_B)


def touchdown_line(span, dh, w, EA, L, depth, start):
    """One segment from A ``depth`` above the seabed, resting on it, up to B (frictionless):
    ``(H, V_A, V_B)`` from ``start = (H, V_A, V_B)``."""
    span, dh, w, EA, L, d = (mp.mpf(v) for v in (span, dh, w, EA, L, depth))

    def f(H, V1, VB):
        s1, s2 = V1 / w, VB / w
        h1 = (mp.hypot(H, V1) - H) / w + V1 * V1 / (2 * EA * w) - d
        h2 = (mp.hypot(H, VB) - H) / w + VB * VB / (2 * EA * w) - (d + dh)
        x1 = H * s1 / EA + H / w * mp.asinh(V1 / H)
        x2 = H * s2 / EA + H / w * mp.asinh(VB / H)
        return h1, h2, x1 + x2 + (L - s1 - s2) * (1 + H / EA) - span

    H, V1, VB = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    return float(H), float(V1), float(VB)


def end_forces(a, b, H_a, V_a, H_b, V_b):
    """Forces (2, 3) of a line on its ends a and b from the end forces in its vertical plane."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    e = np.array([b[0] - a[0], b[1] - a[1], 0.0])
    e /= np.linalg.norm(e)
    return np.array([H_a * e + [0, 0, -V_a], -H_b * e + [0, 0, -V_b]])


def reference_forces(line, w_EA_L, depth, friction=0.0):
    """mpmath end forces (2, 3) of a solved one-segment `LineBetween` ``line`` at its ends,
    by its geometry over the seabed (``depth``): free, grounded at the lower end or touching
    down between the ends, as the solution says."""
    w, EA, L = w_EA_L
    a, b = line.a, line.b
    flip = b[2] < a[2]
    low, high = (b, a) if flip else (a, b)
    span = float(np.hypot(*(high - low)[:2]))
    dh = float(high[2] - low[2])
    gap = float(low[2] + depth) if depth is not None else None
    s = line.plane.solution
    if line.model == "grounded":
        H, V_B, H_A, _ = grounded_line(span, dh, w, EA, L, friction, (s.H, s.V_B))
        forces = end_forces(low, high, H_A, 0.0, H, V_B)
    elif line.model == "touchdown between the ends":
        H, V_A, V_B = touchdown_line(span, dh, w, EA, L, gap, (s.H, s.V_A, s.V_B))
        forces = end_forces(low, high, H, V_A, H, V_B)
    else:
        H, V_A, V_B = free_line(span, dh, [(L, w, EA)], (s.H, s.V_B))
        forces = end_forces(low, high, H, V_A, H, V_B)
    return forces[::-1] if flip else forces


def balance(eq, forces, external=None):
    """The net force on every free point and the net force and moment on every body of the
    equilibrium ``eq`` from the line end ``forces`` (a list of (2, 3), one per line), the
    points' and bodies' own loads and the ``external`` loads (``{key: vector}``) and nothing
    else: ``{("point", j): (3,), ("body", i): (6,)}``."""
    system = eq.system
    out = {}
    for p in system.points:
        if p.kind == "free":
            out[("point", p.index)] = p.own_force.copy()
    for i, state in enumerate(eq.bodies):
        body = state.body
        R = state.rotation
        W, B = body.weight, body.buoyancy
        total = np.zeros(6)
        total[:3] = W + B
        total[2] -= body.heave_stiffness * state.offset[2]
        if hasattr(body, "center_of_gravity"):
            total[3:] = np.cross(R @ body.center_of_gravity, W) + np.cross(R @ body.metacentre, B)
        out[("body", i)] = total
    for handle, F in zip(eq.handles, forces, strict=True):
        for end, f in zip((handle.a, handle.b), F, strict=True):
            if end.kind == "free":
                out[("point", end.index)] += f
            elif end.kind == "body":
                i = system.bodies.index(end.body)
                arm = eq.points[end.index].position - eq.bodies[i].offset
                out[("body", i)][:3] += f
                out[("body", i)][3:] += np.cross(arm, f)
    for key, vector in (external or {}).items():
        out[key][: len(vector)] += vector
    return out


def sloped_line(span, dh, w, EA, L, slope, friction, start):
    """One segment from A on the plane seabed ``y = x tan α`` to B (Jonkman's line on a slope):
    ``(H_A, V_A, H_B, V_B)`` from ``start = (H, L_B)``."""
    span, dh, w, EA, L, m, mu = (mp.mpf(v) for v in (span, dh, w, EA, L, slope, friction))
    cos = 1 / mp.sqrt(1 + m * m)
    sin = m * cos
    k = w * (sin + mu * cos)

    def f(H, L_B):
        Vt, Tt = H * m, H / cos
        Ls = L - L_B
        VB = Vt + w * Ls
        ell = min(L_B, Tt / k) if k > 0 else L_B
        ground = L_B + (Tt * ell - k * ell * ell / 2) / EA
        X = ground * cos + H * Ls / EA + H / w * (mp.asinh(VB / H) - mp.asinh(Vt / H))
        Z = ground * sin + (mp.hypot(H, VB) - mp.hypot(H, Vt)) / w + (VB * VB - Vt * Vt) / (2 * EA * w)
        return X - span, Z - dh

    H, L_B = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    T_A = max(H / cos - k * L_B, 0)
    return float(T_A * cos), float(-T_A * sin), float(H), float(H * m + w * (L - L_B))


def _hang(H, Vb, w, EA, s):
    """Run and rise (m) of an elastic catenary piece of length ``s`` with the horizontal force ``H``
    and the vertical force ``Vb`` at its start (along its direction of travel), at 30 digits."""
    Vt = Vb + w * s
    run = H * s / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
    rise = (mp.hypot(H, Vt) - mp.hypot(H, Vb)) / w + (Vt * Vt - Vb * Vb) / (2 * EA * w)
    return run, rise


def slope_touchdown_line(span, dh, w, EA, L, seabed, slope, start):
    """One frictionless segment from A to B, both above the plane seabed ``y = seabed + x tan α``
    (``tan α > 0``), touching down on it between them: hanging from A to a tangent touchdown,
    lying straight with ``dT/ds = w sin α``, hanging tangentially to B. ``(H_1, s_1, ℓ, H_2)``
    from ``start = (H_2, ℓ, s_1)``."""
    span, dh, w, EA, L, b, m = (mp.mpf(v) for v in (span, dh, w, EA, L, seabed, slope))
    cos = 1 / mp.sqrt(1 + m * m)
    sin = m * cos

    def parts(H2, ell, s1):
        T1 = H2 / cos - w * sin * ell
        H1 = T1 * cos
        x1, y1 = _hang(H1, H1 * m - w * s1, w, EA, s1)  # A to the first touchdown
        G = ell + (T1 * ell + w * sin * ell * ell / 2) / EA
        x2, y2 = _hang(H2, H2 * m, w, EA, L - s1 - ell)  # the second touchdown to B
        return H1, x1, y1, G, x2, y2

    def f(H2, ell, s1):
        _, x1, y1, G, x2, y2 = parts(H2, ell, s1)
        return y1 - b - m * x1, x1 + G * cos + x2 - span, y1 + G * sin + y2 - dh

    H2, ell, s1 = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    return float(parts(H2, ell, s1)[0]), float(s1), float(ell), float(H2)


def taut_length_on_slope(span, dh, w, EA, seabed, slope, start):
    """The length (m) at which that line's tension at its first touchdown is zero: a vertical
    part from A onto the slope, ``ℓ`` on it from zero tension, the rest hanging to B;
    ``start = (ℓ, s_2)``."""
    span, dh, w, EA, b, m = (mp.mpf(v) for v in (span, dh, w, EA, seabed, slope))
    cos = 1 / mp.sqrt(1 + m * m)
    sin = m * cos
    vertical = mp.findroot(lambda v: v + w * v * v / (2 * EA) + b, -b)

    def f(ell, s2):
        H2 = w * sin * ell * cos
        G = ell + w * sin * ell * ell / (2 * EA)
        x2, y2 = _hang(H2, H2 * m, w, EA, s2)
        return G * cos + x2 - span, b + G * sin + y2 - dh

    ell, s2 = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    return float(vertical + ell + s2)


def grounded_multi(span, dh, segments, start):
    """A frictionless line of segments (from A) resting on the seabed through A up to a tangent
    touchdown inside one of its heavy segments, then suspended to B: ``(H, V_B, grounded)``."""
    span, dh = mp.mpf(span), mp.mpf(dh)
    segs = [tuple(mp.mpf(v) for v in s) for s in segments]

    def parts(H, V):
        tops, Vt = [], V
        for L, w, _ in reversed(segs):
            tops.append(Vt)
            Vt = Vt - w * L
        tops = tops[::-1]  # the vertical force at the top of each segment
        k = next(i for i, v in enumerate(tops) if v > 0)  # the lowest segment that hangs (from A)
        x = y = mp.mpf(0)
        for i in range(k, len(segs)):
            L, w, EA = segs[i]
            Vt = tops[i]
            Vb = max(Vt - w * L, mp.mpf(0)) if i == k else Vt - w * L
            Ls = (Vt - Vb) / w
            x += H * Ls / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
            y += (Vt * Vt - Vb * Vb) / (2 * EA * w) + (mp.hypot(H, Vt) - mp.hypot(H, Vb)) / w
        ground = (
            sum(seg[0] for seg in segs[:k])
            + segs[k][0]
            - (tops[k] - max(tops[k] - segs[k][1] * segs[k][0], 0)) / segs[k][1]
        )
        stretch = (
            sum(H * seg[0] / seg[2] for seg in segs[:k])
            + H * (ground - sum(seg[0] for seg in segs[:k])) / segs[k][2]
        )
        return x + ground + stretch, y, ground

    def f(H, V):
        x, y, _ = parts(H, V)
        return x - span, y - dh

    H, V = mp.findroot(f, tuple(mp.mpf(v) for v in start), solver="mdnewton")
    return float(H), float(V), float(parts(H, V)[2])
