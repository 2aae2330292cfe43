"""The tire-model interface's tires exported as FMUs, and the road test's quarter car co-simulated with one."""

from __future__ import annotations

import numpy as np
import pytest
from fmpy.validation import validate_fmu

import roadnoise_utils as ru
from roadnoise_utils.experiments.road import road_test_conditions
from roadnoise_utils.tire.model import NotApplicable


def test_the_co_simulated_quarter_car_is_ours_per_octave(tmp_path):
    """The paper's car on the rough road at 120 km/h (2 s): per-octave RMS of both accelerations 20-250 Hz
    within 1 % of ru.experiments' quarter car (the closed loop in continuous time)."""
    test = road_test_conditions(duration=2.0, textures=["rough"])
    run = ru.experiments.fmu_quarter_car(tmp_path, conditions=test)
    assert list(run.octaves["octave (Hz)"].unique()) == [31.5, 63.0, 125.0, 250.0]
    assert np.max(np.abs(run.octaves["ratio - 1"])) < 0.01
    assert run.fmu.exists() and validate_fmu(str(run.fmu)) == []


def test_every_model_with_a_hub_transfer_exports(tmp_path):
    """The cross-section tire goes through the same interface as the ring (its cached stages)."""
    path = ru.export_fmu("165_65R14_cross_section", tmp_path / "section.fmu", 30 / 3.6, lateral=False)
    assert validate_fmu(str(path)) == []


def test_a_model_without_a_hub_transfer_is_refused_by_name(monkeypatch, tmp_path):
    model = ru.tire_model("165_65R14")
    monkeypatch.setattr(type(model), "capabilities", frozenset(model.capabilities - {"hub_transfer"}))
    with pytest.raises(NotApplicable, match="hub_transfer"):
        ru.export_fmu(model, tmp_path / "x.fmu", 10.0)


def test_a_texture_outside_the_test_is_refused(tmp_path):
    with pytest.raises(ValueError, match="texture = 'icy'"):
        ru.experiments.fmu_quarter_car(tmp_path, texture="icy")
