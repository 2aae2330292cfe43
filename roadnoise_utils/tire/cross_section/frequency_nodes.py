r"""Smooth harmonics of the cross-section footprint, evaluated on frequency nodes and interpolated.

A harmonic with no resonance near the band (:func:`is_smooth`) has a receptance at the contact DOF
that is a smooth function of frequency, except near 0 Hz where the compounds' fractional laws have
a cusp (:math:`g(\omega) - 1 \propto \omega^{\alpha}`, :math:`\alpha = 0.3 \ldots 0.7`). On a dense
frequency grid (the footprint FRFs are taken every 1 Hz, 0-400 Hz) such a harmonic is evaluated
exactly at every requested frequency up to :data:`DENSE_UP_TO` and on nodes :data:`NODE_STEP` apart
above it, and a local cubic (4-point Lagrange) interpolation gives it at the other frequencies; a
harmonic with a mode in or near the band is evaluated at every frequency. 0-400 Hz every 1 Hz takes
77 nodes; 49 of the 165/65 R14's 76 reduced harmonics (``n >= 27``) and 80 of the 195/65 R15's 135
are interpolated, and the footprint FRFs stay within 3.1e-6 (165/65 R14) and 1.5e-6 (195/65 R15)
of the evaluation at every frequency, per tassello relative to its peak (H_tot within 1.2e-7 at
every frequency).

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
#: ``0..f_top`` than ``(SMOOTH_FACTOR - 1) f_top`` (:func:`is_smooth`).
SMOOTH_FACTOR = 1.25
#: Frequencies up to here (Hz) are evaluated wherever requested: the compound laws' cusp at 0 Hz.
DENSE_UP_TO = 40.0
#: Spacing of the interpolation nodes above :data:`DENSE_UP_TO` (Hz).
NODE_STEP = 10.0
#: Interpolation is used only when it evaluates at most this share of the requested frequencies.
WORTH_IT = 0.5
#: Nodes evaluated together (one batched solve per harmonic part).
NODE_BLOCK = 16


def is_smooth(harmonic, laws: dict, omega_top: float) -> bool:
    r"""Whether a reduced harmonic has no resonance near the band ``0..omega_top`` (rad/s).

    Each compound's stiffness matrix is positive semi-definite and its storage modulus rises with
    frequency, so each ordered eigenvalue :math:`\lambda_i(\omega)` of the undamped pencil
    :math:`(K'(\omega), M)` rises from its static value to its value at ``omega_top``
    (:meth:`~roadnoise_utils.tire.cross_section.dynamics.ReducedHarmonic.eigenvalues`). The harmonic
    is smooth when every one either starts above :math:`(s \omega_{top})^2` or stays below
    :math:`-((s - 1) \omega_{top})^2` (a direction of negative stiffness, from the linear inflation's hoop
    compression, whose pole sits on the imaginary axis at least that far from the band), ``s`` being
    :data:`SMOOTH_FACTOR`.
    """
    above = (SMOOTH_FACTOR * omega_top) ** 2
    static = harmonic.static_eigenvalues
    if static[0] >= above:
        return True
    top = harmonic.eigenvalues(laws, omega_top)
    return bool(np.all((static >= above) | (top <= -(((SMOOTH_FACTOR - 1) * omega_top) ** 2))))


def frequency_nodes(freqs: np.ndarray) -> np.ndarray:
    """Interpolation nodes (Hz) for the ascending ``freqs``: every requested one up to :data:`DENSE_UP_TO`,
    then :data:`NODE_STEP` apart from there to at least the highest."""
    dense = freqs[freqs <= DENSE_UP_TO]
    top = float(freqs.max())
    count = int(np.ceil((top - DENSE_UP_TO) / NODE_STEP)) + 1 if top > DENSE_UP_TO else 0
    coarse = DENSE_UP_TO + NODE_STEP * np.arange(count)
    return np.union1d(dense, coarse)


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
    first, weights : ndarray
        :func:`lagrange_stencil` of the requested frequencies.
    tables : ndarray (n 4, n_nodes) complex
        The smooth harmonics' share of the gather tables
        (:func:`roadnoise_utils.tire.cross_section.footprint_points.angular_tables`) at the nodes.
    """

    smooth: np.ndarray
    first: np.ndarray
    weights: np.ndarray
    tables: np.ndarray

    def tables_at(self, part: slice) -> np.ndarray:
        """The smooth harmonics' share of the gather tables at the requested frequencies ``part``, (n 4, b):
        one product with the weights of the nodes the block's stencils span."""
        first, weights = self.first[part], self.weights[part]
        low, high = int(first.min()), int(first.max()) + 4
        spread = np.zeros((high - low, first.size), complex)
        for a in range(4):
            spread[first - low + a, np.arange(first.size)] = weights[:, a]
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
    omega_top = 2 * np.pi * float(freqs.max())
    smooth = np.array([not inertia or is_smooth(h, laws, omega_top) for h in even.harmonics])
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
    first, weights = lagrange_stencil(nodes, freqs)
    return SmoothHarmonics(smooth, first, weights, tables)
