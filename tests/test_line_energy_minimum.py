"""The energy-minimum oracle of ``benchmarks/line_energy_minimum.py`` (imported from benchmarks/,
as the script imports ``benchmarks/line_bvp_planes.py``): its end forces against the elastic
catenary's closed form, and its verdict either side of the longest line a frictionless slope holds
taut (`skcable.cable.seabed.taut_length_on_slope`)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from skcable.cable import elastic_catenary
from skcable.cable.seabed import taut_length_on_slope

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import line_energy_minimum as oracle  # noqa: E402


def test_end_forces_match_the_elastic_catenary():
    """A chain without a seabed on 1000 nodes: measured 3.3e-7 of the largest end force (the
    discretisation's, falling 4 times per doubling of the nodes)."""
    ref = elastic_catenary(400.0, 80.0, 900.0, 1e9, length=450.0)
    got = oracle.energy_minimum(oracle.Scene(400.0, 80.0, ((450.0, 900.0, 1e9),)), 1000)
    want = np.array([ref.H, ref.V_A, ref.H, ref.V_B], float)
    assert got.taut
    assert np.abs(got.forces() - want).max() < 1e-6 * np.abs(want).max()


@pytest.mark.parametrize(("share", "expected"), [(0.95, "taut"), (1.05, "no taut state")])
def test_a_line_longer_than_a_frictionless_slope_holds_taut_is_slack(share, expected):
    """A = (0, 0), B = (300, 60) over the slope y = -40 + 0.05 x (a wire, 80 N/m, EA 5e8 N):
    L* = 403.6 m. At 1.05 L* the slack slides down the slope past A's foot and folds there (on
    300 and 600 nodes: least strain -0.22, -0.13); at 0.95 L* the least tension is 756 N."""
    longest = taut_length_on_slope(300.0, 60.0, 80.0, 5e8, seabed=-40.0, seabed_slope=0.05)
    scene = oracle.Scene(300.0, 60.0, ((share * longest, 80.0, 5e8),), seabed=(-40.0, 0.05))
    said, one, two = oracle.verdict(scene, 300)
    assert said == expected
    if expected == "taut":
        assert min(one.min_tension, two.min_tension) > 700.0
    else:
        assert "behind A, on the seabed" in two.slack


def test_friction_is_refused():
    with pytest.raises(ValueError, match="frictionless"):
        oracle.energy_minimum(
            oracle.Scene(300.0, 60.0, ((320.0, 80.0, 5e8),), seabed=(0.0, 0.0), friction=0.5), 100
        )
