"""Shared fixtures: the paper's tire at its default mesh and a coarse copy for fast property tests."""

from __future__ import annotations

import pytest

import roadnoise_utils as ru


@pytest.fixture(scope="session")
def tire() -> ru.TireSpec:
    """The 165/65 R14 of the paper's cleat tests, default mesh."""
    return ru.load_tire("165_65R14")


@pytest.fixture(scope="session")
def fet(tire):
    return ru.build_fet(tire)


@pytest.fixture(scope="session")
def flat(fet):
    return ru.solve_static(fet, road="flat")


@pytest.fixture(scope="session")
def drum(fet):
    return ru.solve_static(fet, road="drum")


@pytest.fixture(scope="session")
def coarse_tire(tire) -> ru.TireSpec:
    """Same tire on a coarse mesh (7 strips x 120 elements): properties, not calibration."""
    return tire.replace(**{"mesh.n_strips": 7, "mesh.n_elements": 120, "tasselli.strips_per_column": 1})


@pytest.fixture(scope="session")
def coarse_fet(coarse_tire):
    return ru.build_fet(coarse_tire)


@pytest.fixture(scope="session")
def coarse_flat(coarse_fet):
    return ru.solve_static(coarse_fet, road="flat")
