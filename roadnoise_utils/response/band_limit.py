"""FE reference solves: responses straight from the viscoelastic FE tire, no reduction, no fitting.

The second method every RM-chain result is checked against:

* :func:`fe_road_response` — the hub force of any road input in the frequency domain,
  :math:`F(\\omega) = \\sum_i H_i(\\omega)\\,U_i(\\omega)` with the direct :math:`H_i` at every FFT
  bin, band-limited by :func:`band_window` (the cleat test of paper Fig. 8-9,
  :func:`fe_cleat_response`);
* :func:`fe_moving_hub` — the hub released on a suspension to ground, solved together with
  every belt DOF (paper Eq. 5-7, in the exact mirror-symmetric subspace of
  :mod:`roadnoise_utils.tire.ring.symmetry`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from ..road.input import BAND, RoadInput

if TYPE_CHECKING:
    from ..tire.model import FRFResult


def band_window(freqs: np.ndarray, band: float = BAND, taper: float = 50.0) -> np.ndarray:
    """Zero-phase low-pass: 1 up to ``band``, raised-cosine to 0 at ``band + taper`` Hz."""
    w = np.ones_like(freqs)
    ramp = (freqs > band) & (freqs < band + taper)
    w[ramp] = 0.5 * (1 + np.cos(np.pi * (freqs[ramp] - band) / taper))
    w[freqs >= band + taper] = 0.0
    return w


def band_limited(force: np.ndarray, dt: float, band: float = BAND, n_fft: int | None = None) -> np.ndarray:
    """``force`` low-passed by :func:`band_window` (zero phase, FFT), same length."""
    n = n_fft or force.size
    spectrum = np.fft.rfft(force, n)
    spectrum *= band_window(np.fft.rfftfreq(n, dt), band)
    return np.fft.irfft(spectrum, n)[: force.size]


def record_length(road: RoadInput, duration: float) -> int:
    """Samples of a compared record: the road's, padded to ``duration`` s so the free decay fits in."""
    return max(road.u.shape[1], int(round(duration / road.dt)))


def frequency_domain_response(
    frfs: Callable[[np.ndarray], np.ndarray], u: np.ndarray, dt: float, band: float = BAND, duration: float = 1.0
) -> np.ndarray:
    """Hub force (N) of the inputs ``u`` (n_inputs, n_t; m, every ``dt`` s) through direct FRFs.

    The inputs are zero-padded to ``duration`` s, Fourier transformed, weighed by ``frfs(freqs)``
    (n_inputs, n_freqs; N/m) at every FFT bin the :func:`band_window` keeps, summed, windowed and
    transformed back. Works for the FRFs of either tire model.
    """
    n = max(u.shape[1], int(round(duration / dt)))
    freqs = np.fft.rfftfreq(n, dt)
    window = band_window(freqs, band)
    keep = window > 0
    spectrum = np.zeros(freqs.size, complex)
    spectrum[keep] = np.sum(frfs(freqs[keep]) * np.fft.rfft(u, n, axis=1)[:, keep], axis=0) * window[keep]
    return np.fft.irfft(spectrum, n)[: u.shape[1]]


def on_frf_grid(frfs: FRFResult) -> Callable[[np.ndarray], np.ndarray]:
    """The FRFs ``frfs.H`` (n_inputs, n_freqs) as a function of frequency for
    :func:`frequency_domain_response`, read at their own frequencies (no interpolation): a record
    of whole seconds puts every FFT bin on the default 1 Hz grid (each bin taken at the nearest of
    the FRFs' frequencies, within 1e-6 Hz); a bin between them is refused."""

    def at(freqs: np.ndarray) -> np.ndarray:
        freqs = np.asarray(freqs, dtype=float)
        after = np.clip(np.searchsorted(frfs.freqs, freqs), 1, frfs.freqs.size - 1)
        nearer_below = np.abs(freqs - frfs.freqs[after - 1]) <= np.abs(frfs.freqs[after] - freqs)
        pick = np.where(nearer_below, after - 1, after)
        if np.any(np.abs(frfs.freqs[pick] - freqs) > 1e-6):
            off = freqs[np.argmax(np.abs(frfs.freqs[pick] - freqs))]
            raise ValueError(
                f"the record's FFT bin at {off:.6g} Hz is not a frequency of the FRFs ({frfs.freqs[0]:g}-"
                f"{frfs.freqs[-1]:g} Hz, {frfs.freqs.size} of them): a record of whole seconds on a 1 Hz grid "
                "reaching past the band"
            )
        return frfs.H[:, pick]

    return at
