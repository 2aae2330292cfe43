"""Small analysis helpers shared by the stages: resonance peaks, relative errors, damped components,
the largest of equal candidates."""

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


def relative_rms_error(approximation: np.ndarray, reference: np.ndarray) -> float:
    r""":math:`\|a - r\|_2 / \|r\|_2` over all samples (real or complex): the error measure of
    every "relative RMS error" the collection reports (fits, FRF bands, time histories)."""
    reference = np.asarray(reference)
    return float(np.linalg.norm(np.asarray(approximation) - reference) / np.linalg.norm(reference))


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
            "complex rel. RMS": relative_rms_error(app, ref),
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


def local_frf_errors(reference, models: dict, frequency: float) -> pd.DataFrame:
    """Relative error of each model's local FRFs :math:`H_i` against the reference's, tassello by tassello.

    A sum over the footprint hides errors that cancel; this compares every tassello, at the sample
    nearest ``frequency`` (Hz) and at 0 Hz.

    Parameters
    ----------
    reference : FRFResult
        The reference FRFs (e.g. the direct viscoelastic ones), starting at 0 Hz.
    models : dict of str to FRFResult
        The approximations, on the reference's frequencies.
    frequency : float
        Frequency of the first comparison (Hz), within the reference's range.

    Returns
    -------
    DataFrame
        One row per model: ``max at f``, ``median at f`` (over the tasselli, at the sample ``f``
        nearest ``frequency``) and ``max at 0 Hz``; the sample's frequency is in ``attrs["f"]``.
    """
    freqs = np.asarray(reference.freqs, dtype=float)
    if freqs[0] != 0.0:
        raise ValueError(f"reference.freqs: must start at 0 Hz for the static comparison, starts at {freqs[0]} Hz")
    if not freqs[0] <= frequency <= freqs[-1]:
        raise ValueError(f"frequency = {frequency} Hz: valid range is [0, {freqs[-1]}] Hz (the reference's)")
    k = int(np.argmin(np.abs(freqs - frequency)))
    rows = {}
    for name, frf in models.items():
        at_f = np.abs(frf.H[:, k] - reference.H[:, k]) / np.abs(reference.H[:, k])
        at_0 = np.abs(frf.H[:, 0] - reference.H[:, 0]) / np.abs(reference.H[:, 0])
        rows[name] = {"max at f": at_f.max(), "median at f": float(np.median(at_f)), "max at 0 Hz": at_0.max()}
    table = pd.DataFrame(rows).T.rename_axis("model")
    table.attrs["f"] = float(freqs[k])
    return table


def format_small(value: float, floor: float = 1e-9) -> str:
    """``"< floor"`` for round-off-sized values, else ``value`` in ``.1e``: stable printed output."""
    return f"< {floor:.0e}" if abs(value) < floor else f"{value:.1e}"


def argmax_all(values: np.ndarray, rtol: float = 1e-6) -> np.ndarray:
    """Indices of every value within ``rtol`` (relative) of the largest, ascending.

    The choice of "the largest" among equal candidates — the mirror images of a symmetric
    footprint, the left and right wheels of a symmetric car — is left to round-off by
    ``np.argmax``, which changes with the BLAS build and the thread count; this names them all.
    """
    values = np.asarray(values, dtype=float)
    if values.ndim != 1 or values.size == 0 or not np.all(np.isfinite(values)):
        raise ValueError(f"values: need a finite, non-empty 1-D array, got shape {values.shape}")
    if not 0.0 <= rtol < 1.0:
        raise ValueError(f"rtol = {rtol}: valid range is [0, 1)")
    top = values.max()
    return np.flatnonzero(values >= top - rtol * abs(top))


def damped_components(y: np.ndarray, dt: float, n_components: int = 6) -> pd.DataFrame:
    """Damped sinusoids in a free decay, by the matrix pencil method (Hua & Sarkar 1990).

    ``y`` (uniform step ``dt`` s) is modelled as :math:`\\sum_k a_k e^{s_k t}`; the poles come
    from the signal itself (a shifted-Hankel eigenproblem), the amplitudes by least squares.

    Returns
    -------
    pandas.DataFrame
        One row per oscillating component (conjugate pairs merged), largest amplitude first:
        ``frequency (Hz)``, ``damping ratio``, ``amplitude`` (peak value at the start of ``y``).
    """
    y = np.asarray(y, dtype=float)
    if y.ndim != 1 or y.size < 4 * n_components or not np.all(np.isfinite(y)):
        raise ValueError(f"need a finite 1-D decay of at least {4 * n_components} samples")
    order = 2 * n_components
    pencil = y.size // 3
    hankel = np.lib.stride_tricks.sliding_window_view(y, pencil + 1)  # (N - L, L + 1)
    _, _, vt = np.linalg.svd(hankel, full_matrices=False)
    v = vt[:order].T
    z = np.linalg.eigvals(np.linalg.pinv(v[:-1]) @ v[1:])
    s = np.log(z.astype(complex)) / dt
    basis = np.exp(np.outer(np.arange(y.size) * dt, s))
    # each column scaled to unit norm first: a spurious growing pole (noise the pencil fits, e.g. a
    # contact's chatter) has a column ~1e19 times the others, and least squares would cut them all off
    norms = np.linalg.norm(basis, axis=0)
    amplitude = np.linalg.lstsq(basis / norms, y.astype(complex), rcond=None)[0] / norms
    rows = []
    for sk, ak in zip(s, amplitude):
        if sk.imag <= 0:
            continue  # keep the upper member of each pair
        omega = abs(sk)
        rows.append(
            {"frequency (Hz)": sk.imag / (2 * np.pi), "damping ratio": -sk.real / omega, "amplitude": 2 * abs(ak)}
        )
    table = pd.DataFrame(rows).sort_values("amplitude", ascending=False, ignore_index=True)
    table.index = pd.Index(np.arange(1, len(table) + 1), name="component")
    return table


def distinct_peaks(
    distance: np.ndarray, force: np.ndarray, window: tuple[float, float] = (-np.inf, np.inf), prominence: float = 0.1
) -> int:
    """How many peaks of ``force`` inside ``window`` (m) stand out by at least ``prominence`` times
    the largest force there (scipy's peak prominence): the "distinct peaks" of a cleat passage."""
    inside = (distance >= window[0]) & (distance <= window[1])
    values = np.asarray(force)[inside]
    idx, _ = find_peaks(values, prominence=prominence * values.max())
    return int(idx.size)


def force_peaks(
    distance: np.ndarray,
    force: np.ndarray,
    n: int = 2,
    min_separation: float = 0.02,
    window: tuple[float, float] = (-np.inf, np.inf),
) -> pd.DataFrame:
    """The ``n`` largest local maxima of a force history inside ``window`` (m), at least
    ``min_separation`` m apart, in order of distance."""
    step = float(np.median(np.diff(distance)))
    idx, _ = find_peaks(force, distance=max(1, int(min_separation / step)))
    idx = idx[(distance[idx] >= window[0]) & (distance[idx] <= window[1])]
    top = idx[np.argsort(force[idx])[::-1][:n]]
    top = np.sort(top)
    return pd.DataFrame(
        {"distance (m)": distance[top], "force (N)": force[top]},
        index=pd.Index(np.arange(1, top.size + 1), name="peak"),
    )
