"""The rigid surface a tire stands on, shared by every tire model: a flat road or a drum.

The paper's cleat test runs on a drum of R = 1.25 m, its road test on the flat road
(*Validation of the Model for Fixed Hub*); every tire model loads its footprint on one of
these (:class:`.model.LoadCase`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import guards

#: Largest drum radius (m): test drums are 0.8-3 m; a radius in millimetres would pass unnoticed.
MAX_DRUM_RADIUS = 20.0


@dataclass(frozen=True, eq=False)
class RoadSurface:
    """A rigid road under the tire: flat (``drum_radius = inf``) or a drum of radius ``drum_radius`` (m).

    The surface height at the tire's longitudinal coordinate ``x`` is
    ``z(x) = top - (R - sqrt(R^2 - x^2))`` with ``top`` its highest point (under the axle).
    """

    kind: str
    drum_radius: float = np.inf

    def __post_init__(self) -> None:
        if self.kind not in ("flat", "drum"):
            raise ValueError(f"road = {self.kind!r}: valid values are 'flat' and 'drum'")
        if self.kind == "drum":
            # test drums are 0.8-3 m; 20 m is already nearly flat for a 0.1 m footprint: more is a unit slip
            guards.real("drum_radius", self.drum_radius, 0.3, MAX_DRUM_RADIUS, lo_open=True, unit="m")

    def drop(self, x: np.ndarray) -> np.ndarray:
        """How far the surface lies below its top at ``x`` (m)."""
        if self.kind == "flat":
            return np.zeros_like(x)
        r = self.drum_radius
        return r - np.sqrt(np.maximum(r**2 - x**2, 0.0))


def make_road(road: str, drum_radius: float | None = None) -> RoadSurface:
    """A :class:`RoadSurface` from its name and, for ``"drum"``, its radius (m).

    The radius has no default here: the test conditions (``data/conditions``) are resolved by
    :mod:`roadnoise_utils.experiments`, e.g. ``experiments.cleat_conditions().drum_radius``.
    """
    if road not in ("flat", "drum"):
        raise ValueError(f"road = {road!r}: valid values are 'flat' and 'drum'")
    if road == "flat":
        return RoadSurface("flat")
    if drum_radius is None:
        raise ValueError(
            f"drum_radius is required for road='drum': give the drum radius in m, valid range (0.3, {MAX_DRUM_RADIUS:g}]"
        )
    return RoadSurface("drum", guards.real("drum_radius", drum_radius, 0.3, MAX_DRUM_RADIUS, lo_open=True, unit="m"))
