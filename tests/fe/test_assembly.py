"""The one assembly against scikit-fem's forms, and the banded and sparse solves against scipy's."""

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import Basis, BilinearForm, ElementLineHermite, ElementLineP2, LinearForm, MeshLine, asm, bmat

from skcable.errors import ConvergenceError, InputError
from skcable.fe import Assembly, LinearSystem, SparseSystem, minimize, newton

STRAINS = (("u", 1), ("v", 0), ("v", 1), ("v", 2), ("phi", 1))


def _d(f, order):
    return np.asarray(f) if order == 0 else f.grad[0] if order == 1 else f.hess[0][0]


@pytest.fixture(scope="module")
def setup():
    mesh = MeshLine(np.sort(np.r_[0.0, np.random.default_rng(0).uniform(0, 2, 9), 2.0]))
    ub = Basis(mesh, ElementLineP2(), intorder=6)
    bases = {"u": ub, "v": ub.with_element(ElementLineHermite()), "phi": ub}
    return Assembly(bases, STRAINS), bases


def test_vector_and_matrix_equal_scikit_fem_forms(setup):
    asmb, bases = setup
    rng = np.random.default_rng(1)
    nq, ne = asmb.dx.shape  # elements last
    S = rng.standard_normal((len(STRAINS), nq, ne))
    D = rng.standard_normal((len(STRAINS), len(STRAINS), nq, ne))
    names = list(bases)
    vec, blocks = [], []
    for test in names:
        rows = [(a, o) for a, (f, o) in enumerate(STRAINS) if f == test]
        vec.append(
            asm(
                LinearForm(lambda v, w, r=rows: sum(w[f"S{a}"] * _d(v, o) for a, o in r)),
                bases[test],
                **{f"S{a}": S[a].T for a in range(len(STRAINS))},
            )
        )
        row = []
        for trial in names:
            cols = [(b, o) for b, (f, o) in enumerate(STRAINS) if f == trial]

            @BilinearForm
            def form(u, v, w, r=rows, c=cols):
                return sum(w[f"D{a}{b}"] * _d(u, ob) * _d(v, oa) for a, oa in r for b, ob in c)

            kw = {f"D{a}{b}": D[a, b].T for a in range(len(STRAINS)) for b in range(len(STRAINS))}
            row.append(asm(form, bases[trial], bases[test], **kw))
        blocks.append(row)
    R = np.concatenate(vec)
    K = bmat(blocks).toarray()
    scale_R, scale_K = np.max(np.abs(R)), np.max(np.abs(K))
    np.testing.assert_allclose(asmb.vector(S), R, rtol=0, atol=1e-12 * scale_R)
    np.testing.assert_allclose(asmb.matrix(D=D).toarray(), K, rtol=0, atol=1e-12 * scale_K)
    # the one-pair fast path equals the full tangent of that pair alone
    pair = np.zeros_like(D)
    pair[2, 1] = D[2, 1]
    np.testing.assert_allclose(
        asmb.block(2, 1, D[2, 1]), asmb.element_matrices(pair), rtol=0, atol=1e-12 * scale_K
    )
    U = rng.standard_normal(asmb.N)
    parts = np.split(U, asmb.offsets[1:-1])
    fields = {n: bases[n].interpolate(p) for n, p in zip(names, parts, strict=True)}
    g = np.array([_d(fields[f], o) for f, o in STRAINS])  # scikit-fem's (ne, nq)
    np.testing.assert_allclose(
        asmb.interpolate(U), g.transpose(0, 2, 1), rtol=0, atol=1e-12 * np.max(np.abs(g))
    )


def test_the_strain_assembly_deprecated_in_0_2_0_is_gone():
    from skcable import fe

    assert not hasattr(fe, "StrainAssembly") and "StrainAssembly" not in fe.__all__


def _positive_system(asmb, seed):
    """A symmetric positive-definite section tangent, its banded free block, a right-hand side and
    the sparse solution to compare with."""
    rng = np.random.default_rng(seed)
    nq, ne = asmb.dx.shape
    A = rng.standard_normal((len(STRAINS), len(STRAINS), nq, ne))
    D = np.einsum("abqe,cbqe->acqe", A, A) + 0.1 * np.eye(len(STRAINS))[:, :, None, None]
    K = asmb.matrix(D=D)
    free = np.setdiff1d(np.arange(asmb.N), [0, 3, asmb.N - 1])
    system = asmb.banded(free)
    ab = system.add_elements(system.band(), asmb.element_matrices(D))
    b = rng.standard_normal(len(free))
    return K, free, system, ab, b, spla.spsolve(K[free][:, free].tocsc(), b)


def test_banded_solve_equals_sparse_solve(setup):
    asmb, _ = setup
    K, free, system, ab, b, expected = _positive_system(asmb, 2)
    x = system.solve(ab, b)
    np.testing.assert_allclose(x, expected, rtol=1e-9, atol=1e-12 * np.max(np.abs(expected)))
    assert system.kl < len(free) // 2  # ordered along the axis: a narrow band
    ab = system.add_sparse(system.band(), K)  # the same matrix from CSR
    np.testing.assert_allclose(
        system.solve(ab, b), expected, rtol=1e-9, atol=1e-12 * np.max(np.abs(expected))
    )


def test_a_coupling_beyond_the_band_moves_the_solve_to_sparse(setup):
    """A tie between the two ends (a multi-point constraint) breaks the band: the system moves to
    SuperLU and solves the same equations, and its Cholesky-like solve still tells definiteness."""
    asmb, _ = setup
    K, free, system, ab, b, _ = _positive_system(asmb, 3)
    a, z = free[0], free[-1]
    tie = sp.coo_matrix(([1e3, -1e3, -1e3, 1e3], ([a, a, z, z], [a, z, a, z])), shape=K.shape).tocsr()
    expected = spla.spsolve((K + tie)[free][:, free].tocsc(), b)
    linear = LinearSystem(system)
    assert linear.accept([tie]) and not linear.is_banded
    acc = linear.add_sparse(linear.add_elements(linear.band(), _element_matrices(asmb, 3)), tie)
    np.testing.assert_allclose(linear.solve(acc, b), expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())
    np.testing.assert_allclose(
        linear.solve_positive(acc, b), expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max()
    )
    negative = linear.add_sparse(linear.band(), -(K + tie))
    with pytest.raises(np.linalg.LinAlgError):
        linear.solve_positive(negative, b)
    assert isinstance(linear.current, SparseSystem)


def _element_matrices(asmb, seed):
    rng = np.random.default_rng(seed)
    nq, ne = asmb.dx.shape
    A = rng.standard_normal((len(STRAINS), len(STRAINS), nq, ne))
    return asmb.element_matrices(
        np.einsum("abqe,cbqe->acqe", A, A) + 0.1 * np.eye(len(STRAINS))[:, :, None, None]
    )


def test_singular_banded_system_raises(setup):
    asmb, _ = setup
    free = np.arange(asmb.N)
    system = asmb.banded(free)
    with pytest.raises(ConvergenceError, match="singular"):
        system.solve(system.band(), np.ones(asmb.N))


def test_unknown_field_or_order_is_refused(setup):
    _, bases = setup
    with pytest.raises(InputError, match="strains"):
        Assembly(bases, [("q", 1)])
    with pytest.raises(InputError, match="order"):
        Assembly(bases, [("u", 3)])


def test_newton_converges_quadratically_and_stops_on_stagnation():
    # x³ = 8: quadratic convergence to the root 2
    result = newton(
        lambda x: x,
        np.array([5.0]),
        norm=lambda x: abs(x[0] ** 3 - 8) / 8,
        increment=lambda x: -(x**3 - 8) / (3 * x**2),
        tol=1e-14,
    )
    assert result.x[0] == pytest.approx(2.0, rel=1e-14)
    assert result.history[-1] < 1e-14 and result.iterations < 12
    # x² + 1 = 0 has no real root: Newton wanders, the stagnation rule stops it early
    with pytest.raises(ConvergenceError, match="stagnates|no descent") as info:
        newton(
            lambda x: x,
            np.array([0.5]),
            norm=lambda x: abs(x[0] ** 2 + 1),
            increment=lambda x: -(x**2 + 1) / (2 * x),
            tol=1e-12,
            max_iter=50,
        )
    assert len(info.value.history) < 10


def test_banded_cholesky_equals_sparse_solve_and_refuses_indefinite(setup):
    asmb, _ = setup
    K, free, system, ab, b, expected = _positive_system(asmb, 5)
    np.testing.assert_allclose(
        system.solve_positive(ab, b), expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max()
    )
    # a shift by the same matrix: (1 + mu) K x = b
    x = system.solve_positive(ab, b, shift=ab, mu=1.0)
    np.testing.assert_allclose(2 * x, expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())
    with pytest.raises(np.linalg.LinAlgError):
        system.solve_positive(-ab, b)


def test_minimize_passes_a_fold_that_newton_cannot():
    """Π(x) = x⁴/4 − x²/2 − 0.3 x: at x0 = 0.2 the tangent 3x² − 1 is negative; plain Newton heads for
    the local maximum, the shifted one descends to the minimum near x = 1.13 (a root of x³ − x − 0.3)."""
    f = lambda x: x[0] ** 3 - x[0] - 0.3  # noqa: E731

    def solve(x, mu):
        k = 3 * x[0] ** 2 - 1 + mu
        if k <= 0:
            raise np.linalg.LinAlgError("not positive definite")
        return np.array([-f(x) / k])

    result = minimize(
        lambda x: x,
        np.array([0.2]),
        norm=lambda x: abs(f(x)),
        energy=lambda x: x[0] ** 4 / 4 - x[0] ** 2 / 2 - 0.3 * x[0],
        gradient=lambda x: np.array([f(x)]),
        solve=solve,
        tol=1e-13,
        mu_max=10.0,
    )
    root = max(np.roots([1, 0, -1, -0.3]).real)
    assert result.x[0] == pytest.approx(root, rel=1e-12) and result.shifted


def test_newton_rejects_failed_trials_and_stops_at_a_given_round_off_floor():

    # R(x) = x³ - 8 from x0 = 1: the full first step lands at x = 10/3; an inner solve that
    # fails beyond x = 2.5 (raising InputError) makes that trial rejected, the step halved
    calls = []

    def assemble(x):
        calls.append(float(x[0]))
        if x[0] > 2.5:
            raise InputError("x", "beyond the inner solve's range")
        return x**3 - 8.0

    result = newton(
        assemble,
        np.array([1.0]),
        norm=lambda r: abs(float(r[0])) / 8.0,
        increment=lambda r: -r / (3.0 * (np.cbrt(r + 8.0)) ** 2),
        tol=1e-14,
        rejects=(InputError,),
    )
    assert result.x[0] == pytest.approx(2.0, rel=1e-14) and not result.at_floor
    assert calls[1] == pytest.approx(1.0 + 7.0 / 3.0) and calls[2] == pytest.approx(1.0 + 7.0 / 6.0)
    with pytest.raises(InputError):  # not listed in rejects: it propagates
        newton(
            assemble,
            np.array([1.0]),
            norm=lambda r: abs(float(r[0])),
            increment=lambda r: -r / 3.0,
            tol=1e-14,
        )

    # a residual that cannot fall below 1e-9 (an inner solve's round-off): stops loudly, unless
    # that floor is given, when the stop at it returns, marked
    def noisy(x):
        return x - 2.0

    def floored(r):  # the measure cannot tell residuals below 1e-9
        return max(abs(float(r[0])), 1e-9)

    with pytest.raises(ConvergenceError):
        newton(noisy, np.array([0.0]), norm=floored, increment=lambda r: -r, tol=1e-14)
    result = newton(
        noisy, np.array([0.0]), norm=floored, increment=lambda r: -r, tol=1e-14, floor=lambda r: 2e-9
    )
    assert result.at_floor and result.x[0] == 2.0


@pytest.mark.parametrize("old", ["skcable.bvp.assembly", "skcable.bvp.bordered", "skcable.bvp.probes"])
def test_the_shims_deprecated_in_0_2_0_are_gone(old):
    """0.2.0 served LineAssembly, BorderedSolver and the probes from the cable BVPs for one
    release; 0.3.0 has them in skcable.fe only."""
    import importlib

    with pytest.raises(ModuleNotFoundError):
        importlib.import_module(old)
