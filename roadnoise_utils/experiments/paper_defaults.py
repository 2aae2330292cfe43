"""The top-level entry points whose defaults are the paper's test.

``ru.solve_static(fet, road="drum")`` and ``ru.cleat_input(static, speed)`` need the drum and
the cleat of the paper's test when none is given. The numerics
(:func:`roadnoise_utils.tire.ring.static.solve_static`,
:func:`roadnoise_utils.road.cleat.cleat_input`) take them explicitly; these two functions fill
the ones left at ``None`` from ``data/conditions/cleat_test.toml``
(:func:`.cleat.cleat_conditions`) and call them.
"""

from __future__ import annotations

from ..road import cleat as road_cleat
from ..road.input import RoadInput
from ..tire.ring import static as tire_static
from ..tire.ring.mechanics import FETModel
from ..tire.ring.static import StaticState
from .cleat import cleat_conditions


def solve_static(
    fet: FETModel, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> StaticState:
    """:func:`roadnoise_utils.tire.ring.static.solve_static`, a drum defaulting to the paper's (R = 1.25 m).

    Parameters
    ----------
    fet : FETModel
        The tire (:func:`roadnoise_utils.tire.ring.mechanics.build_fet`).
    road : {"flat", "drum"}
        Road surface.
    load : float, optional
        Vertical load (N); default the tire's nominal load.
    drum_radius : float, optional
        Drum radius (m) for ``road="drum"``; default the cleat test's drum.
    """
    if road == "drum" and drum_radius is None:
        drum_radius = cleat_conditions().drum_radius
    return tire_static.solve_static(fet, road=road, load=load, drum_radius=drum_radius)


def cleat_input(
    static: StaticState,
    speed: float,
    height: float | None = None,
    base: float | None = None,
    shape: str | None = None,
    distance: tuple[float, float] = (-0.1, 0.5),
    sample_rate: float | None = None,
) -> RoadInput:
    """:func:`roadnoise_utils.road.cleat.cleat_input`, the cleat defaulting to the paper's (triangle, 15 x 15 mm).

    ``speed`` in m/s; ``height``, ``base`` and ``distance`` in m.
    """
    test = cleat_conditions(height=height, base=base, shape=shape)
    return road_cleat.cleat_input(static, speed, test.height, test.base, test.shape, distance, sample_rate)
