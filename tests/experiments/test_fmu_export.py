"""The tire-model interface's tires exported as FMUs, and the road test's quarter car co-simulated with one."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from fmpy.validation import validate_fmu

import roadnoise_utils as ru
from roadnoise_utils.experiments.road import road_test_conditions
from roadnoise_utils.experiments.tire_models import tire_as_files
from roadnoise_utils.fmu.drive import run_fmu
from roadnoise_utils.repro.paths import REPO_ROOT
from roadnoise_utils.rm.aggregated import road_hub_force
from roadnoise_utils.road.cleat import cleat_profile
from roadnoise_utils.tire.model import NotApplicable


def test_the_co_simulated_quarter_car_is_ours_per_octave(tmp_path):
    """The paper's car on the rough road at 120 km/h (2 s): per-octave RMS of both accelerations 20-250 Hz
    within 1 % of ru.experiments' quarter car (the closed loop in continuous time)."""
    test = road_test_conditions(duration=2.0, textures=["rough"])
    run = ru.experiments.fmu_quarter_car(tmp_path, conditions=test)
    assert list(run.octaves["octave (Hz)"].unique()) == [31.5, 63.0, 125.0, 250.0]
    assert np.max(np.abs(run.octaves["ratio - 1"])) < 0.01
    assert run.fmu.exists() and validate_fmu(str(run.fmu)) == []


#: A master loop over fmpy alone, as a user's tool would run the FMU: roadnoise is not imported.
STANDALONE = """
import sys
import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

path, road_file, out_file = sys.argv[1:4]
description = read_model_description(path)
dt = float(description.defaultExperiment.stepSize)
refs = {v.name: v.valueReference for v in description.modelVariables}
slave = FMU2Slave(guid=description.guid, unzipDirectory=extract(path),
                  modelIdentifier=description.coSimulation.modelIdentifier, instanceName="tire")
slave.instantiate()
slave.setupExperiment(startTime=0.0)
slave.enterInitializationMode()
slave.exitInitializationMode()
forces = []
for k, height in enumerate(np.load(road_file)):
    slave.setReal([refs["road_height[1]"], refs["hub_displacement"]], [float(height), 0.0])
    forces.append(slave.getReal([refs["F_M"]])[0])
    slave.doStep(k * dt, dt)
slave.terminate()
slave.freeInstance()
assert not any(name.startswith("roadnoise") for name in sys.modules), "roadnoise was imported"
np.save(out_file, np.array(forces))
"""


@pytest.fixture(scope="module")
def file_tire():
    """The paper's ring written as a tire from files (UFF 58 + footprint CSV): the third registered model."""
    return tire_as_files("165_65R14")


@pytest.mark.parametrize("model", ["ring", "cross-section", "frf-file"])
def test_each_model_exports_validates_and_runs_in_fmpy_alone(model, file_tire, tmp_path):
    """Every registered tire model through the same export; a Python with fmpy and no roadnoise drives the FMU
    over the paper's cleat and gets our road_hub_force on the same road samples (round-off apart)."""
    tire = {"ring": "165_65R14", "cross-section": "165_65R14_cross_section", "frf-file": file_tire}[model]
    assert ru.tire_model(tire).kind == model
    speed = 30 / 3.6
    path = ru.export_fmu(tire, tmp_path / "tire.fmu", speed, lateral=False)
    assert validate_fmu(str(path)) == []
    tables = ru.experiments.fmu_export.fmu_tables(tire, speed, lateral=False)
    grid = speed * tables.dt
    knots = tables.leading_edge - 0.1 + grid * np.arange(int(0.4 / grid) + 2)
    heights = cleat_profile(0.015, 0.015)(knots)
    profile = lambda s: np.interp(s, knots, heights)  # noqa: E731
    system = ru.assemble_fixed_hub(ru.stages.fit_tasselli(tire))
    expected = road_hub_force(system, ru.stages.solve_static(tire), profile, speed, (-0.1, 0.3), 1 / tables.dt).force
    np.save(tmp_path / "road.npy", heights[: expected.size])
    script = tmp_path / "drive.py"
    script.write_text(STANDALONE)
    subprocess.run([sys.executable, str(script), str(path), str(tmp_path / "road.npy"), str(tmp_path / "force.npy")],
                   check=True, capture_output=True, cwd=tmp_path)  # fmt: skip
    forces = np.load(tmp_path / "force.npy")
    assert np.max(np.abs(forces - expected)) <= 1e-9 * np.max(np.abs(expected))


def test_a_model_without_a_hub_transfer_is_refused_by_name(monkeypatch, tmp_path):
    model = ru.tire_model("165_65R14")
    monkeypatch.setattr(type(model), "capabilities", frozenset(model.capabilities - {"hub_transfer"}))
    with pytest.raises(NotApplicable, match="hub_transfer"):
        ru.export_fmu(model, tmp_path / "x.fmu", 10.0)


def test_a_texture_outside_the_test_is_refused(tmp_path):
    with pytest.raises(ValueError, match="texture = 'icy'"):
        ru.experiments.fmu_quarter_car(tmp_path, texture="icy")


def test_the_book_s_three_lines_and_fmpy_loop_run_as_written(tmp_path, monkeypatch):
    """The book's vehicle-tools page: its export lines, then its fmpy loop over a rough road with the hub moving,
    equal to run_fmu (our own fmpy driver) sample by sample."""
    page = (REPO_ROOT / "book" / "reference" / "vehicle-tools.md").read_text()
    export, loop = [block.split("```", 1)[0] for block in page.split("```python")[1:3]]
    monkeypatch.chdir(tmp_path)
    exec(compile(export, "vehicle-tools.md", "exec"), {})  # the book's code, as written
    assert validate_fmu("tire.fmu") == [] and validate_fmu("car_tire.fmu") == []
    rng = np.random.default_rng(3)
    road, hub = np.cumsum(rng.normal(size=(2, 300)), axis=1) * 1e-5
    namespace = {"road_heights": road, "hub": hub}
    exec(compile(loop, "vehicle-tools.md", "exec"), namespace)
    expected = run_fmu("tire.fmu", road, hub).F_M
    assert np.max(np.abs(expected)) > 10.0  # newtons: the road and the hub move the tire
    np.testing.assert_array_equal(namespace["forces"], expected)
