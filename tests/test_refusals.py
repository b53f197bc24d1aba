"""Inputs that once escaped as a bare Python or NumPy error, or were silently read
otherwise (found by fuzzing the lines, conductor and vibration code): each now raises
InputError naming its argument (or ConvergenceError)."""

import numpy as np
import pytest

from skcable import cli, conductors, mooring, strand, study
from skcable.errors import ConvergenceError, InputError


def _named(name, call):
    with pytest.raises(InputError) as info:
        call()
    assert info.value.argument == name, info.value


def test_line_refusals_name_their_argument():
    # a buoy in a line whose slack would lie in a heap: the polish of the hanging part left
    # its bracket and a TypeError escaped
    line = mooring.Line(
        [mooring.Segment(53.0, 156.0, 1e9), mooring.Segment(41.0, 894.0, 1e9)],
        [mooring.Buoy(1, 31000.0)],
        seabed=0.0,
    )
    _named("attachments", lambda: line.solve(1.0, 30.0))
    segment = mooring.Segment(100.0, 10.0, 1e8)
    _named("attachments", lambda: mooring.Line([segment], mooring.ClumpWeight(1, 5.0)))  # not a list
    _named("segments", lambda: mooring.Line(segment))


def test_seabed_bvp_refusals_name_their_argument():
    segments = [(100.0, 10.0, 1e8)]

    def bvp(**kw):
        return lambda: mooring.solve_line_bvp(80.0, 20.0, segments, **kw)

    for value in (2.7, "16", True):  # 2.7 once ran 2 elements, True escaped as a scipy ValueError
        _named("n_elements", bvp(n_elements=value))
    _named("fit_touchdown", bvp(seabed=0.0, fit_touchdown=True))
    for loads in ([(np.array([10.0, 20.0]), 5.0)], [(10.0, np.array([1.0, 2.0]))], 5):
        _named("point_loads", bvp(point_loads=loads))


@pytest.mark.filterwarnings("ignore::skcable.errors.PlausibilityWarning")  # EA = 5 N under 1e9 N/m
def test_conductor_vibration_and_section_refusals():
    section = strand.preset("acsr-drake").section()
    for axis in (1.0, np.array([0])):  # once an IndexError / TypeError
        _named("axis", lambda axis=axis: strand.strand_bending_frequencies(section, 1e3, 1.0, 1.6, axis=axis))
    _named(
        "spans",
        lambda: conductors.tension_section(
            [],
            EA=3e7,
            alpha=2e-5,
            w0=16,
            t0=15,
            H0=2e4,
            w=16,
            t=80,
            insulator_length=3.0,
            insulator_weight=700.0,
        ),
    )
    # H so large that Irvine's λ² underflows (once a ZeroDivisionError) or K overflows
    _named("H", lambda: conductors.natural_frequencies(2.5, 0.0, 1e9, 5.0, H=1e300))
    with pytest.raises((InputError, ConvergenceError)):
        conductors.natural_frequencies(2.5, 0.0, 1e3, 5.0, H=1e300, g=1e10)


def test_a_bool_inside_a_sequence_is_not_a_number():
    angles = np.radians([0.0, 120.0, 240.0])
    anchors = np.column_stack([800 * np.cos(angles), 800 * np.sin(angles), np.full(3, -200.0)])
    fairleads = np.column_stack([20 * np.cos(angles), 20 * np.sin(angles), np.full(3, -14.0)])
    line = mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0)
    body = mooring.RigidBody(fairleads, waterplane_area=600.0)
    system = mooring.MooringSystem(body, [line] * 3, anchors)
    _named("force", lambda: system.equilibrium(force=(True, 0, 0)))  # once read as 1 N


def test_cli_frequencies_out_of_range_is_no_internal_error(capsys):
    args = ["frequencies", "--span", "2.5", "--EA", "5", "--w", "1e9", "--H", "1e300", "--g", "1e300"]
    status = cli.main([*args, "--n-modes", "2"])
    assert status in (cli.EXIT_USAGE, cli.EXIT_NO_CONVERGENCE)
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_a_choice_given_as_an_unhashable_value_names_its_argument(tmp_path):
    # a list where a name is expected: looked up in a dict, it escaped as a bare TypeError
    _named("element", lambda: strand.StrandModel(strand.preset("steel-9.5"), 0.3, element=["P2"]))
    spec = tmp_path / "study.toml"
    spec.write_text('model = ["catenary"]\n[grid]\nspan = [100.0]\n')
    _named("model", lambda: study.load_study(spec))
    _named(
        "mesh",
        lambda: mooring.line_bvp.space.solve_line_bvp_3d(
            (0, 0, 0), (50, 0, 10), [(60, 10, 1e8)], mesh=["graded"]
        ),
    )
