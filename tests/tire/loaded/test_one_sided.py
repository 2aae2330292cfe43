"""The cleat test with one-sided contact on the loaded FE tire (its test mesh at 1 kN on the 1.25 m drum).

Checked by a second method each: the quasi-static run's hub force is the rim's reaction and the
momentum balance the dynamic runs rest on, to round-off, and the loaded state comes back once the
cleat has left; a cleat too low to lift any node gives the linear footprint's static transfer (the
FRFs at 0 Hz, a different reduction of the same tangent); the frozen dynamic run is the frequency
domain of the FRFs (the frozen check); a node out of contact never penetrates; after the cleat the
footprint settles back. Bad input is refused by name.
"""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.road.cleat import cleat_profile
from roadnoise_utils.tire.cavity import air_coordinates
from roadnoise_utils.tire.loaded import cavity, one_sided, stages

CLEAT = (0.015, 0.015, "triangle")
SPEED = 30 / 3.6
#: Travel of the dynamic runs (m): the measured test's (``data/conditions/cleat_test.toml``), so that these runs are
#: the chapter's own cached stages.
DISTANCE = tuple(ru.experiments.one_sided_cleat.one_sided_conditions().distance)


@pytest.fixture(scope="module")
def drum_case(small_loaded):
    return small_loaded.case("drum", drum_radius=1.25)


@pytest.fixture(scope="module")
def drum_state(small_loaded, drum_case):
    return stages.loaded_state(small_loaded.spec, drum_case)


@pytest.fixture(scope="module")
def quasi_static(small_loaded, drum_case):
    return small_loaded.one_sided_run(
        drum_case,
        {"speed": 0.0, **dict(zip(("height", "base", "shape"), CLEAT)), "distance": (-0.12, 0.13), "step": 1e-3},
    )


@pytest.fixture(scope="module")
def dynamic(small_loaded, drum_case):
    """(one-sided, frozen) at 30 km/h, the model's own step."""
    return stages.dynamic_cleat_runs(small_loaded.spec, drum_case, SPEED, *CLEAT, DISTANCE, dt=small_loaded.contact_dt)


def test_the_quasi_static_hub_force_is_the_rim_reaction_and_the_momentum_balance(quasi_static):
    # force_balance: the loaded state back off the profile, and the rim's reaction against the contact
    # forces' and the drum curvature's vertical shares, both over the load
    assert quasi_static.force_balance < 1e-9
    assert quasi_static.max_penetration < 1e-12 and quasi_static.iterations < 10
    assert quasi_static.on_profile.any() and quasi_static.contact_points.min() < quasi_static.contact_points[0]
    assert 300.0 < quasi_static.peak_force < 1500.0


@pytest.fixture(scope="module")
def with_air(small_loaded):
    """The test tire with its air cavity coupled (the same static states: the air is its dynamics)."""
    return small_loaded.replace(**{"cavity.enabled": True})


@pytest.mark.parametrize("air", [False, True])
def test_a_cleat_too_low_to_lift_a_node_gives_the_linear_footprint_s_static_transfer(
    small_loaded, with_air, drum_case, air
):
    """At 10 um no node lifts off (the loaded forces are >= 15 N, a node's change is < 1 N) and the
    cleat reaches only nodes in contact: the run is the footprint FRFs at 0 Hz times the drum's rise
    under each contact node (a different reduction of the same tangent, the road's motion vertical
    rather than along each node's normal, the drum's surface sliding with it: 3.8e-6 apart here).
    With the air the FRFs carry its compressibility by the reduced basis's static loads, the run by
    Woodbury's identity on the full tangent: it moves the transfer by 10 times the tolerance."""
    tire, state = stages.built_tire(small_loaded.spec), stages.loaded_state(small_loaded.spec, drum_case)
    profile = cleat_profile(1e-5, 0.015, "triangle")
    travel = np.arange(-0.08, 0.08, 2e-3)
    coupling = cavity.loaded_coupling(tire, state) if air else None
    run = one_sided.quasi_static_run(tire, state, profile, (travel[0], travel[-1]), 2e-3, air=coupling)
    assert np.all(run.contact_points == state.contact.size)
    motion = one_sided.footprint_road_motion(tire, state, profile, run.distance)
    static = (with_air if air else small_loaded).fixed_hub_frfs(drum_case).H_points[:, 0].real
    linear = static @ motion
    assert np.abs(linear).max() > 0.1  # N: the check is not vacuous
    # 2e-5: the road's motion along the normals taken as vertical (no 1 / n_z) would miss by 1.2e-4
    assert np.abs(run.hub_force - linear).max() < 2e-5 * np.abs(linear).max()
    if air:
        plain = small_loaded.fixed_hub_frfs(drum_case).H_points[:, 0].real @ motion
        assert np.abs(linear - plain).max() > 2e-4 * np.abs(linear).max()


def test_the_frozen_run_is_the_frequency_domain_of_the_footprint_frfs(small_loaded, drum_case, dynamic):
    time_domain, reference = small_loaded.frozen_reference(drum_case, dynamic[1], CLEAT, 1.0)
    window = dynamic[1].distance <= 0.3
    assert abs(time_domain.max() / reference.max() - 1) < 0.005
    assert ru.analysis.relative_rms_error(time_domain[window], reference[window]) < 0.01
    assert reference.max() > 300.0


def test_with_its_air_the_frozen_run_is_the_frequency_domain_of_the_coupled_frfs(small_loaded, with_air, dynamic):
    """The air's resonant modes stepped as coordinates of their own (causal springs and dashpots) against
    the FRFs' hysteretic air (:func:`~roadnoise_utils.tire.cavity.air_coordinates`): within 0.5 % at
    the model's step with the air, 1/24 000 s (measured: peak 0.04 %, RMS 0.31 %; 2.0 % RMS at
    1/12 000 s, the air's 1 % damping against the step's period error). The air moves the band-limited
    hub force by over 20 % of its peak (its resonance near 245 Hz, the band's top): the check sees it."""
    case = with_air.case("drum", drum_radius=1.25)
    runs = stages.dynamic_cleat_runs(with_air.spec, case, SPEED, *CLEAT, DISTANCE, dt=with_air.contact_dt)
    time_domain, reference = with_air.frozen_reference(case, runs[1], CLEAT, 1.0)
    window = runs[1].distance <= 0.3
    assert abs(time_domain.max() / reference.max() - 1) < 0.005
    assert ru.analysis.relative_rms_error(time_domain[window], reference[window]) < 0.005
    assert runs[0].max_penetration < 1e-9 and runs[0].contact_points.min() < runs[1].contact_points.min()
    plain, _ = small_loaded.frozen_reference(case, dynamic[1], CLEAT, 1.0)  # without the air, every 1/12 000 s
    assert dynamic[1].dt == pytest.approx(2.0 * runs[1].dt)
    n = min(plain.size, time_domain[::2].size)
    assert np.abs(time_domain[::2][:n] - plain[:n]).max() > 0.2 * reference.max()


@pytest.mark.parametrize("f", [80.0, 230.0, 247.0])
def test_with_the_air_the_momentum_balance_is_the_hub_s_reaction(with_air, f):
    """The dynamic runs' hub force with the air, in the frequency domain of the reduced tire with its air's
    causal coordinates (flat road, a unit rise of one contact node, the hub held): the contact forces'
    vertical shares less the momentum's rate plus the pressures' push on the wheel (elastic and viscous)
    is the hub's reaction to round-off; without the push it misses by 1.7 % at 80 Hz and by 54-107 % near
    the air's doublet."""
    reduced = stages.reduced_footprint(with_air.spec, with_air.case(), 400.0)  # cached: the modal tests' own
    air = air_coordinates(reduced.cavity, causal=True)
    r, b = reduced.mass.shape[0], reduced.n_boundary
    translation = np.zeros(r)
    translation[:b] = 1.0  # the whole wheel up by one: every boundary motion (the interior's static shape is 0)
    w = 2 * np.pi * f
    d = np.pad(reduced.stiffness(w) - w**2 * reduced.mass, ((0, air.size), (0, air.size))) + air.stiffness
    d = d + 1j * w * air.damping
    d[r:, r:] -= w**2 * np.diag(air.mass)
    q = np.zeros(r + air.size, complex)
    q[0] = 1.0
    q[b:] = -np.linalg.solve(d[b:, b:], d[b:, :b] @ q[:b])
    forces = d @ q
    reaction = -forces[b - 1]
    momentum = w**2 * (reduced.mass @ translation) @ q[:r]
    share = translation @ reduced.cavity.volume  # each mode's volume lost to the translation
    push = share @ (air.pressure @ q + 1j * w * air.pressure_rate @ q)
    balance = forces[: b - 1].sum() + momentum
    assert abs(balance + push - reaction) < 1e-9 * abs(reaction)
    assert abs(balance - reaction) > (0.1 if f > 200.0 else 0.01) * abs(reaction)


def test_the_one_sided_run_lifts_off_never_penetrates_and_settles_back(drum_state, dynamic):
    lifted, frozen = dynamic
    assert frozen.contact == "frozen" and np.all(frozen.contact_points == drum_state.contact.size)
    assert lifted.contact_points.min() < drum_state.contact.size  # the tread lifts off beside the cleat
    assert lifted.max_penetration < 1e-9
    # before the cleat touches, both runs stay in the loaded state at rest
    before = ~np.cumsum(lifted.on_profile).astype(bool)
    assert np.abs(lifted.hub_force[before]).max() < 1e-6 and np.abs(frozen.hub_force[before]).max() < 1e-6
    # after the cleat has left: the footprint back to its static set, the hub force decaying (on this
    # coarse mesh its ~84 Hz ring loses 6 % per radian: its last 40 mm, 0.43-0.47 m on, at 0.19 of its first 40 mm)
    left = lifted.distance[np.flatnonzero(lifted.on_profile)[-1]]
    after, tail = lifted.distance - left, lifted.distance > DISTANCE[1] - 0.04
    assert np.all(lifted.contact_points[after > 0.08] == drum_state.contact.size)
    assert np.abs(lifted.hub_force[tail]).max() < 0.4 * np.abs(lifted.hub_force[(after > 0) & (after < 0.04)]).max()


def test_bad_input_is_refused_by_name(small_loaded, drum_case, drum_state):
    tire = stages.built_tire(small_loaded.spec)
    profile = cleat_profile(*CLEAT)
    flat = stages.loaded_state(small_loaded.spec, small_loaded.case("flat"))
    with pytest.raises(ValueError, match="drum"):
        one_sided.quasi_static_run(tire, flat, profile, (-0.1, 0.1))

    def plateau(x: np.ndarray) -> np.ndarray:  # 0.2 m high, 0.8 m long: the test mesh's far rings meet it
        return np.where(np.abs(x) < 0.4, 0.2, 0.0)

    with pytest.raises(ValueError, match="tread nodes beyond 150 mm of the axle"):
        one_sided.quasi_static_run(tire, drum_state, plateau, (-0.1, 0.1))
    contact = one_sided.cleat_contact(tire, drum_state, profile, np.zeros(1))
    assert not np.isin(3 * contact.watched + 2, tire.fixed).any()  # the held bead stations are not watched
    gap = np.ones(contact.watched.size)
    gap[np.flatnonzero(contact.candidate)[0]] = -1e-3  # a candidate's own penetration: the contact solve's
    one_sided.check_outside(contact, gap, 0.0)
    gap[np.flatnonzero(~contact.candidate)[0]] = -1e-6  # any other node's: refused
    with pytest.raises(RuntimeError, match="left out of the contact candidates penetrates the drum by 0.001 mm"):
        one_sided.check_outside(contact, gap, 0.0)
    # the time step's spacing: the footprint's rings along the drum (its 40 mm arcs: nodes ~20 mm apart)
    assert 0.45 * 0.04 < one_sided._node_spacing(tire, drum_state) <= 0.5 * 0.04
    with pytest.raises(ValueError, match="already touches the tread"):
        one_sided.dynamic_runs(tire, drum_state, profile, SPEED, (-0.02, 0.1))
    with pytest.raises(ValueError, match="frozen"):
        one_sided.dynamic_runs(tire, drum_state, profile, SPEED, DISTANCE, frozen=("yes",))
    with pytest.raises(ValueError, match="speed"):
        one_sided.dynamic_runs(tire, drum_state, profile, -1.0, DISTANCE)
    with pytest.raises(ValueError, match="drum"):
        small_loaded.one_sided_run(small_loaded.case("flat"), {"speed": 0.0})
