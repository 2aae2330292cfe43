"""The calibration table: the paper tire meets its targets; a tire without targets shows its values only."""

from __future__ import annotations

import shutil

import roadnoise_utils as ru
from roadnoise_utils.repro.paths import data_dir


def test_paper_tire_meets_its_targets():
    table = ru.experiments.calibration_table("165_65R14")
    assert table["ok"].all() and (table["target"] != "-").all()
    static = ru.stages.solve_static("165_65R14")
    assert table.loc["vertical stiffness", "obtained"] == static.vertical_stiffness / 1e3


def test_a_tire_without_targets_gets_its_values_only(tmp_path):
    mine = tmp_path / "my_tire.toml"
    shutil.copy(data_dir() / "tires" / "165_65R14.toml", mine)
    table = ru.experiments.calibration_table(mine)
    assert (table["target"] == "-").all() and table["ok"].all()
    assert table.loc["n tasselli", "obtained"] == ru.stages.solve_static(mine).tasselli.n
