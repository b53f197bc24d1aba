r"""The strand beam-cable finite element: a mesh, its scikit-fem bases and a list of terms.

The strand axis is x ∈ [0, L]; the fields are the displacements of the core
centre line: axial u (P2), transverse v, w (``ElementLineHermite``: value and
slope per node) and twist φ (P2), on bases that share one quadrature. The
physics is a list of [terms][skcable.strand.Term]; by default the helical wire
fibres with a slip law and the wires' own bending and torsion (and, for the
thesis's reading of the damage, its sinusoidal loads). The strand is clamped
at both ends and pulled at x = L: ``u(L) = ε L`` (Pino Vidal 2021, §4.1,
"fixed – fixed sliding").

Pipeline: strand → mesh and bases → terms → `skcable.fe.newton` per step
→ [`StepResult`][skcable.strand.StepResult] → [`CapacityCurve`][skcable.strand.CapacityCurve]
→ writers and plots.

Source: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico",
Universidad de Chile, 2021, chapter 4.
"""

from __future__ import annotations

import numpy as np
from skfem import Basis, ElementLineHermite, ElementLineP2, MeshLine

from skcable import _plausible
from skcable._checks import nonnegative, positive
from skcable.errors import ConvergenceError, InputError
from skcable.fe import StrainAssembly, minimize, newton
from skcable.strand.capacity import StepResult, StrandLayout, capacity_curve
from skcable.strand.fe.slip import SlipLaw, slip_law
from skcable.strand.fe.terms import (
    FIELDS,
    STRAINS,
    HelicalWires,
    SectionTerm,
    SinusoidalDamageLoads,
    Step,
    WireBending,
    check_terms,
)

__all__ = ["StrandModel", "DAMAGE_LOADS", "default_physics"]

#: how a broken wire loads the strand: the net section's helical eccentricity
#: (mechanism (a)) or the thesis's reading, a prismatic section under the
#: sinusoidal biaxial loads of Beltrán & De Vico (mechanism (b))
DAMAGE_LOADS = ("eccentricity", "sinusoidal")


def default_physics(slip="none", mu: float = 0.5, damage_load: str = "eccentricity") -> list:
    """The built-in terms: helical wires with a slip law, the wires' own bending and torsion,
    and (``damage_load="sinusoidal"``) the sinusoidal damage loads on a prismatic section."""
    if damage_load not in DAMAGE_LOADS:
        raise InputError("damage_load", f"must be one of {DAMAGE_LOADS}, got {damage_load!r}")
    sinusoidal = damage_load == "sinusoidal"
    terms = [HelicalWires(slip, mu, helical=not sinusoidal), WireBending()]
    return terms + [SinusoidalDamageLoads()] if sinusoidal else terms


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
        Mesh grading toward both clamps (boundary layer ~ sqrt(EI/N)):
        ``x = L (s - g sin(2 pi s) / (2 pi))``, 0 uniform.
    slip : {"none", "axis", "element"} or SlipLaw
        Stick, Cardou's law per quadrature point and principal axis, the thesis's
        element rule, or any [`SlipLaw`][skcable.strand.SlipLaw].
    mu : float
        Friction coefficient when ``slip`` is a name.
    damage_load : {"eccentricity", "sinusoidal"}
        How broken wires load the strand (include the mechanism once).
        ``"eccentricity"``: every fibre on its helix, so the net section's centroid
        turns with the lay and the axial force acts on a helical eccentricity.
        ``"sinusoidal"``: the thesis's reading (Pino Vidal 2021 §2.4; Beltrán & De
        Vico 2015): a prismatic section under the biaxial sinusoidal loads of the
        broken wires ([`SinusoidalDamageLoads`][skcable.strand.SinusoidalDamageLoads]).
    terms : sequence of Term
        Terms added to the built-in physics (foundations, loads, springs, an
        analyst's own).
    physics : sequence of Term, optional
        Replaces the built-in physics (``slip``, ``mu`` and ``damage_load`` are then unused).
    twist : {"clamped", "free"}
        The twist at the pulled end x = L: clamped (the thesis's "fixed – fixed sliding",
        default) or free to turn.

    Attributes
    ----------
    terms : list of Term
        Every term of the model (unbound, as given): the physics, then ``terms``.
    bases : dict of str to skfem.Basis
        ``u``, ``v``, ``w``, ``phi``.
    assembly : skcable.fe.StrainAssembly
        Basis values, weights and sparsity pattern, computed once.
    x : ndarray (n_elements, n_quad)
        Quadrature points (m).
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
    ):
        self.strand, self.length = strand, float(positive("length", length))
        if twist not in ("clamped", "free"):
            raise InputError("twist", f"must be 'clamped' or 'free', got {twist!r}")
        self.twist = twist
        if not 0 <= grading < 1:
            raise InputError("grading", f"must lie in [0, 1), got {grading!r}")
        nonnegative("mu", mu)
        if physics is None:
            physics = default_physics(slip, mu, damage_load)
            self.damage_load = damage_load
        else:
            self.damage_load = "custom"
        self.terms = check_terms(physics) + check_terms(terms)
        laws = [t.slip for t in self.terms if isinstance(getattr(t, "slip", None), SlipLaw)]
        self.slip = laws[0] if laws else slip_law("none", mu)
        if self.slip.name != "none" and len(strand.layers) != 1:
            raise InputError("slip", "slip models need a single helical layer (1x7-type strands)")
        self.mesh = self._mesh(n_elements, mesh, grading)
        ub = Basis(self.mesh, ElementLineP2(), intorder=6)
        vb = ub.with_element(ElementLineHermite())
        self.bases = {"u": ub, "v": vb, "w": vb, "phi": ub}
        self.assembly = StrainAssembly(self.bases, STRAINS)
        self.offsets = self.assembly.offsets
        self.x = np.asarray(ub.global_coordinates())[0]  # (ne, nq)
        self._boundary()
        self.EA = strand.section().EA
        self._bound = [t.bind(self) for t in self.terms]
        # (position in the model's term list, bound term): the states and outputs follow that list
        self._section_terms = [(i, t) for i, t in enumerate(self._bound) if isinstance(t, SectionTerm)]
        self._other_terms = [(i, t) for i, t in enumerate(self._bound) if not isinstance(t, SectionTerm)]
        self._band = self.assembly.banded(self.free)
        self._dx = self.bases["u"].dx
        self._metric = None  # the elastic tangent of the straight strand, band storage (on first use)
        self.layout = self._layout()

    def __repr__(self) -> str:
        s = self.strand
        return (
            f"StrandModel({s!r}, length={self.length:g} m, {self.mesh.t.shape[1]} elements, "
            f"{self.assembly.N} dofs, slip={self.slip!r}, terms=[{', '.join(map(repr, self.terms))}])"
        )

    # --- set-up --------------------------------------------------------------
    def _mesh(self, n_elements, mesh, grading):
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
            if n_elements is None:
                n = max(64, int(np.ceil(16 * self.length / lay)))
            elif isinstance(n_elements, (int, np.integer)) and not isinstance(n_elements, bool):
                n = int(n_elements)
            else:
                raise InputError("n_elements", f"must be a whole number, got {n_elements!r}")
            if n < 2:
                raise InputError("n_elements", f"must be at least 2, got {n_elements!r}")
            s = np.linspace(0.0, 1.0, n + 1)
            nodes = self.length * (s - grading * np.sin(2 * np.pi * s) / (2 * np.pi))
        L = self.length
        return MeshLine(nodes).with_boundaries(
            {"left": lambda x: np.isclose(x[0], 0.0), "right": lambda x: np.isclose(x[0], L)}
        )

    def _boundary(self):
        fixed = []
        for i, name in enumerate(FIELDS):
            basis, offset = self.bases[name], self.offsets[i]
            left, right = basis.get_dofs("left").all(), basis.get_dofs("right").all()
            fixed += [offset + left] + ([] if name == "phi" and self.twist == "free" else [offset + right])
            if name == "u":
                self.pull = int(offset + right[0])
        self.fixed = np.unique(np.concatenate(fixed))
        self.free = np.setdiff1d(np.arange(self.assembly.N), self.fixed)

    def _layout(self) -> StrandLayout:
        w = self.strand.wires()
        helical = w.layer > 0
        lay_length = np.ones_like(w.radius)
        lay_length[helical] = self.strand.lay_lengths[w.layer[helical] - 1]
        return StrandLayout(
            nodes=self.mesh.p[0].copy(),
            elements=self.mesh.t.copy(),
            x=self.x,
            dx=self.bases["u"].dx,
            wire_psi=w.psi,
            wire_rate=np.where(helical, w.direction * 2 * np.pi / lay_length, 0.0),
            wire_radius=w.radius,
            wire_layer=w.layer,
            wire_broken=~w.intact,
            wire_size=np.sqrt(w.area / np.pi),
            slip=self.slip.name,
            eps_rupture=min(m.eps_rupture for m in self.strand.materials),
            eps_y1=min(m.eps_y1 for m in self.strand.materials),
            wire_eps_rupture=self.strand.wire_materials().take("eps_rupture"),
            wire_eps_y1=self.strand.wire_materials().take("eps_y1"),
        )

    def twin(self, strand=None) -> StrandModel:
        """The same model (mesh, terms, settings) for another strand, every damage term left out:
        by default the intact strand, the reference of the damage index D_r."""
        from dataclasses import replace

        strand = replace(self.strand, broken=frozenset()) if strand is None else strand
        kept = [t for t in self.terms if not t.damage]
        return type(self)(strand, self.length, mesh=self.mesh, physics=kept, twist=self.twist)

    # --- fields ----------------------------------------------------------------
    def split(self, U):
        """Views of ``U`` per field: dict of ``u``, ``v``, ``w``, ``phi``."""
        return {name: U[self.offsets[i] : self.offsets[i + 1]] for i, name in enumerate(FIELDS)}

    def nodal_values(self, U):
        """Values of u, v, w, φ at the mesh nodes (their vertex dofs): dict of (n_nodes,) arrays."""
        parts = self.split(U)
        return {name: parts[name][self.bases[name].nodal_dofs[0]] for name in FIELDS}

    def generalized_strains(self, U):
        """g = (u′, v′, v″, w′, w″, φ′) at the quadrature points: (6, ne, nq)."""
        return self.assembly.interpolate(U)

    def uniform(self, strain):
        """Dof vector of the uniform axial strain ``u = strain·x`` (the straight start)."""
        U = np.zeros(self.assembly.N)
        U[: self.bases["u"].N] = strain * self.bases["u"].doflocs[0]
        return U

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

    # --- assembly ----------------------------------------------------------------
    def _assemble(self, U, state, strain):
        """Residual, element matrices of the section terms, other tangents, and the terms' outputs."""
        state = self.initial_state() if state is None else state
        g = self.assembly.interpolate(U)
        S = D = None
        outputs = [None] * len(self._bound)
        for i, t in self._section_terms:
            St, Dt, outputs[i] = t.section(g, Step(strain, self.x, state[i]))
            S, D = (St, Dt.copy()) if S is None else (S + St, D + Dt)
        R = self.assembly.vector(S) if S is not None else np.zeros(self.assembly.N)
        Ke = self.assembly.element_matrices(D) if D is not None else None
        densities = [outputs[i].get("energy") for i, _ in self._section_terms]
        energy = None if any(e is None for e in densities) else float(np.sum(sum(densities) * self._dx))
        extra = []
        for i, t in self._other_terms:
            step = Step(strain, self.x, state[i])
            Rt, Kt, outputs[i] = t.contribute(U, step)
            if Rt is not None:
                R = R + Rt
            if Kt is not None:
                extra.append(Kt)
            if energy is not None:
                e = t.energy(U, step)
                energy = None if e is None else energy + e
        return dict(R=R, Ke=Ke, extra=extra, outputs=outputs, g=g, S=S, D=D, energy=energy)

    def assemble(self, U, state=None):
        """``(R, K, outputs)``: residual (N,), tangent (CSR, N × N) and the terms' outputs at ``U``
        (the imposed strain is read from U at the pulled end; ``state`` as from a solve)."""
        a = self._assemble(U, state, U[self.pull] / self.length)
        K = self.assembly.matrix(element_matrices=a["Ke"]) if a["Ke"] is not None else 0
        for Kt in a["extra"]:
            K = K + Kt
        return a["R"], K, a["outputs"]

    def _band_of(self, a) -> np.ndarray:
        """The free–free tangent of an assembly in band storage (section terms and the others)."""
        ab = self._band.band()
        if a["Ke"] is not None:
            self._band.add_elements(ab, a["Ke"])
        for Kt in a["extra"]:
            self._band.add_sparse(ab, Kt)
        return ab

    def _increment(self, a):
        dU = np.zeros(self.assembly.N)
        dU[self.free] = self._band.solve(self._band_of(a), -a["R"][self.free])
        return dU

    # --- solution ----------------------------------------------------------------
    def _increment_positive(self, a, mu):
        """``-(K + mu K0)⁻¹ R`` by banded Cholesky (raises LinAlgError when not positive definite);
        K0 is the tangent of the straight, unstrained strand (positive definite), built on first use."""
        if mu != 0.0 and self._metric is None:
            self._metric = self._band_of(self._assemble(np.zeros(self.assembly.N), self.initial_state(), 0.0))
        dU = np.zeros(self.assembly.N)
        dU[self.free] = self._band.solve_positive(self._band_of(a), -a["R"][self.free], self._metric, mu)
        return dU

    def _newton(self, U, strain, state, tol, max_iter):
        U = self.uniform(strain) if U is None else np.array(U, dtype=float)
        U[self.fixed] = 0.0
        U[self.pull] = strain * self.length
        scale = max(self.EA * max(abs(strain), 1e-6), 1.0)
        free = self.free
        name = f"StrandModel: Newton at strain {strain:.6g}"

        def norm(a):
            return float(np.max(np.abs(a["R"][free]))) / scale

        def assemble(x):
            return self._assemble(x, state, strain)

        first = assemble(U)
        if first["energy"] is not None:  # every term has a potential: minimise it, shifted at folds
            free_R = np.zeros(self.assembly.N)

            def gradient(a):
                free_R[free] = a["R"][free]
                return free_R

            return minimize(
                assemble,
                U,
                norm=norm,
                energy=lambda a: a["energy"],
                gradient=gradient,
                solve=self._increment_positive,
                tol=tol,
                max_iter=max(max_iter, 40),
                name=name,
                state=first,
            )
        return newton(
            assemble,
            U,
            norm=norm,
            merit=lambda a: float(np.sqrt(np.sum(a["R"][free] ** 2))) / scale,  # smooth, for the line search
            increment=self._increment,
            tol=tol,
            max_iter=max_iter,
            name=name,
            state=first,
        )

    def solve(self, strain: float, guess=None, state=None, *, passes: int = 6, tol=1e-9, max_iter=25):
        """Equilibrium at the imposed axial strain ``u(L) = strain·L``: a
        [`StepResult`][skcable.strand.StepResult].

        ``guess``: starting dofs (default: the uniform strain). ``state``: the terms'
        states (default: all stick). Each state is frozen within a Newton solve and
        updated from the converged solution, the step re-solved until the states settle
        (``passes`` at most); a state that cycles, or whose re-solve fails, is left as it
        was and the step is reported as not ``settled``.

        Raises
        ------
        ConvergenceError
            Newton did not converge (history attached).
        """
        strain = float(strain)
        if not np.isfinite(strain):
            raise InputError("strain", f"must be finite, got {strain!r}")
        _plausible.strand_strain("strain", strain, [m.eps_rupture for m in self.strand.materials])
        state = self.initial_state() if state is None else tuple(state)
        result = self._newton(guess, strain, state, tol, max_iter)
        settled, seen, assemblies, shifted = True, [state], result.assemblies, result.shifted
        for _ in range(passes):
            outputs = result.state["outputs"]
            new = tuple(t.next_state(o, s) for t, o, s in zip(self._bound, outputs, state, strict=True))
            if _same(new, state):
                break
            if any(_same(new, old) for old in seen):
                settled = False
                break
            try:
                retry = self._newton(result.x, strain, new, tol, max_iter)
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

    def _step_result(self, strain, result, state, settled, assemblies, shifted=False):
        a, U = result.state, result.x
        # the wire kinematics of the first term that reports them (HelicalWires, AnnexE, ...)
        wires = next((o for o in a["outputs"] if o and {"strain", "curvature", "kappa_m"} <= set(o)), None)
        shape = (2, *self.x.shape)
        zeros = np.zeros(shape)
        g, S, D = a["g"], a["S"], a["D"]
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
        alive = ~self.layout.wire_broken[:, None, None]
        return StepResult(
            strain=strain,
            force=float(a["R"][self.pull]),
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
        )

    def capacity_curve(self, max_strain=None, n_steps=None, **kwargs):
        """Force–strain curve up to rupture (see [`capacity_curve`][skcable.strand.capacity_curve])."""
        return capacity_curve(self, max_strain, n_steps, **kwargs)


def _same(a, b) -> bool:
    return all(
        (x is None and y is None) or (x is not None and y is not None and np.array_equal(x, y))
        for x, y in zip(a, b, strict=True)
    )
