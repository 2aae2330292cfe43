"""Cleat passages with one-sided contact on the cross-section tire: quasi-static and 30 km/h.

The paper's cleat test on the 165/65 R14 (notebook 08's cached stages); the properties of the stepping
(a flat road, runs stepped together, half the step) on its coarse grid (``coarse_section``)."""

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.analysis import distinct_peaks
from roadnoise_utils.road.cleat import cleat_profile
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.one_sided import (
    section_dynamic_run,
    section_dynamic_runs,
    section_quasi_static_run,
)

TIRE = "165_65R14_cross_section"


@pytest.fixture(scope="module")
def run():
    test = ru.experiments.one_sided_conditions()
    c = test.cleat
    return section_stages.quasi_static_cleat(TIRE, c.height, c.base, c.shape, c.drum_radius, test.sweep_distance)


def test_the_held_deflection_carries_the_static_load_off_the_cleat(run):
    """The deflection-held solve against the load-held static solve: off the cleat the hub force is
    the load; no grid point out of contact penetrates the drum at any step."""
    assert run.force_balance < 1e-9
    assert run.max_penetration < 1e-12
    assert abs(run.hub_force[0]) < 1e-6 * 4512.0


@pytest.mark.filterwarnings("ignore:decay components above the 250 Hz band")  # the fits are not held above it
def test_contact_loss_raises_the_base_curve_above_the_tied_footprint(run):
    """Two peaks as the cleat crosses; contact loss hands the lifted tread's load to the cleat, so
    the peak is well above the linear (tied-footprint) chain's quasi-static peak."""
    linear = ru.experiments.cleat_test(TIRE).quasi_static.peak_force
    assert distinct_peaks(run.distance, run.hub_force, (-np.inf, np.inf)) == 2
    assert run.peak_force > 1.5 * linear
    assert run.contact_points.min() < run.contact_points.max()


@pytest.fixture(scope="module")
def coarse(coarse_section):
    """The coarse tire on the paper's drum, and its harmonics reduced for the stepping."""
    tire = section_stages.section_tire(coarse_section)
    drum = ru.stages.solve_static(coarse_section, "drum", drum_radius=1.25)
    return tire, drum, section_stages.harmonic_reductions(coarse_section)


def test_a_flat_profile_changes_nothing(coarse):
    """A zero profile: every step is the static state (superposition of nothing)."""
    tire, drum, _ = coarse
    flat = section_quasi_static_run(tire, drum, lambda s: np.zeros_like(s), (-0.01, 0.01), 0.005)
    assert np.abs(flat.hub_force).max() < 1e-6 * drum.load
    assert np.all(flat.contact_points == drum.contact.sum())


def test_bad_input_is_refused():
    tire = section_stages.section_tire(TIRE)
    drum = ru.stages.solve_static(TIRE, "drum", drum_radius=1.25)
    profile = cleat_profile(0.015, 0.015, "triangle")
    with pytest.raises(ValueError, match="step"):
        section_quasi_static_run(tire, drum, profile, (-0.01, 0.01), 0.0)
    with pytest.raises(ValueError, match="distance"):
        section_quasi_static_run(tire, drum, profile, (0.01, -0.01))
    other = section_stages.section_tire("195_65R15_cross_section")
    with pytest.raises(ValueError, match="another tire"):
        section_quasi_static_run(other, drum, profile, (-0.01, 0.01))


# ---------------------------------------------------------------- the dynamic run (30 km/h)


@pytest.fixture(scope="module")
def section_test():
    return ru.experiments.one_sided_cleat_test(TIRE)


def test_frozen_dynamic_run_equals_the_frequency_domain():
    """Contact held bilateral on the static set: the time-stepped tire (every harmonic, Prony
    moduli, generalised-alpha, the passive part) against the frequency-domain footprint solve of
    the full model on the same point heights, 0-250 Hz."""
    check = ru.experiments.frozen_check(TIRE)
    assert abs(check.peak_difference) < 0.01
    assert check.rms_difference < 0.02


def test_dynamic_run_keeps_contact_one_sided_and_regains_the_footprint(section_test):
    """No grid point out of contact penetrates the drum at any step (from the displacement, not
    the contact algebra); the footprint lifts off around the cleat and comes back after it."""
    raw = ru.experiments.one_sided_cleat.raw_dynamic(TIRE)
    static_points = int(section_test.static.contact.sum())
    assert raw.max_penetration < 1e-9
    assert raw.contact_points.min() < 0.2 * static_points
    after = raw.distance > 0.3
    assert np.median(raw.contact_points[after]) > 0.8 * static_points


def test_dynamic_run_against_the_measured_test(section_test):
    """Two peaks while the cleat crosses, a dynamic amplification over the quasi-static run, and
    the free decay on the first vertical mode (~80 Hz) with positive damping."""
    run = section_test.dynamic
    assert distinct_peaks(run.distance, run.hub_force, (-0.15, 0.15)) == 2
    assert section_test.ratio > 1.2
    leading = section_test.decay.iloc[0]
    assert 70.0 < leading["frequency (Hz)"] < 95.0
    assert leading["damping ratio"] > 0.0


def test_runs_stepped_together_are_the_runs_alone(coarse):
    """The frozen and the one-sided run share one stepper (one pass over the operators): each equals
    its run alone, through the cleat's first contact losses (no run's contact leaks into another)."""
    tire, drum, reduced = coarse
    profile = cleat_profile(0.015, 0.015, "triangle")
    args = (tire, drum, profile, 30 / 3.6, (-0.12, -0.07))  # contact is first lost near -0.09 m
    one_sided, frozen = section_dynamic_runs(*args, dt=1 / 12000, frozen=(False, True), reduced=reduced)
    alone = section_dynamic_run(*args, dt=1 / 12000, reduced=reduced)
    assert one_sided.contact_points.min() < frozen.contact_points.min() == drum.contact.sum()
    assert np.abs(one_sided.hub_force - alone.hub_force).max() < 1e-9 * drum.load
    np.testing.assert_array_equal(one_sided.contact_points, alone.contact_points)
    with pytest.raises(ValueError, match="frozen"):
        section_dynamic_runs(*args, frozen=(), reduced=reduced)


def test_halving_the_step_changes_the_band_limited_impact_little(coarse, coarse_section):
    """The cleat runs' step (``CONTACT_DT``, 24 samples per 250 Hz period) against half of it, through
    the impact (the window's end is band-limited the same way in both): the 0-250 Hz peak moves by
    less than 0.5 %, as second-order time integration at this step predicts (0.2 % per 250 Hz period
    of numerical damping, ``SPECTRAL_RADIUS``)."""
    from roadnoise_utils.experiments.one_sided_cleat import in_model_band
    from roadnoise_utils.tire.cross_section.model import CONTACT_DT

    setup = ru.tire_model(coarse_section).one_sided_setup(ru.experiments.one_sided_conditions())
    tire, drum, reduced = coarse
    profile = cleat_profile(0.015, 0.015, "triangle")
    args = (tire, drum, profile, 30 / 3.6, (-0.12, 0.03))  # from just before the cleat touches
    peaks = []
    for dt in (CONTACT_DT, CONTACT_DT / 2):
        run = in_model_band(setup, section_dynamic_run(*args, dt=dt, reduced=reduced))
        impact = (run.distance > -0.1) & (run.distance < 0.0)
        peaks.append(run.hub_force[impact].max())
    assert abs(peaks[1] / peaks[0] - 1.0) < 5e-3


def test_dynamic_bad_input_is_refused():
    tire = section_stages.section_tire(TIRE)
    drum = ru.stages.solve_static(TIRE, "drum", drum_radius=1.25)
    profile = cleat_profile(0.015, 0.015, "triangle")
    with pytest.raises(ValueError, match="speed"):
        section_dynamic_run(tire, drum, profile, 0.0, (-0.15, 0.0))
    with pytest.raises(ValueError, match="dt"):
        section_dynamic_run(tire, drum, profile, 8.0, (-0.15, 0.0), dt=1e-3)
    with pytest.raises(ValueError, match="already touches"):
        section_dynamic_run(tire, drum, profile, 8.0, (-0.05, 0.0), reduced=section_stages.harmonic_reductions(TIRE))
