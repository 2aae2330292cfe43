"""A real tire's published vertical curve and contact length, beside the tire models: MF-Swift 6.1.

MF-Swift 6.1 (Besselink, Schmeitz & Pacejka, Vehicle System Dynamics 48 sup1, 2010; Pacejka, *Tire
and Vehicle Dynamics*, 3rd ed., 2012, ch. 10) gives, rolling freely without slip or camber, the
vertical force of a tire deflected by :math:`\\rho` (its free radius :math:`R_0` less the loaded
one) at inflation pressure :math:`p_i`:

.. math:: F_z = \\Big(q_{Fz1} \\frac{\\rho}{R_0} + q_{Fz2} \\frac{\\rho^2}{R_0^2}\\Big)
          (1 + p_{Fz1}\\,dp_i)\\,F_{z0},\\qquad dp_i = \\frac{p_i - p_{i0}}{p_{i0}},

with :math:`q_{Fz1} = \\sqrt{(C_z R_0 / F_{z0})^2 - 4 q_{Fz2}}`, so that the tangent stiffness
:math:`dF_z/d\\rho` at the nominal load and pressure is the file's ``VERTICAL_STIFFNESS``
:math:`C_z`; and the contact length :math:`2a` with

.. math:: a = R_0 \\Big(q_{ra2} \\frac{\\rho}{R_0} + q_{ra1} \\sqrt{\\frac{\\rho}{R_0}}\\Big).

A published tire's parameters live in ``data/published/<name>.toml`` with their source
(:func:`mf_swift_tire`); the tire models are compared with it, never tuned to it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from .. import guards
from ..repro.paths import data_dir, read_toml
from ..tire.model import TireModel, tire_model

#: The property file's parameters a published tire gives, and their meaning.
PARAMETERS = {
    "UNLOADED_RADIUS": "free tire radius R0 (m)",
    "FNOMIN": "nominal load Fz0 (N)",
    "NOMPRES": "nominal inflation pressure pi0 (Pa)",
    "VERTICAL_STIFFNESS": "tangent vertical stiffness Cz at the nominal load and pressure (N/m)",
    "Q_FZ2": "quadratic term of the load-deflection curve (-)",
    "PFZ1": "pressure effect on the vertical stiffness (-)",
    "Q_RA1": "square-root term of the contact length (-)",
    "Q_RA2": "linear term of the contact length (-)",
}


@dataclass(frozen=True)
class MFSwiftVertical:
    """The MF-Swift 6.1 vertical model and contact length of one tire (SI units, the property file's names)."""

    name: str
    source: str
    unloaded_radius: float
    nominal_load: float
    nominal_pressure: float
    vertical_stiffness: float
    q_fz2: float
    p_fz1: float
    q_ra1: float
    q_ra2: float

    @property
    def q_fz1(self) -> float:
        """:math:`q_{Fz1}` (-): the linear term that makes the tangent stiffness at the nominal load :math:`C_z`."""
        return float(
            np.sqrt((self.vertical_stiffness * self.unloaded_radius / self.nominal_load) ** 2 - 4 * self.q_fz2)
        )

    def _pressure_factor(self, pressure: float | None) -> float:
        if pressure is None:
            return 1.0
        pressure = guards.real(
            "pressure", pressure, 0.3 * self.nominal_pressure, 3.0 * self.nominal_pressure, unit="Pa"
        )
        factor = 1.0 + self.p_fz1 * (pressure - self.nominal_pressure) / self.nominal_pressure
        if factor <= 0.0:
            raise ValueError(
                f"pressure = {pressure:g} Pa: the vertical model gives no stiffness there (PFZ1 = {self.p_fz1:g})"
            )
        return factor

    def force(self, deflection: np.ndarray, pressure: float | None = None) -> np.ndarray:
        """Vertical force (N) at ``deflection`` (m, >= 0) and ``pressure`` (Pa; default the nominal)."""
        x = np.asarray(deflection, float) / self.unloaded_radius
        if np.any(~np.isfinite(x)) or np.any(x < 0.0):
            raise ValueError("deflection must be finite and >= 0 m")
        return (self.q_fz1 * x + self.q_fz2 * x**2) * self._pressure_factor(pressure) * self.nominal_load

    def deflection(self, load: np.ndarray, pressure: float | None = None) -> np.ndarray:
        """Deflection (m) that carries ``load`` (N, >= 0): the root of the quadratic load-deflection curve."""
        share = self._load_share(load, pressure)
        q1, q2 = self.q_fz1, self.q_fz2
        return self.unloaded_radius * 2 * share / (q1 + np.sqrt(q1**2 + 4 * q2 * share))

    def tangent_stiffness(self, load: np.ndarray, pressure: float | None = None) -> np.ndarray:
        """Tangent vertical stiffness :math:`dF_z/d\\rho` (N/m) at ``load`` (N): :math:`\\sqrt{q_{Fz1}^2 + 4 q_{Fz2}
        F_z / ((1 + p_{Fz1} dp_i) F_{z0})}\\,(1 + p_{Fz1} dp_i) F_{z0} / R_0`."""
        share = self._load_share(load, pressure)
        scale = self._pressure_factor(pressure) * self.nominal_load / self.unloaded_radius
        return np.sqrt(self.q_fz1**2 + 4 * self.q_fz2 * share) * scale

    def contact_length(self, load: np.ndarray, pressure: float | None = None) -> np.ndarray:
        """Contact length :math:`2a` (m) at ``load`` (N)."""
        x = self.deflection(load, pressure) / self.unloaded_radius
        return 2 * self.unloaded_radius * (self.q_ra2 * x + self.q_ra1 * np.sqrt(x))

    def _load_share(self, load: np.ndarray, pressure: float | None) -> np.ndarray:
        load = np.asarray(load, float)
        if np.any(~np.isfinite(load)) or np.any(load < 0.0) or np.any(load > 5 * self.nominal_load):
            raise ValueError(f"load must be finite, in [0, {5 * self.nominal_load:g}] N (five times FNOMIN)")
        return load / (self._pressure_factor(pressure) * self.nominal_load)


def mf_swift_tire(name: str = "205_60R15_mf_swift") -> MFSwiftVertical:
    """The published tire ``data/published/<name>.toml``: its MF-Swift 6.1 vertical parameters (:data:`PARAMETERS`).

    Raises
    ------
    ValueError
        The file is missing, lacks a parameter or has one it does not know, a value is not a
        positive number (``PFZ1`` any finite number), or :math:`C_z R_0 / F_{z0}` is below
        :math:`2\\sqrt{q_{Fz2}}` (no real :math:`q_{Fz1}`).
    """
    path = data_dir() / "published" / f"{name}.toml"
    if not path.exists():
        known = sorted(p.stem for p in (data_dir() / "published").glob("*.toml"))
        raise ValueError(f"published tire {name!r}: no file {path.name} in data/published (known: {known})")
    content = read_toml(path)
    values = content.get("parameters", {})
    unknown, missing = set(values) - set(PARAMETERS), set(PARAMETERS) - set(values)
    if unknown or missing:
        raise ValueError(f"{path.name} [parameters]: unknown {sorted(unknown)}, missing {sorted(missing)}")
    for key, value in values.items():
        lo = -np.inf if key == "PFZ1" else 0.0
        values[key] = guards.real(f"{path.name} {key}", value, lo, lo_open=True)
    tire = MFSwiftVertical(
        name=content["tire"]["name"],
        source=content["tire"]["source"],
        unloaded_radius=values["UNLOADED_RADIUS"],
        nominal_load=values["FNOMIN"],
        nominal_pressure=values["NOMPRES"],
        vertical_stiffness=values["VERTICAL_STIFFNESS"],
        q_fz2=values["Q_FZ2"],
        p_fz1=values["PFZ1"],
        q_ra1=values["Q_RA1"],
        q_ra2=values["Q_RA2"],
    )
    if (tire.vertical_stiffness * tire.unloaded_radius / tire.nominal_load) ** 2 <= 4 * tire.q_fz2:
        raise ValueError(f"{path.name}: VERTICAL_STIFFNESS too low for Q_FZ2 = {tire.q_fz2:g} (no real Q_FZ1)")
    return tire


def mf_swift_table(
    tire: MFSwiftVertical, loads: tuple[float, ...] = (2000.0, 4000.0, 6000.0), pressure: float | None = None
) -> pd.DataFrame:
    """Deflection (mm), tangent K_v (N/mm), K_v over its value at the nominal load, contact length (mm) at ``loads`` (N)."""
    loads = np.asarray(loads, float)
    stiffness = tire.tangent_stiffness(loads, pressure)
    return pd.DataFrame(
        {
            "load (N)": loads,
            "deflection (mm)": tire.deflection(loads, pressure) * 1e3,
            "tangent K_v (N/mm)": stiffness / 1e3,
            "K_v / K_v(FNOMIN)": stiffness / tire.tangent_stiffness(tire.nominal_load, pressure),
            "contact length (mm)": tire.contact_length(loads, pressure) * 1e3,
        }
    )


def published_comparison(
    published: MFSwiftVertical,
    tires: Sequence[TireModel | str],
    loads: tuple[float, float, float] = (2000.0, 4000.0, 6000.0),
    pressure_change: float = 0.22,
) -> pd.DataFrame:
    """The published tire and each of ``tires`` (tire models of its size, at its nominal pressure) on the flat road.

    One row per tire, the published one first: its inflation (bar), its tangent vertical stiffness
    and deflection at the middle of ``loads`` (the published tire's nominal load), the tangent's
    change to the lightest and the heaviest load (:math:`K_v(F)/K_v(F_{nom})`: how the tire hardens)
    and to an inflation ``pressure_change`` (-) below and above its own at the nominal load (the
    model's file with the pressure changed; MF-Swift's force at a deflection scales with
    :math:`1 + p_{Fz1}\\,dp_i`), and its contact length at the nominal load (a model's footprint
    length: its contact points' extent, their tributary lengths included; MF-Swift's :math:`2a`).

    Raises
    ------
    ValueError
        ``loads`` not three increasing loads with the published tire's nominal load in the middle;
        ``pressure_change`` outside (0, 0.5).
    """
    loads = tuple(guards.real("loads", load, *guards.LOAD_RANGE, unit="N") for load in loads)
    if len(loads) != 3 or not loads[0] < loads[1] < loads[2] or loads[1] != published.nominal_load:
        raise ValueError(
            f"loads = {loads}: give three increasing loads (N), the middle one the published tire's nominal "
            f"load {published.nominal_load:g} N"
        )
    change = guards.real("pressure_change", pressure_change, 0.0, 0.5, lo_open=True, hi_open=True, unit="")
    factors = (1.0 - change, 1.0 + change)
    pressures = [factor * published.nominal_pressure for factor in factors]
    rows = [
        _comparison_row(
            published.name,
            published.nominal_pressure,
            published.tangent_stiffness(np.asarray(loads)),
            np.array([published.tangent_stiffness(loads[1], p) for p in pressures]),
            float(published.deflection(loads[1])),
            float(published.contact_length(loads[1])),
            change,
        )
    ]
    for tire in tires:
        model = tire_model(tire)
        pressure = _inflation(model)
        footprints = [model.load(model.case("flat", load)) for load in loads]
        inflated = [
            model.replace(**{"operating.inflation_pressure": factor * pressure}).load(model.case("flat", loads[1]))
            for factor in factors
        ]
        rows.append(
            _comparison_row(
                model.name,
                pressure,
                np.array([f.vertical_stiffness for f in footprints]),
                np.array([f.vertical_stiffness for f in inflated]),
                footprints[1].deflection,
                footprints[1].footprint_length,
                change,
            )
        )
    return pd.DataFrame(rows).set_index("tire")


def _comparison_row(
    name: str,
    pressure: float,
    stiffness: np.ndarray,
    stiffness_at_pressures: np.ndarray,
    deflection: float,
    length: float,
    change: float,
) -> dict:
    percent = f"{100 * change:g} %"
    return {
        "tire": name,
        "inflation (bar)": pressure / 1e5,
        "K_v at the nominal load (N/mm)": stiffness[1] / 1e3,
        "deflection (mm)": deflection * 1e3,
        "K_v(light) / K_v(nominal)": stiffness[0] / stiffness[1],
        "K_v(heavy) / K_v(nominal)": stiffness[2] / stiffness[1],
        f"K_v(pressure - {percent}) / K_v": stiffness_at_pressures[0] / stiffness[1],
        f"K_v(pressure + {percent}) / K_v": stiffness_at_pressures[1] / stiffness[1],
        "contact length (mm)": length * 1e3,
    }


def _inflation(model: TireModel) -> float:
    """The model's inflation pressure (Pa) from its files (the loaded FE tire's from its construction's)."""
    operating = getattr(model.spec, "operating", None)
    if operating is None:
        operating = getattr(getattr(model.spec, "construction", None), "operating", None)
    if operating is None:
        raise ValueError(f"tire {model.name!r}: its files give no inflation pressure to change")
    return float(operating.inflation_pressure)
