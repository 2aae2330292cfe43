"""The chain at 0-250 and 0-400 Hz (paper: "easily improved to 400 Hz"), on the cleat and the rough road."""

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.analysis import relative_rms_error
from roadnoise_utils.experiments import bands
from roadnoise_utils.road.input import MAX_ROAD_STEP, SAMPLES_PER_PERIOD

TIRE = "165_65R14_cross_section"


@pytest.fixture(scope="module")
def extension():
    return ru.experiments.band_extension(TIRE)


def test_the_400_hz_chain_follows_its_direct_fe_reference(extension):
    """Fits over 0-400 Hz, sampled for 400 Hz: the RM cleat force within 1 % of the direct FE
    sum (peak and RMS), both band-limited the same way, as the 250 Hz chain is."""
    for band, model in extension.models.items():
        assert abs(model.cleat_rm.max() / model.cleat_fe.max() - 1) < 0.01, band
        assert relative_rms_error(model.cleat_rm, model.cleat_fe) < 0.01, band
        assert model.road_fits.rms_errors.max() < 0.01 and model.drum_fits.rms_errors.max() < 0.01
    wide, narrow = extension.models[400.0], extension.models[250.0]
    assert wide.drum_fits.n_poles > narrow.drum_fits.n_poles  # more modes in band
    # the 250 Hz model misses what the cleat excites between 250 and 400 Hz
    missed = extension.cleat_against_widest()["RMS against the widest FE"]
    assert relative_rms_error(narrow.cleat_rm, narrow.cleat_fe) < missed["0-250 Hz"]
    assert missed["0-400 Hz"] == pytest.approx(relative_rms_error(wide.cleat_rm, wide.cleat_fe), rel=1e-12)


def test_sampling_and_road_resolution_follow_the_band(extension):
    """Closed forms: 20 samples per period of the band (or the 3.5 mm road step), the shortest
    wavelength speed / band."""
    speed = extension.cleat_conditions.dynamic_speed
    for band, model in extension.models.items():
        expected = np.ceil(max(SAMPLES_PER_PERIOD * band, speed / MAX_ROAD_STEP) / 100) * 100
        assert model.cleat.sample_rate == pytest.approx(expected)
    road, cleat = bands.band_wavelengths(400.0, 120 / 3.6, 30 / 3.6)
    assert road == pytest.approx(0.08333, rel=1e-4) and cleat == pytest.approx(0.020833, rel=1e-4)
    table = extension.table()
    assert list(table.columns) == ["0-250 Hz", "0-400 Hz"]


def test_the_400_hz_model_follows_the_rough_road_above_250_hz(extension):
    """Between 250 and 350 Hz the 250 Hz fits extrapolate; the 400 Hz fits follow the FE spectrum."""
    table = extension.table()
    level = table.loc["rough road: RM vs FE level 250-350 Hz (dB)"]
    assert abs(level["0-400 Hz"]) < 0.1 < abs(level["0-250 Hz"])


def test_the_modal_reduction_reaches_twice_the_band(extension):
    for band, model in extension.models.items():
        assert model.modal.model.freqs.max() >= 2 * band


@pytest.mark.parametrize("bad", [(450.0,), (40.0,), (float("nan"),)])
def test_band_extension_refuses_bands_the_frfs_do_not_cover(bad):
    with pytest.raises(ValueError, match="bands"):
        ru.experiments.band_extension(TIRE, bands=bad)
    with pytest.raises(ValueError, match="bands is empty"):
        ru.experiments.band_extension(TIRE, bands=())
    with pytest.raises(ValueError, match="band"):
        bands.cleat_chain(TIRE, 500.0)
