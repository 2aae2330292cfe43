"""Static contact: exact force balance, symmetry, complementarity, stiffness, drum vs flat."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.ring.mechanics import UZ
from roadnoise_utils.tire.ring.static import contact_problem
from roadnoise_utils.tire.surface import make_road


@pytest.mark.parametrize("road", ["flat", "drum"])
def test_force_balance_exact(road, flat, drum):
    st = flat if road == "flat" else drum
    assert abs(st.contact_force.sum() / st.load - 1) < 1e-9
    assert abs(st.hub_force / st.load - 1) < 1e-9  # the fixed hub receives the whole load


@pytest.mark.parametrize("road", ["flat", "drum"])
def test_footprint_symmetric(road, flat, drum):
    st = flat if road == "flat" else drum
    ne = st.contact.shape[1]
    mirror_x = np.roll(st.contact_force[:, ::-1], 1, axis=1)  # node k -> node (ne - k) % ne
    mirror_y = st.contact_force[::-1, :]
    scale = st.contact_force.max()
    assert np.array_equal(st.contact, st.contact[::-1, :])
    assert np.array_equal(st.contact, np.roll(st.contact[:, ::-1], 1, axis=1))
    assert np.max(np.abs(mirror_x - st.contact_force)) < 1e-9 * scale
    assert np.max(np.abs(mirror_y - st.contact_force)) < 1e-9 * scale
    assert ne == st.contact.shape[1]


def test_complementarity(fet, flat):
    """No tension in contact, no penetration outside it."""
    mesh = fet.mesh
    assert np.all(flat.contact_force >= 0)
    tx, tz = mesh.tread_xz()
    j, k = np.meshgrid(range(mesh.n_strips), range(mesh.n_elements), indexing="ij")
    z = tz + flat.displacement[mesh.dof(j, k, UZ)]
    road = tz.min() + flat.deflection
    lower = np.cos(mesh.theta)[None, :] > 0.5
    assert np.all(z[~flat.contact & lower] >= road - 1e-12)
    # in contact: the tread spring carries the force, k (road - z)
    assert np.allclose(
        fet.tread_normal[flat.contact] * (road - z[flat.contact]),
        flat.contact_force[flat.contact],
        rtol=1e-6,
        atol=1e-9 * flat.load,
    )


def test_tangent_stiffness_is_the_load_deflection_slope(fet, flat):
    """dF/d(delta) from the active set equals a finite difference when the contact set does not change."""
    problem = contact_problem(fet, make_road("flat"))
    w = flat.load
    d_minus = problem.solve(w * (1 - 1e-4))[1]
    d_plus = problem.solve(w * (1 + 1e-4))[1]
    assert (2e-4 * w) / (d_plus - d_minus) == pytest.approx(flat.vertical_stiffness, rel=1e-6)


def test_load_deflection_monotonic_and_progressive(fet):
    loads = np.linspace(1000, 7000, 7)
    d = ru.load_deflection(fet, loads)
    assert np.all(np.diff(d) > 0)
    slopes = np.diff(loads) / np.diff(d)
    assert slopes[-1] > slopes[0]  # the footprint grows: the tire stiffens


def test_drum_footprint_shorter_and_pressure_higher(flat, drum):
    assert drum.footprint_length < flat.footprint_length
    assert drum.mean_pressure > flat.mean_pressure


def test_footprint_grows_with_load(coarse_fet):
    light = ru.solve_static(coarse_fet, load=2500.0)
    heavy = ru.solve_static(coarse_fet, load=6000.0)
    assert heavy.footprint_length > light.footprint_length
    assert heavy.contact.sum() > light.contact.sum()


@pytest.mark.parametrize("load", [0.0, -100.0, float("nan")])
def test_bad_load(coarse_fet, load):
    with pytest.raises(ValueError, match="load"):
        ru.solve_static(coarse_fet, load=load)


def test_bad_road(coarse_fet):
    with pytest.raises(ValueError, match="'flat' and 'drum'"):
        ru.solve_static(coarse_fet, road="cobbles")
    with pytest.raises(ValueError, match="drum_radius"):
        ru.solve_static(coarse_fet, road="drum", drum_radius=0.1)
