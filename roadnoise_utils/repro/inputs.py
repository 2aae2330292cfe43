"""What the cached stages of both tire models share: the default frequency grid, the fit tolerance
and the resolved arguments of a loaded tire (the core of every cache key)."""

from __future__ import annotations

import numpy as np

from ..tire.static import make_road

#: Default frequency grid of the direct sweeps: 0-400 Hz every 1 Hz (paper: up to 250 Hz,
#: "easily improved to 400 Hz").
DEFAULT_FREQS = np.arange(0.0, 400.0 + 0.5, 1.0)
#: Relative RMS error every fit must meet when the order is chosen automatically.
FIT_TOLERANCE = 0.01


def loaded_inputs(tire_spec, road: str, load: float | None, drum_radius: float | None) -> dict:
    """The resolved arguments of a loaded tire of either model (its validated spec): the cache key's core."""
    surface = make_road(road, drum_radius)
    return {
        "tire": tire_spec,
        "road": surface.kind,
        "drum_radius": surface.drum_radius,
        "load": tire_spec.operating.vertical_load if load is None else float(load),
    }
