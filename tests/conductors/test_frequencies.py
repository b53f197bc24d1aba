"""Natural frequencies: Irvine's closed forms for small sag, the taut string,
the crossover at lambda^2 = 4 pi^2, mode counts, orthogonality, errors."""

import numpy as np
import pytest
import scipy.linalg

from skcable import cable, conductors
from skcable.errors import InputError

L, W, H = 100.0, 10.0, 12500.0  # sag/span = wL/8H = 1 %


def _EA_for(lambda2, L=L, w=W, H=H):
    """EA giving Irvine's lambda^2 = (wL/H)^2 L EA / (H L_e), L_e = L (1 + 8 (d/L)^2)."""
    d = w * L**2 / (8 * H)
    L_e = L * (1 + 8 * (d / L) ** 2)
    return lambda2 * H * L_e / ((w * L / H) ** 2 * L)


def _irvine_by_hand(lambda2, n_modes, L=L, w=W, H=H, g=9.81):
    """Irvine's frequencies from the textbook formulas, roots by a dense scan + bisection."""
    c = np.sqrt(H * g / w)
    sym = []
    for j in range(1, n_modes + 1):  # tan(b) = b - 4 b^3 / lambda2 on ((j-1/2) pi, (j+1/2) pi)
        lo, hi = (j - 0.5) * np.pi + 1e-12, (j + 0.5) * np.pi - 1e-12
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if np.tan(mid) - mid + 4 / lambda2 * mid**3 > 0:
                hi = mid
            else:
                lo = mid
        sym.append(0.5 * (lo + hi) * c / (np.pi * L))
    anti = [j * c / L for j in range(1, n_modes + 1)]
    return np.sort(np.array(sym + anti))[:n_modes], np.arange(1, n_modes + 1) * c / (2 * L)


@pytest.mark.parametrize("lambda2", [0.5, 10.0, 100.0, 400.0, 2000.0])
def test_irvine_within_one_percent_for_small_sag(lambda2):
    r = conductors.natural_frequencies(L, 0.0, W, _EA_for(lambda2), H=H)
    in_plane, out_of_plane = _irvine_by_hand(lambda2, 6)
    assert r.lambda2 == pytest.approx(lambda2, rel=1e-5)  # L_e = ∫ sec^3 vs L (1 + 8 (d/L)^2)
    assert r.f_in_plane == pytest.approx(in_plane, rel=1e-2)
    assert r.f_out_of_plane == pytest.approx(out_of_plane, rel=1e-2)
    # the closed form returned beside the FE result is the same textbook formula
    assert r.irvine["in_plane"] == pytest.approx(in_plane, rel=1e-12)
    assert r.irvine["out_of_plane"] == pytest.approx(out_of_plane, rel=1e-14)
    assert r.irvine["lambda2"] == pytest.approx(lambda2, rel=1e-12)


def test_taut_string_limit():
    # w -> 0: sag/span ~ 1e-6, lambda^2 ~ 1e-6: both families are the string's n c / 2L
    w, H_s, EA = 1e-3, 1e4, 1e8
    r = conductors.natural_frequencies(L, 0.0, w, EA, H=H_s, n_modes=8)
    string = np.arange(1, 9) * np.sqrt(H_s * 9.81 / w) / (2 * L)
    assert r.f_in_plane == pytest.approx(string, rel=1e-4)
    assert r.f_out_of_plane == pytest.approx(string, rel=1e-4)
    assert r.irvine["in_plane"] == pytest.approx(string, rel=1e-4)
    # mode shapes sin(n pi x / L), up to sign and normalisation
    for n in range(1, 9):
        exact = np.sin(n * np.pi * r.x / L)
        for shape in (r.modes_in_plane[n - 1], r.modes_out_of_plane[n - 1]):
            # signed so that the first lobe from A is up, as sin(n pi x / L)
            cos = (shape @ exact) / (np.linalg.norm(shape) * np.linalg.norm(exact))
            assert cos == pytest.approx(1.0, abs=1e-8)


def test_inclined_taut_string_limit():
    # an inclined taut wire: the string along the chord, tension H / cos psi,
    # mass w/g per chord length: f_n = n / (2 L_c) sqrt(T / m), L_c = L / cos psi
    dh, w, H_s = 40.0, 1e-3, 1e4
    r = conductors.natural_frequencies(L, dh, w, 1e8, H=H_s, n_modes=4)
    chord = np.hypot(L, dh)
    string = np.arange(1, 5) / (2 * chord) * np.sqrt(H_s * chord / L / (w / 9.81))
    assert r.f_out_of_plane == pytest.approx(string, rel=1e-4)
    assert r.f_in_plane == pytest.approx(string, rel=1e-4)


def test_crossover_at_four_pi_squared():
    # closed form: at lambda^2 = 4 pi^2 the first symmetric root is beta = pi, i.e. c / L
    c = np.sqrt(H * 9.81 / W)
    at = conductors.irvine_frequencies(L, W, _EA_for(4 * np.pi**2), H, n_modes=2)
    assert at["in_plane"] == pytest.approx([c / L, c / L], rel=1e-9)
    below = conductors.natural_frequencies(L, 0.0, W, _EA_for(0.8 * 4 * np.pi**2), H=H, n_modes=3)
    above = conductors.natural_frequencies(L, 0.0, W, _EA_for(1.2 * 4 * np.pi**2), H=H, n_modes=3)
    assert below.in_plane_symmetric.tolist() == [True, False, True]
    assert above.in_plane_symmetric.tolist() == [False, True, True]
    assert below.irvine["in_plane_symmetric"].tolist() == [True, False, True]
    assert above.irvine["in_plane_symmetric"].tolist() == [False, True, True]


@pytest.mark.parametrize("n_modes", [1, 3, 10])
def test_mode_counts_and_orthogonality(n_modes):
    r = conductors.natural_frequencies(300.0, 20.0, 15.0, 2e7, sag=9.0, n_modes=n_modes)
    assert r.f_in_plane.shape == r.f_out_of_plane.shape == (n_modes,)
    assert r.modes_in_plane.shape == r.modes_out_of_plane.shape == (n_modes, r.x.size)
    assert np.all(np.diff(r.f_in_plane) > 0) and np.all(np.diff(r.f_out_of_plane) > 0)
    assert r.sag == pytest.approx(9.0, rel=1e-12)
    for modes, K, f in (
        (r.modes_in_plane, r.stiffness_in_plane, r.f_in_plane),
        (r.modes_out_of_plane, r.stiffness_out_of_plane, r.f_out_of_plane),
    ):
        phi = modes[:, 1:-1].T
        assert phi.T @ r.mass @ phi == pytest.approx(np.eye(n_modes), abs=1e-10)
        assert phi.T @ K @ phi == pytest.approx(
            np.diag((2 * np.pi * f) ** 2), rel=1e-10, abs=1e-8 * f[-1] ** 2
        )
        assert np.all(modes[:, 0] == 0) and np.all(modes[:, -1] == 0)


def test_given_H_or_sag_agree():
    a = conductors.natural_frequencies(300.0, 0.0, 15.0, 2e7, sag=9.0, n_modes=3)
    b = conductors.natural_frequencies(300.0, 0.0, 15.0, 2e7, H=a.H, n_modes=3)
    assert b.f_in_plane == pytest.approx(a.f_in_plane, rel=1e-12)


@pytest.mark.parametrize(
    "kw, argument",
    [
        (dict(H=1e4, sag=2.0), "constraint"),
        (dict(), "constraint"),
        (dict(H=-1.0), "H"),
        (dict(sag=0.0), "sag"),
        (dict(H=1e4, n_modes=0), "n_modes"),
        (dict(H=1e4, n_modes=2.0), "n_modes"),
        (dict(H=1e4, n_modes=True), "n_modes"),
        (dict(H=1e4, n_modes=61), "n_modes"),
        (dict(H=1e4, g=0.0), "g"),
        (dict(H=[1e4, 2e4]), "H"),
    ],
)
def test_bad_input(kw, argument):
    with pytest.raises(InputError) as info:
        conductors.natural_frequencies(100.0, 0.0, 10.0, 1e7, **kw)
    assert info.value.argument == argument


def test_bad_input_positional():
    with pytest.raises(InputError, match="EA"):
        conductors.natural_frequencies(100.0, 0.0, 10.0, -1e7, H=1e4)
    with pytest.raises(InputError, match="w"):
        conductors.natural_frequencies(100.0, 0.0, np.nan, 1e7, H=1e4)
    with pytest.raises(InputError, match="dh"):
        conductors.natural_frequencies(100.0, np.inf, 10.0, 1e7, H=1e4)


# --- static profile and mode shapes to VTK ---------------------------------------
def test_static_profile_is_the_catenary():
    res = conductors.natural_frequencies(120.0, 15.0, 12.0, 2e7, H=8e3, n_modes=2)
    ref = cable.catenary(120.0, 15.0, 12.0, H=8e3)
    np.testing.assert_allclose(res.y, ref.y(res.x), rtol=0, atol=1e-12 * 120)
    assert (res.span, res.dh) == (120.0, 15.0)


@pytest.mark.parametrize("suffix", [".vtu", ".vtk"])
def test_mode_shapes_round_trip_through_vtk(tmp_path, suffix):
    import meshio

    from skcable.io import write_mode_shapes

    res = conductors.natural_frequencies(100.0, -8.0, 10.0, 5e7, sag=3.0, n_modes=3)
    path = write_mode_shapes(res, tmp_path / f"modes{suffix}")
    assert [p.name for p in tmp_path.iterdir()] == [path.name]  # no temporary left behind
    mesh = meshio.read(path)
    np.testing.assert_array_equal(mesh.points[:, 0], res.x)
    np.testing.assert_array_equal(mesh.points[:, 1], res.y)
    np.testing.assert_array_equal(mesh.points[:, 2], 0.0)
    for k in range(3):
        in_plane = mesh.point_data[f"in_plane_{k + 1}_m_per_sqrt_kg"]
        out_of_plane = mesh.point_data[f"out_of_plane_{k + 1}_m_per_sqrt_kg"]
        np.testing.assert_array_equal(in_plane[:, 1], res.modes_in_plane[k])
        np.testing.assert_array_equal(out_of_plane[:, 2], res.modes_out_of_plane[k])
        np.testing.assert_array_equal(in_plane[:, [0, 2]], 0.0)
        np.testing.assert_array_equal(out_of_plane[:, :2], 0.0)
    cells = mesh.cells_dict["line"]
    joined = np.column_stack([np.arange(res.x.size - 1), np.arange(1, res.x.size)])
    np.testing.assert_array_equal(cells, joined)


def test_mode_shape_writer_refuses_bad_input(tmp_path):
    from skcable.io import mode_shape_mesh, write_mode_shapes

    res = conductors.natural_frequencies(100.0, 0.0, 10.0, 5e7, sag=3.0, n_modes=2)
    with pytest.raises(InputError, match="path"):
        write_mode_shapes(res, tmp_path / "modes.csv")
    with pytest.raises(InputError, match="result"):
        mode_shape_mesh(object())
    res.modes_in_plane = res.modes_in_plane[:, :-1]
    with pytest.raises(InputError, match="modes_in_plane"):
        mode_shape_mesh(res)
    assert list(tmp_path.iterdir()) == []


# --- the lowest modes, all of them: a nearly double pair at the crossover ----------------
def test_nearly_double_pair_at_the_crossover_is_found_whole():
    # a level span whose first symmetric and antisymmetric in-plane modes coincide to 1e-9:
    # EA by bisection on the sign of f_sym - f_anti; the frequencies are those of the dense
    # scipy eigh of the same matrices (bisection on the whole spectrum: none skipped)
    def gap(EA):
        r = conductors.natural_frequencies(L, 0.0, W, EA, H=H, n_modes=3)
        sym = r.f_in_plane[r.in_plane_symmetric][0]
        anti = r.f_in_plane[~r.in_plane_symmetric][0]
        return sym / anti - 1.0

    lo, hi = _EA_for(0.9 * 4 * np.pi**2), _EA_for(1.1 * 4 * np.pi**2)
    assert gap(lo) < 0 < gap(hi)
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if gap(mid) < 0 else (lo, mid)
    r = conductors.natural_frequencies(L, 0.0, W, lo, H=H, n_modes=3)
    assert abs(r.f_in_plane[1] / r.f_in_plane[0] - 1) < 1e-9
    assert sorted(r.in_plane_symmetric[:2].tolist()) == [False, True]
    for K, f in ((r.stiffness_in_plane, r.f_in_plane), (r.stiffness_out_of_plane, r.f_out_of_plane)):
        omega2 = scipy.linalg.eigh(K, r.mass, subset_by_index=[0, 2], eigvals_only=True)
        np.testing.assert_allclose(f, np.sqrt(omega2) / (2 * np.pi), rtol=1e-9)


# --- magnitudes at the edges of the float range (issue 26, D7) ---------------------------
@pytest.mark.parametrize("s", [1e-301, 1e-150, 1e150, 1e298])
def test_weight_and_stiffness_scaled_together_leave_the_frequencies(s):
    # w and EA times s at the same sag: H scales by s, EA/H and the wave speed sqrt(H g/w) do
    # not, so neither do the frequencies; the mass-normalised shapes scale by 1/sqrt(s)
    # (w = 1e-300 once escaped as LinAlgError)
    ref = conductors.natural_frequencies(300.0, 0.0, 10.0, 3e8, sag=6.0, n_modes=4)
    r = conductors.natural_frequencies(300.0, 0.0, 10.0 * s, 3e8 * s, sag=6.0, n_modes=4)
    np.testing.assert_allclose(r.f_in_plane, ref.f_in_plane, rtol=1e-12)
    np.testing.assert_allclose(r.f_out_of_plane, ref.f_out_of_plane, rtol=1e-12)
    assert r.lambda2 == pytest.approx(ref.lambda2, rel=1e-12)
    assert r.in_plane_symmetric.tolist() == ref.in_plane_symmetric.tolist()
    peak = np.abs(ref.modes_in_plane).max()
    np.testing.assert_allclose(r.modes_in_plane * np.sqrt(s), ref.modes_in_plane, rtol=0, atol=1e-9 * peak)


@pytest.mark.parametrize("s", [1e-300, 1e-100, 1e100, 1e290])
def test_lengths_and_stiffness_scaled_together_scale_the_frequencies(s):
    # span, sag and EA times s: wL/H, L/L_e and EA/H, hence lambda^2, stay; c/L scales by
    # 1/sqrt(s), and so do the frequencies
    ref = conductors.natural_frequencies(300.0, 0.0, 10.0, 3e8, sag=6.0, n_modes=4)
    r = conductors.natural_frequencies(300.0 * s, 0.0, 10.0, 3e8 * s, sag=6.0 * s, n_modes=4)
    np.testing.assert_allclose(r.f_in_plane * np.sqrt(s), ref.f_in_plane, rtol=1e-12)
    np.testing.assert_allclose(r.f_out_of_plane * np.sqrt(s), ref.f_out_of_plane, rtol=1e-12)


def test_weight_1e_300_is_the_inextensible_cable_of_irvine():
    # w = 1e-300 at sag/span = 1 %: H ~ 4e-297, lambda^2 ~ 1e303, the inextensible limit,
    # where Irvine's first in-plane mode is antisymmetric (c/L) and his symmetric root is
    # tan b = b (4.4934); the FE within his small-sag 1 %
    w = 1e-300
    r = conductors.natural_frequencies(L, 0.0, w, 1e8, sag=1.0)
    assert r.lambda2 > 1e300 and np.isfinite(r.lambda2)
    in_plane, out_of_plane = _irvine_by_hand(r.lambda2, 6, w=w, H=r.H)
    np.testing.assert_allclose(r.f_in_plane, in_plane, rtol=1e-2)
    np.testing.assert_allclose(r.f_out_of_plane, out_of_plane, rtol=1e-2)
    c = np.sqrt(r.H * 9.81 / w)
    assert r.f_in_plane[0] == pytest.approx(c / L, rel=1e-2)
    assert r.f_in_plane[1] == pytest.approx(4.493409457909064 * c / (np.pi * L), rel=1e-2)


@pytest.mark.parametrize(
    "kw, argument",
    [
        (dict(w=1e-310, sag=6.0), "w"),  # a denormal weight: lambda^2 beyond the float range
        (dict(w=5e-324, sag=6.0), "w"),
        (dict(g=1e-310, H=1e4), "g"),  # a denormal g: the mass matrix beyond the float range
        (dict(EA=1e-310, H=1e4), "EA"),  # lambda^2 below the smallest normal float
        (dict(H=1e300), "H"),
    ],
)
def test_out_of_range_magnitudes_are_refused_by_name(kw, argument):
    args = dict(span=300.0, dh=0.0, w=10.0, EA=3e7) | kw
    with pytest.raises(InputError) as info:
        conductors.natural_frequencies(**args)
    assert info.value.argument == argument


def test_extreme_irvine_roots_without_overflow():
    # the symmetric roots at the two limits: lambda^2 -> 0 gives (j - 1/2) pi (the taut
    # string's odd modes), lambda^2 -> infinity tan b = b (4.4934, 7.7253)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        taut = conductors.irvine_frequencies(100.0, 1e-3, 1e-200, 1e4, n_modes=2)
        stiff = conductors.irvine_frequencies(100.0, 10.0, 1e300, 1e4, n_modes=3)
    c = np.sqrt(1e4 * 9.81 / 1e-3)
    assert taut["in_plane"] == pytest.approx([c / 200, c / 100], rel=1e-12)
    c = np.sqrt(1e4 * 9.81 / 10.0)
    assert stiff["in_plane"] == pytest.approx(
        [c / 100, 4.493409457909064 * c / (np.pi * 100), 2 * c / 100], rel=1e-12
    )
