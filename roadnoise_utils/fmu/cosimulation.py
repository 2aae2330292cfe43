"""A quarter car co-simulated with the tire FMU: a Python master loop, the car's discrete state space.

What a vehicle tool does with the FMU, in a few lines: at every communication point ``t_k``
the master reads the car's hub displacement, sets it and the road heights at the footprint's
leading edge on the FMU, reads the hub force :math:`F_M` (Eq. 5) and advances the car one
step with that force held over the step (its exact zero-order-hold discretisation), then the
FMU. The car's own model is exact; the coupling (the force held over a step while the hub
moves) is first order in the step: the error against the closed loop of
:func:`roadnoise_utils.vehicle.corner.corner_model` (the quarter car closed through
:math:`G_H` in continuous time) halves when the step halves.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.signal import cont2discrete

from ..vehicle.corner import OUTPUTS
from ..vehicle.quarter_car import QuarterCar, vehicle_statespace, with_extra_hub_mass
from .drive import TireSlave


@dataclass(frozen=True, eq=False)
class CoSimulationRun:
    """Histories of :func:`cosimulate_quarter_car`: time (s), the hub force :math:`F_M` (N) and the car's
    outputs ``z_hub`` (m), ``a_hub`` and ``a_mount`` (m/s^2)."""

    t: np.ndarray
    force: np.ndarray
    outputs: dict[str, np.ndarray]

    @property
    def sample_rate(self) -> float:
        return 1.0 / float(self.t[1] - self.t[0])


def leading_edge_heights(profile, slave: TireSlave, n: int, start: float = 0.0) -> np.ndarray:
    """The road heights the FMU takes (n_strips, n): ``profile(s)`` or ``profile(s, y)`` (m) at the leading edge
    (``leading_edge_x`` ahead of the footprint centre) after the wheel has travelled ``start + speed t_k``."""
    s = slave.leading_edge + start + slave.speed * slave.dt * np.arange(n)
    try:
        heights = np.array([profile(s, y) for y in slave.strip_y], float)
    except TypeError:  # a road uniform across the width: profile(s)
        heights = np.broadcast_to(np.asarray(profile(s), float), (slave.n_strips, n)).copy()
    if heights.shape != (slave.n_strips, n):
        raise ValueError(f"profile must give one height per road coordinate: got shape {heights.shape[1:]} for {n}")
    bad = ~np.isfinite(heights).all(axis=0)
    if bad.any():
        first = int(np.argmax(bad))
        raise ValueError(
            f"the road has no finite height at s = {s[first]:.4g} m (step {first} of {n}): it ends before the "
            f"travel's last point s = {s[-1]:.4g} m (the leading edge is {slave.leading_edge * 1e3:.1f} mm ahead "
            "of the footprint centre); give a longer road or a shorter run"
        )
    return heights


def cosimulate_quarter_car(
    slave: TireSlave, vehicle: QuarterCar, tire_hub_mass: float, road: np.ndarray
) -> CoSimulationRun:
    """Co-simulate ``vehicle`` with the tire FMU ``slave`` over ``road`` (n_strips, n) leading-edge heights (m).

    ``tire_hub_mass`` (kg): the FE tire's rim-side mass, added to the hub (:math:`G_H` leaves it out),
    as in :func:`roadnoise_utils.vehicle.corner.corner_model`. The car starts at rest with its hub at 0, the
    FMU in the steady state of the first road heights and that hub.
    """
    road = np.asarray(road, float)
    if road.ndim != 2 or road.shape[0] != slave.n_strips or road.shape[1] < 2:
        raise ValueError(f"road must be (n_strips = {slave.n_strips}, n >= 2) heights, got shape {road.shape}")
    car = vehicle_statespace(with_extra_hub_mass(vehicle, tire_hub_mass))
    a, b, c, d = (np.asarray(m, float) for m in (car.A, car.B, car.C, car.D))
    step_matrix, drive, _, _, _ = cont2discrete((a, b, c, d), slave.dt, method="zoh")
    drive = drive[:, 0]
    n = road.shape[1]
    state = np.zeros(a.shape[0])
    force, outputs = np.empty(n), np.empty((n, c.shape[0]))
    for k in range(n):
        slave.set(road[:, k], c[0] @ state)  # z_hub has no feedthrough from the force
        force[k] = slave.outputs()[0]
        outputs[k] = c @ state + d[:, 0] * force[k]
        state = step_matrix @ state + drive * force[k]
        if k + 1 < n:
            slave.step()
    return CoSimulationRun(t=slave.dt * np.arange(n), force=force, outputs=dict(zip(OUTPUTS, outputs.T)))
