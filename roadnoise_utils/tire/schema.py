"""The schema of every tire file: validated fields with a unit, a valid range and a meaning.

A tire file section is a frozen dataclass whose fields are declared with :func:`param` (a real
or integer number: unit, valid range, meaning) or :func:`flag` (a boolean); :func:`build_section`
validates a TOML table against it — unknown keys, missing keys, wrong types and values out of
range are refused with the file, the key and the valid range. Every tire model's spec
(:mod:`roadnoise_utils.tire.ring.spec`, :mod:`roadnoise_utils.tire.cross_section.spec`,
:mod:`roadnoise_utils.tire.frf_file.spec`) is built from these, with the sections they share
(operating load and pressure, tassellation, air cavity, rubber compounds).
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from dataclasses import dataclass, field
from typing import Any

from ..guards import LOAD_RANGE
from .rubber import FractionalZener


def param(unit: str, lo: float, hi: float, doc: str, integer: bool = False) -> Any:
    """Declare a parameter field with its unit, valid closed range and meaning."""
    return field(metadata={"unit": unit, "range": (lo, hi), "doc": doc, "integer": integer})


@dataclass(frozen=True)
class Operating:
    """Test conditions the tire is built for."""

    inflation_pressure: float = param("Pa", 0.5e5, 5.0e5, "inflation pressure")
    vertical_load: float = param("N", *LOAD_RANGE, "nominal vertical load")
    rim_width: float = param(
        "m",
        0.08,
        0.30,
        "rim width (e.g. 4J = 4 in); the ring model's sidewall foundation is calibrated, not built from it",
    )


@dataclass(frozen=True)
class Tassellation:
    """How the footprint is divided into tasselli (paper Fig. 2)."""

    target_length: float = param(
        "m", 0.005, 0.025, "longitudinal length of a row of tasselli (<= 25 mm to resolve 5 cm wavelengths)"
    )
    strips_per_column: int = param("-", 1, 10, "belt strips grouped into one column of tasselli", integer=True)


def flag(doc: str) -> Any:
    """Declare a true/false field of a tire file."""
    return field(metadata={"unit": "-", "range": (0, 1), "doc": doc, "integer": False, "boolean": True})


@dataclass(frozen=True)
class AirCavity:
    """The tire's air cavity (beyond the paper; :mod:`~roadnoise_utils.tire.cavity`). Optional in a tire file: absent, it is off."""

    enabled: bool = flag("couple the air cavity's plane-wave modes to the tire (false: the paper's model)")
    temperature: float = param("deg C", -40.0, 120.0, "temperature of the inflation air")
    damping_ratio: float = param("-", 0.0, 0.2, "damping ratio of the cavity's modes")
    modes: int = param(
        "-",
        1,
        60,
        "plane-wave modes kept, the uniform one included (41: to ~4.5 kHz, the FRFs converged to 400 Hz)",
        integer=True,
    )

    def refuse_in(self, stage: str) -> None:
        """Refuse the cavity, switched on, in a stage whose FE numerics do not carry it (a ValueError naming
        ``stage``): a stage never ignores the air it was asked for."""
        if self.enabled:
            raise ValueError(
                f"{stage}: the FE numerics of this stage do not include the air cavity yet; valid tires have "
                "[cavity] enabled = false (the cavity reaches the fixed-hub FRFs, the fits and the RM chain)"
            )


#: The cavity of a tire file without a ``[cavity]`` table: off (the paper's model).
NO_CAVITY = AirCavity(enabled=False, temperature=20.0, damping_ratio=0.01, modes=41)


@dataclass(frozen=True)
class Compound:
    """Fractional-Zener parameters of one rubber compound (see :mod:`.viscoelastic`)."""

    modulus_ratio: float = param("-", 1.0001, 100.0, "E_inf / E_0")
    relaxation_time: float = param("s", 1.0e-9, 1.0, "relaxation time tau")
    order: float = param("-", 0.01, 1.0, "fractional order alpha")

    def law(self) -> FractionalZener:
        """The :class:`FractionalZener` law of this compound."""
        return FractionalZener(self.modulus_ratio, self.relaxation_time, self.order)


def set_parameter(data: dict[str, Any], key: str, value: Any) -> None:
    """Set ``"section.field"`` (any depth) of a tire file's nested data; unknown keys raise ``KeyError``."""
    node = data
    *parents, leaf = key.split(".")
    for part in parents:
        if part not in node or not isinstance(node[part], dict):
            raise KeyError(f"unknown parameter section {part!r} in {key!r}")
        node = node[part]
    if leaf not in node:
        raise KeyError(f"unknown parameter {key!r}")
    node[leaf] = value


def build_section(cls: type, values: Any, where: str, source: str) -> Any:
    """Validate one TOML table against the field metadata of ``cls``."""
    if not isinstance(values, dict):
        raise ValueError(f"{source}: [{where}] must be a table")
    names = {f.name for f in dataclasses.fields(cls)}
    unknown = sorted(set(values) - names)
    if unknown:
        raise ValueError(f"{source}: [{where}] has unknown parameter(s) {unknown}; expected {sorted(names)}")
    kwargs = {}
    for f in dataclasses.fields(cls):
        meta = f.metadata
        lo, hi = meta["range"]
        unit = meta["unit"]
        if f.name not in values:
            raise ValueError(
                f"{source}: [{where}] is missing {f.name!r} ({meta['doc']}; {unit}, valid range [{lo:g}, {hi:g}])"
            )
        value = values[f.name]
        if meta.get("boolean"):
            if not isinstance(value, bool):
                raise ValueError(f"{source}: [{where}] {f.name} = {value!r} must be true or false ({meta['doc']})")
            kwargs[f.name] = value
            continue
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise ValueError(f"{source}: [{where}] {f.name} = {value!r} must be a number ({unit})")
        if meta["integer"] and not float(value).is_integer():
            raise ValueError(f"{source}: [{where}] {f.name} = {value!r} must be an integer")
        if not (math.isfinite(value) and lo <= value <= hi):
            raise ValueError(
                f"{source}: [{where}] {f.name} = {value:g} {unit} is outside its valid range "
                f"[{lo:g}, {hi:g}] {unit} ({meta['doc']})"
            )
        kwargs[f.name] = int(value) if meta["integer"] else float(value)
    return cls(**kwargs)


def check_model(data: dict[str, Any], source: str, expected: str) -> str:
    """The ``[tire] model`` of a tire file, refused unless it is ``expected`` (the parser's own kind)."""
    tire = data.get("tire")
    model = tire.get("model") if isinstance(tire, dict) else None
    if model != expected:
        raise ValueError(f"{source}: [tire] model = {model!r} where a {expected!r} tire file is expected")
    return model


def check_keys(table: Any, allowed: set[str], source: str, where: str, required: set[str] = frozenset()) -> dict:
    """A TOML table whose keys are among ``allowed`` and include ``required``; else a clear error."""
    if not isinstance(table, dict):
        raise ValueError(f"{source}: {where} must be a table")
    missing = sorted(set(required) - set(table))
    if missing:
        raise ValueError(f"{source}: {where} is missing {missing}")
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        raise ValueError(f"{source}: {where} has unknown key(s) {unknown}; expected {sorted(allowed)}")
    return table


def check_sections(data: dict[str, Any], source: str, required: set[str], optional: set[str] = frozenset()) -> None:
    """Refuse a tire file that lacks a ``required`` section or has one outside ``required | optional``."""
    missing = sorted(set(required) - set(data))
    if missing:
        raise ValueError(f"{source}: missing section(s) {['[' + m + ']' for m in missing]}")
    expected = set(required) | set(optional)
    unknown = sorted(set(data) - expected)
    if unknown:
        raise ValueError(f"{source}: unknown section(s) {unknown}; expected {sorted(expected)}")


def tire_name(data: dict[str, Any], source: str, model: str) -> str:
    """The ``[tire]`` table's ``name``, its ``model`` checked to be ``model`` (keys: model, name)."""
    tire = check_keys(data.get("tire"), {"model", "name"}, source, "[tire]")
    check_model(data, source, model)
    name = tire.get("name")
    if not isinstance(name, str) or not name.strip():
        raise ValueError(f"{source}: [tire] name must be a non-empty string")
    return name


def build_compounds(data: dict[str, Any], source: str, required: tuple[str, ...] = ()) -> dict[str, Compound]:
    """The ``[compounds.*]`` tables, each a :class:`Compound`; the ``required`` names must be there."""
    tables = data["compounds"]
    if not isinstance(tables, dict):
        raise ValueError(f"{source}: [compounds] must be a table of compound tables")
    missing = sorted(set(required) - set(tables))
    if missing:
        raise ValueError(f"{source}: missing compound table(s) {['[compounds.' + c + ']' for c in missing]}")
    return {key: build_section(Compound, value, f"compounds.{key}", source) for key, value in sorted(tables.items())}


def build_cavity(data: dict[str, Any], source: str) -> AirCavity:
    """The optional ``[cavity]`` table; absent, :data:`NO_CAVITY` (the paper's model)."""
    return build_section(AirCavity, data["cavity"], "cavity", source) if "cavity" in data else NO_CAVITY
