"""Annex E of S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico" (2021), as a section law.

The element matrices ``∫ Bᵀ D B dx`` built from :func:`annex_e_section` are compared with the annex's
printed terms, transcribed below as formulas (typos fixed, each marked); the straight undamaged limit
with the textbook 3D Euler-Bernoulli beam; the axial stiffness with the twist free with the fit of
REFERENCE.md §3 (6287.8 kN).
"""

from dataclasses import replace
from math import pi, radians

import numpy as np
import pytest

from skcable.errors import InputError
from skcable.strand import Layer, Strand, preset
from skcable.strand.fe.annex_e import THESIS_DOFS, annex_e_element, annex_e_forces, annex_e_section

L = 0.05  # element length (m)
F = 1.5e3  # axial force of the geometric matrices (N)


def damage_about(axis: str) -> Strand:
    """steel-9.5 with two broken wires straddling +z (the thesis's damage 2) or turned to straddle +y."""
    s = preset("steel-9.5").damaged(2)
    if axis == "z":
        return s
    layer = s.layers[0]
    return replace(s, layers=(replace(layer, phase=layer.phase + pi / 2),))


def thesis_parameters(strand: Strand) -> dict:
    """The symbols of annex E, computed directly from the wires (one lay angle for the section)."""
    w = strand.wires()
    a = w.intact
    alpha = strand.lay_angles[0]
    c = np.cos(alpha)
    A = w.area[a].sum()
    y_c = w.area[a] @ w.y[a] / A
    z_c = w.area[a] @ w.z[a] / A
    own = c * w.inertia[a].sum()
    return dict(
        A=A,
        E=strand.material.E_e,
        c=c,
        s=np.sin(alpha),
        y=y_c,
        z=z_c,
        r=np.hypot(y_c, z_c),
        Izz=c**3 * w.area[a] @ (w.y[a] - y_c) ** 2 + own,
        Iyy=c**3 * w.area[a] @ (w.z[a] - z_c) ** 2 + own,
        Imin=own,
    )


# --- annex E transcribed: (row, col) -> formula of the parameters; FIX marks a corrected typo ------------
def printed_KE(p, slip=False):
    """Nonzero upper-triangle terms of E.1.1 (slip: E.2.1), as printed except where marked FIX."""
    A, E, c, s, y, z, r = (p[k] for k in "A E c s y z r".split())
    Izz, Iyy = (p["Imin"], p["Imin"]) if slip else (p["Izz"], p["Iyy"])
    k = {
        (1, 1): A * E * c**3 / L,
        (1, 2): -(A * E * c**3 / L),
        (1, 7): A * E * r * c**2 * s / L,  # FIX: A missing in print
        (1, 8): -(A * E * r * c**2 * s / L),  # FIX: A
        (1, 9): A * E * z * c**3 / L,
        (1, 10): -(A * E * z * c**3 / L),
        (1, 11): A * E * y * c**3 / L,
        (1, 12): -(A * E * y * c**3 / L),
        (2, 2): A * E * c**3 / L,
        (2, 7): -(A * E * r * c**2 * s / L),  # FIX: A
        (2, 8): A * E * r * c**2 * s / L,  # FIX: A
        (2, 9): -(A * E * z * c**3 / L),
        (2, 10): A * E * z * c**3 / L,
        (2, 11): -(A * E * y * c**3 / L),
        (2, 12): A * E * y * c**3 / L,
        (3, 3): 12 * E * Izz * c / L**3 + 12 * A * E * y**2 * c**3 / L**3,
        (3, 4): -(12 * E * Izz * c / L**3) - 12 * A * E * y**2 * c**3 / L**3,
        (3, 11): 6 * E * Izz * c / L**2 + 6 * A * E * y**2 * c**3 / L**2,
        (3, 12): 6 * E * Izz * c / L**2 + 6 * A * E * y**2 * c**3 / L**2,
        (4, 4): 12 * E * Izz * c / L**3 + 12 * A * E * y**2 * c**3 / L**3,  # FIX: y_c printed for y_c^2
        (4, 11): -(6 * E * Izz * c / L**2) - 6 * E * A * y**2 * c**3 / L**2,
        (4, 12): -(6 * E * Izz * c / L**2) - 6 * E * A * y**2 * c**3 / L**2,
        (5, 5): 12 * E * Iyy * c / L**3 + 12 * E * A * z**2 * c**3 / L**3,
        (5, 6): -(12 * E * Iyy * c / L**3) - 12 * E * A * z**2 * c**3 / L**3,
        (5, 9): 6 * E * Iyy * c / L**2 + 6 * E * A * z**2 * c**3 / L**2,
        (5, 10): 6 * E * Iyy * c / L**2 + 6 * E * A * z**2 * c**3 / L**2,
        (6, 6): 12 * E * Iyy * c / L**3 + 12 * E * A * z**2 * c**3 / L**3,
        (6, 9): -(6 * E * Iyy * c / L**2) - 6 * E * A * z**2 * c**3 / L**2,
        (6, 10): -(6 * E * Iyy * c / L**2) - 6 * E * A * z**2 * c**3 / L**2,
        (7, 7): E * (Izz / c**2 + A * y**2) * c * s**2 / L + E * (Iyy / c**2 + A * z**2) * c * s**2 / L,
        (7, 8): -(E * (Izz / c**2 + A * y**2) * c * s**2 / L) - E * (Iyy / c**2 + A * z**2) * c * s**2 / L,
        (8, 8): E * (Izz / c**2 + A * y**2) * c * s**2 / L + E * (Iyy / c**2 + A * z**2) * c * s**2 / L,
        (9, 9): 4 * E * Iyy * c / L + 4 * E * A * z**2 * c**3 / L,
        (9, 10): 2 * E * Iyy * c / L + 2 * E * A * z**2 * c**3 / L,
        (10, 10): 4 * E * Iyy * c / L + 4 * E * A * z**2 * c**3 / L,
        (11, 11): 4 * E * Izz * c / L + 4 * E * A * y**2 * c**3 / L,
        (11, 12): 2 * E * Izz * c / L + 2 * E * A * y**2 * c**3 / L,
        (12, 12): 4 * E * Izz * c / L + 4 * E * A * y**2 * c**3 / L,
    }
    if not slip:  # E.2.1 prints these couplings as 0
        k |= {
            (7, 9): A * E * z * r * c**2 * s / L,  # FIX: A (all four pairs)
            (7, 10): -(A * E * z * r * c**2 * s / L),
            (7, 11): A * E * y * r * c**2 * s / L,
            (7, 12): -(A * E * y * r * c**2 * s / L),
            (8, 9): -(A * E * z * r * c**2 * s / L),
            (8, 10): A * E * z * r * c**2 * s / L,
            (8, 11): -(A * E * y * r * c**2 * s / L),
            (8, 12): A * E * y * r * c**2 * s / L,
        }
    return k


def printed_KG(p, slip=False):
    """Nonzero upper-triangle terms of E.1.2 (slip: E.2.2), F_x = F."""
    A, c, s, y, z, r = (p[k] for k in "A c s y z r".split())
    Izz, Iyy = (p["Imin"], p["Imin"]) if slip else (p["Izz"], p["Iyy"])
    sec, tan = 1 / c, s / c
    tw = (
        F * y**2 * c / L
        + F * z**2 * c / L
        + F * Iyy * sec / (A * L)
        + F * Izz * sec / (A * L)
        + F * y**2 * c * s**2 / L
        + F * z**2 * c * s**2 / L
        + F * Iyy * s * tan / (A * L)
        + F * Izz * s * tan / (A * L)
    )
    return {
        (1, 1): F * c**3 / L,
        (1, 2): -(F * c**3 / L),
        (1, 7): F * r * c**2 * s / L,
        (1, 8): -(F * r * c**2 * s / L),
        (1, 9): F * z * c**3 / L,
        (1, 10): -(F * z * c**3 / L),
        (1, 11): F * y * c**3 / L,  # FIX: printed -(...)
        (1, 12): -(F * y * c**3 / L),  # FIX: printed +
        (2, 2): F * c**3 / L,
        (2, 7): -(F * r * c**2 * s / L),
        (2, 8): F * r * c**2 * s / L,
        (2, 9): -(F * z * c**3 / L),
        (2, 10): F * z * c**3 / L,
        (2, 11): -(F * y * c**3 / L),  # FIX: printed +
        (2, 12): F * y * c**3 / L,  # FIX: printed -(...)
        # E.2.2 drops the F y_c^2 terms of 0303, 0304, 0311, 0312 only: FIX (kept, as in 0404 ...)
        (3, 3): 12 * F * Izz * c / (A * L**3) + 6 * F * c / (5 * L) + 12 * F * y**2 * c**3 / L**3,
        (3, 4): -(12 * F * Izz * c / (A * L**3)) - 6 * F * c / (5 * L) - 12 * F * y**2 * c**3 / L**3,
        (3, 7): F * z * c / L + F * r * c**2 * s / L,
        (3, 8): -(F * z * c / L) - F * r * c**2 * s / L,
        (3, 11): F * c / 10 + 6 * F * Izz * c / (A * L**2) + 6 * F * y**2 * c**3 / L**2,
        (3, 12): F * c / 10 + 6 * F * Izz * c / (A * L**2) + 6 * F * y**2 * c**3 / L**2,
        (4, 4): 12 * F * Izz * c / (A * L**3) + 6 * F * c / (5 * L) + 12 * F * y**2 * c**3 / L**3,
        (4, 7): -(F * z * c / L) - F * r * c**2 * s / L,
        (4, 8): F * z * c / L + F * r * c**2 * s / L,
        (4, 11): -(F * c / 10) - 6 * F * Izz * c / (A * L**2) - 6 * F * y**2 * c**3 / L**2,
        (4, 12): -(F * c / 10) - 6 * F * Izz * c / (A * L**2) - 6 * F * y**2 * c**3 / L**2,
        (5, 5): 12 * F * Iyy * c / (A * L**3) + 6 * F * c / (5 * L) + 12 * F * z**2 * c**3 / L**3,
        (5, 6): -(12 * F * Iyy * c / (A * L**3)) - 6 * F * c / (5 * L) - 12 * F * z**2 * c**3 / L**3,
        (5, 7): -(F * y * c / L) + F * r * c**2 * s / L,  # FIX: printed +F y_c c / L
        (5, 8): F * y * c / L - F * r * c**2 * s / L,  # FIX: printed -(F y_c c / L)
        (5, 9): F * c / 10 + 6 * F * Iyy * c / (A * L**2) + 6 * F * z**2 * c**3 / L**2,
        (5, 10): F * c / 10 + 6 * F * Iyy * c / (A * L**2) + 6 * F * z**2 * c**3 / L**2,
        (6, 6): 12 * F * Iyy * c / (A * L**3) + 6 * F * c / (5 * L) + 12 * F * z**2 * c**3 / L**3,
        (6, 7): F * y * c / L - F * r * c**2 * s / L,  # FIX: printed -(F y_c c / L)
        (6, 8): -(F * y * c / L) + F * r * c**2 * s / L,  # FIX: printed +F y_c c / L
        (6, 9): -(F * c / 10) - 6 * F * Iyy * c / (A * L**2) - 6 * F * z**2 * c**3 / L**2,
        (6, 10): -(F * c / 10) - 6 * F * Iyy * c / (A * L**2) - 6 * F * z**2 * c**3 / L**2,
        (7, 7): tw,
        (7, 8): -tw,
        (8, 8): tw,
        (9, 9): 4 * F * Iyy * c / (A * L) + 2 * F * L * c / 15 + 4 * F * z**2 * c**3 / L,
        (9, 10): 2 * F * Iyy * c / (A * L) - F * L * c / 30 + 2 * F * z**2 * c**3 / L,  # FIX: printed 4 F z^2
        (10, 10): 4 * F * Iyy * c / (A * L) + 2 * F * L * c / 15 + 4 * F * z**2 * c**3 / L,
        (11, 11): 4 * F * Izz * c / (A * L) + 2 * F * L * c / 15 + 4 * F * y**2 * c**3 / L,
        (11, 12): 2 * F * Izz * c / (A * L) - F * L * c / 30 + 2 * F * y**2 * c**3 / L,
        (12, 12): 4 * F * Izz * c / (A * L) + 2 * F * L * c / 15 + 4 * F * y**2 * c**3 / L,
    }


def as_matrix(terms):
    K = np.zeros((12, 12))
    for (i, j), value in terms.items():
        K[i - 1, j - 1] = K[j - 1, i - 1] = value
    return K


def element(strand, slip, part):
    D_E, D_G = annex_e_section(strand, slip=slip, x=0.0, turning=False)
    return annex_e_element(D_E if part == "E" else F * D_G, L)


# --- element matrices against the printed annex ---------------------------------------------------------
@pytest.mark.parametrize("axis", ["z", "y"])
@pytest.mark.parametrize("slip", [False, True])
@pytest.mark.parametrize("part", ["E", "G"])
def test_element_reproduces_printed_annex_term_by_term(axis, slip, part):
    s = damage_about(axis)
    p = thesis_parameters(s)
    assert abs(p[axis]) > 1e-4 and abs(p["y" if axis == "z" else "z"]) < 1e-15  # the eccentricity exercised
    printed = as_matrix((printed_KE if part == "E" else printed_KG)(p, slip))
    K = element(s, slip, part)
    scale = np.abs(printed).max(axis=1)
    for i in range(12):  # every term, zeros included, relative to its row
        for j in range(12):
            assert K[i, j] == pytest.approx(printed[i, j], rel=1e-9, abs=1e-12 * scale[i]), (
                f"K_{part}{i + 1:02d}{j + 1:02d} ({THESIS_DOFS[i]}, {THESIS_DOFS[j]})"
            )


def test_printed_typos_are_not_what_the_section_gives():
    """The printed forms of the corrected terms differ from the element (the fixes are not cosmetic)."""
    py, pz = thesis_parameters(damage_about("y")), thesis_parameters(damage_about("z"))
    KEy, KGy = element(damage_about("y"), False, "E"), element(damage_about("y"), False, "G")
    KGz, KGz_slip = element(damage_about("z"), False, "G"), element(damage_about("z"), True, "G")
    KGy_slip = element(damage_about("y"), True, "G")
    A, E, c, s = pz["A"], pz["E"], pz["c"], pz["s"]
    y, z, r = py["y"], pz["z"], pz["r"]
    KEz = element(damage_about("z"), False, "E")
    as_printed = {
        "K_E0404": (KEy[3, 3], 12 * E * py["Izz"] * c / L**3 + 12 * A * E * y * c**3 / L**3),
        "K_E0107": (KEz[0, 6], E * r * c**2 * s / L),
        "K_E0709": (KEz[6, 8], E * z * r * c**2 * s / L),
        "K_G0111": (KGy[0, 10], -(F * y * c**3 / L)),
        "K_G0211": (KGy[1, 10], F * y * c**3 / L),
        "K_G0507": (KGy[4, 6], F * y * c / L + F * py["r"] * c**2 * s / L),
        "K_G0910": (KGz[8, 9], 2 * F * pz["Iyy"] * c / (A * L) - F * L * c / 30 + 4 * F * z**2 * c**3 / L),
        "K_G0910 (E.2.2)": (
            KGz_slip[8, 9],
            2 * F * pz["Imin"] * c / (A * L) - F * L * c / 30 + 4 * F * z**2 * c**3 / L,
        ),
        "K_G0303 (E.2.2)": (KGy_slip[2, 2], 12 * F * py["Imin"] * c / (A * L**3) + 6 * F * c / (5 * L)),
    }
    for name, (ours, printed) in as_printed.items():
        assert not np.isclose(ours, printed, rtol=1e-6), name


# --- standard limits, symmetry, null space, definiteness --------------------------------------------------
def test_straight_undamaged_section_is_the_euler_bernoulli_beam():
    d, alpha = 3.1e-3, 1e-7
    s = Strand(d, (Layer(6, d, lay_angle=alpha),), preset("steel-9.5").material)
    D_E, D_G = annex_e_section(s, slip=False, x=0.0)
    w = s.wires()
    E, A = s.material.E_e, w.area.sum()
    EI = E * (w.area @ w.y**2 + w.inertia.sum())
    assert np.allclose(D_E, np.diag([E * A, 0, EI, 0, EI, 0]), rtol=1e-12, atol=1e-9 * EI)
    assert EI == pytest.approx(E * (w.area @ w.z**2 + w.inertia.sum()), rel=1e-12)  # isotropic section
    # textbook 12x12 3D beam (Przemieniecki), slopes as rotations, no St-Venant torsion (annex E has no GJ)
    a, b = E * A / L, EI / L**3
    bend = b * np.array(
        [[12, 6 * L, -12, 6 * L], [6 * L, 4 * L**2, -6 * L, 2 * L**2], [-12, -6 * L, 12, -6 * L],
         [6 * L, 2 * L**2, -6 * L, 4 * L**2]]
    )  # fmt: skip
    K = np.zeros((12, 12))
    K[np.ix_([0, 1], [0, 1])] = a * np.array([[1, -1], [-1, 1]])
    v, wz = [2, 10, 3, 11], [4, 8, 5, 9]  # (v_A, θz_A, v_B, θz_B), (w_A, θy_A, w_B, θy_B)
    K[np.ix_(v, v)] = bend
    K[np.ix_(wz, wz)] = bend
    assert np.allclose(annex_e_element(D_E, L), K, rtol=0, atol=1e-9 * np.abs(K).max())
    # the geometric part: the textbook string stiffness (6/5L, 1/10, 2L/15, -L/30) plus F I/(A) bending
    geo = np.array(
        [[6 / (5 * L), 1 / 10, -6 / (5 * L), 1 / 10], [1 / 10, 2 * L / 15, -1 / 10, -L / 30],
         [-6 / (5 * L), -1 / 10, 6 / (5 * L), -1 / 10], [1 / 10, -L / 30, -1 / 10, 2 * L / 15]]
    )  # fmt: skip
    KG = annex_e_element(D_G, L)
    assert np.allclose(KG[np.ix_(v, v)], geo + bend / E / A, rtol=1e-6, atol=1e-12)


@pytest.mark.parametrize("slip", [False, True])
@pytest.mark.parametrize("turning", [False, True])
def test_symmetry_and_rigid_body_modes(slip, turning):
    s = preset("steel-9.5").damaged(2)
    x = np.linspace(0, 0.2, 7)
    D_E, D_G = annex_e_section(s, slip=slip, x=x, turning=turning)
    assert np.allclose(D_E, D_E.swapaxes(0, 1), rtol=0, atol=1e-12 * np.abs(D_E).max())
    assert np.allclose(D_G, D_G.swapaxes(0, 1), rtol=0, atol=1e-15)
    assert not D_E[[1, 3]].any()  # no elastic stiffness on the slopes: rigid rotations are free
    K_E = annex_e_element(D_E[..., 2], L)
    # six rigid-body modes in annex E's dofs: translations u, v, w; rotations about x, z (v = x, θz = 1), y
    modes = np.zeros((6, 12))
    modes[0, [0, 1]] = 1
    modes[1, [2, 3]] = 1
    modes[2, [4, 5]] = 1
    modes[3, [6, 7]] = 1
    modes[4, [3, 10, 11]] = [L, 1, 1]
    modes[5, [5, 8, 9]] = [L, 1, 1]
    assert np.abs(K_E @ modes.T).max() < 1e-9 * np.abs(K_E).max()
    eig = np.linalg.eigvalsh(K_E)
    if not slip:
        assert np.sum(np.abs(eig) < 1e-9 * eig.max()) == 6  # exactly those
    K_G = annex_e_element(
        D_G[..., 2], L
    )  # translations and the twist are free; rotations are not (prestress)
    assert np.abs(K_G @ modes[:4].T).max() < 1e-12 * np.abs(K_G).max()
    assert np.abs(K_G @ modes[4]).max() > 1e-3 * np.abs(K_G).max()


def test_positive_definiteness():
    """Stick: D_E positive definite on (u', v'', w'', φ'). Slip (E.2.1) zeroes the bending-torsion couplings
    but keeps the eccentric and axial-torsion ones: D_E is then indefinite as soon as the Schur complement
    E² s² (2 I_min² − A² z_c² r_c² c⁴) of the (w'', φ') block is negative, as for steel 9.5 damage 2 (not 1).
    Intact (r_c = 0) it is positive definite."""
    active = [0, 2, 4, 5]
    for damage, definite in ((1, True), (2, False)):
        s = preset("steel-9.5").damaged(damage)
        stick, _ = annex_e_section(s, slip=False, x=0.0)
        slip, _ = annex_e_section(s, slip=True, x=0.0)
        assert np.linalg.eigvalsh(stick[np.ix_(active, active)]).min() > 0
        assert np.linalg.eigvalsh(annex_e_element(stick, L)).min() > -1e-9 * np.abs(stick).max()
        p = thesis_parameters(s)
        E, sn, c, A = p["E"], p["s"], p["c"], p["A"]
        schur = E**2 * sn**2 * (2 * p["Imin"] ** 2 - A**2 * p["z"] ** 2 * p["r"] ** 2 * c**4)
        assert (schur > 0) == definite
        assert (np.linalg.eigvalsh(slip[np.ix_(active, active)]).min() > 0) == definite
        assert (np.linalg.eigvalsh(annex_e_element(slip, L)).min() > -1e-9 * np.abs(slip).max()) == definite
    intact, _ = annex_e_section(preset("steel-9.5"), slip=True, x=0.0)
    assert np.linalg.eigvalsh(intact[np.ix_(active, active)]).min() > 0


# --- the section against independent sources ---------------------------------------------------------------
def test_entries_match_the_developers_table():
    """REFERENCE.md §3 'Annex E read as a section matrix' (an independent prototype), model convention."""
    s = damage_about("y")  # y_c != 0 exercises the v-entries; the z-entries are checked by damage about z
    for strand in (s, damage_about("z")):
        p = thesis_parameters(strand)
        A, E, c, sn, y, z, r = (p[k] for k in "A E c s y z r".split())
        D, _ = annex_e_section(strand, slip=False, x=0.0, turning=False)
        expected = {
            (0, 0): E * A * c**3,
            (0, 2): -E * A * y * c**3,
            (0, 4): -E * A * z * c**3,
            (2, 2): E * p["Izz"] * c + E * A * y**2 * c**3,
            (4, 4): E * p["Iyy"] * c + E * A * z**2 * c**3,
            (0, 5): E * A * r * c**2 * sn,
            (2, 5): -E * A * y * r * c**2 * sn,
            (4, 5): -E * A * z * r * c**2 * sn,
            (5, 5): E * ((p["Izz"] / c**2 + A * y**2) + (p["Iyy"] / c**2 + A * z**2)) * c * sn**2,
        }
        for (i, j), value in expected.items():
            assert D[i, j] == pytest.approx(value, rel=1e-12, abs=1e-12 * abs(D[i, i])), (i, j)


def test_eccentric_terms_are_a_fibre_at_the_centroid():
    """Sign convention: a fibre of area A at (y_c, z_c) strained c²(u' - y v'' - z w'') + r_c s c φ'
    (the model's), weight E A / c, gives the eccentric and coupling entries of the stick D_E."""
    for axis in ("y", "z"):
        strand = damage_about(axis)
        p = thesis_parameters(strand)
        c, sn = p["c"], p["s"]
        b = np.array([c**2, 0, -(c**2) * p["y"], 0, -(c**2) * p["z"], p["r"] * sn * c])
        fibre = p["E"] * p["A"] / c * np.outer(b, b)
        D, _ = annex_e_section(strand, slip=False, x=0.0, turning=False)
        own = D - fibre  # what remains is the bending of the section about its centroid: diagonal
        assert np.allclose(own - np.diag(np.diag(own)), 0, atol=1e-9 * np.abs(D).max())
        assert own[0, 0] == pytest.approx(0, abs=1e-9 * D[0, 0])


def test_axial_stiffness_with_twist_free_is_the_fit_of_table_4_1():
    """REFERENCE.md §3: the stick K_Leq of damage 2 (Table 4.1: 6297.25 kN printed) is EA - C²/K_θ =
    6287.8 kN; C and K_θ are the axial-torsion coupling and the torsional stiffness of D_E."""
    D_E, _ = annex_e_section(preset("steel-9.5").damaged(2), slip=False, x=0.0)
    K_L = D_E[0, 0] - D_E[0, 5] ** 2 / D_E[5, 5]
    assert round(K_L / 1e3, 1) == 6287.8
    assert K_L / 6297.25e3 == pytest.approx(1, abs=2e-3)


def test_turning_section_is_the_turned_strand():
    """At x the turning section equals the prismatic section of the strand with its wires turned by
    d 2π x / p (the Strand geometry turned through the layer's phase: an independent path)."""
    for direction in (1, -1):
        s0 = preset("steel-9.5").damaged(2)
        layer = replace(s0.layers[0], direction=direction)
        s = replace(s0, layers=(layer,))
        p = float(s.lay_lengths[0])
        x = np.array([0.0, p / 8, p / 4, 0.37 * p, p])
        D_E, D_G = annex_e_section(s, slip=False, x=x)
        for k, xk in enumerate(x):
            turned = replace(s, layers=(replace(layer, phase=layer.phase + direction * 2 * pi * xk / p),))
            R_E, R_G = annex_e_section(turned, slip=False, x=0.0, turning=False)
            assert np.allclose(D_E[..., k], R_E, rtol=1e-9, atol=1e-9 * np.abs(R_E).max())
            assert np.allclose(D_G[..., k], R_G, rtol=1e-9, atol=1e-12)
        # a quarter lay puts the centroid of damage about +z on the y axis
        assert D_E[0, 4, 2] == pytest.approx(0, abs=1e-9 * D_E[0, 4, 0])
        assert D_E[0, 2, 2] == pytest.approx(direction * D_E[0, 4, 0], rel=1e-9)
        assert np.allclose(D_E[..., -1], D_E[..., 0], rtol=1e-9, atol=1e-6)  # one lay: back


def test_slip_array_and_shapes():
    s = preset("steel-9.5").damaged(1)
    x = np.linspace(0, 0.1, 6).reshape(2, 3)
    mask = np.array([[True, False, True], [False, False, True]])
    D_E, D_G = annex_e_section(s, slip=mask, x=x)
    assert D_E.shape == D_G.shape == (6, 6, 2, 3)
    stick, _ = annex_e_section(s, slip=False, x=x)
    slip, _ = annex_e_section(s, slip=True, x=x)
    assert np.array_equal(D_E, np.where(mask, slip, stick))
    assert annex_e_section(s, slip=False, x=0.3)[0].shape == (6, 6)
    assert annex_e_section(s, slip=np.array([True, False]), x=0.3)[0].shape == (6, 6, 2)


def test_slip_uses_the_wires_own_inertia():
    s = preset("steel-9.5").damaged(1)
    p = thesis_parameters(s)
    stick, G1 = annex_e_section(s, slip=False, x=0.0, turning=False)
    slip, G2 = annex_e_section(s, slip=True, x=0.0, turning=False)
    E, c, A = p["E"], p["c"], p["A"]
    assert slip[2, 2] == pytest.approx(E * p["Imin"] * c + E * A * p["y"] ** 2 * c**3)
    assert slip[4, 4] == pytest.approx(E * p["Imin"] * c + E * A * p["z"] ** 2 * c**3)
    assert slip[2, 5] == slip[4, 5] == 0 and stick[4, 5] != 0
    assert G2[5, 5] < G1[5, 5] and G2[4, 4] == pytest.approx(p["Imin"] / A * c + p["z"] ** 2 * c**3)
    # annex A: I min of steel 9.5 damage 1 is 27.006 mm^4 (core straight); annex E's one lay angle: core too
    assert p["Imin"] == pytest.approx(27.006e-12 - (1 - c) * np.pi * (1.55e-3) ** 4 / 4, rel=1e-4)


# --- the section law -------------------------------------------------------------------------------------
def _law(n=4, seed=0):
    rng = np.random.default_rng(seed)
    s = preset("steel-9.5").damaged(2)
    x = rng.uniform(0, 0.2, n)
    D_E, D_G = annex_e_section(s, slip=rng.uniform(size=n) < 0.5, x=x)
    scale = np.array([1e-3, 1e-2, 1.0, 1e-2, 1.0, 1.0])[:, None]  # strains, slopes, curvatures (1/m)
    return rng.standard_normal((6, n)) * scale, D_E, D_G


def test_forces_with_given_axial_force():
    g, D_E, D_G = _law()
    Fx = np.array([1e3, 2e3, -5e2, 0.0])
    S, D = annex_e_forces(g, Fx, D_E, D_G)
    assert np.allclose(D, D_E + Fx * D_G)
    assert np.allclose(S, np.einsum("abn,bn->an", D, g))
    S1, _ = annex_e_forces(g, 7.0, D_E, D_G)  # a scalar broadcasts
    assert np.allclose(S1, np.einsum("abn,bn->an", D_E + 7.0 * D_G, g))


def test_forces_with_current_axial_force_and_finite_difference_tangent():
    g, D_E, D_G = _law()
    S, D = annex_e_forces(g, None, D_E, D_G)
    Fx = np.einsum("bn,bn->n", D_E[0], g)
    assert np.allclose(S, np.einsum("abn,bn->an", D_E + Fx * D_G, g))
    h = 1e-6 * np.array([1e-3, 1e-2, 1.0, 1e-2, 1.0, 1.0])
    for b in range(6):
        dg = np.zeros_like(g)
        dg[b] = h[b]
        Sp, _ = annex_e_forces(g + dg, None, D_E, D_G)
        Sm, _ = annex_e_forces(g - dg, None, D_E, D_G)
        fd = (Sp - Sm) / (2 * h[b])
        assert np.allclose(D[:, b], fd, rtol=1e-6, atol=1e-8 * np.abs(D).max()), b
    assert not np.allclose(D, D.swapaxes(0, 1))  # ∂F/∂g makes it unsymmetric
    # a pure stretch: F = EA c³ u', S_0 = F (1 + c³ u')
    u = np.array([2e-3, 0, 0, 0, 0, 0])
    S0, _ = annex_e_forces(u, None, D_E[..., 0], D_G[..., 0])
    EA = D_E[0, 0, 0]
    assert S0[0] == pytest.approx(EA * u[0] * (1 + D_G[0, 0, 0] * u[0]))


def test_bad_input():
    s = preset("steel-9.5").damaged(1)
    with pytest.raises(InputError, match="strand"):
        annex_e_section("steel", slip=False, x=0.0)
    two = Strand(
        3e-3, (Layer(6, 3e-3, lay_angle=radians(7)), Layer(12, 3e-3, lay_angle=radians(9))), s.material
    )
    with pytest.raises(InputError, match="strand: .*one helical layer"):
        annex_e_section(two, slip=False, x=0.0)
    with pytest.raises(InputError, match="x"):
        annex_e_section(s, slip=False, x=[0.0, np.nan])
    with pytest.raises(InputError, match="slip"):
        annex_e_section(s, slip="yes", x=0.0)
    with pytest.raises(InputError, match="slip"):
        annex_e_section(s, slip=np.zeros(3, bool), x=np.zeros(2))
    with pytest.raises(InputError, match="turning"):
        annex_e_section(s, slip=False, x=0.0, turning=1)
    D_E, D_G = annex_e_section(s, slip=False, x=np.zeros(3))
    with pytest.raises(InputError, match="g"):
        annex_e_forces(np.zeros(5), None, D_E, D_G)
    with pytest.raises(InputError, match="D_E"):
        annex_e_forces(np.zeros(6), None, np.zeros((6, 5)), D_G)
    with pytest.raises(InputError, match="F"):
        annex_e_forces(np.zeros((6, 3)), np.zeros(2), D_E, D_G)
    with pytest.raises(InputError, match="g"):
        annex_e_forces(np.zeros((6, 2)), None, D_E, D_G)
    with pytest.raises(InputError, match="length"):
        annex_e_element(np.eye(6), 0.0)
    with pytest.raises(InputError, match="D"):
        annex_e_element(np.eye(5), 1.0)
