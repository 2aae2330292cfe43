"""The small test tire of the loaded-tire tests: the 165/65 R14 file's section at 4 crown and 2 x 2
sidewall elements swept through 6 arcs (3060 DOF), its inflated state and the flat road pressed 5 mm
into it; built once per worker."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.loaded import statics

SMALL = {"mesh.crown_elements": 4, "mesh.sidewall_elements": 2}


@pytest.fixture(scope="session")
def tire():
    spec = ru.load_tire("165_65R14_cross_section").replace(**SMALL)
    return statics.build_loaded_tire(spec, np.linspace(-np.pi, np.pi, 7))


@pytest.fixture(scope="session")
def inflated(tire):
    return statics.inflate(tire)


@pytest.fixture(scope="session")
def loaded(tire, inflated):
    return statics.press_on_flat_road(tire, inflated, 0.005, steps=2)
