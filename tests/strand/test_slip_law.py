"""Slip laws as section laws: the strand model computes Cardou's law it documents.

A tensioned steel 9.5 mm strand (ε = 0.002 imposed) with its ends turned by ±θ: at every
quadrature point and principal axis the section moment is `BendingLaw.moment` of the point's
curvature at its own axial strain, and the end moments equal an independent shooting solution
(scipy's ``solve_ivp``) of the same beam equations with Cardou's law.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import root

from skcable import strand
from skcable.errors import InputError
from skcable.fe import check_tangent
from skcable.strand._bending import CardouSection

STEEL = strand.preset("steel-9.5")
SECTION = STEEL.section()
MU, EPS, L = 0.5, 2e-3, 1.0
THETAS = (1e-3, 5e-3, 2e-2)


def _turned(theta):
    return (
        {"u": 0.0, "v": 0.0, "v'": theta, "w": 0.0, "w'": 0.0, "phi": 0.0},
        {"v": 0.0, "v'": -theta, "w": 0.0, "w'": 0.0, "phi": 0.0},
    )


def _lever_angle_law():
    """The section at x is the section at 0 turned about the axis as the wires turn
    (ψ = ψ0 + 2π d x / lay, y = R sin ψ, z = R cos ψ): the lever direction ℓ_k = (sin β, cos β) of
    principal axis k (the unit normal to the axis t_k in the y–z plane), β = β0 + 2π d x / lay.
    Returns ``(β0 of both axes, 2π d / lay)``."""
    w = SECTION.wires
    rate = 2 * np.pi * w.direction[w.layer > 0][0] / STEEL.lay_lengths[0]
    return [math.atan2(-t[1], t[0]) for t in SECTION.principal_axes], float(rate)


BETA0, RATE = _lever_angle_law()


def _lever_angles(x):
    return [b + RATE * x for b in BETA0]


@pytest.fixture(scope="module", params=THETAS, ids=lambda t: f"theta={t:g}")
def turned(request):
    theta = request.param
    model = strand.StrandModel(STEEL, L, n_elements=512, slip="axis", mu=MU, supports=_turned(theta))
    return theta, model.solve(EPS, tol=1e-11)


def test_the_section_moment_is_cardous_law_at_every_point(turned):
    theta, step = turned
    worst, slipping = 0.0, 0
    for e, q in np.ndindex(step.x.shape):
        law = strand.BendingLaw(SECTION, mu=MU, axial_strain=float(step.axial_strain[e, q]))
        for k, beta in enumerate(_lever_angles(step.x[e, q])):
            lever = np.array([math.sin(beta), math.cos(beta)])
            kappa = float(lever @ step.bending[:, e, q])
            assert kappa == pytest.approx(step.curvature[k, e, q], rel=1e-12, abs=1e-12)
            want = law.moment(kappa, k)
            worst = max(worst, abs(float(lever @ step.moment[:, e, q]) - want) / abs(want))
            slipping += abs(kappa) > law.kappa_m[k]
    assert worst < 1e-6
    # the range covers stick (θ = 1e-3) and slip over a fifth of the length (θ = 2e-2)
    assert (slipping == 0) == (theta == 1e-3)


def _shooting(theta, X=0.15):
    """End moments (M_y, M_z) at x = 0 and x = L of EI(κ) κ = M, M = N (v, w) + C0 + C1 x
    (the tensioned beam without transverse load: (M′ − N v′)′ = 0), with Cardou's law about each
    principal axis of the turning section, v = w = 0 and (v′, w′) = (±θ, 0) at the ends.

    Between X and L − X the strand sticks: the law is linear and isotropic (EI_stick about both
    axes of the intact section), and (v, w) = −(C0 + C1 x)/N + B_L e^{−x/λ} + B_R e^{−(L−x)/λ},
    λ = √(EI/N). Each boundary layer is integrated from that solution at X (or L − X) to its end
    (integrating toward the end, the growing mode of the other end decays: a well-posed shooting
    over a stiff length); the 8 constants solve the 8 end conditions. The axial strain follows
    from the imposed end displacement: ε_a = ε + (1/2L) ∫ (v′² + w′²) (a fixed point)."""
    EA = SECTION.EA
    EI = strand.BendingLaw(SECTION, mu=MU, axial_strain=EPS).EI_stick[0]
    lam0 = math.sqrt(EI / (EA * EPS))
    Ms, Bs = EI * theta / lam0, lam0 * theta

    def run(p, a, b, eps_a):
        C0, C1, BL, BR = p[0:2] * Ms, p[2:4] * Ms, p[4:6] * Bs, p[6:8] * Bs
        law = strand.BendingLaw(SECTION, mu=MU, axial_strain=eps_a)
        N = EA * eps_a
        lam = math.sqrt(law.EI_stick[0] / N)
        k_m, EIs, EIf = law.kappa_m, law.EI_stick, law.EI_slip

        def rhs(x, y):
            My, Mz = N * y[0] + C0[0] + C1[0] * x, N * y[1] + C0[1] + C1[1] * x
            ky = kz = 0.0
            for k, beta in enumerate(_lever_angles(x)):
                ly, lz = math.sin(beta), math.cos(beta)
                M = ly * My + lz * Mz
                Mm = EIs[k] * k_m[k]
                kap = M / EIs[k] if abs(M) <= Mm else math.copysign(k_m[k] + (abs(M) - Mm) / EIf[k], M)
                ky, kz = ky + ly * kap, kz + lz * kap
            return [y[2], y[3], ky, kz, y[2] ** 2 + y[3] ** 2]

        def middle(x):
            el, er = math.exp(-x / lam), math.exp(-(L - x) / lam)
            return -(C0 + C1 * x) / N + BL * el + BR * er, -C1 / N - BL / lam * el + BR / lam * er

        v, dv = middle(a)
        y = solve_ivp(rhs, (a, b), np.r_[v, dv, 0.0], method="DOP853", rtol=1e-11, atol=1e-15).y[:, -1]
        return y, middle, (C0, C1)

    def ends(p, eps_a):
        out = []
        for a, b, slope in ((X, 0.0, theta), (L - X, L, -theta)):
            y = run(p, a, b, eps_a)[0]
            out += [y[0] / Bs, y[1] / Bs, (y[2] - slope) / theta, y[3] / theta]
        return out

    def stretched(p, eps_a):
        total = sum(abs(run(p, a, b, eps_a)[0][4]) for a, b in ((X, 0.0), (L - X, L)))
        middle = run(p, X, X, eps_a)[1]
        total += quad(lambda x: float(np.sum(middle(x)[1] ** 2)), X, L - X, epsabs=0, epsrel=1e-12)[0]
        return EPS + total / (2 * L)

    p, eps_a = np.array([-1.0, 0, 0, 0, -1, 0, -1, 0]), EPS
    for _ in range(20):
        found = root(ends, p, args=(eps_a,), method="hybr", options=dict(xtol=1e-12))
        assert np.max(np.abs(found.fun)) < 1e-9
        p, before, eps_a = found.x, eps_a, stretched(found.x, eps_a)
        if abs(eps_a - before) < 1e-10 * EPS:
            break
    _, middle, (C0, C1) = run(p, X, X, eps_a)
    # the matching points lie where the strand sticks
    law = strand.BendingLaw(SECTION, mu=MU, axial_strain=eps_a)
    for a in (X, L - X):
        M = EA * eps_a * middle(a)[0] + C0 + C1 * a
        assert np.max(np.abs(M)) < 0.5 * law.EI_stick[0] * np.min(law.kappa_m)
    return C0, C0 + C1 * L


def test_the_end_moments_equal_a_shooting_solution_of_cardous_law(turned):
    theta, step = turned
    M0, ML = _shooting(theta)
    left, right = step.reactions["left"], step.reactions["right"]
    # a support's reaction is minus the section moment at x = 0 and plus it at x = L
    np.testing.assert_allclose([left["v'"], left["w'"]], -M0, rtol=0, atol=1e-4 * np.linalg.norm(M0))
    np.testing.assert_allclose([right["v'"], right["w'"]], ML, rtol=0, atol=1e-4 * np.linalg.norm(ML))


def test_the_friction_moment_stiffens_the_ends_beyond_the_lower_bound():
    """The same turned ends under the thesis's element rule (the lower bound, no friction moment)
    take a smaller end moment; stick (no slip) a larger one."""
    moments = {}
    for slip in ("none", "axis", "element"):
        model = strand.StrandModel(STEEL, L, n_elements=128, slip=slip, mu=MU, supports=_turned(2e-2))
        moments[slip] = abs(model.solve(EPS).reactions["left"]["v'"])
    assert moments["element"] < moments["axis"] < moments["none"]


def test_cardou_section_derivatives_match_central_differences():
    """`CardouSection` derivatives against central differences of its values, on both sides of
    the wires' elastic limit (the secant modulus then moves with the strain)."""
    d = strand.preset("steel-9.5").damaged(1)
    cardou = CardouSection(d.section(), 0.5)
    strain = np.array([1e-4, 2e-3, 5.4e-3, 6.5e-3, 0.03])
    values = cardou(strain, derivatives=True)
    h = 1e-8
    plus, minus = cardou(strain + h), cardou(strain - h)
    for key in ("EI_stick", "EI_slip", "M_rf", "kappa_m"):
        fd = (plus[key] - minus[key]) / (2 * h)
        np.testing.assert_allclose(values["d_" + key], fd, rtol=1e-5, atol=1e-6 * np.max(np.abs(fd)))
    # the values are BendingLaw's
    for j, e in enumerate(strain):
        law = d.bending_law(mu=0.5, axial_strain=e)
        np.testing.assert_allclose(values["M_rf"][:, j], law.M_rf, rtol=1e-14)
        np.testing.assert_allclose(values["kappa_m"][:, j], law.kappa_m, rtol=1e-14)


@pytest.mark.parametrize("damage", [0, 1, 2])
def test_section_law_tangent_agrees_with_finite_differences(damage):
    s = strand.preset("steel-9.5").damaged(damage) if damage else STEEL
    model = strand.StrandModel(s, 0.4, n_elements=12, slip="axis", supports=_turned(1e-2))
    step = model.solve(3e-3)
    assert step.slip_fraction > 0
    wires = model.bound(model.terms[0])
    assert not wires.symmetric and wires.potential is False and not wires.smooth
    # away from the kinks (a point on |κ| = κ_m has no derivative): the converged state
    assert check_tangent(model.terms[0], model, step.dofs) < 1e-6


class SmoothFriction(strand.SlipLaw):
    """A section law written outside the library: the composite moment saturates smoothly at the
    friction moment, ``M_c = M_0 tanh(EI_c κ / M_0)``, ``M_0 = M_rf + m_0`` (m_0 = 0.01 N·m keeps
    the untensioned strand, whose M_rf is 0, from a zero-width transition)."""

    def moment(self, kappa, points, state):
        EI, M0 = points.EI_composite, points.M_rf + 0.01
        t = np.tanh(EI * kappa / M0)
        sech2 = 1.0 - t**2
        dM_dEI, dM_dM0 = kappa * sech2, t - EI * kappa / M0 * sech2
        return M0 * t, EI * sech2, dM_dEI * points.d_EI_composite + dM_dM0 * points.d_M_rf


def test_a_section_law_written_outside_the_library_runs_a_curve_like_cardous():
    d = strand.preset("steel-9.5").damaged(1)
    curves = {
        name: strand.StrandModel(d, 0.5, n_elements=16, slip=slip).capacity_curve(n_steps=24)
        for name, slip in (("stick", "none"), ("axis", "axis"), ("smooth", SmoothFriction(0.5)))
    }
    assert all(c.ruptured for c in curves.values())
    secant = {n: c.secant(0.003) for n, c in curves.items()}
    assert secant["axis"] < secant["stick"] and secant["smooth"] < secant["stick"]
    assert secant["smooth"] == pytest.approx(secant["axis"], rel=0.02)
    model = strand.StrandModel(d, 0.4, n_elements=12, slip=SmoothFriction(0.5))
    assert check_tangent(model.terms[0], model, model.solve(0.003).dofs) < 1e-6


def test_a_law_giving_neither_a_moment_nor_a_composite_curvature_is_refused():
    class Nothing(strand.SlipLaw):
        pass

    class OldStyle(strand.SlipLaw):
        def composite(self, kappa, kappa_m, state):
            return kappa, np.ones_like(kappa), np.zeros_like(kappa)

    with pytest.raises(InputError, match="moment"):
        strand.StrandModel(STEEL, 0.3, n_elements=4, slip=Nothing())
    with pytest.raises(InputError, match="kinematic = True"):
        strand.StrandModel(STEEL, 0.3, n_elements=4, slip=OldStyle())
