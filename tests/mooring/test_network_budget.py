"""Every mooring equilibrium has a bound (issue 31): seeded networks of 2-3 bodies on 12-18
lines, shared lines and free points (`tests.fuzz.networks`), each answering or raising
`ConvergenceError` within its ``time_limit``, the error carrying every scaled residual and the
best point reached; an answer balances at every body and free point by an independent recount.
"""

import math
import re
import time

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import ConvergenceError, InputError
from tests.fuzz.networks import network, recount

pytestmark = pytest.mark.filterwarnings("ignore::skcable.errors.PlausibilityWarning")

#: Seconds a search that finds nothing may take; the state it was evaluating when the limit
#: passed ends past it (`OVERRUN` bounds that on a loaded machine: no wall-clock speed is tested).
LIMIT, OVERRUN = 1.0, 10.0


@pytest.mark.parametrize("seed, buoyed", [(0, True), (1, True), (0, False), (1, False)])
def test_a_network_answers_or_stops_within_its_budget(seed, buoyed):
    # buoyed free points float between their lines: an equilibrium, balanced by the recount;
    # unbuoyed ones sink towards the seabed, where a free point has no contact: no equilibrium,
    # the search stalls or runs out of its budget, and says so with its history and best point
    system, loads, data = network(seed, buoyed=buoyed)
    assert 2 <= data["n_bodies"] <= 3 and 12 <= data["n_lines"] <= 18 and data["free"] >= 1
    start = time.monotonic()
    if buoyed:
        eq = system.equilibrium(force=loads, time_limit=60.0)
        assert recount(system, eq, loads) < 1e-8
        return
    with pytest.raises(ConvergenceError) as caught:
        system.equilibrium(force=loads, time_limit=LIMIT)
    err = caught.value
    assert time.monotonic() - start < LIMIT + OVERRUN  # the state that crossed the limit, at most
    assert err.history and all(math.isfinite(h) for h in err.history)
    assert err.last is not None and err.last.shape == (system.n_dof,)
    if "time_limit" in str(err):
        best = float(re.search(r"measures ([-+.\de]+)\)", str(err)).group(1))
        assert min(err.history) == pytest.approx(best, rel=1e-2)


@pytest.mark.parametrize("seed", [2, 3, 4])
def test_a_network_balances_at_every_body_and_free_point(seed):
    # the recount re-solves every line here
    system, loads, data = network(seed)
    assert data["n_bodies"] >= 2 and data["n_lines"] >= 12
    eq = system.equilibrium(force=loads, time_limit=20.0)
    assert recount(system, eq, loads) < 1e-8


def test_the_time_limit_is_checked():
    system, loads, _ = network(0)
    with pytest.raises(InputError) as err:
        system.equilibrium(force=loads, time_limit=0.0)
    assert err.value.argument == "time_limit"
    with pytest.raises(ConvergenceError, match=r"time_limit = 1e-06 s") as err:
        system.equilibrium(force=loads, time_limit=1e-6)
    assert isinstance(err.value.last, np.ndarray) or err.value.last is None


def test_the_line_bvps_stop_at_their_time_limit():
    from skcable.mooring.line_bvp.space import LineSegment, solve_line_bvp_3d

    segments = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    start = time.monotonic()
    with pytest.raises(ConvergenceError, match=r"solve_line_bvp .*time_limit = 1e-09 s") as err:
        mooring.solve_line_bvp(800.0, 150.0, segments, seabed=0.0, time_limit=1e-9)
    assert time.monotonic() - start < OVERRUN and err.value.history == []  # stopped before its first solve
    with pytest.raises(ConvergenceError, match="solve_line_bvp_3d") as err:
        solve_line_bvp_3d(
            (0.0, 0.0, -200.0), (400.0, 0.0, -20.0), [LineSegment(500.0, 600.0, 4e8, 0.1, 1.2, 0.0)],
            current=(0.0, 0.8), time_limit=1e-9,
        )  # fmt: skip
    with pytest.raises(InputError) as bad:
        mooring.solve_line_bvp(800.0, 150.0, segments, time_limit=-1.0)
    assert bad.value.argument == "time_limit"
    # the line model takes it too, for each of its solves
    model = mooring.LineBVP(segments, seabed=0.0, time_limit=1e-9)
    with pytest.raises(ConvergenceError, match=r"solve_line_bvp .*time_limit = 1e-09 s"):
        model.solve(800.0, 150.0)
    with pytest.raises(InputError) as bad:
        mooring.LineBVP(segments, time_limit=0.0)
    assert bad.value.argument == "time_limit"
