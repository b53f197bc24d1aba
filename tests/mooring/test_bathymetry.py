"""Seabeds: planes, depth functions and bilinear grids, against their formulas written here,
central differences and MoorPy's bathymetry grid (``System.getDepthFromBathymetry``)."""

import pickle

import numpy as np
import pytest

from skcable.errors import InputError
from skcable.mooring.bathymetry import DepthFunction, Grid, Plane, bathymetry_of

RNG = np.random.default_rng(11)
XS = np.array([-100.0, 0.0, 150.0, 400.0, 900.0])
YS = np.array([-300.0, -50.0, 100.0, 350.0])
DEPTHS = RNG.uniform(150.0, 250.0, (YS.size, XS.size))  # MoorPy's layout: [iy, ix], positive down


def test_a_plane_is_its_formula():
    plane = Plane(-200.0, slope=(0.05, -0.02), origin=(10.0, 20.0))
    x, y = RNG.uniform(-500, 500, (2, 3, 4))
    np.testing.assert_allclose(plane.height(x, y), -200.0 + 0.05 * (x - 10) - 0.02 * (y - 20), rtol=1e-15)
    assert plane.gradient(x, y).shape == (2, 3, 4) and np.all(plane.hessian(x, y) == 0)
    n = plane.normal(x, y)
    np.testing.assert_allclose(
        n[:, 0, 0], np.array([-0.05, 0.02, 1.0]) / np.sqrt(1 + 0.05**2 + 0.02**2), rtol=1e-15
    )
    assert plane.flat is None and Plane(-50.0).flat == -50.0
    profile = plane.along((10.0, 20.0), (3.0, 4.0))  # slope along e = (0.6, 0.8)
    assert profile.slope(np.array(7.0)) == pytest.approx(0.05 * 0.6 - 0.02 * 0.8, rel=1e-15)
    assert profile(np.array(5.0)) == pytest.approx(-200.0 + 5.0 * (0.05 * 0.6 - 0.02 * 0.8), rel=1e-15)


def test_a_depth_function_and_its_hessian_by_differences():
    def b(x, y):
        return -180.0 + 20.0 * np.sin(x / 150.0) * np.cos(y / 90.0)

    def grad(x, y):
        return (
            20.0 / 150.0 * np.cos(x / 150.0) * np.cos(y / 90.0),
            -20.0 / 90.0 * np.sin(x / 150.0) * np.sin(y / 90.0),
        )

    seabed = DepthFunction(b, grad)
    x, y = RNG.uniform(-300, 300, (2, 6))
    hxx = -20.0 / 150.0**2 * np.sin(x / 150.0) * np.cos(y / 90.0)
    hxy = -20.0 / (150.0 * 90.0) * np.cos(x / 150.0) * np.sin(y / 90.0)
    hyy = -20.0 / 90.0**2 * np.sin(x / 150.0) * np.cos(y / 90.0)
    H = seabed.hessian(x, y)
    np.testing.assert_allclose(H, [[hxx, hxy], [hxy, hyy]], rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(seabed.normal(x, y), axis=0), 1.0, rtol=1e-15)
    # central differences of the height give the gradient it was given
    h = 1e-4
    np.testing.assert_allclose((b(x + h, y) - b(x - h, y)) / (2 * h), seabed.gradient(x, y)[0], rtol=1e-7)


def bilinear(x, y):
    """The bilinear interpolant of the grid (heights = -DEPTHS), written out cell by cell."""
    i = np.clip(np.searchsorted(XS, x, side="right") - 1, 0, XS.size - 2)
    j = np.clip(np.searchsorted(YS, y, side="right") - 1, 0, YS.size - 2)
    tx, ty = (x - XS[i]) / (XS[i + 1] - XS[i]), (y - YS[j]) / (YS[j + 1] - YS[j])
    z = -DEPTHS.T
    z00, z10, z01, z11 = z[i, j], z[i + 1, j], z[i, j + 1], z[i + 1, j + 1]
    height = (1 - tx) * (1 - ty) * z00 + tx * (1 - ty) * z10 + (1 - tx) * ty * z01 + tx * ty * z11
    bx = ((1 - ty) * (z10 - z00) + ty * (z11 - z01)) / (XS[i + 1] - XS[i])
    by = ((1 - tx) * (z01 - z00) + tx * (z11 - z10)) / (YS[j + 1] - YS[j])
    return height, np.array([bx, by])


def test_a_grid_is_bilinear_and_agrees_with_moorpys():
    import moorpy

    grid = Grid(XS, YS, -DEPTHS.T)
    x, y = RNG.uniform(-99, 899, 40), RNG.uniform(-299, 349, 40)
    height, slope = bilinear(x, y)
    np.testing.assert_allclose(grid.height(x, y), height, rtol=1e-13)
    np.testing.assert_allclose(grid.gradient(x, y), slope, rtol=1e-11, atol=1e-14)
    system = moorpy.System(depth=200.0)
    system.setBathymetry(XS, YS, DEPTHS)
    normal = grid.normal(x, y)
    for k in range(x.size):
        depth, nvec = system.getDepthFromBathymetry(x[k], y[k])
        assert -depth == pytest.approx(float(grid.height(x[k], y[k])), rel=1e-13)
        np.testing.assert_allclose(normal[:, k], nvec, rtol=1e-12, atol=1e-14)


def test_the_grids_cross_derivative_is_its_cells_twist():
    grid = Grid(XS, YS, -DEPTHS.T)
    x, y = np.array([75.0, 600.0]), np.array([0.0, 200.0])
    h = 1.0  # inside the cells: the bilinear surface's differences are exact
    twist = (
        grid.height(x + h, y + h)
        - grid.height(x + h, y - h)
        - grid.height(x - h, y + h)
        + grid.height(x - h, y - h)
    ) / (4 * h * h)
    np.testing.assert_allclose(grid.hessian(x, y)[0, 1], twist, rtol=1e-9)
    assert np.all(grid.hessian(x, y)[0, 0] == 0)


def test_bad_seabeds_are_refused_by_name():
    z = -DEPTHS.T.copy()
    z[2, 1] = np.nan
    with pytest.raises(InputError, match="z.*finite"):
        Grid(XS, YS, z)
    with pytest.raises(InputError, match="x.*sorted"):
        Grid(XS[::-1], YS, -DEPTHS.T)
    with pytest.raises(InputError, match="y.*sorted"):
        Grid(XS, np.array([0.0, 10.0, 5.0, 20.0]), -DEPTHS.T)
    with pytest.raises(InputError, match="z.*shape"):
        Grid(XS, YS, -DEPTHS)
    with pytest.raises(InputError, match="seabed.*off the grid"):
        Grid(XS, YS, -DEPTHS.T).height(np.array([1000.0]), np.array([0.0]))
    with pytest.raises(InputError, match="seabed.*gradient"):
        bathymetry_of(lambda x, y: -100.0 + 0 * x)
    with pytest.raises(InputError, match="gradient.*non-finite"):
        DepthFunction(lambda x, y: 0 * x, lambda x, y: (np.inf + 0 * x, 0 * y)).gradient(
            np.zeros(2), np.zeros(2)
        )
    with pytest.raises(InputError, match="slope"):
        Plane(0.0, slope=(0.1, 0.2, 0.3))
    assert bathymetry_of(-120.0).flat == -120.0 and bathymetry_of(None) is None


def test_seabeds_pickle():
    for seabed in (Plane(-150.0, (0.01, 0.02)), Grid(XS, YS, -DEPTHS.T)):
        copy = pickle.loads(pickle.dumps(seabed))
        x, y = RNG.uniform(-99, 899, 5), RNG.uniform(-299, 349, 5)
        np.testing.assert_array_equal(copy.height(x, y), seabed.height(x, y))
        np.testing.assert_array_equal(copy.gradient(x, y), seabed.gradient(x, y))
        assert repr(copy) == repr(seabed)
