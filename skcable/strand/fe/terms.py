r"""The strand's term protocol: what a term of a strand model sees and gives.

A [`StrandModel`][skcable.strand.StrandModel] is a mesh, its bases, its supports and a list of
terms (`skcable.fe.terms`: each declares ``symmetric``, ``potential`` and ``smooth``). There are
two kinds:

**Section terms** (`SectionTerm`) see the generalized strains at the quadrature points,

.. math:: g = (u',\ v',\ v'',\ w',\ w'',\ \varphi'),

and return section forces :math:`S_a(g, x)` (the virtual-work conjugates of :math:`g_a`) and
their tangent :math:`D_{ab} = \partial S_a/\partial g_b`, 6 × 6 per point; the model assembles
:math:`\int B^T S\,dx` and :math:`\int B^T D B\,dx` once for all of them. A section term has a
potential when it returns its energy per length as ``output["energy"]`` (an array, or a callable
asked for only where the solver needs it).

**Other terms** give their residual ``R`` (N,) and tangent ``K = ∂R/∂U`` (sparse N × N) from the
dof vector (`Term.contribute`); `FieldTerm` does it with scikit-fem forms on the named fields.

Arrays at the quadrature points have scikit-fem's layout ``(n_elements, n_quad)``. A term's
output dict may hold ``"point_data"`` and ``"cell_data"``, dicts of named arrays (at the
quadrature points, at the nodes ``(n_nodes,)`` or per element ``(n_elements,)``): they reach
``StepResult.outputs`` and every VTK file of the step. A term flagged ``damage = True`` is left
out of the intact reference twin of the damage index D_r.

Source: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico", Universidad de Chile,
2021, chapters 3–4 (eqs. 4.1–4.8).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from skfem import asm

from skcable._checks import real
from skcable.errors import InputError
from skcable.fe import terms as fe_terms
from skcable.fe.assembly import Assembly

__all__ = ["FIELDS", "STRAINS", "FieldAssembly", "FieldTerm", "SectionTerm", "Step", "Term", "check_terms"]

FIELDS = ("u", "v", "w", "phi")
#: generalized strains: (field, derivative order)
STRAINS = (("u", 1), ("v", 1), ("v", 2), ("w", 1), ("w", 2), ("phi", 1))


@dataclass
class Step:
    """What a term sees of the current solve.

    Attributes
    ----------
    strain : float
        Imposed axial strain of the step (u(L)/L).
    x : ndarray (n_elements, n_quad)
        Quadrature points (m).
    state : object
        This term's state (frozen within a Newton solve), or None.
    """

    strain: float
    x: np.ndarray
    state: object = None


class Term(fe_terms.Term):
    """Base of every term of a strand model: `skcable.fe.terms.Term`'s declarations and state,
    and either `SectionTerm.section` or `contribute`."""

    #: dropped from the intact reference twin (D_r) when True
    damage: bool = False

    def contribute(self, U: np.ndarray, step: Step):
        """``(R, K, output)``: residual (N,) or None, tangent (N, N) sparse or None, and a dict."""
        raise NotImplementedError

    def energy(self, U: np.ndarray, step: Step) -> float | None:
        """The term's potential (J) whose gradient is its residual, or None when it has none
        (then the model solves with plain Newton instead of energy minimisation). Section terms
        give theirs per unit length as ``output["energy"]`` of `section`."""
        return None


class SectionTerm(Term):
    """A term given by section forces and their 6 × 6 tangent at the quadrature points."""

    def section(self, g: np.ndarray, step: Step):
        """``(S, D, output)``: S (6, ne, nq), D (6, 6, ne, nq), and a dict of results."""
        raise NotImplementedError

    def setup(self, model) -> None:
        self._model = model

    def contribute(self, U, step):
        m = self._model
        S, D, output = self.section(m.generalized_strains(U), step)
        return m.section_vector(S), m.assembly.matrix(m.section_matrices(D)), output


class FieldAssembly:
    """`skcable.fe.Assembly` over some of a model's fields, mapped into the model's dof vector:
    the fast way for a nonlinear term to integrate ``∫ Σ S_a B_a`` and ``∫ Bᵀ D B`` over the
    strains it needs (a foundation on v, a contact on u and v).

    Parameters
    ----------
    model : StrandModel
        The model whose fields and dofs it maps.
    strains : sequence of (str, int)
        (field, derivative order 0, 1 or 2) over ``u``, ``v``, ``w``, ``phi``.
    """

    def __init__(self, model, strains):
        strains = tuple(strains)
        names = [f for f in FIELDS if any(f == name for name, _ in strains)]
        unknown = [name for name, _ in strains if name not in FIELDS]
        if unknown:
            raise InputError("strains", f"unknown field {unknown[0]!r}; fields are {FIELDS}")
        self.assembly = Assembly({f: model.bases[f] for f in names}, strains)
        self.index = np.concatenate(
            [np.arange(model.offsets[FIELDS.index(f)], model.offsets[FIELDS.index(f) + 1]) for f in names]
        )
        self.N = int(model.assembly.N)
        self.x = model.x
        self.dx = np.asarray(model.bases["u"].dx)  # (ne, nq), shared by every field

    def interpolate(self, U: np.ndarray) -> np.ndarray:
        """The strains at the quadrature points: (n_strains, n_elements, n_quad)."""
        return self.assembly.interpolate(U[self.index]).transpose(0, 2, 1)

    def vector(self, S: np.ndarray) -> np.ndarray:
        """``∫ Σ_a S_a B_a dx`` in the model's dof vector (N,), from S (n_strains, ne, nq)."""
        out = np.zeros(self.N)
        out[self.index] = self.assembly.vector(S.transpose(0, 2, 1))
        return out

    def matrix(self, D: np.ndarray) -> sp.csr_matrix:
        """``∫ Bᵀ D B dx`` as a sparse (N, N) matrix of the model, from D (n_strains, n_strains, ne, nq)."""
        K = self.assembly.matrix(self.assembly.element_matrices(D.transpose(0, 1, 3, 2))).tocoo()
        return sp.csr_matrix((K.data, (self.index[K.row], self.index[K.col])), shape=(self.N, self.N))


def _evaluate(model, value, name):
    """A parameter at the quadrature points: a constant, or a callable of x (m)."""
    if callable(value):
        out = np.asarray(value(model.x), dtype=float)
        try:
            out = np.broadcast_to(out, model.x.shape)
        except ValueError as exc:
            raise InputError(name, f"a callable must return values at x of shape {model.x.shape}") from exc
        return real(name, out)
    return real(name, value)


class FieldTerm(Term):
    """Any scikit-fem forms on the named fields ``u``, ``v``, ``w``, ``phi``; a linear term is
    assembled once and has a potential if its tangent is symmetric.

    Parameters
    ----------
    tangent : dict of (str, str) to BilinearForm, optional
        ``{(test, trial): form}``: the term's tangent. Without ``residual`` the
        term is linear and its residual is ``K U``; assembled once.
    load : dict of str to LinearForm, optional
        ``{field: form}``: an external load (N, subtracted from the residual); assembled once.
    residual : dict of str to LinearForm, optional
        ``{field: form}``: a nonlinear term's residual at the current fields,
        which its forms (and those of ``tangent``) see as ``w["u"]``, ``w["v"]``,
        ``w["w"]``, ``w["phi"]``; assembled at every iteration.
    damage : bool
        Leave the term out of the intact reference twin (D_r).
    symmetric : bool, optional
        Whether the tangent is symmetric; by default a linear term's assembled matrix is tested
        (to its round-off) and a nonlinear term is taken as not symmetric. Only a linear term
        with a symmetric tangent has a potential.
    smooth : bool
        False for a residual with kinks (contact, a tensionless support): semismooth Newton.
    **params
        Passed to the forms as ``w.<name>``: numbers, or callables of x evaluated
        once at the quadrature points.
    """

    def __init__(
        self,
        tangent=None,
        load=None,
        residual=None,
        *,
        damage: bool = False,
        symmetric: bool | None = None,
        smooth: bool = True,
        **params,
    ):
        self.tangent = dict(tangent or {})
        self.load = dict(load or {})
        self.residual = dict(residual or {})
        self.damage = bool(damage)
        self.smooth = bool(smooth)
        self._declared_symmetric = None if symmetric is None else bool(symmetric)
        self.params = params
        for test, trial in self.tangent:
            for name in (test, trial):
                if name not in FIELDS:
                    raise InputError("tangent", f"unknown field {name!r}; fields are {FIELDS}")
        for name in (*self.load, *self.residual):
            if name not in FIELDS:
                raise InputError("load" if name in self.load else "residual", f"unknown field {name!r}")

    def __repr__(self) -> str:
        return f"{type(self).__name__}({', '.join(f'{k}={v!r}' for k, v in self.params.items())})"

    def setup(self, model):
        self._model = model
        self._w = {k: _evaluate(model, v, k) for k, v in self.params.items()}
        self._K = None if self.residual else self._matrix(self._w)
        self._f = self._vector(self.load, self._w) if self.load else None
        declared = self._declared_symmetric
        self.symmetric = (_is_symmetric(self._K) if self.linear else False) if declared is None else declared
        self.potential = self.linear and self.symmetric

    @property
    def linear(self) -> bool:
        return not self.residual

    def _matrix(self, w):
        if not self.tangent:
            return None
        m = self._model
        index = {n: i for i, n in enumerate(FIELDS)}
        blocks = [[None] * len(FIELDS) for _ in FIELDS]
        for (test, trial), form in self.tangent.items():
            blocks[index[test]][index[trial]] = asm(form, m.bases[trial], m.bases[test], **w)
        for i, name in enumerate(FIELDS):  # bmat needs every block row and column sized
            if blocks[i][i] is None:
                blocks[i][i] = sp.csr_matrix((m.bases[name].N, m.bases[name].N))
        return sp.bmat(blocks, format="csr")

    def _vector(self, forms, w):
        m, out = self._model, np.zeros(self._model.assembly.N)
        parts = m.split(out)
        for name, form in forms.items():
            parts[name][:] += asm(form, m.bases[name], **w)
        return out

    def contribute(self, U, step):
        R = None
        if self.linear:
            K = self._K
            if K is not None:
                R = K @ U
        else:
            parts = self._model.split(U)
            w = dict(self._w, **{n: self._model.bases[n].interpolate(parts[n]) for n in FIELDS})
            R = self._vector(self.residual, w)
            K = self._matrix(w)
        if self._f is not None:
            R = -self._f if R is None else R - self._f
        return R, K, {}

    def energy(self, U, step):
        if not self.potential:
            return None
        out = 0.5 * float(U @ (self._K @ U)) if self._K is not None else 0.0
        return out - float(self._f @ U) if self._f is not None else out


def _is_symmetric(K) -> bool:
    """Whether a sparse matrix equals its transpose to the round-off of its assembly."""
    if K is None:
        return True
    difference = abs(K - K.T)
    size = abs(K).max() if K.nnz else 0.0
    return difference.nnz == 0 or difference.max() <= 1e-12 * size


def check_terms(terms) -> list:
    out = list(terms)
    for i, t in enumerate(out):
        if not isinstance(t, Term):
            raise InputError("terms", f"item {i} is not a Term: {t!r}")
    return out
