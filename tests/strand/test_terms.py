"""Terms and slip laws through the public API: an analyst's term, a plug-in slip law, springs,
the D_r twin, and every built-in section term assembled both ways (scikit-fem's forms)."""

import numpy as np
import pytest
from skfem import BilinearForm, LinearForm, asm, bmat

from skcable import strand
from skcable.errors import InputError

STRAIGHT = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=1e-9),), strand.material("steel"))


# --- the how-to's term (docs/howto_terms.md): a Winkler foundation written by an analyst ------------
@LinearForm
def winkler_residual(v, w):  # the foundation's force on v: k·v, at the current v (w["v"])
    return w.k * w["v"] * v


@BilinearForm
def winkler_tangent(u, v, w):  # its derivative with respect to v
    return w.k * u * v


def my_foundation(k):
    return strand.FieldTerm(residual={"v": winkler_residual}, tangent={("v", "v"): winkler_tangent}, k=k)


def _beam_on_foundation(EI, N, k, q, L, x):
    """Closed form of EI v'''' − N v'' + k v = q, v = v' = 0 at x = 0 and L."""
    r = np.roots([EI, 0.0, -N, 0.0, k]).astype(complex)
    A = np.array([np.ones(4), r, np.exp(r * L), r * np.exp(r * L)])
    C = np.linalg.solve(A, -np.array([q / k, 0, q / k, 0], dtype=complex))
    return (q / k + np.exp(np.outer(x, r)) @ C).real


def test_analyst_foundation_term_matches_the_closed_form_and_the_ready_term():
    L, strain, q, k = 1.0, 0.001, 1.0, 2e4
    sec = STRAIGHT.section()
    x = np.array([0.03, 0.1, 0.25, 0.5])
    exact = _beam_on_foundation(sec.EI_stick[0], sec.EA * strain, k, q, L, x)
    load = strand.TransverseLoad(qy=q)
    for term in (my_foundation(k), strand.ElasticFoundation(ky=k)):
        model = strand.StrandModel(STRAIGHT, L, n_elements=64, grading=0.0, terms=[term, load])
        step = model.solve(strain)
        v = model.bases["v"].probes(np.atleast_2d(x)) @ model.split(step.dofs)["v"]
        assert v == pytest.approx(exact, rel=2e-5)
    # the foundation matters: without it the mid-span deflection is larger by more than 10 %
    free = strand.StrandModel(STRAIGHT, L, n_elements=64, grading=0.0, terms=[load]).solve(strain)
    assert np.max(np.abs(free.nodal["v"])) > 1.1 * np.max(np.abs(exact))


# --- a slip law written outside the library -----------------------------------------------------
class SmoothSaturation(strand.SlipLaw):
    """A kinematic law: κ_c = k tanh(κ/k), k = κ_m + κ_0: stateless and smooth (κ_0 = 0.05 1/m
    keeps the untensioned strand, whose κ_m is 0, from a zero-width transition)."""

    kinematic = True

    def composite(self, kappa, kappa_m, state):
        k = kappa_m + 0.05
        t = np.tanh(kappa / k)
        return k * t, 1.0 - t**2, t - (kappa / k) * (1.0 - t**2)

    def second_derivatives(self, kappa, kappa_m, state):  # for the consistent tangent
        k = kappa_m + 0.05
        t, r = np.tanh(kappa / k), kappa / k
        sech2 = 1.0 - t**2
        return -2 * t * sech2 / k, 2 * r * t * sech2 / k, -2 * r**2 * t * sech2 / k


def test_plug_in_slip_law_runs_a_curve_and_softens_like_cardous_law():
    d = strand.preset("steel-9.5").damaged(1)
    curves = {
        name: strand.StrandModel(d, 0.5, n_elements=16, slip=slip).capacity_curve(n_steps=24)
        for name, slip in (("stick", "none"), ("axis", "axis"), ("smooth", SmoothSaturation(0.5)))
    }
    assert all(c.ruptured for c in curves.values())
    # the smooth law saturates like Cardou's (at κ_m + κ_0): softer than stick, close to axis slip
    secant = {n: c.secant(0.003) for n, c in curves.items()}
    assert secant["axis"] < secant["stick"] and secant["smooth"] < secant["stick"]
    assert secant["smooth"] == pytest.approx(secant["axis"], rel=0.02)
    assert np.max(curves["smooth"].slip_fraction) > 0


@pytest.mark.parametrize("slip", [SmoothSaturation(0.5), "element"])
def test_tangent_of_plug_in_and_element_slip_agrees_with_finite_differences(slip):
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(2), 0.4, n_elements=12, slip=slip)
    rng = np.random.default_rng(3)
    U = model.uniform(0.003) + 1e-5 * rng.standard_normal(model.assembly.N)
    state = model.initial_state()
    R, K, _ = model.assemble(U, state)
    d = np.zeros(U.size)
    d[model.free] = rng.standard_normal(model.free.size) * 1e-3
    eps = 1e-6
    fd = (model.assemble(U + eps * d, state)[0] - model.assemble(U - eps * d, state)[0]) / (2 * eps)
    assert K @ d == pytest.approx(fd, rel=1e-4, abs=1e-6 * np.abs(fd).max())


# --- springs, twin, errors -----------------------------------------------------------------------
def test_nodal_spring_acts_at_its_node_with_a_linear_response():
    """A spring k at mid-span under a transverse load: v_mid(k) = v0 / (1 + k G), so
    (1/v_mid − 1/v0)/k is the same for every k (G the mid-span flexibility)."""
    L, strain = 1.0, 0.001
    load = strand.TransverseLoad(qy=1.0)
    values = []
    for k in (None, 1e3, 4e3):
        terms = [load] if k is None else [load, strand.NodalSpring(0.5, k, "v")]
        model = strand.StrandModel(STRAIGHT, L, n_elements=32, grading=0.0, terms=terms)
        step = model.solve(strain)
        values.append(np.interp(0.5, step.layout.nodes, step.nodal["v"]))
    v0, v1, v2 = values
    assert v2 < v1 < v0
    assert (1 / v1 - 1 / v0) / 1e3 == pytest.approx((1 / v2 - 1 / v0) / 4e3, rel=1e-4)


def test_reference_twin_keeps_every_term_but_the_damage():
    d = strand.preset("steel-9.5").damaged(1)
    foundation = strand.ElasticFoundation(1e4)
    model = strand.StrandModel(d, 0.4, n_elements=12, damage_load="sinusoidal", terms=[foundation])
    twin = model.twin()
    kinds = [type(t) for t in twin.terms]
    assert strand.ElasticFoundation in kinds and strand.SinusoidalDamageLoads not in kinds
    assert strand.SinusoidalDamageLoads in [type(t) for t in model.terms]
    assert not any(twin.strand.wires().intact == False)  # noqa: E712
    curve = model.capacity_curve(n_steps=12)
    assert foundation in curve.reference.model.terms


def test_bad_terms_are_refused():
    s = strand.preset("steel-9.5")
    with pytest.raises(InputError, match="terms"):
        strand.StrandModel(s, 0.3, n_elements=4, terms=[object()])
    with pytest.raises(InputError, match="tangent"):
        strand.FieldTerm(tangent={("v", "q"): winkler_tangent})
    with pytest.raises(InputError, match="x"):
        strand.StrandModel(s, 0.3, n_elements=4, grading=0.0, terms=[strand.NodalSpring(0.1, 1.0)])
    with pytest.raises(InputError, match="k"):
        strand.ElasticFoundation()
    with pytest.raises(InputError, match="ky"):
        strand.StrandModel(s, 0.3, n_elements=4, terms=[strand.ElasticFoundation(ky=-1.0)])
    with pytest.raises(InputError, match="slip"):
        strand.StrandModel(s, 0.3, n_elements=4, slip=3)


# --- the fast assembly of every built-in section term equals scikit-fem's forms -------------------
def _d(f, order):
    return f.grad[0] if order == 1 else f.hess[0][0]


@pytest.mark.parametrize("slip", ["none", "axis", "element"])
def test_built_in_section_terms_assembled_both_ways(slip):
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(2), 0.4, n_elements=10, slip=slip)
    rng = np.random.default_rng(4)
    U = model.uniform(0.004) + 1e-5 * rng.standard_normal(model.assembly.N)
    g = model.generalized_strains(U)
    names = list(model.bases)
    for term, state in zip(model.terms, model.initial_state(), strict=True):
        S, D, _ = term.bind(model).section(g, strand.Step(0.004, model.x, state))
        vec, blocks = [], []
        for test in names:
            rows = [(a, o) for a, (f, o) in enumerate(strand.fe.STRAINS) if f == test]
            form = LinearForm(lambda v, w, r=rows: sum(w[f"S{a}"] * _d(v, o) for a, o in r))
            vec.append(asm(form, model.bases[test], **{f"S{a}": S[a] for a in range(6)}))
            row = []
            for trial in names:
                cols = [(b, o) for b, (f, o) in enumerate(strand.fe.STRAINS) if f == trial]

                @BilinearForm
                def bilinear(u, v, w, r=rows, c=cols):
                    return sum(w[f"D{a}{b}"] * _d(u, ob) * _d(v, oa) for a, oa in r for b, ob in c)

                kw = {f"D{a}{b}": np.broadcast_to(D[a, b], model.x.shape) for a in range(6) for b in range(6)}
                row.append(asm(bilinear, model.bases[trial], model.bases[test], **kw))
            blocks.append(row)
        R, K = np.concatenate(vec), bmat(blocks).toarray()
        fast_R = model.section_vector(S)
        fast_K = model.assembly.matrix(model.section_matrices(D)).toarray()
        assert np.max(np.abs(fast_R - R)) <= 1e-12 * np.max(np.abs(R))
        assert np.max(np.abs(fast_K - K)) <= 1e-12 * np.max(np.abs(K))
