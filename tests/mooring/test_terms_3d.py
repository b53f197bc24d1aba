"""The cable terms in three dimensions (the last coordinate vertical): their forces against
Morison's formula written here, their derivatives against central differences, the plane case
as the 3-D one in a vertical plane, the current profiles and the refusals."""

import pickle

import numpy as np
import pytest

from skcable import bvp
from skcable.bvp.current import ProfileCurrent, TabulatedCurrent, UniformCurrent, current_of
from skcable.errors import InputError

RHO = 1025.0


def states(seed=3, size=9, z_range=(-120.0, -5.0)):
    """Random 3-D cable states: position, a = dr/ds (stretch about 1), tension."""
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(0, 300, size), rng.uniform(-50, 50, size)
    z = rng.uniform(*z_range, size)
    a = rng.normal(size=(3, size))
    a *= rng.uniform(1.0, 1.01, size) / np.linalg.norm(a, axis=0)
    T = rng.uniform(1e3, 1e5, size)
    return x, y, z, a, T


def morison_here(v, a, d, cn, ct):
    """½ρd|a|(C_n|v_n|v_n + C_t|v_t|v_t) for one point, with plain vector algebra."""
    n = np.linalg.norm(a)
    t = a / n
    vt = np.dot(v, t) * t
    vn = v - vt
    return 0.5 * RHO * d * n * (cn * np.linalg.norm(vn) * vn + ct * np.linalg.norm(vt) * vt)


def sheared(z):
    return 0.8 + 0.004 * z, 0.3 - 0.002 * z + 1e-5 * z * z


def sheared_slope(z):
    return 0.004 + 0 * z, -0.002 + 2e-5 * z


CURRENTS = {
    "uniform vector": (0.7, -0.4),
    "profile": ProfileCurrent(sheared, sheared_slope),
    "profile, slope by differences": ProfileCurrent(sheared),
    "table": TabulatedCurrent([0.0, 30.0, 80.0, 200.0], [[1.0, 0.2], [0.8, 0.4], [0.3, 0.5], [0.1, 0.1]]),
}


@pytest.mark.parametrize("name", list(CURRENTS))
def test_current_drag_in_3d_is_morisons_formula(name):
    d, cn, ct = 0.12, 1.2, 0.01
    drag = bvp.CurrentDrag(CURRENTS[name], d, cd_normal=cn, cd_tangential=ct)
    x, y, z, a, T = states()
    f = drag.forces(bvp.CableState(x, y, None, a, T, z=z)).f
    profile = current_of(CURRENTS[name])
    for k in range(x.size):
        U = profile.velocity(np.array(z[k]))
        v = np.array([U[0], U[1], 0.0])
        np.testing.assert_allclose(f[:, k], morison_here(v, a[:, k], d, cn, ct), rtol=1e-13, atol=1e-14)


def test_the_table_is_linear_in_depth_and_held_beyond_it():
    table = TabulatedCurrent([10.0, 50.0], [[1.0, 0.0], [0.2, 0.4]], surface=5.0)
    z = np.array([0.0, -25.0, -45.0, -100.0])  # depths 5 (held), 30 (halfway), 50 (last), 105 (held)
    np.testing.assert_allclose(table.velocity(z), [[1.0, 0.6, 0.2, 0.2], [0.0, 0.2, 0.4, 0.4]], rtol=1e-15)
    np.testing.assert_allclose(table.gradient(z[1:2]), [[0.02], [-0.01]], rtol=1e-14)  # dU/dz = -dU/d(depth)
    assert np.all(table.gradient(z[[0, 3]]) == 0.0)


TERMS_3D = {
    "buoyancy": bvp.Buoyancy(0.02, gradient=0.05, surface=0.0),
    "wind": bvp.WindDrag(lambda z: 20 + 0.01 * z, 0.03, direction=(0.6, 0.8, 0.0)),
    "scalar current": bvp.CurrentDrag(lambda d: 1.5 * (1 - d / 300), 0.1, direction=(0.0, 1.0, 0.0)),
    **{
        f"current, {k}": bvp.CurrentDrag(v, 0.1, cd_tangential=0.02)
        for k, v in CURRENTS.items()
        if k != "profile, slope by differences"
    },
}


@pytest.mark.parametrize("name", list(TERMS_3D))
def test_3d_term_derivatives_match_central_differences(name):
    term = TERMS_3D[name]
    x, y, z, a, T = states(z_range=(-190.0, -5.0))
    if name == "current, table":  # away from the table's kinks (depths 30, 80), where it is smooth
        z = np.where(np.abs(np.abs(z) - 30) < 2, z + 5, z)
        z = np.where(np.abs(np.abs(z) - 80) < 2, z + 5, z)
    out = term.forces(bvp.CableState(x, y, None, a, T, z=z))
    r = np.array([x, y, z])
    h = 1e-6
    scale = np.abs(out.f).max()

    def f_at(r, a):
        return term.forces(bvp.CableState.at(r, None, a, T)).f

    for j in range(3):
        e = np.zeros((3, 1))
        e[j] = h
        fd = (f_at(r + e * np.abs(r).max(), a) - f_at(r - e * np.abs(r).max(), a)) / (2 * h * np.abs(r).max())
        got = np.zeros_like(fd) if out.df_dr is None else out.df_dr[:, j]
        np.testing.assert_allclose(got, fd, rtol=1e-6, atol=1e-8 * scale)
        fd = (f_at(r, a + e) - f_at(r, a - e)) / (2 * h)
        got = np.zeros_like(fd) if out.df_da is None else out.df_da[:, j]
        np.testing.assert_allclose(got, fd, rtol=1e-6, atol=1e-8 * scale)


def test_a_plane_cable_is_the_3d_one_in_its_vertical_plane():
    """The 2-D terms (x, y up) and the 3-D ones (x, z up, y = 0) give the same force."""
    rng = np.random.default_rng(5)
    x, h = rng.uniform(0, 300, 6), rng.uniform(-90, -5, 6)
    a2 = np.array([rng.uniform(0.3, 1.0, 6), rng.uniform(-1.0, 1.0, 6)])
    a3 = np.array([a2[0], np.zeros(6), a2[1]])
    T = rng.uniform(1e3, 1e4, 6)
    pairs = [
        (bvp.Buoyancy(0.01, gradient=0.1), bvp.Buoyancy(0.01, gradient=0.1)),
        (bvp.CurrentDrag(lambda d: 1 + d / 100, 0.1), bvp.CurrentDrag(lambda d: 1 + d / 100, 0.1)),
        (
            bvp.CurrentDrag((0.9, 0.0), 0.1, cd_tangential=0.1),
            bvp.CurrentDrag((0.9, 0.0), 0.1, cd_tangential=0.1),
        ),
        (bvp.WindDrag(20.0, 0.03), bvp.WindDrag(20.0, 0.03)),
    ]
    for plane, space in pairs:
        f2 = plane.forces(bvp.CableState(x, h, None, a2, T)).f
        f3 = space.forces(bvp.CableState(x, 0 * x, None, a3, T, z=h)).f
        np.testing.assert_allclose(f3[[0, 2]], f2, rtol=1e-13, atol=1e-12)
        assert np.all(f3[1] == 0)


def test_a_cross_current_pushes_a_cable_out_of_its_plane():
    """A cable in the x-z plane, a current along y: all of it normal, f = ½ρ d |a| C_n U² ŷ."""
    d, U = 0.1, 0.9
    a = np.array([[0.6], [0.0], [0.8]]) * 1.002
    f = (
        bvp.CurrentDrag((0.0, U), d)
        .forces(bvp.CableState(*np.zeros((2, 1)), None, a, np.ones(1), z=-np.ones(1)))
        .f
    )
    np.testing.assert_allclose(
        f[:, 0], [0.0, 0.5 * RHO * d * 1.002 * 1.2 * U * U, 0.0], rtol=1e-14, atol=1e-15
    )


def test_bad_currents_and_directions_are_refused_by_name():
    with pytest.raises(InputError, match="depths.*sorted"):
        TabulatedCurrent([0.0, 50.0, 20.0], [[1, 0], [1, 0], [1, 0]])
    with pytest.raises(InputError, match="velocities"):
        TabulatedCurrent([0.0, 50.0], [[1, 0, 0], [1, 0, 0]])
    with pytest.raises(InputError, match="cd_normal"):
        bvp.CurrentDrag((1.0, 0.0), 0.1, cd_normal=-0.1)
    with pytest.raises(InputError, match="cd_tangential"):
        bvp.CurrentDrag((1.0, 0.0), 0.1, cd_tangential=-0.1)
    with pytest.raises(InputError, match="direction"):
        bvp.CurrentDrag((1.0, 0.0), 0.1, direction=(1.0, 0.0, 0.0))
    x, y, z, a, T = states()
    with pytest.raises(InputError, match="direction"):  # a plane direction on a cable in space
        bvp.CurrentDrag(1.0, 0.1, direction=(0.6, 0.8)).forces(bvp.CableState(x, y, None, a, T, z=z))
    with pytest.raises(InputError, match="speed.*Uy"):  # a current out of a plane cable's plane
        bvp.CurrentDrag((1.0, 0.5), 0.1).forces(bvp.CableState(x, z, None, a[:2], T))
    with pytest.raises(InputError, match="current.*non-finite"):
        bvp.CurrentDrag(ProfileCurrent(lambda z: (np.full_like(z, np.inf), 0 * z)), 0.1).forces(
            bvp.CableState(x, y, None, a, T, z=z)
        )
    with pytest.raises(InputError, match="current"):
        UniformCurrent((1.0, 2.0, 3.0))
    with pytest.raises(InputError, match="a"):
        bvp.CableState(x, y, None, a, T)  # three rows of a for a plane cable


def test_3d_terms_pickle():
    x, y, z, a, T = states()
    state = bvp.CableState(x, y, None, a, T, z=z)
    for term in [TERMS_3D["buoyancy"], *(bvp.CurrentDrag(v, 0.1) for v in CURRENTS.values())]:
        copy = pickle.loads(pickle.dumps(term))
        np.testing.assert_array_equal(copy.forces(state).f, term.forces(state).f)
        assert repr(copy) == repr(term)
