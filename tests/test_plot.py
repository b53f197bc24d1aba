"""Figures draw the results' own numbers; the strand renders off screen."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from skcable import cable, plot, strand  # noqa: E402
from skcable.errors import InputError  # noqa: E402


@pytest.fixture(scope="module")
def curve():
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(2), 0.3, n_elements=16, slip="axis")
    return model.capacity_curve(max_strain=0.006, n_steps=6)


def test_capacity_and_slip_plots_show_the_curve(curve):
    ax = plot.capacity_curves([curve], ["damaged"])
    np.testing.assert_allclose(ax.lines[0].get_ydata(), curve.force / 1e3)
    ax = plot.slip_fraction([curve])
    np.testing.assert_allclose(ax.lines[0].get_ydata(), 100 * curve.slip_fraction)
    with pytest.raises(InputError, match="labels"):
        plot.capacity_curves([curve], ["a", "b"])


def test_curvature_plot_is_sorted_along_x(curve):
    ax = plot.curvature_along(curve, -1)
    x = ax.lines[0].get_xdata()
    assert np.all(np.diff(x) >= 0) and len(x) == curve.steps[-1].x.size
    assert np.max(np.abs(ax.lines[0].get_ydata())) == pytest.approx(
        np.max(np.abs(curve.steps[-1].curvature[0]))
    )


def test_cable_profile_and_moment_curvature():
    sol = cable.catenary(800, -20, 20, low=-30)
    ax = plot.cable_profile(sol)
    assert min(ax.lines[0].get_ydata()) == pytest.approx(-30, abs=1e-2)  # the lowest point given
    law = strand.preset("steel-9.5").damaged(1).bending_law(mu=0.5, axial_strain=0.004)
    ax = plot.moment_curvature(law)
    kappa, moment = ax.lines[0].get_xdata(), ax.lines[0].get_ydata()
    stick = kappa < law.kappa_m[0]
    np.testing.assert_allclose(moment[stick], law.EI_stick[0] * kappa[stick], rtol=1e-9)  # stick branch


def test_render_strand_off_screen(tmp_path, curve):
    path = plot.render_strand(curve, tmp_path / "strand.png", window=(400, 200))
    image = mpimg.imread(path)
    assert image.shape[:2] == (200, 400)
    assert image[..., :3].std() > 0.05  # not a blank picture
