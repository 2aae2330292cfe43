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
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from ...repro.paths import data_file
from ..model import load_tire as load_tire  # the reader of every model's tire files
from ..schema import (
    NO_CAVITY,
    AirCavity,
    Compound,
    Operating,
    Tassellation,
    build_cavity,
    build_compounds,
    build_section,
    check_sections,
    param,
    set_parameter,
    tire_name,
)


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
    check_sections(data, source, {"tire", "compounds", *SECTIONS}, {"cavity"})
    name = tire_name(data, source, "ring")
    sections = {key: build_section(cls, data[key], key, source) for key, cls in SECTIONS.items()}
    compounds = build_compounds(data, source, COMPOUNDS)
    cavity = build_cavity(data, source)
    spec = TireSpec(name=name, compounds=compounds, cavity=cavity, source=source, **sections)
    _check_consistency(spec, source)
    return spec


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
