r"""The strand element of S. Pino Vidal's thesis read as a section law (annex E).

S. Pino Vidal, *Rigidez a flexión en cables: análisis numérico*, Universidad
de Chile, 2021, prints the 12×12 elastic and geometric stiffness matrices
``K_E`` and ``K_G`` of its beam-cable element term by term (annex E: E.1 stick
state, E.2 slip state), for linear axial displacement and twist and cubic
Hermite transverse displacements (eqs. 3.22–3.31). Every printed term is a
section coefficient times one shape-function integral, so both matrices are
``K = ∫ Bᵀ D B dx`` with a 6×6 section matrix ``D``. This module returns those
section matrices, with the typos of the annex fixed (listed in
``docs/annex_e.md``), in the generalized strains of the strand model

.. math:: g = (u',\ v',\ v'',\ w',\ w'',\ \varphi'),

u axial, v along y, w along z, φ the twist. **Sign convention** (the model's,
physical): a wire at (y, z) of the section strains by

.. math:: \varepsilon = \cos^2\alpha\,(u' - y\,v'' - z\,w'') + R\sin\alpha\cos\alpha\,d\,\varphi',

d = ±1 the lay direction. The annex's terms, read in its own degrees of freedom
(``θ_z = v'``, ``θ_y = w'``: the same Hermite functions for v and w, eqs. 3.23–3.24),
correspond to ``+y v'' + z w''`` instead: its v and w point the other way
(a half-turn of the section about x, which keeps the twist). Hence

.. math:: D = T\,D^\mathrm{annex}\,T, \qquad T = \mathrm{diag}(1, -1, -1, -1, -1, 1).

With c = cos α, s = d sin α, A the net area, E the elastic modulus, (y_c, z_c)
the net centroid and r_c = √(y_c² + z_c²), the elastic section matrix is

.. math::
    D_E = E\begin{pmatrix}
      A c^3 & 0 & -A c^3 y_c & 0 & -A c^3 z_c & A r_c c^2 s \\
      0 & 0 & 0 & 0 & 0 & 0 \\
      \cdot & 0 & I_{zz} c + A c^3 y_c^2 & 0 & I_{yz} c + A c^3 y_c z_c & -\beta A y_c r_c c^2 s \\
      0 & 0 & 0 & 0 & 0 & 0 \\
      \cdot & 0 & \cdot & 0 & I_{yy} c + A c^3 z_c^2 & -\beta A z_c r_c c^2 s \\
      \cdot & 0 & \cdot & 0 & \cdot & \big(\tfrac{I_{zz} + I_{yy}}{c^2} + A r_c^2\big) c s^2
    \end{pmatrix}

(symmetric; β = 1 stick, β = 0 slip), and the geometric one per unit axial force F

.. math::
    D_G = \begin{pmatrix}
      c^3 & 0 & -c^3 y_c & 0 & -c^3 z_c & r_c c^2 s \\
      0 & c & 0 & 0 & 0 & -(z_c c + r_c c^2 s) \\
      \cdot & 0 & \tfrac{I_{zz}}{A} c + c^3 y_c^2 & 0 & \tfrac{I_{yz}}{A} c + c^3 y_c z_c & 0 \\
      0 & 0 & 0 & c & 0 & y_c c - r_c c^2 s \\
      \cdot & 0 & \cdot & 0 & \tfrac{I_{yy}}{A} c + c^3 z_c^2 & 0 \\
      \cdot & \cdot & 0 & \cdot & 0 & \big(r_c^2 c + \tfrac{I_{zz} + I_{yy}}{A c}\big)(1 + s^2)
    \end{pmatrix}.

Slip (annex E.2, eqs. 4.8, 4.24–4.25): the second moments become the wires' own,
``I → I_min``, in bending and torsion of both matrices, and the bending–torsion
couplings of ``D_E`` vanish (β = 0); the eccentric terms (A y_c, A z_c) stay.
The annex has no GJ (twist is resisted only through the helical wires' axial
strain) and no v″–w″ term: the latter vanishes for the thesis's sections,
symmetric about z (y_c = 0, I_yz = 0); it is the term that makes the matrices
of a turned section the turned matrices (`annex_e_section`).

Section properties (annex E's reading): one lay angle for the whole section,
``A E cos³α`` with A the *net* area (the core counted like a laid wire), so

.. math:: I_{zz} = c^3 \sum_j A_j (y_j - y_c)^2 + c \sum_j I_{w,j}, \quad
          I_{yy} = c^3 \sum_j A_j (z_j - z_c)^2 + c \sum_j I_{w,j}, \quad
          I_{yz} = c^3 \sum_j A_j (y_j - y_c)(z_j - z_c), \quad
          I_\mathrm{min} = c \sum_j I_{w,j}

over the intact wires (``I_w = π r⁴/4``). These differ from
`Section` (core straight) by the core's factors only
(0.3 % on I_zz of steel 9.5, damage 2).

Internal force (eq. 4.1 and annex E): ``(K_E + K_G(F)) U``, no membrane
stretch; as a section law ``S = (D_E + F D_G) g`` (`annex_e_forces`),
F the element's current axial force ``∫ σ_tt dA`` (eq. 4.26), from the axial
strain through the elastic part: ``F = (D_E g)_0``.
"""

from __future__ import annotations

from math import pi

import numpy as np

from skcable._checks import positive, real
from skcable.errors import InputError
from skcable.strand.fe.terms import SectionTerm, Step

__all__ = ["STRAINS", "THESIS_DOFS", "annex_e_section", "annex_e_forces", "annex_e_element"]

#: order of the generalized strains g (rows and columns of D_E, D_G)
STRAINS = ("u'", "v'", "v''", "w'", "w''", "phi'")
#: order of the degrees of freedom of annex E's 12×12 matrices (eqs. E.1–E.4)
THESIS_DOFS = ("u_A", "u_B", "v_A", "v_B", "w_A", "w_B", "tx_A", "tx_B", "ty_A", "ty_B", "tz_A", "tz_B")
#: g (model convention) = _FLIP * g (annex E's own degrees of freedom)
_FLIP = np.array([1.0, -1.0, -1.0, -1.0, -1.0, 1.0])


def _strand_data(strand):
    """Lay angle, direction, lay rate, net area and the section at x = 0 in annex E's reading."""
    try:
        wires, layers, section = strand.wires(), strand.layers, strand.section()
    except AttributeError:
        raise InputError("strand", f"must be a skcable.strand.Strand, got {type(strand).__name__}") from None
    if len(strand.materials) != 1:
        raise InputError(
            "strand", "annex E's section takes one modulus E: give a strand whose wires share one material"
        )
    if len(layers) != 1:
        raise InputError(
            "strand", f"annex E's section has one lay angle: need one helical layer, got {len(layers)}"
        )
    alpha = float(strand.lay_angles[0])
    direction = float(layers[0].direction)
    rate = direction * 2 * pi / float(strand.lay_lengths[0])
    alive = wires.intact
    area = float(np.sum(wires.area[alive]))
    y_c, z_c = section.centroid
    dy, dz = wires.y[alive] - y_c, wires.z[alive] - z_c
    c = np.cos(alpha)
    A = wires.area[alive]
    J = c**3 * np.array([[A @ dy**2, A @ (dy * dz)], [A @ (dy * dz), A @ dz**2]])  # lever y, lever z
    own = c * float(np.sum(wires.inertia[alive]))
    return dict(
        alpha=alpha, direction=direction, rate=rate, area=area, centroid=np.array([y_c, z_c]), J=J, own=own
    )


def annex_e_section(strand, *, slip, x, turning: bool = True):
    r"""Annex E's section matrices ``D_E`` and ``D_G`` (per unit axial force) at abscissae ``x``.

    Parameters
    ----------
    strand : Strand
        A strand with one helical layer (1x7 type), intact or damaged.
    slip : bool or array_like of bool
        Annex E.2 (slip state) where True, E.1 (stick) where False; an array
        broadcasts against ``x`` (e.g. the element state at its points).
    x : float or array_like
        Abscissae along the strand (m).
    turning : bool
        True: the section at x is the section at x = 0 turned by ``d 2π x / p`` (from +z toward
        +y, as the wire angles ψ; p the lay length, d the lay direction). False: the prismatic
        section of the thesis (annex E), the section at x = 0 everywhere.

    Returns
    -------
    D_E, D_G : ndarray (6, 6, *shape)
        Elastic section matrix (N, N·m, N·m²) and geometric section matrix per newton of axial
        force (module docstring), rows and columns in the order of `STRAINS`; ``shape`` is the
        broadcast shape of ``x`` and ``slip``.

    Examples
    --------
    >>> from skcable.strand import preset
    >>> D_E, D_G = annex_e_section(preset("steel-9.5").damaged(2), slip=False, x=[0.0, 0.1])
    >>> D_E.shape
    (6, 6, 2)
    >>> K_L = D_E[0, 0] - D_E[0, 5] ** 2 / D_E[5, 5]  # pulled with the twist free (N)
    >>> [round(float(k) / 1e3, 1) for k in K_L]
    [6287.8, 6287.8]
    """
    data = _strand_data(strand)
    x = real("x", x)
    x = np.asarray(x, dtype=float)
    if not isinstance(turning, (bool, np.bool_)):
        raise InputError("turning", f"must be True or False, got {turning!r}")
    slip_arr = np.asarray(slip)
    if slip_arr.dtype != bool:
        raise InputError("slip", f"must be a bool or an array of bools, got {slip!r}")
    try:
        shape = np.broadcast_shapes(x.shape, slip_arr.shape)
    except ValueError:
        raise InputError("slip", f"shape {slip_arr.shape} does not broadcast against x {x.shape}") from None
    x = np.broadcast_to(x, shape)
    slip_arr = np.broadcast_to(slip_arr, shape)

    c, s = np.cos(data["alpha"]), data["direction"] * np.sin(data["alpha"])
    A, E = data["area"], float(strand.material.E_e)
    beta = data["rate"] * x if turning else np.zeros(shape)
    cb, sb = np.cos(beta), np.sin(beta)
    # (y, z) -> Q (y, z), Q = [[cos b, sin b], [-sin b, cos b]]: psi -> psi + b
    Q = np.array([[cb, sb], [-sb, cb]])  # (2, 2, *shape)
    y_c, z_c = np.einsum("ij...,j->i...", Q, data["centroid"])
    J = np.einsum("ik...,kl,jl...->ij...", Q, data["J"], Q)
    own = data["own"]
    I_zz = np.where(slip_arr, own, J[0, 0] + own)
    I_yy = np.where(slip_arr, own, J[1, 1] + own)
    I_yz = np.where(slip_arr, 0.0, J[0, 1])
    stick = np.where(slip_arr, 0.0, 1.0)
    r_c = np.hypot(y_c, z_c)
    zero = np.zeros(shape)

    D_E = np.zeros((6, 6, *shape))
    D_E[0, 0] = E * A * c**3 + zero
    D_E[0, 2] = -E * A * c**3 * y_c
    D_E[0, 4] = -E * A * c**3 * z_c
    D_E[0, 5] = E * A * r_c * c**2 * s
    D_E[2, 2] = E * I_zz * c + E * A * c**3 * y_c**2
    D_E[4, 4] = E * I_yy * c + E * A * c**3 * z_c**2
    D_E[2, 4] = E * I_yz * c + E * A * c**3 * y_c * z_c
    D_E[2, 5] = -stick * E * A * y_c * r_c * c**2 * s
    D_E[4, 5] = -stick * E * A * z_c * r_c * c**2 * s
    D_E[5, 5] = E * ((I_zz + I_yy) / c**2 + A * r_c**2) * c * s**2

    D_G = np.zeros((6, 6, *shape))
    D_G[0, 0] = c**3 + zero
    D_G[0, 2] = -(c**3) * y_c
    D_G[0, 4] = -(c**3) * z_c
    D_G[0, 5] = r_c * c**2 * s
    D_G[1, 1] = c + zero
    D_G[3, 3] = c + zero
    D_G[2, 2] = I_zz / A * c + c**3 * y_c**2
    D_G[4, 4] = I_yy / A * c + c**3 * z_c**2
    D_G[2, 4] = I_yz / A * c + c**3 * y_c * z_c
    D_G[1, 5] = -(z_c * c + r_c * c**2 * s)
    D_G[3, 5] = y_c * c - r_c * c**2 * s
    D_G[5, 5] = (r_c**2 * c + (I_zz + I_yy) / (A * c)) * (1 + s**2)

    for D in (D_E, D_G):  # fill the lower triangle
        upper = np.triu_indices(6, 1)
        D[upper[1], upper[0]] = D[upper]
    return D_E, D_G


def annex_e_forces(g, F, D_E, D_G):
    r"""Section forces and tangent of annex E's law ``S = (D_E + F D_G) g``.

    Parameters
    ----------
    g : array_like (6, ...)
        Generalized strains ``(u', v', v'', w', w'', φ')`` at the points.
    F : None or array_like (...)
        Axial force (N). None: the thesis's current axial force of the point,
        from its strains through the elastic law, ``F = (D_E g)_0``
        (``= EA c³ u' − EA c³ (y_c v'' + z_c w'') + E A r_c c² s φ'``); the
        tangent then includes ∂F/∂g (and is not symmetric). A value: F held
        fixed (imposed, or lagged from the previous iterate as in the
        thesis's eq. 4.1), tangent ``D_E + F D_G``.
    D_E, D_G : array_like (6, 6, ...)
        Section matrices from `annex_e_section`.

    Returns
    -------
    S : ndarray (6, ...)
        Section forces, work-conjugate to g.
    D : ndarray (6, 6, ...)
        Consistent tangent ∂S/∂g:
        ``D_E + F D_G + (D_G g) ⊗ (D_E)_{0,:}`` when ``F`` is None.

    Examples
    --------
    >>> import numpy as np
    >>> D_E, D_G = np.diag([2.0, 0, 1, 0, 1, 1]), np.diag([1.0, 1, 0, 1, 0, 0])
    >>> S, D = annex_e_forces(np.array([0.5, 0.1, 0, 0, 0, 0]), None, D_E, D_G)
    >>> S.tolist()  # F = 2 * 0.5 = 1
    [1.5, 0.1, 0.0, 0.0, 0.0, 0.0]
    """
    g = real("g", g)
    g = np.asarray(g, dtype=float)
    D_E, D_G = (np.asarray(real(n, v), dtype=float) for n, v in (("D_E", D_E), ("D_G", D_G)))
    if g.ndim < 1 or g.shape[0] != 6:
        raise InputError("g", f"must have shape (6, ...), got {g.shape}")
    for name, D in (("D_E", D_E), ("D_G", D_G)):
        if D.ndim < 2 or D.shape[:2] != (6, 6):
            raise InputError(name, f"must have shape (6, 6, ...), got {D.shape}")
    try:
        tail = np.broadcast_shapes(g.shape[1:], D_E.shape[2:], D_G.shape[2:])
    except ValueError:
        raise InputError(
            "g", f"shape {g.shape} does not broadcast with D_E {D_E.shape} and D_G {D_G.shape}"
        ) from None
    Eg = np.einsum("ab...,b...->a...", D_E, g)
    Gg = np.einsum("ab...,b...->a...", D_G, g)
    if F is None:
        F = Eg[0]
        D = D_E + F * D_G + Gg[:, None] * D_E[0][None, :]
    else:
        F = np.asarray(real("F", F), dtype=float)
        try:
            np.broadcast_shapes(F.shape, tail)
        except ValueError:
            raise InputError("F", f"shape {F.shape} does not broadcast against the points {tail}") from None
        D = D_E + F * D_G
    S = Eg + F * Gg
    full = (6, *np.broadcast_shapes(tail, np.shape(F)))
    return np.broadcast_to(S, full).copy(), np.broadcast_to(D, (6, *full)).copy()


_GAUSS = np.polynomial.legendre.leggauss(5)


def annex_e_element(D, length):
    r"""Annex E's 12×12 element matrix ``∫ Bᵀ D B dx`` with the thesis's shape functions.

    Linear u and θ_x, cubic Hermite v and w (eqs. 3.22–3.31), in the thesis's degrees of freedom
    and order `THESIS_DOFS` (eq. E.1; ``θ_z = v'`` and ``θ_y = w'`` at the nodes), so that its
    entries compare one to one with the printed ``K_E0101 … K_G1212``. The section matrix is in
    the model's convention and mapped through ``T`` (module docstring).

    Parameters
    ----------
    D : array_like (6, 6) or callable
        Section matrix (``D_E`` for K_E, ``F D_G`` for K_G), constant over the
        element, or a function of the local abscissa ξ ∈ [0, length]
        (array) returning (6, 6, len(ξ)). Integrated by 5-point Gauss, exact
        for a constant D.
    length : float
        Element length L (m).

    Returns
    -------
    ndarray (12, 12)
    """
    L = float(positive("length", length))
    xi = (_GAUSS[0] + 1) * L / 2
    weights = _GAUSS[1] * L / 2
    if callable(D):
        Dq = np.asarray(D(xi), dtype=float)
    else:
        Dq = np.asarray(real("D", D), dtype=float)
        if Dq.shape != (6, 6):
            raise InputError("D", f"must have shape (6, 6) or be callable, got {Dq.shape}")
        Dq = np.broadcast_to(Dq[..., None], (6, 6, xi.size))
    if Dq.shape != (6, 6, xi.size):
        raise InputError("D", f"the callable must return shape (6, 6, {xi.size}), got {Dq.shape}")
    t = xi / L
    # first and second derivatives of N_u1, N_u2 and of N_v1, N_θ1, N_v2, N_θ2 (eqs. 3.26-3.31)
    du = np.array([-np.ones_like(t), np.ones_like(t)]) / L
    dh = np.array([(-6 * t + 6 * t**2) / L, 1 - 4 * t + 3 * t**2, (6 * t - 6 * t**2) / L, 3 * t**2 - 2 * t])
    ddh = np.array([(-6 + 12 * t) / L**2, (-4 + 6 * t) / L, (6 - 12 * t) / L**2, (6 * t - 2) / L])
    B = np.zeros((6, 12, xi.size))  # annex E's own strains from its dofs
    u, v, w, tx = [0, 1], [2, 10, 3, 11], [4, 8, 5, 9], [6, 7]
    B[0][u] = du
    B[1][v], B[2][v] = dh, ddh
    B[3][w], B[4][w] = dh, ddh
    B[5][tx] = du
    B = _FLIP[:, None, None] * B  # to the model's g
    return np.einsum("aiq,abq,bjq,q->ij", B, Dq, B, weights)


class AnnexE(SectionTerm):
    r"""The thesis's own formulation as a section term: annex E's element matrices (typos fixed).

    Section forces ``S = (D_E + F D_G) g`` of E.1 (stick) or E.2 (slip), F the current axial
    force of the point (`annex_e_forces` with ``F=None``; no membrane stretch, as the thesis's
    ``(K_E + K_G(F)) U``), with the wires' elastic E_e: a linear elastic term, whose capacity
    curve is a straight line of slope K_Leq. Used alone, as the model's ``physics``:
    ``StrandModel(s, physics=[AnnexE(slip="element")])`` (the wires' own bending is in it).

    Parameters
    ----------
    slip : {"none", "element", "axis"} or SlipLaw
        Where E.2 replaces E.1: nowhere (stick), in elements whose curvature exceeds κ_m
        anywhere (the thesis's rule), or at points beyond κ_m about either axis.
    mu : float
        Friction coefficient of κ_m (Cardou's law).
    turning : bool
        The section turns with the lay (the centroid rotates along the strand); False: a
        prismatic section (its position at x = 0).

    Notes
    -----
    Wire strains, curvatures and κ_m in the step results come from the helical-fibre
    kinematics of the same displacement field (for rupture, the elastic limit and slip maps).
    """

    #: the annex's section law has no potential and its tangent is not symmetric
    symmetric = False
    potential = False

    def __init__(self, slip="none", mu: float = 0.5, *, turning: bool = True):
        from skcable.strand.fe.slip import slip_law

        self.slip = slip_law(slip, mu)
        self.turning = bool(turning)

    def __repr__(self) -> str:
        return f"AnnexE(slip={self.slip!r}, turning={self.turning})"

    def setup(self, model):
        from skcable.strand.fe.wires import HelicalWires

        super().setup(model)
        self._matrices = {
            flag: annex_e_section(model.strand, slip=flag, x=model.x, turning=self.turning)
            for flag in (False, True)
        }
        self._kinematics = HelicalWires(self.slip, helical=self.turning).bind(model)

    def initial_state(self, model):
        if self.slip.kinematic:
            return self._kinematics.initial_state(model)
        return np.zeros((2, *model.x.shape), dtype=bool)  # where E.2 holds, frozen within a solve

    def next_state(self, output, state):
        if self.slip.kinematic:
            return self._kinematics.next_state(output, state)
        return np.array(output["slipping"], dtype=bool)

    def section(self, g, step):
        kinematic = self.slip.kinematic
        _, _, output = self._kinematics.section(g, step if kinematic else Step(step.strain, step.x, None))
        output.pop("energy", None)  # the annex's law has no potential: its tangent is not symmetric
        if output["curvature"] is None:  # a law that sticks leaves them to the results: give them
            output["curvature"] = self._kinematics.principal(g)
            output["kappa_m"] = self._kinematics.kappa_m(output["axial"], derivative=False)[0]
        # (ne, nq): E.2 where either axis slips (under a section law, where the frozen state says so)
        slipping = np.any(output["slipping"] if kinematic else np.asarray(step.state), axis=0)
        (E1, G1), (E2, G2) = self._matrices[False], self._matrices[True]
        D_E = np.where(slipping, E2, E1)
        D_G = np.where(slipping, G2, G1)
        S, D = annex_e_forces(g, None, D_E, D_G)
        output["N"] = S[0]
        return S, D, output
