"""A quarter car co-simulated with the tire FMU: the coupling error is first order in the step."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments.road import road_test_conditions, texture_run
from roadnoise_utils.fmu.cosimulation import cosimulate_quarter_car, leading_edge_heights
from roadnoise_utils.fmu.drive import TireSlave
from roadnoise_utils.road.input import contact_tracks, texture_length
from roadnoise_utils.vehicle.corner import run_corner


def coupling_error(setup, folder, sample_rate: float) -> float:
    """RMS of the co-simulated hub acceleration's difference from ours over its own RMS, 1.5 s of rough road
    after the first 0.5 s (the FMU starts with the road level behind its first sample, ours with the road under
    the footprint: a start-up transient that does not depend on the step, as the spectra's skip)."""
    test = road_test_conditions(duration=1.5, textures=["rough"], sample_rate=sample_rate)
    spectrum = test.spectra()["rough"]
    ours = run_corner(setup.sections, setup.model, texture_run(setup.static, spectrum, test, True))
    path = ru.export_fmu(setup.tire, folder / f"car_{int(sample_rate)}.fmu", test.speed, sample_rate)
    road = ru.stages.texture_road(
        spectrum, texture_length(spectrum, test.duration * test.speed), test.seed, contact_tracks(setup.static)
    )
    with TireSlave(path) as slave:
        heights = leading_edge_heights(road.as_3d(), slave, ours.t.size)
        run = cosimulate_quarter_car(slave, setup.vehicle, setup.tire_hub_mass, heights)
    late = ours.t >= 0.5
    difference = run.outputs["a_hub"][late] - ours.outputs["a_hub"][late]
    return float(np.sqrt(np.mean(difference**2) / np.mean(ours.outputs["a_hub"][late] ** 2)))


def test_the_coupling_error_halves_with_the_step(tmp_path):
    """The force held over a step while the hub moves (explicit coupling): error ~ step. The road's own
    discretisation (the leading-edge samples against the texture's grid) is of higher order."""
    setup = ru.experiments.corner_setup()
    coarse, fine = coupling_error(setup, tmp_path, 10000.0), coupling_error(setup, tmp_path, 20000.0)
    assert coarse < 0.01
    assert 1.8 < coarse / fine < 2.2  # measured 1.97 (10 -> 20 kHz) and 1.99 (20 -> 40 kHz)


def test_a_road_that_ends_before_the_travel_is_refused(tmp_path):
    setup = ru.experiments.corner_setup()
    path = ru.export_fmu(setup.tire, tmp_path / "car.fmu", 120 / 3.6, lateral=False)

    def short_road(s):
        return np.where(s < 5.0, 0.0, np.nan)

    with TireSlave(path) as slave:
        with pytest.raises(ValueError, match="ends before the travel"):
            leading_edge_heights(short_road, slave, 20000)
        with pytest.raises(ValueError, match="road must be"):
            cosimulate_quarter_car(slave, setup.vehicle, setup.tire_hub_mass, np.zeros((2, 10)))
