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
