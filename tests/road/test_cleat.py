"""Cleat test: road input, fast simulation and their properties (paper stage 8)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.road import cleat_profile, profile_input


def test_bad_cleats_and_profiles(flat):
    with pytest.raises(ValueError, match="cleat height"):
        cleat_profile(-0.01, 0.015)
    with pytest.raises(ValueError, match="cleat base"):
        cleat_profile(0.01, 0.0)
    with pytest.raises(ValueError, match="finite"):
        profile_input(flat, lambda s: np.where(s > 0.01, np.nan, 0.0), 5.0, (0.0, 0.05))
    road = ru.cleat_input(flat, 5.0)
    bad = ru.RoadInput(t=road.t, distance=road.distance, u=road.u[:-1], speed=5.0, description="")
    with pytest.raises(ValueError, match="72 rows; the model has 73 inputs"):
        ru.simulate(ru.stages.assemble_fixed_hub("165_65R14"), bad)
