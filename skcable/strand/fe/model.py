r"""The strand beam-cable finite element: a mesh, its scikit-fem bases, supports and a list of terms.

The strand axis is x ∈ [0, L]; the fields are the displacements of the core centre line: axial
u (P2, or P3 with ``element="P3"``), transverse v, w (``ElementLineHermite``: value and slope per
node) and twist φ (as u), on bases that share one quadrature. The physics is a list of
[terms][skcable.strand.Term]; by default the helical wire fibres with a slip law and the wires'
own bending and torsion (and, for the thesis's reading of the damage, its sinusoidal loads). The
ends are supports given as data (`skcable.strand.fe.supports`): clamped at both ends by default
and pulled at x = L, ``u(L) = u(0) + ε L`` (Pino Vidal 2021, §4.1, "fixed – fixed sliding"), or
pinned, sliding, free, or any dof fixed at any value; the axial load at x = L is data too
(``axial=``): an imposed strain, an axial force, or none.

**Convergence.** A solve has converged when, for every group of equations of one kind (the
axial, transverse and torsional forces, and the bending moments on the slopes of v and w), the
largest residual over the free dofs is below ``tol`` times that group's force scale: the
largest force flowing through its equations, ``∫ Σ|S_a||B_a| dx`` of the section terms plus the
magnitude of every other term's contribution, at free and fixed dofs alike (so the reactions
count): a transverse load of 0.01 N/m converges as tightly as the axial pull beside it. No group
is asked for less than the round-off of its sums, `ROUND_OFF` times the model's largest force
scale (times the length, for moments). ``atol`` (N) adds an absolute criterion.

Source: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico", Universidad de Chile,
2021, chapter 4.
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementLineHermite, ElementLineP2, MeshLine

from skcable import _plausible
from skcable._checks import one_of, positive, whole
from skcable.errors import ConvergenceError, InputError, NonFiniteError, SlowConvergenceWarning
from skcable.fe import Assembly, LinearSystem, NewtonOptions, first_converged, minimize, newton
from skcable.fe.elements import ElementLinePpExact
from skcable.fe.newton import linear_tail
from skcable.strand._arguments import real_number
from skcable.strand._bending import friction
from skcable.strand._geometry import lay_rates
from skcable.strand.capacity import StepResult, StrandLayout, capacity_curve
from skcable.strand.fe.diagnosis import FirstSolveCheck, non_finite, tangent_modes
from skcable.strand.fe.slip import SlipLaw, slip_law
from skcable.strand.fe.supports import StrandSupports
from skcable.strand.fe.terms import FIELDS, STRAINS, SectionTerm, Step, check_terms
from skcable.strand.fe.wires import HelicalWires, SinusoidalDamageLoads, WireBending

__all__ = ["StrandModel", "DAMAGE_LOADS", "ELEMENTS", "default_physics"]

#: how a broken wire loads the strand: the net section's helical eccentricity
#: (mechanism (a)) or the thesis's reading, a prismatic section under the
#: sinusoidal biaxial loads of Beltrán & De Vico (mechanism (b))
DAMAGE_LOADS = ("eccentricity", "sinusoidal")
#: the elements of u and φ (v and w are always cubic Hermite), with their quadrature order
ELEMENTS = {"P2": 6, "P3": 8}
#: the round-off floor of a residual entry, relative to the model's largest force scale: the sums
#: over wires, points and elements that form it lose about this much (observed: 0.3 eps on an
#: intact strand's transverse equations, whose exact residual is zero)
ROUND_OFF = 100 * np.finfo(float).eps
#: a term whose tangent errs by more than this (`skcable.fe.check_tangent`) is named when Newton
#: converges linearly
TANGENT_ERROR = 1e-6
#: the merits a semismooth step is measured against (`skcable.fe.newton` ``nonmonotone``)
NONMONOTONE = 10
#: the largest relative error of the curvature scikit-fem's Hermite basis (a global polynomial in
#: x, inverted per element) may carry: about ε·(x/h)³ for an element of length h at x (measured:
#: 1.7e-10 at x/h = 100, 1.8e-7 at 1000, 1.5e-4 at 10,000; at 270,000 the inversion fails)
BASIS_ERROR = 1e-5


def default_physics(slip="none", mu: float = 0.5, damage_load: str = "eccentricity") -> list:
    """The built-in terms: helical wires with a slip law, the wires' own bending and torsion,
    and (``damage_load="sinusoidal"``) the sinusoidal damage loads on a prismatic section."""
    one_of("damage_load", damage_load, DAMAGE_LOADS)
    sinusoidal = damage_load == "sinusoidal"
    terms = [HelicalWires(slip, mu, helical=not sinusoidal), WireBending()]
    return terms + [SinusoidalDamageLoads()] if sinusoidal else terms


@functools.lru_cache(maxsize=16)
def _discretisation(nodes: bytes, length: float, element: str):
    """``(mesh, bases, assembly, kept)`` of the node abscissae ``nodes`` (float64 bytes), formed
    once for every model on the mesh (none changes them); ``kept``: what the models derive from
    the mesh and their free dofs alone, ``ends`` (each basis's end dofs) and ``by_free`` (per set
    of free dofs: the banded free block and the equation groups)."""
    L = float(length)
    mesh = MeshLine(np.frombuffer(nodes, dtype=float).copy()).with_boundaries(
        {"left": lambda x: np.isclose(x[0], 0.0), "right": lambda x: np.isclose(x[0], L)}
    )
    bases = _bases(mesh, element)
    return mesh, bases, Assembly(bases, STRAINS), SimpleNamespace(ends={}, by_free={})


@functools.lru_cache(maxsize=16)
def _strand_section(strand):
    """``strand.section()``, formed once per strand for every model of it (nothing changes it)."""
    return strand.section()


def _bases(mesh: MeshLine, element: str) -> dict:
    axial = ElementLineP2() if element == "P2" else ElementLinePpExact(3)
    ub = Basis(mesh, axial, intorder=ELEMENTS[element])
    vb = ub.with_element(ElementLineHermite())
    return {"u": ub, "v": vb, "w": vb, "phi": ub}


@dataclass(slots=True, eq=False)
class Assembled:
    """One assembly of a strand model at a dof vector (`StrandModel._assemble`): the residual
    ``R`` (N, N·m; the axial force at x = L subtracted under ``axial="force"``), the tangents
    ``extra`` of the terms that are not section terms (``tangents``: the same by term position),
    each term's ``outputs``, the generalized strains ``g`` (6, ne, nq), the section terms' summed
    forces ``S`` and tangent ``D`` (None without section terms), the ``energy`` (J, on demand; None
    where a term has no potential), the ``size`` of what each equation sums (the force scales),
    the axial ``strain``, the terms' ``state``, the axial ``load``, and the section terms' element
    matrices ``Ke``, formed on first use (``formed``: a converging iterate never needs them)."""

    R: np.ndarray
    extra: list
    outputs: list
    g: np.ndarray
    S: np.ndarray | None
    D: np.ndarray | None
    energy: Any
    size: np.ndarray
    strain: float
    state: tuple
    load: float
    tangents: dict
    Ke: np.ndarray | None = None
    formed: bool = False


class StrandModel:
    """Finite-element model of a strand pulled along its axis.

    Parameters
    ----------
    strand : Strand
        Geometry, damage, material.
    length : float
        Specimen length (m); the thesis does not state it: 1 m by default.
    n_elements : int, optional
        Number of elements; default: 16 per lay length, at least 64.
    mesh : MeshLine or array, optional
        Node abscissae from 0 to length (overrides ``n_elements``).
    grading : float in [0, 1)
        Mesh grading toward both ends (boundary layer ~ sqrt(EI/N)):
        ``x = L (s - g sin(2 pi s) / (2 pi))``, 0 uniform.
    slip : {"none", "axis", "element"} or SlipLaw
        Stick, Cardou's law per quadrature point and principal axis, the thesis's
        element rule, or any [`SlipLaw`][skcable.strand.SlipLaw].
    mu : float
        Friction coefficient when ``slip`` is a name.
    damage_load : {"eccentricity", "sinusoidal"}
        How broken wires load the strand (`DAMAGE_LOADS`): every fibre on its helix (the
        axial force acts on the helical eccentricity of the net centroid), or the thesis's
        reading, a prismatic section under the sinusoidal loads of the broken wires
        ([`SinusoidalDamageLoads`][skcable.strand.SinusoidalDamageLoads]).
    terms : sequence of Term
        Terms added to the built-in physics (foundations, loads, springs, contact, an
        analyst's own).
    physics : sequence of Term, optional
        Replaces the built-in physics (``slip``, ``mu`` and ``damage_load`` are then unused).
    supports : pair of end conditions, optional
        ``(left, right)``, each ``"clamped"``, ``"pinned"``, ``"sliding"``, ``"free"`` or a
        dict ``{dof: value}`` (m, rad): `skcable.strand.fe.supports`. Default: both clamped.
    axial : {"strain", "force", "none"}
        The axial load at x = L (`skcable.strand.fe.supports`): an imposed strain
        (``solve(strain)``, the capacity curves of the thesis), an axial force P
        (``solve(force=P)``) or none (``solve()``).
    twist : {"clamped", "free"}
        Shortcut: ``"free"`` frees the twist at x = L (of the default or the given supports).
    element : {"P2", "P3"}
        The element of u and φ (v and w are cubic Hermite).
    options : NewtonOptions, optional
        Default Newton settings of `solve` and `capacity_curve`; each call may override them.
    check_tangents : bool
        On the model's first solve, check the tangent of every term an analyst wrote
        (`skcable.strand.fe.diagnosis`; a `skcable.errors.TangentWarning` names a term that is off).

    Attributes
    ----------
    terms : list of Term
        Every term of the model (unbound, as given): the physics, then ``terms``.
    strand_section : skcable.strand.Section
        The strand's section properties, formed once per model: its ``wires`` (the wire table)
        and ``materials`` are what the built-in terms read when they are bound.
    bases : dict of str to skfem.Basis
        ``u``, ``v``, ``w``, ``phi``.
    assembly : skcable.fe.Assembly
        Basis values, weights and sparsity pattern, computed once.
    x : ndarray (n_elements, n_quad)
        Quadrature points (m).
    fixed, fixed_values : ndarray
        The dofs the supports fix and their values (an imposed strain's dof excluded); ``pull``
        is the axial dof at x = L, ``free`` the dofs a solve moves.
    axial : str
        The axial load at x = L.
    """

    def __init__(
        self,
        strand,
        length: float = 1.0,
        *,
        n_elements=None,
        mesh=None,
        grading: float = 0.6,
        slip="none",
        mu: float = 0.5,
        damage_load: str = "eccentricity",
        terms=(),
        physics=None,
        twist: str = "clamped",
        supports=None,
        axial: str = "strain",
        element: str = "P2",
        options: NewtonOptions | None = None,
        check_tangents: bool = True,
    ):
        self.strand, self.length = strand, float(positive("length", length))
        self.supports = StrandSupports.of(supports, twist, axial)
        self.axial = self.supports.axial
        self.twist = "free" if "phi" not in self.supports.right else "clamped"
        if not 0 <= grading < 1:
            raise InputError("grading", f"must lie in [0, 1), got {grading!r}")
        friction(mu)
        self.options = NewtonOptions.of(options)
        if physics is None:
            physics = default_physics(slip, mu, damage_load)
            self.damage_load = damage_load
        else:
            self.damage_load = "custom"
        self.terms = check_terms(physics) + check_terms(terms)
        if self.axial != "strain" and any(isinstance(t, SinusoidalDamageLoads) for t in self.terms):
            raise InputError(
                "axial", "the sinusoidal damage loads take the wires' force at the imposed strain: 'strain'"
            )
        laws = [t.slip for t in self.terms if isinstance(getattr(t, "slip", None), SlipLaw)]
        self.slip = laws[0] if laws else slip_law("none", mu)
        if self.slip.name != "none" and not self.slip.layered and len(strand.layers) != 1:
            raise InputError(
                "slip",
                "this slip law needs a single helical layer (1x7-type strands); a strand of several "
                "layers takes the layer-by-layer law, StageSlip(LayerSlipLaw(...))",
            )
        self.element = one_of("element", element, ELEMENTS)
        nodes = self._nodes(n_elements, mesh, grading)
        self.mesh, self.bases, self.assembly, self._kept = _discretisation(
            nodes.tobytes(), self.length, element
        )
        self.offsets = self.assembly.offsets
        self.x = np.asarray(self.bases["u"].global_coordinates())[0]  # (ne, nq)
        self._dx = self.bases["u"].dx
        self._boundary()
        self.strand_section = _strand_section(strand)  # its wire table and materials, formed once per strand
        self._ruptures = [m.eps_rupture for m in strand.materials]
        self._plausible_strain = max(_plausible.MAX_STRAIN, 1.5 * max(self._ruptures))
        self.EA = self.strand_section.EA
        self._bound = [t.bind(self) for t in self.terms]
        self._section_terms, self._other_terms = _by_kind(self._bound)
        key = self.free.tobytes()
        if key not in self._kept.by_free:
            self._kept.by_free[key] = (self.assembly.banded(self.free), self._equation_groups())
        banded, self._group_index = self._kept.by_free[key]
        self._system = LinearSystem(banded)
        self._first = FirstSolveCheck(self, check_tangents)
        self._metric = None  # the elastic tangent of the straight strand, in the solver's storage
        self.layout = self._layout()
        self._alive_wires = ~self.layout.wire_broken[:, None, None]
        self._init = dict(
            strand=strand, length=length, mesh=self.mesh.p[0].copy(), physics=self.terms[: len(physics)],
            terms=self.terms[len(physics) :], supports=self.supports.describe(), element=element,
            options=options, grading=grading, mu=mu, damage_load=damage_load, axial=self.axial,
            check_tangents=bool(check_tangents),
        )  # fmt: skip

    def __repr__(self) -> str:
        s = self.strand
        return (
            f"StrandModel({s!r}, length={self.length:g} m, {self.mesh.t.shape[1]} elements, "
            f"{self.assembly.N} dofs, slip={self.slip!r}, supports={self.supports.describe()}, "
            f"axial={self.axial!r}, terms=[{', '.join(map(repr, self.terms))}])"
        )

    def __reduce__(self):
        """Pickled as the data it was built from (the bases and tables are rebuilt; the name of
        the built-in physics kept)."""
        a = self._init
        kwargs = {k: v for k, v in a.items() if k not in ("strand", "length", "damage_load")}
        return (_rebuild, (type(self), a["strand"], a["length"], kwargs), {"damage_load": self.damage_load})

    # --- set-up --------------------------------------------------------------
    def _nodes(self, n_elements, mesh, grading) -> np.ndarray:
        """The node abscissae (m), checked (`_check_basis`)."""
        if mesh is not None:
            nodes = np.asarray(mesh.p[0] if isinstance(mesh, MeshLine) else mesh, dtype=float)
            if nodes.ndim != 1 or nodes.size < 3 or not np.all(np.isfinite(nodes)):
                raise InputError("mesh", "must be at least 3 finite node abscissae")
            if not (np.isclose(nodes.min(), 0) and np.isclose(nodes.max(), self.length)):
                raise InputError("mesh", f"must run from 0 to length = {self.length}")
            nodes = np.sort(nodes)
            if np.any(np.diff(nodes) <= 0):
                raise InputError("mesh", "has a repeated node")
        else:
            lay = float(np.min(self.strand.lay_lengths))
            n = (
                max(64, int(np.ceil(16 * self.length / lay)))
                if n_elements is None
                else whole("n_elements", n_elements, 2)
            )
            s = np.linspace(0.0, 1.0, n + 1)
            nodes = self.length * (s - grading * np.sin(2 * np.pi * s) / (2 * np.pi))
        self._check_basis(nodes, n_elements, mesh)
        return np.ascontiguousarray(nodes, dtype=float)

    def _check_basis(self, nodes, n_elements, mesh):
        """Refuse a mesh whose Hermite basis would lose more than `BASIS_ERROR` of the curvature
        (before anything is built: scikit-fem's inversion of it may fail outright)."""
        h = np.diff(nodes)
        reach = np.maximum(np.abs(nodes[:-1]), np.abs(nodes[1:])) / h
        error = np.finfo(float).eps * float(np.max(reach)) ** 3
        if error <= BASIS_ERROR:
            return
        k = int(np.argmax(reach))
        largest = int(len(h) * (BASIS_ERROR / error) ** (1 / 3))
        argument = "mesh" if mesh is not None else "n_elements" if n_elements is not None else "length"
        raise InputError(
            argument,
            f"length = {self.length:g} m on {len(h)} elements: the element at x = {nodes[k + 1]:.4g} m is "
            f"{h[k]:.3g} m long, 1/{reach[k]:.3g} of its distance from x = 0, and scikit-fem's Hermite "
            f"basis of v and w (a polynomial in x) would give its curvature a relative error of about "
            f"{error:.1g} (more than {BASIS_ERROR:g}); give at most about {largest} elements "
            "(n_elements), or model a shorter specimen (the clamps' boundary layers span about sqrt(EI/N))",
        )

    def _boundary(self):
        offsets = {name: int(self.offsets[i]) for i, name in enumerate(FIELDS)}
        seen = self._kept.ends  # each basis's end dofs, looked up once per mesh
        fixed, values = self.supports.dofs(self.bases, offsets, seen)
        self.pull = StrandSupports.index("right", "u", self.bases, offsets, seen)
        self._left_u = StrandSupports.index("left", "u", self.bases, offsets, seen)
        if np.any(np.diff(fixed) == 0):
            raise InputError("supports", "fix a dof twice (both ends on one node?)")
        self.fixed, self.fixed_values = fixed, values
        imposed = np.append(fixed, self.pull) if self.axial == "strain" else fixed
        free = np.ones(self.assembly.N, dtype=bool)
        free[imposed] = False
        self.free = np.flatnonzero(free)  # sorted, as `np.setdiff1d` gives them
        self._nodal_dofs = np.array([offsets[name] + self.bases[name].nodal_dofs[0] for name in FIELDS])
        self._reaction_dofs = self.supports.indices(self.bases, offsets, seen)
        if self.axial == "strain":  # the imposed strain's reaction is the axial force at x = L
            self._reaction_dofs["right"]["u"] = self.pull

    def _equation_groups(self):
        """The equations of one kind (per field, the values, and the slopes of v and w) as flat
        index arrays for ``np.maximum.reduceat``: ``(order, starts, free_order, free_starts,
        forces, free_length, with_free)``, the last three over the groups with free dofs."""
        free = np.zeros(self.assembly.N, dtype=bool)
        free[self.free] = True
        groups = []
        for i, name in enumerate(FIELDS):
            basis, offset = self.bases[name], int(self.offsets[i])
            kinds = [np.arange(basis.N)]
            if isinstance(basis.elem, ElementLineHermite):
                slopes = basis.nodal_dofs[1]
                kinds = [np.setdiff1d(np.arange(basis.N), slopes), slopes]
            for k, dofs in enumerate(kinds):
                dofs = offset + dofs
                groups.append((dofs, dofs[free[dofs]], name == "phi" or k == 1))
        has_free = np.array([free.size > 0 for _, free, _ in groups])
        order = np.concatenate([dofs for dofs, _, _ in groups])
        starts = np.cumsum([0] + [len(dofs) for dofs, _, _ in groups[:-1]])
        with_free = [free for _, free, _ in groups if free.size]
        free_order = np.concatenate(with_free)
        free_starts = np.cumsum([0] + [len(f) for f in with_free[:-1]])
        moment = np.array([is_moment for _, _, is_moment in groups])
        length = np.where(moment, self.length, 1.0)[has_free]
        return (
            order,
            starts,
            free_order,
            free_starts,
            np.flatnonzero(~moment),
            length,
            np.flatnonzero(has_free),
        )

    def _layout(self) -> StrandLayout:
        w, materials = self.strand_section.wires, self.strand_section.materials
        return StrandLayout(
            nodes=self.mesh.p[0].copy(),
            elements=self.mesh.t.copy(),
            x=self.x,
            dx=self._dx,
            wire_psi=w.psi,
            wire_rate=lay_rates(self.strand, w),
            wire_radius=w.radius,
            wire_layer=w.layer,
            wire_broken=~w.intact,
            wire_size=np.sqrt(w.area / np.pi),
            slip=self.slip.name,
            eps_rupture=min(m.eps_rupture for m in self.strand.materials),
            eps_y1=min(m.eps_y1 for m in self.strand.materials),
            wire_eps_rupture=materials.take("eps_rupture"),
            wire_eps_y1=materials.take("eps_y1"),
            element=self.element,
        )

    def twin(self, strand=None) -> StrandModel:
        """The same model (mesh, supports, terms, element, options) for another strand, every
        damage term left out: by default the intact strand, the reference of the damage index D_r."""
        from dataclasses import replace

        strand = replace(self.strand, broken=frozenset()) if strand is None else strand
        kept = [t for t in self.terms if not t.damage]
        return type(self)(
            strand, self.length, mesh=self.mesh, physics=kept, supports=self.supports.describe(),
            axial=self.axial, element=self.element, options=self.options,
        )  # fmt: skip

    # --- fields ----------------------------------------------------------------
    def split(self, U):
        """Views of ``U`` per field: dict of ``u``, ``v``, ``w``, ``phi``."""
        return {name: U[self.offsets[i] : self.offsets[i + 1]] for i, name in enumerate(FIELDS)}

    def nodal_values(self, U):
        """Values of u, v, w, φ at the mesh nodes (their vertex dofs): dict of (n_nodes,) arrays."""
        return dict(zip(FIELDS, np.asarray(U).take(self._nodal_dofs), strict=True))

    def generalized_strains(self, U):
        """g = (u′, v′, v″, w′, w″, φ′) at the quadrature points: (6, ne, nq)."""
        return self.assembly.interpolate_by_element(U)

    def section_vector(self, S):
        """``∫ Σ_a S_a B_a dx`` (N,) from section forces S (6, ne, nq)."""
        return self.assembly.vector(S.transpose(0, 2, 1))

    def section_matrices(self, D):
        """Element matrices ``∫ Bᵀ D B dx`` (n_local, n_local, ne) from D (6, 6, ne, nq)."""
        return self.assembly.element_matrices(D.transpose(0, 1, 3, 2))

    def uniform(self, strain):
        """Dof vector of the uniform axial strain ``u = strain·x`` (the straight start), with the
        supports' prescribed values (and, under an imposed strain, ``u(L) = u(0) + strain·L``)."""
        U = np.zeros(self.assembly.N)
        u = self.bases["u"]
        if isinstance(u.elem, ElementLineP2):
            U[: u.N] = strain * u.doflocs[0]
        else:  # hierarchical: a linear function lives on the vertex dofs alone
            U[u.nodal_dofs[0]] = strain * self.mesh.p[0]
        return self._prescribed(U, strain)

    def _prescribed(self, U, load, values=None):
        """``U`` with the supports' values (``values``: those of a solve's ``prescribed``) and,
        under an imposed strain ``load``, ``u(L)``."""
        U[self.fixed] = self.fixed_values if values is None else values
        if self.axial == "strain":
            U[self.pull] = load * self.length + self.supports.left["u"]
        return U

    def _start(self, load, values=None):
        """The straight start of a solve: the uniform strain of the load (P / EA under a force),
        with the supports' ``values``."""
        strain = load if self.axial == "strain" else load / self.EA if self.axial == "force" else 0.0
        return self._prescribed(self.uniform(strain), load, values)

    def prescribed_values(self, prescribed) -> np.ndarray:
        """The values of the held dofs (``fixed``'s order) with ``prescribed`` in place of the
        supports' own: ``{"left": {dof: value}, "right": {...}}`` (m, rad) over the dofs the
        supports hold at that end (not the axial load's u(L)); refused by name otherwise."""
        values = self.fixed_values.copy()
        if not isinstance(prescribed, dict) or not set(prescribed) <= {"left", "right"}:
            raise InputError("prescribed", f"must be a dict over 'left' and 'right', got {prescribed!r:.80}")
        for end, given in prescribed.items():
            held = getattr(self.supports, end)
            if not isinstance(given, dict):
                raise InputError("prescribed", f"{end} end: must be a dict {{dof: value}}, got {given!r:.80}")
            for dof, value in given.items():
                if dof not in held:
                    raise InputError(
                        "prescribed",
                        f"{end} end: {dof!r} is not held by the supports ({sorted(held)}); a solve "
                        "moves only a held dof (hold it in supports=, at any value)",
                    )
                checked = StrandSupports.value(end, dof, value, "prescribed")
                values[np.searchsorted(self.fixed, self._reaction_dofs[end][dof])] = checked
        return values

    def strain_of(self, U) -> float:
        """The strand's mean axial strain ``(u(L) − u(0)) / L`` of the dofs ``U``."""
        return float((U[self.pull] - U[self._left_u]) / self.length)

    def initial_state(self):
        """The terms' states at the start of a curve (all stick)."""
        return tuple(t.initial_state(self) for t in self._bound)

    def centroid(self) -> np.ndarray:
        """(y_c, z_c) of the net section at the quadrature points (m): (2, ne, nq), axial-stiffness
        weighted (A cos³α), turning with the lay under the eccentricity reading (zero without wires)."""
        for t in self._bound:
            if isinstance(t, HelicalWires):
                return np.array([t.centroid_y, t.centroid_z])
        return np.zeros((2, *self.x.shape))

    def damage_loads(self, strain: float) -> np.ndarray:
        """External load vector of the sinusoidal damage loads at the imposed strain (zero without them)."""
        out = np.zeros(self.assembly.N)
        for t in self._bound:
            if isinstance(t, SinusoidalDamageLoads):
                out += t.loads(strain)
        return out

    def bound(self, term):
        """This model's bound copy of ``term`` (one of `terms`), or ``term`` bound afresh."""
        for given, bound in zip(self.terms, self._bound, strict=True):
            if given is term or bound is term:
                return bound
        return term.bind(self)

    # --- assembly ----------------------------------------------------------------
    def _assemble(self, U, state, load, bound=None):
        """Residual, element matrices of the section terms, other tangents, the terms' outputs,
        and the size of what each equation sums (for the force scales), at the axial ``load``
        (the imposed strain, or the axial force at x = L, or 0); ``bound`` replaces the model's
        bound terms (a surrogate, `_pass_fold`)."""
        state = self.initial_state() if state is None else state
        strain = load if self.axial == "strain" else self.strain_of(U)
        section_terms, other_terms = (
            (self._section_terms, self._other_terms) if bound is None else _by_kind(bound)
        )
        g = self.generalized_strains(U)
        S = D = None
        outputs: list[Any] = [None] * len(self._bound)  # each term's output dict, filled below
        for i, t in section_terms:
            St, Dt, outputs[i] = t.section(g, Step(strain, self.x, state[i]))
            S, D = (St, Dt) if S is None else (S + St, D + Dt)  # new arrays: the terms' stay as given
        if S is not None:
            R, size = self.assembly.vector_and_magnitude(S.transpose(0, 2, 1))
        else:
            R, size = np.zeros(self.assembly.N), np.zeros(self.assembly.N)
        densities = [outputs[i].get("energy") for i, _ in section_terms]
        energy: Any = None if any(e is None for e in densities) else 0.0  # the other terms' part
        extra, tangents = [], {}
        for i, t in other_terms:
            step = Step(strain, self.x, state[i])
            Rt, Kt, outputs[i] = t.contribute(U, step)
            if Rt is not None:
                if np.shape(Rt) != (self.assembly.N,):
                    raise InputError(
                        "terms",
                        f"{t!r} returned a residual of shape {np.shape(Rt)}, not ({self.assembly.N},)",
                    )
                R = R + Rt
                size = size + np.abs(Rt)
            if Kt is not None:
                if getattr(Kt, "shape", None) != (self.assembly.N, self.assembly.N):
                    raise InputError(
                        "terms",
                        f"{t!r} returned a tangent of shape {getattr(Kt, 'shape', None)}, "
                        f"not ({self.assembly.N}, {self.assembly.N})",
                    )
                extra.append(Kt)
                tangents[i] = Kt
            if energy is not None:
                e = t.energy(U, step) if t.potential is not False else None
                energy = None if e is None else energy + e
        # a sum is NaN or infinite where an entry is (one pass, no mask)
        if not (math.isfinite(R.sum()) and (D is None or math.isfinite(D.sum()))) or any(
            not math.isfinite((K.data if sp.issparse(K) else np.asarray(K)).sum()) for K in extra
        ):
            raise self._non_finite(U, state, load, section_terms, other_terms)
        if self.axial == "force" and load != 0.0:  # the axial force at x = L: a dead load
            R = R.copy()
            R[self.pull] -= load
            size[self.pull] += abs(load)
            energy = None if energy is None else energy - load * float(U[self.pull])
        if energy is not None:  # the section terms' part on demand (`_energy`): a converged step needs none
            energy = _Energy(densities, self._dx, energy)
        return Assembled(
            R=R, extra=extra, outputs=outputs, g=g, S=S, D=D, energy=energy, size=size, strain=strain,
            state=state, load=load, tangents=tangents,
        )  # fmt: skip

    def _non_finite(self, U, state, load, section_terms, other_terms):
        """The `NonFiniteError` naming the terms whose residual or tangent is not finite at ``U``."""
        strain = load if self.axial == "strain" else self.strain_of(U)
        g = self.generalized_strains(U)
        pieces = []
        for group in (section_terms, other_terms):
            for i, t in group:
                step = Step(strain, self.x, state[i])
                try:
                    out = t.section(g, step)[:2] if isinstance(t, SectionTerm) else t.contribute(U, step)[:2]
                except NonFiniteError as exc:  # a law inside the term named itself
                    return exc
                pieces.append((t, *out))
        return non_finite(self, pieces, self._load_name(load))

    def _element_matrices(self, a):
        """The section terms' element matrices of an assembly ``a`` (None without section terms),
        formed on first use and kept in it: a Newton iterate that converges never needs them."""
        if not a.formed:
            a.Ke = self.section_matrices(a.D) if a.D is not None else None
            a.formed = True
        return a.Ke

    def assemble(self, U, state=None, *, force: float = 0.0):
        """``(R, K, outputs)``: residual (N,), tangent (CSR, N × N) and the terms' outputs at ``U``
        (an imposed strain is read from U at the pulled end; under ``axial="force"`` the axial
        force at x = L is ``force``; ``state`` as from a solve)."""
        load = (U[self.pull] - self.supports.left["u"]) / self.length if self.axial == "strain" else force
        a = self._assemble(U, state, load)
        return a.R, self._global_tangent(a), a.outputs

    def _global_tangent(self, a):
        Ke = self._element_matrices(a)
        K = self.assembly.matrix(Ke) if Ke is not None else 0
        for Kt in a.extra:
            K = K + Kt
        return K

    def term_contribution(self, term, U, state=None):
        """``(R, K)`` of one term alone at ``U`` (for `skcable.fe.check_tangent`): its residual
        (N,) and its tangent (CSR, N × N); ``state`` the term's state (default: its initial one)."""
        bound = self.bound(term)
        strain = self.strain_of(U)
        step = Step(strain, self.x, bound.initial_state(self) if state is None else state)
        if isinstance(bound, SectionTerm):
            S, D, _ = bound.section(self.generalized_strains(U), step)
            return self.section_vector(S), self.assembly.matrix(self.section_matrices(D))
        R, K, _ = bound.contribute(U, step)
        N = self.assembly.N
        return (np.zeros(N) if R is None else R), (sp.csr_matrix((N, N)) if K is None else sp.csr_matrix(K))

    def free_dofs(self):
        """The dofs a solve moves (for `skcable.fe.check_tangent`)."""
        return self.free

    def tangent_check_state(self) -> np.ndarray:
        """A generic, non-trivial state for `skcable.fe.check_tangent` without ``U``: the uniform
        strain 0.002 (the force EA·0.002 under ``axial="force"``, none under ``"none"``) with every
        free dof moved by a random 1e-5·L (a seeded draw: the same state every time)."""
        load = {"strain": 0.002, "force": 0.002 * self.EA, "none": 0.0}[self.axial]
        U = self._start(load)
        U[self.free] += 1e-5 * self.length * np.random.default_rng(1).standard_normal(self.free.size)
        return U

    def _band_of(self, a, lower: bool = False):
        """The free–free tangent of an assembly in the solver's storage (section terms and the
        others); ``lower``: its lower band alone (a symmetric tangent for the Cholesky solve)."""
        if self._system.accept(a.extra):
            self._metric = None  # rebuilt in the new storage
        system = self._system
        Ke = self._element_matrices(a)
        if lower and system.is_banded:
            ab = system.band_lower() if Ke is None else system.lower_of(Ke)  # a new band
            add_sparse = system.add_sparse_lower
        else:
            ab = system.band()
            add_sparse = system.add_sparse
            if Ke is not None:
                system.add_elements(ab, Ke)
        for Kt in a.extra:
            add_sparse(ab, Kt)
        return ab

    def _increment(self, a):
        dU = np.zeros(self.assembly.N)
        dU[self.free] = self._system.solve(self._band_of(a), -a.R[self.free])
        return dU

    def _increment_positive(self, a, mu):
        """``-(K + mu K0)⁻¹ R`` by a Cholesky-like factorisation (raises LinAlgError when not positive
        definite); K0 is the tangent of the straight, unstrained strand (positive definite), built on
        first use."""
        ab = self._band_of(a, lower=True)
        banded = self._system.is_banded  # `_band_of` may have moved it to the sparse storage
        if mu != 0.0 and self._metric is None:
            straight = self._prescribed(np.zeros(self.assembly.N), 0.0)
            self._metric = self._band_of(self._assemble(straight, self.initial_state(), 0.0), lower=True)
        dU = np.zeros(self.assembly.N)
        solve = self._system.solve_positive_lower if banded else self._system.solve_positive
        dU[self.free] = solve(ab, -a.R[self.free], self._metric, mu)
        return dU

    # --- solution ----------------------------------------------------------------
    def _norm(self, a, tol: float) -> float:
        """The largest residual of each group of equations over its force scale, or over its
        round-off floor divided by the tolerance where that is larger (module docstring)."""
        order, starts, free_order, free_starts, force, free_length, with_free = self._group_index
        scales = np.maximum.reduceat(a.size.take(order), starts)
        # the scales are >= 0 (NaN stays NaN); ndarray methods: a Newton calls this per assembly
        forces = float(scales.take(force).max(initial=0.0))
        # the moment groups' floor times the length, at least 1e-300 (max is exact in any order)
        floor = np.maximum(ROUND_OFF * forces / tol * free_length, 1e-300)
        residual = np.maximum.reduceat(np.abs(a.R.take(free_order)), free_starts)
        worst = residual / np.maximum(scales.take(with_free), floor)
        return float(worst.max(initial=0.0)) if math.isfinite(forces) else float("nan")  # NaN stays NaN

    def _potential(self, first) -> bool:
        """Whether every term has a potential (and the assembly ``first`` an energy)."""
        return first.energy is not None and all(t.symmetric and t.potential is not False for t in self._bound)

    def _solver(self, first, options: NewtonOptions) -> str:
        """'minimize', 'newton' or 'semismooth', from the terms' declarations and the options."""
        smooth = all(t.smooth for t in self._bound)
        potential = self._potential(first)
        search = options.line_search
        if search == "energy" and not potential:
            lacking = [repr(t) for t in self._bound if not t.symmetric or t.potential is False] or ["a term"]
            raise InputError(
                "line_search", f"'energy' needs every term to have a potential; {', '.join(lacking)} has none"
            )
        if not smooth:
            return "semismooth"
        return "minimize" if potential and search in ("auto", "energy") else "newton"

    def _load_name(self, load) -> str:
        if self.axial == "strain":
            return f"at strain {load:.6g}"
        return f"at axial force {load:.6g} N" if self.axial == "force" else "without axial load"

    def _newton(self, U, strain, state, options: NewtonOptions, diagnose: bool = True, values=None):
        if U is None:
            U = self._start(strain, values)
        else:
            U = self._prescribed(np.array(U, dtype=float), strain, values)
        name = f"StrandModel: Newton {self._load_name(strain)}"

        first_check, non_finite_seen = self._first, []

        def assemble(x):
            try:
                a = self._assemble(x, state, strain)
            except NonFiniteError as exc:  # a trial is rejected (halved); keep the name for the error
                non_finite_seen.append(exc)
                raise
            if first_check.pending:
                first_check(x, state)
            return a

        first = assemble(U)
        kind = self._solver(first, options)
        try:
            return self._run(kind, assemble, U, first, options, name, strain, state)
        except NonFiniteError:
            raise
        except ConvergenceError as exc:
            # a solve that crawled linearly to its iteration limit: name the terms whose tangent is off
            h = exc.history
            crawled = len(h) > 3 and linear_tail(np.divide(h[1:], h[:-1])) is not None
            linear = kind != "semismooth" and exc.last is not None and crawled
            suspects = self._suspects(exc.last, state) if linear else []
            off = f"; tangents off by check_tangent: {', '.join(suspects)}"
            note = off if suspects else first_check.note()
            if non_finite_seen:
                note += f"; on the way, {non_finite_seen[-1].args[0]}"
            if diagnose:
                modes = self.explain(exc.last if exc.last is not None else U, strain, state)
                note += f"; {modes}" if modes else ""
            if not note:
                raise
            raise _amended(exc, note) from None

    def explain(self, U, load=None, state=None) -> str:
        """What the tangent at ``U`` says about a failed solve: the dofs its null vectors move (a
        missing support) or its negative modes (under compression: a load beyond buckling), ""
        when it is regular and positive definite (`skcable.strand.fe.diagnosis.tangent_modes`).
        ``load``: the solve's strain or force (read from ``U`` under an imposed strain, 0 by
        default otherwise); ``state``: the terms' states."""
        if load is None:
            load = self.strain_of(np.asarray(U, dtype=float)) if self.axial == "strain" else 0.0
        try:
            return tangent_modes(self, self._assemble(np.asarray(U, dtype=float), state, load))
        except (ConvergenceError, np.linalg.LinAlgError, ValueError):
            return ""

    def _run(self, kind, assemble, U, first, options, name, strain, state):
        common = dict(
            norm=lambda a: self._norm(a, options.tol), tol=options.tol, atol=options.atol,
            name=name, state=first, callback=options.callback, rejects=(NonFiniteError,),
            absolute=lambda a: float(np.max(np.abs(a.R[self.free]), initial=0.0)),
        )  # fmt: skip
        if kind == "minimize":  # every term has a potential: minimise it, shifted at folds
            result = self._minimize(assemble, U, options, common)
        elif kind == "newton":
            result = self._newton_steps(
                assemble, U, options, common, max_iter=options.max_iter,
                stagnation_window=options.stagnation_window,
            )  # fmt: skip
        else:
            result = self._semismooth(assemble, U, first, options, common)
        if kind != "semismooth":
            self._warn_if_linear(result, options.tol, state, strain)
        return result

    def _newton_steps(self, assemble, U, options, common, **settings):
        """`skcable.fe.newton` on the model's increments, merit and line-search options."""
        return newton(
            assemble, U, increment=self._increment, merit=self._merit, max_halvings=options.max_halvings,
            line_search=options.line_search != "none", **settings, **common,
        )  # fmt: skip

    def _merit(self, a) -> float:
        """The residual's 2-norm over the free dofs: the smooth line-search merit."""
        return float(np.sqrt(np.sum(a.R[self.free] ** 2)))

    def _minimize(self, assemble, U, options, common, **settings):
        free, free_R = self.free, np.zeros(self.assembly.N)

        def gradient(a):
            free_R[free] = a.R[free]
            return free_R

        settings = {"max_iter": max(options.max_iter, 40), "mu_max": options.mu_max} | settings
        return minimize(
            assemble, U, energy=lambda a: a.energy(), gradient=gradient, solve=self._increment_positive,
            **settings, **common,
        )  # fmt: skip

    def _minimize_deep(self, assemble, U, options, common):
        """`_minimize` with 40 halvings of a step, a shift of up to 1e6 times the elastic tangent
        and four times the iterations: for a step that may reach deep into a bed or past a fold."""
        return self._minimize(
            assemble, U, options, common, halvings=40, mu_max=max(options.mu_max, 1e6),
            max_iter=max(4 * options.max_iter, 100),
        )  # fmt: skip

    def _semismooth(self, assemble, U, first, options, common):
        """Newton for a model with non-smooth terms (contact, tensionless supports, a kinked
        section law): the attempts of `skcable.fe.first_converged`, the first failure raised.

        1. Full steps on the active sets (`_active`, `skcable.fe.semismooth`), which find a stiff
           contact zone node by node, then a monotone line search, which a kinked section law
           (Cardou's) passes in a few steps;
        2. a section law without potential: its fold passed by a potential surrogate (`_pass_fold`);
        3. a non-monotone line search (`NONMONOTONE`), which identifies a contact's active set
           while the residual rises and falls;
        4. every term with a potential (a convex penalty, a bed): the energy minimised, Armijo's
           rule taking the fraction of a step that would push the strand deep into a bed (40
           halvings), the tangent's shift up to 1e6 times the elastic one."""
        search = options.line_search != "none"
        run = functools.partial(
            self._newton_steps, assemble, U, options, common, max_iter=2 * options.max_iter
        )
        potential = self._potential(first)
        attempts = [  # full steps on the active sets (contact, a slipping law), then a monotone line search
            lambda: run(
                stagnation_window=2 * options.stagnation_window,
                full_steps="first",
                active=self._active,
                full_max_iter=max(4 * options.max_iter, 100),
            )  # fmt: skip
        ]
        if not potential and any(hasattr(t, "frozen") for t in self._bound):
            attempts.append(lambda: self._pass_fold(assemble, U, first, options, common))
        if search:
            attempts.append(lambda: run(stagnation_window=2 * options.max_iter, nonmonotone=NONMONOTONE))
        if potential:
            attempts.append(lambda: self._minimize_deep(assemble, U, options, common))
        return first_converged(attempts)

    def _active(self, a) -> tuple:
        """The active sets of the non-smooth terms of an assembly ``a``, as a fingerprint: a
        term's ``"active"`` (or ``"slipping"``) output where it gives one (a contact's pressed
        points, a law's slipping ones), else the bytes of its tangent (a penalty's tangent is a
        function of its active set)."""
        keys: list = []
        for i, t in enumerate(self._bound):
            if t.smooth:
                continue
            out = a.outputs[i] or {}
            mask = out.get("active", out.get("slipping"))
            if mask is not None:
                keys.append(np.packbits(np.asarray(mask, dtype=bool)).tobytes())
            else:
                K = a.tangents.get(i)
                keys.append(None if K is None else sp.csr_matrix(K).data.tobytes())
        return tuple(keys)

    def _pass_fold(self, assemble, U, first, options, common, rounds: int = 3):
        """A model with a section law whose Newton failed: minimise the energy of the terms'
        potential surrogates (`HelicalWires.frozen`), which passes a fold of the path, and polish
        the step with the model's own Newton from there, refreezing at most ``rounds`` times."""
        load, state = first.load, first.state
        for _ in range(rounds):
            start = assemble(U)
            bound = [_surrogate(t, o) for t, o in zip(self._bound, start.outputs, strict=True)]
            if any(t is None for t in bound):
                raise ConvergenceError(f"{common['name']}: a term has no potential surrogate", last=U)
            surrogate = functools.partial(self._assemble, state=state, load=load, bound=bound)
            try:
                U = self._minimize_deep(surrogate, U, options, {**common, "state": None}).x
            except ConvergenceError as exc:
                U = exc.last if exc.last is not None else U
            try:
                result = self._newton_steps(
                    assemble, U, options, {**common, "state": None}, max_iter=2 * options.max_iter,
                    stagnation_window=2 * options.max_iter,
                )  # fmt: skip
            except ConvergenceError as exc:
                U = exc.last if exc.last is not None else U
                continue
            result.shifted = True  # the path passed a fold
            return result
        raise ConvergenceError(f"{common['name']}: no fold passed in {rounds} rounds", last=U)

    def _suspects(self, U, state) -> list[str]:
        """The terms whose tangent `skcable.fe.check_tangent` finds off at ``U``, worst first."""
        from skcable.fe.check import check_tangent

        errors = []
        for i, t in enumerate(self._bound):
            try:
                errors.append((check_tangent(t, self, U, state=state[i]), t))
            except (ConvergenceError, InputError, np.linalg.LinAlgError):
                continue
        return [f"{t!r} ({e:.1e})" for e, t in sorted(errors, key=lambda p: -p[0]) if e > TANGENT_ERROR]

    def _warn_if_linear(self, result, tol, state, strain):
        ratios = result.linear_rate(tol, full_steps=False) if result.iterations > 3 else None
        if ratios is None:
            return
        suspects = self._suspects(result.x, state)
        if not suspects:  # every tangent is right: a nearly singular tangent (a fold) converges linearly
            return
        warnings.warn(
            f"StrandModel: Newton {self._load_name(strain)} converged linearly (ratios "
            f"{', '.join(f'{q:.2f}' for q in ratios)}) where the tangent should give quadratic "
            f"convergence; tangents off by check_tangent: {', '.join(suspects)}",
            SlowConvergenceWarning,
            stacklevel=4,
        )

    def solve(
        self,
        strain: float | None = None,
        guess=None,
        state=None,
        *,
        force: float | None = None,
        passes: int = 6,
        options=None,
        diagnose: bool = True,
        prescribed=None,
        **newton_options,
    ):
        """Equilibrium under the model's axial load: a [`StepResult`][skcable.strand.StepResult].

        ``strain``: the imposed axial strain ``u(L) = u(0) + strain·L`` (``axial="strain"``);
        ``force``: the axial force at x = L (N, ``axial="force"``); neither under
        ``axial="none"``. ``guess``: starting dofs (default: the uniform strain of the load).
        ``state``: the terms' states (default: all stick). Each state is frozen within a Newton
        solve and updated from the converged solution, the step re-solved until the states
        settle (``passes`` at most); a state that cycles, or whose re-solve fails, is left as it
        was and the step is reported as not ``settled``. Newton options: ``options`` (a
        `NewtonOptions`, default the model's) and any of its fields as keywords (``tol``,
        ``atol``, ``max_iter``, ``line_search``, ``callback``, ...). ``diagnose``: on failure,
        read the tangent's singular or negative modes into the message (an eigendecomposition
        of its free block; `capacity_curve` skips it for the steps it cuts back).
        ``prescribed``: ``{"left": {dof: value}, "right": {...}}`` (m, rad), values of dofs the
        supports hold, for this solve in place of theirs (an end turned or moved step by step:
        `skcable.strand.bending_cycles`).

        Raises
        ------
        ConvergenceError
            Newton did not converge (history attached).
        InputError
            A bad option, or a callback that raised (the iteration is named).
        """
        strain = self._load_of(strain, force)
        options = NewtonOptions.of(self.options if options is None else options, **newton_options)
        whole("passes", passes, 0)
        state = self.initial_state() if state is None else tuple(state)
        values = None if prescribed is None else self.prescribed_values(prescribed)
        result = self._newton(guess, strain, state, options, diagnose, values)
        settled, seen, assemblies, shifted = True, [state], result.assemblies, result.shifted
        for _ in range(passes):
            outputs = result.state.outputs
            new = tuple(t.next_state(o, s) for t, o, s in zip(self._bound, outputs, state, strict=True))
            if _same(new, state):
                break
            if any(_same(new, old) for old in seen):
                settled = False
                break
            try:
                retry = self._newton(result.x, strain, new, options, values=values)
            except ConvergenceError:
                settled = False
                break
            assemblies += retry.assemblies
            shifted = shifted or retry.shifted
            seen.append(new)
            state, result = new, retry
        else:
            settled = False
        return self._step_result(strain, result, state, settled, assemblies, shifted)

    def _load_of(self, strain, force) -> float:
        """The load of a solve from `solve`'s ``strain`` and ``force``, checked against ``axial``."""
        wanted = {"strain": "strain", "force": "force", "none": None}[self.axial]
        for name, value in (("strain", strain), ("force", force)):
            if value is not None and name != wanted:
                needs = f"solve({wanted}=...)" if wanted else "solve() with no load"
                raise InputError(name, f"the model's axial load is {self.axial!r}: {needs}")
        if wanted is None:
            return 0.0
        value = strain if wanted == "strain" else force
        if value is None:
            raise InputError(wanted, f"the model's axial load is {self.axial!r}: give solve({wanted}=...)")
        value = real_number(wanted, value)
        if wanted == "strain":
            if not -1.0 < value < 1.0:
                raise InputError(
                    "strain", f"must lie in (-1, 1): {value!r} stretches the strand to nothing or doubles it"
                )
            if abs(value) > self._plausible_strain:  # `_plausible.strand_strain`'s own bound, kept here
                _plausible.strand_strain("strain", value, self._ruptures)
        return value

    def _step_result(self, load, result, state, settled, assemblies, shifted=False):
        a, U = result.state, result.x
        # the wire kinematics of the first term that reports them (HelicalWires, AnnexE, ...)
        owner: Any = None
        wires: Any = None
        for t, o in zip(self._bound, a.outputs, strict=True):
            if o and _KINEMATICS <= o.keys():
                owner, wires = t, o
                break
        if owner is not None and wires["kappa_m"] is None:  # a law that sticks leaves these to the results
            wires = dict(
                wires,
                kappa_m=owner.kappa_m(wires["axial"], derivative=False)[0],
                curvature=owner.principal(a.g),
            )
        shape = (2, *self.x.shape)
        zeros = np.zeros(shape)
        g, S, D = a.g, a.S, a.D
        if wires is None:
            wires = dict(
                curvature=np.array([g[2], g[4]]),
                kappa_m=zeros,
                slipping=zeros.astype(bool),
                strain=np.zeros((0, *self.x.shape)),
                stress=np.zeros((0, *self.x.shape)),
                axial=g[0] + 0.5 * (g[1] ** 2 + g[3] ** 2),
                N=S[0] if S is not None else zeros[0],
            )
        alive = self._alive_wires
        if self.axial == "force":
            force = load
        else:  # the reaction of the imposed strain or of a support holding u(L); 0 where it is free
            force = float(a.R[self.pull]) if self.axial == "strain" or self.pull in self.fixed else 0.0
        return StepResult(
            strain=a.strain,
            force=force,
            x=self.x,
            curvature=wires["curvature"],
            kappa_m=wires["kappa_m"],
            slipping=np.asarray(wires["slipping"]),
            wire_strain=np.where(alive, wires["strain"], 0.0) if len(wires["strain"]) else wires["strain"],
            wire_stress=wires["stress"],
            dofs=U,
            iterations=result.iterations,
            history=result.history,
            axial_strain=wires["axial"],
            axial_force=wires["N"],
            bending=np.array([g[2], g[4]]),
            moment=np.array([S[2], S[4]]) if S is not None else zeros,
            EI_in_use=np.array([D[2, 2], D[4, 4]]) if D is not None else zeros,
            nodal=self.nodal_values(U),
            layout=self.layout,
            state=state,
            settled=settled,
            assemblies=assemblies,
            shifted=shifted,
            outputs=self._outputs(a),
            reactions=self._reactions(a.R),
        )

    def _outputs(self, a) -> dict:
        """The terms' named point and cell data (`skcable.fe.terms`), names made unique."""
        out = {}
        for t, o in zip(self._bound, a.outputs, strict=True):
            for kind in ("point_data", "cell_data"):
                for name, value in ((o or {}).get(kind) or {}).items():
                    key = name if name not in out else f"{type(t).__name__}.{name}"
                    out[key] = (kind, np.asarray(value, dtype=float))
        return out

    def _reactions(self, R) -> dict:
        """The support reactions: ``{"left": {dof: force}, "right": {...}}`` (N, N·m)."""
        return {end: {dof: float(R[i]) for dof, i in at.items()} for end, at in self._reaction_dofs.items()}

    def capacity_curve(self, max_strain=None, n_steps=None, **kwargs):
        """Force–strain curve up to rupture (see [`capacity_curve`][skcable.strand.capacity_curve])."""
        return capacity_curve(self, max_strain, n_steps, **kwargs)


class _Energy:
    """A model's energy (J) at an assembly, its section terms' densities (arrays, or callables
    that compute them) integrated on first use, plus the other terms' part."""

    def __init__(self, densities, dx, rest: float):
        self.densities, self.dx, self.rest = densities, dx, rest
        self.value: float | None = None

    def __call__(self) -> float:
        if self.value is None:
            total = sum(d() if callable(d) else d for d in self.densities)
            self.value = float(np.sum(total * self.dx)) + self.rest
        return self.value


def _amended(exc: ConvergenceError, note: str) -> ConvergenceError:
    """``exc`` with ``note`` added to its message (its history, last iterate and attempts kept)."""
    out = ConvergenceError(exc.args[0] + note)
    out.history, out.last, out.attempts = exc.history, exc.last, exc.attempts
    return out


def _surrogate(term, output):
    """A term's potential surrogate (`HelicalWires.frozen`), the term itself if it has a potential,
    else None."""
    if hasattr(term, "frozen"):
        return term.frozen(output)
    return term if term.symmetric and term.potential is not False else None


def _by_kind(bound) -> tuple[list, list]:
    """The section terms and the others as ``(position in the term list, term)``: the states and
    outputs follow the model's term list."""
    section = [(i, t) for i, t in enumerate(bound) if isinstance(t, SectionTerm)]
    return section, [(i, t) for i, t in enumerate(bound) if not isinstance(t, SectionTerm)]


def _rebuild(cls, strand, length, kwargs):
    return cls(strand, length, **kwargs)


#: The outputs of a term that reports the wires' kinematics (`StrandModel._step_result`).
_KINEMATICS = frozenset({"strain", "curvature", "kappa_m"})


def _same(a, b) -> bool:
    return all(
        (x is None and y is None) or (x is not None and y is not None and np.array_equal(x, y))
        for x, y in zip(a, b, strict=True)
    )
