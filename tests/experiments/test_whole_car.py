"""The whole car on the road test: spectra, left/right coherence and the experiment's checks."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments import whole_car
from roadnoise_utils.road.kernels import kernel_transforms
from roadnoise_utils.vehicle import car_spectra


@pytest.fixture(scope="module")
def setup():
    return whole_car.whole_car_setup()


def test_strip_transfers_add_up_to_the_uniform_road_transfer(setup):
    """Summed over the belt strips, the strips' shares of F_F are the 2-D road's transfer (1e-12)."""
    static, fits = setup.tire.static, setup.tire.fits
    f = np.array([5.0, 60.0, 180.0])
    n = f / 20.0
    y, a = car_spectra.strip_transfers(static, fits.responses(f), n)
    uniform = np.sum(fits.responses(f) * kernel_transforms(static, n), axis=0)
    assert y.size == a.shape[0] > 1 and np.all(np.diff(np.sort(y)) > 0)
    assert np.abs(a.sum(axis=0) - uniform).max() < 1e-12 * np.abs(uniform).max()


def test_left_right_force_coherence_is_the_roads_at_the_track(setup):
    """The predicted coherence of an axle's two road forces equals the road's at the track width
    (track 1.48 m against a 0.15 m footprint: within 0.01); a 60 s time-domain run estimates it
    within 3.5 standard deviations of the Welch estimate (Bendat & Piersol) where it exceeds 0.3,
    and below 0.3 on average where the prediction is below 0.01."""
    check = whole_car.axle_coherence(setup)
    assert np.abs(check.predicted - check.road).max() < 0.01
    strong = check.predicted > 0.3
    assert strong.sum() >= 3
    assert np.all(np.abs(check.estimated - check.predicted)[strong] < 3.5 * check.deviation[strong])
    weak = check.predicted < 0.01
    assert weak.sum() > 10 and check.estimated[weak].mean() < 0.05  # the bias of ~60 windows is ~0.015
    assert check.predicted[check.freqs > 10].max() < 0.01


def test_closed_form_limits_of_the_experiment(setup):
    """The claims' numbers: the heavy-body corner limit and the symmetric car's notches."""
    assert whole_car.heavy_body_difference(setup.car) < 1e-7
    depth = whole_car.notch_depth(setup, 20.0)
    assert (depth["largest at a notch / peak"] < 1e-9).all() and (depth["notches"] > 10).all()
    notches = whole_car.notch_frequencies(20.0, 2.6, 30.0)
    np.testing.assert_allclose(notches["pitch"], [20 / 2.6, 40 / 2.6, 60 / 2.6])
    np.testing.assert_allclose(notches["heave"], 20 / 2.6 * np.array([0.5, 1.5, 2.5, 3.5]))


def test_car_spectra_of_a_run_have_every_output_and_both_axles():
    """Welch spectra of every output and the coherence of each axle, on a synthetic run: identical
    left and right forces are fully coherent, independent ones nearly not."""
    rng = np.random.default_rng(2)
    t = np.arange(40000) / 4000.0
    common = rng.standard_normal(t.size)
    forces = np.array([common, common, rng.standard_normal(t.size), rng.standard_normal(t.size)])
    run = ru.vehicle.full_car.FullCarRun(t, forces, {"a_heave": common, "a_pitch": forces[2]})
    spectra = car_spectra.car_spectra(run)
    assert set(spectra.psd) == {"a_heave", "a_pitch"} and spectra.psd["a_heave"].shape == spectra.freqs.shape
    assert spectra.force_coherence["front"][1:].min() > 0.999
    assert spectra.force_coherence["rear"][1:].mean() < 0.1


def test_bad_whole_car_conditions_are_refused():
    with pytest.raises(ValueError, match="speed_kmh"):
        whole_car.whole_car_conditions(speed_kmh=0.0)
    with pytest.raises(ValueError, match="duration"):
        whole_car.whole_car_conditions(duration=1.0)
