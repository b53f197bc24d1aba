"""``skcable conductor vibration``: JSON equal to the API, a table with units, one-line errors
naming the flag."""

import json

import numpy as np
import pytest

from skcable import cli, conductors, strand
from skcable.cli import _vibration


def main(capsys, *args):
    status = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


def test_json_is_the_api(capsys):
    flags = "--tension 28e3 --f-min 10 --f-max 40 --n-frequencies 4 --damage 3 --axis 2 --damping foti"
    status, out, err = main(
        capsys, "conductor", "vibration", *flags.split(), "--hours-per-year", "1000", "--json"
    )
    assert status == 0 and err == ""
    values = json.loads(out)
    f = np.linspace(10.0, 40.0, 4)
    api = conductors.aeolian_vibration(
        strand.preset("acsr-drake"),
        28e3,
        f,
        damage=3,
        axis=1,
        damping="foti",
        hours_per_year=np.full(4, 250.0),
    )
    assert values["f_Hz"] == f.tolist()
    assert values["y_max_m"] == api.y_max.tolist()
    assert values["Y_b_peak_to_peak_m"] == api.Y_b.tolist()
    assert values["sigma_a_Pa"] == api.sigma_a.tolist()
    assert values["knees_per_m"] == api.law.kappa_slip[1].tolist()
    assert values["life_years"] == api.life_years


def test_table_with_units_and_the_strouhal_band(capsys):
    status, out, err = main(capsys, "conductor", "vibration", "--tension", "28e3", "--n-frequencies", "3")
    assert status == 0 and err == ""
    assert "Y_b p-p [m]" in out and "sigma_a [Pa]" in out and "EI_max = " in out and "N·m²" in out
    d = strand.preset("acsr-drake").diameter
    assert f"{0.185 / d:.10g}" in out and f"{0.185 * 7 / d:.10g}" in out  # 1 and 7 m/s, Strouhal
    assert "life" not in out  # no hours, no life


def test_the_wind_models_are_the_librarys():
    assert _vibration.WIND_MODELS == conductors.WIND_MODELS


@pytest.mark.parametrize(
    ("args", "flag"),
    [
        (("--tension", "-1"), "--tension"),
        (("--tension", "28e3", "--damage", "40"), "--damage"),
        (("--tension", "28e3", "--preset", "acsr-drak"), "--preset"),
        (("--tension", "28e3", "--mu", "-0.5"), "--mu"),
        (("--tension", "28e3", "--turbulence", "-0.1"), "--turbulence"),
        (("--tension", "28e3", "--hours-per-year", "9000"), "--hours-per-year"),
        (("--tension", "28e3", "--f-min", "10", "--f-max", "5"), "--f-min"),
        (("--tension", "28e3", "--wind", "karman"), "--wind"),
        (("--tension", "28e3", "--axis", "3"), "--axis"),
    ],
)
def test_errors_name_the_flag(capsys, args, flag):
    status, out, err = main(capsys, "conductor", "vibration", *args)
    assert status == cli.EXIT_USAGE and out == ""
    assert err.count("\n") == 1 and flag in err and "Traceback" not in err, err


def test_the_group_alone_says_what_to_choose(capsys):
    status, out, err = main(capsys, "conductor")
    assert status == cli.EXIT_USAGE and "'vibration'" in err and "choose 'table'" in err
