"""The conductor catalogue: masses and diameters as the standards print them, the strands built
from the stranding against those masses (an independent check of every entry's geometry),
refusals with the nearest names, and results in % RTS."""

import numpy as np
import pytest

from skcable import conductors, strand
from skcable.conductors import catalogue
from skcable.errors import InputError

G = 9.80665
LB_KFT = 0.45359237 / 304.8  # kg/m per lb/1000 ft

# The published masses (lb/1000 ft), typed from the tables: ASTM B232/B232M Table 1 (ACSR, row of
# the code word), ASTM B231/B231M Table 1 (AAC), ASTM B399/B399M Table 1 (AAAC).
PUBLISHED = {
    "acsr-turkey": 36.0, "acsr-swan": 57.4, "acsr-sparrow": 91.3, "acsr-raven": 145.2,
    "acsr-quail": 183.1, "acsr-pigeon": 230.6, "acsr-penguin": 291.1, "acsr-partridge": 367.3,
    "acsr-linnet": 463.2, "acsr-ibis": 547.3, "acsr-hawk": 656, "acsr-dove": 766,
    "acsr-grosbeak": 874, "acsr-drake": 1094, "acsr-rail": 1075, "acsr-cardinal": 1229,
    "acsr-falcon": 2044, "aac-tulip": 316, "aac-arbutus": 746, "aac-magnolia": 896,
    "aac-marigold": 1046, "aaac-alton": 45.4, "aaac-ames": 72.2, "aaac-azusa": 114.9,
    "aaac-butte": 291.6, "aaac-canton": 367.9, "aaac-darien": 521.7, "aaac-flint": 690.8,
    "aaac-greeley": 864.6,
}  # fmt: skip


def test_catalogue_masses_are_the_published_ones():
    table = catalogue()
    assert set(table.index) == set(PUBLISHED) and set(table["kind"]) == {"ACSR", "AAC", "AAAC"}
    for name, lb in PUBLISHED.items():
        decimals = len(str(lb).split(".")[1]) if "." in str(lb) else 0
        printed = round(table.loc[name, "mass_kg_km"] / 1e3 / LB_KFT, decimals)
        assert printed == lb, name
        assert name.split("-")[1].capitalize() in table.loc[name, "source"]


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_the_strand_of_each_size_weighs_and_measures_what_the_table_prints(name):
    """Independent of the typed mass: the wires of the stranding (diameters, counts, lay) and
    the materials' densities give the printed mass within 0.5 % and the printed diameter within
    0.2 % (the standards' stranding increments differ from these presets' lay ratios by that)."""
    s = strand.preset(name)
    c = conductors.Conductor.from_strand(s)
    mass = PUBLISHED[name] * LB_KFT
    assert c.w / G == pytest.approx(mass, rel=5e-3)
    assert s.diameter == pytest.approx(catalogue().loc[name, "diameter_mm"] / 1e3, rel=2e-3)


def test_from_catalogue_reports_percent_rts():
    drake = conductors.Conductor.from_catalogue("acsr-drake")
    assert drake.rts == pytest.approx(31500 * 4.4482216152605, rel=1e-15)
    assert drake.w == pytest.approx(1094 * LB_KFT * G, rel=1e-15)
    assert drake.EA == conductors.Conductor.from_strand(strand.preset("acsr-drake")).EA
    r = drake.change_of_state(400.0, t0=15.0, H0=28e3, t=[-20.0, 75.0])
    np.testing.assert_allclose(r.T_max_pct_rts, 100 * r.T_max / drake.rts, rtol=1e-15)
    table = drake.sag_tension_table(400.0, t0=15.0, H0=28e3, temperatures=[15.0])
    assert table["T_max_pct_rts"].iloc[0] == pytest.approx(100 * table["T_max"].iloc[0] / drake.rts)
    assert 19.5 < table["T_max_pct_rts"].iloc[0] < 21.0  # 28 kN is 20 % of Drake's 140.1 kN


@pytest.mark.parametrize(
    "bad, near", [("acsr-drak", "acsr-drake"), ("aac-arbutis", "aac-arbutus"), ("Drake", None)]
)
def test_an_unknown_name_is_refused_with_the_nearest(bad, near):
    for build in (conductors.Conductor.from_catalogue, strand.preset):
        with pytest.raises(InputError) as info:
            build(bad)
        assert info.value.argument == "name"
        if near:
            assert near in str(info.value)
    with pytest.raises(InputError) as info:
        catalogue(kind="ACSS")
    assert info.value.argument == "kind"
