"""The tire from files as a :class:`~roadnoise_utils.tire.model.TireModel`: measured data beside the models.

Like python-control's ``FrequencyResponseData`` beside ``StateSpace``, it answers what its data
can answer — the loaded footprint and the fixed-hub FRFs of each load case its files give, and
``G_H`` where they carry it — and nothing else: the modal reduction, an FE reference of a road
input, contact loss and the air cavity need an FE model and are "not applicable". Its files are
read and validated once, with the tire file (:mod:`roadnoise_utils.tire.ring.spec`), and travel in the spec, so the stage
cache keys on their contents.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ...response import uff
from .. import footprint_file
from ..model import Footprint, FRFResult, LoadCase, TireModel, register
from . import spec as spec_module
from .spec import FileCase, FRFFileSpec, from_dict

#: How close a requested frequency must be to one of the file's (Hz).
FREQUENCY_MATCH = 1e-9


@register
class FRFFileModel(TireModel):
    """A tire given by its footprint FRFs and footprint geometry, per load case (:mod:`roadnoise_utils.tire.ring.spec`)."""

    kind = "frf-file"
    capabilities = frozenset({"hub_transfer"})  # only where every file carries G_H (:meth:`has`)

    @classmethod
    def parse(cls, data: dict[str, Any], source: str, path: Path | None = None) -> FRFFileSpec:
        return from_dict(data, source=source, folder=None if path is None else Path(path).parent)

    @property
    def default_load(self) -> float:
        return self.spec.vertical_load

    def has(self, capability: str) -> bool:
        return super().has(capability) and (capability != "hub_transfer" or self.spec.has_hub_transfer)

    def rim_side_mass(self) -> float:
        """The tire file's ``[hub] rim_side_mass`` (kg)."""
        return self.spec.rim_side_mass

    def frf_runs(self) -> tuple:
        return (spec_module, uff.read_uff58, footprint_file.read_footprint_csv)

    def file_case(self, case: LoadCase) -> FileCase:
        """The load case of the files that is ``case``; refused, listing them, when none is."""
        for c in self.spec.cases:
            same_road = c.road == case.road.kind and (
                c.road == "flat" or np.isclose(c.drum_radius, case.road.drum_radius, rtol=1e-9)
            )
            if same_road and np.isclose(c.load, case.load, rtol=1e-9, atol=0.0):
                return c
        given = "; ".join(c.describe() for c in self.spec.cases)
        raise ValueError(f"{self.name}: its files give no load case {case.describe()}; they give {given}")

    def load(self, case: LoadCase) -> Footprint:
        """The footprint of the files' load case (its tasselli, pressures and K_v)."""
        c = self.file_case(case)
        return Footprint(
            road=case.road,
            load=c.load,
            deflection=c.deflection,
            hub_force=c.load,
            vertical_stiffness=c.vertical_stiffness,
            tasselli=c.tasselli,
            node_pressure=c.node_pressure,
        )

    def fixed_hub_frfs(
        self, case: LoadCase, freqs: np.ndarray | None = None, progress: bool = False, stick: bool | None = None
    ) -> FRFResult:
        """The FRFs of the files' load case: all its frequencies (``freqs=None``) or those of ``freqs``
        (Hz), each of which must be one of the file's (nothing is interpolated). ``stick`` must be
        ``None``: the footprint is held as the FE code held it."""
        if stick is not None:
            raise ValueError(f"stick = {stick!r}: a tire from files gives its FRFs as computed; valid value is None")
        frfs = self.file_case(case).frfs
        if freqs is None:
            return frfs
        freqs = np.asarray(freqs, float)
        pick = np.searchsorted(frfs.freqs, freqs - FREQUENCY_MATCH)
        pick = np.minimum(pick, frfs.freqs.size - 1)
        off = np.abs(frfs.freqs[pick] - freqs) > FREQUENCY_MATCH
        if np.any(off):
            raise ValueError(
                f"freqs: {freqs[off][:5].tolist()} Hz are not frequencies of the file's FRFs "
                f"({frfs.freqs[0]:g}-{frfs.freqs[-1]:g} Hz, {frfs.freqs.size} frequencies); nothing is interpolated"
            )
        return frfs.take(pick)
