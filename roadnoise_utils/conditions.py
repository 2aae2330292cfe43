"""Test conditions (drum, cleat, speeds, vehicles) read from ``data/conditions/*.toml``."""

from __future__ import annotations

from typing import Any

from .paths import data_file, read_toml


def load_conditions(name: str) -> dict[str, Any]:
    """The TOML file ``data/conditions/<name>.toml`` as nested dicts (SI units)."""
    return read_toml(data_file(name, "conditions", "conditions file"))
