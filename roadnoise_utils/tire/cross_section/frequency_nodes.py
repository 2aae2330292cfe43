r"""Smooth harmonics of the cross-section footprint, evaluated on frequency nodes and interpolated.

A harmonic with no resonance near the band (:func:`is_smooth`) has a receptance at the contact DOF
that is a smooth function of frequency, except near 0 Hz where the compounds' fractional laws have
a cusp (:math:`g(\omega) - 1 \propto \omega^{\alpha}`, :math:`\alpha = 0.3 \ldots 0.7`). On a dense
frequency grid (the footprint FRFs are taken every 1 Hz, 0-400 Hz) such a harmonic is evaluated
exactly at every requested frequency up to :data:`DENSE_UP_TO` and on nodes :data:`NODE_STEP` apart
above it, and a local cubic (4-point Lagrange) interpolation gives it at the other frequencies; a
harmonic with a mode in or near the band is evaluated at every frequency. 0-400 Hz every 1 Hz takes
77 nodes; 47 of the 165/65 R14's 76 reduced harmonics and 58 of the 195/65 R15's 135 are
interpolated, and the footprint FRFs stay within 6.1e-6 (165/65 R14) and 1.5e-6 (195/65 R15) of the
evaluation at every frequency, per tassello relative to its peak (H_tot within 2.8e-7 at every
frequency).

The interpolation is linear, so the interpolated blocks enter the harmonic sums like the evaluated
ones; nothing is interpolated below :data:`DENSE_UP_TO`, where every requested frequency is a node.
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np
from threadpoolctl import threadpool_limits

from ... import guards
from ...parallel import threads
from .footprint_points import angular_tables, blocks_by_sum, contact_rows

#: A harmonic is interpolated when none of its undamped natural frequencies can come nearer the band
#: ``0..f_top`` than :func:`margin` (:func:`is_smooth`): a quarter of ``f_top``...
MARGIN_FACTOR = 0.25
#: ... and at least this many node steps (the interpolation's error grows as the margin nears the step).
MARGIN_STEPS = 10
#: Sub-bands of :func:`is_smooth`'s bound for an indefinite compound: ``0, f_top / 2^(n-1), ..., f_top / 2, f_top``.
SUB_BANDS = 6
#: Frequencies up to here (Hz) are evaluated wherever requested: the compound laws' cusp at 0 Hz.
DENSE_UP_TO = 40.0
#: Spacing of the interpolation nodes above :data:`DENSE_UP_TO` (Hz).
NODE_STEP = 10.0
#: Interpolation is used only when it evaluates at most this share of the requested frequencies.
WORTH_IT = 0.5
#: Nodes evaluated together (one batched solve per harmonic part).
NODE_BLOCK = 16


def margin(f_top: float) -> float:
    """How far (Hz) every mode of an interpolated harmonic stays from the band ``0..f_top`` (Hz)."""
    return max(MARGIN_FACTOR * f_top, MARGIN_STEPS * NODE_STEP)


def storage_rises(laws: dict, names, freqs: np.ndarray) -> bool:
    """Whether every law's storage modulus is non-decreasing over ``freqs`` (Hz, with 0): what :func:`is_smooth`
    assumes (true of the fractional and Prony laws and of frozen ones)."""
    omegas = 2 * np.pi * np.union1d([0.0], freqs)
    return all(np.all(np.diff(np.real(laws[name].ratio(omegas))) >= 0.0) for name in names)


def is_smooth(harmonic, laws: dict, omega_top: float, omega_margin: float) -> bool:
    r"""Whether a reduced harmonic has no resonance within ``omega_margin`` of the band ``0..omega_top`` (rad/s).

    With the storage moduli rising with frequency (:func:`storage_rises`), :math:`K'(\omega) = K'(0) +
    \sum_c \Delta_c(\omega) K_c` with :math:`0 \le \Delta_c(\omega) \le \Delta_c(\omega_{top})`. A compound
    that carries the pneumatic stiffness may be indefinite, :math:`K_c \ge \mu_c M` with :math:`\mu_c < 0`
    (:attr:`~roadnoise_utils.tire.cross_section.dynamics.ReducedHarmonic.compound_floors`), so each ordered
    eigenvalue of the undamped pencil :math:`(K'(\omega), M)` stays within :math:`[\lambda_i(0) - \delta,
    \lambda_i(\omega_{top}) + \delta]`, :math:`\delta = \sum_c \Delta_c(\omega_{top}) |\mu_c|` (Weyl), and
    likewise over each of :data:`SUB_BANDS` sub-bands with the rise over it (tighter). The harmonic is
    smooth when every eigenvalue either stays above :math:`(\omega_{top} + \omega_m)^2` or stays below
    :math:`-\omega_m^2` (a direction of negative stiffness, from the linear inflation's hoop compression, its
    pole on the imaginary axis at least :math:`\omega_m` from the band).
    """
    above, below = (omega_top + omega_margin) ** 2, -(omega_margin**2)
    start, top = harmonic.eigenvalues(laws, 0.0), harmonic.eigenvalues(laws, omega_top)
    if not np.all((start >= above) | (top <= below)):
        return False
    floors = harmonic.compound_floors
    if all(floor == 0.0 for floor in floors.values()):
        return True  # every compound semi-definite: each eigenvalue rises from start to top
    # the bound over sub-bands, split where the storage moduli rise fastest (the low frequencies)
    omegas = np.concatenate([[0.0], omega_top * 2.0 ** -np.arange(SUB_BANDS - 1, -1, -1)])
    storage = {name: np.real(laws[name].ratio(omegas)) for name in floors}
    eigenvalues = [start] + [harmonic.eigenvalues(laws, w) for w in omegas[1:-1]] + [top]
    for k in range(SUB_BANDS):
        drift = sum((storage[name][k + 1] - storage[name][k]) * -floor for name, floor in floors.items())
        if not np.all((eigenvalues[k] - drift >= above) | (eigenvalues[k + 1] + drift <= below)):
            return False
    return True


def frequency_nodes(freqs: np.ndarray) -> np.ndarray:
    """Interpolation nodes (Hz) for the ascending ``freqs``: every requested one up to :data:`DENSE_UP_TO`,
    then the coarse nodes (:func:`coarse_nodes`)."""
    return np.union1d(freqs[freqs <= DENSE_UP_TO], coarse_nodes(freqs))


def coarse_nodes(freqs: np.ndarray) -> np.ndarray:
    """Nodes :data:`NODE_STEP` apart from one step below :data:`DENSE_UP_TO` to at least the highest of ``freqs``
    (none when it is not above :data:`DENSE_UP_TO`)."""
    top = float(freqs.max())
    if top <= DENSE_UP_TO:
        return np.zeros(0)
    steps = int(np.ceil((top - DENSE_UP_TO) / NODE_STEP))
    return DENSE_UP_TO + NODE_STEP * np.arange(-1, steps + 1)


def node_stencil(nodes: np.ndarray, freqs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The interpolation from ``nodes`` (:func:`frequency_nodes`) to ``freqs``: a frequency up to
    :data:`DENSE_UP_TO` is a node (weight 1); one above, the 4-point Lagrange interpolation over the coarse
    nodes alone (evenly spaced, clear of the laws' cusp). Returns the nodes' indices (n_f, 4) and weights."""
    coarse = coarse_nodes(freqs)
    index = np.zeros((freqs.size, 4), int)
    weights = np.zeros((freqs.size, 4))
    low = freqs <= DENSE_UP_TO
    index[low, 0], weights[low, 0] = np.searchsorted(nodes, freqs[low]), 1.0
    if (~low).any():
        first, weights[~low] = lagrange_stencil(coarse, freqs[~low])
        index[~low] = np.searchsorted(nodes, coarse)[first[:, None] + np.arange(4)]
    return index, weights


def lagrange_stencil(nodes: np.ndarray, freqs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """4-point Lagrange interpolation from ``nodes`` (ascending, at least 4) to ``freqs`` inside them:
    the first node of each frequency's stencil (n_f,) and the weights (n_f, 4). A frequency on a node
    has the weight 1 there and 0 elsewhere, exactly."""
    first = np.clip(np.searchsorted(nodes, freqs, side="right") - 2, 0, nodes.size - 4)
    points = nodes[first[:, None] + np.arange(4)]
    weights = np.ones((freqs.size, 4))
    for a in range(4):
        for b in range(4):
            if a != b:
                weights[:, a] *= (freqs - points[:, b]) / (points[:, a] - points[:, b])
    return first, weights


@dataclass(frozen=True, eq=False)
class SmoothHarmonics:
    """The smooth harmonics' share of the gather tables on the nodes, and its interpolation to the requested
    frequencies.

    Attributes
    ----------
    smooth : ndarray of bool (n_harmonics,)
        The harmonics interpolated (the others are evaluated at every frequency).
    index, weights : ndarray (n_f, 4)
        :func:`node_stencil` of the requested frequencies.
    tables : ndarray (n 4, n_nodes) complex
        The smooth harmonics' share of the gather tables
        (:func:`roadnoise_utils.tire.cross_section.footprint_points.angular_tables`) at the nodes.
    """

    smooth: np.ndarray
    index: np.ndarray
    weights: np.ndarray
    tables: np.ndarray

    def tables_at(self, part: slice) -> np.ndarray:
        """The smooth harmonics' share of the gather tables at the requested frequencies ``part``, (n 4, b):
        one product with the weights of the nodes the block's stencils span."""
        index, weights = self.index[part], self.weights[part]
        low, high = int(index.min()), int(index.max()) + 1
        spread = np.zeros((high - low, index.shape[0]), complex)
        for a in range(4):
            np.add.at(spread, (index[:, a] - low, np.arange(index.shape[0])), weights[:, a])
        return self.tables[:, low:high] @ spread


def smooth_harmonics(even, freqs: np.ndarray, laws: dict, inertia: bool, columns: np.ndarray) -> SmoothHarmonics | None:
    """Plan and evaluate the interpolation of the smooth harmonics of ``even``
    (:class:`~roadnoise_utils.tire.cross_section.footprint.EvenFootprint`) at ``freqs`` (Hz, ascending)
    for the receptance rows of the grid columns ``columns``, or None when it would not save work (few
    frequencies, no smooth harmonic).

    Without ``inertia`` every harmonic is smooth (no resonance); ``laws`` as in
    :meth:`roadnoise_utils.tire.cross_section.dynamics.ReducedHarmonic.receptance`.
    """
    nodes = frequency_nodes(freqs)
    if nodes.size < 4 or nodes.size > WORTH_IT * freqs.size:
        return None
    f_top = float(freqs.max())
    names = even.harmonics[0].projected.compounds
    if inertia and not storage_rises(laws, names, np.union1d(freqs, nodes)):
        return None
    omega_top, omega_margin = 2 * np.pi * f_top, 2 * np.pi * margin(f_top)
    smooth = np.array([not inertia or is_smooth(h, laws, omega_top, omega_margin) for h in even.harmonics])
    if not smooth.any():
        return None
    picked = np.flatnonzero(smooth)
    c = even.tire.grid.n_cols
    n_table = even.cos.shape[0] * columns.size * c
    guards.check_memory(16.0 * 4 * n_table * (nodes.size + NODE_BLOCK), "the smooth harmonics' tables", "freqs")
    tables = np.empty((4 * n_table, nodes.size), complex)
    rows = contact_rows(c, columns)
    cos, sin = even.cos[:, picked], even.sin[:, picked]
    parts = [slice(start, min(start + NODE_BLOCK, nodes.size)) for start in range(0, nodes.size, NODE_BLOCK)]

    def evaluate(part: slice) -> None:
        omegas = 2 * np.pi * nodes[part]
        blocks = np.empty((omegas.size, picked.size, 4, columns.size, c), complex)
        for j, k in enumerate(picked):
            blocks[:, j] = blocks_by_sum(even.harmonics[k].receptance(laws, omegas, inertia, rows), c, columns)
        tables[:, part] = angular_tables(blocks, cos, sin)

    with ThreadPoolExecutor(max_workers=threads()) as workers, threadpool_limits(1):
        list(workers.map(evaluate, parts))
    index, weights = node_stencil(nodes, freqs)
    return SmoothHarmonics(smooth, index, weights, tables)
