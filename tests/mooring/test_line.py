"""Multi-segment mooring lines (`mooring.Line`): clump weights, buoys, seabed and friction.

References: `elastic_catenary` (the one-segment closed form, solved independently),
an mpmath solution of the closure equations written out here at 30 digits,
MoorPy's `System` (an independent quasi-static code), equilibrium of forces,
and central differences of the solver for the stiffness.
"""

import mpmath as mp
import numpy as np
import pytest

from skcable import cable, mooring
from skcable.errors import ConvergenceError, InputError
from skcable.mooring import Buoy, ClumpWeight, Line, Segment

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings("ignore:(strain|uplift_angle)\\b:skcable.errors.PlausibilityWarning")

CHAIN = (1000.0, 7.5e8)  # w (N/m in water), EA (N)
WIRE = (150.0, 6.0e8)


def _chain_wire_chain(clump=2.0e4, seabed=0.0, friction=0.0, lengths=(400.0, 300.0, 150.0)):
    segments = [
        mooring.Segment(lengths[0], *CHAIN),
        mooring.Segment(lengths[1], *WIRE),
        mooring.Segment(lengths[2], *CHAIN),
    ]
    attachments = [mooring.ClumpWeight(1, clump)] if clump else []
    return mooring.Line(segments, attachments, seabed=seabed, friction=friction)


# -- one segment and split segments against elastic_catenary ---------------------------------
ONE = [
    (800.0, 150.0, 1000.0, 5e8, 850.0, None, 0.0),  # slack, no seabed
    (800.0, 150.0, 1000.0, 5e8, 700.0, None, 0.0),  # taut (shorter than the chord)
    (800.0, 150.0, 1000.0, 5e8, 850.0, 0.0, 0.0),  # grounded
    (800.0, 150.0, 1000.0, 5e8, 850.0, 0.0, 0.5),  # grounded, friction
    (800.0, 150.0, 1000.0, 5e8, 850.0, 0.0, 3.0),  # friction holds the whole pull
    (600.0, 300.0, 1500.0, 2e9, 780.0, 0.0, 1.0),
    (50.0, 300.0, 500.0, 3e9, 345.0, 0.0, 0.3),  # nearly vertical
    (990.0, 10.0, 300.0, 8e8, 999.0, 0.0, 0.6),  # nearly all on the seabed
    (700.0, 100.0, 800.0, 1e9, 690.0, 0.0, 0.0),  # lifted off the seabed
    (700.0, 100.0, 800.0, 1e9, 690.0, -50.0, 0.0),  # anchor above the seabed, clear of it
]


def _reference(span, dh, w, EA, L, seabed, mu):
    ref = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=seabed, friction=mu)
    H_A = getattr(ref, "H_A", ref.H)
    L_B = getattr(ref, "length_on_seabed", 0.0)
    return ref, H_A, L_B


@pytest.mark.parametrize("scene", ONE)
@pytest.mark.parametrize("pieces", [1, 2, 3])
def test_one_material_equals_elastic_catenary(scene, pieces):
    span, dh, w, EA, L, seabed, mu = scene
    ref, H_A, L_B = _reference(*scene)
    cuts = {1: [0.0, 1.0], 2: [0.0, 0.37, 1.0], 3: [0.0, 0.37, 0.81, 1.0]}[pieces]
    segments = [mooring.Segment(L * (b - a), w, EA) for a, b in zip(cuts[:-1], cuts[1:], strict=True)]
    sol = mooring.Line(segments, seabed=seabed, friction=mu).solve(span, dh)
    scale = max(ref.H, abs(ref.V_B))
    assert abs(sol.H - ref.H) <= 1e-12 * scale
    assert abs(sol.V_B - ref.V_B) <= 1e-12 * scale
    assert abs(sol.V_A - ref.V_A) <= 1e-12 * scale
    assert abs(sol.H_A - H_A) <= 1e-12 * scale
    assert abs(sol.length_on_seabed - L_B) <= 1e-12 * L
    assert sol.stiffness() == pytest.approx(np.asarray(ref.stiffness()), rel=1e-10)
    s = np.linspace(0.0, L, 41)
    assert sol.x_of_s(s) == pytest.approx(ref.x_of_s(s), abs=1e-9 * L)
    assert sol.y_of_s(s) == pytest.approx(ref.y_of_s(s), abs=1e-9 * L)
    # (SeabedCatenary.T_of_s(0) of a lifted line gives H, not T_A: compare inside the line)
    T_ref = ref.T_of_s(s[1:]) if hasattr(ref, "T_of_s") else ref.T(ref.x_of_s(s[1:]))
    assert sol.T_of_s(s[1:]) == pytest.approx(T_ref, rel=1e-10, abs=1e-10 * scale)
    assert sol.T_of_s(0.0) == pytest.approx(ref.T_A, rel=1e-12)
    if seabed == 0.0:
        assert sol.x_touchdown == pytest.approx(ref.x_touchdown, abs=1e-9 * L)


# -- an independent solution at 30 digits ---------------------------------------------------
def _mp_piece(H, Vb, Vt, w, EA):
    """Run and rise of an elastic catenary piece with end vertical forces Vb < Vt (Irvine 1981)."""
    L = (Vt - Vb) / w
    x = H * L / EA + H / w * (mp.asinh(Vt / H) - mp.asinh(Vb / H))
    y = (mp.sqrt(H**2 + Vt**2) - mp.sqrt(H**2 + Vb**2)) / w + (Vt**2 - Vb**2) / (2 * EA * w)
    return x, y


def _mp_grounded(T, m, l, EA):
    """Stretch of a grounded piece under tension T at its upper end, friction m per length."""
    ell = l if m == 0 else min(l, T / m)
    ell = max(ell, 0)
    return (T * ell - m * ell**2 / 2) / EA


def _mp_solve(line, span, dh, regime, H0, V0):
    """Closure of a 3-segment line with a clump at joint 1, written per regime:
    'free' (nothing on the seabed), 'in0' (touchdown inside segment 0),
    'joint1' (segment 0 grounded, the clump at joint 1 resting on the seabed)."""
    mp.mp.dps = 30
    L0, L1, L2 = (mp.mpf(s.length) for s in line.segments)
    w0, w1, w2 = (mp.mpf(s.w) for s in line.segments)
    EA0, EA1, EA2 = (mp.mpf(s.EA) for s in line.segments)
    P1 = mp.mpf(line.joint_forces[1])
    mu = mp.mpf(line.friction)
    span, dh = mp.mpf(span), mp.mpf(dh)

    def parts(H, V):
        Vb2 = V - w2 * L2
        Vt1 = Vb2
        Vb1 = Vt1 - w1 * L1
        Vt0 = Vb1 - P1
        Vb0 = Vt0 - w0 * L0
        x2, y2 = _mp_piece(H, Vb2, V, w2, EA2)
        x1, y1 = _mp_piece(H, Vb1, Vt1, w1, EA1)
        if regime == "free":
            x0, y0 = _mp_piece(H, Vb0, Vt0, w0, EA0)
            return x0 + x1 + x2, y0 + y1 + y2, 0
        if regime == "in0":
            x0, y0 = _mp_piece(H, mp.mpf(0), Vt0, w0, EA0)
            Lg = L0 - Vt0 / w0
            xg = Lg + _mp_grounded(H, mu * w0, Lg, EA0)
            return xg + x0 + x1 + x2, y0 + y1 + y2, Lg
        # joint1: segment 1 rises from the seabed with Vb1 in [0, P1]; the seabed carries P1 - Vb1
        T0 = max(H - mu * (P1 - Vb1), 0)
        xg = L0 + _mp_grounded(T0, mu * w0, L0, EA0)
        return xg + x1 + x2, y1 + y2, L0

    def f(H, V):
        X, Z, _ = parts(H, V)
        return [X - span, Z - dh]

    H, V = mp.findroot(f, (mp.mpf(H0), mp.mpf(V0)), tol=mp.mpf(10) ** -50)
    return H, V, parts(H, V)[2]


MP_SCENES = [
    # (span, dh, clump, friction, regime)
    (800.0, 300.0, 2.0e4, 0.0, "free"),
    (600.0, 450.0, 2.0e4, 0.0, "in0"),
    (600.0, 450.0, 2.0e4, 0.3, "in0"),  # friction takes part of the pull
    (600.0, 450.0, 2.0e4, 1.5, "in0"),  # friction takes it all: H_A = 0
    (780.0, 200.0, 2.0e5, 0.0, "joint1"),
    (780.0, 200.0, 2.0e5, 0.3, "joint1"),
]


@pytest.mark.parametrize("span, dh, clump, mu, regime", MP_SCENES)
def test_against_mpmath_closure(span, dh, clump, mu, regime):
    line = _chain_wire_chain(clump=clump, friction=mu)
    sol = line.solve(span, dh)
    st = sol._st
    assert st.contact == (regime != "free")
    assert (st.k, st.a > 0) == {"free": (0, False), "in0": (0, True), "joint1": (1, False)}[regime]
    H, V, Lg = _mp_solve(line, span, dh, regime, sol.H * 1.01, sol.V_B * 0.99)
    assert abs(sol.H - float(H)) <= 1e-9 * float(H)
    assert abs(sol.V_B - float(V)) <= 1e-9 * float(V)
    assert abs(sol.length_on_seabed - float(Lg)) <= 1e-9 * line.length


# -- MoorPy -------------------------------------------------------------------------------
def _moorpy_fairlead(line, span, dh, depth, g=9.81, rho=1025.0):
    system = pytest.importorskip("moorpy").System
    ms = system(depth=depth, g=g, rho=rho)
    n = len(line.segments)
    z0 = -depth
    points = [ms.addPoint(1, [0.0, 0.0, z0])]
    for j in range(1, n):
        P = float(line.joint_forces[j])
        m, v = (P / g, 0.0) if P >= 0 else (0.0, -P / (rho * g))
        frac = sum(s.length for s in line.segments[:j]) / line.length
        points.append(ms.addPoint(0, [frac * span, 0.0, z0 + frac * dh], m=m, v=v))
    points.append(ms.addPoint(1, [span, 0.0, z0 + dh]))
    for i, seg in enumerate(line.segments):
        name = f"t{i}"
        props = dict(name=name, d_vol=0.0, m=seg.w / g, w=seg.w, EA=seg.EA, d_nom=0.1)
        ms.setLineType(name=name, lineType=props)
        ms.addLine(seg.length, name, pointA=i + 1, pointB=i + 2, cb=line.friction)
    ms.initialize()
    ms.solveEquilibrium(tol=1e-9, maxIter=2000)
    f = ms.pointList[-1].getForces()
    return -f[0], -f[2]


@pytest.mark.parametrize(
    "span, dh, clump, buoy, mu",
    [(800.0, 300.0, 2.0e4, 0.0, 0.0), (600.0, 450.0, 2.0e4, 0.0, 0.0), (620.0, 300.0, 0.0, 8.0e4, 0.0)],
)
def test_against_moorpy(span, dh, clump, buoy, mu):
    """MoorPy's equilibrium tolerance here: 1e-9 m on the free joint (tol=), its catenary
    solver's own default 1e-6 relative, so agreement to a few 1e-6. Frictionless: MoorPy 1.x's
    `Line.staticSolve` replaces a line's `cb` by the height of its end A above the seabed, so a
    System line carries no seabed friction (the friction is checked against mpmath above)."""
    segments = [mooring.Segment(400.0, *CHAIN), mooring.Segment(300.0, *WIRE), mooring.Segment(150.0, *CHAIN)]
    att = [mooring.ClumpWeight(1, clump)] if clump else [mooring.Buoy(2, buoy)]
    line = mooring.Line(segments, att, seabed=0.0, friction=mu)
    sol = line.solve(span, dh)
    H, V = _moorpy_fairlead(line, span, dh, depth=dh + 100.0)
    assert sol.H == pytest.approx(H, rel=5e-6)
    assert sol.V_B == pytest.approx(V, rel=5e-6)


# -- statics, stiffness, maps ---------------------------------------------------------------
STATE_SCENES = [
    (_chain_wire_chain(friction=0.0), 800.0, 300.0),  # free
    (_chain_wire_chain(friction=0.0), 600.0, 450.0),  # grounded
    (_chain_wire_chain(friction=0.3), 600.0, 450.0),  # grounded, friction
    (_chain_wire_chain(friction=1.5), 600.0, 450.0),  # friction takes the whole pull
    (_chain_wire_chain(clump=2.0e5, friction=0.3), 780.0, 200.0),  # clump resting on the seabed
    (_chain_wire_chain(clump=2.0e5, friction=0.2), 780.0, 120.0),  # grounded clump, friction
    (Line([Segment(400.0, *CHAIN), Segment(300.0, *WIRE), Segment(150.0, *CHAIN)],
          [Buoy(2, 8.0e4), ClumpWeight(1, 1.0e4)], seabed=0.0, friction=0.3), 620.0, 300.0),
    (Line([Segment(300.0, *CHAIN), Segment(400.0, *WIRE), Segment(300.0, *WIRE)],
          [Buoy(2, 1.0e5)], seabed=0.0, friction=0.4), 800.0, 60.0),  # lazy wave
    (Line([Segment(420.0, 180.0, 3e7), Segment(25.0, 60.0, 5e8)],
          [Buoy(1, 9.0e4)], seabed=0.0, friction=1.0), 260.0, 200.0),  # buoy above B: V_B < 0
    (_chain_wire_chain(seabed=None), 500.0, -100.0),  # no seabed, B below A
]  # fmt: skip


@pytest.mark.parametrize("line, span, dh", STATE_SCENES)
def test_vertical_equilibrium_and_closure(line, span, dh):
    sol = line.solve(span, dh)
    # the seabed carries the grounded weight and the grounded clumps' share
    load = sum(s.w * s.length for s in line.segments) + line.joint_forces.sum()
    assert sol.V_A + sol.V_B + sol.seabed_reaction == pytest.approx(load, rel=1e-13)
    assert sol.x_of_s(line.length) == pytest.approx(span, rel=1e-12)
    assert sol.y_of_s(line.length) == pytest.approx(dh, abs=1e-12 * span)
    # horizontal equilibrium of the grounded part: friction takes H - H_A
    if sol.length_on_seabed > 0 and sol.H_A > 0:
        mu = line.friction
        grounded = sol.tensions()["grounded_length"].to_numpy() @ np.array([s.w for s in line.segments])
        clumps = sol.seabed_reaction - grounded
        assert sol.H - sol.H_A == pytest.approx(mu * (grounded + clumps), rel=1e-12, abs=1e-9 * sol.H)
    # tension equals the force of the two ends: T_B from (H, V_B) less the end attachment
    assert sol.T_B == pytest.approx(np.hypot(sol.H, sol.V_B - line.joint_forces[-1]), rel=1e-14)


@pytest.mark.parametrize("line, span, dh", STATE_SCENES)
def test_stiffness_against_central_differences(line, span, dh):
    sol = line.solve(span, dh)
    K = sol.stiffness()
    cols = []
    for d_span, d_dh in ((1.0, 0.0), (0.0, 1.0)):
        h = 1e-5 * np.hypot(span, dh)
        p = line.solve(span + h * d_span, dh + h * d_dh)
        m = line.solve(span - h * d_span, dh - h * d_dh)
        cols.append([(p.H - m.H) / (2 * h), (p.V_B - m.V_B) / (2 * h)])
    fd = np.array(cols).T
    assert K == pytest.approx(fd, rel=1e-6, abs=1e-6 * np.abs(fd).max())


@pytest.mark.parametrize("line, span, dh", STATE_SCENES)
def test_tension_along_the_line(line, span, dh):
    sol = line.solve(span, dh)
    table = sol.tensions()
    columns = ["segment", "length", "w", "EA", "T_lower", "T_upper", "H_upper"]
    assert list(table.columns) == [*columns, "stretched_length", "grounded_length"]
    ends = np.concatenate([[0.0], np.cumsum(table["length"])])
    eps = 1e-9
    # T at the segment ends equals the table, from inside the segment
    assert sol.T_of_s(ends[:-1] + eps) == pytest.approx(table["T_lower"], rel=1e-8, abs=1e-3)
    assert sol.T_of_s(ends[1:] - eps) == pytest.approx(table["T_upper"], rel=1e-8, abs=1e-3)
    # stretched length: the arc length of the profile, segment by segment (the line kinks at
    # loaded joints), from the chord sum of x_of_s, y_of_s
    for a, b, stretched in zip(ends[:-1], ends[1:], table["stretched_length"], strict=True):
        s = np.linspace(a, b, 20001)
        arc = np.hypot(np.diff(sol.x_of_s(s)), np.diff(sol.y_of_s(s))).sum()
        assert arc == pytest.approx(stretched, rel=1e-8)
    assert table["grounded_length"].sum() == pytest.approx(sol.length_on_seabed, rel=1e-14)
    # strain: dx/ds along the grounded part is 1 + T/EA (central differences)
    px, py = sol.outline(50).T
    floor = -np.inf if line.seabed is None else line.seabed
    assert px[0] == 0.0 and px[-1] == pytest.approx(span) and np.all(py >= floor - 1e-9 * span)


def test_end_attachments_go_to_the_supports():
    """A clump at the fairlead joint adds its weight to V_B, one at the anchor to V_A, a buoy
    at the fairlead takes its buoyancy off V_B; the line itself is unchanged (statics)."""
    bare = _chain_wire_chain(clump=0.0, friction=0.3).solve(600.0, 450.0)
    segments = list(_chain_wire_chain().segments)
    for att, dA, dB in (
        (mooring.ClumpWeight(3, 5.0e4), 0.0, 5.0e4),
        (mooring.ClumpWeight(0, 7.0e4), 7.0e4, 0.0),
        (mooring.Buoy(3, 2.0e4), 0.0, -2.0e4),
    ):
        sol = mooring.Line(segments, [att], seabed=0.0, friction=0.3).solve(600.0, 450.0)
        assert sol.H == bare.H and sol.H_A == bare.H_A and sol.T_B == bare.T_B
        assert sol.V_A == pytest.approx(bare.V_A + dA, rel=1e-15, abs=1e-9)
        assert sol.V_B == pytest.approx(bare.V_B + dB, rel=1e-15)


# -- robustness ---------------------------------------------------------------------------
def test_robustness_sweep():
    rng = np.random.default_rng(0)
    solved = refused = 0
    for _ in range(300):
        n = int(rng.integers(1, 4))
        segments = [
            mooring.Segment(rng.uniform(20, 600), 10 ** rng.uniform(1.5, 3.5), 10 ** rng.uniform(7, 10))
            for _ in range(n)
        ]
        att = []
        for j in range(1, n):
            kind = rng.integers(0, 3)
            if kind == 1:
                att.append(mooring.ClumpWeight(j, 10 ** rng.uniform(3, 5.5)))
            elif kind == 2:
                att.append(mooring.Buoy(j, 10 ** rng.uniform(3, 5)))
        L = sum(s.length for s in segments)
        seabed = [None, 0.0, -rng.uniform(1, 100)][int(rng.integers(0, 3))]
        mu = rng.uniform(0, 2) if seabed == 0.0 else 0.0
        line = mooring.Line(segments, att, seabed=seabed, friction=mu)
        span = L * rng.uniform(0.05, 1.2)
        dh = L * rng.uniform(0.02, 0.9) * (1 if seabed is not None else rng.choice([-1, 1]))
        try:
            sol = line.solve(span, dh)
        except (InputError, ConvergenceError):
            refused += 1
            continue
        solved += 1
        values = [sol.H, sol.V_A, sol.V_B, sol.H_A, sol.T_A, sol.T_B, sol.length_on_seabed, sol.x_touchdown]
        assert np.all(np.isfinite(values)) and (sol.H > 0 or sol.heap) and sol.H_A >= 0
        assert sol.residual() < 1e-11
        assert sol.x_of_s(L) == pytest.approx(span, rel=1e-10)
        assert np.all(np.isfinite(sol.stiffness()))
    assert solved > 200  # most random scenes are ordinary lines


@pytest.mark.parametrize(
    "span, dh, lengths, seabed",
    [
        (1500.0, 100.0, (1200.0, 200.0, 100.0), 0.0),  # slack: mostly on the seabed
        (1000.0, 300.0, (400.0, 300.0, 150.0), 0.0),  # taut: shorter than the chord, stretched
        (20.0, 840.0, (400.0, 300.0, 150.0), 0.0),  # nearly vertical
        (1338.0, 5.0, (1000.0, 300.0, 40.0), 0.0),  # all but the last metres grounded
        (700.0, 400.0, (900.0, 300.0, 150.0), None),  # longer than span + dh, hanging freely
        (700.0, 400.0, (900.0, 300.0, 150.0), -600.0),  # the same above a deep seabed
        (1.0, 400.0, (900.0, 300.0, 150.0), None),  # a deep U between close supports
    ],
)
def test_named_extremes(span, dh, lengths, seabed):
    line = _chain_wire_chain(lengths=lengths, seabed=seabed, friction=0.5 if seabed == 0.0 else 0.0)
    sol = line.solve(span, dh)
    assert sol.residual() < 1e-12
    assert np.isfinite(sol.stiffness()).all()


def test_refusals():
    line = _chain_wire_chain()
    assert _chain_wire_chain(lengths=(2000.0, 300.0, 150.0)).solve(500.0, 100.0).heap  # solved: H = 0
    with pytest.raises(InputError, match="^dh"):
        line.solve(500.0, -1.0)
    with pytest.raises(InputError, match="^span"):
        line.solve(0.0, 100.0)
    with pytest.raises(InputError, match="^span"):
        line.solve(np.nan, 100.0)
    # a buoy on the grounded part would lift it: not a single-touchdown line
    lifted = mooring.Line(
        [mooring.Segment(400.0, *CHAIN), mooring.Segment(300.0, *WIRE), mooring.Segment(150.0, *CHAIN)],
        [mooring.Buoy(1, 3.0e4)],
        seabed=0.0,
    )
    with pytest.raises(InputError, match="attachments"):
        lifted.solve(760.0, 100.0)
    # a lazy wave whose sag after the buoy would reach the seabed again
    wave = mooring.Line(
        [mooring.Segment(300.0, *CHAIN), mooring.Segment(400.0, *WIRE), mooring.Segment(300.0, *WIRE)],
        [mooring.Buoy(2, 5.0e4)],
        seabed=0.0,
    )
    with pytest.raises(InputError, match="attachments"):
        wave.solve(700.0, 60.0)
    # anchor above the seabed and the line touching it
    with pytest.raises(InputError, match="seabed"):
        _chain_wire_chain(seabed=-5.0).solve(700.0, 100.0)


@pytest.mark.parametrize(
    "build, argument",
    [
        (lambda: mooring.Segment(-1.0, 1.0, 1.0), "length"),
        (
            lambda: mooring.Line([mooring.Segment(1.0, 0.0, 1.0)]).solve(0.5, 0.1),
            "w",
        ),  # weightless: no catenary
        (lambda: mooring.Segment(1.0, 1.0, np.inf), "EA"),
        (lambda: mooring.Segment(1.0, "1", 1.0), "w"),
        (lambda: mooring.ClumpWeight(1, -5.0), "weight"),
        (lambda: mooring.ClumpWeight(1.5, 5.0), "joint"),
        (lambda: mooring.Buoy(-1, 5.0), "joint"),
        (lambda: mooring.Buoy(1, 0.0), "buoyancy"),
        (lambda: mooring.Line([]), "segments"),
        (lambda: mooring.Line([mooring.Segment(1.0, 1.0, 1.0)], [mooring.Buoy(2, 1.0)]), "joint"),
        (lambda: mooring.Line([mooring.Segment(1.0, 1.0, 1.0)], [object()]), "attachments"),
        (lambda: mooring.Line([mooring.Segment(1.0, 1.0, 1.0)], friction=0.2), "friction"),
        (lambda: mooring.Line([mooring.Segment(1.0, 1.0, 1.0)], seabed=1.0), "seabed"),
        (lambda: mooring.Line([mooring.Segment(1.0, 1.0, 1.0)], seabed=0.0, friction=-0.1), "friction"),
        (lambda: _chain_wire_chain().solve(600.0, 450.0).profile(2.5), "n"),
        (lambda: _chain_wire_chain().solve(600.0, 450.0).x_of_s(851.0), "s"),
    ],
)
def test_bad_inputs_name_the_argument(build, argument):
    with pytest.raises(InputError) as info:
        build()
    assert info.value.argument == argument


@pytest.mark.parametrize(
    ("span", "dh", "friction"), [(800.0, 150.0, 0.3), (500.0, 400.0, 0.0), (500.0, 400.0, 0.02)]
)
def test_line_against_the_seabed_bvp(span, dh, friction):
    # an independent discretisation: the arc-length BVP on scikit-fem with unilateral nodal
    # contact (primal-dual active set) converges to the closed form (as h^4 with the touchdown
    # fitted and the clump suspended; about h^3 with the clump resting on the seabed)
    segments = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    line = mooring.Line(
        [mooring.Segment(*s) for s in segments], [mooring.ClumpWeight(1, 2e4)], seabed=0.0, friction=friction
    )
    r = line.solve(span, dh)
    errors = []
    for n in (80, 160):
        b = mooring.solve_line_bvp(
            span, dh, segments, seabed=0.0, friction=friction, point_loads=[(300.0, 2e4)], n_elements=n
        )
        errors.append(
            max(abs(b.H - r.H) / r.T_B, abs(b.V_B - r.V_B) / r.T_B, abs(b.H_A - r.H_A) / r.T_B,
                abs(b.length_on_seabed - r.length_on_seabed) / line.length)
        )  # fmt: skip
    assert errors[1] < 1e-6 and errors[0] / errors[1] > 6.0, errors


# -- warm starts ------------------------------------------------------------------------------
def _one_material_line(span, dh, w, EA, L, seabed, mu):
    return mooring.Line([mooring.Segment(L, w, EA)], seabed=seabed, friction=mu)


WARM_SCENES = [
    *((_one_material_line(*scene), scene[0], scene[1]) for scene in ONE),
    *((_chain_wire_chain(clump=clump, friction=mu), span, dh) for span, dh, clump, mu, _ in MP_SCENES),
    *STATE_SCENES,
]


def _same_solution(warm, cold, rtol):
    """Forces, stiffness and joints of two solutions of one scene, relative to their scale."""
    force = max(abs(cold.H), abs(cold.V_B), abs(cold.V_A))
    for name in ("H", "V_B", "V_A", "H_A", "T_A", "T_B", "seabed_reaction"):
        assert getattr(warm, name) == pytest.approx(getattr(cold, name), rel=rtol, abs=rtol * force), name
    length = cold.length
    assert warm.length_on_seabed == pytest.approx(cold.length_on_seabed, abs=rtol * length)
    assert warm.x_joints == pytest.approx(cold.x_joints, abs=rtol * length)
    assert warm.y_joints == pytest.approx(cold.y_joints, abs=rtol * length)
    K = cold.stiffness()
    assert warm.stiffness() == pytest.approx(K, rel=1e-9, abs=1e-9 * np.abs(K).max())


@pytest.mark.parametrize("line, span, dh", WARM_SCENES)
def test_warm_start_gives_the_cold_solution(line, span, dh, monkeypatch):
    """Newton from the solution at a nearby fairlead (0.3% off, as between two iterates of a
    moored body) reaches the cold solution to round-off, without the cold path."""
    cold = line.solve(span, dh)
    near = line.solve(span * 1.003, dh + 0.003 * abs(dh))

    def no_cold_path(*args):
        raise AssertionError("the warm start fell back on the cold path")

    monkeypatch.setattr(line, "_guess", no_cold_path)
    monkeypatch.setattr(line, "_bracketed", no_cold_path)
    for start in (near, (near.H, near.V_B)):
        _same_solution(line.solve(span, dh, start=start), cold, rtol=1e-12)


@pytest.mark.parametrize("line, span, dh", STATE_SCENES[1:6])
def test_warm_start_from_far_away_falls_back_on_the_cold_path(line, span, dh, monkeypatch):
    """A start where the closed form has no state (the whole line on the seabed): the cold
    path runs and gives the cold solution; so does a start far off in H and V."""
    cold = line.solve(span, dh)
    calls = []
    guess = line._guess
    monkeypatch.setattr(line, "_guess", lambda *args: calls.append(args) or guess(*args))
    _same_solution(line.solve(span, dh, start=(cold.H, -1e3 * line.weight)), cold, rtol=1e-12)
    assert len(calls) == 1
    _same_solution(line.solve(span, dh, start=(1e-9 * cold.H, 1e3 * line.weight)), cold, rtol=1e-12)
    # forces whose products underflow (the smallest float): no state there, the cold path runs
    _same_solution(line.solve(span, dh, start=(5e-324, 0.0)), cold, rtol=1e-12)
    one = mooring.Line([line.segments[0]], seabed=line.seabed, friction=line.friction)
    _same_solution(one.solve(span, 0.5 * dh, start=(5e-324, 1e-300)), one.solve(span, 0.5 * dh), rtol=1e-12)


def test_bad_warm_starts_are_refused():
    line = _chain_wire_chain()
    other = _chain_wire_chain()
    sol = other.solve(600.0, 450.0)
    for start, argument in (
        (sol, "start"),  # a solution of another line
        ((float("nan"), 1e5), "start"),
        ((-1.0, 1e5), "start"),
        ((1e5, float("inf")), "start"),
        ((1e5, 1e5, 0.0), "start"),
        ("warm", "start"),
        (1e5, "start"),
    ):
        with pytest.raises(InputError) as err:
            line.solve(600.0, 450.0, start=start)
        assert err.value.argument == argument


# -- slack in a heap on the seabed (H = 0) -----------------------------------------------------
HEAP_ONE = [  # (span, dh, w, EA, length, friction): longer than the L-shape
    (400.0, 100.0, 1000.0, 1e9, 700.0, 0.0),
    (400.0, 100.0, 1000.0, 1e9, 700.0, 1.0),
    (50.0, 300.0, 2000.0, 1e6, 900.0, 0.0),  # soft: the hanging part stretches 30 %
]


@pytest.mark.parametrize("scene", HEAP_ONE)
@pytest.mark.parametrize("pieces", [1, 3])
def test_heap_one_material_equals_elastic_catenary(scene, pieces):
    span, dh, w, EA, L, mu = scene
    ref = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0, friction=mu)
    assert ref.heap
    cuts = {1: [0.0, 1.0], 3: [0.0, 0.37, 0.81, 1.0]}[pieces]
    segments = [mooring.Segment(L * (b - a), w, EA) for a, b in zip(cuts[:-1], cuts[1:], strict=True)]
    sol = mooring.Line(segments, seabed=0.0, friction=mu).solve(span, dh)
    assert sol.heap and sol.H == 0.0 and sol.H_A == 0.0 and sol.V_A == 0.0
    assert sol.V_B == pytest.approx(ref.V_B, rel=1e-12) and sol.T_B == pytest.approx(ref.T_B, rel=1e-12)
    assert sol.length_on_seabed == pytest.approx(ref.length_on_seabed, rel=1e-12)
    assert sol.x_touchdown == span
    assert sol.seabed_reaction == pytest.approx(w * ref.length_on_seabed, rel=1e-12)
    assert sol.residual() < 1e-13
    s = np.linspace(0.0, L, 301)
    np.testing.assert_allclose(sol.x_of_s(s), ref.x_of_s(s), rtol=1e-12, atol=1e-12 * L)
    np.testing.assert_allclose(sol.y_of_s(s), ref.y_of_s(s), rtol=1e-12, atol=1e-12 * L)
    np.testing.assert_allclose(sol.T_of_s(s), ref.T_of_s(s), rtol=1e-12, atol=1e-12 * ref.V_B)
    np.testing.assert_allclose(sol.stiffness(), ref.stiffness(), rtol=1e-12, atol=1e-12 * ref.w)
    table = sol.tensions()
    assert table["stretched_length"].sum() == pytest.approx(ref.stretched_length, rel=1e-12)
    assert "heap" in repr(sol)


SOFT_WIRE = (150.0, 1.0e6)  # a soft middle segment: a visible gap where the clump sits on the seabed


def _heap_line():
    segments = [
        mooring.Segment(2000.0, *CHAIN),
        mooring.Segment(60.0, *SOFT_WIRE),
        mooring.Segment(40.0, *CHAIN),
    ]
    return mooring.Line(segments, [mooring.ClumpWeight(1, 2.0e4)], seabed=0.0, friction=0.5)


def _heap_reference(dh):
    """The vertical part of `_heap_line` written out from the seabed up at 30 digits: the
    tension at a height is the weight below it down to the seabed (clump included).
    Returns ``V_B``, the grounded length and the seabed's share of the clump."""
    (w0, EA0), (w1, EA1), (w2, EA2), P = CHAIN, SOFT_WIRE, CHAIN, 2.0e4
    mp.mp.dps = 30

    def piece(L, T_bot, w, EA):  # height and top tension of a piece hanging L above tension T_bot
        return L * (1 + (2 * T_bot + w * L) / (2 * EA)), T_bot + w * L

    def from_clump(T0):  # T0 just above the clump: the wire and the top chain
        z1, T1 = piece(60, T0, w1, EA1)
        z2, T2 = piece(40, T1, w2, EA2)
        return z1 + z2, T2

    if dh <= 40 * (1 + w2 * 40 / (2 * EA2)):  # the foot in the top chain
        l = mp.findroot(lambda l: piece(l, 0, w2, EA2)[0] - dh, 20)
        return float(w2 * l), float(2060 + 40 - l), 2.0e4
    if dh <= from_clump(mp.mpf(P))[0]:  # the foot at the clump, partly carried by the seabed
        T0 = mp.findroot(lambda t: from_clump(t)[0] - dh, 1.0e4)
        return float(from_clump(T0)[1]), 2000.0, float(P - T0)
    # the clump hangs above the seabed with l of the bottom chain
    l = mp.findroot(lambda l: from_clump(w0 * l + P)[0] + piece(l, 0, w0, EA0)[0] - dh, 10)
    return float(from_clump(w0 * l + P)[1]), float(2000 - l), 0.0


@pytest.mark.parametrize("dh", [30.0, 100.5, 101.6, 150.0])  # top chain; clump on the seabed (2); clump hangs
def test_heap_vertical_part_across_segments_and_a_clump(dh):
    line = _heap_line()
    sol = line.solve(800.0, dh)
    V_B, grounded, carried = _heap_reference(dh)
    assert sol.heap and sol.H == 0.0
    assert sol.V_B == pytest.approx(V_B, rel=1e-12)
    assert sol.length_on_seabed == pytest.approx(grounded, rel=1e-12)
    # the seabed carries the grounded chain and its share of the clump: vertical equilibrium
    on_bed = [min(grounded, 2000.0), np.clip(grounded - 2000.0, 0, 60), np.clip(grounded - 2060.0, 0, 40)]
    expected = CHAIN[0] * on_bed[0] + SOFT_WIRE[0] * on_bed[1] + CHAIN[0] * on_bed[2] + carried
    assert sol.seabed_reaction == pytest.approx(expected, rel=1e-12)
    assert sol.V_B + sol.seabed_reaction == pytest.approx(line.weight, rel=1e-13)
    assert sol.residual() < 1e-13
    assert sol.y_joints[-1] == pytest.approx(dh, rel=1e-13) and sol.x_joints[-1] == 800.0
    # the tension along the vertical part: w per metre, the clump's hanging share at joint 1
    s1 = 2000.0
    jump = sol.T_of_s(s1 + 1e-9) - sol.T_of_s(s1 - 1e-9)
    assert jump == pytest.approx(2.0e4 - carried, abs=1e-3)
    # stiffness: only ∂V_B/∂dh, by central differences inside the heap regime
    h = 1e-4
    plus, minus = line.solve(800.0, dh + h), line.solve(800.0, dh - h)
    wider = line.solve(800.0 + 10 * h, dh)
    assert plus.heap and minus.heap and wider.heap
    K = sol.stiffness()
    assert K[0].tolist() == [0.0, 0.0] and K[1, 0] == 0.0 and wider.V_B == sol.V_B
    assert K[1, 1] == pytest.approx((plus.V_B - minus.V_B) / (2 * h), rel=1e-6)


def test_heap_warm_starts_across_the_boundary():
    """Warm starts from a taut solution into the heap and back give the cold solutions."""
    line = _chain_wire_chain(lengths=(700.0, 300.0, 150.0))
    spans = [1080.0, 1000.0, 700.0, 1000.0, 1070.0, 1100.0]
    previous = None
    kinds = []
    for span in spans:
        warm = line.solve(span, 100.0, start=previous)
        cold = line.solve(span, 100.0)
        _same_solution(warm, cold, rtol=1e-12)
        kinds.append(warm.heap)
        previous = warm
    assert True in kinds and False in kinds


def test_heap_with_a_buoy_is_refused():
    segments = [mooring.Segment(2000.0, *CHAIN), mooring.Segment(60.0, *WIRE), mooring.Segment(40.0, *CHAIN)]
    line = mooring.Line(segments, [mooring.Buoy(1, 5.0e3)], seabed=0.0)
    with pytest.raises(InputError) as err:  # the buoy would lift slack off the seabed
        line.solve(800.0, 150.0)
    assert err.value.argument == "attachments"


@pytest.mark.parametrize("dh", [30.0, 150.0])  # the foot in the top chain; below the hanging clump
def test_taut_line_tends_to_the_heap_at_the_boundary(dh):
    line = _heap_line()
    heap = line.solve(800.0, dh)
    boundary = heap.length_on_seabed  # the span the slack just covers
    at = line.solve(boundary, dh)
    assert at.heap and at.V_B == pytest.approx(heap.V_B, rel=1e-14)
    previous = np.inf
    for eps in (1e-3, 1e-5, 1e-7):
        r = line.solve(boundary * (1 + eps), dh)
        assert not r.heap and r.H > 0 and r.residual() < 1e-11
        gaps = [
            r.H / heap.V_B,
            abs(r.V_B - heap.V_B) / heap.V_B,
            abs(r.length_on_seabed - heap.length_on_seabed) / line.length,
        ]
        # about linear in the span's excess over the boundary relative to the height
        # (measured: 0.05-0.3 of eps·boundary/dh down to eps = 1e-8)
        assert max(gaps) <= eps * boundary / dh and max(gaps) < previous
        previous = max(gaps)
