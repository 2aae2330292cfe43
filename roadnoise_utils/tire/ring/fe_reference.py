"""FE reference solves of the ring tire: responses straight from the viscoelastic FE tire, no reduction, no fitting."""

from __future__ import annotations

import numpy as np

from ...response.band_limit import frequency_domain_response
from ...road.cleat import cleat_input
from ...road.input import BAND, RoadInput
from .frf import HubForceSolver, frf_visco
from .loaded import loaded_tire
from .mechanics import FETModel
from .static import StaticState


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
    contact, as the one-sided runs of :mod:`roadnoise_utils.tire.contact`).
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
        lu = solver.factorise(w)
        b = np.asarray(basis.T @ (fet.modulus_ratio("tread", w) * footprint)).astype(complex)
        x_road = lu.solve(b)
        x_hub = lu.solve(row_reduced.astype(complex))
        u_hub[k] = -(row_reduced @ x_road) / (corner - row_reduced @ x_hub)
        u_belt = basis @ (x_road - x_hub * u_hub[k])
        f_hub[k] = -(lt.hub_diagonal(w) * u_hub[k] + row @ u_belt)
    return u_hub, f_hub
