"""The loaded FE tire as a :class:`~roadnoise_utils.tire.model.TireModel`.

The paper's own kind of FE tire: the construction swept into 3-D solids, mounted, inflated and
pressed on the road by large-deformation statics, its dynamics linearised about that loaded
state. Its stages are cached by :mod:`roadnoise_utils.tire.loaded.stages`; this class answers the pipeline's calls with them.
It stands on the flat road or a drum (frictionless one-sided contact); its air cavity's section
round the loaded wheel is computed from the loaded solids (:mod:`roadnoise_utils.tire.loaded.cavity`, the capability
``cavity_shape``), and with ``[cavity] enabled`` in its construction's file the air of that loaded
cavity is coupled into its FRFs (``cavity``); its modal reduction refuses the air. The one-sided cleat
is not part of it (:meth:`~roadnoise_utils.tire.model.TireModel.require` says so).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ...response.modal_reduction import ModalReduction
from ..cavity import Cavity
from ..model import Footprint, FRFResult, LoadCase, TireModel, register
from . import cavity, dynamics, loading, road_contact, stages, statics
from .spec import LoadedSpec, from_dict


@register
class LoadedFEModel(TireModel):
    """The 3-D FE tire linearised about its nonlinear loaded state (:mod:`roadnoise_utils.tire.loaded`)."""

    kind = "loaded-fe"
    capabilities = frozenset({"fe_mesh", "hub_transfer", "modal_reduction", "cavity", "cavity_shape"})

    @classmethod
    def parse(cls, data: dict[str, Any], source: str, path: Path | None = None) -> LoadedSpec:
        return from_dict(data, source=source, folder=None if path is None else Path(path).parent)

    @property
    def default_load(self) -> float:
        return self.spec.vertical_load

    def degrees_of_freedom(self) -> str:
        return f"{stages.built_tire(self.spec).n_dof} (3-D solids)"

    def equivalent_dof(self) -> int:
        """Its solid mesh's degrees of freedom, rim included."""
        return int(stages.built_tire(self.spec).n_dof)

    def rim_side_mass(self) -> float:
        """0 kg: its :math:`G_H` holds the inertia of the rim's nodes (the beads)."""
        return 0.0

    def frf_runs(self) -> tuple:
        return (dynamics, loading, road_contact, statics)

    def load(self, case: LoadCase) -> Footprint:
        """:func:`roadnoise_utils.tire.loaded.stages.loaded_footprint` (cached): the loaded state on the case's road."""
        return stages.loaded_footprint(self.spec, case)

    def load_curve(self, loads: Sequence[float]) -> list[Footprint]:
        """:func:`roadnoise_utils.tire.loaded.stages.load_curve` (cached): one loading through ``loads`` (N, increasing)."""
        return stages.load_curve(self.spec, tuple(loads))

    def fixed_hub_frfs(
        self, case: LoadCase, freqs: np.ndarray | None = None, progress: bool = False, stick: bool | None = None
    ) -> FRFResult:
        """:func:`roadnoise_utils.tire.loaded.stages.loaded_frfs` (cached; default 0-400 Hz every 1 Hz; with the air
        cavity if its file enables it). Its contact nodes are held vertically and slide freely along
        the road, so ``stick`` must be ``None`` or ``False``."""
        if stick:
            raise ValueError(
                "stick = True: the loaded FE tire's contact nodes slide freely (frictionless, held vertically "
                "only); valid values are None or False"
            )
        return stages.loaded_frfs(self.spec, case, freqs)

    def modal_reduction(self, case: LoadCase, **options: Any) -> ModalReduction:
        """:func:`roadnoise_utils.tire.loaded.stages.loaded_modal` (cached): the loaded modes of its reduced
        dynamics, the boundary (contact nodes, rim) held; refused with its air coupled."""
        return stages.loaded_modal(self.spec, case, **options)

    @property
    def cavity_enabled(self) -> bool:
        """Whether its construction's file couples the air cavity (``[cavity] enabled``)."""
        return bool(self.spec.construction.cavity.enabled)

    def air_cavity(self, temperature: float | None = None) -> Cavity:
        """:func:`roadnoise_utils.tire.loaded.cavity.air_cavity`: the construction's cavity, unloaded."""
        return cavity.air_cavity(self.spec.construction, temperature)

    def loaded_cavity_areas(
        self, loads: tuple[float, ...], temperature: float | None = None
    ) -> tuple[list[Footprint], np.ndarray]:
        """:func:`roadnoise_utils.tire.loaded.stages.cavity_areas`: one loading through ``loads`` (N, increasing;
        cached) and the cavity's Webster area round the wheel in each state."""
        return stages.cavity_areas(self.spec, tuple(loads), temperature)
