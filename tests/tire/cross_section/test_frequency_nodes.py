"""The smooth harmonics interpolated in frequency against every harmonic evaluated at every frequency.

The reference is the footprint solve with ``interpolate=False`` (each reduced harmonic evaluated at each
frequency), on the coarse 165/65 R14 every 2 Hz from 0 to 400 Hz: dense enough for the interpolation to
be used, as on the default 1 Hz grid."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.dynamics import FrozenLaw, Projected, ReducedHarmonic
from roadnoise_utils.tire.cross_section.footprint import EvenFootprint, footprint_frf
from roadnoise_utils.tire.cross_section.frequency_nodes import (
    DENSE_UP_TO,
    NODE_STEP,
    frequency_nodes,
    is_smooth,
    lagrange_stencil,
    margin,
    node_stencil,
    smooth_harmonics,
)
from roadnoise_utils.tire.rubber import FractionalZener

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
    assert nodes.max() == FREQS.max()
    assert frequency_nodes(np.array([3.0, 17.5])).tolist() == [3.0, 17.5]  # below the cusp: nothing added


def test_above_the_cusp_the_stencil_is_centred_on_the_coarse_nodes():
    """Between coarse nodes j and j+1 the stencil is j-1..j+2 (never a dense node below the cusp's edge)."""
    nodes = frequency_nodes(FREQS)
    index, weights = node_stencil(nodes, np.array([41.0, 45.0, 123.0, 399.0, 12.0]))
    assert nodes[index[0]].tolist() == nodes[index[1]].tolist() == [30.0, 40.0, 50.0, 60.0]
    assert nodes[index[2]].tolist() == [110.0, 120.0, 130.0, 140.0]
    assert nodes[index[3]].tolist() == [370.0, 380.0, 390.0, 400.0]
    assert nodes[index[4, 0]] == 12.0 and weights[4].tolist() == [1.0, 0.0, 0.0, 0.0]
    np.testing.assert_allclose(weights[1], [-0.0625, 0.5625, 0.5625, -0.0625])


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
    index, weights = node_stencil(nodes, FREQS)  # the stencils the footprint uses
    rows = np.arange(4)
    error = []
    for harmonic in even.harmonics:
        exact = harmonic.receptance(laws, 2 * np.pi * FREQS, True, rows).reshape(FREQS.size, -1)
        at_nodes = harmonic.receptance(laws, 2 * np.pi * nodes, True, rows).reshape(nodes.size, -1)
        interpolated = np.einsum("fa,fak->fk", weights, at_nodes[index])
        error.append(np.abs(interpolated - exact).max() / np.abs(exact).max())
    error = np.array(error)
    assert error[plan.smooth].max() < 1e-4
    assert error[:3].min() > 1e-3 and not plan.smooth[:3].any()
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


def _toy_harmonic(gas: float, compound: float) -> ReducedHarmonic:
    """One coordinate of unit mass: stiffness ``gas + g(omega) compound`` (N/m)."""
    one = np.ones((1, 1))
    projected = Projected({"tread": compound * one}, gas * one, one, np.zeros((1, 1)), np.zeros(1))
    return ReducedHarmonic(n=0, projected=projected, n_modes=0)


def test_the_criterion_keeps_modes_and_imaginary_poles_a_margin_away_from_the_band():
    """A mode above the band or a negative stiffness below it is smooth only beyond the margin; an indefinite
    compound whose rise could carry an eigenvalue towards the band is not trusted on the two ends alone."""
    laws = {"tread": FractionalZener(modulus_ratio=2.6, relaxation_time=5e-5, order=0.45)}
    top = 2 * np.pi * 400.0
    m = 2 * np.pi * margin(400.0)
    assert margin(400.0) == 100.0 and margin(100.0) == 100.0 and margin(1000.0) == 250.0
    assert is_smooth(_toy_harmonic(0.0, (top + 1.1 * m) ** 2), laws, top, m)
    assert not is_smooth(_toy_harmonic(0.0, (top + 0.9 * m) ** 2), laws, top, m)
    assert is_smooth(_toy_harmonic(-((1.1 * m) ** 2), 0.0), laws, top, m)
    assert not is_smooth(_toy_harmonic(-((0.9 * m) ** 2), 0.0), laws, top, m)
    # an indefinite compound (the pneumatic stiffness in it) softens with frequency: above the band at 0 Hz,
    # inside the margin at the top; the ends' test on the static eigenvalue alone would pass it, the bound does not
    above = (top + m) ** 2
    rise = float(np.real(laws["tread"].ratio(top) - 1.0))
    k = -0.15 * above / rise
    harmonic = _toy_harmonic(1.05 * above - k, k)
    assert harmonic.eigenvalues(laws, 0.0)[0] >= above > harmonic.eigenvalues(laws, top)[0]
    assert harmonic.compound_floors["tread"] == pytest.approx(k) and not is_smooth(harmonic, laws, top, m)


def test_every_harmonic_interpolated_without_inertia_and_on_a_low_band(coarse):
    """Without inertia every harmonic is smooth (none evaluated per frequency); 0-100 Hz every 0.5 Hz keeps the
    margin of 100 Hz (10 node steps) and its accuracy; laws whose static storage is below 1 are honoured."""
    tire, static, even = coarse
    every_4_hz = FREQS[::2]  # 101 frequencies, 49 nodes: still interpolated (nodes at most half the frequencies)
    assert frequency_nodes(every_4_hz).size <= every_4_hz.size / 2
    quasi = even.footprint(every_4_hz, inertia=False), even.footprint(every_4_hz, inertia=False, interpolate=False)
    low_freqs = np.arange(0.0, 100.5, 0.5)
    low = EvenFootprint.build(tire, static, 100.0, 250.0)
    assert smooth_harmonics(low, low_freqs, tire.ops.laws, True, low.lateral.columns).smooth.any()
    banded = low.footprint(low_freqs), low.footprint(low_freqs, interpolate=False)
    soft = {name: FrozenLaw(0.3 + 0.003j) for name in tire.ops.laws}
    frozen = even.footprint(every_4_hz, laws=soft), even.footprint(every_4_hz, laws=soft, interpolate=False)
    for fast, direct in (quasi, banded, frozen):
        h_fast, h_direct = fast.H_tasselli(), direct.H_tasselli()
        assert np.max(np.abs(h_fast - h_direct).max(axis=0) / np.abs(h_direct).max(axis=0)) < 1e-4
        assert np.max(np.abs(fast.H_tot - direct.H_tot) / np.abs(direct.H_tot)) < 1e-4


def test_interpolate_is_a_flag(coarse):
    tire, static, _ = coarse
    with pytest.raises(ValueError, match="interpolate"):
        footprint_frf(tire, static, FREQS[:3], interpolate="no")
