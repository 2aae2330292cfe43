"""Cached stages of the loaded FE tire (``[tire] model = "loaded-fe"``).

===========================  ==========================================================================
stage                        caches
===========================  ==========================================================================
:func:`inflated_state`       mount and inflation (:func:`.statics.inflate`), shared by the load cases
:func:`loaded_state`         the nonlinear loading to the case's load on its road
                             (:func:`.loading.load_on_road`)
:func:`loaded_footprint`     the state as every model's footprint (:func:`.footprint.loaded_footprint`)
:func:`loaded_frfs`          the dynamics linearised about it, reduced and swept
                             (:func:`.dynamics.footprint_frf`), on the footprint's tasselli; with
                             ``[cavity] enabled`` the air coupled (:func:`.cavity.loaded_coupling`)
:func:`swept_states`         one loading through several loads on the flat road
                             (:func:`.loading.load_sweep`), from :func:`loaded_state` at the first
:func:`load_curve`           their footprints
:func:`round_stiffness`      K_v with the geometric nonlinearity off (:mod:`.linearised`)
:func:`reduced_footprint`    the linearised tire's Craig-Bampton reduction, its held modes' wave numbers
:func:`loaded_modal`         the paper's modal reduction (Fig. 4) (:mod:`roadnoise_utils.tire.loaded.modal`)
:func:`quasi_static_cleat`   a cleat's quasi-static passage on the drum, one-sided contact
                             (:func:`.one_sided.quasi_static_run`)
:func:`dynamic_cleat_runs`   its dynamic passage, one-sided and frozen contact stepped together
                             (:func:`.one_sided.dynamic_runs`)
===========================  ==========================================================================

:func:`built_tire` (the swept mesh and its integration points: about a second) and :func:`cavity_areas`
(the loaded cavity's section round the wheel from the swept states: a fraction of a second) are not cached.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ... import guards
from ...repro.cache import cached
from ...response.modal_reduction import ModalReduction, check_options
from ...road.cleat import cleat_profile
from ..cavity import CavityCoupling
from ..contact import ContactRun
from ..model import DEFAULT_FREQS, Footprint, FRFResult, LoadCase
from ..schema import NO_CAVITY
from . import cavity, dynamics, footprint, linearised, loading, modal, one_sided, road_contact, statics
from .mesh import graded_arcs
from .spec import LoadedSpec
from .statics import LoadedTire, StaticState


def built_tire(spec: LoadedSpec) -> LoadedTire:
    """The construction swept through the solid mesh's graded arcs (not cached)."""
    m = spec.solid_mesh
    radius = spec.construction.geometry.outer_radius
    arcs = graded_arcs(radius, m.footprint_arc, m.sector_half_angle, m.coarse_arc, m.arc_growth)
    return statics.build_loaded_tire(spec.construction, arcs)


def without_air(spec: LoadedSpec) -> LoadedSpec:
    """The tire file as its statics read it: the ``[cavity]`` settings are the air's dynamics (the inflation
    is the file's operating pressure), so a tire with its air cavity on shares the static states of
    the same tire without it."""
    return replace(spec, construction=replace(spec.construction, cavity=NO_CAVITY))


def with_its_air(spec: LoadedSpec) -> LoadedSpec:
    """The tire file as a dynamic stage's key reads it: with its ``[cavity]`` settings where it couples its
    air, without them (:func:`without_air`) where it does not, so that a tire without its air has one
    cached result for every ``[cavity]`` setting."""
    return spec if spec.construction.cavity.enabled else without_air(spec)


def loaded_air(spec: LoadedSpec, tire: LoadedTire, state: StaticState) -> CavityCoupling | None:
    """The air cavity of ``state`` where the tire file couples it (:func:`.cavity.loaded_coupling`), else None."""
    return cavity.loaded_coupling(tire, state) if spec.construction.cavity.enabled else None


def inflated_state(spec: LoadedSpec) -> StaticState:
    """Cached: the tire mounted and inflated to its file's pressure (:func:`.statics.inflate`), shared by
    every load case of the file (7 s on the production mesh) and by its ``[cavity]`` settings."""
    spec = without_air(spec)
    return cached(inflated_state, {"tire": spec}, lambda: statics.inflate(built_tire(spec)), runs=(statics,))


def loaded_state(spec: LoadedSpec, case: LoadCase) -> StaticState:
    """Cached: :func:`inflated_state` loaded on the case's road (flat or drum) to ``case.load`` (N), whatever
    the ``[cavity]`` settings (:func:`without_air`)."""
    spec = without_air(spec)
    inputs = {"tire": spec, **case.key()}

    def compute() -> StaticState:
        tire = built_tire(spec)
        return loading.load_on_road(tire, inflated_state(spec), case.load, spec.solid_mesh.road_step, case.road)

    return cached(loaded_state, inputs, compute, runs=(loading, road_contact, statics))


def loaded_footprint(spec: LoadedSpec, case: LoadCase) -> Footprint:
    """Cached :func:`.footprint.loaded_footprint` of :func:`loaded_state` (the tangent K_v's solve included),
    whatever the ``[cavity]`` settings (:func:`without_air`)."""
    spec = without_air(spec)
    state = loaded_state(spec, case)
    inputs = {"tire": spec, **case.key()}
    return cached(
        loaded_footprint,
        inputs,
        lambda: footprint.loaded_footprint(built_tire(spec), state, case.load),
        runs=(footprint, loading, road_contact, statics),
    )


def loaded_frfs(spec: LoadedSpec, case: LoadCase, freqs: np.ndarray | None = None) -> FRFResult:
    """Cached fixed-hub FRFs about :func:`loaded_state` at ``freqs`` (Hz; default 0-400 Hz every 1 Hz):
    linearised (:func:`.dynamics.linearise`), reduced for ``max(freqs)`` (:func:`.dynamics.reduce`)
    and swept, on the tasselli of :func:`loaded_footprint`; the construction's ``[cavity] enabled``
    couples the air of the loaded cavity (:func:`.cavity.loaded_coupling`)."""
    freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
    if not np.array_equal(freqs, DEFAULT_FREQS) and np.all(np.isin(freqs, DEFAULT_FREQS)):
        full = loaded_frfs(spec, case)
        return full.take(np.searchsorted(full.freqs, freqs))
    state = loaded_state(spec, case)
    tasselli = loaded_footprint(spec, case).tasselli

    def compute() -> FRFResult:
        tire = built_tire(spec)
        linearised = dynamics.linearise(tire, state)
        frf = dynamics.footprint_frf(linearised, freqs, cavity=loaded_air(spec, tire, state))
        return footprint.frf_result(frf, tasselli)

    # without the air, its settings change nothing: one cached sweep for every [cavity] setting
    inputs = {"tire": with_its_air(spec), **case.key(), "freqs": freqs}
    return cached(loaded_frfs, inputs, compute, runs=(cavity, dynamics, footprint, loading, road_contact, statics))


def swept_states(spec: LoadedSpec, loads: tuple[float, ...]) -> list[StaticState]:
    """Cached: the tire at each of ``loads`` (N, increasing) on the flat road, one loading from
    :func:`inflated_state` continued from load to load (:func:`.loading.load_sweep`).

    The loading's first leg, from the inflated tire to ``loads[0]``, is the flat road's
    :func:`loaded_state` at that load (the same solves): it is that cached stage, shared with the
    load cases, and the sweep continues from it.
    """
    loads = tuple(loading.increasing_loads(loads))
    spec = without_air(spec)

    def compute() -> list[StaticState]:
        first = loaded_state(spec, LoadCase.of("flat", loads[0]))
        if len(loads) == 1:
            return [first]
        rest = loading.load_sweep(
            built_tire(spec), inflated_state(spec), list(loads[1:]), spec.solid_mesh.road_step, start=first
        )
        return [first, *rest]

    inputs = {"tire": spec, "road": "flat", "loads": loads}
    return cached(swept_states, inputs, compute, runs=(loading, road_contact, statics))


def load_curve(spec: LoadedSpec, loads: tuple[float, ...]) -> list[Footprint]:
    """Cached: the footprint (its tangent K_v included) of each of :func:`swept_states`, whatever the
    ``[cavity]`` settings."""
    spec = without_air(spec)
    states = swept_states(spec, loads)

    def compute() -> list[Footprint]:
        tire = built_tire(spec)
        return [footprint.loaded_footprint(tire, state, load) for state, load in zip(states, loads)]

    inputs = {"tire": spec, "road": "flat", "loads": tuple(float(load) for load in loads)}
    return cached(load_curve, inputs, compute, runs=(footprint, loading, road_contact, statics))


def cavity_areas(
    spec: LoadedSpec, loads: tuple[float, ...], temperature: float | None = None
) -> tuple[list[Footprint], np.ndarray]:
    """The footprints of :func:`load_curve` and the cavity's Webster area round the wheel in each of
    :func:`swept_states` (:func:`.cavity.webster_area`, (n_loads, :data:`.cavity.N_ANGLES`) m^2)."""
    tire = built_tire(spec)
    air = cavity.air_cavity(spec.construction, temperature)
    areas = np.array([cavity.webster_area(tire, state, air) for state in swept_states(spec, loads)])
    return load_curve(spec, loads), areas


def round_stiffness(spec: LoadedSpec, load: float) -> float:
    """Cached: K_v (N/m) at ``load`` (N) on the flat road with the geometric nonlinearity switched off, the
    solids linearised about the round tire under its linear inflation as the waveguide tire is
    (:func:`.linearised.round_linearisation`), the one-sided contact solved on that linear tire."""
    load = guards.real("load", load, *guards.LOAD_RANGE, unit="N")
    spec = without_air(spec)

    def compute() -> float:
        tire = built_tire(spec)
        rounded = linearised.round_linearisation(tire)
        compliance = linearised.contact_compliance(tire, rounded.state, tangent=rounded.tangent)
        return linearised.flat_road_at_load(compliance, load).stiffness

    return cached(round_stiffness, {"tire": spec, "road": "flat", "load": load}, compute, runs=(linearised, statics))


def reduced_footprint(spec: LoadedSpec, case: LoadCase, f_max: float) -> dynamics.ReducedFootprint:
    """Cached: the tire linearised about :func:`loaded_state` and reduced for 0-``f_max`` Hz
    (:func:`.dynamics.reduce`), its held modes at rest labelled with their wave numbers
    (:func:`.modal.harmonic_of_modes`); the basis itself is not kept. With the construction's
    ``[cavity] enabled``, the air of the loaded cavity coupled (:func:`.cavity.loaded_coupling`)."""
    f_max = guards.real("f_max", f_max, lo=0.0, lo_open=True, unit="Hz")
    spec = with_its_air(spec)
    state = loaded_state(spec, case)

    def compute() -> dynamics.ReducedFootprint:
        tire = built_tire(spec)
        air = loaded_air(spec, tire, state)
        reduced = dynamics.reduce(dynamics.linearise(tire, state), f_max, keep_basis=True, cavity=air)
        held = reduced.basis[:, reduced.n_boundary : reduced.n_boundary + reduced.n_modes]
        harmonic = modal.harmonic_of_modes(tire.mesh.theta, held)
        return replace(reduced, basis=None, mode_harmonic=harmonic)

    inputs = {"tire": spec, **case.key(), "f_max": f_max}
    runs = (cavity, dynamics, modal.harmonic_of_modes, loading, statics)
    return cached(reduced_footprint, inputs, compute, runs=runs)


def loaded_modal(
    spec: LoadedSpec,
    case: LoadCase,
    frozen: str = "complex",
    damping: str = "identified",
    reference_frequency: float | None = None,
    f_band: float = 250.0,
) -> ModalReduction:
    """Cached :func:`.modal.loaded_modal_reduction` about :func:`loaded_state`, identified on
    :func:`loaded_frfs` (0-400 Hz) and returning its FRFs at those frequencies; a freezing, damping
    or band it does not have is refused before any stage runs. A tire whose file couples its air gets
    the air's modes among its loaded modes (:func:`.modal.loaded_modal_reduction`)."""
    check_options(frozen, damping, f_band)
    options = {"frozen": frozen, "damping": damping, "reference_frequency": reference_frequency, "f_band": f_band}
    visco = loaded_frfs(spec, case)
    membership = loaded_footprint(spec, case).tasselli.membership()
    f_top = max(float(modal.ANCHORS[-1]) * float(f_band), float(DEFAULT_FREQS[-1]))

    def compute() -> ModalReduction:
        return modal.loaded_modal_reduction(reduced_footprint(spec, case, f_top), membership, visco, **options)

    inputs = {"tire": with_its_air(spec), **case.key(), **options}
    return cached(loaded_modal, inputs, compute, runs=(modal, cavity, dynamics, loading, statics))


def _cleat_inputs(spec: LoadedSpec, case: LoadCase, height: float, base: float, shape: str, distance) -> dict:
    """A cleat passage's key: the tire (its air's settings where its file couples the air), the drum's case,
    the cleat (m) and the travel (m)."""
    return {
        "tire": with_its_air(spec), **case.key(),
        "height": float(height), "base": float(base), "shape": shape, "distance": tuple(float(d) for d in distance),
    }  # fmt: skip


def quasi_static_cleat(
    spec: LoadedSpec, case: LoadCase, height: float, base: float, shape: str, distance, step: float = 1.0e-3
) -> ContactRun:
    """Cached :func:`.one_sided.quasi_static_run` of a cleat (m) over the tire loaded on the case's drum
    (:func:`loaded_state`), solved every ``step`` m of travel, with the air where the file couples it."""
    inputs = {**_cleat_inputs(spec, case, height, base, shape, distance), "step": float(step)}
    state = loaded_state(spec, case)

    def compute() -> ContactRun:
        profile, tire = cleat_profile(height, base, shape), built_tire(spec)
        air = loaded_air(spec, tire, state)
        return one_sided.quasi_static_run(tire, state, profile, inputs["distance"], inputs["step"], air=air)

    runs = (one_sided, cavity, dynamics, loading, road_contact, statics)
    return cached(quasi_static_cleat, inputs, compute, runs=runs)


def dynamic_cleat_runs(
    spec: LoadedSpec, case: LoadCase, speed: float, height: float, base: float, shape: str, distance, dt=None
) -> tuple[ContactRun, ContactRun]:
    """Cached :func:`.one_sided.dynamic_runs` at ``speed`` (m/s) over the tire loaded on the case's drum:
    (one-sided contact, frozen contact), stepped together every ``dt`` s, with the air where the file
    couples it."""
    options = {"speed": float(speed), "dt": None if dt is None else float(dt)}
    inputs = {**_cleat_inputs(spec, case, height, base, shape, distance), **options}
    state = loaded_state(spec, case)

    def compute() -> tuple[ContactRun, ContactRun]:
        profile, tire = cleat_profile(height, base, shape), built_tire(spec)
        air = loaded_air(spec, tire, state)
        runs = one_sided.dynamic_runs(tire, state, profile, speed, inputs["distance"], dt, (False, True), air=air)
        return tuple(runs)

    runs = (one_sided, cavity, dynamics, loading, road_contact, statics)
    return cached(dynamic_cleat_runs, inputs, compute, runs=runs)
