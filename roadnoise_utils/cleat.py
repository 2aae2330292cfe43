"""The cleat test on the drum with the hub fixed (paper stage 8, Fig. 8-9).

Paper, *Validation of the Model for Fixed Hub*: 165/65 R14, 4J rim, 2.3 bar, 4512 N, drum
R = 1.25 m, triangular cleat 15 mm base x 15 mm high, a quasi-static run ("base curve") and
one at 30 km/h ("dynamic curve"). Reported: two force peaks while the cleat crosses the
footprint; measured dynamic peak about 2.2 times the quasi-static one; simulated quasi-static
peak 1200 N against 850 N measured; the simulated dynamic peak "very close to the measured
one"; after the cleat has left, a decay dominated by the 80 Hz first vertical mode
(``data/paper/claims.toml`` keeps these numbers with their source).

This module runs the RM chain (fitted state-space tire, :mod:`.simulate`) and, as a second
method, the same cleat response straight from the viscoelastic FE model in the frequency
domain (no modal reduction, no fitting): :math:`F(\\omega) = \\sum_i H_i(\\omega) U_i(\\omega)`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .analysis import damped_components, force_peaks
from .fet import FETModel
from .frf import frf_visco
from .road import BAND, RoadInput
from .simulation import SimulationResult, simulate
from .static import StaticState


@dataclass(frozen=True, eq=False)
class CleatRun:
    """One cleat passage: the road input, the hub force and what we read from it.

    Attributes
    ----------
    result : SimulationResult
        Hub force history (N) against distance travelled (m).
    peaks : pandas.DataFrame
        The two largest force peaks (distance, force).
    decay : pandas.DataFrame or None
        Damped components of the free decay after the cleat has left the footprint (largest
        first), or ``None`` for a quasi-static run.
    """

    result: SimulationResult
    peaks: pd.DataFrame
    decay: pd.DataFrame | None

    @property
    def peak_force(self) -> float:
        """Largest hub force (N)."""
        return float(self.result.force.max())


def footprint_entry(static: StaticState) -> float:
    """Distance travelled (m) at which a feature's leading edge reaches the footprint kernels."""
    t = static.tasselli
    return float(-np.max(t.node_x + t.node_dx_plus))


def footprint_exit(static: StaticState, base: float) -> float:
    """Distance travelled (m) at which a feature of length ``base`` (m) has left the footprint kernels."""
    t = static.tasselli
    return float(base - np.min(t.node_x - t.node_dx_minus))


def analyse_run(result: SimulationResult, static: StaticState, base: float, dynamic: bool) -> CleatRun:
    """Peaks while the cleat crosses the footprint and, for a dynamic run, the free-decay components."""
    crossing = (footprint_entry(static), footprint_exit(static, base))
    peaks = force_peaks(result.distance, result.force, n=2, window=crossing)
    decay = None
    if dynamic:
        free = result.distance > footprint_exit(static, base) + 0.01
        decay = damped_components(result.force[free], float(result.t[1] - result.t[0]), n_components=6)
    return CleatRun(result=result, peaks=peaks, decay=decay)


def band_window(freqs: np.ndarray, band: float = BAND, taper: float = 50.0) -> np.ndarray:
    """Zero-phase low-pass: 1 up to ``band``, raised-cosine to 0 at ``band + taper`` Hz."""
    w = np.ones_like(freqs)
    ramp = (freqs > band) & (freqs < band + taper)
    w[ramp] = 0.5 * (1 + np.cos(np.pi * (freqs[ramp] - band) / taper))
    w[freqs >= band + taper] = 0.0
    return w


def band_limited(force: np.ndarray, dt: float, band: float = BAND, n_fft: int | None = None) -> np.ndarray:
    """``force`` low-passed by :func:`band_window` (zero phase, FFT), same length."""
    n = n_fft or force.size
    spectrum = np.fft.rfft(force, n)
    spectrum *= band_window(np.fft.rfftfreq(n, dt), band)
    return np.fft.irfft(spectrum, n)[: force.size]


def fe_cleat_response(
    fet: FETModel,
    static: StaticState,
    road: RoadInput,
    band: float = BAND,
    duration: float = 1.0,
    progress: bool = False,
) -> np.ndarray:
    """Hub force of ``road`` straight from the viscoelastic FE model, band-limited to ``band`` Hz.

    The tassello inputs are zero-padded to ``duration`` s (long enough for the decay), Fourier
    transformed, multiplied by the direct :math:`H_i(\\omega)` at every FFT bin up to the end of
    the :func:`band_window` taper, summed and transformed back.
    """
    dt = road.dt
    n = _record_length(road, duration)
    freqs = np.fft.rfftfreq(n, dt)
    window = band_window(freqs, band)
    keep = window > 0
    frf = frf_visco(fet, static, freqs[keep], progress=progress)
    spectrum = np.zeros(freqs.size, complex)
    spectrum[keep] = np.sum(frf.H * np.fft.rfft(road.u, n, axis=1)[:, keep], axis=0) * window[keep]
    return np.fft.irfft(spectrum, n)[: road.u.shape[1]]


def _record_length(road: RoadInput, duration: float) -> int:
    """Samples of the record both methods see: the road's, padded to ``duration`` s for the decay."""
    return max(road.u.shape[1], int(round(duration / road.dt)))


def rm_cleat_response(system, road: RoadInput, band: float = BAND, duration: float = 1.0) -> np.ndarray:
    """Hub force of ``road`` from the RM chain, on the same footing as :func:`fe_cleat_response`.

    The tassello inputs are zero-padded to ``duration`` s and simulated (:func:`.simulate`)
    from rest, so the free decay is complete before the record ends; the force is band-limited
    by the same :func:`band_window` (zero phase) and cut back to the road's length. Filtering a
    record cut short in mid-decay instead would smear the cut into the compared samples.
    """
    padded = road.padded(_record_length(road, duration))
    return band_limited(simulate(system, padded).force, road.dt, band)[: road.u.shape[1]]


def run_cleat(
    system,
    static: StaticState,
    speed: float,
    height: float | None = None,
    base: float | None = None,
    shape: str | None = None,
    distance: tuple[float, float] | None = None,
    dynamic: bool | None = None,
) -> CleatRun:
    """Simulate one cleat passage with the fixed-hub tire ``system`` and analyse it.

    ``system`` is the state-space tire (or its :func:`.simulate.modal_sections`); the cleat
    defaults to the paper's (``data/conditions/cleat_test.toml``). ``dynamic`` (default: speed
    above 1 m/s) asks for the free-decay analysis.
    """
    from .conditions import load_conditions
    from .road import cleat_input

    cleat = load_conditions("cleat_test")["cleat"]
    base = cleat["base"] if base is None else base
    road = cleat_input(static, speed, height=height, base=base, shape=shape, distance=distance)
    result = simulate(system, road)
    return analyse_run(result, static, base, speed > 1.0 if dynamic is None else dynamic)


def quasi_static_force(static_influence: np.ndarray, road: RoadInput) -> np.ndarray:
    """Hub force with no dynamics at all: :math:`\\sum_i H_i(0)\\,u_i` (N)."""
    return np.asarray(static_influence) @ road.u


def row_influence(static: StaticState, static_influence: np.ndarray) -> pd.DataFrame:
    """Static influence summed over each row of tasselli, with the row's position (leading row first)."""
    t = static.tasselli
    rows = np.unique(t.row)
    return pd.DataFrame(
        {
            "x centre (mm)": [1e3 * np.mean(t.centre_x[t.row == r]) for r in rows],
            "length (mm)": [1e3 * np.mean(t.length[t.row == r]) for r in rows],
            "H(0) of the row (N/mm)": [np.sum(static_influence[t.row == r]) / 1e3 for r in rows],
        },
        index=pd.Index(rows + 1, name="row"),
    )


def quasi_static_peak(fet: FETModel, static: StaticState, height: float, base: float, shape: str = "triangle") -> float:
    """Peak of :func:`quasi_static_force` for a cleat (N), from the FE model's static influences."""
    from .road import cleat_input

    h0 = frf_visco(fet, static, [0.0], progress=False).H[:, 0].real
    road = cleat_input(static, 0.1, height=height, base=base, shape=shape, distance=(-0.08, 0.1))
    return float(quasi_static_force(h0, road).max())
