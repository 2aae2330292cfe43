"""Cached stages: an edited conditions, tire or road file invalidates exactly the stages that read it."""

from __future__ import annotations

import re
import shutil

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro import cache
from roadnoise_utils.repro.paths import data_dir


@pytest.fixture
def data_copy(tmp_path, monkeypatch):
    """A copy of ``data/`` the test may edit, used in place of the real one, and an empty stage cache."""
    copy = tmp_path / "data"
    shutil.copytree(data_dir(), copy)
    monkeypatch.setenv("ROADNOISE_DATA_DIR", str(copy))
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("ROADNOISE_CACHE", raising=False)
    return copy


def _computed_during(action) -> tuple[object, set[str]]:
    """The result of ``action()`` and the stages it computed (not loaded from the cache)."""
    before = cache.STATS.copy()
    result = action()
    after = cache.STATS
    return result, {stage for (stage, kind), n in after.items() if kind == "computed" and n > before[stage, kind]}


def _fe_cleat_peak() -> float:
    return float(ru.experiments.cleat_test("165_65R14", fe_reference=True).fe_reference.fe_force.max())


def test_editing_the_cleat_conditions_recomputes_only_the_cleat_response(data_copy):
    """The issue's stale-cache case: shape = "rectangle" in the conditions file must change the FE cleat force."""
    triangle, computed = _computed_during(_fe_cleat_peak)
    assert computed == {"solve_static", "frf_visco", "fit_tasselli", "fe_cleat_response"}
    conditions = data_copy / "conditions" / "cleat_test.toml"
    conditions.write_text(conditions.read_text().replace('shape = "triangle"', 'shape = "rectangle"'))
    rectangle, computed = _computed_during(_fe_cleat_peak)
    assert computed == {"fe_cleat_response"}  # the drum's static state, FRFs and fits are reused
    # a rectangle of the same base and height carries twice the area: the linear force roughly doubles
    assert 1.5 < rectangle / triangle < 2.2


def test_a_comment_in_the_tire_file_changes_nothing_a_value_changes_every_stage(data_copy, tire):
    tire_file = data_copy / "tires" / "165_65R14.toml"
    text = tire_file.read_text()
    reference = ru.stages.solve_static(tire_file)
    tire_file.write_text("# an edited comment\n" + text)
    same, computed = _computed_during(lambda: ru.stages.solve_static(tire_file))
    assert computed == set() and same.deflection == reference.deflection
    stiffer = 1.2 * tire.tread.normal_stiffness_per_area
    edited = re.sub(r"^normal_stiffness_per_area = \S+", f"normal_stiffness_per_area = {stiffer!r}", text, flags=re.M)
    tire_file.write_text(edited)
    assert ru.load_tire(tire_file).tread.normal_stiffness_per_area == stiffer
    loaded, computed = _computed_during(lambda: ru.stages.solve_static(tire_file))
    assert computed == {"solve_static"} and loaded.deflection < reference.deflection


def test_editing_a_road_file_recomputes_no_tire_stage(data_copy):
    """Textures are read by the road test, not by any cached stage: 4x the PSD is 2x every tassello input."""
    short = ru.experiments.road_test_conditions(duration=0.3, textures=["rough"])
    before = ru.experiments.road_test("195_65R15", short).inputs["rough"].u
    texture = data_copy / "roads" / "rough.toml"
    lines = texture.read_text().splitlines()
    assert any(line.startswith("iso_class") for line in lines)
    psd = ru.textures.load_texture(texture).reference_psd
    edited = [f"reference_psd = {4 * psd!r}" if line.startswith("iso_class") else line for line in lines]
    texture.write_text("\n".join(edited) + "\n")
    after, computed = _computed_during(lambda: ru.experiments.road_test("195_65R15", short).inputs["rough"].u)
    assert computed == set()
    assert np.allclose(after, 2 * before, rtol=1e-9, atol=1e-12)
