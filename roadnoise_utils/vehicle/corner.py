"""One vehicle corner on a road: the RM tire coupled with the quarter car (paper Eq. 8, Fig. 11-14).

Time domain: the fixed-hub road force :math:`F_F(t)`
is computed once by the fast block-diagonal simulation (:mod:`roadnoise_utils.rm.simulation`), then a *small*
system — the quarter car closed through the hub FRF :math:`G_H` — is driven by it. Because
the whole chain is linear this equals integrating the full Eq. 8 state vector, at a fraction
of the cost.

Frequency domain, as a check: for a road uniform across the width,
:math:`U_i(f) = K_i(f/V)\\,Z(f)` with :math:`K_i` the Fourier transform of tassello ``i``'s
road kernel (:mod:`roadnoise_utils.road.kernels`), so the PSD of the fixed-hub force is
:math:`S_{FF}(f) = |\\sum_i H_i(f) K_i(f/V)|^2\\,G(f/V)/V` and any response
:math:`y` has :math:`S_{yy} = |T_{F_F \\to y}(f)|^2 S_{FF}(f)`.
"""

from __future__ import annotations

from dataclasses import dataclass

import control
import numpy as np

from ..rm.fitting import FitSet
from ..rm.moving_hub import hub_statespace
from ..rm.simulation import ModalSections, response, simulate
from ..road.input import RoadInput
from ..road.kernels import kernel_transforms
from ..road.textures import RoadSpectrum
from ..tire.model import Footprint
from .quarter_car import QuarterCar, couple, vehicle_statespace, with_extra_hub_mass
from .spectra import psd

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


def spectra(
    run: CornerRun, outputs: tuple[str, ...] = ("a_hub", "a_mount")
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Welch PSD (:func:`psd`) of some outputs of a run: ``name -> (freqs Hz, PSD)``."""
    return {name: psd(run.outputs[name], run.sample_rate) for name in outputs}


def predicted_psd(
    freqs: np.ndarray,
    tassello_frf: np.ndarray,
    static: Footprint,
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
