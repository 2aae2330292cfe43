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
does not have, are taken out exactly. The impulse responses are cut where the slowest mode has
decayed to :data:`DECAY` of its start.

**Sums of exponentials.** Past its first sample a section's impulse response is
:math:`\\mathrm{Re}\\, a_s E_s^{m-1}` (:math:`E_s = e^{p_s h}`), so the kernels :math:`C_p[l]`,
the start-up state's free response and the response to the inputs before the first sample are
each one sum :math:`\\mathrm{Re}\\sum_s \\alpha_s E_s^k` over the sections: evaluated in blocks of
steps as two real matrix products with the powers of a block (:class:`_Powers`), never an FFT of
the tasselli's impulse responses.

**What is built once** (:func:`road_path`, kept for the last few tires and speeds): the kernels of
every track and phase and their spectra, which depend on the tire, the speed, the sample rate and
the road grid but not on the road. A repeated call for the same tire and speed costs the road's
evaluation, its overlap-save convolution and a few milliseconds (``benchmarks/bench_road_simulation.py``).

Equal to :func:`.simulation.simulate` on :func:`.road.input.profile_input` to round-off (tested,
2-D and 3-D roads, two speeds and two sample rates); valid where a time step covers at least
:data:`.road.input.ROAD_GRID` of road (the road grid is then the time step's, as in
``profile_input``; slower runs are interpolated there and refused here).

**Blocks.** The road is read once, in pieces (overlap-save blocks of :func:`block_size`, four
times the kernel), and checked as it is read: the memory is the record's time, travel and
force arrays plus the path's kernel spectra, whatever the record's length. It is an explicit
function, not a path :func:`.simulation.simulate` takes by itself: ``simulate`` gets the
tasselli's inputs, which this never forms.
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from dataclasses import dataclass, field

import numpy as np
import scipy.fft as sfft

from .. import guards
from ..road.input import ROAD_GRID, profile_input, road_grid
from ..tire.model import Footprint
from .simulation import ModalSections, as_continuous_statespace, foh_coefficients, modal_sections, simulate

#: The impulse responses are cut where the slowest mode has decayed to this fraction (-).
DECAY = 1e-17
#: Steps per block of the sums of exponentials (:class:`_Powers`).
POWER_BLOCK = 256
#: Paths (tire, speed, sample rate, road grid) kept by :func:`road_path` for repeated calls.
PATHS_KEPT = 4


def impulse_responses(sections: ModalSections, dt: float, n_samples: int) -> tuple[np.ndarray, np.ndarray]:
    """Per input: the exact FOH impulse response (direct term included) and the free response of the
    start-up state per unit first sample, both over ``n_samples`` steps, (n_inputs, n_samples) each.

    In closed form per section (:func:`.simulation.foh_coefficients`): with the state
    :math:`x_{k+1} = E x_k + \\gamma_0 v_k + \\gamma_1 v_{k+1}` and the output :math:`c\\,x` (twice
    its real part for a pair), the impulse gives :math:`c\\gamma_1` at step 0 and
    :math:`c(\\gamma_0 + E\\gamma_1)E^{m-1}` at step ``m``; the start-up state
    (:func:`.simulation.section_filter`) removes the first sample's ramp-in, :math:`-c\\gamma_1 E^m`
    (the state that a zero history with ``v_0`` already applied would carry).
    """
    terms = _SectionTerms.of(sections, dt)
    powers = _Powers(terms.e, n_samples)
    g = np.zeros((sections.n_inputs, n_samples))
    f = np.zeros((sections.n_inputs, n_samples))
    for source in range(sections.n_inputs):
        mine = terms.source == source
        if not mine.any():
            continue
        g[source, 1:] = powers.sums(terms.a[mine], np.nonzero(mine)[0])[: n_samples - 1]
        f[source] = -powers.sums(terms.b[mine], np.nonzero(mine)[0])
    g[:, 0] = terms.first
    return g, f


@dataclass(frozen=True, eq=False)
class _SectionTerms:
    """Per modal section: the pole's step factor ``e`` (:math:`E = e^{ph}`), the input it is driven by, and the
    coefficients of its impulse response past the first sample, ``a`` (:math:`\\sigma c (\\gamma_0 + E \\gamma_1)`),
    and at it, ``b`` (:math:`\\sigma c \\gamma_1`; :math:`\\sigma` = 2 for a conjugate pair: twice the real part);
    ``first`` (n_inputs,) the impulse responses' first samples, direct terms included."""

    e: np.ndarray
    source: np.ndarray
    a: np.ndarray
    b: np.ndarray
    first: np.ndarray

    @classmethod
    def of(cls, sections: ModalSections, dt: float) -> _SectionTerms:
        coeffs = np.array([foh_coefficients(s.pole, dt) for s in sections.sections]).reshape(-1, 3)
        gain = np.array([s.gain for s in sections.sections], complex)
        scale = np.array([1.0 if s.pole.imag == 0.0 else 2.0 for s in sections.sections])
        source = np.array([s.source for s in sections.sections], int)
        b = scale * gain * coeffs[:, 2]
        first = np.asarray(sections.direct, float).copy()
        np.add.at(first, source, b.real)
        return cls(coeffs[:, 0], source, scale * gain * (coeffs[:, 1] + coeffs[:, 0] * coeffs[:, 2]), b, first)


class _Powers:
    """:math:`\\mathrm{Re} \\sum_s \\alpha_s E_s^k` for ``k < n``, as two real matrix products per call.

    With ``k = q B + r``: :math:`\\sum_s (\\alpha_s E_s^{qB})\\, E_s^r`, the block's powers
    :math:`E_s^r` (S, B) and the blocks' first powers :math:`E_s^{qB}` (S, Q) computed once.
    """

    def __init__(self, e: np.ndarray, n: int, block: int = POWER_BLOCK):
        self.n, self.block = int(n), int(block)
        n_blocks = max(1, -(-self.n // self.block))
        log = np.log(e.astype(complex))
        inner = np.exp(np.outer(log, np.arange(self.block)))  # (S, B)
        self._inner = (np.ascontiguousarray(inner.real), np.ascontiguousarray(inner.imag))
        self._outer = np.exp(np.outer(log, self.block * np.arange(n_blocks))).T  # (Q, S)

    def sums(self, alpha: np.ndarray, rows: np.ndarray | slice = slice(None)) -> np.ndarray:
        """:math:`\\mathrm{Re} \\sum_s \\alpha_s E_s^k`, k < n, over the sections ``rows`` (``alpha`` one per row),
        or a batch: ``alpha`` (m, rows) gives (m, n)."""
        alpha = np.asarray(alpha, complex)
        batch = alpha.ndim == 2
        alpha = np.atleast_2d(alpha)
        w = alpha[:, None, :] * self._outer[None, :, rows]  # (m, Q, S)
        real, imag = self._inner[0][rows], self._inner[1][rows]
        out = (w.real @ real - w.imag @ imag).reshape(alpha.shape[0], -1)[:, : self.n]
        return out if batch else out[0]


def _phases(values: np.ndarray, oversample: int, width: int) -> np.ndarray:
    """``values[..., p + O r]`` as (..., O, width), zero beyond the end."""
    padded = np.zeros(values.shape[:-1] + (oversample * width,))
    padded[..., : values.shape[-1]] = values
    return np.moveaxis(padded.reshape(values.shape[:-1] + (width, oversample)), -1, -2)


@dataclass(frozen=True, eq=False)
class _Track:
    """One road track's kernels: the tasselli it drives (``rows``), their kernels by phase ``k_p`` (rows, O, width),
    the sections those tasselli drive (``sections``, indices) and each one's tassello among ``rows`` (``section_rows``),
    and the track's kernels :math:`C_p` (O, L + width - 1) with their spectra per overlap-save length (filled on
    first use)."""

    rows: np.ndarray
    k_p: np.ndarray
    sections: np.ndarray
    section_rows: np.ndarray
    c_p: np.ndarray
    spectra: dict = field(default_factory=dict)

    def spectrum(self, n_fft: int) -> np.ndarray:
        """rfft of the kernels at the overlap-save length ``n_fft``, (O, n_fft // 2 + 1)."""
        if n_fft not in self.spectra:
            self.spectra[n_fft] = sfft.rfft(self.c_p, n_fft)
        return self.spectra[n_fft]


@dataclass(frozen=True, eq=False)
class RoadPath:
    """What the hub force of a road depends on besides the road (:func:`road_path`): the tire's modal sections at
    a time step ``dt`` (s), the road grid's ``width`` (samples per phase of a kernel), ``oversample`` and the
    impulse responses' ``length`` (steps), the kernels of every track and the sums of exponentials' powers."""

    dt: float
    oversample: int
    width: int
    length: int
    terms: _SectionTerms
    powers: _Powers
    tail: np.ndarray  # (S, width): E_s^(b - 1), b = 1 .. width: the inputs before the first sample
    tracks: list


def _track(terms: _SectionTerms, powers: _Powers, kernels: np.ndarray, rows: np.ndarray, o: int, width: int,
           length: int) -> _Track:  # fmt: skip
    """The kernels :math:`C_p[l] = \\sum_i \\sum_j g_i[l + j] K_i^p[j]`, ``l = -(width - 1) .. length - 1`` (stored from
    index 0), of the tasselli ``rows`` with their ``kernels`` (rows, n_x), from the sections' exponentials."""
    k_p = _phases(kernels, o, width)  # (rows, O, width)
    position = np.full(terms.first.size, -1)
    position[rows] = np.arange(rows.size)
    sections = np.nonzero(position[terms.source] >= 0)[0]
    section_rows = position[terms.source[sections]]
    mine = k_p[section_rows]  # (S_t, O, width): each section's tassello's kernels
    e = terms.e[sections][:, None]
    # T[t] = sum_{j >= t} E^(j - t) K[j]: T[width] = 0, T[t] = K[t] + E T[t + 1]
    tails = np.zeros((width + 1,) + mine.shape[:2], complex)
    for t in range(width - 1, -1, -1):
        tails[t] = mine[:, :, t] + e * tails[t + 1]
    a = terms.a[sections][:, None]
    c_p = np.zeros((o, length + width - 1))
    # l >= 1: every term past the first sample, Re sum_s a_s T_s[0] E_s^(l - 1)
    c_p[:, width:] = powers.sums((a * tails[0]).T, sections)[:, : length - 1]
    # l = -(width - 1) .. 0: the first samples g_i[0] K_i[-l] and the sections' partial sums a_s T_s[1 - l]
    for l_index in range(width):
        lag = l_index - (width - 1)  # l
        c_p[:, l_index] = terms.first[rows] @ k_p[:, :, -lag] + np.real(np.sum(a * tails[1 - lag], axis=0))
    return _Track(rows=rows, k_p=k_p, sections=sections, section_rows=section_rows, c_p=c_p)


#: The last paths built (:func:`road_path`), most recent last.
_PATHS: OrderedDict[str, RoadPath] = OrderedDict()


def _digest(sections: ModalSections, parts: list, numbers: tuple) -> str:
    """A key of everything a :class:`RoadPath` depends on: the sections, the road grid's kernels, dt, O, lengths."""
    digest = hashlib.blake2b(repr(numbers).encode(), digest_size=16)
    for s in sections.sections:
        digest.update(np.array([s.pole.real, s.pole.imag, s.gain.real, s.gain.imag, s.source], float).tobytes())
    digest.update(np.asarray(sections.direct, float).tobytes())
    for strip, rows, kernel in parts:
        digest.update(np.asarray([strip], float).tobytes() + rows.tobytes() + np.ascontiguousarray(kernel).tobytes())
    return digest.hexdigest()


def road_path(sections: ModalSections, parts: list, lateral: bool, dt: float, oversample: int, length: int) -> RoadPath:
    """The :class:`RoadPath` of a tire's ``sections`` on the road grid's strip kernels ``parts``
    (:func:`.road.kernels.strip_kernels`; one track for a 2-D road, one per strip for a ``lateral`` 3-D one) at a
    time step ``dt`` (s), built once and kept (the last :data:`PATHS_KEPT`)."""
    key = _digest(sections, parts, (bool(lateral), float(dt), int(oversample), int(length)))
    if key in _PATHS:
        _PATHS.move_to_end(key)
        return _PATHS[key]
    n_inputs = sections.n_inputs
    n_x = parts[0][2].shape[1]
    width = -(-n_x // oversample)
    terms = _SectionTerms.of(sections, dt)
    powers = _Powers(terms.e, max(length, 1))
    tail = np.exp(np.outer(np.log(terms.e.astype(complex)), np.arange(width)))
    groups = [parts] if not lateral else [[part] for part in parts]
    tracks = []
    for group in groups:
        kernels = np.zeros((n_inputs, n_x))
        for _, rows, part in group:
            kernels[rows] += part
        rows = np.unique(np.concatenate([rows for _, rows, _ in group]))
        tracks.append(_track(terms, powers, kernels[rows], rows, oversample, width, length))
    path = RoadPath(dt=float(dt), oversample=int(oversample), width=width, length=int(length), terms=terms,
                    powers=powers, tail=tail, tracks=tracks)  # fmt: skip
    _PATHS[key] = path
    while len(_PATHS) > PATHS_KEPT:
        _PATHS.popitem(last=False)
    return path


def memory_length(sections: ModalSections, dt: float) -> int:
    """Steps until the slowest mode has decayed to :data:`DECAY` (>= 2)."""
    slowest = max(section.pole.real for section in sections.sections)
    if slowest >= 0:
        raise ValueError("the aggregated simulation needs a stable model (every pole in the left half-plane)")
    return max(2, int(np.ceil(np.log(DECAY) / (slowest * dt))) + 1)


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
    force arrays; what does not depend on the road is built once per tire and speed (:func:`road_path`).
    A model with blocks that have no modal form (:class:`.simulation.ExactBlock`: repeated poles)
    is simulated by :func:`.simulation.simulate` on :func:`.road.input.profile_input` instead.
    """
    if not isinstance(static, Footprint):
        raise TypeError(
            f"static must be a Footprint (the loaded tire, e.g. stages.solve_static), got {type(static).__name__}"
        )
    sections = system if isinstance(system, ModalSections) else modal_sections(as_continuous_statespace(system))
    n_tasselli = static.tasselli.n
    if sections.n_inputs != n_tasselli:
        raise ValueError(f"system has {sections.n_inputs} inputs; the footprint has {n_tasselli} tasselli")
    if sections.blocks:  # repeated poles: no sums of exponentials; the inputs formed and simulated exactly
        road = profile_input(static, profile, speed, distance, sample_rate, oversample)
        return RoadHubForce(t=road.t, distance=road.distance, force=simulate(sections, road).force, speed=road.speed)

    def check(n: int, n_grid: int, step: float, dt: float) -> None:
        """The record's time, travel and force, the path's kernels and spectra and one block's spectra."""
        memory = min(memory_length(sections, dt), n)
        n_block = block_size(memory + 64)
        n_bytes = 8.0 * 3 * n + 8.0 * 4 * len(sections.sections) * (memory // POWER_BLOCK + POWER_BLOCK)
        n_bytes += 8.0 * (3 * oversample + 4) * n_block * (1 + static.tasselli.node_strip.max())
        guards.check_memory(n_bytes, f"the aggregated simulation ({n} samples)", "speed and distance")

    where = road_grid(static, profile, speed, distance, sample_rate, oversample, check_memory=check)
    dt, n = float(where.t[1] - where.t[0]), where.t.size
    if not where.on_time_steps:
        raise ValueError(
            f"speed * dt = {where.speed * dt:g} m: the aggregated simulation needs >= {ROAD_GRID:g} m of road per "
            "step (slower runs are interpolated; use simulation.simulate on road.input.profile_input)"
        )
    length = min(memory_length(sections, dt), n)
    path = road_path(sections, where.parts, where.lateral, dt, where.oversample, length)
    step, o, width = where.step, where.oversample, path.width
    force = np.zeros(n)
    alpha = np.zeros(len(sections.sections), complex)
    for track, (_, heights) in zip(path.tracks, where.track_heights()):
        start = _phases(heights(0, o * width), o, width)  # (O, width): z_p[r], r < width
        _convolve_blocks(force, track, width, heights, o, step)
        alpha += _start_terms(path, track, start, step)
    force[: min(path.length, n)] += path.powers.sums(alpha)[: min(path.length, n)]
    return RoadHubForce(t=where.t, distance=where.distance, force=force, speed=where.speed)


def _start_terms(path: RoadPath, track: _Track, start: np.ndarray, step: float) -> np.ndarray:
    """The coefficients :math:`\\alpha_s` (S,) of one track's share of the start-up state's free response and of
    the response to the inputs before the first sample (taken out), both :math:`\\mathrm{Re}\\sum_s \\alpha_s E_s^k`.

    The first input :math:`u_i[0] = h \\sum_{p,r} K_i^p[r] z_p[r]` starts the free response :math:`-b_s u_i[0] E^k`;
    an input :math:`u_i[-b] = h \\sum_p \\sum_{r \\ge b} K_i^p[r] z_p[r - b]` (``b = 1 .. width``) reaches step ``k``
    as :math:`a_s E^{k + b - 1} u_i[-b]`.
    """
    k_p, width = track.k_p, path.width
    first = step * np.einsum("ipr,pr->i", k_p, start)
    before = np.zeros((track.rows.size, width))  # column b - 1: u_i[-b]
    for back in range(1, width):
        before[:, back - 1] = step * np.einsum("ipr,pr->i", k_p[:, :, back:], start[:, : width - back])
    s, mine = track.sections, track.section_rows
    alpha = np.zeros(path.terms.e.size, complex)
    alpha[s] = -path.terms.b[s] * first[mine] - path.terms.a[s] * np.einsum("sb,sb->s", path.tail[s], before[mine])
    return alpha


def block_size(kernel_length: int) -> int:
    """FFT length of the overlap-save blocks for a kernel of ``kernel_length`` samples (4x it, at least 2^16)."""
    return sfft.next_fast_len(max(4 * kernel_length, 1 << 16), real=True)


def _convolve_blocks(force: np.ndarray, track: _Track, width: int, heights, oversample: int, step: float) -> None:
    """``force[k] += step sum_p (C_p * z_p)[k + width - 1]`` by overlap-save in blocks, the road read once.

    ``z_p[r] = heights(p + O r)`` (zero before the road and past its end), ``C_p`` the track's kernels of ``L``
    samples. A block of ``B`` outputs from ``k0`` needs ``z_p`` from ``r0 = k0 + width - L`` on: the FFT of
    ``N = B + L - 1`` road samples per phase (:func:`block_size`), whose last ``B`` circular outputs are the linear
    ones; the next block keeps the last ``L - 1`` and reads ``B`` new ones.
    """
    n, o, kernel = force.size, oversample, track.c_p.shape[1]
    n_fft = block_size(kernel)
    c_hat = track.spectrum(n_fft)
    outputs = n_fft - kernel + 1
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
