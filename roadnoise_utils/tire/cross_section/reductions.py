"""The cross-section tire's harmonics reduced for a band: what the footprint FRFs need of the tire alone.

Every harmonic ``0..N`` of the tire is Ritz-reduced once for ``0..f_max``
(:func:`roadnoise_utils.tire.cross_section.dynamics.reduce_harmonic`): ``0, 1, 2, ...`` with their
modes below the cutoff up to the first (``n >= 2``) that has none, then a few quasi-static ones
sampled in ``n`` (the rest interpolated between them). The reductions depend on the tire, the band
and the cutoff, not on the loaded state: the flat road's and the drum's footprints
(:mod:`roadnoise_utils.tire.cross_section.footprint`) and the time stepping's modal harmonics
(:func:`roadnoise_utils.tire.cross_section.stepping.reduce_all`) share them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline
from threadpoolctl import threadpool_limits

from ...parallel import thread_map, threads
from .dynamics import harmonic_modes, lateral_mirror, reduce_harmonic
from .static import SectionTire


def dynamic_harmonics(tire: SectionTire, f_max: float, cutoff: float) -> int:
    """The last harmonic with a mode below ``cutoff`` (Hz), searching upwards from ``n = 2``."""
    omega = np.pi * f_max
    n = 2
    while n < tire.harmonics and harmonic_modes(tire.ops, n, omega, cutoff, max_modes=4).shape[1]:
        n += 1
    return n - 1


def _dynamic_reductions(tire: SectionTire, f_max: float, cutoff: float, wall: np.ndarray | None = None) -> list:
    """Reduced harmonics 0, 1, 2, ... with their modes, up to the first (n >= 2) with no mode below ``cutoff``.

    Each records the tire's left-right symmetry (:func:`roadnoise_utils.tire.cross_section.dynamics.lateral_mirror`),
    which halves its receptance's work twice over. On two threads (:func:`roadnoise_utils.parallel.threads`)
    two harmonics at a time (the sparse factorisations and products release the GIL): the one after
    the last is then reduced for nothing.
    """
    mirror = lateral_mirror(tire.ops)

    def reduce(n: int):
        return reduce_harmonic(tire.ops, tire.grid.dofs, n, f_max, cutoff, mirror=mirror, wall=wall)

    reduced, step = [], threads()
    for first in range(0, tire.harmonics + 1, step):
        for red in thread_map(reduce, range(first, min(first + step, tire.harmonics + 1))):
            reduced.append(red)
            if red.n >= 2 and red.n_modes == 0:
                return reduced
    return reduced


@dataclass(frozen=True, eq=False)
class FootprintReductions:
    """Every harmonic of a tire reduced for a band: what :meth:`EvenFootprint.build` needs of the tire alone.

    They depend on the tire, the band and the modes' cutoff, not on the loaded state: the flat
    road's and the drum's footprints (and the time stepping's modal harmonics,
    :func:`roadnoise_utils.tire.cross_section.stepping.reduce_all`) share them.

    Attributes
    ----------
    f_max, cutoff : float
        Band and modes' cutoff (Hz).
    dynamic : list of ReducedHarmonic
        Harmonics ``0, 1, ...`` with their modes below ``cutoff``, up to the first (``n >= 2``) without one.
    n_high : ndarray of int
        The quasi-static harmonics above them.
    basis : ndarray (n_high, n_samples)
        Interpolation weights from the sampled quasi-static harmonics to ``n_high``.
    high : list of ReducedHarmonic
        The sampled quasi-static harmonics (no modes).
    """

    f_max: float
    cutoff: float
    dynamic: list
    n_high: np.ndarray
    basis: np.ndarray
    high: list


def footprint_reductions(
    tire: SectionTire, f_max: float, cutoff: float, wall: np.ndarray | None = None
) -> FootprintReductions:
    """Reduce every harmonic for ``0..f_max`` Hz, modes below ``cutoff`` Hz (see the module notes); with
    the cavity wall's load ``wall`` (:func:`roadnoise_utils.tire.cross_section.cavity.wall_volume`) in the dynamic harmonics' bases."""
    with threadpool_limits(1):
        dynamic = _dynamic_reductions(tire, f_max, cutoff, wall)
        n_high, basis, high = _high_harmonics(tire, len(dynamic) - 1, f_max)
        # what the frequency nodes' criterion reads of each harmonic, kept with the reductions
        list(thread_map(lambda h: (h.static_eigenvalues, h.compound_floors), dynamic + high))
    return FootprintReductions(float(f_max), float(cutoff), dynamic, n_high, basis, high)


def _sample_harmonics(first: int, last: int, count: int = 24) -> np.ndarray:
    """Harmonics sampled densely near ``first`` and sparsely towards ``last`` (interpolation nodes)."""
    return np.unique(np.round(np.geomspace(first, last, count)).astype(int))


def _high_harmonics(tire: SectionTire, n_dyn: int, f_max: float) -> tuple:
    """The quasi-static harmonics ``n_dyn + 1 .. N``, sampled in ``n`` and reduced (no modes).

    Returns the harmonics ``n_all``, the interpolation weights ``basis`` (n_all, n_samples) and
    the reduced sampled harmonics, evaluated at every frequency like the dynamic ones (the
    compound laws have a cusp at 0 Hz, where a spline in frequency would be off by a few %).
    """
    grid, ops = tire.grid, tire.ops
    n_all = np.arange(n_dyn + 1, tire.harmonics + 1)
    if n_all.size == 0:
        return n_all, np.zeros((0, 0)), []
    sampled = _sample_harmonics(n_dyn + 1, tire.harmonics)
    mirror = lateral_mirror(ops)
    reduced = list(thread_map(lambda n: reduce_harmonic(ops, grid.dofs, n, f_max, None, mirror=mirror), sampled))
    basis = CubicSpline(sampled, np.eye(sampled.size), axis=0)(n_all) if sampled.size > 1 else np.ones((1, 1))
    return n_all, basis, reduced
