"""Test conditions (drum, cleat, speeds, vehicles) read from ``data/conditions/*.toml``."""

from __future__ import annotations

from typing import Any

from .paths import data_file, read_toml


def load_conditions(name: str) -> dict[str, Any]:
    """The TOML file ``data/conditions/<name>.toml`` as nested dicts (SI units)."""
    return read_toml(data_file(name, "conditions", "conditions file"))


def with_defaults(name: str, section: str | None = None, **given: Any) -> dict[str, Any]:
    """``given`` values, those that are ``None`` taken from ``data/conditions/<name>.toml``.

    How a notebook's papermill parameters default to the paper's test: a parameter left at
    ``None`` takes the data file's value (from the table ``section``, if given).

    Raises
    ------
    KeyError
        A parameter is ``None`` and the file has no value for it.
    """
    table = load_conditions(name)
    if section is not None:
        table = table[section]
    missing = [key for key, value in given.items() if value is None and key not in table]
    if missing:
        raise KeyError(f"data/conditions/{name}.toml has no value for {missing}; known: {sorted(table)}")
    return {key: table[key] if value is None else value for key, value in given.items()}
