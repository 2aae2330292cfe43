"""Small valid inputs the adversarial cases spoil one parameter at a time (built once, in well under a second).

A synthetic three-tassello FRF set from a known two-mode model (no FE solve), its fits and state space, the
coarse ring tire's footprint on the flat road, a short road input and a rough-road profile: every call the
cases make is one bad argument away from a valid, fast call.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

import roadnoise_utils as ru

#: The coarse ring tire of the property tests (7 strips x 260 elements).
COARSE_RING = {"mesh.n_strips": 7, "mesh.n_elements": 260, "tasselli.strips_per_column": 1}


def two_mode_frf(freqs: np.ndarray, n_tasselli: int = 3) -> np.ndarray:
    """(n_tasselli, n_f) receptance-like FRFs of two damped modes (80 and 150 Hz), a static value each."""
    s = 2j * np.pi * freqs
    rows = []
    for i in range(n_tasselli):
        modes = sum(
            (1.0 + 0.3 * i) * w**2 / (s**2 + 2 * 0.05 * w * s + w**2) for w in (2 * np.pi * 80.0, 2 * np.pi * 150.0)
        )
        rows.append(1e4 * (1.0 + 0.1 * i) * modes)
    return np.array(rows)


@dataclass(frozen=True)
class Inputs:
    """The valid inputs (see the module's docstring)."""

    freqs: np.ndarray
    H: np.ndarray
    frf: ru.FRFResult
    fits: ru.FitSet
    system: object
    spec: object
    fet: object
    flat: object
    road: ru.RoadInput
    profile: object
    footprint_system: object


@cache
def inputs() -> Inputs:
    freqs = np.arange(0.0, 251.0, 1.0)
    H = two_mode_frf(freqs)
    frf = ru.FRFResult(freqs=freqs, H=H, H_tot=H.sum(axis=0), G_H=None, H_points=None, method="synthetic")
    fits = ru.fit_tasselli(freqs, H, n_poles=4)
    system = ru.assemble_fixed_hub(fits)
    spec = ru.load_tire("165_65R14").replace(**COARSE_RING)
    fet = ru.build_fet(spec)
    flat = ru.solve_static(fet, road="flat")
    n = 200
    t = np.arange(n) / 10000.0
    road = ru.RoadInput(t=t, distance=10.0 * t, u=np.zeros((3, n)), speed=10.0, description="flat")
    profile = ru.road.generate_profile(ru.road.load_texture("rough"), 60.0, 0.005, seed=1)
    # one synthetic fit per tassello of the coarse footprint: a state space the footprint's road can drive
    footprint_system = ru.assemble_fixed_hub(ru.fit_tasselli(freqs, two_mode_frf(freqs, flat.tasselli.n), n_poles=4))
    return Inputs(freqs, H, frf, fits, system, spec, fet, flat, road, profile, footprint_system)
