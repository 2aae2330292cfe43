"""Export a tire of the collection (any tire model) as an FMU, its stages fetched from the stage cache.

:func:`export_fmu` asks the tire-model interface for the loaded footprint, the tasselli's fits
(Eq. 1-4) and the hub's (Eq. 6), the same cached stages every notebook uses, and writes the
moving-hub tire of Eq. 7 (:mod:`roadnoise_utils.fmu.export`). Every model exports the same way:
the ring, the cross-section tire, a tire read from the user's FRF files.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ..fmu.cosimulation import CoSimulationRun, cosimulate_quarter_car, leading_edge_heights
from ..fmu.drive import TireSlave
from ..fmu.export import write_fmu
from ..fmu.tables import TireTables, tire_tables
from ..repro import stages
from ..road.input import contact_tracks, texture_length
from ..tire.model import TireModel
from ..vehicle.corner import CornerRun, run_corner
from ..vehicle.spectra import OCTAVE_CENTRES, octave_rms, psd
from .corner import PAPER_CAR, CornerSetup, corner_setup
from .road import RoadTestConditions, road_test_conditions, texture_run


def fmu_tables(
    tire: str | Path | TireModel, speed: float, sample_rate: float | None = None, lateral: bool = True,
    road: str = "flat",
) -> TireTables:  # fmt: skip
    """The :class:`~roadnoise_utils.fmu.tables.TireTables` of ``tire`` (a name in ``data/tires``, a path or a
    model) loaded on ``road`` at its default load, at ``speed`` (m/s) and ``sample_rate`` (Hz)."""
    model = stages.tire_model(tire)
    model.require("hub_transfer")
    static = stages.solve_static(model, road)
    fits, hub = stages.fit_tasselli(model, road), stages.fit_hub(model, road)
    return tire_tables(fits, hub, static, speed, sample_rate, lateral)


def export_fmu(
    tire: str | Path | TireModel,
    path: str | Path,
    speed: float,
    sample_rate: float | None = None,
    lateral: bool = True,
    road: str = "flat",
    binary: bool = True,
) -> Path:
    """Write the moving-hub RM tire of ``tire`` as an FMI 2.0 co-simulation FMU; returns its path.

    Parameters
    ----------
    tire : str, Path or TireModel
        Any tire of the tire-model interface.
    path : str or Path
        The ``.fmu`` file to write (its folder must exist).
    speed : float
        Rolling speed (m/s), in (0, 100]: the FMU runs at this speed only (the road's flow through the
        footprint is built for it).
    sample_rate : float, optional
        Steps per second (Hz); default the simulation's own for the speed (:func:`roadnoise_utils.road.input.sample_rate_for`).
        The FMU takes this step only.
    lateral : bool
        One road input per lateral strip of the tread (a 3-D road); ``False``: one input, a road uniform
        across the width.
    road : str
        ``"flat"`` (default) or ``"drum"``: the loaded state the fits belong to.
    binary : bool
        Compile the C source for this platform (``False``: a source-only FMU).
    """
    return write_fmu(
        fmu_tables(tire, speed, sample_rate, lateral, road),
        path,
        f"roadnoise RM tire {stages.tire_model(tire).name}",
        binary,
    )


@dataclass(frozen=True, eq=False)
class FmuQuarterCar:
    """The road test's quarter car twice: ours (:func:`roadnoise_utils.experiments.corner.quarter_car`'s closed loop)
    and co-simulated with the tire FMU by a Python master (:func:`roadnoise_utils.fmu.cosimulation.cosimulate_quarter_car`).

    Attributes
    ----------
    setup : CornerSetup
    ours : CornerRun
    cosimulated : CoSimulationRun
    octaves : pandas.DataFrame
        Per output and octave band (centre Hz): the RMS of both runs (m/s^2) and their ratio minus one.
    fmu : Path
        The FMU driven.
    """

    setup: CornerSetup
    ours: CornerRun
    cosimulated: CoSimulationRun
    octaves: pd.DataFrame
    fmu: Path


def fmu_quarter_car(
    folder: str | Path, vehicle: str = PAPER_CAR, conditions: RoadTestConditions | None = None, texture: str = "rough"
) -> FmuQuarterCar:
    """Export the vehicle's tire as an FMU into ``folder`` and drive the road test's quarter car with it.

    The same road (``texture`` of ``conditions``, default the paper's road test, 3-D) enters both: ours as
    the tassello inputs of :func:`roadnoise_utils.experiments.road.texture_run`, the FMU as its heights at
    the leading edge, strip by strip. The step is the test's sample rate.
    """
    test = road_test_conditions() if conditions is None else conditions
    if texture not in test.textures:
        raise ValueError(f"texture = {texture!r}: the road test has {list(test.textures)}")
    setup = corner_setup(vehicle)
    path = Path(folder) / f"{setup.tire.name.replace('/', '_')}.fmu"
    ours, cosimulated = both_runs(setup, path, test, texture)
    rows = []
    for name in ("a_hub", "a_mount"):
        mine = octave_rms(psd(ours.outputs[name], ours.sample_rate))
        theirs = octave_rms(psd(cosimulated.outputs[name], cosimulated.sample_rate))
        for centre, a, b in zip(OCTAVE_CENTRES, mine, theirs):
            rows.append(
                {"output": name, "octave (Hz)": centre, "ours": a, "FMU co-simulation": b, "ratio - 1": b / a - 1}
            )
    return FmuQuarterCar(setup=setup, ours=ours, cosimulated=cosimulated, octaves=pd.DataFrame(rows), fmu=path)


def both_runs(
    setup: CornerSetup, path: Path, test: RoadTestConditions, texture: str
) -> tuple[CornerRun, CoSimulationRun]:
    """Our quarter car of ``setup`` on ``texture`` of ``test``, and the same car co-simulated with the tire
    exported to ``path`` at the test's speed and sample rate, on the same road."""
    spectrum = test.spectra()[texture]
    ours = run_corner(setup.sections, setup.model, texture_run(setup.static, spectrum, test, True))
    export_fmu(setup.tire, path, test.speed, test.sample_rate)
    road = stages.texture_road(
        spectrum, texture_length(spectrum, test.duration * test.speed), test.seed, contact_tracks(setup.static)
    )
    with TireSlave(path) as slave:
        heights = leading_edge_heights(road.as_3d(), slave, ours.t.size)
        cosimulated = cosimulate_quarter_car(slave, setup.vehicle, setup.tire_hub_mass, heights)
    return ours, cosimulated


def coupling_error(
    setup: CornerSetup, folder: str | Path, sample_rate: float, duration: float = 1.5, skip: float = 0.5
) -> float:
    """The co-simulation's coupling error at one step: the RMS of the co-simulated hub acceleration's
    difference from ours over ours, on the road test's rough road after the first ``skip`` seconds (s).

    The master holds the hub force over each step while the hub moves: an error of the first order in
    the step (1 / ``sample_rate``, Hz), which halves when the step halves. The first ``skip`` seconds
    hold the start-up transients, which differ between the two runs whatever the step (the FMU starts
    in the steady state of the road under its leading edge, our run with the road under the footprint).
    """
    test = road_test_conditions(duration=duration, textures=["rough"], sample_rate=sample_rate)
    ours, cosimulated = both_runs(setup, Path(folder) / f"car_{sample_rate:.0f}.fmu", test, "rough")
    late = ours.t >= skip
    if not late.any():
        raise ValueError(f"skip = {skip:g} s must be shorter than duration = {duration:g} s")
    difference = cosimulated.outputs["a_hub"][late] - ours.outputs["a_hub"][late]
    return float(np.sqrt(np.mean(difference**2) / np.mean(ours.outputs["a_hub"][late] ** 2)))
