"""Spectra of the whole vehicle: every corner and the body, and the left/right coherence of the road forces.

The time-domain run of :func:`.full_car.run_full_car` gives Welch PSDs of every output
(:func:`car_spectra`); the frequency domain gives what they should be on a 2-D road
(:func:`.full_car.predicted_psd_2d`) and, on a 3-D road, how coherent the two wheels of an axle
are (:func:`predicted_axle_coherence`).

On an isotropic road two wheel tracks ``b`` apart have the coherence :math:`\\gamma^2(n, b)`
(:func:`.road.textures.coherence`). A wheel's fixed-hub force sums its belt strips:
:math:`F = \\sum_s A_s(f) Z(y_{wheel} + y_s)` with :math:`A_s = \\sum_{i \\in s} H_i(f) K_{i,s}(f/V)`
(tassello ``i``'s FRF times its road kernel on strip ``s``), so

.. math:: S_{LR}(f) = \\frac{G(n)}{V} \\sum_{s, s'} A_s A_{s'}^* \\gamma(n, |y_L + y_s - y_R - y_{s'}|),
          \\qquad n = f/V,

and :math:`S_{LL}` the same with :math:`y_L = y_R`. With a track much wider than the footprint
the force coherence :math:`|S_{LR}|^2 / (S_{LL} S_{RR})` is the road's at the track width; the
footprint's width makes each force average across its own strips, which lowers
:math:`S_{LL}` at short wavelengths but not the cross-spectrum's coherent part.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.signal import coherence as estimated_coherence

from ..road.input import strip_centres
from ..road.kernels import strip_kernels
from ..road.textures import RoadSpectrum, as_spectrum, coherence
from .full_car import CORNERS, FullCarRun
from .spectra import psd

#: The axles' wheel pairs (left, right).
AXLES = {"front": ("FL", "FR"), "rear": ("RL", "RR")}


@dataclass(frozen=True, eq=False)
class CarSpectra:
    """Welch spectra of a whole-vehicle run.

    Attributes
    ----------
    freqs : ndarray
        Frequencies (Hz).
    psd : dict of str to ndarray
        One-sided PSD of every output of the run by name (``a_hub_FL`` ... ``a_roll``; unit^2/Hz).
    force_coherence : dict of str to ndarray
        Per axle (``front``, ``rear``): the coherence :math:`\\gamma^2` of the left and right
        fixed-hub forces (-).
    """

    freqs: np.ndarray
    psd: dict[str, np.ndarray]
    force_coherence: dict[str, np.ndarray]


def car_spectra(run: FullCarRun, resolution: float = 2.0, skip: float = 0.5) -> CarSpectra:
    """Every output's PSD and each axle's left/right force coherence, with :func:`.spectra.psd`'s
    windows (Hann, ``1/resolution`` s, 50 % overlap) after dropping the first ``skip`` s."""
    spectra = {name: psd(values, run.sample_rate, resolution, skip) for name, values in run.outputs.items()}
    freqs = next(iter(spectra.values()))[0]
    start, nperseg = int(round(skip * run.sample_rate)), int(round(run.sample_rate / resolution))
    forces = dict(zip(CORNERS, run.fixed_hub_force))
    force_coherence = {}
    for axle, (left, right) in AXLES.items():
        _, c = estimated_coherence(
            forces[left][start:], forces[right][start:], fs=run.sample_rate, window="hann", nperseg=nperseg
        )
        force_coherence[axle] = c
    return CarSpectra(freqs=freqs, psd={k: v[1] for k, v in spectra.items()}, force_coherence=force_coherence)


def welch_averages(n_samples: int, nperseg: int) -> float:
    """Equivalent number of independent averages of a Welch estimate with Hann windows at 50 %
    overlap: :math:`K / (1 + 2\\rho^2)`, :math:`\\rho = 0.167` the correlation of adjacent
    windows (Welch 1967, IEEE Trans. Audio Electroacoust. 15(2))."""
    windows = max(1, (n_samples - nperseg) // (nperseg // 2) + 1)
    return windows / (1.0 + 2.0 * 0.167**2)


def coherence_deviation(coherence_value: np.ndarray, averages: float) -> np.ndarray:
    """Standard deviation of an estimated coherence :math:`\\hat\\gamma^2` about a true
    :math:`\\gamma^2` from ``averages`` independent windows: :math:`\\sqrt{2}\\,(1 - \\gamma^2)|\\gamma| / \\sqrt{n_d}`
    (Bendat & Piersol, *Random Data*, 4th ed., Eq. 9.82)."""
    g2 = np.clip(np.asarray(coherence_value, float), 0.0, 1.0)
    return np.sqrt(2.0) * (1.0 - g2) * np.sqrt(g2) / np.sqrt(averages)


def strip_transfers(
    static, tassello_frf: np.ndarray, wavenumbers: np.ndarray, step: float = 2.0e-4
) -> tuple[np.ndarray, np.ndarray]:
    """Each belt strip's share of the fixed-hub force per unit road height on its track.

    ``tassello_frf`` (tasselli, freqs) at the frequencies ``V * wavenumbers``. Returns the
    strips' lateral positions (m) and :math:`A_s(f)` (strips, freqs); summed over the strips it
    is the 2-D road's transfer (:func:`.corner.predicted_psd`).
    """
    parts, x0 = strip_kernels(static.tasselli, step)
    centres = strip_centres(static)
    n = np.asarray(wavenumbers, float)
    y, transfers = [], []
    for strip, rows, kernels in parts:
        x = x0 + step * np.arange(kernels.shape[1])
        transforms = step * (kernels @ np.exp(2j * np.pi * np.outer(x, n)))  # (rows, freqs)
        y.append(centres[strip])
        transfers.append(np.sum(np.asarray(tassello_frf)[rows] * transforms, axis=0))
    return np.array(y), np.array(transfers)


def predicted_axle_coherence(
    freqs: np.ndarray,
    tassello_frf: np.ndarray,
    static,
    spectrum: RoadSpectrum,
    speed: float,
    track: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Coherence :math:`\\gamma^2` of the left and right fixed-hub forces of an axle of ``track`` m
    on an isotropic 3-D road (module notes), and the road's own at the track width (-)."""
    spectrum = as_spectrum(spectrum)
    f = np.asarray(freqs, float)
    n = f / speed
    y, a = strip_transfers(static, tassello_frf, n)

    def cross(offset: float) -> np.ndarray:
        total = np.zeros(f.size, complex)
        for j in range(y.size):
            for k in range(y.size):
                total += a[j] * np.conj(a[k]) * coherence(spectrum, n, abs(offset + y[j] - y[k]))
        return total

    own, across = cross(0.0).real, cross(float(track))
    with np.errstate(invalid="ignore", divide="ignore"):
        force = np.where(own > 0, np.abs(across) ** 2 / own**2, 0.0)
    return force, coherence(spectrum, n, float(track)) ** 2
