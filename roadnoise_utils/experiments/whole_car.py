"""The whole vehicle on the road test, and its checks (paper Eq. 8, beyond the paper; notebook 11).

Reads ``data/conditions/whole_car.toml`` once (:func:`whole_car_conditions`). The car
(:func:`.vehicle.full_car.load_full_vehicle`) carries the same tire on every wheel, with the
tire's cached RM stages (:func:`.corner.corner_setup`): the ring tire of the vehicle file or,
with ``tire``, its cross-section model.

* :func:`whole_car_run` — the 3-D road under the four wheels (rear a wheelbase behind), the
  fixed-hub forces, the closed car, every spectrum and each axle's left/right force coherence.
* :func:`wheelbase_check` — a 2-D road, where the frequency domain is exact: octave band powers
  of the time domain over the expectation of their Welch estimate
  (:func:`.vehicle.spectra.expected_psd`).
* :func:`axle_coherence` — the left/right coherence of the road forces against the road's own.
* :func:`limit_checks` — the closed-form limits: an infinitely heavy body gives each corner its
  quarter car, and a car symmetric front to rear has its pitch and heave notches at
  :math:`kV/L` and :math:`(k + 1/2) V/L`.
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass

import control
import numpy as np
import pandas as pd
from scipy.signal import coherence as estimated_coherence

from .. import guards
from ..repro import stages
from ..rm.simulation import simulate
from ..road import two_track
from ..road.input import profile_input
from ..road.textures import RoadSpectrum, load_texture
from ..vehicle import full_car
from ..vehicle.car_spectra import (
    CarSpectra,
    car_spectra,
    coherence_deviation,
    predicted_axle_coherence,
    welch_averages,
)
from ..vehicle.full_car import CORNERS, FullCar, FullCarRun
from ..vehicle.quarter_car import QuarterCar, vehicle_statespace
from ..vehicle.spectra import band_power_ratios, expected_psd, psd
from .conditions import load_conditions, resolve
from .corner import CornerSetup, corner_setup

#: Octaves of the wheelbase check (Hz).
OCTAVES = ((20.0, 40.0), (40.0, 80.0), (80.0, 160.0), (160.0, 250.0))
#: Outputs the wheelbase check compares.
CHECKED = ("a_hub_FL", "a_hub_RR", "a_mount_FL", "a_mount_RR", "a_heave", "a_pitch")


@dataclass(frozen=True)
class WholeCarConditions:
    """The whole-car road test and its checks, every default resolved (speeds in km/h, as the file)."""

    car: str
    speed_kmh: float
    texture: str
    duration: float
    seed: int
    check_speed_kmh: float
    check_duration: float
    samples_per_delay: int
    check_seed: int
    coherence_speed_kmh: float
    coherence_duration: float
    coherence_resolution: float
    coherence_seed: int

    @property
    def spectrum(self) -> RoadSpectrum:
        return load_texture(self.texture)


def whole_car_conditions(
    speed_kmh: float | None = None, texture: str | None = None, duration: float | None = None, seed: int | None = None
) -> WholeCarConditions:
    """``data/conditions/whole_car.toml`` (read once), any value given here overriding the road test's."""
    table = load_conditions("whole_car")
    main = resolve(table, car=None, speed_kmh=speed_kmh, texture=texture, duration=duration, seed=seed)
    check = resolve(table, "wheelbase_check", speed_kmh=None, duration=None, samples_per_delay=None, seed=None)
    coh = resolve(table, "coherence", speed_kmh=None, duration=None, resolution=None, seed=None)
    kmh = {"lo_open": True, "unit": "km/h"}
    return WholeCarConditions(
        car=str(main["car"]),
        speed_kmh=guards.real("speed_kmh", main["speed_kmh"], 0.0, 360.0, **kmh),
        texture=str(main["texture"]),
        duration=guards.real("duration", main["duration"], 2.5, 600.0, unit="s (2 Hz Welch needs > 2.5 s)"),
        seed=guards.seed(main["seed"]),
        check_speed_kmh=guards.real("wheelbase_check.speed_kmh", check["speed_kmh"], 0.0, 360.0, **kmh),
        check_duration=guards.real("wheelbase_check.duration", check["duration"], 2.5, 600.0, unit="s"),
        samples_per_delay=guards.integer("wheelbase_check.samples_per_delay", check["samples_per_delay"], 50, 10000),
        check_seed=guards.seed(check["seed"]),
        coherence_speed_kmh=guards.real("coherence.speed_kmh", coh["speed_kmh"], 0.0, 360.0, **kmh),
        coherence_duration=guards.real("coherence.duration", coh["duration"], 5.0, 600.0, unit="s"),
        coherence_resolution=guards.real("coherence.resolution", coh["resolution"], 0.05, 10.0, unit="Hz"),
        coherence_seed=guards.seed(coh["seed"]),
    )


@dataclass(frozen=True, eq=False)
class WholeCarSetup:
    """The car, its tire's RM stages (one :class:`.corner.CornerSetup`) and the closed car (python-control)."""

    car: FullCar
    tire: CornerSetup
    model: control.StateSpace


def whole_car_setup(car: str | FullCar | None = None, tire: str | None = None) -> WholeCarSetup:
    """The car of a vehicle file (default the conditions') on its front corner's tire or ``tire``."""
    car = (
        full_car.load_full_vehicle(whole_car_conditions().car if car is None else car)
        if not isinstance(car, FullCar)
        else car
    )
    corner = corner_setup(car.front, tire)
    return WholeCarSetup(car=car, tire=corner, model=full_car.full_car_model(car, corner.hub, corner.tire_hub_mass))


@dataclass(frozen=True, eq=False)
class WholeCarRun:
    """One road under the whole car: the run, its spectra and how long road to spectra took (s)."""

    run: FullCarRun
    spectra: CarSpectra
    seconds: float


def whole_car_run(
    setup: WholeCarSetup,
    spectrum: RoadSpectrum,
    speed: float,
    duration: float,
    seed: int,
    lateral: bool = True,
    resolution: float = 2.0,
    sample_rate: float | None = None,
) -> WholeCarRun:
    """``duration`` s at ``speed`` m/s on a generated road (3-D, or 2-D without ``lateral``): road -> the
    four wheels' inputs -> fixed-hub forces -> the closed car -> spectra (Welch, ``resolution`` Hz)."""
    start = time.perf_counter()
    static, positions = setup.tire.static, setup.car.positions
    travel = speed * duration
    road = two_track.two_track_road(spectrum, static, positions, travel, seed=seed, lateral=lateral)
    inputs = two_track.wheel_inputs(static, road, positions, speed, (0.0, travel), sample_rate=sample_rate)
    run = full_car.run_full_car(setup.tire.sections, setup.model, inputs)
    spectra = car_spectra(run, resolution=resolution)
    return WholeCarRun(run=run, spectra=spectra, seconds=time.perf_counter() - start)


@dataclass(frozen=True, eq=False)
class WheelbaseCheck:
    """The 2-D road run against the frequency domain.

    Attributes
    ----------
    run : WholeCarRun
    freqs, predicted : ndarray, dict
        The frequency-domain PSD of every output on a fine grid (Hz; unit^2/Hz).
    ratios : DataFrame
        Octave band power, time domain over the Welch expectation (:data:`OCTAVES` x :data:`CHECKED`).
    speed, wheelbase : float
        m/s and m: the notches' spacing ``speed / wheelbase``.
    """

    run: WholeCarRun
    freqs: np.ndarray
    predicted: dict[str, np.ndarray]
    ratios: pd.DataFrame
    speed: float
    wheelbase: float


def wheelbase_check(setup: WholeCarSetup, conditions: WholeCarConditions | None = None) -> WheelbaseCheck:
    """The car on a 2-D road at the check's speed, time vs frequency domain per octave (cached run)."""
    test = whole_car_conditions() if conditions is None else conditions
    speed, car = test.check_speed_kmh / 3.6, setup.car
    rate = test.samples_per_delay * speed / car.wheelbase
    run = _cached_run(setup, test.spectrum, speed, test.check_duration, test.check_seed, False, 2.0, rate)
    freqs = np.arange(0.0, 300.0, 0.1)
    fits = setup.tire.fits
    predicted = full_car.predicted_psd_2d(
        freqs, fits.responses(freqs), setup.tire.static, test.spectrum, speed, setup.model, car.wheelbase
    )
    ratios = {}
    for name in CHECKED:
        bins, expected = expected_psd(freqs, predicted[name], run.run.sample_rate)
        measured = psd(run.run.outputs[name], run.run.sample_rate)
        ratios[name] = band_power_ratios(measured, bins, expected, list(OCTAVES))
    table = pd.DataFrame(ratios, index=[f"{lo:.0f}-{hi:.0f} Hz" for lo, hi in OCTAVES])
    return WheelbaseCheck(run, freqs, predicted, table, speed, car.wheelbase)


def predicted_2d(
    setups: dict[str, WholeCarSetup], spectrum: RoadSpectrum, speed: float, freqs: np.ndarray
) -> dict[str, dict[str, np.ndarray]]:
    """Each setup's frequency-domain PSD of every output on a 2-D road at ``speed`` m/s
    (:func:`.vehicle.full_car.predicted_psd_2d`), by the setups' labels."""
    return {
        label: full_car.predicted_psd_2d(
            freqs, s.tire.fits.responses(freqs), s.tire.static, spectrum, speed, s.model, s.car.wheelbase
        )
        for label, s in setups.items()
    }


def _fingerprints(setup: WholeCarSetup) -> tuple:
    """The numerics behind a cached whole-car road run (cache fingerprints)."""
    from ..rm import simulation
    from ..road import input as road_input
    from ..road import textures

    return (two_track, road_input, textures, simulation, *stages.frf_runs(setup.tire.tire))


def _cached_run(setup: WholeCarSetup, spectrum, speed, duration, seed, lateral, resolution, sample_rate) -> WholeCarRun:
    """:func:`whole_car_run` as a cached stage (notebook 11 and the claims share it)."""
    from ..repro.cache import cached
    from ..vehicle import car_spectra as car_spectra_module

    inputs = {
        "tire": setup.tire.tire,
        "car": setup.car,
        "spectrum": spectrum,
        "speed": float(speed),
        "duration": float(duration),
        "seed": int(seed),
        "lateral": bool(lateral),
        "resolution": float(resolution),
        "sample_rate": None if sample_rate is None else float(sample_rate),
    }
    runs = (full_car, car_spectra_module, *_fingerprints(setup))
    return cached(
        "whole_car_run",
        inputs,
        lambda: whole_car_run(setup, spectrum, speed, duration, seed, lateral, resolution, sample_rate),
        runs=runs,
    )


@dataclass(frozen=True, eq=False)
class AxleCoherence:
    """Left/right coherence of the front axle's road forces: estimated, predicted and the road's (-).

    ``forces`` (2, samples): the left and right fixed-hub forces of the run (N), at ``sample_rate``
    Hz; ``deviation``: the estimate's standard deviation about the prediction
    (:func:`.vehicle.car_spectra.coherence_deviation`).
    """

    freqs: np.ndarray
    estimated: np.ndarray
    predicted: np.ndarray
    road: np.ndarray
    forces: np.ndarray
    sample_rate: float
    deviation: np.ndarray


def axle_forces(
    setup: WholeCarSetup, spectrum: RoadSpectrum, speed: float, duration: float, seed: int
) -> tuple[np.ndarray, float]:
    """The front axle's left and right fixed-hub forces (2, samples; N) on a 3-D road of only its
    two wheels' tracks, and the sample rate (Hz): what the coherence needs, half a whole-car run."""
    static, travel = setup.tire.static, speed * duration
    axle = setup.car.positions[:2]  # FL, FR
    road = two_track.two_track_road(spectrum, static, axle, travel, seed=seed)
    forces = []
    for y_wheel in axle[:, 1]:
        profile = lambda s, y, y_wheel=y_wheel: road.height(s, y_wheel + y)  # noqa: E731
        inputs = profile_input(static, profile, speed, (0.0, travel), oversample=1)
        forces.append(simulate(setup.tire.sections, inputs).force)
    return np.array(forces), float(inputs.sample_rate)


def predicted_coherence(
    setup: WholeCarSetup, conditions: WholeCarConditions | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Frequencies (Hz, the coherence run's Welch bins up to 15 Hz), the front axle's predicted
    force coherence and the road's at its track (-): the frequency domain alone."""
    test = whole_car_conditions() if conditions is None else conditions
    speed = test.coherence_speed_kmh / 3.6
    f = np.arange(1, int(15.0 / test.coherence_resolution) + 1) * test.coherence_resolution
    predicted, road = predicted_axle_coherence(
        f, setup.tire.fits.responses(f), setup.tire.static, test.spectrum, speed, setup.car.track_front
    )
    return f, predicted, road


def axle_coherence(setup: WholeCarSetup, conditions: WholeCarConditions | None = None) -> AxleCoherence:
    """The front axle on the coherence run's 3-D road (cached) against the frequency domain, 0-15 Hz."""
    from ..repro.cache import cached

    test = whole_car_conditions() if conditions is None else conditions
    speed = test.coherence_speed_kmh / 3.6
    inputs = {
        "tire": setup.tire.tire,
        "car": setup.car,
        "spectrum": test.spectrum,
        "speed": speed,
        "duration": test.coherence_duration,
        "seed": test.coherence_seed,
    }
    forces, rate = cached(
        "axle_forces",
        inputs,
        lambda: axle_forces(setup, test.spectrum, speed, test.coherence_duration, test.coherence_seed),
        runs=_fingerprints(setup),
    )
    f, predicted, road = predicted_coherence(setup, test)
    nperseg = int(round(rate / test.coherence_resolution))
    skip = int(round(0.5 * rate))  # the start-up, as the spectra
    bins, estimated = estimated_coherence(forces[0, skip:], forces[1, skip:], fs=rate, window="hann", nperseg=nperseg)
    on_bins = np.searchsorted(bins, f)
    if not np.allclose(bins[on_bins], f):
        raise RuntimeError("the coherence estimate's Welch bins are not the prediction's frequencies")
    averages = welch_averages(forces.shape[1] - skip, nperseg)
    deviation = coherence_deviation(predicted, averages)
    return AxleCoherence(f, estimated[on_bins], predicted, road, forces, rate, deviation)


def _with_heavy_body(car: FullCar, factor: float) -> FullCar:
    """``car`` with its body ``factor`` times heavier, past the file's ranges (a limit, not a car)."""
    out = object.__new__(FullCar)
    for field in dataclasses.fields(FullCar):
        object.__setattr__(out, field.name, getattr(car, field.name))
    body = full_car.Body(*(factor * getattr(car.body, f.name) for f in dataclasses.fields(full_car.Body)))
    object.__setattr__(out, "body", body)
    return out


def _grounded(corner: QuarterCar) -> QuarterCar:
    """The quarter car with its body held (an infinitely heavy body)."""
    elements = tuple(
        dataclasses.replace(e, a="ground" if e.a == "body" else e.a, b="ground" if e.b == "body" else e.b)
        for e in corner.elements
    )
    masses = {k: v for k, v in corner.masses.items() if k != "body"}
    return QuarterCar(corner.name, corner.tire, masses, elements, corner.hub, corner.upper_mount)


def heavy_body_difference(car: FullCar, freqs: tuple[float, ...] = (5.0, 50.0, 120.0, 240.0)) -> float:
    """Largest relative difference of each corner's hub and mount responses, body 1e9 times heavier,
    from its quarter car on a held body (-): the full car's corner limit (tested to 1e-7)."""
    s = 2j * np.pi * np.asarray(freqs, float)
    heavy = np.asarray(full_car.full_car_statespace(_with_heavy_body(car, 1e9))(s))
    worst = 0.0
    for j, name in enumerate(CORNERS):
        quarter = np.asarray(vehicle_statespace(_grounded(car.corner(name)))(s))  # (z_hub, a_hub, a_mount) x F
        for k, q in enumerate(quarter[:, 0]):
            mine = heavy[4 * k + j, j]
            worst = max(worst, float(np.max(np.abs(mine - q) / np.abs(q))))
    return worst


def notch_depth(setup: WholeCarSetup, speed: float, f_max: float = 250.0) -> pd.DataFrame:
    """On the car made symmetric front to rear, pitch at :math:`f = kV/L` and heave at :math:`(k + 1/2) V/L`
    relative to each output's largest value over 1 Hz - ``f_max`` (the wheelbase filtering's closed form)."""
    car = setup.car
    symmetric = dataclasses.replace(car, cg_to_front=0.5 * car.wheelbase, rear=car.front, track_rear=car.track_front)
    model = full_car.full_car_model(symmetric, setup.tire.hub, setup.tire.tire_hub_mass)
    base = speed / symmetric.wheelbase
    grid = np.arange(1.0, f_max, 0.25)
    rows = {}
    for name, offset in (("a_pitch", 0.0), ("a_heave", 0.5)):
        k = model.output_labels.index(name)
        notches = base * (np.arange(0 if offset else 1, int(f_max / base)) + offset)  # heave from V/2L
        at = np.abs(full_car.axle_delay_transfer(model, notches, speed, symmetric.wheelbase)[k])
        peak = np.abs(full_car.axle_delay_transfer(model, grid, speed, symmetric.wheelbase)[k]).max()
        rows[name] = {"notches": notches.size, "first (Hz)": notches[0], "largest at a notch / peak": at.max() / peak}
    return pd.DataFrame(rows).T


def notch_frequencies(speed: float, wheelbase: float, f_max: float) -> dict[str, np.ndarray]:
    """The closed form of the wheelbase filtering on a car symmetric front to rear (Hz): pitch
    vanishes at :math:`kV/L`, heave at :math:`(k + 1/2) V/L`."""
    base = speed / wheelbase
    k = np.arange(0, int(f_max / base) + 1)
    return {"pitch": base * k[1:][base * k[1:] <= f_max], "heave": (base * (k + 0.5))[base * (k + 0.5) <= f_max]}
