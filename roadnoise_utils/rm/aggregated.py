"""The hub force of a road flowing through the footprint, aggregated: one kernel per road track (issue 16, item 1).

The per-tassello simulation (:func:`.simulation.simulate`) runs every modal section on its
tassello's input. On a road the inputs are not independent: tassello ``i`` sees its track
through its road-averaging kernel :math:`K_i`, shifted by its position,
:math:`u_i[k] = h\\sum_j K_i[j]\\, z[j + O k]` on a road grid ``O`` (``oversample``) times finer
than a time step (:func:`.road.input.profile_input`). With :math:`g_i` the exact first-order-hold
impulse response of tassello ``i`` (every section it drives, and its direct term), the hub force

.. math:: y[k] = \\sum_i (g_i * u_i)[k] + \\sum_i u_i[0]\\, f_i[k]

(:math:`f_i` the free response of the start-up state that makes each modal state start at zero,
as python-control does) is, per track and per phase ``p`` of the fine grid, one convolution of
the road with the kernel :math:`C_p = \\sum_i g_i \\star K_i^{(p)}`: polyphase, by FFT (scipy).
The kernels' road reaches ahead of the first sample; the inputs before it, which the simulation
does not have, are taken out exactly (their few samples through :math:`g_i`). The impulse
responses are cut where the slowest mode has decayed to :data:`DECAY` of its start.

Equal to :func:`.simulation.simulate` on :func:`.road.input.profile_input` to round-off (tested,
2-D and 3-D roads, two speeds and two sample rates); valid where a time step covers at least
:data:`.road.input.ROAD_GRID` of road (the road grid is then the time step's, as in
``profile_input``; slower runs are interpolated there and refused here).

**Speed so far** (``benchmarks/bench_road_simulation.py``, 195/65 R15, 2-D road, 9.6 kHz): at
2e6 samples 1.5 s and ~0.4 GB against 9.5 s and 2.4 GB per tassello; at 2e5 samples about even
(the impulse responses cover the slowest mode's 26 000-step memory). The issue's goals (>= 20x,
<= 100 MB at 2e6) are not reached yet: the road on the fine grid and the record-long spectra
dominate; not yet chosen by ``simulate`` itself.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.fft as sfft

from .. import guards
from ..road.input import ROAD_GRID, road_grid
from .simulation import ModalSections, as_continuous_statespace, foh_coefficients, modal_sections

#: The impulse responses are cut where the slowest mode has decayed to this fraction (-).
DECAY = 1e-17


def impulse_responses(sections: ModalSections, dt: float, n_samples: int) -> tuple[np.ndarray, np.ndarray]:
    """Per input: the exact FOH impulse response (direct term included) and the free response of the
    start-up state per unit first sample, both over ``n_samples`` steps, (n_inputs, n_samples) each.

    In closed form per section (:func:`.simulation.foh_coefficients`): with the state
    :math:`x_{k+1} = E x_k + \\gamma_0 v_k + \\gamma_1 v_{k+1}` and the output :math:`c\\,x` (twice
    its real part for a pair), the impulse gives :math:`c\\gamma_1` at step 0 and
    :math:`c(\\gamma_0 + E\\gamma_1)E^{m-1}` at step ``m``; the start-up state
    (:func:`.simulation.section_filter`) removes the first sample's ramp-in, :math:`-c\\gamma_1 E^m`
    (the state that a zero history with ``v_0`` already applied would carry). Summed per input in
    chunks of sections.
    """
    g = np.zeros((sections.n_inputs, n_samples))
    f = np.zeros((sections.n_inputs, n_samples))
    m = np.arange(n_samples)
    by_source = {}
    for section in sections.sections:
        by_source.setdefault(section.source, []).append(section)
    for source, members in by_source.items():
        for chunk in range(0, len(members), 32):
            part = members[chunk : chunk + 32]
            coeffs = np.array([foh_coefficients(s.pole, dt) for s in part])  # (k, 3): E, g0, g1
            gain = np.array([s.gain for s in part])
            pair = np.array([0.0 if s.pole.imag == 0.0 else 1.0 for s in part])
            scale = np.where(pair > 0, 2.0, 1.0)  # a pair is twice the real part of its upper member
            powers = np.exp(np.outer(np.array([s.pole for s in part]) * dt, m))  # E^m
            first = (gain * coeffs[:, 2])[:, None]
            h = np.empty((len(part), n_samples), complex)
            h[:, 0] = first[:, 0]
            h[:, 1:] = (gain * (coeffs[:, 1] + coeffs[:, 0] * coeffs[:, 2]))[:, None] * powers[:, :-1]
            g[source] += (scale[:, None] * h.real).sum(axis=0)
            f[source] += (scale[:, None] * (-first * powers).real).sum(axis=0)
    g[:, 0] += sections.direct
    return g, f


def memory_length(sections: ModalSections, dt: float) -> int:
    """Steps until the slowest mode has decayed to :data:`DECAY` (>= 2)."""
    slowest = max(section.pole.real for section in sections.sections)
    if slowest >= 0:
        raise ValueError("the aggregated simulation needs a stable model (every pole in the left half-plane)")
    return max(2, int(np.ceil(np.log(DECAY) / (slowest * dt))) + 1)


def _phases(values: np.ndarray, oversample: int, width: int) -> np.ndarray:
    """``values[..., p + O r]`` as (..., O, width), zero beyond the end."""
    padded = np.zeros(values.shape[:-1] + (oversample * width,))
    padded[..., : values.shape[-1]] = values
    return np.moveaxis(padded.reshape(values.shape[:-1] + (width, oversample)), -1, -2)


@dataclass(frozen=True, eq=False)
class RoadHubForce:
    """The hub force of a road (:func:`road_hub_force`): time (s), distance travelled (m), the force
    on the hub (N, upward, relative to the static preload), as :class:`.simulation.SimulationResult`
    without the tasselli's input histories (never formed)."""

    t: np.ndarray
    distance: np.ndarray
    force: np.ndarray
    speed: float


def road_hub_force(
    system,
    static,
    profile,
    speed: float,
    distance: tuple[float, float],
    sample_rate: float | None = None,
    oversample: int = 4,
) -> RoadHubForce:
    """The hub force of a road flowing through the footprint, aggregated per track (see the module notes).

    The arguments are those of :func:`.road.input.profile_input` and the tire ``system`` of
    :func:`.simulation.simulate` (or its :func:`.simulation.modal_sections`); the force equals
    :func:`.simulation.simulate`'s on that input.
    """
    sections = system if isinstance(system, ModalSections) else modal_sections(as_continuous_statespace(system))
    n_tasselli = static.tasselli.n
    if sections.n_inputs != n_tasselli:
        raise ValueError(f"system has {sections.n_inputs} inputs; the footprint has {n_tasselli} tasselli")

    def check(n: int, n_grid: int, step: float, dt: float) -> None:
        """The record's spectra, the road on the fine grid and the tasselli's responses, never the inputs."""
        memory = min(memory_length(sections, dt), n)
        n_bytes = 16.0 * (n + memory) * 4 + 8.0 * oversample * n_grid * 3 + 48.0 * n_tasselli * memory
        guards.check_memory(n_bytes, f"the aggregated simulation ({n} samples)", "speed and distance")

    where = road_grid(static, profile, speed, distance, sample_rate, oversample, check_memory=check)
    dt, n = float(where.t[1] - where.t[0]), where.t.size
    if not where.on_time_steps:
        raise ValueError(
            f"speed * dt = {where.speed * dt:g} m: the aggregated simulation needs >= {ROAD_GRID:g} m of road per "
            "step (slower runs are interpolated; use simulation.simulate on road.input.profile_input)"
        )
    length = min(memory_length(sections, dt), n)
    g, f = impulse_responses(sections, dt, length)
    step, o = where.step, where.oversample
    n_x = where.parts[0][2].shape[1]
    width = -(-n_x // o)
    n_fft = sfft.next_fast_len(n + length + 2 * width)
    n_small = sfft.next_fast_len(length + width)
    g_hat = sfft.rfft(g, n_small)
    spectrum = np.zeros(n_fft // 2 + 1, complex)
    start = np.zeros(n)
    first = np.zeros(n_tasselli)  # u_i[0]
    for parts, heights in where.tracks():
        kernels = np.zeros((n_tasselli, n_x))
        for _, rows, part in parts:
            kernels[rows] += part
        first += step * kernels @ heights[:n_x]
        k_p = _phases(kernels, o, width)  # (i, O, width)
        z_p = _phases(heights, o, n + width)  # (O, n + width)
        # C_p[l], l = -(width - 1) .. length - 1, stored from index 0: sum_i g_i * reversed K_i^p
        c_p = sfft.irfft(np.einsum("if,ipf->pf", g_hat, sfft.rfft(k_p[..., ::-1], n_small)), n_small)
        for p in range(o):  # one phase at a time: two spectra of the record in memory, not 2 O
            spectrum += sfft.rfft(c_p[p, : length + width - 1], n_fft) * sfft.rfft(z_p[p], n_fft)
        # the kernels' road before the first sample feeds inputs u_i[-width..-1] the simulation does not have
        pre = np.zeros((n_tasselli, width))
        for back in range(1, width + 1):
            seen = np.zeros((o, width))
            seen[:, back:] = z_p[:, : width - back]
            pre[:, width - back] = step * np.einsum("ipr,pr->i", k_p, seen)
        through = sfft.irfft(np.einsum("if,if->f", g_hat, sfft.rfft(pre, n_small)), n_small)
        stop = min(n, n_small - width)  # (g_i * pre_i)[k] sits at index k + width
        start[:stop] -= through[width : width + stop]
    force = step * sfft.irfft(spectrum, n_fft)[width - 1 : width - 1 + n] + start
    force[:length] += first @ f
    return RoadHubForce(t=where.t, distance=where.distance, force=force, speed=where.speed)
