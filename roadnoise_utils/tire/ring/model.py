"""The ring tire as a :class:`~roadnoise_utils.tire.model.TireModel`: its stages, cached.

Each method caches what it computes (:func:`roadnoise_utils.repro.cache.cached`), keyed by the
tire file's every value, the load case and the code it runs, under the name of the pipeline
stage it serves (``solve_static``, ``frf_visco``, ...).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ...repro.cache import cached
from ...response import fe_reference, frf, modes, one_sided
from ...response import modal_reduction as modal
from ...response.modal_reduction import ModalReduction
from ...response.modes import LoadedModes
from ...road.cleat import cleat_profile
from ...road.input import RoadInput
from .. import cavity as cavity_model
from .. import ring_model, static
from ..model import DEFAULT_FREQS, FRFResult, LoadCase, TireModel, register
from ..ring_model import FETModel
from ..spec import TireSpec, from_dict
from ..static import StaticState


@register
class RingModel(TireModel):
    """Coupled rings on a viscoelastic foundation (:mod:`roadnoise_utils.tire.ring_model`), 8103 DOF by default."""

    kind = "ring"
    capabilities = frozenset(
        {"hub_transfer", "modal_reduction", "loaded_modes", "direct_response", "one_sided_cleat", "cavity"}
    )

    @classmethod
    def parse(cls, data: dict[str, Any], source: str, path: Path | None = None) -> TireSpec:
        return from_dict(data, source=source)

    @property
    def default_load(self) -> float:
        return self.spec.operating.vertical_load

    def build_fet(self) -> FETModel:
        """The assembled FE tire (fast; not cached)."""
        return ring_model.build_fet(self.spec)

    def rim_side_mass(self) -> float:
        """:attr:`~roadnoise_utils.tire.ring_model.FETModel.hub_vertical_mass` (kg)."""
        return self.build_fet().hub_vertical_mass

    def frf_runs(self) -> tuple:
        return (frf.frf_visco, static.solve_static)

    def _inputs(self, case: LoadCase) -> dict:
        return {"tire": self.fingerprint(), **case.key()}

    def _no_cavity(self, stage: str) -> None:
        """Refuse a cavity-coupled tire in a stage whose FE numerics do not carry the cavity yet."""
        if self.cavity_enabled:
            raise ValueError(
                f"{stage}: the FE numerics of this stage do not include the air cavity yet; valid tires have "
                "[cavity] enabled = false (the cavity reaches the direct FRFs, the fits and the RM chain)"
            )

    def load(self, case: LoadCase) -> StaticState:
        """:func:`roadnoise_utils.tire.static.solve_static` on ``case`` (cached as ``solve_static``)."""

        def compute() -> StaticState:
            return static.solve_static(
                self.build_fet(), road=case.road.kind, load=case.load, drum_radius=case.drum_radius
            )

        return cached(
            RingModel.load,
            self._inputs(case),
            compute,
            runs=(static.solve_static, ring_model.build_fet),
            name="solve_static",
        )

    def fixed_hub_frfs(
        self, case: LoadCase, freqs: np.ndarray | None = None, progress: bool = False, stick: bool | None = None
    ) -> FRFResult:
        """:func:`roadnoise_utils.response.frf.frf_visco` (cached as ``frf_visco``; default
        :data:`~roadnoise_utils.tire.model.DEFAULT_FREQS`); ``stick``: the footprint held in all
        directions (default) or free to slide."""
        freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
        stick = True if stick is None else bool(stick)
        state = self.load(case)

        def compute() -> FRFResult:
            fet = self.build_fet()
            return frf.frf_visco(
                fet, state, freqs, progress=progress, stick=stick, cavity=self._cavity_coupling(fet, state)
            )

        return cached(
            RingModel.fixed_hub_frfs,
            {**self._inputs(case), "freqs": freqs, "stick": stick},
            compute,
            runs=(frf.frf_visco, static.solve_static, cavity_model.ring_cavity_coupling),
            name="frf_visco",
        )

    def _cavity_coupling(self, fet: FETModel, state: StaticState) -> cavity_model.CavityCoupling | None:
        """The air cavity of a tire file whose ``[cavity]`` is enabled (else None: the paper's model)."""
        air = self.spec.cavity
        if not air.enabled:
            return None
        cav = cavity_model.ring_tire_cavity(self.spec, air.temperature)
        return cavity_model.ring_cavity_coupling(fet, state, cav, n_modes=air.modes, damping_ratio=air.damping_ratio)

    def loaded_modes(self, case: LoadCase, n_modes: int = 60, reference_frequency: float = 70.0) -> LoadedModes:
        """Cached :func:`roadnoise_utils.response.modes.loaded_modes` (without the cavity)."""
        self._no_cavity("loaded_modes")
        options = {"n_modes": int(n_modes), "reference_frequency": float(reference_frequency)}
        state = self.load(case)

        def compute() -> LoadedModes:
            return modes.loaded_modes(self.build_fet(), state, **options)

        return cached(
            RingModel.loaded_modes,
            {**self._inputs(case), **options},
            compute,
            runs=(modes.loaded_modes, static.solve_static),
            name="loaded_modes",
        )

    def modal_reduction(self, case: LoadCase, **options: Any) -> ModalReduction:
        """Cached :func:`roadnoise_utils.response.modal_reduction.modal_reduction` on the default direct sweep."""
        self._no_cavity("modal_reduction")
        state = self.load(case)
        visco = self.fixed_hub_frfs(case, DEFAULT_FREQS)

        def compute() -> ModalReduction:
            return modal.modal_reduction(self.build_fet(), state, visco=visco, **options)

        return cached(
            RingModel.modal_reduction,
            {**self._inputs(case), **options},
            compute,
            runs=(modal.modal_reduction, frf.frf_visco, static.solve_static),
            name="modal_reduction",
        )

    def direct_cleat_response(self, case: LoadCase, cleat: dict[str, Any]) -> tuple[RoadInput, np.ndarray]:
        """Cached :func:`roadnoise_utils.response.fe_reference.fe_cleat_response` (``cleat``: speed,
        height, base, shape, distance, duration, band)."""
        self._no_cavity("fe_cleat_response")
        state = self.load(case)

        def compute() -> tuple[RoadInput, np.ndarray]:
            return fe_reference.fe_cleat_response(self.build_fet(), state, **cleat)

        return cached(
            RingModel.direct_cleat_response,
            {**self._inputs(case), **cleat},
            compute,
            runs=(fe_reference.fe_cleat_response, static.solve_static),
            name="fe_cleat_response",
        )

    def one_sided_run(self, case: LoadCase, cleat: dict[str, Any]) -> one_sided.ContactRun:
        """Cached cleat passage with one-sided contact on the drum of ``case``: quasi-static for
        ``speed = 0``, else dynamic (``cleat``: speed, height, base, shape, distance, frozen, step, dt)."""
        self._no_cavity("one_sided_run")
        state = self.load(case)

        def compute() -> one_sided.ContactRun:
            fet = self.build_fet()
            profile = cleat_profile(cleat["height"], cleat["base"], cleat["shape"])
            if cleat["speed"] == 0:
                return one_sided.quasi_static_run(fet, state, profile, cleat["distance"], cleat["step"])
            return one_sided.dynamic_run(
                fet, state, profile, cleat["speed"], cleat["distance"], dt=cleat["dt"], frozen=cleat["frozen"]
            )

        runs = (one_sided.quasi_static_run, one_sided.dynamic_run, static.solve_static)
        return cached(
            RingModel.one_sided_run, {**self._inputs(case), **cleat}, compute, runs=runs, name="one_sided_run"
        )
