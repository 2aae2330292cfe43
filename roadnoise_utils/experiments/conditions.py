"""Test conditions (drum, cleat, speeds, suspension, road test) from ``data/conditions/*.toml``.

The only place the package reads a conditions file (besides the claims' list of the paper's
numbers): each experiment reads its file once with :func:`load_conditions` and fills the
arguments left at ``None`` with :func:`resolve`; everything downstream takes explicit values.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..repro.paths import data_file, read_toml
from ..tire.schema import check_keys

#: Every key the package reads from each conditions file, by table (``""``: the top level). A key
#: outside them (a misspelt one would otherwise be ignored and the paper's value used) is refused.
KEYS: dict[str, dict[str, set[str]]] = {
    "cleat_test": {
        "drum": {"radius"},
        "cleat": {"shape", "base", "height"},
        "speeds": {"dynamic_kmh", "quasi_static_kmh"},
        "runs": {"quasi_static_distance", "dynamic_distance", "fe_distance", "fe_duration"},
        "one_sided": {"n_elements", "distance", "quasi_static_step", "sweep_kmh", "sweep_distance"},
    },
    "moving_hub_check": {"hub": {"mass", "stiffness", "damping"}},
    "road_test": {"": {"speed_kmh", "textures", "duration", "seed", "sample_rate"}},
    "whole_car": {
        "": {"car", "speed_kmh", "texture", "duration", "seed"},
        "wheelbase_check": {"speed_kmh", "duration", "samples_per_delay", "seed"},
        "coherence": {"speed_kmh", "duration", "resolution", "seed"},
        "cavity": {"tire", "loads", "band", "temperature", "speeds_kmh", "rolling_frf_speeds_kmh", "rolling_band"},
    },
}


def load_conditions(name: str) -> dict[str, Any]:
    """The TOML file ``data/conditions/<name>.toml`` (or a path) as nested dicts (SI units).

    A file of a known test (its name, or a path whose stem is one, :data:`KEYS`) is checked: an
    unknown table or key is an error naming the file, the table and the keys expected.
    """
    path = data_file(name, "conditions", "conditions file")
    table = read_toml(path)
    schema = KEYS.get(Path(str(name)).stem)
    if schema is not None:
        check_conditions(table, schema, path.name)
    return table


def check_conditions(table: dict[str, Any], schema: dict[str, set[str]], source: str) -> None:
    """Refuse a conditions ``table`` with a table or key outside ``schema`` (:data:`KEYS`)."""
    top = schema.get("", set())
    check_keys(table, top | (set(schema) - {""}), source, "the file")
    for section, keys in schema.items():
        if section and section in table:
            check_keys(table[section], keys, source, f"[{section}]")


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
