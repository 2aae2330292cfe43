"""Tire files of the loaded FE tire (``[tire] model = "loaded-fe"``): a construction and its solid mesh.

The loaded FE tire sweeps a cross-section tire file's construction (profile, meridian, layers,
compounds, inflation and load: :mod:`roadnoise_utils.tire.cross_section.spec`) into 3-D solids;
its own file names that file and says how fine the solids are and how the load is stepped::

    [tire]
    model = "loaded-fe"
    name = "165/65 R14, loaded 3-D FE"

    [construction]
    file = "165_65R14_cross_section.toml"   # a cross-section tire file, relative to this one

    [solid_mesh]
    crown_elements = 4          # section elements across the crown (even: a node on the centre line)
    sidewall_elements = 2       # section elements per sidewall
    footprint_arc = 0.02        # m, arc length of the elements in the footprint sector
    sector_half_angle = 0.28    # rad, half-angle of that sector
    coarse_arc = 0.06           # m, longest arc elsewhere
    arc_growth = 1.3            # -, largest length ratio of neighbouring arcs
    road_step = 0.006           # m, road lift per load step

The section's element counts replace the construction file's ``[mesh]`` (the waveguide's,
finer across the section: its cost grows with the section alone). Keys of :meth:`LoadedSpec.replace`
are the construction's (``"layers.tread.youngs_modulus"``, ``"operating.vertical_load"``) or
``"solid_mesh.*"``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

from ...repro.paths import read_toml
from ..cross_section.spec import CrossSectionSpec
from ..cross_section.spec import from_dict as section_from_dict
from ..schema import build_section, check_keys, check_sections, param, tire_name


@dataclass(frozen=True)
class SolidMeshing:
    """The ``[solid_mesh]`` table: the solids' size and the load steps."""

    crown_elements: int = param(
        "-", 2, 40, "section elements across the crown (even: a node on the centre line)", integer=True
    )
    sidewall_elements: int = param("-", 1, 30, "section elements per sidewall, bead to belt edge", integer=True)
    footprint_arc: float = param("m", 0.002, 0.3, "arc length of the solid elements in the footprint sector")
    sector_half_angle: float = param("rad", 0.05, 1.5, "half-angle of the footprint sector around the bottom")
    coarse_arc: float = param("m", 0.005, 0.4, "longest arc of the elements outside the footprint sector")
    arc_growth: float = param("-", 1.05, 4.0, "largest length ratio of neighbouring arcs outside the sector")
    road_step: float = param("m", 1e-4, 0.02, "road lift per load step of the nonlinear loading")


@dataclass(frozen=True)
class LoadedSpec:
    """A validated loaded FE tire file: its name, its construction and its solid mesh.

    Attributes
    ----------
    name : str
    construction : CrossSectionSpec
        The construction swept, with the section's element counts of ``solid_mesh``.
    solid_mesh : SolidMeshing
    """

    name: str
    construction: CrossSectionSpec
    solid_mesh: SolidMeshing
    source: str = field(default="<dict>", metadata={"identity": False})

    #: The tire model this file builds (``[tire] model``).
    model: ClassVar[str] = "loaded-fe"

    @property
    def vertical_load(self) -> float:
        """The construction's nominal load (N)."""
        return self.construction.operating.vertical_load

    def replace(self, **changes: Any) -> LoadedSpec:
        """A copy with ``"name"``, ``"solid_mesh.*"`` or the construction's keys changed, validated again."""
        mesh = dataclasses.asdict(self.solid_mesh)
        section, name = {}, self.name
        for key, value in changes.items():
            if key == "name":
                name = value
            elif key.startswith("solid_mesh."):
                leaf = key.removeprefix("solid_mesh.")
                if leaf not in mesh:
                    raise KeyError(f"unknown parameter {key!r}; [solid_mesh] holds {sorted(mesh)}")
                mesh[leaf] = value
            else:
                section[key] = value
        source = self.source + " (modified)"
        solid_mesh = build_section(SolidMeshing, mesh, "solid_mesh", source)
        construction = _with_section_mesh(self.construction.replace(**section), solid_mesh, source)
        if not isinstance(name, str) or not name.strip():
            raise ValueError(f"name = {name!r}: a non-empty string")
        return LoadedSpec(name=name, construction=construction, solid_mesh=solid_mesh, source=source)


def from_dict(data: dict[str, Any], source: str = "<dict>", folder: Path | None = None) -> LoadedSpec:
    """Validate a loaded FE tire file's contents; its construction file is read relative to ``folder``."""
    check_sections(data, source, {"tire", "construction", "solid_mesh"})
    name = tire_name(data, source, LoadedSpec.model)
    table = check_keys(data["construction"], {"file"}, source, "[construction]", required={"file"})
    if not isinstance(table["file"], str) or not table["file"]:
        raise ValueError(f"{source}: [construction] file must name a cross-section tire file (a path)")
    path = (Path(".") if folder is None else Path(folder)) / table["file"]
    if not path.is_file():
        raise ValueError(f"{source}: [construction] file = {table['file']!r}: no such file ({path})")
    contents = read_toml(path)
    model = contents.get("tire", {}).get("model") if isinstance(contents.get("tire"), dict) else None
    if model != CrossSectionSpec.model:
        raise ValueError(
            f"{source}: [construction] file = {table['file']!r} is a {model!r} tire file; the loaded FE tire sweeps "
            f"a {CrossSectionSpec.model!r} construction"
        )
    solid_mesh = build_section(SolidMeshing, data["solid_mesh"], "solid_mesh", source)
    construction = _with_section_mesh(section_from_dict(contents, source=path.name), solid_mesh, source)
    return LoadedSpec(name=name, construction=construction, solid_mesh=solid_mesh, source=source)


def _with_section_mesh(construction: CrossSectionSpec, solid_mesh: SolidMeshing, source: str) -> CrossSectionSpec:
    """The construction with the solid mesh's section element counts."""
    try:
        return construction.replace(
            **{
                "mesh.crown_elements": solid_mesh.crown_elements,
                "mesh.sidewall_elements": solid_mesh.sidewall_elements,
            }
        )
    except ValueError as exc:
        raise ValueError(f"{source}: [solid_mesh] {exc}") from None
