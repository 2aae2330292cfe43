"""Cached stage functions: what a notebook calls to get an earlier stage of the pipeline, on any tire model.

Each function carries the name of the stage it caches and takes the tire (a name in
``data/tires``, a path, a validated spec or a :class:`~roadnoise_utils.tire.model.TireModel`)
instead of the earlier stages' results, which it fetches itself. The tire file's ``[tire] model``
chooses the :class:`~roadnoise_utils.tire.model.TireModel` (:func:`tire_model`); each stage asks
it through the interface and never asks which model it holds. Its arguments are explicit: test
conditions (the drum radius, the cleat) are resolved by :mod:`roadnoise_utils.experiments` and
passed in, so the cache key (:mod:`.cache`) holds every value a result depends on.

==========================  ==================================================================
stage                       asks the tire model for
==========================  ==================================================================
:func:`solve_static`        :meth:`~.TireModel.load`: the loaded tire on a road or a drum
:func:`frf_visco`           :meth:`~.TireModel.fixed_hub_frfs` (default 0-400 Hz)
:func:`loaded_modes`        its loaded modes (capability ``loaded_modes``)
:func:`modal_reduction`     the paper's modal reduction (capability ``modal_reduction``)
:func:`fit_tasselli`        :func:`roadnoise_utils.rm.order.fit_at_order` on the direct H_i
:func:`fit_hub`             :func:`roadnoise_utils.rm.moving_hub.fit_hub` on G_H (``hub_transfer``)
:func:`fe_cleat_response`   a cleat straight from the FE tire (capability ``direct_response``)
:func:`one_sided_run`       a cleat with one-sided contact (capability ``one_sided_cleat``)
:func:`texture_road`        :func:`roadnoise_utils.road.input.texture_road` (a generated road)
==========================  ==================================================================

:func:`load_tire`, :func:`build_fet` and :func:`assemble_fixed_hub` are fast and not cached. A
stage whose capability the tire model lacks raises
:class:`~roadnoise_utils.tire.model.NotApplicable`, naming it.
"""

from __future__ import annotations

from typing import Any

import control
import numpy as np

from ..response.modal_reduction import ModalReduction
from ..rm import moving_hub, order, realisation
from ..rm.fitting import FitSet
from ..road import input as road_input
from ..road.input import BAND, RoadInput
from ..road.textures import RoadProfile, RoadSpectrum
from ..tire.contact import ContactRun
from ..tire.model import Footprint, FRFResult, TireModel, tire_model
from .cache import cached
from .inputs import DEFAULT_FREQS, FIT_TOLERANCE

Tire = str | TireModel | object


def load_tire(tire: Tire):
    """The validated tire file of a tire name, path, model or spec (its ``[tire] model`` chooses the class)."""
    return tire_model(tire).spec


def rim_side_mass(tire: Tire) -> float:
    """The FE tire's mass the hub carries besides :math:`G_H` (kg), added to the unsprung mass (Eq. 5-7)."""
    return tire_model(tire).rim_side_mass()


def frf_runs(tire: Tire) -> tuple:
    """What the stages built on this tire's results fingerprint: its model's :meth:`~.TireModel.code_runs`."""
    return tire_model(tire).code_runs()


def has_cavity(tire: Tire) -> bool:
    """Whether the tire file couples its air cavity (``[cavity] enabled``)."""
    return tire_model(tire).cavity_enabled


def solve_static(
    tire: Tire, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> Footprint:
    """The loaded tire (cached): the model's :meth:`~.TireModel.load`; ``drum_radius`` (m) is required for a drum."""
    model = tire_model(tire)
    return model.load(model.case(road, load, drum_radius))


def frf_visco(
    tire: Tire,
    road: str = "flat",
    freqs: np.ndarray | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
    stick: bool | None = None,
    progress: bool = False,
) -> FRFResult:
    """The direct fixed-hub FRFs (cached; default the model's grid, :data:`DEFAULT_FREQS` for an FE tire): the model's
    :meth:`~.TireModel.fixed_hub_frfs`. ``stick``: the footprint held in all directions or free to
    slide (``None``: the model's own contact; a frictionless model refuses ``True``)."""
    freqs = None if freqs is None else np.asarray(freqs, dtype=float)
    model = tire_model(tire)
    return model.fixed_hub_frfs(model.case(road, load, drum_radius), freqs, progress=progress, stick=stick)


def loaded_modes(
    tire: Tire,
    road: str = "flat",
    n_modes: int = 60,
    reference_frequency: float = 70.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> Any:
    """The loaded tire's modes (cached; capability ``loaded_modes``): the model's :meth:`loaded_modes`."""
    model = tire_model(tire)
    model.require("loaded_modes")
    return model.loaded_modes(model.case(road, load, drum_radius), n_modes, reference_frequency)


def modal_reduction(
    tire: Tire,
    road: str = "flat",
    frozen: str = "complex",
    damping: str = "identified",
    reference_frequency: float | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
    f_band: float = 250.0,
) -> ModalReduction:
    """Cached modal reduction (paper Fig. 4) on the default direct sweep, band 0-``f_band`` Hz
    (capability ``modal_reduction``)."""
    model = tire_model(tire)
    model.require("modal_reduction")
    options = {"frozen": frozen, "damping": damping, "reference_frequency": reference_frequency, "f_band": f_band}
    return model.modal_reduction(model.case(road, load, drum_radius), **options)


def fit_tasselli(
    tire: Tire,
    road: str = "flat",
    n_poles: int | None = None,
    f_max: float = 250.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> FitSet:
    """Cached rational fits (Eq. 1) of the direct local FRFs :math:`H_i` over 0-``f_max`` Hz.

    ``n_poles=None`` takes the lowest order at which every tassello is fitted within
    :data:`FIT_TOLERANCE` (:func:`roadnoise_utils.rm.order.lowest_order`; notebook 03 shows
    why the direct FRFs and this order), or, when no order up to 24 gets there, the order with the
    smallest worst error, with a warning (the 195/65 R15 cross-section tire: its shoulder tasselli).
    """
    model = tire_model(tire)
    case = model.case(road, load, drum_radius)
    options = {"n_poles": n_poles, "f_max": float(f_max), "tolerance": FIT_TOLERANCE}
    visco = model.fixed_hub_frfs(case)

    def compute() -> FitSet:
        return order.fit_at_order(visco.freqs, visco.H, n_poles, f_max, FIT_TOLERANCE, strict=False)

    inputs = {"tire": model.fingerprint(), **case.key(), **options}
    return cached(fit_tasselli, inputs, compute, runs=(order.fit_at_order, *model.code_runs()))


def fit_hub(
    tire: Tire,
    road: str = "flat",
    n_poles: int | None = None,
    f_max: float = 250.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> FitSet:
    """Cached :func:`roadnoise_utils.rm.moving_hub.fit_hub` of the direct hub FRF :math:`G_H` (Eq. 6;
    capability ``hub_transfer``)."""
    model = tire_model(tire)
    model.require("hub_transfer")
    case = model.case(road, load, drum_radius)
    options = {"n_poles": n_poles, "f_max": float(f_max), "tolerance": FIT_TOLERANCE}
    visco = model.fixed_hub_frfs(case)

    def compute() -> FitSet:
        return moving_hub.fit_hub(visco.freqs, visco.G_H, n_poles=n_poles, f_max=f_max, tolerance=FIT_TOLERANCE)

    inputs = {"tire": model.fingerprint(), **case.key(), **options}
    return cached(fit_hub, inputs, compute, runs=(moving_hub.fit_hub, *model.code_runs()))


def assemble_fixed_hub(
    tire: Tire,
    road: str = "flat",
    n_poles: int | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
) -> control.StateSpace:
    """The fixed-hub state-space tire (Eq. 3-4) assembled from the cached :func:`fit_tasselli`."""
    return realisation.assemble_fixed_hub(fit_tasselli(tire, road, n_poles, load=load, drum_radius=drum_radius))


def fe_cleat_response(
    tire: Tire,
    speed: float,
    height: float,
    base: float,
    shape: str,
    drum_radius: float,
    distance: tuple[float, float] = (-0.1, 0.5),
    duration: float = 1.0,
    band: float = BAND,
) -> tuple[RoadInput, np.ndarray]:
    """A cleat on the drum and its hub force straight from the FE tire (no reduction, no fit):
    ``(road, force)`` (capability ``direct_response``). Every cleat argument is explicit
    (``ru.experiments.cleat_test`` resolves them from ``data/conditions/cleat_test.toml``), so
    editing the conditions changes the key."""
    model = tire_model(tire)
    model.require("direct_response")
    cleat = {
        "speed": float(speed),
        "height": float(height),
        "base": float(base),
        "shape": shape,
        "distance": tuple(float(d) for d in distance),
        "duration": float(duration),
        "band": float(band),
    }
    return model.direct_cleat_response(model.case("drum", None, drum_radius), cleat)


def one_sided_run(
    tire: Tire,
    speed: float,
    height: float,
    base: float,
    shape: str,
    drum_radius: float,
    distance: tuple[float, float],
    frozen: bool = False,
    step: float = 5.0e-4,
    dt: float | None = None,
) -> ContactRun:
    """Cached cleat passage with one-sided contact on the drum: quasi-static for ``speed = 0``, else
    dynamic (capability ``one_sided_cleat``).

    ``speed`` in m/s, cleat and ``distance`` in m; ``frozen`` keeps the static contact set
    bilateral (dynamic only); ``step`` is the travel between quasi-static solves (m); ``dt`` the
    time step (s; default the model's).
    """
    model = tire_model(tire)
    model.require("one_sided_cleat")
    cleat = {
        "speed": float(speed),
        "height": float(height),
        "base": float(base),
        "shape": shape,
        "distance": tuple(float(d) for d in distance),
        "frozen": bool(frozen),
        "step": float(step),
        "dt": None if dt is None else float(dt),
    }
    return model.one_sided_run(model.case("drum", None, drum_radius), cleat)


def texture_road(spectrum: RoadSpectrum, length: float, seed: int, tracks: np.ndarray | None = None) -> RoadProfile:
    """Cached :func:`roadnoise_utils.road.input.texture_road`: a generated road (3D over ``tracks``, m, or 2D)."""
    inputs = {
        "spectrum": spectrum,
        "length": float(length),
        "seed": int(seed),
        "tracks": None if tracks is None else np.asarray(tracks, float),
    }

    def compute() -> RoadProfile:
        return road_input.texture_road(spectrum, inputs["length"], inputs["seed"], inputs["tracks"])

    return cached(texture_road, inputs, compute, runs=(road_input.texture_road,))


__all__ = [
    "DEFAULT_FREQS",
    "FIT_TOLERANCE",
    "assemble_fixed_hub",
    "fe_cleat_response",
    "fit_hub",
    "fit_tasselli",
    "frf_visco",
    "load_tire",
    "loaded_modes",
    "modal_reduction",
    "one_sided_run",
    "solve_static",
    "texture_road",
    "tire_model",
]
