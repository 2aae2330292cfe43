"""Designs of a tire and what each one gives: the rows of a design sweep (:mod:`.sweep`).

A *design* is a tire file with some of its parameters overridden, each named by its dotted
key in the file (``"tread.normal_stiffness_per_area"``, ``"belt.bending_stiffness"``,
``"operating.inflation_pressure"``, ``"operating.vertical_load"``, ``"compounds.tread.order"``;
on a cross-section tire ``"layers.tread.youngs_modulus"``...). :func:`sweep_parameters` lists
the names a tire file offers with their units and valid ranges; :func:`make_designs` checks
every name and value, and builds every design's validated spec, before any work is done.

What a design gives (:data:`OUTPUTS`) comes from the package's tested experiments, called as
they are, on either tire model:

====================  ===========================================================  ===========
output                computed by                                                  cost (ring)
====================  ===========================================================  ===========
``K_v``, footprint    :func:`roadnoise_utils.repro.stages.solve_static` (flat)     ~0.1 s
``f1``, ``zeta1``     :func:`.calibration.calibration_values` (direct FRF, flat)   ~2 s
``cleat``             :func:`.cleat.cleat_test` (linear RM chain on the drum)      ~3 s more
``one_sided``         :func:`.one_sided_cleat.one_sided_cleat_test` (as the model   ~20 s more
                      runs it: :meth:`.tire.model.TireModel.one_sided_setup`)
``hub_acceleration``  :func:`.corner.corner_setup` on the vehicle file, the        ~1 s more
                      predicted hub PSD on the road test's texture, its band RMS
====================  ===========================================================  ===========

:func:`evaluate_design` computes one design's outputs and caches them as one stage
(:func:`roadnoise_utils.repro.cache.cached`): keyed by the design's full spec, the outputs and
the conditions they use, and the code of every experiment they run, written atomically, so a
sweep interrupted half-way resumes where it stopped. The stages beneath (static state, FRFs,
fits) are cached as usual.
"""

from __future__ import annotations

import dataclasses
import itertools
import time
import warnings
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from .. import guards
from ..repro import stages
from ..repro.cache import cached
from ..vehicle.spectra import band_rms
from . import calibration, cleat, corner, one_sided_cleat
from .cleat import CleatConditions, cleat_conditions
from .one_sided_cleat import OneSidedConditions, one_sided_conditions
from .road import RoadTestConditions, road_test_conditions

#: A validated tire file of any registered model (:func:`roadnoise_utils.tire.model.load_tire`).
Spec = Any

#: Each output -> the table columns it gives (SI units in the names).
OUTPUTS: dict[str, tuple[str, ...]] = {
    "K_v": ("K_v (N/m)",),
    "footprint": ("footprint_length (m)", "footprint_width (m)"),
    "f1": ("f1 (Hz)",),
    "zeta1": ("zeta1 (-)",),
    "cleat": ("cleat_quasi_static_peak (N)", "cleat_dynamic_peak (N)"),
    "one_sided": ("one_sided_quasi_static_peak (N)", "one_sided_dynamic_peak (N)"),
    "hub_acceleration": ("a_hub_rms (m/s^2)",),
}
#: The outputs a sweep computes by default: the static and first-mode values, about 2 s a ring design.
CHEAP_OUTPUTS = ("K_v", "f1", "zeta1")
#: Hub-acceleration band (Hz) of the paper's Fig. 14 (the first four vertical tire modes).
HUB_BAND = (40.0, 220.0)
#: Frequency step (Hz) of the predicted hub-acceleration PSD.
HUB_STEP = 0.5


@dataclass(frozen=True)
class SweepConditions:
    """The tests every design of a sweep runs, every default resolved once (SI units, speeds in km/h).

    Attributes
    ----------
    cleat : CleatConditions
        The drum cleat test of the ``cleat`` output (``data/conditions/cleat_test.toml``).
    one_sided : OneSidedConditions
        The one-sided runs of the ``one_sided`` output (``[one_sided]`` of the same file).
    road : RoadTestConditions
        The road test of the ``hub_acceleration`` output (speed, textures; ``road_test.toml``).
    vehicle : str
        The vehicle file (``data/vehicles``) whose corner carries each design for ``hub_acceleration``.
    texture : str
        The road texture of ``hub_acceleration`` (a name in ``data/roads``).
    hub_band : (float, float)
        Band (Hz) of the hub-acceleration RMS.
    """

    cleat: CleatConditions
    one_sided: OneSidedConditions
    road: RoadTestConditions
    vehicle: str
    texture: str
    hub_band: tuple[float, float]

    def used_by(self, outputs: Iterable[str]) -> dict[str, Any]:
        """The conditions the ``outputs`` depend on (the per-design cache key holds only those)."""
        outputs = set(outputs)
        used: dict[str, Any] = {}
        if "cleat" in outputs:
            used["cleat"] = self.cleat
        if "one_sided" in outputs:
            used["one_sided"] = self.one_sided
        if "hub_acceleration" in outputs:
            used.update(road=self.road, vehicle=self.vehicle, texture=self.texture, hub_band=self.hub_band)
        return used


def sweep_conditions(
    cleat: CleatConditions | None = None,
    one_sided: OneSidedConditions | None = None,
    road: RoadTestConditions | None = None,
    vehicle: str = corner.PAPER_CAR,
    texture: str | None = None,
    hub_band: tuple[float, float] = HUB_BAND,
) -> SweepConditions:
    """The paper's tests for a sweep (condition files read once); any value given here overrides them.

    ``texture`` defaults to the road test's first texture (``"rough"``); ``hub_band`` in Hz.
    """
    road = road_test_conditions() if road is None else road
    texture = road.textures[0] if texture is None else texture
    if not isinstance(texture, str):
        raise ValueError(f"texture = {texture!r}: give a texture name in data/roads, e.g. 'rough'")
    band = guards.interval("hub_band", hub_band, unit="Hz")
    guards.real("hub_band[0]", band[0], 0.0, unit="Hz")
    return SweepConditions(
        cleat=cleat_conditions() if cleat is None else cleat,
        one_sided=one_sided_conditions(cleat) if one_sided is None else one_sided,
        road=dataclasses.replace(road, textures=(texture,)),
        vehicle=str(vehicle),
        texture=texture,
        hub_band=band,
    )


# ---------------------------------------------------------------- parameters and designs


def _fields(obj: Any, prefix: str) -> Iterable[tuple[str, Any, dict]]:
    """``(dotted name, value, field metadata)`` of every numeric parameter of a spec, depth first."""
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        name = f"{prefix}{f.name}"
        if dataclasses.is_dataclass(value):
            yield from _fields(value, f"{name}.")
        elif isinstance(value, dict):
            for key, item in value.items():
                if dataclasses.is_dataclass(item):
                    yield from _fields(item, f"{name}.{key}.")
        elif "range" in f.metadata and not f.metadata.get("boolean"):
            yield name, value, f.metadata


def sweep_parameters(tire: str | Spec = "165_65R14", names: Iterable[str] | None = None) -> pd.DataFrame:
    """Every parameter a sweep can override on a tire file (or the ``names`` given): value, unit,
    valid range, meaning.

    Index: the dotted names :func:`make_designs` accepts (the tire file's own keys, e.g.
    ``"operating.inflation_pressure"``), the same on a ring and a cross-section tire file where
    the two share a table (``operating``, ``tasselli``, ``compounds``). An unknown name among
    ``names`` is an error listing the valid ones.
    """
    spec = stages.load_tire(tire)
    table = _parameter_table(spec)
    if names is None:
        return table
    if isinstance(names, str):
        raise ValueError(f"names = {names!r}: give a list of parameter names (a grid's keys), or None for all")
    names = list(names)
    if not names:
        raise ValueError("names is empty: give at least one parameter name, or None for all")
    _check_names(spec, names, table)
    return table.loc[names]


def _check_names(spec: Spec, names: list[str], table: pd.DataFrame) -> None:
    unknown = [name for name in names if name not in table.index]
    if unknown:
        raise ValueError(
            f"unknown parameter(s) {unknown} for the {spec.model} tire {spec.name!r}; valid names are the tire "
            f"file's keys: {list(table.index)} (ru.experiments.design.sweep_parameters(tire) lists them with ranges)"
        )


def _parameter_table(spec: Spec) -> pd.DataFrame:
    rows = {
        name: {
            "value": value,
            "unit": meta["unit"],
            "low": meta["range"][0],
            "high": meta["range"][1],
            "integer": bool(meta.get("integer")),
            "meaning": meta["doc"],
        }
        for name, value, meta in _fields(spec, "")
    }
    return pd.DataFrame.from_dict(rows, orient="index").rename_axis("parameter")


def column(parameter: str, unit: str) -> str:
    """The table column of a swept parameter: its dotted name and unit (``"operating.vertical_load (N)"``)."""
    return f"{parameter} ({unit})"


@dataclass(frozen=True)
class Design:
    """One design of a sweep.

    Attributes
    ----------
    index : int
        Its row in the sweep's table (0, 1, ...).
    overrides : dict of str to float
        The overridden parameters (dotted name -> value, SI units).
    spec : Spec
        The tire file with the overrides, validated.
    """

    index: int
    overrides: dict[str, float]
    spec: Spec

    def describe(self) -> str:
        """``design 3 (operating.inflation_pressure = 2.1e+05, ...)``."""
        values = ", ".join(f"{k} = {v:g}" for k, v in self.overrides.items())
        return f"design {self.index} ({values})"


def _plain(value: Any) -> Any:
    """A numpy scalar as the Python number it holds (so messages show ``2.3e5``, not ``np.float64(...)``)."""
    return value.item() if isinstance(value, np.generic) else value


def design_rows(parameters: Mapping[str, Sequence[float]] | pd.DataFrame | Sequence[Mapping[str, float]]) -> list[dict]:
    """The designs as rows: a mapping of value lists gives the full grid (the last name varying fastest),
    a DataFrame or a list of mappings one design per row (a sample)."""
    if isinstance(parameters, pd.DataFrame):
        return [{k: _plain(v) for k, v in zip(parameters.columns, row)} for row in parameters.itertuples(index=False)]
    if isinstance(parameters, Mapping):
        names = list(parameters)
        for name in names:
            values = parameters[name]
            if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
                raise ValueError(f"parameters[{name!r}] = {values!r}: give a list of values for the grid")
        grids = [[_plain(v) for v in parameters[n]] for n in names]
        for name, values in zip(names, grids):
            if not values:
                raise ValueError(f"parameters[{name!r}] is empty: give at least one value")
        return [dict(zip(names, combo)) for combo in itertools.product(*grids)]
    if (
        isinstance(parameters, (str, bytes))
        or not isinstance(parameters, Iterable)
        or not all(isinstance(row, Mapping) for row in parameters)
    ):
        raise ValueError(
            f"parameters = {parameters!r}: give a mapping of value lists (a grid), a DataFrame or a list of mappings"
        )
    rows = [{k: _plain(v) for k, v in dict(row).items()} for row in parameters]
    if not all(set(row) == set(rows[0]) for row in rows):
        raise ValueError("parameters: every design of a list must set the same parameters")
    return rows


def make_designs(
    tire: str | Spec, parameters: Mapping[str, Sequence[float]] | pd.DataFrame | Sequence[Mapping[str, float]]
) -> list[Design]:
    """Every design of a sweep, each name and value checked and each spec validated (no work done yet).

    Raises
    ------
    ValueError
        An unknown parameter (the message lists the valid names), a value that is not a number,
        not an integer where one is required, or outside the parameter's valid range (the
        message names the design, the parameter, the value and the range), a combination the
        tire file refuses (e.g. a belt wider than the section), or no design at all.
    """
    spec = stages.load_tire(tire)
    rows = design_rows(parameters)
    if not rows or not rows[0]:
        raise ValueError("parameters: no design; give at least one parameter with at least one value")
    table = _parameter_table(spec)
    _check_names(spec, list(rows[0]), table)
    _warn_switched_off(spec, rows[0])
    designs = []
    for index, row in enumerate(rows):
        overrides = {}
        for name, value in row.items():
            info = table.loc[name]
            where = f"design {index}: {name}"
            if info["integer"]:
                overrides[name] = guards.integer(where, value, int(info["low"]), info["high"])
            else:
                overrides[name] = guards.real(where, value, info["low"], info["high"], unit=info["unit"])
        design = Design(index, overrides, spec)
        try:
            design = Design(index, overrides, spec.replace(**overrides))
        except ValueError as exc:
            raise ValueError(f"{design.describe()}: {exc}") from exc
        designs.append(design)
    _warn_duplicates(designs)
    return designs


def _warn_switched_off(spec: Spec, names: Iterable[str]) -> None:
    """Warn when a swept parameter belongs to a sub-model the tire file switches off (``enabled = false``):
    it cannot change any output, so every design gives the same numbers."""
    idle = []
    for name in names:
        section = getattr(spec, name.split(".")[0], None)
        if getattr(section, "enabled", True) is False:
            idle.append(name)
    if idle:
        guards.warn(
            f"{idle} belong to a sub-model the tire file switches off ([{idle[0].split('.')[0]}] enabled = false): "
            "they cannot change any output; switch it on in the tire file to sweep them",
            4,
        )


def _warn_duplicates(designs: list[Design]) -> None:
    """Warn when two designs are the same tire (a grid axis listing a value twice): computed once, shown twice."""
    first: dict[tuple, int] = {}
    repeats = []
    for design in designs:
        key = tuple(sorted(design.overrides.items()))
        if key in first:
            repeats.append(f"design {design.index} = design {first[key]}")
        else:
            first[key] = design.index
    if repeats:
        guards.warn(f"{len(repeats)} design(s) repeat another ({', '.join(repeats[:5])}): a value listed twice?", 4)


def check_outputs(outputs: str | Iterable[str]) -> tuple[str, ...]:
    """The outputs asked for, in :data:`OUTPUTS` order; unknown names are refused with the valid ones."""
    asked = [outputs] if isinstance(outputs, str) else list(outputs)
    unknown = [o for o in asked if o not in OUTPUTS]
    if unknown or not asked:
        raise ValueError(f"outputs = {asked!r}: valid outputs are {list(OUTPUTS)} (at least one)")
    return tuple(o for o in OUTPUTS if o in asked)


def output_columns(outputs: Iterable[str]) -> list[str]:
    """The table columns of ``outputs``."""
    return [c for o in check_outputs(outputs) for c in OUTPUTS[o]]


# ---------------------------------------------------------------- one design's outputs


def design_outputs(spec: Spec, outputs: Sequence[str], conditions: SweepConditions) -> dict[str, float]:
    """The ``outputs`` of one tire design (uncached here; the experiments' own stages are cached).

    Returns ``column -> value`` in SI units (:data:`OUTPUTS`).
    """
    row: dict[str, float] = {}
    if "K_v" in outputs or "footprint" in outputs:
        static = stages.solve_static(spec, "flat")
        row["K_v (N/m)"] = float(static.vertical_stiffness)
        row["footprint_length (m)"] = float(static.footprint_length)
        row["footprint_width (m)"] = float(static.footprint_width)
    if "f1" in outputs or "zeta1" in outputs:
        values = calibration.calibration_values(spec)
        row["f1 (Hz)"] = float(values["first_vertical_resonance"])
        row["zeta1 (-)"] = float(values["first_vertical_damping"])
    if "cleat" in outputs:
        test = cleat.cleat_test(spec, conditions=conditions.cleat)
        row["cleat_quasi_static_peak (N)"] = test.quasi_static.peak_force
        row["cleat_dynamic_peak (N)"] = test.dynamic.peak_force
    if "one_sided" in outputs:
        contact = one_sided_cleat.one_sided_cleat_test(spec, conditions=conditions.one_sided)
        row["one_sided_quasi_static_peak (N)"] = contact.quasi_static.peak_force
        row["one_sided_dynamic_peak (N)"] = contact.dynamic.peak_force
    if "hub_acceleration" in outputs:
        setup = corner.corner_setup(conditions.vehicle, tire=spec)
        lo, hi = conditions.hub_band
        freqs = np.arange(lo, hi + HUB_STEP / 2, HUB_STEP)
        spectrum = conditions.road.spectra()[conditions.texture]
        psd = setup.predicted(freqs, spectrum, conditions.road.speed)["a_hub"]
        row["a_hub_rms (m/s^2)"] = band_rms((freqs, psd), conditions.hub_band)
    return {c: row[c] for c in output_columns(outputs)}


@dataclass(frozen=True)
class DesignResult:
    """What one design gave (plain numbers and strings: picklable, sent back from a worker).

    Attributes
    ----------
    values : dict of str to float
        Output column -> value (SI units).
    warnings : tuple of str
        The warnings its computation gave (kept with the cached result; a stage beneath it read
        from the stage cache does not warn again, so a design recomputed over cached stages may
        report fewer).
    computed : bool
        Computed in this call (False: read from the cache).
    seconds : float
        Wall time of this call (s).
    cpu_seconds : float
        CPU time of this process during the call, all its threads (s): against ``seconds``, the
        share of a core the design had.
    """

    values: dict[str, float]
    warnings: tuple[str, ...]
    computed: bool
    seconds: float
    cpu_seconds: float


#: Warnings a design's computation can meet that say nothing of its numbers: a file another part of the
#: process left open, collected meanwhile; a library's deprecation. Not kept with the design's values.
_NOT_THE_DESIGNS = (ResourceWarning, DeprecationWarning, PendingDeprecationWarning)


def evaluate_design(
    spec: Spec, outputs: Sequence[str], conditions: SweepConditions, cache: bool = True
) -> DesignResult:
    """One design's outputs, cached as one stage (``"sweep_design"``) unless ``cache`` is False.

    The key holds the design's full spec, the outputs, the conditions they use and the code of
    every experiment :func:`design_outputs` runs; the warnings the computation gave are kept
    with the values, so a result read back from the cache reports them too.
    """
    outputs = check_outputs(outputs)
    start, cpu = time.perf_counter(), time.process_time()
    computed = []

    def compute() -> tuple[dict[str, float], tuple[str, ...]]:
        computed.append(True)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            for unrelated in _NOT_THE_DESIGNS:  # the process's (a collected file, an import), not the numbers'
                warnings.simplefilter("ignore", unrelated)
            values = design_outputs(spec, outputs, conditions)
        return values, tuple(dict.fromkeys(str(w.message) for w in caught))

    if cache:
        inputs = {"tire": spec, "outputs": list(outputs), "conditions": conditions.used_by(outputs)}
        # this module's closure: every experiment design_outputs runs, and the stages beneath them
        values, caught = cached(evaluate_design, inputs, compute, runs=(evaluate_design, *stages.frf_runs(spec)))
    else:
        values, caught = compute()
    return DesignResult(dict(values), caught, bool(computed), time.perf_counter() - start, time.process_time() - cpu)
