"""``skcable mooring FILE`` and the TOML system file: the command's numbers are the API's, a bad
file is refused in one line naming the key, never a traceback."""

import json
from pathlib import Path

import numpy as np
import pytest

from skcable import cli, mooring
from skcable.errors import InputError
from skcable.mooring.system_file import read_system

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(uplift_angle|position)\\b:skcable.errors.PlausibilityWarning"
)

DATA = Path(__file__).resolve().parents[1] / "data"


def test_toml_system_equals_the_one_built_by_hand():
    described = read_system(DATA / "spread_system.toml")
    eq = described.system.equilibrium(force=described.force, moment=described.moment)
    hand = mooring.MooringSystem(depth=200.0)
    hull = hand.add_body(
        mooring.RigidBody(
            mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5), metacentre=(0, 0, 10), waterplane_area=600.0
        )
    )
    line = mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)])
    for h in np.radians([0.0, 120.0, 240.0]):
        c, s = np.cos(h), np.sin(h)
        hand.add_line(
            line,
            hand.add_point([800 * c, 800 * s, -200.0], fixed=True),
            hand.add_point([20 * c, 20 * s, -14.0], body=hull),
        )
    ref = hand.equilibrium(force={hull: (2e6, 5e5, 0.0)})
    np.testing.assert_allclose(eq.position, ref.position, rtol=0, atol=1e-9)


def test_cli_mooring_json_equals_the_api(capsys):
    status = cli.main(["mooring", str(DATA / "spread_system.toml"), "--json"])
    out, err = capsys.readouterr()
    assert status == 0 and err == ""
    values = json.loads(out)
    described = read_system(DATA / "spread_system.toml")
    eq = described.system.equilibrium(force=described.force, moment=described.moment)
    assert values["bodies"][0] == eq.bodies[0].position.tolist()
    assert [r["T_b"] for r in values["lines"]] == [line.tension_b for line in eq.lines]
    assert values["stiffness"] == eq.stiffness(condensed=True).tolist()
    assert [r["horizontal"] for r in values["anchors"]] == eq.anchor_loads()["horizontal"].tolist()


def test_cli_mooring_reads_a_moordyn_file_and_writes_vtk(capsys, tmp_path):
    from tests.mooring.test_moordyn import FILE

    path = tmp_path / "buoy.dat"
    path.write_text(FILE)
    status = cli.main(["mooring", str(path), "--vtk", str(tmp_path / "buoy.vtu")])
    out, err = capsys.readouterr()
    assert "body 0 x" in out and "uplift" in out
    # the file's buoy (300 m³, 100 t, no waterplane) rises out of the water on its slack lines, its
    # buoyancy kept: solved, with that warning (issue 31)
    assert status == cli.EXIT_WARNINGS and "position: puts body 0 clear of the water" in err
    assert (tmp_path / "buoy.vtu").stat().st_size > 1000


@pytest.mark.parametrize(
    "text, keyword",
    [
        ("depth = 100.0\nwibble = 1\n", "wibble"),
        ('[[points]]\nname = "p"\nposition = [0, 0, -10]\ncolour = "red"\n', "colour"),
        ('[[lines]]\na = "x"\nb = "y"\nsegments = []\n', "x"),
    ],
)
def test_a_bad_toml_file_is_refused_by_name(tmp_path, capsys, text, keyword):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(InputError) as err:
        read_system(path)
    assert err.value.argument == keyword
    status = cli.main(["mooring", str(path)])
    out, err_text = capsys.readouterr()
    assert status == cli.EXIT_USAGE and out == "" and len(err_text.strip().splitlines()) == 1
    assert keyword in err_text
