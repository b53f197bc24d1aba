"""A rod cut by the still water line: the buoyancy of its sections' submerged area (issue 33).

Each value is checked against a computation written here: the circular segment's area
``r² acos(y/r) - y sqrt(r² - y²)`` of a section whose centre lies ``y = z / cos β`` above the water
line (``β`` the axis' inclination from the horizontal), integrated along the axis by scipy's
``quad``; the floating rod's draught by ``brentq`` on that area; the submerged length of a
vertical rod's axis (the model before this one, its closed form); and the stiffness by central
differences of the forces.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.spatial.transform import Rotation

from skcable import mooring
from skcable.errors import PlausibilityWarning
from skcable.mooring.rod import Rod, RodBody
from skcable.mooring.rod_waterline import slice_integrals, waterline_shares

ADDED_MASS = (
    Path(__file__).resolve().parents[1] / "data" / "moordyn" / "MoorDyn" / "tests" / "Mooring" / "rod_tests"
) / "AddedMass.txt"
RHO, G = 1025.0, 9.80665


def segment_area(r, y):
    """The area (m²) of a disc of radius ``r`` below a chord ``y`` above its centre."""
    y = min(max(y, -r), r)
    return r * r * math.acos(y / r) - y * math.sqrt(r * r - y * y)


def quad_buoyancy(r, a, b):
    """``(volume (m³), centre along the axis from a (0..1))`` of the rod from ``a`` to ``b`` below
    ``z = 0``: its sections' segments integrated by ``quad``."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    length = float(np.linalg.norm(b - a))
    cos_beta = float(np.hypot(*(b - a)[:2])) / length
    za, dz = float(a[2]), float(b[2] - a[2])

    def area(t):
        z = za + t * dz
        if cos_beta == 0.0:
            return math.pi * r * r if z < 0.0 else 0.0
        return segment_area(r, z / cos_beta)

    cuts = [(c - za) / dz for c in (-r * cos_beta, 0.0, r * cos_beta)] if dz != 0.0 else []
    options = dict(points=[t for t in cuts if 0.0 < t < 1.0] or None, epsabs=1e-14 * r * r, epsrel=1e-13)
    first = quad(area, 0.0, 1.0, limit=200, **options)[0]
    moment = quad(lambda t: t * area(t), 0.0, 1.0, limit=200, **options)[0]
    return first * length, (moment / first if first > 0 else 0.0)


TILTED = [  # (a, b): rods crossing the water line at every inclination, and near its limits
    ([0.0, 0.0, -0.3], [2.0, 1.0, 0.4]),
    ([0.0, 0.0, 0.1], [3.0, 0.0, -0.05]),  # near horizontal, band across its whole length
    ([0.0, 0.0, -0.2], [2.0, 0.0, -0.2 + 1e-9]),  # horizontal to 1e-9: u_a = u_b to 4e-9
    ([0.0, 0.0, -1.0], [1e-4, 0.0, 1.0]),  # near vertical: the band 5e-5 of its length
    ([1.0, -1.0, 0.24], [-1.0, 2.0, 0.26]),  # just touching, the rest dry
    ([0.0, 0.0, -0.26], [1.0, 1.0, -0.23]),  # just wet at one end
    ([0.0, 0.0, 0.24999], [0.0, 3.0, 0.24999]),  # level, its lowest 1e-5 of its radius wet
]


@pytest.mark.parametrize(("a", "b"), TILTED)
def test_a_tilted_rod_s_buoyancy_and_its_centre_are_its_sections_segments_integrated(a, b):
    r = 0.25
    length = float(np.linalg.norm(np.subtract(b, a)))
    q = RHO * G * math.pi * r * r * length
    shares = waterline_shares(q, r, np.array(a), np.array(b))
    volume, centre = quad_buoyancy(r, a, b)
    assert shares.fa + shares.fb == pytest.approx(RHO * G * volume, rel=1e-12, abs=1e-13 * q)
    assert shares.fb == pytest.approx(centre * RHO * G * volume, rel=1e-12, abs=1e-13 * q)


def test_the_integrals_hold_to_round_off_where_the_rod_is_near_horizontal():
    """Near horizontal (``u_a`` and ``u_b`` 4e-9 apart, near ``u = -1`` where the segment's area
    has its branch point) against mpmath's quadrature at 40 digits."""
    mpmath = pytest.importorskip("mpmath")
    mpmath.mp.dps = 40
    za, zb, h = -0.25 + 1e-9, -0.25 + 2e-9, 0.25

    def f(t):
        u = (mpmath.mpf(za) + t * (mpmath.mpf(zb) - mpmath.mpf(za))) / mpmath.mpf(h)
        return (mpmath.acos(u) - u * mpmath.sqrt(1 - u * u)) / mpmath.pi

    I0, I1 = slice_integrals(za, zb, h)[:2]
    assert abs(I0 - float(mpmath.quad(f, [0, 1]))) < 1e-15
    assert abs(I1 - float(mpmath.quad(lambda t: t * f(t), [0, 1]))) < 1e-15


@pytest.mark.parametrize(("za", "zb"), [(-3.0, 1.0), (2.0, -0.5), (-1e-3, 4.0)])
def test_a_vertical_rod_has_the_submerged_length_of_its_axis(za, zb):
    """Vertical: the model before this one, its closed form: the submerged length ``s`` of the
    axis at the middle of that part, shared by the lever rule, to the last digit."""
    r, length = 0.3, abs(zb - za)
    q = RHO * G * math.pi * r * r * length
    shares = waterline_shares(q, r, np.array([1.0, 2.0, za]), np.array([1.0, 2.0, zb]))
    t = za / (za - zb)  # the crossing, from a
    lo, hi = (0.0, t) if za < 0 else (t, 1.0)
    total, centre = q * (hi - lo), 0.5 * (lo + hi)
    assert shares.fa + shares.fb == pytest.approx(total, rel=1e-15)
    assert shares.fb == pytest.approx(centre * total, rel=1e-15)


@pytest.mark.parametrize("where", ["below", "above"])
def test_a_rod_wholly_below_or_above_the_water_line_is_unchanged(where):
    """Its lowest section's top below ``z = 0`` (all of ``ρ g π r² L``, half on each end) or its
    highest section's bottom above it (none); no stiffness from the water line."""
    r = 0.5
    a, b = np.array([0.0, 0.0, -0.6]), np.array([3.0, 0.0, -0.51])  # top of the sections: -0.01
    if where == "above":
        a, b = -a, -b
    q = 1234.5
    shares = waterline_shares(q, r, a, b)
    expected = 0.5 * q if where == "below" else 0.0
    assert (shares.fa, shares.fb) == (expected, expected)
    assert not shares.grad.any()


def _central(fun, x, e=1e-6):
    """Central differences of ``fun`` (a vector) with ``x``, column by column."""
    cols = []
    for k in range(len(x)):
        dx = np.zeros(len(x))
        dx[k] = e
        cols.append((fun(x + dx) - fun(x - dx)) / (2 * e))
    return np.array(cols).T


@pytest.mark.parametrize(("a", "b"), TILTED[:2] + TILTED[4:6] + [([0.0, 0.0, -1.0], [0.3, 0.2, 1.0])])
def test_a_rod_between_points_stiffness_is_its_forces_derivative(a, b):
    """``RodBetween.stiffness()`` against central differences of its end forces (a crossing rod:
    its buoyancy moves with its ends' heights and its inclination)."""
    length = float(np.linalg.norm(np.subtract(b, a)))
    rod = Rod(length, 0.5, 80.0, axial_stiffness=1e6)
    x0 = np.concatenate([a, b]).astype(float)

    def forces(x):
        return rod.solve_between(x[:3], x[3:], None).end_forces.ravel()

    K = rod.solve_between(x0[:3], x0[3:], None).stiffness()
    fd = -_central(forces, x0)
    assert np.abs(K - fd).max() <= 1e-7 * np.abs(K).max()


def _angles(R):
    yaw, pitch, roll = Rotation.from_matrix(R).as_euler("ZYX")
    return [roll, pitch, yaw]


@pytest.mark.parametrize("reference", ["a", "middle"])
@pytest.mark.parametrize(
    "pose",
    [[0.3, -0.2, -0.4, 0.2, 0.3, 0.5], [0.0, 0.0, 0.05, 0.0, 0.02, 0.1], [1.0, 2.0, -1.3, 1.2, 0.1, -0.4]],
)
def test_a_rod_body_s_stiffness_is_its_loads_derivative(reference, pose):
    """``RodBody.posed_loads``: ``K = -∂(force, moment about the reference)/∂(x, rotation
    vector)`` against central differences, the rotation vector turning its axes
    (``R → exp([ω]x) R``, scipy's ``Rotation``)."""
    body = RodBody(Rod(3.0, 0.6, 100.0), reference=reference)
    q = np.array(pose)
    G0, K = body.posed_loads(q)
    R = body.rotation(q)

    def loads(v):
        turned = Rotation.from_rotvec(v[3:]).as_matrix() @ R
        return body.posed_loads(np.array([*(q[:3] + v[:3]), *_angles(turned)]))[0]

    fd = -_central(loads, np.zeros(6))
    assert np.abs(G0).max() > 0 and np.abs(K).max() > 0
    assert np.abs(K - fd).max() <= 1e-7 * np.abs(K).max()


def test_moordyn_s_floating_rod_floats_level_at_its_segment_s_draught():
    """MoorDyn's ``rod_tests/AddedMass.txt``: a free rod (d = 0.5 m, 100 kg/m, 2 m) starts level 10
    m under water and floats up; it comes to rest level at the surface, its axis where its
    section's submerged segment weighs its mass, ``ρ A_seg(z) = m`` (``brentq`` here: about half
    of its section, ``m / (ρ π d²/4) = 0.497``), stable but for its turning about its own axis and
    its moves in the plane (nothing holds them)."""
    model = mooring.read_moordyn(ADDED_MASS)
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        eq = model.equilibrium()
    r, m = 0.25, 100.0
    system = model.system
    assert m / (system.rho * math.pi * r * r) == pytest.approx(0.497, abs=5e-4)
    z = brentq(lambda y: system.rho * segment_area(r, y) - m, -r, r, xtol=1e-15, rtol=1e-15)
    (rod,) = model.rods.values()
    a, b = (eq.points[p.index].position for p in rod.points)
    np.testing.assert_allclose([a[2], b[2]], [z, z], rtol=0, atol=1e-9)
    np.testing.assert_allclose(a[:2], [0.0, -1.0], atol=1e-12)  # level, where it started in plan
    np.testing.assert_allclose(b[:2], [0.0, 1.0], atol=1e-12)
    assert eq.stable and sorted(eq.neutral) == ["body 0 pitch", "body 0 surge", "body 0 sway", "body 0 yaw"]
    # its waterplane (J.N. Newman, Marine Hydrodynamics, 1977, ch. 6): a rectangle w = 2 sqrt(r² - z²)
    # by L, heave ρ g w L, tilt about its middle ρ g w L³/12 (its loads on its axis: G and B there)
    K = eq.stiffness()
    w, L, rho_g = 2.0 * math.sqrt(r * r - z * z), 2.0, system.rho * system.g
    assert K[2, 2] == pytest.approx(rho_g * w * L, rel=1e-9)
    assert K[3, 3] == pytest.approx(rho_g * w * L**3 / 12.0, rel=1e-9)


def test_a_rod_held_out_of_the_water_has_no_buoyancy_and_no_warning():
    """A rod pinned at z = 5 m hangs straight down, clear of the water: no buoyancy, and no
    warning (a rod's buoyancy is its submerged volume's, none there: nothing implausible)."""
    system = mooring.MooringSystem(depth=50.0)
    rod = Rod(2.0, 0.4, 30.0, rho=system.rho, g=system.g)
    body = RodBody(rod)
    system.add_body(body, position=body.start([0.0, 0.0, 5.0], [1.0, 0.0, 5.0 - math.sqrt(3.0)]), pinned=True)
    A = system.add_point(body.end_a, body=body)
    B = system.add_point(body.end_b, body=body)
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        eq = system.equilibrium(neutral="hold")
    np.testing.assert_allclose(eq.points[B.index].position, [0.0, 0.0, 3.0], atol=1e-9)
    np.testing.assert_allclose(eq.points[A.index].position, [0.0, 0.0, 5.0], atol=1e-12)
    G, _ = body.posed_loads(eq.bodies[0].position)
    assert not G.any()
