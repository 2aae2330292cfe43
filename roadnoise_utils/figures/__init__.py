"""The collection's figures, a module per chapter (notebooks 13 and 14 reuse the others'), shared helpers in ``common``.

Each figure mirrors a figure of the paper where there is one (same axes and units, paper units
at this edge only) and draws the paper's own numbers as labelled reference lines
(:func:`.common.paper_lines`).
"""

from . import (
    band_extension,
    cleat_test,
    common,
    contact_loss,
    cross_section,
    design_exploration,
    fe_tire_model,
    loaded_tire,
    moving_hub,
    overview,
    quarter_car,
    road_input,
    superposition,
    tassello_fitting,
    vehicle_tools,
    whole_car,
)

__all__ = [
    "band_extension",
    "cleat_test",
    "common",
    "contact_loss",
    "cross_section",
    "design_exploration",
    "fe_tire_model",
    "loaded_tire",
    "moving_hub",
    "overview",
    "quarter_car",
    "road_input",
    "superposition",
    "tassello_fitting",
    "vehicle_tools",
    "whole_car",
]
