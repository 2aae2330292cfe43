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
:func:`texture_road`      :func:`roadnoise_utils.road.input.texture_road` (a generated road)
========================  ==================================================================

:func:`load_tire`, :func:`build_fet` and :func:`assemble_fixed_hub` are fast and not cached.

The tire file's ``[tire] model`` chooses the numerics: for a cross-section tire
:func:`solve_static`, :func:`frf_visco`, :func:`modal_reduction` and :func:`fe_cleat_response`
run :mod:`.section_stages` and return the same types, so the fits, the state space, the cleat
test, the moving hub and the quarter car run unchanged; :func:`loaded_modes` and
:func:`one_sided_run` are ring-only and refuse it.
"""

from __future__ import annotations

import control
import numpy as np

from ..response import fe_reference, frf, modes, one_sided, section_footprint
from ..response import modal_reduction as modal
from ..response.frf import FRFResult
from ..response.modal_reduction import ModalReduction
from ..response.modes import LoadedModes
from ..rm import moving_hub, order, realisation
from ..rm.fitting import FitSet
from ..road import input as road_input
from ..road.cleat import cleat_input, cleat_profile
from ..road.input import BAND, RoadInput
from ..road.textures import RoadProfile, RoadSpectrum
from ..tire import cavity as cavity_model
from ..tire import ring_model, section_static, spec, static
from ..tire.cross_section import CrossSectionSpec
from ..tire.ring_model import FETModel
from ..tire.section_static import SectionStaticState
from ..tire.spec import NO_CAVITY, TireSpec
from ..tire.static import StaticState
from . import section_stages
from .cache import cached
from .inputs import DEFAULT_FREQS, FIT_TOLERANCE, loaded_inputs

Tire = str | TireSpec | CrossSectionSpec


def load_tire(tire: Tire) -> TireSpec | CrossSectionSpec:
    """The spec of a tire name or path (:func:`roadnoise_utils.tire.spec.load_tire`), or the spec itself.

    The file's ``[tire] model`` chooses the model: a :class:`TireSpec` (ring) or a
    :class:`~roadnoise_utils.tire.cross_section.CrossSectionSpec`; every stage below runs on either,
    except those named ring-only.
    """
    return tire if isinstance(tire, (TireSpec, CrossSectionSpec)) else spec.load_tire(tire)


def is_cross_section(tire: Tire) -> bool:
    """Whether the tire is a cross-section tire (``[tire] model = "cross-section"``)."""
    return isinstance(load_tire(tire), CrossSectionSpec)


def model_name(tire: Tire) -> str:
    """The tire model of a tire file: ``"ring"`` or ``"cross-section"``."""
    return "cross-section" if is_cross_section(tire) else "ring"


def build_fet(tire: Tire) -> FETModel:
    """The assembled FE tire (fast; not cached)."""
    return ring_model.build_fet(load_tire(tire))


def rim_side_mass(tire: Tire) -> float:
    """The FE tire's mass the hub carries besides :math:`G_H` (kg), added to the unsprung mass (Eq. 5-7).

    Ring: :attr:`~roadnoise_utils.tire.ring_model.FETModel.hub_vertical_mass`. Cross-section:
    0, its :math:`G_H` holding the inertia of the clamped bead nodes (0.06 kg on the 165/65 R14).
    """
    return 0.0 if is_cross_section(tire) else build_fet(tire).hub_vertical_mass


def _loaded(tire: Tire, road: str, load: float | None, drum_radius: float | None) -> dict:
    """The resolved arguments of the loaded tire: spec, road, drum radius, load."""
    return loaded_inputs(load_tire(tire), road, load, drum_radius)


def _ring_only(tire: Tire, stage: str) -> None:
    """Refuse a cross-section tire in a stage only the ring model has."""
    if is_cross_section(tire):
        raise ValueError(f'{stage} runs on ring tires ([tire] model = "ring"); {tire!r} is a cross-section tire')


def frf_runs(tire: Tire) -> tuple:
    """The numerics behind :func:`frf_visco` for this tire's model (cache fingerprints)."""
    if is_cross_section(tire):
        return (section_footprint.footprint_frf, section_static.solve_section_static)
    return (frf.frf_visco, static.solve_static)


def _finite(inputs: dict) -> float | None:
    """The drum radius to pass on: ``None`` for a flat road."""
    return inputs["drum_radius"] if inputs["road"] == "drum" else None


def solve_static(
    tire: Tire, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> StaticState | SectionStaticState:
    """The loaded tire (cached): :func:`roadnoise_utils.tire.static.solve_static` for a ring tire,
    :func:`.section_stages.section_static` for a cross-section tire; ``drum_radius`` (m) is required for a drum."""
    tire = load_tire(tire)  # the file read once
    if is_cross_section(tire):
        return section_stages.section_static(tire, road, load, drum_radius)
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
    stick: bool | None = None,
    progress: bool = False,
) -> FRFResult:
    """The direct fixed-hub FRFs (cached; default :data:`DEFAULT_FREQS`, 0-400 Hz).

    A ring tire runs :func:`roadnoise_utils.response.frf.frf_visco` (``stick``: the footprint
    held in all directions, default, or free to slide); a cross-section tire runs
    :func:`.section_stages.section_footprint` (its contact is frictionless: ``stick`` must be
    ``None`` or ``False``) and returns the same :class:`FRFResult`.
    """
    freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
    tire = load_tire(tire)  # the file read once
    if is_cross_section(tire):
        if stick:
            raise ValueError(
                "stick = True: the cross-section tire's contact points slide freely (frictionless, vertical "
                "only); valid values are None or False"
            )
        found = section_stages.section_footprint(tire, road, freqs, load, drum_radius, progress)
        return found.to_frf_result()
    stick = True if stick is None else bool(stick)
    inputs = _loaded(tire, road, load, drum_radius)
    state = solve_static(tire, road, load, drum_radius)

    def compute() -> FRFResult:
        fet = build_fet(inputs["tire"])
        coupling = _cavity_coupling(inputs["tire"], fet, state)
        return frf.frf_visco(fet, state, freqs, progress=progress, stick=stick, cavity=coupling)

    return cached(
        frf_visco,
        {**inputs, "freqs": freqs, "stick": stick},
        compute,
        runs=(frf.frf_visco, static.solve_static, cavity_model.ring_cavity_coupling),
    )


def _cavity_coupling(spec: TireSpec, fet: FETModel, state: StaticState) -> cavity_model.CavityCoupling | None:
    """The air cavity of a ring tire file whose ``[cavity]`` is enabled (else None: the paper's model)."""
    air = spec.cavity
    if not air.enabled:
        return None
    cav = cavity_model.ring_tire_cavity(spec, air.temperature)
    return cavity_model.ring_cavity_coupling(fet, state, cav, n_modes=air.modes, damping_ratio=air.damping_ratio)


def has_cavity(tire: Tire) -> bool:
    """Whether the tire file couples its air cavity (``[cavity] enabled``), on either tire model."""
    return bool(getattr(load_tire(tire), "cavity", NO_CAVITY).enabled)


def _no_cavity(tire: Tire, stage: str) -> None:
    """Refuse a cavity-coupled tire in a stage whose FE numerics do not carry the cavity yet."""
    if has_cavity(tire):
        raise ValueError(
            f"{stage}: the FE numerics of this stage do not include the air cavity yet; valid tires have "
            "[cavity] enabled = false (the cavity reaches the direct FRFs, the fits and the RM chain)"
        )


def loaded_modes(
    tire: Tire,
    road: str = "flat",
    n_modes: int = 60,
    reference_frequency: float = 70.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> LoadedModes:
    """Cached :func:`roadnoise_utils.response.modes.loaded_modes` (ring tires, without the cavity)."""
    _ring_only(tire, "loaded_modes")
    _no_cavity(tire, "loaded_modes")
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
    f_band: float = 250.0,
) -> ModalReduction:
    """Cached modal reduction (paper Fig. 4) on the default direct sweep, band 0-``f_band`` Hz.

    A ring tire runs :func:`roadnoise_utils.response.modal_reduction.modal_reduction`, a
    cross-section tire :func:`.section_stages.section_modal` (loaded modes by component-mode
    synthesis of its harmonics).
    """
    tire = load_tire(tire)  # the file read once
    options = {"frozen": frozen, "damping": damping, "reference_frequency": reference_frequency, "f_band": f_band}
    _no_cavity(tire, "modal_reduction")
    if is_cross_section(tire):
        return section_stages.section_modal(tire, road, load=load, drum_radius=drum_radius, **options)
    inputs = _loaded(tire, road, load, drum_radius)
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
    why the direct FRFs and this order), or, when no order up to 24 gets there, the order with the
    smallest worst error, with a warning (the 195/65 R15 cross-section tire: its shoulder tasselli).
    """
    inputs = _loaded(tire, road, load, drum_radius)
    options = {"n_poles": n_poles, "f_max": float(f_max), "tolerance": FIT_TOLERANCE}
    visco = frf_visco(tire, road, load=load, drum_radius=drum_radius)

    def compute() -> FitSet:
        return order.fit_at_order(visco.freqs, visco.H, n_poles, f_max, FIT_TOLERANCE, strict=False)

    return cached(fit_tasselli, {**inputs, **options}, compute, runs=(order.fit_at_order, *frf_runs(tire)))


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

    return cached(fit_hub, {**inputs, **options}, compute, runs=(moving_hub.fit_hub, *frf_runs(tire)))


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
    """A cleat on the drum and its hub force straight from the FE tire (no reduction, no fit): ``(road, force)``.

    A ring tire: cached :func:`roadnoise_utils.response.fe_reference.fe_cleat_response`. A
    cross-section tire: the same frequency-domain sum
    (:func:`~roadnoise_utils.response.fe_reference.frequency_domain_response`) over its direct
    tassello FRFs (:func:`.section_stages.tassello_frfs`). Every cleat argument is explicit
    (``ru.experiments.cleat_test`` resolves them from ``data/conditions/cleat_test.toml``), so
    editing the conditions changes the key.
    """
    tire = load_tire(tire)  # the file read once
    if is_cross_section(tire):
        state = solve_static(tire, "drum", drum_radius=drum_radius)
        road = cleat_input(state, speed, height, base, shape, distance)
        frfs = section_stages.tassello_frfs(tire, "drum", drum_radius=drum_radius)
        return road, fe_reference.frequency_domain_response(frfs, road.u, road.dt, band, duration)
    _no_cavity(tire, "fe_cleat_response")
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
    time step (s; default :data:`roadnoise_utils.response.one_sided.DT_MAX` or finer). Ring tires.
    """
    _ring_only(tire, "one_sided_run")
    _no_cavity(tire, "one_sided_run")
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
    "texture_road",
]
