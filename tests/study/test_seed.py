"""The seed study (Pino Vidal 2021, Tables 4.1 and 4.2) gives 16 of 16 cases, each the capacity
curve of the strand model computed directly."""

from pathlib import Path

import pytest

import skcable
from skcable import strand, study

SEED = Path(skcable.__file__).resolve().parents[1] / "studies" / "pino_vidal_2021_tables_4_1_4_2.toml"


@pytest.fixture(scope="module")
def seed_table():
    spec = study.load_study(SEED)
    return spec, study.run(spec["model"], spec["cases"], executor="serial", progress=False)


def test_seed_study_gives_16_of_16(seed_table):
    spec, table = seed_table
    assert len(table) == 16 and table.status.tolist() == ["ok"] * 16
    assert table[["preset", "damage", "slip"]].to_dict("records") == [
        {k: c[k] for k in ("preset", "damage", "slip")} for c in spec["cases"]
    ]


@pytest.mark.parametrize("row", [0, 7, 10, 13])  # a case of each strand, both damages, both models
def test_seed_rows_are_the_strand_models_curves(seed_table, row):
    _, table = seed_table
    case = table.iloc[row]
    strand_ = strand.preset(case.preset).damaged(int(case.damage))
    curve = strand.StrandModel(strand_, case.length, slip=case.slip, mu=case.mu).capacity_curve()
    assert case.K_Leq == curve.K_Leq and case.D_r == curve.D_r and case.toughness == curve.toughness
    assert case.rupture_force == curve.force[-1] and case.rupture_strain == curve.strain[-1]
