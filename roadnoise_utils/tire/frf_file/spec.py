"""Tire files of the tire from files (``[tire] model = "frf-file"``).

The tire file names, per load case, the FRFs an FE code (Abaqus, Nastran, ...) or a
measurement gave for the loaded tire, and its footprint::

    [tire]
    model = "frf-file"
    name = "my 205/55 R16 at 2.2 bar"

    [operating]
    vertical_load = 4500.0            # N: the load the chain runs at unless told

    [hub]
    rim_side_mass = 0.0               # kg the hub carries besides G_H (0 when G_H holds it)

    [[load_case]]
    road = "flat"                     # or "drum", with drum_radius (m)
    frfs = "my_tire-flat.uff"         # UFF 58 as ru.write_uff58 writes: H_tot, G_H (optional), H_i
    footprint = "my_tire-flat.csv"    # contact nodes (roadnoise_utils.tire.footprint_file)
    # load = 4500.0                   # N, default [operating] vertical_load
    # vertical_stiffness = 2.1e5      # N/m: required when the FRFs do not start at 0 Hz
    # deflection = 0.021              # m, optional

Paths are relative to the tire file's folder. Every value is checked: a missing, unknown or
out-of-range value, an unreadable data file, FRFs and footprint with different tasselli are
refused, naming the file and the value.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

from ... import guards
from ...guards import LOAD_RANGE
from ...response.uff import read_uff58
from ..footprint_file import read_footprint_csv
from ..model import FRFResult
from ..schema import build_section, check_keys, check_sections, param, tire_name
from ..surface import make_road
from ..tasselli import Tasselli

#: Vertical stiffness a tire file may give (N/m): a small car tire to a truck's.
STIFFNESS_RANGE = (1.0e4, 1.0e7)
#: How far the tasselli's FRFs may sum from H_tot before a warning (relative, largest over frequency).
SUPERPOSITION_WARNING = 1e-3
#: How far a given K_v may lie from H_tot(0) before a warning (relative): H_tot(0) holds the footprint
#: as the FRFs hold it, and a K_v from a static solve that lets it slide differs by a few per cent
#: (1.6 % on the ring tire's coarse test mesh on the drum, 5.5e-5 at its default mesh on the flat road).
STIFFNESS_WARNING = 0.05


@dataclass(frozen=True)
class FileOperating:
    """The ``[operating]`` table of a tire from files."""

    vertical_load: float = param("N", *LOAD_RANGE, "nominal vertical load: the default load case's")


@dataclass(frozen=True)
class Hub:
    """The ``[hub]`` table of a tire from files."""

    rim_side_mass: float = param("kg", 0.0, 50.0, "the FE tire's mass the hub carries besides G_H (Eq. 5-7)")


@dataclass(frozen=True, eq=False)
class FileCase:
    """One load case of the tire from files: the road, the load and what the files give for it.

    Attributes
    ----------
    road : str
        ``"flat"`` or ``"drum"``.
    drum_radius : float
        Drum radius (m), ``inf`` on the flat road.
    load : float
        Vertical load (N).
    frfs : FRFResult
        The FRFs of the file (N/m), on its own frequencies.
    tasselli : Tasselli
        The footprint's contact nodes and tasselli.
    node_pressure : ndarray
        Contact pressure at each node (Pa).
    vertical_stiffness : float
        K_v (N/m): the file's value, else ``H_tot(0)``.
    deflection : float
        Deflection (m), NaN when the file gives none.
    """

    road: str
    drum_radius: float
    load: float
    frfs: FRFResult
    tasselli: Tasselli
    node_pressure: np.ndarray
    vertical_stiffness: float
    deflection: float
    files: tuple[str, str] = field(default=("", ""), metadata={"identity": False})

    def describe(self) -> str:
        where = "the flat road" if self.road == "flat" else f"a drum of R = {self.drum_radius:.2f} m"
        return f"{self.load:.0f} N on {where}"


@dataclass(frozen=True, eq=False)
class FRFFileSpec:
    """A validated tire from files: its name, load, rim-side mass and load cases."""

    name: str
    vertical_load: float
    rim_side_mass: float
    cases: tuple[FileCase, ...]
    source: str = field(default="<dict>", metadata={"identity": False})

    #: The tire model this file builds (``[tire] model``).
    model: ClassVar[str] = "frf-file"

    @property
    def has_hub_transfer(self) -> bool:
        """Whether every load case's file carries :math:`G_H`."""
        return all(c.frfs.G_H is not None for c in self.cases)

    def replace(self, **changes: Any) -> FRFFileSpec:
        """A copy with another ``name`` or ``operating.vertical_load`` (a load one of its cases gives)."""
        unknown = sorted(set(changes) - {"name", "operating.vertical_load"})
        if unknown:
            raise KeyError(
                f"{unknown}: a tire from files has no construction to change; valid keys are 'name' and "
                "'operating.vertical_load' (a load its files give)"
            )
        load = float(changes.get("operating.vertical_load", self.vertical_load))
        if not any(np.isclose(c.load, load, rtol=1e-9, atol=0.0) for c in self.cases):
            raise ValueError(
                f"operating.vertical_load = {load:g} N: the files give {sorted({c.load for c in self.cases})} N"
            )
        return dataclasses.replace(
            self, name=str(changes.get("name", self.name)), vertical_load=load, source=self.source + " (modified)"
        )


def from_dict(data: dict[str, Any], source: str = "<dict>", folder: Path | None = None) -> FRFFileSpec:
    """Validate a tire file's contents and read its data files (paths relative to ``folder``)."""
    folder = Path(".") if folder is None else Path(folder)
    check_sections(data, source, {"tire", "operating", "hub", "load_case"})
    name = tire_name(data, source, FRFFileSpec.model)
    vertical_load = build_section(FileOperating, data["operating"], "operating", source).vertical_load
    rim_side_mass = build_section(Hub, data["hub"], "hub", source).rim_side_mass
    entries = data.get("load_case")
    if not isinstance(entries, list) or not entries or not all(isinstance(e, dict) for e in entries):
        raise ValueError(f"{source}: give at least one [[load_case]] table (road, frfs, footprint)")
    cases = tuple(_case(entry, k + 1, vertical_load, source, folder) for k, entry in enumerate(entries))
    seen = {}
    for c in cases:
        key = (c.road, c.drum_radius, c.load)
        if key in seen:
            raise ValueError(f"{source}: load cases {seen[key]} and {cases.index(c) + 1} are both {c.describe()}")
        seen[key] = cases.index(c) + 1
    if not any(np.isclose(c.load, vertical_load, rtol=1e-9, atol=0.0) for c in cases):
        raise ValueError(f"{source}: no load case at [operating] vertical_load = {vertical_load:g} N")
    return FRFFileSpec(name=name, vertical_load=vertical_load, rim_side_mass=rim_side_mass, cases=cases, source=source)


def _case(entry: dict, number: int, default_load: float, source: str, folder: Path) -> FileCase:
    where = f"{source}, [[load_case]] {number}"
    check_keys(
        entry, {"road", "drum_radius", "load", "frfs", "footprint", "vertical_stiffness", "deflection"}, where, "it"
    )
    road = entry.get("road", "flat")
    if road not in ("flat", "drum"):
        raise ValueError(f"{where}: road = {road!r}: valid values are 'flat' and 'drum'")
    if road == "flat" and "drum_radius" in entry:
        raise ValueError(f"{where}: drum_radius is given for the flat road; give road = 'drum' or drop it")
    surface = make_road(road, entry.get("drum_radius"))
    load = guards.real(f"{where}: load", entry.get("load", default_load), *guards.LOAD_RANGE, unit="N")
    paths = {}
    for key in ("frfs", "footprint"):
        if not isinstance(entry.get(key), str):
            raise ValueError(f"{where}: {key} must name a file (a path relative to the tire file)")
        paths[key] = folder / entry[key]
    frfs = read_uff58(paths["frfs"])
    tasselli, pressure = read_footprint_csv(paths["footprint"])
    if frfs.H.shape[0] != tasselli.n:
        raise ValueError(
            f"{where}: {paths['frfs'].name} has FRFs of {frfs.H.shape[0]} tasselli, {paths['footprint'].name} "
            f"{tasselli.n}; they must be the same tasselli"
        )
    frfs = dataclasses.replace(frfs, H_points=None)  # the footprint file gives the tasselli, not the FE points
    _check_superposition(frfs, where)
    stiffness = _stiffness(entry, frfs, where)
    deflection = entry.get("deflection")
    deflection = (
        np.nan
        if deflection is None
        else guards.real(f"{where}: deflection", deflection, 0.0, 0.2, lo_open=True, unit="m")
    )
    return FileCase(
        road=surface.kind,
        drum_radius=surface.drum_radius,
        load=load,
        frfs=frfs,
        tasselli=tasselli,
        node_pressure=pressure,
        vertical_stiffness=stiffness,
        deflection=float(deflection),
        files=(str(entry["frfs"]), str(entry["footprint"])),
    )


def _stiffness(entry: dict, frfs: FRFResult, where: str) -> float:
    """K_v (N/m): ``H_tot(0)`` where the FRFs start at 0 Hz (the file's value checked against it), else the file's."""
    given = entry.get("vertical_stiffness")
    if given is not None:
        given = guards.real(f"{where}: vertical_stiffness", given, *STIFFNESS_RANGE, unit="N/m")
    if frfs.freqs[0] == 0.0:
        static = float(frfs.H_tot[0].real)
        if given is not None and abs(given / static - 1.0) > STIFFNESS_WARNING:
            guards.warn(
                f"{where}: vertical_stiffness = {given:g} N/m, but H_tot(0) = {static:g} N/m; using the file's value"
            )
            return given
        return static if given is None else given
    if given is None:
        raise ValueError(
            f"{where}: the FRFs start at {frfs.freqs[0]:g} Hz, not at 0 Hz: give vertical_stiffness (N/m), "
            f"valid range [{STIFFNESS_RANGE[0]:g}, {STIFFNESS_RANGE[1]:g}]"
        )
    return given


def _check_superposition(frfs: FRFResult, where: str) -> None:
    """Warn when the tasselli's FRFs do not add up to ``H_tot`` (paper Eq. i): a footprint that misses nodes."""
    error = float(np.max(np.abs(frfs.H.sum(axis=0) - frfs.H_tot) / np.abs(frfs.H_tot)))
    if error > SUPERPOSITION_WARNING:
        guards.warn(
            f"{where}: the tasselli's FRFs sum to H_tot within {error:.2g} only (Eq. i); is a tassello missing?"
        )
