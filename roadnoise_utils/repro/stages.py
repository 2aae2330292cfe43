"""Cached stage functions: what a notebook calls to get an earlier stage of the pipeline.

Each function carries the name of the stage function it caches and takes the tire (a name in
``data/tires``, a path, or a :class:`~roadnoise_utils.tire.spec.TireSpec`) instead of the
earlier stages' results, which it fetches itself. Its arguments are explicit: test conditions
(the drum radius, the cleat) are resolved by :mod:`roadnoise_utils.experiments` and passed
in, so the cache key (:mod:`.cache`) holds every value a result depends on.

========================  ==================================================================
stage                     caches
========================  ==================================================================
:func:`solve_static`      :func:`roadnoise_utils.tire.static.solve_static`
:func:`frf_visco`         :func:`roadnoise_utils.response.frf.frf_visco` (default 0-400 Hz)
:func:`loaded_modes`      :func:`roadnoise_utils.response.modes.loaded_modes`
:func:`modal_reduction`   :func:`roadnoise_utils.response.modal_reduction.modal_reduction`
:func:`fit_tasselli`      :func:`roadnoise_utils.rm.fitting.fit_tasselli` on the direct H_i
:func:`fit_hub`           :func:`roadnoise_utils.rm.moving_hub.fit_hub` on the direct G_H
:func:`fe_cleat_response` :func:`roadnoise_utils.response.fe_reference.fe_cleat_response`
:func:`one_sided_run`     :func:`roadnoise_utils.response.one_sided.quasi_static_run` and
                          :func:`~roadnoise_utils.response.one_sided.dynamic_run` of a cleat
========================  ==================================================================

:func:`load_tire`, :func:`build_fet` and :func:`assemble_fixed_hub` are fast and not cached.
"""

from __future__ import annotations

import control
import numpy as np

from ..response import fe_reference, frf, modes, one_sided
from ..response import modal_reduction as modal
from ..response.frf import FRFResult
from ..response.modal_reduction import ModalReduction
from ..response.modes import LoadedModes
from ..rm import moving_hub, order, realisation
from ..rm.fitting import FitSet
from ..road.cleat import cleat_profile
from ..road.input import BAND, RoadInput
from ..tire import ring_model, spec, static
from ..tire.ring_model import FETModel
from ..tire.spec import TireSpec
from ..tire.static import StaticState, make_road
from .cache import cached

#: Default frequency grid of the direct sweeps: 0-400 Hz every 1 Hz (paper: up to 250 Hz,
#: "easily improved to 400 Hz").
DEFAULT_FREQS = np.arange(0.0, 400.0 + 0.5, 1.0)
#: Relative RMS error every fit must meet when the order is chosen automatically.
FIT_TOLERANCE = 0.01

Tire = str | TireSpec


def load_tire(tire: Tire) -> TireSpec:
    """A :class:`TireSpec` from a name or path (:func:`roadnoise_utils.tire.spec.load_tire`) or the spec itself.

    A cross-section tire file loads as its own spec (``[tire] model``); the ring stages refuse it
    in :func:`roadnoise_utils.tire.ring_model.build_fet`.
    """
    return tire if isinstance(tire, TireSpec) else spec.load_tire(tire)


def build_fet(tire: Tire) -> FETModel:
    """The assembled FE tire (fast; not cached)."""
    return ring_model.build_fet(load_tire(tire))


def _loaded(tire: Tire, road: str, load: float | None, drum_radius: float | None) -> dict:
    """The resolved arguments of the loaded tire: spec, road, drum radius, load."""
    return loaded_inputs(load_tire(tire), road, load, drum_radius)


def loaded_inputs(tire_spec, road: str, load: float | None, drum_radius: float | None) -> dict:
    """The resolved arguments of a loaded tire of either model (its validated spec): the cache key's core."""
    surface = make_road(road, drum_radius)
    return {
        "tire": tire_spec,
        "road": surface.kind,
        "drum_radius": surface.drum_radius,
        "load": tire_spec.operating.vertical_load if load is None else float(load),
    }


def _finite(inputs: dict) -> float | None:
    """The drum radius to pass on: ``None`` for a flat road."""
    return inputs["drum_radius"] if inputs["road"] == "drum" else None


def solve_static(
    tire: Tire, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> StaticState:
    """Cached :func:`roadnoise_utils.tire.static.solve_static`; ``drum_radius`` (m) is required for a drum."""
    inputs = _loaded(tire, road, load, drum_radius)

    def compute() -> StaticState:
        fet = ring_model.build_fet(inputs["tire"])
        return static.solve_static(fet, road=road, load=inputs["load"], drum_radius=_finite(inputs))

    return cached(solve_static, inputs, compute, runs=(static.solve_static, ring_model.build_fet))


def frf_visco(
    tire: Tire,
    road: str = "flat",
    freqs: np.ndarray | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
    stick: bool = True,
    progress: bool = False,
) -> FRFResult:
    """Cached :func:`roadnoise_utils.response.frf.frf_visco` (default :data:`DEFAULT_FREQS`, 0-400 Hz)."""
    inputs = _loaded(tire, road, load, drum_radius)
    freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
    state = solve_static(tire, road, load, drum_radius)

    def compute() -> FRFResult:
        return frf.frf_visco(build_fet(inputs["tire"]), state, freqs, progress=progress, stick=stick)

    return cached(
        frf_visco, {**inputs, "freqs": freqs, "stick": stick}, compute, runs=(frf.frf_visco, static.solve_static)
    )


def loaded_modes(
    tire: Tire,
    road: str = "flat",
    n_modes: int = 60,
    reference_frequency: float = 70.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> LoadedModes:
    """Cached :func:`roadnoise_utils.response.modes.loaded_modes`."""
    inputs = _loaded(tire, road, load, drum_radius)
    options = {"n_modes": int(n_modes), "reference_frequency": float(reference_frequency)}
    state = solve_static(tire, road, load, drum_radius)

    def compute() -> LoadedModes:
        return modes.loaded_modes(build_fet(inputs["tire"]), state, **options)

    return cached(loaded_modes, {**inputs, **options}, compute, runs=(modes.loaded_modes, static.solve_static))


def modal_reduction(
    tire: Tire,
    road: str = "flat",
    frozen: str = "complex",
    damping: str = "identified",
    reference_frequency: float | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
) -> ModalReduction:
    """Cached :func:`roadnoise_utils.response.modal_reduction.modal_reduction` on the default direct sweep."""
    inputs = _loaded(tire, road, load, drum_radius)
    options = {"frozen": frozen, "damping": damping, "reference_frequency": reference_frequency}
    state = solve_static(tire, road, load, drum_radius)
    visco = frf_visco(tire, road, load=load, drum_radius=drum_radius)

    def compute() -> ModalReduction:
        return modal.modal_reduction(build_fet(inputs["tire"]), state, visco=visco, **options)

    return cached(
        modal_reduction,
        {**inputs, **options},
        compute,
        runs=(modal.modal_reduction, frf.frf_visco, static.solve_static),
    )


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
    why the direct FRFs and this order).
    """
    inputs = _loaded(tire, road, load, drum_radius)
    options = {"n_poles": n_poles, "f_max": float(f_max), "tolerance": FIT_TOLERANCE}
    visco = frf_visco(tire, road, load=load, drum_radius=drum_radius)

    def compute() -> FitSet:
        return order.fit_at_order(visco.freqs, visco.H, n_poles, f_max, FIT_TOLERANCE)

    return cached(fit_tasselli, {**inputs, **options}, compute, runs=(order.fit_at_order, frf.frf_visco))


def fit_hub(
    tire: Tire,
    road: str = "flat",
    n_poles: int | None = None,
    f_max: float = 250.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> FitSet:
    """Cached :func:`roadnoise_utils.rm.moving_hub.fit_hub` of the direct hub FRF :math:`G_H` (Eq. 6)."""
    inputs = _loaded(tire, road, load, drum_radius)
    options = {"n_poles": n_poles, "f_max": float(f_max), "tolerance": FIT_TOLERANCE}
    visco = frf_visco(tire, road, load=load, drum_radius=drum_radius)

    def compute() -> FitSet:
        return moving_hub.fit_hub(visco.freqs, visco.G_H, n_poles=n_poles, f_max=f_max, tolerance=FIT_TOLERANCE)

    return cached(fit_hub, {**inputs, **options}, compute, runs=(moving_hub.fit_hub, frf.frf_visco))


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
    """Cached :func:`roadnoise_utils.response.fe_reference.fe_cleat_response` on the drum: ``(road, force)``.

    Every cleat argument is explicit (``ru.experiments.cleat_test`` resolves them from
    ``data/conditions/cleat_test.toml``), so editing the conditions changes the key.
    """
    inputs = {
        **_loaded(tire, "drum", None, drum_radius),
        "speed": float(speed),
        "height": float(height),
        "base": float(base),
        "shape": shape,
        "distance": tuple(float(d) for d in distance),
        "duration": float(duration),
        "band": float(band),
    }
    state = solve_static(tire, "drum", drum_radius=drum_radius)

    def compute() -> tuple[RoadInput, np.ndarray]:
        fet = build_fet(inputs["tire"])
        return fe_reference.fe_cleat_response(fet, state, speed, height, base, shape, distance, duration, band)

    return cached(fe_cleat_response, inputs, compute, runs=(fe_reference.fe_cleat_response, static.solve_static))


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
) -> one_sided.ContactRun:
    """Cached cleat passage with one-sided contact on the drum: quasi-static for ``speed = 0``, else dynamic.

    ``speed`` in m/s, cleat and ``distance`` in m; ``frozen`` keeps the static contact set
    bilateral (dynamic only); ``step`` is the travel between quasi-static solves (m); ``dt`` the
    time step (s; default :data:`roadnoise_utils.response.one_sided.DT_MAX` or finer).
    """
    inputs = {
        **_loaded(tire, "drum", None, drum_radius),
        "speed": float(speed),
        "height": float(height),
        "base": float(base),
        "shape": shape,
        "distance": tuple(float(d) for d in distance),
        "frozen": bool(frozen),
        "step": float(step),
        "dt": None if dt is None else float(dt),
    }
    state = solve_static(tire, "drum", drum_radius=drum_radius)

    def compute() -> one_sided.ContactRun:
        fet = build_fet(inputs["tire"])
        profile = cleat_profile(height, base, shape)
        if speed == 0:
            return one_sided.quasi_static_run(fet, state, profile, distance, step)
        return one_sided.dynamic_run(fet, state, profile, speed, distance, dt=dt, frozen=frozen)

    runs = (one_sided.quasi_static_run, one_sided.dynamic_run, static.solve_static)
    return cached(one_sided_run, inputs, compute, runs=runs)


__all__ = [
    "DEFAULT_FREQS",
    "FIT_TOLERANCE",
    "assemble_fixed_hub",
    "build_fet",
    "fe_cleat_response",
    "fit_hub",
    "fit_tasselli",
    "frf_visco",
    "load_tire",
    "loaded_modes",
    "modal_reduction",
    "one_sided_run",
    "solve_static",
]
