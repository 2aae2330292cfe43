"""Cached stages: an edited conditions, tire or road file invalidates exactly the stages that read it;
the tire file's model chooses the numerics behind them."""

from __future__ import annotations

import re
import shutil

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro import cache, stages
from roadnoise_utils.repro.paths import data_dir
from roadnoise_utils.tire.cross_section.static import SectionStaticState


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
    """The issue's stale-cache case: shape = "rectangle" in the conditions file must change the FE cleat
    force and the RM chain's runs (both cached), nothing else."""
    triangle, computed = _computed_during(_fe_cleat_peak)
    assert computed == {"solve_static", "frf_visco", "fit_tasselli", "cleat_runs", "fe_cleat_response"}
    conditions = data_copy / "conditions" / "cleat_test.toml"
    conditions.write_text(conditions.read_text().replace('shape = "triangle"', 'shape = "rectangle"'))
    rectangle, computed = _computed_during(_fe_cleat_peak)
    assert computed == {"cleat_runs", "fe_cleat_response"}  # the drum's static state, FRFs and fits are reused
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
    """A texture file feeds only the generated road (its own stage), no tire stage: 4x the PSD is 2x every tassello input."""
    short = ru.experiments.road_test_conditions(duration=0.3, textures=["rough"])
    before = ru.experiments.road_test("195_65R15", short).inputs["rough"].u
    texture = data_copy / "roads" / "rough.toml"
    lines = texture.read_text().splitlines()
    assert any(line.startswith("iso_class") for line in lines)
    psd = ru.textures.load_texture(texture).reference_psd
    edited = [f"reference_psd = {4 * psd!r}" if line.startswith("iso_class") else line for line in lines]
    texture.write_text("\n".join(edited) + "\n")
    after, computed = _computed_during(lambda: ru.experiments.road_test("195_65R15", short).inputs["rough"].u)
    assert computed == {"texture_road"}
    assert np.allclose(after, 2 * before, rtol=1e-9, atol=1e-12)


CROSS_SECTION = "165_65R14_cross_section"


def test_the_stages_run_the_tire_model_its_file_names():
    """A cross-section tire file runs its own static and footprint solves behind the same stage
    functions, and a stage whose capability it lacks says so before any work."""
    static = stages.solve_static(CROSS_SECTION)
    assert isinstance(static, SectionStaticState) and ru.tire_model(CROSS_SECTION).kind == "cross-section"
    visco = stages.frf_visco(CROSS_SECTION)
    assert visco.H.shape == (static.tasselli.n, stages.DEFAULT_FREQS.size)
    part, computed = _computed_during(lambda: stages.frf_visco(CROSS_SECTION, freqs=[0.0, 80.0, 250.0]))
    assert computed == set()  # read from the default grid: the contact points' FRFs as stored
    np.testing.assert_array_equal(part.H_points, visco.H_points[:, [0, 80, 250]])
    # the tassello sums are one BLAS product over the frequencies: its summation order (so its
    # last bit) depends on the product's shape and the BLAS build
    np.testing.assert_allclose(part.H, visco.H[:, [0, 80, 250]], rtol=1e-13, atol=1e-13 * np.abs(visco.H).max())
    assert stages.rim_side_mass(CROSS_SECTION) == 0.0 < stages.rim_side_mass("165_65R14")
    with pytest.raises(ValueError, match="stick = True"):
        stages.frf_visco(CROSS_SECTION, stick=True)
    with pytest.raises(ru.NotApplicable, match="not applicable: loaded_modes"):
        stages.loaded_modes(CROSS_SECTION)
    assert stages.tire_model(CROSS_SECTION).has("one_sided_cleat")  # stages.one_sided_run runs its stepping


def test_editing_the_road_texture_or_the_vehicle_recomputes_a_cached_sweep(data_copy):
    """A sweep's design is keyed by the names of the texture and the vehicle it reads; the entry records
    the files' contents, so an edit of either recomputes it (it served the old number before)."""
    coarse = ru.load_tire("165_65R14").replace(
        **{"mesh.n_strips": 7, "mesh.n_elements": 260, "tasselli.strips_per_column": 1}
    )

    def hub_rms() -> float:
        table = ru.experiments.sweep(
            {"operating.inflation_pressure": [2.3e5]}, ["hub_acceleration"], tire=coarse, scheduler="serial",
            progress=False,
        )  # fmt: skip
        return float(table["a_hub_rms (m/s^2)"].iloc[0])

    class_c = hub_rms()
    texture = data_copy / "roads" / "rough.toml"
    texture.write_text(texture.read_text().replace('iso_class = "C"', 'iso_class = "E"'))
    class_e, computed = _computed_during(hub_rms)
    assert "evaluate_design" in computed
    assert class_e / class_c == pytest.approx(4.0, rel=0.05)  # class E: 16 times class C's PSD, 4 times its RMS
    vehicle = data_copy / "vehicles" / "midsize_195_65R15.toml"
    vehicle.write_text(vehicle.read_text().replace("unsprung = 32.0", "unsprung = 64.0"))
    heavier, computed = _computed_during(hub_rms)
    assert "evaluate_design" in computed and heavier < 0.9 * class_e
