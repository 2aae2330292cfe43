"""Test conditions (drum, cleat, speeds, vehicles) read from ``data/conditions/*.toml``."""

from __future__ import annotations

import tomllib
from typing import Any

from .paths import data_dir


def load_conditions(name: str) -> dict[str, Any]:
    """The TOML file ``data/conditions/<name>.toml`` as nested dicts (SI units)."""
    path = data_dir() / "conditions" / f"{name}.toml"
    if not path.exists():
        available = sorted(p.stem for p in path.parent.glob("*.toml"))
        raise FileNotFoundError(f"no conditions file {name!r}; available: {available}")
    with open(path, "rb") as fh:
        return tomllib.load(fh)
