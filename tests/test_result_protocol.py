"""One set of checks over every result type of `skcable.results.CableResult`.

Each entry of `FACTORIES` is a function ``(span, dh) -> result`` of one scene whose unstretched
length is fixed (so that re-solving at a moved B gives the stiffness by central differences),
under `W` newtons per metre of unstretched cable, or per horizontal metre for the parabola (a
type under other loads extends `applied_load`). Every check compares the result with something
that does not come from the same formula: the end tensions from their components, the ends of
the profile from the scene's supports, the vertical balance from the load, the stiffness from
re-solved scenes, the repr from the attributes, the VTK file from what meshio reads back.

Other result types join by appending ``pytest.param(factory, id=...)`` to `FACTORIES`.
"""

from __future__ import annotations

import math
import re

import meshio
import numpy as np
import pytest

from skcable import bvp, cable, mooring
from skcable.mooring import LineBVPSolution
from skcable.results import CableResult

SPAN, DH, W = 100.0, 20.0, 20.0
#: the unstretched length of every scene: 10 % over the chord
LENGTH = 1.1 * math.hypot(SPAN, DH)


def fe(factory, accuracy):
    """A finite-element factory: its field's tensions match the reactions to ``accuracy``."""
    factory.accuracy = accuracy
    return factory


def accuracy(result_factory) -> float:
    return getattr(result_factory, "accuracy", 1e-12)


FACTORIES = [
    pytest.param(lambda span, dh: cable.catenary(span, dh, W, length=LENGTH), id="catenary"),
    pytest.param(lambda span, dh: cable.parabola(span, dh, W, length=LENGTH), id="parabola"),
    pytest.param(lambda span, dh: cable.elastic_catenary(span, dh, W, 2e5, length=LENGTH), id="elastic"),
    pytest.param(
        lambda span, dh: cable.elastic_catenary(span, -dh, W, 1e9, length=LENGTH), id="elastic-down"
    ),
    # the mooring lines (branch lines): on a flat and on a sloped seabed
    pytest.param(
        lambda span, dh: cable.elastic_catenary(span, dh, W, 2e4, length=LENGTH, seabed=0.0, friction=0.05),
        id="seabed",
    ),
    pytest.param(
        lambda span, dh: cable.sloped_seabed_catenary(
            span, dh, W, 2e5, length=LENGTH, seabed_slope=-0.05, friction=0.02
        ),
        id="sloped",
    ),
    pytest.param(
        lambda span, dh: cable.seabed.touchdown_on_slope(
            span, dh, W, 2e5, length=LENGTH, seabed=-15.0, seabed_slope=0.1
        ),
        id="slope-touchdown",
    ),
    # LineSolution (a multi-segment Line) is checked in tests/mooring/test_lines_protocol.py: its
    # tensions() has no H_lower column (one more column would move the pinned tables' shape)
    # the finite-element solutions (graph and arc forms): their tensions along the cable are the
    # field's, the end tensions the reactions', which agree to the discretisation's accuracy
    pytest.param(
        fe(
            lambda span, dh: bvp.solve_bvp(
                span, dh, bvp.SelfWeight(W), length=LENGTH, EA=2e5, n_elements=256, rtol=1e-13
            ),
            1e-5,
        ),
        id="bvp-graph",
    ),
    pytest.param(
        fe(
            lambda span, dh: bvp.solve_bvp(
                span,
                dh,
                bvp.SelfWeight(W),
                length=LENGTH,
                EA=2e5,
                formulation="arc",
                n_elements=128,
                rtol=1e-13,
            ),
            1e-5,
        ),
        id="bvp-arc",
    ),
    # the line BVP (branch linebvp): free, and touching a seabed below the anchor
    pytest.param(
        fe(lambda span, dh: mooring.solve_line_bvp(span, dh, [(LENGTH, W, 2e5)], n_elements=256), 1e-5),
        id="line-bvp",
    ),
    pytest.param(
        fe(
            lambda span, dh: mooring.solve_line_bvp(
                span, dh, [(LENGTH / 2, W, 2e5), (LENGTH / 2, W, 2e5)], seabed=-5.0, n_elements=256
            ),
            1e-5,
        ),
        id="line-bvp-seabed",
    ),
]


def applied_load(result) -> float:
    """The total downward load of a factory's scene (N), from the scene, not the result."""
    if isinstance(result, cable.Parabola):
        return W * result.span
    if isinstance(result, LineBVPSolution):  # the seabed carries part of the weight
        return W * result.length - float(np.sum(result.contact_force[:, 1]))
    if isinstance(result, cable.seabed.SlopeTouchdownLine):
        # the frictionless slope's reaction is normal to it, w cos(alpha) per length: its vertical
        # part w cos^2(alpha) over the lying length
        return W * result.length - W * result.length_on_seabed / (1.0 + result.seabed_slope**2)
    if isinstance(result, cable.SlopedSeabedCatenary):
        # the grounded part's balance: the seabed's vertical force is W L_B - (T_t - T_A) sin(alpha)
        sin = result.seabed_slope / math.hypot(1.0, result.seabed_slope)
        grounded = result.length_on_seabed
        return W * (result.length - grounded) + (result.T_touchdown - result.T_A) * sin
    # a line on the seabed: the seabed carries its grounded part, the supports the rest
    return W * (result.length - getattr(result, "length_on_seabed", 0.0))


def largest_strain(result) -> float:
    """``T/EA`` at its largest (the end tensions over the softest ``EA``), a bound on the stretch."""
    line = getattr(result, "line", None)
    EA = min(s.EA for s in line.segments) if line is not None else getattr(result, "EA", math.inf)
    return max(result.T_A, result.T_B) / EA


@pytest.fixture(params=FACTORIES)
def factory(request):
    return request.param


def test_satisfies_the_protocol(factory):
    result = factory(SPAN, DH)
    assert isinstance(result, CableResult)
    for name in ("H_A", "V_A", "H_B", "V_B", "T_A", "T_B", "length"):
        assert isinstance(getattr(result, name), float) and math.isfinite(getattr(result, name)), name


def test_end_tensions_are_their_components(factory):
    r = factory(SPAN, DH)
    assert r.T_A == pytest.approx(math.hypot(r.H_A, r.V_A), rel=1e-13)
    assert r.T_B == pytest.approx(math.hypot(r.H_B, r.V_B), rel=1e-13)


def test_profile_runs_from_A_to_B_in_unstretched_arc_length(factory):
    r = factory(SPAN, DH)
    B = (SPAN, r.dh)
    np.testing.assert_allclose(r.xy(0.0), (0.0, 0.0), atol=1e-12 * LENGTH)
    np.testing.assert_allclose(r.xy(r.length), B, rtol=0, atol=1e-12 * LENGTH)
    assert r.T_of_s(0.0) == pytest.approx(r.T_A, rel=accuracy(factory))
    assert r.T_of_s(r.length) == pytest.approx(r.T_B, rel=accuracy(factory))
    profile = r.profile(401)
    assert profile.shape == (401, 2)
    np.testing.assert_allclose(profile[[0, -1]], [(0.0, 0.0), B], rtol=0, atol=1e-12 * LENGTH)
    # s is arc length: the polyline through the points is as long as the cable (stretched, for
    # an elastic one: its strain is T/EA, below 2e-3 here), less the chords' shortfall O(1/n²)
    sides = np.hypot(*np.diff(profile, axis=0).T)
    assert np.sum(sides) == pytest.approx(r.length, rel=2e-5 + largest_strain(r))
    assert np.allclose(sides, sides[0], rtol=1e-4 + 2 * largest_strain(r))


def test_vertical_balance(factory):
    r = factory(SPAN, DH)
    assert r.V_A + r.V_B == pytest.approx(applied_load(r), rel=1e-12)


def test_stiffness_against_central_differences_of_resolved_scenes(factory):
    r = factory(SPAN, DH)
    K = r.stiffness()
    assert K.shape == (2, 2)
    # the truncation of central differences, h²/6 ∂³H, is 1e-6 of K at h = 1e-4 span on a line
    # lying on the seabed, 1e-8 at 1e-5 (their round-off, eps H/h, 4e-12)
    h = 1e-5 * SPAN
    fd = np.empty((2, 2))
    for column, (d_span, d_dh) in enumerate([(h, 0.0), (0.0, h)]):
        plus, minus = factory(SPAN + d_span, DH + d_dh), factory(SPAN - d_span, DH - d_dh)
        fd[0, column] = (plus.H_B - minus.H_B) / (2 * h)
        fd[1, column] = (plus.V_B - minus.V_B) / (2 * h)
    if r.dh < 0:  # the factory mirrors dh: d/d(dh) of the result is minus d/d(DH)
        fd[:, 1] *= -1.0
    np.testing.assert_allclose(K, fd, rtol=0, atol=1e-6 * np.abs(fd).max())


def test_frames(factory):
    r = factory(SPAN, DH)
    frame = r.to_frame(11)
    assert list(frame.columns) == ["s", "x", "y", "T"] and len(frame) == 11
    np.testing.assert_allclose(frame["s"], np.linspace(0.0, r.length, 11))
    np.testing.assert_allclose(frame[["x", "y"]].to_numpy(), r.profile(11))
    np.testing.assert_allclose(frame["T"].iloc[[0, -1]], [r.T_A, r.T_B], rtol=accuracy(factory))
    tensions = r.tensions()
    assert {"segment", "length", "T_lower", "T_upper", "H_lower", "H_upper"} <= set(tensions.columns)
    assert tensions["length"].sum() == pytest.approx(r.length, rel=1e-12)
    assert tensions["T_lower"].iloc[0] == pytest.approx(r.T_A, rel=1e-12)
    assert tensions["T_upper"].iloc[-1] == pytest.approx(r.T_B, rel=1e-12)


def test_vtk_round_trip(factory, tmp_path):
    r = factory(SPAN, DH)
    path = r.to_vtk(tmp_path / "cable.vtu", 33)
    mesh = meshio.read(path)
    points = mesh.points
    assert points.shape == (33, 3)
    np.testing.assert_allclose(points[[0, -1], :2], [(0.0, 0.0), (SPAN, r.dh)], atol=1e-12 * LENGTH)
    tension = mesh.point_data["tension_N"]
    np.testing.assert_allclose(tension[[0, -1]], [r.T_A, r.T_B], rtol=accuracy(factory))
    assert np.all(tension > 0) and np.all(np.diff(points[:, 0]) > 0)


def test_repr_shows_the_key_numbers(factory):
    r = factory(SPAN, DH)
    shown = dict(re.findall(r"(\w+)=([-+0-9.e]+)", repr(r)))
    for name in ("V_A", "V_B", "T_A", "T_B", "length"):
        assert float(shown[name]) == pytest.approx(getattr(r, name), rel=1e-8), name
    assert float(shown.get("H", shown.get("H_B", "nan"))) == pytest.approx(r.H_B, rel=1e-8)
