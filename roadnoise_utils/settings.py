"""The environment settings (``ROADNOISE_*``): one table, one reader, every value checked.

Every setting the package reads from the environment is listed in :data:`SETTINGS` with its
valid values, and read only through this module: an unrecognised value is an error naming the
setting and its valid values, a blank one is refused (except where blank means "none"), a
relative path is taken from the repository root (:data:`REPO_ROOT`, so a notebook run in
``notebooks/`` and the reproduction run at the root share one folder), and a ``ROADNOISE_*``
variable that is not a setting (a misspelt name, which would otherwise be ignored) gives a
:class:`~roadnoise_utils.guards.RoadnoiseWarning` naming the settings there are.
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from . import guards

#: The repository root (the folder holding ``roadnoise_utils/`` and ``data/``): relative paths
#: in the settings are taken from here.
REPO_ROOT = Path(__file__).resolve().parents[1]

#: The words of an on/off setting.
ON, OFF = ("on", "1", "true", "yes"), ("off", "0", "false", "no")


@dataclass(frozen=True)
class Setting:
    """One environment setting: its name, its valid values, its default and what it does."""

    name: str
    valid: str
    default: str
    meaning: str


SETTINGS: dict[str, Setting] = {
    s.name: s
    for s in (
        Setting(
            "ROADNOISE_DATA_DIR",
            "a folder holding tires/ (relative: from the repository root)",
            "<repo>/data",
            "the data files: tires, roads, vehicles, conditions, the paper's claims",
        ),
        Setting(
            "ROADNOISE_CACHE_DIR",
            "a folder (relative: from the repository root)",
            "<repo>/.cache",
            "the stage cache",
        ),
        Setting(
            "ROADNOISE_CACHE",
            "on/off, 1/0, true/false, yes/no",
            "on",
            "off bypasses the stage cache (every stage computes, nothing is stored)",
        ),
        Setting(
            "ROADNOISE_FIGURE_DIR",
            "a folder (relative: from the repository root)",
            "<repo>/figures",
            "where the reproduction writes the figures and the report",
        ),
        Setting(
            "ROADNOISE_STAGE_LOG",
            "a file (relative: from the repository root); blank: no log",
            "no log",
            "one line per stage computed: name, wall time (s), process id, cache key",
        ),
        Setting(
            "ROADNOISE_THREADS",
            "1 or 2",
            "2 (1 on a one-core machine)",
            "threads inside one computation (the results are the same to the last bit)",
        ),
        Setting(
            "ROADNOISE_MAX_BYTES",
            "a number of bytes > 0, e.g. 8e9 (inf: no limit)",
            "4 GiB",
            "the largest allocation a stage may make before it refuses its input",
        ),
    )
}


def table() -> pd.DataFrame:
    """Every setting, its valid values, default and meaning (the book's settings table)."""
    return pd.DataFrame(
        [(s.valid, s.default, s.meaning) for s in SETTINGS.values()],
        index=pd.Index(list(SETTINGS), name="setting"),
        columns=["valid values", "default", "what it does"],
    )


def raw(name: str) -> str | None:
    """The environment's value of the setting ``name`` (None when unset); warns once about unknown ``ROADNOISE_*``."""
    if name not in SETTINGS:
        raise KeyError(f"{name} is not a roadnoise setting; the settings are {sorted(SETTINGS)}")
    _warn_unknown(tuple(sorted(v for v in os.environ if v.startswith("ROADNOISE_") and v not in SETTINGS)))
    return os.environ.get(name)


@functools.cache
def _warn_unknown(names: tuple[str, ...]) -> None:
    if names:
        guards.warn(
            f"{', '.join(names)}: not a roadnoise setting, ignored (a misspelt name?); the settings are "
            f"{', '.join(sorted(SETTINGS))}",
            stacklevel=5,
        )


def path(name: str, default: Path | None) -> Path | None:
    """The path (a folder or a file) the setting ``name`` gives, or ``default`` when unset.

    A relative path is taken from :data:`REPO_ROOT`; ``~`` is expanded. A blank value is
    refused (it would name the working folder without saying so), except for
    ``ROADNOISE_STAGE_LOG``, where blank means no log (``default``).
    """
    value = raw(name)
    if value is None:
        return default
    if not value.strip():
        if name == "ROADNOISE_STAGE_LOG":
            return default
        raise ValueError(f"{name} is set but empty: valid values are {SETTINGS[name].valid}; or unset it")
    found = Path(value).expanduser()
    return found if found.is_absolute() else REPO_ROOT / found


def flag(name: str, default: bool) -> bool:
    """The on/off setting ``name`` (:data:`ON`, :data:`OFF`, any case), ``default`` when unset."""
    value = raw(name)
    if value is None:
        return default
    word = value.strip().lower()
    if word in ON or word in OFF:
        return word in ON
    raise ValueError(f"{name} = {value!r}: valid values are {SETTINGS[name].valid}")


def choice(name: str, valid: tuple[str, ...]) -> str | None:
    """The setting ``name`` if it is one of ``valid`` (blanks stripped), None when unset or blank."""
    value = raw(name)
    if value is None or not value.strip():
        return None
    if value.strip() not in valid:
        raise ValueError(f"{name} = {value!r}: valid values are {SETTINGS[name].valid}")
    return value.strip()


def positive_number(name: str, default: float) -> float:
    """The setting ``name`` as a number > 0 (``inf`` allowed), ``default`` when unset."""
    value = raw(name)
    if value is None:
        return default
    try:
        number = float(value)
    except ValueError:
        raise ValueError(f"{name} = {value!r}: valid values are {SETTINGS[name].valid}") from None
    if not number > 0:
        raise ValueError(f"{name} = {value!r}: valid values are {SETTINGS[name].valid}")
    return number
