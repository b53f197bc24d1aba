"""Semismooth Newton that holds: an analyst's penalty contact and the built-in sheave.

An analyst writes a unilateral bed as scikit-fem forms, ``R = ∫ k min(v − s, 0) δv``,
``K = ∫ k H(s − v) δv Δv`` (``FieldTerm(..., smooth=False)``), under a load of −100 N/m: the
model converges for penalties 1e8 to 1e12 N/m² at its default tolerance and at 1e-11, and the
bed's force equals that of a plain semismooth Newton written here (full steps on the model's own
``assemble``, scipy's sparse solve) to 1e-6.
"""

import numpy as np
import pytest
from scipy.sparse.linalg import spsolve
from skfem import BilinearForm, LinearForm

from skcable import strand

STRAIGHT = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=1e-9),), strand.material("steel"))
Q, SURFACE = -100.0, -1e-4


@LinearForm
def bed_residual(v, w):
    return w.k * np.minimum(w["v"] - w.s, 0.0) * v


@BilinearForm
def bed_tangent(u, v, w):
    return w.k * (w["v"] <= w.s) * u * v


def _model(k):
    bed = strand.FieldTerm(
        tangent={("v", "v"): bed_tangent}, residual={"v": bed_residual}, smooth=False, k=k, s=SURFACE
    )
    model = strand.StrandModel(
        STRAIGHT, 1.0, n_elements=64, grading=0.0, terms=[strand.TransverseLoad(qy=Q), bed]
    )
    return model, bed


def _bed_force(model, bed, U):
    """The bed's total force on the strand (N): its residual summed over the value dofs of v."""
    R, _ = model.term_contribution(bed, U)
    values = model.offsets[1] + model.bases["v"].nodal_dofs[0]
    return -float(np.sum(R[values]))


def _plain_semismooth(model):
    """Full Newton steps on the generalized derivative, the model's residual and tangent."""
    U, free = model.uniform(0.001), model.free
    for _ in range(300):
        R, K, _ = model.assemble(U)
        dU = spsolve(K[free][:, free].tocsc(), -R[free])
        U[free] += dU
        if np.max(np.abs(dU[: model.bases["u"].N])) < 1e-16 and np.max(np.abs(dU)) < 1e-15:
            return U
    raise AssertionError("the plain semismooth Newton did not converge")


@pytest.mark.parametrize("k", [1e8, 1e10, 1e12])
@pytest.mark.parametrize("tol", [None, 1e-11])
def test_an_analysts_penalty_contact_converges_and_matches_a_plain_semismooth_newton(k, tol):
    model, bed = _model(k)
    step = model.solve(0.001, tol=tol)
    assert step.history[-1] < (tol or model.options.tol)
    plain = _plain_semismooth(_model(k)[0])
    force = _bed_force(model, bed, step.dofs)
    assert force == pytest.approx(_bed_force(model, bed, plain), rel=1e-6)
    # the bed carries most of the load on the strand (the rest goes to the clamps), pushing up
    assert 0.5 * abs(Q) < force < abs(Q)


def test_the_built_in_sheave_converges_at_a_tight_tolerance():
    sheave = strand.RigidCylinder((0.5, -0.5 + 1e-3), 0.5, 1e12)
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=64, grading=0.0, terms=[sheave])
    step = model.solve(0.001, tol=1e-11)
    assert step.history[-1] < 1e-11
    pressure = step.outputs["contact_pressure"][1]
    assert np.max(pressure) > 0  # the sheave pushes the strand up where it wraps it
