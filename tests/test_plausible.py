"""Plausibility warnings (issue 25, item 5): data that solve but that a unit slip explains
warn once, naming the argument and the likely unit mistake; ordinary scenes stay quiet; the
command line prints each warning as one line and still exits 0."""

import re
import warnings
from pathlib import Path

import numpy as np
import pytest

from skcable import _plausible, cable, cli, conductors, mooring, strand
from skcable.errors import InputError, PlausibilityWarning

STATE = dict(alpha=2.3e-5, w0=15.0, t0=15.0, H0=2e4, w=[15.0, 25.0], t=[-20.0, 60.0])


def _ratio(warning) -> float:
    """The first number of a warning's message."""
    return float(re.search(r"[-+]?\d[\d.]*(?:e[-+]?\d+)?", str(warning.message)).group())


def test_ea_typed_in_mn_for_a_conductor():
    # issue 25: EA = 30 (MN) gave a 0.45 m unstressed length for a 300 m span
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = conductors.change_of_state(300.0, 0.0, EA=30.0, **STATE)
    assert re.match(r"^EA: .*MN", str(caught[0].message))
    assert res.L0 < 1.0  # solved: it is a warning, not a refusal
    # EA and the answer's strain T_max / EA, far beyond a conductor's 5 %: one line each
    assert {w.message.argument for w in caught} == {"EA", "T_max"}
    ea = [w for w in caught if w.message.argument == "EA"]
    assert {str(w.message) for w in ea} == {str(ea[0].message)}  # one line, however many solves
    assert 30.0 < 0.01 * 25.0 * 300.0 and _ratio(ea[0]) == 30.0


@pytest.mark.filterwarnings("ignore:(strain|uplift_angle)\\b:skcable.errors.PlausibilityWarning")
def test_ea_below_the_weight_of_a_line():
    with pytest.warns(PlausibilityWarning, match=r"^EA: ") as caught:
        cable.elastic_catenary(800.0, -20.0, 20.0, 100.0, length=810.0)  # 100 N under 16 kN
    assert 100.0 < 0.01 * 20.0 * 810.0 and _ratio(caught[0]) == 100.0
    with pytest.warns(PlausibilityWarning, match=r"^EA: "):
        mooring.Segment(850.0, 1000.0, 500.0)  # 5e8 N typed in MN
    with pytest.warns(PlausibilityWarning, match=r"^EA: "):
        cable.elastic_catenary(800.0, 150.0, 1000.0, 500.0, length=850.0, seabed=0.0)


def test_sag_typed_in_mm():
    # issue 25: --sag 6000 for a 250 m span gave an effective length of 3.8e8 m
    with pytest.warns(PlausibilityWarning, match=r"^sag: .*mm") as caught:
        conductors.natural_frequencies(250.0, 0.0, 1.2, 2e7, sag=6000.0)
    assert _ratio(caught[0]) == pytest.approx(6000.0 / 250.0, rel=1e-2)
    with pytest.warns(PlausibilityWarning, match=r"^sag: "):
        conductors.change_of_state(
            250.0, 0.0, EA=2e7, alpha=2.3e-5, w0=12.0, t0=15.0, sag0=300.0, w=12.0, t=15.0
        )


def test_alpha_typed_in_micro_per_kelvin():
    # alpha 23 (1e-6/K meant): a thermal strain of 23 per kelvin is refused, naming alpha (not t)
    with pytest.raises(InputError) as info:
        conductors.change_of_state(300.0, 0.0, EA=3e7, **dict(STATE, alpha=23.0, t=[15.0, 16.0]))
    assert info.value.argument == "alpha"
    with pytest.raises(InputError) as info:  # colder than t0 as well
        conductors.change_of_state(300.0, 0.0, EA=3e7, **dict(STATE, alpha=23.0))
    assert info.value.argument == "alpha"
    # alpha in 1e-4/K, a strain of 0.1 over 40 K: it solves, and warns naming alpha
    warm = dict(STATE, alpha=2.5e-3, t=[15.0, 55.0])
    with pytest.warns(PlausibilityWarning, match=r"^alpha: .*23e-6") as caught:
        conductors.change_of_state(300.0, 0.0, EA=3e7, **warm)
    strain = float(re.search(r"up to ([-+.\de]+),", str(caught[0].message)).group(1))
    assert strain == pytest.approx(2.5e-3 * (55.0 - 15.0), rel=1e-2)


@pytest.mark.parametrize(
    "alpha, t, t0, blamed",
    [
        (23.0, -20.0, 15.0, "alpha"),
        (2.3e-5, -1e5, 15.0, "t"),
        (-1e-5, 15.0, -1e6, "t0"),
        (-1e-5, 2e5, 0, "t"),
    ],
)
def test_the_argument_blamed_for_a_negative_thermal_factor(alpha, t, t0, blamed):
    assert 1 + alpha * (t - t0) <= 0
    assert _plausible.thermal_argument(alpha, np.asarray(t), t0) == blamed


def test_strand_strain_typed_in_per_cent():
    model = strand.StrandModel(strand.preset("steel-9.5"), 0.3, n_elements=8)
    limit = 1.5 * max(m.eps_rupture for m in model.strand.materials)  # 0.123 for this steel
    with pytest.warns(PlausibilityWarning, match=r"^max_strain: .*per cent"):
        model.capacity_curve(max_strain=1.0, n_steps=4)  # 1 %, typed as 1
    with pytest.warns(PlausibilityWarning, match=r"^strain: "):
        model.solve(0.2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        model.solve(0.06)  # between 5 % and the rupture: a wire's plastic range, no warning
        model.capacity_curve(max_strain=limit, n_steps=4)


def test_ordinary_scenes_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cable.catenary(800.0, -20.0, 20.0, low=-30.0)
        cable.catenary(1.0, 0.0, 1.0, sag=5.0)  # a slack rope hangs deeper than its span: exact
        cable.parabola(200.0, 0.0, 1.0, sag=20.0)
        cable.elastic_catenary(800.0, -20.0, 20.0, 1e12, length=801.409)
        cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.5)
        line = mooring.Line(
            [mooring.Segment(300.0, 1000.0, 5e8), mooring.Segment(250.0, 400.0, 2e8)], seabed=0.0
        )
        line.solve(500.0, 150.0)
        conductors.change_of_state(300.0, 0.0, EA=3e7, **STATE)
        conductors.sag_tension_table(
            400.0, 0.0, EA=3e7, alpha=1.9e-5, w0=16.0, t0=15.0, H0=28e3,
            temperatures=[-20.0, 15.0, 75.0], load_cases={"ice": (25.0, 0.0)},
        )  # fmt: skip
        conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0)
        strand.preset("steel-9.5").damaged(1).bending_law(mu=0.5, axial_strain=0.004)


def test_cli_prints_the_warning_naming_the_flag_and_exits_5(capsys):
    args = ["change-of-state", "--span", "300", "--EA", "30", "--alpha", "2.3e-5", "--w0", "15"]
    status = cli.main([*args, "--t0", "15", "--H0", "2e4", "--w", "15", "25", "--t", "-20", "60"])
    out, err = capsys.readouterr()
    assert status == cli.EXIT_WARNINGS == 5 and "L0" in out
    lines = err.splitlines()
    assert lines[0].startswith("skcable: warning: --EA: ") and "MN" in lines[0]
    assert len(lines) == 2 and lines[1].startswith("skcable: warning: T_max: is a strain of ")
    status = cli.main(
        ["frequencies", "--span", "250", "--EA", "2e7", "--w", "1.2", "--sag", "6000", "--json"]
    )
    out, err = capsys.readouterr()
    assert status == cli.EXIT_WARNINGS and "f_in_plane" in out
    assert err.startswith("skcable: warning: --sag: ") and err.count("\n") == 1


def test_cli_alpha_is_blamed_not_t(capsys):
    args = ["change-of-state", "--span", "300", "--EA", "3e7", "--alpha", "23", "--w0", "15", "--t0", "15"]
    status = cli.main([*args, "--H0", "2e4", "--w", "15", "25", "--t", "-20", "60"])
    err = capsys.readouterr().err
    assert status == cli.EXIT_USAGE and err.startswith("skcable: error: --alpha: ") and err.count("\n") == 1


# -- answers (issue 31): each absurd scene warns naming the quantity, its value and the limit ---------


def _spread(length):
    """The README's spread mooring, its chains ``length`` long (850 m there)."""
    heading = np.radians([0.0, 120.0, 240.0])
    ring = np.column_stack([np.cos(heading), np.sin(heading), np.zeros(3)])
    body = mooring.RigidBody(
        20.0 * ring + [0.0, 0.0, -14.0], mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5),
        metacentre=(0, 0, 10), waterplane_area=600.0,
    )  # fmt: skip
    leg = mooring.Line([mooring.Segment(length, 2456.82, 1.2326e9)], seabed=0.0)
    return mooring.MooringSystem(body, [leg] * 3, 800.0 * ring + [0.0, 0.0, -200.0], depth=200.0)


def test_a_spread_mooring_with_a_digit_dropped_is_not_stable():
    # 85 m chains on 800 m spans: Newton finds a positive-definite equilibrium at ~800 % strain
    with pytest.warns(PlausibilityWarning, match=r"^strain: is a strain of .* on line \d") as caught:
        eq = _spread(85.0).equilibrium(force=(2e6, 0.0, 0.0))
    assert eq.positive_definite and not eq.stable
    assert {q for q, _ in eq.implausible} == {"strain"} and len(eq.implausible) == 3
    # the strain recounted here: the chord of each line over its length, at least (it is straight)
    chords = np.linalg.norm(eq.anchors - eq.fairleads, axis=1)
    strain = float(re.search(r"strain of ([\d.e+]+) %", str(caught[0].message)).group(1)) / 100
    assert strain == pytest.approx(chords[0] / 85.0 - 1, rel=2e-3) and "50 %" in str(caught[0].message)
    with warnings.catch_warnings():  # the README's own: silent and stable
        warnings.simplefilter("error")
        assert _spread(850.0).equilibrium(force=(2e6, 0.0, 0.0)).stable


def test_a_catenary_at_100_per_cent_strain_warns():
    with pytest.warns(PlausibilityWarning, match=r"^strain: is a strain of 100 %.* 50 %"):
        c = cable.elastic_catenary(100.0, 0.0, 10.0, 1e7, length=50.0)
    assert c.T_A / 1e7 == pytest.approx(100.0 / 50.0 - 1.0, rel=1e-3)  # the stretch of a taut line


MATERIAL_SCENES = [("chain", 0.3, True), ("chain", 0.2, False), ("wire rope", 0.06, True),
                   ("synthetic rope", 0.6, False), (None, 0.6, True)]  # fmt: skip


@pytest.mark.parametrize("material, strain, warns", MATERIAL_SCENES)
def test_a_segment_is_held_to_its_materials_strain(material, strain, warns):
    EA, span = 1e8, 100.0
    line = mooring.Line([mooring.Segment(span / (1 + strain), 10.0, EA, material=material)])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = line.solve(span, 0.0)
    assert r.T_B / EA == pytest.approx(strain, rel=1e-3)  # a taut, nearly straight line: T = EA strain
    named = [w for w in caught if issubclass(w.category, PlausibilityWarning)]
    assert bool(named) == warns
    if warns:
        assert named[0].message.argument == "strain" and (material or "unknown") in str(named[0].message)


@pytest.mark.parametrize("last_strain, warns", [(0.005, True), (0.02, False)])
def test_a_tension_beyond_the_strain_tension_table_warns(last_strain, warns):
    """A line stretched 1 % on a table that ends at 0.5 % is solved on the table's end slope, which
    no point of the data backs (MoorDyn holds the last tension there): it warns, naming its
    tension; on a table that reaches 2 % it does not."""
    EA, span, strain = 1e8, 100.0, 0.01
    law = mooring.axial.StrainTable([0.0, last_strain], [0.0, EA * last_strain], interpolation="linear")
    line = mooring.Line([mooring.Segment(span / (1 + strain), 10.0, law)])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = line.solve(span, 0.0)
    assert r.T_B / EA == pytest.approx(strain, rel=1e-3)  # a taut, nearly straight line: T = EA strain
    named = [w for w in caught if issubclass(w.category, PlausibilityWarning)]
    assert [w.message.argument for w in named] == (["tension"] if warns else [])
    if warns:
        assert _ratio(named[0]) == pytest.approx(r.T_B, rel=1e-5) and f"({EA * last_strain:.6g} N)" in str(
            named[0].message
        )


def test_an_anchor_on_the_seabed_pulled_up(capsys):
    args = ["line", "--span", "900", "--dh", "150", "--length", "850", "--w", "1000", "--EA", "5e8"]
    status = cli.main([*args, "--seabed", "0"])
    out, err = capsys.readouterr()
    assert status == cli.EXIT_WARNINGS and "H" in out
    assert err.startswith("skcable: warning: uplift_angle: is 8.81° at the anchor A") and "5°" in err
    r = mooring.Line([mooring.Segment(850.0, 1000.0, 5e8)], seabed=0.0)
    with pytest.warns(PlausibilityWarning, match=r"^uplift_angle: is 8\.81°"):
        r = r.solve(900.0, 150.0)
    assert np.degrees(np.arctan2(-r.V_A, r.H_A)) == pytest.approx(8.81, abs=5e-3) and r.V_A < -5e6
    assert cli.main([*args, "--seabed", "0", "--strict"]) == cli.EXIT_USAGE
    out, err = capsys.readouterr()
    assert out == "" and err.startswith("skcable: error: uplift_angle: ") and "(--strict)" in err
    with pytest.warns(PlausibilityWarning, match=r"^uplift_angle: "):
        cable.elastic_catenary(900.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0)


def test_a_buoy_risen_out_of_the_water_keeps_no_buoyancy():
    # a submerged buoy (no waterplane) on slack chains: nothing holds it below the surface
    heading = np.radians([0.0, 120.0, 240.0])
    anchors = 300.0 * np.column_stack([np.cos(heading), np.sin(heading), np.zeros(3)]) + [0, 0, -150.0]
    leg = mooring.Line([mooring.Segment(400.0, 300.0, 1e9)], seabed=0.0)
    system = mooring.MooringSystem(mooring.PointBody(mass=1e5, volume=300.0), [leg] * 3, anchors, depth=150.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        eq = system.equilibrium(start=[0.0, 0.0, -20.0])
    z = float(eq.position[2])
    assert z > 0 and not eq.stable and eq.positive_definite
    body = [w for w in caught if w.message.argument == "position"]
    assert (
        len(body) == 1
        and f"z = {z:.4g} m" in str(body[0].message)
        and "clear of the water" in str(body[0].message)
    )


def test_a_temperature_in_kelvin(capsys):
    with pytest.warns(
        PlausibilityWarning, match=r"^t: is 323 °C, outside .*-60 to 250 °C.*kelvin .*49\.85 °C"
    ):
        conductors.change_of_state(300.0, 0.0, EA=3e7, **dict(STATE, w=15.0, t=323.0))
    args = [
        "change-of-state",
        "--span",
        "300",
        "--EA",
        "3e7",
        "--alpha",
        "2.3e-5",
        "--w0",
        "15",
        "--t0",
        "15",
    ]
    assert cli.main([*args, "--H0", "2e4", "--w", "15", "--t", "323"]) == cli.EXIT_WARNINGS
    assert capsys.readouterr().err.startswith("skcable: warning: --t: is 323 °C")


def test_gravity_and_friction_out_of_range(capsys):
    with pytest.warns(PlausibilityWarning, match=r"^g: is 9810 m/s², not the Earth's \(9.7 to 9.9"):
        conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0, g=9810.0)
    status = cli.main(
        ["frequencies", "--span", "250", "--EA", "2e7", "--w", "12", "--sag", "6", "--g", "9810"]
    )
    assert status == cli.EXIT_WARNINGS and capsys.readouterr().err.startswith(
        "skcable: warning: --g: is 9810"
    )
    with pytest.warns(PlausibilityWarning, match=r"^friction: is a friction coefficient of 50, beyond 5"):
        cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=50.0)
    with pytest.warns(PlausibilityWarning, match=r"^mu: is a friction coefficient of 50"):
        cable.capstan(100.0, 50.0, np.pi)
    with pytest.warns(PlausibilityWarning, match=r"^g: "):
        mooring.PointBody(volume=1.0, g=32.2)


def test_every_limit_has_a_reason_and_a_source():
    assert all(len(row) == 4 and all(isinstance(v, str) and v for v in row) for row in _plausible.LIMITS)
    assert set(_plausible.STRAIN_LIMITS) == {*_plausible.MATERIALS, None}


def test_the_answer_checks_leave_inner_solves_alone():
    # a Line solved inside an equilibrium is a trial, not an answer: only the outermost call warns
    with _plausible.quiet(), warnings.catch_warnings():
        warnings.simplefilter("error")
        cable.elastic_catenary(100.0, 0.0, 10.0, 1e7, length=50.0)
    assert _plausible.outermost()


README = Path(__file__).resolve().parents[1] / "README.md"


def test_the_readmes_examples_are_silent(tmp_path):
    """The README's Python blocks, run as a script under ``-W error::...PlausibilityWarning``
    (a fresh interpreter: the suite's own filter plays no part), and its commands exit 0."""
    import subprocess
    import sys

    from tests.test_docs import python_blocks

    script = tmp_path / "readme.py"
    script.write_text("\n\n".join(block.source for block in python_blocks(README)))
    run = subprocess.run(
        [sys.executable, "-W", "error::skcable.errors.PlausibilityWarning", str(script)],
        cwd=tmp_path, capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr[-2000:]
    text = README.read_text()
    commands = [
        line.split("#")[0].split() for line in text.splitlines()
        if line.startswith("skcable ") and not line.startswith(("skcable demo", "skcable strand capacity"))
    ]  # fmt: skip
    assert len(commands) >= 8
    for argv in commands:
        argv = [a if not a.endswith((".vtu", "/")) else str(tmp_path / a) for a in argv[1:]]
        assert cli.main(argv) == cli.EXIT_OK, argv
