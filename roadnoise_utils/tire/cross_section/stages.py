"""Cached stages of the cross-section tire (``[tire] model = "cross-section"``).

============================  ================================================================================
stage                         caches
============================  ================================================================================
:func:`section_static`        :func:`~roadnoise_utils.tire.cross_section.static.solve_section_static`
:func:`footprint_reductions`  :func:`~roadnoise_utils.tire.cross_section.reductions.footprint_reductions`
                              (the harmonics reduced for a band: shared by the loaded states)
:func:`section_footprint`     :func:`~roadnoise_utils.tire.cross_section.footprint.footprint_frf`
                              (default 0-400 Hz every 1 Hz)
:func:`section_modal`         :func:`~roadnoise_utils.tire.cross_section.modal.section_modal_reduction`
                              on the default sweep
:func:`frozen_check`          :func:`~roadnoise_utils.tire.cross_section.modal.frozen_check`
:func:`quasi_static_cleat`    :func:`~roadnoise_utils.tire.cross_section.one_sided.section_quasi_static_run`
                              of a cleat on the drum
:func:`harmonic_reductions`   :func:`~roadnoise_utils.tire.cross_section.stepping.reduce_all` (every harmonic)
:func:`dynamic_cleat_runs`    :func:`~roadnoise_utils.tire.cross_section.one_sided.section_dynamic_runs`
                              of a cleat on the drum: the one-sided run and its frozen twin,
                              stepped together (:func:`dynamic_cleat` picks one)
:func:`cavity_areas`          :func:`~roadnoise_utils.tire.cross_section.cavity.loaded_areas` on the flat
                              road at several loads (one compliance and one factorisation per
                              harmonic for all)
============================  ================================================================================

:func:`section_tire` (mesh, harmonic matrices and inflation: about half a second) is not cached.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from ...repro.cache import cached
from ...response.modal_reduction import ModalReduction
from ...road.cleat import cleat_profile
from ..contact import ContactRun
from ..model import DEFAULT_FREQS, LoadCase, load_tire
from . import cavity as cavity_module
from . import cavity_frf, footprint, modal, one_sided, reductions, stepping
from . import static as static_module
from .footprint import FootprintFRF
from .spec import CrossSectionSpec
from .static import SectionStaticState, SectionTire, build_section_tire

SectionTireLike = str | Path | CrossSectionSpec


def load_section_tire(tire: SectionTireLike) -> CrossSectionSpec:
    """A :class:`CrossSectionSpec` from a name or path, or the spec itself; refuses a ring tire file."""
    loaded = tire if isinstance(tire, CrossSectionSpec) else load_tire(tire)
    if not isinstance(loaded, CrossSectionSpec):
        raise ValueError(
            f"tire {tire!r} is a {loaded.model!r} tire file; the cross-section stages need [tire] model = "
            '"cross-section" (e.g. "165_65R14_cross_section")'
        )
    return loaded


def section_tire(tire: SectionTireLike) -> SectionTire:
    """The built cross-section tire (fast; not cached)."""
    return build_section_tire(load_section_tire(tire))


def nominal_case(tire: SectionTireLike, road: str = "flat", drum_radius: float | None = None) -> LoadCase:
    """The load case of the tire file's nominal load on a road (``drum_radius`` in m for a drum)."""
    return LoadCase.of(road, load_section_tire(tire).operating.vertical_load, drum_radius)


def _inputs(tire: SectionTireLike, case: LoadCase) -> dict:
    """The cache key's core: the tire file's every value and the load case."""
    return {"tire": load_section_tire(tire), **case.key()}


def section_static(tire: SectionTireLike, case: LoadCase) -> SectionStaticState:
    """Cached :func:`roadnoise_utils.tire.cross_section.static.solve_section_static` for a load case."""
    inputs = _inputs(tire, case)

    def compute() -> SectionStaticState:
        drum = inputs["drum_radius"] if inputs["road"] == "drum" else None
        built = build_section_tire(inputs["tire"])
        return static_module.solve_section_static(built, inputs["road"], inputs["load"], drum)

    return cached(section_static, inputs, compute, runs=(static_module.solve_section_static,))


def section_footprint(
    tire: SectionTireLike, case: LoadCase, freqs: np.ndarray | None = None, progress: bool = False
) -> FootprintFRF:
    """Cached :func:`roadnoise_utils.tire.cross_section.footprint.footprint_frf` (default 0-400 Hz every 1 Hz).

    Frequencies of the default grid (whole Hz, 0-400) are read from its cached result.
    """
    inputs = _inputs(tire, case)
    freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
    if not np.array_equal(freqs, DEFAULT_FREQS) and np.all(np.isin(freqs, DEFAULT_FREQS)):
        return section_footprint(tire, case, None, progress).at(freqs)
    state = section_static(tire, case)

    def compute() -> FootprintFRF:
        f_max = float(freqs.max())
        reduced = footprint_reductions(tire, f_max, footprint.CUTOFF_FACTOR * f_max)
        built = build_section_tire(inputs["tire"])
        cavity = cavity_frf.section_cavity_coupling(built, state) if inputs["tire"].cavity.enabled else None
        return footprint.footprint_frf(built, state, freqs, progress=progress, reductions=reduced, cavity=cavity)

    return cached(section_footprint, {**inputs, "freqs": freqs}, compute, runs=(footprint.footprint_frf,))


def footprint_reductions(tire: SectionTireLike, f_max: float, cutoff: float) -> reductions.FootprintReductions:
    """Cached :func:`roadnoise_utils.tire.cross_section.reductions.footprint_reductions`: every harmonic reduced for
    ``0..f_max`` Hz with its modes below ``cutoff`` Hz; shared by the flat road's and the drum's
    footprints and by the time stepping's modal harmonics (:func:`harmonic_reductions`)."""
    inputs = {"tire": load_section_tire(tire), "f_max": float(f_max), "cutoff": float(cutoff)}

    def compute() -> reductions.FootprintReductions:
        built = build_section_tire(inputs["tire"])
        wall = cavity_module.wall_volume(built) if inputs["tire"].cavity.enabled else None  # the air's load
        return reductions.footprint_reductions(built, inputs["f_max"], inputs["cutoff"], wall)

    return cached(footprint_reductions, inputs, compute, runs=(reductions.footprint_reductions,))


def tassello_frfs(tire: SectionTireLike, case: LoadCase) -> Callable[[np.ndarray], np.ndarray]:
    """The direct tassello FRFs :math:`H_i(f)` (n_tasselli, n_f; N/m) as a function of the frequencies (Hz)."""

    def frfs(freqs: np.ndarray) -> np.ndarray:
        return section_footprint(tire, case, freqs).H_tasselli().T

    return frfs


def section_modal(
    tire: SectionTireLike,
    case: LoadCase,
    frozen: str = "complex",
    damping: str = "identified",
    reference_frequency: float | None = None,
    f_band: float = 250.0,
) -> ModalReduction:
    """Cached :func:`roadnoise_utils.tire.cross_section.modal.section_modal_reduction` on the default direct sweep."""
    load_section_tire(tire).cavity.refuse_in("section_modal")
    inputs = _inputs(tire, case)
    options = {"frozen": frozen, "damping": damping, "reference_frequency": reference_frequency, "f_band": f_band}
    state = section_static(tire, case)
    visco = section_footprint(tire, case).to_frf_result()

    def compute() -> ModalReduction:
        built = build_section_tire(inputs["tire"])
        reduced = footprint_reductions(tire, *modal.reduction_band(f_band))  # shared by the band's stages
        return modal.section_modal_reduction(built, state, visco, **options, reductions=reduced)

    return cached(
        section_modal,
        {**inputs, **options},
        compute,
        runs=(
            modal.section_modal_reduction,
            footprint.footprint_frf,
            reductions.footprint_reductions,
            static_module.solve_section_static,
        ),
    )


def frozen_check(tire: SectionTireLike, reference_frequency: float, freqs: np.ndarray) -> modal.FrozenCheck:
    """Cached :func:`roadnoise_utils.tire.cross_section.modal.frozen_check` (the synthesis and the direct frozen
    solve) on the flat road at the nominal load."""
    case = nominal_case(tire)
    inputs = _inputs(tire, case)
    options = {"reference_frequency": float(reference_frequency), "freqs": np.asarray(freqs, float)}
    state = section_static(tire, case)

    def compute() -> modal.FrozenCheck:
        built = build_section_tire(inputs["tire"])
        band = 250.0  # the paper's
        reduced = footprint_reductions(tire, *modal.reduction_band(band))  # shared by the band's stages
        return modal.frozen_check(
            built, state, options["freqs"], options["reference_frequency"], f_band=band, reductions=reduced
        )

    runs = (modal.frozen_check, reductions.footprint_reductions, static_module.solve_section_static)
    return cached(frozen_check, {**inputs, **options}, compute, runs=runs)


def quasi_static_cleat(
    tire: SectionTireLike,
    height: float,
    base: float,
    shape: str,
    drum_radius: float,
    distance: tuple[float, float],
    step: float = 1.0e-3,
) -> ContactRun:
    """Cached quasi-static cleat passage with one-sided contact on the drum (cleat and travel in m)."""
    case = nominal_case(tire, "drum", drum_radius)
    inputs = _inputs(tire, case)
    options = {**_cleat(height, base, shape, distance), "step": float(step)}
    state = section_static(tire, case)

    def compute() -> ContactRun:
        built = build_section_tire(inputs["tire"])
        profile = cleat_profile(height, base, shape)
        return one_sided.section_quasi_static_run(built, state, profile, options["distance"], step)

    runs = (one_sided.section_quasi_static_run, static_module.solve_section_static)
    return cached(quasi_static_cleat, {**inputs, **options}, compute, runs=runs)


def _cleat(height: float, base: float, shape: str, distance: tuple[float, float]) -> dict:
    """A cleat passage's key: the cleat (m) and the travel (m)."""
    return {"height": float(height), "base": float(base), "shape": shape, "distance": tuple(float(d) for d in distance)}


def harmonic_reductions(tire: SectionTireLike, f_max: float = 400.0) -> list:
    """Cached :func:`roadnoise_utils.tire.cross_section.stepping.reduce_all`: every harmonic's Ritz basis for the time-stepped runs."""
    load_section_tire(tire).cavity.refuse_in("harmonic_reductions")
    inputs = {"tire": load_section_tire(tire), "f_max": float(f_max)}

    def compute() -> list:
        f_max = inputs["f_max"]
        shared = footprint_reductions(tire, f_max, stepping.CUTOFF_FACTOR * f_max)  # the same modal harmonics
        return stepping.reduce_all(build_section_tire(inputs["tire"]), f_max, dynamic=shared.dynamic)

    return cached(harmonic_reductions, inputs, compute, runs=(stepping.reduce_all, reductions.footprint_reductions))


def dynamic_cleat(
    tire: SectionTireLike,
    speed: float,
    height: float,
    base: float,
    shape: str,
    drum_radius: float,
    distance: tuple[float, float],
    frozen: bool = False,
    dt: float | None = None,
) -> ContactRun:
    """Cached dynamic cleat passage on the drum, one-sided (or ``frozen``) contact (speed in m/s, lengths in m).

    One of the pair of :func:`dynamic_cleat_runs`.
    """
    return dynamic_cleat_runs(tire, speed, height, base, shape, drum_radius, distance, dt)[int(bool(frozen))]


def dynamic_cleat_runs(
    tire: SectionTireLike,
    speed: float,
    height: float,
    base: float,
    shape: str,
    drum_radius: float,
    distance: tuple[float, float],
    dt: float | None = None,
) -> tuple[ContactRun, ContactRun]:
    """Cached dynamic cleat passage on the drum: (one-sided contact, frozen contact), stepped together.

    Stepping the two runs in one :class:`roadnoise_utils.tire.cross_section.stepping.HarmonicStepper` reads the
    harmonics' operators once per step for both: the pair costs ~30 % less than two runs.
    """
    case = nominal_case(tire, "drum", drum_radius)
    inputs = _inputs(tire, case)
    options = {"speed": float(speed), **_cleat(height, base, shape, distance), "dt": None if dt is None else float(dt)}
    state = section_static(tire, case)

    def compute() -> tuple[ContactRun, ContactRun]:
        built = build_section_tire(inputs["tire"])
        profile = cleat_profile(height, base, shape)
        reduced = harmonic_reductions(tire)
        runs = one_sided.section_dynamic_runs(
            built, state, profile, speed, options["distance"], dt=dt, frozen=(False, True), reduced=reduced
        )
        return tuple(runs)

    runs = (one_sided.section_dynamic_runs, stepping, static_module.solve_section_static)
    return cached(dynamic_cleat_runs, {**inputs, **options}, compute, runs=runs)


def cavity_areas(tire: SectionTireLike, loads: tuple[float, ...]) -> tuple[list[SectionStaticState], np.ndarray]:
    """Cached loaded states on the flat road at ``loads`` (N) and the cavity's Webster area of each
    (:func:`roadnoise_utils.tire.cross_section.cavity.loaded_areas`, (n_loads, 720) m^2): the split against the load."""
    inputs = {"tire": load_section_tire(tire), "loads": tuple(float(v) for v in loads)}

    def compute() -> tuple[list[SectionStaticState], np.ndarray]:
        built = build_section_tire(inputs["tire"])
        states = static_module.solve_section_statics(built, "flat", inputs["loads"])
        return states, cavity_module.loaded_areas(built, states)

    return cached(cavity_areas, inputs, compute, runs=(cavity_module.loaded_areas, static_module.solve_section_statics))
