"""Roads for a whole vehicle: the four wheels' tasselli on a two-track road, the rear delayed.

Each wheel's belt strips see their own lateral positions of one height field: a 3-D road of
tracks at every strip of the left and the right wheels (:func:`.textures.generate_field`,
jointly Gaussian with the coherence of an isotropic surface, :func:`.textures.coherence`), so the
left and right wheel tracks are coherent for wavelengths much longer than the track width and
independent for shorter ones. The rear axle runs the front's road a wheelbase later: with the
rear axle at road coordinate ``d`` the front one is at ``d + wheelbase``, a delay of
``wheelbase / V``.
"""

from __future__ import annotations

import numpy as np

from .. import guards
from .input import TEXTURE_STEP, RoadInput, contact_tracks, profile_input, texture_length
from .textures import RoadProfile, RoadSpectrum, as_spectrum, generate_field, generate_profile

#: The wheels, in the vehicle's corner order (:data:`.vehicle.full_car.CORNERS`).
WHEELS = ("FL", "FR", "RL", "RR")


def wheel_tracks(static, positions: np.ndarray, rounding: float = 1e-3) -> np.ndarray:
    """Lateral positions (m) of the road tracks the four wheels' strips in contact run on.

    ``positions`` (4, 2): each wheel's ``(x, y)`` (m). Tracks closer than ``rounding`` (m) are
    merged (e.g. a rear track 2 cm narrower than the front puts its strips on their own tracks;
    the same track on both axles shares them).
    """
    strips = contact_tracks(static)
    wanted = np.concatenate([y + strips for _, y in np.asarray(positions, float)])
    return np.unique(np.round(wanted / rounding) * rounding)


def two_track_road(
    spectrum: RoadSpectrum, static, positions: np.ndarray, travel: float, seed: int, lateral: bool = True
) -> RoadProfile:
    """The generated road of a whole-vehicle run of ``travel`` m: every wheel track (3-D) or uniform across (2-D).

    Long enough for the rear axle's travel, the wheelbase ahead of it and the footprints' margin.
    """
    spectrum = as_spectrum(spectrum)
    positions = np.asarray(positions, float)
    wheelbase = float(positions[:, 0].max() - positions[:, 0].min())
    length = texture_length(spectrum, travel + wheelbase)
    if not lateral:
        return generate_profile(spectrum, length, TEXTURE_STEP, seed=seed)
    return generate_field(spectrum, length, TEXTURE_STEP, wheel_tracks(static, positions), seed=seed)


def _check_road(road: RoadProfile, static, positions: np.ndarray, travel: tuple[float, float]) -> None:
    """Refuse a road narrower than the wheel tracks or, for a measured road, shorter than the travel plus the wheelbase."""
    wheelbase = float(positions[:, 0].max() - positions[:, 0].min())
    if road.y.size > 1:
        needed = wheel_tracks(static, positions)
        if needed.min() < road.y.min() - 0.01 or needed.max() > road.y.max() + 0.01:
            raise ValueError(
                f"road: its tracks span y = {road.y.min():.3f} to {road.y.max():.3f} m, narrower than the "
                f"wheels' {needed.min():.3f} to {needed.max():.3f} m (the track width and the footprints): "
                "give a wider road"
            )
    if not road.periodic:
        span = road.s[-1] - road.s[0]
        if travel[1] - travel[0] + wheelbase > span:
            raise ValueError(
                f"road: {span:.2f} m long, but the travel ({travel[1] - travel[0]:.2f} m) plus the wheelbase "
                f"delay ({wheelbase:.2f} m) needs more: shorten the travel"
            )


def wheel_inputs(
    static,
    road: RoadProfile,
    positions: np.ndarray,
    speed: float,
    travel: tuple[float, float],
    sample_rate: float | None = None,
) -> dict[str, RoadInput]:
    """Tassello displacements of each wheel (:data:`WHEELS`) on ``road``, the same tire on every wheel.

    Parameters
    ----------
    static : StaticState or SectionStaticState
        The loaded tire.
    road : RoadProfile
        A 3-D road with tracks at every wheel's strips (:func:`two_track_road`), or a 2-D road
        (one track: both wheels of an axle see it).
    positions : ndarray (4, 2)
        Each wheel's ``(x, y)`` (m) from the centre of mass (:attr:`.vehicle.full_car.FullCar.positions`).
    speed : float
        Rolling speed (m/s).
    travel : (float, float)
        Travel of the rear axle on the road (m): the front axle is a wheelbase ahead.
    sample_rate : float, optional
        Samples per second (default :func:`.input.sample_rate_for`).
    """
    positions = np.asarray(positions, float)
    if positions.shape != (4, 2) or not np.all(np.isfinite(positions)):
        raise ValueError(f"positions must be (4, 2): (x, y) of each wheel {WHEELS} in m, got shape {positions.shape}")
    travel = guards.interval("travel", travel)
    _check_road(road, static, positions, travel)
    rear = positions[:, 0].min()
    inputs = {}
    for wheel, (x, y_wheel) in zip(WHEELS, positions):
        ahead = x - rear  # the wheelbase for the front axle, 0 for the rear
        if road.y.size > 1:  # 3-D: strip at y of the tire on the track at y_wheel + y

            def profile(s, y, ahead=ahead, y_wheel=y_wheel):
                return road.height(s + ahead, y_wheel + y)
        else:

            def profile(s, ahead=ahead):
                return road.height(s + ahead)

        inputs[wheel] = profile_input(
            static, profile, speed, travel, sample_rate=sample_rate, oversample=1, description=f"{wheel} wheel"
        )
    return inputs
