"""Small analysis helpers shared by the stages: resonance peaks of frequency responses."""

from __future__ import annotations

import numpy as np
from scipy.signal import find_peaks


def resonance_peaks(freqs: np.ndarray, frf: np.ndarray, min_ratio: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
    """Resonance peaks of ``|frf|``: local maxima at least ``min_ratio`` times ``|frf(f_0)|``.

    Peak frequencies are refined by a parabola through the three samples around each maximum
    (of ``|frf|``), so they are not tied to the grid.

    Returns
    -------
    freqs_peak : ndarray
        Peak frequencies (Hz).
    magnitude : ndarray
        ``|frf|`` at the peak samples (same unit as ``frf``).
    """
    freqs = np.asarray(freqs, dtype=float)
    mag = np.abs(np.asarray(frf))
    idx, _ = find_peaks(mag, height=min_ratio * mag[0])
    refined = []
    for i in idx:
        y0, y1, y2 = mag[i - 1], mag[i], mag[i + 1]
        denom = y0 - 2 * y1 + y2
        shift = 0.5 * (y0 - y2) / denom if denom != 0 else 0.0
        refined.append(freqs[i] + shift * (freqs[i + 1] - freqs[i - 1]) / 2)
    return np.array(refined), mag[idx]
