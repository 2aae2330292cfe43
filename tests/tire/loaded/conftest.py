"""The small test tire of the statics' tests: the 165/65 R14 file's section at 4 crown and 2 x 2
sidewall elements swept through 6 equal arcs (3060 DOF), its inflated state and the flat road
pressed 5 mm into it; built once per worker. The model's tests (and the dynamics') use the loaded
FE tire's test mesh instead (``small_loaded``: graded arcs, several rings in the footprint)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.loaded import road_contact, stages, statics

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
    return road_contact.press_on_road(tire, inflated, 0.005, steps=2)


@pytest.fixture(scope="session")
def model_tire(small_loaded):
    """The loaded FE tire's test mesh (``SMALL_LOADED``: 8 graded arcs, 4080 DOF)."""
    return stages.built_tire(small_loaded.spec)


@pytest.fixture(scope="session")
def model_inflated(small_loaded):
    """Its inflated state, the model's cached stage (the one its load cases start from)."""
    return stages.inflated_state(small_loaded.spec)


@pytest.fixture(scope="session")
def model_state(small_loaded):
    """Its state at its file's load (1 kN), the model's cached stage."""
    return stages.loaded_state(small_loaded.spec, small_loaded.case())
