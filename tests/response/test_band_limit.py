"""The frequency-domain reading of FRFs on their own grid (the second method of a cleat passage)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from roadnoise_utils.response.band_limit import frequency_domain_response, on_frf_grid


def test_the_frfs_are_read_at_their_own_frequencies_and_a_bin_between_them_is_refused():
    """FFT bins land on whole hertz only up to round-off (a 1 s record at 5.5 kHz puts bin 29 at
    29.000000000000004 Hz): each is read at the nearest grid frequency; half a hertz off is refused by name."""
    grid = np.arange(0.0, 401.0)
    frfs = SimpleNamespace(freqs=grid, H=np.vstack([grid, -grid]))
    at = on_frf_grid(frfs)
    bins = np.fft.rfftfreq(5500, 1.0 / 5500)[:300]
    assert np.array_equal(at(bins), np.vstack([np.arange(300.0), -np.arange(300.0)]))
    for off in ([0.5], [401.0], [-1.0]):
        with pytest.raises(ValueError, match="is not a frequency of the FRFs"):
            at(np.array(off))


def test_a_constant_frf_passes_the_input_band_limited():
    """Second method: H_i = k for every frequency gives k times the summed input, low-passed."""
    frfs = SimpleNamespace(freqs=np.arange(0.0, 401.0), H=np.full((2, 401), 3.0 + 0j))
    dt, n = 1.0 / 2000.0, 2000
    t = dt * np.arange(n)
    u = np.vstack([np.sin(2 * np.pi * 20.0 * t), np.cos(2 * np.pi * 40.0 * t)])
    force = frequency_domain_response(on_frf_grid(frfs), u, dt, band=250.0, duration=1.0)
    assert np.allclose(force, 3.0 * u.sum(axis=0), atol=1e-9)
