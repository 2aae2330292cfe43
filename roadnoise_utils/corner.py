"""One vehicle corner on a road: the RM tire coupled with the quarter car (paper Eq. 8, Fig. 11-14).

Time domain, as the issue and DESIGN section 4 ask: the fixed-hub road force :math:`F_F(t)`
is computed once by the fast block-diagonal simulation (:mod:`.simulation`), then a *small*
system — the quarter car closed through the hub FRF :math:`G_H` — is driven by it. Because
the whole chain is linear this equals integrating the full Eq. 8 state vector, at a fraction
of the cost.

Frequency domain, as a check: for a road uniform across the width,
:math:`U_i(f) = K_i(f/V)\\,Z(f)` with :math:`K_i` the Fourier transform of tassello ``i``'s
road kernel, so the PSD of the fixed-hub force is
:math:`S_{FF}(f) = |\\sum_i H_i(f) K_i(f/V)|^2\\,G(f/V)/V` and any response
:math:`y` has :math:`S_{yy} = |T_{F_F \\to y}(f)|^2 S_{FF}(f)`.
"""

from __future__ import annotations

from dataclasses import dataclass

import control
import numpy as np
from scipy.signal import welch

from .fitting import FitSet
from .movinghub import hub_statespace
from .road import RoadInput, tassello_kernels
from .simulation import ModalSections, response, simulate
from .static import StaticState
from .textures import RoadSpectrum
from .vehicle import QuarterCar, couple, vehicle_statespace, with_extra_hub_mass

#: Output names of the corner model.
OUTPUTS = ("z_hub", "a_hub", "a_mount")


def corner_model(vehicle: QuarterCar, hub: FitSet, tire_hub_mass: float) -> control.StateSpace:
    """Quarter car closed through :math:`G_H`: input :math:`F_F` (N), outputs ``z_hub, a_hub, a_mount``.

    ``tire_hub_mass`` (kg), the FE tire's rim-side mass, is added to the hub (``G_H`` leaves it out).
    """
    return couple(vehicle_statespace(with_extra_hub_mass(vehicle, tire_hub_mass)), hub_statespace(hub))


@dataclass(frozen=True, eq=False)
class CornerRun:
    """Time histories of one run: road force and accelerations.

    Attributes
    ----------
    t : ndarray
        Time (s).
    fixed_hub_force : ndarray
        :math:`F_F` (N).
    outputs : dict of str to ndarray
        ``z_hub`` (m), ``a_hub`` and ``a_mount`` (m/s^2).
    road : RoadInput
        The tassello inputs.
    """

    t: np.ndarray
    fixed_hub_force: np.ndarray
    outputs: dict[str, np.ndarray]
    road: RoadInput

    @property
    def sample_rate(self) -> float:
        return 1.0 / float(self.t[1] - self.t[0])


def run_corner(tire: control.StateSpace | ModalSections, corner: control.StateSpace, road: RoadInput) -> CornerRun:
    """Road -> fixed-hub force (fast simulation) -> corner responses (small system)."""
    force = simulate(tire, road).force
    out = response(corner, road.t, force[None, :])
    return CornerRun(t=road.t, fixed_hub_force=force, outputs=dict(zip(OUTPUTS, out)), road=road)


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


def spectra(
    run: CornerRun, outputs: tuple[str, ...] = ("a_hub", "a_mount")
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Welch PSD (:func:`psd`) of some outputs of a run: ``name -> (freqs Hz, PSD)``."""
    return {name: psd(run.outputs[name], run.sample_rate) for name in outputs}


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


def kernel_transforms(static: StaticState, wavenumbers: np.ndarray, step: float = 2.0e-4) -> np.ndarray:
    """:math:`K_i(n) = \\int k_i(x) e^{i 2\\pi n x} dx` for every tassello (rows) and wavenumber (cycles/m)."""
    kernels, x0 = tassello_kernels(static.tasselli, step)
    x = x0 + step * np.arange(kernels.shape[1])
    phase = np.exp(2j * np.pi * np.outer(x, np.asarray(wavenumbers, float)))
    return step * (kernels @ phase)


def _phi(z: np.ndarray) -> np.ndarray:
    """:math:`(e^z - 1 - z)/z^2`, with its Taylor series near 0 (no cancellation)."""
    z = np.asarray(z, dtype=complex)
    small = np.abs(z) < 0.1
    safe = np.where(small, 1.0, z)
    closed = (np.expm1(safe) - safe) / safe**2
    series = sum(z**j / float(np.prod(np.arange(1, j + 3))) for j in range(10))
    return np.where(small, series, closed)


def point_transforms(static: StaticState, wavenumbers: np.ndarray) -> np.ndarray:
    """Transforms of each contact point's normalised hat kernel, (n_points, n_wavenumbers).

    A hat rising over ``a`` to 1 at ``x`` and falling over ``b`` has
    :math:`\\int N e^{iks} ds = e^{ikx}\\,[a\\,\\varphi(-ika) + b\\,\\varphi(ikb)]`,
    :math:`\\varphi(z) = (e^z - 1 - z)/z^2`; divided by its area :math:`(a+b)/2`.
    """
    t = static.tasselli
    k = 2 * np.pi * np.asarray(wavenumbers, float)[None, :]
    a, b, x = t.node_dx_minus[:, None], t.node_dx_plus[:, None], t.node_x[:, None]
    return np.exp(1j * k * x) * (a * _phi(-1j * k * a) + b * _phi(1j * k * b)) * 2 / (a + b)


def tassellation_error(static: StaticState, point_frf: np.ndarray, wavelengths: np.ndarray) -> np.ndarray:
    """Error of the hub force from tasselli against contact-point resolution, per wavelength.

    Relative to the force a long wave of the same amplitude would give, :math:`|\\sum_n H_n|`
    (at short wavelengths the exact force itself nearly cancels over the footprint).

    For a sinusoidal road of wavelength λ, the FE model at the resolution of its contact points
    gives :math:`F = \\sum_n H_n Z_n`; the RM model moves each tassello as one block with the
    weighted average of its points, :math:`F = \\sum_i H_i \\sum_{n\\in i} w_n Z_n`.
    ``point_frf``: the contact points' FRFs at the frequency of interest (one column).
    """
    t = static.tasselli
    z = point_transforms(static, 1.0 / np.asarray(wavelengths, float))  # (points, wavelengths)
    points = np.asarray(point_frf)[:, None] * z
    exact = points.sum(axis=0)
    membership = t.membership()
    tassello_frf = membership @ np.asarray(point_frf)
    tassello_input = membership @ (t.node_weight[:, None] * z)
    blocks = (tassello_frf[:, None] * tassello_input).sum(axis=0)
    return np.abs(blocks - exact) / np.abs(np.sum(point_frf))


def predicted_psd(
    freqs: np.ndarray,
    tassello_frf: np.ndarray,
    static: StaticState,
    spectrum: RoadSpectrum,
    speed: float,
    corner: control.StateSpace | None = None,
) -> dict[str, np.ndarray]:
    """Frequency-domain PSDs for a road uniform across the width (see the module docstring).

    ``tassello_frf``: (n_tasselli, n_freq) fixed-hub FRFs at ``freqs`` (Hz), e.g. the fitted
    ones. Returns ``F_F`` (N^2/Hz) and, with ``corner``, each of its outputs' PSD.
    """
    f = np.asarray(freqs, float)
    n = f / speed
    transfer = np.sum(tassello_frf * kernel_transforms(static, n), axis=0)  # F_F per road height
    road_psd = spectrum.psd(n) / speed
    out = {"F_F": np.abs(transfer) ** 2 * road_psd}
    if corner is not None:
        gains = corner(2j * np.pi * f)  # (outputs, 1, freqs)
        for k, name in enumerate(OUTPUTS):
            out[name] = np.abs(np.asarray(gains)[k, 0]) ** 2 * out["F_F"]
    return out
