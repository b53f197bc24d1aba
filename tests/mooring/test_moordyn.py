"""MoorDyn v2 input files: read, write, round trips, and refusals by name.

References: MoorPy's own MoorDyn reader (``System(file=...)``) on the files written here, and
MoorPy's writer (``System.unload``) for a file read here (independent implementations of the
format); the equilibrium of the system read back against the system written.
"""

import textwrap

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError
from tests.mooring.test_mooring_system import basic_u

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(uplift_angle|position)\\b:skcable.errors.PlausibilityWarning"
)

FILE = textwrap.dedent(
    """\
    --------------------- MoorDyn Input File ------------------------------------
    A buoy moored by three lines and a shared free point  ! front matter
    ---------------------- LINE TYPES ----------------------------------------------------------------------
    TypeName   Diam    Mass/m     EA     BA/-zeta    EI         Cd     Ca     CdAx    CaAx
    (name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
    chain      0.216   288.0      1.2326e9  -1       0          1.33   1.0    0.64    0.5
    rope       0.17    30.0       3.0e7|5.0e7  -1    0          2.0    1.1    0.0     0.15
    ---------------------- BODIES ---------------------------------------
    ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass  CG*   I*      Volume   CdA*   Ca*
    (#)   (word)     (m)    (m)   (m)   (deg)   (deg)  (deg)   (kg)  (m)  (kg-m^2)  (m^3)   (m^2)  (-)
    1     free       0      0     -20    0       0      0      1.0e5  -1.0  0       300.0    0      0
    ---------------------- POINTS ---------------------------------------
    ID   Attachment  X       Y     Z      Mass   Volume  CdA    Ca
    (#)   (word/ID) (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
    1     Fixed      600     0     -150    0      0       0      0
    2     Fixed     -300   519.6   -150    0      0       0      0
    3     Anchor    -300  -519.6   -150    0      0       0      0
    4     Body1       5      0      -2     0      0       0      0
    5     Body1     -2.5   4.33    -2     0      0       0      0
    6     Body1     -2.5  -4.33    -2     0      0       0      0
    7     Free      300      0     -100   2000    0       0      0   # a clump on line 1
    ---------------------- LINES ----------------------------------------
    ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
    (#)   (name)     (ID)     (ID)      (m)       (-)      (-)
    1     chain       1        7        330        20       p
    2     rope        7        4        310        20       -
    3     chain       2        5        640        30       -
    4     chain       3        6        640        30       -
    ---------------------- OPTIONS -----------------------------------------
    0.002         dtM           time step to use in mooring integration (s)
    150           WtrDpth       water depth (m)
    1025          rho           water density
    9.81          g
    3.0e6         kBot
    ---------------------- OUTPUTS -----------------------------------------
    FairTen1
    END
    --------------------- need this line ------------------
    """
)


def test_read_a_file_with_a_body_and_a_free_point(tmp_path):
    path = tmp_path / "buoy.dat"
    path.write_text(FILE)
    model = mooring.read_moordyn(path)
    system = model.system
    assert system.depth == 150.0 and len(system.bodies) == 1 and len(system.mooring_lines) == 4
    assert [p.kind for p in system.points] == ["fixed"] * 3 + ["body"] * 3 + ["free"]
    chain = system.mooring_lines[0].model.segments[0]
    assert chain.w == pytest.approx(9.81 * (288.0 - 1025.0 * np.pi / 4 * 0.216**2), rel=1e-14)
    assert system.mooring_lines[1].model.segments[0].EA == 3.0e7  # the static EA of EA_s|EA_d
    assert model.line_type_of == ["chain", "rope", "chain", "chain"] and model.segments == [20, 20, 30, 30]
    assert model.outputs == ["FairTen1"] and model.options["kBot"] == "3.0e6"
    eq = system.equilibrium()
    scale = max(np.linalg.norm(line.end_forces, axis=1).max() for line in eq.lines)
    assert eq.positive_definite and np.abs(eq.residual).max() < 1e-9 * scale


def test_round_trip(tmp_path):
    first = tmp_path / "first.dat"
    first.write_text(FILE)
    model = mooring.read_moordyn(first)
    second = mooring.write_moordyn(model, tmp_path / "second.dat")
    again = mooring.read_moordyn(second)
    a, b = model.system, again.system
    assert [p.kind for p in a.points] == [p.kind for p in b.points]
    np.testing.assert_array_equal([p.position for p in a.points], [p.position for p in b.points])
    for ha, hb in zip(a.mooring_lines, b.mooring_lines, strict=True):
        sa, sb = ha.model.segments[0], hb.model.segments[0]
        assert (sa.length, sa.w, sa.EA, sa.diameter) == (sb.length, sb.w, sb.EA, sb.diameter)
        assert (ha.a.index, ha.b.index) == (hb.a.index, hb.b.index)
    assert again.line_types == model.line_types
    assert {k: float(v) for k, v in again.options.items()} == {k: float(v) for k, v in model.options.items()}
    np.testing.assert_array_equal(a.equilibrium().position, b.equilibrium().position)


def test_a_written_file_reads_in_moorpy(tmp_path):
    moorpy = pytest.importorskip("moorpy")
    system, _ = basic_u()
    path = mooring.write_moordyn(system, tmp_path / "u.dat", diameter=0.216)
    ms = moorpy.System(file=str(path))
    assert ms.depth == 100.0 and len(ms.pointList) == 4 and len(ms.lineList) == 3
    for mp_point, p in zip(ms.pointList, system.points, strict=True):
        np.testing.assert_array_equal(mp_point.r, p.position)
        assert mp_point.type == (1 if p.fixed else 0) and mp_point.v == p.volume
    for mp_line, h in zip(ms.lineList, system.mooring_lines, strict=True):
        s = h.model.segments[0]
        assert mp_line.L == s.length and mp_line.type["EA"] == s.EA
        assert mp_line.type["w"] == pytest.approx(s.w, rel=1e-13)


def test_a_file_moorpy_wrote_reads_here(tmp_path):
    moorpy = pytest.importorskip("moorpy")
    ms = moorpy.System(depth=200.0)
    ms.setLineType(dnommm=120, material="chain", name="chain")
    ms.addPoint(1, [800.0, 0.0, -200.0])
    ms.addPoint(0, [20.0, 0.0, -14.0], m=1e4, v=30.0)
    ms.addPoint(1, [-800.0, 0.0, -200.0])
    ms.addLine(850.0, "chain", pointA=1, pointB=2)
    ms.addLine(850.0, "chain", pointA=3, pointB=2)
    ms.initialize()
    path = tmp_path / "moorpy.dat"
    ms.unload(str(path))
    system = mooring.read_moordyn(path).system
    assert system.depth == 200.0
    np.testing.assert_allclose([p.position for p in system.points], [p.r for p in ms.pointList], atol=1e-3)
    assert [p.kind for p in system.points] == ["fixed", "free", "fixed"]
    seg = system.mooring_lines[0].model.segments[0]
    # MoorPy writes its line types to four significant digits
    assert seg.EA == pytest.approx(ms.lineTypes["chain"]["EA"], rel=5e-4)
    assert seg.w == pytest.approx(ms.lineTypes["chain"]["w"], rel=5e-4)


def test_a_multi_segment_line_written_as_lines_between_free_points(tmp_path):
    # the joints of the multi-segment lines become free points (their clump weights as mass): the
    # system read back is solved point by point, the one written by the multi-segment closed form
    chain, rope = mooring.component("studless chain R3"), mooring.component("polyester rope")
    line = mooring.Line(
        [chain.segment(60.0, 0.1), rope.segment(440.0, 0.16), chain.segment(80.0, 0.1)],
        [mooring.ClumpWeight(2, 3e4)],
    )
    system = mooring.MooringSystem(depth=200.0)
    hub = system.add_body(mooring.PointBody(volume=200.0, mass=2e4), position=[0.0, 0.0, -20.0])
    for h in np.radians([0.0, 120.0, 240.0]):
        c, s = np.cos(h), np.sin(h)
        system.add_line(
            line,
            system.add_point([560 * c, 560 * s, -200.0], fixed=True),
            system.add_point([0, 0, 0], body=hub),
        )
    eq = system.equilibrium()
    back = mooring.read_moordyn(mooring.write_moordyn(system, tmp_path / "multi.dat")).system
    assert len(back.mooring_lines) == 9 and sum(p.kind == "free" for p in back.points) == 7
    clumps = [p for p in back.points if p.kind == "free" and p.mass > 0 and p.volume == 0]
    assert len(clumps) == 3 and clumps[0].mass == pytest.approx(3e4 / back.g, rel=1e-15)
    eq_back = back.equilibrium()
    np.testing.assert_allclose(eq_back.points[1].position, eq.position, atol=1e-9)


_RODS = "---------------------- RODS ---\nID RodType\n(#) (name)\n1 Can Body1 0 0 2 0 0 15 8 p\n"


@pytest.mark.parametrize(
    "change, keyword, line",
    [
        (("4     Body1", "4     Floating"), "Floating", 18),
        (("1     chain       1        7", "1     chain       R1A      7"), "R1A", 25),  # no rod 1
        (("---------------------- OPTIONS", _RODS + "---------------------- OPTIONS"), "Can", 32),
        (("1     chain       1        7", "1     steel       1        7"), "steel", 25),
        (("0.216   288.0", "0.216   heavy"), "Mass/m", 6),
        (("1     chain       1        7", "1     chain       1        9"), "9", 25),  # no point 9
    ],
)
def test_unknown_keywords_are_refused_by_name_and_line(tmp_path, change, keyword, line):
    path = tmp_path / "bad.dat"
    path.write_text(FILE.replace(*change))
    with pytest.raises(InputError) as err:
        mooring.read_moordyn(path)
    assert (
        err.value.argument == keyword
        and err.value.line == line
        and f"bad.dat, line {line}:" in str(err.value)
    )


def test_unknown_sections_are_skipped_and_unknown_options_warn(tmp_path):
    """As MoorDyn-C: a '---' line naming no section starts nothing (its rows belong to no section),
    an option it does not know warns and is left aside."""
    path = tmp_path / "odd.dat"
    path.write_text(FILE.replace("3.0e6         kBot", "3.0e6         kBottom"))
    with pytest.warns(UserWarning, match="kBottom"):
        model = mooring.read_moordyn(path)
    assert "kBottom" in model.ignored and model.system.depth == 150.0
    path.write_text(FILE.replace("---------------------- OPTIONS", "---------------------- WIBBLE"))
    model = mooring.read_moordyn(path)
    assert model.options == {}  # not read: the depth is MoorDyn's, the lowest point's
    assert model.system.depth == 150.0 and model.system.g == 9.80665 and model.system.rho == 1025.0


def test_what_moordyn_cannot_take_is_refused(tmp_path):
    system = mooring.MooringSystem(depth=100.0)
    hull = system.add_body(mooring.RigidBody(waterplane_area=10.0))
    line = mooring.Line([mooring.Segment(110.0, 100.0, 1e8, diameter=0.05)])
    system.add_line(
        line, system.add_point([100, 0, -100.0], fixed=True), system.add_point([0, 0, 0], body=hull)
    )
    with pytest.raises(InputError) as err:
        mooring.write_moordyn(system, tmp_path / "x.dat")
    assert err.value.argument == "body"
    assert not (tmp_path / "x.dat").exists()
    bare, _ = basic_u()
    with pytest.raises(InputError) as err:
        mooring.write_moordyn(bare, tmp_path / "y.dat")  # no diameter
    assert err.value.argument == "diameter"


def test_drag_coefficients_written_on_moordyn_areas(tmp_path):
    """A segment's drag coefficients reach the file as MoorDyn defines them: ``Cd`` on the frontal
    area d l (as ``cd_normal``), ``CdAx`` on the surface π d l (MoorPy's line.py applies
    ``½ ρ CdAx π d |u_t| u_t``), so that MoorPy's tangential drag per length is ours."""
    moorpy = pytest.importorskip("moorpy")
    system = mooring.MooringSystem(depth=100.0)
    seg = mooring.Segment(110.0, 100.0, 1e8, diameter=0.05, cd_normal=1.2, cd_tangential=0.3)
    a, b = system.add_point([100, 0, -100.0], fixed=True), system.add_point([0, 0, -10.0], fixed=True)
    system.add_line(mooring.Line([seg]), a, b)
    ms = moorpy.System(file=str(mooring.write_moordyn(system, tmp_path / "d.dat")))
    kind = ms.lineList[0].type
    rho, d, u = 1025.0, 0.05, 0.7  # a current of 0.7 m/s along the line
    assert kind["Cd"] == 1.2
    assert 0.5 * rho * kind["CdAx"] * np.pi * d * u * u == pytest.approx(
        0.5 * rho * 0.3 * d * u * u, rel=1e-15
    )


def test_a_line_in_the_sea_is_not_written(tmp_path):
    """What the file cannot hold with a line (its current, a nonlinear EA) is refused by name,
    not dropped."""
    seg = mooring.Segment(850.0, 2456.82, 1.2326e9, diameter=0.12, cd_normal=1.2)
    anchors = np.array([[800.0, 0.0, -200.0], [-400.0, 692.8, -200.0], [-400.0, -692.8, -200.0]])
    fair = 20.0 * anchors / 800.0 * np.array([1.0, 1.0, 0.0]) + np.array([0.0, 0.0, -14.0])
    body = mooring.RigidBody(fairleads=fair, mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5))
    rope = mooring.axial.StrainTable([0.0, 0.01, 0.02], [0.0, 1e7, 3e7])  # a nonlinear law
    for line in (
        mooring.Line([seg], current=(0.5, 0.0)),
        mooring.Line([mooring.Segment(850.0, 2456.82, rope, diameter=0.12)]),
    ):
        system = mooring.MooringSystem(body, [line] * 3, anchors, depth=200.0)
        with pytest.raises(InputError) as err:
            mooring.write_moordyn(system, tmp_path / "s.dat")
        assert err.value.argument == "lines"
        assert not (tmp_path / "s.dat").exists()


def _same_system(a, b) -> bool:
    """Whether two systems read are the same: points, lines and their segments, depth, rho, g."""
    if (a.depth, a.rho, a.g, len(a.points), len(a.mooring_lines)) != (
        b.depth,
        b.rho,
        b.g,
        len(b.points),
        len(b.mooring_lines),
    ):
        return False
    if any(
        p.kind != q.kind or not np.array_equal(p.position, q.position)
        for p, q in zip(a.points, b.points, strict=True)
    ):
        return False
    return all(
        (ha.a.index, ha.b.index, ha.model.segments[0].length)
        == (hb.a.index, hb.b.index, hb.model.segments[0].length)
        for ha, hb in zip(a.mooring_lines, b.mooring_lines, strict=True)
    )


def test_a_file_cut_anywhere_is_refused_or_is_the_whole(tmp_path):
    """Cut after any line, or in the middle of any line: read, it is refused with the file and the
    line (a section's rows end at a '---' line, and MoorDyn's files end with one), or it is the very
    system of the whole file (a cut inside its closing '--- need this line ---'), never another."""
    path = tmp_path / "cut.dat"
    path.write_text(FILE)
    whole = mooring.read_moordyn(path).system
    lines = FILE.splitlines(keepends=True)
    refused = 0
    for k in range(1, len(lines)):
        for text in ("".join(lines[:k]), "".join(lines[:k]) + lines[k][: len(lines[k]) // 2]):
            path.write_text(text)
            try:
                read = mooring.read_moordyn(path).system
            except InputError as err:
                assert str(err).split(": ", 1)[1].startswith("cut.dat"), str(err)  # the file, its line
                refused += 1
                continue
            assert _same_system(read, whole), repr(text[-80:])
    assert refused >= 2 * (len(lines) - 1) - 2


@pytest.mark.parametrize(
    "change, argument, line, reason",
    [
        (
            (
                "6     Body1     -2.5  -4.33    -2     0      0       0      0",
                "6     Body1     -2.5  -4.33    -2     0      0       0",
            ),
            "POINTS",
            20,
            "8 columns",
        ),
        (("2     rope        7        4        310", "2     rope        7        4"), "LINES", 26, "columns"),
        (("1     chain       1        7", "1     chain       1        8"), "8", 25, "no point 8"),
        (("1.2326e9", "1.2326e999"), "EA", 6, "overflows"),
        (("150           WtrDpth", "1e400         WtrDpth"), "WtrDpth", 31, "overflows"),
        (("5      0      -2     0", "5      0      -2e-999999999999999999999 0"), "Z", 18, None),
    ],
    ids=[
        "a point row short of a column",
        "a line row short",
        "a line naming a missing point",
        "EA overflows",
        "the depth overflows",
        "an underflow is a number",
    ],
)
def test_bad_rows_are_named_with_their_line(tmp_path, change, argument, line, reason):
    path = tmp_path / "bad.dat"
    assert change[0] in FILE
    path.write_text(FILE.replace(*change))
    if reason is None:  # 2e-...: a number that underflows to zero is a number, read as MoorDyn reads it
        assert mooring.read_moordyn(path).system.points[3].position[2] == 0.0
        return
    with pytest.raises(InputError) as err:
        mooring.read_moordyn(path)
    assert err.value.argument == argument and err.value.line == line, str(err.value)
    assert f"bad.dat, line {line}:" in str(err.value) and reason in str(err.value)


def test_a_byte_that_is_not_utf8_is_named_where_it_is_read(tmp_path):
    """A byte that is not UTF-8 in a number MoorDyn reads is refused with its line; in the units row or
    a comment, which nothing reads, it is left there (MoorDyn reads bytes)."""
    path = tmp_path / "bytes.dat"
    data = FILE.encode("utf-8")
    path.write_bytes(data.replace(b"600     0     -150", b"6\xff0     0     -150", 1))
    with pytest.raises(InputError) as err:
        mooring.read_moordyn(path)
    assert err.value.line == 15 and "0xff" in str(err.value) and "not UTF-8" in str(err.value)
    path.write_bytes(
        data.replace(b"(m^3)   (m^2)  (-)", b"(m\xb33)   (m^2)  (-)", 1)
    )  # a Latin-1 cube in the units
    assert len(mooring.read_moordyn(path).system.points) == 7


# -- EA as a strain–tension curve file (MoorDyn-C's ``read_curve``: three header lines, then
# ``strain tension`` rows, read beside the input file; ``moordyn::interp`` between the rows) ----
CURVE_HEADER = "strain–tension curve of the chain\nStrain Tension\n(-) (N)\n"


def _with_chain_curve(tmp_path, rows, ea="chain.txt"):
    """`FILE` with the chain's EA column ``ea`` and the curve file ``chain.txt`` of ``rows``."""
    (tmp_path / "chain.txt").write_text(CURVE_HEADER + "".join(f"{e!r} {t!r}\n" for e, t in rows))
    path = tmp_path / "curve.dat"
    path.write_text(FILE.replace("1.2326e9", ea))
    return path


def test_an_ea_curve_file_is_the_law_moordyn_interpolates(tmp_path):
    """The chain's EA as a curve file: its strain at any tension within the file's rows is the
    straight line between them (numpy's interp of the file's numbers); a curve that is the
    straight line ``T = EA ε`` gives the equilibrium of the file with the number EA (1.2326e9 N)."""
    rows = [(0.0, 0.0), (0.002, 1.0e6), (0.005, 4.0e6), (0.01, 1.2e7)]
    model = mooring.read_moordyn(_with_chain_curve(tmp_path, rows))
    law = model.system.mooring_lines[0].model.segments[0].law
    eps, T = np.array(rows).T
    probe = np.linspace(0.0, T[-1], 37)
    np.testing.assert_allclose(law.strain(probe), np.interp(probe, T, eps), rtol=1e-13, atol=1e-16)

    straight = mooring.read_moordyn(_with_chain_curve(tmp_path, [(0.0, 0.0), (0.01, 1.2326e7)]))
    number = tmp_path / "number.dat"
    number.write_text(FILE)
    eq, reference = straight.system.equilibrium(), mooring.read_moordyn(number).system.equilibrium()
    for p, q in zip(eq.points, reference.points, strict=True):
        np.testing.assert_allclose(p.position, q.position, rtol=0, atol=1e-8 * 600.0)


@pytest.mark.parametrize(
    "rows, reason",
    [
        ([(0.0, 0.0)], "fewer than two curve points"),
        ([(0.0, 0.0), (0.01, 2.0e5), (0.005, 3.0e5)], "must increase strictly"),
        ([(-0.001, 0.0), (0.01, 2.0e5)], "not at or above (0, 0)"),
        ([(0.0, 1.0e4), (0.01, 2.0e5)], "below it MoorDyn holds the first tension"),
        ([(0.002, 1.0e4), (0.01, 2.0e5)], "below it MoorDyn holds the first tension"),
        ([(0.001, 0.0), (0.01, 2.0e5)], "below it MoorDyn's tension is zero"),
        ([(0.0, 0.0), (0.01, float("inf"))], "is not finite"),
    ],
)
def test_a_curve_moordyn_would_misread_is_refused_naming_the_file(tmp_path, rows, reason):
    """A curve with fewer than two points, not increasing, not from (0, 0) or with a number
    that is not finite is refused, the message naming the input file's line (or the curve
    file's row) and the reason. Below its first row MoorDyn's ``interp`` holds the first
    tension: a curve from (0, T₀ > 0) is a rope taut when slack, one from (ε₀ > 0, 0) a rope
    slack up to ε₀."""
    with pytest.raises(InputError) as err:
        mooring.read_moordyn(_with_chain_curve(tmp_path, rows))
    message = str(err.value)
    assert reason in message and ("curve.dat, line 6" in message or "chain.txt" in message), message


def test_a_missing_or_garbled_curve_file_is_named(tmp_path):
    """A curve file that is not there, or a row of it that is not two numbers, is refused naming
    the file (and the row: MoorDyn's rows start after three header lines)."""
    path = _with_chain_curve(tmp_path, [(0.0, 0.0), (0.01, 2.0e5)], ea="none.txt")
    with pytest.raises(InputError, match=r"curve\.dat, line 6.*the curve file 'none\.txt' cannot be read"):
        mooring.read_moordyn(path)
    (tmp_path / "chain.txt").write_text(CURVE_HEADER + "0 0\n0.01 two\n")
    path.write_text(FILE.replace("1.2326e9", "chain.txt"))
    with pytest.raises(InputError, match=r"chain\.txt, line 5.*is not two numbers"):
        mooring.read_moordyn(path)
