"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru

CAR = "midsize_195_65R15"


def test_band_power_helpers_on_a_flat_spectrum():
    """A white PSD: power shares are bandwidth ratios, the RMS is sqrt(level x bandwidth)."""
    f = np.arange(0.0, 501.0, 0.5)
    p = np.full(f.size, 4.0)
    assert ru.vehicle.spectra.power_share((f, p), 0.0, 50.0, band=(2.0, 250.0)) == pytest.approx(48 / 248, rel=0.02)
    assert ru.vehicle.spectra.band_rms((f, p), band=(2.0, 250.0)) == pytest.approx(np.sqrt(4.0 * 248.0), rel=0.01)
    ratios = ru.vehicle.spectra.band_power_ratios(
        (f, p), np.arange(0.0, 501.0), np.full(501, 2.0), [(10, 20), (100, 200)]
    )
    assert np.allclose(ratios, 2.0)


def test_expected_welch_estimate_of_a_steep_spectrum():
    """A first-order (1/f^2) process, 400 s: the Welch estimate matches :func:`expected_psd` of its
    exact PSD bin by bin (median within 1 %) and per octave from 10 Hz (2 %), where the raw PSD's
    band powers read up to 20 % high (the window's leakage on a steep spectrum); bad grids refused."""
    from scipy.signal import lfilter

    fs, pole = 2000.0, 0.995
    rng = np.random.default_rng(0)
    x = lfilter([1.0], [1.0, -pole], rng.standard_normal(int(fs * 400)))
    measured = ru.vehicle.spectra.psd(x, fs)
    fine = np.arange(0.0, 500.0, 0.02)
    exact = 2.0 / fs / np.abs(1.0 - pole * np.exp(-2j * np.pi * fine / fs)) ** 2  # one-sided, unit white noise
    bins, expected = ru.vehicle.spectra.expected_psd(fine, exact, fs)
    assert bins[0] == pytest.approx(2.0) and bins[-1] <= 500.0 - 16 * 2.0
    on_bins = np.isin(np.round(measured[0], 9), np.round(bins, 9))
    assert abs(np.median(measured[1][on_bins] / expected) - 1.0) < 0.01
    bands = [(10, 20), (20, 40), (40, 80), (80, 160)]
    ratios = ru.vehicle.spectra.band_power_ratios(measured, bins, expected, bands)
    assert np.all(np.abs(ratios - 1.0) < 0.02), ratios
    raw = ru.vehicle.spectra.band_power_ratios(measured, fine, exact, bands)
    assert raw[0] > 1.1  # what the comparison without the window's kernel would report
    with pytest.raises(ValueError, match="tenth of a Welch bin"):
        ru.vehicle.spectra.expected_psd(np.arange(0.0, 500.0, 0.5), np.ones(1000), fs)


def test_octave_rms_of_a_sine_and_of_white_noise():
    """A 100 Hz sine lies in the 125 Hz octave with its RMS; white noise splits its power by the bands' widths."""
    from roadnoise_utils.vehicle.spectra import octave_rms

    freqs = np.arange(0.0, 500.0, 0.5)
    sine = np.where(freqs == 100.0, 0.5 / 0.5, 0.0)  # amplitude 1: power 1/2 in one bin of 0.5 Hz
    np.testing.assert_allclose(octave_rms((freqs, sine)), [0.0, 0.0, np.sqrt(0.5), 0.0])
    white = np.ones_like(freqs)
    powers = octave_rms((freqs, white)) ** 2
    np.testing.assert_allclose(powers.sum(), 250.0 - 31.5 / np.sqrt(2.0), atol=1.0)
