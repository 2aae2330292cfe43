"""Cached stages of the loaded FE tire (``[tire] model = "loaded-fe"``).

========================  =========================================================================
stage                     caches
========================  =========================================================================
:func:`inflated_state`    mount and inflation (:func:`.statics.inflate`), shared by the load cases
:func:`loaded_state`      the nonlinear loading to the case's load on its road
                          (:func:`.loading.load_on_road`)
:func:`loaded_footprint`  the state as every model's footprint (:func:`.footprint.loaded_footprint`)
:func:`loaded_frfs`       the dynamics linearised about it, reduced and swept
                          (:func:`.dynamics.footprint_frf`), on the footprint's tasselli
========================  =========================================================================

:func:`built_tire` (the swept mesh and its integration points: about a second) is not cached.
"""

from __future__ import annotations

import numpy as np

from ...repro.cache import cached
from ..model import DEFAULT_FREQS, Footprint, FRFResult, LoadCase
from . import dynamics, footprint, loading, road_contact, statics
from .mesh import graded_arcs
from .spec import LoadedSpec
from .statics import LoadedTire, StaticState


def built_tire(spec: LoadedSpec) -> LoadedTire:
    """The construction swept through the solid mesh's graded arcs (not cached)."""
    m = spec.solid_mesh
    radius = spec.construction.geometry.outer_radius
    arcs = graded_arcs(radius, m.footprint_arc, m.sector_half_angle, m.coarse_arc, m.arc_growth)
    return statics.build_loaded_tire(spec.construction, arcs)


def inflated_state(spec: LoadedSpec) -> StaticState:
    """Cached: the tire mounted and inflated to its file's pressure (:func:`.statics.inflate`), shared by
    every load case of the file (7 s on the production mesh)."""
    return cached(inflated_state, {"tire": spec}, lambda: statics.inflate(built_tire(spec)), runs=(statics,))


def loaded_state(spec: LoadedSpec, case: LoadCase) -> StaticState:
    """Cached: :func:`inflated_state` loaded on the case's road (flat or drum) to ``case.load`` (N)."""
    inputs = {"tire": spec, **case.key()}

    def compute() -> StaticState:
        tire = built_tire(spec)
        return loading.load_on_road(tire, inflated_state(spec), case.load, spec.solid_mesh.road_step, case.road)

    return cached(loaded_state, inputs, compute, runs=(loading, road_contact, statics))


def loaded_footprint(spec: LoadedSpec, case: LoadCase) -> Footprint:
    """Cached :func:`.footprint.loaded_footprint` of :func:`loaded_state` (the tangent K_v's solve included)."""
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
    and swept, on the tasselli of :func:`loaded_footprint`."""
    freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
    if not np.array_equal(freqs, DEFAULT_FREQS) and np.all(np.isin(freqs, DEFAULT_FREQS)):
        full = loaded_frfs(spec, case)
        return full.take(np.searchsorted(full.freqs, freqs))
    state = loaded_state(spec, case)
    tasselli = loaded_footprint(spec, case).tasselli

    def compute() -> FRFResult:
        linearised = dynamics.linearise(built_tire(spec), state)
        frf = dynamics.footprint_frf(linearised, freqs)
        return footprint.frf_result(frf, tasselli)

    inputs = {"tire": spec, **case.key(), "freqs": freqs}
    return cached(loaded_frfs, inputs, compute, runs=(dynamics, footprint, loading, road_contact, statics))
