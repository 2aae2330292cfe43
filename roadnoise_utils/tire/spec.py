"""Tire parameters: the validated :class:`TireSpec` read from ``data/tires/*.toml``.

Every parameter of the finite-element tire (FET) lives in a TOML file, with a comment giving
its source or reasoning. This module only knows each parameter's unit and physically valid
range, and refuses a file with a missing, unknown or out-of-range value, naming the field::

    ValueError: 165_65R14.toml: [belt] bending_stiffness = -1.0 N m^2 is outside its valid
    range [0.01, 200] N m^2 (bending stiffness EI of the whole belt width)

SI units throughout (m, kg, s, N, Pa).
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from ..guards import LOAD_RANGE
from ..repro.paths import data_file
from .model import load_tire as load_tire  # the reader of every model's tire files
from .rubber import FractionalZener


def param(unit: str, lo: float, hi: float, doc: str, integer: bool = False) -> Any:
    """Declare a parameter field with its unit, valid closed range and meaning."""
    return field(metadata={"unit": unit, "range": (lo, hi), "doc": doc, "integer": integer})


@dataclass(frozen=True)
class Geometry:
    """Size and shape of the unloaded, inflated tire."""

    rim_diameter: float = param("m", 0.25, 0.60, "nominal rim (bead seat) diameter")
    section_width: float = param("m", 0.10, 0.40, "nominal section width")
    aspect_ratio: float = param("-", 0.20, 1.00, "section height / section width")
    belt_width: float = param("m", 0.05, 0.35, "width of the belt/tread band that is modelled")
    tread_thickness: float = param("m", 0.003, 0.030, "belt centre line to tread surface")
    crown_drop: float = param("m", 0.0, 0.020, "drop of the tread-surface radius from centre to belt edge")
    crown_exponent: float = param("-", 1.0, 8.0, "shape exponent of the crown drop, drop * |2y/b|^exponent")
    max_width_radius: float = param("m", 0.10, 0.60, "radius at which the inflated section is widest")

    @property
    def outer_radius(self) -> float:
        """Unloaded outer radius of the tread centre (m)."""
        return 0.5 * self.rim_diameter + self.section_width * self.aspect_ratio

    @property
    def belt_radius(self) -> float:
        """Radius of the belt centre line (m), where the ring elements lie."""
        return self.outer_radius - self.tread_thickness

    @property
    def rim_radius(self) -> float:
        """Rim (bead seat) radius (m)."""
        return 0.5 * self.rim_diameter


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
class Mesh:
    """Discretisation of the belt."""

    n_strips: int = param("-", 1, 41, "number of lateral belt strips (rings)", integer=True)
    n_elements: int = param("-", 24, 2000, "frame elements around each ring", integer=True)


@dataclass(frozen=True)
class Belt:
    """Belt + tread band, per whole belt width, modelled as coupled rings of frame elements."""

    mass_per_length: float = param(
        "kg/m", 0.3, 10.0, "mass per circumferential length of belt, tread and the crown share of the sidewalls"
    )
    axial_stiffness: float = param("N", 1.0e4, 1.0e9, "membrane stiffness EA of the whole belt width")
    bending_stiffness: float = param("N m^2", 0.01, 200.0, "bending stiffness EI of the whole belt width")
    bending_rubber_fraction: float = param(
        "-", 0.0, 1.0, "share of EI carried by rubber (viscoelastic, compound 'belt')"
    )
    inplane_shear_stiffness: float = param(
        "N/m", 0.0, 1.0e8, "in-plane shear stiffness G*h coupling the circumferential motion of adjacent strips"
    )
    lateral_bending_stiffness: float = param(
        "N m", 0.0, 200.0, "bending stiffness D across the width, per unit circumferential length"
    )


@dataclass(frozen=True)
class Foundation:
    """Sidewalls and air as a distributed foundation from the belt to the rim, per unit length."""

    radial_pressure_factor: float = param("-", 0.0, 20.0, "pneumatic radial foundation stiffness / inflation pressure")
    radial_rubber: float = param(
        "N/m^2", 0.0, 5.0e6, "radial foundation stiffness of the sidewall rubber (compound 'sidewall')"
    )
    tangential_pressure_factor: float = param(
        "-", 0.0, 20.0, "pneumatic tangential foundation stiffness / inflation pressure"
    )
    tangential_rubber: float = param(
        "N/m^2", 0.0, 5.0e6, "tangential foundation stiffness of the sidewall rubber (compound 'sidewall')"
    )
    edge_factor: float = param("-", 0.1, 50.0, "foundation stiffness of each edge strip relative to an inner strip")
    crown_mass_share: float = param(
        "-", 0.0, 1.0, "share of the sidewall mass carried by the belt (rest moves with the rim)"
    )
    sidewall_mass: float = param("kg", 0.0, 20.0, "mass of both sidewalls")


@dataclass(frozen=True)
class Tread:
    """Tread rubber between the belt and the road: a viscoelastic (compound 'tread') foundation."""

    normal_stiffness_per_area: float = param(
        "N/m^3", 1.0e7, 1.0e11, "normal stiffness of the tread per unit gross contact area, E_c(1 - void)/h"
    )
    shear_stiffness_per_area: float = param(
        "N/m^3", 1.0e6, 1.0e11, "shear stiffness of the tread per unit gross contact area, G(1 - void)/h"
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
    """The tire's air cavity (beyond the paper; :mod:`.cavity`). Optional in a tire file: absent, it is off."""

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


#: Compounds every tire file must define.
COMPOUNDS = ("tread", "sidewall", "belt", "belt_plies", "carcass")


@dataclass(frozen=True)
class TireSpec:
    """All parameters of one tire, validated. Build it with :func:`load_tire`."""

    name: str
    geometry: Geometry
    operating: Operating
    mesh: Mesh
    belt: Belt
    foundation: Foundation
    tread: Tread
    tasselli: Tassellation
    compounds: dict[str, Compound]
    cavity: AirCavity = NO_CAVITY
    source: str = field(default="", metadata={"identity": False})  # where it was read from: not part of its identity

    #: The tire model this file builds (``[tire] model``).
    model = "ring"

    @property
    def lateral_tension(self) -> float:
        """Meridional membrane tension across the crown (N/m).

        Equilibrium of an inflated toroidal membrane (e.g. Clark, *Mechanics of Pneumatic
        Tires*, ch. 8): :math:`N = p (R_o^2 - R_w^2) / (2 R_o)` with :math:`R_o` the crown
        radius and :math:`R_w` the radius of maximum section width.
        """
        g = self.geometry
        r_o = g.outer_radius
        return self.operating.inflation_pressure * (r_o**2 - g.max_width_radius**2) / (2.0 * r_o)

    @property
    def hoop_tension(self) -> float:
        """Inflation pre-tension of the whole belt, :math:`T = p\\,b\\,R` (N)."""
        return self.operating.inflation_pressure * self.geometry.belt_width * self.geometry.belt_radius

    def replace(self, **changes: Any) -> TireSpec:
        """A copy with some parameters changed, validated again.

        Keys are ``"section.field"`` (``"belt.bending_stiffness"``,
        ``"compounds.tread.order"``) or ``"name"``.
        """
        data = to_dict(self)
        for key, value in changes.items():
            if key == "name":
                data["tire"]["name"] = value
                continue
            set_parameter(data, key, value)
        return from_dict(data, source=self.source + " (modified)")


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


def to_dict(spec: TireSpec) -> dict[str, Any]:
    """The spec as nested plain data (the TOML layout); the basis of its cache key."""
    out: dict[str, Any] = {"tire": {"name": spec.name, "model": "ring"}}
    for f in dataclasses.fields(spec):
        value = getattr(spec, f.name)
        if dataclasses.is_dataclass(value):
            out[f.name] = dataclasses.asdict(value)
    out["compounds"] = {k: dataclasses.asdict(v) for k, v in sorted(spec.compounds.items())}
    return out


SECTIONS = {
    "geometry": Geometry,
    "operating": Operating,
    "mesh": Mesh,
    "belt": Belt,
    "foundation": Foundation,
    "tread": Tread,
    "tasselli": Tassellation,
}


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


def _check_consistency(spec: TireSpec, source: str) -> None:
    """Cross-field checks that single ranges cannot express."""
    g = spec.geometry
    height = g.section_width * g.aspect_ratio
    if g.belt_width > g.section_width:
        raise ValueError(
            f"{source}: [geometry] belt_width = {g.belt_width:g} m must not exceed section_width = {g.section_width:g} m"
        )
    if not g.rim_radius < g.max_width_radius < g.outer_radius:
        raise ValueError(
            f"{source}: [geometry] max_width_radius = {g.max_width_radius:g} m must lie between the rim radius "
            f"{g.rim_radius:g} m and the outer radius {g.outer_radius:g} m"
        )
    if not g.tread_thickness < 0.5 * height:
        raise ValueError(
            f"{source}: [geometry] tread_thickness = {g.tread_thickness:g} m must be below half the section height "
            f"({0.5 * height:g} m)"
        )
    if spec.operating.rim_width >= g.section_width:
        raise ValueError(
            f"{source}: [operating] rim_width = {spec.operating.rim_width:g} m must be below section_width = "
            f"{g.section_width:g} m"
        )
    if g.crown_drop >= g.tread_thickness:
        raise ValueError(
            f"{source}: [geometry] crown_drop = {g.crown_drop:g} m must be below tread_thickness = {g.tread_thickness:g} m"
        )


def from_dict(data: dict[str, Any], source: str = "<dict>") -> TireSpec:
    """Validate nested data (the TOML layout) and build a :class:`TireSpec`."""
    expected = {"tire", "compounds", *SECTIONS}
    missing = sorted(expected - set(data))
    expected.add("cavity")  # optional
    if missing:
        raise ValueError(f"{source}: missing section(s) {['[' + m + ']' for m in missing]}")
    unknown = sorted(set(data) - expected)
    if unknown:
        raise ValueError(f"{source}: unknown section(s) {unknown}; expected {sorted(expected)}")
    name = data["tire"].get("name") if isinstance(data["tire"], dict) else None
    if not isinstance(name, str) or not name:
        raise ValueError(f"{source}: [tire] name must be a non-empty string")
    check_model(data, source, "ring")
    sections = {key: build_section(cls, data[key], key, source) for key, cls in SECTIONS.items()}
    compounds_data = data["compounds"]
    if not isinstance(compounds_data, dict):
        raise ValueError(f"{source}: [compounds] must be a table of compound tables")
    missing_c = sorted(set(COMPOUNDS) - set(compounds_data))
    if missing_c:
        raise ValueError(f"{source}: missing compound table(s) {['[compounds.' + c + ']' for c in missing_c]}")
    compounds = {
        key: build_section(Compound, value, f"compounds.{key}", source) for key, value in sorted(compounds_data.items())
    }
    cavity = build_section(AirCavity, data["cavity"], "cavity", source) if "cavity" in data else NO_CAVITY
    spec = TireSpec(name=name, compounds=compounds, cavity=cavity, source=source, **sections)
    _check_consistency(spec, source)
    return spec


def check_model(data: dict[str, Any], source: str, expected: str) -> str:
    """The ``[tire] model`` of a tire file, refused unless it is ``expected`` (the parser's own kind)."""
    tire = data.get("tire")
    model = tire.get("model") if isinstance(tire, dict) else None
    if model != expected:
        raise ValueError(f"{source}: [tire] model = {model!r} where a {expected!r} tire file is expected")
    return model


def tire_path(name: str | Path) -> Path:
    """Resolve a tire name (``"165_65R14"``) or a path to its TOML file."""
    return data_file(name, "tires", "tire file")


def tire_table(spec: TireSpec) -> pd.DataFrame:
    """Every parameter of a tire with its unit, valid range and meaning."""
    rows = []
    for section, cls in SECTIONS.items():
        obj = getattr(spec, section)
        for f in dataclasses.fields(cls):
            rows.append(
                {
                    "section": section,
                    "parameter": f.name,
                    "value": getattr(obj, f.name),
                    "unit": f.metadata["unit"],
                    "valid range": "[{:g}, {:g}]".format(*f.metadata["range"]),
                    "meaning": f.metadata["doc"],
                }
            )
    for name, compound in sorted(spec.compounds.items()):
        for f in dataclasses.fields(Compound):
            rows.append(
                {
                    "section": f"compounds.{name}",
                    "parameter": f.name,
                    "value": getattr(compound, f.name),
                    "unit": f.metadata["unit"],
                    "valid range": "[{:g}, {:g}]".format(*f.metadata["range"]),
                    "meaning": f.metadata["doc"],
                }
            )
    return pd.DataFrame(rows).set_index(["section", "parameter"])
