"""Regimes of natural frequencies (a sagging cable against Chebyshev collocation of Irvine's
theory; its unit-scale and mirror invariances) and of strand sections (recounted wire by wire
from the layers' data, a damage pattern turned by one wire, the bending frequencies of a
pinned strand against the tensioned beam's closed form).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np

from tests.fuzz.compare import fmt
from tests.fuzz.harness import Case
from tests.fuzz.scenes import log_uniform, pick
from tests.fuzz.vibration import catenary_H, frequencies

__all__ = ["REGIMES"]

FREQ_NAMES = frozenset({"span", "dh", "w", "EA", "H", "sag", "n_modes", "g"})
STRAND_NAMES = frozenset(
    {
        "name",
        "n",
        "wires",
        "section",
        "N",
        "length",
        "mass_per_length",
        "axis",
        "ends",
        "n_modes",
        "n_elements",
        "strand",
    }
)


def _cable(rng):
    span = log_uniform(rng, 1.0, 2000.0)
    dh = 0.0 if rng.uniform() < 0.4 else span * math.tan(rng.uniform(-0.5, 0.5))
    w = log_uniform(rng, 0.1, 100.0)
    EA = w * span * log_uniform(rng, 1e1, 1e7)
    ratio = log_uniform(rng, 3e-4, 0.12)
    given = ("H", w * span / (8 * ratio)) if rng.uniform() < 0.7 else ("sag", ratio * span)
    return span, dh, w, EA, given, int(rng.integers(1, 9))


def _freq_call(span, dh, w, EA, given, n, g=9.81):
    return (
        f"conductors.natural_frequencies({fmt(span)}, {fmt(dh)}, {fmt(w)}, {fmt(EA)}, "
        f"{given[0]}={fmt(given[1])}, n_modes={n}, g={fmt(g)})"
    )


def _freq_problems(result, span, dh, w, EA, given, n, g=9.81) -> list[str]:
    H = given[1] if given[0] == "H" else catenary_H(span, dh, w, given[1])
    f_in, f_out, error = frequencies(span, dh, w, EA, H, g, n)
    rel = 2e-5 + 10 * error
    problems = []
    for name, got, want in (
        ("f_in_plane", result.f_in_plane, f_in),
        ("f_out_of_plane", result.f_out_of_plane, f_out),
    ):
        got = np.asarray(got, dtype=float)
        if got.shape != want.shape:
            problems.append(f"{name}: {got.size} modes, oracle {want.size}")
            continue
        off = np.abs(got / want - 1)
        if off.max() > rel:
            k = int(off.argmax())
            problems.append(
                f"{name}[{k}]: oracle {want[k]:.15g} Hz, skcable {got[k]!r} (rel {off[k]:.3g} > {rel:.2g})"
            )
    if given[0] == "sag" and abs(result.H / H - 1) > 1e-10:
        problems.append(f"H of the sag: oracle {H!r}, skcable {result.H!r}")
    return problems


def natural(rng) -> Case:
    """`natural_frequencies` against Chebyshev collocation of Irvine's linear theory."""
    span, dh, w, EA, given, n = _cable(rng)

    def check(result, caught):
        return _freq_problems(result, span, dh, w, EA, given, n)

    return Case("natural_frequencies", _freq_call(span, dh, w, EA, given, n), FREQ_NAMES, check, None)


def natural_invariant(rng) -> Case:
    """Units x (10^a m, 10^b N) and the mirror (dh -> -dh): frequencies times 10^(-a/2), the same."""
    span, dh, w, EA, given, n = _cable(rng)
    a, b = int(rng.integers(-2, 3)), int(rng.integers(-3, 5))
    lam, mu = 10.0**a, 10.0**b
    scaled = lam * given[1] if given[0] == "sag" else mu * given[1]
    expr = (
        f"({_freq_call(span, dh, w, EA, given, n)}, "
        f"{_freq_call(span * lam, -dh * lam, w * mu / lam, EA * mu, (given[0], scaled), n)})"
    )

    def check(result, caught):
        first, other = result
        problems = _freq_problems(first, span, dh, w, EA, given, n)
        for name in ("f_in_plane", "f_out_of_plane"):
            got = np.asarray(getattr(other, name)) * math.sqrt(lam)
            ref = np.asarray(getattr(first, name))
            off = np.abs(got / ref - 1).max()
            if off > 1e-9:
                problems.append(
                    f"mirrored, x{lam:g} m, x{mu:g} N: {name} x sqrt({lam:g}) off by {off:.3g} (> 1e-9)"
                )
        return problems

    return Case("natural_frequencies/invariant", expr, FREQ_NAMES, check, None, calls=2)


PRESETS = ("steel-9.5", "aluminium-10.1", "steel-12.7", "aluminium-14.3", "acsr-drake", "acsr-hawk")


def _recount(strand_obj, broken):
    """Area, EA, centroid, principal stick inertias and the slip inertia from the layers' data
    (wire j of a layer at ``phase + 2π j/count`` from +z towards +y, helix radius the core's
    radius plus the layers below and half the wire), in mpmath."""
    with mpmath.workdps(40):
        mats = strand_obj.layer_materials
        E_ref = mpmath.mpf(strand_obj.material.E_e)
        d0 = mpmath.mpf(strand_obj.core_diameter)
        wires = [(mpmath.mpf(0), mpmath.mpf(0), d0, mpmath.mpf(0), mats[0], True)]
        radius = d0 / 2
        for k, layer in enumerate(strand_obj.layers, 1):
            d = mpmath.mpf(layer.wire_diameter)
            R = radius + d / 2
            radius += d
            alpha = (
                mpmath.mpf(layer.lay_angle)
                if layer.lay_angle is not None
                else mpmath.atan(2 * mpmath.pi * R / mpmath.mpf(layer.lay_length))
            )
            for j in range(layer.count):
                psi = mpmath.mpf(layer.phase) + 2 * mpmath.pi * j / layer.count
                wires.append(
                    (R * mpmath.sin(psi), R * mpmath.cos(psi), d, alpha, mats[k], (k, j) not in broken)
                )
        alive = [wi for wi in wires if wi[5]]
        A = [mpmath.pi * wi[2] ** 2 / 4 for wi in alive]
        m = [mpmath.mpf(wi[4].E_e) / E_ref for wi in alive]
        c3 = [mpmath.cos(wi[3]) ** 3 for wi in alive]
        area = sum(A)
        EA = sum(E_ref * a * mi * c for a, mi, c in zip(A, m, c3, strict=True))
        am = sum(a * mi for a, mi in zip(A, m, strict=True))
        yc = sum(a * mi * wi[0] for a, mi, wi in zip(A, m, alive, strict=True)) / am
        zc = sum(a * mi * wi[1] for a, mi, wi in zip(A, m, alive, strict=True)) / am
        T = mpmath.matrix(2, 2)
        for a, mi, c, wi in zip(A, m, c3, alive, strict=True):
            dy, dz = wi[0] - yc, wi[1] - zc
            T[0, 0] += a * c * mi * dy * dy
            T[0, 1] += a * c * mi * dy * dz
            T[1, 1] += a * c * mi * dz * dz
        T[1, 0] = T[0, 1]
        values = sorted(mpmath.eigsy(T)[0], reverse=True)
        own = sum(
            mpmath.pi * wi[2] ** 4 / 64 * mpmath.cos(wi[3]) * mi for wi, mi in zip(alive, m, strict=True)
        )
        return {
            "area": area,
            "EA": EA,
            "centroid": (yc, zc),
            "principal": values,
            "own": own,
            "trace": T[0, 0] + T[1, 1],
        }


def _section_problems(sec, want, label) -> list[str]:
    problems = []

    def near(name, got, ref, scale):
        if abs(float(got) - float(ref)) > 1e-12 * float(scale):
            problems.append(f"{label}{name}: oracle {float(ref):.17g}, skcable {float(got)!r}")

    near("area", sec.area, want["area"], want["area"])
    near("EA", sec.EA, want["EA"], want["EA"])
    size = mpmath.sqrt(want["area"])
    for i in range(2):
        near(f"centroid[{i}]", sec.centroid[i], want["centroid"][i], size)
    total = want["principal"][0] + want["own"]
    for i in range(2):
        stick = want["principal"][i] if want["principal"][i] > 1e-9 * want["trace"] else 0
        near(f"I_stick[{i}]", sec.I_stick[i], stick + want["own"], total)
        near(f"I_slip[{i}]", sec.I_slip[i], want["own"], total)
    return problems


def strand_section(rng) -> Case:
    """A preset strand, intact or with broken wires: its section recounted from the layers."""
    name = pick(rng, PRESETS)
    import skcable.strand as strand_module

    s = strand_module.preset(name)
    pairs = [(k, j) for k, layer in enumerate(s.layers, 1) for j in range(layer.count)]
    count = int(rng.integers(0, min(4, len(pairs)) + 1))
    broken = [pairs[i] for i in rng.choice(len(pairs), size=count, replace=False)] if count else []
    expr = f"strand.preset({name!r}).damaged(wires={sorted(broken)!r}).section()"

    def check(sec, caught):
        return _section_problems(sec, _recount(s, set(broken)), "")

    return Case("strand_section", expr, STRAND_NAMES, check, None)


def strand_turned(rng) -> Case:
    """A 1x7 strand's damage turned by one wire (60°): the same principal stiffnesses and area."""
    name = pick(rng, PRESETS[:4])
    count = int(rng.integers(1, 6))
    broken = sorted(int(j) for j in rng.choice(6, size=count, replace=False))
    shift = int(rng.integers(1, 6))
    turned = sorted((j + shift) % 6 for j in broken)
    expr = (
        f"(strand.preset({name!r}).damaged(wires={[(1, j) for j in broken]!r}).section(), "
        f"strand.preset({name!r}).damaged(wires={[(1, j) for j in turned]!r}).section())"
    )

    def check(result, caught):
        first, other = result
        problems = []
        for attr in ("area", "EA"):
            if abs(getattr(first, attr) / getattr(other, attr) - 1) > 1e-13:
                problems.append(
                    f"turned by {shift} wires: {attr} {getattr(other, attr)!r} != {getattr(first, attr)!r}"
                )
        scale = float(np.max(first.I_stick))
        for i in range(2):
            if abs(first.I_stick[i] - other.I_stick[i]) > 1e-12 * scale:
                problems.append(
                    f"turned by {shift} wires: I_stick[{i}] {other.I_stick[i]!r} != {first.I_stick[i]!r}"
                )
        return problems

    return Case("strand_section/turned", expr, STRAND_NAMES, check, None, calls=2)


def strand_frequencies(rng) -> Case:
    """Bending frequencies of a pinned strand under tension: the tensioned beam's closed form
    ``f_n = n/(2L) sqrt(N/m) sqrt(1 + (nπ)² EI/(N L²))`` (EI stick and slip)."""
    name = pick(rng, PRESETS)
    N = pick(rng, [0.0, log_uniform(rng, 1.0, 1e6)])
    length = log_uniform(rng, 0.05, 100.0)
    mass = log_uniform(rng, 0.05, 5.0)
    axis = int(rng.integers(0, 2))
    n = int(rng.integers(1, 7))
    damage = int(rng.integers(0, 3))
    expr = (
        f"strand.strand_bending_frequencies(strand.preset({name!r}).damaged({damage}).section(), {fmt(N)}, "
        f"{fmt(length)}, {fmt(mass)}, axis={axis}, ends='pinned', n_modes={n})"
    )

    def check(result, caught):
        problems = []
        k = np.arange(1, n + 1)
        for label, EI, got in (
            ("f_stick", result.EI_stick, result.f_stick),
            ("f_slip", result.EI_slip, result.f_slip),
        ):
            omega2 = (k * np.pi / length) ** 4 * EI / mass + (k * np.pi / length) ** 2 * N / mass
            want = np.sqrt(omega2) / (2 * np.pi)
            off = np.abs(np.asarray(got) / want - 1)
            if off.max() > 1e-5:
                j = int(off.argmax())
                problems.append(
                    f"{label}[{j}]: closed form {want[j]:.15g} Hz, skcable {got[j]!r} (rel {off[j]:.3g})"
                )
        return problems

    return Case("strand_frequencies", expr, STRAND_NAMES, check, None)


REGIMES = {
    "natural_frequencies": natural,
    "natural_frequencies/invariant": natural_invariant,
    "strand_section": strand_section,
    "strand_section/turned": strand_turned,
    "strand_frequencies": strand_frequencies,
}
