"""Strand finite element: textbook matrices, FD tangent, closed forms, EA, convergence, capacity."""

import numpy as np
import pytest

from skcable import strand
from skcable.errors import ConvergenceError, InputError
from skcable.strand.fe.wires import critical_curvature_table

STRAIGHT = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=1e-9),), strand.material("steel"))


def block(model, K, a, b):
    fields = ("u", "v", "w", "phi")
    i, j = fields.index(a), fields.index(b)
    o = model.offsets
    return K[o[i] : o[i + 1]][:, o[j] : o[j + 1]].toarray()


def test_straight_section_gives_textbook_euler_bernoulli_matrices():
    L, strain = 0.5, 0.001
    model = strand.StrandModel(STRAIGHT, L, n_elements=2, grading=0.0)
    U = model.uniform(strain)
    _, K, _ = model.assemble(U)
    _, K0, _ = model.assemble(model.uniform(0.0))  # no tension: the bending matrix alone
    sec = STRAIGHT.section()
    EI, N, h = sec.EI_stick[0], sec.EA * strain, L / 2
    # Hermite element: EI (bending) + N/(30 h) (geometric), dofs (v, v') per node
    kb = (
        EI
        / h**3
        * np.array(
            [
                [12, 6 * h, -12, 6 * h],
                [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                [-12, -6 * h, 12, -6 * h],
                [6 * h, 2 * h * h, -6 * h, 4 * h * h],
            ]
        )
    )
    kg = (
        N
        / (30 * h)
        * np.array(
            [
                [36, 3 * h, -36, 3 * h],
                [3 * h, 4 * h * h, -3 * h, -h * h],
                [-36, -3 * h, 36, -3 * h],
                [3 * h, -h * h, -3 * h, 4 * h * h],
            ]
        )
    )
    vb = model.bases["v"]
    order = np.array([[vb.nodal_dofs[0, n], vb.nodal_dofs[1, n]] for n in range(3)])  # (node, [v, v'])
    expected = np.zeros((vb.N, vb.N))
    for e in range(2):
        dofs = order[[e, e + 1]].ravel()
        expected[np.ix_(dofs, dofs)] += kb + kg
    bending = np.zeros_like(expected)
    for e in range(2):
        dofs = order[[e, e + 1]].ravel()
        bending[np.ix_(dofs, dofs)] += kb
    assert block(model, K0, "v", "v") == pytest.approx(bending, rel=1e-10, abs=1e-9 * EI / h**3)
    assert block(model, K, "v", "v") == pytest.approx(expected, rel=1e-10, abs=1e-9 * EI / h**3)
    assert block(model, K, "w", "w") == pytest.approx(expected, rel=1e-10, abs=1e-9 * EI / h**3)
    # P2 bar for the axial field: EA/(3h) [[7, -8, 1], [-8, 16, -8], [1, -8, 7]]
    bar = np.array([[7, -8, 1], [-8, 16, -8], [1, -8, 7]]) / (3 * h)
    ub = model.bases["u"]
    expected_u = np.zeros((ub.N, ub.N))
    for e in range(2):
        dofs = ub.element_dofs[[0, 2, 1], e]  # left, middle, right
        expected_u[np.ix_(dofs, dofs)] += sec.EA * bar
    assert block(model, K, "u", "u") == pytest.approx(expected_u, rel=1e-10, abs=1e-6 * sec.EA / h)
    # bending, axial and torsion decouple for a straight, intact section
    scale = sec.EA / h  # the largest stiffness entries
    for a, b in (("u", "v"), ("u", "w"), ("v", "w"), ("u", "phi"), ("v", "phi")):
        assert np.abs(block(model, K, a, b)).max() < 1e-9 * scale  # lay angle 1e-9: coupling ~ 1e-11


@pytest.mark.parametrize(
    "slip, damage_load", [("none", "eccentricity"), ("axis", "eccentricity"), ("none", "sinusoidal")]
)
def test_tangent_agrees_with_finite_differences(slip, damage_load):
    model = strand.StrandModel(
        strand.preset("steel-9.5").damaged(2), 0.4, n_elements=12, slip=slip, damage_load=damage_load
    )
    rng = np.random.default_rng(0)
    U = model.uniform(0.003) + 1e-5 * rng.standard_normal(model.offsets[-1])
    R, K, _ = model.assemble(U)
    d = np.zeros(U.size)  # the free dofs (the pulled end sets the sinusoidal loads' strain)
    d[model.free] = rng.standard_normal(model.free.size) * 1e-3
    eps = 1e-6
    fd = (model.assemble(U + eps * d)[0] - model.assemble(U - eps * d)[0]) / (2 * eps)
    assert K @ d == pytest.approx(fd, rel=1e-4, abs=1e-6 * np.abs(fd).max())


def test_clamped_tensioned_beam_under_transverse_load():
    L, q, strain = 1.0, 1.0, 0.001
    model = strand.StrandModel(STRAIGHT, L, n_elements=64, grading=0.0, terms=[strand.TransverseLoad(qy=q)])
    U = model.solve(strain).dofs
    N, EI = STRAIGHT.section().EA * strain, STRAIGHT.section().EI_stick[0]
    k = np.sqrt(N / EI)
    x = np.array([0.05, 0.25, 0.5])
    A = q * L / (2 * N * k * np.sinh(k * L / 2))
    exact = q * x * (L - x) / (2 * N) + A * (np.cosh(k * (x - L / 2)) - np.cosh(k * L / 2))
    assert model.bases["v"].probes(np.atleast_2d(x)) @ model.split(U)["v"] == pytest.approx(exact, rel=2e-5)


@pytest.mark.parametrize(
    "name, damage_load",
    [("steel-9.5", "eccentricity"), ("aluminium-14.3", "eccentricity"), ("steel-9.5", "sinusoidal")],
)
def test_undamaged_strand_stays_straight_with_F_equal_EA_eps(name, damage_load):
    model = strand.StrandModel(strand.preset(name), 0.6, n_elements=24, damage_load=damage_load)
    step = model.solve(0.002)
    assert step.force == pytest.approx(strand.preset(name).section().EA * 0.002, rel=1e-12)
    parts = model.split(step.dofs)
    assert np.abs(parts["v"]).max() < 1e-12 and np.abs(parts["w"]).max() < 1e-12


def test_mesh_convergence_of_force_and_peak_curvature():
    d = strand.preset("steel-9.5").damaged(1)
    forces, peaks = [], []
    for n in (24, 48, 96):
        model = strand.StrandModel(d, 0.5, n_elements=n)
        step = model.solve(0.003)
        forces.append(step.force)
        peaks.append(np.abs(step.curvature).max())
    assert abs(forces[2] / forces[1] - 1) < abs(forces[1] / forces[0] - 1) + 1e-9
    assert abs(forces[2] / forces[1] - 1) < 1e-3
    assert abs(peaks[2] / peaks[1] - 1) < 0.02


def test_capacity_curve_undamaged_is_EA_then_yields_and_breaks():
    model = strand.StrandModel(strand.preset("steel-9.5"), 0.3, n_elements=12)
    curve = model.capacity_curve(n_steps=24)
    assert curve.ruptured
    assert curve.K_Leq == pytest.approx(strand.preset("steel-9.5").section().EA, rel=1e-10)
    # the outer wires reach eps_rupture when the strand strain is eps_rupture / cos^2(alpha)... the core first
    assert curve.strain[-1] == pytest.approx(strand.material("steel").eps_rupture, rel=1e-6)
    assert curve.D_r == pytest.approx(0.0, abs=1e-12)


def test_secant_of_an_undamaged_curve_is_EA_and_checks_its_range():
    model = strand.StrandModel(strand.preset("steel-9.5"), 0.3, n_elements=8)
    curve = model.capacity_curve(max_strain=0.004, n_steps=8)
    assert curve.secant(0.0031) == pytest.approx(strand.preset("steel-9.5").section().EA, rel=1e-10)
    with pytest.raises(InputError, match="strain"):
        curve.secant(0.0)
    with pytest.raises(InputError, match="strain"):
        curve.secant(0.01)


def test_damage_softens_and_bends():
    d = strand.preset("steel-9.5").damaged(1)
    stick = strand.StrandModel(d, 1.0, n_elements=32).capacity_curve(n_steps=40)
    slip = strand.StrandModel(d, 1.0, n_elements=32, slip="element").capacity_curve(n_steps=40)
    EA = d.section().EA
    assert stick.K_Leq < EA  # the eccentric, rotating resultant bends the strand
    assert slip.K_Leq < stick.K_Leq
    assert slip.slip_fraction.max() == 1.0
    assert 0 < stick.D_r < slip.D_r < 1


@pytest.mark.parametrize("damage", [1, 2])
def test_sinusoidal_damage_loads_resultant_matches_closed_form(damage):
    """∫ q_y dx, ∫ q_z dx of the assembled loads against the integral of the Beltrán–De Vico
    load ``F sin²α/(R cos α)·(sin ψ_b, cos ψ_b)`` over the length, ψ_b = ψ_b0 + r x."""
    d = strand.preset("steel-9.5").damaged(damage)
    L, strain = 0.37, 0.003
    model = strand.StrandModel(d, L, n_elements=20, damage_load="sinusoidal")
    loads = model.split(model.damage_loads(strain))
    vb = model.bases["v"]
    one = np.zeros(vb.N)
    one[vb.nodal_dofs[0]] = 1.0  # v = 1: value dofs 1, slopes 0
    wires, material = d.wires(), d.material
    broken = np.flatnonzero(~wires.intact)
    assert broken.size == damage
    expected = np.zeros(2)
    for b in broken:
        a, R, psi0 = wires.lay_angle[b], wires.radius[b], wires.psi[b]
        rate = 2 * np.pi * wires.direction[b] / d.lay_lengths[0]
        q = wires.area[b] * material.stress(np.cos(a) ** 2 * strain) * np.sin(a) ** 2 / (R * np.cos(a))
        expected += q * np.array(
            [(np.cos(psi0) - np.cos(psi0 + rate * L)) / rate, (np.sin(psi0 + rate * L) - np.sin(psi0)) / rate]
        )
    scale = np.abs(expected).max()
    assert [loads["v"] @ one, loads["w"] @ one] == pytest.approx(expected, rel=1e-8, abs=1e-8 * scale)
    assert np.all(loads["u"] == 0) and np.all(loads["phi"] == 0)
    assert np.all(strand.StrandModel(d, L, n_elements=10).damage_loads(strain) == 0)


@pytest.mark.parametrize("damage_load", ["eccentricity", "sinusoidal"])
def test_axial_force_is_EA_times_mean_centroid_strain(damage_load):
    """Statics in the elastic range: N is uniform, so F = EA (ε − ⟨c·κ⟩ + ½⟨v′² + w′²⟩), the
    twist terms averaging out between the clamps; the bending offset of the centroid
    (c·κ) softens, the membrane stretch stiffens."""
    d = strand.preset("steel-9.5").damaged(2)
    model = strand.StrandModel(d, 0.5, n_elements=32, damage_load=damage_load)
    strain = 0.002
    step = model.solve(strain)
    g = model.generalized_strains(step.dofs)
    dx = model.bases["u"].dx

    def mean(f):
        return np.sum(f * dx) / np.sum(dx)

    # the net section's centroid, axial-stiffness weighted (A cos³α), turning with the lay
    # under the eccentricity reading and fixed at its x = 0 position under the sinusoidal one
    w = d.wires()
    rate = np.where(w.layer > 0, 2 * np.pi * w.direction / d.lay_lengths[0], 0.0)
    rate = rate if damage_load == "eccentricity" else 0 * rate
    psi = w.psi[:, None, None] + rate[:, None, None] * step.x[None]
    weight = np.where(w.intact, w.area * np.cos(w.lay_angle) ** 3, 0.0)[:, None, None]
    cy = np.sum(weight * w.radius[:, None, None] * np.sin(psi), axis=0) / weight.sum()
    cz = np.sum(weight * w.radius[:, None, None] * np.cos(psi), axis=0) / weight.sum()
    bending = mean(cy * g[2] + cz * g[4])
    membrane = mean(0.5 * (g[1] ** 2 + g[3] ** 2))
    EA = d.section().EA
    # a bent strand, not a trivial check: the force is off EA·ε by more than 0.5 %
    assert abs(step.force / (EA * strain) - 1) > 5e-3
    assert step.force == pytest.approx(EA * (strain - bending + membrane), rel=1e-9)


def test_two_readings_of_the_damage_bend_the_strand_alike_away_from_the_clamps():
    """Mechanisms (a) and (b) are the same load (N e k² = F sin²α/(R cos α), REFERENCE.md
    §3): in the middle of the specimen both deflect in phase with curvatures of one size."""
    d = strand.preset("steel-9.5").damaged(1)
    out = {}
    for damage_load in ("eccentricity", "sinusoidal"):
        model = strand.StrandModel(d, 0.5, n_elements=64, damage_load=damage_load)
        step = model.solve(0.003)
        nodes = step.layout.nodes
        middle = (nodes > 0.15) & (nodes < 0.35)
        values = step.nodal
        inside = (step.x > 0.15) & (step.x < 0.35)
        curvature = np.mean(np.hypot(*step.curvature)[inside])
        out[damage_load] = (values["v"][middle], values["w"][middle], curvature)
    (va, wa, ka), (vb, wb, kb) = out["eccentricity"], out["sinusoidal"]
    assert np.corrcoef(va, vb)[0, 1] > 0.99 and np.corrcoef(wa, wb)[0, 1] > 0.99
    assert kb == pytest.approx(ka, rel=0.15)


def test_bad_input():
    with pytest.raises(InputError, match="damage_load"):
        strand.StrandModel(strand.preset("steel-9.5"), 1.0, damage_load="both")
    with pytest.raises(InputError, match="slip"):
        strand.StrandModel(strand.preset("steel-9.5"), 1.0, slip="sometimes")
    with pytest.raises(InputError, match="length"):
        strand.StrandModel(strand.preset("steel-9.5"), -1.0)
    with pytest.raises(InputError, match="grading"):
        strand.StrandModel(strand.preset("steel-9.5"), 1.0, grading=1.0)
    with pytest.raises(InputError, match="n_steps"):
        strand.StrandModel(strand.preset("steel-9.5"), 0.3, n_elements=8).capacity_curve(n_steps=2)


class FailingBeyond(strand.StrandModel):
    """A model whose Newton 'fails' beyond a strain: exercises the capacity curve's failure path."""

    limit = 0.002

    def solve(self, strain, guess=None, state=None, **kw):
        if strain > self.limit:
            raise ConvergenceError(f"forced failure at {strain}", [1.0, 0.5, 0.4])
        return super().solve(strain, guess, state, **kw)


def test_capacity_curve_failure_raises_with_history_or_stops():
    model = FailingBeyond(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=8)
    with pytest.raises(ConvergenceError) as info:
        model.capacity_curve(n_steps=20)
    assert info.value.history == [1.0, 0.5, 0.4]
    partial = model.capacity_curve(n_steps=20, on_failure="stop")
    assert not partial.ruptured and partial.failure.startswith("no convergence beyond strain")
    # the cutbacks close in on the limit from below
    assert 0.99 * FailingBeyond.limit < partial.strain[-1] <= FailingBeyond.limit
    with pytest.raises(ConvergenceError, match="rupture"):
        _ = partial.D_r
    with pytest.raises(InputError, match="on_failure"):
        model.capacity_curve(n_steps=20, on_failure="ignore")


def test_a_stop_among_softening_wires_says_so():
    """Aluminium's blend (Table B.1) softens: a curve that stops with wires there names it;
    steel's law never softens and its stop message stays plain."""
    window = strand.material("aluminium").softening_range
    model = FailingBeyond(strand.preset("aluminium-10.1"), 0.3, n_elements=8)
    model.limit = 0.5 * sum(window)  # every wire (cos²α ε ≈ ε) inside the window
    partial = model.capacity_curve(n_steps=20, on_failure="stop")
    assert "material law softens" in partial.failure
    plain = FailingBeyond(strand.preset("steel-9.5"), 0.3, n_elements=8).capacity_curve(
        n_steps=20, on_failure="stop"
    )
    assert "softens" not in plain.failure


def test_critical_curvature_is_c1_in_the_axial_strain():
    """kappa_m(eps) and its derivative are consistent across the table's grid points (a
    piecewise-linear table once stalled Newton at 384 elements and 160 steps), and the table is
    Cardou's law itself."""
    d = strand.preset("steel-9.5").damaged(1)
    grid, table, spline, slope = critical_curvature_table(d, 0.5)
    points = np.concatenate([grid[5:200:17], 0.5 * (grid[5:200:17] + grid[6:201:17])])
    h = 1e-7 * grid[-1]
    np.testing.assert_allclose(
        (spline(points + h) - spline(points - h)) / (2 * h),
        slope(points),
        rtol=1e-4,
        atol=1e-6 * np.max(np.abs(slope(points))),
    )
    law = [strand.BendingLaw(d.section(), mu=0.5, axial_strain=e).kappa_m for e in grid[1::40]]
    np.testing.assert_allclose(spline(grid[1::40]).T, law, rtol=1e-12)


class FailingLargeIncrements(strand.StrandModel):
    """Newton 'fails' whenever the strain jumps by more than a third of a schedule step."""

    jump = None

    def solve(self, strain, guess=None, state=None, **kw):
        if strain - self.last > self.jump:
            raise ConvergenceError(f"forced failure at {strain}", [1.0, 0.9])
        step = super().solve(strain, guess, state, **kw)
        self.last = strain
        return step


def test_after_a_cutback_the_increment_stays_reduced():
    model = FailingLargeIncrements(strand.preset("steel-9.5"), 0.3, n_elements=4)
    model.last, model.jump = 0.0, 2 * model.strand.material.eps_y / 4 / 3  # a third of a step
    curve = model.capacity_curve(max_strain=2 * model.strand.material.eps_y, n_steps=8)
    accepted = len(curve.steps)
    # the reduced increment is kept and doubled only after two converged steps: one failure per
    # three accepted steps, where jumping back to the goal failed about twice per accepted step
    assert accepted >= 12 and curve.cutbacks <= accepted // 2
    assert np.all(np.diff(curve.strain) <= model.jump * (1 + 1e-9))


@pytest.mark.parametrize("name", ["steel-9.5", "aluminium-10.1", "steel-12.7", "aluminium-14.3"])
def test_every_table_case_reaches_rupture_on_default_settings(name):
    """Pino Vidal (2021) traced all eight strands to rupture: so does the default model, stick and
    element rule; where the printed aluminium blend softens, the path folds and the result says
    so (``snaps``), steel's law never softens and never snaps."""
    for damage in (1, 2):
        for slip in ("none", "element"):
            curve = strand.StrandModel(strand.preset(name).damaged(damage), slip=slip).capacity_curve()
            assert curve.ruptured and curve.failure is None, (name, damage, slip, curve.failure)
            if name.startswith("steel"):
                assert curve.snaps == []
            # where it snapped, the wires' strains straddle the softening window of the law
            window = strand.material("aluminium").softening_range
            for step in (s for s in curve.steps if s.shifted):
                alive = step.wire_strain[~step.layout.wire_broken]
                assert np.any(alive > window[0])


class BreaksBeyond(strand.SectionTerm):
    """A term whose forces turn non-finite beyond a strain (a law that breaks down): counts its calls."""

    calls = 0

    def section(self, g, step):
        type(self).calls += 1
        S = np.full_like(g, np.nan) if step.strain > 0.01 else np.zeros_like(g)
        return S, np.zeros((6, 6, *g.shape[1:])), {"energy": np.zeros(g.shape[1:])}


def test_a_failing_curve_costs_at_most_twice_a_successful_one():
    s = strand.preset("steel-9.5").damaged(1)
    base = strand.default_physics()
    counter = BreaksBeyond()
    BreaksBeyond.calls = 0
    ok = strand.StrandModel(s, 0.5, n_elements=16, physics=[*base, counter]).capacity_curve(max_strain=0.01)
    success = BreaksBeyond.calls
    BreaksBeyond.calls = 0
    failed = strand.StrandModel(s, 0.5, n_elements=16, physics=[*base, counter]).capacity_curve(
        max_strain=0.02, on_failure="stop"
    )
    assert (
        ok.failure is None
        and failed.failure is not None
        and failed.strain[-1] == pytest.approx(0.01, rel=1e-3)
    )
    assert BreaksBeyond.calls <= 2 * success


def test_summaries_are_short():
    """print(curve) printed 58,761 lines: curve, step and model now print one line each."""
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=8)
    curve = model.capacity_curve(n_steps=8)
    for thing in (curve, curve.steps[-1], model):
        text = repr(thing)
        assert "\n" not in text and len(text) < 600, text
    assert f"{curve.K_Leq:.6g}" in repr(curve) and "ruptured" in repr(curve)
    assert f"{curve.steps[-1].strain:.6g}" in repr(curve.steps[-1])


def test_an_amended_error_keeps_its_history_and_every_attempt():
    """The strand model adds its diagnosis to a solve's `ConvergenceError` (`_amended`): the
    damped Newton's history, its last iterate and every attempt's history stay on it."""
    from skcable.strand.fe.model import _amended

    err = ConvergenceError(
        "no convergence", [1.0, 0.5], last=np.array([0.1, 0.2]), attempts=[[1.0, 0.5], [1.0, 2.0]]
    )
    out = _amended(err, "; a term's tangent is off")
    assert out.args[0].startswith("no convergence") and out.args[0].endswith("; a term's tangent is off")
    assert out.history == [1.0, 0.5] and out.attempts == [[1.0, 0.5], [1.0, 2.0]]
    np.testing.assert_array_equal(out.last, [0.1, 0.2])
