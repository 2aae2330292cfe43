"""Fixtures of the FMU tests: the paper's 165/65 R14 exported once per test module (2-D and 3-D road inputs)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fmu.tables import TireTables

#: The paper's cleat speed (m/s): 30 km/h.
SPEED = 30 / 3.6


@dataclass(frozen=True)
class ExportedTire:
    path: Path
    tables: TireTables
    static: ru.Footprint
    fits: ru.FitSet
    hub: ru.FitSet


def export(folder: Path, lateral: bool) -> ExportedTire:
    tire = "165_65R14"
    path = ru.export_fmu(tire, folder / f"tire_{'3d' if lateral else '2d'}.fmu", SPEED, lateral=lateral)
    tables = ru.experiments.fmu_export.fmu_tables(tire, SPEED, lateral=lateral)
    return ExportedTire(
        path, tables, ru.stages.solve_static(tire), ru.stages.fit_tasselli(tire), ru.stages.fit_hub(tire)
    )


@pytest.fixture(scope="module")
def tire_2d(tmp_path_factory) -> ExportedTire:
    """One FMU for a road uniform across the width (one road input), compiled once per module."""
    return export(tmp_path_factory.mktemp("fmu"), lateral=False)


@pytest.fixture(scope="module")
def tire_3d(tmp_path_factory) -> ExportedTire:
    """One FMU with a road input per lateral strip, compiled once per module."""
    return export(tmp_path_factory.mktemp("fmu"), lateral=True)


def knots(tables: TireTables, n: int, start: float = -0.1) -> np.ndarray:
    """Road coordinates of the FMU's leading-edge samples when the travel starts at ``start`` (m)."""
    return tables.leading_edge + start + tables.speed * tables.dt * np.arange(n)
