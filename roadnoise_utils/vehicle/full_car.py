"""The whole vehicle on four RM tires (paper Eq. 8): a rigid body in heave, pitch and roll on four corners.

Paper, *Simulation of Wheel-Road Interaction*: with :math:`x_T` the states of the four
moving-hub tires, :math:`u_R` the displacements of all their tasselli, :math:`F_V` the four hub
forces and :math:`u_V` the hub displacements,

.. math::

    \\dot x_T = A_T x_T + B_T [u_R; u_V],\\quad F_V = C_T x_T + D_T [u_R; u_V],\\quad
    u_V = K x_V,\\quad \\dot x_V = f(x_V, F_V, t)  \\qquad (8)

The paper runs only a quarter car. Here ``f`` is linear: each corner is the network of its
corner file (:mod:`~roadnoise_utils.vehicle.quarter_car`: hub, damper rod, strut tower, springs, dampers, Maxwell
dampers) whose ``body`` end is the point of the body above that corner, and the body is rigid
(heave ``z`` up, pitch ``theta`` nose down, roll ``phi`` left side up), so a point at ``x``
ahead of the centre of mass and ``y`` to its left moves by ``z - x theta + y phi``.

As for the quarter car (:mod:`~roadnoise_utils.vehicle.corner`), the tires enter through linearity (Eq. 5): the
fixed-hub road forces :math:`F_F` of each tire are simulated apart (the large, block-diagonal
part), and the small system — the car closed through each corner's :math:`G_H` — is driven by
them. :func:`full_car_model` is that system as one python-control object (inputs the four
:math:`F_F`) for users' own tools.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import control
import numpy as np
import pandas as pd

from .. import guards
from ..analysis import argmax_all
from ..repro.paths import data_file, read_toml
from ..rm.fitting import FitSet
from ..rm.moving_hub import hub_statespace
from ..rm.simulation import ModalSections, response, simulate
from ..road.textures import RoadSpectrum
from .corner import predicted_psd
from .quarter_car import QuarterCar, load_vehicle, with_extra_hub_mass

#: The corners, in the order of every input and output: front left, front right, rear left, rear right.
CORNERS = ("FL", "FR", "RL", "RR")
#: Body outputs: heave (m), pitch and roll (rad), then their accelerations.
BODY_OUTPUTS = ("heave", "pitch", "roll", "a_heave", "a_pitch", "a_roll")
#: Valid ranges (min, max, unit) of the body and geometry values.
_RANGES = {
    "mass": (50.0, 1e5, "kg"),
    "pitch_inertia": (10.0, 1e6, "kg m^2"),
    "roll_inertia": (10.0, 1e6, "kg m^2"),
    "wheelbase": (0.5, 20.0, "m"),
    "track_front": (0.3, 5.0, "m"),
    "track_rear": (0.3, 5.0, "m"),
}


@dataclass(frozen=True)
class Body:
    """The sprung body as a rigid body: mass (kg), pitch and roll inertias about its centre of mass (kg m^2)."""

    mass: float
    pitch_inertia: float
    roll_inertia: float


@dataclass(frozen=True)
class FullCar:
    """A vehicle: rigid body, geometry and the front and rear corner networks.

    Attributes
    ----------
    name : str
    body : Body
    wheelbase : float
        Front to rear axle (m).
    cg_to_front : float
        Centre of mass to the front axle (m), in ``(0, wheelbase)``.
    track_front, track_rear : float
        Left to right wheel centre, per axle (m).
    front, rear : QuarterCar
        The corner networks; their mass named ``attachment`` is replaced by the body's point
        above the corner (its value in the corner file is not used).
    attachment : str
        Name of that mass in the corner files.
    """

    name: str
    body: Body
    wheelbase: float
    cg_to_front: float
    track_front: float
    track_rear: float
    front: QuarterCar
    rear: QuarterCar
    attachment: str = "body"

    def __post_init__(self) -> None:
        for field in ("mass", "pitch_inertia", "roll_inertia"):
            lo, hi, unit = _RANGES[field]
            guards.real(f"body {field}", getattr(self.body, field), lo, hi, unit=unit)
        for field in ("wheelbase", "track_front", "track_rear"):
            lo, hi, unit = _RANGES[field]
            guards.real(field, getattr(self, field), lo, hi, unit=unit)
        guards.real("cg_to_front", self.cg_to_front, 0.0, self.wheelbase, lo_open=True, hi_open=True, unit="m")
        for axle, corner in (("front", self.front), ("rear", self.rear)):
            if self.attachment not in corner.masses:
                raise ValueError(
                    f"{axle} corner {corner.name!r} has no mass {self.attachment!r} (the attachment to the body); "
                    f"its masses are {corner.names}"
                )
            if self.attachment in (corner.hub, corner.upper_mount):
                raise ValueError(f"{axle} corner: the attachment {self.attachment!r} cannot be its hub or upper mount")
        if self.front.tire != self.rear.tire:
            guards.warn(
                f"front tire {self.front.tire!r} and rear tire {self.rear.tire!r} differ: each axle runs its own"
            )

    @property
    def positions(self) -> np.ndarray:
        """``(x, y)`` of each corner (m) from the centre of mass, x forward, y left, (4, 2) in :data:`CORNERS` order."""
        a, b = self.cg_to_front, self.wheelbase - self.cg_to_front
        tf, tr = 0.5 * self.track_front, 0.5 * self.track_rear
        return np.array([[a, tf], [a, -tf], [-b, tr], [-b, -tr]])

    def corner(self, name: str) -> QuarterCar:
        """The network of corner ``name`` (``"FL"`` ... ``"RR"``)."""
        if name not in CORNERS:
            raise ValueError(f"corner {name!r}: valid corners are {CORNERS}")
        return self.front if name[0] == "F" else self.rear


def load_full_vehicle(name: str | Path) -> FullCar:
    """A whole vehicle from ``data/vehicles/<name>.toml`` (or a path): body, geometry, corner files."""
    path = data_file(name, "vehicles", "vehicle")
    data = read_toml(path)
    source = path.name
    expected = {"name", "front_corner", "rear_corner", "attachment", "body", "geometry"}
    if set(data) != expected:
        raise ValueError(f"{source}: keys {sorted(data)}; a full vehicle file has exactly {sorted(expected)}")
    body_keys, geometry_keys = (
        {"mass", "pitch_inertia", "roll_inertia"},
        {
            "wheelbase",
            "cg_to_front",
            "track_front",
            "track_rear",
        },
    )
    for table, keys in (("body", body_keys), ("geometry", geometry_keys)):
        if not isinstance(data[table], dict) or set(data[table]) != keys:
            raise ValueError(f"{source}: [{table}] must have exactly {sorted(keys)}")
    g = data["geometry"]
    try:
        return FullCar(
            name=str(data["name"]),
            body=Body(**{k: float(v) for k, v in data["body"].items()}),
            wheelbase=float(g["wheelbase"]),
            cg_to_front=float(g["cg_to_front"]),
            track_front=float(g["track_front"]),
            track_rear=float(g["track_rear"]),
            front=load_vehicle(data["front_corner"]),
            rear=load_vehicle(data["rear_corner"]),
            attachment=str(data["attachment"]),
        )
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{source}: {exc}") from None


def _dof(car: FullCar, corners: dict[str, QuarterCar]) -> tuple[list[str], dict[str, np.ndarray], np.ndarray]:
    """DOF names (heave, pitch, roll, then each corner's own masses), each point's displacement row
    over the DOF (``"FL.hub"``, ...; the attachment of a corner is the body point), and the mass matrix."""
    names = ["heave", "pitch", "roll"]
    masses = [car.body.mass, car.body.pitch_inertia, car.body.roll_inertia]
    for corner in CORNERS:
        for mass_name, value in corners[corner].masses.items():
            if mass_name != car.attachment:
                names.append(f"{corner}.{mass_name}")
                masses.append(value)
    index = {name: i for i, name in enumerate(names)}
    rows: dict[str, np.ndarray] = {}
    for corner, (x, y) in zip(CORNERS, car.positions):
        for mass_name in corners[corner].masses:
            row = np.zeros(len(names))
            if mass_name == car.attachment:
                row[:3] = (1.0, -x, y)  # z - x theta + y phi
            else:
                row[index[f"{corner}.{mass_name}"]] = 1.0
            rows[f"{corner}.{mass_name}"] = row
        rows[f"{corner}.ground"] = np.zeros(len(names))
    return names, rows, np.diag(masses)


def full_car_statespace(car: FullCar, tire_hub_mass: float = 0.0) -> control.StateSpace:
    """The car as a state space: inputs the vertical tire force on each hub (N, up), :data:`CORNERS` order.

    States: displacement and velocity of every DOF (:func:`_dof`), then the internal
    displacement of every Maxwell element (as :func:`.quarter_car.vehicle_statespace`).
    Outputs: ``z_hub`` (4, m), ``a_hub`` (4, m/s^2), ``a_mount`` (4, m/s^2), then
    :data:`BODY_OUTPUTS` (m, rad; m/s^2, rad/s^2). ``tire_hub_mass`` (kg) is added to every hub.
    """
    guards.real("tire_hub_mass", tire_hub_mass, 0.0, 1e3, unit="kg")
    corners = {c: with_extra_hub_mass(car.corner(c), tire_hub_mass) for c in CORNERS}
    names, rows, mass = _dof(car, corners)
    n = len(names)
    stiffness, damping, maxwell = np.zeros((n, n)), np.zeros((n, n)), []
    for corner in CORNERS:
        for e in corners[corner].elements:
            a, b = rows[f"{corner}.{e.a}"], rows[f"{corner}.{e.b}"]
            relative = np.outer(a - b, a - b)
            if e.kind == "spring":
                stiffness += e.stiffness * relative
            elif e.kind == "damper":
                damping += e.damping * relative
            else:
                maxwell.append((a, b, e))
    inv_m = np.diag(1.0 / np.diag(mass))
    m_e = len(maxwell)
    a_mat = np.zeros((2 * n + m_e, 2 * n + m_e))
    a_mat[:n, n : 2 * n] = np.eye(n)
    a_mat[n : 2 * n, :n] = -inv_m @ stiffness
    a_mat[n : 2 * n, n : 2 * n] = -inv_m @ damping
    for k, (a, b, e) in enumerate(maxwell):
        p, rate = 2 * n + k, e.stiffness / e.damping
        # dashpot from a to p, spring from p to b: x_p' = v_a - (k/c)(x_p - x_b); force -k (x_p - x_b) on a
        a_mat[p, p] = -rate
        a_mat[p, n : 2 * n] = a
        a_mat[p, :n] = rate * b
        force_on_a = -e.stiffness * np.append(-b, 1.0)  # over (x, x_p)
        for row, sign in ((a, 1.0), (b, -1.0)):
            generalised = sign * inv_m @ row
            a_mat[n : 2 * n, :n] += np.outer(generalised, force_on_a[:-1])
            a_mat[n : 2 * n, p] += generalised * force_on_a[-1]
    hubs = np.array([rows[f"{c}.{corners[c].hub}"] for c in CORNERS])  # (4, n): each hub's DOF row
    mounts = np.array([rows[f"{c}.{corners[c].upper_mount}"] for c in CORNERS])
    b_mat = np.zeros((2 * n + m_e, 4))
    b_mat[n : 2 * n] = inv_m @ hubs.T  # a unit force on hub j
    displacement = np.hstack([np.eye(n), np.zeros((n, n + m_e))])
    acceleration, acceleration_d = a_mat[n : 2 * n], b_mat[n : 2 * n]
    c_mat = np.vstack(
        [hubs @ displacement, hubs @ acceleration, mounts @ acceleration, displacement[:3], acceleration[:3]]
    )
    d_mat = np.vstack(
        [np.zeros((4, 4)), hubs @ acceleration_d, mounts @ acceleration_d, np.zeros((3, 4)), acceleration_d[:3]]
    )
    outputs = [f"{q}_{c}" for q in ("z_hub", "a_hub", "a_mount") for c in CORNERS] + list(BODY_OUTPUTS)
    return control.ss(a_mat, b_mat, c_mat, d_mat, inputs=[f"F_tire_{c}" for c in CORNERS], outputs=outputs)


#: DOFs whose kinetic energy in a mode is within this fraction of the largest are all named dominant:
#: on a left-right symmetric car the two wheels of an axle carry equal energy (to ~1e-8, the
#: eigenvectors' accuracy), and picking one would leave the choice to round-off.
ENERGY_TIE = 1e-3


def car_modes(car: FullCar, model: control.StateSpace, tire_hub_mass: float, f_max: float = 30.0) -> pd.DataFrame:
    """The modes of the car on its tires (``model`` from :func:`full_car_model`) below ``f_max`` Hz:
    natural frequency (Hz), damping ratio, and the DOF with the largest share of the car's kinetic
    energy in it (the closed model's first states are the car's, :func:`full_car_statespace`).

    ``dominant DOF`` names every DOF within :data:`ENERGY_TIE` of the largest energy, in the
    car's DOF order, joined by ``" = "`` (``"FL.unsprung = FR.unsprung"`` on a symmetric car);
    ``its energy share`` is the share of one of them.
    """
    corners = {c: with_extra_hub_mass(car.corner(c), tire_hub_mass) for c in CORNERS}
    names, _, mass = _dof(car, corners)
    lam, vectors = np.linalg.eig(np.asarray(model.A))
    n = len(names)
    rows = []
    for k in np.nonzero((lam.imag > 0) & (np.abs(lam) < 2 * np.pi * f_max))[0]:
        energy = np.diag(mass) * np.abs(vectors[n : 2 * n, k]) ** 2  # kinetic energy per DOF
        rows.append(
            {
                "frequency (Hz)": abs(lam[k]) / (2 * np.pi),
                "damping ratio": -lam[k].real / abs(lam[k]),
                "dominant DOF": " = ".join(names[i] for i in argmax_all(energy, ENERGY_TIE)),
                "its energy share": float(energy.max() / energy.sum()),
            }
        )
    return pd.DataFrame(rows).sort_values("frequency (Hz)").reset_index(drop=True)


def couple_full_car(vehicle: control.StateSpace, hub_tires: list[control.StateSpace]) -> control.StateSpace:
    """Close the car through each corner's moving-hub tire (paper Eq. 5, 8): inputs the four :math:`F_F`.

    ``hub_tires[j]`` maps hub ``j``'s displacement to its hub force :math:`F_H` (:math:`G_H`);
    the tire force on hub ``j`` is :math:`F_F + F_H` (positive feedback from ``z_hub``).
    """
    if len(hub_tires) != 4:
        raise ValueError(f"hub_tires: give one G_H model per corner ({CORNERS}), got {len(hub_tires)}")
    tires = control.append(*hub_tires)
    pick = np.zeros((4, vehicle.noutputs))
    pick[:, :4] = np.eye(4)  # z_hub of each corner
    closed = control.feedback(vehicle, tires * control.ss([], [], [], pick), sign=+1)
    closed.input_labels, closed.output_labels = vehicle.input_labels, vehicle.output_labels
    return closed


def full_car_model(car: FullCar, hub: FitSet | dict[str, FitSet], tire_hub_mass: float) -> control.StateSpace:
    """The car closed through :math:`G_H` at every corner: inputs the four :math:`F_F` (N), outputs as
    :func:`full_car_statespace`. ``hub``: one hub fit for all corners or one per corner name."""
    fits = {c: hub for c in CORNERS} if isinstance(hub, FitSet) else dict(hub)
    if sorted(fits) != sorted(CORNERS):
        raise ValueError(f"hub: give one FitSet or one per corner {CORNERS}, got {sorted(fits)}")
    return couple_full_car(full_car_statespace(car, tire_hub_mass), [hub_statespace(fits[c]) for c in CORNERS])


@dataclass(frozen=True, eq=False)
class FullCarRun:
    """Time histories of a whole-vehicle run.

    Attributes
    ----------
    t : ndarray
        Time (s).
    fixed_hub_force : ndarray (4, n)
        :math:`F_F` of each wheel (N), :data:`CORNERS` order.
    outputs : dict of str to ndarray
        Every output of :func:`full_car_statespace` by name (``a_hub_FL``, ``pitch``, ...).
    """

    t: np.ndarray
    fixed_hub_force: np.ndarray
    outputs: dict[str, np.ndarray]

    @property
    def sample_rate(self) -> float:
        return 1.0 / float(self.t[1] - self.t[0])


def run_full_car(tire: control.StateSpace | ModalSections, model: control.StateSpace, inputs: dict) -> FullCarRun:
    """Each wheel's road -> its fixed-hub force (fast simulation, paper Eq. 3) -> the closed car (Eq. 8).

    ``inputs``: a :class:`.road.input.RoadInput` per corner (:func:`.road.two_track.wheel_inputs`),
    on one time grid; ``tire`` the fixed-hub tire (the same on every wheel).
    """
    if sorted(inputs) != sorted(CORNERS):
        raise ValueError(f"inputs: give one road input per corner {CORNERS}, got {sorted(inputs)}")
    t = inputs[CORNERS[0]].t
    if any(inputs[c].t.shape != t.shape or not np.allclose(inputs[c].t, t) for c in CORNERS):
        raise ValueError("inputs: every corner's road input must have the same time samples")
    forces = np.array([simulate(tire, inputs[c]).force for c in CORNERS])
    out = response(model, t, forces)
    return FullCarRun(t=t, fixed_hub_force=forces, outputs=dict(zip(model.output_labels, out)))


def axle_delay_transfer(model: control.StateSpace, freqs: np.ndarray, speed: float, wheelbase: float) -> np.ndarray:
    """Every output per unit fixed-hub force of the rear wheels on a 2-D road (outputs, freqs), complex.

    On a road uniform across the width both wheels of an axle see one force, and the front axle
    sees the rear's a time ``wheelbase / speed`` earlier: :math:`F_{front}(f) = F_{rear}(f)\\,e^{i 2\\pi f L/V}`,
    so :math:`y = [(H_{FL} + H_{FR}) e^{i 2\\pi f L/V} + H_{RL} + H_{RR}] F_{rear}`. On a car
    symmetric front to rear it is zero for pitch at :math:`f = k V/L` and for heave at
    :math:`f = (k + 1/2) V/L`: the wheelbase filtering.
    """
    guards.real("speed", speed, 0.0, lo_open=True, unit="m/s")
    guards.real("wheelbase", wheelbase, 0.0, lo_open=True, unit="m")
    f = np.asarray(freqs, float)
    h = np.asarray(model(2j * np.pi * f))  # (outputs, 4 inputs, freqs)
    delay = np.exp(2j * np.pi * f * wheelbase / speed)
    return (h[:, 0] + h[:, 1]) * delay + h[:, 2] + h[:, 3]


def predicted_psd_2d(
    freqs: np.ndarray,
    tassello_frf: np.ndarray,
    static,
    spectrum: RoadSpectrum,
    speed: float,
    model: control.StateSpace,
    wheelbase: float,
) -> dict[str, np.ndarray]:
    """Frequency-domain PSD of every output on a 2-D road (:func:`axle_delay_transfer` times one
    wheel's fixed-hub force PSD, :func:`.corner.predicted_psd`), by output name."""
    force = predicted_psd(freqs, tassello_frf, static, spectrum, speed)["F_F"]
    transfer = axle_delay_transfer(model, freqs, speed, wheelbase)
    return {name: np.abs(row) ** 2 * force for name, row in zip(model.output_labels, transfer)}
