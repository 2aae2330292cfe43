"""The tire's air cavity: its split under load, its rolling doublet and the fixed-hub FRFs with and without it (notebook 14).

Reads the ``[cavity]`` table of ``data/conditions/whole_car.toml`` once
(:func:`cavity_conditions`); the tire answers through the capabilities ``cavity`` and
``rolling_cavity`` of its model (:class:`roadnoise_utils.tire.model.TireModel`), the waveguide's
numerics are :mod:`roadnoise_utils.tire.cavity`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from .. import guards
from ..repro import stages
from ..tire import cavity as cavity_model
from ..tire.model import FRFResult, TireModel, tire_model
from .conditions import load_conditions, resolve


@dataclass(frozen=True)
class CavityConditions:
    """The cavity's test: tire file, loads (N), FRF band (Hz), air temperature (deg C), rolling speeds (km/h) of the
    doublet and of the rolling FRFs, and the rolling FRFs' band (Hz)."""

    tire: str
    loads: tuple[float, ...]
    band: tuple[float, float]
    temperature: float
    speeds_kmh: tuple[float, ...]
    rolling_frf_speeds_kmh: tuple[float, ...]
    rolling_band: tuple[float, float]


def cavity_conditions(tire: str | None = None) -> CavityConditions:
    """``[cavity]`` of ``data/conditions/whole_car.toml`` (read once), ``tire`` overriding its tire."""
    values = resolve(
        load_conditions("whole_car"),
        "cavity",
        tire=tire,
        loads=None,
        band=None,
        temperature=None,
        speeds_kmh=None,
        rolling_frf_speeds_kmh=None,
        rolling_band=None,
    )
    loads = tuple(guards.real("cavity.loads", v, 0.0, 2.0e4, lo_open=True, unit="N") for v in values["loads"])
    if len(loads) < 2:
        raise ValueError(f"cavity.loads = {list(loads)}: give at least two loads (N) for the split against the load")
    band = guards.interval("cavity.band", values["band"])
    speeds = tuple(guards.real("cavity.speeds_kmh", v, 0.0, 300.0, unit="km/h") for v in values["speeds_kmh"])
    temperature = guards.real("cavity.temperature", values["temperature"])
    frf_speeds = tuple(
        guards.real("cavity.rolling_frf_speeds_kmh", v, 0.0, 300.0, unit="km/h")
        for v in values["rolling_frf_speeds_kmh"]
    )
    rolling_band = guards.interval("cavity.rolling_band", values["rolling_band"])
    return CavityConditions(str(values["tire"]), loads, band, temperature, speeds, frf_speeds, rolling_band)


def split_against_load(conditions: CavityConditions | None = None) -> pd.DataFrame:
    """The loaded cavity's first doublet at each load: fore-aft and vertical frequency (Hz), their split,
    the first-order formula's split (module notes of :mod:`.tire.cavity`) and the static deflection (mm).

    Any tire model with the capability ``cavity_shape`` (:meth:`~.tire.model.TireModel.loaded_cavity_areas`:
    the ring tire's belt and sidewall arcs, the cross-section tire's inner surface, the loaded FE
    tire's loaded solids).
    """
    test = cavity_conditions() if conditions is None else conditions
    model = tire_model(test.tire)
    cav = model.air_cavity(test.temperature)
    states, areas = model.loaded_cavity_areas(test.loads, test.temperature)
    f1 = float(cavity_model.rigid_torus_frequencies(cav, 1)[0])
    rows = []
    for load, static, area in zip(test.loads, states, areas):
        fore_aft, vertical = cavity_model.webster_modes(cav, area).split()
        theta = 2.0 * np.pi * np.arange(area.size) / area.size
        ds = 2.0 * np.pi * cav.mean_radius / area.size
        first_order = np.sum((cav.area - area) * np.cos(2 * theta)) * ds / (np.pi * cav.mean_radius * cav.area) * f1
        rows.append(
            {
                "load (N)": load,
                "deflection (mm)": 1e3 * static.deflection,
                "fore-aft (Hz)": fore_aft,
                "vertical (Hz)": vertical,
                "split (Hz)": vertical - fore_aft,
                "first-order split (Hz)": first_order,
            }
        )
    return pd.DataFrame(rows)


def load_exponent(table: pd.DataFrame) -> float:
    """The exponent of a power law ``split ~ load^k`` fitted to :func:`split_against_load` (log-log least squares)."""
    return float(np.polyfit(np.log(table["load (N)"]), np.log(table["split (Hz)"]), 1)[0])


@dataclass(frozen=True, eq=False)
class CavityFRFs:
    """The tire on the flat road at its file's load: fixed-hub FRFs without and with the cavity, and the rigid torus's first mode (Hz)."""

    plain: FRFResult
    with_cavity: FRFResult
    rigid_torus: float
    loaded_doublet: tuple[float, float]

    def resonance(self, above: float = 0.0) -> tuple[float, float]:
        """Where :math:`|H_{tot}|` with the cavity peaks above ``above`` Hz (Hz), and its largest ratio to
        the tire's alone there (-)."""
        near = self.plain.freqs >= above
        if not near.any():
            raise ValueError(
                f"above = {above:g} Hz: valid values are below the FRFs' last, {self.plain.freqs[-1]:g} Hz"
            )
        coupled = np.abs(self.with_cavity.H_tot[near])
        gain = coupled / np.abs(self.plain.H_tot[near])
        return float(self.plain.freqs[near][coupled.argmax()]), float(gain.max())

    def stiffening_at_rest(self) -> float:
        """How much stiffer the air makes the tire at rest: :math:`K_v` with the cavity over without, less
        one (-), from :math:`G_H(0)` (the FRFs must start at 0 Hz)."""
        if self.plain.freqs[0] != 0.0:
            raise ValueError(f"the FRFs start at {self.plain.freqs[0]:g} Hz: the stiffening at rest needs 0 Hz")
        return float(self.with_cavity.G_H[0].real / self.plain.G_H[0].real - 1.0)


def cavity_frfs(conditions: CavityConditions | None = None, step: float = 1.0) -> CavityFRFs:
    """``H_tot`` and ``G_H`` over the band every ``step`` Hz, without and with the cavity (the tire file's ``[cavity] modes``)."""
    test = cavity_conditions() if conditions is None else conditions
    model = tire_model(test.tire).replace(**{"cavity.temperature": test.temperature})
    freqs = np.arange(test.band[0], test.band[1] + 0.5 * step, step)
    case = model.case("flat")
    plain = model.replace(**{"cavity.enabled": False}).fixed_hub_frfs(case, freqs)
    with_cavity = model.replace(**{"cavity.enabled": True}).fixed_hub_frfs(case, freqs)
    cav = model.air_cavity()
    _, areas = model.loaded_cavity_areas((model.default_load,))
    doublet = cavity_model.webster_modes(cav, areas[0]).split()
    return CavityFRFs(plain, with_cavity, float(cavity_model.rigid_torus_frequencies(cav, 1)[0]), doublet)


def with_cavity(tire: str | TireModel) -> TireModel:
    """The tire with its air cavity switched on (``[cavity] enabled = true``), every other value as the file's."""
    return tire_model(tire).replace(**{"cavity.enabled": True})


def chain_check(tire: str | TireModel, freqs: np.ndarray) -> float:
    """Largest difference of the RM chain's fixed-hub :math:`H_{tot}` (the fits summed, Eq. 1-3) from the
    direct one, relative to the direct one's peak over ``freqs`` (Hz): how well the fits carry the cavity."""
    fits, direct = stages.fit_tasselli(tire), stages.frf_visco(tire)
    on = np.isin(direct.freqs, freqs)
    chain = fits.responses(direct.freqs[on]).sum(axis=0)
    return float(np.abs(chain - direct.H_tot[on]).max() / np.abs(direct.H_tot[on]).max())


def band_gains(
    freqs: np.ndarray, without: dict[str, np.ndarray], with_cavity: dict[str, np.ndarray], band: tuple[float, float]
) -> pd.DataFrame:
    """Per output: the band power with the cavity over without it (dB) and where the cavity's PSD peaks in
    ``band`` (Hz, closed), from two sets of PSDs on the same ``freqs``."""
    inside = (freqs >= band[0]) & (freqs <= band[1])
    rows = {
        name: {
            "gain (dB)": 10.0 * np.log10(with_cavity[name][inside].sum() / without[name][inside].sum()),
            "peak (Hz)": float(freqs[inside][with_cavity[name][inside].argmax()]),
        }
        for name in with_cavity
    }
    return pd.DataFrame(rows).T


def _loaded_cavity(model: TireModel, temperature: float) -> tuple[cavity_model.Cavity, np.ndarray]:
    """The tire's cavity and its section around the tire loaded at its file's load (m^2)."""
    _, areas = model.loaded_cavity_areas((model.default_load,), temperature)
    return model.air_cavity(temperature), areas[0]


def flow_speed(spec: Any, cavity: cavity_model.Cavity, speed_kmh: float) -> float:
    """The air's speed round the waveguide's axis (m/s) on a tire rolling at ``speed_kmh``: it turns with the
    wheel, :math:`U = \\Omega R_{mean}`, :math:`\\Omega = V/R` (the tire's outer radius)."""
    return speed_kmh / 3.6 * cavity.mean_radius / spec.geometry.outer_radius


def rolling_split(conditions: CavityConditions | None = None) -> pd.DataFrame:
    """The loaded cavity's first doublet at each rolling speed (:func:`.tire.cavity.rolling_modes`): the
    wheel's rotation frequency, the two frequencies and their separation (Hz), with the closed form
    :math:`2\\sqrt{(\\Delta_0/2)^2 + f_{rot}^2}`. Either tire model (its loaded section at its file's load)."""
    test = cavity_conditions() if conditions is None else conditions
    model = tire_model(test.tire)
    cav, area = _loaded_cavity(model, test.temperature)
    rows = []
    for kmh in test.speeds_kmh:
        flow = flow_speed(model.spec, cav, kmh)
        rest, rolling = cavity_model.rolling_modes(cav, area, flow)
        f_rot = flow / (2.0 * np.pi * cav.mean_radius)
        rows.append(
            {
                "speed (km/h)": kmh,
                "rotation (Hz)": f_rot,
                "lower (Hz)": rolling[0],
                "upper (Hz)": rolling[1],
                "separation (Hz)": rolling[1] - rolling[0],
                "closed form (Hz)": 2.0 * np.sqrt((0.5 * (rest[1] - rest[0])) ** 2 + f_rot**2),
            }
        )
    return pd.DataFrame(rows)


@dataclass(frozen=True, eq=False)
class RollingCavityFRFs:
    """The fixed-hub ``H_tot`` and ``G_H`` (n_speeds, n_freq; N/m) with its cavity's air streaming at
    each of ``speeds_kmh``, and the waveguide's rolling doublet at each speed (Hz, (n_speeds, 2))."""

    speeds_kmh: tuple[float, ...]
    freqs: np.ndarray
    H_tot: np.ndarray
    G_H: np.ndarray
    doublets: np.ndarray


def rolling_frfs(conditions: CavityConditions | None = None, step: float = 1.0) -> RollingCavityFRFs:
    """``H_tot`` and ``G_H`` of the tire with its rolling cavity (capability ``rolling_cavity``) at
    the conditions' ``rolling_frf_speeds_kmh``, over ``rolling_band`` every ``step`` Hz."""
    test = cavity_conditions() if conditions is None else conditions
    model = tire_model(test.tire).replace(**{"cavity.temperature": test.temperature})
    model.require("rolling_cavity")
    cav, area = _loaded_cavity(model, test.temperature)
    freqs = np.arange(test.rolling_band[0], test.rolling_band[1] + 0.5 * step, step)
    h_tot, g_h, doublets = [], [], []
    for kmh in test.rolling_frf_speeds_kmh:
        flow = flow_speed(model.spec, cav, kmh)
        result = model.rolling_cavity_frfs(model.case("flat"), freqs, flow)
        h_tot.append(result.H_tot)
        g_h.append(result.G_H)
        doublets.append(cavity_model.rolling_modes(cav, area, flow)[1][:2])
    return RollingCavityFRFs(test.rolling_frf_speeds_kmh, freqs, np.array(h_tot), np.array(g_h), np.array(doublets))
