"""Test conditions (drum, cleat, speeds, suspension, road test) from ``data/conditions/*.toml``.

The only place the package reads a conditions file (besides the claims' list of the paper's
numbers): each experiment reads its file once with :func:`load_conditions` and fills the
arguments left at ``None`` with :func:`resolve`; everything downstream takes explicit values.
"""

from __future__ import annotations

from typing import Any

from ..repro.paths import data_file, read_toml


def load_conditions(name: str) -> dict[str, Any]:
    """The TOML file ``data/conditions/<name>.toml`` (or a path) as nested dicts (SI units)."""
    return read_toml(data_file(name, "conditions", "conditions file"))


def resolve(table: dict[str, Any], section: str | None = None, **given: Any) -> dict[str, Any]:
    """``given`` values, those that are ``None`` taken from ``table`` (or its sub-table ``section``).

    How a notebook's papermill parameters default to the paper's test: a parameter left at
    ``None`` takes the data file's value.

    Raises
    ------
    KeyError
        A parameter is ``None`` and the table has no value for it; the message lists the known keys.
    """
    if section is not None:
        if section not in table:
            raise KeyError(f"the conditions have no [{section}] table; known: {sorted(table)}")
        table = table[section]
    missing = [key for key, value in given.items() if value is None and key not in table]
    if missing:
        where = f"[{section}]" if section else "the conditions"
        raise KeyError(f"{where} has no value for {missing}; known: {sorted(table)}")
    return {key: table[key] if value is None else value for key, value in given.items()}
