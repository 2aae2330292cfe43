"""The notebooks' parameters that no experiment's ``*_conditions`` function takes, checked up front.

Each notebook hands its papermill parameters to the package before doing anything with them:
those of a paper test to its ``*_conditions`` function (speeds, textures, seeds, the cleat...),
the rest here (:func:`check_parameters`): tire and vehicle names, the road of the static
state, frequency bands, an error target, a road length, a mode count. A wrong value is refused
naming the parameter, its value and its valid range or values, before any stage runs.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .. import guards
from ..repro.paths import data_file

#: Roads a static state can be computed on.
ROADS = ("flat", "drum")
#: Highest frequency a notebook's band may reach (Hz): the FE tires' FRFs reach 400 Hz.
MAX_FREQUENCY = 400.0


def _tire(name: str, value: Any) -> Any:
    """A tire file's name or path (None: the notebook's default, e.g. the vehicle file's tire)."""
    if value is not None:
        _file(name, value, "tires", "tire file")
    return value


def _file(name: str, value: Any, folder: str, what: str, given: Any = None) -> None:
    """Refuse ``value`` unless it names a file in ``data/<folder>`` (or is a path to one), naming
    the parameter and the value it was ``given``."""
    try:
        data_file(value, folder, what)
    except (TypeError, ValueError, FileNotFoundError) as exc:
        raise type(exc)(f"{name} = {value if given is None else given!r}: {exc}") from None


def _tire_size(name: str, value: Any) -> str:
    """A size with a ring tire file and a cross-section tire file (``<size>`` and ``<size>_cross_section``)."""
    if not isinstance(value, str):
        raise TypeError(f"{name} = {value!r}: give a tire size as a string, e.g. '165_65R14'")
    _file(name, value, "tires", "tire file")
    _file(name, f"{value}_cross_section", "tires", "tire file", given=value)
    return value


def _car_tire_size(name: str, value: Any) -> str:
    """A size whose car is in ``data/vehicles`` as ``midsize_<size>``, besides its two tire files."""
    _tire_size(name, value)
    _file(name, f"midsize_{value}", "vehicles", "vehicle file", given=value)
    return value


def _road(name: str, value: Any) -> str:
    if value not in ROADS:
        raise ValueError(f"{name} = {value!r}: valid values are {ROADS}")
    return value


def _frequency(name: str, value: Any) -> float:
    return guards.real(name, value, 0.0, MAX_FREQUENCY, lo_open=True, unit="Hz")


def _band_top(name: str, value: Any) -> float:
    """The top of a spectrum's band (Hz), which starts at 2 Hz."""
    return guards.real(name, value, 2.0, MAX_FREQUENCY, lo_open=True, unit="Hz")


def _tires(name: str, value: Any) -> dict:
    """Labels mapped to tire file names or paths (the models shown beside another)."""
    if not isinstance(value, dict) or not all(isinstance(k, str) and k for k in value):
        raise TypeError(f"{name} = {value!r}: give a dict of labels (non-empty strings) to tire file names")
    for label, tire in value.items():
        _file(f"{name}[{label!r}]", tire, "tires", "tire file")
    return value


def _loads(name: str, value: Any) -> list[float]:
    """Increasing vertical loads (N), each within :data:`roadnoise_utils.guards.LOAD_RANGE`."""
    if isinstance(value, str) or not hasattr(value, "__len__") or len(value) < 1:
        raise TypeError(f"{name} = {value!r}: give a list of one or more loads (N)")
    loads = [guards.real(f"{name}[{i}]", v, *guards.LOAD_RANGE, unit="N") for i, v in enumerate(value)]
    if any(b <= a for a, b in zip(loads, loads[1:])):
        raise ValueError(f"{name} = {value!r}: give strictly increasing loads (N)")
    return loads


#: Each parameter's check: ``check(name, value)`` raises, naming both, when the value is not valid.
CHECKS: dict[str, Callable[[str, Any], Any]] = {
    "tire_name": _tire,
    "ring_name": _tire,
    "loaded_tire": _tire,
    "beside": _tires,
    "loads": _loads,
    "vehicle_name": lambda name, value: _file(name, value, "vehicles", "vehicle file"),
    "tire_size": _tire_size,
    "car_tire_size": _car_tire_size,
    "road": _road,
    "f_band": _frequency,
    "f_max": _frequency,
    "band": _band_top,
    "tolerance": lambda name, value: guards.real(name, value, 0.0, 1.0, lo_open=True, hi_open=True),
    "n_modes": lambda name, value: guards.integer(name, value, 1, 500),
    "length": lambda name, value: guards.real(name, value, 0.0, 1e4, lo_open=True, unit="m"),
}


def check_parameters(**values: Any) -> None:
    """Check a notebook's parameters (``name=value``) before it uses them.

    Raises ``TypeError``/``ValueError``/``FileNotFoundError`` naming the parameter, its value and
    what is valid; an unknown name is refused with the known ones (:data:`CHECKS`).
    """
    unknown = sorted(set(values) - set(CHECKS))
    if unknown:
        raise ValueError(f"{unknown}: not a notebook parameter checked here; the known ones are {sorted(CHECKS)}")
    for name, value in values.items():
        CHECKS[name](name, value)
