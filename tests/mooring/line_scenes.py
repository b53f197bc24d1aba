"""Seeded scenes of mooring lines for `solve_line_bvp`, and the references it is checked against.

`scenes(seed, count)` draws lines from taut to slack: one to three segments of chain, wire or
rope (weights 1 to 3000 N/m, ``EA/(wL)`` from 1e2 to 1e9), optionally a clump weight at a
joint, with no seabed, a flat seabed through the anchor (friction 0 to 1) or one below it; the
fairlead at any height above the seabed, the length from 0.98 to 3 chords. Each scene is the
keyword arguments of both `mooring.Line` (closed form, the reference) and `solve_line_bvp`.

The references are independent of the BVP: `mooring.Line.solve` (closed-form closures of the
segments, Jonkman's grounded pieces) and, for one-segment lines, a 40-digit mpmath solution of
Irvine's or Jonkman's closure (`exact_one_segment`).

`tolerance(scene, line)` sizes the comparison of fairlead forces: the BVP's discretisation at
64 elements (``DISCRETE``) or, where it is larger, the round-off of the data carried into H. A
taut line's H is set by its strain: ``H ≈ EA (c/L' - 1)`` with ``L'`` the suspended length, so
a rounding ``ε`` of the data moves H by ``ε`` times the condition number ``|∂ ln H/∂ ln L|``,
which `condition` measures on the closed form (central differences in the length).

Used by ``tests/bvp/test_bvp_scenes.py`` (a sample in CI) and ``benchmarks/line_bvp_survey.py``
(the full survey).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from skcable import mooring

#: relative error in the fairlead force of the BVP at its default 64 elements, on graded meshes
DISCRETE = 1e-6
EPS = float(np.finfo(float).eps)


@dataclass(frozen=True)
class Scene:
    """One line: ``span, dh`` (m), ``segments`` ``(length, w, EA)`` from the anchor, a clump
    ``(joint, weight)`` or None, ``seabed`` (None or a height <= 0), ``friction``."""

    span: float
    dh: float
    segments: tuple
    clump: tuple | None = None
    seabed: float | None = None
    friction: float = 0.0
    tags: dict = field(default_factory=dict, compare=False)

    @property
    def length(self) -> float:
        return float(sum(seg[0] for seg in self.segments))

    def line(self):
        """The closed-form `mooring.Line` of the scene."""
        attachments = [] if self.clump is None else [mooring.ClumpWeight(*self.clump)]
        return mooring.Line(
            [mooring.Segment(*seg) for seg in self.segments],
            attachments,
            seabed=self.seabed,
            friction=self.friction,
        )

    def bvp_kwargs(self):
        """Keyword arguments of `solve_line_bvp` (without span, dh, segments)."""
        point_loads = []
        if self.clump is not None:
            joint, weight = self.clump
            point_loads = [(float(sum(seg[0] for seg in self.segments[:joint])), weight)]
        return dict(seabed=self.seabed, friction=self.friction, point_loads=point_loads)

    def solve_bvp(self, **options):
        return mooring.solve_line_bvp(self.span, self.dh, list(self.segments), **self.bvp_kwargs(), **options)


def _log_uniform(rng, low, high):
    return float(math.exp(rng.uniform(math.log(low), math.log(high))))


def scene(rng) -> Scene:
    """One scene drawn from ``rng`` (module docstring)."""
    n = int(rng.integers(1, 4))
    span = _log_uniform(rng, 10.0, 2000.0)
    kind = rng.choice(["free", "flat", "below"], p=[0.35, 0.45, 0.2])
    if kind == "free":
        dh = float(span * rng.uniform(-3.0, 5.0))
    else:
        dh = float(span * _log_uniform(rng, 0.02, 10.0))
    seabed = None if kind == "free" else (0.0 if kind == "flat" else -float(rng.uniform(0.05, 1.0) * abs(dh)))
    chord = math.hypot(span, dh)
    regime = rng.choice(["taut", "mid", "slack"], p=[0.35, 0.35, 0.3])
    ratio = {
        "taut": 1.0 + _log_uniform(rng, 1e-7, 1e-2) * rng.choice([-1.0, 1.0]),
        "mid": 1.0 + _log_uniform(rng, 1e-2, 0.3),
        "slack": 1.0 + _log_uniform(rng, 0.3, 2.0),
    }[regime]
    length = chord * ratio
    shares = rng.dirichlet(np.ones(n)) * 0.9 + 0.1 / n
    segments = []
    for share in shares:
        w = _log_uniform(rng, 1.0, 3000.0)
        ea = _log_uniform(rng, 1e2, 1e9) * w * length
        segments.append((float(share * length), w, float(ea)))
    clump = None
    if n > 1 and rng.uniform() < 0.3:
        clump = (
            int(rng.integers(1, n)),
            float(_log_uniform(rng, 0.01, 1.0) * sum(s[0] * s[1] for s in segments)),
        )
    friction = float(rng.choice([0.0, 0.3, 1.0])) if kind == "flat" else 0.0
    tags = dict(kind=str(kind), regime=str(regime), n=n)
    return Scene(span, dh, tuple(segments), clump, seabed, friction, tags)


def scenes(seed: int, count: int):
    """``count`` scenes from the seed (a `numpy.random.default_rng`)."""
    rng = np.random.default_rng(seed)
    return [scene(rng) for _ in range(count)]


def condition(sc: Scene, line=None) -> float:
    """``|∂ ln H/∂ ln L|`` of the closed form: the segments' lengths scaled by ``1 ± 1e-7``."""

    def H(scale):
        segs = [(l * scale, w, ea) for l, w, ea in sc.segments]
        moved = Scene(sc.span, sc.dh, tuple(segs), sc.clump, sc.seabed, sc.friction)
        return moved.line().solve(sc.span, sc.dh).H

    h = 1e-7
    base = (line or sc.line().solve(sc.span, sc.dh)).H
    return abs(H(1 + h) - H(1 - h)) / (2 * h * base)


def tolerance(sc: Scene, line=None) -> float:
    """The relative tolerance of the fairlead force: ``DISCRETE``, or ``64 ε`` times the
    condition number where that is larger (module docstring)."""
    return max(DISCRETE, 64 * EPS * condition(sc, line))


def exact_one_segment(sc: Scene, start, digits=60):
    """(H, V_B) of a one-segment line without clump (Irvine's closure when it hangs free,
    Jonkman's when grounded on a flat seabed through the anchor), solved in mpmath at ``digits``
    digits from the ``start`` (H, V_B); None if the root found does not close to ``digits - 20``
    digits of the length (a taut line's closure cancels about 15 of them)."""
    import mpmath as mp

    mp.mp.dps = digits
    ((L, w, EA),) = sc.segments
    span, dh, L, w, EA, mu = (mp.mpf(repr(float(v))) for v in (sc.span, sc.dh, L, w, EA, sc.friction))

    def free(H, V):
        tva, tvb = V - w * L, V
        X = H * L / EA + H / w * (mp.asinh(tvb / H) - mp.asinh(tva / H))
        Z = (tvb**2 - tva**2) / (2 * w * EA) + (mp.hypot(H, tvb) - mp.hypot(H, tva)) / w
        return [X - span, Z - dh]

    def grounded(H, V):
        L_B = L - V / w
        X = L_B + H / w * mp.asinh(V / H) + H * L / EA
        if mu > 0:
            d = L_B - H / (mu * w)
            X += mu * w / (2 * EA) * (-(L_B**2) + d * max(d, 0))
        Z = H / w * (mp.sqrt(1 + (V / H) ** 2) - 1) + V**2 / (2 * EA * w)
        return [X - span, Z - dh]

    f = grounded if (sc.seabed == 0.0 and start[1] <= float(w * L)) else free
    try:
        H, V = mp.findroot(
            f, (mp.mpf(start[0]), mp.mpf(start[1])), tol=mp.mpf(10) ** (-digits + 10), verify=False
        )
    except (ValueError, ZeroDivisionError):
        return None
    if not (H > 0 and max(abs(r) for r in f(H, V)) < mp.mpf(10) ** (-digits + 20) * L):
        return None
    return float(H), float(V)
