"""Cyclic bending of the stick/slip laws: Masing's loop energy (the backbone integrated by
quadrature here), the bilinear closed form, loops traced by the history, Masing's rules along
any path, and the friction work of the return mapping."""

import numpy as np
import pytest
from scipy.integrate import quad

from skcable import strand
from skcable.errors import InputError
from skcable.strand import LayerSlipLaw, StageLaw


@pytest.fixture(scope="module")
def cardinal():
    return LayerSlipLaw(strand.preset("acsr-cardinal").section(), mu=0.7, tension=40e3)


@pytest.fixture(scope="module")
def damaged():
    return LayerSlipLaw(strand.preset("acsr-drake").damaged(2).section(), mu=0.7, tension=28e3)


def masing_energy(backbone, kappa_a, knees):
    """W = 8 ∫_0^κa M_b dκ - 4 κa M_b(κa), the integral by adaptive quadrature (split at the knees)."""
    inside = [k for k in knees if 0 < k < kappa_a]
    integral = quad(backbone, 0.0, kappa_a, points=inside or None, epsabs=0, epsrel=1e-13, limit=200)[0]
    return 8 * integral - 4 * kappa_a * backbone(kappa_a)


def shoelace(x, y):
    return 0.5 * abs(np.dot(x[:-1], y[1:]) - np.dot(x[1:], y[:-1]))


@pytest.mark.parametrize("law_name", ["cardinal", "damaged"])
@pytest.mark.parametrize("axis", [0, 1])
def test_energy_per_cycle_is_masings_for_the_backbone(request, law_name, axis):
    law = request.getfixturevalue(law_name)
    knees = np.sort(law.kappa_slip[axis])
    amplitudes = np.concatenate(
        [[0.5 * knees[0]], knees * 1.0001, 0.5 * (knees[1:] + knees[:-1]), [3 * knees[-1]]]
    )
    for a in amplitudes:
        W = masing_energy(lambda k: float(law.moment(k, axis)), float(a), knees)
        assert law.energy_per_cycle(a, axis) == pytest.approx(
            W, rel=1e-9, abs=1e-9 * abs(a * law.moment(a, axis))
        )
    assert law.energy_per_cycle(0.5 * knees[0], axis) == 0.0
    np.testing.assert_array_equal(
        law.energy_per_cycle(amplitudes, axis), [law.energy_per_cycle(a, axis) for a in amplitudes]
    )


def test_bilinear_energy_is_the_closed_form():
    EI1, EI2, ks = 1800.0, 30.0, 0.02
    law = StageLaw(EI2, [EI1 - EI2], [(EI1 - EI2) * ks])
    a = np.array([0.0, 0.01, 0.02, 0.021, 0.05, 0.5])
    expected = 4 * (EI1 - EI2) * ks * np.maximum(a - ks, 0.0)
    np.testing.assert_allclose(law.energy_per_cycle(a), expected, rtol=1e-14, atol=0)
    for value in a[1:]:
        W = masing_energy(lambda k: float(law.moment(k)), float(value), [ks])
        assert law.energy_per_cycle(value) == pytest.approx(W, rel=1e-9, abs=1e-12)


def test_a_1x7s_loop_is_the_single_knee_laws_bilinear_loop():
    s = strand.preset("steel-9.5").damaged(1)
    single = s.bending_law(mu=0.5, axial_strain=0.004)
    law = LayerSlipLaw(s.section(), mu=0.5, axial_strain=0.004)
    for axis in (0, 1):
        a = np.array([0.5, 1.0, 3.0]) * single.kappa_m[axis]
        expected = (
            4
            * (single.EI_stick[axis] - single.EI_slip[axis])
            * single.kappa_m[axis]
            * np.maximum(a - single.kappa_m[axis], 0.0)
        )
        np.testing.assert_allclose(law.energy_per_cycle(a, axis), expected, rtol=1e-12, atol=0)


@pytest.mark.parametrize("law_name", ["cardinal", "damaged"])
def test_the_loop_traced_by_the_history_encloses_the_energy(request, law_name):
    law = request.getfixturevalue(law_name)
    for axis in (0, 1):
        a = 2.5 * float(np.median(law.kappa_slip[axis]))
        kappa, moment = law.loop(a, axis)
        assert kappa[0] == kappa[-1] == a and moment[0] == pytest.approx(moment[-1], rel=1e-14)
        assert shoelace(kappa, moment) == pytest.approx(law.energy_per_cycle(a, axis), rel=1e-12)
        # Masing's branch from the reversal at +a: M = M_b(a) - 2 M_b((a - κ)/2), and its mirror
        down = slice(0, int(np.argmin(kappa)) + 1)
        expected = law.moment(a, axis) - 2 * law.moment((a - kappa[down]) / 2, axis)
        np.testing.assert_allclose(moment[down], expected, rtol=1e-12, atol=1e-12 * law.moment(a, axis))
        # the loop is symmetric: M(-κ) on the rising branch is -M(κ) on the falling one
        up = slice(int(np.argmin(kappa)), None)
        np.testing.assert_array_equal(kappa[up], -kappa[down])
        np.testing.assert_allclose(moment[up], -moment[down], rtol=1e-12, atol=1e-12)
        # a denser loop passes through the same polygon
        dense_k, dense_m = law.loop(a, axis, n=200)
        low = int(np.argmin(dense_k))
        falling = np.interp(dense_k[:low][::-1], kappa[down][::-1], moment[down][::-1])[::-1]
        rising = np.interp(dense_k[low:], kappa[up], moment[up])
        scale = abs(moment).max()
        np.testing.assert_allclose(dense_m, np.concatenate([falling, rising]), rtol=0, atol=1e-12 * scale)


def test_a_second_cycle_repeats_the_first(damaged):
    for axis in (0, 1):
        a = 3.0 * float(damaged.kappa_slip[axis].max())
        cycle = np.concatenate([np.linspace(a, -a, 301), np.linspace(-a, a, 301)[1:]])
        path = damaged.path(np.concatenate([np.linspace(0, a, 50), cycle[1:], cycle[1:]]), axis)
        first, second = path.moment[49 : 49 + 601], path.moment[49 + 600 :]
        np.testing.assert_allclose(second, first, rtol=0, atol=1e-12 * abs(first).max())
        # the friction work of each cycle is the energy of the loop
        work = path.work[[49, 49 + 600, 49 + 1200]]
        np.testing.assert_allclose(np.diff(work), damaged.energy_per_cycle(a, axis), rtol=1e-12)


def test_masings_memory_along_any_path(cardinal):
    """A partial unloading and reloading rejoins the curve it left (memory); beyond the largest
    curvature reached the law is back on its backbone."""
    knees = np.sort(cardinal.kappa_slip[0])
    a, b, c = 1.5 * knees[2], 0.2 * knees[2], 2.0 * knees[3]
    path = cardinal.path(
        np.concatenate([np.linspace(0, a, 40), np.linspace(a, b, 40), np.linspace(b, c, 80)])
    )
    at_c = path.moment[-1]
    assert at_c == pytest.approx(cardinal.moment(c), rel=1e-13)
    # on the way back up from b, before a, it follows Masing's branch from the reversal at b
    rising, kb = np.linspace(b, a, 80)[1:-1], path.moment[79]
    up = cardinal.path(np.concatenate([np.linspace(0, a, 40), np.linspace(a, b, 40), rising])).moment[80:]
    np.testing.assert_allclose(up, kb + 2 * cardinal.moment((rising - b) / 2), rtol=1e-12)


def test_update_at_many_points_is_the_path_point_by_point(damaged):
    rng = np.random.default_rng(3)
    scale = damaged.kappa_slip.max()
    steps = rng.uniform(-2, 2, size=(5, 2, 4, 3)) * scale  # 5 steps, 2 axes, 4 elements, 3 points
    slip = damaged.initial_slip((4, 3))
    for k in range(5):
        response = damaged.update(steps[k], slip)
        slip = response.slip
    for axis in (0, 1):
        for e in range(4):
            for q in range(3):
                alone = damaged.path(steps[:, axis, e, q], axis)
                assert response.moment[axis, e, q] == pytest.approx(alone.moment[-1], rel=1e-13, abs=1e-12)


def test_update_tangent_is_the_derivative_of_the_moment(damaged):
    rng = np.random.default_rng(4)
    slip = damaged.update(
        rng.uniform(-2, 2, (2, 50)) * damaged.kappa_slip.max(), damaged.initial_slip((50,))
    ).slip
    kappa = rng.uniform(-2, 2, (2, 50)) * damaged.kappa_slip.max()
    h = 1e-7 * damaged.kappa_slip.max()
    response = damaged.update(kappa, slip)
    fd = (damaged.update(kappa + h, slip).moment - damaged.update(kappa - h, slip).moment) / (2 * h)
    np.testing.assert_allclose(response.tangent, fd, rtol=1e-6)


def test_update_and_loop_refuse_bad_input(damaged):
    with pytest.raises(InputError) as err:
        damaged.update(np.zeros((2, 3)), np.zeros((2, 2, 3)))
    assert err.value.argument == "slip"
    for call, argument in [
        (lambda: damaged.loop(-0.1), "kappa_a"),
        (lambda: damaged.loop([0.1, 0.2]), "kappa_a"),
        (lambda: damaged.loop(0.1, n=-1), "n"),
        (lambda: damaged.loop(0.1, axis=2), "axis"),
        (lambda: damaged.energy_per_cycle(-1e-3), "kappa_a"),
        (lambda: damaged.energy_per_cycle(float("nan")), "kappa_a"),
        (lambda: damaged.path([[0.1]]), "kappa"),
        (lambda: StageLaw(0.0, [1.0], [1.0]), "EI_min"),
        (lambda: StageLaw(1.0, [-1.0], [1.0]), "stiffness"),
        (lambda: StageLaw(1.0, [0.0], [1.0]), "slip_moment"),
        (lambda: StageLaw(1.0, [[1.0, 2.0]] * 3, [1.0, 1.0]), "stiffness"),
    ]:
        with pytest.raises(InputError) as err:
            call()
        assert err.value.argument == argument
