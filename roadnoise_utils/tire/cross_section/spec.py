"""Tire files of the cross-section model (``[tire] model = "cross-section"``): the construction.

A cross-section tire file describes the tire as it is built: the outer
profile, the sidewall meridian from the bead to the belt edge, and the layers with their
thickness, density, moduli and compound. It is validated as strictly as a ring file
(:mod:`roadnoise_utils.tire.ring.spec`): every missing, unknown, non-numeric or out-of-range value is refused with its
name, unit and valid range.

Layer kinds:

* ``rubber``: isotropic (``youngs_modulus``, ``poisson``): liner, sidewall, undertread.
* ``cord``: a cord-rubber ply, its constants from cord and matrix by the rule of mixtures and
  Halpin-Tsai (:mod:`roadnoise_utils.tire.cross_section.laminate`), at ``cord_angle`` from the circumferential direction.
* ``tread``: the grooved tread as a smeared layer of bonded blocks: normal modulus
  :math:`E(1 + 2S^2)(1 - v)` with shape factor ``S`` (Gent & Lindley, Proc. IMechE 173, 1959)
  and groove void ratio ``v``, in-plane and shear moduli :math:`E(1 - v)` and
  :math:`E(1 - v)/3`, no Poisson coupling (the grooves let the blocks bulge).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

import numpy as np

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
from . import laminate


@dataclass(frozen=True)
class SectionGeometry:
    """Outer profile and meridian of the inflated cross-section."""

    rim_diameter: float = param("m", 0.25, 0.60, "nominal rim (bead seat) diameter")
    section_width: float = param("m", 0.10, 0.40, "nominal section width (outer faces of the sidewalls)")
    aspect_ratio: float = param("-", 0.20, 1.00, "section height / section width")
    tread_width: float = param("m", 0.05, 0.35, "width of the crown (tread and belt) measured across the tread surface")
    crown_radius: float = param("m", 0.05, 5.0, "transverse radius of the tread surface")
    shoulder_drop: float = param("m", 0.0, 0.01, "extra drop of the tread surface at its edges (rounded shoulder)")
    shoulder_width: float = param("m", 0.002, 0.05, "width of the shoulder rounding at each edge of the tread")
    bead_radius: float = param("m", 0.12, 0.35, "radius where the sidewall leaves the rim flange (clamped below)")
    bead_width: float = param(
        "m", 0.05, 0.40, "axial distance between the two points where the sidewalls leave the rim"
    )

    @property
    def rim_radius(self) -> float:
        return 0.5 * self.rim_diameter

    @property
    def outer_radius(self) -> float:
        """Unloaded outer radius of the tread centre (m)."""
        return self.rim_radius + self.section_width * self.aspect_ratio


@dataclass(frozen=True)
class SectionMeshing:
    """Discretisation: elements across the cross-section, harmonics around it, contact grid."""

    crown_elements: int = param("-", 2, 80, "9-node elements across the crown (contact nodes 2x + 1)", integer=True)
    sidewall_elements: int = param("-", 2, 60, "9-node elements along each sidewall, bead to belt edge", integer=True)
    harmonics: int = param("-", 8, 4000, "highest circumferential harmonic n of the Fourier series", integer=True)
    contact_spacing: float = param("m", 0.0005, 0.02, "spacing of the contact points along the circumference")


@dataclass(frozen=True)
class RubberLayer:
    """An isotropic rubber layer (liner, sidewall, undertread)."""

    thickness: float = param("m", 1e-4, 0.05, "layer thickness")
    density: float = param("kg/m^3", 500.0, 3000.0, "density")
    youngs_modulus: float = param("Pa", 1e5, 1e8, "static Young's modulus of the compound")
    poisson: float = param("-", 0.0, 0.499, "Poisson ratio (rubber ~0.49; the element is displacement-based)")
    compound: str = field(default="", metadata={"compound": True})

    def stiffness(self) -> np.ndarray:
        """Static 6x6 stiffness in the layer axes (Pa)."""
        return laminate.isotropic(self.youngs_modulus, self.poisson)


@dataclass(frozen=True)
class CordLayer:
    """A cord-rubber ply: carcass, steel belt, nylon cap."""

    thickness: float = param("m", 1e-4, 0.01, "ply thickness (cords and skim)")
    density: float = param("kg/m^3", 500.0, 8000.0, "density of the ply (cords and skim)")
    cord_modulus: float = param(
        "Pa", 1e8, 3e11, "Young's modulus of the cord (twisted steel ~150 GPa, polyester ~4 GPa)"
    )
    matrix_modulus: float = param("Pa", 1e5, 1e8, "static Young's modulus of the skim rubber")
    cord_volume_fraction: float = param("-", 0.01, 0.7, "volume fraction of cord in the ply")
    cord_angle: float = param(
        "deg", 0.0, 90.0, "cord angle from the circumferential direction (plies come in +/- pairs)"
    )
    compound: str = field(default="", metadata={"compound": True})

    def constants(self) -> dict[str, float]:
        """Engineering constants (:func:`roadnoise_utils.tire.cross_section.laminate.cord_ply_constants`)."""
        return laminate.cord_ply_constants(self.cord_modulus, self.matrix_modulus, self.cord_volume_fraction)

    def stiffness(self) -> np.ndarray:
        return laminate.cord_layer(self.constants(), self.cord_angle)


@dataclass(frozen=True)
class TreadLayer:
    """The grooved tread as a smeared layer of bonded blocks (see the module notes)."""

    thickness: float = param("m", 1e-3, 0.03, "tread depth (blocks)")
    density: float = param("kg/m^3", 500.0, 3000.0, "density of the tread compound")
    youngs_modulus: float = param("Pa", 1e5, 1e8, "static Young's modulus of the tread compound")
    shape_factor: float = param("-", 0.0, 5.0, "block shape factor S = loaded area / free (bulging) area")
    void_ratio: float = param("-", 0.0, 0.8, "groove void ratio of the tread pattern")
    compound: str = field(default="", metadata={"compound": True})

    @property
    def effective_density(self) -> float:
        return self.density * (1.0 - self.void_ratio)

    def stiffness(self) -> np.ndarray:
        solid = 1.0 - self.void_ratio
        e = self.youngs_modulus * solid
        normal = self.youngs_modulus * (1.0 + 2.0 * self.shape_factor**2) * solid
        return np.diag([normal, e, e, e / 3.0, e / 3.0, e / 3.0])


LAYER_KINDS = {"rubber": RubberLayer, "cord": CordLayer, "tread": TreadLayer}
#: The four stacks of the construction: element layer (structure or cover) by region.
STACKS = {
    "crown": "inner element layer of the crown, inside out (liner, carcass, belts, cap)",
    "tread": "outer element layer of the crown, inside out (undertread, tread)",
    "sidewall": "inner element layer of the sidewalls, inside out (liner, carcass)",
    "sidewall_cover": "outer element layer of the sidewalls (sidewall rubber)",
}


@dataclass(frozen=True)
class CrossSectionSpec:
    """All parameters of a cross-section tire, validated. Build it with :func:`roadnoise_utils.tire.ring.spec.load_tire`."""

    name: str
    geometry: SectionGeometry
    operating: Operating
    mesh: SectionMeshing
    layers: dict[str, RubberLayer | CordLayer | TreadLayer]
    construction: dict[str, tuple[str, ...]]
    tasselli: Tassellation
    compounds: dict[str, Compound]
    pneumatic: str = "none"
    cavity: AirCavity = NO_CAVITY
    source: str = field(default="", metadata={"identity": False})

    model = "cross-section"

    @property
    def pneumatic_law(self) -> str | None:
        """Compound whose law scales the pneumatic stiffness (``[pneumatic] compound``), None if lossless."""
        return None if self.pneumatic == "none" else self.pneumatic

    def stack(self, region: str) -> list[tuple[str, RubberLayer | CordLayer | TreadLayer]]:
        """Layers of one stack (:data:`STACKS`), inside out."""
        return [(name, self.layers[name]) for name in self.construction[region]]

    def thickness(self, region: str) -> float:
        """Total thickness of a stack (m)."""
        return sum(layer.thickness for _, layer in self.stack(region))

    def laws(self) -> dict:
        return {name: c.law() for name, c in self.compounds.items()}

    def replace(self, **changes: Any) -> CrossSectionSpec:
        """A copy with some parameters changed (``"layers.tread.youngs_modulus"``) or ``"name"``, validated again."""
        data = to_dict(self)
        for key, value in changes.items():
            if key == "name":
                data["tire"]["name"] = value
                continue
            set_parameter(data, key, value)
        return from_dict(data, source=self.source + " (modified)")


def to_dict(spec: CrossSectionSpec) -> dict[str, Any]:
    """The spec as nested plain data (the TOML layout)."""
    out: dict[str, Any] = {"tire": {"name": spec.name, "model": "cross-section"}}
    for key in ("geometry", "operating", "mesh", "tasselli"):
        out[key] = dataclasses.asdict(getattr(spec, key))
    out["layers"] = {}
    for name, layer in spec.layers.items():
        kind = next(k for k, cls in LAYER_KINDS.items() if isinstance(layer, cls))
        out["layers"][name] = {"kind": kind, **dataclasses.asdict(layer)}
    out["construction"] = {k: list(v) for k, v in spec.construction.items()}
    out["pneumatic"] = {"compound": spec.pneumatic}
    out["cavity"] = dataclasses.asdict(spec.cavity)
    out["compounds"] = {k: dataclasses.asdict(v) for k, v in sorted(spec.compounds.items())}
    return out


SECTIONS = {"geometry": SectionGeometry, "operating": Operating, "mesh": SectionMeshing, "tasselli": Tassellation}


def _layer(name: str, values: Any, source: str, compounds: dict) -> RubberLayer | CordLayer | TreadLayer:
    where = f"layers.{name}"
    if not isinstance(values, dict):
        raise ValueError(f"{source}: [{where}] must be a table")
    kind = values.get("kind")
    if kind not in LAYER_KINDS:
        raise ValueError(f"{source}: [{where}] kind = {kind!r}: valid kinds are {sorted(LAYER_KINDS)}")
    cls = LAYER_KINDS[kind]
    compound = values.get("compound")
    if compound not in compounds:
        raise ValueError(
            f"{source}: [{where}] compound = {compound!r} names no [compounds.*] table; defined: {sorted(compounds)}"
        )
    numeric = {k: v for k, v in values.items() if k not in ("kind", "compound")}
    layer = build_section(_numeric_view(cls), numeric, where, source)
    return cls(**dataclasses.asdict(layer), compound=compound)


def _numeric_view(cls: type) -> type:
    """A dataclass with only the numeric fields of ``cls`` (for :func:`roadnoise_utils.tire.ring.spec.build_section`)."""
    fields = [(f.name, float, field(metadata=f.metadata)) for f in dataclasses.fields(cls) if "range" in f.metadata]
    return dataclasses.make_dataclass(cls.__name__, fields, frozen=True)


def from_dict(data: dict[str, Any], source: str = "<dict>") -> CrossSectionSpec:
    """Validate nested data (the TOML layout) and build a :class:`CrossSectionSpec`."""
    check_sections(data, source, {"tire", "compounds", "layers", "construction", "pneumatic", *SECTIONS}, {"cavity"})
    name = tire_name(data, source, "cross-section")
    sections = {key: build_section(cls, data[key], key, source) for key, cls in SECTIONS.items()}
    compounds = build_compounds(data, source)
    layers = {key: _layer(key, value, source, compounds) for key, value in data["layers"].items()}
    construction = _construction(data["construction"], layers, source)
    pneumatic = data["pneumatic"].get("compound") if isinstance(data["pneumatic"], dict) else None
    if set(data["pneumatic"]) != {"compound"} or (pneumatic != "none" and pneumatic not in compounds):
        raise ValueError(
            f"{source}: [pneumatic] compound = {pneumatic!r}: valid values are 'none' (a lossless pneumatic "
            f"stiffness) or a [compounds.*] name {sorted(compounds)}"
        )
    spec = CrossSectionSpec(
        name=name,
        layers=layers,
        construction=construction,
        compounds=compounds,
        pneumatic=pneumatic,
        cavity=build_cavity(data, source),
        source=source,
        **sections,
    )
    _check_consistency(spec, source)
    return spec


def _construction(values: Any, layers: dict, source: str) -> dict[str, tuple[str, ...]]:
    if not isinstance(values, dict) or set(values) != set(STACKS):
        raise ValueError(f"{source}: [construction] must list exactly the stacks {sorted(STACKS)}")
    out = {}
    for region, names in values.items():
        if not isinstance(names, list) or not names or any(n not in layers for n in names):
            raise ValueError(
                f"{source}: [construction] {region} = {names!r} must be a non-empty list of [layers.*] names "
                f"({STACKS[region]}); defined: {sorted(layers)}"
            )
        out[region] = tuple(names)
    return out


def _check_consistency(spec: CrossSectionSpec, source: str) -> None:
    """Cross-field checks: the section must fit between the rim and the outer radius."""
    g = spec.geometry
    height = g.section_width * g.aspect_ratio
    if g.shoulder_width >= 0.5 * g.tread_width or g.shoulder_drop >= spec.thickness("tread"):
        raise ValueError(
            f"{source}: [geometry] shoulder_width = {g.shoulder_width:g} m must be below half the tread width and "
            f"shoulder_drop = {g.shoulder_drop:g} m below the tread stack ({spec.thickness('tread'):g} m)"
        )
    if spec.mesh.crown_elements % 2:
        raise ValueError(
            f"{source}: [mesh] crown_elements = {spec.mesh.crown_elements} must be even (a node on the centre line)"
        )
    if g.tread_width >= g.section_width:
        raise ValueError(f"{source}: [geometry] tread_width = {g.tread_width:g} m must be below section_width")
    if g.tread_width >= 2 * g.crown_radius:
        raise ValueError(f"{source}: [geometry] crown_radius = {g.crown_radius:g} m must exceed tread_width / 2")
    if not g.rim_radius < g.bead_radius < g.outer_radius - spec.thickness("crown") - spec.thickness("tread"):
        raise ValueError(
            f"{source}: [geometry] need rim radius {g.rim_radius:g} < bead_radius {g.bead_radius:g} < "
            f"the belt's inner radius {g.outer_radius - spec.thickness('crown') - spec.thickness('tread'):g} m"
        )
    cover = spec.thickness("sidewall_cover")
    if g.bead_width >= g.section_width - 2 * cover:
        raise ValueError(
            f"{source}: [geometry] bead_width = {g.bead_width:g} m must be below the carcass width at the widest "
            f"point, section_width - 2 x sidewall cover = {g.section_width - 2 * cover:g} m"
        )
    crown = spec.thickness("crown") + spec.thickness("tread")
    if crown >= 0.5 * height:
        raise ValueError(f"{source}: the crown stacks ({crown:g} m) must be thinner than half the section height")
