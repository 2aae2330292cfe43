"""The ring tire as a :class:`~roadnoise_utils.tire.model.TireModel`: its stages, cached.

Each method caches what it computes (:func:`roadnoise_utils.repro.cache.cached`), keyed by the
tire file's every value, the load case and the code it runs, under the name of the pipeline
stage it serves (``solve_static``, ``frf_visco``, ...).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ... import guards
from ...repro.cache import cached
from ...response import band_limit
from ...response.modal_reduction import ModalReduction
from ...road.cleat import cleat_profile, point_heights
from ...road.input import RoadInput
from .. import cavity as shared_cavity
from ..contact import ContactRun
from ..model import DEFAULT_FREQS, ContactSetup, FRFResult, LoadCase, TireModel, register
from . import cavity, fe_reference, frf, modal_reduction, modes, one_sided, static
from . import mechanics as ring_model
from .mechanics import FETModel
from .modes import LoadedModes
from .spec import TireSpec, from_dict
from .static import DEFLECTION_LIMIT, StaticState


@register
class RingModel(TireModel):
    """Coupled rings on a viscoelastic foundation (:mod:`roadnoise_utils.tire.ring.mechanics`), 8103 DOF by default."""

    kind = "ring"
    capabilities = frozenset(
        {
            "fe_mesh",
            "hub_transfer",
            "modal_reduction",
            "loaded_modes",
            "released_hub",
            "direct_response",
            "one_sided_cleat",
            "cavity",
            "cavity_shape",
            "rolling_cavity",
        }
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

    def degrees_of_freedom(self) -> str:
        return f"{self.build_fet().n_dof}"

    def equivalent_dof(self) -> int:
        return int(self.build_fet().n_dof)

    def rim_side_mass(self) -> float:
        """:attr:`~roadnoise_utils.tire.ring.mechanics.FETModel.hub_vertical_mass` (kg)."""
        return self.build_fet().hub_vertical_mass

    def frf_runs(self) -> tuple:
        return (frf.frf_visco, static.solve_static)

    def _inputs(self, case: LoadCase) -> dict:
        return {"tire": self.fingerprint(), **case.key()}

    def load(self, case: LoadCase) -> StaticState:
        """:func:`roadnoise_utils.tire.ring.static.solve_static` on ``case`` (cached as ``solve_static``)."""

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
        """:func:`roadnoise_utils.tire.ring.frf.frf_visco` (cached as ``frf_visco``; default
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
            runs=(frf.frf_visco, static.solve_static, cavity.ring_cavity_coupling),
            name="frf_visco",
        )

    def _cavity_coupling(self, fet: FETModel, state: StaticState) -> shared_cavity.CavityCoupling | None:
        """The air cavity of a tire file whose ``[cavity]`` is enabled (else None: the paper's model)."""
        air = self.spec.cavity
        if not air.enabled:
            return None
        cav = cavity.ring_tire_cavity(self.spec, air.temperature)
        return cavity.ring_cavity_coupling(fet, state, cav, n_modes=air.modes, damping_ratio=air.damping_ratio)

    def released_hub(
        self, case: LoadCase, freqs: np.ndarray, mass: float, stiffness: float, damping: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """:func:`roadnoise_utils.tire.ring.fe_reference.fe_moving_hub`: the FE tire with its hub DOF free."""
        return fe_reference.fe_moving_hub(self.build_fet(), self.load(case), freqs, mass, stiffness, damping)

    def air_cavity(self, temperature: float | None = None) -> shared_cavity.Cavity:
        """:func:`roadnoise_utils.tire.ring.cavity.ring_tire_cavity`: from the rim to the belt's inner surface."""
        return cavity.ring_tire_cavity(self.spec, temperature)

    def loaded_cavity_areas(
        self, loads: tuple[float, ...], temperature: float | None = None
    ) -> tuple[list[StaticState], np.ndarray]:
        """The cached loaded states and :func:`roadnoise_utils.tire.ring.cavity.loaded_area` of each (at the belt nodes)."""
        cav = self.air_cavity(temperature)
        states = [self.load(self.case("flat", load)) for load in loads]
        return states, np.array([cavity.loaded_area(cav, state) for state in states])

    def rolling_cavity_frfs(self, case: LoadCase, freqs: np.ndarray, flow_speed: float) -> FRFResult:
        """:func:`roadnoise_utils.tire.ring.frf.frf_visco` with the loaded cavity's coupling
        (:func:`~roadnoise_utils.tire.ring.cavity.ring_cavity_coupling`) streaming at ``flow_speed`` (m/s;
        :func:`~roadnoise_utils.tire.cavity.rolling_coupling`)."""
        air, state, fet = self.spec.cavity, self.load(case), self.build_fet()
        cav = self.air_cavity()
        coupling = cavity.ring_cavity_coupling(fet, state, cav, n_modes=air.modes, damping_ratio=air.damping_ratio)
        rolling = shared_cavity.rolling_coupling(coupling, cav, flow_speed)
        return frf.frf_visco(fet, state, np.asarray(freqs, dtype=float), progress=False, cavity=rolling)

    def loaded_modes(self, case: LoadCase, n_modes: int = 60, reference_frequency: float = 70.0) -> LoadedModes:
        """Cached :func:`roadnoise_utils.tire.ring.modes.loaded_modes` (without the cavity)."""
        self.spec.cavity.refuse_in("loaded_modes")
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
        """Cached :func:`roadnoise_utils.tire.ring.modal_reduction.modal_reduction` on the default direct sweep."""
        self.spec.cavity.refuse_in("modal_reduction")
        state = self.load(case)
        visco = self.fixed_hub_frfs(case, DEFAULT_FREQS)

        def compute() -> ModalReduction:
            return modal_reduction.modal_reduction(self.build_fet(), state, visco=visco, **options)

        return cached(
            RingModel.modal_reduction,
            {**self._inputs(case), **options},
            compute,
            runs=(modal_reduction.modal_reduction, frf.frf_visco, static.solve_static),
            name="modal_reduction",
        )

    def direct_cleat_response(self, case: LoadCase, cleat: dict[str, Any]) -> tuple[RoadInput, np.ndarray]:
        """Cached :func:`roadnoise_utils.tire.ring.fe_reference.fe_cleat_response` (``cleat``: speed,
        height, base, shape, distance, duration, band)."""
        self.spec.cavity.refuse_in("fe_cleat_response")
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

    def refined(self, n_elements: int) -> RingModel:
        """The tire with ``n_elements`` around the circumference, everything else unchanged (named so)."""
        if self.spec.mesh.n_elements == n_elements:
            return self
        name = f"{self.spec.name} ({n_elements} elements)"
        return RingModel(self.spec.replace(**{"mesh.n_elements": n_elements}, name=name))

    def one_sided_setup(self, conditions: Any) -> ContactSetup:
        """The tire refined to ``conditions.n_elements`` (its contact points then 3 mm apart on the
        165/65 R14), the quasi-static passage over the dynamic run's travel, the force as stepped
        (its massless tread springs do not ring); a cleat it cannot envelop is refused first."""
        refined = self.refined(conditions.n_elements)
        static = refined.load(refined.case("drum", drum_radius=conditions.cleat.drum_radius))
        check_cleat_height(static, conditions.cleat.height)
        return ContactSetup(refined, conditions.distance, conditions.quasi_static_step, None, None)

    def frozen_reference(
        self, case: LoadCase, run: ContactRun, cleat: tuple[float, float, str], duration: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """:func:`roadnoise_utils.tire.ring.fe_reference.fe_point_response` of the hat-averaged cleat
        heights under every contact node (the footprint sliding freely, as the frictionless contact)."""
        state = self.load(case)
        t = state.tasselli
        heights = point_heights(t.node_x, t.node_dx_minus, t.node_dx_plus, cleat_profile(*cleat), run.distance)
        reference = fe_reference.fe_point_response(
            self.build_fet(), state, heights, run.dt, duration=duration, stick=False
        )
        n_fft = max(run.t.size, int(round(duration / run.dt)))
        return band_limit.band_limited(run.hub_force, run.dt, n_fft=n_fft), reference

    def one_sided_run(self, case: LoadCase, cleat: dict[str, Any]) -> ContactRun:
        """Cached cleat passage with one-sided contact on the drum of ``case``: quasi-static for
        ``speed = 0``, else dynamic (``cleat``: speed, height, base, shape, distance, frozen, step, dt)."""
        self.spec.cavity.refuse_in("one_sided_run")
        state = self.load(case)

        def compute() -> ContactRun:
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


def check_cleat_height(static: StaticState, height: float) -> None:
    """Refuse a cleat the tire cannot envelop; warn when it is taller than the static deflection.

    Over the cleat the tire deflects by its static deflection plus the cleat height; past
    :data:`~roadnoise_utils.tire.ring.static.DEFLECTION_LIMIT` of the section height it would
    bottom on the rim, which the model does not know.
    """
    g = static.tire.geometry
    section = g.section_width * g.aspect_ratio
    room = DEFLECTION_LIMIT * section - static.deflection
    if height > room:
        raise ValueError(
            f"cleat height = {height * 1e3:.1f} mm: valid range is <= {room * 1e3:.1f} mm, what the tire can envelop "
            f"over its {static.deflection * 1e3:.1f} mm static deflection ({DEFLECTION_LIMIT:.0%} of the "
            f"{section * 1e3:.0f} mm section height in all)"
        )
    if height > static.deflection:
        guards.warn(
            f"cleat height = {height * 1e3:.1f} mm exceeds the static deflection ({static.deflection * 1e3:.1f} mm): "
            "the whole footprint lifts off the drum over the cleat",
            stacklevel=4,
        )
