"""The loaded FE tire as a :class:`~roadnoise_utils.tire.model.TireModel`.

The paper's own kind of FE tire: the construction swept into 3-D solids, mounted, inflated and
pressed on the road by large-deformation statics, its dynamics linearised about that loaded
state. Its stages are cached by :mod:`roadnoise_utils.tire.loaded.stages`; this class answers the pipeline's calls with them.
It stands on the flat road or a drum (frictionless one-sided contact); its air cavity's section
round the loaded wheel is computed from the loaded solids (:mod:`roadnoise_utils.tire.loaded.cavity`, the capability
``cavity_shape``), and with ``[cavity] enabled`` in its construction's file the air of that loaded
cavity is coupled into its FRFs (``cavity``), its modal reduction (the air's modes among the loaded
modes) and its cleat test with one-sided contact about its loaded state on the drum
(``one_sided_cleat``, :mod:`roadnoise_utils.tire.loaded.one_sided`: the air's modes stepped as
coordinates of their own, :func:`roadnoise_utils.tire.cavity.air_coordinates`).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ...response import band_limit
from ...response.modal_reduction import ModalReduction
from ...road.cleat import cleat_profile
from ..cavity import Cavity
from ..contact import ContactRun
from ..cross_section.model import CONTACT_BAND, QUASI_STATIC_STEP
from ..model import ContactSetup, Footprint, FRFResult, LoadCase, TireModel, register
from . import cavity, dynamics, loading, one_sided, road_contact, stages, statics
from .spec import LoadedSpec, from_dict

#: Time step of the one-sided dynamic runs (s): a whole number of samples per second, so that a 1 s record
#: falls on the 1 Hz grid of the footprint FRFs (the frozen check). Half the cross-section tire's: its
#: tread nodes carry the contact directly, and on the test mesh the frozen check's RMS difference from
#: the FRFs is 3.0 % at 1/6000 s and 0.61 % at 1/12 000 s (0.33 % with no numerical damping: the rest is
#: the step's own error, second order).
CONTACT_DT = 1.0 / 12000.0
#: With the air cavity coupled, half of :data:`CONTACT_DT`: the air's resonance near 245 Hz is damped
#: by 1 % alone, so the step's period error there (0.14 % at 1/12 000 s) is a seventh of its
#: half-power width; on the test mesh the frozen check's RMS difference is 2.0 % at 1/12 000 s and
#: 0.27 % at 1/24 000 s (7.3 times less, more than the scheme's second order alone gives).
CONTACT_DT_WITH_AIR = CONTACT_DT / 2.0


@register
class LoadedFEModel(TireModel):
    """The 3-D FE tire linearised about its nonlinear loaded state (:mod:`roadnoise_utils.tire.loaded`)."""

    kind = "loaded-fe"
    capabilities = frozenset(
        {"fe_mesh", "hub_transfer", "modal_reduction", "one_sided_cleat", "cavity", "cavity_shape"}
    )

    @property
    def contact_dt(self) -> float:  # type: ignore[override]
        """Time step of the one-sided dynamic runs (s): :data:`CONTACT_DT`, or :data:`CONTACT_DT_WITH_AIR`
        where the file couples the air cavity."""
        return CONTACT_DT_WITH_AIR if self.cavity_enabled else CONTACT_DT

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
        dynamics, the boundary (contact nodes, rim) held, its air's modes among them where its file couples it."""
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

    def one_sided_setup(self, conditions: Any) -> ContactSetup:
        """The tire file's own mesh; the quasi-static passage over the sweep's travel every 1 mm; the dynamic
        runs every :attr:`contact_dt` s, compared band-limited to the paper's 250 Hz (as the cross-section tire)."""
        return ContactSetup(self, conditions.sweep_distance, QUASI_STATIC_STEP, self.contact_dt, CONTACT_BAND)

    def one_sided_run(self, case: LoadCase, cleat: dict[str, Any]) -> ContactRun:
        """Cached cleat passage with one-sided contact about the loaded state on the drum of ``case``:
        quasi-static for ``speed = 0`` (:func:`.stages.quasi_static_cleat`), else dynamic
        (:func:`.stages.dynamic_cleat_runs`, ``cleat["frozen"]`` picking the frozen run)."""
        if case.road.kind != "drum":
            raise ValueError(f"one-sided cleat runs: the tire loaded on a drum; got {case.describe()}")
        shape = (cleat["height"], cleat["base"], cleat["shape"], cleat["distance"])
        if cleat["speed"] == 0:
            return stages.quasi_static_cleat(self.spec, case, *shape, step=cleat["step"])
        runs = stages.dynamic_cleat_runs(self.spec, case, cleat["speed"], *shape, dt=cleat["dt"])
        return runs[int(bool(cleat["frozen"]))]

    def frozen_reference(
        self, case: LoadCase, run: ContactRun, cleat: tuple[float, float, str], duration: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """:func:`~roadnoise_utils.response.band_limit.frequency_domain_response` of the footprint FRFs
        (:func:`.stages.loaded_frfs`, per contact node, 1 Hz grid) to the vertical road motion that raises
        the drum under each contact node by the cleat's hat-averaged height along the node's normal
        (:func:`.one_sided.footprint_road_motion`); both hub forces band-limited to 250 Hz the same way."""
        frfs = stages.loaded_frfs(self.spec, case)
        motion = one_sided.footprint_road_motion(
            stages.built_tire(self.spec), stages.loaded_state(self.spec, case), cleat_profile(*cleat), run.distance
        )

        def at(freqs: np.ndarray) -> np.ndarray:
            index = np.searchsorted(frfs.freqs, freqs)
            if np.any(index >= frfs.freqs.size) or not np.allclose(frfs.freqs[index], freqs):
                raise ValueError(
                    "the record's frequencies miss the FRFs' 1 Hz grid: a whole number of samples per second"
                )
            return frfs.H_points[:, index]

        reference = band_limit.frequency_domain_response(at, motion, run.dt, CONTACT_BAND, duration)
        n_fft = max(run.t.size, int(round(duration / run.dt)))
        return band_limit.band_limited(run.hub_force, run.dt, CONTACT_BAND, n_fft=n_fft), reference
