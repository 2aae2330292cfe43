"""The paper's tests, each reading its ``data/conditions`` file once and returning a typed result.

============================  =================================================  ========
experiment                    what it runs                                       notebook
============================  =================================================  ========
:func:`cleat_test`            drum cleat, quasi-static and dynamic, FE check     04
:func:`one_sided_cleat_test`  the same with one-sided contact of the FE tire     08
:func:`moving_hub_check`      RM moving hub vs the FE tire with its hub free     05
:func:`road_test`             textures flowing through the footprint             06
:func:`quarter_car`           the corner on the road test, spectra               07
:func:`calibration_table`     the tire against its calibration targets           01
:func:`band_extension`        the chain at 0-250 and 0-400 Hz, cleat and road    10
:func:`whole_car_run`         the whole car on a 3-D road, spectra, checks       11
:func:`cavity.cavity_frfs`    the tire's FRFs with and without its air cavity    14
:func:`sweep`                 a grid or sample of tire designs on dask -> table  12
:func:`tire_as_files`         any tire model written as a tire from files        13
:func:`check_parameters`      the notebooks' other parameters, checked up front  01-13
:func:`export_fmu`            any tire as an FMI 2.0 co-simulation FMU           15
:func:`fmu_quarter_car`       the road test's quarter car co-simulated with it   15
:func:`coupling_error`        that co-simulation's error at one step             15
:mod:`loaded_tire`            the loaded FE tire's mesh, steps and load curves    16
============================  =================================================  ========

``*_conditions`` functions resolve a test's defaults (an argument left at ``None`` is the
paper's value); the numerics below them take explicit arguments and read no TOML.
"""

from . import (
    bands,
    calibration,
    cavity,
    cleat,
    conditions,
    corner,
    cross_section,
    design,
    design_sweep,
    fmu_export,
    loaded_tire,
    mf_swift,
    moving_hub,
    one_sided_cleat,
    paper_defaults,
    parameters,
    road,
    tire_models,
    whole_car,
)
from .bands import BandExtension, BandModel, band_extension
from .calibration import calibration_table
from .cleat import CleatConditions, CleatRun, CleatTest, cleat_conditions, cleat_test
from .corner import CornerSetup, QuarterCarTest, corner_setup, quarter_car
from .design_sweep import SweepError, sample, sweep
from .fmu_export import FmuQuarterCar, coupling_error, export_fmu, fmu_quarter_car
from .moving_hub import MovingHubCheck, Suspension, moving_hub_check, suspension_conditions
from .one_sided_cleat import (
    FrozenCheck,
    OneSidedCleatTest,
    OneSidedConditions,
    frozen_check,
    one_sided_cleat_test,
    one_sided_conditions,
    speed_sweep,
)
from .parameters import check_parameters
from .road import RoadTest, RoadTestConditions, road_test, road_test_conditions
from .tire_models import applicable, tire_as_files

__all__ = [
    "BandExtension",
    "BandModel",
    "band_extension",
    "check_parameters",
    "bands",
    "cross_section",
    "loaded_tire",
    "mf_swift",
    "CleatConditions",
    "CleatRun",
    "CleatTest",
    "CornerSetup",
    "FmuQuarterCar",
    "FrozenCheck",
    "OneSidedCleatTest",
    "OneSidedConditions",
    "MovingHubCheck",
    "QuarterCarTest",
    "RoadTest",
    "RoadTestConditions",
    "Suspension",
    "calibration",
    "coupling_error",
    "export_fmu",
    "fmu_export",
    "fmu_quarter_car",
    "cavity",
    "calibration_table",
    "cleat",
    "cleat_conditions",
    "cleat_test",
    "conditions",
    "corner",
    "corner_setup",
    "moving_hub",
    "moving_hub_check",
    "frozen_check",
    "one_sided_cleat",
    "one_sided_cleat_test",
    "one_sided_conditions",
    "paper_defaults",
    "parameters",
    "quarter_car",
    "road",
    "road_test",
    "road_test_conditions",
    "whole_car",
    "tire_models",
    "tire_as_files",
    "applicable",
    "speed_sweep",
    "SweepError",
    "design",
    "design_sweep",
    "sample",
    "sweep",
    "suspension_conditions",
]
