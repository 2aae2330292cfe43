"""The cross-section tire as a :class:`~roadnoise_utils.tire.model.TireModel`.

Its stages are cached by :mod:`~roadnoise_utils.tire.cross_section.stages` (the harmonic reductions shared by the flat road's and
the drum's footprints, the time-stepped harmonics of contact loss); this class answers the
pipeline's calls with them.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ...response import band_limit as fe_reference
from ...response.modal_reduction import ModalReduction
from ...road.cleat import cleat_input, cleat_profile, point_heights
from ...road.input import RoadInput
from ..cavity import Cavity
from ..contact import ContactRun
from ..model import ContactSetup, FRFResult, LoadCase, TireModel, register
from . import cavity as section_cavity
from . import footprint, stages
from . import static as static_module
from .spec import CrossSectionSpec, from_dict
from .static import SectionStaticState

#: Time step of the one-sided dynamic runs (s): a whole number of samples per second, so that a 1 s
#: record falls on the 1 Hz grid of the footprint FRFs (the frozen check); 1.39 mm of travel at 30 km/h,
#: 24 samples per period at the band's 250 Hz (halving it changes the band-limited peak by 0.2 %, test).
CONTACT_DT = 1.0 / 6000.0
#: Band of the compared one-sided hub force (Hz): the paper's. The contact sits on the tread's FE
#: nodes, so the cleat's impact also rings the tread at kHz in the raw hub force (raw peak 1751 N
#: against 1681 N in band on the 165/65 R14); the paper's model and its measurement are 0-250 Hz.
CONTACT_BAND = 250.0
#: Travel between the quasi-static contact solves (m).
QUASI_STATIC_STEP = 1.0e-3


@register
class CrossSectionModel(TireModel):
    """The layered waveguide tire built from its construction (:mod:`roadnoise_utils.tire.cross_section.operators`)."""

    kind = "cross-section"
    capabilities = frozenset(
        {"fe_mesh", "hub_transfer", "modal_reduction", "direct_response", "one_sided_cleat", "cavity", "cavity_shape"}
    )
    contact_dt = CONTACT_DT

    @classmethod
    def parse(cls, data: dict[str, Any], source: str, path: Path | None = None) -> CrossSectionSpec:
        return from_dict(data, source=source)

    @property
    def default_load(self) -> float:
        return self.spec.operating.vertical_load

    def degrees_of_freedom(self) -> str:
        return f"{stages.section_tire(self.spec).mesh.n_dof} x {self.spec.mesh.harmonics + 1} harmonics"

    def equivalent_dof(self) -> int:
        """Its free cross-section DOF at 2N + 1 stations round the wheel (N harmonics)."""
        tire = stages.section_tire(self.spec)
        return int(tire.ops.free.size * (2 * tire.harmonics + 1))

    def rim_side_mass(self) -> float:
        """0 kg: its :math:`G_H` holds the inertia of the clamped bead nodes (0.06 kg on the 165/65 R14)."""
        return 0.0

    def frf_runs(self) -> tuple:
        return (footprint.footprint_frf, static_module.solve_section_static)

    def load(self, case: LoadCase) -> SectionStaticState:
        """:func:`.stages.section_static` (cached)."""
        return stages.section_static(self.spec, case)

    def fixed_hub_frfs(
        self, case: LoadCase, freqs: np.ndarray | None = None, progress: bool = False, stick: bool | None = None
    ) -> FRFResult:
        """:func:`.stages.section_footprint` (cached; default 0-400 Hz every 1 Hz) as an :class:`FRFResult`;
        its contact is frictionless, so ``stick`` must be ``None`` or ``False``."""
        if stick:
            raise ValueError(
                "stick = True: the cross-section tire's contact points slide freely (frictionless, vertical "
                "only); valid values are None or False"
            )
        return stages.section_footprint(self.spec, case, freqs, progress).to_frf_result()

    def air_cavity(self, temperature: float | None = None) -> Cavity:
        """:func:`roadnoise_utils.tire.cross_section.cavity.section_cavity`: the inner surface from bead to bead, closed by the rim."""
        return section_cavity.section_cavity(stages.section_tire(self.spec), temperature).cavity

    def loaded_cavity_areas(
        self, loads: tuple[float, ...], temperature: float | None = None
    ) -> tuple[list[SectionStaticState], np.ndarray]:
        """:func:`.stages.cavity_areas` (cached): the loaded states and the inner surface's Webster area of each."""
        return stages.cavity_areas(self.spec, tuple(loads))

    def modal_reduction(self, case: LoadCase, **options: Any) -> ModalReduction:
        """:func:`.stages.section_modal` (cached): loaded modes by component-mode synthesis of its harmonics."""
        return stages.section_modal(self.spec, case, **options)

    def direct_cleat_response(self, case: LoadCase, cleat: dict[str, Any]) -> tuple[RoadInput, np.ndarray]:
        """The frequency-domain sum (:func:`~roadnoise_utils.response.band_limit.frequency_domain_response`)
        of a cleat over the direct tassello FRFs (``cleat``: speed, height, base, shape, distance, duration, band)."""
        state = self.load(case)
        road = cleat_input(state, cleat["speed"], cleat["height"], cleat["base"], cleat["shape"], cleat["distance"])
        frfs = stages.tassello_frfs(self.spec, case)
        return road, fe_reference.frequency_domain_response(frfs, road.u, road.dt, cleat["band"], cleat["duration"])

    def one_sided_setup(self, conditions: Any) -> ContactSetup:
        """The tire file's own grid; the quasi-static passage over the sweep's travel every 1 mm; the
        dynamic runs every :data:`CONTACT_DT` s, compared band-limited to :data:`CONTACT_BAND` Hz."""
        return ContactSetup(self, conditions.sweep_distance, QUASI_STATIC_STEP, self.contact_dt, CONTACT_BAND)

    def frozen_reference(
        self, case: LoadCase, run: ContactRun, cleat: tuple[float, float, str], duration: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """:func:`~roadnoise_utils.response.band_limit.frequency_domain_response` of the footprint FRFs
        (:func:`.stages.section_footprint`, 1 Hz grid) to the hat-averaged cleat heights under every
        static contact point; both hub forces band-limited to :data:`CONTACT_BAND` Hz the same way."""
        state, footprint_frfs = self.load(case), stages.section_footprint(self.spec, case)
        grid = state.grid
        x, _ = grid.xz()
        col, row = state.points
        arc = grid.radius[col] * grid.dtheta
        heights = point_heights(x[col, row], arc, arc, cleat_profile(*cleat), run.distance)
        reference = fe_reference.frequency_domain_response(
            lambda f: footprint_frfs.at(f).hub.T, heights, run.dt, CONTACT_BAND, duration
        )
        n_fft = max(run.t.size, int(round(duration / run.dt)))
        return fe_reference.band_limited(run.hub_force, run.dt, CONTACT_BAND, n_fft=n_fft), reference

    def one_sided_run(self, case: LoadCase, cleat: dict[str, Any]) -> ContactRun:
        """Cached cleat passage with one-sided contact on the drum of ``case``: quasi-static for
        ``speed = 0`` (:func:`.stages.quasi_static_cleat`), else dynamic (:func:`.stages.dynamic_cleat`)."""
        if case.road.kind != "drum" or case.load != self.default_load:
            raise ValueError(f"one-sided cleat runs: the tire file's load on a drum; got {case.describe()}")
        shape = (cleat["height"], cleat["base"], cleat["shape"], case.drum_radius, cleat["distance"])
        if cleat["speed"] == 0:
            return stages.quasi_static_cleat(self.spec, *shape, step=cleat["step"])
        return stages.dynamic_cleat(self.spec, cleat["speed"], *shape, frozen=cleat["frozen"], dt=cleat["dt"])
