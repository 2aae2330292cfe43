"""The quarter car on the road test: one corner setup, every texture driven, spectra as the vehicle stage computes them."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru


def test_quarter_car_runs_every_texture_of_its_conditions():
    setup = ru.experiments.corner_setup()
    assert setup.tire.name == ru.load_tire(setup.vehicle.tire).name
    assert setup.model.ninputs == 1 and setup.model.noutputs == 3
    short = ru.experiments.road_test_conditions(duration=2.0)
    test = ru.experiments.quarter_car(setup, short, lateral=False)
    assert set(test.runs) == set(short.textures) == set(test.spectra)
    rough = test.runs["rough"]
    assert rough.t.size == int(short.duration * short.sample_rate) + 1
    f, p = test.spectra["rough"]["a_hub"]
    f_again, p_again = ru.vehicle.corner.spectra(rough)["a_hub"]
    assert np.array_equal(f, f_again) and np.array_equal(p, p_again)


def test_road_test_inputs_follow_the_seed_and_the_tracks():
    short = ru.experiments.road_test_conditions(duration=0.5, textures=["smooth"])
    flat_road = ru.experiments.road_test("195_65R15", short, lateral=False).inputs["smooth"]
    field = ru.experiments.road_test("195_65R15", short, lateral=True).inputs["smooth"]
    other_seed = ru.experiments.road_test_conditions(duration=0.5, textures=["smooth"], seed=short.seed + 1)
    again = ru.experiments.road_test("195_65R15", other_seed, lateral=True).inputs["smooth"]
    assert flat_road.u.shape == field.u.shape
    assert not np.allclose(field.u, flat_road.u) and not np.allclose(field.u, again.u)


def test_the_hub_mode_peaks_are_maxima_of_the_prediction_and_name_the_nearest_mode():
    """Each peak is a local maximum of the predicted ASD it was found on (above its neighbours 2 Hz
    away), the ASD given is the prediction there, and the mode named is the identified mode nearest it."""
    setup = ru.experiments.corner_setup()
    test = ru.experiments.road_test_conditions()
    peaks = ru.experiments.corner.hub_mode_peaks(setup, test.spectra()["rough"], test.speed)
    freqs, asd = peaks.attrs["freqs"], peaks.attrs["asd"]
    assert len(peaks) >= 4 and np.all(np.diff(peaks["peak (Hz)"]) > 0)
    for _, row in peaks.iterrows():
        f = row["peak (Hz)"]
        assert row["ASD ((m/s²)/√Hz)"] >= np.interp([f - 2.0, f + 2.0], freqs, asd).max()
    visco = ru.stages.frf_visco(setup.tire)
    modes = ru.response.modal_reduction.identify_modes(visco.freqs, visco.H_tot).freqs
    for _, row in peaks.iterrows():
        assert row["mode (Hz, fixed hub)"] == modes[int(row["nearest vertical mode"]) - 1]
        assert abs(row["mode (Hz, fixed hub)"] - row["peak (Hz)"]) == np.abs(modes - row["peak (Hz)"]).min()
    with pytest.raises(ValueError, match="band"):
        ru.experiments.corner.hub_mode_peaks(setup, test.spectra()["rough"], test.speed, band=(220.0, 40.0))
