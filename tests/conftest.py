"""Shared fixtures: the paper's tire at its default mesh, coarse copies of the ring and the cross-section tire for
fast property tests, and the cached RM stages the tests of several folders use."""

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
    """On the paper's drum (``ru.solve_static`` takes its radius from the cleat test's conditions)."""
    return ru.solve_static(fet, road="drum")


@pytest.fixture(scope="session")
def coarse_tire(tire) -> ru.TireSpec:
    """Same tire on a coarse mesh (7 strips x 260 elements, two contact points per row): properties, not calibration."""
    return tire.replace(**{"mesh.n_strips": 7, "mesh.n_elements": 260, "tasselli.strips_per_column": 1})


@pytest.fixture(scope="session")
def coarse_fet(coarse_tire):
    return ru.build_fet(coarse_tire)


@pytest.fixture(scope="session")
def coarse_flat(coarse_fet):
    return ru.solve_static(coarse_fet, road="flat")


@pytest.fixture(scope="session")
def paper_fits(tire):
    """The paper tire's tassello fits on the flat road (cached stage)."""
    return ru.stages.fit_tasselli(tire)


@pytest.fixture(scope="session")
def drum_tire(tire):
    """The paper tire on the paper's drum: static state, fixed-hub state space and its modal sections."""
    drum_radius = ru.experiments.cleat_conditions().drum_radius
    static = ru.stages.solve_static(tire, road="drum", drum_radius=drum_radius)
    system = ru.stages.assemble_fixed_hub(tire, road="drum", drum_radius=drum_radius)
    return static, system, ru.rm.modal_sections(system)


@pytest.fixture(scope="session")
def car_tire():
    """The paper's car corner: (vehicle, FE tire, static state, tassello fits, hub fit, rim-side mass)."""
    setup = ru.experiments.corner_setup()
    return setup.vehicle, ru.build_fet(setup.tire), setup.static, setup.fits, setup.hub, setup.tire_hub_mass


#: The cross-section 165/65 R14 on a coarse grid: 150 harmonics, contact points 6 mm apart, 10 crown and 6 sidewall
#: elements (645 DOF per harmonic against 1005, 323 contact points against 891). For properties that hold on any
#: grid (two methods against each other), not for the paper's numbers: its direct solves take a sixth of the time.
COARSE_SECTION = {
    "mesh.harmonics": 150,
    "mesh.contact_spacing": 0.006,
    "mesh.crown_elements": 10,
    "mesh.sidewall_elements": 6,
}


#: The loaded FE tire's test mesh: the section at 4 crown and 2 x 2 sidewall elements (tread nodes 15 mm
#: apart, within the footprint files' 25 mm) swept through 40 mm arcs over +-40 mm at the bottom, growing
#: threefold per arc (8 arcs, 4080 DOF), loaded to 1 kN on the flat road (6.1 mm: one road step of 7 mm, then
#: Brent's method on the lift).
SMALL_LOADED = {
    "solid_mesh.crown_elements": 4,
    "solid_mesh.sidewall_elements": 2,
    "solid_mesh.footprint_arc": 0.04,
    "solid_mesh.sector_half_angle": 0.14,
    "solid_mesh.coarse_arc": 0.4,
    "solid_mesh.arc_growth": 3.0,
    "solid_mesh.road_step": 0.007,
    "operating.vertical_load": 1000.0,
}


@pytest.fixture(scope="session")
def small_loaded():
    """The loaded FE 165/65 R14 on the test mesh of :data:`SMALL_LOADED` (its stages cached)."""
    return ru.tire_model(ru.load_tire("165_65R14_loaded").replace(**SMALL_LOADED))


@pytest.fixture(scope="session")
def coarse_section():
    """The cross-section 165/65 R14's spec on the coarse grid of :data:`COARSE_SECTION`."""
    return ru.load_tire("165_65R14_cross_section").replace(**COARSE_SECTION)
