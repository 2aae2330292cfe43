"""Our number for each of the paper's claims, on either tire model (:mod:`.claims` judges them).

Each evaluator takes the tire model (a kind of ``data/paper/report.toml``) and runs the paper's
experiment on that model's tire files (:data:`TIRES`): the 165/65 R14 of the cleat test and
the FE-model claims, the 195/65 R15 of the moving-hub check and the quarter car. Whatever a
notebook's parameters, the claims are always evaluated on these. Shared inputs are computed
once per model (``functools.cache`` over the cached stages).
"""

from __future__ import annotations

import functools
from collections.abc import Callable

import numpy as np

from ..analysis import band_errors, distinct_peaks, peak_comparison, relative_rms_error, resonance_peaks
from ..experiments.bands import cleat_chain
from ..experiments.cavity import cavity_conditions, load_exponent, split_against_load
from ..experiments.cleat import CleatTest, cleat_test
from ..experiments.corner import PAPER_CAR, corner_setup, hub_mode_peaks, quarter_car_spectra
from ..experiments.moving_hub import moving_hub_check
from ..experiments.one_sided_cleat import OneSidedCleatTest, one_sided_cleat_test
from ..experiments.road import road_test_conditions
from ..experiments.whole_car import (
    WholeCarSetup,
    heavy_body_difference,
    notch_depth,
    predicted_coherence,
    wheelbase_check,
    whole_car_setup,
)
from ..rm.fitting import fit_tasselli
from ..road.kernels import tassellation_error
from ..tire.model import FRFResult, tire_model
from ..vehicle.quarter_car import FrequencyBand, load_vehicle, transmissibility_statistics
from ..vehicle.spectra import band_rms, power_share
from . import stages
from .paths import data_dir, read_toml

#: The report's tire models and their tire files by role, from ``data/paper/report.toml``.
_REPORT_MODELS = read_toml(data_dir() / "paper" / "report.toml")["model"]
TIRES = {m["kind"]: {role: m[role] for role in ("paper", "check")} for m in _REPORT_MODELS}
#: The tire models, in the report's column order.
MODELS = tuple(TIRES)
#: The models notebook 00 shows (``overview = false`` in the file: the reproduction's report only).
OVERVIEW_MODELS = tuple(m["kind"] for m in _REPORT_MODELS if m.get("overview", True))


def tire_of(model: str, role: str = "paper") -> str:
    """The tire file of ``model`` for a role (``"paper"`` or ``"check"``)."""
    if model not in TIRES:
        raise ValueError(f"model = {model!r}: valid values are {list(TIRES)}")
    return TIRES[model][role]


def role_of(tire: str) -> str:
    """The role (``"paper"`` or ``"check"``) of a report tire file, in whichever model lists it."""
    for files in TIRES.values():
        for role, name in files.items():
            if name == tire:
                return role
    raise ValueError(
        f"tire = {tire!r} is none of the report's tire files {[f for m in TIRES.values() for f in m.values()]}"
    )


# ---------------------------------------------------------------- shared inputs, each computed once per model


@functools.cache
def _visco(model: str) -> FRFResult:
    return stages.frf_visco(tire_of(model))


@functools.cache
def _cleat(model: str) -> CleatTest:
    return cleat_test(tire_of(model))


@functools.cache
def _contact(model: str) -> OneSidedCleatTest:
    return one_sided_cleat_test(tire_of(model))


@functools.cache
def _quarter_car(model: str) -> dict:
    """The road test's spectra on ``model``'s check tire (cached with notebook 07's run)."""
    return quarter_car_spectra(PAPER_CAR, tire=tire_of(model, "check"))


def transmissibility_bands() -> dict[str, FrequencyBand]:
    """The paper's Fig. 10 claims as bands: ``claim id -> FrequencyBand`` (Hz, statistic of :math:`|T|`, label)."""
    claims = read_toml(data_dir() / "paper" / "claims.toml")["claim"]
    return {c["id"]: FrequencyBand(*c["band"], c["statistic"], c["label"]) for c in claims if "band" in c}


@functools.cache
def _transmissibility_stats() -> dict[str, float]:
    """The vehicle's hub -> upper-mount statistics (Fig. 10): no tire in them, the same on both models."""
    return transmissibility_statistics(load_vehicle(PAPER_CAR), transmissibility_bands())


# ---------------------------------------------------------------- one evaluator per claim


def _fe_dof(model: str) -> float:
    return float(tire_model(tire_of(model)).equivalent_dof())


def _first_vertical_resonance(model: str) -> float:
    v = _visco(model)
    return float(resonance_peaks(v.freqs, v.H_tot)[0][0])


def _superposition(model: str) -> float:
    v = _visco(model)
    return float(np.max(np.abs(v.H_sum - v.H_tot) / np.abs(v.H_tot)))


def _footprint_slip(model: str) -> float:
    v = _visco(model)
    keep = v.freqs <= 300
    sliding = stages.frf_visco(tire_of(model), freqs=v.freqs[keep], stick=False)
    return float(band_errors(v.freqs[keep], v.H_tot[keep], sliding.H_tot)["complex rel. RMS"].max())


def _frozen_underestimates(model: str) -> float:
    """Resonances seen by the tasselli (peaks of their RMS FRF): H_tot of the cross-section tire
    shows one mode only, the others cancel in the sum."""
    reduced = stages.modal_reduction(tire_of(model))
    v = _visco(model)
    peaks = peak_comparison(v.freqs, v.H_rms, reduced.frf.H_rms, f_max=260.0, min_ratio=1.0)
    above = peaks["reference (Hz)"] > reduced.reference_frequency + 5.0
    return float(peaks.loc[above, "shift (%)"].max())


def _paper_modal_errors(model: str) -> np.ndarray:
    v = _visco(model)
    paper = stages.modal_reduction(tire_of(model), frozen="storage", damping="identified")
    return band_errors(v.freqs, v.H_tot, paper.frf.H_sum)["complex rel. RMS"].to_numpy()


def _eight_poles(model: str) -> float:
    v = _visco(model)
    return float(fit_tasselli(v.freqs, v.H, n_poles=8, f_max=250.0).rms_errors.max())  # the paper's band


def _fig6_fit(model: str) -> float:
    static = stages.solve_static(tire_of(model))
    centre = int(np.argmin(np.hypot(static.tasselli.centre_x, static.tasselli.centre_y)))
    return float(stages.fit_tasselli(tire_of(model))[centre].rms_error)


def _moving_hub(model: str) -> float:
    check = moving_hub_check(tire_of(model, "check"), freqs=np.arange(2.0, 251.0, 4.0))
    return check.errors()["hub force F_M"]


def _resolution(model: str) -> float:
    tire = tire_of(model, "check")
    v = stages.frf_visco(tire)
    k = int(np.argmin(np.abs(v.freqs - 100.0)))
    return float(tassellation_error(stages.solve_static(tire), v.H_points[:, k], [0.05])[0])


def _fig14_modes(model: str) -> float:
    setup, test = corner_setup(PAPER_CAR, tire_of(model, "check")), road_test_conditions()
    return float(len(hub_mode_peaks(setup, test.spectra()["rough"], test.speed)))


def _hub_rms(model: str, texture: str) -> float:
    return band_rms(_quarter_car(model)[texture]["a_hub"])


def _low_share(model: str, texture: str, output: str) -> float:
    return power_share(_quarter_car(model)[texture][output], 0.0, 50.0)


def _two_peaks(model: str, which: str) -> float:
    """Distinct peaks (prominence >= 10 % of the largest force) while the cleat passes."""
    if which == "linear":
        run = _cleat(model).quasi_static.result
        return float(distinct_peaks(run.distance, run.force, (-np.inf, np.inf)))
    run = _contact(model).dynamic
    return float(distinct_peaks(run.distance, run.hub_force, (-0.15, 0.15)))


@functools.cache
def _whole_car(model: str) -> WholeCarSetup:
    return whole_car_setup(tire=tire_of(model, "check"))


def _car_coherence(model: str) -> float:
    _, predicted, road = predicted_coherence(_whole_car(model))
    return float(np.abs(predicted - road).max())


@functools.cache
def _cavity_split(model: str):
    return split_against_load(cavity_conditions(_cavity_tire(model)))


def _cavity_tire(model: str) -> str:
    """The cavity test's tire (``[cavity] tire`` of whole_car.toml) in the role it has, on ``model``."""
    return tire_of(model, role_of(cavity_conditions().tire))


def _rated_load(model: str) -> float:
    return float(tire_model(_cavity_tire(model)).default_load)


EVALUATORS: dict[str, Callable[[str], float]] = {
    "fe_dof": _fe_dof,
    "n_tasselli": lambda m: float(stages.solve_static(tire_of(m)).tasselli.n),
    "first_vertical_resonance": _first_vertical_resonance,
    "superposition": _superposition,
    "footprint_slip": _footprint_slip,
    "freezing_frequency": lambda m: stages.modal_reduction(tire_of(m)).reference_frequency,
    "frozen_underestimates": _frozen_underestimates,
    "fig5_match": lambda m: float(_paper_modal_errors(m)[0]),
    "fig5_degrades": lambda m: float(_paper_modal_errors(m)[-1] / _paper_modal_errors(m)[0]),
    "eight_poles": _eight_poles,
    "fig6_fit": _fig6_fit,
    "cleat_two_peaks": lambda m: _two_peaks(m, "linear"),
    "cleat_quasi_static": lambda m: _cleat(m).quasi_static.peak_force,
    "cleat_dynamic": lambda m: _cleat(m).dynamic.peak_force,
    "moving_hub": _moving_hub,
    "hub_poles": lambda m: float(stages.fit_hub(tire_of(m, "check")).n_poles),
    "resolution_5cm": _resolution,
    "extension_400": lambda m: relative_rms_error(*cleat_chain(tire_of(m), 400.0)[2:]),
    "fig10_low": lambda m: _transmissibility_stats()["fig10_low"],
    "fig10_mid": lambda m: _transmissibility_stats()["fig10_mid"],
    "fig10_high": lambda m: _transmissibility_stats()["fig10_high"],
    "fig11_low_frequency": lambda m: _low_share(m, "rough", "a_hub"),
    "fig12_equalized": lambda m: _low_share(m, "rough", "a_mount"),
    "fig11_textures": lambda m: _hub_rms(m, "rough") / _hub_rms(m, "smooth"),
    "fig14_modes": _fig14_modes,
    "contact_two_peaks": lambda m: _two_peaks(m, "contact"),
    "contact_quasi_static": lambda m: _contact(m).quasi_static.peak_force,
    "contact_dynamic": lambda m: _contact(m).dynamic.peak_force,
    "contact_ratio": lambda m: _contact(m).ratio,
    "contact_decay": lambda m: float(_contact(m).decay["frequency (Hz)"].iloc[0]),
    "car_heavy_body": lambda m: heavy_body_difference(_whole_car(m).car),
    "car_notches": lambda m: float(notch_depth(_whole_car(m), 20.0)["largest at a notch / peak"].max()),
    "car_time_vs_frequency": lambda m: float((wheelbase_check(_whole_car(m)).ratios - 1.0).abs().to_numpy().max()),
    "car_coherence": _car_coherence,
    "cavity_split": lambda m: _cavity_split(m).set_index("load (N)").loc[_rated_load(m), "split (Hz)"],
    "cavity_load_exponent": lambda m: load_exponent(_cavity_split(m)),
}
