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
