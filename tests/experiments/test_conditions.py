"""Test conditions: a parameter left at None is the paper's test, a given value wins, a typo is named."""

from __future__ import annotations

import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments.conditions import load_conditions, resolve


def test_resolve_fills_none_from_the_table():
    table = load_conditions("cleat_test")
    filled = resolve(table, "cleat", height=None, base=0.03)
    assert filled == {"height": table["cleat"]["height"], "base": 0.03}
    with pytest.raises(KeyError, match="no value for \\['colour'\\]"):
        resolve(table, "cleat", colour=None)
    with pytest.raises(KeyError, match="no \\[wheel\\] table"):
        resolve(table, "wheel", radius=None)


def test_each_experiment_resolves_its_conditions_file():
    """The conditions objects carry the files' values (SI), overrides replace exactly what they name."""
    table = load_conditions("cleat_test")
    paper = ru.experiments.cleat_conditions()
    assert (paper.height, paper.base, paper.shape) == (
        table["cleat"]["height"],
        table["cleat"]["base"],
        table["cleat"]["shape"],
    )
    assert paper.drum_radius == table["drum"]["radius"]
    assert paper.dynamic_speed == pytest.approx(table["speeds"]["dynamic_kmh"] / 3.6)
    faster = ru.experiments.cleat_conditions(dynamic_kmh=60.0, height=0.01)
    assert (faster.dynamic_kmh, faster.height, faster.base) == (60.0, 0.01, paper.base)
    road = ru.experiments.road_test_conditions(seed=7)
    assert road.seed == 7 and road.textures == tuple(load_conditions("road_test")["textures"])
    hub = ru.experiments.suspension_conditions(stiffness=1e4)
    assert hub.stiffness == 1e4 and hub.mass == load_conditions("moving_hub_check")["hub"]["mass"]


def test_paper_defaults_of_the_top_level_entry_points(fet, drum):
    """``ru.solve_static(fet, road="drum")`` and ``ru.cleat_input(static, speed)`` are the paper's test."""
    paper = ru.experiments.cleat_conditions()
    assert drum.road.drum_radius == paper.drum_radius
    explicit = ru.road.cleat.cleat_input(drum, 5.0, paper.height, paper.base, paper.shape)
    assert (ru.cleat_input(drum, 5.0).u == explicit.u).all()
    with pytest.raises(ValueError, match="drum_radius is required"):
        ru.tire.ring.static.solve_static(fet, road="drum")


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("\nheight =", "\nheigth =", r"cleat_test.toml: \[cleat\] has unknown key\(s\) \['heigth'\]"),
        ("[cleat]", "[cleats]", r"cleat_test.toml: the file has unknown key\(s\) \['cleats'\]"),
    ],
)
def test_a_misspelt_key_of_a_conditions_file_is_refused_naming_table_and_key(tmp_path, monkeypatch, old, new, message):
    """A misspelt key was ignored before and the paper's value used in its place."""
    import shutil

    from roadnoise_utils.repro.paths import REPO_ROOT

    data = tmp_path / "data"
    shutil.copytree(REPO_ROOT / "data", data)
    path = data / "conditions" / "cleat_test.toml"
    text = path.read_text()
    assert text.count(old) == 1
    path.write_text(text.replace(old, new))
    monkeypatch.setenv("ROADNOISE_DATA_DIR", str(data))
    with pytest.raises(ValueError, match=message):
        ru.experiments.cleat_conditions()
