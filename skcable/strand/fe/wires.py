r"""The strand's built-in physics: the helical wire fibres with a slip law, the wires' own bending
and torsion, and the thesis's sinusoidal damage loads.

Source: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico", Universidad de Chile,
2021, chapters 3–4 (eqs. 4.1–4.8); B. Beltrán, E. De Vico (2015) for the damage loads.
"""

from __future__ import annotations

import copy
from functools import lru_cache

import numpy as np
from scipy.interpolate import PchipInterpolator
from skfem import asm

from skcable.errors import NonFiniteError
from skcable.fe.assembly import contract
from skcable.strand._bending import CardouSection, critical_curvature
from skcable.strand._geometry import lay_rates
from skcable.strand.fe.loads import unit_load
from skcable.strand.fe.slip import SlipLaw, SlipPoints, Stick, slip_law
from skcable.strand.fe.terms import SectionTerm, Term

__all__ = ["HelicalWires", "SinusoidalDamageLoads", "WireBending", "critical_curvature_table"]


@lru_cache(maxsize=32)
def critical_curvature_table(strand, mu: float):
    """κ_m of both principal axes on a strain grid, and its PCHIP interpolant (built once per
    strand and friction, one vectorised call of Cardou's law): ``(grid, table (2, n), spline, slope)``."""
    section = strand.section()
    grid = np.linspace(0.0, 0.999 * min(m.eps_rupture for m in strand.materials), 201)
    table = critical_curvature(section, mu, grid)
    spline = PchipInterpolator(grid, table, axis=1)
    return grid, table, spline, spline.derivative()


#: The rows of the stick section forces S (6) from the reduced ones S4 (ε_a, v″, w″, φ′): N on
#: ε_a, v′ and w′ (the last two then times v′ and w′), the moments and the torque.
_STICK_FORCES = np.array([0, 0, 1, 0, 2, 3])


def _stick_map() -> np.ndarray:
    """Which of `HelicalWires._section_stick`'s 21 rows each entry of the 6 × 6 section tangent
    D is (the rows: that method's comment)."""
    pair = {(int(a), int(b)): p for p, (a, b) in enumerate(zip(*_STICK_PAIRS, strict=True))}
    reduced = {0: 0, 2: 1, 4: 2, 5: 3}
    stick_map = np.empty((6, 6), dtype=np.intp)
    for a in range(6):
        for b in range(6):
            if a in reduced and b in reduced:
                low, high = sorted((reduced[a], reduced[b]))
                stick_map[a, b] = pair[low, high]
            elif {a, b} <= {1, 3}:
                stick_map[a, b] = 18 if a == b == 1 else 19 if a == b == 3 else 20
            else:
                geometric, other = (a, b) if a in (1, 3) else (b, a)
                stick_map[a, b] = (10 if geometric == 1 else 14) + reduced[other]
    stick_map.flags.writeable = False
    return stick_map


#: The 10 pairs a <= b of the 4 reduced strains (ε_a, v″, w″, φ′), in `triu_indices` order.
_STICK_PAIRS = np.triu_indices(4)
_STICK_MAP = _stick_map()


@lru_cache(maxsize=32)
def _cardou_section(section, mu: float) -> CardouSection:
    """Cardou's law of ``section`` at friction ``mu``, formed once per section (the models of one
    strand share it, `skcable.strand.fe.model`) and friction."""
    return CardouSection(section, mu)


class HelicalWires(SectionTerm):
    r"""Every wire a fibre on its helix: material and geometric stiffness, with a slip law.

    A wire's axial strain, with y up and z out of the v-plane (Pino Vidal 2021, eq. 4.5),

    .. math:: \varepsilon_j = \cos^2\alpha_j\left(\varepsilon_a - y_j\kappa_v - z_j\kappa_w\right)
              + R_j\sin\alpha_j\cos\alpha_j\,d_j\,\varphi', \qquad
              \varepsilon_a = u' + \tfrac12(v'^2 + w'^2),

    with the lever (y_j, z_j) split into the net section's centroid c(x) (the
    eccentricity, which never slips) and the offset from it, whose curvature the
    slip law saturates. Section forces :math:`S = \sum_j s_j b_j` with
    :math:`s_j = A_j\sigma(\varepsilon_j)/\cos\alpha_j`, :math:`b_j = \partial\varepsilon_j/\partial g`,
    and the consistent tangent

    .. math:: D = \sum_j \frac{A_j E_t(\varepsilon_j)}{\cos\alpha_j} b_j b_j^T
              + N\,(e_{v'}e_{v'}^T + e_{w'}e_{w'}^T),
              \qquad N = \sum_j s_j\,\partial\varepsilon_j/\partial\varepsilon_a,

    the material stiffness K_L and the geometric stiffness K_G (eq. 4.1), for a kinematic slip
    law (`Stick`, `ElementSlip`: the composite curvature κ_c is the law's). Under a section law
    (`AxisSlip`, any `SlipLaw` with `SlipLaw.moment`) the bending about the centroid is the
    law's moment instead: with :math:`\hat c = (1, v', -c_y, w', -c_z, 0)`,

    .. math:: S = \sum_j s_j\,(\cos^2\alpha_j\,\hat c + R_j\sin\alpha_j\cos\alpha_j d_j\,e_{\varphi'})
              + \sum_k \ell_k\,M_{c,k}(\kappa_k, \varepsilon_a),

    :math:`\ell_k` the lever direction of principal axis k (in the v″, w″ components), the wires'
    strains taken at :math:`\kappa_{c,k} = M_{c,k}/(EI_{stick} - EI_{slip})` (the curvature that
    carries the law's moment elastically), and the tangent its exact derivative (not symmetric:
    the term then has no potential). Every wire
    has its own material's σ and E_t (`Layer.material`: a steel core under aluminium
    layers), evaluated per material group; the centroid c(x) is modulus-weighted,
    :math:`\sum E_j A_j\cos^3\alpha_j (y_j, z_j) / \sum E_j A_j\cos^3\alpha_j`.

    Parameters
    ----------
    slip : str or SlipLaw
        ``"none"``, ``"axis"``, ``"element"`` or a [`SlipLaw`][skcable.strand.SlipLaw].
    mu : float
        Friction coefficient when ``slip`` is a name.
    helical : bool
        Fibres on their helices (the eccentricity of a damaged section turns with
        the lay: mechanism (a)); False: at their positions at x = 0 (a prismatic
        section, the thesis's reading, used with `SinusoidalDamageLoads`).
    """

    def __init__(self, slip="none", mu: float = 0.5, *, helical: bool = True):
        self.slip = slip_law(slip, mu)
        self.helical = bool(helical)

    def __repr__(self) -> str:
        return f"HelicalWires(slip={self.slip!r}, helical={self.helical})"

    def setup(self, model) -> None:
        super().setup(model)
        s, section = model.strand, model.strand_section
        w = section.wires
        self.material = s.material
        self.materials = section.materials
        self.alive = w.intact
        cos, sin = np.cos(w.lay_angle), np.sin(w.lay_angle)
        helical = w.layer > 0
        rate = lay_rates(s, w)
        x = model.x
        fibre_rate = rate if self.helical else 0.0 * rate
        psi = w.psi[:, None, None] + fibre_rate[:, None, None] * x[None]
        self.wire_y = w.radius[:, None, None] * np.sin(psi)
        self.wire_z = w.radius[:, None, None] * np.cos(psi)
        rotation = fibre_rate[helical][0] * x if helical.any() else 0 * x
        modular = self.materials.take("E_e") / s.material.E_e  # exactly 1.0 with one material
        weight = np.where(self.alive, w.area * cos**3 * modular, 0.0)[:, None, None]  # axial stiffness / E
        self.centroid_y = np.sum(weight * self.wire_y, axis=0) / np.sum(weight)
        self.centroid_z = np.sum(weight * self.wire_z, axis=0) / np.sum(weight)
        self.c2 = (cos**2)[:, None, None]
        self.sc = (w.radius * sin * cos * w.direction)[:, None, None]
        self.area_weight = np.where(self.alive, w.area / cos, 0.0)[:, None, None]
        levers = [np.array([-t[1], t[0]]) for t in section.principal_axes]
        lever_angle = np.array([np.arctan2(n[0], n[1]) for n in levers])
        angle = lever_angle[:, None, None] + rotation[None]
        # unit lever directions (y, z) of principal axes 1, 2: (axis, yz, ne, nq)
        self.levers = np.array([np.sin(angle), np.cos(angle)]).transpose(1, 0, 2, 3)
        self.kappa_grid, _, spline, self._slope = critical_curvature_table(s, self.slip.mu)
        self._curvature = self._slope.derivative()
        self._cubics = np.ascontiguousarray(spline.c.transpose(0, 2, 1))  # (power, axis, n - 1)
        self._slopes = np.ascontiguousarray(self._slope.c.transpose(0, 2, 1))
        # the lever offsets from the centroid, and the centroid, per wire: fixed per model
        self._y = self.wire_y - self.centroid_y[None]
        self._z = self.wire_z - self.centroid_z[None]
        self._alive3 = self.alive[:, None, None]
        self._cy, self._cz = self.centroid_y[None], self.centroid_z[None]
        self._neg_c2 = -self.c2
        self._stick_constants(x.shape)
        self._cardou = _cardou_section(section, self.slip.mu)
        self.slip.check(model)
        # the composite curvatures and points of `frozen`
        self._frozen: tuple[np.ndarray, SlipPoints] | None = None
        if not self.slip.kinematic:  # a section law: a friction moment has no potential
            self.symmetric, self.potential, self.smooth = False, False, bool(self.slip.smooth)

    def _stick_constants(self, shape):
        """What a law that sticks everywhere (`Stick`'s composite, no second derivatives) fixes per
        model: ∂κ_c/∂κ of the unit composite and the rows of ∂ε_j/∂g that do not depend on g."""
        kind = type(self.slip)
        self._sticks = (
            self.slip.kinematic
            and kind.composite is Stick.composite
            and kind.second_derivatives is SlipLaw.second_derivatives
        )
        P = contract("kcen,ken,kden->cden", self.levers, np.ones((2, *shape)), self.levers)
        b = self._strain_gradients(np.zeros((6, *shape)), P, np.zeros((2, *shape)), self._y.shape)
        self._b_stick = np.ascontiguousarray(b[[0, 2, 4, 5]])
        # the products C_a C_b of the 10 pairs a <= b of the rows on the strains 0, 2, 4, 5
        upper = _STICK_PAIRS
        self._stick_pairs = np.ascontiguousarray(self._b_stick[upper[0]] * self._b_stick[upper[1]])
        self._no_slip = np.zeros((2, *shape), dtype=bool)
        self._no_slip.flags.writeable = False

    def kappa_m(self, axial_strain, derivative: bool = True):
        """Critical curvatures (2, ...) and, with ``derivative``, their derivative in the axial
        strain (else None): the cubic pieces of the tabulated law's monotone C¹ interpolant
        (PCHIP: a piecewise-linear one has kinks that stall Newton) by Horner's rule, one
        interval lookup for both (``PchipInterpolator``'s values to round-off)."""
        grid = self.kappa_grid
        eps = np.minimum(np.maximum(axial_strain, 0.0), grid[-1])  # `np.clip`, without its wrapper
        # the interval of each point (a NaN strain takes the first: its value stays NaN)
        inside = np.fmin(np.fmax(axial_strain, 0.0), grid[-1])
        i = np.minimum((inside * ((len(grid) - 1) / grid[-1])).astype(np.intp), len(grid) - 2)
        t = eps - grid.take(i, mode="clip")
        c = np.take(self._cubics, i, axis=2, mode="clip")  # (4, 2, ...): each point's cubic, per axis
        value = ((c[0] * t + c[1]) * t + c[2]) * t + c[3]
        if not derivative:
            return value, None
        d = np.take(self._slopes, i, axis=2, mode="clip")  # (3, 2, ...): its derivative
        return value, ((d[0] * t + d[1]) * t + d[2]) * (axial_strain > 0)

    def initial_state(self, model):
        return self.slip.initial_state((2, *model.x.shape))

    def next_state(self, output, state):
        if self._sticks:
            return state
        return self.slip.next_state(output["curvature"], output["points"], state)

    def points(self, axial_strain, kappa_m=None) -> SlipPoints:
        """What the slip law sees at the points of axial strain ``axial_strain`` (`SlipPoints`),
        ``kappa_m`` the kinematic laws' tabulated one."""
        return SlipPoints(self._cardou, axial_strain, self.kappa_grid[-1], kappa_m)

    def _curved_slip(self, D, s, g, axial, levers, k_principal, k_m, dk_m, d_km, state):
        """Stress times the second derivatives of the wire strains through the slip law:
        ``Σ_j s_j ∂²ε_j/∂g²`` beyond the membrane part, for a law curved in κ or κ_m (and κ_m″)."""
        second = self.slip.second_derivatives(k_principal, k_m, state)
        if second is None and not np.any(d_km):
            return
        d2k_m = self._curvature(np.clip(axial, 0.0, self.kappa_grid[-1])) * (axial > 0)
        # M_k = Σ_j s_j ∂ε_j/∂κ_c,k: minus the composite moment about axis k
        rho = contract("kcen,cjen->kjen", levers, np.array([self._y, self._z]))
        M = -contract("jen,kjen->ken", s * self.c2, rho)
        zero = np.zeros_like(axial)
        E = np.array([np.ones_like(axial), g[1], zero, g[3], zero, zero])  # ∂ε_a/∂g
        coef_ee = M * d_km * d2k_m
        if second is not None:
            f_kk, f_km, f_mm = second
            A = np.zeros((2, 6, *axial.shape))  # ∂κ_k/∂g
            A[:, 2], A[:, 4] = levers[:, 0], levers[:, 1]
            coef_ee = coef_ee + M * f_mm * dk_m**2
            D += contract("ken,kaen,kben->aben", M * f_kk, A, A)
            cross = contract("ken,kaen,ben->aben", M * f_km * dk_m, A, E)
            D += cross + cross.transpose(1, 0, 2, 3)
        D += contract("en,aen,ben->aben", coef_ee.sum(axis=0), E, E)

    def _slip_derivatives(self, kappa, k_principal, k_m, dk_m, state):
        """``(κ_c, ∂κ_c/∂κ (2, 2, ...), ∂κ_c/∂ε_a, ∂κ_c/∂κ_m)`` in (y, z) through a kinematic slip law."""
        levers = self.levers
        clamped, d_clamp, d_km = self.slip.composite(k_principal, k_m, state)
        kappa_c = contract("kcen,ken->cen", levers, clamped)  # bending about the centroid seen by the wires
        P = contract("kcen,ken,kden->cden", levers, d_clamp, levers)  # dκc/dκ (2x2)
        q = contract("kcen,ken->cen", levers, d_km * dk_m)  # dκc/dε_a
        return kappa_c, P, q, d_km

    def _strains(self, g, axial, kappa, kappa_c):
        """The wires' strains ``ε_j`` (nw, ne, nq): the axial strain less the bending of the
        eccentric centroid (``kappa``) and of the wires about it (``kappa_c``, as the slip law
        leaves it), along each wire (``cos² α_j``), plus the twist's share (``g[5]``)."""
        eccentric = self._cy * kappa[0][None] + self._cz * kappa[1][None]
        return (
            self.c2 * (axial[None] - eccentric - self._y * kappa_c[0][None] - self._z * kappa_c[1][None])
            + self.sc * g[5][None]
        )

    def _strain_gradients(self, g, P, q, shape):
        """``b = ∂ε_j/∂g`` (6, nw, ne, nq), its first row ∂ε_j/∂ε_a, filled row by row in one array."""
        y, z, c2, cy, cz = self._y, self._z, self.c2, self._cy, self._cz
        b = np.empty((6, *shape))
        np.multiply(c2, 1.0 - y * q[0][None] - z * q[1][None], out=b[0])  # ∂ε_j/∂ε_a
        b[2] = self._neg_c2 * (cy + y * P[0, 0][None] + z * P[1, 0][None])
        b[4] = self._neg_c2 * (cz + y * P[0, 1][None] + z * P[1, 1][None])
        b[5] = self.sc
        np.multiply(b[0], g[1][None], out=b[1])
        np.multiply(b[0], g[3][None], out=b[3])
        return b

    def section(self, g, step):
        axial = g[0] + 0.5 * (g[1] ** 2 + g[3] ** 2)
        if self._sticks:  # the principal curvatures are for the results alone (`principal`)
            return self._section_stick(g, axial)
        kappa = g[2:5:2]  # (v'', w'') components along y, z
        levers = self.levers
        k_principal = contract("kcen,cen->ken", levers, kappa)
        if not self.slip.kinematic:
            if self._frozen is not None:
                return self._section_frozen(g, step, axial, kappa, k_principal)
            return self._section_law(g, step, axial, kappa, k_principal)
        k_m, dk_m = self.kappa_m(axial)
        state = step.state
        points = self.points(axial, k_m)
        kappa_c, P, q, d_km = self._slip_derivatives(kappa, k_principal, k_m, dk_m, state)
        strain = self._strains(g, axial, kappa, kappa_c)
        stress, tangent = self.materials.stress_and_tangent(strain)
        stress = stress * self._alive3  # a broken wire carries nothing (its area weight is zero too)
        b = self._strain_gradients(g, P, q, strain.shape)
        s = self.area_weight * stress
        k = self.area_weight * tangent
        S, D, N = _fibres(s, k, b, contract("jen,jen->en", s, b[0]))
        self._curved_slip(D, s, g, axial, levers, k_principal, k_m, dk_m, d_km, state)
        output = dict(
            strain=strain,
            stress=stress,
            curvature=k_principal,
            kappa_m=k_m,
            slipping=self.slip.slipping(k_principal, points, state),
            axial=axial,
            N=N,
            energy=lambda: np.sum(self.area_weight * self.materials.energy(strain), axis=0),  # on demand
            points=points,
        )
        return S, D, output

    def principal(self, g) -> np.ndarray:
        """The curvatures about the principal axes of the turning section (2, ne, nq) (1/m) at
        generalized strains ``g``."""
        return contract("kcen,cen->ken", self.levers, g[2:5:2])

    def _section_stick(self, g, axial):
        """`section` of a law that sticks everywhere: the strains are ``Σ_a C_a g̃_a`` over the
        rows of ∂ε_j/∂g fixed per model (``C``: on ε_a, v″, w″, φ′), the forces and tangent their
        4 × 4 sums, and the rows of v′ and w′ the axial row times v′ and w′ (∂ε_a/∂v′ = v′)."""
        C = self._b_stick  # (4, nw, ne, nq)
        reduced = np.array([axial, g[2], g[4], g[5]])
        strain = contract("ajen,aen->jen", C, reduced)
        stress, tangent = self.materials.stress_and_tangent(strain)
        stress = stress * self._alive3  # a broken wire carries nothing (its area weight is zero too)
        s = self.area_weight * stress
        S4 = contract("jen,ajen->aen", s, C)
        N = S4[0]
        v1, w1 = g[1], g[3]
        S = S4[_STICK_FORCES]  # rows N, N, S_v″, N, S_w″, S_φ′ (a copy), then the rows of v′ and w′:
        S[1] *= v1  # N v′
        S[3] *= w1  # N w′
        # D from 21 rows in one gather (`_stick_map`): rows 0–9 the 10 distinct entries of the
        # symmetric 4 × 4 Σ_j k_j C_a C_b (the products fixed per model) on the rows and columns
        # of ε_a, v″, w″, φ′; those of v′ and w′ the axial row (pairs (0, 0)–(0, 3)) times v′ and
        # w′, with N on the diagonal (the geometric stiffness K_G)
        rows = np.empty((21, *axial.shape))
        np.einsum(
            "pjen,jen->pen", self._stick_pairs, self.area_weight * tangent, out=rows[:10], optimize=False
        )
        np.multiply(rows[:4], v1, out=rows[10:14])
        np.multiply(rows[:4], w1, out=rows[14:18])
        np.multiply(rows[10], v1, out=rows[18])  # D_00 v′ v′ + N
        rows[18] += N
        np.multiply(rows[14], w1, out=rows[19])  # D_00 w′ w′ + N
        rows[19] += N
        np.multiply(rows[10], w1, out=rows[20])  # D_00 v′ w′
        D = rows[_STICK_MAP]
        output = dict(
            strain=strain,
            stress=stress,
            curvature=None,  # Stick: for the results only, `principal` and `kappa_m` at the converged state
            kappa_m=None,
            slipping=self._no_slip,
            axial=axial,
            N=N,
            energy=lambda: np.sum(self.area_weight * self.materials.energy(strain), axis=0),  # on demand
        )
        return S, D, output

    def _section_law(self, g, step, axial, kappa, k_principal):
        """`section` under a section law (the class docstring): the law's moment about the
        centroid, the wires' strains at the composite curvature that carries it."""
        levers, state = self.levers, step.state
        points = self.points(axial)
        M, dM_dk, dM_de = self._law_moment(k_principal, points, state)
        EI, d_EI = points.EI_composite, points.d_EI_composite
        composite = EI > 0.0  # an axis without composite bending: the wires have no lever about it
        safe = np.where(composite, EI, 1.0)
        k_c = np.where(composite, M / safe, k_principal)
        kappa_c = contract("kcen,ken->cen", levers, k_c)
        P = contract("kcen,ken,kden->cden", levers, np.where(composite, dM_dk / safe, 1.0), levers)
        q = contract("kcen,ken->cen", levers, np.where(composite, (dM_de - k_c * d_EI) / safe, 0.0))
        strain = self._strains(g, axial, kappa, kappa_c)
        stress, tangent = self.materials.stress_and_tangent(strain)
        stress = stress * self._alive3
        s, k = self.area_weight * stress, self.area_weight * tangent
        b = self._strain_gradients(g, P, q, strain.shape)  # ∂ε_j/∂g through the law
        N = contract("jen,jen->en", s, self.c2)
        n_b = contract("jen,ajen->aen", k * self.c2, b)  # ∂N/∂g
        t_b = contract("jen,ajen->aen", k * self.sc, b)  # ∂(Σ s_j R_j sin α cos α d_j)/∂g
        zero = np.zeros_like(axial)
        c_hat = np.array([np.ones_like(axial), g[1], -self.centroid_y, g[3], -self.centroid_z, zero])
        S = c_hat * N
        S[5] = contract("jen,jen->en", s, self.sc)
        D = contract("aen,ben->aben", c_hat, n_b)
        D[5] += t_b
        D[1, 1] += N  # the geometric stiffness K_G
        D[3, 3] += N
        self._add_moment(S, D, M, dM_dk)
        strain_row = contract("kcen,ken->cen", levers, dM_de)
        E = np.array([np.ones_like(axial), g[1], zero, g[3], zero, zero])  # ∂ε_a/∂g
        D[2] += strain_row[0] * E
        D[4] += strain_row[1] * E
        output = dict(
            strain=strain,
            stress=stress,
            curvature=k_principal,
            kappa_m=self.slip.onset(points),
            slipping=self.slip.slipping(k_principal, points, state),
            axial=axial,
            N=N,
            points=points,
            composite=k_c,
        )
        return S, D, output

    def _add_moment(self, S, D, M, dM_dk) -> None:
        """The law's moments ``M`` (2, ...) about the principal axes, in the (v″, w″) components,
        added to ``S``, and their bending tangent ``dM_dk`` to ``D``."""
        levers = self.levers
        moment = contract("kcen,ken->cen", levers, M)
        S[2] += moment[0]
        S[4] += moment[1]
        bending = contract("kcen,ken,kden->cden", levers, dM_dk, levers)
        D[2, 2] += bending[0, 0]
        D[2, 4] += bending[0, 1]
        D[4, 2] += bending[1, 0]
        D[4, 4] += bending[1, 1]

    def _law_moment(self, kappa, points, state):
        """The slip law's ``(M_c, ∂M_c/∂κ, ∂M_c/∂ε_a)``, checked finite (`NonFiniteError` names the law)."""
        out = self.slip.moment(kappa, points, state)
        bad = ~(np.isfinite(out[0]) & np.isfinite(out[1]) & np.isfinite(out[2]))
        if bad.any():
            x = np.broadcast_to(self._model.x, bad.shape[1:])[np.any(bad, axis=0)]
            raise NonFiniteError(
                f"the slip law {self.slip!r} gave a moment or tangent that is not finite at "
                f"{int(bad.sum())} of {bad.size} (axis, point) pairs, x = {x.min():.4g} to {x.max():.4g} m",
                repr(self.slip),
            )
        return out

    def frozen(self, output):
        """A potential surrogate of this term under a section law, or None (a kinematic law has
        its potential; a section law without `SlipLaw.energy` has none): the wires' strains at
        the composite curvatures of ``output`` (an assembly's), frozen, and the law's moment at
        its points there, frozen, with the law's potential ψ (``∂ψ/∂κ = M_c``). Its residual is
        this term's at that assembly's state; it has the energy Σ ∫ A σ dε / cos α + Σ ψ and a
        symmetric tangent, so a model whose path folds (a softening wire law) can minimise it
        past the fold and polish the step with the section law from there."""
        if self.slip.kinematic or type(self.slip).energy is SlipLaw.energy:
            return None
        out = copy.copy(self)
        out._frozen = (output["composite"], output["points"])
        out.symmetric, out.potential = True, None
        return out

    def _section_frozen(self, g, step, axial, kappa, k_principal):
        """`section` of the surrogate of `frozen`."""
        assert self._frozen is not None  # a surrogate of `frozen`
        k_c, points = self._frozen
        levers, state = self.levers, step.state
        kappa_c = contract("kcen,ken->cen", levers, k_c)
        strain = self._strains(g, axial, kappa, kappa_c)
        stress, tangent, density = self.materials.stress_tangent_energy(strain)
        stress = stress * self._alive3
        s, k = self.area_weight * stress, self.area_weight * tangent
        frozen = np.zeros((2, 2, *axial.shape)), np.zeros((2, *axial.shape))  # κ_c depends on nothing
        b = self._strain_gradients(g, *frozen, strain.shape)
        S, D, N = _fibres(s, k, b, contract("jen,jen->en", s, self.c2))
        M, dM_dk, _ = self._law_moment(k_principal, points, state)
        psi = self.slip.energy(k_principal, points, state)
        self._add_moment(S, D, M, dM_dk)
        energy = np.sum(self.area_weight * density, axis=0) + np.sum(psi, axis=0)
        output = dict(
            strain=strain, stress=stress, curvature=k_principal, kappa_m=self.slip.onset(points),
            slipping=self.slip.slipping(k_principal, points, state), axial=axial, N=N, points=points,
            composite=k_c, energy=energy,
        )  # fmt: skip
        return S, D, output


def _fibres(s, k, b, N):
    """``(S, D, N)`` of fibres of forces ``s`` and tangents ``k`` (nw, ne, nq) along the strain
    gradients ``b`` (6, nw, ne, nq), with the geometric stiffness ``N`` on v′ and w′ (K_G)."""
    S = contract("jen,ajen->aen", s, b)
    D = contract("ajen,jen,bjen->aben", b, k, b)
    D[1, 1] += N
    D[3, 3] += N
    return S, D, N


class WireBending(SectionTerm):
    """The wires' own bending and torsion: ``EI_w = Σ E I_w cos α``, ``GJ_w = Σ G J_w cos α`` over
    the intact wires (the core straight), on v″, w″ and φ′ (Pino Vidal 2021, eqs. 3.11–3.12);
    E and G of each wire's own material."""

    def setup(self, model):
        super().setup(model)
        s, w = model.strand, model.strand_section.wires
        cos = np.cos(w.lay_angle)
        materials = model.strand_section.materials
        E_ratio = materials.take("E_e") / s.material.E_e  # exactly 1.0 with one material
        G_ratio = materials.take("G") / s.material.G
        self.EI = s.material.E_e * float(np.sum(np.where(w.intact, w.inertia * cos * E_ratio, 0.0)))
        self.GJ = s.material.G * float(np.sum(np.where(w.intact, 2 * w.inertia * cos * G_ratio, 0.0)))
        ne, nq = model.x.shape
        self._D = np.zeros((6, 6, ne, nq))
        self._D[2, 2] = self._D[4, 4] = self.EI
        self._D[5, 5] = self.GJ
        self._D.flags.writeable = False  # shared by every assembly
        self._stiffness = np.array([0.0, 0.0, self.EI, 0.0, self.EI, self.GJ])[:, None, None]

    def section(self, g, step):
        S = self._stiffness * g
        return S, self._D, {"energy": lambda: 0.5 * np.sum(S * g, axis=0)}  # the energy on demand


class SinusoidalDamageLoads(Term):
    r"""The thesis's reading of the damage: the loads a broken wire's missing pressure leaves.

    A helical wire of tension F presses on the core with :math:`F\sin^2\alpha/(R\cos\alpha)`
    per unit strand length; intact wires balance, so each broken wire b leaves a resultant
    pointing at it and turning with the lay (Beltrán & De Vico 2015; Pino Vidal 2021 §2.4):

    .. math:: q_y + i\,q_z = \sum_b \frac{F_b\sin^2\alpha_b}{R_b\cos\alpha_b}
              \left(\sin\psi_b(x) + i\cos\psi_b(x)\right),
              \qquad F_b = A_b\,\sigma(\cos^2\alpha_b\,\varepsilon),

    with ε the imposed strain of the step (a dead load within the step). Use with
    ``HelicalWires(helical=False)``; a damage term (left out of the D_r twin).
    """

    damage = True

    def setup(self, model):
        s, w = model.strand, model.strand_section.wires
        self.material = s.material
        self.broken = np.flatnonzero(~w.intact & (w.layer > 0))
        self.materials = model.strand_section.materials.subset(self.broken)
        rate = lay_rates(s, w)
        rows = []
        for j in self.broken:
            psi = w.psi[j] + rate[j] * model.x
            alpha = w.lay_angle[j]
            q = np.sin(alpha) ** 2 / (w.radius[j] * np.cos(alpha))
            vec = np.zeros(model.assembly.N)
            parts = model.split(vec)
            parts["v"][:] = asm(unit_load, model.bases["v"], q=q * np.sin(psi))
            parts["w"][:] = asm(unit_load, model.bases["w"], q=q * np.cos(psi))
            rows.append(vec)
        self.unit = np.array(rows).reshape(len(self.broken), model.assembly.N)  # per newton of wire force
        self.area = w.area[self.broken]
        self.cos = np.cos(w.lay_angle[self.broken])

    def loads(self, strain: float) -> np.ndarray:
        """The load vector (N) at the imposed axial strain."""
        return (self.area * self.materials.stress(self.cos**2 * strain)) @ self.unit

    def contribute(self, U, step):
        return -self.loads(step.strain), None, {}

    def energy(self, U, step):  # a dead load within the step
        return -float(self.loads(step.strain) @ U)
