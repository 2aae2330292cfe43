"""The hub force of a road flowing through the footprint, aggregated: one kernel per road track.

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

**Blocks.** The road is read once, in pieces (overlap-save blocks of :func:`block_size`, four
times the kernel), and checked as it is read: the memory is the record's time, travel and
force arrays plus a fixed ~40 MB (the impulse responses and one block's spectra), whatever the
record's length.

**Speed** (``benchmarks/bench_road_simulation.py``, 195/65 R15, 2-D road, 9.6 kHz, the book's
"Performance" page): at 2e6 samples 0.24-0.84 s and 90 MB against 6.8-32.8 s and 2.3 GB per tassello. It is
an explicit function, not a path :func:`.simulation.simulate` takes by itself: ``simulate`` gets
the tasselli's inputs, which this never forms.
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
    (the state that a zero history with ``v_0`` already applied would carry). Summed per input as one
    product with the powers :math:`E^m` (:func:`_powers`).
    """
    g = np.zeros((sections.n_inputs, n_samples))
    f = np.zeros((sections.n_inputs, n_samples))
    by_source = {}
    for section in sections.sections:
        by_source.setdefault(section.source, []).append(section)
    for source, members in by_source.items():
        coeffs = np.array([foh_coefficients(s.pole, dt) for s in members])  # (k, 3): E, g0, g1
        gain = np.array([s.gain for s in members])
        scale = np.array([1.0 if s.pole.imag == 0.0 else 2.0 for s in members])  # a pair: twice the real part
        powers = _powers(np.array([s.pole for s in members]) * dt, n_samples)  # E^m, (k, n)
        first = scale * gain * coeffs[:, 2]
        g[source, 0] = first.sum().real
        g[source, 1:] = ((scale * gain * (coeffs[:, 1] + coeffs[:, 0] * coeffs[:, 2])) @ powers[:, :-1]).real
        f[source] = -(first @ powers).real
    g[:, 0] += sections.direct
    return g, f


def _powers(exponents: np.ndarray, n_samples: int, block: int = 256) -> np.ndarray:
    """:math:`e^{a m}` for every exponent ``a`` and step ``m < n_samples``, (k, n): a block of powers times
    the powers of the block (one complex product per entry instead of an exponential)."""
    n_blocks = -(-n_samples // block)
    inner = np.exp(np.outer(exponents, np.arange(block)))
    outer = np.exp(np.outer(exponents, block * np.arange(n_blocks)))
    return (outer[:, :, None] * inner[:, None, :]).reshape(exponents.size, -1)[:, :n_samples]


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
    :func:`.simulation.simulate`'s on that input. The road is read in pieces of :func:`block_size`
    samples (overlap-save), so the memory does not grow with the record beyond its time, travel and
    force arrays.
    """
    sections = system if isinstance(system, ModalSections) else modal_sections(as_continuous_statespace(system))
    n_tasselli = static.tasselli.n
    if sections.n_inputs != n_tasselli:
        raise ValueError(f"system has {sections.n_inputs} inputs; the footprint has {n_tasselli} tasselli")

    def check(n: int, n_grid: int, step: float, dt: float) -> None:
        """The record's time, travel and force, the tasselli's responses and one block's spectra."""
        memory = min(memory_length(sections, dt), n)
        n_block = block_size(memory + 64)
        n_bytes = 8.0 * 3 * n + 8.0 * 4 * n_tasselli * memory + 8.0 * (3 * oversample + 4) * n_block
        guards.check_memory(n_bytes, f"the aggregated simulation ({n} samples)", "speed and distance")

    where = road_grid(static, profile, speed, distance, sample_rate, oversample, check_memory=check)
    dt, n = float(where.t[1] - where.t[0]), where.t.size
    if not where.on_time_steps:
        raise ValueError(
            f"speed * dt = {where.speed * dt:g} m: the aggregated simulation needs >= {ROAD_GRID:g} m of road per "
            "step (slower runs are interpolated; use simulation.simulate on road.input.profile_input)"
        )
    length = min(memory_length(sections, dt), n)
    step, o = where.step, where.oversample
    n_x = where.parts[0][2].shape[1]
    width = -(-n_x // o)
    tracks = []  # (kernels, heights, the first o * width heights) per track
    first = np.zeros(n_tasselli)  # u_i[0]
    for parts, heights in where.track_heights():
        kernels = np.zeros((n_tasselli, n_x))
        for _, rows, part in parts:
            kernels[rows] += part
        start = heights(0, o * width)
        first += step * kernels @ start[:n_x]
        tracks.append((kernels, heights, start))
    g, f = impulse_responses(sections, dt, length)
    free = first @ f  # the start-up state's free response
    del f
    n_small = sfft.next_fast_len(length + width)
    g_hat = sfft.rfft(g, n_small)
    del g
    force = np.zeros(n)
    for kernels, heights, start in tracks:
        k_p = _phases(kernels, o, width)  # (i, O, width)
        # C_p[l], l = -(width - 1) .. length - 1, stored from index 0: sum_i g_i * reversed K_i^p
        c_p = np.array(  # one phase at a time: the tasselli's kernel spectra of one phase in memory
            [sfft.irfft(np.einsum("if,if->f", g_hat, sfft.rfft(k_p[:, p, ::-1], n_small)), n_small) for p in range(o)]
        )
        _convolve_blocks(force, c_p[:, : length + width - 1], heights, o, step, width)
        force[: n_small - width] -= _before_start(g_hat, k_p, _phases(start, o, width), step, n_small)[:n]
    force[:length] += free
    return RoadHubForce(t=where.t, distance=where.distance, force=force, speed=where.speed)


def block_size(kernel_length: int) -> int:
    """FFT length of the overlap-save blocks for a kernel of ``kernel_length`` samples (4x it, at least 2^16)."""
    return sfft.next_fast_len(max(4 * kernel_length, 1 << 16), real=True)


def _convolve_blocks(force: np.ndarray, c_p: np.ndarray, heights, oversample: int, step: float, width: int) -> None:
    """``force[k] += step sum_p (C_p * z_p)[k + width - 1]`` by overlap-save in blocks, the road read once.

    ``z_p[r] = heights(p + O r)`` (zero before the road and past its end), ``C_p`` of ``L`` samples.
    A block of ``B`` outputs from ``k0`` needs ``z_p`` from ``r0 = k0 + width - L`` on: the FFT of
    ``N = B + L - 1`` road samples per phase, whose last ``B`` circular outputs are the linear ones;
    the next block keeps the last ``L - 1`` and reads ``B`` new ones.
    """
    n, o, kernel = force.size, oversample, c_p.shape[1]
    n_fft = block_size(kernel)
    outputs = n_fft - kernel + 1
    c_hat = sfft.rfft(c_p, n_fft)
    window = None
    for k0 in range(0, n, outputs):
        r0 = k0 + width - kernel
        if window is None:
            window = heights(o * r0, o * (r0 + n_fft))
        else:
            window = np.concatenate([window[o * outputs :], heights(o * (r0 + kernel - 1), o * (r0 + n_fft))])
        spectra = sfft.rfft(window.reshape(n_fft, o).T, axis=-1)  # (O, n_fft // 2 + 1)
        block = sfft.irfft(np.einsum("pf,pf->f", spectra, c_hat), n_fft)[kernel - 1 :]
        stop = min(outputs, n - k0)
        force[k0 : k0 + stop] += step * block[:stop]


def _before_start(g_hat: np.ndarray, k_p: np.ndarray, z_start: np.ndarray, step: float, n_small: int) -> np.ndarray:
    """The share of the inputs :math:`u_i[-w .. -1]` (the kernels' road before the first sample, which the
    simulation does not have) in the force, from step 0: :math:`\\sum_i g_i * pre_i` shifted by ``w``."""
    width = k_p.shape[-1]
    o = k_p.shape[1]
    pre = np.zeros((k_p.shape[0], width))
    for back in range(1, width + 1):
        seen = np.zeros((o, width))
        seen[:, back:] = z_start[:, : width - back]
        pre[:, width - back] = step * np.einsum("ipr,pr->i", k_p, seen)
    through = sfft.irfft(np.einsum("if,if->f", g_hat, sfft.rfft(pre, n_small)), n_small)
    return through[width:]
