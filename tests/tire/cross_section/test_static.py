"""The loaded cross-section tire: contact, force balance, reciprocity, footprint FRFs (verification c, d, f).

The checks against every harmonic solved directly run on the 165/65 R14 on a coarse grid (``coarse_section``)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.contact import harmonic_flexibility, vertical_compliance
from roadnoise_utils.tire.cross_section.dynamics import reduce_harmonic, ritz_error
from roadnoise_utils.tire.cross_section.footprint import (
    EvenFootprint,
    contact_receptance,
    dynamic_harmonics,
    footprint_frf,
)
from roadnoise_utils.tire.cross_section.footprint_points import lateral_split
from roadnoise_utils.tire.cross_section.static import force_balance, section_summary, solve_section_static

NAME = "165_65R14_cross_section"


@pytest.fixture(scope="module")
def tire():
    return section_stages.section_tire(NAME)


@pytest.fixture(scope="module")
def flat():
    return ru.stages.solve_static(NAME, "flat")


@pytest.fixture(scope="module")
def coarse(coarse_section):
    """The coarse tire and its loaded state on the flat road."""
    return section_stages.section_tire(coarse_section), ru.stages.solve_static(coarse_section, "flat")


def test_force_balance_to_round_off(flat):
    """(f) The rim's n = 1 reaction, computed apart from the contact solve, equals the load."""
    spread = np.sinc(flat.grid.dtheta / (2 * np.pi))  # vertical resultant of an arc-spread point load
    assert flat.contact_force.sum() == pytest.approx(flat.load, rel=1e-12)
    assert flat.hub_force / (flat.load * spread) - 1 == pytest.approx(0.0, abs=1e-9)
    assert np.all(flat.contact_force >= 0)
    assert force_balance(flat) < 1e-9 and section_summary(flat)["force balance (contact and hub = load to 1e-9)"]


def test_footprint_is_fore_aft_symmetric_and_inside_the_grid(flat):
    assert np.array_equal(flat.contact, flat.contact[:, ::-1])
    np.testing.assert_allclose(flat.contact_force, flat.contact_force[:, ::-1], rtol=1e-6, atol=1e-9 * flat.load)
    assert not flat.contact[:, [0, -1]].any()


def test_drum_shortens_the_footprint(flat):
    drum = ru.stages.solve_static(NAME, "drum", drum_radius=1.25)
    assert drum.footprint_length < flat.footprint_length
    assert drum.deflection > flat.deflection


def test_static_compliance_is_symmetric_and_positive_definite(coarse):
    """(d) Reciprocity of the static Green's functions on the contact grid."""
    tire, _ = coarse
    grid = tire.grid
    flex = harmonic_flexibility(tire.ops, grid.dofs, tire.harmonics)
    c = vertical_compliance(grid, flex)
    assert np.abs(c - c.T).max() < 1e-10 * np.abs(c).max()
    assert np.linalg.eigvalsh(c[:400, :400]).min() > 0


@pytest.mark.parametrize("n", [0, 1, 3, 20, "first quasi-static", 150])
def test_ritz_reduction_matches_the_direct_solve(tire, n):
    """Every reduced harmonic within 3e-3 of the direct solve, the first one without modes included."""
    if n == "first quasi-static":  # footprint_frf's default cutoff: 2.5 x 400 Hz
        n = dynamic_harmonics(tire, 400.0, 1000.0) + 1
    red = reduce_harmonic(tire.ops, tire.grid.dofs, n, 400.0, 1000.0 if n <= 20 else None)
    for f in (0.0, 80.0, 250.0, 400.0):
        assert ritz_error(tire.ops, red, tire.grid.dofs, 2 * np.pi * f) < 3e-3


@pytest.fixture(scope="module")
def frf(coarse):
    tire, flat = coarse
    return footprint_frf(tire, flat, np.array([0.0, 5.0, 40.0, 80.0, 160.0, 320.0]))


def test_static_footprint_frf_is_the_vertical_stiffness(frf):
    flat = frf.static
    spread = np.sinc(flat.grid.dtheta / (2 * np.pi))
    # exact but for the quasi-static harmonics' cubic interpolation in n (5e-9 on the coarse grid, 2e-7 on the default)
    assert frf.H_tot[0].real / (flat.vertical_stiffness * spread) - 1 == pytest.approx(0.0, abs=1e-6)
    assert abs(frf.H_tot[0].imag) < 1e-8 * abs(frf.H_tot[0])
    # the tasselli partition the points: their FRFs add up to the whole footprint's
    np.testing.assert_allclose(frf.H_tasselli().sum(axis=1), frf.H_tot, rtol=1e-12)


@pytest.mark.parametrize(("index", "f"), [(1, 5.0), (3, 80.0)])
def test_footprint_frf_matches_a_direct_harmonic_sum(coarse, frf, index, f):
    """The reduced, interpolated FRF against every harmonic solved directly, contact points all kept (no mirror);
    5 Hz sits on the compound laws' steepest rise, 80 Hz on the first vertical resonance."""
    tire, flat = coarse
    comp = contact_receptance(tire, flat, f)
    assert np.abs(comp - comp.T).max() < 1e-10 * np.abs(comp).max()  # (d) reciprocity
    hub = np.linalg.solve(comp, frf.transfer[index])
    assert abs(frf.H_tot[index] / hub.sum() - 1) < 3e-3


def test_the_left_right_split_footprint_is_the_plain_solve(tire, flat):
    """Symmetric and antisymmetric loads solved apart on one point of each lateral pair (from half the
    receptance's rows) give the plain solve over every point; without a mirror the plain solve is used."""
    even = EvenFootprint.build(tire, flat, 320.0, 800.0)
    lateral = even.lateral
    assert lateral.rows.size < 0.6 * even.keep.size  # the split is on: about half the points
    assert lateral.columns.max() == (tire.grid.n_cols - 1) // 2  # the left half and the centre column
    unmirrored = [replace(even.harmonics[0], mirror=None)]
    plain = replace(even, lateral=lateral_split(tire, flat, even.keep, even.partner, unmirrored))
    assert np.array_equal(plain.lateral.rows, np.arange(even.keep.size))
    assert np.array_equal(plain.lateral.partner, plain.lateral.rows)
    freqs = np.array([0.0, 80.0, 320.0])
    split, whole = even.footprint(freqs), plain.footprint(freqs)
    assert np.abs(split.hub - whole.hub).max() < 1e-9 * np.abs(whole.hub).max()
    np.testing.assert_allclose(split.H_tot, whole.H_tot, rtol=1e-10)


def test_moving_hub_stiffness_equals_the_footprint_stiffness_at_rest(frf):
    """Hub raised with the footprint held, or road raised with the hub held: the same static stiffness
    (to the arc-spreading factor the hub transfer of a point carries once more)."""
    spread = np.sinc(frf.static.grid.dtheta / (2 * np.pi))
    # G_H is the force on the hub (the ring model's convention): -K_v at rest
    assert -frf.G_H[0].real / (frf.H_tot[0].real * spread) - 1 == pytest.approx(0.0, abs=1e-9)


def test_frf_result_feeds_the_ring_models_stages(frf):
    """The footprint FRFs in the ring model's FRFResult: one row per tassello, superposition exact (Eq. i)."""
    result = frf.to_frf_result()
    assert result.H.shape == (frf.static.tasselli.n, frf.freqs.size)
    np.testing.assert_allclose(result.H_sum, result.H_tot, rtol=1e-12)
    np.testing.assert_allclose(result.G_H, frf.G_H)


def test_harmonic_convergence(tire):
    """(c) The loaded deflection moves < 0.1 % from 300 to 400 harmonics."""
    coarse = solve_section_static(section_stages.section_tire(tire.spec.replace(**{"mesh.harmonics": 300})))
    fine = ru.stages.solve_static(NAME)
    assert coarse.deflection / fine.deflection - 1 == pytest.approx(0.0, abs=1e-3)
    assert section_summary(fine)["tasselli"] >= 60
