"""The quarter car of the paper's Fig. 13, with the top mount and damper that shape Fig. 10.

Paper, *Simulations with the Moving Hub System*: a 195/65 R15 car; the measured
shock-absorber transmissibility (Fig. 10, hub to suspension upper mount) "filters the 90 % of
the excitation amplitude with frequency lower than 120 Hz, leaves almost unaltered the
amplitudes in the range 120-200 Hz, and filters not more than the 40 % of the excitation
amplitude in the range 200-250 Hz". A textbook two-mass quarter car cannot do that; ours adds
the damper's upper end (rod and top-mount inner part), the damper's high-frequency stiffness
(oil compressibility and bushings, in series with the damping: a Maxwell element) and the
local mass of the strut tower, where the upper-mount accelerometer sits.

The vehicle is a linear mass-spring-damper network read from ``data/vehicles/*.toml``: named
masses and elements (``spring``, ``damper``, ``maxwell``) between them or ``ground``. It is
built into a python-control ``StateSpace`` with the tire force on the hub as input; coupling
it with the moving-hub tire (paper Eq. 5-8 for one corner) is a positive feedback
:math:`F = F_F + G_H\\,z_{hub}`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

import control
import numpy as np

from .. import guards
from ..repro.paths import data_file, read_toml

_KINDS = {"spring": ("stiffness",), "damper": ("damping",), "maxwell": ("stiffness", "damping")}
#: Valid ranges (min, max, unit) of the element and mass values.
_RANGES = {"stiffness": (1.0, 1e10, "N/m"), "damping": (0.0, 1e6, "N s/m"), "mass": (0.01, 1e5, "kg")}


@dataclass(frozen=True)
class Element:
    """A spring, damper or Maxwell element (spring in series with a damper) between two masses."""

    kind: str
    a: str
    b: str
    stiffness: float = 0.0
    damping: float = 0.0


@dataclass(frozen=True)
class QuarterCar:
    """A vehicle corner: masses (kg), elements, the hub and upper-mount mass names, its tire.

    Attributes
    ----------
    name : str
        Description.
    tire : str
        Tire file (``data/tires``) the corner runs on.
    masses : dict of str to float
        Lumped masses (kg); the tire's own masses are in the FET and are not repeated here.
    elements : tuple of Element
        Connections.
    hub, upper_mount : str
        Names of the hub mass and of the mass carrying the upper-mount accelerometer.
    """

    name: str
    tire: str
    masses: dict[str, float]
    elements: tuple[Element, ...]
    hub: str
    upper_mount: str

    @property
    def names(self) -> list[str]:
        return list(self.masses)

    def __post_init__(self) -> None:
        _validate(self, "QuarterCar")


def _validate(vehicle: QuarterCar, source: str) -> None:
    for name, m in vehicle.masses.items():
        lo, hi, unit = _RANGES["mass"]
        guards.real(f"{source}: mass {name!r}", m, lo, hi, unit=unit)
    known = set(vehicle.masses) | {"ground"}
    for e in vehicle.elements:
        if e.kind not in _KINDS:
            raise ValueError(f"{source}: element kind {e.kind!r}: valid kinds are {sorted(_KINDS)}")
        for end in (e.a, e.b):
            if end not in known:
                raise ValueError(f"{source}: element {e.kind} refers to {end!r}; known masses are {sorted(known)}")
        for field in _KINDS[e.kind]:
            lo, hi, unit = _RANGES[field]
            value = guards.real(f"{source}: {e.kind} {e.a}-{e.b} {field}", getattr(e, field), lo, hi, unit=unit)
            if e.kind == "maxwell" and value <= 0:
                raise ValueError(
                    f"{source}: {e.kind} {e.a}-{e.b} {field} = {value} {unit}: valid range is [{lo:g}, {hi:g}] {unit}"
                )
    for role in ("hub", "upper_mount"):
        if getattr(vehicle, role) not in vehicle.masses:
            raise ValueError(f"{source}: {role} = {getattr(vehicle, role)!r} is not one of the masses")


def load_vehicle(name: str | Path) -> QuarterCar:
    """A vehicle corner from ``data/vehicles/<name>.toml`` (or a path), validated."""
    path = data_file(name, "vehicles", "vehicle")
    data = read_toml(path)
    source = path.name
    _check_keys(data, _TOP_KEYS, _TOP_KEYS, source, "the file")
    if not isinstance(data["masses"], dict) or not isinstance(data["element"], list):
        raise ValueError(f"{source}: [masses] must be a table and [[element]] a list of tables")
    elements = tuple(_element(e, k, source) for k, e in enumerate(data["element"]))
    try:
        return QuarterCar(
            name=str(data["name"]),
            tire=str(data["tire"]),
            masses=dict(data["masses"]),
            elements=elements,
            hub=str(data["hub"]),
            upper_mount=str(data["upper_mount"]),
        )
    except ValueError as exc:
        raise ValueError(str(exc).replace("QuarterCar", source, 1)) from None


_TOP_KEYS = {"name", "tire", "hub", "upper_mount", "masses", "element"}


def _check_keys(table: dict, required: set[str], allowed: set[str], source: str, where: str) -> None:
    missing = sorted(required - set(table))
    unknown = sorted(set(table) - allowed)
    if missing:
        raise ValueError(f"{source}: {where} is missing {missing}")
    if unknown:
        raise ValueError(f"{source}: {where} has unknown key(s) {unknown}; expected {sorted(allowed)}")


def _element(table: object, k: int, source: str) -> Element:
    """One ``[[element]]`` table, its keys checked for its kind (a misspelt value is an error, not a zero)."""
    where = f"[[element]] {k + 1}"
    if not isinstance(table, dict) or table.get("kind") not in _KINDS:
        kind = table.get("kind") if isinstance(table, dict) else table
        raise ValueError(f"{source}: {where} kind = {kind!r}: valid kinds are {sorted(_KINDS)}")
    values = set(_KINDS[table["kind"]])
    _check_keys(table, {"kind", "between"} | values, {"kind", "between"} | values, source, where)
    between = table["between"]
    if not (isinstance(between, list) and len(between) == 2 and all(isinstance(b, str) for b in between)):
        raise ValueError(f'{source}: {where} between = {between!r}: give two mass names, e.g. ["unsprung", "body"]')
    return Element(table["kind"], between[0], between[1], table.get("stiffness", 0.0), table.get("damping", 0.0))


def with_extra_hub_mass(vehicle: QuarterCar, mass: float) -> QuarterCar:
    """The same corner with ``mass`` (kg) added to the hub (e.g. the tire's rim-side mass)."""
    masses = dict(vehicle.masses)
    masses[vehicle.hub] += mass
    return QuarterCar(vehicle.name, vehicle.tire, masses, vehicle.elements, vehicle.hub, vehicle.upper_mount)


def _connect(matrix: np.ndarray, i: int | None, j: int | None, value: float) -> None:
    """Add a two-node element of coefficient ``value`` between DOF i and j (None = ground)."""
    for p, q in ((i, j), (j, i)):
        if p is not None:
            matrix[p, p] += value
            if q is not None:
                matrix[p, q] -= value


def vehicle_statespace(vehicle: QuarterCar) -> control.StateSpace:
    r"""The corner as a state space: input the vertical tire force on the hub (N, up).

    States: displacement and velocity of every mass, then the internal displacement ``x_p`` of
    every Maxwell element (dashpot from mass a to ``p``, spring from ``p`` to mass b, massless
    ``p``: :math:`c(\dot x_a - \dot x_p) = k(x_p - x_b)`). Outputs:
    ``[z_hub, a_hub, a_upper_mount]`` (m, m/s^2, m/s^2).
    """
    names = vehicle.names
    n = len(names)
    idx = {name: i for i, name in enumerate(names)}
    dof = {**idx, "ground": None}
    stiffness = np.zeros((n, n))
    damping = np.zeros((n, n))
    maxwell = [e for e in vehicle.elements if e.kind == "maxwell"]
    for e in vehicle.elements:
        if e.kind == "spring":
            _connect(stiffness, dof[e.a], dof[e.b], e.stiffness)
        elif e.kind == "damper":
            _connect(damping, dof[e.a], dof[e.b], e.damping)
    inv_m = np.diag([1.0 / vehicle.masses[name] for name in names])
    m_e = len(maxwell)
    a = np.zeros((2 * n + m_e, 2 * n + m_e))
    a[:n, n : 2 * n] = np.eye(n)
    a[n : 2 * n, :n] = -inv_m @ stiffness
    a[n : 2 * n, n : 2 * n] = -inv_m @ damping
    for k, e in enumerate(maxwell):
        p = 2 * n + k
        ia, ib = dof[e.a], dof[e.b]
        rate = e.stiffness / e.damping
        a[p, p] = -rate
        if ia is not None:
            a[p, n + ia] = 1.0  # x_p' = v_a - (k/c)(x_p - x_b)
            a[n + ia, p] -= e.stiffness * inv_m[ia, ia]  # force on a: -k (x_p - x_b)
        if ib is not None:
            a[p, ib] = rate
            a[n + ib, p] += e.stiffness * inv_m[ib, ib]  # force on b: +k (x_p - x_b)
            a[n + ib, ib] -= e.stiffness * inv_m[ib, ib]
            if ia is not None:
                a[n + ia, ib] += e.stiffness * inv_m[ia, ia]
    b = np.zeros((2 * n + m_e, 1))
    hub, mount = idx[vehicle.hub], idx[vehicle.upper_mount]
    b[n + hub, 0] = inv_m[hub, hub]
    c = np.zeros((3, 2 * n + m_e))
    c[0, hub] = 1.0
    c[1] = a[n + hub]
    c[2] = a[n + mount]
    d = np.array([[0.0], [b[n + hub, 0]], [b[n + mount, 0]]])
    return control.ss(a, b, c, d, inputs=["F_tire"], outputs=["z_hub", "a_hub", "a_mount"])


def couple(vehicle: control.StateSpace, hub_tire: control.StateSpace) -> control.StateSpace:
    """Close the loop through the moving-hub tire (paper Eq. 5): input :math:`F_F`, same outputs.

    ``hub_tire`` maps the hub displacement to the hub force :math:`F_H` (:math:`G_H`); the
    tire force on the hub is :math:`F_M = F_F + F_H` (positive feedback from ``z_hub``).
    """
    pick_hub = control.ss([], [], [], [[1.0, 0.0, 0.0]])
    return control.feedback(vehicle, hub_tire * pick_hub, sign=+1)


def transmissibility(vehicle: QuarterCar, freqs: np.ndarray) -> np.ndarray:
    """Upper-mount over hub acceleration, :math:`a_{mount}/a_{hub}` (paper Fig. 10), complex."""
    response = vehicle_statespace(vehicle)(2j * np.pi * np.asarray(freqs, float))
    return response[2, 0] / response[1, 0]


#: Statistics of :math:`|T|` over a band that :func:`transmissibility_statistics` knows.
STATISTICS = {"mean": np.mean, "min": np.min, "max": np.max}


class FrequencyBand(NamedTuple):
    """A frequency band (Hz), the statistic of :math:`|T|` taken over it, and a label for plots."""

    f_low: float
    f_high: float
    statistic: str
    label: str = ""


def transmissibility_statistics(
    vehicle: QuarterCar, bands: dict[str, FrequencyBand], points: int = 501
) -> dict[str, float]:
    """A statistic of :math:`|T|` (:func:`transmissibility`) over each of some frequency bands.

    Parameters
    ----------
    vehicle : QuarterCar
        The corner.
    bands : dict of str to FrequencyBand
        The bands; the statistic is one of :data:`STATISTICS` (the paper's Fig. 10 claims:
        :func:`.claims.transmissibility_bands`).
    points : int
        Uniform frequency samples per band.

    Returns
    -------
    dict of str to float
        The statistic of each band (-).
    """
    values = {}
    for name, band in bands.items():
        if band.statistic not in STATISTICS:
            raise ValueError(f"band {name!r}: statistic = {band.statistic!r}: valid values are {list(STATISTICS)}")
        if not 0 <= band.f_low < band.f_high:
            raise ValueError(f"band {name!r}: ({band.f_low}, {band.f_high}) Hz: valid bands have 0 <= f_low < f_high")
        magnitude = np.abs(transmissibility(vehicle, np.linspace(band.f_low, band.f_high, points)))
        values[name] = float(STATISTICS[band.statistic](magnitude))
    return values


def two_mass_transmissibility(
    sprung: float, unsprung: float, spring: float, damping: float, tire: float, freqs: np.ndarray
) -> np.ndarray:
    """Textbook quarter car: body displacement over road displacement (complex, -).

    Two masses, suspension spring and damper, tire spring (e.g. Gillespie, *Fundamentals of
    Vehicle Dynamics*, 1992, ch. 5).
    """
    s = 2j * np.pi * np.asarray(freqs, float)
    ks = spring + damping * s
    body = sprung * s**2 + ks
    wheel = unsprung * s**2 + ks + tire
    return ks * tire / (body * wheel - ks**2)
