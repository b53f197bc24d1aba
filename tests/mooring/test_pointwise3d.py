"""The 3-D line's point evaluation and its warm starts on a seabed.

`LinePoints` against scikit-fem's own ``probes`` (and the repo's `gradient_probes`, built on
scikit-fem's basis): the same numbers to the bit, at nodes, joints, the ends and inside
elements of a fitted mesh. A warm-started grounded line (the same meshes, graded by the start
and by the line, solved from its start moved along the tangent; on the uniform mesh too) against
the same line solved from scratch at the same ends.
"""

from __future__ import annotations

import numpy as np
import pytest

from skcable.fe.probes import gradient_probes
from skcable.mooring.line_bvp.space import LineBVP3D, LineBVP3DSolver, LineSegment

CHAIN = LineSegment(500.0, 600.0, 4e8, 0.1, 1.2, 0.008)
ANCHOR, FAIRLEAD = np.array([420.0, 0.0, -200.0]), np.array([20.0, 0.0, -20.0])


def grounded_model(**options):
    return LineBVP3D([CHAIN], seabed=-200.0, friction=0.02, current=(0.6, 0.3), n_elements=48, **options)


def test_points_are_scikit_fems_probes():
    two = [CHAIN, LineSegment(100.0, 300.0, 2e8, 0.1, 1.2, 0.008)]
    model = LineBVP3D(two, attachments=[(1, 2e4)], seabed=-200.0, current=(0.6, 0.3), n_elements=37)
    line = model.solve((520.0, 0.0, -200.0), FAIRLEAD)
    problem, z = line.problem, line.dofs
    assert problem.fitted, "the scene must have a fitted touchdown node (a mesh not uniform)"
    s = np.concatenate(
        [
            np.random.default_rng(3).uniform(0.0, problem.L, 300),
            problem.mesh.p[0],
            np.linspace(0.0, problem.L, 77),
        ]
    )
    state = problem.state_at(z, s)
    S, N = s.reshape(1, -1), problem.N
    P, G = problem.basis.probes(S), gradient_probes(problem.basis, S)
    r = np.array([P @ z[k * N : (k + 1) * N] for k in range(3)])
    a = np.array([G @ z[k * N : (k + 1) * N] for k in range(3)])
    T = problem.tbasis.probes(S) @ z[3 * N :]
    assert np.array_equal(np.array([state.x, state.y, state.z]), r)
    assert np.array_equal(state.a, a)
    assert np.array_equal(state.T, T)
    assert np.array_equal(problem.tension_at(z, s), T)


def test_points_outside_the_line_are_refused():
    line = grounded_model().solve(ANCHOR, FAIRLEAD)
    with pytest.raises(ValueError, match="outside"):
        line.problem.points.cells(np.array([line.length * (1 + 1e-9)]))
    with pytest.raises(ValueError, match="outside"):
        line.problem.points.cells(np.array([-1e-9]))


@pytest.mark.parametrize("move", [(1.0, 0.5, 0.2), (-4.0, 2.0, -1.0), (1e-4, 0.0, 0.0)])
def test_warm_start_on_the_seabed_is_the_cold_solve(move, monkeypatch):
    model = grounded_model()
    start = model.solve(ANCHOR, FAIRLEAD)
    assert start.in_contact.any()
    fairlead = FAIRLEAD + np.array(move)
    cold = model.solve(ANCHOR, fairlead)

    def from_scratch(*args, **kwargs):
        raise AssertionError("the warm start fell back to a solve from scratch")

    # the closed-form starts (`starts`) and the uniform mesh (`level`) are the cold paths
    monkeypatch.setattr(LineBVP3DSolver, "starts", from_scratch)
    monkeypatch.setattr(LineBVP3DSolver, "level", from_scratch)
    warm = model.solve(ANCHOR, fairlead, start=start)
    scale = np.linalg.norm(cold.force_on_fairlead)
    # both settle their touchdown node to 1e-9 of the length: the end forces agree far below that
    assert np.max(np.abs(warm.force_on_fairlead - cold.force_on_fairlead)) <= 1e-11 * scale
    assert np.max(np.abs(warm.force_on_anchor - cold.force_on_anchor)) <= 1e-11 * scale
    assert warm.problem.fitted == pytest.approx(cold.problem.fitted, abs=1e-9 * model.length)
    assert warm.equilibrium_residual <= warm.residual_bound


@pytest.mark.parametrize("move", [(1.0, 0.5, 0.2), (-4.0, 2.0, -1.0)])
def test_warm_start_on_the_uniform_mesh_is_the_cold_solve(move):
    """``mesh="uniform"``: a warm start solves the uniform mesh from its start moved (its fitted
    nodes dropped, then fitted anew, as from scratch): the cold solve to round-off."""
    model = grounded_model(mesh="uniform")
    start = model.solve(ANCHOR, FAIRLEAD)
    assert start.problem.fitted and start.problem.nodes_at is None
    fairlead = FAIRLEAD + np.array(move)
    cold = model.solve(ANCHOR, fairlead)
    warm = model.solve(ANCHOR, fairlead, start=start)
    scale = np.linalg.norm(cold.force_on_fairlead)
    assert np.max(np.abs(warm.force_on_fairlead - cold.force_on_fairlead)) <= 1e-11 * scale
    assert np.max(np.abs(warm.force_on_anchor - cold.force_on_anchor)) <= 1e-11 * scale
