"""The smooth harmonics interpolated in frequency against every harmonic evaluated at every frequency.

The reference is the footprint solve with ``interpolate=False`` (each reduced harmonic evaluated at each
frequency), on the coarse 165/65 R14 every 2 Hz from 0 to 400 Hz: dense enough for the interpolation to
be used, as on the default 1 Hz grid."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.footprint import EvenFootprint, footprint_frf
from roadnoise_utils.tire.cross_section.frequency_nodes import (
    DENSE_UP_TO,
    NODE_STEP,
    SMOOTH_FACTOR,
    frequency_nodes,
    lagrange_stencil,
    smooth_harmonics,
)

FREQS = np.arange(0.0, 401.0, 2.0)


@pytest.fixture(scope="module")
def coarse(coarse_section):
    tire = section_stages.section_tire(coarse_section)
    static = ru.stages.solve_static(coarse_section, "flat")
    return tire, static, EvenFootprint.build(tire, static, 400.0, 1000.0)


@pytest.fixture(scope="module")
def both(coarse):
    _, _, even = coarse
    return even.footprint(FREQS), even.footprint(FREQS, interpolate=False)


def test_nodes_are_every_requested_frequency_below_the_cusp_then_a_coarse_grid():
    nodes = frequency_nodes(FREQS)
    assert np.array_equal(nodes[nodes <= DENSE_UP_TO], FREQS[FREQS <= DENSE_UP_TO])
    assert np.allclose(np.diff(nodes[nodes >= DENSE_UP_TO]), NODE_STEP)
    assert nodes.max() >= FREQS.max()
    assert frequency_nodes(np.array([3.0, 17.5])).tolist() == [3.0, 17.5]  # below the cusp: nothing added


def test_lagrange_weights_are_exact_for_cubics_and_on_nodes():
    nodes = np.array([0.0, 1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 40.0])
    x = np.linspace(0.0, 40.0, 97)
    first, weights = lagrange_stencil(nodes, x)
    assert np.allclose(weights.sum(axis=1), 1.0, atol=1e-13)  # a constant is interpolated exactly
    cubic = lambda f: 0.3 * f**3 - 2.0 * f**2 + f - 7.0  # noqa: E731
    values = cubic(nodes)[first[:, None] + np.arange(4)]
    np.testing.assert_allclose(np.sum(weights * values, axis=1), cubic(x), rtol=1e-11, atol=1e-9)
    first, weights = lagrange_stencil(nodes, nodes)
    assert np.array_equal(np.sort(weights, axis=1), np.tile([0.0, 0.0, 0.0, 1.0], (nodes.size, 1)))


def test_the_harmonics_called_smooth_interpolate_and_the_others_would_not(coarse):
    """Each harmonic's receptance on the 2 Hz grid against its interpolation from the nodes: the smooth ones
    within 1e-4 of their peak, the first harmonics (a mode in the band) far off: the classification is what
    the interpolation needs, not a list kept by hand."""
    _, _, even = coarse
    laws = even.tire.ops.laws
    plan = smooth_harmonics(even, FREQS, laws, True, even.lateral.columns)
    assert 0 < plan.smooth.sum() < plan.smooth.size  # both kinds present
    nodes = frequency_nodes(FREQS)
    first, weights = lagrange_stencil(nodes, FREQS)
    rows = np.arange(4)
    error = []
    for harmonic in even.harmonics:
        exact = harmonic.receptance(laws, 2 * np.pi * FREQS, True, rows).reshape(FREQS.size, -1)
        at_nodes = harmonic.receptance(laws, 2 * np.pi * nodes, True, rows).reshape(nodes.size, -1)
        interpolated = np.einsum("fa,fak->fk", weights, at_nodes[first[:, None] + np.arange(4)])
        error.append(np.abs(interpolated - exact).max() / np.abs(exact).max())
    error = np.array(error)
    assert error[plan.smooth].max() < 1e-4
    assert error[:3].min() > 1e-3 and not plan.smooth[:3].any()
    lowest = np.array([h.lowest_frequency for h in even.harmonics])
    assert plan.smooth[lowest >= SMOOTH_FACTOR * FREQS.max()].all()  # no mode near the band: always smooth
    assert smooth_harmonics(even, FREQS[:20], laws, True, even.lateral.columns) is None  # few frequencies


def test_interpolated_footprint_frfs_equal_the_direct_evaluation(both, coarse):
    """Within 1e-4 (the budget is 1e-3): per tassello relative to its peak, H_tot and G_H at every frequency;
    below the cusp every frequency is a node and the two agree to round-off."""
    fast, direct = both
    h_fast, h_direct = fast.H_tasselli(), direct.H_tasselli()
    per_tassello = np.abs(h_fast - h_direct).max(axis=0) / np.abs(h_direct).max(axis=0)
    assert per_tassello.max() < 1e-4
    assert np.max(np.abs(fast.H_tot - direct.H_tot) / np.abs(direct.H_tot)) < 1e-4
    assert np.max(np.abs(fast.G_H - direct.G_H) / np.abs(direct.G_H)) < 1e-4
    below = FREQS <= DENSE_UP_TO
    assert np.abs(fast.hub[below] - direct.hub[below]).max() < 1e-9 * np.abs(direct.hub).max()
    assert per_tassello.max() > 0  # the interpolation ran (not the direct path twice)


def test_interpolate_is_a_flag(coarse):
    tire, static, _ = coarse
    with pytest.raises(ValueError, match="interpolate"):
        footprint_frf(tire, static, FREQS[:3], interpolate="no")
