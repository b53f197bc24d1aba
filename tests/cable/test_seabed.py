"""Elastic catenary on a flat seabed with friction (Jonkman 2007; MoorPy as a peer).

References: an mpmath solution of the same closure equations at 40 digits,
MoorPy's `Catenary.catenary` (an independent implementation), central finite
differences of the solver for the stiffness, and equilibrium of the parts.
"""

import mpmath as mp
import numpy as np
import pytest

from skcable import cable
from skcable.errors import InputError

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings("ignore:(strain|uplift_angle)\\b:skcable.errors.PlausibilityWarning")


def _moorpy_catenary():
    """MoorPy's catenary, for the tests that compare with it (skipped where MoorPy is absent;
    the rest of this module runs everywhere)."""
    return pytest.importorskip("moorpy.Catenary").catenary


# (span, dh, w, EA, length, friction): slack, taut, nearly vertical, nearly all grounded
SCENES = [
    (800.0, 150.0, 1000.0, 5e8, 850.0, 0.0),  # the issue's scene
    (800.0, 150.0, 1000.0, 5e8, 850.0, 0.5),
    (800.0, 150.0, 1000.0, 5e8, 850.0, 3.0),  # friction holds the whole pull: H_A = 0
    (1000.0, 200.0, 700.0, 1e7, 1150.0, 0.2),  # soft line
    (600.0, 300.0, 1500.0, 2e9, 780.0, 1.0),
    (50.0, 300.0, 500.0, 3e9, 345.0, 0.3),  # nearly vertical
    (990.0, 10.0, 300.0, 8e8, 999.0, 0.6),  # nearly all on the seabed
    (500.0, 5.0, 2000.0, 1e6, 503.0, 0.1),  # shallow, soft
]


def _mp_grounded(span, dh, w, EA, L, cb, H0, V0):
    """Jonkman's (2007) closure at 40 digits, from the reference's form with max()."""
    mp.mp.dps = 40
    span, dh, w, EA, L, cb = (mp.mpf(v) for v in (span, dh, w, EA, L, cb))

    def f(H, V):
        L_B = L - V / w
        X = L_B + H / w * mp.asinh(V / H) + H * L / EA
        if cb > 0:
            d = L_B - H / (cb * w)
            X += cb * w / (2 * EA) * (-(L_B**2) + d * max(d, 0))
        Z = H / w * (mp.sqrt(1 + (V / H) ** 2) - 1) + V**2 / (2 * EA * w)
        return [X - span, Z - dh]

    H, V = mp.findroot(f, (mp.mpf(H0), mp.mpf(V0)), tol=mp.mpf(10) ** -35)
    L_B = L - V / w
    return H, V, L_B, max(H - cb * w * L_B, 0)


def _mp_free(span, dh, w, EA, L, H0, V0):
    """Irvine's (1981) elastic catenary closure at 40 digits, unknowns (H, V_A)."""
    mp.mp.dps = 40
    span, dh, w, EA, L = (mp.mpf(v) for v in (span, dh, w, EA, L))

    def f(H, VA):
        VB = w * L - VA
        X = H * L / EA + H / w * (mp.asinh(VB / H) - mp.asinh(-VA / H))
        Z = L * (w * L / 2 - VA) / EA + (mp.sqrt(H**2 + VB**2) - mp.sqrt(H**2 + VA**2)) / w
        return [X - span, Z - dh]

    return mp.findroot(f, (mp.mpf(H0), mp.mpf(V0)), tol=mp.mpf(10) ** -35)


@pytest.mark.parametrize("scene", SCENES)
def test_against_mpmath_40_digits(scene):
    span, dh, w, EA, L, cb = scene
    r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0, friction=cb)
    H, V, L_B, H_A = _mp_grounded(*scene, r.H * 1.001, r.V_B * 0.999)
    assert r.H == pytest.approx(float(H), rel=1e-12)
    assert r.V_B == pytest.approx(float(V), rel=1e-12)
    assert r.length_on_seabed == pytest.approx(float(L_B), rel=1e-12)
    assert r.H_A == pytest.approx(float(H_A), rel=1e-12, abs=1e-12 * r.H)
    assert r.residual() < 1e-13


def test_issue_scene_against_moorpy():
    moorpy_catenary = _moorpy_catenary()
    # skcable gave H = 753 kN with the line 47 m below the anchor; MoorPy with contact 250 kN
    free = cable.elastic_catenary(800, 150, 1000, 5e8, length=850)
    r = cable.elastic_catenary(800, 150, 1000, 5e8, length=850, seabed=0.0)
    fAH, fAV, fBH, fBV, info = moorpy_catenary(800, 150, 850, 5e8, 1000, CB=0.0, Tol=1e-12)
    assert free.y_low < -40  # the free line dips below the anchor
    assert r.H == pytest.approx(-fBH, rel=1e-9)
    assert r.V_B == pytest.approx(-fBV, rel=1e-9)
    assert r.length_on_seabed == pytest.approx(info["LBot"], rel=1e-9)
    assert r.H_A == pytest.approx(fAH, rel=1e-9) and r.V_A == 0.0
    assert 2.50e5 < r.H < 2.51e5
    # no seabed: both free solutions agree
    fAH, fAV, fBH, fBV, info = moorpy_catenary(800, 150, 850, 5e8, 1000, CB=-1e3, Tol=1e-12)
    assert free.H == pytest.approx(-fBH, rel=1e-9) and free.V_B == pytest.approx(-fBV, rel=1e-9)


def _random_scenes(n, seed, top=0.98):
    rng = np.random.default_rng(seed)
    span = rng.uniform(20.0, 1500.0, n)
    dh = rng.uniform(1.0, 400.0, n)
    chord = np.hypot(span, dh)
    # between the chord (taut) and span + dh (the L-shape: longer lies in a heap)
    L = chord + rng.uniform(-0.002, top, n) * (span + dh - chord)
    w = rng.uniform(50.0, 3000.0, n)
    EA = 10 ** rng.uniform(6.0, 10.0, n)
    cb = rng.choice([0.0, 0.05, 0.3, 1.0, 5.0], n)
    return span, dh, w, EA, L, cb


def test_random_scenes_against_moorpy_forces_length_stiffness():
    moorpy_catenary = _moorpy_catenary()
    compared = heaps = 0
    for span, dh, w, EA, L, cb in zip(*_random_scenes(150, 7), strict=True):
        fAH, fAV, fBH, fBV, info = moorpy_catenary(span, dh, L, EA, w, CB=cb, Tol=1e-12, MaxIter=500)
        r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0, friction=cb)
        assert r.residual() < 1e-12
        if r.heap:  # MoorPy's slack profile 4, H = 0; its K_HH is a regularising slack_kx
            assert info["ProfileType"] == 4 and r.H == fBH == 0.0 and r.H_A == 0.0
            assert r.V_B == pytest.approx(-fBV, rel=1e-12)
            assert r.length_on_seabed == pytest.approx(info["LBot"], rel=1e-12)
            assert r.stiffness()[1, 1] == pytest.approx(info["stiffnessB"][1][1], rel=1e-12)
            heaps += 1
            continue
        assert info["ProfileType"] != 4
        if info["ProfileType"] < 0 or info.get("error", False):
            continue  # MoorPy flags its own failure
        compared += 1
        assert r.H == pytest.approx(-fBH, rel=1e-6)
        assert r.V_B == pytest.approx(-fBV, rel=1e-6)
        assert r.H_A == pytest.approx(fAH, rel=1e-6, abs=1e-9 * r.T_B)
        assert r.length_on_seabed == pytest.approx(info["LBot"], rel=1e-6, abs=1e-9 * L)
        K, Km = r.stiffness(), np.asarray(info["stiffnessB"])
        assert np.abs(K - Km).max() <= 1e-5 * np.abs(K).max()
    assert compared > 100 and heaps > 0


def test_vectorised_equals_scalar():
    args = _random_scenes(40, 3)
    r = cable.elastic_catenary(*args[:4], length=args[4], seabed=0.0, friction=args[5])
    assert r.H.shape == (40,) and r.stiffness().shape == (40, 2, 2)
    assert np.any(r.length_on_seabed > 0) and np.any(r.length_on_seabed == 0)
    for i in range(40):
        s = cable.elastic_catenary(
            *(a[i] for a in args[:4]), length=args[4][i], seabed=0.0, friction=args[5][i]
        )
        for name in ("H", "V_A", "V_B", "H_A", "T_A", "T_B", "length_on_seabed", "x_touchdown"):
            assert getattr(r, name)[i] == pytest.approx(getattr(s, name), rel=1e-11, abs=1e-11 * s.T_B)
        np.testing.assert_allclose(r.stiffness()[i], s.stiffness(), rtol=1e-9)


def _fd_stiffness(span, dh, kwargs, h=1e-4):
    out = np.empty((2, 2))
    for j, (ds, dd) in enumerate(((h, 0.0), (0.0, h))):
        p = cable.elastic_catenary(span + ds, dh + dd, **kwargs)
        m = cable.elastic_catenary(span - ds, dh - dd, **kwargs)
        out[:, j] = [(p.H - m.H) / (2 * h), (p.V_B - m.V_B) / (2 * h)]
    return out


@pytest.mark.parametrize(
    "scene",
    [*SCENES, (300.0, 40.0, 100.0, 1e8, 320.0, None), (300.0, -40.0, 100.0, 1e6, 290.0, None)],
)
def test_stiffness_against_central_differences(scene):
    span, dh, w, EA, L, cb = scene
    kwargs = {"w": w, "EA": EA, "length": L}
    if cb is not None:
        kwargs.update(seabed=0.0, friction=cb)
    K = cable.elastic_catenary(span, dh, **kwargs).stiffness()
    K_fd = _fd_stiffness(span, dh, kwargs, h=1e-5 * span)
    np.testing.assert_allclose(K, K_fd, rtol=2e-5, atol=2e-5 * np.abs(K).max())


def test_free_line_is_irvines_with_nothing_on_the_seabed():
    # the fairlead low and the line rising from A: no contact
    span, dh, w, EA, L = 400.0, 150.0, 200.0, 1e8, 430.0
    r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0, friction=0.7)
    H, VA = _mp_free(span, dh, w, EA, L, r.H, r.V_A)
    assert r.length_on_seabed == 0.0 and r.x_touchdown == 0.0 and r.V_A < 0
    assert r.H == pytest.approx(float(H), rel=1e-12) and r.V_A == pytest.approx(float(VA), rel=1e-12)
    assert r.H_A == r.H


def test_anchor_above_seabed_without_touchdown():
    r = cable.elastic_catenary(800, 150, 1000, 5e8, length=850, seabed=-60.0, friction=1.0)
    free = cable.elastic_catenary(800, 150, 1000, 5e8, length=850)
    assert r.length_on_seabed == 0.0 and r.H == free.H and r.V_A == free.V_A and r.y_low > -60


def test_just_lifting_is_continuous():
    # the length at which the free line leaves A horizontally (V_A = 0, V_B = wL), 40 digits
    span, dh, w, EA = 500.0, 100.0, 800.0, 1e9
    mp.mp.dps = 40

    def lift_off(H, L):
        X = H * L / EA + H / w * mp.asinh(w * L / H)
        Z = H / w * (mp.sqrt(1 + (w * L / H) ** 2) - 1) + w * L**2 / (2 * EA)
        return [X - span, Z - dh]

    start = cable.elastic_catenary(span, dh, w, EA, length=520.0)
    H0, L0 = (float(v) for v in mp.findroot(lift_off, (mp.mpf(start.H), mp.mpf(520)), tol=mp.mpf(10) ** -30))
    for L in (L0 * (1 - 1e-12), L0, L0 * (1 + 1e-12)):
        r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=0.0, friction=0.5)
        assert r.residual() < 1e-12
        # L_B grows from zero in proportion to L - L0 (here about 40 (L - L0))
        assert r.length_on_seabed <= 100 * L0 * 1e-12 and abs(r.V_A) <= 1e-8 * r.T_B
        assert r.H == pytest.approx(H0, rel=1e-9)  # dH/dL L0/H ~ 100: continuous across lift-off
    above = cable.elastic_catenary(span, dh, w, EA, length=L0 * (1 + 1e-12), seabed=0.0)
    below = cable.elastic_catenary(span, dh, w, EA, length=L0 * (1 - 1e-12), seabed=0.0)
    assert above.length_on_seabed > 0 and below.length_on_seabed == 0


def test_profile_tension_and_equilibrium_along_the_line():
    r = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.2)
    L_B, mu_w = r.length_on_seabed, 0.2 * 1000.0
    assert r.T_of_s(0.0) == pytest.approx(r.H_A, rel=1e-14)
    assert r.T_of_s(850.0) == pytest.approx(r.T_B, rel=1e-14)
    assert r.T_of_s(L_B) == pytest.approx(r.H, rel=1e-14)
    # friction: dT/ds = C_B w on the seabed
    assert (r.T_of_s(L_B - 10.0) - r.T_of_s(L_B - 20.0)) / 10.0 == pytest.approx(mu_w, rel=1e-10)
    assert float(r.x_of_s(850.0)) == pytest.approx(800.0, rel=1e-14)
    assert float(r.y_of_s(850.0)) == pytest.approx(150.0, rel=1e-13)
    x = np.linspace(0.0, 800.0, 41)
    assert np.all(r.y(x)[x <= r.x_touchdown] == 0.0) and np.all(r.y(x)[x > r.x_touchdown] > 0.0)
    np.testing.assert_allclose(r.x_of_s(r.s_of_x(x)), x, rtol=1e-12, atol=1e-9)
    samples = r.samples(11)
    assert samples["xy"][0].tolist() == [0.0, 0.0] and samples["xy"][-1] == pytest.approx([800.0, 150.0])
    assert samples["tension"][0] == pytest.approx(r.H_A, rel=1e-12)


def test_to_vtk(tmp_path):
    meshio = pytest.importorskip("meshio")
    r = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.2)
    mesh = meshio.read(r.to_vtk(tmp_path / "line.vtu", n=21))
    assert mesh.points.shape == (21, 3) and np.all(mesh.points[:, 1] >= 0.0)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"seabed": 5.0}, "seabed"),  # above the anchor
        ({"seabed": 0.0, "friction": -0.1}, "friction"),
        ({"friction": 0.3}, "friction"),  # no seabed to rub on
        ({"seabed": -20.0, "friction": 0.3}, "friction"),  # touchdown between A and B: indeterminate
        ({"seabed": 200.0 - 400.0, "dh": -250.0}, "dh"),  # B below the seabed
        ({"seabed": 0.0, "dh": 0.0}, "dh"),  # B on the seabed
        ({"seabed": float("nan")}, "seabed"),
    ],
)
def test_errors(kwargs, name):
    args = {"length": 850.0, "dh": 150.0} | kwargs
    dh = args.pop("dh")
    with pytest.raises(InputError) as err:
        cable.elastic_catenary(800.0, dh, 1000.0, 5e8, **args)
    assert err.value.args[0].startswith(name) or name in str(err.value)


@pytest.mark.filterwarnings("ignore::skcable.errors.PlausibilityWarning")  # extremes by design
def test_extreme_magnitudes_converge_or_refuse():
    # lengths from mm to 100 km, weights and stiffnesses over many decades, with contact
    rng = np.random.default_rng(11)
    n = 400
    span = 10 ** rng.uniform(-3, 5, n)
    dh = span * 10 ** rng.uniform(-5, 2, n)
    w, EA = 10 ** rng.uniform(-3, 6, n), 10 ** rng.uniform(3, 13, n)
    chord = np.hypot(span, dh)
    L = chord + rng.uniform(0.05, 0.9, n) * (span + dh - chord)
    cb = rng.choice([0.0, 0.1, 1.0, 10.0], n)
    solved = 0
    for args in zip(span, dh, w, EA, L, cb, strict=True):
        r = cable.elastic_catenary(*args[:4], length=args[4], seabed=0.0, friction=args[5])
        solved += r.length_on_seabed > 0
        assert r.residual() < 1e-10
        K = r.stiffness()
        assert np.isfinite(K).all() and (K[0, 0] > 0 or r.heap) and K[1, 1] > 0
    assert solved > 200  # grounded lines


def test_frictionless_stiffness_is_symmetric_friction_breaks_it():
    # without friction the line is conservative: K = ∂(H, V_B)/∂(span, dh) is a Hessian
    args = _random_scenes(60, 13, top=0.8)
    r = cable.elastic_catenary(*args[:4], length=args[4], seabed=0.0)
    K = r.stiffness()
    np.testing.assert_allclose(K[..., 0, 1], K[..., 1, 0], rtol=1e-10)
    f = cable.elastic_catenary(*args[:4], length=args[4], seabed=0.0, friction=1.0)
    Kf = f.stiffness()
    holding = (f.length_on_seabed > 0) & (f.H_A > 0)  # friction acts and the anchor still pulls
    assert np.all(np.abs(Kf[holding, 0, 1] - Kf[holding, 1, 0]) > 1e-9 * np.abs(Kf[holding, 0, 1]))


def test_mixed_seabed_heights_broadcast():
    seabed = np.array([0.0, -60.0, 0.0])
    span = np.array([800.0, 800.0, 760.0])
    r = cable.elastic_catenary(span, 150.0, 1000.0, 5e8, length=850.0, seabed=seabed, friction=0.0)
    for i in range(3):
        s = cable.elastic_catenary(span[i], 150.0, 1000.0, 5e8, length=850.0, seabed=seabed[i])
        assert r.H[i] == pytest.approx(s.H, rel=1e-12) and r.V_B[i] == pytest.approx(s.V_B, rel=1e-12)
        assert r.length_on_seabed[i] == pytest.approx(s.length_on_seabed, rel=1e-12)
    assert r.length_on_seabed[0] > 0 and r.length_on_seabed[1] == 0


def _mp_anchor_above(span, dh, w, EA, L, d, H0, V10, VB0):
    """Three parts at 40 digits: A down to the seabed (vertex there), grounded, up to B;
    unknowns H, V_1 (vertical at A), V_B; frictionless, so H is constant."""
    mp.mp.dps = 40
    span, dh, w, EA, L, d = (mp.mpf(v) for v in (span, dh, w, EA, L, d))

    def height(H, V):  # rise of an elastic catenary from its vertex, V = w s
        return (mp.sqrt(H**2 + V**2) - H) / w + V**2 / (2 * EA * w)

    def run(H, V):  # its horizontal run
        return H * V / (w * EA) + H / w * mp.asinh(V / H)

    def f(H, V1, VB):
        L_B = L - V1 / w - VB / w
        return [
            height(H, V1) - d,
            height(H, VB) - (dh + d),
            run(H, V1) + L_B * (1 + H / EA) + run(H, VB) - span,
        ]

    return mp.findroot(f, (mp.mpf(H0), mp.mpf(V10), mp.mpf(VB0)), tol=mp.mpf(10) ** -35)


@pytest.mark.parametrize(
    "scene",
    [
        (800.0, 150.0, 1000.0, 5e8, 850.0, 20.0),
        (800.0, 150.0, 1000.0, 5e8, 850.0, 46.5),  # the free line dips 47 m: just touching
        (600.0, 100.0, 300.0, 1e8, 700.0, 30.0),
        (300.0, 80.0, 50.0, 2e6, 420.0, 60.0),  # soft
    ],
)
def test_anchor_above_seabed_against_mpmath(scene):
    span, dh, w, EA, L, d = scene
    r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=-d)
    H, V1, VB = _mp_anchor_above(*scene, r.H, r.V_A, r.V_B)
    assert r.H == pytest.approx(float(H), rel=1e-12) and r.H_A == r.H
    assert r.V_A == pytest.approx(float(V1), rel=1e-12) and r.V_B == pytest.approx(float(VB), rel=1e-12)
    assert r.length_on_seabed == pytest.approx(float(L - (V1 + VB) / w), rel=1e-10)
    assert r.residual() < 1e-13 and r.y_low == -d
    K, K_fd = (
        r.stiffness(),
        _fd_stiffness(span, dh, {"w": w, "EA": EA, "length": L, "seabed": -d}, 1e-5 * span),
    )
    np.testing.assert_allclose(K, K_fd, rtol=2e-5)
    # the profile: down to the seabed, along it, up to B
    x = np.linspace(0.0, span, 101)
    y = r.y(x)
    assert np.all(y >= -d - 1e-12 * d) and y[0] == 0.0 and y[-1] == pytest.approx(dh, rel=1e-12)
    assert np.all(y[(x >= r.x_landing) & (x <= r.x_touchdown)] == -d)
    np.testing.assert_allclose(r.x_of_s(r.s_of_x(x)), x, rtol=1e-12, atol=1e-9)
    assert r.T_of_s(0.0) == pytest.approx(r.T_A, rel=1e-14) and r.T_of_s(L) == pytest.approx(r.T_B, rel=1e-14)


def test_anchor_above_seabed_against_moorpy():
    moorpy_catenary = _moorpy_catenary()
    # MoorPy splits the line at the touchdown (frictionless there); where it converges, both agree
    fAH, fAV, fBH, fBV, info = moorpy_catenary(800.0, 150.0, 850.0, 5e8, 1000.0, CB=-40.0, Tol=1e-12)
    r = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=-40.0)
    assert r.H == pytest.approx(-fBH, rel=1e-9) and r.V_B == pytest.approx(-fBV, rel=1e-9)
    assert r.V_A == pytest.approx(-fAV, rel=1e-9) and r.length_on_seabed == pytest.approx(
        info["LBot"], rel=1e-9
    )
    np.testing.assert_allclose(r.stiffness(), info["stiffnessB"], rtol=1e-8)


def test_anchor_above_seabed_continuous_at_first_contact():
    free = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0)
    d = -free.y_low  # the seabed at the free line's low point
    for seabed in (-d * (1 - 1e-12), -d * (1 + 1e-12)):
        r = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=seabed)
        assert r.H == pytest.approx(free.H, rel=1e-8) and r.length_on_seabed < 1e-6


@pytest.mark.parametrize(("seabed", "friction"), [(0.0, 0.4), (-20.0, 0.0), (-100.0, 0.0)])
def test_stretched_length_is_the_integral_of_the_strain(seabed, friction):
    from scipy.integrate import quad

    r = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e6, length=850.0, seabed=seabed, friction=friction)
    breaks = [r.length_to_seabed, r.length_to_seabed + r.length_on_seabed]
    total = quad(lambda s: 1.0 + r.T_of_s(s) / 5e6, 0.0, 850.0, points=breaks, epsabs=0, epsrel=1e-13)[0]
    assert r.stretched_length == pytest.approx(total, rel=1e-12)
    # the grounded part lies straight: its stretched length is x_touchdown - x_landing
    ground = (
        quad(lambda s: 1.0 + r.T_of_s(s) / 5e6, *breaks, epsabs=0, epsrel=1e-13)[0]
        if breaks[1] > breaks[0]
        else 0
    )
    assert r.x_touchdown - r.x_landing == pytest.approx(ground, rel=1e-12, abs=1e-12)


def test_tension_at_the_anchor_of_a_lifted_line_is_T_A():
    # the line leaves the anchor upward (nothing grounded): T(0) carries the anchor's pull
    # V_A, not the seabed's H_A; checked against hypot(H, V_A) and Irvine's free line
    r = cable.elastic_catenary(np.array([700.0, 800.0]), 100.0, 800.0, 1e9, length=690.0, seabed=0.0)
    free = cable.elastic_catenary(np.array([700.0, 800.0]), 100.0, 800.0, 1e9, length=690.0)
    assert np.all(r.length_on_seabed == 0.0) and np.all(r.V_A < 0)
    np.testing.assert_allclose(r.T_of_s(0.0), np.hypot(free.H, free.V_A), rtol=1e-14)
    np.testing.assert_allclose(r.T_of_s(0.0), r.T_A, rtol=1e-14)


def test_scalar_path_equals_the_array_path_over_every_regime():
    """One scene runs on Python floats, several on arrays: the same iteration, to round-off.
    Grounded with and without friction, lifted, and anchor above the seabed with and without
    a touchdown."""
    span = np.array([800.0, 800.0, 700.0, 800.0, 800.0, 760.0, 990.0])
    dh = np.array([150.0, 150.0, 100.0, 150.0, 150.0, 150.0, 10.0])
    length = np.array([850.0, 850.0, 690.0, 850.0, 850.0, 850.0, 999.0])
    seabed = np.array([0.0, 0.0, 0.0, -20.0, -46.5, -200.0, 0.0])
    friction = np.array([0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.6])
    r = cable.elastic_catenary(span, dh, 1000.0, 5e8, length=length, seabed=seabed, friction=friction)
    assert np.any(r.length_to_seabed > 0) and np.any(r.length_on_seabed == 0)
    for i in range(len(span)):
        s = cable.elastic_catenary(
            span[i], dh[i], 1000.0, 5e8, length=length[i], seabed=seabed[i], friction=friction[i]
        )
        assert isinstance(s.H, float)
        names = ("H", "V_A", "V_B", "H_A", "T_B", "length_on_seabed", "length_to_seabed", "x_touchdown")
        for name in names:
            assert getattr(s, name) == pytest.approx(getattr(r, name)[i], rel=1e-12, abs=1e-12 * s.T_B), name
        np.testing.assert_allclose(s.stiffness(), r.stiffness()[i], rtol=1e-10)


# -- slack in a heap on the seabed (H = 0) ---------------------------------------------
def _hanging(height, w, EA):
    """Unstretched length hanging vertically over ``height``: the positive root of
    ``w l^2/(2 EA) + l - height = 0`` by the textbook formula at 50 digits (mpmath: its
    cancellation costs at most ~15 of them)."""
    with mp.workdps(50):
        c = mp.mpf(EA) / mp.mpf(w)
        return float(c * (mp.sqrt(1 + 2 * mp.mpf(height) / c) - 1))


# (span, dh, w, EA, length, seabed, friction): more line than the L-shape needs
HEAPS = [
    (400.0, 100.0, 1000.0, 1e9, 700.0, 0.0, 0.0),
    (400.0, 100.0, 1000.0, 1e9, 700.0, 0.0, 1.0),  # friction plays no part
    (800.0, 150.0, 1000.0, 5e8, 990.0, 0.0, 0.3),
    (50.0, 300.0, 2000.0, 1e6, 900.0, 0.0, 0.0),  # soft: the hanging part stretches 30 %
    (400.0, 100.0, 1000.0, 1e9, 700.0, -50.0, 0.0),  # anchor 50 m above the seabed
    (300.0, 20.0, 500.0, 1e7, 800.0, -120.0, 0.0),
]


@pytest.mark.parametrize(("span", "dh", "w", "EA", "L", "seabed", "mu"), HEAPS)
def test_heap_is_the_vertical_hanging_line(span, dh, w, EA, L, seabed, mu):
    r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=seabed, friction=mu)
    l_A, l_B = _hanging(-seabed, w, EA), _hanging(dh - seabed, w, EA)
    assert r.heap is True and r.H == 0.0 and r.H_A == 0.0
    assert r.V_B == pytest.approx(w * l_B, rel=1e-14) and r.T_B == r.V_B
    assert r.V_A == pytest.approx(w * l_A, rel=1e-14, abs=1e-300)  # upward reaction: A holds its part
    assert r.length_on_seabed == pytest.approx(L - l_A - l_B, rel=1e-14)
    assert r.length_to_seabed == pytest.approx(l_A, rel=1e-14, abs=1e-300)
    assert r.x_touchdown == span and r.x_landing == 0.0
    assert r.stretched_length == pytest.approx(-seabed + r.length_on_seabed + dh - seabed, rel=1e-14)
    assert r.residual() < 1e-14
    # the maps: vertical parts at x = 0 and span, the slack spread on the seabed
    s = np.linspace(0.0, L, 2001)
    x, y, T = r.x_of_s(s), r.y_of_s(s), r.T_of_s(s)
    on = (s > l_A) & (s < L - l_B)
    assert np.all(y[on] == seabed) and np.all(T[on] == 0.0)
    np.testing.assert_allclose(np.diff(x[on]), span / r.length_on_seabed * (s[1] - s[0]), rtol=1e-9)
    assert x[-1] == span and y[-1] == pytest.approx(dh, rel=1e-14)
    assert T[-1] == pytest.approx(r.V_B, rel=1e-14)
    assert x[0] == 0.0 and y[0] == 0.0 and T[0] == pytest.approx(r.V_A, rel=1e-14, abs=1e-300)
    # the tension of a vertical part is the weight below it, its height the stretched length below
    up = s >= L - l_B
    sigma = s[up] - (L - l_B)
    np.testing.assert_allclose(T[up], w * sigma, rtol=1e-12, atol=1e-12 * r.V_B)
    with mp.workdps(30):  # height of the point sigma: ∫ (1 + T(u)/EA) du from the foot, T = w u
        expected = [float(mp.quad(lambda u: 1 + w * u / EA, [0, sg])) + seabed for sg in sigma[::50]]
    below = s <= l_A  # the part from A: T = w (l_A - u) at u below A
    with mp.workdps(30):
        expected_A = [-float(mp.quad(lambda u: 1 + w * (l_A - u) / EA, [0, sg])) for sg in s[below][::20]]
    np.testing.assert_allclose(y[below][::20], expected_A, rtol=1e-12, atol=1e-12 * dh)
    np.testing.assert_allclose(y[up][::50], expected, rtol=1e-12, atol=1e-12 * dh)
    assert r.y(np.array([0.0, 0.5 * span, span])).tolist() == pytest.approx([0.0, seabed, dh], rel=1e-14)
    assert r.slope(0.5 * span) == 0.0
    with pytest.raises(InputError) as err:  # vertical at B: no finite slope
        r.slope(span)
    assert err.value.argument == "x"
    assert "heap" in repr(r)
    with pytest.raises(InputError):
        r.suspended  # noqa: B018 - no catenary hangs


def test_heap_matches_moorpy_profiles_4_and_5():
    """MoorPy's slack profiles: 4 (anchor on the seabed), 5 (anchor above it, CB = -height)."""
    moorpy_catenary = _moorpy_catenary()
    for span, dh, w, EA, L, seabed, mu in HEAPS:
        cb = mu if seabed == 0.0 else seabed
        fAH, fAV, fBH, fBV, info = moorpy_catenary(span, dh, L, EA, w, CB=cb, Tol=1e-12)
        r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=seabed, friction=mu)
        assert info["ProfileType"] == (4 if seabed == 0.0 else 5)
        assert r.H == -fBH == 0.0 and r.H_A == fAH == 0.0
        # MoorPy writes l = sqrt(2 h EA/w + (EA/w)^2) - EA/w, which cancels: 1e-9
        assert r.V_B == pytest.approx(-fBV, rel=1e-9)
        assert r.V_A == pytest.approx(-fAV, rel=1e-9, abs=1e-9 * r.V_B)
        assert r.length_on_seabed == pytest.approx(info["LBot"], rel=1e-9)
        # MoorPy's K_HH is a regularising constant (slack_kx); the statics give 0
        K = r.stiffness()
        assert K[0, 0] == K[0, 1] == K[1, 0] == 0.0
        assert K[1, 1] == pytest.approx(info["stiffnessB"][1][1], rel=1e-9)


def test_heap_stiffness_matches_central_differences():
    for span, dh, w, EA, L, seabed, mu in HEAPS:
        r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=seabed, friction=mu)
        K = r.stiffness()
        for j, h in enumerate((1e-3 * span, 1e-4 * dh)):
            d = np.array([h, 0.0]) if j == 0 else np.array([0.0, h])
            kwargs = {"length": L, "seabed": seabed, "friction": mu}
            plus = cable.elastic_catenary(span + d[0], dh + d[1], w, EA, **kwargs)
            minus = cable.elastic_catenary(span - d[0], dh - d[1], w, EA, **kwargs)
            assert plus.heap and minus.heap
            numeric = [(plus.H - minus.H) / (2 * h), (plus.V_B - minus.V_B) / (2 * h)]
            np.testing.assert_allclose(K[:, j], numeric, rtol=1e-7, atol=1e-7 * K[1, 1])


@pytest.mark.parametrize("seabed", [0.0, -40.0])
def test_taut_line_tends_to_the_heap_at_the_boundary(seabed):
    w, EA, L, dh, mu = 1000.0, 5e8, 850.0, 150.0, (0.5 if seabed == 0.0 else 0.0)
    boundary = L - _hanging(dh - seabed, w, EA) - _hanging(-seabed, w, EA)  # span of the L-shape
    heap = cable.elastic_catenary(boundary, dh, w, EA, length=L, seabed=seabed, friction=mu)
    assert heap.heap
    previous = np.inf
    for eps in (1e-3, 1e-5, 1e-7, 1e-9):
        r = cable.elastic_catenary(boundary * (1 + eps), dh, w, EA, length=L, seabed=seabed, friction=mu)
        assert not r.heap and r.residual() < 1e-12
        # the gap closes about linearly in eps (measured: <= 1.2 eps); 3 eps leaves a margin
        gaps = [
            r.H / heap.V_B,
            abs(r.V_B - heap.V_B) / heap.V_B,
            abs(r.V_A - heap.V_A) / heap.V_B,
            abs(r.length_on_seabed - heap.length_on_seabed) / L,
        ]
        assert max(gaps) <= 3 * eps and max(gaps) < previous
        previous = max(gaps)


def test_heap_array_equals_scalar():
    span = np.array([400.0, 400.0, 300.0, 800.0, 50.0, 400.0])
    L = np.array([700.0, 450.0, 800.0, 850.0, 900.0, 700.0])
    seabed = np.array([0.0, 0.0, -120.0, 0.0, 0.0, -50.0])
    dh, w, EA = np.array([100.0, 100.0, 20.0, 150.0, 300.0, 100.0]), 1000.0, 5e8
    r = cable.elastic_catenary(span, dh, w, EA, length=L, seabed=seabed)
    assert r.heap.tolist() == [True, False, True, False, True, True]
    s = 0.37 * L
    K = r.stiffness()
    for i in range(span.size):
        one = cable.elastic_catenary(span[i], dh[i], w, EA, length=L[i], seabed=seabed[i])
        assert one.heap == r.heap[i]
        for name in ("H", "V_A", "V_B", "H_A", "T_A", "T_B", "length_on_seabed", "x_touchdown", "x_landing"):
            assert getattr(r, name)[i] == pytest.approx(getattr(one, name), rel=1e-12, abs=1e-9), name
        assert r.x_of_s(s)[i] == pytest.approx(one.x_of_s(s[i]), rel=1e-12)
        assert r.y_of_s(s)[i] == pytest.approx(one.y_of_s(s[i]), rel=1e-12, abs=1e-12)
        assert r.T_of_s(s)[i] == pytest.approx(one.T_of_s(s[i]), rel=1e-12, abs=1e-9)
        np.testing.assert_allclose(K[i], one.stiffness(), rtol=1e-12, atol=1e-12 * np.abs(K[i]).max())
    assert r.residual() < 1e-12
    assert "heap at 4 of 6" in repr(r)


def test_heap_inputs_still_refused():
    with pytest.raises(InputError) as err:  # B below the seabed, however long the line
        cable.elastic_catenary(400.0, -60.0, 1000.0, 1e9, length=900.0, seabed=-50.0)
    assert err.value.argument == "dh"
    with pytest.raises(InputError) as err:
        cable.elastic_catenary(400.0, 100.0, 1000.0, 1e9, length=900.0, seabed=0.0, friction=-1.0)
    assert err.value.argument == "friction"
    with pytest.raises(InputError) as err:  # friction where a taut line touches down between A and B
        cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=-20.0, friction=0.3)
    assert err.value.argument == "friction"


def test_heap_samples_and_vtk(tmp_path):
    meshio = pytest.importorskip("meshio")
    r = cable.elastic_catenary(400.0, 100.0, 1000.0, 1e9, length=700.0, seabed=-30.0)
    samples = r.samples(5)
    # A, the seabed, B; vertical tangents at the ends; tensions those of the supports
    np.testing.assert_allclose(samples["xy"][:, 1], [0.0, -30.0, -30.0, -30.0, 100.0], rtol=1e-14)
    np.testing.assert_array_equal(samples["angle"], [-np.pi / 2, 0.0, 0.0, 0.0, np.pi / 2])
    np.testing.assert_allclose(samples["tension"], [r.T_A, 0.0, 0.0, 0.0, r.T_B], rtol=1e-14)
    mesh = meshio.read(r.to_vtk(tmp_path / "heap.vtu", n=11))
    assert mesh.points.shape == (11, 3) and np.all(mesh.points[1:-1, 1] == -30.0)
