"""A quarter car co-simulated with the tire FMU: the coupling error is first order in the step."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fmu.cosimulation import cosimulate_quarter_car, leading_edge_heights
from roadnoise_utils.fmu.drive import TireSlave


def test_the_coupling_error_halves_with_the_step(tmp_path):
    """The force held over a step while the hub moves (explicit coupling): error ~ step. The road's own
    discretisation (the leading-edge samples against the texture's grid) is of higher order."""
    setup = ru.experiments.corner_setup()
    coarse, fine = (ru.experiments.coupling_error(setup, tmp_path, rate) for rate in (10000.0, 20000.0))
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
