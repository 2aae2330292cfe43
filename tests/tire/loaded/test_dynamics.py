"""The loaded tire's dynamics about its static state, on the loaded FE tire's test mesh loaded to 1 kN.

Checked by a second method each: the stiffness parts sum to the static tangent; at rest the
footprint transfer is the static vertical stiffness of the condensed tangent; the footprint's
fore-aft and left-right symmetry holds in every node's transfer; the reduced solve equals the
direct one over the band.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import scipy.sparse as sp

from roadnoise_utils.tire.loaded import dynamics, footprint, road_contact, statics
from roadnoise_utils.tire.loaded.direct import footprint_frf_direct
from roadnoise_utils.tire.symmetric_factor import SymmetricFactor

FREQS = np.array([0.0, 100.0, 250.0, 400.0])


@pytest.fixture(scope="module")
def tire(model_tire):
    """The model's test mesh (``SMALL_LOADED``): several rings of contact nodes at 1 kN."""
    return model_tire


@pytest.fixture(scope="module")
def loaded(model_state):
    return model_state


@pytest.fixture(scope="module")
def linearised(tire, loaded):
    return dynamics.linearise(tire, loaded)


@pytest.fixture(scope="module")
def direct(linearised):
    return footprint_frf_direct(linearised, FREQS)


def test_the_stiffness_parts_sum_to_the_static_tangent(tire, loaded, linearised):
    _, tangent = statics.residual_and_tangent(tire, loaded.u, loaded.pressure)
    total = sum(linearised.compounds.values()) + linearised.pneumatic
    assert abs(total - tangent).max() < 1e-12 * abs(tangent).max()
    assert set(linearised.compounds) == set(tire.mesh.section.points.compounds)
    assert all(abs(part - part.T).max() < 1e-9 * abs(tangent).max() for part in linearised.compounds.values())


def test_at_rest_the_footprint_transfer_is_the_static_vertical_stiffness(tire, loaded, direct):
    """H_tot(0) = K_v and G_H(0) = -K_v, K_v from the condensed static tangent (every ratio is 1 at rest)."""
    k_v = road_contact.vertical_stiffness(tire, loaded)
    assert abs(direct.H_tot[0] / k_v - 1) < 1e-9 and abs(direct.G_H[0] / k_v + 1) < 1e-9
    assert np.all(np.abs(direct.hub[0].imag) < 1e-9 * k_v)


def test_mirrored_contact_nodes_transfer_the_same_force(tire, loaded, direct):
    """The tire and its footprint are symmetric fore-aft and left-right: mirrored nodes are equivalent."""
    x, y = (tire.mesh.coordinates[loaded.contact, i] for i in (0, 1))
    scale = np.abs(direct.hub).max()
    for node in range(x.size):
        for mirror_x, mirror_y in ((-x[node], y[node]), (x[node], -y[node])):
            (mirror,) = np.nonzero((np.abs(x - mirror_x) < 1e-9) & (np.abs(y - mirror_y) < 1e-9))[0]
            np.testing.assert_allclose(direct.hub[:, mirror], direct.hub[:, node], rtol=0, atol=1e-8 * scale)
    assert np.ptp(np.abs(direct.hub[1])) > 1e-3 * scale  # the nodes differ: the check is not vacuous


def test_the_reduced_solve_is_the_direct_one_over_the_band(small_loaded, linearised, direct):
    """The model's FRFs (Craig-Bampton with the modes at rest and their change at the band's storage
    moduli, and the shapes' corrections, reduced for 0-400 Hz): within 1e-3 of the direct solve, relative to the
    largest transfer."""
    frf = small_loaded.fixed_hub_frfs(small_loaded.case(), FREQS)
    assert np.abs(frf.H_points.T - direct.hub).max() < 1e-3 * np.abs(direct.hub).max()
    assert np.abs(frf.G_H - direct.G_H).max() < 1e-3 * np.abs(direct.G_H).max()
    assert abs(frf.H_tot[0] / direct.H_tot[0] - 1) < 1e-9  # the static shapes are in the basis: exact at rest


def test_bad_input_is_refused_naming_it(tire, loaded, linearised):
    with pytest.raises(ValueError, match="touches no road"):
        dynamics.linearise(tire, dataclasses.replace(loaded, contact=loaded.contact[:0]))
    for freqs in ([], [10.0, 5.0], [-1.0], [np.nan], "abc"):
        with pytest.raises(ValueError, match="freqs"):
            footprint_frf_direct(linearised, freqs)
    with pytest.raises(ValueError, match="f_max"):
        dynamics.reduce(linearised, 0.0)


def test_the_footprint_s_tasselli_partition_its_nodes_and_carry_their_transfer(tire, loaded, direct):
    """Every contact node in one tassello, weights summing to one per tassello, the tasselli's H summing
    to H_tot, the nodes found on their rings and columns, and a left-right symmetric footprint giving
    tasselli symmetric across."""
    tasselli = footprint.loaded_tasselli(tire, loaded)
    assert tasselli.node_x.size == loaded.contact.size
    np.testing.assert_allclose(np.bincount(tasselli.node_tassello, weights=tasselli.node_weight), 1.0, rtol=1e-12)
    result = footprint.frf_result(direct, tasselli)
    np.testing.assert_allclose(result.H_sum, result.H_tot, rtol=1e-12)
    np.testing.assert_allclose(result.H_points, direct.hub.T)
    np.testing.assert_allclose(np.sort(tasselli.centre_y), np.sort(-tasselli.centre_y), atol=1e-12)
    ring, column = footprint.contact_grid(tire, loaded)
    assert np.array_equal(tire.tread.reshape(tire.mesh.theta.size, -1)[ring, column], loaded.contact)
    with pytest.raises(ValueError, match="contact nodes"):
        footprint.frf_result(
            direct, footprint.loaded_tasselli(tire, dataclasses.replace(loaded, contact=loaded.contact[:2]))
        )
    with pytest.raises(ValueError, match="touches no road"):
        footprint.loaded_tasselli(tire, dataclasses.replace(loaded, contact=loaded.contact[:0]))


def test_the_loaded_footprint_balances_the_load_with_its_pressures_and_the_hub(tire, loaded):
    """The pressures over the nodes' shape functions give back the road's force, the hub carries it,
    mirrored nodes press alike, and the footprint's K_v is the condensed tangent's: the Footprint
    every model gives, from the loaded state."""
    fp = footprint.loaded_footprint(tire, loaded)
    area = footprint.shape_function_areas(tire, loaded)
    assert abs(np.sum(fp.node_pressure * area) / loaded.road_force - 1) < 1e-12
    x, y = fp.tasselli.node_x, fp.tasselli.node_y
    mirror = [int(np.argmin(np.hypot(x - x[i], y + y[i]))) for i in range(x.size)]  # the node across the centre line
    assert np.hypot(x[mirror] - x, y[mirror] + y).max() < 1e-9
    np.testing.assert_allclose(fp.node_pressure[mirror], fp.node_pressure, rtol=1e-9)
    assert fp.force_balance() < 1e-9 and np.all(fp.node_pressure > 0)
    assert fp.deflection == loaded.road_lift and fp.vertical_stiffness == road_contact.vertical_stiffness(tire, loaded)


@pytest.mark.parametrize("target", [0.0165, 0.0185, 0.0245])
def test_the_tasselli_columns_are_symmetric_and_no_wider_than_the_rows(tire, loaded, target):
    """A node on a band edge goes to the band nearer the centre line (an even number of bands
    splits a symmetric footprint symmetrically), and the bands are at most the target wide."""
    narrow = dataclasses.replace(tire, spec=tire.spec.replace(**{"tasselli.target_length": target}))
    tasselli = footprint.loaded_tasselli(narrow, loaded)
    column = tasselli.column[tasselli.node_tassello]
    for node, y in enumerate(tasselli.node_y):
        mirrors = np.nonzero(np.abs(tasselli.node_y + y) < 1e-9)[0]
        assert mirrors.size and np.all(column[mirrors] == column.max() - column[node])
    assert tasselli.strip_width <= target + 1e-12


@pytest.mark.parametrize("count", [None, 104, 120])
def test_the_modes_below_the_cut_off_are_all_found_whatever_the_count_says(monkeypatch, count):
    """A diagonal pencil with 104 eigenvalues below the cut-off: all of them, mass-normalised, whether the
    inertia count is right (104), missing (None: the request grows from 24) or too high (120: one more request)."""
    n = 300
    values = np.linspace(1.0, 30.0, n) ** 2  # 104 of them below 11^2
    stiffness, mass = sp.diags(values).tocsc(), sp.identity(n, format="csc") * 2.0
    if count != 104:
        monkeypatch.setattr(dynamics, "_count_below", lambda *args: count)
    modes = dynamics._modes_below(stiffness, mass, SymmetricFactor(stiffness), 11.0 / np.sqrt(2.0))
    expected = np.count_nonzero(values / 2.0 < 11.0**2 / 2.0)
    assert modes.shape == (n, expected) and expected == 104
    np.testing.assert_allclose(modes.T @ (mass @ modes), np.eye(expected), atol=1e-10)
