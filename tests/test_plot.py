"""Figures draw the results' own numbers; the strand renders off screen."""

import matplotlib

matplotlib.use("Agg")

import re  # noqa: E402

import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from PIL import Image  # noqa: E402

from skcable import cable, plot, strand  # noqa: E402
from skcable.cli import main  # noqa: E402
from skcable.errors import InputError  # noqa: E402
from skcable.strand.capacity import restick  # noqa: E402


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


def test_the_tension_is_drawn_apart_from_the_profile_and_named():
    # issue 31: on a catenary T = H + w (y - y0) is linear in y, and a twin axis scaled to its own
    # range drew it exactly on the profile, with no legend entry
    sol = cable.catenary(800, -20, 20, low=-30)
    ax = plot.cable_profile(sol)
    twin = [other for other in ax.figure.axes if other is not ax][0]
    profile, tension = ax.lines[0], twin.lines[0]
    np.testing.assert_allclose(tension.get_ydata() * 1e3, sol.T(tension.get_xdata()), rtol=1e-9)
    ax.figure.canvas.draw()
    on_screen = [line.get_transform().transform(line.get_xydata())[:, 1] for line in (profile, tension)]
    height = ax.figure.bbox.height
    assert np.max(np.abs(on_screen[0] - on_screen[1])) > 0.2 * height  # apart by a fifth of the figure
    assert twin.get_ylim()[0] == 0.0
    labels = [text.get_text() for text in ax.get_legend().get_texts()]
    assert labels == ["profile y(x)", "chord", "tension T(x) (right axis)"]


@pytest.fixture(scope="module")
def pair():
    """Stick and stick–slip curves to rupture of a strand with two broken wires."""
    damaged = strand.preset("steel-9.5").damaged(2)
    return {
        label: strand.StrandModel(damaged, 0.3, n_elements=16, slip=slip).capacity_curve(n_steps=12)
        for label, slip in (("stick", "none"), ("stick-slip", "axis"))
    }


def test_secant_stiffness_draws_force_over_EA_strain(pair):
    EA = strand.preset("steel-9.5").damaged(2).section().EA  # the damaged section's axial stiffness
    ax = plot.secant_stiffness(pair.values(), list(pair), at=0.002)
    secants = [line for line in ax.lines if line.get_linestyle() == "-"]
    for line, curve in zip(secants, pair.values(), strict=True):
        np.testing.assert_allclose(line.get_xdata(), curve.strain[1:])
        np.testing.assert_allclose(line.get_ydata(), curve.force[1:] / (EA * curve.strain[1:]), rtol=1e-12)
    at = {label: np.interp(0.002, c.strain, c.force) / (EA * 0.002) for label, c in pair.items()}
    assert at["stick-slip"] < at["stick"]  # slip softens the strand at small strain
    marks = [line for line in ax.lines if line.get_marker() == "o"]
    np.testing.assert_allclose([m.get_ydata()[0] for m in marks], list(at.values()), rtol=1e-12)
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == [f"{label}: {value:.3f} at ε = 0.002" for label, value in at.items()]
    (twin,) = [other for other in ax.figure.axes if other is not ax]  # the slip fraction, stick–slip only
    (slip,) = twin.lines
    np.testing.assert_array_equal(slip.get_ydata(), 100 * pair["stick-slip"].slip_fraction[1:])
    plt.close(ax.figure)


def test_secant_stiffness_marks_where_the_strand_resticks(pair):
    curve = pair["stick-slip"]
    fraction = curve.slip_fraction
    fall = -np.diff(fraction)
    steep = np.flatnonzero(fall > 0.1)  # the steps where the slip fraction falls steeply: one run here
    assert np.all(np.diff(steep) == 1)
    found = curve.restick()
    assert found == (
        curve.strain[steep[0]],
        curve.strain[steep[-1] + 1],
        fraction[steep[0]],
        fraction[steep[-1] + 1],
    )
    ax = plot.secant_stiffness([curve])
    (marked,) = [line for line in ax.lines if line.get_linestyle() == ":"]
    assert marked.get_xdata()[0] == found.strain_after
    (note,) = ax.texts
    assert f"{100 * found.fraction_before:.0f} % → {100 * found.fraction_after:.0f} %" in note.get_text()
    plt.close(ax.figure)
    assert pair["stick"].restick() is None  # no slip, no re-stick


@pytest.mark.parametrize(
    ("fraction", "expected"),
    [
        ([0, 1, 1, 0.9, 0.4, 0.05, 0.04], (3, 5)),  # a fall over two steps, from 90 % to 5 %
        ([0, 1, 0.97, 0.1, 0.1], (2, 3)),
        ([0, 1, 1, 0.7, 0.7], None),  # it falls, by less than half the length
        ([0, 1, 0.95, 0.9, 0.85, 0.8, 0.75], None),  # it creeps down, no cliff
        ([0, 0, 0], None),
    ],
)
def test_restick_finds_the_cliff_of_the_slip_fraction(fraction, expected):
    strain = np.linspace(0.0, 0.06, len(fraction))
    found = restick(strain, np.array(fraction, dtype=float))
    if expected is None:
        assert found is None
    else:
        i, j = expected
        assert found == (strain[i], strain[j], fraction[i], fraction[j])


def test_demo_prints_the_secant_stiffness_and_the_restick(tmp_path, capsys):
    assert (
        main(["demo", "--no-progress", "--n-elements", "16", "--n-steps", "8", "--out", tmp_path / "r"]) == 0
    )
    printed = capsys.readouterr().out
    damaged = strand.preset("steel-9.5").damaged(1)
    EA = damaged.section().EA
    for label, slip in (("stick", "none"), ("stick-slip", "axis")):
        c = strand.StrandModel(damaged, slip=slip, n_elements=16).capacity_curve(n_steps=8)
        value = np.interp(0.002, c.strain, c.force) / (EA * 0.002)
        assert re.search(rf"at ε = 0.002: .*{label} {value:.3f}", printed), (label, value, printed)
    assert "re-sticks" in printed and (tmp_path / "r" / "stiffness.png").stat().st_size > 10_000
    # issue 31: both models' wires and curvatures at one strain, where slip makes them differ
    captions = [
        Image.open(tmp_path / "r" / f"{name}_wires.png").text["Description"]
        for name in ("stick", "stick-slip")
    ]
    strains = [float(re.search(r"axial strain ([\d.e-]+)", c).group(1)) for c in captions]
    assert strains[0] == strains[1]
    stick = strand.StrandModel(damaged, slip="none", n_elements=16).capacity_curve(n_steps=8)
    slip = strand.StrandModel(damaged, slip="axis", n_elements=16).capacity_curve(n_steps=8)
    k = int(np.argmin(np.abs(stick.strain[1:] - 0.002)))  # the steps (strain 0 is no step)
    assert slip.steps[k].strain == stick.steps[k].strain == pytest.approx(strains[0], rel=1e-3)
    assert np.max(np.abs(slip.steps[k].curvature)) > 1.05 * np.max(np.abs(stick.steps[k].curvature))


def test_render_strand_off_screen(tmp_path, curve):
    path = plot.render_strand(curve, tmp_path / "strand.png", window=(400, 200))
    image = mpimg.imread(path)
    assert image.shape[:2] == (200, 400)
    assert image[..., :3].std() > 0.05  # not a blank picture


@pytest.mark.parametrize(("scale", "xscale"), [(5.0, 0.1), (1.0, 1.0)])
def test_render_strand_prints_its_scales(tmp_path, curve, scale, xscale):
    path = plot.render_strand(curve, tmp_path / "strand.png", scale=scale, xscale=xscale, window=(800, 300))
    caption = Image.open(path).text["Description"]  # the caption printed on the picture, kept in the PNG
    if scale == xscale == 1.0:
        assert caption.startswith("true scale;")
    else:
        length, moved = re.search(r"length x ([\d.e+-]+), displacements x ([\d.e+-]+)", caption).groups()
        assert (float(length), float(moved)) == (xscale, scale)
    assert f"axial strain {curve.steps[-1].strain:.4g}" in caption
    corner = mpimg.imread(path)[:14, :300, :3]  # the caption's corner: text on the background
    assert corner.min() < 0.3 and np.median(corner) > 0.9
    with pytest.raises(InputError, match="xscale"):
        plot.render_strand(curve, tmp_path / "bad.png", xscale=0.0)
