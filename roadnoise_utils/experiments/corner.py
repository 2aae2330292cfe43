"""The quarter car on the road test: the moving-hub tire on a vehicle corner (paper Eq. 8, Fig. 10-14).

:func:`corner_setup` builds, once, what every corner computation needs — the vehicle file, its
tire's cached stages (loaded state, tassello fits, hub fit), the corner model closed through
:math:`G_H` and the fast form of the fixed-hub tire; :func:`quarter_car` drives it over each
texture of the road test (:mod:`~roadnoise_utils.experiments.road`) and returns the time histories and Welch spectra.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import control
import numpy as np
import pandas as pd

from ..analysis import resonance_peaks
from ..repro import stages
from ..response.modal_reduction import identify_modes
from ..rm.fitting import FitSet
from ..rm.realisation import assemble_fixed_hub
from ..rm.simulation import ModalSections, modal_sections
from ..road.textures import RoadSpectrum
from ..tire.model import Footprint, ModelSpec
from ..vehicle.corner import CornerRun, corner_model, predicted_psd, run_corner, spectra
from ..vehicle.quarter_car import QuarterCar, load_vehicle
from .road import RoadTestConditions, road_test_conditions, texture_run

#: The paper's car (195/65 R15) as our vehicle file.
PAPER_CAR = "midsize_195_65R15"

Spectrum = tuple[np.ndarray, np.ndarray]


@dataclass(frozen=True, eq=False)
class CornerSetup:
    """A vehicle corner with its RM tire, ready to be driven.

    Attributes
    ----------
    vehicle : QuarterCar
        The corner (``data/vehicles``).
    tire : ModelSpec
        Its tire.
    static : Footprint
        The tire loaded on the flat road.
    fits, hub : FitSet
        Tassello fits (Eq. 1) and the hub fit :math:`G_H` (Eq. 6).
    tire_hub_mass : float
        The FE tire's rim-side mass, added to the hub (kg).
    model : control.StateSpace
        The quarter car closed through :math:`G_H`: input :math:`F_F` (N), outputs
        ``z_hub, a_hub, a_mount``.
    sections : ModalSections
        The fixed-hub tire in the form the fast simulation runs.
    """

    vehicle: QuarterCar
    tire: ModelSpec
    static: Footprint
    fits: FitSet
    hub: FitSet
    tire_hub_mass: float
    model: control.StateSpace
    sections: ModalSections

    def predicted(self, freqs: np.ndarray, spectrum: RoadSpectrum, speed: float) -> dict[str, np.ndarray]:
        """Frequency-domain PSDs of every corner output for a road uniform across the width (2D), at ``speed`` m/s."""
        return predicted_psd(freqs, self.fits.responses(freqs), self.static, spectrum, speed, self.model)


def corner_setup(vehicle: str | QuarterCar = PAPER_CAR, tire: str | None = None) -> CornerSetup:
    """The corner of a vehicle file with its tire's cached RM stages.

    ``tire`` (a tire file name or path) replaces the vehicle file's, e.g. by its cross-section
    model (``"195_65R15_cross_section"``).
    """
    car = load_vehicle(vehicle) if not isinstance(vehicle, QuarterCar) else vehicle
    tire = stages.load_tire(car.tire if tire is None else tire)
    fits, hub = stages.fit_tasselli(tire), stages.fit_hub(tire)
    rim_side_mass = stages.rim_side_mass(tire)
    return CornerSetup(
        vehicle=car,
        tire=tire,
        static=stages.solve_static(tire),
        fits=fits,
        hub=hub,
        tire_hub_mass=rim_side_mass,
        model=corner_model(car, hub, rim_side_mass),
        sections=modal_sections(assemble_fixed_hub(fits)),
    )


@dataclass(frozen=True, eq=False)
class QuarterCarTest:
    """The corner driven over each texture of the road test.

    Attributes
    ----------
    setup : CornerSetup
        The corner.
    conditions : RoadTestConditions
        The resolved road test.
    runs : dict of str to CornerRun
        Time histories per texture.
    spectra : dict of str to dict
        Welch PSDs per texture: ``"a_hub"`` and ``"a_mount"`` -> (freqs Hz, PSD (m/s^2)^2/Hz).
    seconds : dict of str to float
        Wall time from road to time histories, per texture (s).
    lateral : bool
        3D roads (one coherent track per belt strip) or uniform across the width.
    """

    setup: CornerSetup
    conditions: RoadTestConditions
    runs: dict[str, CornerRun]
    spectra: dict[str, dict[str, Spectrum]]
    seconds: dict[str, float]
    lateral: bool


def quarter_car(
    vehicle: str | QuarterCar | CornerSetup = PAPER_CAR,
    conditions: RoadTestConditions | None = None,
    lateral: bool = True,
    tire: str | None = None,
) -> QuarterCarTest:
    """Drive a corner over every texture of the road test: road -> F_F -> corner -> spectra.

    ``tire`` replaces the vehicle file's tire (:func:`corner_setup`; not with a ``CornerSetup``).
    """
    if isinstance(vehicle, CornerSetup) and tire is not None:
        raise ValueError("tire: give it with a vehicle file, not with a CornerSetup (which has its tire)")
    setup = vehicle if isinstance(vehicle, CornerSetup) else corner_setup(vehicle, tire)
    test = road_test_conditions() if conditions is None else conditions
    runs, seconds = {}, {}
    for name, spectrum in test.spectra().items():
        start = time.perf_counter()
        runs[name] = run_corner(setup.sections, setup.model, texture_run(setup.static, spectrum, test, lateral))
        seconds[name] = time.perf_counter() - start
    found = {name: spectra(run) for name, run in runs.items()}
    _spectra_stage(setup, test, lateral, lambda: found)  # kept for quarter_car_spectra (the claims)
    return QuarterCarTest(setup=setup, conditions=test, runs=runs, spectra=found, seconds=seconds, lateral=lateral)


def _spectra_stage(setup: CornerSetup, test: RoadTestConditions, lateral: bool, compute) -> dict:
    from ..repro.cache import cached
    from ..rm import simulation
    from ..road import input as road_input
    from ..vehicle import corner as corner_module

    inputs = {"vehicle": setup.vehicle, "tire": setup.tire, "conditions": test, "lateral": bool(lateral)}
    runs = (corner_module, simulation, road_input, texture_run, *stages.frf_runs(setup.tire))
    return cached("quarter_car_spectra", inputs, compute, runs=runs)


def quarter_car_spectra(
    vehicle: str | QuarterCar = PAPER_CAR,
    conditions: RoadTestConditions | None = None,
    lateral: bool = True,
    tire: str | None = None,
) -> dict[str, dict[str, tuple[np.ndarray, np.ndarray]]]:
    """The spectra of :func:`quarter_car` (texture -> output -> (freqs, PSD)), cached: a run of the same
    test (notebook 07) leaves them for the claims."""
    setup = corner_setup(vehicle, tire)
    test = road_test_conditions() if conditions is None else conditions

    def compute() -> dict:
        return {
            name: spectra(run_corner(setup.sections, setup.model, texture_run(setup.static, spectrum, test, lateral)))
            for name, spectrum in test.spectra().items()
        }

    return _spectra_stage(setup, test, lateral, compute)


def hub_mode_peaks(
    setup: CornerSetup, spectrum: RoadSpectrum, speed: float, band: tuple[float, float] = (40.0, 220.0)
) -> pd.DataFrame:
    """The paper's Fig. 14 reading: the peaks of the hub-acceleration ASD in ``band`` (Hz) and the tire's
    vertical mode nearest each.

    The ASD is the frequency-domain prediction on the 2D road (smooth, every 1 Hz), so its peaks
    do not depend on a Welch estimate's variance; the modes are identified from the tire's
    fixed-hub :math:`H_{tot}` (paper Fig. 4, step 1).

    Returns
    -------
    DataFrame
        One row per peak (numbered from 1): ``peak (Hz)``, ``ASD ((m/s²)/√Hz)`` (the prediction at
        the peak), ``nearest vertical mode`` (its number) and ``mode (Hz, fixed hub)``;
        ``attrs["freqs"]``, ``attrs["asd"]``: the prediction the peaks were found on.
    """
    lo, hi = band
    if not 0.0 < lo < hi:
        raise ValueError(f"band = {band}: valid range is 0 < low < high (Hz)")
    freqs = np.arange(lo, hi + 1.0, 1.0)
    asd = np.sqrt(setup.predicted(freqs, spectrum, speed)["a_hub"])
    peaks, _ = resonance_peaks(freqs, asd, min_ratio=0.0)
    visco = stages.frf_visco(setup.tire)
    modes = identify_modes(visco.freqs, visco.H_tot).freqs
    nearest = np.array([int(np.argmin(np.abs(modes - f))) for f in peaks], dtype=int)
    table = pd.DataFrame(
        {
            "peak (Hz)": peaks,
            "ASD ((m/s²)/√Hz)": np.interp(peaks, freqs, asd),
            "nearest vertical mode": nearest + 1,
            "mode (Hz, fixed hub)": modes[nearest] if peaks.size else np.zeros(0),
        },
        index=pd.Index(np.arange(1, peaks.size + 1), name="peak"),
    )
    table.attrs.update(freqs=freqs, asd=asd)
    return table
