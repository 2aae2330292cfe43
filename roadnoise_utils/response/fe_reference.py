"""FE reference solves: responses straight from the viscoelastic FE tire, no reduction, no fitting.

The second method every RM-chain result is checked against:

* :func:`fe_road_response` — the hub force of any road input in the frequency domain,
  :math:`F(\\omega) = \\sum_i H_i(\\omega)\\,U_i(\\omega)` with the direct :math:`H_i` at every FFT
  bin, band-limited by :func:`band_window` (the cleat test of paper Fig. 8-9,
  :func:`fe_cleat_response`);
* :func:`fe_moving_hub` — the hub released on a suspension to ground, solved together with
  every belt DOF (paper Eq. 5-7, in the exact mirror-symmetric subspace of
  :mod:`roadnoise_utils.tire.symmetry`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import scipy.sparse.linalg as spla

from ..road.cleat import cleat_input
from ..road.input import BAND, RoadInput
from ..tire.ring_model import FETModel
from ..tire.static import StaticState
from .frf import HubForceSolver, frf_visco
from .loaded import loaded_tire


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


def fe_road_response(
    fet: FETModel,
    static: StaticState,
    road: RoadInput,
    band: float = BAND,
    duration: float = 1.0,
    progress: bool = False,
) -> np.ndarray:
    """Hub force of ``road`` straight from the viscoelastic FE model, band-limited to ``band`` Hz.

    The tassello inputs are zero-padded to ``duration`` s (long enough for the decay), Fourier
    transformed, multiplied by the direct :math:`H_i(\\omega)` at every FFT bin up to the end of
    the :func:`band_window` taper, summed and transformed back.
    """
    return _frequency_response(fet, static, road.u, road.dt, "H", band, duration, progress=progress)


def fe_point_response(
    fet: FETModel,
    static: StaticState,
    heights: np.ndarray,
    dt: float,
    band: float = BAND,
    duration: float = 1.0,
    stick: bool = True,
) -> np.ndarray:
    r"""Hub force (N) of road heights under every contact point (no tassellation), band-limited to ``band`` Hz.

    ``heights`` is (n_contact_points, n_t) in m, in the order of ``static.tasselli``'s ``node_*``
    arrays, sampled every ``dt`` s: :math:`F(\omega) = \sum_n H_n(\omega) U_n(\omega)` with the
    direct point FRFs; ``stick=False`` lets the footprint slide longitudinally (frictionless
    contact, as the one-sided runs of :mod:`.one_sided`).
    """
    heights = np.asarray(heights, float)
    if heights.ndim != 2 or heights.shape[0] != int(static.contact.sum()):
        raise ValueError(f"heights must be (n_contact_points = {int(static.contact.sum())}, n_t), got {heights.shape}")
    return _frequency_response(fet, static, heights, dt, "H_points", band, duration, stick=stick)


def _frequency_response(
    fet: FETModel,
    static: StaticState,
    u: np.ndarray,
    dt: float,
    which: str,
    band: float,
    duration: float,
    progress: bool = False,
    stick: bool = True,
) -> np.ndarray:
    """:func:`frequency_domain_response` with the FRFs ``which`` of :func:`frf_visco`."""

    def frfs(freqs: np.ndarray) -> np.ndarray:
        return getattr(frf_visco(fet, static, freqs, progress=progress, stick=stick), which)

    return frequency_domain_response(frfs, u, dt, band, duration)


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


def fe_cleat_response(
    fet: FETModel,
    static: StaticState,
    speed: float,
    height: float,
    base: float,
    shape: str = "triangle",
    distance: tuple[float, float] = (-0.1, 0.5),
    duration: float = 1.0,
    band: float = BAND,
) -> tuple[RoadInput, np.ndarray]:
    """A cleat on the drum (:func:`roadnoise_utils.road.cleat.cleat_input`) and its FE hub force.

    ``speed`` in m/s, ``height`` and ``base`` in m, ``distance`` the travel range (m); the force
    is :func:`fe_road_response` of the cleat's tassello inputs (N, band-limited to ``band`` Hz).
    """
    road = cleat_input(static, speed, height, base, shape, distance)
    return road, fe_road_response(fet, static, road, band=band, duration=duration)


def record_length(road: RoadInput, duration: float) -> int:
    """Samples of a compared record: the road's, padded to ``duration`` s so the free decay fits in."""
    return max(road.u.shape[1], int(round(duration / road.dt)))


def fe_moving_hub(
    fet: FETModel,
    static: StaticState,
    freqs: np.ndarray,
    hub_mass: float,
    stiffness: float,
    damping: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Hub displacement and hub force per unit displacement of the whole footprint, FE direct.

    The hub's vertical DOF is free: mass ``hub_mass`` (kg) plus the FE's own rim-side mass, on
    a spring ``stiffness`` (N/m) and damper ``damping`` (N s/m) to ground. Returns
    ``(U_H, F_M)`` per unit road displacement (m/m, N/m), complex arrays over ``freqs`` (Hz).
    """
    for name, value in (("hub_mass", hub_mass), ("stiffness", stiffness), ("damping", damping)):
        if not (np.isfinite(value) and value >= 0):
            raise ValueError(f"{name} = {value}: valid range is [0, inf)")
    lt = loaded_tire(fet, static)
    solver = HubForceSolver(lt)
    basis = solver.basis_matrix
    own_mass = fet.hub_vertical_mass
    footprint = np.asarray(lt.road_input.sum(axis=1)).ravel()
    u_hub = np.empty(len(freqs), complex)
    f_hub = np.empty(len(freqs), complex)
    for k, f in enumerate(np.asarray(freqs, float)):
        w = 2 * np.pi * f
        row = lt.hub_row(w)
        row_reduced = np.asarray(basis.T @ row)
        corner = lt.hub_diagonal(w) - w**2 * (own_mass + hub_mass) + stiffness + 1j * w * damping
        # [[D, c], [c^T, corner]] [u; U_H] = [b; 0], with c the hub column: Schur complement on the hub
        lu = spla.splu(solver.dynamic_stiffness(w), permc_spec="NATURAL")
        b = np.asarray(basis.T @ (fet.modulus_ratio("tread", w) * footprint)).astype(complex)
        x_road = lu.solve(b)
        x_hub = lu.solve(row_reduced.astype(complex))
        u_hub[k] = -(row_reduced @ x_road) / (corner - row_reduced @ x_hub)
        u_belt = basis @ (x_road - x_hub * u_hub[k])
        f_hub[k] = -(lt.hub_diagonal(w) * u_hub[k] + row @ u_belt)
    return u_hub, f_hub
