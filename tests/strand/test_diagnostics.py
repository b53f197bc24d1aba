"""Diagnostics an analyst acts on: each names the term, the law, the dofs or the buckling.

- a term of the analyst's whose tangent is ⅓ of the true one, of the wrong sign, or zero: the
  first solve's check warns with the term and the ratio (`TangentWarning`), a slow solve warns
  whatever the line search did (`SlowConvergenceWarning`), a failed one names the term;
- a free–free strand: the error names the dofs its null vectors move; a compression beyond
  Euler's load π²EI/L²: the error says the load exceeds buckling;
- a slip law that returns NaN: `NonFiniteError` names the law; a term that does: the term;
- `check_tangent(term, model)` without U; lengths and frictions the model cannot take are
  `InputError`s before Newton, the CLI's included.
"""

import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

from skcable import strand
from skcable.errors import (
    ConvergenceError,
    InputError,
    NonFiniteError,
    SlowConvergenceWarning,
    TangentWarning,
)
from skcable.fe import check_tangent

STRAIGHT = strand.Strand(3e-3, (strand.Layer(6, 3e-3, lay_angle=1e-9),), strand.material("steel"))
EI = STRAIGHT.section().EI_stick[0]


class Cubic(strand.Term):
    """A cubic spring bed on v, ``q = −c v³``, its tangent times ``factor`` (1: right)."""

    def __init__(self, c, factor=1.0):
        self.c, self.factor = c, factor

    def __repr__(self):
        return f"Cubic(factor={self.factor:g})"

    def setup(self, model):
        self.fa = strand.FieldAssembly(model, [("v", 0)])

    def contribute(self, U, step):
        v = self.fa.interpolate(U)[0]
        tangent = self.factor * 3 * self.c * v**2
        return self.fa.vector((self.c * v**3)[None]), self.fa.matrix(tangent[None, None]), {}


def _bed(factor, **kwargs):
    return strand.StrandModel(
        STRAIGHT, 1.0, n_elements=16, grading=0.0, terms=[strand.TransverseLoad(qy=2e3), Cubic(1e12, factor)],
        **kwargs,
    )  # fmt: skip


@pytest.mark.parametrize("factor, ratio", [(1 / 3, "0.333"), (-1.0, "-1"), (0.0, "0")])
def test_the_first_solve_names_a_term_whose_tangent_is_off_with_its_ratio(factor, ratio):
    model = _bed(factor)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        try:
            model.solve(0.001)
        except ConvergenceError as exc:  # the wrong sign and the zero tangent do not converge:
            assert f"Cubic(factor={factor:g}) (tangent/difference {ratio})" in str(exc)  # named
    first = [w for w in seen if isinstance(w.message, TangentWarning)]
    assert len(first) == 1
    assert re.search(rf"Cubic\(factor=[-0-9.e]+\).*tangent/difference = {ratio}\b", str(first[0].message))
    # checked once: the next solve's check says nothing more
    with warnings.catch_warnings(record=True) as again:
        warnings.simplefilter("always")
        try:
            model.solve(0.001)
        except ConvergenceError:
            pass
    assert not any(isinstance(w.message, TangentWarning) for w in again)


def test_a_right_tangent_is_quiet_and_the_check_can_be_switched_off():
    with warnings.catch_warnings():
        warnings.simplefilter("error", SlowConvergenceWarning)
        step = _bed(1.0).solve(0.001, tol=1e-12)
        assert step.iterations < 15
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        _bed(1 / 3, check_tangents=False).solve(0.001, max_iter=60)
    assert not any(isinstance(w.message, TangentWarning) for w in seen)


def test_slow_convergence_is_detected_whatever_the_line_search_does():
    """The ⅓ tangent: every step is cut by the line search, none is a full Newton step (the old
    detector looked at full steps only); the solve converges linearly and says which tangent is off."""
    model = _bed(1 / 3, check_tangents=False)
    with pytest.warns(
        SlowConvergenceWarning, match=r"converged linearly.*Cubic\(factor=0\.333333\) \(6\.7e-01\)"
    ):
        step = model.solve(0.001, max_iter=60)
    assert step.iterations > 15


def test_a_free_free_strand_names_the_dofs_that_move():
    model = strand.StrandModel(
        STRAIGHT, 1.0, n_elements=16, grading=0.0, supports=("free", "free"), axial="none",
        terms=[strand.TransverseLoad(qy=1.0)],
    )  # fmt: skip
    with pytest.raises(ConvergenceError, match="singular") as info:
        model.solve()
    message = str(info.value)
    for moving in ("u at all 17 nodes", "v at all 17 nodes", "w at all 17 nodes", "phi at all 17 nodes"):
        assert moving in message
    assert "hold u, v, w, phi at an end" in message
    # a support that holds everything but the twist: only phi is named
    twistless = strand.StrandModel(
        STRAIGHT, 1.0, n_elements=16, grading=0.0, axial="none",
        supports=({"u": 0.0, "v": 0.0, "w": 0.0, "v'": 0.0, "w'": 0.0}, "free"),
        terms=[strand.TransverseLoad(qy=1.0), strand.FieldTerm(load={"phi": _torque})],
    )  # fmt: skip
    with pytest.raises(ConvergenceError, match=r"moving phi at all 17 nodes: .*hold phi at an end"):
        twistless.solve()


def _torque():
    from skfem import LinearForm

    return LinearForm(lambda v, w: 1.0 * v)


_torque = _torque()


def test_a_compression_beyond_buckling_says_so():
    """A pinned–pinned strand pushed by an axial force: below Euler's π²EI/L² it bends under a
    small lateral load as the beam-column does; at twice the load the error says buckling."""
    euler = np.pi**2 * EI
    q = 0.01

    def pushed(P):
        model = strand.StrandModel(
            STRAIGHT, 1.0, n_elements=16, grading=0.0, supports=("pinned", "pinned"), axial="force",
            terms=[strand.TransverseLoad(qy=q)],
        )  # fmt: skip
        return model.solve(force=-P)

    P = 0.5 * euler
    half = pushed(P)
    # the beam-column under a uniform load: v(L/2) = q/(P k²) (sec(kL/2) − 1) − q L²/(8P), k² = P/EI
    k = np.sqrt(P / EI)
    exact = q / (P * k**2) * (1 / np.cos(k / 2) - 1) - q / (8 * P)
    mid = float(np.interp(0.5, half.layout.nodes, half.nodal["v"]))
    assert mid == pytest.approx(exact, rel=1e-5)
    with pytest.raises(
        ConvergenceError, match=r"negative mode.*moving v at.*compression.*exceeds the strand's buckling load"
    ):
        pushed(2.0 * euler)


class NaNLaw(strand.SlipLaw):
    def moment(self, kappa, points, state):
        nan = np.full_like(kappa, np.nan)
        return nan, nan, nan


class NaNTerm(strand.Term):
    def contribute(self, U, step):
        R = np.zeros(U.size)
        R[3] = np.nan
        return R, None, {}


def test_a_value_that_is_not_finite_names_the_law_or_the_term():
    d = strand.preset("steel-9.5").damaged(1)
    with pytest.raises(
        NonFiniteError, match=r"slip law NaNLaw\(mu=0.5\) gave a moment or tangent that is not finite"
    ) as info:
        strand.StrandModel(d, 0.5, n_elements=8, slip=NaNLaw(0.5)).solve(0.002)
    assert info.value.source == "NaNLaw(mu=0.5)"
    with pytest.raises(NonFiniteError, match=r"NaNTerm\(\) gave a residual or tangent that is not finite"):
        strand.StrandModel(d, 0.5, n_elements=8, terms=[NaNTerm()]).solve(0.002)


def test_check_tangent_has_its_documented_default_state():
    model = strand.StrandModel(STRAIGHT, 1.0, n_elements=16, terms=[Cubic(1e12), Cubic(1e12, 1 / 3)])
    right, third = model.terms[-2:]
    assert check_tangent(right, model) < 1e-6
    assert check_tangent(third, model) == pytest.approx(2 / 3, rel=1e-6)
    for axial in ("force", "none"):
        other = strand.StrandModel(strand.preset("steel-9.5").damaged(1), 0.5, n_elements=8, slip="axis",
                                   axial=axial, supports=("clamped", "free"))  # fmt: skip
        assert check_tangent(other.terms[0], other) < 1e-6


def test_what_the_model_cannot_take_is_refused_before_newton():
    s = strand.preset("steel-9.5")
    with pytest.raises(
        InputError, match=r"length: length = 1000 m on 108146 elements.*at most about \d+ elements"
    ):
        strand.StrandModel(s, 1000.0)
    with pytest.raises(InputError, match="n_elements"):
        strand.StrandModel(s, 10.0, n_elements=20000)
    strand.StrandModel(s, 1000.0, n_elements=64)  # long, on a coarse mesh: its basis is accurate
    with pytest.raises(InputError, match=r"mu: must lie in \[0, 2\]"):
        strand.StrandModel(s, 1.0, mu=50)
    with pytest.raises(InputError, match="mu"):
        s.bending_law(mu=50, axial_strain=0.002)
    with pytest.raises(InputError, match="strain"):
        strand.StrandModel(s, 1.0, n_elements=8).solve(1.5)
    with pytest.raises(InputError, match="supports.*moderate rotations"):
        strand.StrandModel(s, 1.0, n_elements=8, supports=("clamped", {"v": 0.0, "v'": 0.5}))


@pytest.mark.parametrize(
    "flags, message",
    [(["--length", "1000"], "--length: length = 1000 m"), (["--mu", "50"], "--mu: must lie in [0, 2]")],
)
def test_the_cli_refuses_them_by_flag(flags, message):
    out = subprocess.run(
        [sys.executable, "-m", "skcable", "strand", "capacity", *flags],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode != 0 and message in out.stderr and "internal error" not in out.stderr
