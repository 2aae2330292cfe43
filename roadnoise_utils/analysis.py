"""Small analysis helpers shared by the stages: resonance peaks of frequency responses."""

from __future__ import annotations

import numpy as np
import pandas as pd
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


def band_errors(
    freqs: np.ndarray,
    reference: np.ndarray,
    approximation: np.ndarray,
    bands: tuple[tuple[float, float], ...] = ((0.0, 100.0), (100.0, 150.0), (150.0, 250.0)),
) -> pd.DataFrame:
    """Relative error of an FRF against a reference in frequency bands.

    Columns: ``complex rel. RMS`` = ||approx - ref|| / ||ref|| over the band (complex values,
    sensitive to small frequency shifts of sharp peaks), and ``modulus median rel.`` = median
    of ||approx| / |ref| - 1| (what a plot of the modulus shows).
    """
    freqs = np.asarray(freqs, float)
    rows = {}
    for lo, hi in bands:
        b = (freqs >= lo) & (freqs <= hi)
        ref, app = reference[b], approximation[b]
        rows[f"{lo:g}-{hi:g} Hz"] = {
            "complex rel. RMS": float(np.linalg.norm(app - ref) / np.linalg.norm(ref)),
            "modulus median rel.": float(np.median(np.abs(np.abs(app) / np.abs(ref) - 1))),
        }
    return pd.DataFrame(rows).T.rename_axis("band")


def peak_comparison(
    freqs: np.ndarray, reference: np.ndarray, approximation: np.ndarray, f_max: float = 300.0, min_ratio: float = 2.0
) -> pd.DataFrame:
    """Resonance peaks of a reference FRF and the nearest peak of an approximation: frequency and height."""
    f_ref, m_ref = resonance_peaks(freqs, reference, min_ratio)
    f_app, m_app = resonance_peaks(freqs, approximation, min_ratio)
    rows = []
    for f, m in zip(f_ref, m_ref):
        if f > f_max or f_app.size == 0:
            continue
        k = int(np.argmin(np.abs(f_app - f)))
        rows.append(
            {
                "reference (Hz)": f,
                "approximation (Hz)": f_app[k],
                "shift (%)": 100 * (f_app[k] / f - 1),
                "height ratio": m_app[k] / m,
            }
        )
    return pd.DataFrame(rows, index=pd.Index(np.arange(1, len(rows) + 1), name="peak"))


def format_small(value: float, floor: float = 1e-9) -> str:
    """``"< floor"`` for round-off-sized values, else ``value`` in ``.1e``: stable printed output."""
    return f"< {floor:.0e}" if abs(value) < floor else f"{value:.1e}"
