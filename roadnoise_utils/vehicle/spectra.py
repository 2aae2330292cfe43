"""Spectra of simulated signals: Welch PSDs with stated resolution and band statistics (paper Fig. 11-14)."""

from __future__ import annotations

import numpy as np
from scipy.signal import welch


def psd(
    signal: np.ndarray, sample_rate: float, resolution: float = 2.0, skip: float = 0.5
) -> tuple[np.ndarray, np.ndarray]:
    """Welch PSD (one-sided, unit^2/Hz) with Hann windows of ``1/resolution`` s, 50 % overlap,
    after dropping the first ``skip`` s (the start-up transient)."""
    start = int(round(skip * sample_rate))
    nperseg = int(round(sample_rate / resolution))
    if signal.size - start < 2 * nperseg:
        raise ValueError(f"signal too short for {resolution} Hz resolution: need > {2 / resolution + skip:.1f} s")
    return welch(signal[start:], fs=sample_rate, window="hann", nperseg=nperseg, noverlap=nperseg // 2, detrend=False)


#: Welch bins each side of a bin over which :func:`expected_psd` spreads a PSD (the Hann
#: window's leakage 16 bins away is below 1e-7 of its peak).
LEAKAGE_BINS = 16


def _hann_kernel(offset: np.ndarray, sample_rate: float, nperseg: int) -> np.ndarray:
    """:math:`|W(\\nu)|^2 / (f_s \\sum w^2)` of the periodic Hann window of ``nperseg`` samples at
    frequency offsets ``offset`` (Hz): the spectral window of a Welch estimate (1/Hz)."""
    theta = 2.0 * np.pi * np.asarray(offset, float) / sample_rate

    def dirichlet(x):  # |sum_n e^{-i x n}|, n < nperseg, with its phase about the window centre dropped
        half = 0.5 * x
        small = np.abs(np.sin(half)) < 1e-12
        value = np.where(small, float(nperseg), np.sin(nperseg * half) / np.where(small, 1.0, np.sin(half)))
        return value * np.exp(-1j * half * (nperseg - 1))

    step = 2.0 * np.pi / nperseg
    w = 0.5 * dirichlet(theta) - 0.25 * dirichlet(theta - step) - 0.25 * dirichlet(theta + step)
    return np.abs(w) ** 2 / (sample_rate * 0.375 * nperseg)  # sum of the Hann window squared: 3 N / 8


def expected_psd(
    freqs: np.ndarray, density: np.ndarray, sample_rate: float, resolution: float = 2.0
) -> tuple[np.ndarray, np.ndarray]:
    """What :func:`psd` estimates, on average, from a signal of PSD ``density`` (given on the fine, uniform ``freqs``).

    A Welch estimate is the PSD seen through its window's spectral kernel: a steep spectrum (a
    road's n^-2, a body acceleration above the wheel hop) or a notched one (the wheelbase delay)
    is spread over the window's main lobe, and the bins' powers differ from the PSD's own. The
    expectation is :math:`E\\hat P(f_k) = \\int_0^\\infty P(f) [K(f_k - f) + K(f_k + f)]\\,df`,
    :math:`K = |W|^2 / (f_s \\sum w^2)` (the second term: leakage from negative frequencies), here
    over :data:`LEAKAGE_BINS` bins each side. Give ``freqs`` from 0 Hz for the lowest bins (else
    the bins start that many bins above ``freqs[0]``). Returns the Welch bins (from the first
    above 0 Hz) and their expected values: compare measured and expected bin by bin
    (:func:`band_power_ratios`).
    """
    freqs, density = np.asarray(freqs, float), np.asarray(density, float)
    df = float(freqs[1] - freqs[0])
    if freqs.ndim != 1 or density.shape != freqs.shape or not np.allclose(np.diff(freqs), df, rtol=1e-6):
        raise ValueError("freqs must be uniform and density given at each of them")
    nperseg = int(round(sample_rate / resolution))
    bin_width = sample_rate / nperseg
    if df > 0.1 * bin_width:
        raise ValueError(f"freqs step {df:g} Hz: valid range is <= {0.1 * bin_width:g} Hz (a tenth of a Welch bin)")
    reach = LEAKAGE_BINS * bin_width
    first = 1 if freqs[0] <= 0.5 * df else int(np.ceil((freqs[0] + reach) / bin_width))
    last = int(np.floor((freqs[-1] - reach) / bin_width))
    bins = bin_width * np.arange(first, last + 1)
    weight = np.full(freqs.size, df)
    weight[[0, -1]] *= 0.5  # trapezoidal rule

    def expectation(f: float) -> float:
        near = np.abs(freqs - f) <= reach
        kernel = _hann_kernel(f - freqs[near], sample_rate, nperseg) + _hann_kernel(
            f + freqs[near], sample_rate, nperseg
        )
        return float(np.sum(density[near] * kernel * weight[near]))

    return bins, np.array([expectation(f) for f in bins])


def _in_band(freqs: np.ndarray, band: tuple[float, float]) -> np.ndarray:
    return (freqs > band[0]) & (freqs <= band[1])


def power_share(
    spectrum: tuple[np.ndarray, np.ndarray], f_low: float, f_high: float, band: tuple[float, float] = (2.0, 250.0)
) -> float:
    """Share of the power in ``band`` (Hz, lower edge excluded) lying in ``[f_low, f_high)`` Hz."""
    f, p = spectrum
    inside = _in_band(f, band)
    return float(p[inside & (f >= f_low) & (f < f_high)].sum() / p[inside].sum())


def band_rms(spectrum: tuple[np.ndarray, np.ndarray], band: tuple[float, float] = (2.0, 250.0)) -> float:
    """RMS of a signal in ``band`` (Hz) from its PSD (square root of the integrated PSD)."""
    f, p = spectrum
    inside = _in_band(f, band)
    return float(np.sqrt(np.trapezoid(p[inside], f[inside])))


def band_power_ratios(
    spectrum: tuple[np.ndarray, np.ndarray],
    predicted_freqs: np.ndarray,
    predicted: np.ndarray,
    bands: list[tuple[float, float]],
) -> np.ndarray:
    """Power of a measured (Welch) spectrum over the power of a predicted PSD, band by band.

    Both are integrated as sums times their (uniform) frequency steps over ``[f_low, f_high)``.
    """
    f, p = spectrum
    fc = np.asarray(predicted_freqs, float)
    ratios = []
    for lo, hi in bands:
        measured = p[(f >= lo) & (f < hi)].sum() * (f[1] - f[0])
        expected = predicted[(fc >= lo) & (fc < hi)].sum() * (fc[1] - fc[0])
        ratios.append(measured / expected)
    return np.array(ratios)


#: Octave centres (Hz) of the road-noise band (IEC 61260 nominal: 31.5 to 250 Hz).
OCTAVE_CENTRES = (31.5, 63.0, 125.0, 250.0)


def octave_rms(
    spectrum: tuple[np.ndarray, np.ndarray], centres=OCTAVE_CENTRES, band: tuple[float, float] = (20.0, 250.0)
) -> np.ndarray:
    """:func:`band_rms` of a signal's PSD in each octave band (unit).

    The band of centre ``c`` (Hz) spans ``c / sqrt(2)`` to ``c * sqrt(2)``, clipped to ``band`` (Hz).
    """
    edges = [(max(c / np.sqrt(2.0), band[0]), min(c * np.sqrt(2.0), band[1])) for c in centres]
    return np.array([band_rms(spectrum, edge) for edge in edges])
