r"""The strand beam-cable finite element on scikit-fem (seed 003 chapter 4).

The strand axis is x ∈ [0, L]; the fields are the displacements of the core
centre line: axial u (P2), transverse v, w (``ElementLineHermite``: value and
slope per node) and twist φ (P2), on bases that share one quadrature.
Every wire j is a fibre at its helical position

.. math:: y_j = R_j \sin\psi_j(x), \quad z_j = R_j\cos\psi_j(x), \quad
          \psi_j(x) = \psi_{j0} + d_j\,2\pi x / p_j

(lay length p, lay direction d), so the eccentricity of a damaged section
rotates with the lay exactly (REFERENCE.md §3, mechanism (a), included once).
With ``damage_load="sinusoidal"`` the fibres stay at ψ_j0 (a prismatic
section) and the broken wires act instead through the sinusoidal biaxial
loads of Beltrán & De Vico (mechanism (b), the thesis's reading):

.. math:: q_y + i\,q_z = \sum_{b\ \mathrm{broken}} \frac{F_b\sin^2\alpha_b}{R_b\cos\alpha_b}
          \left(\sin\psi_b(x) + i\cos\psi_b(x)\right), \qquad
          F_b = A_b\,\sigma(\cos^2\alpha_b\,\varepsilon).

A wire's axial strain, signs as in seed 003 eq. 4.5 with y up and z out of the
v-plane,

.. math:: \varepsilon_j = \cos^2\alpha_j\left(\varepsilon_a - y_j\kappa_v - z_j\kappa_w\right)
          + R_j\sin\alpha_j\cos\alpha_j\,d_j\,\varphi', \qquad
          \varepsilon_a = u' + \tfrac12(v'^2 + w'^2),

with (κ_v, κ_w) = (v″, w″). The lever (y_j, z_j) splits into the net
section's centroid c(x) (axial-stiffness weighted, rotating with the lay)
and the offset from it: the resultant of the wire forces always acts at the
centroid (the eccentric moment N·e is statics, whatever the slip state),
and slip saturates only the bending about the centroid. Virtual work per unit
strand length (wire length per strand length ``1/cos α``):

.. math:: \delta W = \int_0^L \Big[\sum_j \frac{A_j\sigma(\varepsilon_j)}{\cos\alpha_j}\,\delta\varepsilon_j
          + EI_w (v''\delta v'' + w''\delta w'') + GJ_w\,\varphi'\delta\varphi'\Big]dx,

``EI_w = Σ E I_w cos α`` and ``GJ_w = Σ G J_w cos α`` the wires' own bending and
torsion (core straight). With the generalized strains g = (u′, v′, v″, w′,
w″, φ′), ``b_j = ∂ε_j/∂g`` gives the section forces ``S = Σ s_j b_j`` and
the consistent tangent

.. math:: D = \sum_j \frac{A_j E_t(\varepsilon_j)}{\cos\alpha_j} b_j b_j^T
          \;+\; N\,(e_{v'}e_{v'}^T + e_{w'}e_{w'}^T),

the first part the material (elastic) stiffness ``K_L``, the second the
geometric stiffness ``K_G`` with ``N = Σ s_j ∂ε_j/∂ε_a`` (seed 003 eq. 4.1).

Slip (Cardou's bilinear law, :class:`~skcable.strand.BendingLaw`):
``slip="axis"`` clamps each principal-axis component of the composite
curvature at ±κ_m(ε_a) at every quadrature point (the rest is carried by
the wires' own bending, so ``M = M_rf + EI_min κ`` beyond κ_m);
``slip="element"`` is the thesis's rule: an element whose curvature exceeds
κ_m about either principal axis anywhere loses the composite bending
altogether (wires bend about their own axes, seed 003 eq. 4.8).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from scipy.interpolate import PchipInterpolator
from skfem import Basis, BilinearForm, ElementLineHermite, ElementLineP2, LinearForm, MeshLine, asm, solve

from skcable._checks import nonnegative, positive
from skcable.errors import ConvergenceError, InputError

__all__ = [
    "StrandModel",
    "StepResult",
    "material_block",
    "geometric_block",
    "section_residual",
    "distributed_load",
]

FIELDS = ("u", "v", "w", "phi")
#: how a broken wire loads the strand: the net section's helical eccentricity
#: (mechanism (a)) or the thesis's reading, a prismatic section under the
#: sinusoidal biaxial loads of Beltrán & De Vico (mechanism (b))
DAMAGE_LOADS = ("eccentricity", "sinusoidal")
#: generalized strains: (field, derivative order)
STRAINS = (("u", 1), ("v", 1), ("v", 2), ("w", 1), ("w", 2), ("phi", 1))


def _derivative(f, order):
    return f.grad[0] if order == 1 else f.hess[0][0]


def section_residual(name: str) -> LinearForm:
    """``∫ Σ_a S_a d_a(δ)`` over the generalized strains of field ``name``;
    the section forces are passed as ``S0 … S5``."""
    entries = [(a, order) for a, (f, order) in enumerate(STRAINS) if f == name]

    @LinearForm
    def form(v, w):
        return sum(w[f"S{a}"] * _derivative(v, order) for a, order in entries)

    form.__doc__ = f"Internal virtual work of field {name!r}: section forces times its strain variations."
    return form


def material_block(test: str, trial: str) -> BilinearForm:
    """``∫ Σ_ab D_ab d_b(Δ) d_a(δ)``: material (elastic) tangent block; ``D`` as ``Dab``."""
    rows = [(a, order) for a, (f, order) in enumerate(STRAINS) if f == test]
    cols = [(b, order) for b, (f, order) in enumerate(STRAINS) if f == trial]

    @BilinearForm
    def form(u, v, w):
        return sum(
            w[f"D{a}{b}"] * _derivative(u, ob) * _derivative(v, oa) for a, oa in rows for b, ob in cols
        )

    return form


@LinearForm
def distributed_load(v, w):
    """``∫ q δv dx``: a load per unit length ``q`` (N/m, passed as ``q``) on a field."""
    return w.q * v


@BilinearForm
def _geometric_form(u, v, w):
    return w.N * u.grad[0] * v.grad[0]


def geometric_block(test: str, trial: str) -> BilinearForm | None:
    """``∫ N Δ' δ'`` for (v, v) and (w, w): the geometric stiffness; None elsewhere."""
    return _geometric_form if test == trial and test in ("v", "w") else None


_RESIDUAL = {name: section_residual(name) for name in FIELDS}
_MATERIAL = {(a, b): material_block(a, b) for a in FIELDS for b in FIELDS}


@dataclass
class StepResult:
    """State of the strand at one load step.

    Attributes
    ----------
    strain, force : float
        Imposed axial strain and the axial reaction at x = L (N).
    x : ndarray (n_elements, n_quad)
        Quadrature points (m).
    curvature : ndarray (2, n_elements, n_quad)
        Curvature about principal axes 1 and 2 of the local (rotating) section (1/m).
    kappa_m : ndarray (2, n_elements, n_quad)
        Critical curvatures there.
    slipping : ndarray (2, n_elements, n_quad) of bool
        Quadrature points in slip, per principal axis (``slip="axis"``), or
        the element state broadcast (``slip="element"``).
    wire_strain, wire_stress : ndarray (n_wires, n_elements, n_quad)
        Broken wires carry zero.
    iterations : int
    history : list of float
    """

    strain: float
    force: float
    x: np.ndarray
    curvature: np.ndarray
    kappa_m: np.ndarray
    slipping: np.ndarray
    wire_strain: np.ndarray
    wire_stress: np.ndarray
    dofs: np.ndarray
    iterations: int
    history: list = field(default_factory=list)

    @property
    def slip_fraction(self) -> float:
        """Fraction of the strand length in slip (about either axis)."""
        return float(np.mean(np.any(self.slipping, axis=0)))


class StrandModel:
    """Finite-element model of a strand pulled along its axis.

    Parameters
    ----------
    strand : Strand
        Geometry, damage, material.
    length : float
        Specimen length (m); seed 003 does not state it: 1 m by default.
    n_elements : int, optional
        Number of elements; default: 16 per lay length, at least 64.
    mesh : MeshLine or array, optional
        Node abscissae from 0 to length (overrides ``n_elements``).
    grading : float in [0, 1)
        Mesh grading toward both clamps (boundary layer ~ sqrt(EI/N)):
        ``x = L (s - g sin(2 pi s) / (2 pi))``, 0 uniform.
    slip : {"none", "axis", "element"}
        Stick model, Cardou's law per quadrature point and principal axis, or
        the thesis's element rule.
    mu : float
        Friction coefficient of the bending law.
    damage_load : {"eccentricity", "sinusoidal"}
        How broken wires load the strand (REFERENCE.md §3; include the mechanism
        once). ``"eccentricity"``: every fibre on its helix, so the net section's
        centroid turns with the lay and the axial force acts on a helical
        eccentricity (mechanism (a), the default). ``"sinusoidal"``: the thesis's
        reading (seed 003 §2.4, Fig. 2.15; Beltrán & De Vico 2015): a prismatic
        section (fibres at their positions at x = 0) under the biaxial sinusoidal
        loads that the broken wires' missing radial pressure leaves on the core,
        see :meth:`damage_loads` (mechanism (b)). Wire results of this reading
        belong to the prismatic fibres; VTK output still draws them on their helices.

    Attributes
    ----------
    external : list of (field, LinearForm, dict)
        Terms an analyst adds: each is assembled on the field's basis (with
        the dict as extra ``w`` fields) and subtracted from the internal
        force, e.g. ``("v", LinearForm(lambda v, w: q * v), {})`` for a
        transverse load per unit length.
    """

    def __init__(
        self,
        strand,
        length: float = 1.0,
        *,
        n_elements=None,
        mesh=None,
        grading: float = 0.6,
        slip: str = "none",
        mu: float = 0.5,
        damage_load: str = "eccentricity",
    ):
        if slip not in ("none", "axis", "element"):
            raise InputError("slip", f"must be 'none', 'axis' or 'element', got {slip!r}")
        if damage_load not in DAMAGE_LOADS:
            raise InputError("damage_load", f"must be one of {DAMAGE_LOADS}, got {damage_load!r}")
        self.damage_load = damage_load
        self.strand, self.length, self.slip = strand, float(positive("length", length)), slip
        self.mu = float(nonnegative("mu", mu))
        if not 0 <= grading < 1:
            raise InputError("grading", f"must lie in [0, 1), got {grading!r}")
        if slip != "none" and len(strand.layers) != 1:
            raise InputError("slip", "slip models need a single helical layer (1x7-type strands)")
        self.mesh = self._mesh(n_elements, mesh, grading)
        self.ub = Basis(self.mesh, ElementLineP2(), intorder=6)
        self.vb = self.ub.with_element(ElementLineHermite())
        self.bases = {"u": self.ub, "v": self.vb, "w": self.vb, "phi": self.ub}
        self.offsets = np.cumsum([0] + [self.bases[f].N for f in FIELDS])
        self._wires()
        self._boundary()
        self._critical_curvature_table()
        self.external = []

    # --- set-up --------------------------------------------------------------
    def _mesh(self, n_elements, mesh, grading):
        if mesh is not None:
            nodes = np.asarray(mesh.p[0] if isinstance(mesh, MeshLine) else mesh, dtype=float)
            if not (np.isclose(nodes.min(), 0) and np.isclose(nodes.max(), self.length)):
                raise InputError("mesh", f"must run from 0 to length = {self.length}")
            nodes = np.sort(nodes)
        else:
            lay = float(np.min(self.strand.lay_lengths))
            n = int(n_elements) if n_elements is not None else max(64, int(np.ceil(16 * self.length / lay)))
            if n < 2:
                raise InputError("n_elements", f"must be at least 2, got {n_elements!r}")
            s = np.linspace(0.0, 1.0, n + 1)
            nodes = self.length * (s - grading * np.sin(2 * np.pi * s) / (2 * np.pi))
        L = self.length
        return MeshLine(nodes).with_boundaries(
            {"left": lambda x: np.isclose(x[0], 0.0), "right": lambda x: np.isclose(x[0], L)}
        )

    def _wires(self):
        s, w = self.strand, self.strand.wires()
        self.wire_data = w
        alive = w.intact
        cos, sin = np.cos(w.lay_angle), np.sin(w.lay_angle)
        lay_length = np.zeros_like(w.radius)
        helical = w.layer > 0
        lay_length[helical] = s.lay_lengths[w.layer[helical] - 1]
        self.x_quad = np.asarray(self.ub.global_coordinates())[0]  # (ne, nq)
        rate = np.where(helical, w.direction * 2 * np.pi / np.where(helical, lay_length, 1.0), 0.0)
        self.wire_rate = rate  # dψ_j/dx (rad/m), 0 for the core
        # fibre positions: on the helix, or prismatic (the lay enters through the loads)
        fibre_rate = rate if self.damage_load == "eccentricity" else 0.0 * rate
        psi = w.psi[:, None, None] + fibre_rate[:, None, None] * self.x_quad[None]
        self.wire_y = w.radius[:, None, None] * np.sin(psi)
        self.wire_z = w.radius[:, None, None] * np.cos(psi)
        self.rotation = (
            fibre_rate[helical][0] * self.x_quad if helical.any() else 0 * self.x_quad
        )  # section rotation
        weight = np.where(alive, w.area * cos**3, 0.0)[:, None, None]  # axial stiffness / E
        self.centroid_y = np.sum(weight * self.wire_y, axis=0) / np.sum(weight)
        self.centroid_z = np.sum(weight * self.wire_z, axis=0) / np.sum(weight)
        self.c2 = (cos**2)[:, None, None]
        self.sc = (w.radius * sin * cos * w.direction)[:, None, None]
        self.area_weight = np.where(alive, w.area / cos, 0.0)[:, None, None]  # A / cos(alpha)
        material = s.material
        self.EI_own = material.E_e * float(np.sum(np.where(alive, w.inertia * cos, 0.0)))
        self.GJ_own = material.G * float(np.sum(np.where(alive, 2 * w.inertia * cos, 0.0)))
        self.alive = alive
        self.broken_helical = np.flatnonzero(~alive & (w.layer > 0))
        self._lay_load_unit = self._lay_load_per_unit_force() if self.damage_load == "sinusoidal" else None

    def _lay_load_per_unit_force(self):
        """Load vectors (n_broken, n_dofs) of the sinusoidal loads per newton of wire force.

        A helical wire of tension F presses on the core with
        ``F sin²α / (R cos α)`` per unit strand length, toward the axis; intact
        wires balance, so a broken wire leaves a resultant on the core of that
        magnitude pointing at it and turning with the lay (Beltrán & De Vico
        2015; seed 003 §2.4, Fig. 2.15): ``q_y = q sin ψ_b(x)``, ``q_z = q cos ψ_b(x)``.
        """
        w, x, rows = self.wire_data, self.x_quad, []
        for j in self.broken_helical:
            psi = w.psi[j] + self.wire_rate[j] * x
            alpha = w.lay_angle[j]
            q = np.sin(alpha) ** 2 / (w.radius[j] * np.cos(alpha))
            vec = np.zeros(self.offsets[-1])
            parts = self.split(vec)  # views into vec
            parts["v"][:] = asm(distributed_load, self.vb, q=q * np.sin(psi))
            parts["w"][:] = asm(distributed_load, self.vb, q=q * np.cos(psi))
            rows.append(vec)
        return np.array(rows).reshape(len(self.broken_helical), self.offsets[-1])

    def damage_loads(self, strain: float) -> np.ndarray:
        """External load vector of ``damage_load="sinusoidal"`` at the strand's axial strain.

        Each broken wire would carry ``F = A σ(cos²α ε)``, evaluated at the imposed
        (mean) axial strain of the step: a dead load within each step. Zero for the
        ``"eccentricity"`` reading, where the fibres' helical positions carry the effect.
        """
        if self._lay_load_unit is None:
            return np.zeros(self.offsets[-1])
        w, broken = self.wire_data, self.broken_helical
        cos = np.cos(w.lay_angle[broken])
        force = w.area[broken] * self.strand.material.stress(cos**2 * strain)
        return force @ self._lay_load_unit

    def _boundary(self):
        D, self.pull = [], None
        for name in FIELDS:
            basis, offset = self.bases[name], self.offsets[FIELDS.index(name)]
            left, right = basis.get_dofs("left").all(), basis.get_dofs("right").all()
            D += [offset + left, offset + right]
            if name == "u":
                self.pull = offset + right[0]
                self.anchor = offset + left[0]
        self.fixed = np.unique(np.concatenate(D))
        self.free = np.setdiff1d(np.arange(self.offsets[-1]), self.fixed)

    def _critical_curvature_table(self):
        """κ_m per principal axis on a strain grid (Cardou's law, this section)."""
        from skcable.strand._bending import BendingLaw

        section = self.strand.section()
        self.section = section
        levers = [np.array([-t[1], t[0]]) for t in section.principal_axes]  # (y, z) of each lever direction
        self.lever_angle = np.array([np.arctan2(n[0], n[1]) for n in levers])  # from +z toward +y
        top = self.strand.material.eps_rupture
        self.kappa_grid = np.linspace(0.0, 0.999 * top, 201)
        table = [
            BendingLaw(section, mu=self.mu, axial_strain=e).kappa_m if e > 0 else np.zeros(2)
            for e in self.kappa_grid
        ]
        self.kappa_table = np.array(table).T  # (2, n)
        self._kappa_spline = PchipInterpolator(self.kappa_grid, self.kappa_table, axis=1)
        self._kappa_slope = self._kappa_spline.derivative()

    def kappa_m(self, axial_strain):
        """Critical curvatures (2, ...) and their derivative w.r.t. the axial strain.

        A monotone C¹ interpolant (PCHIP) of the tabulated law: a piecewise-linear
        one has a derivative that jumps at every grid point, and Newton then
        stalls on a kink (seen at 384 elements and 160 steps).
        """
        eps = np.clip(axial_strain, 0.0, self.kappa_grid[-1])
        return self._kappa_spline(eps), self._kappa_slope(eps) * (axial_strain > 0)

    # --- fields and section ----------------------------------------------------
    def split(self, U):
        return {name: U[self.offsets[i] : self.offsets[i + 1]] for i, name in enumerate(FIELDS)}

    def nodal_values(self, U):
        """Values of u, v, w, φ at the mesh nodes (their vertex dofs): dict of (n_nodes,) arrays."""
        parts = self.split(U)
        return {name: parts[name][self.bases[name].nodal_dofs[0]] for name in FIELDS}

    def generalized_strains(self, U):
        parts = self.split(U)
        fu, fv, fw, fp = (self.bases[n].interpolate(parts[n]) for n in FIELDS)
        return np.array([fu.grad[0], fv.grad[0], fv.hess[0][0], fw.grad[0], fw.hess[0][0], fp.grad[0]])

    def levers(self):
        """Unit lever directions (y, z) of principal axes 1, 2 at the quadrature points: (2, 2, ne, nq)."""
        angle = self.lever_angle[:, None, None] + self.rotation[None]
        return np.array([np.sin(angle), np.cos(angle)]).transpose(1, 0, 2, 3)

    def section_state(self, U, slip_mask=None):
        """Wire strains, stresses, section forces S (6, ne, nq) and tangents D_mat (6, 6, ne, nq), N."""
        g = self.generalized_strains(U)
        axial = g[0] + 0.5 * (g[1] ** 2 + g[3] ** 2)
        kappa = np.array([g[2], g[4]])  # (v'', w'') components along y, z
        levers = self.levers()  # (axis, yz, ne, nq)
        k_principal = np.einsum("kcen,cen->ken", levers, kappa)
        k_m, dk_m = self.kappa_m(axial)
        if self.slip == "none":
            slipping = np.zeros(k_principal.shape, dtype=bool)
        elif slip_mask is None:  # no state given: the current curvatures decide
            slipping = self.slip_state(dict(curvature=k_principal, kappa_m=k_m), broadcast=True)
        elif self.slip == "element":
            slipping = np.broadcast_to(slip_mask[None, :, None], k_principal.shape)
        else:
            slipping = slip_mask
        if self.slip == "element":
            clamped = np.where(slipping, 0.0, k_principal)
            d_clamp = np.where(slipping, 0.0, 1.0)
            d_eps = np.zeros_like(k_principal)
        else:
            clamped = np.where(slipping, np.sign(k_principal) * k_m, k_principal)
            d_clamp = np.where(slipping, 0.0, 1.0)
            d_eps = np.where(slipping, np.sign(k_principal) * dk_m, 0.0)
        kappa_c = np.einsum("kcen,ken->cen", levers, clamped)  # bending about the centroid seen by the wires
        # dκc/dκ (2x2) and dκc/dε_a (2)
        P = np.einsum("kcen,ken,kden->cden", levers, d_clamp, levers)
        q = np.einsum("kcen,ken->cen", levers, d_eps)
        # lever = centroid offset (the eccentricity: never slips) + offset from the centroid (saturates)
        cy, cz = self.centroid_y[None], self.centroid_z[None]
        y, z, c2, sc = self.wire_y - cy, self.wire_z - cz, self.c2, self.sc
        eccentric = cy * kappa[0][None] + cz * kappa[1][None]
        strain = (
            c2 * (axial[None] - eccentric - y * kappa_c[0][None] - z * kappa_c[1][None]) + sc * g[5][None]
        )
        material = self.strand.material
        stress = np.where(self.alive[:, None, None], material.stress(strain), 0.0)
        tangent = np.where(self.alive[:, None, None], material.tangent(strain), 0.0)
        d_axial = c2 * (1.0 - y * q[0][None] - z * q[1][None])  # ∂ε_j/∂ε_a
        b = np.array(
            [
                d_axial,
                d_axial * g[1][None],
                -c2 * (cy + y * P[0, 0][None] + z * P[1, 0][None]),
                d_axial * g[3][None],
                -c2 * (cz + y * P[0, 1][None] + z * P[1, 1][None]),
                np.broadcast_to(sc, strain.shape),
            ]
        )  # (6, nw, ne, nq)
        s = self.area_weight * stress
        k = self.area_weight * tangent
        S = np.einsum("jen,ajen->aen", s, b)
        D = np.einsum("ajen,jen,bjen->aben", b, k, b)
        S[2] += self.EI_own * g[2]
        S[4] += self.EI_own * g[4]
        S[5] += self.GJ_own * g[5]
        D[2, 2] += self.EI_own
        D[4, 4] += self.EI_own
        D[5, 5] += self.GJ_own
        N = np.einsum("jen,jen->en", s, d_axial)
        return dict(
            S=S,
            D=D,
            N=N,
            strain=strain,
            stress=stress,
            curvature=k_principal,
            kappa_m=k_m,
            slipping=slipping,
            axial=axial,
        )

    def slip_state(self, state, *, broadcast=False):
        """Slip state implied by a section state's curvatures: per element (``slip="element"``:
        any quadrature point and either axis beyond κ_m) or per point and axis (``"axis"``)."""
        beyond = np.abs(state["curvature"]) > state["kappa_m"]
        if self.slip == "element":
            per_element = np.any(beyond, axis=(0, 2))
            return np.broadcast_to(per_element[None, :, None], beyond.shape) if broadcast else per_element
        return beyond

    def initial_slip_state(self):
        """All stick."""
        if self.slip == "element":
            return np.zeros(self.mesh.t.shape[1], dtype=bool)
        return np.zeros((2, *self.x_quad.shape), dtype=bool)

    # --- assembly ----------------------------------------------------------------
    def assemble(self, U, slip_mask=None, *, parts=("material", "geometric")):
        """Residual (internal force vector) and tangent ``K = K_L + K_G`` (or the parts asked)."""
        state = self.section_state(U, slip_mask)
        S, D, N = state["S"], state["D"], state["N"]
        R = np.concatenate(
            [asm(_RESIDUAL[n], self.bases[n], **{f"S{a}": S[a] for a in range(6)}) for n in FIELDS]
        )
        if self._lay_load_unit is not None:
            R -= self.damage_loads(U[self.pull] / self.length)
        for name, form, kwargs in self.external:  # terms an analyst adds (loads)
            self.split(R)[name][:] -= asm(form, self.bases[name], **kwargs)
        Dkw = {f"D{a}{b}": D[a, b] for a in range(6) for b in range(6)}
        blocks = []
        for test in FIELDS:
            row = []
            for trial in FIELDS:
                block = None
                if "material" in parts:
                    block = asm(_MATERIAL[(test, trial)], self.bases[trial], self.bases[test], **Dkw)
                geometric = geometric_block(test, trial)
                if "geometric" in parts and geometric is not None:
                    G = asm(geometric, self.bases[trial], self.bases[test], N=N)
                    block = G if block is None else block + G
                row.append(
                    block if block is not None else sp.csr_matrix((self.bases[test].N, self.bases[trial].N))
                )
            blocks.append(row)
        K = sp.bmat(blocks, format="csr")
        return R, K, state

    # --- solution ----------------------------------------------------------------
    def uniform(self, strain):
        """Dof vector of the uniform axial strain ``u = strain·x`` (the straight start)."""
        U = np.zeros(self.offsets[-1])
        U[: self.ub.N] = strain * self.ub.doflocs[0]
        return U

    def solve_step(self, U, strain, slip_mask=None, *, tol=1e-9, max_iter=25):
        """Newton at imposed axial strain (u(L) = strain·L) from ``U`` (None: uniform strain).

        Returns ``(U, state, history, R)``; raises ConvergenceError with the history.
        """
        U = self.uniform(strain) if U is None else U.copy()
        U[self.fixed] = 0.0
        U[self.pull] = strain * self.length
        scale = max(self.section.EA * max(abs(strain), 1e-6), 1.0)
        history = []
        R, K, state = self.assemble(U, slip_mask)
        for _ in range(max_iter):
            norm = float(np.max(np.abs(R[self.free]))) / scale
            history.append(norm)
            if norm < tol:
                return U, state, history, R
            dU = solve(K[self.free][:, self.free], -R[self.free])
            step = 1.0
            for _ in range(12):  # backtracking on the residual; the accepted assembly is reused
                trial = U.copy()
                trial[self.free] += step * dU
                R_trial, K_trial, state_trial = self.assemble(trial, slip_mask)
                if np.max(np.abs(R_trial[self.free])) / scale < (1 - 1e-4 * step) * norm:
                    break
                step *= 0.5
            U, R, K, state = trial, R_trial, K_trial, state_trial
        raise ConvergenceError(f"StrandModel: Newton did not converge at strain {strain:.6g}", history)

    def capacity_curve(self, max_strain=None, n_steps=None, **kwargs):
        """Force–strain curve up to rupture (see :func:`skcable.strand.capacity_curve`)."""
        from skcable.strand._capacity import capacity_curve

        return capacity_curve(self, max_strain, n_steps, **kwargs)
