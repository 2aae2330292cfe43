"""The cross-section tire as a :class:`~roadnoise_utils.tire.model.TireModel`.

Its stages are cached by :mod:`.stages` (the harmonic reductions shared by the flat road's and
the drum's footprints, the time-stepped harmonics of contact loss); this class answers the
pipeline's calls with them.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ...response import fe_reference
from ...response import section_footprint as footprint
from ...response.modal_reduction import ModalReduction
from ...response.one_sided import ContactRun
from ...road.cleat import cleat_input
from ...road.input import RoadInput
from .. import section_static as static_module
from ..model import FRFResult, LoadCase, TireModel, register
from ..section_static import SectionStaticState
from . import stages
from .spec import CrossSectionSpec, from_dict


@register
class CrossSectionModel(TireModel):
    """The layered waveguide tire built from its construction (:mod:`roadnoise_utils.tire.section_model`)."""

    kind = "cross-section"
    capabilities = frozenset({"hub_transfer", "modal_reduction", "direct_response", "one_sided_cleat", "cavity"})

    @classmethod
    def parse(cls, data: dict[str, Any], source: str, path: Path | None = None) -> CrossSectionSpec:
        return from_dict(data, source=source)

    @property
    def default_load(self) -> float:
        return self.spec.operating.vertical_load

    def rim_side_mass(self) -> float:
        """0 kg: its :math:`G_H` holds the inertia of the clamped bead nodes (0.06 kg on the 165/65 R14)."""
        return 0.0

    def frf_runs(self) -> tuple:
        return (footprint.footprint_frf, static_module.solve_section_static)

    def load(self, case: LoadCase) -> SectionStaticState:
        """:func:`.stages.section_static` (cached)."""
        return stages.section_static(self.spec, case.road.kind, case.load, case.drum_radius)

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
        return stages.section_footprint(
            self.spec, case.road.kind, freqs, case.load, case.drum_radius, progress
        ).to_frf_result()

    def modal_reduction(self, case: LoadCase, **options: Any) -> ModalReduction:
        """:func:`.stages.section_modal` (cached): loaded modes by component-mode synthesis of its harmonics."""
        return stages.section_modal(self.spec, case.road.kind, load=case.load, drum_radius=case.drum_radius, **options)

    def direct_cleat_response(self, case: LoadCase, cleat: dict[str, Any]) -> tuple[RoadInput, np.ndarray]:
        """The frequency-domain sum (:func:`~roadnoise_utils.response.fe_reference.frequency_domain_response`)
        of a cleat over the direct tassello FRFs (``cleat``: speed, height, base, shape, distance, duration, band)."""
        state = self.load(case)
        road = cleat_input(state, cleat["speed"], cleat["height"], cleat["base"], cleat["shape"], cleat["distance"])
        frfs = stages.tassello_frfs(self.spec, case.road.kind, case.load, case.drum_radius)
        return road, fe_reference.frequency_domain_response(frfs, road.u, road.dt, cleat["band"], cleat["duration"])

    def one_sided_run(self, case: LoadCase, cleat: dict[str, Any]) -> ContactRun:
        """Cached cleat passage with one-sided contact on the drum of ``case``: quasi-static for
        ``speed = 0`` (:func:`.stages.quasi_static_cleat`), else dynamic (:func:`.stages.dynamic_cleat`)."""
        if case.road.kind != "drum" or case.load != self.default_load:
            raise ValueError(f"one-sided cleat runs: the tire file's load on a drum; got {case.describe()}")
        shape = (cleat["height"], cleat["base"], cleat["shape"], case.drum_radius, cleat["distance"])
        if cleat["speed"] == 0:
            return stages.quasi_static_cleat(self.spec, *shape, step=cleat["step"])
        return stages.dynamic_cleat(self.spec, cleat["speed"], *shape, frozen=cleat["frozen"], dt=cleat["dt"])
