"""A mooring system's equilibrium run again: the lines it solved at its start are the warm starts of
the next solve from there, and the numbers do not depend on that.

References: a fresh system of the same parts, whose first solve starts every line cold; the force
balance of each line's closure at 30 digits (`tests.mooring.mooring_reference`).
"""

import numpy as np
import pytest

from skcable import mooring
from tests.mooring.mooring_reference import reference_forces

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(uplift_angle|position)\\b:skcable.errors.PlausibilityWarning"
)

W, EA, L = 2456.82, 1.2326e9, 850.0


def _system(n=3):
    system = mooring.MooringSystem(depth=200.0)
    hull = system.add_body(
        mooring.RigidBody(mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5), metacentre=(0, 0, 10))
    )
    line = mooring.Line([mooring.Segment(L, W, EA)])
    for h in np.radians(np.arange(n) * 360.0 / n):
        c, s = np.cos(h), np.sin(h)
        a = system.add_point([800 * c, 800 * s, -200.0], fixed=True)
        system.add_line(line, a, system.add_point([20 * c, 20 * s, -14.0], body=hull))
    return system, hull


def test_a_rerun_from_rest_gives_the_fresh_systems_numbers():
    system, hull = _system()
    first = system.equilibrium(force={hull: (2e6, 5e5, 0.0)})
    again = system.equilibrium(force={hull: (2e6, 5e5, 0.0)})
    fresh_system, fresh_hull = _system()
    fresh = fresh_system.equilibrium(force={fresh_hull: (2e6, 5e5, 0.0)})
    for eq in (first, again):
        np.testing.assert_allclose(eq.position, fresh.position, rtol=0, atol=1e-12 * 60.0)
        np.testing.assert_allclose(
            eq.stiffness(), fresh.stiffness(), rtol=0, atol=1e-9 * np.abs(fresh.stiffness()).max()
        )
    for line in again.lines:  # each line's closure met, against mpmath
        F = reference_forces(line, (W, EA, L), 200.0, 0.0)
        np.testing.assert_allclose(line.end_forces, F, rtol=0, atol=1e-10 * np.abs(F).max())


def test_a_rerun_under_another_load_and_after_a_new_model():
    system, hull = _system()
    system.equilibrium(force={hull: (2e6, 5e5, 0.0)})
    other = system.equilibrium(force={hull: (-1e6, 0.0, 0.0)})
    fresh_system, fresh_hull = _system()
    ref = fresh_system.equilibrium(force={fresh_hull: (-1e6, 0.0, 0.0)})
    np.testing.assert_allclose(other.position, ref.position, rtol=0, atol=1e-11 * 60.0)
    # a handle given a new model: the remembered lines are of the old one, not its starts
    longer = mooring.Line([mooring.Segment(L + 10.0, W, EA)])
    for h in system.mooring_lines:
        h.model = longer
    moved = system.equilibrium(force={hull: (-1e6, 0.0, 0.0)})
    for line in moved.lines:
        F = reference_forces(line, (W, EA, L + 10.0), 200.0, 0.0)
        np.testing.assert_allclose(line.end_forces, F, rtol=0, atol=1e-10 * np.abs(F).max())
